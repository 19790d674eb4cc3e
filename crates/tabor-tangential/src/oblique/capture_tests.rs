//! The capture of a damped contact (`super::capture`) against the impact
//! without it: the same decision (stick or separate) at every speed of a
//! bisection for the sticking velocity, the same rebound where they separate,
//! an earlier end where they stick; and the overdamped contacts that without it
//! ran into the step limit.
#![allow(clippy::unwrap_used)]

use super::capture::WITHOUT_CAPTURE;
use super::silica_tests::{shear_modulus, silica, R};
use super::{Body, ObliqueOutcome};
use crate::{Friction, Rolling, Tangential, TangentialModel, Twisting};
use tabor_dynamics::SimulationSettings;
use tabor_jkr::SeparationRule;

/// The friction of a case: `linear_history` with a dashpot (as the scene of
/// the overdamped record, `tabor-scene`'s `damped_oblique.rs`) and `sds`
/// rolling, or `mindlin` with `marshall` twisting.
fn friction(linear: bool) -> Friction {
    if linear {
        let t = Tangential::new(TangentialModel::LinearHistory, 2.0e3, 0.5, 0.3).unwrap();
        Friction::sliding(t).with_rolling(Rolling::sds(50.0, 1e-9, 0.1).unwrap())
    } else {
        let t = Tangential::new(TangentialModel::Mindlin, 8.0 * shear_modulus(), 0.0, 0.3).unwrap();
        Friction::sliding(t).with_twisting(Twisting::Marshall)
    }
}

/// [`silica`] (JKR load-controlled, viscoelastic damping `c a ḋ`) with the
/// friction of [`friction`] and a spin about z, at speed
/// `v` and angle 10°; `capture`: watched (as simulated) or not.
fn impact(flat: bool, linear: bool, c: f64, v: f64, capture: bool) -> ObliqueOutcome {
    impact_spinning(flat, linear, c, v, capture, [0.0, 0.0, 1e4])
}

/// [`impact`] with the sphere's spin `spin` (out of the impact plane: the
/// full, three-dimensional state).
fn impact_spinning(
    flat: bool,
    linear: bool,
    c: f64,
    v: f64,
    capture: bool,
    spin: [f64; 3],
) -> ObliqueOutcome {
    let load = SeparationRule::LoadControlled;
    let (imp, mut law) = silica(flat, load, (c, 1.0), friction(linear), (spin, [0.0; 3]));
    WITHOUT_CAPTURE.with(|w| w.set(!capture));
    let out = imp.simulate(
        &mut law,
        v,
        10.0,
        &SimulationSettings::with_tolerance(1e-10).unwrap(),
    );
    WITHOUT_CAPTURE.with(|w| w.set(false));
    out.unwrap()
}

/// At every speed a bisection for the sticking velocity visits (in log space,
/// 0.01 to 3 m/s), the impact with the capture sticks exactly where the one
/// without it sticks; where they separate the rebound (e_n, e_t, rebound angle,
/// contact time) is the same to 1e-9 relative (the capture's event value only
/// joins the others' minimum); planar and, with a spin out of the plane, the
/// full state; the ledger closes
/// (1e-8 of the kinetic energy). Where they stick either may end first: the
/// impact without the capture ends where the bodies turn inward again (the
/// law's `on_min_compression`), the capture where the escape energy runs out. Flat (rigorous) and pair, two friction models, a damping that makes
/// the sticking velocity lie inside the range.
#[test]
fn capture_decides_as_the_impact_without_it() {
    for (flat, linear, spin) in [
        (true, true, [0.0, 0.0, 1e4]),
        (true, false, [0.0, 0.0, 1e4]),
        (false, true, [0.0, 0.0, 1e4]),
        (false, false, [0.0, 0.0, 1e4]),
        (false, false, [1e4, -5e3, 1e4]),
    ] {
        let c = 30.0;
        let (mut lo, mut hi) = (0.01f64.ln(), 3.0f64.ln());
        let (mut sticks_seen, mut separates_seen) = (0, 0);
        for _ in 0..10 {
            let v = (0.5 * (lo + hi)).exp();
            let with = impact_spinning(flat, linear, c, v, true, spin);
            let without = impact_spinning(flat, linear, c, v, false, spin);
            let case = format!("flat {flat}, linear {linear}, spin {spin:?}, v {v:.6}");
            assert_eq!(with.sticks, without.sticks, "{case}");
            assert!(with.energy_error < 1e-8, "{case}: {}", with.energy_error);
            if with.sticks {
                sticks_seen += 1;
                lo = v.ln();
            } else {
                separates_seen += 1;
                for ((name, a), (_, b)) in with.compared().into_iter().zip(without.compared()) {
                    assert!((a - b).abs() <= 1e-9 * b.abs(), "{case}: {name} {a} vs {b}");
                }
                hi = v.ln();
            }
        }
        assert!(
            sticks_seen > 0 && separates_seen > 0,
            "{flat} {linear} {spin:?}"
        );
    }
}

/// Strongly overdamped contacts (the viscoelastic η_n0 = 10¹⁹ 1/(m s) of the
/// record in `tabor-scene`, `c = η_n0 m*`, about 100 times critical, and on a
/// flat 200 times more) creep into the adhesive equilibrium without a turning
/// point: without the capture they ran into DOP853's step limit (10⁶ steps);
/// with it they stick, the ledger closed. On a flat, and on the pair with
/// `mindlin`, within 100 steps of first touch (the capture, then the normal
/// motion's rest: 15 and 46 steps); the pair with the soft
/// `linear_history` spring and its dashpot only once the tangential spring
/// has crept (relaxation time γ/k ≈ 1.4 µs, so ~60 000 steps of the inertial
/// time): the escape energy counts its stored energy and the kinetic energy
/// beyond a rigid rotation as convertible (`Setup::escape_energy`).
#[test]
fn overdamped_contacts_are_captured() {
    let m_eff = 0.5 * 4.0 / 3.0 * std::f64::consts::PI * R * R * R * 2650.0;
    for (flat, c) in [(false, 1e19 * m_eff), (true, 2e21 * m_eff)] {
        for linear in [true, false] {
            let o = impact(flat, linear, c, 0.3, true);
            let case = format!("flat {flat}, linear {linear}");
            assert!(o.sticks, "{case}");
            assert!(o.energy_error < 1e-8, "{case}: {}", o.energy_error);
            if flat || !linear {
                assert!(o.cost.iterations <= 100, "{case}: {:?}", o.cost);
            }
        }
    }
}

/// The capture's bound for a pair rests on the conservation of the angular
/// momentum about the centre of mass, `m* d × u + I_i ω_i + I_j ω_j`, by every
/// contact force and torque (LAMMPS's torque arms `R − δ/2` sum to the
/// distance of the centres; rolling and twisting torques are equal and
/// opposite). Along whole impacts with `mindlin` friction, `sds` rolling,
/// `marshall` twisting and spins in three dimensions (the full state), damped
/// and undamped, it stays at its value at first touch to 1e-9 of the orbital
/// scale `m* (R_i + R_j) v` at every segment end (measured: ≤ 4e-16; with the
/// sphere's torque arm `R_i` instead of `R_i − δ/2` it drifts by 1.6e-6).
#[test]
fn the_angular_momentum_of_a_pair_is_conserved() {
    use super::capture::MOMENTA;
    let t = Tangential::new(TangentialModel::Mindlin, 8.0 * shear_modulus(), 0.5, 0.3).unwrap();
    let fr = Friction::sliding(t)
        .with_rolling(Rolling::sds(50.0, 1e-9, 0.1).unwrap())
        .with_twisting(Twisting::Marshall);
    let m_eff = 0.5 * Body::solid_sphere(R, 2650.0).unwrap().mass;
    for (c, angle) in [(0.0, 10.0), (0.0, 60.0), (30.0, 40.0)] {
        let spins = ([2e4, -1e4, 3e4], [-1e4, 5e3, 1e4]);
        let load = SeparationRule::LoadControlled;
        let (imp, mut law) = silica(false, load, (c, 1.0), fr, spins);
        MOMENTA.with(|m| m.borrow_mut().clear());
        imp.simulate(
            &mut law,
            0.3,
            angle,
            &SimulationSettings::with_tolerance(1e-10).unwrap(),
        )
        .unwrap();
        let momenta = MOMENTA.with(|m| m.take());
        let scale = m_eff * 2.0 * R * 0.3;
        assert!(
            momenta.len() >= 3,
            "c {c}, {angle}°: {} segments",
            momenta.len()
        );
        for l in &momenta {
            let drift = (l - momenta[0]).norm() / scale;
            assert!(
                drift <= 1e-9,
                "c {c}, {angle}°: {drift:e} ({l:?} vs {:?})",
                momenta[0]
            );
        }
    }
}

/// A damped contact that forms without the energy to separate (here at
/// 0.01 m/s, far below the sticking velocity) sticks whatever it does, but runs
/// until its normal motion has come to rest, so its ledger books what it lost:
/// on a flat the normal kinetic energy (`½ m (v cos α)²`, all but 10⁻⁶ of it),
/// the normal velocity left at 10⁻³ of `v cos α`. (Ended at once, as until
/// it was judged at onset, it booked 0 J.)
#[test]
fn a_contact_formed_without_the_energy_to_separate_books_its_loss() {
    for linear in [true, false] {
        let o = impact(true, linear, 30.0, 0.01, true);
        let v_n = 0.01 * 10f64.to_radians().cos();
        let m = Body::solid_sphere(R, 2650.0).unwrap().mass;
        let normal = 0.5 * m * v_n * v_n;
        assert!(o.sticks, "linear {linear}");
        assert!(o.contact_time > 0.0, "linear {linear}: {o:?}");
        assert!(
            o.energy_loss >= (1.0 - 1e-6) * normal,
            "linear {linear}: {o:?}"
        );
        let u_n = o.after.sphere.velocity[0];
        // where it ended the normal energy is 10⁻⁶ of its value: |u_n| = 10⁻³ v_n
        assert!(
            u_n.abs() <= 1e-3 * v_n * (1.0 + 1e-9),
            "linear {linear}: {u_n:e}"
        );
        assert!(o.energy_error < 1e-8, "linear {linear}: {}", o.energy_error);
    }
}
