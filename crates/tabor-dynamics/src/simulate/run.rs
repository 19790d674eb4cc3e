//! [`Run`]: the state of a simulation between its smooth segments, what happens
//! at an event (the law's hook), and the outcome assembled at the end.

use super::{
    ContactEvent, EventKind, ImpactSimulation, SimulationSettings, TrajectoryPoint, Units,
};
use crate::law::{BranchChange, CurvePoint, ForceLaw};
use std::cell::Cell;
use tabor_numerics::ode::{DormandPrince853, EventPoint};
use tabor_numerics::Cost;
use tabor_restitution::{Error, Result};

/// The state of a simulation between segments, and what it has recorded.
pub(super) struct Run<'s> {
    pub(super) settings: &'s SimulationSettings,
    pub(super) units: Units,
    /// Normalized time and state `(x, u, w)`.
    pub(super) s: f64,
    pub(super) y: [f64; 3],
    /// The integrator, created on the first segment and restarted at every event.
    pub(super) stepper: Option<DormandPrince853<3>>,
    /// What the integrations beside the time-domain stepper cost: the segments
    /// on a [`BranchCurve`] and the steps taken again to a branch end
    /// ([`Run::integrate_to_event`]).
    pub(super) side_cost: Cost,
    pub(super) events: Vec<ContactEvent>,
    /// Normalized time of contact onset, once known.
    pub(super) onset: Option<f64>,
    /// The largest overlap and force, and the trajectory.
    pub(super) seen: Seen,
}

/// What a run has seen: the largest overlap and force so far, and the trajectory
/// (when it is kept). The one place the observers of the segments write to,
/// borrowed apart from the run's integrator.
pub(super) struct Seen {
    pub(super) trajectory: Vec<TrajectoryPoint>,
    pub(super) max_overlap: f64,
    pub(super) max_force: f64,
    /// Whether the trajectory is kept (`SimulationSettings::record_trajectory`).
    keep: bool,
}

impl Seen {
    /// The force (N) at normalized time `s` and state `y`, kept in the largest
    /// force and, when the trajectory is kept, as its next point.
    pub(super) fn record<L: ForceLaw + ?Sized>(
        &mut self,
        law: &L,
        units: &Units,
        s: f64,
        y: &[f64; 3],
    ) -> Result<f64> {
        let d = units.overlap(y);
        let r = units.rate(y);
        let f = law.force(d, r)?;
        if self.keep {
            self.trajectory.push(TrajectoryPoint {
                time: s * units.time,
                overlap: d,
                overlap_rate: r,
                force: f,
                contact_radius: law.contact_radius(d, r)?,
                contact_work: y[2] * units.mass * units.speed * units.speed,
            });
        }
        self.max_force = self.max_force.max(f);
        Ok(f)
    }

    /// The end of an accepted step of a segment integrated in time, at normalized
    /// time `s` and state `y`: the largest overlap, then [`Seen::record`].
    pub(super) fn time_step<L: ForceLaw + ?Sized>(
        &mut self,
        law: &L,
        units: &Units,
        s: f64,
        y: &[f64; 3],
    ) -> Result<()> {
        self.max_overlap = self.max_overlap.max(units.overlap(y));
        self.record(law, units, s, y).map(|_| ())
    }

    /// The end of an accepted step of a segment on a [`BranchCurve`]: the point
    /// `p` of the curve at the state `(q, u, w, s)` `st`.
    ///
    /// [`BranchCurve`]: crate::BranchCurve
    pub(super) fn curve_step(&mut self, p: &CurvePoint, units: &Units, st: &[f64; 4]) {
        self.max_overlap = self.max_overlap.max(p.overlap);
        self.max_force = self.max_force.max(p.force);
        if self.keep {
            self.trajectory.push(TrajectoryPoint {
                time: st[3] * units.time,
                overlap: p.overlap,
                overlap_rate: st[1] * units.speed,
                force: p.force,
                contact_radius: p.contact_radius,
                contact_work: st[2] * units.mass * units.speed * units.speed,
            });
        }
    }
}

impl<'s> Run<'s> {
    /// The run at the start overlap `start` (m), ḋ = v0, no work done; the starting
    /// point recorded.
    pub(super) fn new<L: ForceLaw + ?Sized>(
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
            side_cost: Cost::ZERO,
            events: Vec::new(),
            onset: law.in_contact().then_some(0.0),
            seen: Seen {
                trajectory: Vec::new(),
                max_overlap: start,
                max_force: f64::NEG_INFINITY,
                keep: settings.record_trajectory,
            },
        };
        let (s, y) = (run.s, run.y);
        run.record(law, s, &y)?;
        Ok(run)
    }

    /// The force at normalized time `s` and state `y` (N), kept in the trajectory
    /// (when requested) and in the largest force ([`Seen::record`]).
    pub(super) fn record<L: ForceLaw + ?Sized>(
        &mut self,
        law: &L,
        s: f64,
        y: &[f64; 3],
    ) -> Result<f64> {
        self.seen.record(law, &self.units, s, y)
    }

    /// Moves to the event point `hit` (a turning point has ḋ = 0 exactly), records it
    /// and asks the law's hook what happens: `Some(decision)` ends the impact
    /// (separation or sticking), `None` goes on with the next segment.
    pub(super) fn handle_event<L: ForceLaw + ?Sized>(
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
        self.seen.max_overlap = self.seen.max_overlap.max(d);
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
    pub(super) fn outcome<L: ForceLaw + ?Sized>(
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
        let cost = self.stepper.map_or(Cost::ZERO, |st| st.cost()) + self.side_cost;
        ImpactSimulation {
            law: law.name(),
            impact_speed: v0,
            rebound_speed,
            restitution: rebound_speed / v0,
            sticks,
            contact_time: (!sticks).then_some((s - onset_s) * time_unit),
            contact_onset_time: onset_s * time_unit,
            end_time: s * time_unit,
            max_overlap: self.seen.max_overlap,
            max_force: self.seen.max_force,
            kinetic_energy: kinetic,
            energy_loss: if sticks {
                kinetic
            } else {
                kinetic - 0.5 * m * rebound_speed * rebound_speed
            },
            energy_error,
            events: self.events,
            trajectory: self.seen.trajectory,
            cost,
        }
    }
}

/// An error of the simulation itself (not of the law or the integrator).
pub(super) fn simulation_error(message: String) -> Error {
    Error::Model {
        model: "impact simulation",
        message,
    }
}

/// The law did not separate within `settings.max_duration`.
pub(super) fn time_limit_error<L: ForceLaw + ?Sized>(
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

pub(super) fn keep_first(slot: &Cell<Option<Error>>, e: Error) {
    let old = slot.take();
    slot.set(Some(old.unwrap_or(e)));
}
