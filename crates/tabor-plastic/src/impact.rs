//! The physical shell of the non-adhesive elasto-plastic impact (Thornton, the
//! interpolation model): energy loss for the restitution core, and the time-domain
//! force law for the simulator.

use crate::contact::PlasticContact;
use crate::loading::LoadingLaw;
use crate::util::{finite_output, positive_output};
use tabor_dynamics::{BranchChange, ForceLaw};
use tabor_restitution::{validate, EnergyLoss, ImpactModel, Result};

/// The central impact of a rigid sphere on an elastic-perfectly plastic half-space
/// with a loading law `L` ([`crate::Thornton`] or [`crate::Interpolation`]) and
/// elastic unloading; an [`ImpactModel`], so restitution (5.37) and the rest come
/// from `tabor-restitution`.
///
/// Seed 000, eqs. (5.101)-(5.107).
#[derive(Clone, Debug, PartialEq)]
pub struct PlasticImpact<L> {
    contact: PlasticContact,
    law: L,
    mass: f64,
    yield_velocity: f64,
}

impl<L: LoadingLaw> PlasticImpact<L> {
    /// The impact of `contact` with loading law `law` and effective mass `m` (kg,
    /// finite, > 0).
    ///
    /// Seed 000, eqs. (5.101)-(5.103).
    pub fn new(contact: PlasticContact, law: L, effective_mass: f64) -> Result<Self> {
        let m = validate::positive("effective_mass", effective_mass)?;
        let yield_velocity = contact.yield_velocity(m)?;
        Ok(PlasticImpact {
            contact,
            law,
            mass: m,
            yield_velocity,
        })
    }

    /// The contact.
    ///
    /// Seed 000, eq. (5.102).
    pub fn contact(&self) -> &PlasticContact {
        &self.contact
    }

    /// The loading law.
    ///
    /// Seed 000, eqs. (5.101), (5.107).
    pub fn law(&self) -> &L {
        &self.law
    }

    /// The yield velocity `v_Y` (m/s). Seed 000, eq. (5.103).
    pub fn yield_velocity(&self) -> f64 {
        self.yield_velocity
    }

    /// `v0/v_Y` for an impact speed `v0` (m/s, > 0).
    fn speed_ratio(&self, impact_speed: f64) -> Result<f64> {
        let v = validate::positive("impact_speed", impact_speed)?;
        positive_output("plastic impact", "v0/v_Y", v / self.yield_velocity)
    }

    /// The coefficient of restitution in the closed form of the model, seed 000
    /// eq. (5.105) (1 below `v_Y`). The generic path is
    /// `tabor_restitution::impact(&model, v0)`; both agree.
    pub fn restitution(&self, impact_speed: f64) -> Result<f64> {
        self.law.restitution(self.speed_ratio(impact_speed)?)
    }

    /// The maximum depth `d_max` (m) at impact speed `v0` (m/s, > 0).
    ///
    /// Seed 000, eq. (5.104) (Thornton), (5.107) (interpolation).
    pub fn max_depth(&self, impact_speed: f64) -> Result<f64> {
        let x = self.law.max_depth_ratio(self.speed_ratio(impact_speed)?)?;
        finite_output("plastic impact", "d_max", x * self.contact.yield_depth())
    }

    /// The residual depth `d_res` (m) after an impact at `v0` (m/s, > 0).
    ///
    /// Seed 000, eq. (5.105) with (3.274): `d_res = d_max − a_max²/R_p`.
    pub fn residual_depth(&self, impact_speed: f64) -> Result<f64> {
        let t = self.law.turning_point(self.speed_ratio(impact_speed)?)?;
        finite_output(
            "plastic impact",
            "d_res",
            t.residual_depth_ratio * self.contact.yield_depth(),
        )
    }

    /// The time-domain force law of this model for `tabor_dynamics::simulate_impact`
    /// (loading, turning point, Hertzian unloading with `R_p` and `d_res`,
    /// separation at `F = 0`).
    ///
    /// Seed 000, eqs. (5.101)-(5.105).
    pub fn force_law(&self) -> PlasticForceLaw<L> {
        PlasticForceLaw {
            contact: self.contact,
            law: self.law.clone(),
            unloading: None,
        }
    }
}

impl<L: LoadingLaw> ImpactModel for PlasticImpact<L> {
    fn name(&self) -> String {
        format!("elasto-plastic impact, {}", self.law.name())
    }

    fn effective_mass(&self) -> f64 {
        self.mass
    }

    /// Loading work `m v0²/2` minus the elastic unloading work
    /// `(2/5) F_max (d_max − d_res)`; 0 below `v_Y`.
    ///
    /// Seed 000, eqs. (5.101)-(5.105).
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        let s = self.speed_ratio(impact_speed)?;
        let kinetic = 0.5 * self.mass * impact_speed * impact_speed;
        if s <= 1.0 {
            return Ok(EnergyLoss::closed_form(0.0, "elastic (v0 <= v_Y)"));
        }
        let rebound = self.law.rebound_work_ratio(s)? * self.contact.yield_energy();
        let loss = finite_output("plastic impact", "energy loss", kinetic - rebound)?;
        Ok(EnergyLoss::closed_form(
            loss.max(0.0),
            format!(
                "{}: loading work minus elastic unloading (5.105)",
                self.law.name()
            ),
        ))
    }

    fn speed_scale(&self) -> f64 {
        self.yield_velocity
    }
}

/// The unloading branch set at the turning point.
#[derive(Clone, Copy, Debug, PartialEq)]
struct HertzUnloading {
    residual_depth: f64,
    /// `(4/3) E* √R_p`.
    stiffness: f64,
    radius: f64,
}

/// The time-domain force law of [`PlasticImpact`]: loading `F = F_Y f(d/d_Y)` until
/// the turning point, then Hertzian unloading `F = (4/3)E*√R_p (d − d_res)^(3/2)`
/// (odd extension below `d_res`), separation where `d = d_res` (F = 0).
///
/// Seed 000, eqs. (5.101)-(5.105), chapter 3 (3.273)-(3.274); the plastic-law
/// recipe of `tabor_dynamics::ForceLaw`.
#[derive(Clone, Debug, PartialEq)]
pub struct PlasticForceLaw<L> {
    contact: PlasticContact,
    law: L,
    unloading: Option<HertzUnloading>,
}

impl<L: LoadingLaw> ForceLaw for PlasticForceLaw<L> {
    fn name(&self) -> String {
        format!("elasto-plastic contact, {}", self.law.name())
    }

    /// `d_max` of the model's own closed form.
    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64> {
        let v_y = self.contact.yield_velocity(effective_mass)?;
        let v = validate::positive("impact_speed", impact_speed)?;
        let x = self.law.max_depth_ratio(v / v_y)?;
        positive_output(
            "plastic force law",
            "overlap scale",
            x * self.contact.yield_depth(),
        )
    }

    fn begin_impact(&mut self, _effective_mass: f64, _impact_speed: f64) -> Result<()> {
        self.unloading = None;
        Ok(())
    }

    fn force(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        let d = validate::finite("overlap", overlap)?;
        match self.unloading {
            None => {
                if d <= 0.0 {
                    Ok(0.0)
                } else {
                    let x = d / self.contact.yield_depth();
                    Ok(self.contact.yield_force() * self.law.force_ratio(x)?)
                }
            }
            Some(u) => {
                let delta = d - u.residual_depth;
                Ok(u.stiffness * delta * delta.abs().sqrt())
            }
        }
    }

    fn contact_radius(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        let d = validate::finite("overlap", overlap)?;
        match self.unloading {
            None => {
                let x = d.max(0.0) / self.contact.yield_depth();
                Ok(self.contact.yield_contact_radius() * self.law.contact_radius_ratio(x)?)
            }
            Some(u) => Ok((u.radius * (d - u.residual_depth).max(0.0)).sqrt()),
        }
    }

    fn branch_end(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        Ok(match self.unloading {
            None => overlap,
            Some(u) => overlap - u.residual_depth,
        })
    }

    /// Stores `R_p = 4E* a_max³/(3F_max)` and `d_res = d_max − a_max²/R_p` and
    /// switches to unloading. Seed 000, (5.105) with chapter 3 (3.273)-(3.274).
    fn on_max_compression(&mut self, overlap: f64) -> Result<BranchChange> {
        let d = validate::positive("overlap", overlap)?;
        let x = d / self.contact.yield_depth();
        let f = self.law.force_ratio(x)?;
        let alpha = self.law.contact_radius_ratio(x)?;
        let r = self.contact.effective_radius();
        let radius = positive_output("plastic force law", "R_p", r * alpha * alpha * alpha / f)?;
        let residual_depth = (d - self.contact.yield_depth() * f / alpha).max(0.0);
        self.unloading = Some(HertzUnloading {
            residual_depth,
            stiffness: 4.0 / 3.0 * self.contact.effective_modulus() * radius.sqrt(),
            radius,
        });
        Ok(BranchChange::Continue)
    }
}
