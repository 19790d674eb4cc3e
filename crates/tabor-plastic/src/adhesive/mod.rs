//! The adhesive interpolation model: JKR loading to the adhesive yield onset, cubic
//! elasto-plastic interpolation, fully plastic law; JKR unloading with the radius
//! `R_p` and residual depth `d_res`; separation at the displacement-controlled
//! instability. Seed 000, eqs. (5.111)-(5.126).
//!
//! - `normalized`: the normalized core ([`AdhesiveInterpolation`], the yield
//!   fit (5.111), the turning point and JKR unloading (5.121)-(5.125));
//! - `impact`: the SI shell [`AdhesiveInterpolationImpact`], an `ImpactModel`;
//! - `force_law`: [`AdhesiveForceLaw`], the time-domain force law.
//!
//! Normalized core in the units of the JKR force-controlled critical state (seed 000
//! eq. (5.43): `a_c = (9πΔγR²/(8E*))^(1/3)`, `F_n = (3/2)πΔγR`, `d_n = a_c²/(3R)`,
//! energies in `F_n d_n`; `tabor_jkr::normalized` documents them), force positive in
//! compression. The JKR relations are those of `tabor_jkr::normalized`.

mod force_law;
mod impact;
mod normalized;

pub use force_law::AdhesiveForceLaw;
pub use impact::{AdhesiveInterpolationImpact, AdhesivePlasticContact};
pub use normalized::{
    adhesion_parameter, adhesive_yield_force, AdhesiveInterpolation, AdhesiveTurningPoint,
    ADHESION_PARAMETER_FACTOR, ADHESIVE_PLASTIC_ONSET, ADHESIVE_PLASTIC_SLOPE,
    WEAK_ADHESION_YIELD_COEFFICIENT,
};

/// The model's name in errors.
const MODEL: &str = "adhesive interpolation";
