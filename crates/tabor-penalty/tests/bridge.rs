#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The bridge: penalty laws calibrated against tabor's JKR and Maugis-Dugdale
//! models reproduce the model's restitution in a simulated impact.

use tabor_dynamics::SimulationSettings;
use tabor_jkr::{JkrImpact, JkrSphere};
use tabor_maugis::{MaugisContact, MaugisDugdaleImpact};
use tabor_penalty::{calibrate_characteristic, calibrate_damped_law, Error, PenaltyStiffness};
use tabor_restitution::{impact, ImpactModel};

// Two silica spheres of radius 1 µm (README worked example).
const MODULUS: f64 = 27_803_521_779.425_392;
const RADIUS: f64 = 5e-7;
const WORK: f64 = 0.05;
const MASS: f64 = 5.550_147_021_341_967e-15;

fn check<M: ImpactModel>(model: &M, speeds: &[f64]) {
    let settings = SimulationSettings::default();
    let hertz = PenaltyStiffness::hertz(MODULUS, RADIUS).unwrap();
    assert!((hertz.exponent() - 1.5).abs() < 1e-15);
    // K = (4/3) E* √R (seed 000 (5.5)), to 1e-14.
    assert!((hertz.coefficient() / (4.0 / 3.0 * MODULUS * RADIUS.sqrt()) - 1.0).abs() < 1e-14);
    let user = PenaltyStiffness::new(1e4, 1.0).unwrap();
    for &v in speeds {
        // The target, from the model directly (tabor_restitution::impact, (5.37)).
        let target = impact(model, v).unwrap().restitution;
        assert!(target > 0.0 && target < 1.0, "v {v}: {target}");
        for stiffness in [hertz, user] {
            let c = calibrate_damped_law(model, v, stiffness, &settings).unwrap();
            assert_eq!(c.target_restitution, target);
            // Reproduced to 1e-6 (observed ~1e-10) in a simulated impact.
            assert!(
                (c.achieved_restitution - target).abs() < 1e-6,
                "{} v {v}: simulated {} target {target}",
                model.name(),
                c.achieved_restitution
            );
            assert!(c.simulation.energy_error < 1e-8);
        }
        let c = calibrate_characteristic(model, v, 50.0, 1e-10, &settings).unwrap();
        assert!(
            (c.achieved_restitution - target).abs() < 1e-6,
            "characteristic v {v}: {} vs {target}",
            c.achieved_restitution
        );
    }
}

#[test]
fn calibrated_law_reproduces_jkr_restitution() {
    let sphere = JkrSphere::new(MODULUS, RADIUS, WORK).unwrap();
    let model = JkrImpact::new(sphere, MASS).unwrap();
    // Sticking velocity ≈ 0.0866 m/s: from just above it (ε ≈ 0.1) to ε ≈ 0.99.
    check(&model, &[0.0871, 0.1, 0.3, 1.0, 10.0]);
}

#[test]
fn calibrated_law_reproduces_maugis_dugdale_restitution() {
    for &lambda in &[0.5, 2.0] {
        let model = MaugisDugdaleImpact::new(
            MaugisContact::new(JkrSphere::new(MODULUS, RADIUS, WORK).unwrap(), lambda).unwrap(),
            MASS,
        )
        .unwrap();
        check(&model, &[0.08, 0.2, 1.0]);
    }
}

#[test]
fn a_sticking_model_is_an_error_not_a_law() {
    let sphere = JkrSphere::new(MODULUS, RADIUS, WORK).unwrap();
    let model = JkrImpact::new(sphere, MASS).unwrap();
    let hertz = PenaltyStiffness::hertz(MODULUS, RADIUS).unwrap();
    let err = calibrate_damped_law(&model, 0.01, hertz, &SimulationSettings::default());
    assert!(matches!(err, Err(Error::Model { .. })), "{err:?}");
    let err = calibrate_damped_law(&model, f64::NAN, hertz, &SimulationSettings::default());
    assert!(
        matches!(
            err,
            Err(Error::InvalidParameter {
                parameter: "impact_speed",
                ..
            })
        ),
        "{err:?}"
    );
}
