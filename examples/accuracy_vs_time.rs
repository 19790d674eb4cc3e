//! What accuracy costs in time: for each numerical answer of tabor, the requested
//! relative tolerance (1e-2 … 1e-14, one per decade), the achieved relative error
//! against a tight reference, the integrand evaluations the answer reports
//! (`cost.evaluations`) and the median time of one evaluation of the answer.
//!
//! Rows:
//! - the Maugis-Dugdale loss W(Λ) of seed 000 eqs. (5.43)-(5.46) at Λ = 0.3 (case 1,
//!   closed form (5.44), reference written out here as `17·2¹⁹Λ⁵/(3⁴π⁸)`), Λ = 0.55
//!   (case 2), Λ = 2 (case 3) and Λ = 1e3 (references: the independent 20-digit
//!   mpmath values of `crates/tabor-maugis/tests/reference/md_reference.py`, a
//!   different parametrization, root finder and quadrature);
//! - the fast tier of W(Λ)/W_JKR (Fig. 5.2) at the same Λ, against the same
//!   references (its requested tolerance is the bound it is built and tested for,
//!   1e-10);
//! - the JKR loss with load-controlled separation (the integral of (5.36) to the
//!   load-controlled pull-off point, by quadrature), against its elementary
//!   antiderivative: with F̂ = â³ − 2â^(3/2), d̂ = 3â² − 4â^(1/2),
//!   `∫ F̂ (dd̂/dâ) dâ = [(6/5)â⁵ − 4â^(7/2) + 2â²]` from â0 = (4/3)^(2/3) to 1,
//!   `= (6/5)(4/3)^(4/3) − 4/5` (units F_n d_n);
//! - the time-domain simulation of one JKR impact (two silica spheres of radius
//!   1 µm at twice their sticking velocity, fixed grip), the simulated restitution
//!   against the closed form (5.37)-(5.38) (√3/2 at v0 = 2 v_c), and the same for a
//!   Maugis-Dugdale impact at Λ = 1 (reference: (5.37) with the direct loss at 1e-15).
//!
//! Times are medians over 7 batches of repeated calls timed with `Instant`; a batch
//! lasts at least 2 ms. Rows whose achieved error exceeds the requested tolerance are
//! marked **NO** in the printed table and counted at its end (there are none:
//! `tests/examples.rs` requires every row to track its tolerance).
//!
//! `cargo run --release --example accuracy_vs_time [-- --out <dir>]` writes
//! `accuracy_vs_time.csv` and `accuracy_vs_time.svg` into `<dir>` (default: `.`).
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::excessive_precision)]

use plotters::prelude::*;
use std::error::Error;
use std::hint::black_box;
use std::io::Write;
use std::path::PathBuf;
use std::time::{Duration, Instant};
use tabor::dynamics::{simulate_impact, SimulationSettings};
use tabor::jkr::{normalized, JkrForceLaw, JkrImpact, JkrSphere, SeparationRule};
use tabor::maugis::{
    loss_over_jkr_fast, normalized_loss, prepare_fast_tier, MaugisContact, MaugisDugdaleForceLaw,
    MaugisDugdaleImpact, FAST_TIER_RELATIVE_ERROR,
};
use tabor::restitution::{impact, restitution_from_loss, sticking_velocity};

/// Requested tolerances: 1e-2 … 1e-14.
const TOLERANCES: [f64; 13] = [
    1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10, 1e-11, 1e-12, 1e-13, 1e-14,
];
/// Tolerance of the direct evaluation behind the simulated Maugis-Dugdale reference.
const REFERENCE_TOLERANCE: f64 = 1e-15;
/// W(Λ)/W_JKR at Λ = 0.3, 0.55, 2, 1e3 from the mpmath derivation
/// `crates/tabor-maugis/tests/reference/md_reference.py` (20 digits; Λ = 0.3 is the
/// closed form (5.44), the other three its quadrature on the â-parametrized branch).
const MD_REFERENCE: [(f64, f64); 4] = [
    (0.3, 0.014_481_554_790_627_017),
    (0.55, 0.236_545_169_834_087_40),
    (2.0, 0.785_906_781_316_458_88),
    (1e3, 0.999_543_272_426_684_67),
];
/// The JKR loss (5.36) in units of F_n d_n, `4(1 + ∛864)/(15∛3)` = 1.94592420590397015…
/// (mpmath), which turns the references above into losses.
const W_JKR: f64 = 1.945_924_205_903_970_2;
/// Batches per timing and the shortest batch.
const BATCHES: usize = 7;
const MIN_BATCH: Duration = Duration::from_millis(2);
/// Errors of exactly zero are drawn at this floor on the log axis.
const ERROR_FLOOR: f64 = 1e-17;

/// The row groups, in order.
const GROUPS: [&str; 8] = [
    "Maugis-Dugdale, Λ = 0.3 (case 1, closed form)",
    "Maugis-Dugdale, Λ = 0.55 (case 2)",
    "Maugis-Dugdale, Λ = 2 (case 3)",
    "Maugis-Dugdale, Λ = 1e3 (case 3)",
    "Maugis-Dugdale fast tier",
    "JKR load-controlled loss (quadrature)",
    "simulated JKR impact (restitution)",
    "simulated Maugis-Dugdale impact, Λ = 1 (restitution)",
];

/// The row groups as written into the CSV (no commas).
const GROUP_KEYS: [&str; 8] = [
    "maugis_lambda_0.3",
    "maugis_lambda_0.55",
    "maugis_lambda_2",
    "maugis_lambda_1e3",
    "maugis_fast_tier",
    "jkr_load_controlled",
    "simulated_jkr",
    "simulated_maugis_lambda_1",
];

struct Row {
    group: usize,
    /// Λ for the fast-tier rows, the requested tolerance otherwise.
    label: String,
    requested: f64,
    achieved: f64,
    evaluations: u64,
    time: f64,
    value: f64,
    reference: f64,
}

fn out_dir() -> Result<PathBuf, Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [] => Ok(PathBuf::from(".")),
        [flag, dir] if flag == "--out" => Ok(PathBuf::from(dir)),
        _ => Err("usage: accuracy_vs_time [--out <dir>]".into()),
    }
}

/// Median wall-clock time (s) of one call of `f`.
fn median_time<R>(mut f: impl FnMut() -> R) -> f64 {
    let start = Instant::now();
    black_box(f());
    let once = start.elapsed().max(Duration::from_nanos(1));
    let reps = (MIN_BATCH.as_secs_f64() / once.as_secs_f64())
        .ceil()
        .max(1.0) as u32;
    let mut batches: Vec<f64> = (0..BATCHES)
        .map(|_| {
            let start = Instant::now();
            for _ in 0..reps {
                black_box(f());
            }
            start.elapsed().as_secs_f64() / f64::from(reps)
        })
        .collect();
    batches.sort_by(f64::total_cmp);
    batches[BATCHES / 2]
}

fn relative_error(value: f64, reference: f64) -> f64 {
    ((value - reference) / reference).abs()
}

/// Seed 000 eq. (5.44), written out: `17·2¹⁹Λ⁵/(3⁴π⁸)`.
fn case_1_closed_form(lambda: f64) -> f64 {
    17.0 * 2f64.powi(19) * lambda.powi(5) / (81.0 * std::f64::consts::PI.powi(8))
}

/// The JKR load-controlled loss from the antiderivative: `(6/5)(4/3)^(4/3) − 4/5`.
fn jkr_load_controlled_closed_form() -> f64 {
    1.2 * (4.0f64 / 3.0).powf(4.0 / 3.0) - 0.8
}

fn main() -> Result<(), Box<dyn Error>> {
    let dir = out_dir()?;
    std::fs::create_dir_all(&dir)?;
    let mut rows = Vec::new();

    // Maugis-Dugdale direct evaluation.
    for (group, (lambda, ratio)) in MD_REFERENCE.into_iter().enumerate() {
        let reference = if group == 0 {
            case_1_closed_form(lambda)
        } else {
            ratio * W_JKR
        };
        for tol in TOLERANCES {
            let w = normalized_loss(lambda, tol)?;
            rows.push(Row {
                group,
                label: format!("{tol:.0e}"),
                requested: tol,
                achieved: relative_error(w.loss, reference),
                evaluations: w.cost.evaluations,
                time: median_time(|| normalized_loss(black_box(lambda), tol)),
                value: w.loss,
                reference,
            });
        }
    }

    // The fast tier.
    let build = Instant::now();
    let build_cost = prepare_fast_tier()?;
    let build_time = build.elapsed();
    for (lambda, reference) in MD_REFERENCE {
        let fast = loss_over_jkr_fast(lambda)?;
        rows.push(Row {
            group: 4,
            label: format!("lambda={lambda}"),
            requested: FAST_TIER_RELATIVE_ERROR,
            achieved: relative_error(fast, reference),
            evaluations: 0,
            time: median_time(|| loss_over_jkr_fast(black_box(lambda))),
            value: fast,
            reference,
        });
    }

    // JKR load-controlled loss.
    let reference = jkr_load_controlled_closed_form();
    for tol in TOLERANCES {
        let w = normalized::energy_loss(SeparationRule::LoadControlled, tol)?;
        rows.push(Row {
            group: 5,
            label: format!("{tol:.0e}"),
            requested: tol,
            achieved: relative_error(w.value, reference),
            evaluations: w.cost.evaluations,
            time: median_time(|| {
                normalized::energy_loss(black_box(SeparationRule::LoadControlled), tol)
            }),
            value: w.value,
            reference,
        });
    }

    // Time-domain impacts: two silica spheres of radius 1 µm.
    let (e, nu, r1, rho, dg): (f64, f64, f64, f64, f64) = (54e9, 0.17, 1e-6, 2650.0, 0.05);
    let e_star = e / (2.0 * (1.0 - nu * nu));
    let r = r1 / 2.0;
    let m = 4.0 / 3.0 * std::f64::consts::PI * r1.powi(3) * rho / 2.0;
    let sphere = JkrSphere::new(e_star, r, dg)?;
    let jkr = JkrImpact::new(sphere, m)?;
    let v0 = 2.0 * sticking_velocity(&jkr, 1e-15)?.speed;
    let reference = impact(&jkr, v0)?.restitution;
    for tol in TOLERANCES {
        let settings = SimulationSettings {
            record_trajectory: false,
            ..SimulationSettings::with_tolerance(tol)?
        };
        let run = || {
            simulate_impact(
                &mut JkrForceLaw::new(sphere, SeparationRule::FixedGrip),
                m,
                v0,
                &settings,
            )
        };
        let sim = run()?;
        rows.push(Row {
            group: 6,
            label: format!("{tol:.0e}"),
            requested: tol,
            achieved: relative_error(sim.restitution, reference),
            evaluations: sim.cost.evaluations,
            time: median_time(run),
            value: sim.restitution,
            reference,
        });
    }
    let md = MaugisDugdaleImpact::new(MaugisContact::new(JkrSphere::new(e_star, r, dg)?, 1.0)?, m)?;
    let md_loss = normalized_loss(1.0, REFERENCE_TOLERANCE)?.loss * md.scales().energy;
    let reference = restitution_from_loss(md_loss, m, v0)?;
    for tol in TOLERANCES {
        let settings = SimulationSettings {
            record_trajectory: false,
            ..SimulationSettings::with_tolerance(tol)?
        };
        let run = || simulate_impact(&mut MaugisDugdaleForceLaw::new(&md)?, m, v0, &settings);
        let sim = run()?;
        rows.push(Row {
            group: 7,
            label: format!("{tol:.0e}"),
            requested: tol,
            achieved: relative_error(sim.restitution, reference),
            evaluations: sim.cost.evaluations,
            time: median_time(run),
            value: sim.restitution,
            reference,
        });
    }

    let csv_path = dir.join("accuracy_vs_time.csv");
    let mut csv = std::io::BufWriter::new(std::fs::File::create(&csv_path)?);
    writeln!(
        csv,
        "group,label,requested_tolerance,achieved_error,evaluations,time_s,value,reference"
    )?;
    for r in &rows {
        writeln!(
            csv,
            "{},{},{:.3e},{:.6e},{},{:.6e},{:.17e},{:.17e}",
            GROUP_KEYS[r.group],
            r.label,
            r.requested,
            r.achieved,
            r.evaluations,
            r.time,
            r.value,
            r.reference
        )?;
    }
    csv.flush()?;

    let svg_path = dir.join("accuracy_vs_time.svg");
    plot(&rows, &svg_path)?;

    println!(
        "fast tier built in {:.2} ms from {} direct-evaluation integrand evaluations",
        build_time.as_secs_f64() * 1e3,
        build_cost.evaluations
    );
    println!(
        "| row | requested | achieved | evaluations | time per evaluation | achieved ≤ requested |"
    );
    println!("|---|---|---|---|---|---|");
    let mut exceeded = 0;
    for r in &rows {
        let ok = r.achieved <= r.requested;
        exceeded += usize::from(!ok);
        println!(
            "| {} | {} | {:.1e} | {} | {} | {} |",
            GROUPS[r.group],
            if r.group == 4 {
                format!("Λ = {} (bound {:.0e})", &r.label[7..], r.requested)
            } else {
                r.label.clone()
            },
            r.achieved,
            r.evaluations,
            format_time(r.time),
            if ok { "yes" } else { "**NO**" }
        );
    }
    println!(
        "{exceeded} of {} rows with an achieved error above the requested tolerance",
        rows.len()
    );
    println!("wrote {} and {}", csv_path.display(), svg_path.display());
    Ok(())
}

fn format_time(seconds: f64) -> String {
    if seconds < 1e-6 {
        format!("{:.1} ns", seconds * 1e9)
    } else if seconds < 1e-3 {
        format!("{:.2} µs", seconds * 1e6)
    } else {
        format!("{:.2} ms", seconds * 1e3)
    }
}

fn plot(rows: &[Row], path: &std::path::Path) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1300, 700)).into_drawing_area();
    root.fill(&WHITE)?;
    let (charts, legend) = root.split_vertically(600);
    let (left, right) = charts.split_horizontally(600);
    let colors = [
        RGBColor(120, 120, 120),
        BLUE,
        RGBColor(0, 150, 0),
        RED,
        RGBColor(230, 140, 0),
        MAGENTA,
        BLACK,
        RGBColor(0, 170, 170),
    ];
    let err = |r: &Row| r.achieved.max(ERROR_FLOOR);
    let (t_min, t_max) = rows.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), r| {
        (lo.min(r.time), hi.max(r.time))
    });
    let t_lo = 10f64.powf(t_min.log10().floor());
    let t_hi = 10f64.powf(t_max.log10().ceil());
    let y_range = (ERROR_FLOOR / 3.0..1.0f64).log_scale();
    let label_formatter = |v: &f64| format!("{v:.0e}");

    // Left: achieved versus requested, with the diagonal.
    let mut chart = ChartBuilder::on(&left)
        .caption("achieved error vs requested tolerance", ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d((1e-15..1e-1f64).log_scale(), y_range.clone())?;
    chart
        .configure_mesh()
        .x_desc("requested relative tolerance")
        .y_desc("achieved relative error")
        .x_label_formatter(&label_formatter)
        .y_label_formatter(&label_formatter)
        .draw()?;
    chart.draw_series(DashedLineSeries::new(
        [(1e-15, 1e-15), (1e-1, 1e-1)],
        6,
        4,
        BLACK.stroke_width(1),
    ))?;
    for (g, color) in colors.iter().enumerate() {
        let points: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.group == g)
            .map(|r| (r.requested, err(r)))
            .collect();
        if g != 4 {
            chart.draw_series(LineSeries::new(points.clone(), color.stroke_width(2)))?;
        }
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 3, color.filled())))?;
    }
    chart.draw_series(std::iter::once(Text::new(
        "achieved = requested",
        (3e-5, 1e-6),
        ("sans-serif", 14),
    )))?;
    chart.draw_series(std::iter::once(Text::new(
        format!("an error of 0 is drawn at {ERROR_FLOOR:.0e}"),
        (1e-9, ERROR_FLOOR * 0.6),
        ("sans-serif", 13),
    )))?;

    // Right: achieved versus time.
    let mut chart = ChartBuilder::on(&right)
        .caption("achieved error vs time per evaluation", ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d((t_lo..t_hi).log_scale(), y_range)?;
    chart
        .configure_mesh()
        .x_desc("median time per evaluation (s)")
        .y_desc("achieved relative error")
        .x_label_formatter(&label_formatter)
        .y_label_formatter(&label_formatter)
        .draw()?;
    for (g, color) in colors.iter().enumerate() {
        let points: Vec<(f64, f64)> = rows
            .iter()
            .filter(|r| r.group == g)
            .map(|r| (r.time, err(r)))
            .collect();
        if g != 4 {
            // in tolerance order: a line from loose to tight
            chart.draw_series(LineSeries::new(points.clone(), color.stroke_width(2)))?;
        }
        chart.draw_series(points.iter().map(|&p| Circle::new(p, 3, color.filled())))?;
    }

    // The legend, below both charts, in two columns.
    for (g, (name, color)) in GROUPS.iter().zip(colors).enumerate() {
        let x = 90 + 620 * (g / 4) as i32;
        let y = 18 + 22 * (g % 4) as i32;
        legend.draw(&PathElement::new(
            vec![(x, y), (x + 24, y)],
            color.stroke_width(2),
        ))?;
        legend.draw(&Circle::new((x + 12, y), 3, color.filled()))?;
        legend.draw(&Text::new(
            name.to_string(),
            (x + 32, y - 8),
            ("sans-serif", 15),
        ))?;
    }
    root.present()?;
    Ok(())
}
