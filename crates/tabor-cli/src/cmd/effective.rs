//! `tabor effective`: the effective properties of a collision of a sphere with a
//! second sphere or a flat half-space.

use crate::output::{print_json, print_table, stdout, Outcome};
use serde::Serialize;
use tabor::restitution::effective::{
    effective_modulus, effective_radius, reduced_mass, sphere_mass,
};
use tabor::restitution::ElasticMaterial;

/// Arguments of `tabor effective`.
#[derive(clap::Args)]
pub struct Args {
    /// Young's modulus of the sphere (Pa)
    #[arg(long, allow_negative_numbers = true)]
    youngs_modulus: f64,
    /// Poisson's ratio of the sphere
    #[arg(long, allow_negative_numbers = true)]
    poisson_ratio: f64,
    /// Radius of the sphere (m)
    #[arg(long, allow_negative_numbers = true)]
    radius: f64,
    /// Density of the sphere (kg/m³); or give --mass
    #[arg(long, allow_negative_numbers = true, conflicts_with = "mass")]
    density: Option<f64>,
    /// Mass of the sphere (kg)
    #[arg(long, allow_negative_numbers = true)]
    mass: Option<f64>,
    /// Young's modulus of the target (Pa); default: same as the sphere
    #[arg(long, allow_negative_numbers = true, conflicts_with = "rigid_target")]
    target_youngs_modulus: Option<f64>,
    /// Poisson's ratio of the target; default: same as the sphere
    #[arg(long, allow_negative_numbers = true, conflicts_with = "rigid_target")]
    target_poisson_ratio: Option<f64>,
    /// The target is rigid
    #[arg(long)]
    rigid_target: bool,
    /// Radius of the target (m); omit for a flat half-space
    #[arg(long, allow_negative_numbers = true)]
    target_radius: Option<f64>,
    /// Density of the target (kg/m³), for a spherical target (default: the sphere's
    /// --density; with neither density nor --target-mass the target is immovable)
    #[arg(long, allow_negative_numbers = true, conflicts_with = "target_mass")]
    target_density: Option<f64>,
    /// Mass of the target (kg); omit for an immovable target
    #[arg(long, allow_negative_numbers = true)]
    target_mass: Option<f64>,
    /// Print one JSON object instead of a table
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Effective {
    effective_modulus: f64,
    effective_radius: f64,
    effective_mass: f64,
}

/// Runs `tabor effective`.
pub fn run(args: &Args) -> Outcome {
    // The library names the parameter (`youngs_modulus`, `radius`, …); the flags
    // differ between the two bodies, so the shared flag table is not used here.
    let err = |e: tabor::restitution::Error| e.to_string();
    let sphere = ElasticMaterial::new(args.youngs_modulus, args.poisson_ratio).map_err(err)?;
    let target = if args.rigid_target {
        ElasticMaterial::rigid()
    } else {
        ElasticMaterial::new(
            args.target_youngs_modulus.unwrap_or(args.youngs_modulus),
            args.target_poisson_ratio.unwrap_or(args.poisson_ratio),
        )
        .map_err(err)?
    };
    let m1 = match (args.mass, args.density) {
        (Some(m), _) => m,
        (None, Some(rho)) => sphere_mass(args.radius, rho).map_err(err)?,
        (None, None) => return Err("give the sphere's --density or --mass".into()),
    };
    let m2 = match (args.target_mass, args.target_density, args.target_radius) {
        (Some(m), _, _) => Some(m),
        (None, Some(rho), Some(r)) => Some(sphere_mass(r, rho).map_err(err)?),
        (None, None, Some(r)) => match args.density {
            Some(rho) => Some(sphere_mass(r, rho).map_err(err)?),
            None => None,
        },
        (None, Some(_), None) => {
            return Err("--target-density needs --target-radius".into());
        }
        (None, None, None) => None,
    };
    let out = Effective {
        effective_modulus: effective_modulus(&sphere, &target).map_err(err)?,
        effective_radius: effective_radius(args.radius, args.target_radius).map_err(err)?,
        effective_mass: reduced_mass(m1, m2).map_err(err)?,
    };
    if args.json {
        print_json(&out)
    } else {
        let mut stdout = stdout();
        print_table(
            &mut stdout,
            &[
                ("effective_modulus", out.effective_modulus, "Pa"),
                ("effective_radius", out.effective_radius, "m"),
                ("effective_mass", out.effective_mass, "kg"),
            ],
        )?;
        stdout.finish()
    }
}
