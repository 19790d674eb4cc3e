//! The impact: a contact, an effective mass and a separation rule, as an
//! [`ImpactModel`].

use crate::common::{finite_output, JkrContactState, MaxContactRadius, SeparationRule};
use tabor_restitution::{validate, EnergyLoss, ImpactModel, Result};

/// The relative tolerance [`JkrImpact`] uses unless told otherwise: the
/// workspace's `tabor_numerics::tolerance::DEFAULT_TOLERANCE` (1e-12).
pub const DEFAULT_TOLERANCE: f64 = tabor_numerics::tolerance::DEFAULT_TOLERANCE;

mod sealed {
    pub trait Sealed {}
    impl Sealed for crate::JkrSphere {}
    impl Sealed for crate::PowerLawProfile {}
    impl Sealed for crate::GradedSphere {}
}

/// An elastic contact with JKR adhesion, as the impact sees it: first touch, the
/// state where contact breaks, the adhesive loss and the energy balance. Implemented
/// by [`crate::JkrSphere`], [`crate::PowerLawProfile`] and [`crate::GradedSphere`]
/// (sealed). All quantities in SI units.
pub trait AdhesiveContact: sealed::Sealed {
    /// A short name of the contact ("JKR sphere", ...).
    fn description(&self) -> String;

    /// The state at first touch, `d = 0`, where the contact radius jumps to `a0`
    /// (seed 000, lower limit of (5.35)-(5.36)).
    fn first_touch(&self) -> Result<JkrContactState>;

    /// The state where contact breaks under `rule` (seed 000, upper limit of (5.36)).
    fn critical_state(&self, rule: SeparationRule) -> Result<JkrContactState>;

    /// The energy scale of the contact's normalized units (J).
    fn energy_scale(&self) -> f64;

    /// The adhesive energy loss |ΔU_kin| (J) between first touch and separation under
    /// `rule`; `tolerance` (relative, in [1e-15, 0.5]) applies where a quadrature is
    /// needed. Seed 000, eqs. (5.36), (5.39), (5.51).
    fn energy_loss(&self, rule: SeparationRule, tolerance: f64) -> Result<EnergyLoss>;

    /// The maximum contact radius (m) reached with kinetic energy `kinetic_energy`
    /// (J, > 0), from the energy balance to the relative `tolerance`.
    /// Seed 000, eqs. (5.35), (5.49).
    fn max_contact_radius(&self, kinetic_energy: f64, tolerance: f64) -> Result<MaxContactRadius>;

    /// [`AdhesiveContact::max_contact_radius`] started from `near` (m), the
    /// maximum contact radius of a nearby kinetic energy, where the contact's
    /// solver can use it (the sphere's does; the others ignore it).
    fn max_contact_radius_near(
        &self,
        kinetic_energy: f64,
        tolerance: f64,
        near: Option<f64>,
    ) -> Result<MaxContactRadius> {
        let _ = near;
        self.max_contact_radius(kinetic_energy, tolerance)
    }
}

/// A JKR-adhesive impact: an [`AdhesiveContact`], the effective mass and the
/// [`SeparationRule`] (fixed grip by default).
///
/// Its [`ImpactModel`] implementation returns the speed-independent adhesive loss,
/// so `tabor_restitution::impact` gives the restitution of seed 000 eq. (5.37) and
/// `tabor_restitution::sticking_velocity` the closed form (5.38).
#[derive(Clone, Debug, PartialEq)]
pub struct JkrImpact<C> {
    contact: C,
    mass: f64,
    separation: SeparationRule,
    tolerance: f64,
}

impl<C: AdhesiveContact> JkrImpact<C> {
    /// An impact of `contact` with effective (reduced) mass `m` (kg, finite, > 0),
    /// fixed-grip separation and tolerance [`DEFAULT_TOLERANCE`].
    ///
    /// Seed 000, the mass `m̃` of (5.33), (5.35), (5.37)-(5.38).
    pub fn new(contact: C, effective_mass: f64) -> Result<Self> {
        let m = validate::positive("effective_mass", effective_mass)?;
        Ok(JkrImpact {
            contact,
            mass: m,
            separation: SeparationRule::default(),
            tolerance: DEFAULT_TOLERANCE,
        })
    }

    /// The same impact with separation rule `rule`.
    pub fn with_separation(mut self, rule: SeparationRule) -> Self {
        self.separation = rule;
        self
    }

    /// The same impact with relative tolerance `tolerance` (in [1e-15, 0.5]) for its
    /// quadratures and root searches.
    pub fn with_tolerance(mut self, tolerance: f64) -> Result<Self> {
        self.tolerance = validate::tolerance("tolerance", tolerance)?;
        Ok(self)
    }

    /// The contact.
    pub fn contact(&self) -> &C {
        &self.contact
    }

    /// The separation rule.
    pub fn separation(&self) -> SeparationRule {
        self.separation
    }

    /// The adhesive energy loss |ΔU_kin| (J), the same at every impact speed.
    ///
    /// Seed 000, eqs. (5.36), (5.39), (5.51) (fixed grip) or their integrals to the
    /// load-controlled pull-off point.
    pub fn adhesive_energy_loss(&self) -> Result<EnergyLoss> {
        self.contact.energy_loss(self.separation, self.tolerance)
    }

    /// The maximum contact radius (m) of an impact at relative speed `v0` (m/s, > 0),
    /// from the energy balance `m v0²/2 = ∫ F dd` (first touch to `a_max`).
    ///
    /// Seed 000, eqs. (5.35), (5.49).
    pub fn max_contact_radius(&self, impact_speed: f64) -> Result<MaxContactRadius> {
        self.max_contact_radius_near(impact_speed, None)
    }

    /// [`JkrImpact::max_contact_radius`] started from `near` (m), the maximum
    /// contact radius at a nearby speed (a batch over sorted speeds).
    ///
    /// Seed 000, eq. (5.35).
    #[inline]
    pub fn max_contact_radius_near(
        &self,
        impact_speed: f64,
        near: Option<f64>,
    ) -> Result<MaxContactRadius> {
        let v = validate::positive("impact_speed", impact_speed)?;
        let kinetic = finite_output(MODEL, "kinetic energy m v0^2/2", 0.5 * self.mass * v * v)?;
        if kinetic <= 0.0 {
            return Err(tabor_restitution::Error::invalid(
                "impact_speed",
                v,
                "gives a kinetic energy m v0^2/2 that underflows to zero",
            ));
        }
        self.contact
            .max_contact_radius_near(kinetic, self.tolerance, near)
    }
}

const MODEL: &str = "JKR impact";

impl<C: AdhesiveContact> ImpactModel for JkrImpact<C> {
    fn name(&self) -> String {
        format!("{} ({})", self.contact.description(), self.separation)
    }

    fn effective_mass(&self) -> f64 {
        self.mass
    }

    /// The adhesive loss (independent of `impact_speed`, which is only validated).
    fn energy_loss(&self, impact_speed: f64) -> Result<EnergyLoss> {
        validate::positive("impact_speed", impact_speed)?;
        self.adhesive_energy_loss()
    }

    fn loss_is_speed_independent(&self) -> bool {
        true
    }

    /// `√(2 E_scale / m)`, the sticking velocity up to a factor of order one.
    fn speed_scale(&self) -> f64 {
        let v = (2.0 * self.contact.energy_scale() / self.mass).sqrt();
        if v.is_finite() && v > 0.0 {
            v
        } else {
            1.0
        }
    }
}
