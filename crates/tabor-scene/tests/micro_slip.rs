//! `tangential = "mindlin_deresiewicz"` through a scene: the key, the stiffness
//! 8 G* from the materials, the adhesive pull-off of the Coulomb limit, the report's
//! `micro_slip` mechanism, against the same impact assembled here by hand.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use tabor_dynamics::SimulationSettings;
use tabor_jkr::{JkrForceLaw, JkrSphere, SeparationRule};
use tabor_scene::{Format, Scene};
use tabor_tangential::oblique::{Body, NormalContact, ObliqueImpact};
use tabor_tangential::{EffectiveShear, Friction, Tangential, TangentialModel};

const SILICA: &str = r#"
name = "silica"
accuracy = 1e-9
[sphere]
radius = 1e-6
density = 2650
youngs_modulus = 54e9
poisson_ratio = 0.17
[target]
radius = 1e-6
density = 2650
youngs_modulus = 54e9
poisson_ratio = 0.17
[adhesion]
work_of_adhesion = 0.05
separation = "load-controlled"
[friction]
coefficient = 0.3
tangential = "mindlin_deresiewicz"
[impact]
speed = 0.3
"#;

#[test]
fn the_scene_builds_the_impact_a_user_would_build() {
    let scene = Scene::from_str(SILICA, Format::Toml).unwrap();
    let f = scene.friction().unwrap().unwrap();
    assert_eq!(f.tangential.model, TangentialModel::MindlinDeresiewicz);
    // by hand: two silica spheres, E* = E/(2(1 − ν²)), R* = R/2, JKR pull-off
    // (3/2)π w R*, G* of the pair, 8 G*
    let (r, e, nu, w) = (1e-6, 54e9, 0.17, 0.05);
    let shear = EffectiveShear::of_pair(e, nu, e, nu).unwrap();
    let g_star = 1.0 / (2.0 * 2.0 * (2.0 - nu) * (1.0 + nu) / e);
    assert!((shear.modulus() / g_star - 1.0).abs() < 1e-14);
    assert!((f.tangential.stiffness / (8.0 * g_star) - 1.0).abs() < 1e-14);
    let body = Body::solid_sphere(r, 2650.0).unwrap();
    let imp = ObliqueImpact {
        sphere: body,
        target: body,
        normal: NormalContact {
            pull_off_force: 1.5 * std::f64::consts::PI * w * 0.5 * r,
            damping: 0.0,
            damping_exponent: 1.0,
        },
        friction: Some(Friction::sliding(
            Tangential::new(TangentialModel::MindlinDeresiewicz, 8.0 * g_star, 0.0, 0.3).unwrap(),
        )),
        sphere_spin: [0.0; 3],
        target_spin: [0.0; 3],
    };
    let e_star = e / (2.0 * (1.0 - nu * nu));
    let mut law = JkrForceLaw::new(
        JkrSphere::new(e_star, 0.5 * r, w).unwrap(),
        SeparationRule::LoadControlled,
    );
    let settings = SimulationSettings::with_tolerance(1e-9).unwrap();
    for angle in [10.0, 40.0] {
        let by_hand = imp.simulate(&mut law, 0.3, angle, &settings).unwrap();
        let finer = imp
            .simulate(
                &mut law,
                0.3,
                angle,
                &SimulationSettings::with_tolerance(1e-10).unwrap(),
            )
            .unwrap();
        let scene_out = scene.oblique(0.3, angle).unwrap();
        let (a, b) = (
            by_hand.tangential_restitution.unwrap(),
            scene_out.tangential_restitution.unwrap(),
        );
        // the same model at the same tolerance: equal to the integration's error
        // (rounding in the inputs moves the adaptive steps), which the finer run
        // shows; a wrong stiffness or pull-off would move β by percents
        let error = (finer.tangential_restitution.unwrap() - a).abs();
        assert!(
            (a - b).abs() < 3.0 * error + 1e-9,
            "{angle}°: {a} vs {b} ({error:e})"
        );
        assert!(scene_out.losses.micro_slip > 0.0);
        assert_eq!(scene_out.losses.sliding_friction, 0.0);
    }
}

#[test]
fn the_report_names_micro_slip_and_adds_up() {
    let scene = Scene::from_str(SILICA, Format::Toml).unwrap();
    let (json, _) = scene.oblique_report(0.3, 40.0).unwrap().unwrap();
    let m = &json["energy_lost_by_mechanism"];
    let micro = m["micro_slip"].as_f64().unwrap();
    assert!(micro > 0.0, "{m}");
    let total: f64 = m
        .as_object()
        .unwrap()
        .values()
        .map(|v| v.as_f64().unwrap())
        .sum();
    let lost = json["oblique"]["energy_loss"].as_f64().unwrap();
    let kinetic = json["oblique"]["kinetic_energy"].as_f64().unwrap();
    assert!((total - lost).abs() < 1e-9 * kinetic, "{total} vs {lost}");
}

#[test]
fn the_lammps_models_are_unchanged_by_the_new_key() {
    // the same scene with mindlin: no micro-slip booked, its own numbers
    let scene = Scene::from_str(
        &SILICA.replace("mindlin_deresiewicz", "mindlin"),
        Format::Toml,
    )
    .unwrap();
    let out = scene.oblique(0.3, 40.0).unwrap();
    assert_eq!(out.losses.micro_slip, 0.0);
    assert!(out.losses.sliding_friction > 0.0);
}
