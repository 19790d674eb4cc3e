#![allow(clippy::unwrap_used, missing_docs)]
use tabor_restitution::ImpactModel;
use tabor_viscoadhesive::{Adhesion, SeparationRule, ViscoadhesiveImpact};
fn int(x: Option<&f64>) -> usize {
    x.map_or(12, |v| *v as usize)
}
fn main() {
    let (e, r, dg, m) = (2.78e10, 0.5e-6, 0.05, 5.55e-15);
    let args: Vec<f64> = std::env::args()
        .skip(1)
        .map(|s| s.parse().unwrap())
        .collect();
    let eta_c = args[0];
    let adh = if args[1] == 0.0 {
        Adhesion::Jkr(SeparationRule::FixedGrip)
    } else {
        Adhesion::MaugisDugdale {
            tabor_parameter: args[1],
        }
    };
    let model = ViscoadhesiveImpact::new(e, r, m, dg, adh, eta_c, 1e-8).unwrap();
    let mut v = model.speed_scale();
    for _ in 0..int(args.get(2)) {
        match model.simulate(v, &model.settings()) {
            Ok(s) => println!(
                "v {v:.3e}: eps {:.6} sticks {} steps {:?} events {:?}",
                s.restitution,
                s.sticks,
                s.cost,
                s.events
                    .iter()
                    .map(|e| (e.kind, e.decision))
                    .collect::<Vec<_>>()
            ),
            Err(e) => println!("v {v:.3e}: {e}"),
        }
        let _ = model.energy_loss(v);
        v *= 2.0;
    }
}
