//! One coupled impact (JKR fixed grip + Kuwabara-Kono damping) of two silica
//! spheres of radius 1 µm at twice the elastic sticking velocity, at tolerances
//! 1e-8 and 1e-10, and one sticking-velocity search.
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use tabor_restitution::{sticking_velocity, ImpactModel};
use tabor_viscoadhesive::{Adhesion, SeparationRule, ViscoadhesiveImpact};

fn impacts(c: &mut Criterion) {
    let (e, r, dg, m) = (2.78e10, 0.5e-6, 0.05, 5.55e-15);
    let eta_c = 40.0;
    let mut group = c.benchmark_group("viscoadhesive");
    for tol in [1e-8, 1e-10] {
        for (label, adhesion) in [
            ("JKR fixed grip", Adhesion::Jkr(SeparationRule::FixedGrip)),
            (
                "MD Lambda=1",
                Adhesion::MaugisDugdale {
                    tabor_parameter: 1.0,
                },
            ),
        ] {
            let model = ViscoadhesiveImpact::new(e, r, m, dg, adhesion, eta_c, tol).unwrap();
            let v0 = 2.0 * model.speed_scale();
            group.bench_function(format!("{label}, one impact, tol {tol:e}"), |b| {
                b.iter(|| model.energy_loss(black_box(v0)).unwrap().joules)
            });
        }
    }
    let model = ViscoadhesiveImpact::new(
        e,
        r,
        m,
        dg,
        Adhesion::Jkr(SeparationRule::FixedGrip),
        eta_c,
        1e-8,
    )
    .unwrap();
    group.sample_size(10);
    group.bench_function("JKR fixed grip, sticking velocity 1e-8", |b| {
        b.iter(|| sticking_velocity(&model, 1e-8).unwrap().speed)
    });
    group.finish();
}

criterion_group!(benches, impacts);
criterion_main!(benches);
