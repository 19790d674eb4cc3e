//! The default tolerances of tabor: one constant, [`DEFAULT_TOLERANCE`], and the
//! default of each kind of computation as a fixed multiple of it. Every default
//! in the workspace (the library's `Default` impls and constants, the command
//! line's `--tolerance`, a scene's `accuracy`, the Python keywords) is one of
//! these; change `DEFAULT_TOLERANCE` and every default moves with it, change one
//! line below and that kind of computation moves alone.
//!
//! | constant | value | the default of |
//! |---|---|---|
//! | [`DEFAULT_TOLERANCE`] | 1e-12 | quadratures and root searches of the closed-form and quadrature models (JKR, Maugis-Dugdale, plastic), [`QuadTolerance::default`](crate::QuadTolerance), `tabor jkr`/`maugis-loss --tolerance` |
//! | [`ODE_TOLERANCE`] | 1e-11 | time-domain simulation, per step: [`OdeTolerance::default`](crate::ode::OdeTolerance), hence `tabor_dynamics::SimulationSettings::default` (absolute [`ODE_ABSOLUTE_TOLERANCE`], 1e-13) |
//! | [`ACCURACY`] | 1e-10 | a scene's requested `accuracy`; the scaled viscoelastic solvers and `tabor visco --tolerance`; sticking-velocity searches |
//! | [`COSTLY_TOLERANCE`] | 1e-9 | the viscoelastic models in SI units and contacts; `tabor trajectory --tolerance` |
//!
//! The floors: a requested accuracy finer than these is computed at these (a
//! scene's outcome then carries a warning with the code `accuracy-floor`).
//!
//! | constant | value | the floor of |
//! |---|---|---|
//! | [`MODEL_ACCURACY_FLOOR`] | 1e-12 | the viscoelastic and viscous-adhesive models a scene builds |
//! | [`SIMULATION_ACCURACY_FLOOR`] | 1e-13 | a simulated impact (per step: the accuracy / 100), a scene's oblique impact |
//! | [`STICKING_ACCURACY_FLOOR`] | 1e-14 | a scene's sticking-velocity search |
//! | [`FINEST_TOLERANCE`] | 1e-15 | one integration step |
//! | [`MICRO_SLIP_RESOLUTION`] | 1e-4 | the tangential restitution of Mindlin-Deresiewicz micro-slip (`tabor-tangential`'s spring bed) |
//!
//! The multiples are powers of ten applied to 1e-12, which gives each tier's
//! value exactly (`10.0 * 1e-12 == 1e-11` in `f64`, and so on).

/// The base of every default tolerance (relative): that of the quadratures and
/// root searches behind closed-form and quadrature models.
pub const DEFAULT_TOLERANCE: f64 = 1e-12;

/// The default relative per-step tolerance of ODE integration (time-domain
/// simulations): `OdeTolerance::default`.
pub const ODE_TOLERANCE: f64 = 10.0 * DEFAULT_TOLERANCE;

/// The default absolute per-step tolerance of ODE integration (normalized units).
pub const ODE_ABSOLUTE_TOLERANCE: f64 = DEFAULT_TOLERANCE / 10.0;

/// The default requested relative accuracy of a composite answer (a scene's
/// outcome, a viscoelastic restitution, a sticking velocity).
pub const ACCURACY: f64 = 100.0 * DEFAULT_TOLERANCE;

/// The default relative tolerance of the costliest integrations (viscoelastic
/// models in SI units, simulated trajectories).
pub const COSTLY_TOLERANCE: f64 = 1000.0 * DEFAULT_TOLERANCE;

/// The finest relative tolerance of one integration step: [`OdeTolerance`]'s
/// effective relative tolerance and the per-step tolerance of
/// `tabor_dynamics::SimulationSettings::with_tolerance` are never below it, nor
/// are the integrations of `tabor-visco` (Hertz with damping, MDR) and the
/// sticking search of `tabor jkr` (about 4.5 ε; a scene's `accuracy` may not be
/// below it either).
///
/// [`OdeTolerance`]: crate::ode::OdeTolerance
pub const FINEST_TOLERANCE: f64 = DEFAULT_TOLERANCE / 1000.0;

/// The finest accuracy a simulated impact resolves: its per-step tolerance is
/// the requested accuracy over 100 (`SimulationSettings::with_tolerance`), floored
/// at [`FINEST_TOLERANCE`], so a finer request integrates as this one. The floor of
/// a scene's oblique impact (`Scene::oblique`; it was 1e-9 before: the silica
/// oblique scene at 10, 40 and 80 degrees converges at 1e-12, within 4e-14 of a
/// 1e-13 run); also of the samples of the viscous-adhesive speed table and the
/// inner solves of the Kelvin-Voigt sphere's inversion. A scene asking for less is
/// told so by a warning.
pub const SIMULATION_ACCURACY_FLOOR: f64 = DEFAULT_TOLERANCE / 10.0;

/// The finest tolerance at which a scene builds its viscoelastic models (the
/// viscoelastic contact's impact model and the viscous-adhesive model of
/// `tabor-viscoadhesive`), and of the Kelvin-Voigt sphere's inversion for a
/// restitution. A scene asking for less is told so by a warning.
pub const MODEL_ACCURACY_FLOOR: f64 = DEFAULT_TOLERANCE;

/// The finest relative tolerance of a scene's sticking-velocity search (the root
/// of e(v) = 0 and the upper edge of the sticking set). A scene asking for less is
/// told so by a warning.
pub const STICKING_ACCURACY_FLOOR: f64 = DEFAULT_TOLERANCE / 100.0;

/// What Mindlin-Deresiewicz micro-slip resolves, relative to the tangential
/// restitution: `tabor-tangential`'s spring bed (the return map along each step's
/// path; exact in x² for a planar history, 1024 nodes in x² otherwise) reproduces
/// Maw, Barber & Fawcett's steel impact to 2.3e-6 from its path at an integration
/// tolerance of 1e-9 (9e-7 at 1e-10, since the steps where springs freeze or enter
/// stuck follow the step's continuous solution; 3e-5 before), plus ~6e-6 from the
/// node spacing where the history is not planar (9e-5 from 256 to 1024 nodes, 6e-6
/// from 1024 to 4096; `tabor-tangential/tests/micro_slip.rs` and the crate
/// README). The floor keeps a factor of ten above the sum: the node bed's error
/// is measured on MBF's impact only, and is larger in a young contact that spans
/// few nodes. A scene asking for less is told so by a warning.
pub const MICRO_SLIP_RESOLUTION: f64 = 1e-4;

#[cfg(test)]
mod tests {
    use super::*;

    /// The tiers are exactly the decimal values the documentation states (so a
    /// default taken from here computes bit for bit what the literal did).
    #[test]
    fn tiers_are_exact_powers_of_ten() {
        assert_eq!(DEFAULT_TOLERANCE, 1e-12);
        assert_eq!(ODE_TOLERANCE, 1e-11);
        assert_eq!(ODE_ABSOLUTE_TOLERANCE, 1e-13);
        assert_eq!(ACCURACY, 1e-10);
        assert_eq!(COSTLY_TOLERANCE, 1e-9);
        assert_eq!(MODEL_ACCURACY_FLOOR, 1e-12);
        assert_eq!(SIMULATION_ACCURACY_FLOOR, 1e-13);
        assert_eq!(STICKING_ACCURACY_FLOOR, 1e-14);
        assert_eq!(FINEST_TOLERANCE, 1e-15);
    }
}
