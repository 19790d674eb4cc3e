//! A restitution map of 10⁵ (impact speed, radius) pairs — 250 log-spaced speeds
//! from 1 mm/s to 10 m/s times 400 log-spaced radii from 10 nm to 100 µm — for two
//! identical silica spheres (E = 54 GPa, ν = 0.17, ρ = 2650 kg/m³,
//! Δγ = 0.05 J/m²), on rayon pools of 1 and 2 threads; the 1-thread pool is the
//! baseline of the run, so the ratio is the parallel speed-up. Two models:
//! JKR fixed grip (closed forms (5.36)-(5.37) per point) and Maugis-Dugdale with a
//! fixed range h = 0.3 nm (Λ varies with the radius; the fast tier per point).
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use rayon::prelude::*;
use std::hint::black_box;
use tabor::jkr::{JkrImpact, JkrSphere};
use tabor::maugis::units::JkrScales;
use tabor::maugis::{jkr_normalized_loss, loss_over_jkr_fast, prepare_fast_tier};
use tabor::restitution::{impact, restitution_from_loss};

const SPEEDS: usize = 250;
const RADII: usize = 400;
const E: f64 = 54e9;
const NU: f64 = 0.17;
const RHO: f64 = 2650.0;
const DG: f64 = 0.05;
const RANGE: f64 = 0.3e-9;

fn log_spaced(from: f64, to: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| from * (to / from).powf(i as f64 / (n - 1) as f64))
        .collect()
}

/// (E*, R, m) of two identical spheres of radius `r1`.
fn pair(r1: f64) -> (f64, f64, f64) {
    let e_star = E / (2.0 * (1.0 - NU * NU));
    let m = 4.0 / 3.0 * std::f64::consts::PI * r1.powi(3) * RHO / 2.0;
    (e_star, r1 / 2.0, m)
}

fn jkr_point(r1: f64, v: f64) -> f64 {
    let (e_star, r, m) = pair(r1);
    let model = JkrImpact::new(JkrSphere::new(e_star, r, DG).unwrap(), m).unwrap();
    impact(&model, v).unwrap().restitution
}

fn maugis_point(r1: f64, v: f64) -> f64 {
    let (e_star, r, m) = pair(r1);
    let scales = JkrScales::new(e_star, r, DG).unwrap();
    let lambda = scales.depth / RANGE;
    let loss = loss_over_jkr_fast(lambda).unwrap() * jkr_normalized_loss() * scales.energy;
    restitution_from_loss(loss, m, v).unwrap()
}

/// The mean restitution of the map (so that nothing is optimized away).
fn map(points: &[(f64, f64)], f: fn(f64, f64) -> f64) -> f64 {
    points.par_iter().map(|&(r1, v)| f(r1, v)).sum::<f64>() / points.len() as f64
}

fn restitution_map(c: &mut Criterion) {
    prepare_fast_tier().unwrap();
    let speeds = log_spaced(1e-3, 10.0, SPEEDS);
    let radii = log_spaced(1e-8, 1e-4, RADII);
    let points: Vec<(f64, f64)> = radii
        .iter()
        .flat_map(|&r1| speeds.iter().map(move |&v| (r1, v)))
        .collect();
    assert_eq!(points.len(), 100_000);
    let pools: Vec<(usize, rayon::ThreadPool)> = [1, 2]
        .into_iter()
        .map(|n| {
            (
                n,
                rayon::ThreadPoolBuilder::new()
                    .num_threads(n)
                    .build()
                    .unwrap(),
            )
        })
        .collect();
    // both pools give the same map
    for f in [jkr_point as fn(f64, f64) -> f64, maugis_point] {
        let one = pools[0].1.install(|| map(&points, f));
        let two = pools[1].1.install(|| map(&points, f));
        assert!((one / two - 1.0).abs() < 1e-12 && one > 0.0 && one < 1.0);
    }

    for (model, f) in [
        ("JKR", jkr_point as fn(f64, f64) -> f64),
        ("Maugis-Dugdale fast tier", maugis_point),
    ] {
        let mut group = c.benchmark_group(format!("restitution_map_1e5/{model}"));
        group.sample_size(20);
        for (n, pool) in &pools {
            let name = if *n == 1 {
                "baseline: 1 thread".to_string()
            } else {
                format!("{n} threads")
            };
            group.bench_function(name, |b| {
                b.iter(|| pool.install(|| map(black_box(&points), f)))
            });
        }
        group.finish();
    }
}

criterion_group!(benches, restitution_map);
criterion_main!(benches);
