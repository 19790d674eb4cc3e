//! `tabor impact --angle`, `trajectory --angle`, `sweep --parameter angle` end to end.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;
use std::process::Command;

fn tabor(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(args)
        .output()
        .expect("the tabor binary runs")
}

fn scene(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/scenes")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

fn json(out: &std::process::Output) -> serde_json::Value {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

#[test]
fn impact_angle_json_has_the_oblique_fields() {
    let v = json(&tabor(&[
        "impact",
        &scene("silica_oblique.toml"),
        "--speed",
        "0.3",
        "--angle",
        "10",
        "--json",
    ]));
    for key in [
        "normal_restitution",
        "tangential_restitution",
        "rebound_angle",
        "energy_lost_by_mechanism",
        "after",
        "restitution",
        "model",
    ] {
        assert!(v.get(key).is_some(), "missing {key}: {v}");
    }
    for body in ["sphere", "target"] {
        for field in ["velocity", "angular_velocity"] {
            assert_eq!(v["after"][body][field].as_array().unwrap().len(), 3);
        }
    }
    // LAMMPS's pair granular on the same case: (-0.14455, 0.01749) m/s, -2.145e4 rad/s
    let vx = v["after"]["sphere"]["velocity"][0].as_f64().unwrap();
    let wz = v["after"]["sphere"]["angular_velocity"][2]
        .as_f64()
        .unwrap();
    assert!((vx + 0.14455).abs() < 2e-4, "{vx}");
    assert!((wz + 2.145e4).abs() < 200.0, "{wz}");
}

#[test]
fn angle_zero_without_friction_is_todays_answer() {
    let s = scene("silica.toml");
    let plain = tabor(&["impact", &s, "--json"]);
    let zero = tabor(&["impact", &s, "--angle", "0", "--json"]);
    assert!(plain.status.success());
    assert_eq!(plain.stdout, zero.stdout);
    let plain = tabor(&["trajectory", &s, "--json"]);
    let zero = tabor(&["trajectory", &s, "--angle", "0", "--json"]);
    assert_eq!(plain.stdout, zero.stdout);
}

#[test]
fn trajectory_and_sweep_take_the_angle() {
    let v = json(&tabor(&[
        "trajectory",
        &scene("silica_oblique.toml"),
        "--angle",
        "20",
        "--json",
    ]));
    assert_eq!(v["angle"].as_f64(), Some(20.0));
    let out = tabor(&[
        "sweep",
        &scene("silica_oblique.toml"),
        "--parameter",
        "angle",
        "--values",
        "0:40:3",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    assert!(
        text.starts_with("angle_deg,normal_restitution,tangential_restitution"),
        "{text}"
    );
    assert_eq!(text.lines().count(), 4);
}

#[test]
fn a_bad_angle_is_named() {
    let out = tabor(&["impact", &scene("silica_oblique.toml"), "--angle", "95"]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("angle"), "{err}");
}
