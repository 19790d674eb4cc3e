//! The silica impact the oblique module's tests share (`capture_tests`,
//! `polar_tests`, `planar`'s tests): two silica microspheres of
//! `examples/scenes/silica_oblique.toml` (R = 1 µm, E = 54 GPa, ν = 0.17,
//! w = 0.05 J/m², JKR) or one on a flat.
#![allow(clippy::unwrap_used)]

use super::{Body, NormalContact, ObliqueImpact};
use crate::{EffectiveShear, Friction};
use tabor_jkr::{JkrForceLaw, JkrSphere, SeparationRule};

/// Young's modulus (Pa).
pub(super) const E: f64 = 54e9;
/// Poisson's ratio.
pub(super) const NU: f64 = 0.17;
/// Work of adhesion (J/m²).
pub(super) const W: f64 = 0.05;
/// Sphere radius (m).
pub(super) const R: f64 = 1e-6;

/// The shear modulus `G*` of the pair (Pa): `mindlin`'s `k_t = 8 G*`.
pub(super) fn shear_modulus() -> f64 {
    EffectiveShear::of_pair(E, NU, E, NU).unwrap().modulus()
}

/// The silica sphere on a flat or a pair (JKR with separation rule `rule`,
/// the pull-off force `(3/2) π w R*`), with the normal damping `(c, β)` of
/// [`NormalContact`], the friction `friction` and the spins `(ω_i, ω_j)`
/// given, and its force law.
pub(super) fn silica(
    flat: bool,
    rule: SeparationRule,
    (damping, damping_exponent): (f64, f64),
    friction: Friction,
    (sphere_spin, target_spin): ([f64; 3], [f64; 3]),
) -> (ObliqueImpact, JkrForceLaw) {
    let sphere = Body::solid_sphere(R, 2650.0).unwrap();
    let target = if flat { Body::flat() } else { sphere };
    let reff = if flat { R } else { 0.5 * R };
    let law = JkrForceLaw::new(
        JkrSphere::new(E / (2.0 * (1.0 - NU * NU)), reff, W).unwrap(),
        rule,
    );
    let imp = ObliqueImpact {
        sphere,
        target,
        normal: NormalContact {
            pull_off_force: 1.5 * std::f64::consts::PI * W * reff,
            damping,
            damping_exponent,
        },
        friction: Some(friction),
        sphere_spin,
        target_spin,
    };
    (imp, law)
}
