#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Arbitrary f64 inputs: constructors and loss functions never panic and return a
//! finite result or an error naming a parameter.

use proptest::prelude::*;
use tabor_dynamics::SimulationSettings;
use tabor_jkr::JkrSphere;
use tabor_plastic::{
    adhesion_parameter, adhesive_yield_force, AdhesiveInterpolation, AdhesiveInterpolationImpact,
    AdhesivePlasticContact, DimensionlessFit, Interpolation, JacksonGreen, LoadingLaw,
    PlasticContact, PlasticImpact, Superposition, Thornton,
};
use tabor_restitution::{Error, ImpactModel, Result};

fn any_f64() -> impl Strategy<Value = f64> {
    prop_oneof![
        any::<f64>(),
        Just(f64::NAN),
        Just(f64::INFINITY),
        Just(f64::NEG_INFINITY),
        Just(0.0),
        Just(-1.0),
        Just(1e-300),
        Just(1e300),
        (-20.0f64..20.0).prop_map(|e| 10f64.powf(e)),
    ]
}

fn ok_or_error(r: Result<f64>) -> std::result::Result<(), TestCaseError> {
    match r {
        Ok(v) => prop_assert!(v.is_finite(), "non-finite result {v}"),
        Err(Error::InvalidParameter { parameter, .. }) => prop_assert!(!parameter.is_empty()),
        Err(_) => {}
    }
    Ok(())
}

fn loss(m: &dyn ImpactModel, v: f64) -> Result<f64> {
    m.energy_loss(v).map(|l| l.joules)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    #[test]
    fn non_adhesive_models_never_panic(e in any_f64(), r in any_f64(), s in any_f64(),
                                       m in any_f64(), v in any_f64(), nu in any_f64()) {
        ok_or_error(Thornton.restitution(v))?;
        ok_or_error(Interpolation::default().restitution(v))?;
        ok_or_error(Thornton.loading_work_ratio(v))?;
        ok_or_error(Interpolation::new(e, r).map(|_| 0.0))?;
        ok_or_error(Thornton::high_speed_restitution(v))?;
        if let Ok(c) = PlasticContact::new(e, r, s) {
            ok_or_error(c.yield_velocity(m))?;
            if let Ok(model) = PlasticImpact::new(c, Interpolation::default(), m) {
                ok_or_error(loss(&model, v))?;
                ok_or_error(model.restitution(v))?;
                ok_or_error(model.residual_depth(v))?;
            }
            if let Ok(model) = PlasticImpact::new(c, Thornton, m) {
                ok_or_error(loss(&model, v))?;
            }
        }
        if let Ok(fit) = DimensionlessFit::new(e, s, r, m) {
            ok_or_error(loss(&fit, v))?;
        }
        if let Ok(jg) = PlasticContact::new(e, r, s).and_then(|contact| JacksonGreen::new(contact, nu)) {
            ok_or_error(jg.loading_force(v))?;
            ok_or_error(jg.loading_contact_radius(v))?;
            ok_or_error(jg.residual_depth(v))?;
            ok_or_error(jg.yield_velocity(m))?;
        }
    }

    #[test]
    fn adhesive_models_never_panic(e in any_f64(), r in any_f64(), s in any_f64(),
                                   dg in any_f64(), m in any_f64(), v in any_f64(), phi in any_f64()) {
        ok_or_error(adhesion_parameter(e, r, s, dg))?;
        ok_or_error(adhesive_yield_force(phi))?;
        if let Ok(model) = AdhesiveInterpolation::new(phi) {
            ok_or_error(model.restitution(v))?;
            ok_or_error(model.energy_loss(v))?;
            ok_or_error(model.loading_force(v))?;
            ok_or_error(model.loading_work(v))?;
        }
        if let Ok(model) = JkrSphere::new(e, r, dg).and_then(|sphere| AdhesivePlasticContact::from_yield_stress(sphere, s)).and_then(|contact| AdhesiveInterpolationImpact::new(contact, m)) {
            ok_or_error(loss(&model, v))?;
        }
        if let (Ok(c), Ok(sphere)) = (PlasticContact::new(e, r, s), JkrSphere::new(e, r, dg)) {
            if let Ok(p) = PlasticImpact::new(c, Thornton, m) {
                if let Ok(sup) = Superposition::new(p, sphere) {
                    ok_or_error(loss(&sup, v))?;
                }
            }
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(16))]
    #[test]
    fn jackson_green_simulation_never_panics(log_e in 8.0f64..12.0, log_r in -8.0f64..0.0,
        strain in 1e-4f64..0.05, log_m in -16.0f64..0.0, log_s in -1.0f64..3.0, nu in -0.5f64..0.5) {
        let e = 10f64.powf(log_e);
        let jg = PlasticContact::new(e, 10f64.powf(log_r), strain * e).and_then(|contact| JacksonGreen::new(contact, nu)).unwrap();
        let model = jg.impact(10f64.powf(log_m), SimulationSettings::default()).unwrap();
        let v = 10f64.powf(log_s) * model.yield_velocity();
        let l = loss(&model, v).unwrap();
        prop_assert!(l.is_finite() && l >= 0.0);
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]
    /// Valid inputs over many decades: a finite restitution in [0, 1] or a typed error.
    #[test]
    fn wide_ranges_give_finite_results(log_phi in -4.0f64..4.0, log_s in -6.0f64..8.0,
                                       log_q in -1.0f64..2.0, log_d in 0.01f64..4.0) {
        let s = 10f64.powf(log_s);
        if let Ok(model) = AdhesiveInterpolation::new(10f64.powf(log_phi)) {
            let e = model.restitution(s).unwrap();
            prop_assert!((0.0..=1.0).contains(&e));
        }
        if let Ok(law) = Interpolation::new(10f64.powf(log_q), 10f64.powf(log_d)) {
            let e = law.restitution(s).unwrap();
            prop_assert!((0.0..=1.0).contains(&e));
        }
        let e = Thornton.restitution(s).unwrap();
        prop_assert!((0.0..=1.0).contains(&e));
    }
}
