//! One time-domain impact (`tabor-dynamics`, default settings: relative tolerance
//! 1e-11, no trajectory kept) of two silica spheres of radius 1 µm at twice their
//! sticking velocity, with the JKR law (fixed grip) and the Maugis-Dugdale law at
//! Λ = 1, against the closed-form restitution (5.37) of the same JKR impact as the
//! baseline of the run.
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion};
use std::hint::black_box;
use tabor::dynamics::{simulate_impact, SimulationSettings};
use tabor::jkr::{JkrForceLaw, JkrImpact, JkrSphere, SeparationRule};
use tabor::maugis::{MaugisContact, MaugisDugdaleForceLaw, MaugisDugdaleImpact};
use tabor::restitution::{impact, sticking_velocity};

fn impacts(c: &mut Criterion) {
    let (e_star, r, dg, m) = (
        2.780_352_177_942_539e10,
        0.5e-6,
        0.05,
        5.550_147_021_341_967e-15,
    );
    let sphere = JkrSphere::new(e_star, r, dg).unwrap();
    let jkr = JkrImpact::new(sphere, m).unwrap();
    let md = MaugisDugdaleImpact::new(
        MaugisContact::new(JkrSphere::new(e_star, r, dg).unwrap(), 1.0).unwrap(),
        m,
    )
    .unwrap();
    let v0 = 2.0 * sticking_velocity(&jkr, 1e-12).unwrap().speed;
    let settings = SimulationSettings {
        record_trajectory: false,
        ..SimulationSettings::default()
    };

    let mut group = c.benchmark_group("time_domain_impact");
    group.bench_function("baseline: JKR closed-form restitution", |b| {
        b.iter(|| impact(&jkr, black_box(v0)).unwrap().restitution)
    });
    group.bench_function("JKR fixed grip, simulated", |b| {
        b.iter(|| {
            let mut law = JkrForceLaw::new(sphere, SeparationRule::FixedGrip);
            simulate_impact(&mut law, m, black_box(v0), &settings)
                .unwrap()
                .restitution
        })
    });
    group.bench_function("Maugis-Dugdale Λ = 1, simulated", |b| {
        b.iter(|| {
            let mut law = MaugisDugdaleForceLaw::new(&md).unwrap();
            simulate_impact(&mut law, m, black_box(v0), &settings)
                .unwrap()
                .restitution
        })
    });
    group.finish();
}

criterion_group!(benches, impacts);
criterion_main!(benches);
