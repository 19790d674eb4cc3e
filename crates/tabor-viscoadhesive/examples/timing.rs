//! Wall time of one coupled impact and of one sticking-velocity search, release
//! mode: `cargo run --release -p tabor-viscoadhesive --example timing`.
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use std::time::Instant;
use tabor_restitution::{impact, sticking_velocity, ImpactModel};
use tabor_viscoadhesive::{Adhesion, SeparationRule, ViscoadhesiveImpact};

fn main() {
    let (e, r, dg, m) = (2.78e10, 0.5e-6, 0.05, 5.55e-15);
    for eta_c in [0.4, 4.0, 40.0, 400.0] {
        for tol in [1e-8, 1e-10] {
            for (label, adhesion) in [
                ("JKR fixed grip", Adhesion::Jkr(SeparationRule::FixedGrip)),
                (
                    "JKR load-ctrl ",
                    Adhesion::Jkr(SeparationRule::LoadControlled),
                ),
                (
                    "MD Lambda=1   ",
                    Adhesion::MaugisDugdale {
                        tabor_parameter: 1.0,
                    },
                ),
                (
                    "MD Lambda=0.3 ",
                    Adhesion::MaugisDugdale {
                        tabor_parameter: 0.3,
                    },
                ),
            ] {
                let model = ViscoadhesiveImpact::new(e, r, m, dg, adhesion, eta_c, tol).unwrap();
                let v0 = 2.0 * model.speed_scale();
                let n = 200;
                let t = Instant::now();
                let mut eps = 0.0;
                for _ in 0..n {
                    eps = impact(&model, v0).unwrap().restitution;
                }
                let one = t.elapsed().as_secs_f64() / n as f64;
                let cost = model.energy_loss(v0).unwrap().cost;
                let t = Instant::now();
                let vs = sticking_velocity(&model, tol.max(1e-12));
                let st = t.elapsed().as_secs_f64();
                let vs = match vs {
                    Ok(v) => format!("{:.8e} m/s ({} evals)", v.speed, v.cost.evaluations),
                    Err(e) => format!("error: {}", &e.to_string()[..60]),
                };
                println!(
                    "eta_c {eta_c:5} tol {tol:.0e} {label}: eps(2 v_s0) = {eps:.8}  one impact {:7.1} us ({} steps)  v_stick search {:6.2} ms: {vs}",
                    one * 1e6,
                    cost.iterations,
                    st * 1e3,
                );
            }
        }
    }
}
