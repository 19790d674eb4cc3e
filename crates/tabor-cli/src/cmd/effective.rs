//! `tabor effective`: the effective properties of a collision of a sphere with a
//! second sphere or a flat half-space.

use crate::output::{print_result, Outcome};
use tabor::single::effective::{effective, EffectiveArgs};
use tabor::single::Naming;

/// Arguments of `tabor effective`.
#[derive(clap::Args)]
pub struct Args {
    /// Young's modulus of the sphere (Pa)
    #[arg(long, allow_hyphen_values = true)]
    youngs_modulus: f64,
    /// Poisson's ratio of the sphere
    #[arg(long, allow_hyphen_values = true)]
    poisson_ratio: f64,
    /// Radius of the sphere (m)
    #[arg(long, allow_hyphen_values = true)]
    radius: f64,
    /// Density of the sphere (kg/m³); or give --mass
    #[arg(long, allow_hyphen_values = true, conflicts_with = "mass")]
    density: Option<f64>,
    /// Mass of the sphere (kg)
    #[arg(long, allow_hyphen_values = true)]
    mass: Option<f64>,
    /// Young's modulus of the target (Pa); default: same as the sphere
    #[arg(long, allow_hyphen_values = true, conflicts_with = "rigid_target")]
    target_youngs_modulus: Option<f64>,
    /// Poisson's ratio of the target; default: same as the sphere
    #[arg(long, allow_hyphen_values = true, conflicts_with = "rigid_target")]
    target_poisson_ratio: Option<f64>,
    /// The target is rigid
    #[arg(long)]
    rigid_target: bool,
    /// Radius of the target (m); omit for a flat half-space
    #[arg(long, allow_hyphen_values = true)]
    target_radius: Option<f64>,
    /// Density of the target (kg/m³), for a spherical target (default: the sphere's
    /// --density; with neither density nor --target-mass the target is immovable)
    #[arg(long, allow_hyphen_values = true, conflicts_with = "target_mass")]
    target_density: Option<f64>,
    /// Mass of the target (kg); omit for an immovable target
    #[arg(long, allow_hyphen_values = true)]
    target_mass: Option<f64>,
    /// Print one JSON object instead of a table
    #[arg(long)]
    json: bool,
}

/// Runs `tabor effective`.
pub fn run(args: &Args) -> Outcome {
    // The library names the parameter (`youngs_modulus`, `radius`, …); the flags
    // differ between the two bodies, so the shared flag table is not used here.
    let out = effective(
        &EffectiveArgs {
            youngs_modulus: args.youngs_modulus,
            poisson_ratio: args.poisson_ratio,
            radius: args.radius,
            density: args.density,
            mass: args.mass,
            target_youngs_modulus: args.target_youngs_modulus,
            target_poisson_ratio: args.target_poisson_ratio,
            rigid_target: args.rigid_target,
            target_radius: args.target_radius,
            target_density: args.target_density,
            target_mass: args.target_mass,
        },
        Naming::Flags,
    )
    .map_err(|e| e.message(|e| e.to_string()))?;
    let rows = [
        ("effective_modulus", out.effective_modulus, "Pa"),
        ("effective_radius", out.effective_radius, "m"),
        ("effective_mass", out.effective_mass, "kg"),
    ];
    print_result(args.json, &out, &[], &rows, &[])
}
