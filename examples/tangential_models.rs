//! The tangential restitution of Maw, Barber & Fawcett's (1976) elastic oblique
//! impact, a solid steel sphere on a steel flat (ν = 0.3, μ = 0.3, 1 m/s,
//! `examples/scenes/thornton_2011/steel_on_steel.toml`), against their
//! normalized angle Ψ = κ tan α/μ, for tabor's four tangential models: LAMMPS's
//! `mindlin` (the current stiffness 8G*a times the total displacement),
//! `mindlin_rescale` (the same, the displacement scaled by a/a_old as the contact
//! shrinks), `linear_history` (a constant spring, here k_t = κ · 2E* a_max, the
//! Mindlin ratio at the largest contact radius of the impact) and
//! `mindlin_deresiewicz` (Mindlin-Deresiewicz micro-slip, exact), beside MBF's
//! values read off their Fig. 5 (β → −0.21 as Ψ → 0, β = 0 at Ψ ≈ 0.85, a
//! maximum 0.46 near Ψ = 2.75, ±0.02) and their sliding line β = −1 + 7κ/Ψ,
//! exact for every Coulomb model where the contact slides throughout
//! (Ψ ≥ 7κ = 5.76).
//!
//! β = −c'/c is the tangential restitution of the contact point (−1 when
//! frictionless, positive when the contact point reverses).
//!
//! `cargo run --release --example tangential_models [-- --out <dir>]` writes
//! `tangential_models.csv` and `tangential_models.svg` into `<dir>` (default: `.`).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use plotters::prelude::*;
use std::error::Error;
use std::io::Write;
use std::path::PathBuf;
use tabor::scene::{Format, Scene};

const SPEED: f64 = 1.0;
const MU: f64 = 0.3;
const POINTS: usize = 48;
const PSI: (f64, f64) = (0.05, 12.0);
/// κ = 4G*/E* = 2(1 − ν)/(2 − ν) for one material, ν = 0.3.
const KAPPA: f64 = 2.0 * 0.7 / 1.7;

/// MBF (1976) Fig. 5, read to ±0.02 in β: (Ψ, β).
const MBF_FIGURE: [(f64, f64); 3] = [(0.05, -0.21), (0.85, 0.0), (2.75, 0.46)];

/// The four models: name in the legend and scene key.
const MODELS: [&str; 4] = [
    "mindlin",
    "mindlin_rescale",
    "linear_history",
    "mindlin_deresiewicz",
];

fn out_dir() -> Result<PathBuf, Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [] => Ok(PathBuf::from(".")),
        [flag, dir] if flag == "--out" => Ok(PathBuf::from(dir)),
        _ => Err("usage: tangential_models [--out <dir>]".into()),
    }
}

/// The steel scene with tangential model `model` (`linear_history` with
/// k_t = κ · 2E* a_max, a_max = √(R δ_max) of Hertz's impact at 1 m/s).
fn scene(model: &str) -> Result<Scene, Box<dyn Error>> {
    let path = PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples/scenes/thornton_2011/steel_on_steel.toml");
    let text = std::fs::read_to_string(path)?;
    let key = "tangential = \"mindlin_deresiewicz\"";
    let plain = Scene::from_str(&text, Format::Toml)?;
    let replacement = if model == "linear_history" {
        let (m, e, r) = (
            plain.effective_mass,
            plain.effective_modulus,
            plain.effective_radius,
        );
        let d_max = (15.0 * m * SPEED * SPEED / (16.0 * e * r.sqrt())).powf(0.4);
        let k_t = KAPPA * 2.0 * e * (r * d_max).sqrt();
        format!("tangential = \"linear_history\"\ntangential_stiffness = {k_t}")
    } else {
        format!("tangential = \"{model}\"")
    };
    Ok(Scene::from_str(
        &text.replace(key, &replacement),
        Format::Toml,
    )?)
}

fn main() -> Result<(), Box<dyn Error>> {
    let dir = out_dir()?;
    std::fs::create_dir_all(&dir)?;
    let psis: Vec<f64> = (0..POINTS)
        .map(|i| PSI.0 * (PSI.1 / PSI.0).powf(i as f64 / (POINTS - 1) as f64))
        .collect();
    let mut csv = std::fs::File::create(dir.join("tangential_models.csv"))?;
    writeln!(
        csv,
        "model,psi,angle_deg,tangential_restitution,micro_slip_fraction,tangential_spring_fraction,energy_error"
    )?;
    let mut curves: Vec<(&str, Vec<(f64, f64)>)> = Vec::new();
    for model in MODELS {
        let scene = scene(model)?;
        let mut curve = Vec::new();
        for &psi in &psis {
            let angle = (psi * MU / KAPPA).atan().to_degrees();
            let o = scene.oblique(SPEED, angle)?;
            let beta = o
                .tangential_restitution
                .ok_or("no tangential restitution")?;
            writeln!(
                csv,
                "{model},{psi},{angle},{beta},{},{},{}",
                o.losses.micro_slip / o.kinetic_energy,
                o.losses.tangential_spring / o.kinetic_energy,
                o.energy_error
            )?;
            curve.push((psi, beta));
        }
        println!(
            "{model:<20} beta({:.2}) = {:+.4}, max {:+.4}",
            PSI.0,
            curve[0].1,
            curve.iter().map(|p| p.1).fold(f64::NEG_INFINITY, f64::max)
        );
        curves.push((model, curve));
    }

    let path = dir.join("tangential_models.svg");
    let root = SVGBackend::new(&path, (900, 580)).into_drawing_area();
    root.fill(&WHITE)?;
    let mut chart = ChartBuilder::on(&root)
        .caption(
            "Elastic oblique impact, steel on steel (ν = 0.3, μ = 0.3): four tangential models",
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
    let colors = [BLUE, RGBColor(230, 120, 0), RGBColor(150, 0, 150), RED];
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
    let line: Vec<(f64, f64)> = (0..200)
        .map(|i| PSI.0 * (PSI.1 / PSI.0).powf(i as f64 / 199.0))
        .filter(|psi| *psi >= 2.0 * KAPPA)
        .map(|psi| (psi, -1.0 + 7.0 * KAPPA / psi))
        .collect();
    chart
        .draw_series(LineSeries::new(line, BLACK.stroke_width(1)))?
        .label("MBF sliding line β = −1 + 7κ/Ψ (exact where sliding throughout)")
        .legend(|(x, y)| PathElement::new(vec![(x, y), (x + 20, y)], BLACK));
    chart.draw_series(MBF_FIGURE.iter().map(|&(psi, beta)| {
        PathElement::new(
            vec![(psi, beta - 0.02), (psi, beta + 0.02)],
            BLACK.stroke_width(2),
        )
    }))?;
    chart
        .draw_series(
            MBF_FIGURE
                .iter()
                .map(|&p| Circle::new(p, 4, BLACK.filled())),
        )?
        .label("MBF (1976) Fig. 5, read (±0.02)")
        .legend(|(x, y)| Circle::new((x + 10, y), 4, BLACK.filled()));
    chart
        .configure_series_labels()
        .background_style(WHITE.mix(0.9))
        .border_style(BLACK)
        .position(SeriesLabelPosition::LowerRight)
        .draw()?;
    root.present()?;
    println!("wrote {} and tangential_models.csv", path.display());
    Ok(())
}
