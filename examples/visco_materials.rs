//! Rubber and potato (seed 000, Table 5.1) as scaled viscoelastic impacts: for each
//! material the viscous parameter δ (5.68) is chosen so that the Kuwabara-Kono and
//! the rigorous Kelvin-Voigt sphere models reproduce the measured restitution; the
//! scaled trajectories (5.74) are then rescaled with the table's v0, d0 and m.
//!
//! Writes `visco_materials.csv` (material, model, δ, t, d, F) and
//! `visco_materials.svg` (d(t) and F(t)) into `--out <dir>` (default `.`).
//!
//!     cargo run --release --example visco_materials -- --out target
#![allow(clippy::unwrap_used, clippy::expect_used)]

use plotters::prelude::*;
use std::error::Error;
use std::fmt::Write as _;
use std::path::PathBuf;
use tabor::visco::kelvin_voigt_sphere::{trajectory, viscous_parameter_for_restitution};
use tabor::visco::SphereModel;

/// A row of Table 5.1: restitution, v0 (m/s), d0 (m), m (kg).
struct Material {
    name: &'static str,
    restitution: f64,
    speed: f64,
    overlap_scale: f64,
    mass: f64,
}

const MATERIALS: [Material; 2] = [
    Material {
        name: "rubber",
        restitution: 0.71,
        speed: 0.2,
        overlap_scale: 1.06e-3,
        mass: 0.279,
    },
    Material {
        name: "potato",
        restitution: 0.56,
        speed: 0.4,
        overlap_scale: 1.51e-3,
        mass: 0.320,
    },
];

/// One curve in SI units: (t [s], d [m], F [N]).
struct Curve {
    label: String,
    points: Vec<(f64, f64, f64)>,
}

fn out_dir() -> Result<PathBuf, String> {
    let mut args = std::env::args().skip(1);
    let mut dir = PathBuf::from(".");
    while let Some(a) = args.next() {
        match a.as_str() {
            "--out" => {
                dir = PathBuf::from(args.next().ok_or("--out needs a directory")?);
            }
            other => return Err(format!("unknown argument {other} (usage: --out <dir>)")),
        }
    }
    Ok(dir)
}

fn main() -> Result<(), Box<dyn Error>> {
    let dir = out_dir()?;
    std::fs::create_dir_all(&dir)?;
    let mut csv = String::from("material,model,viscous_parameter,time_s,overlap_m,force_n\n");
    let mut curves = Vec::new();
    for mat in &MATERIALS {
        for model in [SphereModel::KuwabaraKono, SphereModel::Rigorous] {
            let delta = viscous_parameter_for_restitution(mat.restitution, model, 1e-10)?;
            let scaled = trajectory(delta, model, 1e-10)?;
            let (t0, f0) = (
                mat.overlap_scale / mat.speed,
                mat.mass * mat.speed * mat.speed / mat.overlap_scale,
            );
            let points: Vec<(f64, f64, f64)> = scaled
                .iter()
                .map(|p| (p.time * t0, p.overlap * mat.overlap_scale, p.force * f0))
                .collect();
            for &(t, d, f) in &points {
                writeln!(
                    csv,
                    "{},{},{delta:.6},{t:.6e},{d:.6e},{f:.6e}",
                    mat.name,
                    model.as_str()
                )?;
            }
            let last = scaled.last().map_or(0.0, |p| -p.overlap_rate);
            println!(
                "{:7} {:14} delta = {delta:.5}, restitution {last:.4}, contact time {:.3} ms",
                mat.name,
                model.as_str(),
                points.last().map_or(0.0, |p| p.0) * 1e3
            );
            curves.push(Curve {
                label: format!("{} ({})", mat.name, model.as_str()),
                points,
            });
        }
    }
    let csv_path = dir.join("visco_materials.csv");
    std::fs::write(&csv_path, csv)?;
    let svg_path = dir.join("visco_materials.svg");
    plot(&svg_path, &curves)?;
    println!("wrote {} and {}", csv_path.display(), svg_path.display());
    Ok(())
}

fn plot(path: &std::path::Path, curves: &[Curve]) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (900, 900)).into_drawing_area();
    root.fill(&WHITE)?;
    let panels = root.split_evenly((2, 1));
    let t_max = curves
        .iter()
        .flat_map(|c| c.points.iter().map(|p| p.0))
        .fold(0.0, f64::max)
        * 1e3;
    let d_max = curves
        .iter()
        .flat_map(|c| c.points.iter().map(|p| p.1))
        .fold(0.0, f64::max)
        * 1e3;
    let f_max = curves
        .iter()
        .flat_map(|c| c.points.iter().map(|p| p.2))
        .fold(0.0, f64::max);
    let colors = [RED, BLUE, GREEN, MAGENTA];
    type Pick = fn(&(f64, f64, f64)) -> f64;
    let specs: [(&str, f64, Pick); 2] = [
        ("indentation d [mm]", d_max, |p| p.1 * 1e3),
        ("normal force F [N]", f_max, |p| p.2),
    ];
    for (panel, (label, y_max, pick)) in panels.iter().zip(specs) {
        let mut chart = ChartBuilder::on(panel)
            .caption(
                format!("Table 5.1 cases: {label} vs time"),
                ("sans-serif", 18),
            )
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(60)
            .build_cartesian_2d(0.0..t_max * 1.02, 0.0..y_max * 1.1)?;
        chart
            .configure_mesh()
            .x_desc("time t [ms]")
            .y_desc(label)
            .draw()?;
        for (curve, color) in curves.iter().zip(colors) {
            chart
                .draw_series(LineSeries::new(
                    curve.points.iter().map(|p| (p.0 * 1e3, pick(p))),
                    color.stroke_width(2),
                ))?
                .label(curve.label.clone())
                .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], color));
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.8))
            .border_style(BLACK)
            .draw()?;
    }
    root.present()?;
    Ok(())
}
