//! The impact speed at which a contact starts to yield, behind one trait so that
//! callers need not match on the concrete model.

use crate::{
    AdhesiveInterpolationImpact, DimensionlessFit, JacksonGreenImpact, LoadingLaw, PlasticImpact,
    Superposition,
};

/// The impact speed (m/s) above which the contact yields: below it the impact is
/// elastic (Hertz, or JKR with adhesion), above it the model dissipates plastically.
///
/// - [`PlasticImpact`] (Thornton, interpolation): `v_Y² = (16/15)(4π/5)⁵ (σ_Y/E*)⁵ E* R³/m`,
///   seed 000 eq. (5.103);
/// - [`JacksonGreenImpact`]: `v*_Y = v_Y (5C(ν)/8)^(5/2)`, seed 000 eq. (5.108);
/// - [`DimensionlessFit`]: `v_y = (15.81 σ_y^4.5/(ρ E*^3.5))^0.5`, seed 001 eq. (18);
/// - [`AdhesiveInterpolationImpact`]: the speed whose JKR loading work (5.35) reaches
///   the adhesive yield load (5.111)-(5.113); 0 when the contact yields at first touch
///   or inside the adhesive well;
/// - [`Superposition`]: that of its plastic part (seed 000 (5.109)).
///
/// Seed 000, eqs. (5.103), (5.108), (5.111); seed 001, eq. (18).
pub trait YieldVelocity {
    /// The yield velocity (m/s, ≥ 0). Seed 000, eq. (5.103) and its analogues above.
    fn yield_velocity(&self) -> f64;
}

/// Seed 000, eq. (5.103).
impl<L: LoadingLaw> YieldVelocity for PlasticImpact<L> {
    fn yield_velocity(&self) -> f64 {
        PlasticImpact::yield_velocity(self)
    }
}

/// Seed 000, eq. (5.108).
impl YieldVelocity for JacksonGreenImpact {
    fn yield_velocity(&self) -> f64 {
        JacksonGreenImpact::yield_velocity(self)
    }
}

/// Seed 001, eq. (18).
impl YieldVelocity for DimensionlessFit {
    fn yield_velocity(&self) -> f64 {
        DimensionlessFit::yield_velocity(self)
    }
}

/// Seed 000, eqs. (5.35), (5.111)-(5.113).
impl YieldVelocity for AdhesiveInterpolationImpact {
    fn yield_velocity(&self) -> f64 {
        AdhesiveInterpolationImpact::yield_velocity(self)
    }
}

/// The yield velocity of the plastic part. Seed 000, eq. (5.109).
impl<P: YieldVelocity + tabor_restitution::ImpactModel> YieldVelocity for Superposition<P> {
    fn yield_velocity(&self) -> f64 {
        self.plastic().yield_velocity()
    }
}

/// A borrowed model. Seed 000, eq. (5.103) and analogues.
impl<T: YieldVelocity + ?Sized> YieldVelocity for &T {
    fn yield_velocity(&self) -> f64 {
        (**self).yield_velocity()
    }
}

/// A boxed model. Seed 000, eq. (5.103) and analogues.
impl<T: YieldVelocity + ?Sized> YieldVelocity for Box<T> {
    fn yield_velocity(&self) -> f64 {
        (**self).yield_velocity()
    }
}
