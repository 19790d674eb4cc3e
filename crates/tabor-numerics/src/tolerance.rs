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
    }
}
