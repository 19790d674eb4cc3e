#![allow(clippy::unwrap_used, clippy::expect_used)]
//! The closed forms of tabor-elastic against the seed's formulas written out
//! literally (an independent transcription), quadrature, and limits.

use proptest::prelude::*;
use std::f64::consts::PI;
use tabor_elastic::trajectory::{
    harmonic_normalized_time, normalized_contact_time, normalized_time,
};
use tabor_elastic::{ElasticContact, ElasticImpact};
use tabor_numerics::quadrature::{integrate_singular_by_distance, QuadTolerance};
use tabor_numerics::special::{beta, incomplete_beta, power_law_beta};
use tabor_restitution::{impact, ElasticMaterial, Error, ImpactModel};

fn rel(a: f64, b: f64) -> f64 {
    ((a - b) / b).abs()
}

/// The normalized contact time of a power-law impact from (5.10) and (5.15)
/// directly, without the Beta function: `v0 T_S / d_max = 2 ∫₀¹ dx / √(1 − x^q)`,
/// q = (2n+1)/n, by a tanh-sinh rule written out here (independent of `statrs`,
/// which the crate's closed form (5.18) uses). The square root near x = 1 is taken
/// from the distance s = 1 − x, 1 − (1 − s)^q = −expm1(q ln1p(−s)), so there is no
/// cancellation; step 1/64 on |t| ≤ 4 (converged to rounding: halving the step
/// changes nothing beyond 1e-15).
fn contact_time_by_quadrature(n: f64) -> f64 {
    let q = (2.0 * n + 1.0) / n;
    let h = 1.0 / 64.0;
    let mut sum = 0.0;
    for k in -256..=256 {
        let t = f64::from(k) * h;
        let u = 0.5 * PI * t.sinh();
        // x = (1 + tanh u)/2 and its complement, each without cancellation.
        let x = 1.0 / (1.0 + (-2.0 * u).exp());
        let s = 1.0 / (1.0 + (2.0 * u).exp());
        let weight = 0.25 * PI * t.cosh() / u.cosh().powi(2);
        let gap = if x < 0.5 {
            1.0 - x.powf(q)
        } else {
            -(q * (-s).ln_1p()).exp_m1()
        };
        if gap > 0.0 && weight > 0.0 {
            sum += weight / gap.sqrt();
        }
    }
    2.0 * h * sum
}

/// Seed 000 (5.8), literally.
fn hertz_d_max(m: f64, v: f64, e: f64, r: f64) -> f64 {
    (15.0 * m * v * v / (16.0 * e * r.sqrt())).powf(0.4)
}

#[test]
fn hertz_closed_forms_match_the_seed_literally() {
    // Micron silica spheres (README example): E* = 27.8 GPa, R = 0.5 µm,
    // m = 5.55e-15 kg, v0 = 1 m/s. Tolerance 1e-13 relative.
    let (e, r, m, v) = (27.803521779425392e9, 5e-7, 5.550147021341967e-15, 1.0);
    let imp = ElasticImpact::new(ElasticContact::hertz(e, r).unwrap(), m).unwrap();
    let d_max = hertz_d_max(m, v, e, r);
    assert!(rel(imp.max_overlap(v).unwrap(), d_max) < 1e-13);
    // (5.9), both forms.
    let f_max = (125.0 / 36.0 * m.powi(3) * v.powi(6) * r * e * e).powf(0.2);
    assert!(rel(imp.max_force(v).unwrap(), f_max) < 1e-13);
    assert!(rel(4.0 / 3.0 * e * (r * d_max.powi(3)).sqrt(), f_max) < 1e-13);
    // (5.12)
    let t_s = 4.0 * d_max / (5.0 * v) * beta(0.4, 0.5).unwrap();
    assert!(rel(imp.contact_time(v).unwrap(), t_s) < 1e-13);
    // Textbook form T_S ≈ 2.868 (m²/(E*² R v0))^(1/5).
    let t_s_textbook = 2.868 * (m * m / (e * e * r * v)).powf(0.2);
    assert!(rel(t_s, t_s_textbook) < 1e-3);
    // (5.13), both forms.
    let p_max = 2.0 / PI * (15.0 * e.powi(4) * m * v * v / (16.0 * r.powi(3))).powf(0.2);
    assert!(rel(imp.max_pressure(v).unwrap(), p_max) < 1e-13);
    assert!(rel(2.0 * e / PI * (d_max / r).sqrt(), p_max) < 1e-13);
    // (5.26)
    let a_max = (15.0 * m * v * v * r * r / (16.0 * e)).powf(0.2);
    assert!(rel(imp.max_contact_radius(v).unwrap(), a_max) < 1e-13);
    // (5.11) at d_max/2.
    let xi = 0.5f64.powf(2.5);
    let t_half = 2.0 * d_max / (5.0 * v) * incomplete_beta(xi, 0.4, 0.5).unwrap();
    assert!(rel(imp.time_at_overlap(v, 0.5 * d_max).unwrap(), t_half) < 1e-13);
    assert_eq!(imp.time_at_overlap(v, 0.0).unwrap(), 0.0);
    // At the turning point t(d) has a square-root sensitivity (one ulp in d moves t
    // by ~1e-8 relative), so use the crate's own d_max here.
    let t_top = imp.time_at_overlap(v, imp.max_overlap(v).unwrap()).unwrap();
    assert!(rel(t_top, 0.5 * t_s) < 1e-12, "{t_top} vs {}", 0.5 * t_s);
}

#[test]
fn inverse_trajectory_equals_quadrature_of_the_separated_equation() {
    // (5.10): t(d) = ∫₀ᵈ dd' / (v0 √(1 − U(d')/(m v0²/2))), by tanh-sinh quadrature
    // (independent of the incomplete beta function). Tolerance 1e-9 relative.
    let contacts = [
        ElasticContact::hertz(1e9, 1e-3).unwrap(),
        ElasticContact::power_law(2e8, 3.0, 1.0).unwrap(),
        ElasticContact::power_law(2e8, 1e4, 3.5).unwrap(),
        ElasticContact::graded_sphere(5e11, 0.4, 2e-3).unwrap(),
        ElasticContact::graded_power_law(3e7, -0.6, 50.0, 1.5).unwrap(),
    ];
    for c in contacts {
        let imp = ElasticImpact::new(c, 1e-3).unwrap();
        let v = 0.7;
        let w = 0.5 * 1e-3 * v * v;
        let d_max = imp.max_overlap(v).unwrap();
        assert!(rel(c.stored_energy(d_max), w) < 1e-12, "{}", c.name());
        let q1 = c.force_exponent() + 1.0;
        for frac in [0.2, 0.7, 1.0] {
            let d = frac * d_max;
            // Below d_max with the stored energy; up to d_max with the distance
            // δ = d_max − x, 1 − U/w = 1 − (1 − δ/d_max)^(q+1) without cancellation.
            let q = integrate_singular_by_distance(
                |x, _, db| {
                    let gap = if frac < 1.0 {
                        1.0 - c.stored_energy(x) / w
                    } else {
                        -((q1 * (-db / d_max).ln_1p()).exp_m1())
                    };
                    1.0 / (v * gap.sqrt())
                },
                0.0,
                d,
                QuadTolerance::relative(1e-12),
            )
            .unwrap();
            let t = imp.time_at_overlap(v, d).unwrap();
            assert!(
                rel(t, q.value) < 1e-9,
                "{} at {frac}: {t} vs {}",
                c.name(),
                q.value
            );
        }
    }
}

#[test]
fn force_law_is_the_derivative_of_the_stored_energy_and_matches_contact_relations() {
    // F = dU/dd by central differences (1e-7 relative) and F = 2E n/(n+1) β A a^(n+1),
    // d = β A aⁿ (exact to 1e-13) for homogeneous power laws.
    for &(e, a_pref, n) in &[(1e9, 2.0, 1.0), (3e10, 0.5 / 1e-3, 2.0), (5e6, 7.0, 4.5)] {
        let c = ElasticContact::power_law(e, a_pref, n).unwrap();
        let beta_n = power_law_beta(n).unwrap();
        for &d in &[1e-9, 1e-6, 1e-4] {
            let h = 1e-5 * d;
            let dudd = (c.stored_energy(d + h) - c.stored_energy(d - h)) / (2.0 * h);
            assert!(rel(dudd, c.force(d)) < 1e-7);
            let a = c.contact_radius(d);
            assert!(rel(beta_n * a_pref * a.powf(n), d) < 1e-13);
            let f = 2.0 * e * n / (n + 1.0) * beta_n * a_pref * a.powf(n + 1.0);
            assert!(rel(c.force(d), f) < 1e-12);
            // dF/dd = 2 E a for homogeneous media.
            assert!(rel(c.stiffness(d), 2.0 * e * a) < 1e-12);
        }
    }
    // Graded sphere (5.20): U = 8 c/((3+k)(5+k)) √((1+k)^(k−1) R^(1+k) d^(5+k)),
    // a² = (1+k) R d.
    for &(cn, k, r) in &[(1e12, 0.5, 1e-3), (2e8, -0.5, 1e-2), (1e9, 0.0, 1e-4)] {
        let c = ElasticContact::graded_sphere(cn, k, r).unwrap();
        let d: f64 = 3e-7;
        let u = 8.0 * cn / ((3.0 + k) * (5.0 + k))
            * ((1.0 + k).powf(k - 1.0) * r.powf(1.0 + k) * d.powf(5.0 + k)).sqrt();
        assert!(rel(c.stored_energy(d), u) < 1e-12);
        assert!(rel(c.contact_radius(d).powi(2), (1.0 + k) * r * d) < 1e-12);
        assert!(rel(c.profile_factor(), 2.0 / (1.0 + k)) < 1e-12);
    }
    // Out of contact: no force.
    let c = ElasticContact::hertz(1e9, 1e-3).unwrap();
    assert_eq!(c.force(-1e-6), 0.0);
    assert_eq!(c.contact_radius(0.0), 0.0);
    assert!(c.force(f64::NAN).is_nan());
}

#[test]
fn graded_sphere_closed_forms_match_the_seed_literally() {
    // (5.21), (5.23), (5.24) written out; tolerance 1e-12 relative.
    for &(cn, k, r, m, v) in &[
        (1e12, 0.5, 1e-3, 1e-3, 0.3),
        (2e8, -0.5, 1e-2, 2e-2, 5.0),
        (4e10, 0.9, 1e-5, 1e-9, 1e-2),
        (3e9, -0.9, 1e-4, 1e-7, 1.0),
    ] {
        let imp = ElasticImpact::new(ElasticContact::graded_sphere(cn, k, r).unwrap(), m).unwrap();
        let d_max = ((3.0 + k) * (5.0 + k) * m * v * v
            / (16.0 * cn * ((1.0f64 + k).powf(k - 1.0) * r.powf(1.0 + k)).sqrt()))
        .powf(2.0 / (5.0 + k));
        assert!(rel(imp.max_overlap(v).unwrap(), d_max) < 1e-12, "k = {k}");
        let t_s = 4.0 * d_max / ((5.0 + k) * v) * beta(2.0 / (5.0 + k), 0.5).unwrap();
        assert!(rel(imp.contact_time(v).unwrap(), t_s) < 1e-12);
        let xi = 0.3f64.powf((5.0 + k) / 2.0);
        let t = 2.0 * d_max / ((5.0 + k) * v) * incomplete_beta(xi, 2.0 / (5.0 + k), 0.5).unwrap();
        assert!(rel(imp.time_at_overlap(v, 0.3 * d_max).unwrap(), t) < 1e-12);
        let p_max = 2.0 / PI
            * cn.powf(4.0 / (5.0 + k))
            * r.powf((k - 3.0) / (5.0 + k))
            * (1.0 + k).powf((k - 7.0) / (5.0 + k))
            * (m * v * v * (3.0 + k) * (5.0 + k) / 16.0).powf((1.0 + k) / (5.0 + k));
        let p = imp.max_pressure(v).unwrap();
        assert!(rel(p, p_max) < 1e-12);
        // Independent path: the graded Hertz pressure p(r) = p0 (1 − r²/a²)^((1+k)/2)
        // carries F = 2π p0 a²/(3+k), so p0 = (3+k) F/(2π a²).
        let f = imp.max_force(v).unwrap();
        let a = imp.max_contact_radius(v).unwrap();
        assert!(
            rel(p, (3.0 + k) * f / (2.0 * PI * a * a)) < 1e-12,
            "k = {k}"
        );
        // (5.25)-(5.26): the ratio to the homogeneous pressure with E = E* (any E*).
        let e = 7e9;
        let hom = ElasticImpact::new(ElasticContact::hertz(e, r).unwrap(), m).unwrap();
        let a0 = (15.0 * m * v * v * r * r / (16.0 * e)).powf(0.2);
        let ratio = (cn / e).powf(4.0 / (5.0 + k))
            * a0.powf(4.0 * k / (5.0 + k))
            * (1.0 + k).powf((k - 7.0) / (5.0 + k))
            * ((3.0 + k) * (5.0 + k) / 15.0).powf((1.0 + k) / (5.0 + k));
        assert!(rel(p / hom.max_pressure(v).unwrap(), ratio) < 1e-12);
    }
}

#[test]
fn power_law_closed_forms_match_the_seed_literally() {
    // (5.16), (5.18) homogeneous; (5.28), (5.30) graded; tolerance 1e-12.
    for &(e, a, n, m, v) in &[(1e9, 2.0, 1.0, 1e-3, 1.0), (5e7, 1e5, 3.0, 1e-6, 0.1)] {
        let imp = ElasticImpact::new(ElasticContact::power_law(e, a, n).unwrap(), m).unwrap();
        let b = power_law_beta(n).unwrap();
        let d_max = ((b * a).powf(1.0 / n) * (2.0 * n + 1.0) * (n + 1.0) * m * v * v
            / (4.0 * n * n * e))
            .powf(n / (2.0 * n + 1.0));
        assert!(rel(imp.max_overlap(v).unwrap(), d_max) < 1e-12);
        let p = n / (2.0 * n + 1.0);
        let t_s = 2.0 * p * d_max / v * beta(p, 0.5).unwrap();
        assert!(rel(imp.contact_time(v).unwrap(), t_s) < 1e-12);
        assert!(matches!(imp.max_pressure(v), Err(Error::Model { .. })));
    }
    for &(c, k, a, n, m, v) in &[
        (1e12, 0.5, 2.0, 1.0, 1e-3, 1.0),
        (5e7, -0.3, 1e5, 3.0, 1e-6, 0.1),
    ] {
        let contact = ElasticContact::graded_power_law(c, k, a, n).unwrap();
        let imp = ElasticImpact::new(contact, m).unwrap();
        let b = contact.profile_factor();
        let s = 2.0 * n + k + 1.0;
        let d_max = ((b * a).powf((1.0 + k) / n) * s * (n + k + 1.0) * (1.0 + k) * m * v * v
            / (4.0 * n * n * c))
            .powf(n / s);
        assert!(rel(imp.max_overlap(v).unwrap(), d_max) < 1e-12);
        let t_s = 2.0 * n / s * d_max / v * beta(n / s, 0.5).unwrap();
        assert!(rel(imp.contact_time(v).unwrap(), t_s) < 1e-12);
        // (5.29) at d = 0.6 d_max.
        let t = n / s * d_max / v * incomplete_beta(0.6f64.powf(s / n), n / s, 0.5).unwrap();
        assert!(rel(imp.time_at_overlap(v, 0.6 * d_max).unwrap(), t) < 1e-12);
    }
    // β(2, k) = 2/(1+k): the graded power law with n = 2, A = 1/(2R) is the graded sphere.
    let gs = ElasticContact::graded_sphere(1e10, 0.3, 1e-3).unwrap();
    let gp = ElasticContact::graded_power_law(1e10, 0.3, 500.0, 2.0).unwrap();
    assert!(rel(gs.force(1e-6), gp.force(1e-6)) < 1e-12);
}

#[test]
fn normalized_trajectory_and_its_limits() {
    // T̂_S(2) = (4/5) B(2/5, 1/2); π in the limit ñ → ∞ (5.19).
    assert!(
        rel(
            normalized_contact_time(2.0).unwrap(),
            0.8 * beta(0.4, 0.5).unwrap()
        ) < 1e-14
    );
    let big = normalized_contact_time(1e6).unwrap();
    assert!((big - PI).abs() < 1e-5, "{big}");
    // (5.19): B(z²; 1/2, 1/2) = 2 arcsin z.
    for &z in &[0.1, 0.5, 0.9, 1.0] {
        let b = incomplete_beta(z * z, 0.5, 0.5).unwrap();
        assert!((b - 2.0 * harmonic_normalized_time(z).unwrap()).abs() < 1e-12);
    }
    // Convergence to the harmonic curve: |t̂(d̂; ñ) − arcsin d̂| ≤ 2/ñ on a grid
    // (the difference is O(1/ñ)).
    for &n in &[20.0, 200.0, 2000.0] {
        for j in 0..=20 {
            let d = j as f64 / 20.0;
            let diff = (normalized_time(d, n).unwrap() - d.asin()).abs();
            assert!(diff <= 2.0 / n, "ñ = {n}, d̂ = {d}: {diff}");
        }
    }
    // (5.18) for n = 1, 2, 5 against the quadrature of (5.10)/(5.15) (1e-12
    // relative). Exact: cone 2.8044 = 0.893 π (Γ(1/3)Γ(1/2)/Γ(5/6)·2/3 with the
    // DLMF values of Γ, 1e-12), parabola 2.9433, n = 5 3.0528 = 0.972 π; the profile barely
    // matters (Abb. 5.1).
    for &n in &[1.0, 2.0, 5.0] {
        let t = normalized_contact_time(n).unwrap();
        let exact = contact_time_by_quadrature(n);
        println!(
            "n = {n}: T̂_S = {t:.15} (quadrature {exact:.15}), {:.4} π",
            t / PI
        );
        assert!(rel(t, exact) < 1e-12, "{n}: {t} vs {exact}");
    }
    let cone = 2.0 / 3.0 * 2.678_938_534_707_748 * PI.sqrt() / 1.128_787_029_908_126;
    assert!(rel(contact_time_by_quadrature(1.0), cone) < 1e-12);
}

#[test]
fn hunter_approximation_is_close_and_exact_at_the_ends() {
    // (5.14): equals d_max at T_S/2 and 0 at the ends; within 3 % of d_max of the
    // exact Hertz trajectory (Hunter's approximation is good to a few per cent).
    let imp = ElasticImpact::new(ElasticContact::hertz(1e10, 1e-3).unwrap(), 1e-2).unwrap();
    let v = 0.5;
    let d_max = imp.max_overlap(v).unwrap();
    let t_s = imp.contact_time(v).unwrap();
    assert!(rel(imp.hunter_overlap(v, 0.5 * t_s).unwrap(), d_max) < 1e-14);
    assert!(imp.hunter_overlap(v, t_s).unwrap().abs() < 1e-12 * d_max);
    for j in 1..10 {
        let d = j as f64 / 10.0 * d_max;
        let t = imp.time_at_overlap(v, d).unwrap();
        let approx = imp.hunter_overlap(v, t).unwrap();
        assert!((approx - d).abs() < 0.03 * d_max, "{j}: {approx} vs {d}");
    }
}

#[test]
fn impact_model_is_lossless_and_from_materials() {
    let steel = ElasticMaterial::new(210e9, 0.3).unwrap();
    let c = ElasticContact::hertz_between(&steel, &steel, 1e-3, Some(1e-3)).unwrap();
    let e_star = 210e9 / (2.0 * (1.0 - 0.09));
    assert!(rel(c.modulus_coefficient(), e_star) < 1e-14);
    let imp = ElasticImpact::new(c, 1e-3).unwrap();
    let out = impact(&imp, 2.0).unwrap();
    assert_eq!(out.restitution, 1.0);
    assert_eq!(out.energy_loss, 0.0);
    assert!(!out.sticks);
    assert!(imp.loss_is_speed_independent());
}

#[test]
fn invalid_inputs_are_named_errors() {
    let name = |e: Error| match e {
        Error::InvalidParameter { parameter, .. } => parameter,
        other => panic!("{other:?}"),
    };
    assert_eq!(
        name(ElasticContact::hertz(-1.0, 1e-3).unwrap_err()),
        "effective_modulus"
    );
    assert_eq!(
        name(ElasticContact::hertz(1e9, f64::NAN).unwrap_err()),
        "effective_radius"
    );
    assert_eq!(
        name(ElasticContact::hertz(1e9, 0.0).unwrap_err()),
        "effective_radius"
    );
    assert_eq!(
        name(ElasticContact::power_law(1e9, 1.0, 0.0).unwrap_err()),
        "profile_exponent"
    );
    assert_eq!(
        name(ElasticContact::power_law(1e9, f64::INFINITY, 2.0).unwrap_err()),
        "profile_prefactor"
    );
    for k in [-1.0, 1.0, 1.5, f64::NAN] {
        assert_eq!(
            name(ElasticContact::graded_sphere(1e9, k, 1e-3).unwrap_err()),
            "gradation_exponent"
        );
    }
    assert_eq!(
        name(ElasticContact::graded_power_law(0.0, 0.2, 1.0, 2.0).unwrap_err()),
        "gradation_coefficient"
    );
    let c = ElasticContact::hertz(1e9, 1e-3).unwrap();
    assert_eq!(
        name(ElasticImpact::new(c, -1.0).unwrap_err()),
        "effective_mass"
    );
    let imp = ElasticImpact::new(c, 1e-3).unwrap();
    for v in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(name(imp.max_overlap(v).unwrap_err()), "impact_speed");
        assert_eq!(name(imp.contact_time(v).unwrap_err()), "impact_speed");
        assert_eq!(name(imp.energy_loss(v).unwrap_err()), "impact_speed");
    }
    let d_max = imp.max_overlap(1.0).unwrap();
    assert_eq!(
        name(imp.time_at_overlap(1.0, 2.0 * d_max).unwrap_err()),
        "overlap"
    );
    assert_eq!(
        name(imp.time_at_overlap(1.0, -1e-9).unwrap_err()),
        "overlap"
    );
    assert_eq!(
        name(normalized_time(1.5, 2.0).unwrap_err()),
        "normalized_overlap"
    );
    assert_eq!(
        name(normalized_time(0.5, -2.0).unwrap_err()),
        "equivalent_exponent"
    );
    // Overflowing combinations are errors, not infinities.
    assert!(ElasticContact::power_law(1e9, 1e-300, 1e-3).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig { cases: std::env::var("PROPTEST_CASES").ok().and_then(|s| s.parse().ok()).unwrap_or(64), ..ProptestConfig::default() })]

    #[test]
    fn hertz_d_max_over_decades(
        log_e in 6.0f64..12.0, log_r in -7.0f64..-1.0, log_m in -15.0f64..0.0, log_v in -4.0f64..2.0,
    ) {
        let (e, r, m, v) = (10f64.powf(log_e), 10f64.powf(log_r), 10f64.powf(log_m), 10f64.powf(log_v));
        let imp = ElasticImpact::new(ElasticContact::hertz(e, r).unwrap(), m).unwrap();
        prop_assert!(rel(imp.max_overlap(v).unwrap(), hertz_d_max(m, v, e, r)) < 1e-12);
        let t_s = imp.contact_time(v).unwrap();
        // (5.12) with d_max of (5.8) and the Beta function by quadrature.
        let t_exact = contact_time_by_quadrature(2.0) * hertz_d_max(m, v, e, r) / v;
        prop_assert!(rel(t_s, t_exact) < 1e-12, "{} vs {}", t_s, t_exact);
        // Graded medium with k = 0 and c_N = E* is Hertz.
        let g = ElasticImpact::new(ElasticContact::graded_sphere(e, 0.0, r).unwrap(), m).unwrap();
        prop_assert!(rel(g.contact_time(v).unwrap(), t_s) < 1e-12);
        prop_assert!(rel(g.max_pressure(v).unwrap(), imp.max_pressure(v).unwrap()) < 1e-12);
    }
}
