//! The driver of an oblique impact: [`ObliqueImpact::simulate`] runs segment
//! after segment from first touch to separation (or sticking), each ended by an
//! event ([`Event`]), with the constants of its regularizations.

use super::bodies::ObliqueImpact;
use super::elements::*;
use super::limits::*;
use super::outcome::ObliqueOutcome;
use super::state::*;
use crate::model::Twisting;
use nalgebra::Vector3;
use std::cell::Cell;
use tabor_dynamics::{BranchChange, ForceLaw, SimulationSettings};
use tabor_numerics::{Cost, NumericsError};
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
    /// The total normal force of a damped contact without adhesion crosses 0
    /// (the Coulomb limits `μ |F_n|` touch 0 and their rates jump).
    NormalForceZero,
    /// A damped contact can no longer separate (its escape energy falls to 0,
    /// `Setup::escape_energy`): the bodies stick.
    Capture,
    /// A segment ended where no event value is at 0 (one jumped across it):
    /// an error, named by the driver.
    Unidentified,
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
    /// `mindlin_deresiewicz` keeps a planar history's spring bed exactly (its
    /// breakpoints), any other on [`MICRO_SLIP_NODES`](super::MICRO_SLIP_NODES) nodes per squared
    /// contact-radius scale ([`ObliqueImpact::simulate_with_nodes`] takes the
    /// nodes throughout, at a count given).
    pub fn simulate(
        &self,
        law: &mut dyn ForceLaw,
        speed: f64,
        angle: f64,
        settings: &SimulationSettings,
    ) -> Result<ObliqueOutcome> {
        self.run(law, speed, angle, settings, None)
    }

    /// [`ObliqueImpact::simulate`] with `mindlin_deresiewicz`'s spring bed on
    /// nodes throughout, at the count given (≥ 16; ignored by the other
    /// tangential models): the error of the nodes falls as `1/nodes²` (the crate
    /// README gives the measured constant), so two counts show it.
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
        self.run(law, speed, angle, settings, Some(nodes))
    }

    /// The simulation, with the node count of the spring bed (`None`: planar
    /// where the history allows).
    fn run(
        &self,
        law: &mut dyn ForceLaw,
        speed: f64,
        angle: f64,
        settings: &SimulationSettings,
        nodes: Option<usize>,
    ) -> Result<ObliqueOutcome> {
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
            return this.run(law, speed, angle, settings, nodes);
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
            thaw: [f64::INFINITY; 3],
            warmup: false,
            loading: true,
            tangential: Mode::Stick,
            rolling: Mode::Stick,
            twisting: Mode::Stick,
            twist_sign: 1.0,
            tensile: false,
            doomed: false,
        };
        let mut t = t0;
        let mut onset = modes.in_contact.then_some(t0);
        if modes.in_contact {
            setup.reset_bed(law, t, &y)?;
            setup.decide_initial_modes(law, t, &mut y, &mut modes)?;
        }
        #[cfg(test)]
        setup.record_momentum(t, &y);
        let mut cost = Cost::ZERO;
        let mut events = 0usize;
        let mut slip_switches = 0usize;
        let mut last_switch: [Option<f64>; 3] = [None; 3];
        // how long an element that chatters stays frozen: doubled at each freeze
        let mut freeze_for = [FROZEN_FIRST * setup.time; 3];
        let linear_history = self
            .friction
            .as_ref()
            .is_some_and(|f| f.tangential.model == crate::model::TangentialModel::LinearHistory);
        let decision = loop {
            // a frozen element whose thaw time has come (its own event, or one of
            // another kind at the same time) is looked at again here
            for element in 0..3 {
                if modes.frozen[element] && modes.thaw[element] <= t {
                    slip_switches += setup.thaw(law, t, &mut y, &mut modes, element)?;
                }
            }
            // a damped contact without the energy to separate (`Modes::doomed`:
            // it formed without it, judged here after its onset; its escape
            // energy ran out at the event `Capture`; or a value that jumped
            // below 0 starts a segment) sticks once its normal motion has come
            // to rest (`Capture` again)
            modes.doomed &= modes.in_contact;
            if !modes.doomed
                && setup
                    .escape_energy(law, t, &y, &modes)?
                    .is_some_and(|e| e <= 0.0)
            {
                modes.doomed = true;
            }
            if modes.doomed && setup.capture_value(law, t, &y, &modes)? <= 0.0 {
                break BranchChange::Stick;
            }
            // a slipping linear_history spring's energy, left out of the sliding
            // work's quadrature ([`slip_power`](super::state::slip_power)),
            // enters at the segment's ends
            let slipping = modes.in_contact && modes.tangential == Mode::Slip && linear_history;
            let spring_before = match slipping {
                true => setup.evaluate(law, t, &y, &modes)?.slip_energy,
                false => 0.0,
            };
            let watched = |modes: &Modes| {
                modes.doomed
                    || setup
                        .escape_energy(law, t, &y, modes)
                        .is_ok_and(|e| e.is_some())
            };
            let (event, t_hit, y_hit, spent) = match setup.segment(law, t, &y, &modes, settings) {
                Err(Error::Numerics(e @ NumericsError::NoConvergence { .. }))
                    if watched(&modes) =>
                {
                    return Err(model_error(format!(
                        "{}: at angle {alpha_deg} degrees the damped contact did not reach \
                         a turning point, a separation or its capture ({e}): an overdamped \
                         contact creeps into its equilibrium in steps of its inertial time; \
                         between two spheres the capture waits until the kinetic energy \
                         beyond a rigid rotation and the springs' store (a tangential spring \
                         creeping through its dashpot) fall below the adhesive barrier",
                        law.name()
                    )))
                }
                other => other?,
            };
            cost += spent;
            t = t_hit;
            y = y_hit;
            #[cfg(test)]
            setup.record_momentum(t, &y);
            if slipping {
                y[EN + 2] -= setup.evaluate(law, t, &y, &modes)?.slip_energy - spring_before;
            }
            events += 1;
            if events > settings.max_events {
                return Err(model_error(format!(
                    "{}: more than {} events without separation",
                    law.name(),
                    settings.max_events
                )));
            }
            let (_, overlap, rate, _) = setup.geometry(t, &y);
            if !matches!(
                event,
                Event::BranchEnd
                    | Event::Turn
                    | Event::FrictionOnset
                    | Event::NormalForceZero
                    | Event::Capture
                    | Event::Unidentified
            ) {
                // Stick/slip switches at a vanishing contact (the branch within
                // 10⁻⁶ of its end, where every limit and spring is ~10⁻⁹ of its
                // size) are chattering of a law whose limit vanishes with the
                // contact: every element is frozen for the rest of the impact.
                // Two switches of one element in immediate succession (10⁻⁹ of
                // the time unit) are chattering at a tangency of its trial force
                // and its limit (a stiff dashpot keeps them together): that
                // element is frozen, its force capped at the limit, for
                // FROZEN_FIRST of the time unit, then twice as long each time it
                // chatters again. Frozen for the rest of the impact, an element
                // frozen in slip kept pushing along its old direction after the
                // motion had turned: the bodies gained energy (a Maugis-Dugdale
                // jump-in with tangential damping: e_t = −3.7, the kinetic
                // energy up by 170 %).
                let element = match event {
                    Event::TangentialLimit | Event::TangentialStick => 0,
                    Event::RollingLimit | Event::RollingStick => 1,
                    _ => 2,
                };
                // a frozen element's event is its thaw time, located to within
                // ulps of it: due now (looked at again before the next segment;
                // chattering there freezes it for twice as long)
                if modes.frozen[element] {
                    modes.thaw[element] = modes.thaw[element].min(t);
                    continue;
                }
                let near_end = law.branch_end(overlap, rate)? < 1e-6 * setup.length;
                let repeated = last_switch[element].is_some_and(|s: f64| t - s < 1e-9 * setup.time);
                last_switch[element] = Some(t);
                if near_end {
                    modes.frozen = [true; 3];
                    modes.thaw = [f64::INFINITY; 3];
                    continue;
                }
                if repeated {
                    modes.frozen[element] = true;
                    modes.thaw[element] = t + freeze_for[element];
                    freeze_for[element] *= 2.0;
                    continue;
                }
            }
            // the law's branch ended while the bodies still approach: not a
            // separation (seen at grazing adhesive impacts, α within 10⁻³
            // degrees of 90°, where the branch set up for the normal speed
            // v cos α is left by a normal motion the tangential one drives; there
            // the event values, in units of v cos α, are 10⁶-10¹⁶ and a
            // segment may end where none of them is at 0): refused, not answered
            let grazing = move |name: String| {
                model_error(format!(
                    "{}: at angle {alpha_deg} degrees the normal branch ended while the \
                     bodies still approach (overlap rate {rate:e} m/s): a grazing impact \
                     the simulation does not resolve",
                    name
                ))
            };
            // the contact radius where the branch ends (before its hook), asked
            // only where an element's stiffness vanishes with it (an error of the
            // law there: taken as a contact with area, nothing released)
            let a_at_end = match event {
                Event::BranchEnd if modes.in_contact && setup.has_area_springs() => setup
                    .normal(law, overlap, rate, false)
                    .map_or(f64::INFINITY, |p| p.radius),
                _ => f64::INFINITY,
            };
            match event {
                Event::Unidentified if rate > 0.0 => return Err(grazing(law.name())),
                Event::Unidentified => {
                    return Err(model_error(format!(
                        "{}: at angle {alpha_deg} degrees a segment ended at t = {t:e} s where \
                         none of its event values is at 0 (one jumped across it, or, near \
                         grazing incidence, they change too fast in units of the normal speed \
                         to be resolved): not answered",
                        law.name()
                    )))
                }
                Event::BranchEnd => match setup.hook(law.on_branch_end(overlap, rate))? {
                    BranchChange::Continue => {
                        if modes.in_contact {
                            setup.release_without_area(a_at_end, &mut y, &modes);
                        }
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
                    BranchChange::Separate if rate > 0.0 => return Err(grazing(law.name())),
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
                Event::NormalForceZero => {
                    modes.tensile = !modes.tensile;
                }
                // the escape energy ran out: the contact sticks, once its normal
                // motion has come to rest (the same event, now on that value)
                Event::Capture if !modes.doomed => modes.doomed = true,
                Event::Capture => break BranchChange::Stick,
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
            slip_switches += setup.stick_reversed_slips(law, t, &mut y, &mut modes)?;
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
