//! Plasticity and adhesion by superposing their losses (seed 000, (5.109)-(5.110)).

use crate::util::finite_output;
use tabor_jkr::{JkrImpact, JkrSphere};
use tabor_restitution::{EnergyLoss, Error, ImpactModel, Result};

/// The superposition model: the kinetic energy lost is the plastic loss of any
/// non-adhesive model `P` plus the elastic JKR adhesive loss (5.36) (fixed grip),
/// i.e. `1 − ε² = (1 − ε_adh²) + (1 − ε_pl²)`, `ε = √(ε_pl² − v_c²/v0²)`.
///
/// Seed 000, eqs. (5.109)-(5.110).
#[derive(Clone, Debug)]
pub struct Superposition<P> {
    plastic: P,
    adhesive: JkrImpact<JkrSphere>,
}

impl<P: ImpactModel> Superposition<P> {
    /// Superposes `plastic` (a non-adhesive model) and the JKR adhesion of `sphere`
    /// (same effective modulus and radius), with the mass of `plastic`.
    ///
    /// Seed 000, eq. (5.109).
    pub fn new(plastic: P, sphere: JkrSphere) -> Result<Self> {
        let adhesive = JkrImpact::new(sphere, plastic.effective_mass())?;
        Ok(Superposition { plastic, adhesive })
    }

    /// The non-adhesive plastic model.
    ///
    /// Seed 000, `ε_pl` of (5.109).
    pub fn plastic(&self) -> &P {
        &self.plastic
    }

    /// The elastic adhesive impact (its loss is (5.36), its sticking velocity (5.38)).
    ///
    /// Seed 000, `ε_adh` of (5.109), (5.36)-(5.38).
    pub fn adhesive(&self) -> &JkrImpact<JkrSphere> {
        &self.adhesive
    }
}

impl<P: ImpactModel> ImpactModel for Superposition<P> {
    fn name(&self) -> String {
        format!("superposition of {} and JKR adhesion", self.plastic.name())
    }
    fn effective_mass(&self) -> f64 {
        self.plastic.effective_mass()
    }
    /// `|ΔU_pl(v0)| + |ΔU_JKR|`. Seed 000, eq. (5.109).
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let pl = self.plastic.energy_loss(impact_speed)?;
        let adh = self.adhesive.adhesive_energy_loss()?;
        let joules = finite_output("superposition", "energy loss", pl.joules + adh.joules)?;
        if joules < 0.0 {
            return Err(Error::Model {
                model: "superposition",
                message: format!("negative energy loss {joules:e}"),
            });
        }
        Ok(EnergyLoss {
            joules,
            error_estimate: pl.error_estimate + adh.error_estimate,
            branch: format!("(5.109): {} + {}", pl.branch, adh.branch),
            cost: pl.cost + adh.cost,
        })
    }
    fn speed_scale(&self) -> f64 {
        self.plastic.speed_scale()
    }
}
