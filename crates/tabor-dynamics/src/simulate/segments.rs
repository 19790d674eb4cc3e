//! The smooth segments of a run: one integration with DOP853 from the current
//! point to the first event, in time ([`Run::integrate_to_event`]) or, on a branch
//! the law gives as a curve, over a regularized time ([`Run::integrate_on_curve`]).

use super::run::{keep_first, simulation_error, time_limit_error, Run};
use super::{EventKind, SimulationSettings};
use crate::law::{BranchCurve, ForceLaw};
use std::cell::Cell;
use tabor_numerics::ode::{
    drive_events, DenseStepper, DormandPrince853, EventDirection, EventPoint, OdeTolerance,
};
use tabor_restitution::{Error, Result};

impl<'s> Run<'s> {
    /// Integrates one smooth segment from the current point to its first event: the
    /// end of the law's branch (`branch_end` falling to 0) or a turning point (ḋ
    /// changing sign), whichever comes first (the branch end when they coincide);
    /// every accepted step before it is recorded. One run of
    /// [`tabor_numerics::ode::drive_events`] with DOP853.
    pub(super) fn integrate_to_event<L: ForceLaw + ?Sized>(
        &mut self,
        law: &L,
    ) -> Result<(EventKind, EventPoint<3>, Option<f64>)> {
        if let Some(curve) = law.curve() {
            let (kind, hit, q) = self.integrate_on_curve(law, curve)?;
            return Ok((kind, hit, Some(q)));
        }
        let units = self.units;
        let settings = self.settings;
        let g_start = law.branch_end(units.overlap(&self.y), units.rate(&self.y))?;
        if g_start.is_nan() || g_start < 0.0 {
            return Err(simulation_error(format!(
                "{}: branch_end = {g_start:e} at the start of a branch (d = {:e} m); \
                 it must be >= 0 there",
                law.name(),
                units.overlap(&self.y)
            )));
        }
        let failure: Cell<Option<Error>> = Cell::new(None);
        let mut rhs = |_s: f64, st: &[f64; 3]| -> [f64; 3] {
            match law.force(units.overlap(st), units.rate(st)) {
                Ok(f) => {
                    let a = -f / units.force;
                    [st[1], a, a * st[1]]
                }
                Err(e) => {
                    keep_first(&failure, e);
                    [f64::NAN; 3]
                }
            }
        };
        // errors of the event function and of the recording: always reported (those
        // of f at trial points only when the integrator cannot recover from them)
        let event_failure: Cell<Option<Error>> = Cell::new(None);
        // [branch end, ḋ]: the branch end falling to 0, ḋ changing sign
        let mut events = |_s: f64, st: &[f64; 3]| -> [f64; 2] {
            match law.branch_end(units.overlap(st), units.rate(st)) {
                Ok(g) => [g, st[1]],
                Err(e) => {
                    keep_first(&event_failure, e);
                    [f64::NAN, st[1]]
                }
            }
        };
        let st = start_stepper(
            &mut self.stepper,
            &mut rhs,
            self.s,
            self.y,
            settings,
            &failure,
        )?;
        // ḋ at the start of the current step: its sign tells the kind of turning point
        let mut u_prev = self.y[1];
        let seen = &mut self.seen;
        let mut observer = |s: f64, y: &[f64; 3]| {
            if let Err(e) = seen.time_step(law, &units, s, y) {
                keep_first(&event_failure, e);
            }
            u_prev = y[1];
        };
        let run = drive_events(
            st,
            &mut rhs,
            &mut events,
            [EventDirection::Falling, EventDirection::Either],
            settings.max_duration,
            &mut observer,
        );
        if let Some(e) = event_failure.take() {
            return Err(e);
        }
        let run = run.map_err(|e| failure.take().unwrap_or(Error::Numerics(e)))?;
        let mut hit = EventPoint {
            t: run.solution.t,
            y: run.solution.y,
        };
        let kind = event_kind(run.event, u_prev);
        if kind == Some(EventKind::BranchEnd) {
            // The step that holds a branch end took stages beyond it, where the
            // law's force continues with a kink (an elastic law's 0 beyond
            // d = 0): its dense output carries that kink's error to the event.
            // The state there is taken again by stepping from the step's start
            // to the event alone, every stage on the branch.
            let start = st.step_start();
            if hit.t > start {
                // an error of f at a trial point the run recovered from is not
                // this step's
                failure.take();
                let numerics = |e| failure.take().unwrap_or(Error::Numerics(e));
                let tolerance = OdeTolerance {
                    initial_step: Some(hit.t - start),
                    ..settings.tolerance
                };
                let mut redo =
                    DormandPrince853::new(&mut rhs, start, st.dense(start), hit.t, tolerance)
                        .map_err(numerics)?;
                while redo.t() < hit.t {
                    redo.advance(&mut rhs, hit.t).map_err(numerics)?;
                }
                hit.y = redo.y();
                self.side_cost += redo.cost();
            }
        }
        match kind {
            Some(kind) => Ok((kind, hit, None)),
            None => Err(time_limit_error(law, settings, units)),
        }
    }

    /// [`Run::integrate_to_event`] on a branch the law gives in a coordinate q of its
    /// own ([`BranchCurve`]): one run of [`drive_events`] with DOP853 on the state
    /// `(q, u, w, s)` over a regularized time σ. With `S = ±dx/dq` (x = d/L, the
    /// sign fixed at the segment's start so that S > 0 inside the branch) and
    /// `c = CURVE_BLEND · max(S(q_start), S_scale)` ([`BranchCurve::slope_scale`]):
    ///
    /// `ds/dσ = S/(S + c)`, `dq/dσ = ±u/(S + c)`, `du/dσ = a ds/dσ`,
    /// `dw/dσ = a u ds/dσ`, with `a = −F/(m v0²/L)`.
    ///
    /// Where S ≫ c, σ is the time s; where S falls to 0 (a fold of d(q) at the
    /// branch end), `dq/dσ → ±u/c` stays finite, so the square-root singularity of
    /// F(d(t)) there is not met (the Sundman transformation `dt = S dσ` near the
    /// fold). Events: [`BranchCurve::end`] falling to 0, u changing sign, the time
    /// limit. No largest step (σ is not the time; the error control keeps the
    /// steps far below a half oscillation); the per-step tolerance is the settings'
    /// times `CURVE_TOLERANCE_FACTOR`. Returns the event point in the units of the
    /// time-domain state `(x, u, w)` at time s, and the coordinate there.
    fn integrate_on_curve<L: ForceLaw + ?Sized>(
        &mut self,
        law: &L,
        curve: &dyn BranchCurve,
    ) -> Result<(EventKind, EventPoint<3>, f64)> {
        let units = self.units;
        let settings = self.settings;
        let q0 = curve.coordinate(units.overlap(&self.y))?;
        let start = curve.point(q0, units.rate(&self.y))?;
        let slope0 = start.overlap_slope / units.length;
        let g_start = curve.end(q0, units.rate(&self.y))?;
        if !(slope0.is_finite() && slope0 != 0.0 && g_start.is_finite() && g_start >= 0.0) {
            return Err(simulation_error(format!(
                "{}: at the start of a branch (d = {:e} m, q = {q0:e}) its curve has \
                 dd/dq = {:e} and end = {g_start:e}; they must be nonzero and >= 0",
                law.name(),
                units.overlap(&self.y),
                start.overlap_slope
            )));
        }
        let sign = slope0.signum();
        let blend = CURVE_BLEND * slope0.abs().max(curve.slope_scale() / units.length);
        let failure: Cell<Option<Error>> = Cell::new(None);
        let mut rhs = |_sigma: f64, st: &[f64; 4]| -> [f64; 4] {
            match curve.point(st[0], st[1] * units.speed) {
                Ok(p) => {
                    let slope = sign * p.overlap_slope / units.length;
                    let ds = slope / (slope + blend);
                    let a = -p.force / units.force;
                    [sign * st[1] / (slope + blend), a * ds, a * st[1] * ds, ds]
                }
                Err(e) => {
                    keep_first(&failure, e);
                    [f64::NAN; 4]
                }
            }
        };
        let event_failure: Cell<Option<Error>> = Cell::new(None);
        // [branch end, ḋ, time left]
        let mut events = |_sigma: f64, st: &[f64; 4]| -> [f64; 3] {
            let end = curve.end(st[0], st[1] * units.speed).unwrap_or_else(|e| {
                keep_first(&event_failure, e);
                f64::NAN
            });
            [end, st[1], settings.max_duration - st[3]]
        };
        let tolerance = OdeTolerance {
            relative: settings.tolerance.relative * CURVE_TOLERANCE_FACTOR,
            absolute: settings.tolerance.absolute * CURVE_TOLERANCE_FACTOR,
            max_step: f64::INFINITY,
            ..settings.tolerance
        };
        let sigma_end = f64::MAX;
        let y0 = [q0, self.y[1], self.y[2], self.s];
        let mut stepper = DormandPrince853::new(&mut rhs, 0.0, y0, sigma_end, tolerance)
            .map_err(|e| failure.take().unwrap_or(Error::Numerics(e)))?;
        let mut u_prev = self.y[1];
        let seen = &mut self.seen;
        let mut observer = |_sigma: f64, st: &[f64; 4]| {
            match curve.point(st[0], st[1] * units.speed) {
                Ok(p) => seen.curve_step(&p, &units, st),
                Err(e) => keep_first(&event_failure, e),
            }
            u_prev = st[1];
        };
        let run = drive_events(
            &mut stepper,
            &mut rhs,
            &mut events,
            [
                EventDirection::Falling,
                EventDirection::Either,
                EventDirection::Falling,
            ],
            sigma_end,
            &mut observer,
        );
        self.side_cost += stepper.cost();
        if let Some(e) = event_failure.take() {
            return Err(e);
        }
        let run = run.map_err(|e| failure.take().unwrap_or(Error::Numerics(e)))?;
        let st = run.solution.y;
        let end = curve.point(st[0], st[1] * units.speed)?;
        let hit = EventPoint {
            t: st[3],
            y: [end.overlap / units.length, st[1], st[2]],
        };
        match event_kind(run.event, u_prev) {
            Some(kind) => Ok((kind, hit, st[0])),
            None => Err(time_limit_error(law, settings, units)),
        }
    }
}

/// The kind of the event of index `event` among a segment's event functions
/// `[branch end, ḋ, …]` (`u_prev`: ḋ at the start of the step that held it, whose
/// sign tells the turning point); `None` for no event or a later index (the time
/// limit).
fn event_kind(event: Option<usize>, u_prev: f64) -> Option<EventKind> {
    match event? {
        0 => Some(EventKind::BranchEnd),
        1 if u_prev > 0.0 => Some(EventKind::MaxCompression),
        1 => Some(EventKind::MinCompression),
        _ => None,
    }
}

/// The blend `c/S(q_start)` of [`Run::integrate_on_curve`]: the regularized time
/// follows the time where the branch's slope dx/dq exceeds about this fraction of
/// its value at the segment's start, and the Sundman time `dt = S dσ` below.
/// Chosen from the force evaluations of the impacts of `benches/impact.rs` at
/// 1.001 to 1000 v_c (JKR fixed grip; Maugis-Dugdale Λ = 1: example
/// `tabor-maugis/examples/simcount.rs`): 0.3 takes the fewest, within 10 % of
/// 0.5 and 1; the pure Sundman time (c → ∞) takes 1.2 to 1.5× as many.
const CURVE_BLEND: f64 = 0.3;

/// The per-step tolerance on a [`BranchCurve`] relative to the settings': the
/// coordinate q is coarser than the overlap at depth (JKR: d ∝ q⁴, F ∝ q⁶ for
/// large q), so the same relative error in q gives up to four times the error in
/// d. At 1/4 the restitution and the energy bookkeeping of the impacts of
/// `benches/impact.rs` (1.001 to 1000 v_c) are as close to the closed forms as
/// those of the integration in time (measured: ≤ 3e-12 and ≤ 2e-12 at the default
/// 1e-11); at 1 they were up to 8e-12 and 1.4e-11.
const CURVE_TOLERANCE_FACTOR: f64 = 0.25;

/// Starts the integrator at `(s, y)` on the first segment, restarts it on the
/// others; an error of the right-hand side (kept in `failure`) takes precedence
/// over the integrator's.
fn start_stepper<'a, F>(
    stepper: &'a mut Option<DormandPrince853<3>>,
    rhs: &mut F,
    s: f64,
    y: [f64; 3],
    settings: &SimulationSettings,
    failure: &Cell<Option<Error>>,
) -> Result<&'a mut DormandPrince853<3>>
where
    F: FnMut(f64, &[f64; 3]) -> [f64; 3],
{
    let started = match stepper.as_mut() {
        None => {
            DormandPrince853::new(rhs, s, y, settings.max_duration, settings.tolerance).map(|st| {
                *stepper = Some(st);
            })
        }
        Some(st) => st.restart(rhs, s, y, settings.max_duration),
    };
    let Some(st) = stepper.as_mut() else {
        return Err(started.err().map_or_else(
            || simulation_error("integrator did not start".into()),
            |e| failure.take().unwrap_or(Error::Numerics(e)),
        ));
    };
    if let Err(e) = started {
        return Err(failure.take().unwrap_or(Error::Numerics(e)));
    }
    Ok(st)
}
