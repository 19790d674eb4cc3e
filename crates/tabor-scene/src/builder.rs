//! Building a scene in code ([`SceneBuilder`]), validated exactly as a file.

use crate::error::SceneError;
use crate::file::{AdhesionFile, BodyFile, ImpactFile, PlasticityFile, SceneFile};
use crate::scene::Scene;
use tabor_jkr::SeparationRule;
use tabor_restitution::ElasticMaterial;

/// An elastic sphere for [`SceneBuilder::sphere`] and [`SceneBuilder::target_sphere`]:
/// radius (m), density (kg/m³) and elastic material (Young's modulus, Poisson's
/// ratio). The radius and density are checked by [`SceneBuilder::build`], as in a file.
///
/// Seed 000, introduction of chapter 5 (a sphere of radius `R_i`, mass
/// `m_i = (4/3)π R_i³ ρ_i`, modulus `E_i` and Poisson's ratio `ν_i`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ElasticSphere {
    /// Radius (m).
    pub radius: f64,
    /// Density (kg/m³).
    pub density: f64,
    /// Young's modulus and Poisson's ratio.
    pub material: ElasticMaterial,
}

impl ElasticSphere {
    /// The scene-file section of this sphere.
    fn body_file(&self) -> BodyFile {
        BodyFile {
            radius: Some(self.radius),
            density: Some(self.density),
            youngs_modulus: self.material.youngs_modulus(),
            poisson_ratio: self.material.poisson_ratio(),
            ..BodyFile::default()
        }
    }
}

/// Builds a scene in code; [`SceneBuilder::build`] validates it exactly as a file.
#[derive(Clone, Debug, Default)]
pub struct SceneBuilder {
    data: SceneFile,
}

impl SceneBuilder {
    /// A new builder: the sphere and the target need at least their elastic
    /// constants (and the sphere a radius and density or mass).
    pub fn new() -> Self {
        SceneBuilder::default()
    }
    /// The sphere (radius, density, elastic material).
    ///
    /// Seed 000, introduction of chapter 5 (the impacting sphere of radius `R1`, mass
    /// `m1` and material `E1`, `ν1`).
    pub fn sphere(mut self, sphere: ElasticSphere) -> Self {
        self.data.sphere = sphere.body_file();
        self
    }
    /// A spherical target (radius, density, elastic material).
    ///
    /// Seed 000, introduction of chapter 5 (`1/R = 1/R1 + 1/R2`, `1/m = 1/m1 + 1/m2`).
    pub fn target_sphere(mut self, target: ElasticSphere) -> Self {
        self.data.target = target.body_file();
        self
    }
    /// A flat half-space target of elastic material `material`; its density (kg/m³)
    /// optional (for the quasi-static check).
    ///
    /// Seed 000, introduction of chapter 5 (`R2 → ∞`: `R = R1`).
    pub fn target_half_space(mut self, material: ElasticMaterial, density: Option<f64>) -> Self {
        self.data.target = BodyFile {
            density,
            youngs_modulus: material.youngs_modulus(),
            poisson_ratio: material.poisson_ratio(),
            ..BodyFile::default()
        };
        self
    }
    /// The target's yield stress (Pa).
    pub fn target_yield_stress(mut self, yield_stress: f64) -> Self {
        self.data.target.yield_stress = Some(yield_stress);
        self
    }
    /// JKR adhesion with work of adhesion Δγ (J/m²).
    pub fn adhesion(mut self, work_of_adhesion: f64) -> Self {
        self.data.adhesion = Some(AdhesionFile {
            work_of_adhesion,
            ..AdhesionFile::default()
        });
        self
    }
    /// The range of adhesion h (m): Maugis-Dugdale adhesion.
    pub fn adhesion_range(mut self, range: f64) -> Self {
        self.data
            .adhesion
            .get_or_insert_with(AdhesionFile::default)
            .range = Some(range);
        self
    }
    /// The Tabor parameter Λ directly.
    pub fn tabor_parameter(mut self, lambda: f64) -> Self {
        self.data
            .adhesion
            .get_or_insert_with(AdhesionFile::default)
            .tabor_parameter = Some(lambda);
        self
    }
    /// The JKR separation rule ("fixed-grip" or "load-controlled").
    pub fn separation(mut self, rule: SeparationRule) -> Self {
        self.data
            .adhesion
            .get_or_insert_with(AdhesionFile::default)
            .separation = Some(rule.as_str().to_string());
        self
    }
    /// The plasticity model name.
    pub fn plasticity_model(mut self, model: &str) -> Self {
        self.data
            .plasticity
            .get_or_insert_with(PlasticityFile::default)
            .model = Some(model.into());
        self
    }
    /// The impact speed (m/s).
    pub fn speed(mut self, speed: f64) -> Self {
        self.data
            .impact
            .get_or_insert_with(ImpactFile::default)
            .speed = Some(speed);
        self
    }
    /// The requested relative accuracy.
    pub fn accuracy(mut self, accuracy: f64) -> Self {
        self.data.accuracy = Some(accuracy);
        self
    }
    /// Validates and builds the scene.
    pub fn build(self) -> Result<Scene, SceneError> {
        Scene::from_data(self.data)
    }
}
