//! The tangential restitution of an oblique impact against Maw, Barber & Fawcett's
//! normalized angle, for two silica microspheres (R = 1 µm, E = 54 GPa, ν = 0.17,
//! 1 m/s, μ = 0.3, LAMMPS's `mindlin` tangential model) with three normal models:
//! Hertz, JKR (w = 0.05 J/m², load-controlled as LAMMPS's `jkr`) and
//! Maugis-Dugdale at Λ = 0.5 (same w), beside MBF's sliding line and the points
//! LAMMPS's own `pair_style granular` gives for Hertz and JKR
//! (`docs/figures/oblique_impact_lammps.csv`, written by
//! `integrations/lammps/test_oblique.py --figure-points`).
//!
//! β = −c'/c is the tangential restitution of the contact point (−1 when
//! frictionless, positive when the contact point reverses), Ψ = κ tan α / μ with
//! κ = 4G*/E* (MBF 1976, Thornton's normalization). Where the spheres slide
//! throughout (Ψ ≥ 7κ for elastic spheres) every Coulomb model is on MBF's line
//! β = −1 + (1 + e_n)(1 + 1/K) μ/tan α, K = 2/5; below it MBF resolve micro-slip,
//! which LAMMPS's `mindlin` does not have (see `crates/tabor-tangential/README.md`).
//!
//! `cargo run --release --example oblique_impact [-- --out <dir>]` writes
//! `oblique_impact.csv` and `oblique_impact.svg` into `<dir>` (default: `.`).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use plotters::prelude::*;
use std::error::Error;
use std::io::Write;
use std::path::PathBuf;
use tabor::scene::{Format, Scene};
use tabor::tangential::EffectiveShear;

const SPEED: f64 = 1.0;
const MU: f64 = 0.3;
const POINTS: usize = 40;
const PSI: (f64, f64) = (0.05, 10.0);

const BASE: &str = r#"
[sphere]
radius = 1e-6
density = 2650
youngs_modulus = 54e9
poisson_ratio = 0.17
[target]
radius = 1e-6
density = 2650
youngs_modulus = 54e9
poisson_ratio = 0.17
[friction]
coefficient = 0.3
"#;

/// The three normal models: name and `[adhesion]` section.
const MODELS: [(&str, &str); 3] = [
    ("Hertz", ""),
    (
        "JKR",
        "[adhesion]\nwork_of_adhesion = 0.05\nseparation = \"load-controlled\"\n",
    ),
    (
        "Maugis-Dugdale (Λ = 0.5)",
        "[adhesion]\nwork_of_adhesion = 0.05\ntabor_parameter = 0.5\n",
    ),
];

fn out_dir() -> Result<PathBuf, Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [] => Ok(PathBuf::from(".")),
        [flag, dir] if flag == "--out" => Ok(PathBuf::from(dir)),
        _ => Err("usage: oblique_impact [--out <dir>]".into()),
    }
}

/// κ = 4G*/E* of the silica pair.
fn kappa() -> Result<f64, Box<dyn Error>> {
    let g = EffectiveShear::of_pair(54e9, 0.17, 54e9, 0.17)?.modulus();
    let e_star = 54e9 / (2.0 * (1.0 - 0.17 * 0.17));
    Ok(4.0 * g / e_star)
}

/// LAMMPS's points (model, Ψ, β), when the CSV is there.
fn lammps_points() -> Vec<(String, f64, f64)> {
    let path =
        PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("docs/figures/oblique_impact_lammps.csv");
    let Ok(text) = std::fs::read_to_string(path) else {
        return Vec::new();
    };
    text.lines()
        .skip(1)
        .filter_map(|l| {
            let f: Vec<&str> = l.split(',').collect();
            Some((
                f.first()?.to_string(),
                f.get(1)?.parse().ok()?,
                f.get(2)?.parse().ok()?,
            ))
        })
        .collect()
}

fn main() -> Result<(), Box<dyn Error>> {
    let dir = out_dir()?;
    std::fs::create_dir_all(&dir)?;
    let kappa = kappa()?;
    let psis: Vec<f64> = (0..POINTS)
        .map(|i| PSI.0 * (PSI.1 / PSI.0).powf(i as f64 / (POINTS - 1) as f64))
        .collect();
    let mut csv = std::fs::File::create(dir.join("oblique_impact.csv"))?;
    writeln!(
        csv,
        "model,psi,angle_deg,tangential_restitution,normal_restitution,rebound_angle_deg,sphere_spin_z_rad_per_s,energy_error"
    )?;
    let mut curves: Vec<(&str, Vec<(f64, f64)>)> = Vec::new();
    for (name, adhesion) in MODELS {
        let scene = Scene::from_str(&format!("{BASE}{adhesion}"), Format::Toml)?;
        let mut curve = Vec::new();
        for &psi in &psis {
            let angle = (psi * MU / kappa).atan().to_degrees();
            let o = scene.oblique(SPEED, angle)?;
            let Some(beta) = o.tangential_restitution.filter(|_| !o.sticks) else {
                continue;
            };
            writeln!(
                csv,
                "{name},{psi},{angle},{beta},{},{},{},{}",
                o.normal_restitution,
                o.rebound_angle.unwrap_or(f64::NAN),
                o.after.sphere.angular_velocity[2],
                o.energy_error
            )?;
            curve.push((psi, beta));
        }
        println!(
            "{name:<26} beta from {:+.4} (Psi = {:.2}) to {:+.4} (Psi = {:.2}), max {:+.4}",
            curve.first().map_or(f64::NAN, |p| p.1),
            curve.first().map_or(f64::NAN, |p| p.0),
            curve.last().map_or(f64::NAN, |p| p.1),
            curve.last().map_or(f64::NAN, |p| p.0),
            curve.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max)
        );
        curves.push((name, curve));
    }

    let path = dir.join("oblique_impact.svg");
    let root = SVGBackend::new(&path, (900, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Oblique impact of two silica microspheres (1 m/s, μ = 0.3, LAMMPS mindlin)",
            ("sans-serif", 18),
        )
        .margin(15)
        .x_label_area_size(45)
        .y_label_area_size(60)
        .build_cartesian_2d((PSI.0..PSI.1).log_scale(), -1.1f64..0.8)?;
    chart
        .configure_mesh()
        .x_desc("normalized angle Ψ = κ tan α / μ  (Maw, Barber & Fawcett)")
        .y_desc("tangential restitution β of the contact point")
        .draw()?;
    let colors = [BLUE, RED, RGBColor(0, 140, 0)];
    for ((name, curve), color) in curves.iter().zip(colors) {
        chart
            .draw_series(LineSeries::new(
                curve.iter().copied(),
                color.stroke_width(2),
            ))?
            .label(format!("tabor: {name}"))
            .legend(move |(x, y)| {
                PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
            });
    }
    // MBF's sliding line, exact where the spheres slide throughout (e_n = 1 for Hertz)
    let line: Vec<(f64, f64)> = (0..200)
        .map(|i| PSI.0 * (PSI.1 / PSI.0).powf(i as f64 / 199.0))
        .filter(|psi| *psi >= 2.0 * kappa)
        .map(|psi| (psi, -1.0 + 7.0 * kappa / psi))
        .collect();
    chart
        .draw_series(LineSeries::new(line, BLACK.stroke_width(1)))?
        .label("MBF sliding line β = −1 + 7κ/Ψ (exact where sliding throughout)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK));
    let points = lammps_points();
    for (model, color) in [("Hertz", BLUE), ("JKR", RED)] {
        let pts: Vec<(f64, f64)> = points
            .iter()
            .filter(|p| p.0 == model)
            .map(|p| (p.1, p.2))
            .collect();
        if pts.is_empty() {
            continue;
        }
        chart
            .draw_series(
                pts.into_iter()
                    .map(|p| Circle::new(p, 5, color.stroke_width(2))),
            )?
            .label(format!("LAMMPS pair granular: {model}"))
            .legend(move |(x, y)| Circle::new((x + 10, y), 5, color.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .position(SeriesLabelPosition::LowerLeft)
        .draw()?;
    root.present()?;
    println!("wrote {} and oblique_impact.csv", path.display());
    Ok(())
}
