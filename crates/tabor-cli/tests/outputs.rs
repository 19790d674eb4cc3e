//! Output conventions end to end: the version in every output, CSV that reads back
//! as the same f64 the JSON output reports, sweep to stdout, a closed pipe, shell
//! completions, the three spellings of the Tabor parameter.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::io::Read;
use std::path::PathBuf;
use std::process::{Command, Stdio};

const VERSION: &str = env!("CARGO_PKG_VERSION");

fn tabor(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(args)
        .output()
        .expect("the tabor binary runs")
}

fn ok(out: &std::process::Output) -> &[u8] {
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    &out.stdout
}

fn scene(name: &str) -> String {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("../../examples/scenes")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

/// The records of a CSV (or TSV) text, read with the csv crate's defaults.
fn records(text: &[u8], delimiter: u8) -> (csv::StringRecord, Vec<csv::StringRecord>) {
    let mut reader = csv::ReaderBuilder::new()
        .delimiter(delimiter)
        .from_reader(text);
    let header = reader.headers().unwrap().clone();
    let rows = reader.records().map(|r| r.unwrap()).collect();
    (header, rows)
}

fn field<'a>(header: &csv::StringRecord, row: &'a csv::StringRecord, name: &str) -> &'a str {
    let i = header
        .iter()
        .position(|h| h == name)
        .unwrap_or_else(|| panic!("no column {name} in {header:?}"));
    &row[i]
}

#[test]
fn version_flag_and_json_carry_the_version() {
    let out = tabor(&["--version"]);
    assert_eq!(
        String::from_utf8_lossy(ok(&out)).trim(),
        format!("tabor {VERSION}")
    );
    for args in [
        &["impact", &scene("silica.toml"), "--json"][..],
        &["sticking", &scene("silica.toml"), "--json"][..],
        &[
            "jkr",
            "--modulus",
            "1e9",
            "--radius",
            "1e-6",
            "--work-of-adhesion",
            "0.1",
            "--mass",
            "1e-14",
            "--json",
        ][..],
    ] {
        let v: serde_json::Value = serde_json::from_slice(ok(&tabor(args))).unwrap();
        assert_eq!(v["tabor_version"], VERSION, "{args:?}");
    }
    let v: serde_json::Value =
        serde_json::from_slice(ok(&tabor(&["maugis-loss", "--lambda", "2", "--json"]))).unwrap();
    assert_eq!(v[0]["tabor_version"], VERSION);
}

#[test]
fn sweep_csv_reads_back_as_the_json_values() {
    // The sweep without --out writes to stdout.
    let out = tabor(&["sweep", &scene("silica.toml"), "--speed", "0.03:0.7:4"]);
    let (header, rows) = records(ok(&out), b',');
    assert_eq!(
        header.iter().collect::<Vec<_>>(),
        [
            "speed_m_per_s",
            "restitution",
            "sticks",
            "energy_loss_j",
            "sticking_velocity_m_per_s",
            "model",
            "tabor_version"
        ]
    );
    assert_eq!(rows.len(), 4);
    for row in &rows {
        assert_eq!(field(&header, row, "tabor_version"), VERSION);
        let speed = field(&header, row, "speed_m_per_s");
        let v: serde_json::Value = serde_json::from_slice(ok(&tabor(&[
            "impact",
            &scene("silica.toml"),
            "--speed",
            speed,
            "--json",
        ])))
        .unwrap();
        assert_eq!(
            v["impact_speed"].as_f64().unwrap(),
            speed.parse::<f64>().unwrap()
        );
        for (column, key) in [
            ("restitution", "restitution"),
            ("energy_loss_j", "energy_loss"),
            ("sticking_velocity_m_per_s", "sticking_velocity"),
        ] {
            let csv: f64 = field(&header, row, column).parse().unwrap();
            assert_eq!(
                csv.to_bits(),
                v[key].as_f64().unwrap().to_bits(),
                "{column} at {speed}"
            );
        }
        assert_eq!(field(&header, row, "model"), v["model"].as_str().unwrap());
    }
}

#[test]
fn maugis_table_reads_back_as_the_json_values() {
    let args = [
        "maugis-loss",
        "--from",
        "0.05",
        "--to",
        "30",
        "--points",
        "7",
        "--log",
    ];
    let (header, rows) = records(ok(&tabor(&args)), b'\t');
    let mut json_args = args.to_vec();
    json_args.push("--json");
    let v: serde_json::Value = serde_json::from_slice(ok(&tabor(&json_args))).unwrap();
    assert_eq!(rows.len(), 7);
    for (i, row) in rows.iter().enumerate() {
        for key in ["lambda", "loss", "loss_over_jkr"] {
            let table: f64 = field(&header, row, key).parse().unwrap();
            assert_eq!(
                table.to_bits(),
                v[i][key].as_f64().unwrap().to_bits(),
                "{key}"
            );
        }
        assert_eq!(field(&header, row, "tabor_version"), VERSION);
    }
}

#[test]
fn trajectory_csv_has_units_and_version() {
    let dir = std::env::temp_dir().join(format!("tabor-cli-outputs-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("t.csv");
    ok(&tabor(&[
        "trajectory",
        &scene("silica.toml"),
        "--speed",
        "0.5",
        "--out",
        path.to_str().unwrap(),
    ]));
    let (header, rows) = records(&std::fs::read(&path).unwrap(), b',');
    assert_eq!(
        header.iter().collect::<Vec<_>>(),
        [
            "time_s",
            "overlap_m",
            "overlap_rate_m_per_s",
            "force_n",
            "contact_radius_m",
            "tabor_version"
        ]
    );
    assert!(rows.len() > 10);
    // starts at first touch with the impact speed
    let first = &rows[0];
    assert_eq!(field(&header, first, "time_s").parse::<f64>().unwrap(), 0.0);
    assert_eq!(field(&header, first, "tabor_version"), VERSION);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn closed_stdout_ends_quietly() {
    // The reproduction: `tabor maugis-loss … | head -1` panicked.
    let mut child = Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args([
            "maugis-loss",
            "--from",
            "0.1",
            "--to",
            "10",
            "--points",
            "100000",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    let mut stdout = child.stdout.take().unwrap();
    let mut first = [0u8; 16];
    stdout.read_exact(&mut first).unwrap();
    assert!(first.starts_with(b"lambda\t"));
    drop(stdout);
    let out = child.wait_with_output().unwrap();
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(stderr.is_empty(), "{stderr}");
    assert_eq!(out.status.code(), Some(0));
}

#[test]
fn completions_for_each_shell() {
    for shell in ["bash", "zsh", "fish", "elvish", "powershell"] {
        let out = tabor(&["completions", shell]);
        let text = String::from_utf8_lossy(ok(&out)).into_owned();
        assert!(text.contains("maugis-loss"), "{shell}");
        assert!(text.contains("completions"), "{shell}");
    }
    assert_eq!(tabor(&["completions", "tcsh"]).status.code(), Some(2));
}

#[test]
fn maugis_parameter_and_tabor_mu_convert_to_lambda() {
    let (header, rows) = records(
        ok(&tabor(&[
            "maugis-loss",
            "--maugis-parameter",
            "1",
            "--tabor-mu",
            "1",
        ])),
        b'\t',
    );
    // Λ = π(9/4)^(1/3)/6 λ, and λ ≈ 1.157 μ (tabor_maugis::units)
    let per_maugis = std::f64::consts::PI * 2.25f64.cbrt() / 6.0;
    let lambda: f64 = field(&header, &rows[0], "lambda").parse().unwrap();
    assert!((lambda / per_maugis - 1.0).abs() < 1e-15, "{lambda}");
    let lambda: f64 = field(&header, &rows[1], "lambda").parse().unwrap();
    assert!(
        (lambda / (per_maugis * 1.157) - 1.0).abs() < 1e-15,
        "{lambda}"
    );
    // the same rows as --lambda with those values
    let direct = tabor(&[
        "maugis-loss",
        "--lambda",
        field(&header, &rows[0], "lambda"),
    ]);
    let (_, direct) = records(ok(&direct), b'\t');
    assert_eq!(direct[0], rows[0]);
    // bad values name their flag
    for (flag, name) in [
        ("--maugis-parameter", "--maugis-parameter"),
        ("--tabor-mu", "--tabor-mu"),
    ] {
        let out = tabor(&["maugis-loss", flag, "-1"]);
        assert_eq!(out.status.code(), Some(2));
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.starts_with(&format!("error: invalid {name} = -1")),
            "{err}"
        );
    }
}

#[test]
fn one_flag_table_for_every_subcommand() {
    // the same library parameter gets the same flag in jkr and plastic
    let jkr = tabor(&[
        "jkr",
        "--modulus",
        "-1",
        "--radius",
        "1e-6",
        "--work-of-adhesion",
        "0.1",
        "--mass",
        "1e-14",
    ]);
    let plastic = tabor(&[
        "plastic",
        "--model",
        "thornton",
        "--modulus",
        "-1",
        "--radius",
        "1e-6",
        "--mass",
        "1e-14",
        "--yield-stress",
        "1e8",
        "--speed",
        "1",
    ]);
    for out in [jkr, plastic] {
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(err.starts_with("error: invalid --modulus = -1"), "{err}");
    }
}
