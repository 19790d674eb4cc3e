//! The time-domain simulation of one central impact.

use crate::law::{BranchChange, BranchCurve, ForceLaw};
use serde::Serialize;
use std::cell::Cell;
use tabor_numerics::ode::{
    drive_events, DormandPrince853, EventDirection, EventPoint, OdeTolerance,
};
use tabor_numerics::Cost;
use tabor_restitution::{validate, EnergyLoss, Error, ImpactModel, Result};

/// How accurately and how long to simulate.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SimulationSettings {
    /// Integrator tolerance, applied to the normalized state (d/L, ḋ/v0 and the
    /// contact work over m v0², with L the law's overlap scale), so an absolute
    /// tolerance of 1e-13 means 1e-13 L. `max_step` is in units of L/v0.
    pub tolerance: OdeTolerance,
    /// Keep a [`TrajectoryPoint`] at every accepted step and event.
    pub record_trajectory: bool,
    /// Give up (an error) after this time, in units of L/v0.
    pub max_duration: f64,
    /// Give up (an error) after this many events.
    pub max_events: usize,
}

impl Default for SimulationSettings {
    /// `OdeTolerance::default()` (relative 1e-11, absolute 1e-13: one line in
    /// `tabor_numerics::tolerance`), at most 0.1 L/v0 per step (so that no
    /// turning point is stepped over), trajectory recorded, 10⁶ L/v0, 1000 events.
    fn default() -> Self {
        SimulationSettings {
            tolerance: OdeTolerance::default().with_max_step(0.1),
            record_trajectory: true,
            max_duration: 1e6,
            max_events: 1000,
        }
    }
}

impl SimulationSettings {
    /// Default settings for a requested relative accuracy `relative` of the
    /// impact's outcome (restitution, contact time). The integrator's per-step
    /// tolerance is `relative / 100` (at least 1e-15), absolute a further factor 100
    /// below, in normalized units: local errors add up over the few hundred steps of
    /// an impact, and a per-step tolerance equal to the requested accuracy was
    /// measured to miss it by up to 11× (`examples/accuracy_vs_time.rs`).
    pub fn with_tolerance(relative: f64) -> Result<Self> {
        let rel = validate::tolerance("tolerance", relative)?;
        let mut s = SimulationSettings::default();
        let per_step = (rel * 1e-2).max(1e-15);
        s.tolerance.relative = per_step;
        s.tolerance.absolute = per_step * 1e-2;
        Ok(s)
    }
}

/// One recorded state of the impact.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TrajectoryPoint {
    /// Time since the start of the simulation (s).
    pub time: f64,
    /// Overlap d (m), positive in contact.
    pub overlap: f64,
    /// Overlap rate ḋ (m/s).
    pub overlap_rate: f64,
    /// Contact force F (N), repulsive > 0.
    pub force: f64,
    /// Contact radius (m).
    pub contact_radius: f64,
    /// Work done on the body by the contact force so far, `−∫ F ḋ dt` (J); equals
    /// the change of kinetic energy.
    pub contact_work: f64,
}

/// What kind of event the simulation met.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum EventKind {
    /// ḋ: + → − (maximum compression).
    MaxCompression,
    /// ḋ: − → + (turned inward again).
    MinCompression,
    /// The law's current branch ended.
    BranchEnd,
}

/// A located event and what the law decided there.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ContactEvent {
    /// Time (s).
    pub time: f64,
    /// Overlap (m).
    pub overlap: f64,
    /// Overlap rate (m/s).
    pub overlap_rate: f64,
    /// What happened.
    pub kind: EventKind,
    /// What the law decided.
    pub decision: BranchChange,
}

/// The result of one simulated impact.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ImpactSimulation {
    /// The law's name.
    pub law: String,
    /// Impact speed v0 (m/s).
    pub impact_speed: f64,
    /// Rebound speed −ḋ at separation (m/s); 0 when the bodies stick.
    pub rebound_speed: f64,
    /// Coefficient of restitution, rebound speed / v0. Not clamped: for a lossless
    /// (elastic) impact it may exceed 1 by the integration error, which
    /// is of the order of [`ImpactSimulation::energy_error`].
    pub restitution: f64,
    /// True when the bodies stay together.
    pub sticks: bool,
    /// Time from contact onset to separation (s); `None` when the bodies stick.
    pub contact_time: Option<f64>,
    /// Time at which contact began (s; 0 for laws that start in contact).
    pub contact_onset_time: f64,
    /// Time at which the simulation ended (separation or sticking) (s).
    pub end_time: f64,
    /// Largest overlap (m), located at the turning point.
    pub max_overlap: f64,
    /// Largest force over the accepted steps and events (N); exact when it occurs
    /// at an event (the turning point of monotone laws).
    pub max_force: f64,
    /// Kinetic energy before the impact, m v0²/2 (J).
    pub kinetic_energy: f64,
    /// Kinetic energy lost, m (v0² − v_rebound²)/2 (J); all of it when sticking.
    pub energy_loss: f64,
    /// Energy bookkeeping error: |ΔE_kin − W_contact| / (m v0²/2), with the contact
    /// work integrated alongside the motion.
    pub energy_error: f64,
    /// The events met, in order.
    pub events: Vec<ContactEvent>,
    /// The recorded trajectory (empty unless requested).
    pub trajectory: Vec<TrajectoryPoint>,
    /// Right-hand-side evaluations and integrator steps.
    pub cost: Cost,
}

/// Simulates the central impact of effective mass `effective_mass` (kg) at
/// `impact_speed` v0 > 0 (m/s) through `law`: integrates `m d̈ = −F(d, ḋ)` from
/// d = [`ForceLaw::start_overlap`] (0: first contact), ḋ = v0 (seed 000 eq. (5.6)),
/// with the contact work `W = −∫ F ḋ dt` as a third state, until the law separates
/// or sticks. The law is left in its final state.
///
/// The run is a sequence of smooth segments: each is integrated to its first event
/// (`Run::integrate_to_event`), where the law's hook decides how the motion goes on
/// (`Run::handle_event`); the outcome is assembled from the last event
/// (`Run::outcome`).
///
/// Seed 000, eq. (5.5) (and (5.15), (5.20) for the other elastic laws).
pub fn simulate_impact<L: ForceLaw + ?Sized>(
    law: &mut L,
    effective_mass: f64,
    impact_speed: f64,
    settings: &SimulationSettings,
) -> Result<ImpactSimulation> {
    let m = validate::positive("effective_mass", effective_mass)?;
    let v0 = validate::positive("impact_speed", impact_speed)?;
    let kinetic = 0.5 * m * v0 * v0;
    if !(kinetic.is_finite() && kinetic > 0.0) {
        return Err(Error::invalid(
            "impact_speed",
            v0,
            "gives a kinetic energy m v0^2/2 that is zero or overflows",
        ));
    }
    validate::positive("max_duration", settings.max_duration)?;
    law.begin_impact(m, v0)?;
    let scale = validate::positive("overlap_scale", law.overlap_scale(m, v0)?)?;
    let start = validate::finite("start_overlap", law.start_overlap())?;
    let mut run = Run::new(law, Units::new(m, v0, scale), start, settings)?;
    let decision = loop {
        let (kind, hit, coordinate) = run.integrate_to_event(law)?;
        if let Some(decision) = run.handle_event(law, kind, hit, coordinate)? {
            break decision;
        }
    };
    Ok(run.outcome(law, decision, kinetic))
}

/// The normalized units of one simulation: `x = d/L`, `s = t v0/L`, `u = ḋ/v0`,
/// `w = W/(m v0²)`, with L the law's overlap scale.
#[derive(Clone, Copy, Debug)]
struct Units {
    /// Effective mass m (kg).
    mass: f64,
    /// Impact speed v0 (m/s).
    speed: f64,
    /// Overlap scale L (m).
    length: f64,
    /// L/v0 (s).
    time: f64,
    /// m v0²/L (N).
    force: f64,
}

impl Units {
    fn new(mass: f64, speed: f64, length: f64) -> Self {
        Units {
            mass,
            speed,
            length,
            time: length / speed,
            force: mass * speed * speed / length,
        }
    }

    /// Overlap d (m) of the normalized state.
    fn overlap(&self, y: &[f64; 3]) -> f64 {
        y[0] * self.length
    }

    /// Overlap rate ḋ (m/s) of the normalized state.
    fn rate(&self, y: &[f64; 3]) -> f64 {
        y[1] * self.speed
    }
}

/// The state of a simulation between segments, and what it has recorded.
struct Run<'s> {
    settings: &'s SimulationSettings,
    units: Units,
    /// Normalized time and state `(x, u, w)`.
    s: f64,
    y: [f64; 3],
    /// The integrator, created on the first segment and restarted at every event.
    stepper: Option<DormandPrince853<3>>,
    /// What the segments integrated on a [`BranchCurve`] cost.
    curve_cost: Cost,
    events: Vec<ContactEvent>,
    trajectory: Vec<TrajectoryPoint>,
    /// Normalized time of contact onset, once known.
    onset: Option<f64>,
    max_overlap: f64,
    max_force: f64,
}

impl<'s> Run<'s> {
    /// The run at the start overlap `start` (m), ḋ = v0, no work done; the starting
    /// point recorded.
    fn new<L: ForceLaw + ?Sized>(
        law: &L,
        units: Units,
        start: f64,
        settings: &'s SimulationSettings,
    ) -> Result<Self> {
        let mut run = Run {
            settings,
            units,
            s: 0.0,
            y: [start / units.length, 1.0, 0.0],
            stepper: None,
            curve_cost: Cost::ZERO,
            events: Vec::new(),
            trajectory: Vec::new(),
            onset: law.in_contact().then_some(0.0),
            max_overlap: start,
            max_force: f64::NEG_INFINITY,
        };
        let (s, y) = (run.s, run.y);
        run.record(law, s, &y)?;
        Ok(run)
    }

    /// The force at normalized time `s` and state `y` (N), kept in the trajectory
    /// (when requested) and in the largest force.
    fn record<L: ForceLaw + ?Sized>(&mut self, law: &L, s: f64, y: &[f64; 3]) -> Result<f64> {
        let force = record_point(
            law,
            &self.units,
            self.settings.record_trajectory,
            s,
            y,
            &mut self.trajectory,
        )?;
        self.max_force = self.max_force.max(force);
        Ok(force)
    }

    /// Integrates one smooth segment from the current point to its first event: the
    /// end of the law's branch (`branch_end` falling to 0) or a turning point (ḋ
    /// changing sign), whichever comes first (the branch end when they coincide);
    /// every accepted step before it is recorded. One run of
    /// [`tabor_numerics::ode::drive_events`] with DOP853.
    fn integrate_to_event<L: ForceLaw + ?Sized>(
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
        let (trajectory, max_overlap, max_force) = (
            &mut self.trajectory,
            &mut self.max_overlap,
            &mut self.max_force,
        );
        let mut observer = |s: f64, y: &[f64; 3]| {
            *max_overlap = max_overlap.max(units.overlap(y));
            match record_point(law, &units, settings.record_trajectory, s, y, trajectory) {
                Ok(force) => *max_force = max_force.max(force),
                Err(e) => keep_first(&event_failure, e),
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
        let hit = EventPoint {
            t: run.solution.t,
            y: run.solution.y,
        };
        match event_kind(run.event, u_prev) {
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
        let (trajectory, max_overlap, max_force) = (
            &mut self.trajectory,
            &mut self.max_overlap,
            &mut self.max_force,
        );
        let mut observer = |_sigma: f64, st: &[f64; 4]| {
            match curve.point(st[0], st[1] * units.speed) {
                Ok(p) => {
                    *max_overlap = max_overlap.max(p.overlap);
                    *max_force = max_force.max(p.force);
                    if settings.record_trajectory {
                        trajectory.push(TrajectoryPoint {
                            time: st[3] * units.time,
                            overlap: p.overlap,
                            overlap_rate: st[1] * units.speed,
                            force: p.force,
                            contact_radius: p.contact_radius,
                            contact_work: st[2] * units.mass * units.speed * units.speed,
                        });
                    }
                }
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
        self.curve_cost += stepper.cost();
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

    /// Moves to the event point `hit` (a turning point has ḋ = 0 exactly), records it
    /// and asks the law's hook what happens: `Some(decision)` ends the impact
    /// (separation or sticking), `None` goes on with the next segment.
    fn handle_event<L: ForceLaw + ?Sized>(
        &mut self,
        law: &mut L,
        kind: EventKind,
        hit: EventPoint<3>,
        coordinate: Option<f64>,
    ) -> Result<Option<BranchChange>> {
        let units = self.units;
        self.s = hit.t;
        self.y = hit.y;
        if kind != EventKind::BranchEnd {
            self.y[1] = 0.0;
        }
        let (s, y) = (self.s, self.y);
        let d = units.overlap(&y);
        self.max_overlap = self.max_overlap.max(d);
        let force_before = self.record(law, s, &y)?;
        let decision = match kind {
            EventKind::MaxCompression => law.on_max_compression(d)?,
            EventKind::MinCompression => law.on_min_compression(d)?,
            EventKind::BranchEnd => match coordinate {
                Some(q) => law.on_curve_end(q, d, units.rate(&y))?,
                None => law.on_branch_end(d, units.rate(&y))?,
            },
        };
        self.events.push(ContactEvent {
            time: s * units.time,
            overlap: d,
            overlap_rate: units.rate(&y),
            kind,
            decision,
        });
        if self.onset.is_none() && law.in_contact() {
            self.onset = Some(s);
        }
        if decision != BranchChange::Continue {
            return Ok(Some(decision));
        }
        if law.force(d, units.rate(&y))? != force_before {
            // The hook switched to a branch with a different force (jump-in): record
            // the state again, so the jump shows as two points at the same time.
            self.record(law, s, &y)?;
        }
        if kind == EventKind::BranchEnd {
            let g = law.branch_end(d, units.rate(&y))?;
            if g.is_nan() || g <= 0.0 {
                return Err(simulation_error(format!(
                    "{}: on_branch_end returned Continue at d = {d:e} m, but the new branch \
                     ends there too (branch_end = {g:e})",
                    law.name()
                )));
            }
        }
        if self.events.len() >= self.settings.max_events {
            return Err(simulation_error(format!(
                "{}: more than {} events without separation",
                law.name(),
                self.settings.max_events
            )));
        }
        Ok(None)
    }

    /// The outcome of a run that ended with `decision` (separation or sticking) at
    /// the current point, for the initial kinetic energy `kinetic` (J).
    fn outcome<L: ForceLaw + ?Sized>(
        self,
        law: &L,
        decision: BranchChange,
        kinetic: f64,
    ) -> ImpactSimulation {
        let Units {
            mass: m,
            speed: v0,
            time: time_unit,
            ..
        } = self.units;
        let (s, end_y) = (self.s, self.y);
        let sticks = decision == BranchChange::Stick;
        let rebound_speed = if sticks {
            0.0
        } else {
            (-end_y[1] * v0).max(0.0)
        };
        // in units of the initial kinetic energy m v0²/2 (no overflow for huge m v0²):
        // kinetic_end/kinetic = ḋ̂², work/kinetic = 2 ŵ
        let energy_error = ((end_y[1] * end_y[1] - 1.0) - 2.0 * end_y[2]).abs();
        let onset_s = self.onset.unwrap_or(s);
        let cost = self.stepper.map_or(Cost::ZERO, |st| st.cost()) + self.curve_cost;
        ImpactSimulation {
            law: law.name(),
            impact_speed: v0,
            rebound_speed,
            restitution: rebound_speed / v0,
            sticks,
            contact_time: (!sticks).then_some((s - onset_s) * time_unit),
            contact_onset_time: onset_s * time_unit,
            end_time: s * time_unit,
            max_overlap: self.max_overlap,
            max_force: self.max_force,
            kinetic_energy: kinetic,
            energy_loss: if sticks {
                kinetic
            } else {
                kinetic - 0.5 * m * rebound_speed * rebound_speed
            },
            energy_error,
            events: self.events,
            trajectory: self.trajectory,
            cost,
        }
    }
}

/// The force (N) at normalized time `s` and state `y`, and, when `keep` is true, the
/// trajectory point there appended to `out`.
fn record_point<L: ForceLaw + ?Sized>(
    law: &L,
    units: &Units,
    keep: bool,
    s: f64,
    y: &[f64; 3],
    out: &mut Vec<TrajectoryPoint>,
) -> Result<f64> {
    let d = units.overlap(y);
    let r = units.rate(y);
    let f = law.force(d, r)?;
    if keep {
        out.push(TrajectoryPoint {
            time: s * units.time,
            overlap: d,
            overlap_rate: r,
            force: f,
            contact_radius: law.contact_radius(d, r)?,
            contact_work: y[2] * units.mass * units.speed * units.speed,
        });
    }
    Ok(f)
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

/// An error of the simulation itself (not of the law or the integrator).
fn simulation_error(message: String) -> Error {
    Error::Model {
        model: "impact simulation",
        message,
    }
}

/// The law did not separate within `settings.max_duration`.
fn time_limit_error<L: ForceLaw + ?Sized>(
    law: &L,
    settings: &SimulationSettings,
    units: Units,
) -> Error {
    simulation_error(format!(
        "{}: no separation within the time limit {:e} s",
        law.name(),
        settings.max_duration * units.time
    ))
}

/// An [`ImpactModel`] whose energy loss comes from [`simulate_impact`]: any
/// [`ForceLaw`] gets restitution (5.37) and sticking velocity (5.38) from
/// `tabor-restitution` for free.
#[derive(Clone, Debug)]
pub struct SimulatedImpact<L> {
    law: L,
    mass: f64,
    settings: SimulationSettings,
}

impl<L: ForceLaw + Clone> SimulatedImpact<L> {
    /// The model of `law` with effective mass `effective_mass` (kg).
    pub fn new(law: L, effective_mass: f64, settings: SimulationSettings) -> Result<Self> {
        Ok(SimulatedImpact {
            law,
            mass: validate::positive("effective_mass", effective_mass)?,
            settings: SimulationSettings {
                record_trajectory: false,
                ..settings
            },
        })
    }

    /// Simulates one impact at `impact_speed` on a copy of the law.
    pub fn simulate(&self, impact_speed: f64) -> Result<ImpactSimulation> {
        let mut law = self.law.clone();
        simulate_impact(&mut law, self.mass, impact_speed, &self.settings)
    }
}

impl<L: ForceLaw + Clone> ImpactModel for SimulatedImpact<L> {
    fn name(&self) -> String {
        format!("{} (time-domain simulation)", self.law.name())
    }

    fn effective_mass(&self) -> f64 {
        self.mass
    }

    /// The kinetic energy lost in the simulated impact, seed 000 eq. (5.37) read
    /// backwards; tiny negative values from the integration error are clipped to 0
    /// and the error estimate is the energy bookkeeping error.
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let sim = self.simulate(impact_speed)?;
        let error_estimate = sim.energy_error * sim.kinetic_energy;
        Ok(EnergyLoss {
            joules: sim.energy_loss.max(0.0),
            error_estimate: error_estimate + (-sim.energy_loss).max(0.0),
            branch: format!("time-domain simulation of {}", sim.law),
            cost: sim.cost,
        })
    }
}

fn keep_first(slot: &Cell<Option<Error>>, e: Error) {
    let old = slot.take();
    slot.set(Some(old.unwrap_or(e)));
}
