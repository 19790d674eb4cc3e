#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The per-contact Tabor parameter (module `lambda`): the table over Λ against the
//! exact Maugis-Dugdale law of `tabor-maugis` at Λ between the nodes, in all three
//! cases and across the case boundaries Λ1 and Λ2; the per-contact law at R*
//! against the fixed-Λ law built at that contact's Λ; the relation Λ = d_n(R*)/h
//! against `tabor_maugis::units`; bad input refused by name.
#![allow(missing_docs)]

use tabor_ffi::lambda::{shared_table, TABOR_LAMBDA_CASE_2_INTERVALS};
use tabor_ffi::*;
use tabor_maugis::units::{tabor_parameter_from_cohesive_stress, tabor_parameter_from_range};
use tabor_maugis::{LAMBDA_1, LAMBDA_2};

const E: f64 = 54e9 / (2.0 * (1.0 - 0.17 * 0.17));
const W: f64 = 0.05;

/// The grid step in ln Λ.
fn q() -> f64 {
    (LAMBDA_2 / LAMBDA_1).ln() / f64::from(TABOR_LAMBDA_CASE_2_INTERVALS)
}

/// The stated accuracy of the table (module docs, pair_tabor.rst), measured by
/// `examples/lambda_table.rs` midway between every pair of nodes: |ΔF̂| ≤ 1e-6 F_n
/// (relative where |F| > F_n), |Δâ| ≤ 1e-6 a_c at the same distance above the
/// snap-off, |ΔF/F| ≤ 1e-7 beyond the adhesive part, |Δd̂₀| ≤ 1e-7 d_n,
/// |ΔF̂_pull-off| ≤ 1e-8 F_n; within 0.58 < Λ < 0.75 around Λ2 ≈ 0.6435 (where the
/// snap-off moves from the no-contact to the contact branch and the branch is not
/// a smooth function of Λ) |ΔF̂| ≤ 5e-5, |Δâ| ≤ 1e-4, |Δd̂₀| ≤ 5e-6 (measured
/// at most 2.7e-5, 6.9e-5, 1.9e-6, just above Λ2).
fn stated(lambda: f64) -> [f64; 5] {
    if lambda > 0.58 && lambda < 0.75 {
        [5e-5, 1e-4, 1e-7, 5e-6, 1e-8]
    } else {
        [1e-6, 1e-6, 1e-7, 1e-7, 1e-8]
    }
}

#[test]
fn the_table_over_lambda_matches_the_exact_law_between_the_nodes() {
    let t = shared_table();
    // midway between nodes (the extremum of the interpolation error) in each case,
    // and on either side of Λ1 and Λ2
    let mut lambdas = vec![
        0.05, 0.2, 0.3, 0.5, 0.55, 0.6, 0.7, 0.8, 1.0, 1.3, 3.0, 20.0,
    ];
    lambdas.extend([
        LAMBDA_1 * 0.999,
        LAMBDA_1 * 1.001,
        LAMBDA_2 * 0.999,
        LAMBDA_2 * 1.001,
    ]);
    for l in lambdas {
        let l = l * (0.5 * q()).exp();
        let e = t.measure_error(l, 400).expect("measures");
        eprintln!("Lambda {l:.5}: {e:?}");
        let s = stated(l);
        let got = [
            e.force_abs,
            e.radius_abs,
            e.hertz_force_rel,
            e.snap_off_abs,
            e.pull_off_abs,
        ];
        for (g, s) in got.iter().zip(s) {
            assert!(g <= &s, "Lambda {l}: {e:?} above the stated {s:e}");
        }
    }
}

fn range_law(r: f64, h: f64) -> ContactLaw {
    ContactLaw::maugis_dugdale_range(E, r, W, h).expect("builds")
}

/// The normal force along an approach to `depth` and back to separation, with
/// the events, at effective radius `r`.
fn trajectory(law: &ContactLaw, r: f64, depth: f64) -> Vec<(f64, f64, i32)> {
    let s = law.scales(r).unwrap();
    let mut h = TaborHistory::default();
    let jump = law.jump_in_overlap_at(&s);
    let n = 4000;
    (0..=2 * n)
        .map(|i| {
            let x = if i <= n { i } else { 2 * n - i } as f64 / n as f64;
            let d = 1.5 * jump + x * (depth - 1.5 * jump);
            let f = law.evaluate_scaled(&s, d, 0.0, &mut h).unwrap();
            (f.force, f.contact_radius, f.event)
        })
        .collect()
}

#[test]
fn the_per_contact_law_at_r_is_the_fixed_law_at_that_contacts_lambda() {
    let h = 2e-10;
    let per = range_law(1e-6, h);
    let d_n_unit = per.scales(1.0).unwrap().depth; // d_n at R* = 1 m: d_n ∝ R*^(1/3)
                                                   // radii whose Λ lie in the three cases, at a node and between nodes
    let at = |lambda: f64| (lambda * h / d_n_unit).powi(3);
    for (lambda, on_node) in [
        (0.3, false),
        (LAMBDA_1 * (2.0 * q()).exp(), true),
        (0.55, false),
        (LAMBDA_2, true),
        (1.7, false),
    ] {
        let r = at(lambda);
        let s = per.scales(r).unwrap();
        let l = per.tabor_parameter_at(&s).unwrap();
        assert!((l / lambda - 1.0).abs() < 1e-12);
        // the relation against the library's own conversions
        let lib = tabor_parameter_from_range(h, W, E, r).unwrap();
        assert!((l / lib - 1.0).abs() < 1e-13, "{l} vs {lib}");
        let lib = tabor_parameter_from_cohesive_stress(W / h, W, E, r).unwrap();
        assert!((l / lib - 1.0).abs() < 1e-13, "{l} vs {lib}");
        let fixed = ContactLaw::maugis_dugdale(E, r, W, l).unwrap();
        let fs = fixed.scales(r).unwrap();
        assert!((per.jump_in_overlap_at(&s) / fixed.jump_in_overlap_at(&fs) - 1.0).abs() < 1e-12);
        let d_n = s.depth;
        let tol_d = if on_node { 1e-12 } else { stated(l)[3] };
        assert!(
            (per.snap_off_overlap_at(&s) - fixed.snap_off_overlap_at(&fs)).abs() <= tol_d * d_n,
            "snap-off at Lambda {l}"
        );
        let tol_f = if on_node { 1e-10 } else { stated(l)[4] };
        assert!(
            (per.pull_off_force_at(&s) - fixed.pull_off_force_at(&fs)).abs() <= tol_f * s.force
        );
        // whole approach and retraction: forces to the stated accuracy plus the
        // fixed law's own table error, events at the same steps (a step is 1/4000
        // of the path, far above the snap-off's shift)
        let a = trajectory(&per, r, 5.0 * d_n);
        let b = trajectory(&fixed, r, 5.0 * d_n);
        let tol = if on_node { 1e-9 } else { stated(l)[0] } + fixed.table_error().fine_force_abs;
        // near a snap-off moved by Δd̂₀ the force moves by up to c √Δd̂₀ (c ~ 1)
        let near = (stated(l)[3]).sqrt() * 3.0;
        for (i, (x, y)) in a.iter().zip(&b).enumerate() {
            assert_eq!(x.2, y.2, "event at step {i}, Lambda {l}");
            let allowed = if on_node { tol } else { tol.max(near) };
            assert!(
                (x.0 - y.0).abs() <= allowed * s.force,
                "Lambda {l} step {i}: {} vs {} (F_n {})",
                x.0,
                y.0,
                s.force
            );
        }
    }
}

#[test]
fn the_stress_form_is_the_range_form_and_bad_input_is_refused_by_name() {
    let a = ContactLaw::maugis_dugdale_range(E, 1e-6, W, 2e-10).unwrap();
    let b = ContactLaw::maugis_dugdale_stress(E, 1e-6, W, W / 2e-10).unwrap();
    assert_eq!(a.kind(), b.kind());
    let base = TaborLawParams {
        model: TABOR_MODEL_MAUGIS_DUGDALE,
        effective_modulus: E,
        effective_radius: 1e-6,
        work_of_adhesion: W,
        tabor_parameter: 0.0,
        damping_time: 0.0,
        damping_model: TABOR_DAMPING_KUWABARA_KONO,
        damping_value: 0.0,
        dugdale_range: 2e-10,
        cohesive_stress: 0.0,
    };
    assert!(law_from_params(&base).is_ok());
    let cases = [
        (
            TaborLawParams {
                dugdale_range: -1e-9,
                ..base
            },
            "range",
        ),
        (
            TaborLawParams {
                dugdale_range: f64::NAN,
                ..base
            },
            "range",
        ),
        (
            TaborLawParams {
                dugdale_range: 0.0,
                cohesive_stress: f64::INFINITY,
                ..base
            },
            "cohesive_stress",
        ),
        (
            TaborLawParams {
                cohesive_stress: 1e8,
                ..base
            },
            "cohesive_stress",
        ),
        (
            TaborLawParams {
                tabor_parameter: 0.5,
                ..base
            },
            "tabor_parameter",
        ),
    ];
    for (p, name) in cases {
        let e = law_from_params(&p).expect_err("refused").to_string();
        assert!(e.contains(name), "{e} should name {name}");
    }
    // Λ = d_n/h ≈ 1e-7 at R* = 1 µm with h = 1 cm: outside the table's domain,
    // refused when the radii are prepared (LAMMPS: at init, on all ranks)
    let far = ContactLaw::maugis_dugdale_range(E, 1e-6, W, 1e-2).unwrap();
    let e = far
        .prepare_radii(1e-6, 1e-6)
        .expect_err("refused")
        .to_string();
    assert!(e.contains("tabor_parameter"), "{e}");
    let mut out = TaborForce::default();
    let s = far.scales(1e-6).unwrap();
    assert!(far
        .evaluate_scaled(&s, 0.0, 0.0, &mut TaborHistory::default())
        .map(|f| out = f)
        .is_err());
}

#[test]
fn prepare_covers_the_radii_and_reports_the_reach() {
    let law = range_law(1e-6, 2e-10);
    let built = law.prepare_radii(1e-7, 1e-6).unwrap();
    // a factor 10 in R* is a factor 10^(1/3) in Λ: ln(2.154)/q + 6 stencil nodes
    let expected = (10f64.cbrt().ln() / q()).ceil() as usize + 7;
    assert!(built <= expected + 1, "{built} nodes for a factor 10 in R*");
    let reach = law.interaction_range_over(1e-7, 1e-6).unwrap();
    assert!(reach >= 2e-10);
    for r in [1e-7, 3e-7, 1e-6] {
        let s = law.scales(r).unwrap();
        assert!(law.interaction_range_at(&s) <= reach);
    }
}
