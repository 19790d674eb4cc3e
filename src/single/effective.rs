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

/// A library error of one body's input, its parameter named as the input of that
/// body (`target_poisson_ratio` for the target's): the error names what the user
/// typed (`--target-poisson-ratio`, `--poisson-ratio`).
fn of_body(naming: Naming, target: bool) -> impl Fn(crate::restitution::Error) -> Error {
    move |e| match e {
        crate::restitution::Error::InvalidParameter {
            parameter,
            value,
            requirement,
        } => {
            let input = match (target, parameter) {
                (true, "youngs_modulus") => "target_youngs_modulus",
                (true, "poisson_ratio") => "target_poisson_ratio",
                (true, "radius") => "target_radius",
                (true, "density") => "target_density",
                (_, p) => p,
            };
            Error::Input(format!(
                "invalid {} = {}: {requirement}",
                naming.input(input),
                crate::numerics::readable::plain(value)
            ))
        }
        other => Error::Library(other),
    }
}

/// Validates `a` and computes the record of `tabor effective`; inputs are named
/// in `naming`, each body's as its own (`--poisson-ratio`,
/// `--target-poisson-ratio`).
pub fn effective(a: &EffectiveArgs, naming: Naming) -> Result<Effective, Error> {
    let sphere_input = of_body(naming, false);
    let sphere = ElasticMaterial::new(a.youngs_modulus, a.poisson_ratio).map_err(&sphere_input)?;
    let target = if a.rigid_target {
        ElasticMaterial::rigid()
    } else {
        // a target constant not given is the sphere's: an error there is the
        // sphere's input
        let input = of_body(
            naming,
            a.target_youngs_modulus.is_some() || a.target_poisson_ratio.is_some(),
        );
        ElasticMaterial::new(
            a.target_youngs_modulus.unwrap_or(a.youngs_modulus),
            a.target_poisson_ratio.unwrap_or(a.poisson_ratio),
        )
        .map_err(input)?
    };
    let m1 = match (a.mass, a.density) {
        (Some(m), _) => m,
        (None, Some(rho)) => sphere_mass(a.radius, rho).map_err(&sphere_input)?,
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
        (None, Some(rho), Some(r)) => Some(sphere_mass(r, rho).map_err(of_body(naming, true))?),
        (None, None, Some(r)) => match a.density {
            Some(rho) => Some(sphere_mass(r, rho).map_err(of_body(naming, true))?),
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
