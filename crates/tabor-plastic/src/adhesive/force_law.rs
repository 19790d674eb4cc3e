//! The adhesive interpolation model as a time-domain force law for
//! `tabor-dynamics`. Seed 000, eqs. (5.111)-(5.125).

use super::normalized::{AdhesiveInterpolation, JkrUnloading};
use super::MODEL;
use crate::util::{finite_output, positive_output};
use tabor_dynamics::{BranchChange, ForceLaw};
use tabor_jkr::JkrScales;
use tabor_restitution::{validate, Result};

/// The adhesive interpolation model as a `tabor_dynamics::ForceLaw`: the motion
/// starts at first touch (`d = 0`) on the JKR branch (the jump-in force −(8/9)F_n is
/// already attractive there), loads along (5.111)-(5.115), switches at the turning
/// point to JKR unloading with `R_p` and `d_res` (5.121)-(5.124), and separates at
/// the displacement-controlled instability (5.125) (`branch_end = d − d_sep`).
///
/// Seed 000, eqs. (5.111)-(5.125).
#[derive(Clone, Debug, PartialEq)]
pub struct AdhesiveForceLaw {
    model: AdhesiveInterpolation,
    scales: JkrScales,
    unloading: Option<JkrUnloading>,
}

impl AdhesiveForceLaw {
    /// The force law of `model` in the physical units `scales`, on the loading branch.
    pub(super) fn new(model: AdhesiveInterpolation, scales: JkrScales) -> Self {
        AdhesiveForceLaw {
            model,
            scales,
            unloading: None,
        }
    }
}

impl ForceLaw for AdhesiveForceLaw {
    fn name(&self) -> String {
        format!(
            "adhesive interpolation (Phi = {:.4})",
            self.model.adhesion_parameter()
        )
    }

    /// `d_max` of the analytic model (at least `d_n`).
    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64> {
        let m = validate::positive("effective_mass", effective_mass)?;
        let v = validate::positive("impact_speed", impact_speed)?;
        let k = positive_output(
            MODEL,
            "kinetic energy",
            0.5 * m * v * v / self.scales.energy,
        )?;
        let d = self.model.max_depth(k)?;
        positive_output(MODEL, "overlap scale", d.max(1.0) * self.scales.depth)
    }

    fn begin_impact(&mut self, _m: f64, _v0: f64) -> Result<()> {
        self.unloading = None;
        Ok(())
    }

    fn force(&self, overlap: f64, _rate: f64) -> Result<f64> {
        let d = validate::finite("overlap", overlap)? / self.scales.depth;
        let f = match self.unloading {
            None => self.model.loading_state(d)?.force,
            Some(u) => u.state(d)?.1,
        };
        finite_output(MODEL, "force", f * self.scales.force)
    }

    fn contact_radius(&self, overlap: f64, _rate: f64) -> Result<f64> {
        let d = validate::finite("overlap", overlap)? / self.scales.depth;
        let a = match self.unloading {
            None => self.model.loading_state(d)?.contact_radius,
            Some(u) => u.state(d)?.0,
        };
        finite_output(MODEL, "contact radius", a * self.scales.contact_radius)
    }

    fn branch_end(&self, overlap: f64, _rate: f64) -> Result<f64> {
        Ok(match self.unloading {
            None => overlap,
            Some(u) => overlap - u.separation * self.scales.depth,
        })
    }

    /// Seed 000, eqs. (5.123)-(5.124) (corrected (5.123)).
    fn on_max_compression(&mut self, overlap: f64) -> Result<BranchChange> {
        let d = validate::finite("overlap", overlap)? / self.scales.depth;
        let state = self.model.loading_state(d)?;
        self.unloading = Some(JkrUnloading::from_turning_point(state)?);
        Ok(BranchChange::Continue)
    }
}
