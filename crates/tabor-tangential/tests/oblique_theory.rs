//! The oblique impact against theory: frictionless and gross-sliding limits
//! (exact, rigid-body Coulomb), the stick limit against an independent
//! integration, Maw-Barber-Fawcett's tangential restitution, energy bookkeeping.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use approx::assert_relative_eq;
use tabor_dynamics::SimulationSettings;
use tabor_elastic::ElasticContact;
use tabor_tangential::oblique::{Body, NormalContact, ObliqueImpact};
use tabor_tangential::{EffectiveShear, Friction, Tangential};

const R: f64 = 1e-6;
const RHO: f64 = 2650.0;
const E_Y: f64 = 54e9;
const NU: f64 = 0.17;

fn effective_modulus_flat() -> f64 {
    // sphere on a rigid flat of the same material, LAMMPS wall: E/(2(1 − ν²))... here
    // a flat of the same material: 1/E* = 2(1 − ν²)/E
    E_Y / (2.0 * (1.0 - NU * NU))
}

fn on_flat(mu: f64) -> (ObliqueImpact, ElasticContact) {
    let shear = EffectiveShear::of_pair(E_Y, NU, E_Y, NU).unwrap();
    let friction = Friction::sliding(Tangential::mindlin(shear, 0.0, mu).unwrap());
    let imp = ObliqueImpact {
        sphere: Body::solid_sphere(R, RHO).unwrap(),
        target: Body::flat(),
        normal: NormalContact::ELASTIC,
        friction: Some(friction),
        sphere_spin: [0.0; 3],
        target_spin: [0.0; 3],
    };
    (
        imp,
        ElasticContact::hertz(effective_modulus_flat(), R).unwrap(),
    )
}

fn settings() -> SimulationSettings {
    SimulationSettings::with_tolerance(1e-9).unwrap()
}

#[test]
fn frictionless_impact_keeps_the_tangential_velocity() {
    let (mut imp, mut law) = on_flat(0.3);
    imp.friction = None;
    let out = imp.simulate(&mut law, 0.5, 40.0, &settings()).unwrap();
    assert_relative_eq!(out.normal_restitution, 1.0, max_relative = 1e-8);
    assert_relative_eq!(
        out.tangential_restitution.unwrap(),
        -1.0,
        max_relative = 1e-12
    );
    assert!(out.energy_error < 1e-8, "{}", out.energy_error);
}

#[test]
fn gross_sliding_is_rigid_body_coulomb() {
    // sliding throughout: the friction impulse is μ P_n with P_n = 2 m v_n (e_n = 1),
    // so the contact point slows by μ P_n (1/m + R²/I) = 7 μ v_n (solid sphere) and
    // the sphere spins up to ω_z = −R μ P_n / I = −5 μ v_n / R. A flat target: the
    // torque arm is R exactly (LAMMPS's wall), so the closed form is exact.
    let mu = 0.1;
    let (imp, mut law) = on_flat(mu);
    for &(v, angle) in &[(0.3, 80.0), (1.0, 70.0), (0.05, 85.0)] {
        let out = imp.simulate(&mut law, v, angle, &settings()).unwrap();
        let a = f64::to_radians(angle);
        let vn = v * a.cos();
        assert_eq!(out.slip_switches, 0, "slides throughout");
        assert_relative_eq!(out.normal_restitution, 1.0, max_relative = 1e-8);
        let et = -1.0 + 7.0 * mu / a.tan();
        assert_relative_eq!(out.tangential_restitution.unwrap(), et, max_relative = 1e-8);
        assert_relative_eq!(
            out.after.sphere.angular_velocity[2],
            -5.0 * mu * vn / R,
            max_relative = 1e-8
        );
        // all of the loss is sliding friction: μ P_n times the mean slip speed
        let loss = out.energy_loss;
        assert_relative_eq!(
            out.losses.sliding_friction + out.losses.tangential_spring,
            loss,
            max_relative = 1e-7
        );
        assert!(out.energy_error < 1e-8, "{}", out.energy_error);
    }
}

/// Maw, Barber & Fawcett (1976), Wear 38, 101: the tangential restitution β of the
/// contact point against the normalized angle Ψ = κ tan α / μ, κ = 4G*/E*
/// (= 2(1 − ν)/(2 − ν) for equal materials), for a solid sphere (K = 2/5).
///
/// Expected agreement. Where the sphere slides throughout (Ψ ≥ 7κ, the contact
/// point never stops), every Coulomb model gives MBF's line β = −1 + 7κ/Ψ exactly
/// (the impulse ratio is μ): the library must reproduce it to the integration
/// tolerance. Below it MBF resolve the Mindlin-Deresiewicz micro-slip annulus,
/// which LAMMPS's `mindlin` (the model here) does not have, and LAMMPS's
/// total-displacement form loads 3/2 times stiffer than Mindlin's incremental
/// law: only MBF's shape is expected, not their numbers — β rises above the
/// sliding line's zero to a positive maximum (the contact point reverses) and
/// tends to a stick limit independent of Ψ as Ψ → 0. The example
/// `oblique_impact` plots the curves.
#[test]
fn maw_barber_fawcett_sliding_line_and_shape() {
    let mu = 0.2;
    let (imp, mut law) = on_flat(mu);
    let shear = EffectiveShear::of_pair(E_Y, NU, E_Y, NU).unwrap().modulus();
    let kappa = 4.0 * shear / effective_modulus_flat();
    assert!((kappa - 2.0 * (1.0 - NU) / (2.0 - NU)).abs() < 1e-12);
    let beta = |psi: f64, law: &mut ElasticContact| {
        let angle = (psi * mu / kappa).atan().to_degrees();
        let out = imp.simulate(law, 0.5, angle, &settings()).unwrap();
        assert!(out.energy_error < 1e-8);
        (out.tangential_restitution.unwrap(), out.slip_switches)
    };
    // the sliding line: beyond Ψ = 7κ the contact point never stops
    for psi in [7.5 * kappa, 10.0, 20.0] {
        let (b, switches) = beta(psi, &mut law);
        assert_eq!(switches, 0, "Ψ = {psi}: slides throughout");
        assert_relative_eq!(b, -1.0 + 7.0 * kappa / psi, max_relative = 1e-8);
    }
    // below it: a positive maximum (the contact point reverses) ...
    let maximum = [2.0, 3.0, 4.0]
        .iter()
        .map(|&p| beta(p, &mut law).0)
        .fold(f64::NEG_INFINITY, f64::max);
    assert!(maximum > 0.1 && maximum < 1.0, "maximum β = {maximum}");
    // ... and a stick limit that no longer depends on Ψ
    let (b1, _) = beta(0.01, &mut law);
    let (b2, _) = beta(0.02, &mut law);
    assert!((b1 - b2).abs() < 1e-3, "β(0.01) = {b1}, β(0.02) = {b2}");
}
