//! The speed table against the simulation it replaces, at speeds that were neither
//! its samples nor its certifying checks.
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use tabor_restitution::{sticking_velocity, ImpactModel};
use tabor_viscoadhesive::{Adhesion, SeparationRule, ViscoadhesiveImpact};

/// Two soft polymer grains like `examples/scenes/polymer_grains_viscoadhesive.toml`
/// (E = 2 MPa, ν = 0.49, R = 5 µm each, ρ = 970 kg/m³, Δγ = 0.04 J/m²).
fn grains(rule: SeparationRule, tolerance: f64) -> ViscoadhesiveImpact {
    let e_star = 2e6 / (2.0 * (1.0 - 0.49 * 0.49));
    let mass = 0.5 * 4.0 / 3.0 * std::f64::consts::PI * 5e-6f64.powi(3) * 970.0;
    ViscoadhesiveImpact::new(
        e_star,
        2.5e-6,
        mass,
        0.04,
        Adhesion::Jkr(rule),
        4e-4,
        tolerance,
    )
    .unwrap()
}

#[test]
fn table_agrees_with_simulation_within_the_accuracy() {
    for (rule, tolerance) in [
        (SeparationRule::FixedGrip, 1e-10),
        (SeparationRule::LoadControlled, 1e-8),
    ] {
        let model = grains(rule, tolerance);
        let vc = sticking_velocity(&model, 1e-12).unwrap().speed;
        let started = std::time::Instant::now();
        let tabled = model
            .clone()
            .with_speed_table(0.3 * vc, 5.0, Some(vc))
            .unwrap();
        let table = tabled.speed_table().unwrap();
        eprintln!(
            "{rule:?}: vc {vc:.6} table {:?} pieces {} bound {:.1e} worst check {:.1e} cost {:?} in {:?}",
            table.interval(),
            table.pieces(),
            table.error_bound(),
            table.worst_check(),
            table.cost(),
            started.elapsed()
        );
        let (lo, hi) = table.interval();
        assert!(lo > vc && lo < 1.2 * vc && hi == 5.0, "{lo} {hi}");
        // the bound on the loss fraction keeps the restitution within a tenth of
        // the tolerance (ε ≥ 0.1 in the table)
        assert!(
            table.error_bound() <= 0.5 * 0.1 * tolerance,
            "{}",
            table.error_bound()
        );
        // 37 speeds at irrational positions (never a sample or a check)
        let mut answered = 0;
        let mut worst: f64 = 0.0;
        for i in 0..37 {
            let v = lo * (hi / lo).powf((f64::from(i) + 0.5 * 2f64.sqrt()) / 37.5);
            let from_table = tabled.energy_loss(v).unwrap();
            assert!(
                from_table.branch.contains("speed table"),
                "{}",
                from_table.branch
            );
            let simulated = model.energy_loss(v).unwrap();
            let kinetic = 0.5 * model.effective_mass() * v * v;
            let eps_table = (1.0 - from_table.joules / kinetic).sqrt();
            let eps_sim = (1.0 - simulated.joules / kinetic).sqrt();
            worst = worst.max((eps_table - eps_sim).abs());
            // the restitutions agree to the requested accuracy, and the two error
            // estimates cover the difference of the losses
            assert!(
                (eps_table - eps_sim).abs() <= tolerance,
                "{v}: {eps_table} vs {eps_sim}"
            );
            assert!(
                (from_table.joules - simulated.joules).abs()
                    <= from_table.error_estimate + simulated.error_estimate,
                "{v}: {from_table:?} vs {simulated:?}"
            );
            // the viscous loss of the superposition comparison too, to the accuracy
            // the Kuwabara-Kono sphere has itself (about 1e-7 of its small loss)
            let s_table = tabled.superposition(v).unwrap();
            let s_sim = model.superposition(v).unwrap();
            let relative = (s_table.viscous - s_sim.viscous).abs() / s_sim.viscous;
            assert!(relative <= 1e-6, "{v}: {relative:e}");
            answered += 1;
        }
        assert_eq!(answered, 37);
        eprintln!("worst restitution difference {worst:.1e}");
        // below the sticking velocity: "sticks" with the model's own loss
        for v in [0.3 * vc, 0.77 * vc, vc * (1.0 - 2e-6)] {
            let l = tabled.energy_loss(v).unwrap();
            assert!(l.branch.contains("sticks below"), "{v}: {}", l.branch);
            let simulated = model.energy_loss(v).unwrap();
            assert!((l.joules - simulated.joules).abs() <= 1e-12 * simulated.joules);
            assert!(simulated.joules > 0.5 * model.effective_mass() * v * v);
        }
        // outside the table (next to the sticking velocity, below its start, and
        // above it) the model simulates
        for v in [0.2 * vc, vc * (1.0 - 1e-7), 0.5 * (vc + lo), 6.0] {
            let l = tabled.energy_loss(v).unwrap();
            assert!(
                l.branch.starts_with("time-domain simulation"),
                "{v}: {}",
                l.branch
            );
            assert_eq!(l, model.energy_loss(v).unwrap());
        }
    }
}

#[test]
fn bad_ranges_are_errors() {
    let model = grains(SeparationRule::FixedGrip, 1e-8);
    assert!(model.clone().with_speed_table(2.0, 1.0, None).is_err());
    assert!(model.clone().with_speed_table(0.0, 1.0, None).is_err());
    assert!(model.clone().with_speed_table(1.0, f64::NAN, None).is_err());
    let limit = model.small_strain_limit();
    assert!(model
        .clone()
        .with_speed_table(1.0, 2.0 * limit, None)
        .is_err());
    // a range where the bodies stick everywhere has no rebound table
    let vc = sticking_velocity(&model, 1e-12).unwrap().speed;
    assert!(model
        .clone()
        .with_speed_table(0.1 * vc, 0.5 * vc, None)
        .is_err());
    // a sticking velocity that is wrong (the bodies rebound below it) is caught
    assert!(model
        .with_speed_table(0.5 * vc, 3.0, Some(2.0 * vc))
        .is_err());
}
