//! End-to-end tests of `tabor plastic`.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::process::Command;

fn tabor(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(args)
        .output()
        .expect("the tabor binary runs")
}

/// Alumina sphere (R = 2.5 mm, m = 0.25 g) on a steel plate, seed 000 Table 5.2.
const BASE: [&str; 10] = [
    "--modulus",
    "1.413e11",
    "--radius",
    "2.5e-3",
    "--mass",
    "2.5e-4",
    "--yield-stress",
    "1.03e9",
    "--speed",
    "1.0",
];

fn json(model: &str, extra: &[&str]) -> serde_json::Value {
    let mut args = vec!["plastic", "--model", model];
    args.extend(BASE);
    args.extend(extra);
    args.push("--json");
    let out = tabor(&args);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).unwrap()
}

/// (5.103): v_Y² = (16/15)(4π/5)⁵ (σ_Y/E*)⁵ E* R³/m, for BASE.
fn thornton_yield_velocity() -> f64 {
    let (e, r, m, s) = (1.413e11_f64, 2.5e-3_f64, 2.5e-4_f64, 1.03e9_f64);
    (16.0 / 15.0 * (0.8 * std::f64::consts::PI).powi(5) * (s / e).powi(5) * e * r.powi(3) / m)
        .sqrt()
}

/// Thornton's closed form (Thornton 1997, eq. (36)) in x = v_Y/v0 ≤ 1:
/// ε = √(6√3/5) √(1 − x²/6) [x/(x + 2√(6/5 − x²/5))]^(1/4); ε(1/2) = 0.9306.
fn thornton_restitution(x: f64) -> f64 {
    (6.0 * 3f64.sqrt() / 5.0).sqrt()
        * (1.0 - x * x / 6.0).sqrt()
        * (x / (x + 2.0 * (1.2 - 0.2 * x * x).sqrt())).powf(0.25)
}

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

#[test]
fn every_model_reports_restitution_and_yield_velocity() {
    // Every model: energy_loss = (1 − ε²) m v0²/2 (m = 2.5e-4 kg, v0 = 1 m/s) to
    // 1e-12, and the output fields. Values from closed forms written here: Thornton's
    // ε (closed form) and v_Y (5.103); the interpolation model with the same v_Y;
    // Jackson-Green's v*_Y = v_Y (5C(ν)/8)^(5/2), C(ν) = 1.295 exp(0.736 ν) (5.108);
    // the dimensionless fit's v_y and e, seed 001 (18), (19). The interpolation
    // and Jackson-Green models have no closed-form ε: they lie above Thornton's
    // (seed, Fig. 5.17: "das Modell von Thornton [sagt] eine deutlich kleinere
    // Stoßzahl vorher als die anderen Modelle").
    let v_y = thornton_yield_velocity();
    let e_thornton = thornton_restitution(v_y / 1.0);
    let mut restitution = std::collections::HashMap::new();
    for (model, extra) in [
        ("thornton", vec![]),
        ("interpolation", vec![]),
        ("jackson-green", vec!["--poisson-ratio", "0.29"]),
        ("dimensionless-fit", vec!["--density", "3820"]),
        ("adhesive-interpolation", vec!["--work-of-adhesion", "0.5"]),
        ("superposition", vec!["--work-of-adhesion", "0.5"]),
    ] {
        let v = json(model, &extra);
        let e = v["restitution"].as_f64().unwrap();
        let yv = v["yield_velocity"].as_f64().unwrap();
        let loss = v["energy_loss"].as_f64().unwrap();
        println!("{model}: ε {e:.12}, yield velocity {yv:.12e}, loss {loss:.6e}");
        assert!(
            rel(loss, (1.0 - e * e) * 0.5 * 2.5e-4) < 1e-12,
            "{model}: {loss}, ε {e}"
        );
        assert!(v["model"].is_string() && v["warnings"].is_array());
        let adhesive = model.starts_with("adhesive") || model == "superposition";
        assert_eq!(v.get("sticking_velocity").is_some(), adhesive, "{model}");
        restitution.insert(model, e);
        match model {
            "thornton" => {
                assert!(rel(yv, v_y) < 1e-12, "{yv} vs {v_y}");
                assert!(rel(e, e_thornton) < 1e-12, "{e} vs {e_thornton}");
            }
            // (5.109): the superposition yields as its plastic part, the interpolation.
            "interpolation" | "superposition" => assert!(rel(yv, v_y) < 1e-12, "{yv} vs {v_y}"),
            "jackson-green" => {
                let c = 1.295 * (0.736 * 0.29_f64).exp();
                let expected = v_y * (5.0 * c / 8.0).powf(2.5);
                assert!(rel(yv, expected) < 1e-12, "{yv} vs {expected}");
            }
            "dimensionless-fit" => {
                let (es, s, rho) = (1.413e11_f64, 1.03e9_f64, 3820.0_f64);
                let expected_v = (15.81 * s.powf(4.5) / (rho * es.powf(3.5))).sqrt();
                assert!(rel(yv, expected_v) < 1e-12, "{yv} vs {expected_v}");
                assert!(1.0 > expected_v);
                let expected = 1.16 + 0.253 * (s / es).ln() + 0.056 * (es / rho).ln();
                assert!((e - expected).abs() < 1e-12, "{e} vs {expected}");
            }
            _ => {}
        }
    }
    for model in ["interpolation", "jackson-green"] {
        assert!(
            restitution[model] > e_thornton + 0.01,
            "{model}: {} vs Thornton {e_thornton}",
            restitution[model]
        );
    }
}

#[test]
fn thornton_matches_the_published_restitution() {
    // v0 = 2 v_Y: eps = 0.9306 (seed 000 / spec), 5e-5.
    let v_y = json("thornton", &[])["yield_velocity"].as_f64().unwrap();
    let speed = format!("{}", 2.0 * v_y);
    let mut args = vec!["plastic", "--model", "thornton"];
    args.extend(&BASE[..8]);
    args.extend(["--speed", speed.as_str(), "--json"]);
    let out = tabor(&args);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert!((v["restitution"].as_f64().unwrap() - 0.9306).abs() < 5e-5);
}

#[test]
fn adhesive_interpolation_wires_phi_and_the_sticking_velocity() {
    // Phi from the material data is κ (Δγ E*²/(σ_Y³ R))^(1/3), with
    // κ = (9c/(π² 1.6³))^(1/3), c = 2 · 1.2429, so that the weak-adhesion yield load
    // of (5.111) is Thornton's (5.102) (tabor-plastic README; the spec's 0.81447 was
    // calibrated to (5.126) instead); giving that Phi through --adhesion-parameter reproduces
    // the same impact (1e-12) and warns that --yield-stress is not used. The adhesive
    // sticking velocity is never below the elastic JKR one (5.38).
    let (e, r, s, dg) = (1.413e11_f64, 2.5e-3_f64, 1.03e9_f64, 0.5_f64);
    let kappa = (9.0 * 2.0 * 1.2429 / (std::f64::consts::PI.powi(2) * 1.6f64.powi(3))).cbrt();
    let phi = kappa * (dg * e * e / (s * s * s * r)).cbrt();
    let from_data = json("adhesive-interpolation", &["--work-of-adhesion", "0.5"]);
    let got = from_data["adhesion_parameter"].as_f64().unwrap();
    assert!(((got - phi) / phi).abs() < 1e-9, "{got} vs {phi}");
    assert!(
        from_data["sticking_velocity"].as_f64().unwrap()
            >= from_data["elastic_sticking_velocity"].as_f64().unwrap() * (1.0 - 1e-9)
    );
    let phi_text = format!("{got:e}");
    let direct = json(
        "adhesive-interpolation",
        &[
            "--work-of-adhesion",
            "0.5",
            "--adhesion-parameter",
            phi_text.as_str(),
        ],
    );
    let (a, b) = (
        from_data["restitution"].as_f64().unwrap(),
        direct["restitution"].as_f64().unwrap(),
    );
    assert!((a - b).abs() < 1e-12, "{a} vs {b}");
    let warned = direct["warnings"].as_array().unwrap();
    assert!(warned
        .iter()
        .any(|w| w.as_str().unwrap().contains("--yield-stress")));
}

#[test]
fn seed_001_clamping_is_reported() {
    // Just above its yield velocity the fit exceeds 1 for this material.
    let v = json("dimensionless-fit", &["--density", "3958.226"]);
    let v_y = v["yield_velocity"].as_f64().unwrap();
    let speed = format!("{}", 1.0001 * v_y);
    let mut args = vec![
        "plastic",
        "--model",
        "dimensionless-fit",
        "--density",
        "3958.226",
    ];
    args.extend(&BASE[..8]);
    args.extend(["--speed", speed.as_str(), "--json"]);
    let out = tabor(&args);
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(v["clamping"], "to-one");
    assert_eq!(v["restitution"].as_f64().unwrap(), 1.0);
    assert!(!v["warnings"].as_array().unwrap().is_empty());
}

#[test]
fn bad_input_is_one_line_naming_the_parameter_and_exit_2() {
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec!["--model", "thornton", "--modulus", "-1"], "--modulus"),
        (vec!["--model", "thornton", "--radius", "nan"], "--radius"),
        (vec!["--model", "thornton", "--mass", "0"], "--mass"),
        (
            vec!["--model", "thornton", "--yield-stress", "inf"],
            "--yield-stress",
        ),
        (vec!["--model", "thornton", "--speed", "-2"], "--speed"),
        (vec!["--model", "jackson-green"], "--poisson-ratio"),
        (
            vec!["--model", "jackson-green", "--poisson-ratio", "0.7"],
            "--poisson-ratio",
        ),
        (vec!["--model", "dimensionless-fit"], "--density"),
        (
            vec!["--model", "adhesive-interpolation"],
            "--work-of-adhesion",
        ),
        (
            vec!["--model", "superposition", "--work-of-adhesion", "-1"],
            "--work-of-adhesion",
        ),
    ];
    for (overrides, name) in cases {
        // Base values, with the overridden flags replaced.
        let mut args = vec!["plastic"];
        let mut i = 0;
        while i < BASE.len() {
            if !overrides.contains(&BASE[i]) {
                args.extend([BASE[i], BASE[i + 1]]);
            }
            i += 2;
        }
        args.extend(&overrides);
        let out = tabor(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains(name), "{args:?}: {err}");
    }
}

#[test]
fn help_says_which_model_needs_which_flag() {
    let out = tabor(&["plastic", "--help"]);
    let help = String::from_utf8_lossy(&out.stdout);
    for needle in [
        "--poisson-ratio",
        "--density",
        "--work-of-adhesion",
        "jackson-green",
    ] {
        assert!(help.contains(needle), "{needle}");
    }
}
