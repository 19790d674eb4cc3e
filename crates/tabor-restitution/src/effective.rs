//! Effective properties of a two-body collision: the central impact of two spheres
//! (or a sphere and a half-space) is equivalent to a rigid sphere of effective
//! radius and reduced mass hitting a half-space of effective modulus (seed 000,
//! introduction of chapter 5).

use crate::validate;
use crate::Result;
use serde::Serialize;

/// An isotropic linear-elastic material: Young's modulus E (Pa) and Poisson's ratio ν.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct ElasticMaterial {
    youngs_modulus: f64,
    poisson_ratio: f64,
}

impl ElasticMaterial {
    /// A material with Young's modulus `youngs_modulus` > 0 (Pa) and Poisson's ratio
    /// −1 < `poisson_ratio` ≤ 1/2.
    pub fn new(youngs_modulus: f64, poisson_ratio: f64) -> Result<Self> {
        Ok(ElasticMaterial {
            youngs_modulus: validate::positive("youngs_modulus", youngs_modulus)?,
            poisson_ratio: validate::poisson_ratio("poisson_ratio", poisson_ratio)?,
        })
    }

    /// A rigid body (infinite modulus): its compliance is zero.
    pub const fn rigid() -> Self {
        ElasticMaterial {
            youngs_modulus: f64::INFINITY,
            poisson_ratio: 0.0,
        }
    }

    /// Young's modulus E (Pa); infinite for [`ElasticMaterial::rigid`].
    pub fn youngs_modulus(&self) -> f64 {
        self.youngs_modulus
    }

    /// Poisson's ratio ν.
    pub fn poisson_ratio(&self) -> f64 {
        self.poisson_ratio
    }

    /// The plane-strain modulus E/(1 − ν²).
    pub fn plane_strain_modulus(&self) -> f64 {
        self.youngs_modulus / (1.0 - self.poisson_ratio * self.poisson_ratio)
    }

    /// The contact compliance (1 − ν²)/E (1/Pa).
    pub fn compliance(&self) -> f64 {
        (1.0 - self.poisson_ratio * self.poisson_ratio) / self.youngs_modulus
    }
}

/// The effective modulus E* of a contact, `1/E* = (1 − ν1²)/E1 + (1 − ν2²)/E2`.
///
/// Seed 000 chapter 5 (the symbol Ẽ); at least one body must be deformable, else an
/// error names `youngs_modulus`.
pub fn effective_modulus(first: &ElasticMaterial, second: &ElasticMaterial) -> Result<f64> {
    let compliance = first.compliance() + second.compliance();
    // 1/compliance overflows for moduli near f64::MAX: checked too
    if compliance > 0.0 && compliance.is_finite() && (1.0 / compliance).is_finite() {
        Ok(1.0 / compliance)
    } else {
        Err(crate::Error::invalid(
            "youngs_modulus",
            f64::INFINITY,
            "at least one body must be deformable",
        ))
    }
}

/// The effective radius R, `1/R = 1/R1 + 1/R2`; `second = None` is a flat
/// half-space (R = R1). Seed 000 chapter 5 (the symbol R̃).
pub fn effective_radius(first: f64, second: Option<f64>) -> Result<f64> {
    let r1 = validate::positive("radius", first)?;
    match second {
        None => Ok(r1),
        Some(r2) => {
            let r2 = validate::positive("target radius", r2)?;
            validate::positive("radius", harmonic_half(r1, r2))
        }
    }
}

/// The reduced mass m, `1/m = 1/m1 + 1/m2`; `second = None` is an immovable
/// half-space (m = m1). Seed 000 chapter 5 (the symbol m̃).
pub fn reduced_mass(first: f64, second: Option<f64>) -> Result<f64> {
    let m1 = validate::positive("mass", first)?;
    match second {
        None => Ok(m1),
        Some(m2) => {
            let m2 = validate::positive("target mass", m2)?;
            validate::positive("mass", harmonic_half(m1, m2))
        }
    }
}

/// `a b/(a + b)` for finite a, b > 0; when the product overflows or underflows
/// (radii or masses near the ends of the f64 range) the same value is computed as
/// `min/(1 + min/max)`, which stays finite and positive.
fn harmonic_half(a: f64, b: f64) -> f64 {
    let direct = a * b / (a + b);
    if direct.is_finite() && direct > 0.0 {
        direct
    } else {
        let (lo, hi) = if a <= b { (a, b) } else { (b, a) };
        lo / (1.0 + lo / hi)
    }
}

/// The mass of a homogeneous sphere, (4/3) π R³ ρ.
pub fn sphere_mass(radius: f64, density: f64) -> Result<f64> {
    let r = validate::positive("radius", radius)?;
    let rho = validate::positive("density", density)?;
    validate::positive("mass", 4.0 / 3.0 * std::f64::consts::PI * r * r * r * rho)
}
