#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Issue 9: the scene subcommands (`impact`, `sweep`, `sticking`, `trajectory`)
//! given bad input exit with code 2 and one clear line on stderr (`error: ...`),
//! never a panic or a backtrace. Scene-file errors name the position (line) and the
//! field; a scene file is read up to a ceiling, `-` is standard input, a sweep has
//! a ceiling on its points and leaves no partial file, and speeds beyond small
//! strain and overflowing oblique inputs are refused by name. The flags of the
//! model subcommands: `bad_input.rs`.

use std::path::PathBuf;
use std::process::Command;

mod common;

use common::{kv, one_line_error, tabor, usage_error, BAD_NUMBERS};

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
