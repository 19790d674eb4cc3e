//! A simulated adhesive impact in the time domain: two silica spheres (R = 1 µm,
//! work of adhesion 0.05 J/m²) at twice their sticking velocity, with the JKR law
//! (fixed grip) and the Maugis-Dugdale law at Λ = 1. Plots d(t) and F(d); the
//! hysteresis loop of F(d) encloses the energy lost.
//!
//! `cargo run --release --example trajectory [-- --out <dir>]` writes
//! `trajectory.csv` and `trajectory.svg` into `<dir>` (default: `.`).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use plotters::prelude::*;
use std::error::Error;
use std::io::Write;
use std::path::PathBuf;
use tabor::dynamics::{simulate_impact, ImpactSimulation, SimulationSettings};
use tabor::jkr::{JkrForceLaw, JkrImpact, JkrSphere, SeparationRule};
use tabor::maugis::{MaugisContact, MaugisDugdaleForceLaw, MaugisDugdaleImpact};
use tabor::restitution::{impact, sticking_velocity};

fn out_dir() -> Result<PathBuf, Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [] => Ok(PathBuf::from(".")),
        [flag, dir] if flag == "--out" => Ok(PathBuf::from(dir)),
        _ => Err("usage: trajectory [--out <dir>]".into()),
    }
}

fn main() -> Result<(), Box<dyn Error>> {
    let dir = out_dir()?;
    std::fs::create_dir_all(&dir)?;
    // two silica spheres: E* = E/(2(1−ν²)), R = R1/2, m = m1/2
    let (e, nu, r1, rho, w): (f64, f64, f64, f64, f64) = (54e9, 0.17, 1e-6, 2650.0, 0.05);
    let e_star = e / (2.0 * (1.0 - nu * nu));
    let r = r1 / 2.0;
    let m = 4.0 / 3.0 * std::f64::consts::PI * r1.powi(3) * rho / 2.0;
    let sphere = JkrSphere::new(e_star, r, w)?;
    let jkr = JkrImpact::new(sphere, m)?;
    let md = MaugisDugdaleImpact::new(MaugisContact::new(JkrSphere::new(e_star, r, w)?, 1.0)?, m)?;
    let v0 = 2.0 * sticking_velocity(&jkr, 1e-12)?.speed;
    let settings = SimulationSettings::default();

    let jkr_sim = simulate_impact(
        &mut JkrForceLaw::new(sphere, SeparationRule::FixedGrip),
        m,
        v0,
        &settings,
    )?;
    let md_sim = simulate_impact(&mut MaugisDugdaleForceLaw::new(&md)?, m, v0, &settings)?;
    let runs: [(&str, &ImpactSimulation, f64); 2] = [
        ("JKR (fixed grip)", &jkr_sim, impact(&jkr, v0)?.restitution),
        (
            "Maugis-Dugdale, Λ = 1",
            &md_sim,
            impact(&md, v0)?.restitution,
        ),
    ];

    let csv_path = dir.join("trajectory.csv");
    let mut csv = std::io::BufWriter::new(std::fs::File::create(&csv_path)?);
    writeln!(
        csv,
        "law,time_s,overlap_m,overlap_rate_m_per_s,force_n,contact_radius_m"
    )?;
    for (name, sim, _) in &runs {
        for p in &sim.trajectory {
            writeln!(
                csv,
                "{name},{:.12e},{:.12e},{:.12e},{:.12e},{:.12e}",
                p.time, p.overlap, p.overlap_rate, p.force, p.contact_radius
            )?;
        }
    }
    csv.flush()?;

    let svg_path = dir.join("trajectory.svg");
    plot(&runs, &svg_path)?;
    println!("impact speed v0 = {v0:.6e} m/s (twice the JKR sticking velocity)");
    for (name, sim, analytic) in &runs {
        println!(
            "{name:<24} simulated ε = {:.9}, analytic ε = {analytic:.9}, contact time {:.4e} s, energy bookkeeping error {:.1e}",
            sim.restitution,
            sim.contact_time.unwrap_or(f64::NAN),
            sim.energy_error
        );
    }
    println!("wrote {} and {}", csv_path.display(), svg_path.display());
    Ok(())
}

fn plot(
    runs: &[(&str, &ImpactSimulation, f64)],
    path: &std::path::Path,
) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1200, 500)).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = root.split_horizontally(600);
    let nm = 1e9;
    let ns = 1e9;
    let un = 1e6;
    let all = || runs.iter().flat_map(|(_, s, _)| s.trajectory.iter());
    let (t_max, d_min, d_max) = all().fold(
        (0.0f64, f64::INFINITY, f64::NEG_INFINITY),
        |(t, lo, hi), p| {
            (
                t.max(p.time * ns),
                lo.min(p.overlap * nm),
                hi.max(p.overlap * nm),
            )
        },
    );
    let (f_min, f_max) = all().fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
        (lo.min(p.force * un), hi.max(p.force * un))
    });
    let pad = |lo: f64, hi: f64| (lo - 0.05 * (hi - lo), hi + 0.05 * (hi - lo));
    let (d_lo, d_hi) = pad(d_min, d_max);
    let (f_lo, f_hi) = pad(f_min, f_max);
    let colors = [BLUE, RED];

    let mut chart = ChartBuilder::on(&left)
        .caption("overlap d(t)", ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(55)
        .build_cartesian_2d(0.0..t_max * 1.02, d_lo..d_hi)?;
    chart
        .configure_mesh()
        .x_desc("time (ns)")
        .y_desc("overlap d (nm)")
        .draw()?;
    for ((name, sim, _), color) in runs.iter().zip(colors) {
        chart
            .draw_series(LineSeries::new(
                sim.trajectory.iter().map(|p| (p.time * ns, p.overlap * nm)),
                color.stroke_width(2),
            ))?
            .label(*name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;

    let mut chart = ChartBuilder::on(&right)
        .caption("force F(d): the loop encloses the loss", ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(55)
        .build_cartesian_2d(d_lo..d_hi, f_lo..f_hi)?;
    chart
        .configure_mesh()
        .x_desc("overlap d (nm)")
        .y_desc("force F (µN)")
        .draw()?;
    for ((name, sim, _), color) in runs.iter().zip(colors) {
        chart
            .draw_series(LineSeries::new(
                sim.trajectory
                    .iter()
                    .map(|p| (p.overlap * nm, p.force * un)),
                color.stroke_width(2),
            ))?
            .label(*name)
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperLeft)
        .background_style(WHITE.mix(0.8))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}
