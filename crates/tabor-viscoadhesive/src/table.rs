//! A speed table of the coupled model: its loss over a range of impact speeds,
//! interpolated from simulations and certified against them, for sweeps.
//!
//! The coupled model answers by a time-domain simulation per speed (README eq.
//! (V1)), 0.1-1 ms each; a sweep of thousands of speeds repeats it. For one model
//! (E*, R, m, Δγ, adhesion and η_c fixed, so the damping number is fixed) the loss
//! over the kinetic energy, `y(v) = ΔU/(m v²/2) = 1 − ε²`, is a smooth function of
//! the impact speed wherever the bodies rebound (ε² has a simple zero at the
//! sticking velocity and no other feature), so piecewise Chebyshev interpolation in
//! `ln v` resolves it with a few dozen simulations:
//!
//! - the table starts where ε ≥ [`MIN_RESTITUTION`] (below, and at speeds where the
//!   bodies stick, the model simulates as before): there an error δy of the loss
//!   fraction is an error `δy/(2ε) ≤ 5 δy` of ε;
//! - its samples are simulations at a hundredth of the model's tolerance, and each
//!   piece is refined until its Chebyshev coefficient tail is below
//!   `0.05 · MIN_RESTITUTION · tolerance`, so the interpolation error of ε stays
//!   below a tenth of the tolerance the simulation promises;
//! - **certified against simulation**: after the fit, the table is compared with a
//!   simulation at the model's own tolerance at the middle of every piece and at the
//!   ends of the range; the build fails (the model keeps simulating) unless every
//!   check agrees within the simulation's own error estimate. `tests/table.rs`
//!   checks the table against simulation at speeds that were neither samples nor
//!   checks.
//!
//! The viscous loss of the Kuwabara-Kono sphere with the same E*, R, m and η_c (the
//! superposition comparison, [`crate::Superposition`]) is tabulated alongside to a
//! relative tail of [`VISCOUS_TAIL`]: that sphere's restitution is accurate to
//! about 1e-10 (`tabor_visco`'s accuracy), which leaves its small loss fraction
//! 2ε·δε (a few 1e-3 in the bundled scene) only about 1e-7 relative accuracy.

use std::sync::Arc;
use tabor_dynamics::{ImpactSimulation, SimulationSettings};
use tabor_numerics::chebyshev::PiecewiseChebyshev;
use tabor_numerics::tolerance::SIMULATION_ACCURACY_FLOOR;
use tabor_numerics::Cost;
use tabor_restitution::{validate, EnergyLoss, Error, ImpactModel, Result};
use tabor_visco::models::KelvinVoigtSphere;

/// What a [`SpeedTable`] needs of the model it tabulates (implemented by
/// [`crate::ViscoadhesiveImpact`]; a trait so that this module does not import the
/// model's, which holds the table).
pub trait Tabulated: ImpactModel {
    /// The small-strain limit (m/s) the table may not pass.
    fn small_strain_limit(&self) -> f64;
    /// The requested relative accuracy of the simulated outcome.
    fn tolerance(&self) -> f64;
    /// The simulation settings of the model's own answers (no trajectory).
    fn settings(&self) -> SimulationSettings;
    /// One simulated impact at `impact_speed` (m/s) with `settings`.
    fn simulate(
        &self,
        impact_speed: f64,
        settings: &SimulationSettings,
    ) -> Result<ImpactSimulation>;
    /// The Kuwabara-Kono sphere without adhesion with the same E*, R, m, η_c.
    fn kuwabara_kono(&self) -> Result<KelvinVoigtSphere>;
}

/// The table starts at the lowest speed of the range where the restitution is at
/// least this (so the error of ε is at most 5× that of the loss fraction there).
pub const MIN_RESTITUTION: f64 = 0.1;

/// Relative coefficient tail of the viscous (Kuwabara-Kono) loss table.
pub const VISCOUS_TAIL: f64 = 1e-7;

/// Chebyshev points per piece.
const POINTS: usize = 12;
/// Pieces at most (each takes [`POINTS`] simulations).
const MAX_PIECES: usize = 48;

/// The loss of a [`ViscoadhesiveImpact`](crate::ViscoadhesiveImpact) over
/// `[lower, upper]` (m/s), tabulated (module docs). Built by
/// [`ViscoadhesiveImpact::with_speed_table`](crate::ViscoadhesiveImpact::with_speed_table), which
/// answers from it inside its range.
#[derive(Clone, Debug, PartialEq)]
pub struct SpeedTable {
    lower: f64,
    upper: f64,
    loss_fraction: PiecewiseChebyshev,
    viscous_fraction: PiecewiseChebyshev,
    /// Bound on the error of the loss fraction y = 1 − ε² (absolute).
    error_bound: f64,
    /// The model tolerance of the samples.
    sample_tolerance: f64,
    /// Largest disagreement with the certifying simulations (in y).
    worst_check: f64,
    cost: Cost,
    law: String,
    /// Below the sticking velocity: `[lower, upper)` (m/s) where the bodies stick,
    /// and the depth of the adhesive well (J) that the model adds to m v²/2 there.
    sticking: Option<StickingRange>,
}

/// Speeds where the bodies stick, certified by simulation (module docs).
#[derive(Clone, Copy, Debug, PartialEq)]
struct StickingRange {
    lower: f64,
    upper: f64,
    well_depth: f64,
    energy_error: f64,
}

/// The sticking range ends this far (relative) below the sticking velocity: speeds
/// closer to it are simulated.
const STICKING_MARGIN: f64 = 1e-6;
/// Simulations that certify a sticking range (log-spaced, both ends included).
const STICKING_CHECKS: usize = 6;

impl SpeedTable {
    /// Tabulates `model` for impact speeds from the lowest speed ≥ `lower` (or ≥
    /// the sticking velocity `sticking_velocity`, when given and higher) with
    /// restitution ≥ [`MIN_RESTITUTION`] up to `upper` (m/s, 0 < lower < upper ≤
    /// the small-strain limit). With a sticking velocity above `lower`, the speeds
    /// from `lower` to just below it (`STICKING_MARGIN`) answer "sticks" with the
    /// model's loss m v²/2 + well depth, after simulations at `STICKING_CHECKS`
    /// speeds of that range all stuck. Fails when the range is invalid, when no
    /// speed near the start rebounds well enough, when a sample sticks or fails,
    /// when the pieces do not resolve the loss, or when a certifying simulation
    /// disagrees.
    pub fn build<M: Tabulated>(
        model: &M,
        lower: f64,
        upper: f64,
        sticking_velocity: Option<f64>,
    ) -> Result<SpeedTable> {
        let lower = validate::positive("lower", lower)?;
        let upper = validate::positive("upper", upper)?;
        if upper <= lower || upper > model.small_strain_limit() {
            return Err(Error::invalid(
                "upper",
                upper,
                "must exceed the lower speed and not the small-strain limit",
            ));
        }
        let tolerance = model.tolerance();
        let sample_tolerance = (tolerance * 1e-2).max(SIMULATION_ACCURACY_FLOOR);
        let mut settings = SimulationSettings::with_tolerance(sample_tolerance)?;
        settings.record_trajectory = false;
        let mut cost = Cost::ZERO;
        let mut worst_energy_error: f64 = 0.0;
        let mut law = String::new();
        let mut fraction = |v: f64| -> Result<f64> {
            let sim = model.simulate(v, &settings)?;
            cost += sim.cost;
            if sim.sticks {
                return Err(Error::Model {
                    model: "viscoadhesive speed table",
                    message: format!("the bodies stick at {v:e} m/s inside the table"),
                });
            }
            worst_energy_error = worst_energy_error.max(sim.energy_error);
            if law.is_empty() {
                law.clone_from(&sim.law);
            }
            Ok(sim.energy_loss / sim.kinetic_energy)
        };
        let sticking = match sticking_velocity {
            Some(vs) if vs * (1.0 - STICKING_MARGIN) > lower => {
                Some(sticking_range(model, lower, vs * (1.0 - STICKING_MARGIN))?)
            }
            _ => None,
        };
        let lower = match sticking_velocity {
            Some(vs) if vs > lower && vs < upper => vs,
            _ => lower,
        };
        // the lowest speed with ε ≥ MIN_RESTITUTION: steps of 0.1 %, 0.2 %, 0.4 %, …
        // up from `lower` (from the sticking velocity, a few steps)
        let mut start = lower;
        let mut step = 1e-3;
        loop {
            let y = match fraction(start) {
                Ok(y) => Some(y),
                Err(Error::Model { .. }) => None,
                Err(e) => return Err(e),
            };
            if y.is_some_and(|y| 1.0 - y >= MIN_RESTITUTION * MIN_RESTITUTION) {
                break;
            }
            start = lower * (1.0 + step);
            step *= 2.0;
            if start >= upper {
                return Err(Error::Model {
                    model: "viscoadhesive speed table",
                    message: format!(
                        "no speed in [{lower:e}, {upper:e}] m/s rebounds with restitution >= {MIN_RESTITUTION}"
                    ),
                });
            }
        }
        let tail = 0.05 * MIN_RESTITUTION * tolerance;
        let (a, b) = (start.ln(), upper.ln());
        let loss_fraction =
            PiecewiseChebyshev::fit(|x: f64| fraction(x.exp()), a, b, POINTS, tail, MAX_PIECES)?;
        let kuwabara_kono = model.kuwabara_kono()?;
        let mass = model.effective_mass();
        let viscous_fraction = PiecewiseChebyshev::fit(
            |x: f64| {
                let v = x.exp();
                kuwabara_kono
                    .energy_loss(v)
                    .map(|l| l.joules / (0.5 * mass * v * v))
            },
            a,
            b,
            POINTS,
            VISCOUS_TAIL,
            MAX_PIECES,
        )?;
        let sample_error = worst_energy_error + 2.0 * sample_tolerance;
        let mut table = SpeedTable {
            lower: start,
            upper,
            loss_fraction,
            viscous_fraction,
            error_bound: tail + sample_error,
            sample_tolerance,
            worst_check: 0.0,
            cost,
            law,
            sticking,
        };
        // certify against the model's own simulation: the middle of every piece and
        // both ends
        let breaks = table.loss_fraction.breaks().to_vec();
        let mut checks: Vec<f64> = breaks.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
        checks.extend([a, b]);
        for x in checks {
            let v = x.exp().clamp(start, upper);
            let sim = model.simulate(v, &model.settings())?;
            table.cost += sim.cost;
            let simulated = sim.energy_loss / sim.kinetic_energy;
            let allowed = sim.energy_error + 2.0 * sim.restitution * tolerance + table.error_bound;
            let difference = (table.loss_fraction.eval(x) - simulated).abs();
            if sim.sticks || difference > allowed {
                return Err(Error::Model {
                    model: "viscoadhesive speed table",
                    message: format!(
                        "the table disagrees with the simulation at {v:e} m/s by {difference:e} of the kinetic energy (allowed {allowed:e})"
                    ),
                });
            }
            table.worst_check = table.worst_check.max(difference);
        }
        Ok(table)
    }

    /// The speed range `[lower, upper]` (m/s) the table answers in.
    pub fn interval(&self) -> (f64, f64) {
        (self.lower, self.upper)
    }

    /// The bound on the error of the loss fraction `1 − ε²` (interpolation tail
    /// plus the samples' own error).
    pub fn error_bound(&self) -> f64 {
        self.error_bound
    }

    /// The largest disagreement with the certifying simulations, as a fraction of
    /// the kinetic energy.
    pub fn worst_check(&self) -> f64 {
        self.worst_check
    }

    /// Number of pieces of the loss table.
    pub fn pieces(&self) -> usize {
        self.loss_fraction.pieces().len()
    }

    /// What building the table cost (the simulations' force evaluations and steps).
    pub fn cost(&self) -> Cost {
        self.cost
    }

    /// The coupled loss at `v` (m/s) when `v` is inside the table, else `None`;
    /// `mass` is the model's effective mass. Error estimate: the table's bound
    /// plus `2 ε ·` the samples' tolerance, times m v²/2.
    pub fn energy_loss(&self, mass: f64, v: f64) -> Option<EnergyLoss> {
        let kinetic = 0.5 * mass * v * v;
        if let Some(s) = self.sticking.filter(|s| (s.lower..=s.upper).contains(&v)) {
            return Some(EnergyLoss {
                joules: kinetic + s.well_depth,
                error_estimate: s.energy_error * kinetic,
                branch: format!(
                    "speed table of the time-domain simulation of {}: sticks below the sticking velocity (certified against simulation)",
                    self.law
                ),
                cost: Cost::new(0, 1),
            });
        }
        if !(self.lower..=self.upper).contains(&v) {
            return None;
        }
        let y = self.loss_fraction.eval(v.ln()).clamp(0.0, 1.0);
        let restitution = (1.0 - y).sqrt();
        Some(EnergyLoss {
            joules: y * kinetic,
            error_estimate: (self.error_bound + 2.0 * restitution * self.sample_tolerance)
                * kinetic,
            branch: format!(
                "speed table of the time-domain simulation of {} ({} pieces, certified against simulation)",
                self.law,
                self.pieces()
            ),
            cost: Cost::new(0, 1),
        })
    }

    /// The Kuwabara-Kono viscous loss (J) at `v` (m/s) when `v` is inside the
    /// table, else `None`.
    pub fn viscous_loss(&self, mass: f64, v: f64) -> Option<f64> {
        (self.lower..=self.upper)
            .contains(&v)
            .then(|| self.viscous_fraction.eval(v.ln()) * 0.5 * mass * v * v)
    }
}

/// Certifies that the bodies stick at [`STICKING_CHECKS`] log-spaced speeds of
/// `[lower, upper]` and returns the range with the well depth the model reports
/// (its loss minus m v²/2, the same at every check).
fn sticking_range<M: Tabulated>(model: &M, lower: f64, upper: f64) -> Result<StickingRange> {
    let mut well_depth = None;
    let mut energy_error: f64 = 0.0;
    for i in 0..STICKING_CHECKS {
        let f = i as f64 / (STICKING_CHECKS - 1) as f64;
        let v = (lower * (upper / lower).powf(f)).clamp(lower, upper);
        let sim = model.simulate(v, &model.settings())?;
        let loss = model.energy_loss(v)?;
        let depth = loss.joules - sim.kinetic_energy;
        let same =
            well_depth.is_none_or(|w: f64| (depth - w).abs() <= 1e-12 * w.abs().max(loss.joules));
        if !sim.sticks || !same {
            return Err(Error::Model {
                model: "viscoadhesive speed table",
                message: format!(
                    "the bodies do not stick at {v:e} m/s below the sticking velocity {upper:e} m/s"
                ),
            });
        }
        well_depth.get_or_insert(depth);
        energy_error = energy_error.max(sim.energy_error);
    }
    Ok(StickingRange {
        lower,
        upper,
        well_depth: well_depth.unwrap_or(0.0),
        energy_error,
    })
}

/// A shared table (clones of a model share it).
pub(crate) type SharedTable = Option<Arc<SpeedTable>>;
