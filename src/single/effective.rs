//! The effective properties of a collision of a sphere with a second sphere or a
//! flat half-space (`tabor effective`, `tabor.effective`).

use super::{Error, Naming};
use crate::restitution::effective::{
    effective_modulus, effective_radius, reduced_mass, sphere_mass,
};
use crate::restitution::ElasticMaterial;
use serde::Serialize;

/// The inputs of `tabor effective`, named like its flags. Conflicting inputs
/// (`density` and `mass`, `rigid_target` and the target's elastic constants,
/// `target_density` and `target_mass`) are the front end's to reject.
#[derive(Clone, Copy, Debug)]
pub struct EffectiveArgs {
    /// Young's modulus of the sphere (Pa).
    pub youngs_modulus: f64,
    /// Poisson's ratio of the sphere.
    pub poisson_ratio: f64,
    /// Radius of the sphere (m).
    pub radius: f64,
    /// Density of the sphere (kg/m³); or give `mass`.
    pub density: Option<f64>,
    /// Mass of the sphere (kg).
    pub mass: Option<f64>,
    /// Young's modulus of the target (Pa); default: same as the sphere.
    pub target_youngs_modulus: Option<f64>,
    /// Poisson's ratio of the target; default: same as the sphere.
    pub target_poisson_ratio: Option<f64>,
    /// The target is rigid.
    pub rigid_target: bool,
    /// Radius of the target (m); `None` for a flat half-space.
    pub target_radius: Option<f64>,
    /// Density of the target (kg/m³), for a spherical target (default: the
    /// sphere's density; with neither density nor `target_mass` the target is
    /// immovable).
    pub target_density: Option<f64>,
    /// Mass of the target (kg); `None` for an immovable target.
    pub target_mass: Option<f64>,
}

/// The result record of `tabor effective`.
#[derive(Clone, Debug, Serialize)]
pub struct Effective {
    /// Effective modulus E* (Pa).
    pub effective_modulus: f64,
    /// Effective radius R (m).
    pub effective_radius: f64,
    /// Effective (reduced) mass m (kg).
    pub effective_mass: f64,
}

/// Validates `a` and computes the record of `tabor effective`; missing inputs are
/// named in `naming`. A library error names the parameter as the library does
/// (`youngs_modulus`, `radius`, …): the flags differ between the two bodies, so
/// no front end renames it.
pub fn effective(a: &EffectiveArgs, naming: Naming) -> Result<Effective, Error> {
    let sphere = ElasticMaterial::new(a.youngs_modulus, a.poisson_ratio)?;
    let target = if a.rigid_target {
        ElasticMaterial::rigid()
    } else {
        ElasticMaterial::new(
            a.target_youngs_modulus.unwrap_or(a.youngs_modulus),
            a.target_poisson_ratio.unwrap_or(a.poisson_ratio),
        )?
    };
    let m1 = match (a.mass, a.density) {
        (Some(m), _) => m,
        (None, Some(rho)) => sphere_mass(a.radius, rho)?,
        (None, None) => {
            return Err(Error::Input(format!(
                "give the sphere's {} or {}",
                naming.input("density"),
                naming.input("mass")
            )))
        }
    };
    let m2 = match (a.target_mass, a.target_density, a.target_radius) {
        (Some(m), _, _) => Some(m),
        (None, Some(rho), Some(r)) => Some(sphere_mass(r, rho)?),
        (None, None, Some(r)) => match a.density {
            Some(rho) => Some(sphere_mass(r, rho)?),
            None => None,
        },
        (None, Some(_), None) => {
            return Err(Error::Input(format!(
                "{} needs {}",
                naming.input("target_density"),
                naming.input("target_radius")
            )));
        }
        (None, None, None) => None,
    };
    Ok(Effective {
        effective_modulus: effective_modulus(&sphere, &target)?,
        effective_radius: effective_radius(a.radius, a.target_radius)?,
        effective_mass: reduced_mass(m1, m2)?,
    })
}
