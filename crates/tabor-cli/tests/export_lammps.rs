#![allow(clippy::unwrap_used, clippy::expect_used)]
//! `tabor export lammps`: the fragment, --json, --out, --check, exit code 2 for
//! what LAMMPS cannot represent, and a closed stdout pipe.

use std::io::Read;
use std::path::PathBuf;
use std::process::{Command, Output, Stdio};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../..")
}

fn tabor(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(args)
        .current_dir(root())
        .output()
        .expect("runs")
}

#[test]
fn fragment_json_and_out_agree() {
    let text = tabor(&["export", "lammps", "examples/scenes/silica.toml"]);
    assert!(text.status.success());
    let frag = String::from_utf8(text.stdout).unwrap();
    let last = frag.lines().last().unwrap();
    assert!(last.starts_with("pair_coeff * * jkr "), "{last}");
    let json = tabor(&["export", "lammps", "examples/scenes/silica.toml", "--json"]);
    let v: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    assert_eq!(
        last,
        format!("pair_coeff * * {}", v["model_keywords"].as_str().unwrap())
    );
    let out = std::env::temp_dir().join(format!("tabor-export-{}.lmp", std::process::id()));
    let o = tabor(&[
        "export",
        "lammps",
        "examples/scenes/silica.toml",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success() && o.stdout.is_empty());
    assert_eq!(std::fs::read_to_string(&out).unwrap(), frag);
    // one JSON shape whether printed or written to a file
    let o = tabor(&[
        "export",
        "lammps",
        "examples/scenes/silica.toml",
        "--json",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success() && o.stdout.is_empty());
    assert_eq!(std::fs::read(&out).unwrap(), json.stdout);
    std::fs::remove_file(out).ok();
}

#[test]
fn unrepresentable_scene_exits_2_with_one_line() {
    let o = tabor(&["export", "lammps", "examples/scenes/graded_adhesive.toml"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8(o.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("graded medium") && err.contains("k = 0.5"),
        "{err}"
    );
    let bad = tabor(&[
        "export",
        "lammps",
        "examples/scenes/silica.toml",
        "--check",
        "pair_coeff * * jkr 54e9 0.5 0.17 0.025 damping tsuji",
    ]);
    assert_eq!(bad.status.code(), Some(2));
    assert!(String::from_utf8(bad.stderr).unwrap().contains("tsuji"));
}

#[test]
fn check_reports_nominal_and_achieved() {
    let o = tabor(&[
        "export",
        "lammps",
        "examples/scenes/silica.toml",
        "--check",
        "pair_coeff * * hertz/material 54e9 0.5 0.17 damping tsuji",
        "--speed",
        "0.2",
        "--json",
    ]);
    assert!(o.status.success());
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["nominal_restitution"].as_f64(), Some(0.5));
    let achieved = v["at_speed"]["lammps"].as_f64().unwrap();
    assert!((achieved - 0.616).abs() < 1e-3, "{achieved}");
}

#[test]
fn closed_stdout_is_not_an_error() {
    let mut child = Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(["export", "lammps", "examples/scenes/silica.toml"])
        .current_dir(root())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("spawns");
    drop(child.stdout.take()); // the reader goes away before tabor writes
    let status = child.wait().expect("waits");
    let mut err = String::new();
    child
        .stderr
        .take()
        .unwrap()
        .read_to_string(&mut err)
        .unwrap();
    assert!(status.success(), "{status:?}: {err}");
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn plugin_fragment_json_and_refusals() {
    let so = "/x/taborplugin.so";
    let args = [
        "export",
        "lammps",
        "integrations/lammps/scenes/maugis_case1.toml",
        "--plugin",
        so,
    ];
    let o = tabor(&args);
    assert!(o.status.success());
    let frag = String::from_utf8(o.stdout).unwrap();
    let cmds: Vec<&str> = frag.lines().filter(|l| !l.starts_with('#')).collect();
    // no newton line (legal after create_box), the path quoted
    assert_eq!(cmds[1], format!("plugin load \"{so}\""));
    assert_eq!(cmds[2], "pair_style tabor");
    let json = tabor(&[&args[..], &["--json"]].concat());
    let v: serde_json::Value = serde_json::from_slice(&json.stdout).unwrap();
    let listed: Vec<&str> = v["commands"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| c.as_str().unwrap())
        .collect();
    assert_eq!(listed, cmds);
    assert_eq!(v["model"], "maugis");
    assert_eq!(v["tabor_parameter"], 0.3);
    // plasticity: exit 2, one line
    let scene = "examples/scenes/silica_maugis_plastic.toml";
    let o = tabor(&["export", "lammps", scene, "--plugin", so]);
    assert_eq!(o.status.code(), Some(2), "{scene}");
    let err = String::from_utf8(o.stderr).unwrap();
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("pair_style tabor"), "{err}");
}

/// A flat target exports to the plugin's wall fix (zplane 0.0 NULL, or --wall);
/// a bad --wall, or --wall for two spheres, is exit 2 with one line naming it.
#[test]
fn plugin_flat_target_is_the_wall_fix() {
    let so = "/x/taborplugin.so";
    let wall = "integrations/lammps/scenes/jkr_wall.toml";
    let o = tabor(&["export", "lammps", wall, "--plugin", so]);
    assert!(o.status.success());
    let frag = String::from_utf8(o.stdout).unwrap();
    let cmds: Vec<&str> = frag.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(cmds[0], format!("plugin load \"{so}\""));
    assert!(
        cmds[1].starts_with("fix tabor_wall all wall/tabor jkr/fixed-grip "),
        "{}",
        cmds[1]
    );
    assert!(cmds[1].ends_with(" zplane 0.0 NULL"), "{}", cmds[1]);
    let o = tabor(&[
        "export",
        "lammps",
        wall,
        "--plugin",
        so,
        "--wall",
        "zplane NULL 5e-5",
    ]);
    assert!(o.status.success());
    assert!(String::from_utf8(o.stdout)
        .unwrap()
        .contains(" zplane NULL 5e-5\n"));
    for (scene, bad) in [
        (wall, "zplane 0"),
        (
            "integrations/lammps/scenes/maugis_case1.toml",
            "zplane 0 NULL",
        ),
    ] {
        let o = tabor(&["export", "lammps", scene, "--plugin", so, "--wall", bad]);
        assert_eq!(o.status.code(), Some(2), "{scene} {bad}");
        let err = String::from_utf8(o.stderr).unwrap();
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains("--wall"), "{err}");
    }
}

#[test]
fn json_is_one_shape_printed_or_written() {
    // issue 24: --json --out wrote {"export": ..., "tabor_version": ...} while
    // --json to stdout wrote a flat object
    let printed = tabor(&["export", "lammps", "examples/scenes/silica.toml", "--json"]);
    assert!(printed.status.success());
    let out = std::env::temp_dir().join(format!("tabor-export-{}.json", std::process::id()));
    let o = tabor(&[
        "export",
        "lammps",
        "examples/scenes/silica.toml",
        "--json",
        "--out",
        out.to_str().unwrap(),
    ]);
    assert!(o.status.success() && o.stdout.is_empty());
    let written = std::fs::read(&out).unwrap();
    std::fs::remove_file(out).ok();
    assert_eq!(written, printed.stdout);
    let v: serde_json::Value = serde_json::from_slice(&written).unwrap();
    assert!(v["tabor_version"].is_string() && v["reproduces"]["range"].is_array());
}

#[test]
fn check_reads_legacy_lines_and_variables() {
    let base = [
        "export",
        "lammps",
        "examples/scenes/silica.toml",
        "--speed",
        "0.2",
    ];
    let run = |extra: &[&str]| tabor(&[&base[..], extra].concat());
    // ${E} and $g given on the command line
    let o = run(&[
        "--check",
        "pair_coeff * * hertz/material ${E} $g 0.17 damping tsuji",
        "--var",
        "E=54e9",
        "--var",
        "g=0.5",
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["nominal_restitution"].as_f64(), Some(0.5));
    assert!(v["substituted"].as_str().unwrap().contains("54e9 0.5 0.17"));
    // a variable not given: exit 2, one line naming it
    let o = run(&["--check", "pair_coeff * * hertz/material ${E} 0.5 0.17"]);
    assert_eq!(o.status.code(), Some(2));
    let err = String::from_utf8(o.stderr).unwrap();
    assert!(err.contains("\"E\"") && err.lines().count() == 1, "{err}");
    // the legacy style is read, not refused
    let o = run(&[
        "--check",
        "pair_style gran/hertz/history 2e9 NULL 1e3 NULL 0.5 0",
        "--json",
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["parsed"]["style"], "gran/hertz/history");
}
