//! The oblique impact of two spheres (or a sphere and a flat): translation and
//! rotation through any normal [`ForceLaw`](tabor_dynamics::ForceLaw) (Hertz, JKR, Maugis-Dugdale), optional
//! Kuwabara-Kono damping, and the friction, rolling and twisting models of
//! [`Friction`](crate::Friction) in continuous time.
//!
//! # The models in continuous time
//!
//! [`Friction::step`](crate::Friction::step) is LAMMPS's time-stepped scheme. Here its limit dt → 0 is
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
//! [`tabor_numerics::ode`] (DOP853, as the central simulated impact; Dormand-Prince
//! 5(4) for `mindlin_deresiewicz`, whose spring bed is only piecewise smooth within
//! a step): stick → slip where `L − |T|`
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
//! After every event a slipping element whose slip rate is ≤ 0 sticks: the rate
//! can jump there, below 0, with no event value crossing 0 (a branch change, as
//! Maugis-Dugdale's junction, where the Coulomb limit grows at an unbounded
//! rate; another element's switch; a damped contact's normal force at 0).
//!
//! **Capture.** A damped contact whose law knows its potential relative to the
//! separation point ([`ForceLaw::separation_barrier`](tabor_dynamics::ForceLaw::separation_barrier))
//! sticks where the bodies can no longer separate: on a flat where
//! `½ m ḋ² + U(d) − U(d_sep)` falls below 0 (rigorous: the normal motion is
//! one-dimensional there), between two spheres where the kinetic energy beyond a
//! rigid rotation with the pair's angular momentum at the separation distance,
//! plus the energy stored in the friction springs, falls below `U(d_sep) − U(d)`
//! (it neglects energy that LAMMPS's conventions may create later: the torque
//! arms, a stiffness growing with the contact radius, a damped stick reset).
//! Once without it (formed so, or since) the contact sticks whatever it does and
//! ends when its normal motion has come to rest (normal kinetic energy below
//! 10⁻⁶ of its value before the impact), so that its ledger books what it lost. Without it an overdamped contact creeps into its equilibrium
//! without a turning point, in steps of the inertial time, until the step limit.
//! The pair's bound counts the rolling of the spheres over each other and a
//! creeping tangential spring as convertible, so there the capture waits until
//! the contact has crept deep enough into the well (η_n0 = 10¹⁹ with a soft
//! `linear_history` spring and its dashpot: ~60 000 steps; 10²¹ at 10°: still
//! the step limit).
//!
//! Chattering: stick/slip switches within 10⁻⁶ of the branch end freeze every
//! element's mode for the rest of the impact (every force there is ~10⁻⁹ of its
//! size); two switches of one element within 10⁻⁹ time units (a tangency of its
//! trial force with its limit that a stiff dashpot keeps up) freeze that element,
//! its stick force capped at the limit. The energy bookkeeping is exact either way
//! (the work of the forces that act).
//!
//! The normal law is evaluated on its branch curve where it has one
//! ([`tabor_dynamics::BranchCurve`], as the central simulated impact integrates
//! it: one solve for the JKR root or the Maugis-Dugdale angle per overlap, the
//! slopes of force and contact radius as differences along the curve), and the
//! last point is kept for the event values and mode switches at the same state.
//!
//! # Energy
//!
//! The work of every mechanism is integrated with the motion ([`EnergyLosses`]):
//! normal elastic-adhesive hysteresis, normal damping, sliding friction, tangential
//! damping, the tangential spring (the work stored in it and released when the
//! contact breaks, plus what `mindlin`'s radius-dependent stiffness creates or
//! destroys), rolling, twisting and the torque-arm convention. `energy_error` is
//! the mismatch between the change of kinetic energy and their sum. They are
//! quadratures on the motion's steps: where the normal law's slopes are exact
//! (JKR's branch curve) they stay outside DOP853's error control (its norm
//! covers the motion only), elsewhere (slopes by differences, whose rounding
//! grows toward a branch end; the spring bed; a slipping element with a
//! dashpot, whose powers kink where the dashpot alone reaches the limit) inside
//! it; every power is smooth
//! across the step that holds the event ending its segment (the sliding power
//! continues with the slip rate past its zero). In slip the
//! dashpot's force along the slip direction is capped at the limit: where the
//! dashpot alone reaches it (`γ û·v ≥ L`) spring and slider carry nothing along
//! `û` (else LAMMPS's history `(L û − γ v)/k` points against the force, and with
//! a Tsuji damping `∝ √a` beside `k ∝ a` it and the sliding work diverge at a
//! Hertz separation). Where such an element sticks again, the stick force must
//! continue at the limit: LAMMPS's history `(L û − γ v)/k` does that by
//! straining the spring against the slip, energy no work put in
//! (`|L û − γ v|²/2k`), which the spring gives back or loses at the next slip:
//! the tangential spring books it, negative (a damped contact's tensile end;
//! `tabor-scene`'s test `oblique_stick_reset`).
//!
//! # Frame (that of the `impact --angle` outputs)
//!
//! The centre-of-mass frame; x along the line of centres at first touch of the
//! undisturbed paths, from the sphere to the target; z normal to the impact plane.
//! Before the impact the sphere's velocity relative to the target is
//! `v (cos α, sin α, 0)`.
//!
//! A planar impact (relative velocity in the x-y plane, spins about z, no twist)
//! stays planar: its out-of-plane components are exactly 0, and the integration
//! carries only the 18 that move (module `planar`; of the energies only those that
//! can move in the segment), with their rates and the event values in two
//! dimensions (module `plane`); any other integrates all 27. In contact on a
//! branch curve without a fold (JKR load-controlled), undamped, with a single
//! tangential spring, a planar segment integrates in polar coordinates instead
//! (module `polar`): the branch coordinate itself (no solve for it at an
//! evaluation, as the central simulated impact), the overlap rate, the velocity
//! across the line of centres, the spins, the turn of the line of centres and
//! the displacements along the tangent, 8 motion components; a second
//! derivation of the same motion, checked against the Cartesian one.
//!
//! The motion is three-dimensional: between two spheres the line of centres
//! turns by about `v sin α t_c/(R_i + R_j)` during the contact, so the normal
//! restitution `−u'_x/u_x` at angle α is the central one at `v cos α` only on a
//! flat, or as α → 0. Without adhesion the difference is invisible (below 10⁻⁹);
//! with adhesion (a long contact ending in tension) it is of order sin²α: two
//! 1 µm silica spheres (JKR, 0.3 m/s, frictionless) differ by 1.1e-5 at 5° and
//! 8e-4 at 40°; LAMMPS's runs contain the same geometry
//! (`crates/tabor-scene/tests/oblique.rs`).

mod bed;
#[cfg(test)]
mod bed_tests;
mod bodies;
mod capture;
#[cfg(test)]
mod capture_tests;
mod elements;
mod energy;
mod limits;
mod line_bed;
mod modes;
mod node_bed;
mod normal;
mod outcome;
mod planar;
mod plane;
#[cfg(test)]
mod plane_tests;
mod polar;
#[cfg(test)]
mod polar_tests;
mod segment;
#[cfg(test)]
mod silica_tests;
mod simulate;
mod state;

pub use bed::MICRO_SLIP_NODES;
pub use bodies::{Body, NormalContact, ObliqueImpact};
pub use energy::EnergyLosses;
pub use outcome::{AfterImpact, BodyMotion, ObliqueOutcome};
