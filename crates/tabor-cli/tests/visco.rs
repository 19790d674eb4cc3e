//! End-to-end tests of `tabor visco`.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::f64::consts::PI;
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

/// Γ(x) by the Lanczos approximation (g = 7, 9 terms; relative error below 1e-13
/// for x > 0), written out here, independent of the library.
fn gamma(x: f64) -> f64 {
    const C: [f64; 9] = [
        0.999_999_999_999_809_9,
        676.520_368_121_885_1,
        -1_259.139_216_722_402_8,
        771.323_428_777_653_1,
        -176.615_029_162_140_6,
        12.507_343_278_686_905,
        -0.138_571_095_265_720_12,
        9.984_369_578_019_572e-6,
        1.505_632_735_149_311_6e-7,
    ];
    if x < 0.5 {
        return PI / ((PI * x).sin() * gamma(1.0 - x));
    }
    let x = x - 1.0;
    let t = x + 7.5;
    let sum = C[0]
        + C[1..]
            .iter()
            .enumerate()
            .map(|(i, c)| c / (x + i as f64 + 1.0))
            .sum::<f64>();
    (2.0 * PI).sqrt() * t.powf(x + 0.5) * (-t).exp() * sum
}

/// First-order restitution of the Kelvin-Voigt sphere, (5.71), written out.
fn first_order_sphere(delta: f64) -> f64 {
    let b = gamma(0.6) * gamma(1.5) / gamma(2.1);
    1.0 - 6.4 * b * (15.0_f64 / 64.0).powf(0.6) * delta
}

/// Kelvin-Voigt flat punch, (5.61), D < 1.
fn kelvin_voigt_flat(d: f64) -> f64 {
    let w = (1.0 - d * d).sqrt();
    (-2.0 * d / w * (w / d).atan()).exp()
}

/// Classical RK4 with a fixed step h from y0 until `ends(y)` turns
/// true (never at t = 0); the end is then located by bisection of the step (the
/// state at the end to RK4 accuracy, not to the step). Returns that state.
fn rk4_until<const N: usize>(
    f: impl Fn(&[f64; N]) -> [f64; N],
    ends: impl Fn(&[f64; N]) -> bool,
    y0: [f64; N],
    h: f64,
) -> [f64; N] {
    let step = |y: &[f64; N], h: f64| {
        let add = |a: &[f64; N], k: &[f64; N], s: f64| {
            let mut r = *a;
            for i in 0..N {
                r[i] += s * k[i];
            }
            r
        };
        let k1 = f(y);
        let k2 = f(&add(y, &k1, 0.5 * h));
        let k3 = f(&add(y, &k2, 0.5 * h));
        let k4 = f(&add(y, &k3, h));
        let mut r = *y;
        for i in 0..N {
            r[i] += h / 6.0 * (k1[i] + 2.0 * k2[i] + 2.0 * k3[i] + k4[i]);
        }
        r
    };
    let mut y = y0;
    for _ in 0..100_000_000 {
        let next = step(&y, h);
        if ends(&next) {
            let (mut lo, mut hi) = (0.0, h);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if ends(&step(&y, mid)) {
                    hi = mid;
                } else {
                    lo = mid;
                }
            }
            return step(&y, hi);
        }
        y = next;
    }
    panic!("no end of contact");
}

/// The damping law (5.72) in the scaling (5.74), `ẍ = −(5/4) x^(3/2) − γ x^β ẋ`,
/// x(0) = 0, ẋ(0) = 1, ended where the force `(5/4) x^(3/2) + γ x^β ẋ` vanishes
/// (or at x = 0): ε = −ẋ there. Integrated in s = t^(1/4), in which x^β (x ≈ t at
/// the start) is smooth for β = 0, 1/4, 1/2, 3/2 (in t, x^(1/4) would cut RK4 to
/// order 1.25); step 1e-4 in s (halving it changes ε by < 2e-11).
fn damping_law(beta: f64, gamma: f64) -> f64 {
    let force = move |y: &[f64; 3]| {
        let x = y[1].max(0.0);
        1.25 * x.powf(1.5) + gamma * x.powf(beta) * y[2]
    };
    let y = rk4_until(
        |y| {
            let dt = 4.0 * y[0].powi(3);
            [1.0, dt * y[2], -dt * force(y)]
        },
        |y| y[1] <= 0.0 || (y[2] < 0.0 && force(y) <= 0.0),
        [0.0, 0.0, 1.0],
        1e-4,
    );
    -y[2]
}

/// The standard flat punch, third-order form (5.79)-(5.81): ends where d̈ rises
/// to 0. Step 1e-4 (halving it changes ε by < 1e-12).
fn standard_flat(beta: f64, delta: f64) -> f64 {
    let a = 1.0 / (beta * delta);
    let b = 1.0 + 1.0 / beta;
    let y = rk4_until(
        |y: &[f64; 3]| [y[1], y[2], -a * y[2] - b * y[1] - a * y[0]],
        |y| y[1] < 0.0 && y[2] >= 0.0,
        [0.0, 1.0, 0.0],
        1e-4,
    );
    -y[1]
}

#[test]
fn every_model_matches_an_independent_value() {
    // Each model at a point with an independent value computed here: a closed form,
    // the first-order formula (5.71) at small δ with its second-order remainder
    // (≤ 10 δ of the loss; observed 2.8 δ), or the model's own equation integrated
    // here by RK4 (to 1e-9: the CLI integrates at relative tolerance 1e-10,
    // observed differences ≤ 1.5e-10).
    let kk_gamma = |delta: f64| 8.0 * (15.0_f64 / 64.0).powf(0.6) * delta;
    let delta_small = 1e-3;
    let loss_small = 1.0 - first_order_sphere(delta_small);
    let cases: [(&[&str], f64, f64); 11] = [
        // (5.61), to rounding.
        (
            &["--model", "kelvin-voigt-flat", "--damping-ratio", "0.3"],
            kelvin_voigt_flat(0.3),
            1e-14,
        ),
        // (5.66) integrated here (KK = damping law β = 1/2, γ = 8 (15/64)^(3/5) δ).
        (
            &["--model", "kuwabara-kono", "--viscous-parameter", "0.1"],
            damping_law(0.5, kk_gamma(0.1)),
            1e-9,
        ),
        // (5.71) at δ = 1e-3, remainder ≤ 10 δ of the loss.
        (
            &[
                "--model",
                "kelvin-voigt-sphere",
                "--viscous-parameter",
                "1e-3",
            ],
            first_order_sphere(delta_small),
            10.0 * delta_small * loss_small,
        ),
        (
            &["--model", "lee-herrmann", "--damping", "0.5"],
            damping_law(0.0, 0.5),
            1e-9,
        ),
        // (5.73): γ = α √(15/64).
        (
            &["--model", "tsuji", "--alpha", "1"],
            damping_law(0.25, (15.0_f64 / 64.0).sqrt()),
            1e-9,
        ),
        (
            &["--model", "hunt-crossley", "--damping", "0.5"],
            damping_law(1.5, 0.5),
            1e-9,
        ),
        (
            &[
                "--model",
                "power-damping",
                "--damping-exponent",
                "0.5",
                "--damping",
                "0.5",
            ],
            damping_law(0.5, 0.5),
            1e-9,
        ),
        // (5.79)-(5.81) integrated here.
        (
            &[
                "--model",
                "standard-flat",
                "--modulus-ratio",
                "0.1",
                "--viscous-parameter",
                "1",
            ],
            standard_flat(0.1, 1.0),
            1e-9,
        ),
        // δ → 0 at fixed β: the Kelvin-Voigt sphere, (5.71) at δ = 1e-3.
        (
            &[
                "--model",
                "standard-sphere",
                "--modulus-ratio",
                "0.1",
                "--viscous-parameter",
                "1e-3",
            ],
            first_order_sphere(delta_small),
            10.0 * delta_small * loss_small,
        ),
        // A weak Maxwell branch (G1 = G∞/β): its force is at most 1/β of the
        // elastic one, its work at most 1/β of the elastic work (2 × m v0²/2), so ε
        // moves by at most 1/β from the Kelvin-Voigt sphere of the dashpot: (5.71).
        (
            &[
                "--model",
                "kelvin-maxwell-sphere",
                "--modulus-ratio",
                "1e4",
                "--viscous-parameter",
                "1e-3",
            ],
            first_order_sphere(delta_small),
            10.0 * delta_small * loss_small + 1e-4,
        ),
        // ν → 1/2 (D2 → 0 by (5.100)): the incompressible (5.61); the difference is
        // O(1 − 2ν), tolerance 10 (1 − 2ν).
        (
            &[
                "--model",
                "compressible-flat",
                "--poisson-ratio",
                "0.49999",
                "--damping-ratio",
                "0.3",
            ],
            kelvin_voigt_flat(0.3),
            10.0 * 2e-5,
        ),
    ];
    for (args, expected, tol) in cases {
        let e = restitution(&json(args));
        println!(
            "{args:?}: {e:.12} vs {expected:.12} ({:.2e}, tol {tol:.1e})",
            e - expected
        );
        assert!((e - expected).abs() < tol, "{args:?}: {e} vs {expected}");
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
    // The extra fields: (5.71) and the equivalent Kelvin-Voigt value (5.83) with
    // (5.61), both closed forms.
    let kv = json(&[
        "--model",
        "kelvin-voigt-sphere",
        "--viscous-parameter",
        "1e-3",
    ]);
    let fo = kv["first_order_restitution"].as_f64().unwrap();
    assert!((fo - first_order_sphere(1e-3)).abs() < 1e-13, "{fo}");
    let std = json(&[
        "--model",
        "standard-flat",
        "--modulus-ratio",
        "0.1",
        "--viscous-parameter",
        "1",
    ]);
    let (b, d) = (0.1_f64, 1.0_f64);
    let damping = d / 2.0 / (1.0 + d * d * b * b + d * d * b);
    let eq = std["equivalent_kelvin_voigt_restitution"].as_f64().unwrap();
    assert!((eq - kelvin_voigt_flat(damping)).abs() < 1e-14, "{eq}");
    let eq_d = std["equivalent_kelvin_voigt_damping_ratio"]
        .as_f64()
        .unwrap();
    assert!((eq_d - damping).abs() < 1e-15, "{eq_d}");
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
