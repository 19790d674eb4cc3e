//! Energy bookkeeping as a property: for random oblique impacts (Hertz and JKR,
//! sphere on sphere and on a flat, with friction, rolling, twisting, damping and
//! initial spin) the work of every mechanism adds up to the kinetic energy lost.
//! Every case must run: an error counts as a failure (the physics is defined for
//! all of them).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use proptest::prelude::*;
use tabor_dynamics::{ForceLaw, SimulationSettings};
use tabor_elastic::ElasticContact;
use tabor_jkr::{JkrForceLaw, JkrSphere, SeparationRule};
use tabor_tangential::oblique::{Body, NormalContact, ObliqueImpact};
use tabor_tangential::{EffectiveShear, Friction, Rolling, Tangential, TangentialModel, Twisting};

const R: f64 = 1e-6;

#[allow(clippy::too_many_arguments)]
fn run(
    adhesive: bool,
    flat: bool,
    model: usize,
    speed: f64,
    angle: f64,
    mu: f64,
    rolling: Option<(f64, f64)>,
    twisting: usize,
    damping: f64,
    spin: f64,
) -> Result<f64, String> {
    let (e, nu, w) = (54e9, 0.17, 0.05);
    let sphere = Body::solid_sphere(R, 2650.0).unwrap();
    let target = if flat { Body::flat() } else { sphere };
    // a flat of the same material: the same E* as two spheres
    let e_star = e / (2.0 * (1.0 - nu * nu));
    let reff = if flat { R } else { 0.5 * R };
    let shear = EffectiveShear::of_pair(e, nu, e, nu).unwrap();
    let model = TangentialModel::ALL[model];
    let stiffness = match model {
        TangentialModel::LinearHistory => 8.0 * shear.modulus() * 3e-8,
        _ => 8.0 * shear.modulus(),
    };
    let mut friction =
        Friction::sliding(Tangential::new(model, stiffness, 0.5, mu).map_err(|e| e.to_string())?);
    if let Some((k, m)) = rolling {
        friction = friction.with_rolling(Rolling::sds(k, 1e-9, m).unwrap());
    }
    friction.twisting = match twisting {
        0 => None,
        1 => Some(Twisting::Marshall),
        _ => Some(Twisting::sds(1e-9, 1e-15, 1e-7).unwrap()),
    };
    let mut law: Box<dyn ForceLaw> = if adhesive {
        Box::new(JkrForceLaw::new(
            JkrSphere::new(e_star, reff, w).unwrap(),
            SeparationRule::LoadControlled,
        ))
    } else {
        Box::new(ElasticContact::hertz(e_star, reff).unwrap())
    };
    let imp = ObliqueImpact {
        sphere,
        target,
        normal: NormalContact {
            pull_off_force: if adhesive {
                1.5 * std::f64::consts::PI * w * reff
            } else {
                0.0
            },
            damping,
        },
        friction: Some(friction),
        sphere_spin: [0.0, 0.0, spin],
        target_spin: [0.0, 0.0, -0.3 * spin],
    };
    let out = imp
        .simulate(
            law.as_mut(),
            speed,
            angle,
            &SimulationSettings::with_tolerance(1e-8).unwrap(),
        )
        .map_err(|e| e.to_string())?;
    Ok(out.energy_error)
}

proptest! {
    #[test]
    fn the_mechanisms_account_for_the_energy_lost(
        adhesive in any::<bool>(),
        flat in any::<bool>(),
        model in 0usize..3,
        speed in 0.05f64..2.0,
        angle in 0.0f64..85.0,
        mu in 0.05f64..1.0,
        rolling in proptest::option::of((1.0f64..100.0, 0.0f64..0.3)),
        twisting in 0usize..3,
        damping in prop_oneof![Just(0.0), 1e-3f64..1e-1],
        spin in prop_oneof![Just(0.0), -1e5f64..1e5],
    ) {
        match run(adhesive, flat, model, speed, angle, mu, rolling, twisting, damping, spin) {
            Ok(error) => prop_assert!(error < 1e-6, "energy error {error:e}"),
            Err(e) => prop_assert!(false, "the simulation failed: {e}"),
        }
    }
}
