//! The example programs run and their output matches the library point by point.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::path::PathBuf;
use std::process::Command;

/// The compiled example `name` (cargo builds examples for `cargo test`).
fn example(name: &str) -> PathBuf {
    let exe = std::env::current_exe().unwrap();
    let dir = exe.parent().unwrap().parent().unwrap().join("examples");
    let path = dir.join(format!("{name}{}", std::env::consts::EXE_SUFFIX));
    assert!(
        path.exists(),
        "example {name} not built at {} (plain `cargo test` builds the examples)",
        path.display()
    );
    path
}

fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("tabor-test-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

#[test]
fn loss_vs_lambda_matches_the_direct_evaluation() {
    let dir = temp_dir("loss_vs_lambda");
    let out = Command::new(example("loss_vs_lambda"))
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let svg = std::fs::read_to_string(dir.join("loss_vs_lambda.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("Tabor parameter"));
    let csv = std::fs::read_to_string(dir.join("loss_vs_lambda.csv")).unwrap();
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| header.iter().position(|h| *h == name).unwrap();
    let (lambda_col, ratio_col) = (col("lambda"), col("loss_over_jkr"));
    let mut n = 0;
    for line in lines {
        let fields: Vec<&str> = line.split(',').collect();
        let lambda: f64 = fields[lambda_col].parse().unwrap();
        let ratio: f64 = fields[ratio_col].parse().unwrap();
        let direct = tabor::maugis::normalized_loss(lambda, 1e-12)
            .unwrap()
            .loss_over_jkr;
        assert!(
            (ratio / direct - 1.0).abs() <= 1e-14,
            "Λ={lambda}: {ratio} vs {direct}"
        );
        n += 1;
    }
    assert!(n >= 200);
    std::fs::remove_dir_all(&dir).ok();
}

#[test]
fn trajectory_writes_both_laws() {
    let dir = temp_dir("trajectory");
    let out = Command::new(example("trajectory"))
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let csv = std::fs::read_to_string(dir.join("trajectory.csv")).unwrap();
    assert!(csv.lines().any(|l| l.starts_with("JKR")));
    assert!(csv.lines().any(|l| l.starts_with("Maugis-Dugdale")));
    assert!(dir.join("trajectory.svg").exists());
    // the printed simulated and analytic restitutions agree to the printed digits
    let text = String::from_utf8(out.stdout).unwrap();
    for line in text.lines().filter(|l| l.contains("simulated")) {
        let num = |key: &str| -> f64 {
            let rest = &line[line.find(key).unwrap() + key.len()..];
            rest.split(',').next().unwrap().trim().parse().unwrap()
        };
        assert_eq!(num("simulated ε = "), num("analytic ε = "), "{line}");
    }
    std::fs::remove_dir_all(&dir).ok();
}
