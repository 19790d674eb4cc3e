//! End-to-end tests of `tabor visco`.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::process::Command;

fn tabor(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(args)
        .output()
        .expect("the tabor binary runs")
}

fn json(args: &[&str]) -> serde_json::Value {
    let mut all = vec!["visco"];
    all.extend_from_slice(args);
    all.push("--json");
    let out = tabor(&all);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

fn restitution(v: &serde_json::Value) -> f64 {
    v["restitution"]
        .as_f64()
        .unwrap_or_else(|| panic!("no restitution in {v}"))
}

#[test]
fn kelvin_voigt_flat_at_critical_damping_is_e_minus_two() {
    let v = json(&["--model", "kelvin-voigt-flat", "--damping-ratio", "1"]);
    // (5.63), to rounding.
    assert!((restitution(&v) - (-2.0_f64).exp()).abs() < 1e-15);
    assert_eq!(v["model"], "kelvin-voigt-flat");
}

#[test]
fn every_model_answers_in_unit_interval() {
    let cases: [&[&str]; 11] = [
        &["--model", "kelvin-voigt-flat", "--damping-ratio", "0.3"],
        &["--model", "kuwabara-kono", "--viscous-parameter", "0.1"],
        &[
            "--model",
            "kelvin-voigt-sphere",
            "--viscous-parameter",
            "0.1",
        ],
        &["--model", "lee-herrmann", "--damping", "0.5"],
        &["--model", "tsuji", "--alpha", "1"],
        &["--model", "hunt-crossley", "--damping", "0.5"],
        &[
            "--model",
            "power-damping",
            "--damping-exponent",
            "0.5",
            "--damping",
            "0.5",
        ],
        &[
            "--model",
            "standard-flat",
            "--modulus-ratio",
            "0.1",
            "--viscous-parameter",
            "1",
        ],
        &[
            "--model",
            "standard-sphere",
            "--modulus-ratio",
            "0.1",
            "--viscous-parameter",
            "1",
        ],
        &[
            "--model",
            "kelvin-maxwell-sphere",
            "--modulus-ratio",
            "0.1",
            "--viscous-parameter",
            "1",
        ],
        &[
            "--model",
            "compressible-flat",
            "--poisson-ratio",
            "0.3",
            "--damping-ratio",
            "0.3",
        ],
    ];
    for args in cases {
        let e = restitution(&json(args));
        assert!(e > 0.0 && e < 1.0, "{args:?}: {e}");
    }
    // Kuwabara-Kono below the rigorous model (seed Fig. 5.4).
    let kk = restitution(&json(&[
        "--model",
        "kuwabara-kono",
        "--viscous-parameter",
        "0.1",
    ]));
    let rig = restitution(&json(&[
        "--model",
        "kelvin-voigt-sphere",
        "--viscous-parameter",
        "0.1",
    ]));
    assert!(kk < rig);
    let std = json(&[
        "--model",
        "standard-flat",
        "--modulus-ratio",
        "0.1",
        "--viscous-parameter",
        "1",
    ]);
    assert!(std["equivalent_kelvin_voigt_restitution"]
        .as_f64()
        .is_some());
}

#[test]
fn bad_input_is_one_line_naming_the_flag_and_exit_2() {
    for (args, flag) in [
        (
            vec!["--model", "kelvin-voigt-flat", "--damping-ratio", "-1"],
            "--damping-ratio",
        ),
        (
            vec!["--model", "kelvin-voigt-flat", "--damping-ratio", "NaN"],
            "--damping-ratio",
        ),
        (vec!["--model", "kelvin-voigt-flat"], "--damping-ratio"),
        (
            vec![
                "--model",
                "standard-flat",
                "--modulus-ratio",
                "0",
                "--viscous-parameter",
                "1",
            ],
            "--modulus-ratio",
        ),
        (
            vec![
                "--model",
                "compressible-flat",
                "--poisson-ratio",
                "0.6",
                "--damping-ratio",
                "1",
            ],
            "--poisson-ratio",
        ),
    ] {
        let mut all = vec!["visco"];
        all.extend(args.iter().copied());
        let out = tabor(&all);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(flag), "{err}");
        assert!(out.stdout.is_empty());
    }
}

#[test]
fn help_lists_models_and_flags() {
    let out = tabor(&["visco", "--help"]);
    let text = String::from_utf8_lossy(&out.stdout);
    for s in [
        "kelvin-voigt-flat",
        "kuwabara-kono",
        "standard-flat",
        "compressible-flat",
        "--damping-ratio",
        "--viscous-parameter",
        "--modulus-ratio",
        "--poisson-ratio",
    ] {
        assert!(text.contains(s), "{s} missing in help");
    }
}
