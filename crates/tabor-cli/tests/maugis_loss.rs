//! `tabor maugis-loss` end to end.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::process::Command;

fn tabor(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_tabor"))
        .args(args)
        .output()
        .expect("the tabor binary runs")
}

#[test]
fn table_with_header_and_full_precision() {
    let out = tabor(&["maugis-loss", "--lambda", "0.3", "--lambda", "1"]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8(out.stdout).unwrap();
    let mut lines = text.lines();
    assert_eq!(
        lines.next(),
        Some("lambda\tcase\tloss\tloss_over_jkr\ttabor_version")
    );
    let row: Vec<&str> = lines.next().unwrap().split('\t').collect();
    assert_eq!(row[1], "1");
    let ratio: f64 = row[3].parse().unwrap();
    // the mpmath reference of tests/reference in tabor-maugis
    assert!(
        (ratio / 0.014_481_554_790_627_017 - 1.0).abs() < 1e-13,
        "{ratio}"
    );
    assert_eq!(row[4], env!("CARGO_PKG_VERSION"));
    let row: Vec<&str> = lines.next().unwrap().split('\t').collect();
    assert_eq!(row[1], "3");
}

#[test]
fn log_range_and_fast_tier() {
    let out = tabor(&[
        "maugis-loss",
        "--from",
        "0.01",
        "--to",
        "100",
        "--points",
        "50",
        "--log",
    ]);
    assert!(out.status.success());
    let text = String::from_utf8(out.stdout).unwrap();
    assert_eq!(text.lines().count(), 51);
    let fast = tabor(&[
        "maugis-loss",
        "--from",
        "0.01",
        "--to",
        "100",
        "--points",
        "50",
        "--log",
        "--fast",
    ]);
    let fast = String::from_utf8(fast.stdout).unwrap();
    for (a, b) in text.lines().skip(1).zip(fast.lines().skip(1)) {
        let x: f64 = a.split('\t').nth(3).unwrap().parse().unwrap();
        let y: f64 = b.split('\t').nth(3).unwrap().parse().unwrap();
        assert!((x / y - 1.0).abs() < 1e-10);
    }
}

#[test]
fn bad_input_exits_2() {
    for args in [
        &["maugis-loss", "--lambda", "-1"][..],
        &["maugis-loss", "--lambda", "nan"][..],
        &["maugis-loss"][..],
        &["maugis-loss", "--lambda", "1", "--tolerance", "0"][..],
        &[
            "maugis-loss",
            "--from",
            "0",
            "--to",
            "1",
            "--points",
            "5",
            "--log",
        ][..],
        // a range too long to print (was an unbounded allocation)
        &[
            "maugis-loss",
            "--from",
            "1",
            "--to",
            "2",
            "--points",
            "18446744073709551615",
        ][..],
        &["maugis-loss", "--from", "1", "--to", "2", "--points", "1"][..],
    ] {
        let out = tabor(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(!err.contains("panicked"));
    }
}
