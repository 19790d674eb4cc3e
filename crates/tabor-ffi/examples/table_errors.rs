//! Prints the measured table errors, pull-off forces and build times of the laws
//! across Λ (the figures of the crate README).
#![allow(missing_docs, clippy::unwrap_used)]
use tabor_ffi::*;

fn main() {
    let e = 54e9 / (2.0 * (1.0 - 0.17f64 * 0.17));
    println!("law  build_ms  table_err_abs/F_n  hertz_rel  radius_err/a_c  pull_off/(pi w R)  jump_in/d_n snap_off/d_n");
    let mut cases: Vec<(String, ContactLaw)> = vec![];
    for (name, rule) in [
        ("jkr-fg", tabor_jkr::SeparationRule::FixedGrip),
        ("jkr-lc", tabor_jkr::SeparationRule::LoadControlled),
    ] {
        let t = std::time::Instant::now();
        let l = ContactLaw::jkr(e, 0.5e-6, 0.05, rule).unwrap();
        cases.push((format!("{name} {:.2}", t.elapsed().as_secs_f64() * 1e3), l));
    }
    for lambda in [
        0.01, 0.05, 0.1, 0.3, 0.449, 0.45, 0.5, 0.55, 0.6435, 0.65, 1.0, 1.5, 3.0, 10.0, 100.0, 1e4,
    ] {
        let t = std::time::Instant::now();
        let l = ContactLaw::maugis_dugdale(e, 0.5e-6, 0.05, lambda).unwrap();
        cases.push((
            format!("md{lambda} {:.2}", t.elapsed().as_secs_f64() * 1e3),
            l,
        ));
    }
    for (name, l) in cases {
        let err = l.table_error();
        let dn = tabor_jkr::JkrSphere::new(e, 0.5e-6, 0.05)
            .unwrap()
            .scales()
            .depth;
        println!(
            "{name} {:.2e} {:.2e} {:.2e} {:.5} {:.4} {:.4}",
            err.fine_force_abs,
            err.hertz_force_rel,
            err.fine_radius_abs,
            -l.pull_off_force() / (std::f64::consts::PI * 0.05 * 0.5e-6),
            l.jump_in_overlap() / dn,
            l.snap_off_overlap() / dn
        );
    }
}
