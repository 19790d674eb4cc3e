//! Combining models: the sum of their losses, the one place where tabor adds the
//! energy losses of separate effects (the superposition of seed 000 eq. (5.109)).

use crate::validate::finite_output;
use crate::{EnergyLoss, Error, ImpactModel, Result};
use tabor_numerics::Cost;

/// The superposition of several models of the same collision: the energy loss is
/// the sum of the parts' losses (seed 000 eq. (5.109), generalized to any number of
/// effects). Every part must have the same effective mass.
///
/// Each part may be any [`ImpactModel`], boxed or borrowed.
#[derive(Clone, Debug)]
pub struct LossSum<M> {
    parts: Vec<M>,
}

impl<M: ImpactModel> LossSum<M> {
    /// The sum of `parts` (at least one). The parts' effective masses must agree to
    /// 1e-12 relative.
    pub fn new(parts: Vec<M>) -> Result<Self> {
        let Some(first) = parts.first() else {
            return Err(Error::Model {
                model: "loss sum",
                message: "no parts to add".into(),
            });
        };
        let m = first.effective_mass();
        for p in &parts[1..] {
            let mp = p.effective_mass();
            if (mp - m).abs() > 1e-12 * m.abs().max(mp.abs()) {
                return Err(Error::Model {
                    model: "loss sum",
                    message: format!(
                        "parts have different effective masses: {m:e} kg ({}) and {mp:e} kg ({})",
                        first.name(),
                        p.name()
                    ),
                });
            }
        }
        Ok(LossSum { parts })
    }

    /// The parts, in the order given.
    pub fn parts(&self) -> &[M] {
        &self.parts
    }

    /// Each part's loss at `impact_speed`, in the order of [`LossSum::parts`].
    pub fn part_losses(&self, impact_speed: f64) -> Result<Vec<EnergyLoss>> {
        self.parts
            .iter()
            .map(|p| p.energy_loss(impact_speed))
            .collect()
    }
}

impl<M: ImpactModel> ImpactModel for LossSum<M> {
    fn name(&self) -> String {
        let names: Vec<String> = self.parts.iter().map(|p| p.name()).collect();
        names.join(" + ")
    }
    fn effective_mass(&self) -> f64 {
        self.parts[0].effective_mass()
    }
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let mut total = EnergyLoss {
            joules: 0.0,
            error_estimate: 0.0,
            branch: String::new(),
            cost: Cost::ZERO,
        };
        let mut branches = Vec::with_capacity(self.parts.len());
        for l in self.part_losses(impact_speed)? {
            total.joules += l.joules;
            total.error_estimate += l.error_estimate;
            total.cost += l.cost;
            branches.push(l.branch);
        }
        total.joules = finite_output("loss sum", "energy loss", total.joules)?;
        total.branch = branches.join(" + ");
        Ok(total)
    }
    fn loss_is_speed_independent(&self) -> bool {
        self.parts.iter().all(|p| p.loss_is_speed_independent())
    }
    fn speed_scale(&self) -> f64 {
        self.parts[0].speed_scale()
    }
}
