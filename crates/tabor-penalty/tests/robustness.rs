#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Every public function on arbitrary f64 input: no panic, no NaN; bad input is an
//! `Error::InvalidParameter` naming the parameter.

use proptest::prelude::*;
use tabor_dynamics::{simulate_impact, SimulationSettings};
use tabor_penalty::{
    characteristic_loss_speed, characteristic_restitution, contact_characteristic,
    damped_restitution, exact_damping_factor, loss_factor, ContactCharacteristic, DampedPowerLaw,
    DampingModel, Error, PenaltyStiffness,
};

fn ok_not_nan(r: Result<f64, Error>) {
    if let Ok(v) = r {
        assert!(!v.is_nan());
    }
}

fn any() -> impl Strategy<Value = f64> {
    prop_oneof![
        proptest::num::f64::ANY,
        -1e3..1e3f64,
        0.0..1.0f64,
        Just(0.0),
        Just(1.0),
        Just(f64::INFINITY),
    ]
}

proptest! {
    #[test]
    fn no_panic_no_nan(a in any(), b in any(), c in any()) {
        ok_not_nan(contact_characteristic(a, b));
        ok_not_nan(loss_factor(a, b));
        ok_not_nan(characteristic_restitution(a, b));
        ok_not_nan(characteristic_loss_speed(a, b));
        ok_not_nan(damped_restitution(a, b));
        ok_not_nan(exact_damping_factor(a, b));
        for model in DampingModel::ALL {
            ok_not_nan(model.damping_factor(a, b));
        }
        if let Ok(law) = ContactCharacteristic::new(a, b, c) {
            ok_not_nan(law.force(a, c));
            ok_not_nan(law.restitution(c));
            if let Ok(w) = law.oscillation_loss(b, c) {
                prop_assert!(w.joules >= 0.0 && w.joules.is_finite());
            }
        }
        if let Ok(law) = DampedPowerLaw::new(a, b, c) {
            ok_not_nan(law.force(a, c));
            ok_not_nan(law.restitution(a));
        }
        let _ = PenaltyStiffness::hertz(a, b);
        let _ = PenaltyStiffness::new(a, b);
    }

    #[test]
    fn restitutions_lie_in_unit_interval(e in 1e-6..=1.0f64, v in 1e-6..1e6f64) {
        let chi = exact_damping_factor(e, v).unwrap();
        let back = damped_restitution(chi, v).unwrap();
        prop_assert!((back - e).abs() < 1e-12, "{} -> {}", e, back);
        let big_v = characteristic_loss_speed(e, v).unwrap();
        let back = characteristic_restitution(v, big_v).unwrap();
        prop_assert!((back - e).abs() < 1e-12, "{} -> {}", e, back);
        for model in DampingModel::ALL {
            let r = damped_restitution(model.damping_factor(e, v).unwrap(), v).unwrap();
            prop_assert!((0.0..=1.0).contains(&r));
        }
    }

    #[test]
    fn simulated_laws_never_fail(e in 0.01..=1.0f64, n in 1.0..2.5f64, k in 1e-2..1e9f64) {
        let settings = SimulationSettings { record_trajectory: false, ..Default::default() };
        let mut law = DampedPowerLaw::from_model(DampingModel::Flores, k, n, e, 1.0).unwrap();
        let sim = simulate_impact(&mut law, 1.0, 1.0, &settings).unwrap();
        prop_assert!((sim.restitution - law.restitution(1.0).unwrap()).abs() < 1e-7);
    }
}

#[test]
fn bad_input_names_the_parameter() {
    let name = |r: Result<f64, Error>| match r {
        Err(Error::InvalidParameter { parameter, .. }) => parameter,
        other => panic!("expected an invalid parameter, got {other:?}"),
    };
    assert_eq!(name(contact_characteristic(f64::NAN, 0.1)), "gap");
    assert_eq!(name(contact_characteristic(0.0, -0.1)), "rounding");
    assert_eq!(name(loss_factor(0.0, 0.0)), "loss_speed");
    assert_eq!(name(loss_factor(f64::INFINITY, 1.0)), "gap_rate");
    assert_eq!(name(characteristic_loss_speed(1.5, 1.0)), "restitution");
    assert_eq!(name(characteristic_loss_speed(0.0, 1.0)), "restitution");
    assert_eq!(name(characteristic_loss_speed(0.5, -1.0)), "impact_speed");
    assert_eq!(name(exact_damping_factor(-0.5, 1.0)), "restitution");
    assert_eq!(name(damped_restitution(-1.0, 1.0)), "damping_factor");
    assert_eq!(
        name(DampingModel::Flores.damping_factor(0.5, 0.0)),
        "impact_speed"
    );
    assert!(matches!(
        DampedPowerLaw::new(1.0, 0.0, 0.0),
        Err(Error::InvalidParameter {
            parameter: "exponent",
            ..
        })
    ));
    assert!(matches!(
        ContactCharacteristic::new(f64::INFINITY, 0.0, 1.0),
        Err(Error::InvalidParameter {
            parameter: "stiffness",
            ..
        })
    ));
}
