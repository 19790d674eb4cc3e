//! Plasticity and adhesion by superposing their losses (seed 000, (5.109)-(5.110)).

use tabor_jkr::{JkrImpact, JkrSphere};
use tabor_restitution::{EnergyLoss, Error, ImpactModel, LossSum, Result};

/// The superposition model: the kinetic energy lost is the plastic loss of any
/// non-adhesive model `P` plus the elastic JKR adhesive loss (5.36) (fixed grip),
/// i.e. `1 − ε² = (1 − ε_adh²) + (1 − ε_pl²)`, `ε = √(ε_pl² − v_c²/v0²)`.
///
/// The losses are added by `tabor_restitution::LossSum` (the one loss-summing
/// combinator) over the two parts, borrowed per call.
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
        let model = Superposition { plastic, adhesive };
        model.parts()?;
        Ok(model)
    }

    /// The two parts as a `LossSum` (plastic first: its speed scale is the sum's).
    fn parts(&self) -> Result<LossSum<&dyn ImpactModel>> {
        LossSum::new(vec![
            &self.plastic as &dyn ImpactModel,
            &self.adhesive as &dyn ImpactModel,
        ])
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
    /// `|ΔU_pl(v0)| + |ΔU_JKR|` by `LossSum`. Seed 000, eq. (5.109).
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let mut loss = self.parts()?.energy_loss(impact_speed)?;
        // LossSum checked the sum is finite; the parts are non-negative losses.
        let joules = loss.joules;
        if joules < 0.0 {
            return Err(Error::Model {
                model: "superposition",
                message: format!("negative energy loss {joules:e}"),
            });
        }
        loss.branch = format!("(5.109): {}", loss.branch);
        Ok(loss)
    }
    fn speed_scale(&self) -> f64 {
        self.plastic.speed_scale()
    }
}
