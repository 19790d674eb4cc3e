//! A contact without area stores no displacement: on Maugis-Dugdale's
//! no-contact part (the bodies attract, the contact radius is 0) the springs
//! `k_t a` and `½ k_t a²` have no stiffness, and the displacement the motion
//! carries them through there must not load the contact area that forms after
//! it (stop 38's defect §2.3: the `marshall` twisting element gave the bodies
//! 2 700 times the impact's kinetic energy, and the bookkeeping still closed).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use std::f64::consts::PI;
use tabor_scene::{Format, Scene};
use tabor_tangential::oblique::ObliqueOutcome;

/// Steel on alumina, 0.71 µm spheres, Maugis-Dugdale at Λ = 0.030 (range 3 nm),
/// Tsuji damping, micro-slip with a tangential dashpot, `marshall` twisting and a
/// sphere spinning about all three axes (found by a random sweep, stop 38).
const RADIUS: f64 = 7.070538060886218e-07;
const STEEL: (f64, f64, f64) = (7850.0, 210e9, 0.3);
const ALUMINA: (f64, f64, f64) = (3900.0, 380e9, 0.23);
const WORK_OF_ADHESION: f64 = 0.306142;
const RANGE: f64 = 3e-9;
const SPIN: [f64; 3] = [557730.6055069311, 423481.6205256239, 353415.32647131063];

fn scene(twisting: &str) -> Scene {
    let text = format!(
        "name = \"steel on alumina\"\n\
         [sphere]\nradius = {RADIUS:e}\ndensity = {}\nyoungs_modulus = {:e}\npoisson_ratio = {}\n\
         [target]\nradius = {RADIUS:e}\ndensity = {}\nyoungs_modulus = {:e}\npoisson_ratio = {}\n\
         [adhesion]\nwork_of_adhesion = {WORK_OF_ADHESION}\nrange = {RANGE:e}\n\
         [damping]\nmodel = \"tsuji\"\ncoefficient = 0.57498\n\
         [friction]\ncoefficient = 0.581555\ntangential = \"mindlin_deresiewicz\"\n\
         tangential_damping = 0.652599\n{twisting}\
         [impact]\nsphere_spin = [{}, {}, {}]\n",
        STEEL.0, STEEL.1, STEEL.2, ALUMINA.0, ALUMINA.1, ALUMINA.2, SPIN[0], SPIN[1], SPIN[2]
    );
    Scene::from_str(&text, Format::Toml).unwrap()
}

/// Mass and moment of inertia (2/5 m r²) of a sphere of density `rho`.
fn body(rho: f64) -> (f64, f64) {
    let m = rho * 4.0 / 3.0 * PI * RADIUS.powi(3);
    (m, 0.4 * m * RADIUS * RADIUS)
}

fn squared(v: &[f64; 3]) -> f64 {
    v.iter().map(|x| x * x).sum()
}

/// The bodies' kinetic energy (translation and rotation) in the centre-of-mass
/// frame, before (relative speed `v`, the sphere's spin) and after the impact.
fn kinetic_energies(o: &ObliqueOutcome, v: f64) -> (f64, f64) {
    let (m1, i1) = body(STEEL.0);
    let (m2, i2) = body(ALUMINA.0);
    let before = 0.5 * m1 * m2 / (m1 + m2) * v * v + 0.5 * i1 * squared(&SPIN);
    let (s, t) = (&o.after.sphere, &o.after.target);
    let after = 0.5 * m1 * squared(&s.velocity)
        + 0.5 * i1 * squared(&s.angular_velocity)
        + 0.5 * m2 * squared(&t.velocity)
        + 0.5 * i2 * squared(&t.angular_velocity);
    (before, after)
}

/// An upper bound of the energy the adhesion can give the bodies (the depth of
/// the potential well), from the Derjaguin (DMT) limit Λ → 0 that Λ = 0.030 is
/// near: the attraction `2π R* w` over the range `h` and over the Hertz overlap
/// `δ_eq` where the elastic force balances it, doubled for Maugis-Dugdale's
/// departure from that limit (its pull-off lies between 1.5 and 2 π R* w).
fn adhesive_well_bound() -> f64 {
    let r_star = 0.5 * RADIUS;
    let inv_e = (1.0 - STEEL.2 * STEEL.2) / STEEL.1 + (1.0 - ALUMINA.2 * ALUMINA.2) / ALUMINA.1;
    let e_star = 1.0 / inv_e;
    let pull = 2.0 * PI * r_star * WORK_OF_ADHESION;
    let delta_eq = (3.0 * pull / (4.0 * e_star * r_star.sqrt())).powf(2.0 / 3.0);
    2.0 * pull * (RANGE + delta_eq)
}

#[test]
fn twisting_through_the_no_contact_part_creates_no_energy() {
    // the speeds and angles of the sweep (the first) and of a second search:
    // the old code created 2.5e-12 to 6.2e-12 J in each, the bodies' energy
    // before being ~1e-15 J
    let bound = adhesive_well_bound();
    for (v, angle) in [
        (0.33221495396584527, 83.30138363463918),
        (0.14141020709247054, 71.25298359191767),
        (0.20824298458937868, 38.73585452742107),
    ] {
        let o = scene("twisting = \"marshall\"\n")
            .oblique(v, angle)
            .unwrap();
        let (before, after) = kinetic_energies(&o, v);
        assert!(
            after <= before + bound,
            "{v} m/s at {angle}°: the bodies' kinetic energy grew from {before:e} J to \
             {after:e} J, more than the adhesive well's {bound:e} J"
        );
        assert!(
            o.losses.twisting >= 0.0,
            "{v} m/s at {angle}°: twisting gave the bodies {:e} J",
            -o.losses.twisting
        );
        assert!(
            (o.losses.total() - o.energy_loss).abs() <= 1e-6 * before,
            "losses {:e} J against the kinetic energy lost {:e} J",
            o.losses.total(),
            o.energy_loss
        );
    }
}
