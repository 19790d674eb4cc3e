//! The verified LAMMPS reference case of `/work/shared/spec/lammps.md`: two silica
//! spheres (R = 1 µm, w = 0.05 J/m²), `jkr` with `mindlin NULL 0 0.3`, `sds 50 0 0.1`
//! and `marshall`, 10° at 0.3 m/s: CoM-frame velocity (−0.14455, 0.01749) m/s,
//! ω_z = −2.145e4 rad/s (LAMMPS, time step ~1/5000 of the contact time, its own
//! scheme: agreement to about three digits is what the time step allows).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use tabor_dynamics::SimulationSettings;
use tabor_jkr::{JkrForceLaw, JkrSphere, SeparationRule};
use tabor_tangential::oblique::{Body, NormalContact, ObliqueImpact};
use tabor_tangential::{EffectiveShear, Friction, Rolling, Tangential, Twisting};

#[test]
fn silica_10_degrees_matches_lammps() {
    let (r, rho, e, nu, w) = (1e-6, 2650.0, 54e9, 0.17, 0.05);
    let e_star = 1.0 / (2.0 * (1.0 - nu * nu) / e);
    let reff = 0.5 * r;
    let sphere = JkrSphere::new(e_star, reff, w).unwrap();
    let mut law = JkrForceLaw::new(sphere, SeparationRule::LoadControlled);
    let shear = EffectiveShear::of_pair(e, nu, e, nu).unwrap();
    let friction = Friction::sliding(Tangential::mindlin(shear, 0.0, 0.3).unwrap())
        .with_rolling(Rolling::sds(50.0, 0.0, 0.1).unwrap())
        .with_twisting(Twisting::Marshall);
    let body = Body::solid_sphere(r, rho).unwrap();
    let imp = ObliqueImpact {
        sphere: body,
        target: body,
        normal: NormalContact {
            pull_off_force: 1.5 * std::f64::consts::PI * w * reff,
            damping: 0.0,
            damping_exponent: 1.0,
        },
        friction: Some(friction),
        sphere_spin: [0.0; 3],
        target_spin: [0.0; 3],
    };
    let out = imp
        .simulate(
            &mut law,
            0.3,
            10.0,
            &SimulationSettings::with_tolerance(1e-8).unwrap(),
        )
        .unwrap();
    eprintln!("{out:#?}");
    let v = out.after.sphere.velocity;
    let wz = out.after.sphere.angular_velocity[2];
    assert!((v[0] - (-0.14455)).abs() < 2e-4, "{v:?}");
    assert!((v[1] - 0.01749).abs() < 2e-4, "{v:?}");
    assert!((wz - (-2.145e4)).abs() < 0.01 * 2.145e4, "{wz}");
    assert!(out.energy_error < 1e-7);
}
