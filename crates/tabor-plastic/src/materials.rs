//! Material constants of the published comparison cases: alumina spheres on steel
//! and on aluminium plates (the experiments of Kharaz and Gorham), as tabulated by
//! seed 000 (Table 5.2) and seed 001 (Table 3).

use tabor_restitution::effective::{effective_modulus, ElasticMaterial};
use tabor_restitution::Result;

/// One material: Young's modulus (Pa), Poisson's ratio, yield stress (Pa, `None`
/// for the hard sphere) and density (kg/m³, `None` when the table gives none).
///
/// Seed 000, Table 5.2; seed 001, Table 3.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Material {
    /// Name as in the table.
    pub name: &'static str,
    /// Young's modulus E (Pa).
    pub youngs_modulus: f64,
    /// Poisson's ratio ν.
    pub poisson_ratio: f64,
    /// Yield stress σ_Y (Pa).
    pub yield_stress: Option<f64>,
    /// Density ρ (kg/m³).
    pub density: Option<f64>,
}

impl Material {
    /// The effective modulus `E*` of this material against `other`
    /// (`1/E* = (1−ν1²)/E1 + (1−ν2²)/E2`).
    ///
    /// Seed 000, `Ẽ` of section 5.5.2 (Table 5.2).
    pub fn effective_modulus_with(&self, other: &Material) -> Result<f64> {
        effective_modulus(
            &ElasticMaterial::new(self.youngs_modulus, self.poisson_ratio)?,
            &ElasticMaterial::new(other.youngs_modulus, other.poisson_ratio)?,
        )
    }
}

/// Seed 000, Table 5.2: aluminium oxide (the sphere).
pub const ALUMINA_TABLE_5_2: Material = Material {
    name: "alumina (Willert 2020, Table 5.2)",
    youngs_modulus: 360e9,
    poisson_ratio: 0.23,
    yield_stress: None,
    density: None,
};
/// Seed 000, Table 5.2: steel plate (Vickers hardness 3.09 GPa after Kharaz & Gorham).
pub const STEEL_TABLE_5_2: Material = Material {
    name: "steel (Willert 2020, Table 5.2)",
    youngs_modulus: 206e9,
    poisson_ratio: 0.29,
    yield_stress: Some(1030e6),
    density: None,
};
/// Seed 000, Table 5.2: aluminium plate (Vickers hardness 1.14 GPa).
pub const ALUMINIUM_TABLE_5_2: Material = Material {
    name: "aluminium (Willert 2020, Table 5.2)",
    youngs_modulus: 70e9,
    poisson_ratio: 0.345,
    yield_stress: Some(380e6),
    density: None,
};
/// Seed 000, section 5.5.2: sphere radius 2.5 mm (m).
pub const SPHERE_RADIUS_SECTION_5_5_2: f64 = 2.5e-3;
/// Seed 000, section 5.5.2: sphere mass 0.25 g (kg).
pub const SPHERE_MASS_SECTION_5_5_2: f64 = 0.25e-3;

/// Seed 001, Table 3: aluminium oxide sphere (density from MatWeb, as cited there).
pub const ALUMINA_TABLE_3: Material = Material {
    name: "alumina (dimensionless FEM fit, Table 3)",
    youngs_modulus: 370e9,
    poisson_ratio: 0.22,
    yield_stress: None,
    density: Some(3958.226),
};
/// Seed 001, Table 3: aluminium substrate.
pub const ALUMINIUM_TABLE_3: Material = Material {
    name: "aluminium (dimensionless FEM fit, Table 3)",
    youngs_modulus: 68e9,
    poisson_ratio: 0.33,
    yield_stress: Some(0.38e9),
    density: None,
};
/// Seed 001, Table 3: steel substrate.
pub const STEEL_TABLE_3: Material = Material {
    name: "steel (dimensionless FEM fit, Table 3)",
    youngs_modulus: 200e9,
    poisson_ratio: 0.29,
    yield_stress: Some(1.03e9),
    density: None,
};
