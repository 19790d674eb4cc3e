//! One segment of an oblique impact: the integration from one event to the next
//! ([`Setup::segment`]), and the spring bed's onset and commits around it.

use super::bed::BedState;
use super::elements::{keep_first, model_error};
use super::limits::{
    EVENTS, EVENT_ZERO, IDENTIFIED_EVENT_VALUE, NORMAL_FORCE_ZERO, PATH_CHORDS, ZERO_EVENT_VALUE,
};
use super::planar::{PLANAR_MOTION, P_XT};
use super::simulate::Event;
use super::state::*;
use crate::model::{Tangential, TangentialModel};
use std::cell::Cell;
use tabor_dynamics::{ForceLaw, SimulationSettings};
use tabor_numerics::ode::{
    drive, drive_events, DenseStepper, DormandPrince, DormandPrince853, EventDirection,
    EventsIntegration, OdeTolerance,
};
use tabor_numerics::{Cost, GaussLegendre};
use tabor_restitution::{Error, Result};

/// The kinetic energy (in the energies' unit m v², v the impact speed) beyond
/// which a segment's energies leave the step control ([`Setup::segment`]).
const ACCELERATED_KINETIC: f64 = 1e2;

impl<'a> Setup<'a> {
    /// The answer of a hook of the law, its last normal point forgotten (the hook
    /// may have changed the branch).
    pub(super) fn hook<T>(&self, answer: Result<T>) -> Result<T> {
        self.forget_normal();
        self.step_hint.set(None);
        answer
    }

    /// The tolerance of a DOP853 segment: with `quadratures`, the error control
    /// over the first `motion` components only (the energies after them are
    /// quadratures); the first step the one the last segment's control proposed.
    pub(super) fn dop853_tolerance(
        &self,
        mut tolerance: OdeTolerance,
        quadratures: bool,
        motion: usize,
    ) -> OdeTolerance {
        if quadratures {
            tolerance = tolerance.with_error_components(motion);
        }
        if let Some(h) = self.step_hint.get() {
            tolerance.initial_step = Some(h);
        }
        tolerance
    }

    /// The number of leading components of the state (the reduced one where
    /// `planar`) under the step control when the energies leave it: the motion
    /// ([`PLANAR_MOTION`], [`EN`]); in the tensile end of a damped contact
    /// without adhesion the bodies' motion alone (positions, velocities, spins:
    /// [`P_XT`], [`XT`]). There every element's limit `μ|F_n|` falls to 0 as
    /// δ^¼ and a slipping element's direction turns at a rate ∝ 1/L, ∝ (t_e −
    /// t)^(−¼) (its cap 10⁴ per time unit binds only within ~10⁻¹⁶ of the
    /// separation): integrable, but the error control of the displacements
    /// asked for steps below the rounding of t (a spin out of the impact plane
    /// turning a rolling element's slip direction: "step size underflow"). Their
    /// forces are bounded by the limit, and at the separation by 0.
    pub(super) fn controlled_motion(&self, modes: &Modes, planar: bool) -> usize {
        match (modes.tensile, planar) {
            (true, true) => P_XT,
            (true, false) => XT,
            (false, true) => PLANAR_MOTION,
            (false, false) => EN,
        }
    }

    /// Integrates from SI (t, y) to the first event.
    pub(super) fn segment(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &[f64; N],
        modes: &Modes,
        settings: &SimulationSettings,
    ) -> Result<(Event, f64, [f64; N], Cost)> {
        // the integration starts at the normalized state; the event values there
        // are those its event function sees (the round trip SI → normalized → SI
        // moves a value at its zero by rounding, to either side)
        let s0 = t / self.time;
        let yn = self.to_normalized(y);
        let g0 = self.event_values(law, s0 * self.time, &self.to_si(&yn), modes)?;
        // an event function at (or, by the location tolerance or rounding, just
        // past) its zero at the start is shifted to start a margin above it: the
        // crossing just handled is not found again, a genuine later one is. The
        // margin (10⁻¹² of the value's size) exceeds the rounding of the shift.
        let mut offset = [0.0; EVENTS];
        for (o, g) in offset.iter_mut().zip(g0.iter()) {
            let margin = 1e-12 * g.abs().max(1.0);
            if g.is_finite() && *g <= margin {
                *o = 2.0 * margin - g;
            }
        }
        if g0[0].is_nan() || g0[0] < 0.0 {
            return Err(model_error(format!(
                "{}: branch_end = {:e} at the start of a segment",
                law.name(),
                g0[0]
            )));
        }
        let failure: Cell<Option<Error>> = Cell::new(None);
        // SI rates to normalized ones: times the time unit, over the state's unit
        let rate_unit: [f64; N] = std::array::from_fn(|i| self.time / self.scale[i]);
        // the SI rates at SI (t, y)
        let rates = |t: f64, ysi: &[f64; N]| -> [f64; N] {
            match self.evaluate(law, t, ysi, modes) {
                Ok(ev) => ev.dy,
                Err(e) => {
                    keep_first(&failure, e);
                    [f64::NAN; N]
                }
            }
        };
        let mut rhs = |s: f64, yn: &[f64; N]| -> [f64; N] {
            let dy = rates(s * self.time, &self.to_si(yn));
            std::array::from_fn(|i| dy[i] * rate_unit[i])
        };
        let g_failure: Cell<Option<Error>> = Cell::new(None);
        // a value within the rounding of the event values (O(1) in their units)
        // is the zero itself: Brent's method stops there instead of bisecting
        // the rest of the bracket down to 4 ε
        let combine = |v: [f64; EVENTS]| -> f64 {
            let g = v
                .iter()
                .zip(offset.iter())
                .map(|(g, o)| g + o)
                .fold(f64::INFINITY, f64::min);
            if g.abs() <= EVENT_ZERO {
                0.0
            } else {
                g
            }
        };
        let g_si = |t: f64, ysi: &[f64; N]| -> f64 {
            match self.event_values(law, t, ysi, modes) {
                Ok(v) => combine(v),
                Err(e) => {
                    keep_first(&g_failure, e);
                    f64::NAN
                }
            }
        };
        let g = |s: f64, yn: &[f64; N]| g_si(s * self.time, &self.to_si(yn));
        let s_end = s0 + settings.max_duration;
        // a failure of the rates or of the event values (the law's own error)
        // is the cause of the integrator's or the event location's NaN
        let numerics = |e| {
            failure
                .take()
                .or(g_failure.take())
                .unwrap_or(Error::Numerics(e))
        };
        let micro_slip = self.bed.is_some() && modes.in_contact;
        let mut events = |s: f64, yn: &[f64; N]| [g(s, yn)];
        // the smooth models with DOP853 (as the central simulated impact), the
        // spring bed, piecewise smooth within a step, with Dormand-Prince 5(4)
        // The energies are quadratures of the powers along the motion: where the
        // law's slopes are exact (JKR's closed form) its eighth-order steps
        // resolve them, and they do not choose the steps (DOP853's error norm over
        // the motion only); with slopes by differences, whose rounding grows
        // toward a branch end, and for the spring bed's Dormand-Prince 5(4) steps
        // of a piecewise smooth motion, they stay under control.
        // In the tensile end of a damped contact without adhesion (F_n < 0 from
        // its zero to the separation, ∝ δ^¼ for Tsuji's and coeff_restitution's
        // η ∝ √(m k_n)) a slipping element's limit falls as (t_e − t)^¼ and its
        // sliding power grows as (t_e − t)^(−½): integrable, but a step across
        // the separation meets the error control only below the rounding of t.
        // The motion's rates stay finite: it chooses the steps there.
        // Likewise where the attraction has multiplied the kinetic energy far
        // beyond the energies' unit m v² (a slow adhesive impact: 10⁻³ m/s
        // reaches contact at 0.3 m/s): the powers that start at the contact
        // (a damping ∝ (t − t₀)^¼ as the adhesive contact radius opens) would
        // be held to 10⁻¹⁰ of a unit 10⁻⁷ of the energy they move.
        let accelerated = self.kinetic(y) > ACCELERATED_KINETIC * self.scale[EN];
        let free_energies = modes.tensile || accelerated;
        // A slipping tangential element with a dashpot: its powers have a kink
        // inside the segment where the dashpot alone reaches the limit (γ û·v =
        // L: the dashpot's share is capped beyond), which the motion's steps do
        // not resolve (JKR with Tsuji damping and x_γ 0.6: the tangential
        // damping off by 2e-5 and the sliding work by −2e-5 of the kinetic
        // energy at accuracy 1e-10, −1e-6 still at 1e-13): its energies stay
        // under the error control.
        let quadratures =
            free_energies || (!self.dashpot_slips(modes) && self.exact_slopes(law, t, y, modes)?);
        // the spring bed's Dormand-Prince 5(4): the motion alone where free
        let bed_tolerance = |motion: usize| match free_energies {
            true => settings.tolerance.with_error_components(motion),
            false => settings.tolerance,
        };
        let run = if self.is_planar(y, modes) {
            let failures = (&failure, &g_failure);
            let motion = self.controlled_motion(modes, true);
            let (ends, tolerance) = ((s0, s_end), bed_tolerance(motion));
            self.planar_segment(
                law,
                modes,
                &combine,
                failures,
                ends,
                &yn,
                tolerance,
                quadratures,
            )
        } else if self.bed.is_some() {
            let tolerance = bed_tolerance(self.controlled_motion(modes, false));
            let mut stepper =
                DormandPrince::new(&mut rhs, s0, yn, s_end, tolerance).map_err(&numerics)?;
            let mut g = |s: f64, yn: &[f64; N]| events(s, yn)[0];
            let to_si = |yn: &[f64; N]| self.to_si(yn);
            let bed = (
                micro_slip,
                &to_si as &dyn Fn(&[f64; N]) -> [f64; N],
                &failure,
            );
            self.drive_committing(law, &mut stepper, (&mut rhs, &mut g), s_end, bed)
        } else {
            let motion = self.controlled_motion(modes, false);
            let tolerance = self.dop853_tolerance(settings.tolerance, quadratures, motion);
            let mut stepper =
                DormandPrince853::new(&mut rhs, s0, yn, s_end, tolerance).map_err(&numerics)?;
            let mut none = |_: f64, _: &[f64; N]| {};
            let mut run = drive_to_event(&mut stepper, &mut rhs, &mut events, s_end, &mut none);
            self.step_hint.set(Some(stepper.proposed_step()));
            if let Ok(r) = &mut run {
                if self.singular_sliding_power(modes) {
                    sliding_work_to_event(&stepper, &mut rhs, EN + 2, r);
                }
            }
            run
        }
        .map_err(&numerics)?;
        if let Some(e) = failure.take().or(g_failure.take()) {
            return Err(e);
        }
        let sol = run.solution;
        if !sol.event_found {
            return Err(model_error(format!(
                "{}: no separation within {} time units (overlap scale / normal speed)",
                law.name(),
                settings.max_duration
            )));
        }
        let t_hit = sol.t * self.time;
        let y_hit = self.to_si(&sol.y);
        let mut gv = self.event_values(law, t_hit, &y_hit, modes)?;
        for (g, o) in gv.iter_mut().zip(offset.iter()) {
            *g += o;
        }
        // each value in its own size at the segment's start (a value that
        // starts at 10⁸ of its unit, as the slip rates of a grazing impact in
        // units of v cos α, is located as accurately in time, not in value)
        let sizes: [f64; EVENTS] = std::array::from_fn(|i| {
            if g0[i].is_finite() {
                g0[i].abs().max(1.0)
            } else {
                1.0
            }
        });
        let relative: [f64; EVENTS] = std::array::from_fn(|i| gv[i] / sizes[i]);
        let mut crossed_ahead = false;
        let mut which = relative
            .iter()
            .enumerate()
            .min_by(|a, b| a.1.total_cmp(b.1))
            .map_or(0, |(i, _)| i);
        // the zero of a damped contact's normal force is where the limits of
        // the elements touch 0 with it (an element without a trial force meets
        // its limit there too): it is handled before them; the end of the
        // branch (where a Hertz contact's force vanishes with it) before all
        if relative[0] <= ZERO_EVENT_VALUE {
            which = 0;
        } else if relative[NORMAL_FORCE_ZERO] <= ZERO_EVENT_VALUE {
            which = NORMAL_FORCE_ZERO;
        } else if relative[which] > 0.0 {
            // the located zero is within a few ulps of time of the crossing, on
            // either side: on this side every value is above 0, and the event is
            // the value that reaches 0 just beyond. The smallest value here can
            // be one merely near its own zero while another crosses steeply (a
            // slip rate falling by ~10³ of its unit per 10⁻¹⁵ s as
            // Maugis-Dugdale's contact radius vanishes, beside the branch end
            // 6·10⁻⁹ of the overlap scale away, which was taken for the event)
            if let Some(i) = self.crossing_ahead(law, t_hit, &y_hit, modes, &offset, &sizes)? {
                (which, crossed_ahead) = (i, true);
            }
        }
        // the located zero is one of the event values: a crossing without one
        // near 0 or reaching it just beyond (a value that jumped across it) is
        // not guessed at
        if !crossed_ahead && (relative[which].is_nan() || relative[which] > IDENTIFIED_EVENT_VALUE)
        {
            return Ok((Event::Unidentified, t_hit, y_hit, sol.cost + run.event_cost));
        }
        let event = [
            Event::BranchEnd,
            Event::Turn,
            Event::TangentialLimit,
            Event::TangentialStick,
            Event::RollingLimit,
            Event::RollingStick,
            Event::TwistingLimit,
            Event::TwistingStick,
            Event::FrictionOnset,
            Event::NormalForceZero,
            Event::Capture,
        ][which];
        Ok((event, t_hit, y_hit, sol.cost + run.event_cost))
    }

    /// The event value that reaches 0 first a few ulps of time after SI (t, y)
    /// (at 4, 16, 64 and 256 ulps of the normalized time, the state carried
    /// along its rates), each value shifted by its `offset` and measured in its
    /// size at the segment's start (`sizes`, as [`Setup::segment`] measures
    /// them); `None` where none does (a zero that the values only touch) or a
    /// probe cannot be evaluated.
    fn crossing_ahead(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &[f64; N],
        modes: &Modes,
        offset: &[f64; EVENTS],
        sizes: &[f64; EVENTS],
    ) -> Result<Option<usize>> {
        let rates = if self.is_planar(y, modes) {
            let mut dz = [0.0; super::planar::PM];
            let z = Setup::planar_of(y);
            self.planar_rates(law, t, &z, modes, &mut dz)
                .map(|_| Setup::full_of(&dz))
        } else {
            self.evaluate(law, t, y, modes).map(|e| e.dy)
        };
        let Ok(rates) = rates else {
            return Ok(None);
        };
        let ulp = f64::EPSILON * (t / self.time).abs().max(1.0) * self.time;
        let mut h = 4.0 * ulp;
        for _ in 0..4 {
            let ahead: [f64; N] = std::array::from_fn(|i| y[i] + h * rates[i]);
            let Ok(values) = self.event_values(law, t + h, &ahead, modes) else {
                return Ok(None);
            };
            let crossed = (0..EVENTS)
                .map(|i| (i, (values[i] + offset[i]) / sizes[i]))
                .filter(|&(_, v)| v <= 0.0)
                .min_by(|a, b| a.1.total_cmp(&b.1));
            if let Some((i, _)) = crossed {
                return Ok(Some(i));
            }
            h *= 4.0;
        }
        Ok(None)
    }
}

/// The Gauss-Legendre rule of [`sliding_work_to_event`] (5 points: degree 9).
static EVENT_STEP_RULE: std::sync::LazyLock<GaussLegendre> = std::sync::LazyLock::new(|| {
    GaussLegendre::new(5).unwrap_or_else(|_| unreachable!("5 points are a valid rule"))
});

/// The component `k` of the run's state at its located event `t_e` (the sliding
/// work of a slipping Mindlin spring), integrated over the step that holds the
/// event from its start only to `t_e`, by 5-point Gauss-Legendre quadrature of
/// its rate `f` along the motion's dense output, instead of the dense output's
/// own value there. That power, `g (L − γ û·v)/k` ([`slip_power`]), is smooth up
/// to the event, but beyond it, toward a contact radius 0 under a finite
/// cohesive limit L (Maugis-Dugdale's junction, 10⁻¹⁵ s after a slip-to-stick
/// there), its `1/k` diverges: the step's stages beyond the event sampled it
/// (±10²⁴ J of sliding and spring work in an impact of 10⁻⁹ J). No energy
/// enters any rate, so the motion's dense output carries the integrand. Counts
/// its evaluations of `f` in the run's cost; nothing where the run found no
/// event.
pub(super) fn sliding_work_to_event<S, F, const M: usize>(
    stepper: &S,
    f: &mut F,
    k: usize,
    run: &mut EventsIntegration<M>,
) where
    S: DenseStepper<M>,
    F: FnMut(f64, &[f64; M]) -> [f64; M],
{
    let sol = &mut run.solution;
    let t_n = stepper.step_start();
    let half = 0.5 * (sol.t - t_n);
    if !sol.event_found || half <= 0.0 {
        return;
    }
    let rule = &*EVENT_STEP_RULE;
    sol.cost.evaluations += rule.len() as u64;
    let mut work = 0.0;
    for (node, weight) in rule.nodes().iter().zip(rule.weights()) {
        let t = t_n + half * (1.0 + node);
        work += weight * f(t, &stepper.dense(t))[k];
    }
    sol.y[k] = stepper.dense(t_n)[k] + half * work;
}

/// Whether a run commits the spring bed (in contact, with micro-slip), the SI full
/// state of the stepper's state, and the cell that keeps a commit's first error.
type BedCommits<'c, const M: usize> = (
    bool,
    &'c dyn Fn(&[f64; M]) -> [f64; N],
    &'c Cell<Option<Error>>,
);

/// One run of [`drive_events`] to the falling zero of the event function `g`, the
/// dense output prepared only on the step that contains it; `observer` sees the
/// end of every other accepted step.
fn drive_to_event<S, F, G, O>(
    stepper: &mut S,
    f: &mut F,
    g: &mut G,
    t_end: f64,
    observer: &mut O,
) -> tabor_numerics::Result<EventsIntegration<N>>
where
    S: DenseStepper<N>,
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    G: FnMut(f64, &[f64; N]) -> [f64; 1],
    O: FnMut(f64, &[f64; N]),
{
    drive_events(stepper, f, g, [EventDirection::Falling], t_end, observer)
}

impl<'a> Setup<'a> {
    /// The tangential element (not the spring bed) when it slips in `modes`, in
    /// contact and past the warm-up: the segments where its sliding work is
    /// integrated ([`Setup::active_energies`]).
    pub(super) fn slipping_tangential(&self, modes: &Modes) -> Option<&Tangential> {
        let slips = modes.in_contact
            && !modes.warmup
            && self.bed.is_none()
            && modes.tangential == Mode::Slip;
        self.imp
            .friction
            .as_ref()
            .filter(|_| slips)
            .map(|f| &f.tangential)
    }

    /// True when the tangential element has a dashpot: `tangential_damping`
    /// and a normal damping both nonzero (its `γ = x_γ c_n`).
    pub(super) fn tangential_dashpot(&self) -> bool {
        self.imp.normal.damping != 0.0
            && self
                .imp
                .friction
                .as_ref()
                .is_some_and(|f| f.tangential.damping_ratio != 0.0)
    }

    /// True when a Mindlin spring (`mindlin`, `mindlin_rescale`: stiffness
    /// `k_t a`) slips in `modes`: its sliding power has the `1/k` that
    /// [`sliding_work_to_event`] keeps the integration from sampling beyond the
    /// segment's event.
    pub(super) fn singular_sliding_power(&self, modes: &Modes) -> bool {
        self.slipping_tangential(modes)
            .is_some_and(|t| t.model != TangentialModel::LinearHistory)
    }

    /// True when the tangential element slips in `modes` with a dashpot.
    pub(super) fn dashpot_slips(&self, modes: &Modes) -> bool {
        self.slipping_tangential(modes).is_some() && self.tangential_dashpot()
    }

    /// Contact onset: the springs unstrained, the current displacement the
    /// reference.
    pub(super) fn reset_bed(&self, law: &dyn ForceLaw, t: f64, y: &[f64; N]) -> Result<()> {
        if let Some(bed) = &self.bed {
            let (n, overlap, rate, _) = self.geometry(t, y);
            let a = law.contact_radius(overlap, rate)?.max(0.0);
            bed.borrow_mut().reset(&v3(y, XT), &n, a);
        }
        Ok(())
    }

    /// Dormand-Prince 5(4) (the spring bed's method) from its current point to the
    /// falling zero of the event function `g` (or `s_end`), committing the bed
    /// along every accepted step where `commits.0` ([`Setup::commit_bed_along`];
    /// on the step that holds the event, to the event): its continuous solution
    /// is taken at the step's pieces, the step's end is the stepper's own state,
    /// `commits.1` turns a state into the SI full one, and a commit's error is
    /// kept in `commits.2`.
    pub(super) fn drive_committing<const M: usize, F, G>(
        &self,
        law: &dyn ForceLaw,
        stepper: &mut DormandPrince<M>,
        (f, g): (&mut F, &mut G),
        s_end: f64,
        (commits, si, failure): BedCommits<'_, M>,
    ) -> tabor_numerics::Result<EventsIntegration<M>>
    where
        F: FnMut(f64, &[f64; M]) -> [f64; M],
        G: FnMut(f64, &[f64; M]) -> f64,
    {
        let mut commit = |st: &DormandPrince<M>, stop: f64| {
            if !commits {
                return;
            }
            let (t_end, x_end) = st.current();
            let start = st.step_start();
            let state = |theta: f64| {
                si(&match theta == 1.0 && stop == t_end {
                    true => x_end,
                    false => st.dense(start + theta * (stop - start)),
                })
            };
            let step = (start * self.time, stop * self.time);
            if let Err(e) = self.commit_bed_along(law, step, &state) {
                keep_first(failure, e);
            }
        };
        let run = drive(stepper, f, g, EventDirection::Falling, s_end, &mut commit)?;
        Ok(EventsIntegration {
            event: run.solution.event_found.then_some(0),
            solution: run.solution,
            event_cost: run.event_cost,
        })
    }

    /// Commits the spring bed over an accepted step from SI time `start` to
    /// `stop` along the integrator's continuous solution, `state(θ)` the SI state
    /// at `start + θ (stop − start)` (θ = 1: the stepper's own state at `stop`):
    /// one straight step of the return map where the bed's state depends only on
    /// the step's ends, else [`PATH_CHORDS`] straight pieces along it
    /// ([`LineBed::path_dependent`](super::line_bed::LineBed::path_dependent):
    /// springs that stopped slipping or entered stuck during the step; the
    /// straight path's error in their values is second order in its length).
    pub(super) fn commit_bed_along(
        &self,
        law: &dyn ForceLaw,
        (start, stop): (f64, f64),
        state: &dyn Fn(f64) -> [f64; N],
    ) -> Result<()> {
        let (Some(bed), Some(fr)) = (&self.bed, &self.imp.friction) else {
            return Ok(());
        };
        let mu = fr.tangential.coefficient;
        let at = |theta: f64| -> Result<_> {
            let y = state(theta);
            let t = if theta == 1.0 {
                stop
            } else {
                start + theta * (stop - start)
            };
            let (a, fc, .., n) = self.contact(law, t, &y)?;
            Ok(BedState::new(n, v3(&y, XT), a, mu * fc))
        };
        let end = at(1.0)?;
        if bed.borrow().path_dependent(&end) {
            let mut path = [end; PATH_CHORDS];
            for (k, point) in path.iter_mut().enumerate().take(PATH_CHORDS - 1) {
                *point = at((k + 1) as f64 / PATH_CHORDS as f64)?;
            }
            bed.borrow_mut().commit_along(&path);
        } else {
            bed.borrow_mut().commit(&end);
        }
        Ok(())
    }
}
