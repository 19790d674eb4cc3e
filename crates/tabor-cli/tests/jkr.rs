//! End-to-end tests of `tabor jkr`.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::f64::consts::PI;
use std::process::Command;

fn tabor(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(args)
        .output()
        .expect("the tabor binary runs")
}

/// Two silica spheres of radius 1 µm: E* = 54e9/(2(1−0.17²)), R = 0.5 µm, m = half a
/// sphere's mass, Δγ = 0.05 J/m².
fn silica() -> Vec<String> {
    let e = 54e9 / (2.0 * (1.0 - 0.17 * 0.17));
    let m = 0.5 * 4.0 / 3.0 * PI * 1e-18 * 2650.0;
    vec![
        "jkr".into(),
        "--modulus".into(),
        format!("{e:e}"),
        "--radius".into(),
        "5e-7".into(),
        "--work-of-adhesion".into(),
        "0.05".into(),
        "--mass".into(),
        format!("{m:e}"),
    ]
}

fn json(extra: &[&str]) -> serde_json::Value {
    let mut args = silica();
    args.extend(extra.iter().map(|s| s.to_string()));
    args.push("--json".into());
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = tabor(&refs);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("one JSON object")
}

fn num(v: &serde_json::Value, key: &str) -> f64 {
    v[key]
        .as_f64()
        .unwrap_or_else(|| panic!("{key} missing in {v}"))
}

#[test]
fn silica_json_both_separation_rules() {
    let fixed = json(&["--speed", "0.2"]);
    // The seed's (5.36) written out: 0.1(1+∛864)[R⁴(πΔγ)⁵/E²]^(1/3).
    let e = 54e9 / (2.0 * (1.0 - 0.17 * 0.17));
    let loss =
        0.1 * (1.0 + 864f64.cbrt()) * (0.5e-6f64.powi(4) * (PI * 0.05f64).powi(5) / (e * e)).cbrt();
    assert!((num(&fixed, "energy_loss") / loss - 1.0).abs() < 1e-13);
    assert!((num(&fixed, "sticking_velocity") - 0.087).abs() < 0.02 * 0.087);
    assert!(num(&fixed, "max_contact_radius") > 0.0);
    let m = 0.5 * 4.0 / 3.0 * PI * 1e-18 * 2650.0;
    let eps = (1.0 - 2.0 * loss / (m * 0.04)).sqrt();
    assert!((num(&fixed, "restitution") - eps).abs() < 1e-12);
    assert!(fixed["model"].as_str().unwrap().contains("fixed-grip"));
    assert!(fixed["branch"].as_str().unwrap().contains("5.36"));
    // Force at separation −(5/6)πΔγR.
    assert!(
        (num(&fixed, "separation_force") / (-5.0 / 6.0 * PI * 0.05 * 0.5e-6) - 1.0).abs() < 1e-12
    );

    // a_max satisfies the energy balance (5.35), written out here: 1e-10 of the
    // balanced terms (the default tolerance is 1e-12).
    let (r, dg) = (0.5e-6f64, 0.05f64);
    let a = num(&fixed, "max_contact_radius");
    let offset = 0.6 * (4.0 * (PI * dg).powi(5) * r.powi(4) / (e * e)).cbrt();
    let work = 8.0 * e / (15.0 * r * r) * a.powi(5)
        - 8.0 / 3.0 * (PI * dg * e / (2.0 * r * r) * a.powi(7)).sqrt()
        + PI * dg * a * a
        + offset;
    let kinetic = 0.5 * m * 0.04;
    assert!(
        (work - kinetic).abs() <= 1e-10 * (kinetic + offset),
        "{work} vs {kinetic}"
    );
    assert_eq!(fixed["sticks"].as_bool(), Some(false));

    let dem = json(&["--speed", "0.2", "--separation", "load-controlled"]);
    assert!((num(&dem, "sticking_velocity") - 0.061).abs() < 0.02 * 0.061);
    assert!(dem["branch"].as_str().unwrap().contains("quadrature"));
    let ratio = num(&dem, "energy_loss") / num(&fixed, "energy_loss");
    assert!((ratio - 0.493_87).abs() < 1e-5, "{ratio}");
    // The load-controlled loss against the elementary antiderivative of F̂ dd̂/dâ,
    // (6/5)â⁵ − 4â^(7/2) + 2â² between â0 = (4/3)^(2/3) and 1, times F_n d_n.
    let w_hat = |x: f64| 1.2 * x.powi(5) - 4.0 * x.powf(3.5) + 2.0 * x * x;
    let f_n_d_n = 3.0 * 3f64.cbrt() / 8.0 * (r.powi(4) * (PI * dg).powi(5) / (e * e)).cbrt();
    let dem_loss = (w_hat(1.0) - w_hat((4.0f64 / 3.0).powf(2.0 / 3.0))) * f_n_d_n;
    assert!((num(&dem, "energy_loss") / dem_loss - 1.0).abs() < 1e-11);
    // Restitution (5.37) and the sticking velocity (5.38) from that loss.
    let eps = (1.0 - 2.0 * dem_loss / (m * 0.04)).sqrt();
    assert!((num(&dem, "restitution") - eps).abs() < 1e-10);
    assert!((num(&dem, "sticking_velocity") / (2.0 * dem_loss / m).sqrt() - 1.0).abs() < 1e-10);

    // Below the sticking velocity the bodies stick: ε = 0.
    let slow = json(&["--speed", "0.05"]);
    assert_eq!(num(&slow, "restitution"), 0.0);
    assert_eq!(slow["sticks"].as_bool(), Some(true));

    // Without a speed: no restitution, no maximum contact radius.
    let bare = json(&[]);
    assert!(bare.get("restitution").is_none() && bare.get("max_contact_radius").is_none());
    assert!(num(&bare, "energy_loss") > 0.0);
}

#[test]
fn table_and_help() {
    let mut args = silica();
    args.extend(["--speed".to_string(), "0.05".to_string()]);
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    let out = tabor(&refs);
    assert!(out.status.success());
    let text = String::from_utf8_lossy(&out.stdout);
    for key in [
        "energy_loss",
        "sticking_velocity",
        "max_contact_radius",
        "restitution",
        "branch",
    ] {
        assert!(text.contains(key), "{key} in {text}");
    }
    let help = tabor(&["jkr", "--help"]);
    let help = String::from_utf8_lossy(&help.stdout);
    assert!(
        help.contains("effective") && help.contains("load-controlled"),
        "{help}"
    );
}

#[test]
fn bad_input_one_line_exit_2() {
    for (flag, value) in [
        ("--modulus", "-1"),
        ("--radius", "nan"),
        ("--work-of-adhesion", "0"),
        ("--mass", "inf"),
        ("--speed", "-0.1"),
        ("--tolerance", "2"),
    ] {
        let mut args = silica();
        if let Some(i) = args.iter().position(|a| a == flag) {
            args[i + 1] = value.to_string();
        } else {
            args.extend([flag.to_string(), value.to_string()]);
        }
        let refs: Vec<&str> = args.iter().map(String::as_str).collect();
        let out = tabor(&refs);
        assert_eq!(out.status.code(), Some(2), "{flag} {value}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(flag), "{err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    let mut args = silica();
    args.extend(["--separation".to_string(), "sideways".to_string()]);
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    assert_eq!(tabor(&refs).status.code(), Some(2));
}
