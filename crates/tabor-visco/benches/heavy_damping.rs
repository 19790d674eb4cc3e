//! Time of the heavy-damping solutions (was a wall-clock assertion in
//! `tests/heavy_damping.rs`: each forward solution below 5 ms, each inverse below
//! 20 ms; observed ≤ 0.3 ms and ≤ 1.4 ms). The sweeps of that test, at tolerance
//! 1e-8: the damping laws (5.72) over β and γ = 1e-9..1e3, the Kelvin-Voigt sphere
//! (5.66) over δ = 1e-9..1e3 for both models, and the inverse δ(ε).
//!
//! Run: `cargo bench -p tabor-visco --bench heavy_damping`.
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use tabor_visco::{damping_law, kelvin_voigt_sphere, SphereModel};

const EXPONENTS: [f64; 6] = [0.0, 0.25, 0.5, 1.0, 1.25, 1.5];

fn heavy_damping(c: &mut Criterion) {
    let mut group = c.benchmark_group("heavy_damping");
    for &(beta, gamma) in &[(0.0, 1e3), (1.5, 1e3), (0.25, 1.0)] {
        group.bench_function(format!("damping_law beta={beta} gamma={gamma:e}"), |b| {
            b.iter(|| damping_law::solve(black_box(beta), black_box(gamma), 1e-8).unwrap())
        });
    }
    group.bench_function("damping_law sweep (6 exponents x 13 decades)", |b| {
        b.iter(|| {
            for &beta in &EXPONENTS {
                for k in 0..=12 {
                    let gamma = 10f64.powf(-9.0 + k as f64);
                    black_box(damping_law::solve(beta, gamma, 1e-8).unwrap());
                }
            }
        })
    });
    for model in [SphereModel::KuwabaraKono, SphereModel::Rigorous] {
        group.bench_function(format!("kelvin_voigt_sphere {model:?} delta=1e3"), |b| {
            b.iter(|| kelvin_voigt_sphere::solve(black_box(1e3), model, 1e-8).unwrap())
        });
        group.bench_function(
            format!("kelvin_voigt_sphere {model:?} inverse eps=0.99"),
            |b| {
                b.iter(|| {
                    kelvin_voigt_sphere::viscous_parameter_for_restitution(
                        black_box(0.99),
                        model,
                        1e-8,
                    )
                    .unwrap()
                })
            },
        );
        group.bench_function(
            format!("kelvin_voigt_sphere {model:?} inverse eps=4e-6"),
            |b| {
                b.iter(|| {
                    kelvin_voigt_sphere::viscous_parameter_for_restitution(
                        black_box(4e-6),
                        model,
                        1e-8,
                    )
                    .unwrap()
                })
            },
        );
    }
    group.finish();
}

criterion_group!(benches, heavy_damping);
criterion_main!(benches);
