//! Maugis-Dugdale loss: direct evaluation at 1e-12 and the fast tier, one Λ per
//! case plus Λ = 1e3, against the case-1 closed form as the baseline of the run.
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use tabor::maugis::{loss_over_jkr_fast, normalized_loss, prepare_fast_tier};

fn maugis(c: &mut Criterion) {
    prepare_fast_tier().unwrap();
    let mut group = c.benchmark_group("maugis_loss");
    group.bench_function("baseline: case-1 closed form (Λ = 0.3)", |b| {
        b.iter(|| normalized_loss(black_box(0.3), 1e-12).unwrap().loss)
    });
    for lambda in [0.55, 2.0, 1e3] {
        group.bench_function(format!("direct 1e-12, Λ = {lambda}"), |b| {
            b.iter(|| normalized_loss(black_box(lambda), 1e-12).unwrap().loss)
        });
    }
    for lambda in [0.3, 0.55, 2.0, 1e3] {
        group.bench_function(format!("fast tier, Λ = {lambda}"), |b| {
            b.iter(|| loss_over_jkr_fast(black_box(lambda)).unwrap())
        });
    }
    group.finish();
}

criterion_group!(benches, maugis);
criterion_main!(benches);
