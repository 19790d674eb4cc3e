//! A damped element that sticks again while its dashpot alone reaches the
//! limit: LAMMPS's history `(L û − γ v)/k` keeps the force continuous at the
//! limit and strains the spring against the slip, energy no work put in, which
//! the ledger books as a negative `tangential_spring` (found by a random sweep,
//! stop 40: a silica sphere on an alumina flat, Hertz with Tsuji damping,
//! `linear_history` with a tangential dashpot, in the tensile end where the
//! limit falls below the dashpot's force). A constant spring without a dashpot
//! books what it holds, never less than 0.

#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use tabor_scene::{Format, Scene};
use tabor_tangential::oblique::ObliqueOutcome;

const RADIUS: f64 = 2.60500166807499e-06;
const DENSITY: f64 = 2650.0;
const SPIN: f64 = 506218.2332546178;
const SPEED: f64 = 0.8559555160566228;
const ANGLE: f64 = 60.952350458462234;

fn scene(tangential_damping: f64) -> Scene {
    let text = format!(
        "name = \"silica on an alumina flat\"\n\
         [sphere]\nradius = {RADIUS:e}\ndensity = {DENSITY}\nyoungs_modulus = 54e9\npoisson_ratio = 0.17\n\
         [target]\nyoungs_modulus = 380e9\npoisson_ratio = 0.23\n\
         [damping]\nmodel = \"tsuji\"\ncoefficient = 0.882909\n\
         [friction]\ncoefficient = 0.396452\ntangential = \"linear_history\"\n\
         tangential_stiffness = 15666.8\ntangential_damping = {tangential_damping}\n\
         rolling = {{ stiffness = 49.1194, damping = 0.0, coefficient = 0.29667 }}\n\
         [impact]\nsphere_spin = [0.0, 0.0, {SPIN}]\n"
    );
    Scene::from_str(&text, Format::Toml).unwrap()
}

/// The sphere's kinetic energy (translation and rotation) before (relative
/// speed [`SPEED`], spin [`SPIN`]) and after the impact (the flat does not
/// move).
fn kinetic_energies(o: &ObliqueOutcome) -> (f64, f64) {
    let (m, inertia) = common::solid_sphere(RADIUS, DENSITY);
    let before = common::kinetic_energy(m, inertia, &[SPEED, 0.0, 0.0], &[0.0, 0.0, SPIN]);
    let s = &o.after.sphere;
    (
        before,
        common::kinetic_energy(m, inertia, &s.velocity, &s.angular_velocity),
    )
}

/// The impact with the tangential dashpot `tangential_damping`, checked: the
/// ledger closes and the bodies gain nothing (a strain is ~1e-6 of the energy
/// the damping and the sliding take). Returns it and the energy before.
fn checked_impact(tangential_damping: f64) -> (ObliqueOutcome, f64) {
    let o = scene(tangential_damping).oblique(SPEED, ANGLE).unwrap();
    let (before, after) = kinetic_energies(&o);
    assert!(o.energy_error < 1e-9, "energy error {:e}", o.energy_error);
    assert!(
        after < before,
        "kinetic energy {after:e} after, {before:e} before"
    );
    (o, before)
}

#[test]
fn a_spring_strained_by_the_stick_reset_books_negative() {
    let (o, before) = checked_impact(0.635606);
    let spring = o.losses.tangential_spring;
    // measured: −3.3755e-19 J, the strain energy |L û − γ v|²/2k of the
    // history at the switch to stick (L = 3.98e-8 N, γ v = 1.43e-7 N,
    // k = 15 666.8 N/m: ξ = −6.564e-12 m, 3.375e-19 J); −2.4e-6 of the energy
    assert!(
        spring < -1e-7 * before && spring > -1e-5 * before,
        "tangential_spring {spring:e} J of {before:e} J"
    );
}

#[test]
fn a_constant_spring_without_a_dashpot_books_what_it_holds() {
    let (o, before) = checked_impact(0.0);
    // measured: −1.4e-10 of the energy before (rounding of the sliding work)
    assert!(
        o.losses.tangential_spring >= -1e-9 * before,
        "tangential_spring {:e} J of {before:e} J",
        o.losses.tangential_spring
    );
}
