//! The driver of an oblique impact: [`ObliqueImpact::simulate`] runs segment
//! after segment from first touch to separation (or sticking), each ended by an
//! event ([`Event`]), with the constants of its regularizations.

use super::bed::MICRO_SLIP_NODES;
use super::bodies::ObliqueImpact;
use super::elements::*;
use super::limits::*;
use super::outcome::ObliqueOutcome;
use super::state::*;
use crate::model::Twisting;
use nalgebra::Vector3;
use std::cell::Cell;
use tabor_dynamics::{BranchChange, ForceLaw, SimulationSettings};
use tabor_numerics::ode::{
    drive_events, DenseStepper, DormandPrince, DormandPrince853, EventDirection, EventsIntegration,
};
use tabor_numerics::Cost;
use tabor_restitution::{validate, Error, Result};

/// Which event ended a segment.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Event {
    BranchEnd,
    Turn,
    TangentialLimit,
    TangentialStick,
    RollingLimit,
    RollingStick,
    TwistingLimit,
    TwistingStick,
    FrictionOnset,
}

/// `x ≤ limit`, false for NaN.
fn at_most(x: f64, limit: f64) -> bool {
    matches!(
        x.partial_cmp(&limit),
        Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
    )
}

/// The effective radius of the impact (the sphere's on a flat).
fn r_eff_of(imp: &ObliqueImpact) -> f64 {
    if imp.target.is_flat() {
        imp.sphere.radius
    } else {
        imp.sphere.radius * imp.target.radius / (imp.sphere.radius + imp.target.radius)
    }
}

impl ObliqueImpact {
    /// Simulates the impact at relative speed `speed` (m/s) and angle `angle`
    /// (degrees, 0 ≤ α < 90) through the normal law `law` (left in its final
    /// state), to the accuracy of `settings` (tolerances in normalized units: the
    /// law's overlap scale, the impact speed, the normal force scale).
    ///
    /// `mindlin_deresiewicz` uses a spring bed of [`MICRO_SLIP_NODES`] nodes per
    /// squared contact-radius scale ([`ObliqueImpact::simulate_with_nodes`] sets
    /// another count).
    pub fn simulate(
        &self,
        law: &mut dyn ForceLaw,
        speed: f64,
        angle: f64,
        settings: &SimulationSettings,
    ) -> Result<ObliqueOutcome> {
        self.simulate_with_nodes(law, speed, angle, settings, MICRO_SLIP_NODES)
    }

    /// [`ObliqueImpact::simulate`] with the node count of `mindlin_deresiewicz`'s
    /// spring bed given (≥ 16; ignored by the other tangential models): the error
    /// of the micro-slip falls as `1/nodes²` (the crate README gives the measured
    /// constant), so two counts show it.
    pub fn simulate_with_nodes(
        &self,
        law: &mut dyn ForceLaw,
        speed: f64,
        angle: f64,
        settings: &SimulationSettings,
        nodes: usize,
    ) -> Result<ObliqueOutcome> {
        if nodes < 16 {
            return Err(Error::invalid(
                "nodes",
                nodes as f64,
                "the micro-slip spring bed needs at least 16 nodes",
            ));
        }
        let v = validate::positive("speed", speed)?;
        let alpha_deg = validate::finite("angle", angle)?;
        if !(0.0..90.0).contains(&alpha_deg) {
            return Err(Error::invalid(
                "angle",
                alpha_deg,
                "must be in [0, 90) degrees (the bodies must approach)",
            ));
        }
        if let Some(f) = &self.friction {
            f.validate()?;
        }
        // a resistance with a zero coefficient has a zero limit: it exerts nothing
        let mut this = *self;
        if let Some(f) = this.friction.as_mut() {
            if f.rolling.is_some_and(|r| r.coefficient == 0.0) {
                f.rolling = None;
            }
            match f.twisting {
                Some(Twisting::Sds {
                    coefficient: 0.0, ..
                }) => f.twisting = None,
                Some(Twisting::Marshall) if f.tangential.coefficient == 0.0 => f.twisting = None,
                _ => {}
            }
            if f.tangential.coefficient == 0.0 && f.rolling.is_none() && f.twisting.is_none() {
                this.friction = None;
            }
        }
        if this != *self {
            return this.simulate_with_nodes(law, speed, angle, settings, nodes);
        }
        validate::non_negative("pull_off_force", self.normal.pull_off_force)?;
        validate::non_negative("damping", self.normal.damping)?;
        validate::in_open_interval(
            "damping_exponent",
            self.normal.damping_exponent,
            0.0,
            1.0 + f64::EPSILON,
            "must be in (0, 1] (1: Kuwabara-Kono, viscoelastic; 1/2: the Tsuji form)",
        )?;
        let spin_i = Vector3::from(self.sphere_spin);
        let flat = self.target.is_flat();
        let spin_j = if flat {
            Vector3::zeros()
        } else {
            Vector3::from(self.target_spin)
        };
        for s in spin_i.iter() {
            validate::finite("sphere_spin", *s)?;
        }
        for s in spin_j.iter() {
            validate::finite("target_spin", *s)?;
        }
        // a spin whose surface speed dwarfs the impact is no impact problem (and
        // overflows the integration's units)
        for (name, spin, radius) in [
            ("sphere_spin", spin_i, self.sphere.radius),
            ("target_spin", spin_j, self.target.radius),
        ] {
            // the largest component: the norm of huge components overflows
            let largest = spin.amax();
            if radius.is_finite() && !at_most(largest * radius, MAX_SURFACE_SPEED_RATIO * v) {
                return Err(Error::invalid(
                    name,
                    largest,
                    "the surface speed |ω| R must be at most 10⁶ times the impact speed",
                ));
            }
        }
        if self.sphere.is_flat() {
            return Err(Error::invalid(
                "sphere radius",
                self.sphere.radius,
                "the moving body must be a sphere",
            ));
        }
        let alpha = alpha_deg.to_radians();
        let v_n = v * alpha.cos();
        let m_i = self.sphere.mass;
        let m_j = self.target.mass;
        let m_eff = if m_j.is_infinite() {
            m_i
        } else {
            m_i * m_j / (m_i + m_j)
        };
        law.begin_impact(m_eff, v_n)?;
        let length = validate::positive("overlap_scale", law.overlap_scale(m_eff, v_n)?)?;
        let time = length / v_n;
        // the force scale: the kinetic one, or the law's own force at the overlap
        // scale where adhesion outweighs it (a grazing impact's normal speed is
        // tiny, its contact forces are not)
        let force = m_eff * v_n * v_n / length;
        let check_force = force.max(law.force(length, 0.0).map_or(0.0, f64::abs));
        // the friction springs at the overlap scale: finite, and not beyond 10¹² of
        // the normal force scale (a stiffness that overflows the units)
        if let Some(f) = &self.friction {
            let a_ref = (r_eff_of(self) * length).sqrt();
            let spring = f.tangential.spring(a_ref) * length;
            if !at_most(spring, MAX_SPRING_RATIO * check_force) {
                return Err(Error::invalid(
                    "tangential_stiffness",
                    f.tangential.stiffness,
                    "the tangential spring at the overlap scale must be at most 10¹² times the normal force scale",
                ));
            }
            if let Some(r) = &f.rolling {
                if !at_most(r.stiffness * length, MAX_SPRING_RATIO * check_force) {
                    return Err(Error::invalid(
                        "rolling stiffness",
                        r.stiffness,
                        "the rolling spring at the overlap scale must be at most 10¹² times the normal force scale",
                    ));
                }
            }
        }
        let r_i = self.sphere.radius;
        let (r_sum, r_eff) = if flat {
            (r_i, r_i)
        } else {
            let r_j = self.target.radius;
            (r_i + r_j, r_i * r_j / (r_i + r_j))
        };
        let u0 = Vector3::new(v_n, v * alpha.sin(), 0.0);
        let mut scale = [1.0; N];
        let spin_unit = v / r_i;
        for k in 0..3 {
            scale[E + k] = length;
            scale[U + k] = v;
            scale[WI + k] = spin_unit;
            scale[WJ + k] = spin_unit;
            scale[XT + k] = length;
            scale[XR + k] = length;
        }
        scale[XW] = length / r_i;
        for k in 0..8 {
            scale[EN + k] = m_eff * v * v;
        }
        let setup = Setup {
            imp: self,
            flat,
            r_sum,
            r_eff,
            m_eff,
            m_i,
            m_j,
            inv_i_i: 1.0 / self.sphere.moment_of_inertia,
            inv_i_j: if flat {
                0.0
            } else {
                1.0 / self.target.moment_of_inertia
            },
            u0,
            d_touch: -Vector3::x() * r_sum,
            v,
            v_n,
            scale,
            time,
            length,
            force,
            bed: self.micro_slip_bed(law, r_eff, length, v_n, nodes),
            normal_cache: Cell::new(None),
            step_hint: Cell::new(None),
        };

        // start on the undisturbed path at the law's start overlap
        let start = validate::finite("start_overlap", law.start_overlap())?;
        let t0 = if start >= 0.0 {
            0.0
        } else {
            let g = -start;
            if flat {
                -g / v_n
            } else {
                let q = 2.0 * r_sum * g + g * g;
                -q / (r_sum * v_n + (r_sum * r_sum * v_n * v_n + v * v * q).sqrt())
            }
        };
        let mut y = [0.0; N];
        for k in 0..3 {
            y[U + k] = u0[k];
            y[WI + k] = spin_i[k];
            y[WJ + k] = spin_j[k];
        }
        let kinetic0 = setup.kinetic(&y);
        let mut modes = Modes {
            in_contact: law.in_contact(),
            frozen: [false; 3],
            warmup: false,
            loading: true,
            tangential: Mode::Stick,
            rolling: Mode::Stick,
            twisting: Mode::Stick,
            twist_sign: 1.0,
        };
        let mut t = t0;
        let mut onset = modes.in_contact.then_some(t0);
        if modes.in_contact {
            setup.reset_bed(law, t, &y)?;
            setup.decide_initial_modes(law, t, &mut y, &mut modes)?;
        }
        let mut cost = Cost::ZERO;
        let mut events = 0usize;
        let mut slip_switches = 0usize;
        let mut last_switch: [Option<f64>; 3] = [None; 3];
        let decision = loop {
            let (event, t_hit, y_hit, spent) = setup.segment(law, t, &y, &modes, settings)?;
            cost += spent;
            t = t_hit;
            y = y_hit;
            events += 1;
            if events > settings.max_events {
                return Err(model_error(format!(
                    "{}: more than {} events without separation",
                    law.name(),
                    settings.max_events
                )));
            }
            let (_, overlap, rate, _) = setup.geometry(t, &y);
            if !matches!(event, Event::BranchEnd | Event::Turn | Event::FrictionOnset) {
                // Stick/slip switches at a vanishing contact (the branch within
                // 10⁻⁶ of its end, where every limit and spring is ~10⁻⁹ of its
                // size) are chattering of a law whose limit vanishes with the
                // contact: every element is frozen for the rest of the impact.
                // Two switches of one element in immediate succession (10⁻⁹ of
                // the time unit) are chattering at a tangency of its trial force
                // and its limit (a stiff dashpot keeps them together): that
                // element is frozen, its force capped at the limit.
                let element = match event {
                    Event::TangentialLimit | Event::TangentialStick => 0,
                    Event::RollingLimit | Event::RollingStick => 1,
                    _ => 2,
                };
                let near_end = law.branch_end(overlap, rate)? < 1e-6 * setup.length;
                let repeated = last_switch[element].is_some_and(|s: f64| t - s < 1e-9 * setup.time);
                last_switch[element] = Some(t);
                if near_end {
                    modes.frozen = [true; 3];
                    continue;
                }
                if repeated {
                    modes.frozen[element] = true;
                    continue;
                }
            }
            match event {
                Event::BranchEnd => match setup.hook(law.on_branch_end(overlap, rate))? {
                    BranchChange::Continue => {
                        if !modes.in_contact && law.in_contact() {
                            modes.in_contact = true;
                            onset = Some(t);
                            setup.reset_bed(law, t, &y)?;
                            setup.decide_initial_modes(law, t, &mut y, &mut modes)?;
                        }
                        modes.in_contact = law.in_contact();
                        let g = law.branch_end(overlap, rate)?;
                        if g.is_nan() || g <= 0.0 {
                            return Err(model_error(format!(
                                "{}: on_branch_end returned Continue at d = {overlap:e} m, but \
                                 the new branch ends there too",
                                law.name()
                            )));
                        }
                    }
                    BranchChange::Separate if rate > 0.0 => {
                        // the law's branch ended while the bodies still approach:
                        // not a separation (seen at grazing adhesive impacts,
                        // α within 10⁻³ degrees of 90°, where the branch set up for
                        // the normal speed v cos α is left by a normal motion the
                        // tangential one drives): refused, not answered
                        return Err(model_error(format!(
                            "{}: at angle {alpha_deg} degrees the normal branch ended while the \
                             bodies still approach (overlap rate {rate:e} m/s): a grazing impact \
                             the simulation does not resolve",
                            law.name()
                        )));
                    }
                    other => break other,
                },
                Event::Turn => {
                    let decision = setup.hook(if modes.loading {
                        law.on_max_compression(overlap)
                    } else {
                        law.on_min_compression(overlap)
                    })?;
                    modes.loading = !modes.loading;
                    if decision != BranchChange::Continue {
                        break decision;
                    }
                }
                Event::FrictionOnset => {
                    modes.warmup = false;
                    setup.decide_modes(law, t, &mut y, &mut modes)?;
                }
                Event::TangentialLimit => {
                    let mut trial = modes;
                    trial.tangential = Mode::Slip;
                    let mut y_slip = y;
                    setup.enter_slip(law, t, &mut y_slip, &modes, XT)?;
                    // a tangency (the trial force touches the limit and turns back)
                    // stays in stick
                    if setup.evaluate(law, t, &y_slip, &trial)?.slip_rate_t > 0.0 {
                        slip_switches += 1;
                        y = y_slip;
                        modes = trial;
                    }
                }
                Event::TangentialStick => {
                    slip_switches += 1;
                    modes.tangential = Mode::Stick;
                    setup.leave_slip(law, t, &mut y, &modes, XT)?;
                }
                Event::RollingLimit => {
                    let mut trial = modes;
                    trial.rolling = Mode::Slip;
                    let mut y_slip = y;
                    setup.enter_slip(law, t, &mut y_slip, &modes, XR)?;
                    if setup.evaluate(law, t, &y_slip, &trial)?.slip_rate_r > 0.0 {
                        y = y_slip;
                        modes = trial;
                    }
                }
                Event::RollingStick => {
                    modes.rolling = Mode::Stick;
                    setup.leave_slip(law, t, &mut y, &modes, XR)?;
                }
                Event::TwistingLimit => {
                    let m = setup.twist_trial(law, t, &y)?;
                    let mut trial = modes;
                    trial.twist_sign = if m >= 0.0 { 1.0 } else { -1.0 };
                    trial.twisting = Mode::Slip;
                    if setup.evaluate(law, t, &y, &trial)?.slip_rate_w > 0.0 {
                        modes = trial;
                    }
                }
                Event::TwistingStick => {
                    modes.twisting = Mode::Stick;
                    setup.leave_twist_slip(law, t, &mut y, &modes)?;
                }
            }
        };
        setup.outcome(
            law,
            t,
            &y,
            onset.unwrap_or(t),
            decision,
            kinetic0,
            alpha_deg,
            cost,
            slip_switches,
        )
    }
}

impl<'a> Setup<'a> {
    /// The answer of a hook of the law, its last normal point forgotten (the hook
    /// may have changed the branch).
    fn hook<T>(&self, answer: Result<T>) -> Result<T> {
        self.forget_normal();
        self.step_hint.set(None);
        answer
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
        let mut offset = [0.0; 9];
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
        let mut rhs = |s: f64, yn: &[f64; N]| -> [f64; N] {
            let ysi = self.to_si(yn);
            match self.evaluate(law, s * self.time, &ysi, modes) {
                Ok(ev) => std::array::from_fn(|i| ev.dy[i] * rate_unit[i]),
                Err(e) => {
                    keep_first(&failure, e);
                    [f64::NAN; N]
                }
            }
        };
        let g_failure: Cell<Option<Error>> = Cell::new(None);
        // a value within the rounding of the event values (O(1) in their units)
        // is the zero itself: Brent's method stops there instead of bisecting
        // the rest of the bracket down to 4 ε
        let g = |s: f64, yn: &[f64; N]| -> f64 {
            match self.event_values(law, s * self.time, &self.to_si(yn), modes) {
                Ok(v) => {
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
                }
                Err(e) => {
                    keep_first(&g_failure, e);
                    f64::NAN
                }
            }
        };
        let s_end = s0 + settings.max_duration;
        let numerics = |e| failure.take().unwrap_or(Error::Numerics(e));
        let micro_slip = self.bed.is_some() && modes.in_contact;
        // micro-slip: the springs' state at the end of every accepted step
        let mut commit = |stop: f64, yn: &[f64; N]| {
            if micro_slip {
                if let Err(e) = self.commit_bed(law, stop * self.time, &self.to_si(yn)) {
                    keep_first(&failure, e);
                }
            }
        };
        let mut events = |s: f64, yn: &[f64; N]| [g(s, yn)];
        // the smooth models with DOP853 (as the central simulated impact), the
        // spring bed, piecewise smooth within a step, with Dormand-Prince 5(4)
        // The energies are quadratures of the powers along the motion: where the
        // law's slopes are exact (JKR's closed form) its eighth-order steps
        // resolve them, and they do not choose the steps (DOP853's error norm over
        // the motion only); with slopes by differences, whose rounding grows
        // toward a branch end, and for the spring bed's Dormand-Prince 5(4) steps
        // of a piecewise smooth motion, they stay under control.
        let quadratures = self.exact_slopes(law, t, y, modes)?;
        let run = if self.bed.is_some() {
            let mut stepper = DormandPrince::new(&mut rhs, s0, yn, s_end, settings.tolerance)
                .map_err(&numerics)?;
            drive_to_event(&mut stepper, &mut rhs, &mut events, s_end, &mut commit)
        } else if self.is_planar(y, modes) {
            let mut g = g;
            let tolerance = settings.tolerance;
            self.planar_segment(&mut rhs, &mut g, s0, &yn, s_end, tolerance, quadratures)
        } else {
            let mut tolerance = settings.tolerance;
            if quadratures {
                tolerance = tolerance.with_error_components(EN);
            }
            // the first step: the one the last segment's control proposed
            if let Some(h) = self.step_hint.get() {
                tolerance.initial_step = Some(h);
            }
            let mut stepper =
                DormandPrince853::new(&mut rhs, s0, yn, s_end, tolerance).map_err(&numerics)?;
            let run = drive_to_event(&mut stepper, &mut rhs, &mut events, s_end, &mut commit);
            self.step_hint.set(Some(stepper.proposed_step()));
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
        if micro_slip {
            self.commit_bed(law, t_hit, &y_hit)?;
        }
        let mut gv = self.event_values(law, t_hit, &y_hit, modes)?;
        for (g, o) in gv.iter_mut().zip(offset.iter()) {
            *g += o;
        }
        let which = gv
            .iter()
            .enumerate()
            .min_by(|a, b| a.1.total_cmp(b.1))
            .map_or(0, |(i, _)| i);
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
        ][which];
        Ok((event, t_hit, y_hit, sol.cost + run.event_cost))
    }
}

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

    /// Commits the spring bed at SI (t, y) (after an accepted step).
    pub(super) fn commit_bed(&self, law: &dyn ForceLaw, t: f64, y: &[f64; N]) -> Result<()> {
        let (Some(bed), Some(fr)) = (&self.bed, &self.imp.friction) else {
            return Ok(());
        };
        let (a, fc, .., n) = self.contact(law, t, y)?;
        bed.borrow_mut()
            .commit(&n, &v3(y, XT), a, fr.tangential.coefficient * fc);
        Ok(())
    }
}
