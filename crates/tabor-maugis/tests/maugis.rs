//! Tests of the Maugis-Dugdale impact against independent paths: a second
//! derivation in mpmath, direct quadrature along the no-contact branch, the JKR
//! limit, continuity at the case boundaries, and the physical-unit front.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::excessive_precision)]

use approx::assert_relative_eq;
use proptest::prelude::*;
use std::f64::consts::PI;
use tabor_jkr::JkrSphere;
use tabor_maugis::branch::{
    contact_state, junction_factor, no_contact_pull_off_radius, no_contact_state,
};
use tabor_maugis::units::{
    maugis_parameter, tabor_parameter_from_cohesive_stress, tabor_parameter_from_maugis,
    tabor_parameter_from_range, tabor_parameter_from_tabor_mu, JkrScales,
};
use tabor_maugis::*;
use tabor_numerics::quadrature::integrate_smooth;
use tabor_numerics::QuadTolerance;
use tabor_restitution::{impact, sticking_velocity, ImpactModel, StickingMethod};

/// W(Λ)/W_JKR from `tests/reference/md_reference.py`: mpmath at 30-40 digits, the
/// contact branch parametrized by â (not θ), b̂ by bisection of the gap condition
/// with arccos (at 30 + 2 log10 Λ digits, so arccos near 1 costs nothing there),
/// dd̂/dâ by numerical differentiation, tanh-sinh quadrature. Covers every case and
/// the whole accuracy range Λ ∈ [1e-3, 1e4] of the direct evaluation.
const REFERENCE: [(f64, f64); 16] = [
    (0.01, 5.959_487_568_159_266_2e-10),
    (0.3, 0.014_481_554_790_627_017),
    (0.45, 0.109_969_173_715_353_83),
    (0.5, 0.174_004_152_683_569_64),
    (0.55, 0.236_545_169_834_087_40),
    (0.6, 0.295_696_926_668_501_26),
    (0.64, 0.341_278_877_683_137_26),
    (0.65, 0.352_449_037_394_422_71),
    (0.7, 0.402_186_968_573_521_4),
    (1.0, 0.583_728_265_550_754_22),
    (2.0, 0.785_906_781_316_458_88),
    (4.0, 0.889_801_363_884_569_87),
    (10.0, 0.954_987_251_621_391_89),
    (100.0, 0.995_438_807_056_853_74),
    (1e3, 0.999_543_272_426_684_67),
    (1e4, 0.999_954_321_153_915_64),
];

#[test]
fn boundaries_and_constants() {
    assert_relative_eq!(
        LAMBDA_1,
        (3.0 * PI.powi(3) / 1024.0).cbrt(),
        max_relative = 1e-15
    );
    assert_relative_eq!(
        LAMBDA_2,
        (3.0 * PI.powi(4) / (512.0 * (PI - 1.0))).cbrt(),
        max_relative = 1e-15
    );
    // K = 2 at Λ1 (case 1 needs b̂0 = 2 b̂_c on the no-contact branch), K = 1 at Λ2
    assert_relative_eq!(junction_factor(LAMBDA_1), 2.0, max_relative = 1e-14);
    assert_relative_eq!(junction_factor(LAMBDA_2), 1.0, max_relative = 1e-14);
    // (5.36) over F_n d_n, and the prefactor of (5.43) is its inverse
    let w_jkr = 0.1 * (1.0 + 864f64.cbrt()) / (3.0 * 3f64.cbrt() / 8.0);
    assert_relative_eq!(jkr_normalized_loss(), w_jkr, max_relative = 1e-15);
    assert_relative_eq!(
        15.0 * 3f64.cbrt() / (4.0 * (1.0 + 864f64.cbrt())),
        1.0 / jkr_normalized_loss(),
        max_relative = 1e-15
    );
    assert_eq!(TaborCase::of(LAMBDA_1).number(), 1);
    assert_eq!(TaborCase::of(LAMBDA_2).number(), 2);
    assert_eq!(TaborCase::of(0.5).number(), 2);
    assert_eq!(TaborCase::of(0.7).number(), 3);
}

#[test]
fn matches_independent_high_precision_reference() {
    for (lambda, reference) in REFERENCE {
        let w = normalized_loss(lambda, 1e-12).unwrap();
        assert_relative_eq!(w.loss_over_jkr, reference, max_relative = 1e-12);
        assert!(w.error_estimate <= 1e-12 * w.loss, "Λ={lambda}: {w:?}");
    }
}

#[test]
fn case_1_closed_form_equals_quadrature_on_the_branch() {
    // (5.44) against ∫ F̂ dd̂ along the no-contact branch from b̂0 = 2b̂_c to b̂_c
    for lambda in [1e-3, 0.05, 0.2, 0.4, LAMBDA_1] {
        let bc = no_contact_pull_off_radius(lambda);
        let integrand = |b: f64| {
            let s = no_contact_state(lambda, b);
            s.force * (3.0 * b - 32.0 * lambda / (PI * PI))
        };
        let q = integrate_smooth(integrand, 2.0 * bc, bc, QuadTolerance::relative(1e-14)).unwrap();
        let closed = normalized_loss(lambda, 1e-12).unwrap();
        assert_eq!(closed.case, TaborCase::NoContact);
        assert_relative_eq!(closed.loss, q.value, max_relative = 1e-13);
        assert_relative_eq!(
            closed.loss,
            17.0 * 2f64.powi(19) * lambda.powi(5) / (81.0 * PI.powi(8)),
            max_relative = 1e-14
        );
    }
}

#[test]
fn case_2_closed_part_equals_quadrature_on_the_branch() {
    // the no-contact part (5.46) against quadrature from b̂ = K b̂_c to b̂_c
    for lambda in [0.46, 0.5, 0.6, 0.64] {
        let bc = no_contact_pull_off_radius(lambda);
        let k = junction_factor(lambda);
        let integrand =
            |b: f64| no_contact_state(lambda, b).force * (3.0 * b - 32.0 * lambda / (PI * PI));
        let q = integrate_smooth(integrand, k * bc, bc, QuadTolerance::relative(1e-14)).unwrap();
        let seed = 2f64.powi(19) * lambda.powi(5) * (3.0 * k.powi(4) - 4.0 * k.powi(3) + 1.0)
            / (81.0 * PI.powi(8));
        assert_relative_eq!(q.value, seed, max_relative = 1e-12);
        // and the contact part is the rest: the junction state is continuous
        let at_junction = contact_state(lambda, PI / 2.0);
        let nc = no_contact_state(lambda, k * bc);
        assert_relative_eq!(at_junction.cohesive_radius, k * bc, max_relative = 1e-14);
        assert_relative_eq!(at_junction.depth, nc.depth, max_relative = 1e-13);
        assert_relative_eq!(at_junction.force, nc.force, max_relative = 1e-13);
    }
}

#[test]
fn continuous_at_the_case_boundaries() {
    for boundary in [LAMBDA_1, LAMBDA_2] {
        let at = normalized_loss(boundary, 1e-14).unwrap().loss;
        for delta in [1e-3, 1e-6, 1e-9, 1e-12] {
            let below = normalized_loss(boundary * (1.0 - delta), 1e-14)
                .unwrap()
                .loss;
            let above = normalized_loss(boundary * (1.0 + delta), 1e-14)
                .unwrap()
                .loss;
            // |dW/dΛ| ≲ 3 near both boundaries
            let bound = 4.0 * delta * boundary + 1e-14;
            assert!(
                (above - at).abs() <= bound && (at - below).abs() <= bound,
                "Λb={boundary} δ={delta}: {below} {at} {above}"
            );
            assert!(below <= at && at <= above);
        }
    }
}

#[test]
fn jkr_limit_and_its_asymptote() {
    // W/W_JKR → 1 as 1 − c/Λ + O(Λ⁻²)
    let c = |lambda: f64| lambda * (1.0 - normalized_loss(lambda, 1e-14).unwrap().loss_over_jkr);
    let (c2, c3, c4, c5) = (c(1e2), c(1e3), c(1e4), c(1e5));
    assert!((c3 - c2) > 0.0 && (c4 - c3) > 0.0 && (c5 - c4) > 0.0);
    // the O(Λ⁻²) term makes c(Λ) converge by a factor 10 per decade
    for ratio in [(c3 - c2) / (c4 - c3), (c4 - c3) / (c5 - c4)] {
        assert!((ratio - 10.0).abs() < 0.5, "ratio {ratio}");
    }
    // c(Λ) against the mpmath reference (1 − W/W_JKR there is known to ~1e-20, here
    // to ~Λ·1e-16), and the limit c(∞) by Richardson extrapolation of the reference
    // values at 1e3 and 1e4: c(∞) = c4 + (c4 − c3)/9 = 0.456795226…
    let reference_c = |lambda: f64| {
        let r = REFERENCE.iter().find(|(l, _)| *l == lambda).unwrap().1;
        lambda * (1.0 - r)
    };
    for (lambda, value) in [(1e2, c2), (1e3, c3), (1e4, c4)] {
        assert_relative_eq!(value, reference_c(lambda), max_relative = 1e-11);
    }
    // (its own error is the O(Λ⁻³) term: ~7e-9, from the same extrapolation of 1e2
    // and 1e3, which is 6.6e-8 lower)
    let c_limit = reference_c(1e4) + (reference_c(1e4) - reference_c(1e3)) / 9.0;
    assert_relative_eq!(c_limit, 0.456_795_226, max_relative = 1e-9);
    assert_relative_eq!(c5 + (c5 - c4) / 9.0, c_limit, max_relative = 1e-7);
    // the branch itself tends to JKR: F̂ = â³ − 2â^(3/2), d̂ = 3â² − 4â^(1/2)
    let lambda = 1e7;
    for theta in [1e-8, 3e-8, 1e-7] {
        let s = contact_state(lambda, theta);
        let a = s.contact_radius;
        assert_relative_eq!(
            s.force,
            a.powi(3) - 2.0 * a.powf(1.5),
            max_relative = 1e-5,
            epsilon = 1e-6
        );
        assert_relative_eq!(
            s.depth,
            3.0 * a * a - 4.0 * a.sqrt(),
            max_relative = 1e-5,
            epsilon = 1e-6
        );
    }
}

#[test]
fn below_jkr_increasing_and_the_seed_claim_at_4() {
    let mut previous = 0.0;
    for i in 0..=400 {
        let lambda = 1e-3 * 10f64.powf(i as f64 * 7.0 / 400.0); // 1e-3 … 1e4
        let r = normalized_loss(lambda, 1e-12).unwrap().loss_over_jkr;
        assert!(r.is_finite() && r > previous && r < 1.0, "Λ={lambda} r={r}");
        previous = r;
    }
    // Λ = 4 (Tabor's μ ≈ 5): JKR overestimates the loss by more than 10 %
    assert!(normalized_loss(4.0, 1e-12).unwrap().loss_over_jkr < 0.9);
}

#[test]
fn hard_regions_stay_finite_and_accurate() {
    for lambda in [1e-4, 1e-3, 1e5, 1e6] {
        let w = normalized_loss(lambda, 1e-12).unwrap();
        assert!(w.loss.is_finite() && w.loss > 0.0);
    }
    // tiny Λ: full relative accuracy of the ~Λ⁵ loss
    let w = normalized_loss(1e-3, 1e-12).unwrap();
    assert_relative_eq!(
        w.loss,
        17.0 * 2f64.powi(19) * 1e-15 / (81.0 * PI.powi(8)),
        max_relative = 1e-14
    );
}

#[test]
fn beyond_the_quadrature_range_the_jkr_limit_is_exact_to_rounding() {
    // from LAMBDA_JKR_LIMIT on the loss is W_JKR: continuous there (the direct
    // evaluation just below agrees to its rounding), below or at 1 up to f64::MAX
    // (the θ-branch alone gave ratios of 1 + 1.3e-15 and, from Λ ≈ 1e77, an error)
    let just_below = normalized_loss(LAMBDA_JKR_LIMIT * (1.0 - 1e-12), 1e-12).unwrap();
    assert!(just_below.method.contains("quadrature"), "{just_below:?}");
    assert!(
        (just_below.loss_over_jkr - 1.0).abs() <= 2e-15,
        "{just_below:?}"
    );
    for lambda in [LAMBDA_JKR_LIMIT, 1e20, 1e77, 1e154, 1e300, f64::MAX] {
        let w = normalized_loss(lambda, 1e-12).unwrap();
        assert_eq!(w.case, TaborCase::Contact);
        assert_eq!(w.loss_over_jkr, 1.0, "Λ = {lambda:e}");
        assert_eq!(w.loss, jkr_normalized_loss());
        // the neglected 0.4568/Λ
        assert!(w.error_estimate >= 0.4568 / lambda * w.loss, "{w:?}");
        let fast = loss_over_jkr_fast(lambda).unwrap();
        assert!(fast <= 1.0 && 1.0 - fast <= 1e-15, "Λ = {lambda:e}: {fast}");
    }
    for lambda in [1e5, 1e8, 1e12, 1e15] {
        let fast = loss_over_jkr_fast(lambda).unwrap();
        // 1 − c/Λ + O(Λ⁻²), c(∞) = 0.456795226 (jkr_limit_and_its_asymptote)
        let expected = 1.0 - 0.456_795_226 / lambda;
        assert!(fast < 1.0 || lambda >= 1e15, "Λ = {lambda:e}: {fast}");
        let bound = 1.0 / (lambda * lambda) + 1e-15;
        assert!((fast - expected).abs() <= bound, "Λ = {lambda:e}: {fast}");
    }
}

#[test]
fn fast_tier_agrees_with_direct() {
    let cost = prepare_fast_tier().unwrap();
    assert!(cost.evaluations > 0);
    let mut worst: f64 = 0.0;
    let mut check = |lambda: f64| {
        let direct = normalized_loss(lambda, 1e-14).unwrap().loss_over_jkr;
        let fast = loss_over_jkr_fast(lambda).unwrap();
        worst = worst.max((fast / direct - 1.0).abs());
    };
    for i in 0..=2000 {
        check(1e-3 * 10f64.powf(i as f64 * 7.0 / 2000.0));
    }
    for b in [LAMBDA_1, LAMBDA_2] {
        for d in [1e-12, 1e-9, 1e-6, 1e-3] {
            check(b * (1.0 + d));
            check(b * (1.0 - d));
        }
    }
    for lambda in [1e5, 1e6, 1e8] {
        check(lambda);
    }
    eprintln!(
        "fast tier worst relative error {worst:e}, pieces {:?}",
        fast_tier_pieces().unwrap()
    );
    assert!(worst <= FAST_TIER_RELATIVE_ERROR, "worst {worst:e}");
    assert!(loss_over_jkr_fast(f64::INFINITY).is_err());
}

#[test]
fn conversions_into_lambda_agree() {
    let (e, r, w, s0) = (3e10, 2e-6, 0.04, 4e8);
    let from_stress = tabor_parameter_from_cohesive_stress(s0, w, e, r).unwrap();
    let from_range = tabor_parameter_from_range(w / s0, w, e, r).unwrap();
    assert_relative_eq!(from_stress, from_range, max_relative = 1e-14);
    // Maugis' λ from its own definition λ = 2σ0 (R/(πΔγK²))^(1/3), K = 4E/3
    let k = 4.0 * e / 3.0;
    let maugis = 2.0 * s0 * (r / (PI * w * k * k)).cbrt();
    assert_relative_eq!(
        tabor_parameter_from_maugis(maugis).unwrap(),
        from_stress,
        max_relative = 1e-13
    );
    assert_relative_eq!(
        maugis_parameter(from_stress).unwrap(),
        maugis,
        max_relative = 1e-13
    );
    // Λ = 4 is λ_T ≈ 5 (seed 000, text after (5.46))
    let l = tabor_parameter_from_tabor_mu(5.0).unwrap();
    assert!((l - 4.0).abs() < 0.05, "{l}");
    assert!(tabor_parameter_from_range(0.0, w, e, r).is_err());
    assert!(tabor_parameter_from_cohesive_stress(f64::NAN, w, e, r).is_err());
}

#[test]
fn scales_match_the_spec() {
    let (e, r, w) = (2e9, 5e-6, 0.1);
    let s = JkrScales::new(e, r, w).unwrap();
    let energy = 3.0 * 3f64.cbrt() / 8.0 * (r.powi(4) * (PI * w).powi(5) / (e * e)).cbrt();
    assert_relative_eq!(s.energy, energy, max_relative = 1e-14);
    assert_relative_eq!(s.force, 1.5 * PI * w * r, max_relative = 1e-15);
}

#[test]
fn trace_follows_the_branch_and_encloses_the_loss() {
    for lambda in [0.3, 0.55, 1.0, 5.0] {
        let path = impact_path(lambda).unwrap();
        let n = 4000;
        let trace = trace_impact(lambda, 2.0, n).unwrap();
        assert_eq!(trace.first().unwrap().phase, Phase::Approach);
        assert_eq!(trace.last().unwrap().phase, Phase::PullOff);
        let min_depth = trace
            .iter()
            .filter(|p| p.phase != Phase::Approach)
            .map(|p| p.depth)
            .fold(f64::INFINITY, f64::min);
        assert_relative_eq!(min_depth, path.pull_off.depth, max_relative = 1e-12);
        // the hysteresis area under the traced curve, by the trapezoidal rule
        let mut area = 0.0;
        for w in trace.windows(2) {
            area += 0.5 * (w[0].force + w[1].force) * (w[1].depth - w[0].depth);
        }
        let w = normalized_loss(lambda, 1e-12).unwrap().loss;
        assert_relative_eq!(area, w, max_relative = 2e-3);
        // every loaded state is an equilibrium state at its depth
        for p in trace
            .iter()
            .filter(|p| p.phase == Phase::Loading)
            .step_by(500)
        {
            let s = equilibrium_state(lambda, p.depth).unwrap();
            assert_relative_eq!(s.force, p.force, max_relative = 1e-10, epsilon = 1e-12);
        }
    }
    assert!(trace_impact(1.0, -100.0, 10).is_err());
    assert!(equilibrium_state(1.0, -100.0).is_err());
}

#[test]
fn bad_input_is_a_named_error() {
    for bad in [f64::NAN, f64::INFINITY, -1.0, 0.0] {
        let e = normalized_loss(bad, 1e-12).unwrap_err();
        assert!(e.to_string().contains("tabor_parameter"), "{e}");
        assert!(impact_path(bad).is_err());
        assert!(loss_over_jkr_fast(bad).is_err());
    }
    let e = normalized_loss(1.0, 0.0).unwrap_err();
    assert!(e.to_string().contains("tolerance"), "{e}");
    let e = JkrSphere::new(1e9, -1.0, 0.1)
        .and_then(|sphere| MaugisContact::new(sphere, 1.0))
        .and_then(|contact| MaugisDugdaleImpact::new(contact, 1.0))
        .unwrap_err();
    assert!(e.to_string().contains("effective_radius"), "{e}");
}

#[test]
fn restitution_and_sticking_through_the_core() {
    let m = MaugisDugdaleImpact::new(
        MaugisContact::new(JkrSphere::new(2.78e10, 5e-7, 0.05).unwrap(), 2.0).unwrap(),
        5.55e-15,
    )
    .unwrap();
    let joules = m.energy_loss_joules().unwrap();
    let vc = sticking_velocity(&m, 1e-12).unwrap();
    assert_eq!(vc.method, StickingMethod::ClosedForm);
    assert_relative_eq!(
        vc.speed,
        (2.0 * joules / 5.55e-15).sqrt(),
        max_relative = 1e-14
    );
    let o = impact(&m, 2.0 * vc.speed).unwrap();
    assert_relative_eq!(o.restitution, (0.75f64).sqrt(), max_relative = 1e-12);
    assert!(o.branch.contains("case 3"));
    assert!(impact(&m, 0.5 * vc.speed).unwrap().sticks);
    assert!(m.speed_scale() > 0.0);
}

proptest! {
    #[test]
    fn physical_loss_is_energy_scale_times_normalized(
        log_e in 5.0f64..12.0, log_r in -9.0f64..0.0, log_w in -3.0f64..0.0, log_l in -3.0f64..4.0,
    ) {
        let (e, r, w, l) = (10f64.powf(log_e), 10f64.powf(log_r), 10f64.powf(log_w), 10f64.powf(log_l));
        let m = MaugisDugdaleImpact::new(MaugisContact::new(JkrSphere::new(e, r, w).unwrap(), l).unwrap(), 1.0).unwrap();
        let joules = m.energy_loss_joules().unwrap();
        let energy = 3.0 * 3f64.cbrt() / 8.0 * (r.powi(4) * (PI * w).powi(5) / (e * e)).cbrt();
        let normalized = normalized_loss(l, 1e-12).unwrap().loss;
        prop_assert!((joules / (energy * normalized) - 1.0).abs() <= 1e-13);
    }
}

/// The force law's path in its coordinates (what the simulator integrates: the
/// contact branch in θ, the no-contact branch in b̂) against the force law in d
/// (θ solved at a depth): the same overlap and force at the coordinate of a depth,
/// the slope equal to a central difference of the overlap, and the ends of the
/// part the motion unloads along: the snap-off (a fold of d(q): slope 0) in case 3
/// (θ_c) and case 1 (b̂_c), the junction with the no-contact branch in case 2
/// (θ = π/2, where d̂ − d̂_j ∝ (π/2 − θ)²: slope 0 too). No curve while approaching.
#[test]
fn force_law_curve_matches_the_traced_branch() {
    use tabor_dynamics::ForceLaw;
    let (e, r, dg) = (2.780_352_177_942_539e10, 0.5e-6, 0.05);
    for lambda in [0.3, 0.4, 0.55, 0.6, 0.7, 1.0, 4.0, 100.0] {
        let model = MaugisDugdaleImpact::new(
            MaugisContact::new(JkrSphere::new(e, r, dg).unwrap(), lambda).unwrap(),
            5.55e-15,
        )
        .unwrap();
        let mut law = MaugisDugdaleForceLaw::new(&model).unwrap();
        law.begin_impact(5.55e-15, 1.0).unwrap();
        assert!(law.curve().is_none(), "approaching at Lambda = {lambda}");
        let (jump_in, pull_off) = law.jump_in_and_pull_off_depths();
        law.on_branch_end(jump_in, 1.0).unwrap();
        let curve = law.curve().unwrap();
        let d_n = model.scales().depth;
        let f_n = model.scales().force;
        // depths on the part the motion enters at jump-in
        let depths: Vec<f64> = if lambda <= LAMBDA_1 {
            (1..=4)
                .map(|k| pull_off + 0.25 * k as f64 * (jump_in - pull_off))
                .collect()
        } else {
            vec![jump_in, 0.0, 2.0 * d_n, 50.0 * d_n]
        };
        for d in depths {
            let q = curve.coordinate(d).unwrap();
            let p = curve.point(q, 0.0).unwrap();
            let tolerance = 1e-13 * d_n.max(d.abs());
            assert!(
                (p.overlap - d).abs() <= tolerance,
                "{lambda} {d}: {}",
                p.overlap
            );
            let f = law.force(d, 0.0).unwrap();
            assert!(
                (p.force - f).abs() <= 1e-12 * f_n.max(f.abs()),
                "{f} vs {}",
                p.force
            );
            let h = 1e-6 * q;
            let slope = (curve.point(q + h, 0.0).unwrap().overlap
                - curve.point(q - h, 0.0).unwrap().overlap)
                / (2.0 * h);
            assert!(
                (p.overlap_slope - slope).abs() <= 1e-7 * slope.abs(),
                "{slope}"
            );
            // the closed-form slopes of force and contact radius, likewise
            // (central differences: truncation ~h², rounding ~10⁻¹⁶/h ~ 10⁻¹⁰)
            let (df, da) = p.slopes.unwrap();
            let (up, down) = (
                curve.point(q + h, 0.0).unwrap(),
                curve.point(q - h, 0.0).unwrap(),
            );
            let df_num = (up.force - down.force) / (2.0 * h);
            let da_num = (up.contact_radius - down.contact_radius) / (2.0 * h);
            assert!(
                (df - df_num).abs() <= 1e-7 * df_num.abs().max(f_n),
                "{lambda} {d}: dF/dq {df} vs {df_num}"
            );
            let a_c = model.scales().contact_radius;
            assert!(
                (da - da_num).abs() <= 1e-7 * da_num.abs().max(a_c),
                "{lambda} {d}: da/dq {da} vs {da_num}"
            );
            assert!(curve.end(q, -1.0).unwrap() > 0.0);
        }
        // the end the unloading meets: 0 at q_end = q + end(q)·(dq/d(end))
        let q = curve.coordinate(jump_in).unwrap();
        let end = curve.end(q, -1.0).unwrap();
        let q_end = if lambda <= LAMBDA_1 { q - end } else { q + end };
        assert!(curve.end(q_end, -1.0).unwrap().abs() < 1e-15);
        let at_end = curve.point(q_end, -1.0).unwrap();
        assert!(
            at_end.overlap_slope.abs() <= 1e-9 * d_n,
            "{}",
            at_end.overlap_slope
        );
        if lambda <= LAMBDA_1 || lambda > LAMBDA_2 {
            let tolerance = 1e-13 * d_n.max(pull_off.abs());
            assert!((at_end.overlap - pull_off).abs() <= tolerance);
        } else {
            // case 2: the junction, where the no-contact part takes over (â = 0)
            assert!(at_end.overlap > pull_off);
            assert!(at_end.contact_radius.abs() <= 1e-15 * model.scales().contact_radius);
            let f = law.force(at_end.overlap, 0.0).unwrap();
            assert!((at_end.force - f).abs() <= 1e-12 * f_n.max(f.abs()));
            // approaching the junction, d̂ − d̂_j and F̂ − F̂_j are both even in
            // ε = π/2 − θ: dF/dd from the closed-form slopes stays finite (0/0 in
            // the limit) and equals the secant of F against d over θ ± ε/10 at
            // ε = 10⁻³ (truncation ~10⁻²·…, so 10⁻³ relative; 10⁻⁵ between ε's)
            let stiffness = |eps: f64| {
                let p = curve.point(q_end - eps, 0.0).unwrap();
                p.slopes.unwrap().0 / p.overlap_slope
            };
            let eps = 1e-3;
            let (up, down) = (
                curve.point(q_end - 0.9 * eps, 0.0).unwrap(),
                curve.point(q_end - 1.1 * eps, 0.0).unwrap(),
            );
            let secant = (up.force - down.force) / (up.overlap - down.overlap);
            let k = stiffness(eps);
            assert!(
                (k - secant).abs() <= 1e-3 * secant.abs(),
                "{lambda}: {k} vs {secant}"
            );
            for eps in [1e-6, 1e-9, 1e-12] {
                let k_eps = stiffness(eps);
                assert!(k_eps.is_finite(), "{lambda}: dF/dd at {eps}: {k_eps}");
                assert!(
                    (k_eps - k).abs() <= 1e-2 * k.abs(),
                    "{lambda}: {k_eps} vs {k}"
                );
            }
        }
    }
}
