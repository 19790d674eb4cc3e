//! The oblique impact of a scene: the `[friction]` and `[impact] angle` keys, the
//! refusals, and the central impact of today unchanged.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use tabor_scene::{Format, Scene};

const SILICA: &str = r#"
name = "silica"
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
[impact]
speed = 0.3
"#;

fn with(extra: &str) -> Scene {
    Scene::from_str(&format!("{SILICA}{extra}"), Format::Toml).unwrap()
}

#[test]
fn the_lammps_reference_case_through_the_scene() {
    // /work/shared/spec/lammps.md: LAMMPS gives (-0.14455, 0.01749) m/s, w_z = -2.145e4
    let scene = with(
        "angle = 10.0\n[friction]\ncoefficient = 0.3\nrolling = { stiffness = 50.0, damping = 0.0, coefficient = 0.1 }\ntwisting = \"marshall\"\n",
    );
    assert!(scene.is_oblique());
    assert_eq!(scene.angle(), Some(10.0));
    let out = scene.oblique(0.3, 10.0).unwrap();
    let v = out.after.sphere.velocity;
    assert!(
        (v[0] + 0.14455).abs() < 2e-4 && (v[1] - 0.01749).abs() < 2e-4,
        "{v:?}"
    );
    assert!((out.after.sphere.angular_velocity[2] + 2.145e4).abs() < 200.0);
}

#[test]
fn no_friction_and_no_angle_is_todays_scene() {
    let plain = Scene::from_str(SILICA, Format::Toml).unwrap();
    assert!(!plain.is_oblique());
    let zero = with("angle = 0.0\n");
    assert!(!zero.is_oblique());
    assert_eq!(plain.outcome().unwrap(), zero.outcome().unwrap());
    // and the frictionless head-on simulation gives the scene's own restitution
    let o = plain.oblique(0.3, 0.0).unwrap();
    let e = plain.outcome().unwrap().restitution;
    assert!(
        (o.normal_restitution - e).abs() < 1e-6,
        "{} {e}",
        o.normal_restitution
    );
    assert!(o.tangential_restitution.is_none());
}

#[test]
fn bad_friction_keys_are_named_with_their_line() {
    let e = Scene::from_str(
        &format!("{SILICA}[friction]\ncoefficient = -1\n"),
        Format::Toml,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("friction.coefficient"), "{e}");
    let e = Scene::from_str(
        &format!("{SILICA}[friction]\ncoefficient = 0.3\ntangential = \"coulomb\"\n"),
        Format::Toml,
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("friction.tangential") && e.contains("mindlin"),
        "{e}"
    );
    let e = Scene::from_str(&format!("{SILICA}angle = 95.0\n"), Format::Toml)
        .unwrap_err()
        .to_string();
    assert!(e.contains("impact.angle"), "{e}");
    let e = Scene::from_str(
        &format!("{SILICA}[friction]\ncoefficient = 0.3\ntangential = \"linear_history\"\n"),
        Format::Toml,
    )
    .unwrap_err()
    .to_string();
    assert!(e.contains("tangential_stiffness"), "{e}");
}

#[test]
fn loss_level_plasticity_is_refused_by_name() {
    let scene = Scene::from_str(
        &format!(
            "{}\n[friction]\ncoefficient = 0.3\n",
            SILICA.replace(
                "poisson_ratio = 0.17\n[adhesion]",
                "poisson_ratio = 0.17\nyield_stress = 1e8\n[adhesion]"
            )
        ),
        Format::Toml,
    )
    .unwrap();
    let e = scene.oblique(5.0, 30.0).unwrap_err().to_string();
    assert!(e.contains("rule") && e.contains("loss-level"), "{e}");
}
