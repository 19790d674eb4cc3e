#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Exports against independent references: the JKR constants of seed 000 (5.36)
//! and its load-controlled counterpart, γ = w/2 for LAMMPS's own rule, the
//! time-domain LAMMPS law against tabor's restitution, and the refusals.

use std::path::PathBuf;
use tabor_lammps::{export, ExportError, Geometry, Scope};
use tabor_scene::Scene;

fn scene(path: &str) -> Scene {
    let root = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..");
    Scene::from_path(&root.join(path)).expect("scene")
}

fn gamma(x: &tabor_lammps::Export) -> f64 {
    x.parameters
        .iter()
        .find(|p| p.name == "gamma")
        .expect("gamma")
        .value
}

#[test]
fn fixed_grip_gamma_from_the_loss_ratio() {
    // losses 1.9459 (fixed grip) and 0.9610 (load-controlled) F_n d_n (tabor-jkr
    // README, seed 000 (5.36)): w_eff/w = (1.9459/0.9610)^(3/5)
    let x = export(&scene("examples/scenes/silica.toml"), None).expect("export");
    let ratio = gamma(&x) / 0.025;
    let expected = (1.9459f64 / 0.9610).powf(0.6);
    assert!((ratio / expected - 1.0).abs() < 2e-4, "{ratio} {expected}");
    assert_eq!(x.reproduces.scope, Scope::EverySpeed);
    assert_eq!(x.geometry, Geometry::Pair);
    let f = x.fragment();
    assert!(f.contains("\npair_coeff * * jkr 5.4000000000e10 0.0000000000e0 0.17 "));
    assert!(f.contains("# REPRODUCES: "));
    assert!(f.contains("# DOES NOT REPRODUCE: the pull-off force"));
}

#[test]
fn load_controlled_scene_keeps_the_true_gamma() {
    let x = export(
        &scene("integrations/lammps/scenes/jkr_load_controlled.toml"),
        None,
    )
    .expect("export");
    assert!((gamma(&x) / 0.025 - 1.0).abs() < 1e-9);
    assert!(!x
        .fragment()
        .contains("DOES NOT REPRODUCE: the pull-off force"));
}

#[test]
fn adhesive_exports_reproduce_tabor_at_every_speed() {
    for s in [
        "integrations/lammps/scenes/jkr_fixed_grip.toml",
        "integrations/lammps/scenes/maugis_case1.toml",
        "integrations/lammps/scenes/maugis_case2.toml",
        "integrations/lammps/scenes/maugis_case3.toml",
        "integrations/lammps/scenes/jkr_wall.toml",
    ] {
        let x = export(&scene(s), None).expect(s);
        assert_eq!(x.reproduces.scope, Scope::EverySpeed, "{s}");
        for c in &x.comparison {
            assert!(
                c.difference.abs() < 1e-7,
                "{s} at {}: {}",
                c.speed,
                c.difference
            );
        }
        let (vt, vl) = (
            x.sticking_velocity.expect("sticks"),
            x.lammps_sticking_velocity.expect("sticks"),
        );
        assert!((vl / vt - 1.0).abs() < 1e-4, "{s}: {vt} {vl}");
    }
}

#[test]
fn damped_exports_hit_the_calibration_speed() {
    for s in [
        "integrations/lammps/scenes/viscoelastic_pair.toml",
        "integrations/lammps/scenes/viscoelastic_wall.toml",
        "integrations/lammps/scenes/plastic_wall.toml",
        "integrations/lammps/scenes/adhesive_viscoelastic.toml",
    ] {
        let x = export(&scene(s), None).expect(s);
        assert_eq!(x.reproduces.scope, Scope::CalibrationSpeed, "{s}");
        let mid = x.comparison[x.comparison.len() / 2];
        assert!((mid.speed / x.reproduces.speed - 1.0).abs() < 1e-12);
        assert!(mid.difference.abs() < 1e-8, "{s}: {}", mid.difference);
        assert!(x
            .parameters
            .iter()
            .any(|p| p.name == "eta_n0" && p.value > 0.0));
    }
    // adhesion + viscosity: gamma and eta_n0 fitted together, so LAMMPS also sticks
    // below tabor's sticking velocity
    let a = export(
        &scene("integrations/lammps/scenes/adhesive_viscoelastic.toml"),
        None,
    )
    .expect("export");
    let (vt, vl) = (
        a.sticking_velocity.expect("sticks"),
        a.lammps_sticking_velocity.expect("sticks"),
    );
    assert!((vl / vt - 1.0).abs() < 1e-6, "{vt} {vl}");
    let w = export(&scene("examples/scenes/rubber_viscoelastic.toml"), None).expect("wall");
    assert_eq!(w.geometry, Geometry::Wall);
    assert!(w.fragment().contains("wall/gran granular hertz/material"));
    assert!(w.model.limit_damping);
}

#[test]
fn unrepresentable_scenes_are_refused_with_the_reason() {
    match export(&scene("examples/scenes/graded_adhesive.toml"), None) {
        Err(e @ ExportError::Unrepresentable { .. }) => {
            let m = e.to_string();
            assert!(m.contains("graded medium") && m.contains("k = 0.5"), "{m}");
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
    // a viscoelastic scene without a speed
    let mut data = scene("examples/scenes/rubber_viscoelastic.toml")
        .data()
        .clone();
    data.impact = None;
    let s = Scene::from_data(data).expect("scene");
    match export(&s, None) {
        Err(e @ ExportError::Unrepresentable { .. }) => {
            assert!(e.to_string().contains("viscoelasticity"), "{e}")
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
    // a damped scene that sticks at the calibration speed
    match export(
        &scene("integrations/lammps/scenes/adhesive_viscoelastic.toml"),
        Some(0.01),
    ) {
        Err(e @ ExportError::Unrepresentable { .. }) => {
            assert!(e.to_string().contains("stick"), "{e}")
        }
        other => panic!("expected a refusal, got {other:?}"),
    }
}
