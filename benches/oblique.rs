//! The cost of an oblique impact against the central simulated impact of the same
//! normal law, in one run (issue 30, item 6): the silica scene of
//! `examples/scenes/silica_oblique.toml` (JKR load-controlled, `mindlin`, `sds`
//! rolling, `marshall` twisting) at 0.3 m/s through `Scene::oblique`, at 10°, 40°
//! and 80°, with `mindlin` and with `mindlin_deresiewicz` (micro-slip, the default
//! spring bed); the baseline is the central simulated impact of the same scene
//! (`Scene::simulate` at 0.3 m/s, no trajectory kept), and, for reference, the
//! silica scene's `Scene::simulate` (fixed grip) as the issue measured it.
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::path::PathBuf;
use tabor::dynamics::SimulationSettings;
use tabor::scene::{Format, Scene};

fn text(name: &str) -> String {
    std::fs::read_to_string(
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("examples/scenes")
            .join(name),
    )
    .unwrap()
}

fn oblique(c: &mut Criterion) {
    let mindlin_text = text("silica_oblique.toml");
    let mindlin = Scene::from_str(&mindlin_text, Format::Toml).unwrap();
    let micro_slip = Scene::from_str(
        &mindlin_text.replace(
            "tangential = \"mindlin\"",
            "tangential = \"mindlin_deresiewicz\"",
        ),
        Format::Toml,
    )
    .unwrap();
    let silica = Scene::from_str(&text("silica.toml"), Format::Toml).unwrap();
    let settings = SimulationSettings {
        record_trajectory: false,
        ..SimulationSettings::with_tolerance(1e-10).unwrap()
    };
    let mut g = c.benchmark_group("oblique_impact");
    g.bench_function("baseline: central simulated, silica_oblique 0.3 m/s", |b| {
        b.iter(|| {
            mindlin
                .simulate(black_box(0.3), &settings)
                .unwrap()
                .0
                .restitution
        })
    });
    g.bench_function("central simulated, silica (fixed grip) 0.3 m/s", |b| {
        b.iter(|| {
            silica
                .simulate(black_box(0.3), &settings)
                .unwrap()
                .0
                .restitution
        })
    });
    for angle in [10.0, 40.0, 80.0] {
        g.bench_function(format!("mindlin {angle}°"), |b| {
            b.iter(|| {
                mindlin
                    .oblique(black_box(0.3), angle)
                    .unwrap()
                    .normal_restitution
            })
        });
    }
    g.finish();
    // micro-slip costs ~2 ms an impact: ten samples
    let mut g = c.benchmark_group("oblique_impact_micro_slip");
    g.sample_size(10);
    for angle in [10.0, 40.0, 80.0] {
        g.bench_function(format!("mindlin_deresiewicz {angle}°"), |b| {
            b.iter(|| {
                micro_slip
                    .oblique(black_box(0.3), angle)
                    .unwrap()
                    .normal_restitution
            })
        });
    }
    g.finish();
}

criterion_group!(benches, oblique);
criterion_main!(benches);
