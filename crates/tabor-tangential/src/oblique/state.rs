//! The state vector of the integration (its layout and units), the modes of the
//! friction elements, and the quantities fixed during one impact ([`Setup`]):
//! geometry, kinetic energy and the rates of the state ([`Setup::evaluate`]).

use super::bed::{BedState, MicroSlipBed};
use super::bodies::ObliqueImpact;
use super::elements::*;
use super::limits::*;
use crate::model::{TangentialModel, Twisting};
use nalgebra::Vector3;
use std::cell::{Cell, RefCell};
use tabor_dynamics::ForceLaw;
use tabor_restitution::Result;

/// The normal law at one overlap.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct NormalPoint {
    /// Elastic-adhesive force (N, repulsive > 0).
    pub(super) force: f64,
    /// Contact radius (m, ≥ 0).
    pub(super) radius: f64,
    /// `(da/dδ, dF/dδ)`, when asked for.
    pub(super) slopes: Option<(f64, f64)>,
    /// The slopes are the law's closed form (no rounding of differences).
    pub(super) exact: bool,
}

/// The last point evaluated: `(overlap, rate)` as bits and the point.
pub(super) type NormalCache = Cell<Option<([u64; 2], NormalPoint)>>;

// ---------------------------------------------------------------------------
// state layout

pub(super) const E: usize = 0; // deviation from the undisturbed path (3)
pub(super) const U: usize = 3; // relative velocity v_i − v_j (3)
pub(super) const WI: usize = 6; // ω_i (3)
pub(super) const WJ: usize = 9; // ω_j (3)
pub(super) const XT: usize = 12; // tangential displacement (3)
pub(super) const XR: usize = 15; // rolling displacement (3)
pub(super) const XW: usize = 18; // twist angle (1)
pub(super) const EN: usize = 19; // energies (8): normal, damping, sliding, t-damping, t-total, rolling, twisting, arm
pub(super) const N: usize = 27;

#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Mode {
    Stick,
    /// Slipping, with the direction of the limit force (twisting: the sign in x).
    Slip,
}

#[derive(Clone, Copy, Debug)]
pub(super) struct Modes {
    pub(super) in_contact: bool,
    /// Stick/slip switching of the tangential, rolling and twisting element
    /// ended (chattering, see `ObliqueImpact::simulate`): a frozen element keeps
    /// its mode, its stick force capped at the limit.
    pub(super) frozen: [bool; 3],
    /// The SI time at which each frozen element is looked at again (its event
    /// slot's value falls to 0 there: [`Modes::thaw_events`]); ∞ where it stays
    /// frozen for the rest of the impact (at a vanishing contact).
    pub(super) thaw: [f64; 3],
    /// The first 10⁻⁶ of the overlap scale of a contact that starts without a
    /// Coulomb limit: no friction force yet, the springs follow the motion.
    pub(super) warmup: bool,
    pub(super) loading: bool,
    pub(super) tangential: Mode,
    pub(super) rolling: Mode,
    pub(super) twisting: Mode,
    pub(super) twist_sign: f64,
    /// The total normal force of a contact without adhesion is below 0 (a
    /// damping that pulls while the bodies separate): its Coulomb limit
    /// `|F_n|` grows as `F_n` falls. Switched at the zero of `F_n`
    /// ([`Event::NormalForceZero`](super::simulate::Event)), where the limits'
    /// rates jump, so that every event value is smooth within a segment.
    pub(super) tensile: bool,
    /// A damped contact without the energy to separate
    /// (`Setup::escape_energy` ≤ 0 when it formed, or since): it sticks, and
    /// its capture waits for the normal motion to come to rest
    /// (`Setup::capture_value`).
    pub(super) doomed: bool,
}

impl Modes {
    /// True where every element is frozen for the rest of the impact: no
    /// element has an event value.
    pub(super) fn frozen_for_good(&self) -> bool {
        self.frozen == [true; 3] && self.thaw.iter().all(|t| t.is_infinite())
    }

    /// The event values of the frozen elements that are looked at again at
    /// their thaw time, at SI time `t` (`time`: the time unit): `(thaw − t)/time`
    /// in the slot of the element's switch from its mode (its limit while it
    /// sticks, its stick while it slips), which a frozen element leaves empty.
    pub(super) fn thaw_events(&self, g: &mut [f64; EVENTS], t: f64, time: f64) {
        let modes = [self.tangential, self.rolling, self.twisting];
        for (i, mode) in modes.into_iter().enumerate() {
            if self.frozen[i] && self.thaw[i].is_finite() {
                let slot = 2 + 2 * i + usize::from(mode == Mode::Slip);
                g[slot] = (self.thaw[i] - t) / time;
            }
        }
    }
}

/// Everything fixed during one impact.
pub(super) struct Setup<'a> {
    pub(super) imp: &'a ObliqueImpact,
    pub(super) flat: bool,
    pub(super) r_sum: f64,
    pub(super) r_eff: f64,
    pub(super) m_eff: f64,
    pub(super) m_i: f64,
    pub(super) m_j: f64,
    pub(super) inv_i_i: f64,
    pub(super) inv_i_j: f64,
    pub(super) u0: Vector3<f64>,
    pub(super) d_touch: Vector3<f64>,
    pub(super) v: f64,
    pub(super) v_n: f64,
    /// SI value of one normalized unit of each state component.
    pub(super) scale: [f64; N],
    pub(super) time: f64,
    pub(super) length: f64,
    pub(super) force: f64,
    /// The spring bed of `mindlin_deresiewicz` (micro-slip), committed after every
    /// accepted step; `None` for the other tangential models.
    pub(super) bed: Option<RefCell<MicroSlipBed>>,
    /// The normal law at the last overlap asked for ([`Setup::normal`]).
    pub(super) normal_cache: NormalCache,
    /// The step the last segment's control proposed: the first step of the next
    /// (normalized time; `None` at the start and after a branch change).
    pub(super) step_hint: Cell<Option<f64>>,
}

/// Physical quantities at one state.
pub(super) struct Eval {
    pub(super) dy: [f64; N],
    /// event values (positive while the mode holds)
    pub(super) slip_rate_t: f64,
    pub(super) slip_rate_r: f64,
    pub(super) slip_rate_w: f64,
    /// A slipping `linear_history` spring's energy `max(L − γ û·v, 0)²/2k`,
    /// whose change the sliding work's quadrature leaves out ([`slip_power`]);
    /// 0 otherwise.
    pub(super) slip_energy: f64,
}

/// The sliding power of a slipping spring, `g (L − γ û·v)/k` (`on_surface` =
/// L − γ û·v, `slip_rate` = g), and the spring's energy it leaves to the segment
/// ends. For `linear_history` (k constant; not frozen) g = k û·v − d(L − γ û·v)/dt
/// − γ û̇·v, so the power is `(L − γ û·v)(û·v − γ û̇·v/k)` less the rate of the
/// exact differential `(L − γ û·v)²/2k`: its quadrature does not see γ̇, which
/// diverges where γ ∝ √a starts with the contact radius (Tsuji's or
/// `coeff_restitution`'s damping at Maugis-Dugdale's junction, a ∝ (δ − δ_j)^½:
/// sampled there, 4·10⁻³ J of sliding work in an impact of 10⁻¹⁵ J).
/// Returns (power, energy).
pub(super) fn slip_power(
    (model, frozen): (TangentialModel, bool),
    (on_surface, slip_rate, k): (f64, f64, f64),
    (uv, gamma, udot_v): (f64, f64, f64),
) -> (f64, f64) {
    // a frozen element counts g⁺, not g: no exact differential
    let exact = model == TangentialModel::LinearHistory && !frozen;
    match (k > 0.0, exact) {
        (false, _) => (0.0, 0.0),
        (true, true) => (
            on_surface * (uv - gamma * udot_v / k),
            on_surface * on_surface / (2.0 * k),
        ),
        (true, false) => (slip_rate * on_surface / k, 0.0),
    }
}

pub(super) fn v3(y: &[f64; N], i: usize) -> Vector3<f64> {
    Vector3::new(y[i], y[i + 1], y[i + 2])
}

pub(super) fn put(dy: &mut [f64; N], i: usize, v: &Vector3<f64>) {
    dy[i] = v[0];
    dy[i + 1] = v[1];
    dy[i + 2] = v[2];
}

/// `(f(x), f'(x))` by central differences with step `h` (one-sided forward when
/// the law errs below).
pub(super) fn derivative(f: &dyn Fn(f64) -> Result<f64>, x: f64, h: f64) -> Result<(f64, f64)> {
    let fx = f(x)?;
    let up = f(x + h)?;
    match f(x - h) {
        Ok(down) => Ok((fx, (up - down) / (2.0 * h))),
        Err(_) => Ok((fx, (up - fx) / h)),
    }
}

impl<'a> Setup<'a> {
    pub(super) fn to_si(&self, y: &[f64; N]) -> [f64; N] {
        let mut out = *y;
        for (o, s) in out.iter_mut().zip(self.scale.iter()) {
            *o *= s;
        }
        out
    }

    pub(super) fn to_normalized(&self, y: &[f64; N]) -> [f64; N] {
        let mut out = *y;
        for (o, s) in out.iter_mut().zip(self.scale.iter()) {
            *o /= s;
        }
        out
    }

    /// Normal, overlap, overlap rate, ṅ at SI time `t` and SI state `y`.
    pub(super) fn geometry(&self, t: f64, y: &[f64; N]) -> (Vector3<f64>, f64, f64, Vector3<f64>) {
        let e = v3(y, E);
        let u = v3(y, U);
        if self.flat {
            let n = -Vector3::x();
            let overlap = self.v_n * t + e[0];
            return (n, overlap, -n.dot(&u), Vector3::zeros());
        }
        let p = self.d_touch + self.u0 * t;
        let d = p + e;
        let r = d.norm();
        let numerator =
            2.0 * self.r_sum * self.v_n * t - self.v * self.v * t * t - 2.0 * p.dot(&e) - e.dot(&e);
        let overlap = numerator / (self.r_sum + r);
        let inv_r = 1.0 / r;
        let n = d * inv_r;
        let rate = -n.dot(&u);
        let n_dot = (u + n * rate) * inv_r;
        (n, overlap, rate, n_dot)
    }

    /// The step of the central differences of the law's force and contact radius
    /// at `overlap`: 10⁻⁵ of the distance to the branch end (where the law is
    /// singular: Hertz's `a ∝ δ^½` at first touch, JKR's vertical tangent at
    /// pull-off), at most 10⁻⁵ of the overlap scale, at least 10⁻¹² of it.
    /// Relative truncation error ~10⁻¹⁰, rounding ~10⁻¹¹: a fixed step of the
    /// overlap scale is as large as the overlap itself just after first touch,
    /// where the slip conditions are decided.
    pub(super) fn difference_step(
        &self,
        law: &dyn ForceLaw,
        overlap: f64,
        rate: f64,
    ) -> Result<f64> {
        let end = law.branch_end(overlap, rate)?;
        Ok(DIFFERENCE_STEP * end.clamp(1e-7 * self.length, self.length))
    }

    pub(super) fn kinetic(&self, y: &[f64; N]) -> f64 {
        let u = v3(y, U);
        let wi = v3(y, WI);
        let mut k = 0.5 * self.m_eff * u.norm_squared()
            + 0.5 * self.imp.sphere.moment_of_inertia * wi.norm_squared();
        // an immovable target (infinite moment of inertia) keeps its spin: no
        // part of the energy that moves (∞ · 0 would be NaN)
        let i_j = self.imp.target.moment_of_inertia;
        if !self.flat && i_j.is_finite() {
            k += 0.5 * i_j * v3(y, WJ).norm_squared();
        }
        k
    }

    /// The rates of the SI state at SI time `t` in `modes`.
    pub(super) fn evaluate(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &[f64; N],
        modes: &Modes,
    ) -> Result<Eval> {
        let (n, overlap, rate, n_dot) = self.geometry(t, y);
        let u = v3(y, U);
        let wi = v3(y, WI);
        let wj = if self.flat {
            Vector3::zeros()
        } else {
            v3(y, WJ)
        };
        let mut dy = [0.0; N];
        put(&mut dy, E, &(u - self.u0));
        let mut out = Eval {
            dy,
            slip_rate_t: f64::INFINITY,
            slip_rate_r: f64::INFINITY,
            slip_rate_w: f64::INFINITY,
            slip_energy: 0.0,
        };
        if !modes.in_contact {
            // free flight (or the Maugis-Dugdale approach before jump-in)
            let f_el = law.force(overlap, rate)?;
            put(&mut out.dy, U, &(n * (f_el / self.m_eff)));
            out.dy[EN] = f_el * rate;
            return Ok(out);
        }
        // the slopes of the law enter only the rates of the slip conditions and
        // `mindlin_rescale`'s shrinking of ξ while unloading
        let slipping = [modes.tangential, modes.rolling, modes.twisting].contains(&Mode::Slip);
        let rescaling = !modes.loading
            && self
                .imp
                .friction
                .as_ref()
                .is_some_and(|f| f.tangential.model == TangentialModel::MindlinRescale);
        let np = self.normal(law, overlap, rate, slipping || rescaling)?;
        let (f_el, a) = (np.force, np.radius);
        let (a_prime, f_prime) = np.slopes.unwrap_or((0.0, 0.0));
        let normal = &self.imp.normal;
        let c_n = normal.damping_at(a);
        let f_d = c_n * rate;
        let f_n = f_el + f_d;
        let pull_off = self.imp.normal.pull_off_force;
        let cohesive = pull_off > 0.0;
        let fc = crate::critical_force(f_el, f_n, pull_off);

        let (arm_i, arm_j) = if self.flat {
            (self.imp.sphere.radius, 0.0)
        } else {
            (
                self.imp.sphere.radius - 0.5 * overlap,
                self.imp.target.radius - 0.5 * overlap,
            )
        };
        let r_i = self.imp.sphere.radius;
        let r_j = if self.flat {
            0.0
        } else {
            self.imp.target.radius
        };

        let vt = u - n * n.dot(&u);
        let wr = wi * r_i + wj * r_j;
        let v_tr = vt - wr.cross(&n);
        let w_rel = wi - wj;
        let v_rl = w_rel.cross(&n) * self.r_eff;
        let w_tw = w_rel.dot(&n);

        // forces (they do not depend on the slip rates)
        let mut f_t = Vector3::zeros();
        let mut f_r = Vector3::zeros();
        let mut m_tw = 0.0;
        let mut tang = None;
        if modes.warmup {
            put(&mut out.dy, U, &(n * (f_n / self.m_eff)));
            put(&mut out.dy, XT, &v_tr);
            put(&mut out.dy, XR, &v_rl);
            out.dy[XW] = w_tw;
            out.dy[EN] = f_el * rate;
            out.dy[EN + 1] = f_d * rate;
            return Ok(out);
        }
        if let Some(fr) = &self.imp.friction {
            let t = &fr.tangential;
            let k = t.spring(a);
            let gamma = t.damping_ratio * c_n;
            let limit = t.coefficient * fc;
            let xi = v3(y, XT);
            if let Some(bed) = &self.bed {
                // Mindlin-Deresiewicz: the spring bed, a dashpot in parallel up to
                // the Coulomb limit (the bed alone never exceeds it)
                let f_bed = bed.borrow().force(&BedState::new(n, xi, a, limit));
                let s = dashpot_share(&f_bed, &(v_tr * gamma), limit);
                f_t = f_bed - v_tr * (gamma * s);
                put(&mut out.dy, XT, &(v_tr - n * xi.dot(&n_dot)));
                out.dy[EN + 3] = s * gamma * v_tr.norm_squared();
            } else {
                f_t = match modes.tangential {
                    Mode::Stick => cap(-(xi * k + v_tr * gamma), limit, modes.frozen[0]),
                    Mode::Slip => -direction(&xi, &v_tr) * limit,
                };
                tang = Some((k, gamma, limit, xi));
            }
            if let Some(r) = &fr.rolling {
                let psi = v3(y, XR);
                let limit_r = r.coefficient * fc;
                f_r = match modes.rolling {
                    Mode::Stick => cap(
                        -(psi * r.stiffness + v_rl * r.damping),
                        limit_r,
                        modes.frozen[1],
                    ),
                    Mode::Slip => -direction(&psi, &v_rl) * limit_r,
                };
            }
            if let Some(tw) = &fr.twisting {
                let (k_tw, g_tw, l_tw) = twist_coefficients(tw, fr, a, c_n, fc);
                m_tw = match modes.twisting {
                    Mode::Stick => {
                        let m = -(k_tw * y[XW] + g_tw * w_tw);
                        if modes.frozen[2] && m.abs() > l_tw {
                            l_tw.copysign(m)
                        } else {
                            m
                        }
                    }
                    Mode::Slip => -modes.twist_sign * l_tw,
                };
            }
        }

        // accelerations
        let force_i = n * f_n + f_t;
        let u_dot = force_i / self.m_eff;
        let n_cross_ft = n.cross(&f_t);
        let torque_roll = n.cross(&f_r) * self.r_eff;
        let torque_i = -n_cross_ft * arm_i + torque_roll + n * m_tw;
        let torque_j = -n_cross_ft * arm_j - torque_roll - n * m_tw;
        let wi_dot = torque_i * self.inv_i_i;
        let wj_dot = if self.flat {
            Vector3::zeros()
        } else {
            torque_j * self.inv_i_j
        };
        put(&mut out.dy, U, &u_dot);
        put(&mut out.dy, WI, &wi_dot);
        put(&mut out.dy, WJ, &wj_dot);

        // energies (power removed from the bodies)
        out.dy[EN] = f_el * rate;
        out.dy[EN + 1] = f_d * rate;
        out.dy[EN + 4] = -f_t.dot(&v_tr);
        out.dy[EN + 5] = -f_r.dot(&v_rl);
        out.dy[EN + 6] = -m_tw * w_tw;
        // bodies gain F_t·[(δ/2)(ω_i + ω_j) × n] beyond −F_t·v_tr (pair convention)
        let arm_gain = f_t.dot(&(wi * (r_i - arm_i) + wj * (r_j - arm_j)).cross(&n));
        out.dy[EN + 7] = -arm_gain;

        let Some(fr) = &self.imp.friction else {
            return Ok(out);
        };

        // rates of the quantities the slip conditions need
        let accel_normal = -n_dot.dot(&u) - n.dot(&u_dot); // δ̈
        let a_dot = a_prime * rate;
        let c_n_dot = normal.damping_rate(a, a_dot);
        let fc_dot = {
            let raw = if cohesive { f_el + 2.0 * pull_off } else { f_n };
            let mut d = f_prime * rate;
            if !cohesive {
                d += c_n_dot * rate + c_n * accel_normal;
            }
            let tensile = if cohesive { raw < 0.0 } else { modes.tensile };
            if tensile {
                -d
            } else {
                d
            }
        };
        let vt_dot = u_dot - n_dot * n.dot(&u) - n * (n_dot.dot(&u) + n.dot(&u_dot));
        let v_tr_dot = vt_dot - (wi_dot * r_i + wj_dot * r_j).cross(&n) - wr.cross(&n_dot);
        let v_rl_dot = ((wi_dot - wj_dot).cross(&n) + w_rel.cross(&n_dot)) * self.r_eff;
        let w_tw_dot = (wi_dot - wj_dot).dot(&n) + w_rel.dot(&n_dot);

        // tangential
        if let Some((k, gamma, limit, xi)) = tang {
            let t = &fr.tangential;
            let (k_dot, gamma_dot, rescale_rate) =
                spring_rates(t, (a, a_dot), c_n_dot, !modes.loading, self.time);
            let limit_dot = t.coefficient * fc_dot;
            match modes.tangential {
                Mode::Stick => {
                    let d = v_tr - n * xi.dot(&n_dot) + xi * rescale_rate;
                    put(&mut out.dy, XT, &d);
                    out.dy[EN + 3] = gamma * v_tr.norm_squared();
                }
                Mode::Slip => {
                    let uhat = direction(&xi, &v_tr);
                    let drive =
                        v_tr * k + v_tr * (gamma_dot - k_dot * ratio(gamma, k)) + v_tr_dot * gamma;
                    let turn = turn_rate(&drive, &uhat, &n, limit, self.time);
                    let w = turn - n * uhat.dot(&n_dot);
                    let d = w * xi.norm();
                    put(&mut out.dy, XT, &d);
                    // û·Ṫ_stick − L̇ with ξ on the limit surface
                    let uv = uhat.dot(&v_tr);
                    let on_surface = limit - gamma * uv;
                    let kappa_rate = ratio(k_dot, k) + rescale_rate;
                    let g = kappa_rate * on_surface
                        + k * uv
                        + gamma_dot * uv
                        + gamma * uhat.dot(&v_tr_dot)
                        - limit_dot;
                    out.slip_rate_t = g;
                    // The spring's part of the limit force along û, `L − γ û·v`,
                    // carries the sliding work (its force times the slip rate
                    // g/k). Where the dashpot alone reaches the limit (that part
                    // ≤ 0) the dashpot's force along û is capped at the limit
                    // and spring and slider carry nothing along û: else the
                    // spring part points against the force, and where it
                    // vanishes more slowly than k (a Tsuji damping ∝ √a at a
                    // damped Hertz separation, k ∝ a) the history (L û − γ v)/k
                    // and the sliding work g·(L − γ û·v)/k diverge, as 1/δ.
                    // The slip rate g falls to 0 where slip ends (the event that
                    // ends the segment): its smooth continuation beyond, not
                    // g⁺, keeps the power smooth across the step that holds the
                    // event, whose dense output gives the energy there (a kink
                    // inside the step would be integrated at the motion's step
                    // size, the energies being outside the error control). A
                    // frozen element, whose slip has no end event, counts g⁺.
                    let slip_rate = if modes.frozen[0] { g.max(0.0) } else { g };
                    if on_surface >= 0.0 {
                        // û̇ = the turning of ξ's direction
                        let udot_v = (w - uhat * uhat.dot(&w)).dot(&v_tr);
                        let (power, energy) = slip_power(
                            (t.model, modes.frozen[0]),
                            (on_surface, slip_rate, k),
                            (uv, gamma, udot_v),
                        );
                        out.dy[EN + 2] = power;
                        out.slip_energy = energy;
                        out.dy[EN + 3] = gamma * v_tr.norm_squared();
                    } else {
                        out.dy[EN + 3] = gamma * v_tr.norm_squared() + on_surface * uv;
                    }
                }
            }
        }
        // rolling
        if let Some(r) = &fr.rolling {
            let psi = v3(y, XR);
            let limit_r = r.coefficient * fc;
            match modes.rolling {
                Mode::Stick => {
                    let d = v_rl - n * psi.dot(&n_dot);
                    put(&mut out.dy, XR, &d);
                }
                Mode::Slip => {
                    let uhat = direction(&psi, &v_rl);
                    let drive = v_rl * r.stiffness + v_rl_dot * r.damping;
                    let turn = turn_rate(&drive, &uhat, &n, limit_r, self.time);
                    put(
                        &mut out.dy,
                        XR,
                        &((turn - n * uhat.dot(&n_dot)) * psi.norm()),
                    );
                    out.slip_rate_r = uhat.dot(&drive) - r.coefficient * fc_dot;
                }
            }
        }
        // twisting
        if let Some(tw) = &fr.twisting {
            let (k_tw, g_tw, l_tw) = twist_coefficients(tw, fr, a, c_n, fc);
            match modes.twisting {
                Mode::Stick => out.dy[XW] = w_tw,
                Mode::Slip => {
                    let (k_dot, g_dot, l_dot) = match tw {
                        Twisting::Marshall => {
                            let t = &fr.tangential;
                            (
                                t.stiffness * a * a_dot,
                                0.5 * t.damping_ratio * (c_n_dot * a + 2.0 * c_n * a_dot) * a,
                                2.0 / 3.0 * t.coefficient * (a_dot * fc + a * fc_dot),
                            )
                        }
                        Twisting::Sds { coefficient, .. } => (0.0, 0.0, coefficient * fc_dot),
                    };
                    let s = modes.twist_sign;
                    let on_surface = l_tw * s - g_tw * w_tw;
                    let g = s
                        * (ratio(k_dot, k_tw) * on_surface
                            + k_tw * w_tw
                            + g_dot * w_tw
                            + g_tw * w_tw_dot)
                        - l_dot;
                    out.slip_rate_w = g;
                    out.dy[XW] = 0.0;
                }
            }
        }
        Ok(out)
    }
}

/// The share `s ∈ [0, 1]` of the dashpot force `g` that the contact carries on
/// top of the spring bed's force `f` (`|f| ≤ limit`): all of it while
/// `|f − g| ≤ limit`, else the share that brings the sum to the Coulomb limit
/// (the smallest root of `|f − s g| = limit`), so no dashpot pushes a contact
/// beyond `μ F_n0`.
pub(super) fn dashpot_share(f: &Vector3<f64>, g: &Vector3<f64>, limit: f64) -> f64 {
    let g2 = g.norm_squared();
    if g2 == 0.0 || (f - g).norm() <= limit {
        return 1.0;
    }
    let fg = f.dot(g);
    let slack = (limit * limit - f.norm_squared()).max(0.0);
    let root = (fg + (fg * fg + g2 * slack).sqrt()) / g2;
    root.clamp(0.0, 1.0)
}

pub(super) fn put_state(y: &mut [f64; N], i: usize, v: &Vector3<f64>) {
    put(y, i, v);
}
