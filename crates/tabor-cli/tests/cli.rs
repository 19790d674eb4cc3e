//! End-to-end tests of the `tabor` binary.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::process::Command;

fn tabor(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(args)
        .output()
        .expect("the tabor binary runs")
}

#[test]
fn help_and_version() {
    let out = tabor(&["--help"]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).contains("effective"));
    let out = tabor(&["--version"]);
    assert!(out.status.success());
    assert!(String::from_utf8_lossy(&out.stdout).starts_with("tabor "));
}

#[test]
fn effective_json() {
    let out = tabor(&[
        "effective",
        "--youngs-modulus",
        "54e9",
        "--poisson-ratio",
        "0.17",
        "--radius",
        "1e-6",
        "--density",
        "2650",
        "--target-radius",
        "1e-6",
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON output");
    let e = v["effective_modulus"].as_f64().expect("number");
    assert!((e / (54e9 / (2.0 * (1.0 - 0.17 * 0.17))) - 1.0).abs() < 1e-14);
    assert!((v["effective_radius"].as_f64().expect("number") - 0.5e-6).abs() < 1e-20);
    let m = 4.0 / 3.0 * std::f64::consts::PI * 1e-18 * 2650.0 / 2.0;
    assert!((v["effective_mass"].as_f64().expect("number") / m - 1.0).abs() < 1e-14);
}

#[test]
fn effective_sphere_on_rigid_flat() {
    // A steel sphere (E = 210 GPa, ν = 0.3, R = 1 mm, m = 1e-5 kg) on a rigid,
    // immovable flat: E* = E/(1 − ν²), R* = R, m* = m.
    let out = tabor(&[
        "effective",
        "--youngs-modulus",
        "210e9",
        "--poisson-ratio",
        "0.3",
        "--radius",
        "1e-3",
        "--mass",
        "1e-5",
        "--rigid-target",
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON output");
    let e = v["effective_modulus"].as_f64().expect("number");
    assert!((e / (210e9 / (1.0 - 0.09)) - 1.0).abs() < 1e-14);
    assert_eq!(v["effective_radius"].as_f64(), Some(1e-3));
    assert_eq!(v["effective_mass"].as_f64(), Some(1e-5));
    // A rigid target has no Poisson's ratio: contradictory flags are a usage error.
    let out = tabor(&[
        "effective",
        "--youngs-modulus",
        "210e9",
        "--poisson-ratio",
        "0.3",
        "--radius",
        "1e-3",
        "--mass",
        "1e-5",
        "--rigid-target",
        "--target-poisson-ratio",
        "0.2",
    ]);
    assert_eq!(out.status.code(), Some(2));
}

#[test]
fn bad_input_exits_2_with_one_line() {
    for args in [
        &[
            "effective",
            "--youngs-modulus",
            "-1",
            "--poisson-ratio",
            "0.3",
            "--radius",
            "1",
            "--mass",
            "1",
        ][..],
        &[
            "effective",
            "--youngs-modulus",
            "nan",
            "--poisson-ratio",
            "0.3",
            "--radius",
            "1",
            "--mass",
            "1",
        ][..],
        &[
            "effective",
            "--youngs-modulus",
            "1e9",
            "--poisson-ratio",
            "0.3",
            "--radius",
            "1",
        ][..],
        &["effective", "--youngs-modulus", "abc"][..],
    ] {
        let out = tabor(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!err.contains("panicked"), "{err}");
    }
    let out = tabor(&[
        "effective",
        "--youngs-modulus",
        "-1",
        "--poisson-ratio",
        "0.3",
        "--radius",
        "1",
        "--mass",
        "1",
    ]);
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("invalid --youngs-modulus = -1"), "{err}");
}
