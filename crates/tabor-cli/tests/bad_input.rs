#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Issue 9: every subcommand given bad input exits with code 2 and one clear line on
//! stderr (`error: ...`), never a panic or a backtrace. Scene-file errors name the
//! position (line) and the field.

use std::path::PathBuf;
use std::process::{Command, Output};

fn tabor(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(args)
        .env("RUST_BACKTRACE", "1")
        .output()
        .expect("the tabor binary runs")
}

/// Exit code 2, exactly one non-empty stderr line starting with `error:`, no panic,
/// nothing on stdout; returns the line.
fn one_line_error(args: &[&str]) -> String {
    let out = tabor(args);
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(
        out.status.code(),
        Some(2),
        "{args:?}: exit {:?}, stderr {stderr}",
        out.status
    );
    assert!(
        !stderr.contains("panicked") && !stderr.contains("backtrace"),
        "{args:?}: panic: {stderr}"
    );
    let lines: Vec<&str> = stderr.lines().filter(|l| !l.trim().is_empty()).collect();
    assert_eq!(lines.len(), 1, "{args:?}: not one line: {stderr}");
    assert!(lines[0].starts_with("error: "), "{args:?}: {stderr}");
    assert!(lines[0].len() > "error: ".len() + 10, "{args:?}: {stderr}");
    assert!(out.stdout.is_empty(), "{args:?}: stdout {:?}", out.stdout);
    lines[0].to_string()
}

/// As [`one_line_error`], and the line names `flag`, the flag the user typed
/// (`--lambda`, not the library's `tabor_parameter`).
fn names_flag(args: &[&str], flag: &str) {
    let line = one_line_error(args);
    assert!(
        line.starts_with(&format!("error: invalid {flag} = ")),
        "{args:?}: does not name {flag}: {line}"
    );
}

/// Argument-syntax errors (clap): exit code 2, an `error:` first line, no panic.
/// (clap adds a usage hint below its first line.)
fn usage_error(args: &[&str]) {
    let out = tabor(args);
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(2), "{args:?}: {stderr}");
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    assert!(stderr.starts_with("error: "), "{args:?}: {stderr}");
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

/// `--flag=value` as one argument.
fn kv(flag: &str, value: &str) -> &'static str {
    Box::leak(format!("{flag}={value}").into_boxed_str())
}

const BAD_NUMBERS: [&str; 6] = ["-1", "0", "nan", "inf", "-inf", "1e999"];

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

// ---------------------------------------------------------------------------
// Scene files

struct TempScene(PathBuf);

impl TempScene {
    fn new(name: &str, text: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("tabor-bad-input-{}", std::process::id()));
        std::fs::create_dir_all(&dir).expect("temp dir");
        let path = dir.join(name);
        std::fs::write(&path, text).expect("write scene");
        TempScene(path)
    }
    fn path(&self) -> &str {
        self.0.to_str().expect("utf-8 path")
    }
}

impl Drop for TempScene {
    fn drop(&mut self) {
        let _ = std::fs::remove_file(&self.0);
    }
}

const GOOD: &str = include_str!("../../../examples/scenes/silica.toml");

/// (file name, contents, what the error line must mention)
fn bad_scenes() -> Vec<(&'static str, String, Vec<&'static str>)> {
    vec![
        (
            "syntax.toml",
            GOOD.replace("radius = 1e-6            # m", "radius = = 1e-6"),
            vec!["line 9"],
        ),
        (
            "unknown_key.toml",
            GOOD.replace("density = 2650           # kg/m³", "densty = 2650"),
            vec!["line", "sphere", "densty"],
        ),
        (
            "wrong_type.toml",
            GOOD.replace(
                "youngs_modulus = 54e9    # Pa",
                "youngs_modulus = \"54 GPa\"",
            ),
            vec!["line", "sphere.youngs_modulus"],
        ),
        (
            "missing_field.toml",
            GOOD.replace("poisson_ratio = 0.17\n\n[target]", "\n[target]"),
            vec!["sphere", "poisson_ratio"],
        ),
        (
            "negative.toml",
            GOOD.replace("radius = 1e-6            # m", "radius = -1e-6"),
            vec!["line 9", "sphere.radius"],
        ),
        (
            "nan.toml",
            GOOD.replace("work_of_adhesion = 0.05  # J/m²", "work_of_adhesion = nan"),
            vec!["line", "adhesion.work_of_adhesion"],
        ),
        (
            "bad_choice.toml",
            GOOD.replace("\"fixed-grip\"", "\"sideways\""),
            vec!["line", "separation"],
        ),
        ("empty.toml", String::new(), vec!["sphere"]),
        (
            "syntax.json",
            "{\"sphere\": {\"radius\": 1e-6,, }}".to_string(),
            vec!["line 1", "column"],
        ),
        (
            "unknown.json",
            "{\"sphere\": {\"radius\": 1e-6, \"colour\": 1}}".to_string(),
            vec!["line 1", "sphere", "colour"],
        ),
        (
            "wrong_type.json",
            "{\"sphere\": {\"radius\": \"big\"}}".to_string(),
            vec!["line 1", "sphere.radius"],
        ),
    ]
}

#[test]
fn scene_subcommands_bad_files() {
    let out_csv = std::env::temp_dir().join(format!("tabor-bad-input-{}.csv", std::process::id()));
    let out_csv = out_csv.to_str().expect("utf-8").to_string();
    for (name, text, needles) in bad_scenes() {
        let scene = TempScene::new(name, &text);
        let p = scene.path();
        let runs: Vec<Vec<&str>> = vec![
            vec!["impact", p],
            vec!["impact", p, "--json"],
            vec!["sweep", p, "--speed", "0.01:1:3", "--out", &out_csv],
            vec!["sticking", p],
            vec!["trajectory", p],
        ];
        for args in runs {
            let line = one_line_error(&args);
            for needle in &needles {
                assert!(line.contains(needle), "{args:?}: {line:?} lacks {needle:?}");
            }
        }
    }
    let _ = std::fs::remove_file(&out_csv);
}

#[test]
fn scene_subcommands_bad_arguments() {
    let good = TempScene::new("good.toml", GOOD);
    let p = good.path();
    let missing = "/nonexistent/tabor/scene.toml";
    let out_csv = std::env::temp_dir().join(format!("tabor-bad-args-{}.csv", std::process::id()));
    let out_csv = out_csv.to_str().expect("utf-8").to_string();
    for bad in BAD_NUMBERS {
        if bad == "1e999" {
            continue;
        }
        one_line_error(&["impact", p, kv("--speed", bad)]);
        one_line_error(&["trajectory", p, kv("--speed", bad)]);
    }
    for args in [
        vec!["impact", missing],
        vec!["sticking", missing],
        vec!["trajectory", missing],
        vec!["sweep", missing, "--speed", "0.01:1:3", "--out", &out_csv],
        vec!["trajectory", p, "--tolerance", "0"],
        vec!["trajectory", p, "--tolerance", "nan"],
        vec!["sweep", p, "--speed", "0.01:1", "--out", &out_csv],
        vec!["sweep", p, "--speed", "a:b:c", "--out", &out_csv],
        vec!["sweep", p, "--speed", "0.01:1:1", "--out", &out_csv],
        vec!["sweep", p, "--speed=-1:1:3", "--log", "--out", &out_csv],
        vec!["sweep", p, "--speed", "nan:1:3", "--out", &out_csv],
        vec![
            "sweep",
            p,
            "--parameter",
            "colour",
            "--values",
            "1:2:3",
            "--out",
            &out_csv,
        ],
        vec![
            "sweep",
            p,
            "--speed",
            "0.01:1:3",
            "--out",
            "/nonexistent/dir/out.csv",
        ],
    ] {
        one_line_error(&args);
    }
    usage_error(&["impact"]);
    usage_error(&["sweep", p]);
    let _ = std::fs::remove_file(&out_csv);
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

/// Issue 33: a scene file is read up to a ceiling (1 MiB): `/dev/zero` is refused
/// at once (it was read until the memory ran out).
#[test]
fn an_endless_scene_file_is_refused_at_once() {
    let t0 = std::time::Instant::now();
    let line = one_line_error(&["impact", "/dev/zero"]);
    assert!(line.contains("1048576 bytes"), "{line}");
    assert!(t0.elapsed().as_secs_f64() < 1.0, "{:?}", t0.elapsed());
}

/// Issue 33: `-` reads the scene from standard input (TOML, or JSON when it
/// starts with `{`), with the same answer as the file.
#[test]
fn a_scene_on_standard_input() {
    use std::io::Write;
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/silica.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(["impact", "-", "--json"])
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    child
        .stdin
        .take()
        .unwrap()
        .write_all(text.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    assert!(out.status.success(), "{out:?}");
    let file = tabor(&["impact", path.to_str().unwrap(), "--json"]);
    assert_eq!(out.stdout, file.stdout);
}

/// Issue 33: a sweep's point count has a ceiling checked before anything is
/// allocated (2^64 − 1 points panicked with "capacity overflow", 10⁹ aborted
/// after 7.7 GB).
#[test]
fn a_sweep_beyond_its_ceiling_is_refused() {
    let scene = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/silica.toml");
    let scene = scene.to_str().unwrap();
    for points in [
        "18446744073709551615",
        "1000000000",
        "99999999999999999999999",
    ] {
        let range = format!("0.01:1:{points}");
        let line = one_line_error(&["sweep", scene, "--speed", &range]);
        assert!(
            line.contains("--speed") && line.contains("at most 10000000"),
            "{line}"
        );
    }
}

/// Issue 33: a failing point leaves no partial file behind.
#[test]
fn a_failed_sweep_leaves_no_file() {
    let scene = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/silica.toml");
    let dir = std::env::temp_dir().join(format!("tabor-sweep-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let out = dir.join("sweep.csv");
    one_line_error(&[
        "sweep",
        scene.to_str().unwrap(),
        "--speed",
        "-1:1:5",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(!out.exists());
    assert!(
        std::fs::read_dir(&dir).unwrap().next().is_none(),
        "a partial file remains"
    );
    std::fs::remove_dir_all(&dir).unwrap();
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

/// Issue 33: a speed beyond the small-strain limit of the pair is refused, naming
/// the limit (10⁹ m/s answered restitution 1 with exit 0), unless asked for.
#[test]
fn beyond_small_strain_is_refused_unless_asked_for() {
    let scene = PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/silica.toml");
    let scene = scene.to_str().unwrap();
    // two silica spheres of 1 µm: E* = 27.8 GPa, R = 0.5 µm, m = 5.55e-15 kg, the
    // Hertz overlap reaches R at v² = 16 E* R³/(15 m): 817 m/s
    let limit = (16.0 * 54e9 / (2.0 * (1.0 - 0.17f64 * 0.17)) * 0.5e-6f64.powi(3)
        / (15.0 * 0.5 * 4.0 / 3.0 * std::f64::consts::PI * 2650.0 * 1e-18))
        .sqrt();
    assert!((limit / 817.27 - 1.0).abs() < 1e-4, "{limit}");
    for args in [
        vec!["impact", scene, "--speed", "1e9"],
        vec!["trajectory", scene, "--speed", "1e3"],
        vec!["sweep", scene, "--speed", "1:1000:3"],
    ] {
        let line = one_line_error(&args);
        assert!(line.contains("small-strain limit 8.1727e2 m/s"), "{line}");
    }
    assert!(
        tabor(&["impact", scene, "--speed", "1e9", "--allow-large-strain"])
            .status
            .success()
    );
    assert!(tabor(&["impact", scene, "--speed", "800"]).status.success());
}

/// Issue 33: spins and stiffnesses that overflow the oblique integration are
/// refused by name (they answered null energies, "NaN at x = 0" or "invalid
/// depth = NaN").
#[test]
fn overflowing_oblique_inputs_are_named() {
    let scene =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../examples/scenes/silica_oblique.toml");
    let base = std::fs::read_to_string(&scene).unwrap();
    let dir = std::env::temp_dir().join(format!("tabor-overflow-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    for (from, to, named) in [
        (
            "angle = 10.0",
            "angle = 10.0\nsphere_spin = [1e308, 1e308, 1e308]",
            "invalid sphere_spin = 1e308",
        ),
        (
            "angle = 10.0",
            "angle = 10.0\ntarget_spin = [0, 0, 1e300]",
            "invalid target_spin = 1e300",
        ),
        (
            "twisting = \"marshall\"",
            "twisting = \"marshall\"\ntangential_stiffness = 1e308",
            "invalid tangential_stiffness = 1e308",
        ),
    ] {
        let path = dir.join("s.toml");
        std::fs::write(&path, base.replacen(from, to, 1)).unwrap();
        let line = one_line_error(&["impact", path.to_str().unwrap()]);
        assert!(line.contains(named), "{line}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}
