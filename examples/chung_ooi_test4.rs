//! Chung & Ooi (2011), Granular Matter 13:643, Test 4: an alumina sphere
//! (R = 2.5 mm, E = 380 GPa, ν = 0.23) on a rigid plane at 3.9 m/s, μ = 0.092,
//! at impact angles 0.5-89.5° (`examples/scenes/chung_ooi/test4_alumina.toml`):
//! the paper's three quantities (the centre ratio v_t'/v_t, the spin ω' and the
//! contact point's rebound angle atan((v_t' + Rω')/v_n')) of tabor's
//! `mindlin_deresiewicz` (micro-slip) and `mindlin` (LAMMPS, no micro-slip),
//! beside the measurements of Kharaz, Gorham & Salman (2001), Powder Technol.
//! 120:281, and the paper's DEM solution, as the paper draws them
//! (`examples/scenes/chung_ooi/test4_reference.csv`).
//!
//! `cargo run --release --example chung_ooi_test4 [-- --out <dir>]` writes
//! `chung_ooi_test4.csv` and `chung_ooi_test4.svg` into `<dir>` (default: `.`).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use plotters::prelude::*;
use std::error::Error;
use std::io::Write;
use std::path::PathBuf;
use tabor::scene::{Format, Scene};

const SPEED: f64 = 3.9;
const MODELS: [&str; 2] = ["mindlin_deresiewicz", "mindlin"];

fn out_dir() -> Result<PathBuf, Box<dyn Error>> {
    let args: Vec<String> = std::env::args().skip(1).collect();
    match args.as_slice() {
        [] => Ok(PathBuf::from(".")),
        [flag, dir] if flag == "--out" => Ok(PathBuf::from(dir)),
        _ => Err("usage: chung_ooi_test4 [--out <dir>]".into()),
    }
}

fn chung_ooi(file: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
        .join("examples/scenes/chung_ooi")
        .join(file)
}

/// A row of the reference file: series, quantity, angle (°), value.
type Row = (String, String, f64, f64);

/// The rows of the reference file.
fn reference() -> Result<Vec<Row>, Box<dyn Error>> {
    let text = std::fs::read_to_string(chung_ooi("test4_reference.csv"))?;
    let mut rows = Vec::new();
    for line in text.lines().filter(|l| !l.starts_with('#')).skip(1) {
        let f: Vec<&str> = line.split(',').collect();
        rows.push((f[0].into(), f[1].into(), f[2].parse()?, f[3].parse()?));
    }
    Ok(rows)
}

fn main() -> Result<(), Box<dyn Error>> {
    let dir = out_dir()?;
    std::fs::create_dir_all(&dir)?;
    let text = std::fs::read_to_string(chung_ooi("test4_alumina.toml"))?;
    let angles: Vec<f64> = (0..90).map(|i| 0.5 + i as f64).collect();
    let mut csv = std::fs::File::create(dir.join("chung_ooi_test4.csv"))?;
    writeln!(
        csv,
        "model,angle_deg,centre_ratio,angular_velocity,rebound_angle_deg,tangential_restitution,energy_error"
    )?;
    // per model: the three curves
    let mut curves: Vec<[Vec<(f64, f64)>; 3]> = Vec::new();
    for model in MODELS {
        let scene = Scene::from_str(&text.replace("mindlin_deresiewicz", model), Format::Toml)?;
        let r = scene.sphere.radius.ok_or("no radius")?;
        let mut c: [Vec<(f64, f64)>; 3] = Default::default();
        for &a in &angles {
            let o = scene.oblique(SPEED, a)?;
            let v = o.after.sphere.velocity;
            let w = o.after.sphere.angular_velocity[2];
            let ratio = v[1] / (SPEED * a.to_radians().sin());
            let rebound = ((v[1] + r * w) / -v[0]).atan().to_degrees();
            writeln!(
                csv,
                "{model},{a},{ratio},{w},{rebound},{},{}",
                o.tangential_restitution.unwrap_or(f64::NAN),
                o.energy_error
            )?;
            c[0].push((a, ratio));
            c[1].push((a, w));
            c[2].push((a, rebound));
        }
        curves.push(c);
    }
    let rows = reference()?;

    let path = dir.join("chung_ooi_test4.svg");
    let root = SVGBackend::new(&path, (900, 1100)).into_drawing_area();
    root.fill(&WHITE)?;
    let (title, body) = root.split_vertically(40);
    title.titled(
        "Chung & Ooi (2011) Test 4: alumina on a rigid plane, 3.9 m/s, μ = 0.092",
        ("sans-serif", 20),
    )?;
    let panels = body.split_evenly((3, 1));
    let specs = [
        ("tangential_restitution", "centre ratio v_t'/v_t", 0.4..1.05),
        ("angular_velocity", "spin ω' (rad/s)", -750.0..50.0),
        (
            "rebound_angle",
            "rebound angle of the contact point (°)",
            -20.0..90.0,
        ),
    ];
    for (k, ((quantity, label, range), panel)) in specs.into_iter().zip(panels.iter()).enumerate() {
        let mut chart = ChartBuilder::on(panel)
            .margin(10)
            .x_label_area_size(35)
            .y_label_area_size(60)
            .build_cartesian_2d(0.0f64..90.0, range)?;
        chart
            .configure_mesh()
            .x_desc("impact angle α (°)")
            .y_desc(label)
            .draw()?;
        for (model, (c, color)) in MODELS.iter().zip(curves.iter().zip([RED, BLUE])) {
            chart
                .draw_series(LineSeries::new(c[k].iter().copied(), color.stroke_width(2)))?
                .label(format!("tabor: {model}"))
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], color.stroke_width(2))
                });
        }
        let points = |series: &str| -> Vec<(f64, f64)> {
            rows.iter()
                .filter(|r| r.0 == series && r.1 == quantity)
                .map(|r| (r.2, r.3))
                .collect()
        };
        chart
            .draw_series(
                points("paper_dem_alumina")
                    .into_iter()
                    .map(|p| TriangleMarker::new(p, 6, RGBColor(0, 140, 0).stroke_width(2))),
            )?
            .label("Chung & Ooi (2011) DEM")
            .legend(|(x, y)| TriangleMarker::new((x + 10, y), 6, RGBColor(0, 140, 0)));
        chart
            .draw_series(
                points("experiment")
                    .into_iter()
                    .map(|p| Circle::new(p, 5, BLACK.filled())),
            )?
            .label("Kharaz, Gorham & Salman (2001), measured")
            .legend(|(x, y)| Circle::new((x + 10, y), 5, BLACK.filled()));
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.9))
            .border_style(BLACK)
            .position(SeriesLabelPosition::LowerRight)
            .draw()?;
    }
    root.present()?;
    println!("wrote {} and chung_ooi_test4.csv", path.display());
    Ok(())
}
