//! What an oblique impact costs against the central simulated impact of the same
//! normal law (issue 30, item 6), timed so that a shared, noisy machine does not
//! decide the answer: rounds of 20-impact batches, the central impact and the
//! oblique one at 10°, 40° and 80° interleaved in every round, each timed as the
//! best (fastest) batch over the rounds. `benches/oblique.rs` measures the same
//! calls with criterion; its estimates scatter by up to ±30 % from run to run on a
//! 2-core machine with other jobs, this best-of-batch ratio by a few per cent.
//!
//! The scene is `examples/scenes/silica_oblique.toml` (JKR load-controlled,
//! `mindlin`, `sds` rolling, `marshall` twisting) at 0.3 m/s, tolerance 1e-10,
//! no trajectory kept.
//!
//! ```text
//! cargo run --release --example oblique_cost [-- ROUNDS [micro-slip]]
//! ```
//!
//! `micro-slip` times `tangential = "mindlin_deresiewicz"` instead (batches of 2).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::hint::black_box;
use std::time::Instant;
use tabor::dynamics::SimulationSettings;
use tabor::scene::{Format, Scene};

/// The fastest of `rounds` timings of `batch` calls of `f`, per call (s), the
/// rounds interleaved by the caller.
fn time_batch(batch: usize, f: &mut dyn FnMut()) -> f64 {
    let start = Instant::now();
    for _ in 0..batch {
        f();
    }
    start.elapsed().as_secs_f64() / batch as f64
}

fn main() {
    let mut args = std::env::args().skip(1);
    let rounds: usize = args.next().map_or(40, |a| a.parse().expect("ROUNDS"));
    let micro_slip = args.next().is_some_and(|a| a == "micro-slip");
    let path = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/examples/scenes/silica_oblique.toml"
    );
    let mut text = std::fs::read_to_string(path).unwrap();
    if micro_slip {
        text = text.replace(
            "tangential = \"mindlin\"",
            "tangential = \"mindlin_deresiewicz\"",
        );
    }
    let scene = Scene::from_str(&text, Format::Toml).unwrap();
    let settings = SimulationSettings {
        record_trajectory: false,
        ..SimulationSettings::with_tolerance(1e-10).unwrap()
    };
    let angles = [10.0, 40.0, 80.0];
    let oblique_batch = if micro_slip { 2 } else { 20 };
    let mut best = [f64::INFINITY; 4];
    for _ in 0..rounds {
        let mut central = || {
            black_box(scene.simulate(black_box(0.3), &settings).unwrap());
        };
        best[0] = best[0].min(time_batch(20, &mut central));
        for (k, &angle) in angles.iter().enumerate() {
            let mut oblique = || {
                black_box(scene.oblique(black_box(0.3), angle).unwrap());
            };
            best[k + 1] = best[k + 1].min(time_batch(oblique_batch, &mut oblique));
        }
    }
    let model = if micro_slip {
        "mindlin_deresiewicz"
    } else {
        "mindlin"
    };
    println!("central simulated impact: {:.1} µs", best[0] * 1e6);
    for (k, angle) in angles.iter().enumerate() {
        println!(
            "{model} {angle}°: {:.1} µs, {:.2}× the central impact",
            best[k + 1] * 1e6,
            best[k + 1] / best[0]
        );
    }
}
