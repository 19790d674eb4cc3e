//! The cost and accuracy of the per-contact Tabor parameter table (module
//! `tabor_ffi::lambda`): for a cloud whose effective radii span a factor
//! `RATIO` at a fixed Dugdale range, the nodes built, their memory and the time to
//! build them (what `pair_style tabor` pays once, at the first `run`), beside the
//! time of one fixed-Λ law (the baseline, same run); then the interpolation error
//! against the exact law at Λ midway between nodes across the cloud's Λ range.
//!
//! `cargo run --release -p tabor-ffi --example lambda_table [RATIO]`
#![allow(clippy::unwrap_used, clippy::expect_used, missing_docs)]

use std::time::Instant;
use tabor_ffi::lambda::{shared_table, TABOR_LAMBDA_CASE_2_INTERVALS};
use tabor_ffi::ContactLaw;
use tabor_maugis::{LAMBDA_1, LAMBDA_2};

fn main() {
    let ratio: f64 = std::env::args()
        .nth(1)
        .map(|a| a.parse().expect("RATIO: a number"))
        .unwrap_or(10.0);
    let (e, w) = (54e9 / (2.0 * (1.0 - 0.17 * 0.17)), 0.05);
    let (r_min, r_max) = (0.25e-6, 0.25e-6 * ratio);
    let law = ContactLaw::maugis_dugdale_range(e, r_min, w, 1.8961e-10).unwrap();
    let lam = |r: f64| law.tabor_parameter_at(&law.scales(r).unwrap()).unwrap();
    let (l0, l1) = (lam(r_min), lam(r_max));
    let t = Instant::now();
    let _fixed = ContactLaw::maugis_dugdale(e, r_min, w, l0).unwrap();
    let one = t.elapsed();
    let t = Instant::now();
    let built = law.prepare_radii(r_min, r_max).unwrap();
    let all = t.elapsed();
    let table = shared_table();
    println!("R* in [{r_min:.3e}, {r_max:.3e}] m: Lambda in [{l0:.4}, {l1:.4}]");
    println!(
        "nodes built: {built}, memory {:.2} MB (shared by every type pair), build {:.1} ms \
         = {:.1} fixed-Lambda laws ({:.1} ms each, same run)",
        table.memory_bytes() as f64 / 1e6,
        all.as_secs_f64() * 1e3,
        all.as_secs_f64() / one.as_secs_f64(),
        one.as_secs_f64() * 1e3
    );
    // per-contact evaluation cost against the fixed-Λ law (same run, same
    // contacts: a loading-unloading sweep at 64 radii across the cloud)
    let radii: Vec<f64> = (0..64)
        .map(|i| r_min * ratio.powf(f64::from(i) / 63.0))
        .collect();
    let fixed_laws: Vec<ContactLaw> = radii
        .iter()
        .map(|&r| ContactLaw::maugis_dugdale(e, r, w, lam(r)).unwrap())
        .collect();
    let sweep = |per: bool| {
        let t = Instant::now();
        let mut acc = 0.0;
        for _ in 0..20 {
            for (k, &r) in radii.iter().enumerate() {
                let l = if per { &law } else { &fixed_laws[k] };
                let s = l.scales(r).unwrap();
                let mut h = tabor_ffi::TaborHistory::default();
                for i in 0..2000 {
                    let x = f64::from(if i < 1000 { i } else { 2000 - i }) / 1000.0;
                    let d = -1.2e-10 + x * 3e-9;
                    acc += l.evaluate_scaled(&s, d, 0.0, &mut h).unwrap().force;
                }
            }
        }
        (t.elapsed().as_secs_f64(), acc)
    };
    let (t_fixed, a) = sweep(false);
    let (t_per, b) = sweep(true);
    println!(
        "evaluation: per-contact {:.1} ns, fixed Lambda {:.1} ns per call: ratio {:.2} (checksums {a:.6e} {b:.6e})",
        t_per / 2.56e6 * 1e9,
        t_fixed / 2.56e6 * 1e9,
        t_per / t_fixed
    );
    let q = (LAMBDA_2 / LAMBDA_1).ln() / f64::from(TABOR_LAMBDA_CASE_2_INTERVALS);
    println!(
        "Lambda (midway between nodes): |dF|/F_n, |da|/a_c, |dF/F| Hertz, |d d0|/d_n, |dF_po|/F_n"
    );
    let mut k = ((l0 / LAMBDA_1).ln() / q).floor() as i32;
    while LAMBDA_1 * (q * (f64::from(k) + 0.5)).exp() < l1 {
        let l = LAMBDA_1 * (q * (f64::from(k) + 0.5)).exp();
        if l > l0 {
            let m = table.measure_error(l, 200).unwrap();
            println!(
                "{l:.5} {:.1e} {:.1e} {:.1e} {:.1e} {:.1e}",
                m.force_abs, m.radius_abs, m.hertz_force_rel, m.snap_off_abs, m.pull_off_abs
            );
        }
        k += 1;
    }
}
