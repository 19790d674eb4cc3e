//! Regression tests of the combination property tests (`combination_properties.rs`):
//! scenes the opt-in 10⁵-case run drew, each checked for the property it broke (the
//! continuity at Λ1, the sticking velocity found, `sticks` ⇔ v < v_stick), with the
//! properties every outcome has (`tests/common/mod.rs`).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use tabor_maugis::LAMBDA_1;
use tabor_scene::SweepParameter;

mod common;

use common::{jump, outcome_is_consistent, Spec};

/// Two scenes the 10⁵-case run of the properties in combination_properties.rs drew
/// (both viscous-adhesive with a Maugis-Dugdale range; the simulator had stepped over
/// the kink of F(d) at the junction of the contact and no-contact branches): the
/// restitution jumped by 2.1e-7 in 1 − ε² across Λ1 at accuracy 1e-8; and a depth a
/// hair above the junction (between its two formulas' roundings) had no θ, so the
/// scene erred.
#[test]
fn regressions_of_the_large_run_at_the_branch_junction() {
    let across_lambda_1 = Spec {
        radius: 7.22375356290814e-5,
        density: 3233.3929795284107,
        modulus: 59905978.14744807,
        poisson: 0.014353026411759121,
        target_sphere: true,
        target_modulus: 52078452566.35248,
        target_poisson: 0.1333114673475124,
        work_of_adhesion: Some(0.01750662635956151),
        range: None,
        load_controlled: false,
        yield_stress: None,
        plastic_model: "auto",
        superposition: false,
        sphere_viscosity: Some(6.033105208892428),
        target_viscosity: Some(5338.595241121118),
        accuracy: 1e-8,
    };
    let scene = across_lambda_1.scene().unwrap();
    let speed = 0.02263378821607054;
    let eps_at = |l: f64| {
        scene
            .with_parameter(SweepParameter::TaborParameter, l)
            .and_then(|s| s.restitution_with_error(speed))
            .ok()
    };
    let j = jump(LAMBDA_1, &eps_at).unwrap();
    assert!(j <= 3.0 * across_lambda_1.accuracy + 1e-8, "jump {j}");
    let at_the_junction = Spec {
        radius: 1.2591593048519706e-6,
        density: 899.9999999999998,
        modulus: 159653413622.7527,
        poisson: 0.0,
        target_sphere: false,
        target_modulus: 137638487902.3963,
        target_poisson: 0.19358995422374248,
        work_of_adhesion: Some(0.0037716384588271095),
        range: Some(2.3170040751989438e-9),
        load_controlled: false,
        yield_stress: None,
        plastic_model: "auto",
        superposition: false,
        sphere_viscosity: Some(3991335.340568817),
        target_viscosity: Some(3574940.4940465568),
        accuracy: 1e-10,
    };
    let o = at_the_junction.scene().unwrap().outcome_at(1.0).unwrap();
    outcome_is_consistent(&o, 1.0).unwrap();
    assert!(
        o.warnings
            .iter()
            .all(|w| w.code != "sticking-velocity-unknown"),
        "{:?}",
        o.warnings
    );
}

/// A third scene of the 10⁵-case run (superposition of JKR, interpolation-model
/// plasticity and Kelvin-Voigt viscosity): ε(v) is 0 below 0.161 m/s, positive
/// up to about 0.23 m/s, 0 again up to about 0.31 m/s; the upper edge of the
/// sticking set was missed by the check on the grid 0.161·2^k (a window of a
/// factor 1.35), and the scene stuck above its reported sticking velocity.
#[test]
fn regression_of_the_large_run_a_narrow_sticking_window() {
    let spec = Spec {
        radius: 2.2205446423411198e-6,
        density: 1615.5880707248239,
        modulus: 48515218164.397064,
        poisson: 0.0,
        target_sphere: true,
        target_modulus: 11915485.669428578,
        target_poisson: 0.1360975746839234,
        work_of_adhesion: Some(0.0071121177584400515),
        range: None,
        load_controlled: false,
        yield_stress: Some(92094.07599852623),
        plastic_model: "interpolation",
        superposition: false,
        sphere_viscosity: Some(14.008992289623903),
        target_viscosity: Some(0.00350558361469889),
        accuracy: 1e-10,
    };
    let scene = spec.scene().unwrap();
    for speed in [0.1, 0.2, 0.261201787320265, 0.35] {
        let o = scene.outcome_at(speed).unwrap();
        outcome_is_consistent(&o, speed).unwrap();
    }
    let o = scene.outcome_at(0.2).unwrap();
    assert!(!o.sticks, "rebounds inside the window's gap");
    assert!(
        o.warnings
            .iter()
            .any(|w| w.code == "restitution-not-monotone"),
        "{:?}",
        o.warnings
    );
}
