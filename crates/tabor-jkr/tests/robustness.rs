//! Bad input gives an error naming the parameter and its value; arbitrary input
//! (NaN, ±inf, subnormal, huge, negative) never panics and never yields NaN.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use proptest::prelude::*;
use tabor_jkr::{
    normalized, AdhesiveContact, GradedSphere, JkrImpact, JkrSphere, PowerLawProfile,
    SeparationRule,
};
use tabor_restitution::{impact, sticking_velocity, Error, ImpactModel};

fn parameter_of(e: Error) -> &'static str {
    match e {
        Error::InvalidParameter { parameter, .. } => parameter,
        other => panic!("expected an invalid parameter, got {other:?}"),
    }
}

#[test]
fn every_constructor_names_the_bad_parameter() {
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, 0.0, -1.0] {
        assert_eq!(
            parameter_of(JkrSphere::new(bad, 1.0, 1.0).unwrap_err()),
            "effective_modulus"
        );
        assert_eq!(
            parameter_of(JkrSphere::new(1.0, bad, 1.0).unwrap_err()),
            "effective_radius"
        );
        assert_eq!(
            parameter_of(JkrSphere::new(1.0, 1.0, bad).unwrap_err()),
            "work_of_adhesion"
        );
        assert_eq!(
            parameter_of(PowerLawProfile::new(bad, 2.0, 1.0, 1.0).unwrap_err()),
            "effective_modulus"
        );
        assert_eq!(
            parameter_of(PowerLawProfile::new(1.0, 2.0, bad, 1.0).unwrap_err()),
            "profile_coefficient"
        );
        assert_eq!(
            parameter_of(PowerLawProfile::new(1.0, 2.0, 1.0, bad).unwrap_err()),
            "work_of_adhesion"
        );
        assert_eq!(
            parameter_of(GradedSphere::new(bad, 0.0, 1.0, 1.0).unwrap_err()),
            "modulus_coefficient"
        );
        assert_eq!(
            parameter_of(GradedSphere::new(1.0, 0.0, bad, 1.0).unwrap_err()),
            "effective_radius"
        );
        assert_eq!(
            parameter_of(GradedSphere::new(1.0, 0.0, 1.0, bad).unwrap_err()),
            "work_of_adhesion"
        );
        let s = JkrSphere::new(1e9, 1e-6, 0.1).unwrap();
        assert_eq!(
            parameter_of(JkrImpact::new(s, bad).unwrap_err()),
            "effective_mass"
        );
        let m = JkrImpact::new(s, 1e-15).unwrap();
        assert_eq!(
            parameter_of(m.max_contact_radius(bad).unwrap_err()),
            "impact_speed"
        );
        assert_eq!(
            parameter_of(m.energy_loss(bad).unwrap_err()),
            "impact_speed"
        );
        assert_eq!(
            parameter_of(m.clone().with_tolerance(bad).unwrap_err()),
            "tolerance"
        );
        assert_eq!(
            parameter_of(s.max_contact_radius(bad, 1e-9).unwrap_err()),
            "kinetic_energy"
        );
        assert_eq!(
            parameter_of(s.energy_loss(SeparationRule::FixedGrip, bad).unwrap_err()),
            "tolerance"
        );
        assert_eq!(
            parameter_of(normalized::max_contact_radius(bad, 1e-9).unwrap_err()),
            "kinetic_energy"
        );
        if bad < 0.0 || bad.is_nan() || bad.is_infinite() {
            assert_eq!(parameter_of(s.force(bad).unwrap_err()), "contact_radius");
            assert_eq!(
                parameter_of(normalized::depth(bad).unwrap_err()),
                "contact_radius"
            );
        }
    }
    // The message carries the name and the value.
    let msg = JkrSphere::new(-2.5, 1.0, 1.0).unwrap_err().to_string();
    assert!(
        msg.contains("effective_modulus") && msg.contains("-2.5"),
        "{msg}"
    );
}

/// Any f64, weighted towards the awkward ones.
fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<f64>(),
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
        Just(-0.0),
        Just(f64::MIN_POSITIVE),
        Just(5e-324),
        Just(f64::MAX),
        (-300.0f64..300.0).prop_map(|x| 10f64.powf(x)),
        (-30.0f64..30.0).prop_map(|x| -(10f64.powf(x))),
        (-1.5f64..8.0),
    ]
}

fn finite_or_error(r: &tabor_restitution::Result<f64>) -> bool {
    match r {
        Ok(v) => v.is_finite(),
        Err(_) => true,
    }
}

fn check_contact<C: AdhesiveContact>(c: &C, x: f64, tol: f64) -> Result<(), TestCaseError> {
    for rule in [SeparationRule::FixedGrip, SeparationRule::LoadControlled] {
        let r = c.energy_loss(rule, tol);
        if let Ok(l) = &r {
            prop_assert!(l.joules.is_finite() && l.joules >= 0.0, "{l:?}");
            prop_assert!(l.error_estimate.is_finite());
        }
        if let Ok(s) = c.critical_state(rule) {
            prop_assert!(
                s.force.is_finite() && s.depth.is_finite() && s.contact_radius.is_finite()
            );
        }
    }
    if let Ok(t) = c.first_touch() {
        prop_assert!(t.force.is_finite() && t.contact_radius.is_finite());
    }
    prop_assert!(finite_or_error(
        &c.max_contact_radius(x, tol).map(|m| m.contact_radius)
    ));
    Ok(())
}

proptest! {
    #[test]
    fn arbitrary_input_never_panics_nor_gives_nan(
        a in any_f64(), b in any_f64(), c in any_f64(), d in any_f64(), x in any_f64(),
        tol in prop_oneof![any_f64(), Just(1e-12), Just(1e-6)],
    ) {
        prop_assert!(finite_or_error(&normalized::force(x)));
        prop_assert!(finite_or_error(&normalized::depth(x)));
        prop_assert!(finite_or_error(&normalized::kinetic_energy_to_reach(x)));
        prop_assert!(finite_or_error(&normalized::max_contact_radius(x, tol).map(|m| m.contact_radius)));
        for rule in [SeparationRule::FixedGrip, SeparationRule::LoadControlled] {
            prop_assert!(finite_or_error(&normalized::energy_loss(rule, tol).map(|l| l.value)));
        }
        if let Ok(s) = JkrSphere::new(a, b, c) {
            prop_assert!(finite_or_error(&s.force(x)));
            prop_assert!(finite_or_error(&s.depth(x)));
            check_contact(&s, x, tol)?;
            if let Ok(m) = JkrImpact::new(s, d) {
                let m = m.with_separation(SeparationRule::LoadControlled);
                prop_assert!(finite_or_error(&m.max_contact_radius(x).map(|m| m.contact_radius)));
                prop_assert!(finite_or_error(&impact(&m, x).map(|o| o.restitution)));
                // An overflowing √(2|ΔU|/m) (e.g. m = 1e-308) is an error of the core,
                // never +inf.
                if let Ok(v) = sticking_velocity(&m, 1e-9) {
                    prop_assert!(v.speed.is_finite() && v.speed >= 0.0, "{v:?}");
                }
                prop_assert!(m.speed_scale().is_finite());
            }
        }
        if let Ok(p) = PowerLawProfile::new(a, b, c, d) {
            prop_assert!(finite_or_error(&p.force(x)));
            prop_assert!(finite_or_error(&p.depth(x)));
            check_contact(&p, x, tol)?;
        }
        if let Ok(g) = GradedSphere::new(a, b, c, d) {
            prop_assert!(finite_or_error(&g.force(x)));
            prop_assert!(finite_or_error(&g.depth(x)));
            prop_assert!(finite_or_error(&g.loss_ratio_to_homogeneous(x)));
            check_contact(&g, x, tol)?;
        }
    }

    /// Plausible parameters always succeed (no spurious overflow errors).
    #[test]
    fn plausible_parameters_always_succeed(
        le in 3.0f64..12.0, lr in -9.0f64..1.0, lg in -4.0f64..1.0, lm in -20.0f64..3.0,
        n in 0.55f64..8.0, k in -0.95f64..0.95, lv in -4.0f64..2.0,
    ) {
        let (e, r, dg, m, v) = (10f64.powf(le), 10f64.powf(lr), 10f64.powf(lg), 10f64.powf(lm), 10f64.powf(lv));
        let s = JkrSphere::new(e, r, dg).unwrap();
        let a0 = s.first_touch().unwrap().contact_radius;
        let model = JkrImpact::new(s, m).unwrap();
        prop_assert!(model.max_contact_radius(v).unwrap().contact_radius > a0);
        // Dimensional analysis: the JKR loss is Δγ^(5/3) R^(4/3) E*^(-2/3) times a
        // number of the separation rule alone; the numbers come from a reference
        // sphere (E* = 1 GPa, R = 1 µm, Δγ = 0.05 J/m²).
        let reference = JkrSphere::new(1e9, 1e-6, 0.05).unwrap();
        let scale = |e: f64, r: f64, dg: f64| dg.powf(5.0 / 3.0) * r.powf(4.0 / 3.0) * e.powf(-2.0 / 3.0);
        for rule in [SeparationRule::FixedGrip, SeparationRule::LoadControlled] {
            let loss = s.energy_loss(rule, 1e-12).unwrap().joules;
            let number = reference.energy_loss(rule, 1e-12).unwrap().joules / scale(1e9, 1e-6, 0.05);
            prop_assert!(
                (loss / (number * scale(e, r, dg)) - 1.0).abs() < 1e-9,
                "{rule}: {loss:e} vs {:e}", number * scale(e, r, dg)
            );
        }
        let g = GradedSphere::new(e * (1e-7f64).powf(-k), k, r, dg).unwrap();
        prop_assert!(g.energy_loss(SeparationRule::FixedGrip, 1e-12).unwrap().joules > 0.0);
        prop_assert!(g.energy_loss(SeparationRule::LoadControlled, 1e-12).unwrap().joules > 0.0);
        // A profile whose size at first touch is about that of the sphere.
        let a_coef = (0.5 / r) * a0.powf(2.0 - n);
        let p = PowerLawProfile::new(e, n, a_coef, dg).unwrap();
        prop_assert!(p.energy_loss(SeparationRule::FixedGrip, 1e-12).unwrap().joules > 0.0);
        prop_assert!(JkrImpact::new(p, m).unwrap().max_contact_radius(v).is_ok());
    }
}
