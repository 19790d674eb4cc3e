//! The FEM-based elasto-plastic sphere contact of Jackson and Green (the seed's
//! "analytische Approximation von FEM-Lösungen", ref. \[44\]), solved as an impact by
//! integrating the equation of motion (`tabor-dynamics`).

use crate::contact::PlasticContact;
use crate::util::{finite_output, positive_output};
use std::f64::consts::PI;
use tabor_dynamics::{
    BranchChange, ForceLaw, ImpactSimulation, SimulatedImpact, SimulationSettings,
};
use tabor_restitution::{validate, EnergyLoss, Error, ImpactModel, Result};

const MODEL: &str = "Jackson-Green";

/// The hardness over the yield stress used in the fully plastic term of the
/// Jackson-Green law, `H/σ_Y = 2.67` (the mean pressure `Q p_Y/3` of the
/// interpolation model with Q = 5, p_Y = 1.6 σ_Y), instead of Jackson and Green's
/// geometry-dependent `H_G` (this crate's choice; README, "Parameter choices").
///
/// Seed 000, text after (5.108) (Q = 5, chapter 3 (3.282)).
pub const DEFAULT_HARDNESS_RATIO: f64 = 2.67;

/// Jackson and Green's switch from Hertz to the FEM fit, `δ = d/d*_Y = 1.9`.
///
/// Seed 000, section 5.5.1 (ref. \[44\]).
pub const FIT_ONSET: f64 = 1.9;

/// The Jackson-Green contact of an elastic-plastic sphere on a half-space
/// (effective modulus `E*`, radius `R`, yield stress `σ_Y`, Poisson's ratio `ν` of
/// the yielding body): yield depth `d*_Y = (π C σ_Y/(2E*))² R`,
/// `C(ν) = 1.295 exp(0.736 ν)`; loading Hertz for `δ = d/d*_Y < 1.9`, else
/// `F/F*_Y = exp(−δ^(5/12)/4) δ^(3/2) + (4H/(Cσ_Y))[1 − exp(−δ^(5/9)/25)] δ`,
/// contact radius `a = √(R d)(δ/1.9)^B`, `B = 0.07 exp(23 σ_Y/E*)`; residual depth
/// `d_res = 1.02 d_max[1 − ((δ_max + 5.9)/6.9)^(−0.54)]` (Jackson, Chusoipin, Green
/// 2005); elastic (Hertzian) unloading through `(d_max, F_max)`.
///
/// Seed 000, eq. (5.108) and the text before it (the seed's FEM-based model, with the
/// relations of Jackson and Green written out above).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct JacksonGreen {
    modulus: f64,
    radius: f64,
    yield_stress: f64,
    poisson_ratio: f64,
    hardness_ratio: f64,
    critical_depth: f64,
    critical_force: f64,
    area_exponent: f64,
}

impl JacksonGreen {
    /// The Jackson-Green law for the contact `contact` (its effective modulus `E*`,
    /// effective radius `R` and yield stress `σ_Y`, already validated by
    /// [`PlasticContact::new`]) and Poisson's ratio `ν` (−1 < ν ≤ 1/2) of the yielding
    /// body, hardness ratio [`DEFAULT_HARDNESS_RATIO`]. Only `E*`, `R`, `σ_Y` of the
    /// contact are used: the yield onset is Jackson and Green's `C(ν)`, not Thornton's
    /// `p_Y = 1.6 σ_Y`.
    ///
    /// Seed 000, eq. (5.108) (`C(ν)`).
    pub fn new(contact: PlasticContact, poisson_ratio: f64) -> Result<Self> {
        let nu = validate::poisson_ratio("poisson_ratio", poisson_ratio)?;
        let e = contact.effective_modulus();
        let r = contact.effective_radius();
        let s = contact.yield_stress();
        let c = critical_pressure_factor(nu);
        let strain = PI * c * s / (2.0 * e);
        let critical_depth = positive_output(MODEL, "d*_Y", strain * strain * r)?;
        let critical_force = positive_output(
            MODEL,
            "F*_Y",
            4.0 / 3.0 * e * strain * strain * strain * r * r,
        )?;
        positive_output(MODEL, "F*_Y d*_Y", critical_force * critical_depth)?;
        Ok(JacksonGreen {
            modulus: e,
            radius: r,
            yield_stress: s,
            poisson_ratio: nu,
            hardness_ratio: DEFAULT_HARDNESS_RATIO,
            critical_depth,
            critical_force,
            area_exponent: 0.07 * (23.0 * s / e).exp(),
        })
    }

    /// The same contact with hardness ratio `H/σ_Y` (finite, > 0).
    ///
    /// Seed 000, section 5.5.1 (ref. \[44\]).
    pub fn with_hardness_ratio(mut self, hardness_ratio: f64) -> Result<Self> {
        let h = validate::positive("hardness_ratio", hardness_ratio)?;
        if h > 1e6 {
            return Err(Error::invalid("hardness_ratio", h, "must be <= 1e6"));
        }
        self.hardness_ratio = h;
        Ok(self)
    }

    /// The hardness ratio `H/σ_Y` in use.
    ///
    /// Seed 000, section 5.5.1 (ref. \[44\]).
    pub fn hardness_ratio(&self) -> f64 {
        self.hardness_ratio
    }

    /// Poisson's ratio ν of the yielding body.
    ///
    /// Seed 000, eq. (5.108).
    pub fn poisson_ratio(&self) -> f64 {
        self.poisson_ratio
    }

    /// The critical (yield) depth `d*_Y = (π C σ_Y/(2E*))² R` (m).
    ///
    /// Seed 000, eq. (5.108) (`C(ν)`), chapter 3.
    pub fn yield_depth(&self) -> f64 {
        self.critical_depth
    }

    /// The critical load `F*_Y = (4/3) E* √R d*_Y^(3/2)` (N).
    ///
    /// Seed 000, chapter-3 relation behind (5.108).
    pub fn yield_force(&self) -> f64 {
        self.critical_force
    }

    /// The yield velocity of the model for effective mass `m` (kg, > 0):
    /// `v*_Y = v_Y (5C(ν)/8)^(5/2)`, with `v_Y` of (5.103).
    ///
    /// Seed 000, eq. (5.108).
    pub fn yield_velocity(&self, effective_mass: f64) -> Result<f64> {
        let contact = PlasticContact::new(self.modulus, self.radius, self.yield_stress)?;
        let v_y = contact.yield_velocity(effective_mass)?;
        let c = critical_pressure_factor(self.poisson_ratio);
        positive_output(MODEL, "v*_Y", v_y * (5.0 * c / 8.0).powf(2.5))
    }

    /// The loading force `F(d)` (N) at depth `d` (m, ≥ 0).
    ///
    /// Seed 000, the FEM-based law of section 5.5.1 (ref. \[44\]); see the type docs.
    pub fn loading_force(&self, depth: f64) -> Result<f64> {
        let d = validate::non_negative("depth", depth)?;
        finite_output(MODEL, "force", self.force_raw(d / self.critical_depth))
    }

    /// The contact radius `a(d)` (m) while loading, at depth `d` (m, ≥ 0).
    ///
    /// Seed 000, section 5.5.1 (ref. \[44\]): `a = √(R d)(δ/1.9)^B` for δ ≥ 1.9, Hertz below.
    pub fn loading_contact_radius(&self, depth: f64) -> Result<f64> {
        let d = validate::non_negative("depth", depth)?;
        finite_output(MODEL, "contact radius", self.radius_raw(d))
    }

    /// The residual depth (m) after loading to `d_max` (m, ≥ 0):
    /// `1.02 d_max[1 − ((d_max/d*_Y + 5.9)/6.9)^(−0.54)]`, 0 for `d_max ≤ d*_Y`.
    ///
    /// Seed 000, section 5.5.1 (Jackson, Chusoipin, Green 2005).
    pub fn residual_depth(&self, max_depth: f64) -> Result<f64> {
        let d = validate::non_negative("max_depth", max_depth)?;
        finite_output(MODEL, "residual depth", self.residual_raw(d))
    }

    /// The impact of effective mass `m` (kg) as an [`ImpactModel`] solved by the
    /// time-domain simulator with `settings`.
    ///
    /// Seed 000, section 5.5.1: "Durch numerische Integration ... löst man das
    /// Stoßproblem"; speed scale (5.108).
    pub fn impact(
        &self,
        effective_mass: f64,
        settings: SimulationSettings,
    ) -> Result<JacksonGreenImpact> {
        let yield_velocity = self.yield_velocity(effective_mass)?;
        Ok(JacksonGreenImpact {
            simulation: SimulatedImpact::new(self.force_law(), effective_mass, settings)?,
            yield_velocity,
        })
    }

    /// The time-domain force law (loading, turning point, elastic unloading with the
    /// residual depth, separation at `F = 0`).
    ///
    /// Seed 000, section 5.5.1 (ref. \[44\]).
    pub fn force_law(&self) -> JacksonGreenLaw {
        JacksonGreenLaw {
            contact: *self,
            phase: Phase::Hertz,
        }
    }

    fn force_raw(&self, delta: f64) -> f64 {
        let delta = delta.max(0.0);
        let p = if delta < FIT_ONSET {
            delta * delta.sqrt()
        } else {
            let c = critical_pressure_factor(self.poisson_ratio);
            (-0.25 * delta.powf(5.0 / 12.0)).exp() * delta * delta.sqrt()
                + 4.0 * self.hardness_ratio / c
                    * (-(-delta.powf(5.0 / 9.0) / 25.0).exp_m1())
                    * delta
        };
        p * self.critical_force
    }

    fn radius_raw(&self, d: f64) -> f64 {
        let d = d.max(0.0);
        let delta = d / self.critical_depth;
        let hertz = (self.radius * d).sqrt();
        if delta < FIT_ONSET {
            hertz
        } else {
            hertz * (delta / FIT_ONSET).powf(self.area_exponent)
        }
    }

    fn residual_raw(&self, d_max: f64) -> f64 {
        let delta = d_max / self.critical_depth;
        if delta <= 1.0 {
            0.0
        } else {
            1.02 * d_max * (1.0 - ((delta + 5.9) / 6.9).powf(-0.54))
        }
    }
}

/// `C(ν) = 1.295 exp(0.736 ν)`. Seed 000, eq. (5.108).
fn critical_pressure_factor(nu: f64) -> f64 {
    1.295 * (0.736 * nu).exp()
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum Phase {
    /// Hertzian loading, δ < 1.9.
    Hertz,
    /// The FEM fit, δ ≥ 1.9.
    Fit,
    /// Elastic unloading `F = F_max ((d − d_res)/(d_max − d_res))^(3/2)`.
    Unloading {
        residual_depth: f64,
        max_force: f64,
        elastic_depth: f64,
    },
}

/// The Jackson-Green contact as a `tabor_dynamics::ForceLaw`: Hertz branch to
/// `δ = 1.9` (a branch end: the fit starts there, with a force step of about 1 %),
/// fit branch, Hertzian unloading from the turning point through `(d_max, F_max)`
/// to `d_res`, separation at `F = 0`.
///
/// Seed 000, section 5.5.1 (ref. \[44\]).
#[derive(Clone, Debug, PartialEq)]
pub struct JacksonGreenLaw {
    contact: JacksonGreen,
    phase: Phase,
}

impl ForceLaw for JacksonGreenLaw {
    fn name(&self) -> String {
        format!(
            "Jackson-Green (nu = {}, H/sigma_Y = {})",
            self.contact.poisson_ratio, self.contact.hardness_ratio
        )
    }

    /// `d*_Y (v0/v*_Y)^(4/5)` for v0 below `v*_Y`, `d*_Y (v0/v*_Y)` above (a fair
    /// guess of d_max within a factor of a few).
    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64> {
        let v = validate::positive("impact_speed", impact_speed)?;
        let s = v / self.contact.yield_velocity(effective_mass)?;
        let x = if s < 1.0 { s.powf(0.8) } else { s };
        positive_output(MODEL, "overlap scale", x * self.contact.critical_depth)
    }

    fn begin_impact(&mut self, _m: f64, _v0: f64) -> Result<()> {
        self.phase = Phase::Hertz;
        Ok(())
    }

    fn force(&self, overlap: f64, _rate: f64) -> Result<f64> {
        let d = validate::finite("overlap", overlap)?;
        let c = &self.contact;
        Ok(match self.phase {
            Phase::Hertz => {
                let delta = d.max(0.0) / c.critical_depth;
                delta * delta.sqrt() * c.critical_force
            }
            Phase::Fit => c.force_raw(d / c.critical_depth),
            Phase::Unloading {
                residual_depth,
                max_force,
                elastic_depth,
            } => {
                let r = (d - residual_depth) / elastic_depth;
                max_force * r * r.abs().sqrt()
            }
        })
    }

    fn contact_radius(&self, overlap: f64, _rate: f64) -> Result<f64> {
        let d = validate::finite("overlap", overlap)?;
        let c = &self.contact;
        Ok(match self.phase {
            Phase::Hertz | Phase::Fit => c.radius_raw(d),
            Phase::Unloading {
                residual_depth,
                max_force,
                elastic_depth,
            } => {
                // Hertz with R_p: F_max = (4/3)E √R_p δ_e^(3/2), a² = R_p (d − d_res).
                let rp = (0.75 * max_force / c.modulus).powi(2) / elastic_depth.powi(3);
                (rp * (d - residual_depth).max(0.0)).sqrt()
            }
        })
    }

    fn branch_end(&self, overlap: f64, _rate: f64) -> Result<f64> {
        Ok(match self.phase {
            Phase::Hertz => FIT_ONSET * self.contact.critical_depth - overlap,
            Phase::Fit => overlap,
            Phase::Unloading { residual_depth, .. } => overlap - residual_depth,
        })
    }

    fn on_branch_end(&mut self, _overlap: f64, _rate: f64) -> Result<BranchChange> {
        match self.phase {
            Phase::Hertz => {
                self.phase = Phase::Fit;
                Ok(BranchChange::Continue)
            }
            _ => Ok(BranchChange::Separate),
        }
    }

    fn on_max_compression(&mut self, overlap: f64) -> Result<BranchChange> {
        let d = validate::positive("overlap", overlap)?;
        let max_force = positive_output(MODEL, "F_max", self.force(d, 0.0)?)?;
        let residual_depth = self.contact.residual_raw(d);
        let elastic_depth = positive_output(MODEL, "d_max - d_res", d - residual_depth)?;
        self.phase = Phase::Unloading {
            residual_depth,
            max_force,
            elastic_depth,
        };
        Ok(BranchChange::Continue)
    }
}

/// The Jackson-Green impact, solved in the time domain; an [`ImpactModel`].
///
/// Seed 000, section 5.5.1 and eq. (5.108).
#[derive(Clone, Debug)]
pub struct JacksonGreenImpact {
    simulation: SimulatedImpact<JacksonGreenLaw>,
    yield_velocity: f64,
}

impl JacksonGreenImpact {
    /// The yield velocity `v*_Y` (m/s). Seed 000, eq. (5.108).
    pub fn yield_velocity(&self) -> f64 {
        self.yield_velocity
    }

    /// The full simulation of one impact at `v0` (m/s, > 0).
    ///
    /// Seed 000, section 5.5.1.
    pub fn simulate(&self, impact_speed: f64) -> Result<ImpactSimulation> {
        self.simulation.simulate(impact_speed)
    }
}

impl ImpactModel for JacksonGreenImpact {
    fn name(&self) -> String {
        self.simulation.name()
    }
    fn effective_mass(&self) -> f64 {
        self.simulation.effective_mass()
    }
    /// The loss of the simulated impact (seed 000, section 5.5.1).
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        self.simulation.energy_loss(impact_speed)
    }
    fn speed_scale(&self) -> f64 {
        self.yield_velocity
    }
}
