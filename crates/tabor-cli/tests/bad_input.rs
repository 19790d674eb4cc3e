#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Issue 9: every subcommand given bad input exits with code 2 and one clear line on
//! stderr (`error: ...`), never a panic or a backtrace. This file: the flags of the
//! model subcommands (`effective`, `jkr`, `maugis-loss`, `plastic`, `visco`), each
//! error naming the flag as typed with its value in `{:e}` form, and negative numbers
//! in any form taken as values. Scene files and the scene subcommands:
//! `bad_input_scenes.rs`.

use std::path::PathBuf;

mod common;

use common::{kv, one_line_error, tabor, usage_error, BAD_NUMBERS};

/// As [`one_line_error`], and the line names `flag`, the flag the user typed
/// (`--lambda`, not the library's `tabor_parameter`).
fn names_flag(args: &[&str], flag: &str) {
    let line = one_line_error(args);
    assert!(
        line.starts_with(&format!("error: invalid {flag} = ")),
        "{args:?}: does not name {flag}: {line}"
    );
}

/// Replaces the value of flag `flag` in `base` with `value`, as one `--flag=value`
/// argument (so that `-inf` is not taken for a flag).
fn with(base: &[&'static str], flag: &str, value: &'static str) -> Vec<&'static str> {
    let mut v = base.to_vec();
    let i = v.iter().position(|a| *a == flag).expect("flag present");
    v[i] = Box::leak(format!("{flag}={value}").into_boxed_str());
    v.remove(i + 1);
    v
}

#[test]
fn effective_bad_values() {
    let base = [
        "effective",
        "--youngs-modulus",
        "54e9",
        "--poisson-ratio",
        "0.17",
        "--radius",
        "1e-6",
        "--density",
        "2650",
    ];
    for flag in ["--youngs-modulus", "--radius", "--density"] {
        for bad in BAD_NUMBERS {
            let line = one_line_error(&with(&base, flag, bad));
            assert!(
                line.contains(&flag[2..]) || line.contains(&flag[2..].replace('-', "_")),
                "{line}"
            );
        }
    }
    for bad in ["0.6", "-1", "nan", "inf"] {
        one_line_error(&with(&base, "--poisson-ratio", bad));
    }
    usage_error(&with(&base, "--radius", "abc"));
    usage_error(&["effective", "--radius", "1"]);
}

#[test]
fn jkr_bad_values() {
    let base = [
        "jkr",
        "--modulus",
        "2.78e10",
        "--radius",
        "5e-7",
        "--work-of-adhesion",
        "0.05",
        "--mass",
        "5.5e-15",
        "--speed",
        "0.1",
    ];
    for flag in [
        "--modulus",
        "--radius",
        "--work-of-adhesion",
        "--mass",
        "--speed",
    ] {
        for bad in BAD_NUMBERS {
            names_flag(&with(&base, flag, bad), flag);
        }
    }
    let mut t = base.to_vec();
    t.extend(["--tolerance", "2"]);
    names_flag(&t, "--tolerance");
    let mut t = base.to_vec();
    t.extend(["--separation", "sideways"]);
    usage_error(&t);
}

#[test]
fn maugis_loss_bad_values() {
    for bad in BAD_NUMBERS {
        names_flag(&["maugis-loss", kv("--lambda", bad)], "--lambda");
        one_line_error(&[
            "maugis-loss",
            kv("--from", bad),
            "--to",
            "10",
            "--points",
            "5",
            "--log",
        ]);
    }
    for (flag, bad) in [("--from", "-1"), ("--to", "-2"), ("--from", "nan")] {
        let (from, to) = if flag == "--from" {
            (bad, "1")
        } else {
            ("1", bad)
        };
        names_flag(
            &[
                "maugis-loss",
                kv("--from", from),
                kv("--to", to),
                "--points",
                "3",
            ],
            flag,
        );
    }
    names_flag(
        &["maugis-loss", kv("--maugis-parameter", "-1")],
        "--maugis-parameter",
    );
    names_flag(&["maugis-loss", kv("--tabor-mu", "nan")], "--tabor-mu");
    names_flag(
        &["maugis-loss", "--from", "1", "--to", "10", "--points", "1"],
        "--points",
    );
    names_flag(
        &["maugis-loss", "--lambda", "1", "--tolerance", "0"],
        "--tolerance",
    );
    names_flag(
        &["maugis-loss", "--lambda", "1", "--tolerance", "nan"],
        "--tolerance",
    );
    usage_error(&["maugis-loss", "--lambda", "one"]);
}

#[test]
fn plastic_bad_values() {
    let base = [
        "plastic",
        "--model",
        "thornton",
        "--modulus",
        "1e11",
        "--radius",
        "2.5e-3",
        "--mass",
        "2.5e-4",
        "--yield-stress",
        "1e9",
        "--speed",
        "1",
    ];
    for flag in [
        "--modulus",
        "--radius",
        "--mass",
        "--yield-stress",
        "--speed",
    ] {
        for bad in BAD_NUMBERS {
            names_flag(&with(&base, flag, bad), flag);
        }
    }
    for (model, extra) in [
        ("jackson-green", ["--poisson-ratio", "0.7"]),
        ("dimensionless-fit", ["--density", "-1"]),
        ("adhesive-interpolation", ["--work-of-adhesion", "nan"]),
        ("superposition", ["--work-of-adhesion", "-1"]),
    ] {
        let mut v = with(&base, "--model", model);
        v.extend(extra);
        one_line_error(&v);
        // and the model's required flag missing altogether
        one_line_error(&with(&base, "--model", model));
    }
    usage_error(&with(&base, "--model", "rubber"));
}

#[test]
fn visco_bad_values() {
    let cases: &[&[&str]] = &[
        &["--model", "kelvin-voigt-flat", "--damping-ratio", "-1"],
        &["--model", "kelvin-voigt-flat", "--damping-ratio", "nan"],
        &["--model", "kelvin-voigt-flat"],
        &["--model", "kuwabara-kono", "--viscous-parameter", "inf"],
        &[
            "--model",
            "kelvin-voigt-sphere",
            "--viscous-parameter",
            "-0.1",
        ],
        &["--model", "lee-herrmann", "--damping", "nan"],
        &["--model", "tsuji", "--alpha", "-1"],
        &["--model", "hunt-crossley", "--damping", "-1"],
        &[
            "--model",
            "power-damping",
            "--damping-exponent",
            "nan",
            "--damping",
            "0.1",
        ],
        &[
            "--model",
            "standard-flat",
            "--modulus-ratio",
            "0",
            "--viscous-parameter",
            "1",
        ],
        &[
            "--model",
            "standard-sphere",
            "--modulus-ratio",
            "1",
            "--viscous-parameter",
            "-1",
        ],
        &[
            "--model",
            "kelvin-maxwell-sphere",
            "--modulus-ratio",
            "nan",
            "--viscous-parameter",
            "1",
        ],
        &[
            "--model",
            "compressible-flat",
            "--poisson-ratio",
            "0.7",
            "--damping-ratio",
            "0.1",
        ],
        &[
            "--model",
            "kelvin-voigt-sphere",
            "--viscous-parameter",
            "0.1",
            "--tolerance",
            "0",
        ],
        &[
            "--model",
            "standard-sphere",
            "--modulus-ratio",
            "1",
            "--viscous-parameter",
            "1",
            "--tolerance",
            "nan",
        ],
    ];
    for c in cases {
        let mut v = vec!["visco"];
        v.extend_from_slice(c);
        one_line_error(&v);
    }
    usage_error(&["visco", "--model", "honey"]);
}

/// Regression (scenes issue): a huge flag value was echoed as a 300-digit number;
/// values are printed in `{:e}` form.
#[test]
fn huge_values_are_echoed_in_exponent_form() {
    for args in [
        vec![
            "jkr",
            "--modulus=-1e300",
            "--radius",
            "1e-6",
            "--work-of-adhesion",
            "0.05",
            "--mass",
            "1e-15",
        ],
        vec!["maugis-loss", "--lambda=-1e300"],
    ] {
        let line = one_line_error(&args);
        assert!(line.contains("-1e300"), "{line}");
        assert!(line.len() < 200, "{} characters: {line}", line.len());
    }
}

/// Issue 33: a negative number in exponent form is a value, not a flag
/// (`--poisson-ratio -3e-1` was "unexpected argument '-3' found").
#[test]
fn negative_numbers_in_any_form_are_values() {
    let base = [
        "effective",
        "--youngs-modulus",
        "54e9",
        "--radius",
        "1e-6",
        "--density",
        "2650",
        "--json",
        "--poisson-ratio",
    ];
    let run = |nu: &str| {
        let mut args = base.to_vec();
        args.push(nu);
        let out = tabor(&args);
        assert!(out.status.success(), "{nu}: {out:?}");
        String::from_utf8(out.stdout).unwrap()
    };
    assert_eq!(run("-3e-1"), run("-0.3"));
    assert_eq!(run("-3E-1"), run("-.3"));
    // a flag where a value belongs is still an error (clap's usage message)
    let out = tabor(&[
        "effective",
        "--youngs-modulus",
        "54e9",
        "--poisson-ratio",
        "--radius",
        "1e-6",
    ]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).starts_with("error: "));
}

/// Issue 33: errors name the flag as typed, each body's its own, and no Rust type
/// name leaks into a message about a scene file.
#[test]
fn errors_speak_the_users_words() {
    let line = one_line_error(&[
        "effective",
        "--youngs-modulus",
        "54e9",
        "--poisson-ratio",
        "0.3",
        "--target-poisson-ratio",
        "0.7",
        "--radius",
        "1e-6",
        "--density",
        "2650",
    ]);
    assert!(
        line.contains("invalid --target-poisson-ratio = 0.7"),
        "{line}"
    );
    let line = one_line_error(&[
        "effective",
        "--youngs-modulus",
        "54e9",
        "--poisson-ratio",
        "0.6",
        "--radius",
        "1e-6",
        "--density",
        "2650",
    ]);
    assert!(line.contains("invalid --poisson-ratio = 0.6"), "{line}");
    let scene = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/silica.toml");
    let line = one_line_error(&[
        "sweep",
        scene.to_str().unwrap(),
        "--parameter",
        "angle",
        "--values",
        "80:100:2",
    ]);
    assert_eq!(line.matches("100").count(), 1, "{line}");
    let dir = std::env::temp_dir().join(format!("tabor-words-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let base = std::fs::read_to_string(&scene).unwrap();
    for (extra, words) in [
        (
            "\n[friction]\ncoefficient = 0.3\nrolling = 5\n",
            "a table { stiffness",
        ),
        (
            "\n[friction]\ncoefficient = 0.3\ntwisting = 5\n",
            "\"marshall\" or a table",
        ),
    ] {
        let path = dir.join("bad.toml");
        std::fs::write(&path, format!("{base}{extra}")).unwrap();
        let line = one_line_error(&["impact", path.to_str().unwrap()]);
        assert!(line.contains(words) && !line.contains("File"), "{line}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
