//! The oblique impact of two spheres (or a sphere and a flat): translation and
//! rotation through any normal [`ForceLaw`] (Hertz, JKR, Maugis-Dugdale), optional
//! Kuwabara-Kono damping, and the friction, rolling and twisting models of
//! [`Friction`] in continuous time.
//!
//! # The models in continuous time
//!
//! [`Friction::step`] is LAMMPS's time-stepped scheme. Here its limit dt → 0 is
//! integrated accurately instead. Each resistance (tangential, rolling, twisting)
//! is an elastic-plastic spring: a stored displacement ξ (LAMMPS's history) with
//! the trial force `T = k ξ + γ v` and the Coulomb limit `L = μ F_n0`:
//!
//! - **stick** (`|T| < L`): `ξ̇ = v − (ξ·ṅ) n` (the rotation keeps ξ in the turning
//!   tangent plane: the continuous form of LAMMPS's rotate-and-rescale), force `−T`;
//!   `mindlin_rescale` adds `(ȧ/a) ξ` while the contact shrinks;
//! - **slip** (`|T| = L`): the force is `−L û` with `û = T/|T|`; û turns with the
//!   part of `Ṫ` normal to it, `dû/dt = P⊥(k v + (γ̇ − k̇γ/k) v + γ v̇)/L` (for
//!   `mindlin` with damping proportional to a, `γ̇ − k̇γ/k = 0`).
//!
//! The switches are events located on the dense output of
//! [`tabor_numerics::ode`] (Dormand-Prince 5(4)): stick → slip where `L − |T|`
//! falls to 0, slip → stick where `û·Ṫ_stick − L̇` (the rate at which the trial
//! force would outgrow the limit) falls to 0. There ξ is reset to the elastic part
//! of the limit force, `(L û − γ v)/k`, as LAMMPS does at every sliding step. The
//! normal law's own events (turning points, branch ends: jump-in, snap-off) are
//! located the same way and handed to its hooks, as in
//! [`tabor_dynamics::simulate_impact`]. At first touch of a law without adhesion
//! (`F_n0 = 0` there) the initial mode is decided by comparing `|T|` with `L` a
//! little way (10⁻⁶ of the overlap scale) along the undisturbed path: both grow as
//! the same power of the overlap, so their ratio decides.
//!
//! Where a contact without adhesion vanishes (first touch and separation of
//! Hertz) every limit L tends to 0 and the turning rate `|P⊥ Ṫ|/L` of a slip
//! direction diverges: L is floored at `|Ṫ| t₀ / 10⁴` (t₀ the time unit of the
//! impact), so the direction relaxes toward `Ṫ` at most 10⁴ times per time unit,
//! in proportion to the angle; `mindlin_rescale`'s `ȧ/a` is capped alike. Both act
//! only within ~10⁻⁴ of the contact's ends, where every friction force is below
//! ~10⁻⁶ of its largest value. With them, initial spins in any direction are
//! integrated (out of the impact plane the slip directions leave it; about the
//! line of centres twisting acts).
//!
//! Chattering: stick/slip switches within 10⁻⁶ of the branch end freeze every
//! element's mode for the rest of the impact (every force there is ~10⁻⁹ of its
//! size); two switches of one element within 10⁻⁹ time units (a tangency of its
//! trial force with its limit that a stiff dashpot keeps up) freeze that element,
//! its stick force capped at the limit. The energy bookkeeping is exact either way
//! (the work of the forces that act).
//!
//! # Energy
//!
//! The work of every mechanism is integrated with the motion ([`EnergyLosses`]):
//! normal elastic-adhesive hysteresis, normal damping, sliding friction, tangential
//! damping, the tangential spring (the work stored in it and released when the
//! contact breaks, plus what `mindlin`'s radius-dependent stiffness creates or
//! destroys), rolling, twisting and the torque-arm convention. `energy_error` is
//! the mismatch between the change of kinetic energy and their sum.
//!
//! # Frame (that of the `impact --angle` outputs)
//!
//! The centre-of-mass frame; x along the line of centres at first touch of the
//! undisturbed paths, from the sphere to the target; z normal to the impact plane.
//! Before the impact the sphere's velocity relative to the target is
//! `v (cos α, sin α, 0)`.
//!
//! The motion is three-dimensional: between two spheres the line of centres
//! turns by about `v sin α t_c/(R_i + R_j)` during the contact, so the normal
//! restitution `−u'_x/u_x` at angle α is the central one at `v cos α` only on a
//! flat, or as α → 0. Without adhesion the difference is invisible (below 10⁻⁹);
//! with adhesion (a long contact ending in tension) it is of order sin²α: two
//! 1 µm silica spheres (JKR, 0.3 m/s, frictionless) differ by 1.1e-5 at 5° and
//! 8e-4 at 40°; LAMMPS's runs contain the same geometry
//! (`crates/tabor-scene/tests/oblique.rs`).

use crate::model::Friction;
use crate::model::{TangentialModel, Twisting};
use nalgebra::Vector3;
use serde::Serialize;
use std::cell::Cell;
use tabor_dynamics::{BranchChange, ForceLaw, SimulationSettings};
use tabor_numerics::ode::{drive, DormandPrince, EventDirection};
use tabor_numerics::Cost;
use tabor_restitution::{validate, Error, Result};

/// A rigid body of the impact: a sphere, or a flat (infinite radius, mass and
/// moment of inertia).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Body {
    /// Radius (m); infinite for a flat.
    pub radius: f64,
    /// Mass (kg); infinite for a flat.
    pub mass: f64,
    /// Moment of inertia about the centre (kg m²); infinite for a flat.
    pub moment_of_inertia: f64,
}

impl Body {
    /// A homogeneous solid sphere: m = (4/3)πρR³, I = (2/5) m R².
    pub fn solid_sphere(radius: f64, density: f64) -> Result<Self> {
        let r = validate::positive("radius", radius)?;
        let rho = validate::positive("density", density)?;
        let mass = validate::positive("mass", 4.0 / 3.0 * std::f64::consts::PI * rho * r * r * r)?;
        Ok(Body {
            radius: r,
            mass,
            moment_of_inertia: 0.4 * mass * r * r,
        })
    }

    /// A sphere of given mass (kg) and moment of inertia (kg m²).
    pub fn sphere(radius: f64, mass: f64, moment_of_inertia: f64) -> Result<Self> {
        Ok(Body {
            radius: validate::positive("radius", radius)?,
            mass: validate::positive("mass", mass)?,
            moment_of_inertia: validate::positive("moment_of_inertia", moment_of_inertia)?,
        })
    }

    /// A fixed flat (a half-space that does not move).
    pub fn flat() -> Self {
        Body {
            radius: f64::INFINITY,
            mass: f64::INFINITY,
            moment_of_inertia: f64::INFINITY,
        }
    }

    /// True for a flat.
    pub fn is_flat(&self) -> bool {
        self.radius.is_infinite()
    }
}

/// What the normal contact adds to its force law for the friction models.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct NormalContact {
    /// The pull-off force magnitude (N) of a cohesive law (0 for Hertz); see
    /// [`crate::critical_force`].
    pub pull_off_force: f64,
    /// The coefficient `c` (Pa s) of the viscous normal force `F_d = c a δ̇`
    /// (Kuwabara-Kono, seed 000 eq. (5.66): `c = 2 η_c`; LAMMPS `damping
    /// viscoelastic`: `c = η_n0 m_eff`); 0 without damping. The normal damping
    /// coefficient of the friction models is `c a`.
    pub damping: f64,
}

impl NormalContact {
    /// No adhesion, no damping (Hertz).
    pub const ELASTIC: NormalContact = NormalContact {
        pull_off_force: 0.0,
        damping: 0.0,
    };
}

/// The oblique impact: two bodies, the normal contact's extras, the friction (none:
/// frictionless) and the initial spins.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ObliqueImpact {
    /// The moving sphere (body i of LAMMPS's pair).
    pub sphere: Body,
    /// The target: a sphere or a flat (body j).
    pub target: Body,
    /// Pull-off force and damping of the normal contact.
    pub normal: NormalContact,
    /// Friction, rolling and twisting (`None`: frictionless).
    pub friction: Option<Friction>,
    /// Initial angular velocity of the sphere (rad/s, in the frame of the module
    /// docs).
    pub sphere_spin: [f64; 3],
    /// Initial angular velocity of the target (rad/s; ignored for a flat).
    pub target_spin: [f64; 3],
}

/// Velocity and angular velocity of one body after the impact.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct BodyMotion {
    /// Velocity (m/s) in the centre-of-mass frame.
    pub velocity: [f64; 3],
    /// Angular velocity (rad/s).
    pub angular_velocity: [f64; 3],
}

/// The state of both bodies after the impact (or when they stick).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct AfterImpact {
    /// The sphere.
    pub sphere: BodyMotion,
    /// The target (zero for a flat).
    pub target: BodyMotion,
}

/// The kinetic energy lost to each mechanism (J), integrated with the motion.
/// Their sum is the kinetic energy lost, to `energy_error`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Serialize)]
pub struct EnergyLosses {
    /// Work against the elastic-adhesive normal force `∫ F_n δ̇ dt`: 0 for an
    /// elastic law, the adhesive hysteresis for JKR and Maugis-Dugdale.
    pub normal_adhesion: f64,
    /// Work against the viscous normal force.
    pub normal_damping: f64,
    /// Work of the tangential force on the slip (Coulomb friction).
    pub sliding_friction: f64,
    /// Work against the tangential dashpot `∫ γ_t |v_t|² dt`.
    pub tangential_damping: f64,
    /// The rest of the tangential work: elastic energy left in the tangential
    /// spring when the contact breaks, plus the energy `mindlin`'s
    /// radius-dependent stiffness destroys (or, negative, creates).
    pub tangential_spring: f64,
    /// Work of the rolling resistance (dissipated and left in its spring).
    pub rolling: f64,
    /// Work of the twisting resistance (dissipated and left in its spring).
    pub twisting: f64,
    /// The work of LAMMPS's torque-arm convention: torques use `R − δ/2`, the
    /// sliding velocity uses R; their mismatch (small, of order δ/R, either sign).
    pub torque_arm: f64,
}

impl EnergyLosses {
    /// The sum of all mechanisms (J).
    pub fn total(&self) -> f64 {
        self.normal_adhesion
            + self.normal_damping
            + self.sliding_friction
            + self.tangential_damping
            + self.tangential_spring
            + self.rolling
            + self.twisting
            + self.torque_arm
    }
}

/// The result of one oblique impact.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ObliqueOutcome {
    /// The normal force law's name.
    pub law: String,
    /// Impact speed |v| (m/s).
    pub speed: f64,
    /// Impact angle α (degrees) between the relative velocity and the line of
    /// centres.
    pub angle: f64,
    /// Normal restitution `−u'_x / u_x` of the relative velocity (frame axes).
    pub normal_restitution: f64,
    /// Tangential restitution of the contact point, `−c'_y / c_y` with
    /// `c = u_t − (R_i ω_i + R_j ω_j) × n` (n the normal at first touch); `None`
    /// when the contact point does not slide before the impact (α = 0, no spin).
    pub tangential_restitution: Option<f64>,
    /// Rebound angle (degrees) between the relative velocity after the impact and
    /// the line of centres; `None` when the bodies stick.
    pub rebound_angle: Option<f64>,
    /// True when the bodies stay together (the normal law's decision).
    pub sticks: bool,
    /// Velocities and spins after the impact (at the moment of sticking when they
    /// stick).
    pub after: AfterImpact,
    /// Kinetic energy before (translation in the CoM frame and rotation) (J).
    pub kinetic_energy: f64,
    /// Kinetic energy lost (J).
    pub energy_loss: f64,
    /// The loss by mechanism.
    pub losses: EnergyLosses,
    /// |ΔE_kin + Σ losses| / E_kin: the integration's energy error.
    pub energy_error: f64,
    /// Time from contact onset to the end (s).
    pub contact_time: f64,
    /// Stick ↔ slip switches of the tangential force.
    pub slip_switches: usize,
    /// Right-hand-side evaluations and steps.
    pub cost: Cost,
}

// ---------------------------------------------------------------------------
// state layout

const E: usize = 0; // deviation from the undisturbed path (3)
const U: usize = 3; // relative velocity v_i − v_j (3)
const WI: usize = 6; // ω_i (3)
const WJ: usize = 9; // ω_j (3)
const XT: usize = 12; // tangential displacement (3)
const XR: usize = 15; // rolling displacement (3)
const XW: usize = 18; // twist angle (1)
const EN: usize = 19; // energies (8): normal, damping, sliding, t-damping, t-total, rolling, twisting, arm
const N: usize = 27;

#[derive(Clone, Copy, Debug, PartialEq)]
enum Mode {
    Stick,
    /// Slipping, with the direction of the limit force (twisting: the sign in x).
    Slip,
}

#[derive(Clone, Copy, Debug)]
struct Modes {
    in_contact: bool,
    /// Stick/slip switching of the tangential, rolling and twisting element
    /// ended (chattering, see `ObliqueImpact::simulate`): a frozen element keeps
    /// its mode, its stick force capped at the limit.
    frozen: [bool; 3],
    /// The first 10⁻⁶ of the overlap scale of a contact that starts without a
    /// Coulomb limit: no friction force yet, the springs follow the motion.
    warmup: bool,
    loading: bool,
    tangential: Mode,
    rolling: Mode,
    twisting: Mode,
    twist_sign: f64,
}

/// Everything fixed during one impact.
struct Setup<'a> {
    imp: &'a ObliqueImpact,
    flat: bool,
    r_sum: f64,
    r_eff: f64,
    m_eff: f64,
    m_i: f64,
    m_j: f64,
    inv_i_i: f64,
    inv_i_j: f64,
    u0: Vector3<f64>,
    d_touch: Vector3<f64>,
    v: f64,
    v_n: f64,
    /// SI value of one normalized unit of each state component.
    scale: [f64; N],
    time: f64,
    length: f64,
    force: f64,
}

/// Physical quantities at one state.
struct Eval {
    dy: [f64; N],
    /// event values (positive while the mode holds)
    slip_rate_t: f64,
    slip_rate_r: f64,
    slip_rate_w: f64,
}

fn v3(y: &[f64; N], i: usize) -> Vector3<f64> {
    Vector3::new(y[i], y[i + 1], y[i + 2])
}

fn put(dy: &mut [f64; N], i: usize, v: &Vector3<f64>) {
    dy[i] = v[0];
    dy[i + 1] = v[1];
    dy[i + 2] = v[2];
}

/// `(f(x), f'(x))` by central differences with step `h` (one-sided forward when
/// the law errs below).
fn derivative(f: &dyn Fn(f64) -> Result<f64>, x: f64, h: f64) -> Result<(f64, f64)> {
    let fx = f(x)?;
    let up = f(x + h)?;
    match f(x - h) {
        Ok(down) => Ok((fx, (up - down) / (2.0 * h))),
        Err(_) => Ok((fx, (up - fx) / h)),
    }
}

impl<'a> Setup<'a> {
    fn to_si(&self, y: &[f64; N]) -> [f64; N] {
        let mut out = *y;
        for (o, s) in out.iter_mut().zip(self.scale.iter()) {
            *o *= s;
        }
        out
    }

    fn to_normalized(&self, y: &[f64; N]) -> [f64; N] {
        let mut out = *y;
        for (o, s) in out.iter_mut().zip(self.scale.iter()) {
            *o /= s;
        }
        out
    }

    /// Normal, overlap, overlap rate, ṅ at SI time `t` and SI state `y`.
    fn geometry(&self, t: f64, y: &[f64; N]) -> (Vector3<f64>, f64, f64, Vector3<f64>) {
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
        let n = d / r;
        let rate = -n.dot(&u);
        let n_dot = (u - n * n.dot(&u)) / r;
        (n, overlap, rate, n_dot)
    }

    /// The step of the central differences of the law's force and contact radius
    /// at `overlap`: 10⁻⁵ of the distance to the branch end (where the law is
    /// singular: Hertz's `a ∝ δ^½` at first touch, JKR's vertical tangent at
    /// pull-off), at most 10⁻⁵ of the overlap scale, at least 10⁻¹² of it.
    /// Relative truncation error ~10⁻¹⁰, rounding ~10⁻¹¹: a fixed step of the
    /// overlap scale is as large as the overlap itself just after first touch,
    /// where the slip conditions are decided.
    fn difference_step(&self, law: &dyn ForceLaw, overlap: f64, rate: f64) -> Result<f64> {
        let end = law.branch_end(overlap, rate)?;
        Ok(DIFFERENCE_STEP * end.clamp(1e-7 * self.length, self.length))
    }

    fn kinetic(&self, y: &[f64; N]) -> f64 {
        let u = v3(y, U);
        let wi = v3(y, WI);
        let mut k = 0.5 * self.m_eff * u.norm_squared()
            + 0.5 * self.imp.sphere.moment_of_inertia * wi.norm_squared();
        if !self.flat {
            k += 0.5 * self.imp.target.moment_of_inertia * v3(y, WJ).norm_squared();
        }
        k
    }

    /// The rates of the SI state at SI time `t` in `modes`.
    fn evaluate(&self, law: &dyn ForceLaw, t: f64, y: &[f64; N], modes: &Modes) -> Result<Eval> {
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
        let f_el = law.force(overlap, rate)?;
        let mut out = Eval {
            dy,
            slip_rate_t: f64::INFINITY,
            slip_rate_r: f64::INFINITY,
            slip_rate_w: f64::INFINITY,
        };
        if !modes.in_contact {
            // free flight (or the Maugis-Dugdale approach before jump-in)
            put(&mut out.dy, U, &(n * (f_el / self.m_eff)));
            out.dy[EN] = f_el * rate;
            return Ok(out);
        }
        let h = self.difference_step(law, overlap, rate)?;
        let a_of = |d: f64| law.contact_radius(d, rate);
        let (a, a_prime) = derivative(&a_of, overlap, h)?;
        let a = a.max(0.0);
        let c = self.imp.normal.damping;
        let f_d = c * a * rate;
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
            let gamma = t.damping_ratio * c * a;
            let limit = t.coefficient * fc;
            let xi = v3(y, XT);
            f_t = match modes.tangential {
                Mode::Stick => cap(-(xi * k + v_tr * gamma), limit, modes.frozen[0]),
                Mode::Slip => -direction(&xi, &v_tr) * limit,
            };
            tang = Some((k, gamma, limit, xi));
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
                let (k_tw, g_tw, l_tw) = twist_coefficients(tw, fr, a, c, fc);
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
        let f_of = |d: f64| law.force(d, rate);
        let (_, f_prime) = derivative(&f_of, overlap, h)?;
        let a_dot = a_prime * rate;
        let fc_dot = {
            let raw = if cohesive { f_el + 2.0 * pull_off } else { f_n };
            let mut d = f_prime * rate;
            if !cohesive {
                d += c * (a_dot * rate + a * accel_normal);
            }
            if raw < 0.0 {
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
            let k_dot = match t.model {
                TangentialModel::LinearHistory => 0.0,
                _ => t.stiffness * a_dot,
            };
            let gamma_dot = t.damping_ratio * c * a_dot;
            let limit_dot = t.coefficient * fc_dot;
            let rescale = t.model == TangentialModel::MindlinRescale && !modes.loading;
            // ξ ∝ a while it shrinks: the rate ȧ/a diverges where the contact
            // vanishes (Hertz: a ∝ δ^½ at separation), and so do ξ's derivatives;
            // capped as the turning of a slip direction ([`turn_rate`]). The cap
            // acts only within ~10⁻⁴ of the end, where the stick force is
            // bounded by a limit ~10⁻⁶ of its largest value.
            let rescale_rate = if rescale && a > 0.0 {
                (a_dot / a).max(-RATE_CAP / self.time)
            } else {
                0.0
            };
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
                    let d = (turn - n * uhat.dot(&n_dot)) * xi.norm();
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
                    out.dy[EN + 2] = if k > 0.0 {
                        g.max(0.0) * on_surface / k
                    } else {
                        0.0
                    };
                    out.dy[EN + 3] = gamma * v_tr.norm_squared();
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
            let (k_tw, g_tw, l_tw) = twist_coefficients(tw, fr, a, c, fc);
            match modes.twisting {
                Mode::Stick => out.dy[XW] = w_tw,
                Mode::Slip => {
                    let (k_dot, g_dot, l_dot) = match tw {
                        Twisting::Marshall => {
                            let t = &fr.tangential;
                            (
                                t.stiffness * a * a_dot,
                                t.damping_ratio * c * 1.5 * a * a * a_dot,
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

/// The rate `P⊥(drive)/L` at which a slipping element's force direction `uhat`
/// turns toward the direction of `drive` (1/s), in the tangent plane (normal
/// `n`: the limit surface lies in it, so the part of `drive` along `n`, from
/// the turning of the plane, is dropped; the turning of `uhat` with the plane is
/// added by the caller). Where the limit L vanishes (first
/// touch and separation of a law without adhesion) the rate diverges and the
/// direction follows `drive` at once; there L is replaced by its floor
/// `|drive| time / 10⁴`, so the angle between `uhat` and `drive` relaxes at a rate
/// of at most 10⁴ per time unit `time` (s) of the impact, in proportion to the
/// angle (a capped *magnitude* would make the turning bang-bang about the
/// direction of `drive`, which no step size resolves).
fn turn_rate(
    drive: &Vector3<f64>,
    uhat: &Vector3<f64>,
    n: &Vector3<f64>,
    limit: f64,
    time: f64,
) -> Vector3<f64> {
    let drive = drive - n * n.dot(drive);
    let perp = drive - uhat * uhat.dot(&drive);
    let limit = limit.max(drive.norm() * time / RATE_CAP);
    if limit > 0.0 {
        perp / limit
    } else {
        Vector3::zeros()
    }
}

/// The stick force `f` of a frozen element, capped at the limit.
fn cap(f: Vector3<f64>, limit: f64, frozen: bool) -> Vector3<f64> {
    let size = f.norm();
    if frozen && size > limit {
        f * (limit / size)
    } else {
        f
    }
}

/// `a/b`, 0 when b is 0.
fn ratio(a: f64, b: f64) -> f64 {
    if b != 0.0 {
        a / b
    } else {
        0.0
    }
}

/// The unit vector of `x`, or of `fallback` when `x` is zero (or neither: zero).
fn direction(x: &Vector3<f64>, fallback: &Vector3<f64>) -> Vector3<f64> {
    let n = x.norm();
    if n > 0.0 {
        x / n
    } else {
        let m = fallback.norm();
        if m > 0.0 {
            fallback / m
        } else {
            Vector3::zeros()
        }
    }
}

/// Stiffness, damping and limit of the twisting resistance at contact radius `a`.
fn twist_coefficients(tw: &Twisting, fr: &Friction, a: f64, c: f64, fc: f64) -> (f64, f64, f64) {
    match *tw {
        Twisting::Marshall => {
            let t = &fr.tangential;
            (
                0.5 * t.stiffness * a * a,
                0.5 * t.damping_ratio * c * a * a * a,
                2.0 / 3.0 * t.coefficient * a * fc,
            )
        }
        Twisting::Sds {
            stiffness,
            damping,
            coefficient,
        } => (stiffness, damping, coefficient * fc),
    }
}

fn model_error(message: String) -> Error {
    Error::Model {
        model: "oblique impact",
        message,
    }
}

fn keep_first(slot: &Cell<Option<Error>>, e: Error) {
    let old = slot.take();
    slot.set(Some(old.unwrap_or(e)));
}

/// Which event ended a segment.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Event {
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

/// The largest rate (per time unit of the impact) of the relaxations that diverge
/// where a contact without adhesion vanishes: the turning of a slip direction
/// ([`turn_rate`]) and `mindlin_rescale`'s shrinking of ξ.
const RATE_CAP: f64 = 1e4;

/// The step of the central differences of the normal law, relative to the
/// distance to its branch end ([`Setup::difference_step`]).
const DIFFERENCE_STEP: f64 = 1e-5;

/// The overlap (in units of the overlap scale) up to which a contact that starts
/// without a Coulomb limit runs without friction ([`ObliqueImpact::simulate`]).
const WARMUP: f64 = 1e-6;

impl ObliqueImpact {
    /// Simulates the impact at relative speed `speed` (m/s) and angle `angle`
    /// (degrees, 0 ≤ α < 90) through the normal law `law` (left in its final
    /// state), to the accuracy of `settings` (tolerances in normalized units: the
    /// law's overlap scale, the impact speed, the normal force scale).
    pub fn simulate(
        &self,
        law: &mut dyn ForceLaw,
        speed: f64,
        angle: f64,
        settings: &SimulationSettings,
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
            return this.simulate(law, speed, angle, settings);
        }
        validate::non_negative("pull_off_force", self.normal.pull_off_force)?;
        validate::non_negative("damping", self.normal.damping)?;
        let spin_i = Vector3::from(self.sphere_spin);
        let flat = self.target.is_flat();
        let spin_j = if flat {
            Vector3::zeros()
        } else {
            Vector3::from(self.target_spin)
        };
        for s in spin_i.iter().chain(spin_j.iter()) {
            validate::finite("spin", *s)?;
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
        let force = m_eff * v_n * v_n / length;
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
                Event::BranchEnd => match law.on_branch_end(overlap, rate)? {
                    BranchChange::Continue => {
                        if !modes.in_contact && law.in_contact() {
                            modes.in_contact = true;
                            onset = Some(t);
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
                    other => break other,
                },
                Event::Turn => {
                    let decision = if modes.loading {
                        law.on_max_compression(overlap)?
                    } else {
                        law.on_min_compression(overlap)?
                    };
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
    /// Contact quantities at SI state `y`: (a, γ_t, k_t-spring, limit, F_n0, v_tr,
    /// v_rl, ω_tw) for the mode switches.
    #[allow(clippy::type_complexity)]
    fn contact(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &[f64; N],
    ) -> Result<(f64, f64, Vector3<f64>, Vector3<f64>, f64, Vector3<f64>)> {
        let (n, overlap, rate, _) = self.geometry(t, y);
        let u = v3(y, U);
        let wi = v3(y, WI);
        let wj = if self.flat {
            Vector3::zeros()
        } else {
            v3(y, WJ)
        };
        let a = law.contact_radius(overlap, rate)?.max(0.0);
        let f_el = law.force(overlap, rate)?;
        let c = self.imp.normal.damping;
        let fc = crate::critical_force(f_el, f_el + c * a * rate, self.imp.normal.pull_off_force);
        let r_j = if self.flat {
            0.0
        } else {
            self.imp.target.radius
        };
        let v_tr = u - n * n.dot(&u) - (wi * self.imp.sphere.radius + wj * r_j).cross(&n);
        let v_rl = (wi - wj).cross(&n) * self.r_eff;
        Ok((a, fc, v_tr, v_rl, (wi - wj).dot(&n), n))
    }

    /// (trial force T, limit L, damping γ, spring k, velocity) of the vector
    /// element stored at `slot` (XT or XR).
    #[allow(clippy::type_complexity)]
    fn element(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &[f64; N],
        slot: usize,
    ) -> Result<(Vector3<f64>, f64, f64, f64, Vector3<f64>)> {
        let Some(fr) = &self.imp.friction else {
            return Ok((Vector3::zeros(), 0.0, 0.0, 0.0, Vector3::zeros()));
        };
        let (a, fc, v_tr, v_rl, _, _) = self.contact(law, t, y)?;
        let x = v3(y, slot);
        if slot == XT {
            let tg = &fr.tangential;
            let k = tg.spring(a);
            let gamma = tg.damping_ratio * self.imp.normal.damping * a;
            Ok((x * k + v_tr * gamma, tg.coefficient * fc, gamma, k, v_tr))
        } else {
            let Some(r) = &fr.rolling else {
                return Ok((Vector3::zeros(), 0.0, 0.0, 0.0, Vector3::zeros()));
            };
            Ok((
                x * r.stiffness + v_rl * r.damping,
                r.coefficient * fc,
                r.damping,
                r.stiffness,
                v_rl,
            ))
        }
    }

    /// Stick → slip of a vector element: its state now carries the direction of
    /// the trial force (keeping the length of the displacement).
    fn enter_slip(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        _modes: &Modes,
        slot: usize,
    ) -> Result<()> {
        let (trial, _, _, _, vel) = self.element(law, t, y, slot)?;
        let x = v3(y, slot);
        let len = x.norm().max(1e-6 * self.length);
        put_state(y, slot, &(direction(&trial, &vel) * len));
        Ok(())
    }

    /// Slip → stick: the displacement becomes the elastic part of the limit force.
    fn leave_slip(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        _modes: &Modes,
        slot: usize,
    ) -> Result<()> {
        let (_, limit, gamma, k, vel) = self.element(law, t, y, slot)?;
        let x = v3(y, slot);
        let uhat = direction(&x, &vel);
        if k > 0.0 {
            put_state(y, slot, &((uhat * limit - vel * gamma) / k));
        }
        Ok(())
    }

    /// The trial twisting torque `k θ + γ ω_tw` (N m).
    fn twist_trial(&self, law: &dyn ForceLaw, t: f64, y: &[f64; N]) -> Result<f64> {
        let Some(fr) = &self.imp.friction else {
            return Ok(0.0);
        };
        let Some(tw) = &fr.twisting else {
            return Ok(0.0);
        };
        let (a, fc, _, _, w_tw, _) = self.contact(law, t, y)?;
        let (k, g, _) = twist_coefficients(tw, fr, a, self.imp.normal.damping, fc);
        Ok(k * y[XW] + g * w_tw)
    }

    fn leave_twist_slip(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        modes: &Modes,
    ) -> Result<()> {
        let Some(fr) = &self.imp.friction else {
            return Ok(());
        };
        let Some(tw) = &fr.twisting else {
            return Ok(());
        };
        let (a, fc, _, _, w_tw, _) = self.contact(law, t, y)?;
        let (k, g, l) = twist_coefficients(tw, fr, a, self.imp.normal.damping, fc);
        if k > 0.0 {
            y[XW] = (l * modes.twist_sign - g * w_tw) / k;
        }
        Ok(())
    }

    /// At contact onset: a law with a Coulomb limit at first touch (adhesion)
    /// starts in stick; one without (Hertz: every limit and spring starts from 0)
    /// runs the first [`WARMUP`] of the overlap scale without friction forces, the
    /// springs following the motion, and decides there ([`Setup::decide_modes`]).
    fn decide_initial_modes(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        modes: &mut Modes,
    ) -> Result<()> {
        if self.imp.friction.is_none() {
            return Ok(());
        }
        let (_, overlap, ..) = self.geometry(t, y);
        let (_, fc0, ..) = self.contact(law, t, y)?;
        if fc0 > 0.0 || overlap / self.length >= WARMUP {
            return self.decide_modes(law, t, y, modes);
        }
        modes.warmup = true;
        Ok(())
    }

    /// Each element whose trial force exceeds its limit is put on the limit (its
    /// displacement reset to the elastic part of the limit force, as LAMMPS) and
    /// slips if the trial force keeps outgrowing the limit there, else sticks.
    fn decide_modes(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &mut [f64; N],
        modes: &mut Modes,
    ) -> Result<()> {
        let Some(fr) = &self.imp.friction else {
            return Ok(());
        };
        for slot in [XT, XR] {
            if slot == XR && fr.rolling.is_none() {
                continue;
            }
            let (trial, limit, ..) = self.element(law, t, y, slot)?;
            if trial.norm() <= limit {
                continue;
            }
            let mut slip = *modes;
            if slot == XT {
                slip.tangential = Mode::Slip;
            } else {
                slip.rolling = Mode::Slip;
            }
            let mut on_limit = *y;
            self.enter_slip(law, t, &mut on_limit, modes, slot)?;
            let ev = self.evaluate(law, t, &on_limit, &slip)?;
            let rate = if slot == XT {
                ev.slip_rate_t
            } else {
                ev.slip_rate_r
            };
            if rate > 0.0 {
                *y = on_limit;
                *modes = slip;
            } else {
                self.leave_slip(law, t, y, modes, slot)?;
            }
        }
        if fr.twisting.is_some() {
            let m = self.twist_trial(law, t, y)?;
            let (a, fc, ..) = self.contact(law, t, y)?;
            let (_, _, l) = twist_coefficients(
                fr.twisting.as_ref().unwrap_or(&Twisting::Marshall),
                fr,
                a,
                self.imp.normal.damping,
                fc,
            );
            if m.abs() > l {
                let mut slip = *modes;
                slip.twisting = Mode::Slip;
                slip.twist_sign = if m >= 0.0 { 1.0 } else { -1.0 };
                if self.evaluate(law, t, y, &slip)?.slip_rate_w > 0.0 {
                    *modes = slip;
                } else {
                    self.leave_twist_slip(law, t, y, &slip)?;
                }
            }
        }
        Ok(())
    }

    /// The event values at SI (t, y): all positive while the modes hold.
    fn event_values(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &[f64; N],
        modes: &Modes,
    ) -> Result<[f64; 9]> {
        let (_, overlap, rate, _) = self.geometry(t, y);
        let mut g = [f64::INFINITY; 9];
        g[0] = law.branch_end(overlap, rate)? / self.length;
        if modes.in_contact {
            g[1] = if modes.loading { rate } else { -rate } / self.v_n;
        }
        if modes.warmup {
            g[8] = WARMUP - overlap / self.length;
            return Ok(g);
        }
        if !modes.in_contact || self.imp.friction.is_none() || modes.frozen == [true; 3] {
            return Ok(g);
        }
        let fr = self
            .imp
            .friction
            .as_ref()
            .map(|f| (f.rolling.is_some(), f.twisting.is_some()));
        let (rolling, twisting) = fr.unwrap_or((false, false));
        let rate_unit = self.force / self.time;
        let need_rates = modes.tangential == Mode::Slip
            || modes.rolling == Mode::Slip
            || modes.twisting == Mode::Slip;
        let ev = if need_rates {
            Some(self.evaluate(law, t, y, modes)?)
        } else {
            None
        };
        match modes.tangential {
            _ if modes.frozen[0] => {}
            Mode::Stick => {
                let (trial, limit, ..) = self.element(law, t, y, XT)?;
                g[2] = (limit - trial.norm()) / self.force;
            }
            Mode::Slip => g[3] = ev.as_ref().map_or(f64::INFINITY, |e| e.slip_rate_t) / rate_unit,
        }
        if rolling && !modes.frozen[1] {
            match modes.rolling {
                Mode::Stick => {
                    let (trial, limit, ..) = self.element(law, t, y, XR)?;
                    g[4] = (limit - trial.norm()) / self.force;
                }
                Mode::Slip => {
                    g[5] = ev.as_ref().map_or(f64::INFINITY, |e| e.slip_rate_r) / rate_unit
                }
            }
        }
        if twisting && !modes.frozen[2] {
            let torque_unit = self.force * self.length;
            match modes.twisting {
                Mode::Stick => {
                    let m = self.twist_trial(law, t, y)?;
                    let (a, fc, ..) = self.contact(law, t, y)?;
                    let fr = self
                        .imp
                        .friction
                        .as_ref()
                        .ok_or_else(|| model_error("no friction".into()))?;
                    let (_, _, l) = twist_coefficients(
                        fr.twisting.as_ref().unwrap_or(&Twisting::Marshall),
                        fr,
                        a,
                        self.imp.normal.damping,
                        fc,
                    );
                    g[6] = (l - m.abs()) / torque_unit;
                }
                Mode::Slip => {
                    g[7] = ev.as_ref().map_or(f64::INFINITY, |e| e.slip_rate_w)
                        / (torque_unit / self.time)
                }
            }
        }
        Ok(g)
    }

    /// Integrates from SI (t, y) to the first event.
    fn segment(
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
        let mut rhs = |s: f64, yn: &[f64; N]| -> [f64; N] {
            let ysi = self.to_si(yn);
            match self.evaluate(law, s * self.time, &ysi, modes) {
                Ok(ev) => {
                    let mut out = self.to_normalized(&ev.dy);
                    for o in out.iter_mut() {
                        *o *= self.time;
                    }
                    out
                }
                Err(e) => {
                    keep_first(&failure, e);
                    [f64::NAN; N]
                }
            }
        };
        let g_failure: Cell<Option<Error>> = Cell::new(None);
        let mut g = |s: f64, yn: &[f64; N]| -> f64 {
            match self.event_values(law, s * self.time, &self.to_si(yn), modes) {
                Ok(v) => v
                    .iter()
                    .zip(offset.iter())
                    .map(|(g, o)| g + o)
                    .fold(f64::INFINITY, f64::min),
                Err(e) => {
                    keep_first(&g_failure, e);
                    f64::NAN
                }
            }
        };
        let s_end = s0 + settings.max_duration;
        let numerics = |e| failure.take().unwrap_or(Error::Numerics(e));
        let mut stepper =
            DormandPrince::new(&mut rhs, s0, yn, s_end, settings.tolerance).map_err(numerics)?;
        let run = drive(
            &mut stepper,
            &mut rhs,
            &mut g,
            EventDirection::Falling,
            s_end,
            &mut |_: &DormandPrince<N>, _: f64| {},
        )
        .map_err(numerics)?;
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

    #[allow(clippy::too_many_arguments)]
    fn outcome(
        &self,
        law: &dyn ForceLaw,
        t: f64,
        y: &[f64; N],
        onset: f64,
        decision: BranchChange,
        kinetic0: f64,
        angle: f64,
        cost: Cost,
        slip_switches: usize,
    ) -> Result<ObliqueOutcome> {
        let u = v3(y, U);
        let wi = v3(y, WI);
        let wj = if self.flat {
            Vector3::zeros()
        } else {
            v3(y, WJ)
        };
        let sticks = decision == BranchChange::Stick;
        let kinetic = self.kinetic(y);
        let mut losses = EnergyLosses {
            normal_adhesion: y[EN],
            normal_damping: y[EN + 1],
            sliding_friction: y[EN + 2],
            tangential_damping: y[EN + 3],
            tangential_spring: y[EN + 4] - y[EN + 2] - y[EN + 3],
            rolling: y[EN + 5],
            twisting: y[EN + 6],
            torque_arm: y[EN + 7],
        };
        if self.imp.friction.is_none() {
            losses.tangential_spring = 0.0;
        }
        let energy_loss = kinetic0 - kinetic;
        let energy_error = (energy_loss - losses.total()).abs() / kinetic0;
        let (fi, fj) = if self.m_j.is_infinite() {
            (1.0, 0.0)
        } else {
            (
                self.m_j / (self.m_i + self.m_j),
                self.m_i / (self.m_i + self.m_j),
            )
        };
        let n0 = -Vector3::x();
        let r_j = if self.flat {
            0.0
        } else {
            self.imp.target.radius
        };
        let contact_point = |u: &Vector3<f64>, wi: &Vector3<f64>, wj: &Vector3<f64>| {
            let ut = u - n0 * n0.dot(u);
            (ut - (wi * self.imp.sphere.radius + wj * r_j).cross(&n0))[1]
        };
        let wi0 = Vector3::from(self.imp.sphere_spin);
        let wj0 = if self.flat {
            Vector3::zeros()
        } else {
            Vector3::from(self.imp.target_spin)
        };
        let c0 = contact_point(&self.u0, &wi0, &wj0);
        let c1 = contact_point(&u, &wi, &wj);
        let _ = law;
        Ok(ObliqueOutcome {
            law: law.name(),
            speed: self.v,
            angle,
            normal_restitution: -u[0] / self.u0[0],
            tangential_restitution: (c0 != 0.0).then(|| -c1 / c0),
            rebound_angle: (!sticks).then(|| u[1].atan2(-u[0]).to_degrees()),
            sticks,
            after: AfterImpact {
                sphere: BodyMotion {
                    velocity: (u * fi).into(),
                    angular_velocity: wi.into(),
                },
                target: BodyMotion {
                    velocity: (-u * fj).into(),
                    angular_velocity: wj.into(),
                },
            },
            kinetic_energy: kinetic0,
            energy_loss,
            losses,
            energy_error,
            contact_time: t - onset,
            slip_switches,
            cost,
        })
    }
}

fn put_state(y: &mut [f64; N], i: usize, v: &Vector3<f64>) {
    put(y, i, v);
}
