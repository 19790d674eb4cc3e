//! Sweeps over combined scenes: 2 000 log-spaced speeds from 0.5 to 5 m/s through
//! `tabor::scene::sweep`, for the bundled adhesion + viscoelasticity scene (two soft
//! polymer grains, the coupled viscous-adhesive model: one time-domain simulation per
//! point, the sticking velocity once per sweep) and, as the baseline of the same run,
//! the JKR silica scene (closed forms). The scenes issue asks for the combined sweep
//! to finish in under 10 s on this 2-core machine.
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use std::path::PathBuf;
use std::time::Duration;
use tabor::scene::{spaced, sweep, Scene, SweepParameter};

fn scene(name: &str) -> Scene {
    Scene::from_path(
        &PathBuf::from(env!("CARGO_MANIFEST_DIR"))
            .join("examples/scenes")
            .join(name),
    )
    .unwrap()
}

fn scene_sweep(c: &mut Criterion) {
    let speeds = spaced(0.5, 5.0, 2000, true).unwrap();
    let mut g = c.benchmark_group("scene_sweep_2000_speeds");
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(20));
    for (label, file) in [
        ("jkr_silica_baseline", "silica.toml"),
        (
            "adhesion_plus_viscosity",
            "polymer_grains_viscoadhesive.toml",
        ),
    ] {
        let s = scene(file);
        g.bench_function(label, |b| {
            b.iter(|| {
                let out = sweep(&s, SweepParameter::Speed, black_box(&speeds), || {});
                assert!(out.iter().all(|o| o.is_ok()));
                out.len()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, scene_sweep);
criterion_main!(benches);
