//! Restitution versus impact speed of alumina spheres (R = 2.5 mm, m = 0.25 g) on a
//! steel and on an aluminium plate, the comparison cases of seed 000 section 5.5.2
//! (Table 5.2, Figs. 5.18-5.19) and seed 001 (Table 3), through every elasto-plastic
//! model of tabor: Thornton (5.101)-(5.106), the interpolation model (5.107),
//! Jackson-Green (simulated, (5.108)), seed 001's dimensionless fit (its eqs. (12),
//! (18), (19), with its own Table 3 constants), and the adhesive variants with a
//! work of adhesion Δγ = 0.5 J/m²: the superposition of the interpolation model and
//! JKR (5.109)-(5.110), and the adhesive interpolation model (5.111)-(5.126).
//!
//! At millimetre scale adhesion is weak: its sticking velocity is below 1 mm/s, so
//! the speed axis starts at 0.1 mm/s (instead of the seed's 0.01 m/s) to show it.
//!
//! `cargo run --release --example restitution_vs_speed [-- --out <dir>]` writes
//! `restitution_vs_speed.csv` and `restitution_vs_speed.svg` into `<dir>`
//! (default: `.`).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use plotters::prelude::*;
use std::error::Error;
use std::io::Write;
use std::path::PathBuf;
use tabor::jkr::JkrSphere;
use tabor::plastic::materials::{
    Material, ALUMINA_TABLE_3, ALUMINA_TABLE_5_2, ALUMINIUM_TABLE_3, ALUMINIUM_TABLE_5_2,
    SPHERE_MASS_SECTION_5_5_2, SPHERE_RADIUS_SECTION_5_5_2, STEEL_TABLE_3, STEEL_TABLE_5_2,
};
use tabor::plastic::{
    AdhesiveInterpolationImpact, AdhesivePlasticContact, DimensionlessFit, Interpolation,
    JacksonGreen, PlasticContact, PlasticImpact, SimulationSettings, Superposition, Thornton,
};
use tabor::restitution::{impact, sticking_velocity, ImpactModel};

/// Number of log-spaced impact speeds.
const POINTS: usize = 81;
/// Lowest and highest impact speed (m/s).
const SPEEDS: (f64, f64) = (1e-4, 10.0);
/// Work of adhesion of the adhesive variants (J/m²).
const WORK_OF_ADHESION: f64 = 0.5;

/// The model names, in plotting order.
const MODELS: [&str; 6] = [
    "Thornton",
    "interpolation",
    "Jackson-Green",
    "dimensionless FEM fit",
    "superposition (adhesive)",
    "adhesive interpolation",
];

/// One sphere/plate pair: the seed 000 Table 5.2 plate and its seed 001 Table 3
/// counterpart (for the fit).
struct Pair {
    name: &'static str,
    plate: Material,
    plate_table_3: Material,
}

const PAIRS: [Pair; 2] = [
    Pair {
        name: "steel",
        plate: STEEL_TABLE_5_2,
        plate_table_3: STEEL_TABLE_3,
    },
    Pair {
        name: "aluminium",
        plate: ALUMINIUM_TABLE_5_2,
        plate_table_3: ALUMINIUM_TABLE_3,
    },
];

struct Row {
    plate: &'static str,
    model: &'static str,
    speed: f64,
    restitution: f64,
}

/// The models of one pair, with the speeds that characterise it.
struct Models {
    list: Vec<Box<dyn ImpactModel>>,
    yield_velocity: f64,
    sticking_velocity: f64,
    adhesion_parameter: f64,
}

fn out_dir() -> Result<PathBuf, Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [] => Ok(PathBuf::from(".")),
        [flag, dir] if flag == "--out" => Ok(PathBuf::from(dir)),
        _ => Err("usage: restitution_vs_speed [--out <dir>]".into()),
    }
}

fn models(pair: &Pair) -> Result<Models, Box<dyn Error>> {
    let (r, m) = (SPHERE_RADIUS_SECTION_5_5_2, SPHERE_MASS_SECTION_5_5_2);
    let e_star = ALUMINA_TABLE_5_2.effective_modulus_with(&pair.plate)?;
    let sigma_y = pair
        .plate
        .yield_stress
        .ok_or("plate without yield stress")?;
    let contact = PlasticContact::new(e_star, r, sigma_y)?;
    let thornton = PlasticImpact::new(contact, Thornton, m)?;
    let interpolation = PlasticImpact::new(contact, Interpolation::default(), m)?;
    let settings = SimulationSettings {
        record_trajectory: false,
        ..SimulationSettings::default()
    };
    let jackson_green = PlasticContact::new(e_star, r, sigma_y)
        .and_then(|contact| JacksonGreen::new(contact, pair.plate.poisson_ratio))?
        .impact(m, settings)?;
    // Seed 001 with its own Table 3 constants (E*, σ_y, the sphere density).
    let fit = DimensionlessFit::new(
        ALUMINA_TABLE_3.effective_modulus_with(&pair.plate_table_3)?,
        pair.plate_table_3
            .yield_stress
            .ok_or("plate without yield stress")?,
        ALUMINA_TABLE_3.density.ok_or("sphere without density")?,
        m,
    )?;
    let sphere = JkrSphere::new(e_star, r, WORK_OF_ADHESION)?;
    let superposition = Superposition::new(interpolation.clone(), sphere)?;
    let adhesive = AdhesiveInterpolationImpact::new(
        AdhesivePlasticContact::from_yield_stress(
            JkrSphere::new(e_star, r, WORK_OF_ADHESION)?,
            sigma_y,
        )?,
        m,
    )?;
    let sticking = sticking_velocity(superposition.adhesive(), 1e-12)?.speed;
    let phi = adhesive.model().adhesion_parameter();
    Ok(Models {
        yield_velocity: thornton.yield_velocity(),
        sticking_velocity: sticking,
        adhesion_parameter: phi,
        list: vec![
            Box::new(thornton),
            Box::new(interpolation),
            Box::new(jackson_green),
            Box::new(fit),
            Box::new(superposition),
            Box::new(adhesive),
        ],
    })
}

fn main() -> Result<(), Box<dyn Error>> {
    let dir = out_dir()?;
    std::fs::create_dir_all(&dir)?;
    let speeds: Vec<f64> = (0..POINTS)
        .map(|i| SPEEDS.0 * (SPEEDS.1 / SPEEDS.0).powf(i as f64 / (POINTS - 1) as f64))
        .collect();
    let mut rows = Vec::new();
    let mut marks = Vec::new();
    for pair in &PAIRS {
        let set = models(pair)?;
        for (name, model) in MODELS.iter().zip(&set.list) {
            for &v in &speeds {
                rows.push(Row {
                    plate: pair.name,
                    model: name,
                    speed: v,
                    restitution: impact(model.as_ref(), v)?.restitution,
                });
            }
        }
        println!(
            "alumina on {}: v_Y = {:.4} m/s (Thornton), JKR sticking velocity {:.3e} m/s (Δγ = {WORK_OF_ADHESION} J/m²), Φ = {:.3}",
            pair.name, set.yield_velocity, set.sticking_velocity, set.adhesion_parameter
        );
        print!("{:>10}", "v0 (m/s)");
        for name in [
            "Thornton",
            "interp.",
            "Jackson-Green",
            "FEM fit",
            "superpos.",
            "adh. interp.",
        ] {
            print!(" {name:>13}");
        }
        println!();
        for v in [3e-4, 1e-3, 0.01, 0.1, 1.0, 3.0, 6.0] {
            print!("{v:>10}");
            for model in &set.list {
                print!(" {:>13.4}", impact(model.as_ref(), v)?.restitution);
            }
            println!();
        }
        marks.push((set.yield_velocity, set.sticking_velocity));
    }

    let csv_path = dir.join("restitution_vs_speed.csv");
    let mut csv = std::io::BufWriter::new(std::fs::File::create(&csv_path)?);
    writeln!(csv, "plate,model,impact_speed,restitution")?;
    for r in &rows {
        writeln!(
            csv,
            "{},{},{:.16e},{:.16e}",
            r.plate, r.model, r.speed, r.restitution
        )?;
    }
    csv.flush()?;

    let svg_path = dir.join("restitution_vs_speed.svg");
    plot(&rows, &marks, &svg_path)?;
    println!("wrote {} and {}", csv_path.display(), svg_path.display());
    Ok(())
}

fn plot(rows: &[Row], marks: &[(f64, f64)], path: &std::path::Path) -> Result<(), Box<dyn Error>> {
    let root = SVGBackend::new(path, (1300, 560)).into_drawing_area();
    root.fill(&WHITE)?;
    let (left, right) = root.split_horizontally(650);
    let colors = [
        BLUE,
        RED,
        RGBColor(0, 150, 0),
        RGBColor(230, 140, 0),
        MAGENTA,
        BLACK,
    ];
    for ((area, pair), &(v_y, v_c)) in [left, right].iter().zip(&PAIRS).zip(marks) {
        let mut chart = ChartBuilder::on(area)
            .caption(
                format!("alumina sphere (R = 2.5 mm) on {}", pair.name),
                ("sans-serif", 20),
            )
            .margin(12)
            .x_label_area_size(45)
            .y_label_area_size(50)
            .build_cartesian_2d((SPEEDS.0..SPEEDS.1).log_scale(), 0.0f64..1.05)?;
        chart
            .configure_mesh()
            .x_desc("impact speed v0 (m/s)")
            .y_desc("coefficient of restitution ε")
            .x_label_formatter(&|x| format!("{x:.0e}"))
            .draw()?;
        for (i, (model, color)) in MODELS.iter().zip(colors).enumerate() {
            let style = color.stroke_width(2);
            let points: Vec<(f64, f64)> = rows
                .iter()
                .filter(|r| r.plate == pair.name && r.model == *model)
                .map(|r| (r.speed, r.restitution))
                .collect();
            // the adhesive variants dashed: above the yield onset the superposition
            // lies on the interpolation model
            if i < 4 {
                chart
                    .draw_series(LineSeries::new(points, style))?
                    .label(*model)
                    .legend(move |(x, y)| PathElement::new(vec![(x, y), (x + 24, y)], style));
            } else {
                chart
                    .draw_series(DashedLineSeries::new(points, 7, 5, style))?
                    .label(*model)
                    .legend(move |(x, y)| {
                        EmptyElement::at((x, y))
                            + PathElement::new(vec![(0, 0), (9, 0)], style)
                            + PathElement::new(vec![(15, 0), (24, 0)], style)
                    });
            }
        }
        let grey = RGBColor(120, 120, 120);
        for (v, text) in [(v_y, "v_Y"), (v_c, "v_c (JKR)")] {
            chart.draw_series(DashedLineSeries::new(
                [(v, 0.0), (v, 1.05)],
                5,
                4,
                grey.stroke_width(1),
            ))?;
            chart.draw_series(std::iter::once(Text::new(
                text,
                (v * 1.15, 0.3),
                ("sans-serif", 14).into_font().color(&grey),
            )))?;
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::MiddleMiddle)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()?;
    }
    root.present()?;
    Ok(())
}
