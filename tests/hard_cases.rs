#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Hard cases across the crates (issue 9): the Tabor parameter over ten decades and
//! at the case boundaries Λ1, Λ2; impact speeds within 1e-12 of the sticking
//! velocity; power-law profiles n → 1/2⁺; graded media k → −1⁺ and 1⁻; the
//! Kelvin-Voigt damping ratio at D = 1 ± 1e-9; the adhesion parameter Φ across the
//! sign changes of F̂_Y(Φ); bodies from nanometres to metres with moduli from 1e5 to
//! 1e12 Pa. Every result finite, restitution in [0, 1], continuous across the
//! boundaries, monotone where the physics says so. Plus the regression tests of the
//! overflow fixes found by `tests/fuzz_api*.rs`.

use tabor::jkr::{GradedSphere, JkrImpact, JkrSphere, PowerLawProfile};
use tabor::maugis::{
    loss_over_jkr_fast, normalized_loss, MaugisContact, MaugisDugdaleImpact, TaborCase, LAMBDA_1,
    LAMBDA_2,
};
use tabor::restitution::{impact, sticking_velocity, ElasticMaterial, Error, ImpactModel};

fn log_grid(from: f64, to: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| from * (to / from).powf(i as f64 / (n - 1) as f64))
        .collect()
}

fn assert_invalid<T: std::fmt::Debug>(r: Result<T, Error>, parameter: &str) {
    match r {
        Err(Error::InvalidParameter { parameter: p, .. }) => assert_eq!(p, parameter),
        other => panic!("expected an error naming {parameter}, got {other:?}"),
    }
}

fn restitution_of<M: ImpactModel>(m: &M, v: f64) -> f64 {
    let o = impact(m, v).expect("impact");
    assert!(o.restitution.is_finite() && (0.0..=1.0).contains(&o.restitution));
    assert!(o.energy_loss.is_finite() && o.energy_loss >= 0.0);
    o.restitution
}

// ---------------------------------------------------------------------------
// Maugis-Dugdale: Λ from 1e-4 to 1e6

/// Quadrature tolerance of the reference path in these tests.
const TOL: f64 = 1e-12;

#[test]
fn maugis_loss_over_ten_decades_is_finite_below_one_and_increasing() {
    let mut previous = 0.0;
    for lambda in log_grid(1e-4, 1e6, 61) {
        let l = normalized_loss(lambda, TOL).expect("normalized loss");
        assert!(l.loss.is_finite() && l.loss > 0.0, "Λ = {lambda}: {l:?}");
        assert!(
            l.loss_over_jkr > 0.0 && l.loss_over_jkr < 1.0,
            "Λ = {lambda}: W/W_JKR = {}",
            l.loss_over_jkr
        );
        // the loss grows monotonically towards the JKR limit
        assert!(
            l.loss_over_jkr > previous,
            "Λ = {lambda}: {} after {previous}",
            l.loss_over_jkr
        );
        previous = l.loss_over_jkr;
        // the fast tier agrees to its stated relative error (plus the reference's)
        let fast = loss_over_jkr_fast(lambda).expect("fast tier");
        assert!(
            (fast / l.loss_over_jkr - 1.0).abs()
                <= tabor::maugis::FAST_TIER_RELATIVE_ERROR + 10.0 * TOL,
            "Λ = {lambda}: fast {fast} vs {}",
            l.loss_over_jkr
        );
    }
    // large Λ: W/W_JKR → 1 − 0.4568/Λ (README); at 1e6 within 1e-9 of 1
    let l = normalized_loss(1e6, TOL).expect("Λ = 1e6");
    assert!((1.0 - l.loss_over_jkr) < 1e-6 && (1.0 - l.loss_over_jkr) > 0.0);
}

#[test]
fn maugis_loss_is_continuous_at_the_case_boundaries() {
    for (boundary, below, above) in [
        (
            LAMBDA_1,
            TaborCase::NoContact,
            TaborCase::ContactThenNoContact,
        ),
        (
            LAMBDA_2,
            TaborCase::ContactThenNoContact,
            TaborCase::Contact,
        ),
    ] {
        let at = normalized_loss(boundary, TOL).expect("at the boundary");
        assert_eq!(at.case, below, "Λ = {boundary} belongs to the lower case");
        for rel in [-1e-12, -1e-14, 1e-14, 1e-12] {
            let lambda = boundary * (1.0 + rel);
            let l = normalized_loss(lambda, TOL).expect("near the boundary");
            let expected_case = if lambda <= boundary { below } else { above };
            assert_eq!(l.case, expected_case, "Λ = {lambda:e}");
            // W(Λ) is continuous with a bounded slope here: a step of 1e-12 in Λ may
            // move it by the quadrature tolerance and ~1e-12 times the slope
            let jump = (l.loss_over_jkr - at.loss_over_jkr).abs();
            assert!(
                jump <= 1e-10,
                "Λ = {lambda:e} (case {:?}): W/W_JKR jumps by {jump:e} at {boundary}",
                l.case
            );
            let fast = loss_over_jkr_fast(lambda).expect("fast tier");
            assert!(
                (fast - at.loss_over_jkr).abs() <= 1e-9,
                "fast tier at {lambda:e}"
            );
        }
    }
}

// ---------------------------------------------------------------------------
// Sticking velocity ± 1e-12

fn check_sticking_boundary<M: ImpactModel>(name: &str, model: &M) {
    let vs = sticking_velocity(model, 1e-15)
        .expect("sticking velocity")
        .speed;
    assert!(vs.is_finite() && vs > 0.0, "{name}: v_s = {vs}");
    let below = restitution_of(model, vs * (1.0 - 1e-12));
    let at = restitution_of(model, vs);
    let above = restitution_of(model, vs * (1.0 + 1e-12));
    // ε ≈ √(1 − (v_s/v)²) ≈ √(2·1e-12) ≈ 1.4e-6 just above v_s: continuous, no jump
    for e in [below, at, above] {
        assert!(e <= 1e-5, "{name}: ε = {e} within 1e-12 of v_s = {vs}");
    }
    assert!(
        below <= above,
        "{name}: ε({below}) below > ε({above}) above"
    );
    // well away from v_s the impact sticks below and rebounds above
    assert_eq!(
        restitution_of(model, 0.5 * vs),
        0.0,
        "{name}: sticks at v_s/2"
    );
    assert!(
        restitution_of(model, 2.0 * vs) > 0.1,
        "{name}: rebounds at 2 v_s"
    );
}

#[test]
fn restitution_is_continuous_at_the_sticking_velocity() {
    // silica (README): E* = 27.8 GPa, R = 0.5 µm, Δγ = 0.05 J/m², m = 5.55e-15 kg
    let (e, r, w, m) = (
        2.780_352_177_942_539e10,
        5e-7,
        0.05,
        5.550_147_021_341_967e-15,
    );
    let jkr = JkrImpact::new(JkrSphere::new(e, r, w).unwrap(), m).unwrap();
    check_sticking_boundary("JKR sphere", &jkr);
    let jkr_load = JkrImpact::new(JkrSphere::new(e, r, w).unwrap(), m)
        .unwrap()
        .with_separation(tabor::jkr::SeparationRule::LoadControlled);
    check_sticking_boundary("JKR sphere, load-controlled", &jkr_load);
    for lambda in [0.1, LAMBDA_1, 0.5, LAMBDA_2, 1.0, 10.0] {
        let md = MaugisDugdaleImpact::new(
            MaugisContact::new(JkrSphere::new(e, r, w).unwrap(), lambda).unwrap(),
            m,
        )
        .unwrap();
        check_sticking_boundary(&format!("Maugis-Dugdale Λ = {lambda}"), &md);
    }
    let plastic = tabor::plastic::AdhesiveInterpolationImpact::new(
        tabor::plastic::AdhesivePlasticContact::from_yield_stress(
            JkrSphere::new(e, r, w).unwrap(),
            1e9,
        )
        .unwrap(),
        m,
    )
    .unwrap();
    check_sticking_boundary("adhesive interpolation (plastic)", &plastic);
}

#[test]
fn jkr_restitution_increases_with_speed_above_sticking() {
    let jkr = JkrImpact::new(JkrSphere::new(1e10, 1e-6, 0.1).unwrap(), 1e-14).unwrap();
    let vs = sticking_velocity(&jkr, 1e-12).unwrap().speed;
    let mut previous = 0.0;
    for v in log_grid(vs * (1.0 + 1e-9), 1e4 * vs, 40) {
        let e = restitution_of(&jkr, v);
        assert!(e > previous, "ε({v}) = {e} after {previous}");
        previous = e;
    }
    assert!(previous > 0.999_999 && previous < 1.0);
}

// ---------------------------------------------------------------------------
// Power-law profiles n → 1/2⁺, graded media k → ±1

#[test]
fn power_law_profiles_down_to_n_one_half() {
    assert_invalid(
        PowerLawProfile::new(1e9, 0.5, 1e3, 0.05),
        "profile_exponent",
    );
    for j in 1..=12 {
        let n = 0.5 + 10f64.powi(-j);
        // z = A r^n with z = 1 nm at r = 1 µm
        let a = 1e-9 / 1e-6f64.powf(n);
        // the JKR scales go as powers 1/(2n − 1) → ∞: close enough to 1/2 they
        // leave f64, and the constructor says so with a typed model error
        let result = PowerLawProfile::new(1e9, n, a, 0.05);
        if j >= 3 {
            // 1/(2n − 1) ≥ 1000: the first-touch radius leaves f64, and the
            // constructor says exactly that
            assert_eq!(
                result.map(|_| ()),
                Err(Error::Model {
                    model: "JKR power-law profile",
                    message: "the first-touch contact radius under- or overflows (inf) for \
                              these parameters"
                        .into()
                }),
                "n = {n}"
            );
            continue;
        }
        let model =
            JkrImpact::new(result.expect("n ≥ 1/2 + 1e-2 is representable"), 1e-12).expect("model");
        let loss = model.adhesive_energy_loss().expect("loss");
        assert!(
            loss.joules.is_finite() && loss.joules > 0.0,
            "n = {n}: {loss:?}"
        );
        // the loss does not depend on the speed: (5.38) v_s = √(2 |ΔU| / m)
        let s = sticking_velocity(&model, 1e-10).expect("sticking velocity");
        let closed = (2.0 * loss.joules / 1e-12).sqrt();
        assert!(
            (s.speed / closed - 1.0).abs() < 1e-12,
            "n = {n}: {s:?} vs {closed}"
        );
        restitution_of(&model, 2.0 * s.speed);
    }
}

#[test]
fn graded_media_near_k_minus_one_and_one() {
    for k in [-1.0, 1.0, f64::NAN] {
        assert_invalid(GradedSphere::new(1e9, k, 1e-6, 0.05), "gradation_exponent");
        assert_invalid(
            tabor::elastic::ElasticContact::graded_sphere(1e9, k, 1e-6),
            "gradation_exponent",
        );
    }
    // the loss per (1 + k) as k → −1, and the loss as k → 1, of the previous j
    let mut previous: [Option<f64>; 2] = [None, None];
    for j in 1..=12 {
        let eps = 10f64.powi(-j);
        for (side, k) in [-1.0 + eps, 1.0 - eps].into_iter().enumerate() {
            // modulus factor c_N chosen so the modulus at depth 1 µm is 1 GPa
            let c = 1e9 / 1e-6f64.powf(k);
            let Ok(g) = GradedSphere::new(c, k, 1e-6, 0.05) else {
                panic!("k = {k}: rejected")
            };
            let model = JkrImpact::new(g, 1e-14).expect("model");
            let loss = model.adhesive_energy_loss().expect("loss near k = ±1");
            assert!(
                loss.joules.is_finite() && loss.joules > 0.0,
                "k = {k}: {loss:?}"
            );
            // (5.38) for a speed-independent loss: v_s = √(2 |ΔU| / m)
            let s = sticking_velocity(&model, 1e-10).expect("sticking velocity");
            let closed = (2.0 * loss.joules / 1e-14).sqrt();
            assert!(
                (s.speed / closed - 1.0).abs() < 1e-12,
                "k = {k}: {s:?} vs {closed}"
            );
            restitution_of(&model, 2.0 * s.speed);
            // the limits: |ΔU| ∝ (1 + k) as k → −1 (1 + k exact in f64), |ΔU| → a
            // finite value as k → 1, each approached linearly: the relative step from
            // j − 1 to j is of order 1 ± k (measured ≈ 100 · 10^-j at k → −1,
            // ≈ 13 · 10^-j at k → 1)
            let scaled = if side == 0 {
                loss.joules / (1.0 + k)
            } else {
                loss.joules
            };
            if let (Some(p), true) = (previous[side], j >= 3) {
                let step = (scaled / p - 1.0).abs();
                assert!(
                    step < 3.0 * 10f64.powi(2 - j) + 1e-9,
                    "k = {k}: step {step:e}"
                );
            }
            previous[side] = Some(scaled);
            let contact = tabor::elastic::ElasticContact::graded_sphere(c, k, 1e-6).unwrap();
            let elastic = tabor::elastic::ElasticImpact::new(contact, 1e-14).unwrap();
            for v in [1e-4, 1.0, 100.0] {
                let t = elastic.contact_time(v).expect("contact time");
                assert!(t.is_finite() && t > 0.0, "k = {k}, v = {v}");
                assert_eq!(restitution_of(&elastic, v), 1.0);
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Kelvin-Voigt damping ratio D = 1 ± 1e-9

#[test]
fn kelvin_voigt_flat_punch_is_continuous_at_critical_damping() {
    use tabor::visco::kelvin_voigt_flat::{contact_time, restitution};
    let e1 = restitution(1.0).unwrap();
    assert!((e1 - (-2.0f64).exp()).abs() < 1e-15, "ε(1) = {e1} (5.63)");
    let t1 = contact_time(1.0).unwrap();
    assert!((t1 - 2.0).abs() < 1e-14, "ω0 T(1) = {t1}");
    for d in [1.0 - 1e-9, 1.0 - 1e-12, 1.0 + 1e-12, 1.0 + 1e-9] {
        // analytic in D at D = 1 with |dε/dD| < 1: a step of 1e-9 moves ε by < 1e-9
        let e = restitution(d).unwrap();
        assert!((e - e1).abs() < 1e-9, "ε({d}) = {e} vs ε(1) = {e1}");
        let t = contact_time(d).unwrap();
        assert!((t - t1).abs() < 1e-8, "T({d}) = {t} vs {t1}");
    }
    // restitution decreases with damping across the whole range
    let mut previous = 1.0;
    for d in log_grid(1e-6, 1e6, 121) {
        let e = restitution(d).unwrap();
        assert!((0.0..=1.0).contains(&e) && e <= previous, "ε({d}) = {e}");
        previous = e;
    }
}

// ---------------------------------------------------------------------------
// Adhesion parameter Φ from 0.01 to 100

#[test]
fn adhesive_yield_force_sign_changes_and_plastic_adhesive_restitution() {
    use tabor::plastic::{adhesive_yield_force, AdhesiveInterpolation};
    let grid = log_grid(0.01, 100.0, 4001);
    let mut changes = Vec::new();
    let mut previous: Option<(f64, f64)> = None;
    for &phi in &grid {
        let f = adhesive_yield_force(phi).expect("F_Y");
        assert!(f.is_finite(), "Φ = {phi}");
        if let Some((p, fp)) = previous {
            if fp.signum() != f.signum() {
                changes.push(0.5 * (p + phi));
            }
        }
        previous = Some((phi, f));
    }
    assert_eq!(changes.len(), 2, "sign changes of F_Y at {changes:?}");
    assert!((changes[0] - 1.19).abs() < 0.01, "{changes:?}");
    assert!((changes[1] - 7.47).abs() < 0.01, "{changes:?}");

    // across Φ = 0.01 ... 100 and its sign changes the model gives a restitution in
    // [0, 1] that is continuous in Φ
    let mut phis = log_grid(0.01, 100.0, 41);
    for c in &changes {
        for rel in [-1e-9, 0.0, 1e-9] {
            phis.push(c * (1.0 + rel));
        }
    }
    for phi in phis {
        // the model is documented valid up to Φ ≈ 9.3 (no monotone elasto-plastic
        // interpolation above, tabor-plastic README): beyond, a typed error
        let model = match AdhesiveInterpolation::new(phi) {
            Ok(m) => m,
            Err(e) => {
                assert!(phi > 9.0, "Φ = {phi}: {e:?}");
                assert_invalid(Err::<(), _>(e), "adhesion_parameter");
                continue;
            }
        };
        for ratio in [0.5, 1.0, 1.5, 3.0, 10.0, 100.0] {
            let e = model.restitution(ratio).expect("restitution");
            assert!(
                e.is_finite() && (0.0..=1.0).contains(&e),
                "Φ = {phi}, v/v_c = {ratio}: {e}"
            );
            let e2 = AdhesiveInterpolation::new(phi * (1.0 + 1e-9))
                .unwrap()
                .restitution(ratio)
                .unwrap();
            // continuity: a relative step of 1e-9 in Φ moves ε by far less than 1e-6
            assert!(
                (e2 - e).abs() < 1e-6,
                "Φ = {phi}, v/v_c = {ratio}: {e} → {e2}"
            );
        }
    }
}

// ---------------------------------------------------------------------------
// Bodies from nanometres to metres, moduli from 1e5 to 1e12 Pa

#[test]
fn sizes_from_nanometres_to_metres_and_moduli_over_seven_decades() {
    use tabor::elastic::{ElasticContact, ElasticImpact};
    let rho = 2500.0;
    for radius in log_grid(1e-9, 1.0, 10) {
        for modulus in log_grid(1e5, 1e12, 8) {
            let mass = tabor::restitution::effective::sphere_mass(radius, rho).unwrap();
            let hertz =
                ElasticImpact::new(ElasticContact::hertz(modulus, radius).unwrap(), mass).unwrap();
            let mut previous = 0.0;
            for v in [1e-3, 1e-1, 10.0] {
                let d = hertz.max_overlap(v).unwrap();
                assert!(d.is_finite() && d > previous, "R = {radius}, E = {modulus}");
                previous = d;
                assert_eq!(restitution_of(&hertz, v), 1.0);
            }
            let w = 0.05;
            let jkr = JkrImpact::new(JkrSphere::new(modulus, radius, w).unwrap(), mass).unwrap();
            let vs = sticking_velocity(&jkr, 1e-12).unwrap().speed;
            assert!(vs.is_finite() && vs > 0.0, "R = {radius}, E = {modulus}");
            assert_eq!(restitution_of(&jkr, 0.5 * vs), 0.0);
            let e = restitution_of(&jkr, 2.0 * vs);
            assert!(e > 0.5 && e < 1.0, "JKR ε(2 v_s) = {e}");
            // Maugis-Dugdale with a 0.3 nm range: Λ spans many decades over this grid
            let md = MaugisDugdaleImpact::new(
                MaugisContact::from_range(JkrSphere::new(modulus, radius, w).unwrap(), 3e-10)
                    .unwrap(),
                mass,
            )
            .unwrap();
            let lambda = md.tabor_parameter();
            assert!(lambda.is_finite() && lambda > 0.0);
            let vs_md = sticking_velocity(&md, 1e-12).unwrap().speed;
            assert!(
                vs_md.is_finite() && vs_md <= vs * (1.0 + 1e-9),
                "Maugis-Dugdale loses less than JKR: R = {radius}, E = {modulus}, Λ = {lambda}"
            );
            let e_md = restitution_of(&md, 2.0 * vs);
            assert!(e_md >= e * (1.0 - 1e-12), "Λ = {lambda}: {e_md} < {e}");
        }
    }
}

#[test]
fn scenes_over_sizes_and_moduli() {
    use tabor::scene::{ElasticSphere, SceneBuilder};
    for radius in [1e-9, 1e-6, 1e-3, 1.0] {
        for modulus in [1e5, 1e8, 1e12] {
            let scene = SceneBuilder::new()
                .sphere(ElasticSphere {
                    radius,
                    density: 2500.0,
                    material: ElasticMaterial::new(modulus, 0.3).unwrap(),
                })
                .target_half_space(ElasticMaterial::new(modulus, 0.3).unwrap(), Some(2500.0))
                .adhesion(0.05)
                .speed(1.0)
                .build()
                .expect("scene");
            let o = scene.outcome().expect("outcome");
            assert!(
                o.restitution.is_finite() && (0.0..=1.0).contains(&o.restitution),
                "R = {radius}, E = {modulus}: {o:?}"
            );
            assert!(o.energy_loss.is_finite() && o.energy_loss >= 0.0);
            if let Some(v) = scene.sticking_velocity().expect("sticking velocity") {
                assert!(v.is_finite() && v > 0.0);
            }
        }
    }
}

// ---------------------------------------------------------------------------
// Regression tests of the fixes found by tests/fuzz_api*.rs

#[test]
fn regression_effective_quantities_do_not_overflow() {
    use tabor::restitution::effective::{effective_modulus, effective_radius, reduced_mass};
    use tabor::restitution::ElasticMaterial;
    let r = effective_radius(1.8e258, Some(f64::MAX)).unwrap();
    assert!(r.is_finite() && (r / 1.8e258 - 1.0).abs() < 1e-12, "{r}");
    let r = effective_radius(1e-300, Some(1e-300)).unwrap();
    assert!((r / 5e-301 - 1.0).abs() < 1e-15, "{r}");
    // the effective radius of two smallest subnormals is not representable
    assert_invalid(effective_radius(5e-324, Some(5e-324)), "radius");
    assert_eq!(effective_radius(1e-6, Some(1e-6)).unwrap(), 5e-7);
    let m = reduced_mass(f64::MAX, Some(f64::MAX)).unwrap();
    assert!((m / (0.5 * f64::MAX) - 1.0).abs() < 1e-15);
    let huge = ElasticMaterial::new(f64::MAX, 0.0).unwrap();
    assert_invalid(
        effective_modulus(&huge, &ElasticMaterial::rigid()),
        "youngs_modulus",
    );
}

#[test]
fn regression_checks_do_not_overflow() {
    use tabor::restitution::checks::{elastic_limit_check, quasi_static_check};
    // E/ρ underflows: wave speed 0, ratio ∞
    assert_invalid(quasi_static_check(1.0, 1.9e-19, f64::MAX), "density");
    assert_invalid(quasi_static_check(f64::MAX, 1.0, 100.0), "impact_speed");
    assert_invalid(
        elastic_limit_check(1e9, 1e-3, 1e-3, 1.0, f64::MAX),
        "yield_stress",
    );
    assert!(quasi_static_check(1.0, 1e11, 8000.0).unwrap().satisfied);
}

#[test]
fn regression_quadrature_overflow_is_an_error() {
    use tabor::numerics::quadrature::integrate_smooth;
    use tabor::numerics::QuadTolerance;
    assert!(integrate_smooth(|x| x * x, 0.0, 3.9e114, QuadTolerance::relative(1e-3)).is_err());
    let i = integrate_smooth(|x| x * x, 0.0, 3.0, QuadTolerance::relative(1e-12)).unwrap();
    assert!((i.value - 9.0).abs() < 1e-11);
}

#[test]
fn regression_maugis_extremes() {
    use tabor::maugis::units::maugis_parameter;
    use tabor::maugis::{equilibrium_state, impact_path, trace_impact};
    assert_invalid(impact_path(5e-324), "tabor_parameter");
    assert_invalid(maugis_parameter(f64::MAX), "tabor_parameter");
    assert_invalid(equilibrium_state(1.0, 1e300), "depth");
    assert_invalid(trace_impact(1.0, 1e300, 10), "max_depth");
    assert_invalid(trace_impact(1.0, 1.0, usize::MAX), "points");
    assert!(trace_impact(1.0, 1.0, 10).unwrap().len() > 10);
    // F_n d_n finite but W · F_n d_n overflows (full fuzzing run): an error, not ∞
    let m = tabor::maugis::MaugisDugdaleImpact::new(
        MaugisContact::new(
            JkrSphere::new(
                42177358242.0135,
                8.060477340906638e238,
                0.004544629103630278,
            )
            .unwrap(),
            1e3,
        )
        .unwrap(),
        1.0,
    )
    .unwrap();
    assert!(m.scales().energy.is_finite());
    assert!(matches!(
        m.energy_loss_joules(),
        Err(tabor::restitution::Error::Model { .. })
    ));
}

#[test]
fn regression_elastic_power_of_an_overflowing_coefficient() {
    // force coefficient ~4.5e307 and exponent ~39 at a tiny overlap: ∞ · 0 gave NaN
    // (full fuzzing run); the true values underflow to 0
    let c = tabor::elastic::ElasticContact::graded_power_law(
        2071957.633209267,
        0.0,
        1.0355009754632e-8,
        0.026359350830031367,
    )
    .unwrap();
    let d = 2.5808374769343658e-18;
    for f in [c.force(d), c.stiffness(d), c.stored_energy(d)] {
        assert_eq!(f, 0.0);
    }
    // and at an overlap where the product is representable, the direct value
    let h = tabor::elastic::ElasticContact::hertz(1e9, 1e-3).unwrap();
    let d: f64 = 1e-6;
    let f = 4.0 / 3.0 * 1e9 * 1e-3f64.sqrt() * d.powf(1.5);
    assert!((h.force(d) / f - 1.0).abs() < 1e-14);
    assert!((h.stiffness(d) / (1.5 * f / d) - 1.0).abs() < 1e-14);
    assert!((h.stored_energy(d) / (f * d / 2.5) - 1.0).abs() < 1e-14);
}

#[test]
fn regression_plastic_penalty_scene_elastic_extremes() {
    use tabor::penalty::{loss_factor, ContactCharacteristic, DampedPowerLaw};
    let ai = tabor::plastic::AdhesiveInterpolation::new(1.0).unwrap();
    assert!(ai.loading_force(f64::MAX).is_err());
    assert!(ai.loading_force(10.0).unwrap().is_finite());
    assert_invalid(loss_factor(-1.9e81, 2.2e-308), "gap_rate");
    let c = ContactCharacteristic::new(1e10, 1.0, 1.0).unwrap();
    assert_invalid(c.force(-f64::MAX, 0.0), "gap");
    assert_invalid(DampedPowerLaw::new(1e300, 1.5, 1e300), "damping_factor");
    let s = tabor::scene::spaced(5e-324, 1.0, 3, true).unwrap();
    assert!(s.iter().all(|v| v.is_finite() && *v > 0.0), "{s:?}");
    assert_eq!(s[2], 1.0);
    let s = tabor::scene::spaced(-f64::MAX, f64::MAX, 3, false).unwrap();
    assert!(s.iter().all(|v| v.is_finite()), "{s:?}");
    // from · (to/from) rounded up to inf when `to` is near f64::MAX (full fuzzing run)
    let s = tabor::scene::spaced(1059961537625579.4, f64::MAX, 2, true).unwrap();
    assert_eq!(s, vec![1059961537625579.4, f64::MAX]);
    let s = tabor::scene::spaced(1e-300, f64::MAX, 7, true).unwrap();
    assert!(s.iter().all(|v| v.is_finite()), "{s:?}");
    assert!(s.windows(2).all(|w| w[0] < w[1]), "{s:?}");
    let c = tabor::elastic::ElasticContact::hertz(3.4e-91, 8e263).unwrap();
    let a = c.contact_radius(1.5e73);
    // a = √(2R·d/β)... for Hertz a = √(R d): finite and within rounding of it
    let expected = 8e263f64.sqrt() * 1.5e73f64.sqrt();
    assert!(
        a.is_finite() && (a / expected - 1.0).abs() < 1e-12,
        "{a} vs {expected}"
    );
}

#[test]
fn regression_simulation_scene_and_characteristic_extremes() {
    use tabor::dynamics::{simulate_impact, SimulationSettings};
    // m v0² overflows inside the energy bookkeeping: the error is now relative
    let mut law = tabor::elastic::ElasticContact::hertz(1e9, 1e-3).unwrap();
    let s = simulate_impact(&mut law, 6.6e-16, 2.6e154, &SimulationSettings::default()).unwrap();
    assert!(
        s.energy_error.is_finite() && s.energy_error < 1e-6,
        "{}",
        s.energy_error
    );
    let k = tabor::penalty::contact_characteristic(-8.6e193, 3.4e246).unwrap();
    assert!(k.is_finite() && k > 0.0, "{k}");
    // a model error of the effective modulus names the field
    let text = include_str!("../examples/scenes/silica.toml")
        .replace("youngs_modulus = 54e9    # Pa", "youngs_modulus = 1.7e308");
    // E1 = 1.7e308 beside E2 = 54 GPa: 1/E* = (1 − ν²)/E1 + (1 − ν²)/E2 does not
    // overflow, and E* is E2/(1 − ν²) to rounding, so the scene is the JKR impact of
    // that E* (checked against the model crate, not the scene's own arithmetic)
    let scene = tabor::scene::Scene::from_str(&text, tabor::scene::Format::Toml)
        .expect("a huge modulus of one body is accepted");
    let v_s = scene
        .sticking_velocity()
        .expect("sticking")
        .expect("sticks");
    let e_star = 54e9 / (1.0 - 0.17f64.powi(2));
    let mass = 4.0 / 3.0 * std::f64::consts::PI * 1e-18 * 2650.0 / 2.0;
    let jkr = JkrImpact::new(JkrSphere::new(e_star, 0.5e-6, 0.05).unwrap(), mass).unwrap();
    let expected = sticking_velocity(&jkr, 1e-12).unwrap().speed;
    assert!((v_s / expected - 1.0).abs() < 1e-9, "{v_s} vs {expected}");
    // both moduli huge: E* overflows, and the scene refuses to compute
    let text = include_str!("../examples/scenes/silica.toml")
        .replace("youngs_modulus = 54e9", "youngs_modulus = 1.7e308");
    let refused = tabor::scene::Scene::from_str(&text, tabor::scene::Format::Toml)
        .and_then(|s| s.outcome().map(|_| ()))
        .expect_err("E* overflows");
    // the error names the modulus field and its line, with E* and R
    assert_eq!(
        refused.field.as_deref(),
        Some("sphere.youngs_modulus"),
        "{refused}"
    );
    assert_eq!(refused.line, Some(11), "{refused}");
    assert!(refused.message.contains("E* = "), "{refused}");
}
