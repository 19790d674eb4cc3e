//! End-to-end tests of `tabor penalty`.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::process::Command;

fn tabor(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(args)
        .output()
        .expect("the tabor binary runs")
}

fn json(args: &[&str]) -> serde_json::Value {
    let mut all = vec!["penalty"];
    all.extend_from_slice(args);
    all.push("--json");
    let out = tabor(&all);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} missing in {v}"))
}

#[test]
fn characteristic_is_calibrated_exactly() {
    for e in ["0.05", "0.5", "0.95"] {
        let v = json(&[
            "--law",
            "characteristic",
            "--restitution",
            e,
            "--rounding",
            "1e-5",
        ]);
        let target: f64 = e.parse().unwrap();
        // Simulated to 1e-8 (simulator tolerance 1e-11).
        assert!(
            (num(&v, "achieved_restitution") - target).abs() < 1e-8,
            "{v}"
        );
        assert!(num(&v, "loss_speed") > 0.0);
    }
}

#[test]
fn damped_laws_report_their_drift() {
    // At e = 0.5 (speed, mass, stiffness arbitrary): HC 0.6630, LN 0.7252, Flores
    // 0.4704 (exact first integral; the simulation agrees to 1e-8).
    for (law, achieved) in [
        ("hunt-crossley", 0.662_962_2),
        ("lankarani-nikravesh", 0.725_241_1),
        ("flores", 0.470_444_8),
    ] {
        let v = json(&[
            "--law",
            law,
            "--restitution",
            "0.5",
            "--stiffness",
            "3e9",
            "--mass",
            "0.02",
            "--speed",
            "4",
        ]);
        assert_eq!(num(&v, "nominal_restitution"), 0.5);
        assert!(
            (num(&v, "achieved_restitution") - achieved).abs() < 1e-6,
            "{v}"
        );
        assert!(
            (num(&v, "achieved_restitution") - num(&v, "closed_form_restitution")).abs() < 1e-8
        );
        assert!(num(&v, "damping_factor") > 0.0);
        assert!(num(&v, "exact_damping_factor") > 0.0);
    }
}

#[test]
fn bad_input_is_one_line_naming_the_flag_and_exit_2() {
    for (args, flag) in [
        (
            vec!["--law", "flores", "--restitution", "0"],
            "--restitution",
        ),
        (
            vec!["--law", "flores", "--restitution", "1.5"],
            "--restitution",
        ),
        (
            vec!["--law", "flores", "--restitution", "NaN"],
            "--restitution",
        ),
        (
            vec![
                "--law",
                "hunt-crossley",
                "--restitution",
                "0.5",
                "--speed",
                "-1",
            ],
            "--speed",
        ),
        (
            vec!["--law", "flores", "--restitution", "0.5", "--mass", "0"],
            "--mass",
        ),
        (
            vec![
                "--law",
                "flores",
                "--restitution",
                "0.5",
                "--stiffness",
                "inf",
            ],
            "--stiffness",
        ),
        (
            vec![
                "--law",
                "flores",
                "--restitution",
                "0.5",
                "--exponent",
                "-2",
            ],
            "--exponent",
        ),
        (
            vec![
                "--law",
                "characteristic",
                "--restitution",
                "0.5",
                "--rounding",
                "-1",
            ],
            "--rounding",
        ),
    ] {
        let mut all = vec!["penalty"];
        all.extend_from_slice(&args);
        let out = tabor(&all);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(flag), "{args:?}: {err}");
    }
}
