//! A damped Hertz sphere sliding on a flat with LAMMPS's `mindlin` and a tangential
//! dashpot: the Tsuji damping (`c a^½ δ̇`, LAMMPS's `tsuji` and
//! `coeff_restitution`) and a dashpot `x_γ c a^½` beside a spring `k ∝ a`.
//!
//! Regression: in gross sliding to the separation the spring part of the limit,
//! `L − γ û·v`, is negative for a strong dashpot (`x_γ = 1`) and vanishes there as
//! `a^½` while `k ∝ a`; the sliding work `g (L − γ û·v)/k` diverged as `1/δ` and
//! the integration stopped with "step size underflow". The dashpot's force along
//! the slip direction is now capped at the limit there.
//!
//! The reference is independent of the oblique integration: LAMMPS's own
//! time-stepped scheme for this planar impact, written in the test (its limit
//! dt → 0 is the model the library integrates in continuous time), and the energy
//! lost computed from the final velocities.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use tabor_dynamics::SimulationSettings;
use tabor_elastic::ElasticContact;
use tabor_tangential::oblique::{Body, NormalContact, ObliqueImpact};
use tabor_tangential::{EffectiveShear, Friction, Tangential};

// Chung & Ooi's aluminium alloy sphere (Test 6) on a rigid flat
const R: f64 = 0.1;
const RHO: f64 = 2700.0;
const E_Y: f64 = 70e9;
const NU: f64 = 0.33;
const MU: f64 = 0.4;
/// Tsuji's damping ratio of e = 0.5 (LAMMPS's `coeff_restitution` mapping).
const ALPHA: f64 = 0.481_769;

fn e_star() -> f64 {
    E_Y / (1.0 - NU * NU)
}

fn mass() -> f64 {
    4.0 / 3.0 * std::f64::consts::PI * R.powi(3) * RHO
}

/// `c` of `F_d = c a^½ δ̇`: `α √(m k_n)` with `k_n = (4/3) E* a`.
fn damping() -> f64 {
    ALPHA * (mass() * 4.0 / 3.0 * e_star()).sqrt()
}

fn impact(x_gamma: f64) -> ObliqueImpact {
    let shear = EffectiveShear::of_rigid_partner(E_Y, NU).unwrap();
    ObliqueImpact {
        sphere: Body::solid_sphere(R, RHO).unwrap(),
        target: Body::flat(),
        normal: NormalContact {
            pull_off_force: 0.0,
            damping: damping(),
            damping_exponent: 0.5,
        },
        friction: Some(Friction::sliding(
            Tangential::mindlin(shear, x_gamma, MU).unwrap(),
        )),
        sphere_spin: [0.0; 3],
        target_spin: [0.0; 3],
    }
}

/// LAMMPS's scheme for this planar impact, written here independently of the
/// library: velocity Verlet for the centre and the spin, the history `ξ += v_t dt`
/// each step, the trial force `−(k ξ + γ v_t)` capped at `μ |F_n|` with `ξ` reset
/// to the elastic part of the capped force (`pair granular`'s `mindlin`), `dt`
/// = `t_unit / steps`. Returns the sphere's final (v_y, ω_z R) (m/s).
fn time_stepped(x_gamma: f64, speed: f64, angle: f64, steps: f64) -> [f64; 2] {
    let m = mass();
    let inertia = 0.4 * m * R * R;
    let k_h = 4.0 / 3.0 * e_star() * R.sqrt();
    let c = damping();
    let k_t = 8.0 * EffectiveShear::of_rigid_partner(E_Y, NU).unwrap().modulus();
    let (v_n, v_t0) = (
        speed * angle.to_radians().cos(),
        speed * angle.to_radians().sin(),
    );
    let d_max = (15.0 * m * v_n * v_n / (16.0 * e_star() * R.sqrt())).powf(0.4);
    let dt = d_max / v_n / steps;
    // δ, δ̇, v_y, ω_z, ξ; forces at the current state (LAMMPS: after the position
    // update, with the half-step velocities)
    let (mut d, mut dd, mut vy, mut w, mut xi) = (0.0_f64, v_n, v_t0, 0.0_f64, 0.0_f64);
    let forces = |d: f64, dd: f64, vy: f64, w: f64, xi: &mut f64| -> (f64, f64) {
        let a = (R * d.max(0.0)).sqrt();
        let c_n = c * a.sqrt();
        let f_n = k_h * d.max(0.0).powf(1.5) + c_n * dd;
        let slip = vy + w * R;
        let (k, gamma) = (k_t * a, x_gamma * c_n);
        let mut f_t = -(k * *xi + gamma * slip);
        let limit = MU * f_n.abs();
        if f_t.abs() > limit {
            f_t = limit.copysign(f_t);
            *xi = if k > 0.0 {
                -(f_t + gamma * slip) / k
            } else {
                0.0
            };
        }
        (f_n, f_t)
    };
    let (mut f_n, mut f_t) = (0.0, 0.0);
    loop {
        // half kick, drift, history, forces, half kick
        dd -= 0.5 * dt * f_n / m;
        vy += 0.5 * dt * f_t / m;
        w += 0.5 * dt * f_t * R / inertia;
        d += dd * dt;
        if d <= 0.0 && dd < 0.0 {
            return [vy, w * R];
        }
        xi += (vy + w * R) * dt;
        (f_n, f_t) = forces(d, dd, vy, w, &mut xi);
        dd -= 0.5 * dt * f_n / m;
        vy += 0.5 * dt * f_t / m;
        w += 0.5 * dt * f_t * R / inertia;
    }
}

/// The continuous-time integration against LAMMPS's time-stepped scheme
/// ([`time_stepped`]), which converges to it at first order in dt: Richardson's
/// `2 X(dt/2) − X(dt)` from dt = t/4e4 and t/8e4 is its limit, and the same from
/// t/2e4 and t/4e4 differs from it by the error of the extrapolation; the oblique
/// result must lie within three times that plus 1e-7 of the speed (the
/// integration's 1e-10 and the friction-free first 10⁻⁶ of the overlap scale are
/// below it). Dashpots x_γ = 0 … 3 (x_γ ≥ 0.5: the dashpot alone reaches the
/// Coulomb limit at the ends of the contact, where the run stopped), at 20°
/// (stick and slip) and 70° (sliding).
#[test]
fn damped_mindlin_matches_the_time_stepped_scheme() {
    let speed = 0.2;
    let settings = SimulationSettings::with_tolerance(1e-10).unwrap();
    for angle in [20.0, 70.0] {
        for x_gamma in [0.0, 0.5, 1.0, 3.0] {
            let run = |steps| time_stepped(x_gamma, speed, angle, steps);
            let (x1, x2, x4) = (run(2e4), run(4e4), run(8e4));
            let mut law = ElasticContact::hertz(e_star(), R).unwrap();
            let out = impact(x_gamma)
                .simulate(&mut law, speed, angle, &settings)
                .unwrap_or_else(|e| panic!("x_γ = {x_gamma}, {angle}°: {e}"));
            let s = &out.after.sphere;
            let got = [s.velocity[1], s.angular_velocity[2] * R];
            for i in 0..2 {
                let limit = 2.0 * x4[i] - x2[i];
                let error = (limit - (2.0 * x2[i] - x1[i])).abs();
                assert!(
                    (got[i] - limit).abs() < 3.0 * error + 1e-7 * speed,
                    "x_γ = {x_gamma}, {angle}°, component {i}: {:e} against {limit:e} (± {error:e})",
                    got[i]
                );
            }
        }
    }
}

/// At every angle and dashpot the simulation runs (it stopped with a step size
/// underflow at 45° and 70° with `x_γ = 1`), the mechanisms add up to the kinetic
/// energy lost computed from the final velocities (1e-8 of the initial energy: the
/// integration's tolerance 1e-10 on the normalized state), and the dissipative
/// ones (normal and tangential damping, sliding) are non-negative.
#[test]
fn damped_oblique_impacts_run_and_account_for_their_energy() {
    let settings = SimulationSettings::with_tolerance(1e-10).unwrap();
    let m = mass();
    let inertia = 0.4 * m * R * R;
    let v = 0.2_f64;
    for x_gamma in [0.0, 0.5, 1.0, 3.0] {
        for angle in [5.0, 20.0, 45.0, 70.0, 85.0] {
            let mut law = ElasticContact::hertz(e_star(), R).unwrap();
            let out = impact(x_gamma)
                .simulate(&mut law, v, angle, &settings)
                .unwrap_or_else(|e| panic!("x_γ = {x_gamma}, {angle}°: {e}"));
            let s = &out.after.sphere;
            let sq = |w: [f64; 3]| w.iter().map(|c| c * c).sum::<f64>();
            let before = 0.5 * m * v * v;
            let after = 0.5 * m * sq(s.velocity) + 0.5 * inertia * sq(s.angular_velocity);
            let l = &out.losses;
            assert!(
                ((before - after) - l.total()).abs() < 1e-8 * before,
                "x_γ = {x_gamma}, {angle}°: lost {:e}, mechanisms {:e}",
                before - after,
                l.total()
            );
            for (name, w) in [
                ("normal_damping", l.normal_damping),
                ("sliding_friction", l.sliding_friction),
                ("tangential_damping", l.tangential_damping),
            ] {
                assert!(
                    w >= -1e-9 * before,
                    "x_γ = {x_gamma}, {angle}°: {name} = {w:e}"
                );
            }
        }
    }
}
