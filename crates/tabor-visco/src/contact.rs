//! The viscoelastic contact of two bodies by the correspondence principle (seed 000
//! section 5.4: the Laplace-transformed elastic solution with the moduli replaced by
//! the media's operators, (5.54), (5.64), (5.75)).
//!
//! # Convention
//!
//! A [`Body`] has the contact modulus `M = E/(1 − ν²)` and optionally a shear
//! viscosity η (Pa s). A body with a viscosity is a Kelvin-Voigt solid whose
//! viscous part is an incompressible shear: its contact-modulus operator is
//! `M + 4η s` (E/(1 − ν²) = 4G at ν = 1/2, so a shear dashpot η adds 4η s), and
//! its relaxation time is `τ = 4η/M`. The contact compliance is the sum of the
//! two bodies' compliances (Hertz, (5.8), transformed):
//!
//! ```text
//! 1/E*(s) = 1/(M_a + 4η_a s) + 1/(M_b + 4η_b s).
//! ```
//!
//! Every model of this crate is written for a rigid indenter on an incompressible
//! half-space with shear modulus operator G(s) = E*(s)/4; so a contact is
//! classified by E*(s)/4 ([`ViscoelasticContact`]):
//!
//! - **no viscosity**: elastic, G = M_a M_b/(M_a + M_b)/4;
//! - **one viscous body a on an elastic body b**: with G_x = M_x/4,
//!   `G*(s) = G_b (G_a + η_a s)/(G_a + G_b + η_a s)`: a spring in series with a
//!   Kelvin-Voigt element. This is exactly the standard medium (5.75)
//!   `G∞ + G1 τs/(1 + τs)` with
//!   `G∞ = G_a G_b/(G_a + G_b)` (s = 0), `G∞ + G1 = G_b` (s → ∞, so
//!   `G1 = G_b²/(G_a + G_b)`), the pole `τ = η_a/(G_a + G_b)` (= the body's
//!   4η_a/M_a times M_a/(M_a + M_b)), hence the branch viscosity
//!   `η = G1 τ = G_b² η_a/(G_a + G_b)²`, and `β = G∞/G1 = G_a/G_b`;
//! - **two viscous bodies with equal relaxation times** τ: `E*(s) = M*(1 + τs)`,
//!   M* = M_a M_b/(M_a + M_b), exactly a Kelvin-Voigt medium with `G* = M*/4` and
//!   `η* = G* τ` ((5.64)); "equal" means a relative difference below
//!   [`EQUAL_RELAXATION_TOLERANCE`];
//! - **two viscous bodies with different relaxation times**: two Kelvin-Voigt
//!   elements in series, a four-parameter medium (two relaxation times) that no
//!   model of tabor solves: an [`Error::Model`] that says so.
//!
//! The relaxed modulus of every class is the elastic E*/4 of the two bodies, so
//! an elastic model built from E* stays consistent with it.
//!
//! # The standard-medium sphere over the whole parameter range
//!
//! Two bodies of very different stiffness give extreme β = G_a/G_b: viscous steel
//! on rubber β ≈ 2e4 (the branch is negligible: ε ≈ 1), viscous rubber on steel
//! β ≈ 6e-5 (the steel spring is nearly rigid: the Kelvin-Voigt sphere of the
//! rubber), and a relaxation time of a stiff body (~1e-9 s) far below the contact
//! time (~1e-3 s). [`StandardMediumSphere`] covers all of it
//! ([`standard_medium_loss`], regimes [`StandardRegime`]), with
//! `τ̂ = β (64/15)^{2/5} δ` the relaxation time in units of d0/v0 ((5.74), (5.90)):
//!
//! - τ̂ < [`MIN_SCALED_RELAXATION_TIME`] (the MDR solver's stiffness limit): the
//!   Kelvin-Voigt limit, the rigorous sphere with G∞ and η = G1τ: as τ → 0 at fixed
//!   G∞, η the operator `G∞ + ηs/(1 + τs)` tends to `G∞ + ηs`. Measured (tests)
//!   `|ε − ε_KV| ≤ 0.195 τ̂` (δ ≈ 0.3; `≈ 2.8 δ τ̂` for small δ) and
//!   `≤ 0.83 τ̂ (1 − ε_KV)`, linear in τ̂ to 3 digits: the switch costs at most
//!   2e-6 in ε ([`KELVIN_VOIGT_LIMIT_ERROR`]);
//! - β > [`MAX_MODULUS_RATIO`]: the weak branch to first order in 1/β,
//!   `1 − ε² = λ(τ̂)/β` ([`weak_branch_loss_coefficient`], derivation in the private
//!   `weak_branch` module): measured `β²(1 − ε²)_MDR − βλ(τ̂) → −μ(τ̂)` with
//!   0 < μ ≤ 1.04 (τ̂ = 1) for β = 1e2-1e4, so the error is ≤
//!   [`WEAK_BRANCH_ERROR`]`/β²` ≤ 2e-8 in 1 − ε;
//! - otherwise the MDR continuum solution (as [`crate::standard_sphere::solve`],
//!   also below its β = 1e-5: τ̂ ≥ 1e-5 with δ ≤ 1e9 means β ≥ 5.6e-15; measured
//!   down to β = 1e-13, 1.5e4-8e4 evaluations, ≤ 0.1 s).
//!
//! A stiff partner does **not** always give the Kelvin-Voigt sphere: the limit
//! needs τ small against the contact time on the spring G1 ≈ G_b,
//! `T_1 ≈ 2.94 β^{2/5}` (scaled). A body so viscous that τ̂ ≳ 0.1 T_1 acts rigid
//! during the impact, which is then an elastic bounce on the partner (β = 1e-5,
//! δ = 1e3: ε = 0.49, where the Kelvin-Voigt sphere gives 3.3e-6). The MDR
//! solution covers this; with δ ≤ 1e3 and τ̂ < 1e-5 the ratio τ̂/T_1 is below
//! 7e-3, with δ ≤ 1e6 below 0.105, where the Kelvin-Voigt limit holds (tests:
//! at τ̂/T_1 = 0.1 the MDR solution is the Kelvin-Voigt ε to 1e-8 relative; at
//! τ̂/T_1 = 1 it is 0.645 at every δ from 1e3 to 1e9). With τ̂ < 1e-5 and
//! δ > 1e6 neither holds and the loss is an error. For a fixed viscous body and
//! a partner stiffening without bound, τ̂/T_1 ∝ G_b^{-3/5} → 0: the contact
//! tends to the Kelvin-Voigt sphere of the viscous body, at the rate O(β).
//!
//! In both approximations the loss `1 − ε²` is computed accurate relative to
//! itself (from the dissipated energy, not as 1 − ε² of an ε near 1), so a tiny
//! loss (1e-12 of the kinetic energy) is a number, not rounding noise.

mod weak_branch;

use crate::kelvin_voigt_sphere::{self, SphereModel};
use crate::mdr::{self, ScaledMedium};
use crate::models::KelvinVoigtSphere;
use crate::scaled::ScaledImpact;
use crate::standard_sphere;
use serde::Serialize;
use tabor_numerics::special::beta as beta_function;
use tabor_numerics::Cost;
use tabor_restitution::{validate, EnergyLoss, Error, ImpactModel, Result};

/// Two relaxation times 4η/M are equal (a Kelvin-Voigt contact) when their
/// relative difference `|τ_a − τ_b|/max(τ_a, τ_b)` is below this.
pub const EQUAL_RELAXATION_TOLERANCE: f64 = 1e-12;
/// Below this scaled relaxation time τ̂ the standard medium is replaced by its
/// Kelvin-Voigt limit (the MDR solver's own lower limit,
/// [`crate::standard_sphere::MIN_RELAXATION_TIME`]).
pub const MIN_SCALED_RELAXATION_TIME: f64 = standard_sphere::MIN_RELAXATION_TIME;
/// Above this β = G∞/G1 the weak-branch first order is used (the upper end of the
/// MDR solver's range).
pub const MAX_MODULUS_RATIO: f64 = 1e4;
/// Bound on `β² |Δ(1 − ε²)|` of the weak-branch first order (measured maximum
/// over τ̂ ∈ [1e-5, 1e3] about 1.1, tests).
pub const WEAK_BRANCH_ERROR: f64 = 2.0;
/// Bound on `|Δε|/τ̂` of the Kelvin-Voigt limit at τ̂ < [`MIN_SCALED_RELAXATION_TIME`]
/// (measured maximum 0.195 at δ ≈ 0.3, tests).
pub const KELVIN_VOIGT_LIMIT_ERROR: f64 = 0.2;

/// Largest δ of the Kelvin-Voigt limit (τ̂ < [`MIN_SCALED_RELAXATION_TIME`]): there
/// `τ̂/T_1 = 0.61 β^{3/5} δ ≤ 4.2e-4 δ^{2/5} ≤ 0.105` (module docs), where the MDR
/// solution and the rigorous Kelvin-Voigt sphere agree far inside
/// [`KELVIN_VOIGT_LIMIT_ERROR`] (tests; they part at τ̂/T_1 ≈ 1, ε = 0.645 against
/// 3e-11 at δ = 1e6). Above, with τ̂ below the MDR solver's stiffness limit, no
/// solution is offered.
pub const KELVIN_VOIGT_LIMIT_MAX_VISCOUS_PARAMETER: f64 = 1e6;
/// Below this δ the Kelvin-Voigt limit is the first order (5.71) (remainder ~3δ
/// relative; the integration, accurate down to δ = 1e-100, underflows near 1e-300).
const FIRST_ORDER_VISCOUS_PARAMETER: f64 = 1e-30;
/// Relative tolerance of the integrations (1e-9).
const TOLERANCE: f64 = tabor_numerics::tolerance::COSTLY_TOLERANCE;
const MODEL: &str = "viscoelastic contact";

/// One body of a contact: its contact modulus `M = E/(1 − ν²)` and, for a
/// Kelvin-Voigt body, its shear viscosity η, whose contact-modulus operator is
/// `M + 4η s` (module docs).
///
/// Seed 000, eqs. (5.8) (E* from both bodies), (5.54), (5.64) (Kelvin-Voigt, E* = 4G).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Body {
    contact_modulus: f64,
    viscosity: Option<f64>,
}

impl Body {
    /// From Young's modulus E (Pa), Poisson's ratio ν (−1 < ν ≤ 1/2) and an
    /// optional shear viscosity η > 0 (Pa s).
    ///
    /// Seed 000, eq. (5.8) (the body's share 1/M of 1/E*).
    pub fn new(youngs_modulus: f64, poisson_ratio: f64, viscosity: Option<f64>) -> Result<Self> {
        let e = validate::positive("youngs_modulus", youngs_modulus)?;
        let nu = validate::poisson_ratio("poisson_ratio", poisson_ratio)?;
        let m = validate::positive_output(MODEL, "contact modulus", e / (1.0 - nu * nu))?;
        Self::from_contact_modulus(m, viscosity)
    }

    /// From the contact modulus M = E/(1 − ν²) (Pa) and an optional shear
    /// viscosity η > 0 (Pa s).
    ///
    /// Seed 000, eq. (5.8).
    pub fn from_contact_modulus(contact_modulus: f64, viscosity: Option<f64>) -> Result<Self> {
        Ok(Body {
            contact_modulus: validate::positive("contact_modulus", contact_modulus)?,
            viscosity: viscosity
                .map(|eta| validate::positive("viscosity", eta))
                .transpose()?,
        })
    }

    /// The contact modulus M = E/(1 − ν²) (Pa).
    ///
    /// Seed 000, eq. (5.8).
    pub fn contact_modulus(&self) -> f64 {
        self.contact_modulus
    }

    /// The shear viscosity η (Pa s), if the body is viscous.
    ///
    /// Seed 000, eq. (5.64).
    pub fn viscosity(&self) -> Option<f64> {
        self.viscosity
    }

    /// The relaxation (retardation) time τ = 4η/M (s) of a viscous body.
    ///
    /// Seed 000, eq. (5.64) with E* = 4G (τ = η/G).
    pub fn relaxation_time(&self) -> Option<f64> {
        self.viscosity.map(|eta| 4.0 * eta / self.contact_modulus)
    }
}

/// What the contact of two bodies is, in the shear-modulus units (G = E*/4) of the
/// models of this crate (module docs for the derivation).
///
/// Seed 000, eqs. (5.54), (5.64) (Kelvin-Voigt), (5.75), (5.84) (standard medium).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum ViscoelasticContact {
    /// Neither body is viscous: G = E*/4, E* = M_a M_b/(M_a + M_b) (Pa).
    Elastic {
        /// G = E*/4 (Pa).
        shear_modulus: f64,
    },
    /// One Kelvin-Voigt body on an elastic one: a spring in series with a
    /// Kelvin-Voigt element, which is exactly the standard medium (5.75).
    StandardMedium {
        /// Relaxed modulus G∞ = G_a G_b/(G_a + G_b) (Pa).
        relaxed_modulus: f64,
        /// Maxwell-branch modulus G1 = G_b²/(G_a + G_b) (Pa).
        branch_modulus: f64,
        /// Maxwell-branch viscosity η = G_b² η_a/(G_a + G_b)² (Pa s).
        viscosity: f64,
    },
    /// Two Kelvin-Voigt bodies with the same relaxation time τ: a Kelvin-Voigt
    /// medium G* = E*/4, η* = G* τ (exact).
    KelvinVoigt {
        /// G* = E*/4 (Pa).
        shear_modulus: f64,
        /// η* = G* τ (Pa s).
        viscosity: f64,
    },
}

impl ViscoelasticContact {
    /// Classifies the contact of two bodies (symmetric in them); two viscous
    /// bodies with different relaxation times are an [`Error::Model`] (module docs).
    ///
    /// Seed 000, eqs. (5.8), (5.64), (5.75) by the correspondence principle.
    pub fn of(a: &Body, b: &Body) -> Result<Self> {
        let (ga, gb) = (0.25 * a.contact_modulus, 0.25 * b.contact_modulus);
        // Ordered, so that the result does not depend on the order of the bodies.
        let (lo, hi) = if ga <= gb { (ga, gb) } else { (gb, ga) };
        let series = lo * (hi / (lo + hi));
        match (a.viscosity, b.viscosity) {
            (None, None) => Ok(ViscoelasticContact::Elastic {
                shear_modulus: series,
            }),
            (Some(eta), None) => Ok(Self::standard(ga, gb, eta)),
            (None, Some(eta)) => Ok(Self::standard(gb, ga, eta)),
            (Some(_), Some(_)) => {
                let (ta, tb) = (
                    a.relaxation_time().unwrap_or(f64::NAN),
                    b.relaxation_time().unwrap_or(f64::NAN),
                );
                let difference = (ta - tb).abs() / ta.max(tb);
                if difference < EQUAL_RELAXATION_TOLERANCE {
                    let tau = 0.5 * (ta + tb);
                    Ok(ViscoelasticContact::KelvinVoigt {
                        shear_modulus: series,
                        viscosity: validate::positive_output(MODEL, "viscosity", series * tau)?,
                    })
                } else {
                    Err(Error::Model {
                        model: MODEL,
                        message: format!(
                            "both bodies are viscous with different relaxation times \
                             4η/M = {ta:e} s and {tb:e} s: two Kelvin-Voigt bodies in series \
                             are a four-parameter medium with two relaxation times, which no \
                             tabor model solves; give both bodies the same relaxation time \
                             4η/M (then the contact is Kelvin-Voigt), or drop the viscosity \
                             that is negligible (a relaxation time far below the contact time, \
                             or the far stiffer body)"
                        ),
                    })
                }
            }
        }
    }

    /// Viscous body (G_v, η) on elastic body (G_e): the standard medium.
    fn standard(gv: f64, ge: f64, eta: f64) -> Self {
        let share = ge / (gv + ge);
        ViscoelasticContact::StandardMedium {
            relaxed_modulus: gv * share,
            branch_modulus: ge * share,
            viscosity: eta * share * share,
        }
    }

    /// The relaxed (long-time, s → 0) shear modulus G = E*/4 (Pa), the same for
    /// every class: the elastic E* of the two bodies divided by 4.
    ///
    /// Seed 000, eqs. (5.8), (5.75) (G∞).
    pub fn relaxed_shear_modulus(&self) -> f64 {
        match *self {
            ViscoelasticContact::Elastic { shear_modulus }
            | ViscoelasticContact::KelvinVoigt { shear_modulus, .. } => shear_modulus,
            ViscoelasticContact::StandardMedium {
                relaxed_modulus, ..
            } => relaxed_modulus,
        }
    }

    /// The impact model of a sphere of effective radius R (m) and effective mass
    /// m (kg) on this contact: [`StandardMediumSphere`] for the standard medium,
    /// the rigorous [`KelvinVoigtSphere`] for Kelvin-Voigt, `None` when elastic
    /// (no viscous loss).
    ///
    /// Seed 000, eqs. (5.64)-(5.68) and (5.84)-(5.90).
    pub fn impact_model(
        &self,
        radius: f64,
        mass: f64,
    ) -> Result<Option<Box<dyn ImpactModel + Send + Sync>>> {
        self.impact_model_with_tolerance(radius, mass, TOLERANCE)
    }

    /// [`ViscoelasticContact::impact_model`] integrated at relative tolerance
    /// `tolerance` ([1e-15, 0.5]) instead of the default 1e-9.
    ///
    /// Seed 000, eqs. (5.64)-(5.68), (5.75), (5.84)-(5.90).
    pub fn impact_model_with_tolerance(
        &self,
        radius: f64,
        mass: f64,
        tolerance: f64,
    ) -> Result<Option<Box<dyn ImpactModel + Send + Sync>>> {
        validate::tolerance("tolerance", tolerance)?;
        Ok(match *self {
            ViscoelasticContact::Elastic { .. } => {
                validate::positive("radius", radius)?;
                validate::positive("mass", mass)?;
                None
            }
            ViscoelasticContact::StandardMedium {
                relaxed_modulus,
                branch_modulus,
                viscosity,
            } => Some(Box::new(
                StandardMediumSphere::new(
                    relaxed_modulus,
                    branch_modulus,
                    viscosity,
                    radius,
                    mass,
                )?
                .with_tolerance(tolerance)?,
            )),
            ViscoelasticContact::KelvinVoigt {
                shear_modulus,
                viscosity,
            } => Some(Box::new(
                KelvinVoigtSphere::new(
                    shear_modulus,
                    viscosity,
                    radius,
                    mass,
                    SphereModel::Rigorous,
                )?
                .with_tolerance(tolerance)?,
            )),
        })
    }
}

/// Which solution [`standard_medium_loss`] used.
///
/// Seed 000, eqs. (5.64)-(5.68), (5.84)-(5.90).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum StandardRegime {
    /// τ̂ or β tiny: the rigorous Kelvin-Voigt sphere with G∞ and η = G1τ.
    KelvinVoigtLimit,
    /// The MDR continuum solution [`crate::standard_sphere::solve`].
    Mdr,
    /// β large: the weak branch to first order, `1 − ε² = λ(τ̂)/β`.
    WeakBranch,
}

impl StandardRegime {
    /// A short description, with the equations.
    pub fn as_str(self) -> &'static str {
        match self {
            StandardRegime::KelvinVoigtLimit => {
                "standard-medium sphere, Kelvin-Voigt limit τ → 0 (5.64)-(5.68)"
            }
            StandardRegime::Mdr => "standard-medium sphere, MDR (5.84)-(5.90)",
            StandardRegime::WeakBranch => {
                "standard-medium sphere, weak branch to first order in G1/G∞ (5.84)-(5.89)"
            }
        }
    }
}

/// The loss of a sphere on a standard medium, from [`standard_medium_loss`].
///
/// Seed 000, eqs. (5.37), (5.84)-(5.90).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct StandardLoss {
    /// `1 − ε²`, the lost fraction of the kinetic energy, accurate relative to
    /// itself in the two limits (module docs).
    pub loss: f64,
    /// The coefficient of restitution ε = √(1 − loss).
    pub restitution: f64,
    /// A bound on the error of `loss` (absolute, in units of the kinetic energy):
    /// the approximation's bound plus the integration tolerance.
    pub error_bound: f64,
    /// Which solution was used.
    pub regime: StandardRegime,
    /// Right-hand-side evaluations.
    pub cost: Cost,
}

/// `λ(τ̂) = lim_{β→∞} β (1 − ε²)`, the first-order loss of a sphere on a standard
/// medium with a weak Maxwell branch (β = G∞/G1 → ∞ at a fixed scaled relaxation time
/// τ̂ = v0 τ/d0, d0 of (5.74) with G∞), relative tolerance `tolerance`. Limits:
/// `3 B(3/5, 3/2) τ̂` as τ̂ → 0 (Kelvin-Voigt, (5.71)) and `(8/5) B(7/5, 1/2)/τ̂` as
/// τ̂ → ∞. τ̂ must be finite and ≥ 1e-8 (below, the first limit holds to O(τ̂)).
///
/// Seed 000, eqs. (5.84)-(5.89) linearised in G1 (derivation in the module docs of
/// the private `weak_branch` module, README).
pub fn weak_branch_loss_coefficient(scaled_relaxation_time: f64, tolerance: f64) -> Result<f64> {
    let tau = validate::positive("scaled_relaxation_time", scaled_relaxation_time)?;
    if tau < 1e-8 {
        return Err(Error::invalid(
            "scaled_relaxation_time",
            tau,
            "must be >= 1e-8 (below, use the Kelvin-Voigt limit 3 B(3/5, 3/2) τ̂)",
        ));
    }
    let tol = validate::tolerance("tolerance", tolerance)?;
    Ok(weak_branch::loss_coefficient(tau, tol)?.0)
}

/// The loss of a sphere on a standard medium at β = G∞/G1 ∈ (0, ∞) and δ (5.90)
/// over the whole range (module docs: Kelvin-Voigt limit, MDR, weak branch),
/// relative integration tolerance `tolerance`. δ above 1e9 is an error (as for the
/// Kelvin-Voigt and MDR spheres), unless β is in the weak-branch range; so is δ
/// above [`KELVIN_VOIGT_LIMIT_MAX_VISCOUS_PARAMETER`] with τ̂ below
/// [`MIN_SCALED_RELAXATION_TIME`].
///
/// Seed 000, eqs. (5.64)-(5.68), (5.84)-(5.90).
pub fn standard_medium_loss(
    modulus_ratio: f64,
    viscous_parameter: f64,
    tolerance: f64,
) -> Result<StandardLoss> {
    let beta = validate::positive("modulus_ratio", modulus_ratio)?;
    let delta = validate::positive("viscous_parameter", viscous_parameter)?;
    let tol = validate::tolerance("tolerance", tolerance)?;
    let tau = beta * (64.0_f64 / 15.0).powf(0.4) * delta;
    if !tau.is_finite() {
        return Err(Error::invalid(
            "viscous_parameter",
            delta,
            "times modulus_ratio overflows",
        ));
    }
    if tau < MIN_SCALED_RELAXATION_TIME {
        if delta > KELVIN_VOIGT_LIMIT_MAX_VISCOUS_PARAMETER {
            return Err(Error::invalid(
                "viscous_parameter",
                delta,
                "must be <= 1e6 where the scaled relaxation time modulus_ratio (64/15)^(2/5) δ \
                 is below 1e-5: beyond, the viscous body is rigid for a fraction of the \
                 partner's contact time (no Kelvin-Voigt limit) and the MDR solution is too stiff",
            ));
        }
        if delta < FIRST_ORDER_VISCOUS_PARAMETER {
            // (5.71): 1 − ε = sδ (1 + O(δ)), exact here to far below the tolerance
            // (the integration underflows for δ ~ 1e-300).
            let slope = 6.4 * beta_function(0.6, 1.5)? * (15.0_f64 / 64.0).powf(0.6);
            let loss = slope * delta * (2.0 - slope * delta);
            return Ok(StandardLoss {
                loss,
                restitution: 1.0 - slope * delta,
                error_bound: 2.0 * KELVIN_VOIGT_LIMIT_ERROR * tau + tol * loss,
                regime: StandardRegime::KelvinVoigtLimit,
                cost: Cost::ZERO,
            });
        }
        let outcome =
            kelvin_voigt_sphere::solve_with_loss(delta, SphereModel::Rigorous, tol, None)?;
        let e = outcome.impact.restitution;
        let bound = KELVIN_VOIGT_LIMIT_ERROR * tau;
        return Ok(StandardLoss {
            loss: outcome.loss * (1.0 + e),
            restitution: e,
            error_bound: 2.0 * (bound + tol * outcome.loss.max(e)),
            regime: StandardRegime::KelvinVoigtLimit,
            cost: outcome.impact.cost,
        });
    }
    if beta > MAX_MODULUS_RATIO {
        let (lambda, cost) = weak_branch::loss_coefficient(tau, tol)?;
        let loss = (lambda / beta).min(1.0);
        return Ok(StandardLoss {
            loss,
            restitution: (1.0 - loss).sqrt(),
            error_bound: WEAK_BRANCH_ERROR / (beta * beta) + tol * loss,
            regime: StandardRegime::WeakBranch,
            cost,
        });
    }
    if delta > standard_sphere::MAX_VISCOUS_PARAMETER {
        return Err(Error::invalid(
            "viscous_parameter",
            delta,
            "must be finite and lie in (0, 1e9]",
        ));
    }
    // The MDR solution below β = 1e-5 too (the public `standard_sphere` accepts
    // β ≥ 1e-5): here τ̂ ≥ 1e-5 and δ ≤ 1e9 give β ≥ 5.6e-15, tested against the
    // discrete MDR down to β = 1e-13 (δ = 1e8) in `src/mdr/tests.rs`.
    let s: ScaledImpact = mdr::solve(
        &ScaledMedium {
            beta,
            tau,
            tau0: 0.0,
        },
        tol,
    )?;
    let e = s.restitution;
    Ok(StandardLoss {
        loss: (1.0 - e) * (1.0 + e),
        restitution: e,
        error_bound: 4.0 * tol,
        regime: StandardRegime::Mdr,
        cost: s.cost,
    })
}

/// A rigid sphere (effective radius R, mass m) on a standard medium (G∞, G1, η)
/// solved over the whole parameter range ([`standard_medium_loss`]): what a
/// Kelvin-Voigt body on an elastic one gives ([`ViscoelasticContact`]).
///
/// Seed 000, eqs. (5.75), (5.84)-(5.90).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct StandardMediumSphere {
    relaxed_modulus: f64,
    branch_modulus: f64,
    viscosity: f64,
    radius: f64,
    mass: f64,
    tolerance: f64,
}

impl StandardMediumSphere {
    /// From the relaxed modulus G∞, the branch modulus G1 (Pa), the branch
    /// viscosity η (Pa s), the radius R (m) and the mass m (kg).
    ///
    /// Seed 000, eqs. (5.75), (5.84).
    pub fn new(
        relaxed_modulus: f64,
        branch_modulus: f64,
        viscosity: f64,
        radius: f64,
        mass: f64,
    ) -> Result<Self> {
        Ok(StandardMediumSphere {
            relaxed_modulus: validate::positive("relaxed_modulus", relaxed_modulus)?,
            branch_modulus: validate::positive("branch_modulus", branch_modulus)?,
            viscosity: validate::positive("viscosity", viscosity)?,
            radius: validate::positive("radius", radius)?,
            mass: validate::positive("mass", mass)?,
            tolerance: TOLERANCE,
        })
    }

    /// The same sphere solved at relative tolerance `tolerance` (default 1e-9;
    /// [`standard_medium_loss`] accepts [1e-15, 0.5]).
    pub fn with_tolerance(self, tolerance: f64) -> Result<Self> {
        Ok(StandardMediumSphere {
            tolerance: validate::tolerance("tolerance", tolerance)?,
            ..self
        })
    }

    /// (β, δ) at the impact speed v0 (m/s).
    ///
    /// Seed 000, eq. (5.90).
    pub fn parameters(&self, impact_speed: f64) -> Result<(f64, f64)> {
        standard_sphere::parameters(
            self.relaxed_modulus,
            self.branch_modulus,
            self.viscosity,
            self.radius,
            impact_speed,
            self.mass,
        )
    }

    /// The scaled loss at the impact speed v0 (m/s).
    ///
    /// Seed 000, eqs. (5.84)-(5.90).
    pub fn loss(&self, impact_speed: f64) -> Result<StandardLoss> {
        let (b, d) = self.parameters(impact_speed)?;
        standard_medium_loss(b, d, self.tolerance)
    }
}

impl ImpactModel for StandardMediumSphere {
    fn name(&self) -> String {
        "standard-medium sphere (two bodies)".into()
    }
    fn effective_mass(&self) -> f64 {
        self.mass
    }
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let l = self.loss(impact_speed)?;
        let kinetic = 0.5 * self.mass * impact_speed * impact_speed;
        Ok(EnergyLoss {
            joules: validate::non_negative("energy_loss", l.loss * kinetic)?,
            error_estimate: l.error_bound * kinetic,
            branch: l.regime.as_str().to_string(),
            cost: l.cost,
        })
    }
}
