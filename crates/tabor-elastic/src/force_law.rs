//! The elastic contacts as a time-domain force law for `tabor-dynamics`.

use crate::{ElasticContact, ElasticImpact};
use tabor_dynamics::ForceLaw;
use tabor_restitution::Result;

/// The elastic contacts of `tabor-elastic` (Hertz (5.5), power-law indenter
/// (5.15), graded media (5.20), (5.28)): one conservative branch, `F = K d^q` for
/// d > 0 and 0 otherwise, separation at d = 0.
impl ForceLaw for ElasticContact {
    fn name(&self) -> String {
        ElasticContact::name(self)
    }

    /// d_max of the closed form, seed 000 eqs. (5.8), (5.16), (5.21), (5.28).
    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64> {
        ElasticImpact::new(*self, effective_mass)?.max_overlap(impact_speed)
    }

    fn force(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        Ok(ElasticContact::force(self, overlap))
    }

    fn contact_radius(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        Ok(ElasticContact::contact_radius(self, overlap))
    }
}
