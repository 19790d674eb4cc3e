//! The planar impact on a reduced state: where the motion stays in the impact
//! plane (relative velocity and deviation in x-y, spins about z only, no twist)
//! every out-of-plane component of the state and of its rates is exactly 0 (the
//! normal and every tangential vector lie in the plane, every torque about z), so
//! the integration carries the 18 components that move ([`PLANAR`]) instead of
//! 27, and evaluates their rates and the event values in two dimensions
//! ([`super::plane`]): the same equations, with the out-of-plane zeros left out
//! (exact, not an approximation). Any other state integrates in full.

use super::elements::keep_first;
use super::segment::sliding_work_to_event;
use super::state::*;
use std::cell::Cell;
use tabor_dynamics::ForceLaw;
use tabor_numerics::ode::{
    drive_events, DormandPrince, DormandPrince853, EventDirection, EventsIntegration, OdeSolution,
    OdeTolerance,
};
use tabor_restitution::Error;

/// The components of the state that a planar impact moves: the deviation and
/// the relative velocity in x-y, the spins about z, the tangential and rolling
/// displacements in x-y; then the 8 energies (quadratures, last: outside the
/// error control).
pub(super) const PLANAR: [usize; PM] = [
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

/// The number of components of the reduced state.
pub(super) const PM: usize = 18;
/// The reduced state's deviation (2).
pub(super) const P_E: usize = 0;
/// The reduced state's relative velocity (2).
pub(super) const P_U: usize = 2;
/// The reduced state's ω_i about z.
pub(super) const P_WI: usize = 4;
/// The reduced state's ω_j about z.
pub(super) const P_WJ: usize = 5;
/// The reduced state's tangential displacement (2).
pub(super) const P_XT: usize = 6;
/// The reduced state's rolling displacement (2).
pub(super) const P_XR: usize = 8;
/// The reduced state's energies (8, in the order of the full state's).
pub(super) const P_EN: usize = 10;

/// The components of the state that stay 0 in a planar impact.
const OUT_OF_PLANE: [usize; 9] = [E + 2, U + 2, WI, WI + 1, WJ, WJ + 1, XT + 2, XR + 2, XW];

/// The motion components of [`PLANAR`] (the error control's).
pub(super) const PLANAR_MOTION: usize = 10;

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

    /// The reduced state of the full one `y` (either units).
    pub(super) fn planar_of(y: &[f64; N]) -> [f64; PM] {
        std::array::from_fn(|k| y[PLANAR[k]])
    }

    /// The full state of the reduced one `z` (either units).
    pub(super) fn full_of(z: &[f64; PM]) -> [f64; N] {
        let mut y = [0.0; N];
        for (&i, &v) in PLANAR.iter().zip(z.iter()) {
            y[i] = v;
        }
        y
    }

    /// The energies (in the order of [`EN`]) whose rates can differ from 0 on a
    /// planar segment in `modes`: the rest stay constant (their rates are exact
    /// zeros; `planar_rates_match_the_full_ones` checks it) and need no steps.
    pub(super) fn active_energies(&self, modes: &Modes) -> [bool; 8] {
        let contact = modes.in_contact;
        let acting = contact && !modes.warmup;
        let fr = self.imp.friction.as_ref();
        let friction = acting && fr.is_some();
        let damped = self.imp.normal.damping != 0.0;
        [
            true,
            contact && damped,
            self.slipping_tangential(modes).is_some(),
            friction && self.tangential_dashpot(),
            friction,
            acting && fr.is_some_and(|f| f.rolling.is_some()),
            false,
            friction && !self.flat,
        ]
    }

    /// The components a segment integrates, of a state whose first `motion`
    /// components are the motion and whose energies start at `energy`: the
    /// motion, then the energies marked `active` (in the order of [`EN`]; see
    /// [`Setup::active_energies`]); and their number.
    pub(super) fn energy_slots<const L: usize>(
        active: [bool; 8],
        motion: usize,
        energy: usize,
    ) -> ([usize; L], usize) {
        let mut slots: [usize; L] = std::array::from_fn(|k| k);
        let mut m = motion;
        for (k, _) in active.iter().enumerate().filter(|(_, &a)| a) {
            slots[m] = energy + k;
            m += 1;
        }
        (slots, m)
    }

    /// The planar segment from the normalized state `yn` at `ends.0` to the
    /// falling zero of the event function (or `ends.1`) in `modes`: the rates of
    /// [`Setup::planar_evaluate`], the event function `combine` of the values of
    /// [`Setup::planar_event_values`] (the first error of each kept in `failure`
    /// and `g_failure`, the value then NaN). The result in the full normalized
    /// state. DOP853 as the full path (`quadratures`: the energies outside the
    /// error control, and only those of [`Setup::active_energies`] integrated:
    /// the same numbers; starts with the last segment's proposed step and leaves
    /// its own, [`Setup::step_hint`]), or, with the spring bed of micro-slip,
    /// Dormand-Prince 5(4) with the bed committed after every accepted step.
    #[allow(clippy::too_many_arguments)]
    pub(super) fn planar_segment(
        &self,
        law: &dyn ForceLaw,
        modes: &Modes,
        combine: &dyn Fn([f64; super::limits::EVENTS]) -> f64,
        failures: (&Cell<Option<Error>>, &Cell<Option<Error>>),
        ends: (f64, f64),
        yn: &[f64; N],
        tolerance: OdeTolerance,
        quadratures: bool,
    ) -> tabor_numerics::Result<EventsIntegration<N>> {
        let scale: [f64; PM] = std::array::from_fn(|k| self.scale[PLANAR[k]]);
        let run = Run {
            setup: self,
            law,
            modes,
            combine,
            failure: failures.0,
            g_failure: failures.1,
            scale,
            // SI rates to normalized ones: times the time unit, over the state's unit
            rate_unit: std::array::from_fn(|k| self.time / scale[k]),
        };
        let all: [usize; PM] = std::array::from_fn(|k| k);
        let polar = self.polar_segment(
            law,
            modes,
            combine,
            failures,
            ends,
            yn,
            tolerance,
            quadratures,
        );
        if let Some(run) = polar {
            return run;
        }
        if self.bed.is_some() {
            return run.micro_slip(all, ends, yn, tolerance);
        }
        let controlled = self.controlled_motion(modes, true);
        let tolerance = self.dop853_tolerance(tolerance, quadratures, controlled);
        if !quadratures {
            return run.dop853(all, ends, yn, tolerance);
        }
        // the motion, then the energies that move
        let active = self.active_energies(modes);
        let (slots, m) = Setup::energy_slots::<PM>(active, PLANAR_MOTION, P_EN);
        macro_rules! dispatch {
            ($($size:literal)*) => {
                match m {
                    $($size => run.dop853::<$size>(
                        std::array::from_fn(|j| slots[j]), ends, yn, tolerance),)*
                    _ => run.dop853(all, ends, yn, tolerance),
                }
            };
        }
        dispatch!(11 12 13 14 15 16 17)
    }
}

/// One planar segment: the setup, the law, the modes, the event function's
/// combination of the values, the first errors, the units of the reduced state.
struct Run<'s, 'a> {
    setup: &'s Setup<'a>,
    law: &'s dyn ForceLaw,
    modes: &'s Modes,
    combine: &'s dyn Fn([f64; super::limits::EVENTS]) -> f64,
    failure: &'s Cell<Option<Error>>,
    g_failure: &'s Cell<Option<Error>>,
    /// SI value of one normalized unit of each reduced component.
    scale: [f64; PM],
    /// SI rates to normalized ones, per reduced component.
    rate_unit: [f64; PM],
}

impl Run<'_, '_> {
    /// The reduced SI state of the motion components of `x` (the first
    /// [`PLANAR_MOTION`]), the energies 0 (no rate, event value or commit reads
    /// them).
    fn si<const M: usize>(&self, x: &[f64; M]) -> [f64; PM] {
        let mut z = [0.0; PM];
        for k in 0..PLANAR_MOTION {
            z[k] = x[k] * self.scale[k];
        }
        z
    }

    /// The normalized rates of the integrated components `x` (reduced
    /// components `slots`, the motion first; `units`: their SI rates to
    /// normalized ones) at normalized time `s`.
    fn rates<const M: usize>(
        &self,
        (slots, units): (&[usize; M], &[f64; M]),
        s: f64,
        x: &[f64; M],
    ) -> [f64; M] {
        let t = s * self.setup.time;
        let mut dz = [0.0; PM];
        match self
            .setup
            .planar_rates(self.law, t, &self.si(x), self.modes, &mut dz)
        {
            Ok(_) => std::array::from_fn(|j| dz[slots[j]] * units[j]),
            Err(e) => {
                keep_first(self.failure, e);
                [f64::NAN; M]
            }
        }
    }

    /// The event function at the integrated components `x` at normalized time `s`.
    fn event<const M: usize>(&self, s: f64, x: &[f64; M]) -> [f64; 1] {
        let t = s * self.setup.time;
        let z = self.si(x);
        [
            match self.setup.planar_event_values(self.law, t, &z, self.modes) {
                Ok(v) => (self.combine)(v),
                Err(e) => {
                    keep_first(self.g_failure, e);
                    f64::NAN
                }
            },
        ]
    }

    /// DOP853 on the reduced components `slots` (the motion first) from the
    /// normalized full state `yn`; the components left out keep their values.
    fn dop853<const M: usize>(
        &self,
        slots: [usize; M],
        (s0, s_end): (f64, f64),
        yn: &[f64; N],
        tolerance: OdeTolerance,
    ) -> tabor_numerics::Result<EventsIntegration<N>> {
        let units = std::array::from_fn(|j| self.rate_unit[slots[j]]);
        let mut f = |s: f64, x: &[f64; M]| self.rates((&slots, &units), s, x);
        let mut g = |s: f64, x: &[f64; M]| self.event(s, x);
        let x0 = std::array::from_fn(|j| yn[PLANAR[slots[j]]]);
        let mut stepper = DormandPrince853::new(&mut f, s0, x0, s_end, tolerance)?;
        let falling = [EventDirection::Falling];
        let mut observer = |_: f64, _: &[f64; M]| {};
        let mut run = drive_events(&mut stepper, &mut f, &mut g, falling, s_end, &mut observer)?;
        self.setup.step_hint.set(Some(stepper.proposed_step()));
        let sliding = slots.iter().position(|&k| k == P_EN + 2);
        if let Some(k) = sliding.filter(|_| self.setup.singular_sliding_power(self.modes)) {
            sliding_work_to_event(&stepper, &mut f, k, &mut run);
        }
        Ok(expand(yn, &slots, run))
    }

    /// Dormand-Prince 5(4) on the reduced components `slots` with the spring bed
    /// committed at the end of every accepted step (micro-slip in contact).
    fn micro_slip<const M: usize>(
        &self,
        slots: [usize; M],
        (s0, s_end): (f64, f64),
        yn: &[f64; N],
        tolerance: OdeTolerance,
    ) -> tabor_numerics::Result<EventsIntegration<N>> {
        let setup = self.setup;
        let units = std::array::from_fn(|j| self.rate_unit[slots[j]]);
        let mut f = |s: f64, x: &[f64; M]| self.rates((&slots, &units), s, x);
        let mut g = |s: f64, x: &[f64; M]| self.event(s, x)[0];
        let in_contact = self.modes.in_contact;
        // the full state's error norm: its root-mean-square over 27 components,
        // 9 of whose errors are exactly 0, is that over these 18 with the
        // tolerance scaled by √(27/18) (so are Hairer's first-step norms): the
        // same steps, to rounding (the bed's state depends on them)
        let c = (N as f64 / M as f64).sqrt();
        let tolerance = OdeTolerance {
            relative: tolerance.relative * c,
            absolute: tolerance.absolute * c,
            ..tolerance
        };
        let x0 = std::array::from_fn(|j| yn[PLANAR[slots[j]]]);
        let mut stepper = DormandPrince::new(&mut f, s0, x0, s_end, tolerance)?;
        let si = |x: &[f64; M]| Setup::full_of(&self.si(x));
        let bed = (
            in_contact,
            &si as &dyn Fn(&[f64; M]) -> [f64; N],
            self.failure,
        );
        let run = setup.drive_committing(self.law, &mut stepper, (&mut f, &mut g), s_end, bed)?;
        Ok(expand(yn, &slots, run))
    }
}

/// The run on the reduced components `slots` in the full normalized state: the
/// components it left out keep their values in `yn` (out of the plane: 0).
fn expand<const M: usize>(
    yn: &[f64; N],
    slots: &[usize; M],
    run: EventsIntegration<M>,
) -> EventsIntegration<N> {
    let mut y = *yn;
    for (&k, &v) in slots.iter().zip(run.solution.y.iter()) {
        y[PLANAR[k]] = v;
    }
    with_state(run, y)
}

/// The run `run` of a reduced or transformed state with the full normalized
/// state `y` at its end in place of its own.
pub(super) fn with_state<const M: usize>(
    run: EventsIntegration<M>,
    y: [f64; N],
) -> EventsIntegration<N> {
    let sol = run.solution;
    EventsIntegration {
        solution: OdeSolution {
            t: sol.t,
            y,
            event_found: sol.event_found,
            accepted_steps: sol.accepted_steps,
            rejected_steps: sol.rejected_steps,
            cost: sol.cost,
        },
        event: run.event,
        event_cost: run.event_cost,
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use crate::oblique::silica_tests::{shear_modulus, silica};
    use crate::oblique::ObliqueOutcome;
    use crate::{Friction, Rolling, Tangential, TangentialModel, Twisting};
    use std::cell::Cell;
    use tabor_dynamics::SimulationSettings;
    use tabor_jkr::SeparationRule;

    thread_local! {
        /// Integrate every segment on the full state (the reference).
        pub(super) static FULL: Cell<bool> = const { Cell::new(false) };
    }

    /// Two silica spheres (JKR load-controlled, `mindlin`, `sds` rolling,
    /// `marshall` twisting; `examples/scenes/silica_oblique.toml`) at 0.3 m/s, or
    /// a sphere on a flat, with a spin about z; `full`: on the full state.
    fn impact(flat: bool, angle: f64, full: bool, accuracy: f64) -> ObliqueOutcome {
        impact_with(TangentialModel::Mindlin, flat, angle, full, accuracy)
    }

    /// [`impact`] with the tangential `model`.
    fn impact_with(
        model: TangentialModel,
        flat: bool,
        angle: f64,
        full: bool,
        accuracy: f64,
    ) -> ObliqueOutcome {
        let friction =
            Friction::sliding(Tangential::new(model, 8.0 * shear_modulus(), 0.0, 0.3).unwrap())
                .with_rolling(Rolling::sds(50.0, 0.0, 0.1).unwrap())
                .with_twisting(Twisting::Marshall);
        let spins = ([0.0, 0.0, 3e4], [0.0, 0.0, if flat { 0.0 } else { -1e4 }]);
        let load = SeparationRule::LoadControlled;
        let (imp, mut law) = silica(flat, load, (0.0, 1.0), friction, spins);
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
                for ((what, a), (_, b)) in planar.compared().into_iter().zip(full.compared()) {
                    close(a, b, what);
                }
                let total = planar.kinetic_energy;
                let (p, f) = (&planar.losses, &full.losses);
                for ((name, a), (_, b)) in p.by_mechanism().into_iter().zip(f.by_mechanism()) {
                    assert!(
                        (a - b).abs() <= 1e-10 * total,
                        "{name} (flat {flat}, {angle}°): planar {a:e}, full {b:e}"
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
                    let (p, f) = (out.losses.by_mechanism(), reference.losses.by_mechanism());
                    for ((name, a), (_, b)) in p.into_iter().zip(f) {
                        assert!(
                            (a - b).abs() <= 1e-9 * out.kinetic_energy,
                            "{name} (flat {flat}, {angle}°, {accuracy:e}): {a:e} vs {b:e}"
                        );
                    }
                }
            }
        }
    }

    /// The micro-slip bed converges with the accuracy: its state follows the
    /// integrator's continuous solution, in straight pieces of a quarter step
    /// where springs freeze or enter stuck (`Setup::commit_bed_along`). At
    /// accuracy 1e-10 the tangential restitution and the rebound angle are
    /// within 2e-6 relative (or absolute below 1) of those at 1e-13, the
    /// micro-slip and every other loss within 1e-7 of the kinetic energy
    /// (measured ≤ 2.5e-7 and ≤ 2.9e-8). With one straight piece per step (the
    /// bed before) they were 4.9e-6 and 5.0e-7: the path's deviation from the
    /// chord, second order in the step, left in the springs that froze or
    /// entered stuck. At 80° this spinning pair and sphere stick; the split of
    /// their energy between the springs and micro-slip at the stick moves by
    /// ~6e-7 of the kinetic energy with the accuracy either way (not the bed's
    /// path): left out.
    #[test]
    fn the_micro_slip_converges_with_the_accuracy() {
        let model = TangentialModel::MindlinDeresiewicz;
        for flat in [false, true] {
            for angle in [10.0, 40.0] {
                let reference = impact_with(model, flat, angle, false, 1e-13);
                let out = impact_with(model, flat, angle, false, 1e-10);
                for ((what, a), (_, b)) in out.compared().into_iter().zip(reference.compared()) {
                    assert!(
                        (a - b).abs() <= 2e-6 * a.abs().max(b.abs()).max(1.0),
                        "{what} (flat {flat}, {angle}°): {a:e} vs {b:e} at 1e-13"
                    );
                }
                let (p, f) = (out.losses.by_mechanism(), reference.losses.by_mechanism());
                for ((what, a), (_, b)) in p.into_iter().zip(f) {
                    assert!(
                        (a - b).abs() <= 1e-7 * out.kinetic_energy,
                        "{what} (flat {flat}, {angle}°): {a:e} vs {b:e} at 1e-13"
                    );
                }
            }
        }
    }

    /// Micro-slip (`mindlin_deresiewicz`, the planar spring bed) on the reduced
    /// state against the full one. The bed's state follows the path of each
    /// step, so it depends on the steps, which rounding-level differences (the
    /// order of the law's warm-started solves, of the norms) change: measured
    /// differences ≤ 7e-9 in e_t and the rebound angle, ≤ 4e-8 in the losses
    /// (of the kinetic energy), ≤ 7e-13 in e_n and the contact time (with the
    /// straight path of the whole step, before `Setup::commit_bed_along`: 5e-7,
    /// 3e-6). Bounds: 1e-6, half of the 2e-6 within which the bed converges
    /// with the accuracy (`the_micro_slip_converges_with_the_accuracy`), and
    /// 1e-10 for e_n and the contact time (as `mindlin`'s).
    #[test]
    fn the_planar_micro_slip_integrates_the_full_one() {
        for flat in [false, true] {
            for angle in [10.0, 40.0, 80.0] {
                let model = TangentialModel::MindlinDeresiewicz;
                let planar = impact_with(model, flat, angle, false, 1e-10);
                let full = impact_with(model, flat, angle, true, 1e-10);
                for out in [&planar, &full] {
                    let (s, t) = (&out.after.sphere, &out.after.target);
                    assert_eq!(s.velocity[2], 0.0);
                    assert_eq!(t.velocity[2], 0.0);
                    assert_eq!(&s.angular_velocity[..2], &[0.0, 0.0]);
                    assert_eq!(&t.angular_velocity[..2], &[0.0, 0.0]);
                }
                let close = |a: f64, b: f64, bound: f64, what: &str| {
                    assert!(
                        (a - b).abs() <= bound * a.abs().max(b.abs()).max(1.0),
                        "{what} (flat {flat}, {angle}°): planar {a:e}, full {b:e}"
                    );
                };
                let rel = |a: f64, b: f64, what: &str| {
                    assert!(
                        (a - b).abs() <= 1e-6 * a.abs().max(b.abs()),
                        "{what} (flat {flat}, {angle}°): planar {a:e}, full {b:e}"
                    );
                };
                close(
                    planar.normal_restitution,
                    full.normal_restitution,
                    1e-10,
                    "e_n",
                );
                close(
                    planar.contact_time,
                    full.contact_time,
                    1e-10,
                    "contact time",
                );
                close(
                    planar.tangential_restitution.unwrap_or(0.0),
                    full.tangential_restitution.unwrap_or(0.0),
                    1e-6,
                    "e_t",
                );
                rel(
                    planar.rebound_angle.unwrap_or(0.0),
                    full.rebound_angle.unwrap_or(0.0),
                    "rebound angle",
                );
                let total = planar.kinetic_energy;
                let (p, f) = (&planar.losses, &full.losses);
                for ((name, a), (_, b)) in p.by_mechanism().into_iter().zip(f.by_mechanism()) {
                    assert!(
                        (a - b).abs() <= 1e-6 * total,
                        "{name} (flat {flat}, {angle}°): planar {a:e}, full {b:e}"
                    );
                }
                assert!(planar.energy_error < 1e-11 && full.energy_error < 1e-11);
            }
        }
    }
}
