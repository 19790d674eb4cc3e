//! ns per evaluation of the C entry point `tabor_law_evaluate` (issue 17 target:
//! ≤ 100 ns), for each law, over a sweep of overlaps that crosses the adhesive
//! branch (a contact in the middle of an impact: loading and unloading).
#![allow(missing_docs)]

use criterion::{criterion_group, criterion_main, Criterion, Throughput};
use std::hint::black_box;
use tabor_ffi::*;

fn params(model: i32, lambda: f64) -> TaborLawParams {
    // two 1 µm silica spheres (the scenes of integrations/lammps/scenes)
    TaborLawParams {
        model,
        effective_modulus: 54e9 / (2.0 * (1.0 - 0.17 * 0.17)),
        effective_radius: 0.5e-6,
        work_of_adhesion: 0.05,
        tabor_parameter: lambda,
        damping_time: 0.0,
        damping_model: TABOR_DAMPING_KUWABARA_KONO,
        damping_value: 0.0,
        dugdale_range: 0.0,
        cohesive_stress: 0.0,
    }
}

fn bench(c: &mut Criterion) {
    let cases = [
        ("hertz", params(TABOR_MODEL_HERTZ, 1.0)),
        ("jkr_fixed_grip", params(TABOR_MODEL_JKR_FIXED_GRIP, 1.0)),
        (
            "jkr_load_controlled",
            params(TABOR_MODEL_JKR_LOAD_CONTROLLED, 1.0),
        ),
        (
            "maugis_case1_lambda0.3",
            params(TABOR_MODEL_MAUGIS_DUGDALE, 0.3),
        ),
        (
            "maugis_case2_lambda0.55",
            params(TABOR_MODEL_MAUGIS_DUGDALE, 0.55),
        ),
        (
            "maugis_case3_lambda1.5",
            params(TABOR_MODEL_MAUGIS_DUGDALE, 1.5),
        ),
        (
            "maugis_case3_damped",
            TaborLawParams {
                damping_time: 1e-9,
                ..params(TABOR_MODEL_MAUGIS_DUGDALE, 1.5)
            },
        ),
    ];
    let mut group = c.benchmark_group("tabor_law_evaluate");
    const N: usize = 1024;
    group.throughput(Throughput::Elements(N as u64));
    for (name, p) in cases {
        let mut law: *mut TaborLaw = std::ptr::null_mut();
        // SAFETY: valid pointers
        let status = unsafe { tabor_law_new(&p, &mut law) };
        assert_eq!(status, TABOR_OK);
        let mut info = TaborLawInfo::default();
        // SAFETY: valid pointers
        unsafe { tabor_law_info(law, &mut info) };
        // overlaps from the snap-off to 30 d_n-ish: 20 nm for these spheres
        let lo = info.snap_off_overlap.min(-1e-10);
        let overlaps: Vec<f64> = (0..N)
            .map(|i| lo + (20e-9 - lo) * (i as f64 / N as f64))
            .collect();
        group.bench_function(name, |b| {
            b.iter(|| {
                let mut sum = 0.0;
                for &d in &overlaps {
                    let mut h = TaborHistory {
                        contact: 1.0,
                        max_overlap: 2e-8,
                    };
                    let mut f = TaborForce::default();
                    // SAFETY: valid pointers
                    unsafe {
                        tabor_law_evaluate(law, black_box(d), black_box(-0.01), &mut h, &mut f)
                    };
                    sum += f.force;
                }
                black_box(sum)
            })
        });
        // SAFETY: from tabor_law_new
        unsafe { tabor_law_free(law) };
    }
    group.finish();
}

criterion_group!(benches, bench);
criterion_main!(benches);
