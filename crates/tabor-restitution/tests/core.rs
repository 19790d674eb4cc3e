//! Tests of the restitution core with synthetic models whose answers are known in
#![allow(clippy::unwrap_used, clippy::expect_used)]
//! closed form.

use approx::assert_relative_eq;
use proptest::prelude::*;
use tabor_restitution::checks::{elastic_limit_check, quasi_static_check};
use tabor_restitution::effective::{
    effective_modulus, effective_radius, reduced_mass, sphere_mass,
};
use tabor_restitution::{
    impact, restitution_from_loss, sticking_velocity, ElasticMaterial, EnergyLoss, Error,
    ImpactModel, StickingMethod,
};

/// ΔU = c + k·(m v²/2): constant adhesive part plus a fixed fraction of the energy.
#[derive(Debug)]
struct AffineLoss {
    mass: f64,
    constant: f64,
    fraction: f64,
}

impl ImpactModel for AffineLoss {
    fn name(&self) -> String {
        "affine test loss".into()
    }
    fn effective_mass(&self) -> f64 {
        self.mass
    }
    fn energy_loss(&self, v: f64) -> tabor_restitution::Result<EnergyLoss> {
        Ok(EnergyLoss::closed_form(
            self.constant + self.fraction * 0.5 * self.mass * v * v,
            "test",
        ))
    }
    fn loss_is_speed_independent(&self) -> bool {
        self.fraction == 0.0
    }
    fn speed_scale(&self) -> f64 {
        (2.0 * self.constant.max(1e-300) / self.mass)
            .sqrt()
            .max(1e-6)
    }
}

#[test]
fn effective_properties() {
    let silica = ElasticMaterial::new(54e9, 0.17).unwrap();
    let e = effective_modulus(&silica, &silica).unwrap();
    assert_relative_eq!(e, 54e9 / (2.0 * (1.0 - 0.17 * 0.17)), max_relative = 1e-15);
    let e = effective_modulus(&silica, &ElasticMaterial::rigid()).unwrap();
    assert_relative_eq!(e, 54e9 / (1.0 - 0.17 * 0.17), max_relative = 1e-15);
    assert!(effective_modulus(&ElasticMaterial::rigid(), &ElasticMaterial::rigid()).is_err());
    assert_relative_eq!(
        effective_radius(1e-6, Some(1e-6)).unwrap(),
        0.5e-6,
        max_relative = 1e-15
    );
    assert_eq!(effective_radius(2.0, None).unwrap(), 2.0);
    assert_relative_eq!(
        reduced_mass(3.0, Some(6.0)).unwrap(),
        2.0,
        max_relative = 1e-15
    );
    assert_relative_eq!(
        sphere_mass(1.0, 3.0 / (4.0 * std::f64::consts::PI)).unwrap(),
        1.0,
        max_relative = 1e-15
    );
}

#[test]
fn errors_name_the_parameter_and_value() {
    let e = ElasticMaterial::new(-5.0, 0.3).unwrap_err();
    let msg = e.to_string();
    assert!(
        msg.contains("youngs_modulus") && msg.contains("-5"),
        "{msg}"
    );
    let e = ElasticMaterial::new(1e9, 0.7).unwrap_err();
    assert!(e.to_string().contains("poisson_ratio"), "{e}");
    let e = effective_radius(f64::NAN, None).unwrap_err();
    assert!(matches!(
        e,
        Error::InvalidParameter {
            parameter: "radius",
            ..
        }
    ));
    let e = restitution_from_loss(1.0, 1.0, 0.0).unwrap_err();
    assert!(e.to_string().contains("impact_speed"), "{e}");
    let e = restitution_from_loss(-1.0, 1.0, 1.0).unwrap_err();
    assert!(e.to_string().contains("energy_loss"), "{e}");
    let e = restitution_from_loss(1.0, 1.0, 1e300).unwrap_err();
    assert!(e.to_string().contains("impact_speed"), "{e}");
}

#[test]
fn restitution_known_values() {
    // half the energy lost: ε = 1/√2
    assert_relative_eq!(
        restitution_from_loss(0.25, 1.0, 1.0).unwrap(),
        0.5f64.sqrt(),
        max_relative = 1e-15
    );
    assert_eq!(restitution_from_loss(0.0, 1.0, 1.0).unwrap(), 1.0);
    assert_eq!(restitution_from_loss(0.5, 1.0, 1.0).unwrap(), 0.0);
    assert_eq!(restitution_from_loss(7.0, 1.0, 1.0).unwrap(), 0.0);
}

#[test]
fn sticking_velocity_closed_form_and_root_agree() {
    // constant loss: (5.38) closed form
    let model = AffineLoss {
        mass: 2.0,
        constant: 0.09,
        fraction: 0.0,
    };
    let vc = sticking_velocity(&model, 1e-12).unwrap();
    assert_eq!(vc.method, StickingMethod::ClosedForm);
    assert_relative_eq!(vc.speed, 0.3, max_relative = 1e-15);
    // speed-dependent loss: root of ε = 0, known in closed form
    let model = AffineLoss {
        mass: 2.0,
        constant: 0.09,
        fraction: 0.36,
    };
    let vc = sticking_velocity(&model, 1e-13).unwrap();
    assert_eq!(vc.method, StickingMethod::Root);
    let exact = (2.0f64 * 0.09 / (2.0 * (1.0 - 0.36))).sqrt();
    assert_relative_eq!(vc.speed, exact, max_relative = 1e-12);
    assert!(vc.cost.evaluations > 0);
}

#[test]
fn never_and_always_sticking_models() {
    let model = AffineLoss {
        mass: 1.0,
        constant: 0.0,
        fraction: 0.5,
    };
    let vc = sticking_velocity(&model, 1e-10).unwrap();
    assert_eq!(vc.method, StickingMethod::NeverSticks);
    assert_eq!(vc.speed, 0.0);
    // a lossless, speed-independent model (elastic contact) never sticks: before,
    // the closed form (5.38) reported "sticks below 0 m/s"
    let lossless = AffineLoss {
        mass: 1.0,
        constant: 0.0,
        fraction: 0.0,
    };
    assert!(lossless.loss_is_speed_independent());
    let vc = sticking_velocity(&lossless, 1e-10).unwrap();
    assert_eq!(vc.method, StickingMethod::NeverSticks);
    let model = AffineLoss {
        mass: 1.0,
        constant: 1.0,
        fraction: 1.5,
    };
    let e = sticking_velocity(&model, 1e-10).unwrap_err();
    assert!(e.to_string().contains("sticks at every speed"), "{e}");
    assert!(sticking_velocity(&model, f64::NAN).is_err());
}

#[test]
fn validity_checks() {
    // silica at 0.1 m/s is quasi-static, at 10 m/s it is not (v > 1e-3 ṽ_el)
    let ok = quasi_static_check(0.1, 54e9, 2650.0).unwrap();
    assert!(ok.satisfied && ok.warning().is_none());
    assert_relative_eq!(
        ok.wave_speed,
        (54e9f64 / 2650.0).sqrt(),
        max_relative = 1e-15
    );
    let bad = quasi_static_check(10.0, 54e9, 2650.0).unwrap();
    assert!(!bad.satisfied);
    assert_eq!(bad.warning().unwrap().code, "quasi-static");
    // (5.13): the implementation's form against the seed's second form
    let (e, r, m, v) = (1.2e11, 5e-3, 2e-3, 0.5);
    let check = elastic_limit_check(e, r, m, v, 1e9).unwrap();
    let seed =
        2.0 / std::f64::consts::PI * (15.0 * e.powi(4) * m * v * v / (16.0 * r.powi(3))).powf(0.2);
    assert_relative_eq!(check.max_pressure, seed, max_relative = 1e-13);
    assert_eq!(check.satisfied, seed <= 1.6e9);
    let weak = elastic_limit_check(e, r, m, v, 1e6).unwrap();
    assert_eq!(weak.warning().unwrap().code, "elastic-limit");
}

proptest! {
    #[test]
    fn restitution_in_unit_interval_and_energy_balance(
        log_loss in -30.0f64..10.0, log_m in -20.0f64..5.0, log_v in -6.0f64..3.0,
    ) {
        let (loss, m, v) = (10f64.powf(log_loss), 10f64.powf(log_m), 10f64.powf(log_v));
        let eps = restitution_from_loss(loss, m, v).unwrap();
        prop_assert!((0.0..=1.0).contains(&eps));
        let kinetic = 0.5 * m * v * v;
        if loss < kinetic {
            // ε² = 1 − |ΔU|/(m v0²/2)
            prop_assert!((eps * eps - (1.0 - loss / kinetic)).abs() <= 1e-14);
        } else {
            prop_assert_eq!(eps, 0.0);
        }
    }

    #[test]
    fn sticking_velocity_is_where_restitution_vanishes(
        log_c in -25.0f64..0.0, log_m in -18.0f64..2.0, fraction in 0.0f64..0.95,
    ) {
        let model = AffineLoss { mass: 10f64.powf(log_m), constant: 10f64.powf(log_c), fraction };
        let vc = sticking_velocity(&model, 1e-12).unwrap().speed;
        let below = impact(&model, vc * (1.0 - 1e-9)).unwrap();
        let above = impact(&model, vc * (1.0 + 1e-9)).unwrap();
        prop_assert!(below.sticks && below.restitution == 0.0);
        prop_assert!(!above.sticks && above.restitution > 0.0);
        let exact = (2.0 * model.constant / (model.mass * (1.0 - fraction))).sqrt();
        prop_assert!((vc / exact - 1.0).abs() <= 1e-11);
    }
}

#[test]
fn sticking_velocity_overflow_is_an_error() {
    let model = AffineLoss {
        mass: 1e-308,
        constant: 1e10,
        fraction: 0.0,
    };
    // either the speed scale or the closed form overflows: an error, never inf
    assert!(sticking_velocity(&model, 1e-10).is_err());
}

proptest! {
    /// Through the generic `impact` of a model: ε ∈ [0, 1], the rebound carries the
    /// kinetic energy that was not lost (m (ε v0)²/2 = m v0²/2 − |ΔU| when the bodies
    /// separate), and the bodies stick exactly when ε = 0, at v0 < v_c.
    #[test]
    fn impact_outcome_balances_the_energy(
        log_c in -25.0f64..0.0, log_m in -18.0f64..2.0, fraction in 0.0f64..0.95,
        log_ratio in -3.0f64..3.0,
    ) {
        let model = AffineLoss { mass: 10f64.powf(log_m), constant: 10f64.powf(log_c), fraction };
        let vc = (2.0 * model.constant / (model.mass * (1.0 - fraction))).sqrt();
        let v0 = vc * 10f64.powf(log_ratio);
        let out = impact(&model, v0).unwrap();
        prop_assert!((0.0..=1.0).contains(&out.restitution));
        prop_assert_eq!(out.rebound_speed, out.restitution * v0);
        let kinetic = 0.5 * model.mass * v0 * v0;
        prop_assert!((out.kinetic_energy / kinetic - 1.0).abs() <= 1e-15);
        let loss = model.constant + fraction * kinetic;
        if v0 > vc {
            prop_assert!(!out.sticks && out.restitution > 0.0);
            let rebound = 0.5 * model.mass * out.rebound_speed * out.rebound_speed;
            prop_assert!(
                (rebound + loss - kinetic).abs() <= 1e-12 * kinetic,
                "rebound {rebound} + loss {loss} != kinetic {kinetic}"
            );
            prop_assert!((out.energy_loss / loss - 1.0).abs() <= 1e-15);
        } else {
            prop_assert!(out.sticks && out.restitution == 0.0 && out.rebound_speed == 0.0);
            prop_assert_eq!(out.energy_loss, kinetic);
        }
    }
}

/// The loss sum of two affine losses is the affine loss with summed constants and
/// fractions (a closed form), boxed or borrowed; its sticking velocity is then
/// √(2c/(m(1 − k))) from ε² = 1 − 2ΔU/(m v²) = 0.
#[test]
fn loss_sum_adds_affine_losses() {
    use tabor_restitution::LossSum;
    let a = AffineLoss {
        mass: 2e-3,
        constant: 3e-6,
        fraction: 0.1,
    };
    let b = AffineLoss {
        mass: 2e-3,
        constant: 1e-6,
        fraction: 0.25,
    };
    let parts: Vec<Box<dyn ImpactModel>> = vec![Box::new(a), Box::new(b)];
    let sum = LossSum::new(parts).unwrap();
    for v in [0.01, 0.3, 7.0] {
        let expected = 4e-6 + 0.35 * 0.5 * 2e-3 * v * v;
        assert_relative_eq!(
            sum.energy_loss(v).unwrap().joules,
            expected,
            max_relative = 1e-15
        );
    }
    assert!(!sum.loss_is_speed_independent());
    let vc = sticking_velocity(&sum, 1e-13).unwrap();
    assert_relative_eq!(
        vc.speed,
        (2.0_f64 * 4e-6 / (2e-3 * (1.0 - 0.35))).sqrt(),
        max_relative = 1e-10
    );
    assert_eq!(sum.name(), "affine test loss + affine test loss");
}

#[test]
fn loss_sum_refuses_no_parts_and_different_masses() {
    use tabor_restitution::LossSum;
    let none: Vec<AffineLoss> = Vec::new();
    assert!(LossSum::new(none).is_err());
    let e = LossSum::new(vec![
        AffineLoss {
            mass: 1.0,
            constant: 0.0,
            fraction: 0.0,
        },
        AffineLoss {
            mass: 2.0,
            constant: 0.0,
            fraction: 0.0,
        },
    ])
    .unwrap_err()
    .to_string();
    assert!(e.contains("different effective masses"), "{e}");
}
