//! The main figure of tabor: the Maugis-Dugdale adhesive loss normalized by the JKR
//! loss versus the Tabor parameter Λ (seed 000 Fig. 5.2), with the case boundaries
//! Λ1 and Λ2 and the JKR limit; and the pull-off force and the jump-in and pull-off
//! depths versus Λ.
//!
//! `cargo run --release --example loss_vs_lambda [-- --out <dir>]` writes
//! `loss_vs_lambda.csv` and `loss_vs_lambda.svg` into `<dir>` (default: `.`).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use plotters::prelude::*;
use std::error::Error;
use std::io::Write;
use std::path::PathBuf;
use tabor::maugis::{impact_path, loss_over_jkr_fast, normalized_loss, LAMBDA_1, LAMBDA_2};

/// Number of points on the log-spaced Λ axis from 0.01 to 100.
const POINTS: usize = 241;
/// Relative tolerance of the direct evaluation.
const TOLERANCE: f64 = 1e-12;

struct Row {
    lambda: f64,
    case: u8,
    loss: f64,
    loss_over_jkr: f64,
    fast: f64,
    pull_off_force: f64,
    jump_in_depth: f64,
    pull_off_depth: f64,
    evaluations: u64,
}

fn out_dir() -> Result<PathBuf, Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [] => Ok(PathBuf::from(".")),
        [flag, dir] if flag == "--out" => Ok(PathBuf::from(dir)),
        _ => Err("usage: loss_vs_lambda [--out <dir>]".into()),
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let dir = out_dir()?;
    std::fs::create_dir_all(&dir)?;
    let start = std::time::Instant::now();
    let mut rows = Vec::with_capacity(POINTS);
    for i in 0..POINTS {
        let lambda = 0.01 * 10f64.powf(4.0 * i as f64 / (POINTS - 1) as f64);
        let w = normalized_loss(lambda, TOLERANCE)?;
        let path = impact_path(lambda)?;
        rows.push(Row {
            lambda,
            case: w.case.number(),
            loss: w.loss,
            loss_over_jkr: w.loss_over_jkr,
            fast: loss_over_jkr_fast(lambda)?,
            pull_off_force: path.pull_off.force,
            jump_in_depth: path.jump_in.depth,
            pull_off_depth: path.pull_off.depth,
            evaluations: w.cost.evaluations,
        });
    }
    let elapsed = start.elapsed();

    let csv_path = dir.join("loss_vs_lambda.csv");
    let mut csv = std::io::BufWriter::new(std::fs::File::create(&csv_path)?);
    writeln!(
        csv,
        "lambda,case,loss_over_jkr,loss,loss_over_jkr_fast,pull_off_force,jump_in_depth,pull_off_depth,evaluations"
    )?;
    for r in &rows {
        writeln!(
            csv,
            "{:.16e},{},{:.16e},{:.16e},{:.16e},{:.16e},{:.16e},{:.16e},{}",
            r.lambda,
            r.case,
            r.loss_over_jkr,
            r.loss,
            r.fast,
            r.pull_off_force,
            r.jump_in_depth,
            r.pull_off_depth,
            r.evaluations
        )?;
    }
    csv.flush()?;

    let svg_path = dir.join("loss_vs_lambda.svg");
    plot(&rows, &svg_path)?;
    println!(
        "{} points (direct evaluation, tolerance {TOLERANCE:e}) in {:.1} ms",
        rows.len(),
        elapsed.as_secs_f64() * 1e3
    );
    for lambda in [0.1, 1.0, 4.0, 10.0, 100.0] {
        let w = normalized_loss(lambda, TOLERANCE)?;
        println!(
            "  Λ = {lambda:>6}: W/W_JKR = {:.12} (case {})",
            w.loss_over_jkr,
            w.case.number()
        );
    }
    println!("wrote {} and {}", csv_path.display(), svg_path.display());
    Ok(())
}

fn plot(rows: &[Row], path: &std::path::Path) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1200, 520)).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = root.split_horizontally(640);
    let x_range = (0.01f64..100.0f64).log_scale();

    let mut chart = ChartBuilder::on(&left)
        .caption(
            "Maugis-Dugdale loss / JKR loss (Willert 2020, Fig. 5.2)",
            ("sans-serif", 20),
        )
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .build_cartesian_2d(x_range.clone(), 0.0f64..1.05)?;
    chart
        .configure_mesh()
        .x_desc("Tabor parameter Λ")
        .y_desc("|ΔU| / |ΔU_JKR|")
        .draw()?;
    chart
        .draw_series(LineSeries::new(
            rows.iter().map(|r| (r.lambda, r.loss_over_jkr)),
            BLUE.stroke_width(2),
        ))?
        .label("Maugis-Dugdale")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLUE.stroke_width(2)));
    chart
        .draw_series(LineSeries::new(
            [(0.01, 1.0), (100.0, 1.0)],
            BLACK.stroke_width(1),
        ))?
        .label("JKR limit")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK));
    for (lambda, name, color) in [
        (LAMBDA_1, "Λ1 (case 1 | 2)", RED),
        (LAMBDA_2, "Λ2 (case 2 | 3)", GREEN),
    ] {
        chart
            .draw_series(LineSeries::new(
                [(lambda, 0.0), (lambda, 1.05)],
                color.stroke_width(1),
            ))?
            .label(name)
            .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color));
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;

    let y_min = rows
        .iter()
        .map(|r| r.pull_off_depth.min(r.pull_off_force))
        .fold(f64::INFINITY, f64::min)
        .max(-12.0);
    let mut chart = ChartBuilder::on(&right)
        .caption("pull-off force and depths (normalized)", ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(50)
        .build_cartesian_2d(x_range, y_min..0.5)?;
    chart.configure_mesh().x_desc("Tabor parameter Λ").draw()?;
    type Column = fn(&Row) -> f64;
    let series: [(&str, RGBColor, Column); 3] = [
        ("F̂ at pull-off", BLUE, |r| r.pull_off_force),
        ("d̂ at jump-in (−1/Λ)", RED, |r| r.jump_in_depth),
        ("d̂ at pull-off", GREEN, |r| r.pull_off_depth),
    ];
    for (name, color, f) in series {
        chart
            .draw_series(LineSeries::new(
                rows.iter()
                    .map(|r| (r.lambda, f(r)))
                    .filter(|p| p.1 >= y_min),
                color.stroke_width(2),
            ))?
            .label(name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::LowerRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}
