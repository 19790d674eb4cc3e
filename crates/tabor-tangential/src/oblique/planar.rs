//! The planar impact on a reduced state: where the motion stays in the impact
//! plane (relative velocity and deviation in x-y, spins about z only, no twist)
//! every out-of-plane component of the state and of its rates is exactly 0 (the
//! normal and every tangential vector lie in the plane, every torque about z), so
//! DOP853 integrates the 18 components that move ([`PLANAR`]) instead of 27: the
//! same equations, with the out-of-plane zeros left out of the steps (exact, not
//! an approximation). Any other state integrates in full.

use super::state::*;
use tabor_numerics::ode::{
    drive_events, DormandPrince853, EventDirection, EventsIntegration, OdeSolution, OdeTolerance,
};

/// The components of the state that a planar impact moves: the deviation and
/// the relative velocity in x-y, the spins about z, the tangential and rolling
/// displacements in x-y; then the 8 energies (quadratures, last: outside the
/// error control).
pub(super) const PLANAR: [usize; 18] = [
    E,
    E + 1,
    U,
    U + 1,
    WI + 2,
    WJ + 2,
    XT,
    XT + 1,
    XR,
    XR + 1,
    EN,
    EN + 1,
    EN + 2,
    EN + 3,
    EN + 4,
    EN + 5,
    EN + 6,
    EN + 7,
];

/// The components of the state that stay 0 in a planar impact.
const OUT_OF_PLANE: [usize; 9] = [E + 2, U + 2, WI, WI + 1, WJ, WJ + 1, XT + 2, XR + 2, XW];

/// The motion components of [`PLANAR`] (the error control's).
const PLANAR_MOTION: usize = 10;

impl<'a> Setup<'a> {
    /// True when the state `y` in `modes` stays planar: every out-of-plane
    /// component 0 and the twisting element sticking (its torque `−(k θ + γ ω_tw)`
    /// is then 0: θ = 0 and ω_tw = (ω_i − ω_j)·n = 0 with the spins about z and n
    /// in the plane).
    pub(super) fn is_planar(&self, y: &[f64; N], modes: &Modes) -> bool {
        #[cfg(test)]
        if tests::FULL.with(std::cell::Cell::get) {
            return false;
        }
        modes.twisting == Mode::Stick && OUT_OF_PLANE.iter().all(|&i| y[i] == 0.0)
    }

    /// DOP853 on the [`PLANAR`] components from the normalized state `yn` at
    /// `ends.0` to the falling zero of `g` (or `ends.1`), with the SI rates
    /// `rates` and the event function `g` of the full SI state at SI time; the
    /// normalized rates are the SI ones times `rate_unit`. The result in the full
    /// normalized state. The planar components go to SI and their rates back
    /// without the full state's round trip: the same products (the out-of-plane
    /// components are 0 either way), so the same numbers. `quadratures`: the
    /// energies outside the error control. Starts with the last segment's
    /// proposed step and leaves its own ([`Setup::step_hint`]).
    #[allow(clippy::too_many_arguments)]
    pub(super) fn planar_segment<F, G>(
        &self,
        rates: &F,
        g: &G,
        rate_unit: &[f64; N],
        ends: (f64, f64),
        yn: &[f64; N],
        tolerance: OdeTolerance,
        quadratures: bool,
    ) -> tabor_numerics::Result<EventsIntegration<N>>
    where
        F: Fn(f64, &[f64; N]) -> [f64; N],
        G: Fn(f64, &[f64; N]) -> f64,
    {
        const M: usize = PLANAR.len();
        let (s0, s_end) = ends;
        let expand = |z: &[f64; M]| {
            let mut y = [0.0; N];
            for (&i, &v) in PLANAR.iter().zip(z.iter()) {
                y[i] = v;
            }
            y
        };
        let si = |z: &[f64; M]| {
            let mut y = [0.0; N];
            for (&i, &v) in PLANAR.iter().zip(z.iter()) {
                y[i] = v * self.scale[i];
            }
            y
        };
        let compress = |y: &[f64; N]| -> [f64; M] { std::array::from_fn(|k| y[PLANAR[k]]) };
        let mut f = |s: f64, z: &[f64; M]| -> [f64; M] {
            let dy = rates(s * self.time, &si(z));
            std::array::from_fn(|k| dy[PLANAR[k]] * rate_unit[PLANAR[k]])
        };
        let mut events = |s: f64, z: &[f64; M]| [g(s * self.time, &si(z))];
        let tolerance = self.dop853_tolerance(tolerance, quadratures, PLANAR_MOTION);
        let mut stepper = DormandPrince853::new(&mut f, s0, compress(yn), s_end, tolerance)?;
        let run = drive_events(
            &mut stepper,
            &mut f,
            &mut events,
            [EventDirection::Falling],
            s_end,
            &mut |_: f64, _: &[f64; M]| {},
        );
        self.step_hint.set(Some(stepper.proposed_step()));
        let run = run?;
        let sol = run.solution;
        Ok(EventsIntegration {
            solution: OdeSolution {
                t: sol.t,
                y: expand(&sol.y),
                event_found: sol.event_found,
                accepted_steps: sol.accepted_steps,
                rejected_steps: sol.rejected_steps,
                cost: sol.cost,
            },
            event: run.event,
            event_cost: run.event_cost,
        })
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use crate::oblique::{Body, NormalContact, ObliqueImpact, ObliqueOutcome};
    use crate::{EffectiveShear, Friction, Rolling, Tangential, TangentialModel, Twisting};
    use std::cell::Cell;
    use tabor_dynamics::SimulationSettings;
    use tabor_jkr::{JkrForceLaw, JkrSphere, SeparationRule};

    thread_local! {
        /// Integrate every segment on the full state (the reference).
        pub(super) static FULL: Cell<bool> = const { Cell::new(false) };
    }

    /// Two silica spheres (JKR load-controlled, `mindlin`, `sds` rolling,
    /// `marshall` twisting; `examples/scenes/silica_oblique.toml`) at 0.3 m/s, or
    /// a sphere on a flat, with a spin about z; `full`: on the full state.
    fn impact(flat: bool, angle: f64, full: bool, accuracy: f64) -> ObliqueOutcome {
        let (e, nu, w, r) = (54e9, 0.17, 0.05, 1e-6);
        let sphere = Body::solid_sphere(r, 2650.0).unwrap();
        let target = if flat { Body::flat() } else { sphere };
        let reff = if flat { r } else { 0.5 * r };
        let shear = EffectiveShear::of_pair(e, nu, e, nu).unwrap();
        let friction = Friction::sliding(
            Tangential::new(TangentialModel::Mindlin, 8.0 * shear.modulus(), 0.0, 0.3).unwrap(),
        )
        .with_rolling(Rolling::sds(50.0, 0.0, 0.1).unwrap())
        .with_twisting(Twisting::Marshall);
        let mut law = JkrForceLaw::new(
            JkrSphere::new(e / (2.0 * (1.0 - nu * nu)), reff, w).unwrap(),
            SeparationRule::LoadControlled,
        );
        let imp = ObliqueImpact {
            sphere,
            target,
            normal: NormalContact {
                pull_off_force: 1.5 * std::f64::consts::PI * w * reff,
                damping: 0.0,
                damping_exponent: 1.0,
            },
            friction: Some(friction),
            sphere_spin: [0.0, 0.0, 3e4],
            target_spin: [0.0, 0.0, if flat { 0.0 } else { -1e4 }],
        };
        FULL.with(|f| f.set(full));
        let out = imp
            .simulate(
                &mut law,
                0.3,
                angle,
                &SimulationSettings::with_tolerance(accuracy).unwrap(),
            )
            .unwrap();
        FULL.with(|f| f.set(false));
        out
    }

    /// The reduced state is exact: the full integration keeps every
    /// out-of-plane component at exactly 0 (so leaving them out changes nothing
    /// but the steps), and the two agree to the integration's accuracy (per-step
    /// tolerance 1e-12; measured differences ≤ 1e-12 relative, bound 1e-10) in
    /// the restitutions, the rebound angle and every loss.
    #[test]
    fn the_planar_state_integrates_the_full_one() {
        for flat in [false, true] {
            for angle in [10.0, 40.0, 80.0] {
                let planar = impact(flat, angle, false, 1e-10);
                let full = impact(flat, angle, true, 1e-10);
                for out in [&planar, &full] {
                    let (s, t) = (&out.after.sphere, &out.after.target);
                    assert_eq!(s.velocity[2], 0.0);
                    assert_eq!(t.velocity[2], 0.0);
                    assert_eq!(&s.angular_velocity[..2], &[0.0, 0.0]);
                    assert_eq!(&t.angular_velocity[..2], &[0.0, 0.0]);
                }
                // relative, or absolute below 1 (e_t is a small residual of the
                // contact point's velocity: its unit is the velocity before)
                let close = |a: f64, b: f64, what: &str| {
                    assert!(
                        (a - b).abs() <= 1e-10 * a.abs().max(b.abs()).max(1.0),
                        "{what} (flat {flat}, {angle}°): planar {a:e}, full {b:e}"
                    );
                };
                close(planar.normal_restitution, full.normal_restitution, "e_n");
                close(
                    planar.tangential_restitution.unwrap_or(0.0),
                    full.tangential_restitution.unwrap_or(0.0),
                    "e_t",
                );
                close(
                    planar.rebound_angle.unwrap_or(0.0),
                    full.rebound_angle.unwrap_or(0.0),
                    "rebound angle",
                );
                close(planar.contact_time, full.contact_time, "contact time");
                let total = planar.kinetic_energy;
                let (p, f) = (&planar.losses, &full.losses);
                for (a, b) in [
                    (p.normal_adhesion, f.normal_adhesion),
                    (p.sliding_friction, f.sliding_friction),
                    (p.tangential_spring, f.tangential_spring),
                    (p.rolling, f.rolling),
                    (p.twisting, f.twisting),
                    (p.torque_arm, f.torque_arm),
                ] {
                    assert!(
                        (a - b).abs() <= 1e-10 * total,
                        "loss (flat {flat}, {angle}°): planar {a:e}, full {b:e}"
                    );
                }
                assert!(planar.energy_error < 1e-11 && full.energy_error < 1e-11);
            }
        }
    }

    /// The energies outside the error control converge with the motion: the
    /// loss by mechanism at accuracy 1e-8 and 1e-10 equals that at 1e-13 to
    /// 1e-9 of the kinetic energy (measured ≤ 1e-13; the sliding work of a slip
    /// segment whose power had a kink where slip ends, integrated across the
    /// step that holds that event, was off by 2e-7 at every accuracy).
    #[test]
    fn the_losses_converge_with_the_accuracy() {
        for flat in [false, true] {
            for angle in [10.0, 40.0, 80.0] {
                let reference = impact(flat, angle, false, 1e-13);
                for accuracy in [1e-8, 1e-10] {
                    let out = impact(flat, angle, false, accuracy);
                    let (p, f) = (&out.losses, &reference.losses);
                    for (name, a, b) in [
                        ("adhesion", p.normal_adhesion, f.normal_adhesion),
                        ("sliding", p.sliding_friction, f.sliding_friction),
                        ("spring", p.tangential_spring, f.tangential_spring),
                        ("rolling", p.rolling, f.rolling),
                        ("twisting", p.twisting, f.twisting),
                        ("torque arm", p.torque_arm, f.torque_arm),
                    ] {
                        assert!(
                            (a - b).abs() <= 1e-9 * out.kinetic_energy,
                            "{name} (flat {flat}, {angle}°, {accuracy:e}): {a:e} vs {b:e}"
                        );
                    }
                }
            }
        }
    }
}
