//! The sticking velocity of two identical spheres versus their radius, from 1 nm to
//! 1 mm, for silica (E = 54 GPa, ν = 0.17, ρ = 2650 kg/m³, Δγ = 0.05 J/m²) and water
//! ice (E = 7 GPa, ν = 0.25, ρ = 1000 kg/m³, Δγ = 0.38 J/m²), with three adhesion
//! models: JKR with the fixed-grip separation of seed 000 (closed form (5.38)), JKR
//! with the load-controlled separation of DEM codes, and Maugis-Dugdale with a fixed
//! range of adhesion h = 0.3 nm, so that the Tabor parameter Λ = d_n/h grows with the
//! radius as R^(1/3) (seed 000 eqs. (5.38), (5.43)-(5.46); the Λ dependence is that
//! of Fig. 5.2, here turned into a size dependence).
//!
//! `cargo run --release --example sticking_velocity [-- --out <dir>]` writes
//! `sticking_velocity.csv` and `sticking_velocity.svg` into `<dir>` (default: `.`).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use plotters::prelude::*;
use std::error::Error;
use std::io::Write;
use std::path::PathBuf;
use tabor::jkr::{JkrImpact, JkrSphere, SeparationRule};
use tabor::maugis::units::tabor_parameter_from_range;
use tabor::maugis::{MaugisContact, MaugisDugdaleImpact, LAMBDA_1};
use tabor::restitution::{sticking_velocity, ImpactModel};

/// Number of log-spaced particle radii from 1 nm to 1 mm.
const POINTS: usize = 61;
/// Smallest and largest particle radius (m).
const RADII: (f64, f64) = (1e-9, 1e-3);
/// The range of adhesion of the Maugis-Dugdale curves (m).
const RANGE: f64 = 0.3e-9;
/// Relative tolerance of the losses and sticking velocities.
const TOLERANCE: f64 = 1e-12;

/// A material of both spheres.
struct Material {
    name: &'static str,
    youngs_modulus: f64,
    poisson_ratio: f64,
    density: f64,
    work_of_adhesion: f64,
}

const MATERIALS: [Material; 2] = [
    Material {
        name: "silica",
        youngs_modulus: 54e9,
        poisson_ratio: 0.17,
        density: 2650.0,
        work_of_adhesion: 0.05,
    },
    Material {
        name: "ice",
        youngs_modulus: 7e9,
        poisson_ratio: 0.25,
        density: 1000.0,
        work_of_adhesion: 0.38,
    },
];

const MODELS: [&str; 3] = ["JKR fixed grip", "JKR load-controlled", "Maugis-Dugdale"];

struct Row {
    radius: f64,
    material: &'static str,
    model: &'static str,
    sticking_velocity: f64,
    tabor_parameter: f64,
}

fn out_dir() -> Result<PathBuf, Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [] => Ok(PathBuf::from(".")),
        [flag, dir] if flag == "--out" => Ok(PathBuf::from(dir)),
        _ => Err("usage: sticking_velocity [--out <dir>]".into()),
    }
}

/// The sticking velocities of two identical spheres of radius `r1` (m) of
/// `material`: (JKR fixed grip, JKR load-controlled, Maugis-Dugdale), and Λ.
fn sticking_velocities(material: &Material, r1: f64) -> Result<([f64; 3], f64), Box<dyn Error>> {
    // two identical spheres: E* = E/(2(1−ν²)), R = R1/2, m = m1/2
    let nu = material.poisson_ratio;
    let e_star = material.youngs_modulus / (2.0 * (1.0 - nu * nu));
    let r = r1 / 2.0;
    let m = 4.0 / 3.0 * std::f64::consts::PI * r1.powi(3) * material.density / 2.0;
    let dg = material.work_of_adhesion;
    let sphere = JkrSphere::new(e_star, r, dg)?;
    let fixed = JkrImpact::new(sphere, m)?;
    let load = fixed
        .clone()
        .with_separation(SeparationRule::LoadControlled);
    let md = MaugisDugdaleImpact::new(
        MaugisContact::from_range(JkrSphere::new(e_star, r, dg)?, RANGE)?,
        m,
    )?
    .with_tolerance(TOLERANCE)?;
    let models: [&dyn ImpactModel; 3] = [&fixed, &load, &md];
    let mut v = [0.0; 3];
    for (slot, model) in v.iter_mut().zip(models) {
        *slot = sticking_velocity(model, TOLERANCE)?.speed;
    }
    Ok((v, tabor_parameter_from_range(RANGE, dg, e_star, r)?))
}

fn main() -> Result<(), Box<dyn Error>> {
    let dir = out_dir()?;
    std::fs::create_dir_all(&dir)?;
    let mut rows = Vec::with_capacity(POINTS * 6);
    for material in &MATERIALS {
        for i in 0..POINTS {
            let f = i as f64 / (POINTS - 1) as f64;
            let r1 = RADII.0 * (RADII.1 / RADII.0).powf(f);
            let (v, lambda) = sticking_velocities(material, r1)?;
            for (model, speed) in MODELS.iter().zip(v) {
                rows.push(Row {
                    radius: r1,
                    material: material.name,
                    model,
                    sticking_velocity: speed,
                    tabor_parameter: lambda,
                });
            }
        }
    }

    let csv_path = dir.join("sticking_velocity.csv");
    let mut csv = std::io::BufWriter::new(std::fs::File::create(&csv_path)?);
    writeln!(
        csv,
        "radius,material,model,sticking_velocity,tabor_parameter"
    )?;
    for r in &rows {
        writeln!(
            csv,
            "{:.16e},{},{},{:.16e},{:.16e}",
            r.radius, r.material, r.model, r.sticking_velocity, r.tabor_parameter
        )?;
    }
    csv.flush()?;

    let svg_path = dir.join("sticking_velocity.svg");
    plot(&rows, &svg_path)?;

    println!(
        "sticking velocity (m/s) of two identical spheres; Maugis-Dugdale with h = {:.1} nm",
        RANGE * 1e9
    );
    println!(
        "{:<7} {:>9} {:>10} {:>12} {:>12} {:>12}",
        "", "radius", "Λ", "JKR fixed", "JKR load", "M-D"
    );
    for material in &MATERIALS {
        for r1 in [1e-9, 1e-8, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3] {
            let (v, lambda) = sticking_velocities(material, r1)?;
            println!(
                "{:<7} {r1:>9.0e} {lambda:>10.4} {:>12.4e} {:>12.4e} {:>12.4e}",
                material.name, v[0], v[1], v[2]
            );
        }
    }
    println!("wrote {} and {}", csv_path.display(), svg_path.display());
    Ok(())
}

fn plot(rows: &[Row], path: &std::path::Path) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1000, 650)).into_drawing_area();
    root.fill(&WHITE)?;
    let (v_min, v_max) = rows.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), r| {
        (lo.min(r.sticking_velocity), hi.max(r.sticking_velocity))
    });
    // a little room beyond the data, so that the end decades are labelled
    let y_lo = 10f64.powf(v_min.log10().floor()) * 0.8;
    let y_hi = 10f64.powf(v_max.log10().ceil()) * 1.25;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            format!(
                "sticking velocity of two identical spheres (Maugis-Dugdale: h = {:.1} nm)",
                RANGE * 1e9
            ),
            ("sans-serif", 20),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(70)
        .build_cartesian_2d(
            (RADII.0 * 0.8..RADII.1 * 1.25).log_scale(),
            (y_lo..y_hi).log_scale(),
        )?;
    chart
        .configure_mesh()
        .x_desc("particle radius R₁ (m)")
        .y_desc("sticking velocity v_c (m/s)")
        .x_label_formatter(&|x| format!("{x:.0e}"))
        .y_label_formatter(&|y| format!("{y:.0e}"))
        .draw()?;
    let colors = [BLUE, RED, RGBColor(0, 150, 0)];
    for (m_index, material) in MATERIALS.iter().enumerate() {
        for (model, color) in MODELS.iter().zip(colors) {
            let points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.material == material.name && r.model == *model)
                .map(|r| (r.radius, r.sticking_velocity))
                .collect();
            let label = format!("{}, {model}", material.name);
            let style = color.stroke_width(2);
            if m_index == 0 {
                chart
                    .draw_series(LineSeries::new(points, style))?
                    .label(label)
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
            } else {
                chart
                    .draw_series(DashedLineSeries::new(points, 8, 5, style))?
                    .label(label)
                    .legend(move |(x, y)| {
                        EmptyElement::at((x, y))
                            + PathElement::new(vec![(0, 0), (9, 0)], style)
                            + PathElement::new(vec![(15, 0), (24, 0)], style)
                    });
            }
        }
    }
    chart.draw_series(std::iter::once(Text::new(
        format!(
            "silica, Maugis-Dugdale: Λ < Λ1 = {LAMBDA_1:.3} (case 1, no contact): v_c independent of size"
        ),
        (1.3e-9, 2.1e-2),
        ("sans-serif", 14),
    )))?;
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    root.present()?;
    Ok(())
}
