//! `tabor plastic`: elasto-plastic impact with and without adhesion (seed 000,
//! sections 5.5-5.6, (5.101)-(5.126); seed 001, eqs. (12), (18), (19)): energy loss,
//! restitution, yield velocity and, for the adhesive models, sticking velocity.

use crate::output::{message, print_json, print_table, stdout, Outcome};
use serde::Serialize;
use std::io::Write;
use tabor::jkr::JkrSphere;
use tabor::plastic::{
    AdhesiveInterpolationImpact, AdhesivePlasticContact, Clamping, DimensionlessFit, Interpolation,
    JacksonGreen, PlasticContact, PlasticImpact, SimulationSettings, Superposition, Thornton,
};
use tabor::restitution::{impact, sticking_velocity, EnergyLoss, ImpactModel};

/// A boxed model, so that the superposition can wrap whichever one was chosen.
struct Boxed(Box<dyn ImpactModel>);

impl ImpactModel for Boxed {
    fn name(&self) -> String {
        self.0.name()
    }
    fn effective_mass(&self) -> f64 {
        self.0.effective_mass()
    }
    fn energy_loss(&self, impact_speed: f64) -> tabor::restitution::Result<EnergyLoss> {
        self.0.energy_loss(impact_speed)
    }
    fn loss_is_speed_independent(&self) -> bool {
        self.0.loss_is_speed_independent()
    }
    fn speed_scale(&self) -> f64 {
        self.0.speed_scale()
    }
}

/// Which elasto-plastic model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Model {
    /// Thornton (5.101)-(5.106)
    Thornton,
    /// Interpolation model, Q = 5, D = 80 (5.107)
    Interpolation,
    /// Jackson-Green FEM-based law, time-domain simulation (5.108); needs --poisson-ratio
    JacksonGreen,
    /// Seed 001 fitted restitution (12), (18), (19); needs --density
    DimensionlessFit,
    /// Adhesive interpolation model (5.111)-(5.126); needs --work-of-adhesion
    AdhesiveInterpolation,
    /// Plastic + JKR losses (5.109)-(5.110); needs --work-of-adhesion
    Superposition,
}

/// The non-adhesive model under `--model superposition`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum PlasticModel {
    /// Thornton (5.101)-(5.106)
    Thornton,
    /// Interpolation model (5.107)
    Interpolation,
    /// Jackson-Green (5.108); needs --poisson-ratio
    JacksonGreen,
    /// Seed 001 fit; needs --density
    DimensionlessFit,
}

/// Arguments of `tabor plastic`. All inputs are effective quantities of the collision.
#[derive(clap::Args)]
#[command(
    after_help = "Inputs are the effective quantities of the collision: E* with \
    1/E* = (1-nu1^2)/E1 + (1-nu2^2)/E2, R with 1/R = 1/R1 + 1/R2, the reduced mass m \
    (see `tabor effective`), and the yield stress of the softer (yielding) body.\n\n\
    Which model needs which flag:\n  \
    thornton, interpolation      --modulus --radius --mass --yield-stress --speed\n  \
    jackson-green                + --poisson-ratio (of the yielding body; hardness H/sigma_Y = 2.67)\n  \
    dimensionless-fit            + --density (of the sphere, seed 001)\n  \
    adhesive-interpolation       + --work-of-adhesion (or --adhesion-parameter to give Phi)\n  \
    superposition                + --work-of-adhesion, --plastic-model (default interpolation)\n\
    With --json the output has model, restitution, energy_loss, yield_velocity, \
    sticking_velocity (adhesive models) and warnings."
)]
pub struct Args {
    /// The model
    #[arg(long, value_enum)]
    model: Model,
    /// Effective modulus E* (Pa)
    #[arg(long, allow_negative_numbers = true)]
    modulus: f64,
    /// Effective radius R (m)
    #[arg(long, allow_negative_numbers = true)]
    radius: f64,
    /// Effective (reduced) mass m (kg)
    #[arg(long, allow_negative_numbers = true)]
    mass: f64,
    /// Yield stress sigma_Y of the yielding body (Pa)
    #[arg(long, allow_negative_numbers = true)]
    yield_stress: f64,
    /// Relative impact speed v0 (m/s)
    #[arg(long, allow_negative_numbers = true)]
    speed: f64,
    /// Poisson's ratio of the yielding body (jackson-green)
    #[arg(long, allow_negative_numbers = true)]
    poisson_ratio: Option<f64>,
    /// Density of the sphere (kg/m³) (dimensionless-fit)
    #[arg(long, allow_negative_numbers = true)]
    density: Option<f64>,
    /// Work of adhesion Δγ (J/m²) (adhesive-interpolation, superposition)
    #[arg(long, allow_negative_numbers = true)]
    work_of_adhesion: Option<f64>,
    /// Adhesion parameter Phi, instead of computing it from the material data
    /// (adhesive-interpolation)
    #[arg(long, allow_negative_numbers = true)]
    adhesion_parameter: Option<f64>,
    /// The non-adhesive model of --model superposition
    #[arg(long, value_enum, default_value = "interpolation")]
    plastic_model: PlasticModel,
    /// Print one JSON object instead of a table
    #[arg(long)]
    json: bool,
}

#[derive(Serialize)]
struct Plastic {
    model: String,
    branch: String,
    impact_speed: f64,
    /// ε (5.37) in [0, 1].
    restitution: f64,
    /// |ΔU_kin| (J), capped at m v0²/2 when sticking.
    energy_loss: f64,
    sticks: bool,
    /// Speed where plastic deformation begins (m/s).
    yield_velocity: f64,
    #[serde(skip_serializing_if = "Option::is_none")]
    sticking_velocity: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    elastic_sticking_velocity: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    adhesion_parameter: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    clamping: Option<Clamping>,
    warnings: Vec<String>,
}

fn required(value: Option<f64>, name: &str, model: &str) -> Result<f64, String> {
    value.ok_or_else(|| format!("missing {name}: required by --model {model}"))
}

/// A non-adhesive model boxed, with its yield velocity and any clamping report.
struct NonAdhesive {
    model: Box<dyn ImpactModel>,
    yield_velocity: f64,
    clamping: Option<Clamping>,
}

fn non_adhesive(args: &Args, which: PlasticModel) -> Result<NonAdhesive, String> {
    let contact =
        PlasticContact::new(args.modulus, args.radius, args.yield_stress).map_err(message)?;
    Ok(match which {
        PlasticModel::Thornton => {
            let m = PlasticImpact::new(contact, Thornton, args.mass).map_err(message)?;
            NonAdhesive {
                yield_velocity: m.yield_velocity(),
                model: Box::new(m),
                clamping: None,
            }
        }
        PlasticModel::Interpolation => {
            let m = PlasticImpact::new(contact, Interpolation::default(), args.mass)
                .map_err(message)?;
            NonAdhesive {
                yield_velocity: m.yield_velocity(),
                model: Box::new(m),
                clamping: None,
            }
        }
        PlasticModel::JacksonGreen => {
            let nu = required(args.poisson_ratio, "--poisson-ratio", "jackson-green")?;
            let m = PlasticContact::new(args.modulus, args.radius, args.yield_stress)
                .and_then(|contact| JacksonGreen::new(contact, nu))
                .map_err(message)?
                .impact(args.mass, SimulationSettings::default())
                .map_err(message)?;
            NonAdhesive {
                yield_velocity: m.yield_velocity(),
                model: Box::new(m),
                clamping: None,
            }
        }
        PlasticModel::DimensionlessFit => {
            let rho = required(args.density, "--density", "dimensionless-fit")?;
            let m = DimensionlessFit::new(args.modulus, args.yield_stress, rho, args.mass)
                .map_err(message)?;
            let clamping = m.restitution(args.speed).map_err(message)?.clamping;
            NonAdhesive {
                yield_velocity: m.yield_velocity(),
                model: Box::new(m),
                clamping: Some(clamping),
            }
        }
    })
}

/// Runs `tabor plastic`.
pub fn run(args: &Args) -> Outcome {
    let mut warnings = Vec::new();
    let mut sticking = None;
    let mut elastic_sticking = None;
    let mut phi = None;
    let (model, yield_velocity, clamping): (Box<dyn ImpactModel>, f64, Option<Clamping>) =
        match args.model {
            Model::Thornton => {
                let n = non_adhesive(args, PlasticModel::Thornton)?;
                (n.model, n.yield_velocity, n.clamping)
            }
            Model::Interpolation => {
                let n = non_adhesive(args, PlasticModel::Interpolation)?;
                (n.model, n.yield_velocity, n.clamping)
            }
            Model::JacksonGreen => {
                let n = non_adhesive(args, PlasticModel::JacksonGreen)?;
                (n.model, n.yield_velocity, n.clamping)
            }
            Model::DimensionlessFit => {
                let n = non_adhesive(args, PlasticModel::DimensionlessFit)?;
                (n.model, n.yield_velocity, n.clamping)
            }
            Model::Superposition => {
                let dg = required(args.work_of_adhesion, "--work-of-adhesion", "superposition")?;
                let n = non_adhesive(args, args.plastic_model)?;
                let sphere = JkrSphere::new(args.modulus, args.radius, dg).map_err(message)?;
                let sup = Superposition::new(Boxed(n.model), sphere).map_err(message)?;
                elastic_sticking = Some(
                    sticking_velocity(sup.adhesive(), 1e-12)
                        .map_err(message)?
                        .speed,
                );
                (Box::new(sup), n.yield_velocity, n.clamping)
            }
            Model::AdhesiveInterpolation => {
                let dg = required(
                    args.work_of_adhesion,
                    "--work-of-adhesion",
                    "adhesive-interpolation",
                )?;
                // Validates E*, R, sigma_Y even when Phi is given.
                PlasticContact::new(args.modulus, args.radius, args.yield_stress)
                    .map_err(message)?;
                let m = JkrSphere::new(args.modulus, args.radius, dg)
                    .and_then(|sphere| match args.adhesion_parameter {
                        Some(p) => AdhesivePlasticContact::new(sphere, p),
                        None => {
                            AdhesivePlasticContact::from_yield_stress(sphere, args.yield_stress)
                        }
                    })
                    .and_then(|contact| AdhesiveInterpolationImpact::new(contact, args.mass))
                    .map_err(message)?;
                if args.adhesion_parameter.is_some() {
                    warnings.push(
                        "adhesion parameter Phi given directly: --yield-stress is checked but \
                         not used (the model depends on v0/v_c and Phi only)"
                            .to_string(),
                    );
                }
                phi = Some(m.model().adhesion_parameter());
                elastic_sticking = Some(m.elastic_sticking_velocity());
                if m.yield_velocity() == 0.0 {
                    warnings.push(
                        "the adhesive yield load (5.111) is reached inside the JKR adhesive \
                         well: every impact deforms plastically (yield_velocity 0)"
                            .to_string(),
                    );
                }
                let v_y = m.yield_velocity();
                (Box::new(m), v_y, None)
            }
        };
    if matches!(
        args.model,
        Model::Superposition | Model::AdhesiveInterpolation
    ) {
        sticking = Some(sticking_velocity(&*model, 1e-10).map_err(message)?.speed);
    }
    let outcome = impact(&*model, args.speed).map_err(message)?;
    match clamping {
        Some(Clamping::ToOne) => warnings.push(
            "seed 001 fit gave a restitution above 1 (just above its yield velocity): clamped to 1"
                .into(),
        ),
        Some(Clamping::ToZero) => warnings
            .push("seed 001 fit gave a negative restitution: clamped to 0 (sticking)".into()),
        _ => {}
    }
    if args.speed <= yield_velocity && args.model != Model::AdhesiveInterpolation {
        warnings.push("impact speed at or below the yield velocity: elastic impact".into());
    }
    let out = Plastic {
        model: outcome.model.clone(),
        branch: outcome.branch.clone(),
        impact_speed: args.speed,
        restitution: outcome.restitution,
        energy_loss: outcome.energy_loss,
        sticks: outcome.sticks,
        yield_velocity,
        sticking_velocity: sticking,
        elastic_sticking_velocity: elastic_sticking,
        adhesion_parameter: phi,
        clamping,
        warnings,
    };
    if args.json {
        return print_json(&out);
    }
    let mut stdout = stdout();
    writeln!(stdout, "model   {}", out.model)?;
    writeln!(stdout, "branch  {}", out.branch)?;
    let mut rows = vec![
        ("impact_speed", out.impact_speed, "m/s"),
        ("restitution", out.restitution, ""),
        ("energy_loss", out.energy_loss, "J"),
        ("yield_velocity", out.yield_velocity, "m/s"),
    ];
    if let Some(v) = out.sticking_velocity {
        rows.push(("sticking_velocity", v, "m/s"));
    }
    if let Some(v) = out.elastic_sticking_velocity {
        rows.push(("elastic_sticking_velocity", v, "m/s"));
    }
    if let Some(p) = out.adhesion_parameter {
        rows.push(("adhesion_parameter", p, ""));
    }
    print_table(&mut stdout, &rows)?;
    for w in &out.warnings {
        writeln!(stdout, "warning: {w}")?;
    }
    stdout.finish()
}
