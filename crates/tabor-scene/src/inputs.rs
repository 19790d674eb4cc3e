//! The validated physical description of a scene: the bodies, the interface, the
//! plasticity choice, the requested accuracy and the effective quantities every
//! model needs (seed 000, introduction of chapter 5).

use crate::error::{in_field, SceneError};
use crate::file::{AdhesionFile, BodyFile, DampingFile, GradationFile, PlasticityFile, SceneFile};
use serde::Serialize;
use tabor_jkr::SeparationRule;
use tabor_maugis::units::{
    tabor_parameter_from_cohesive_stress, tabor_parameter_from_maugis, tabor_parameter_from_range,
    tabor_parameter_from_tabor_mu,
};
use tabor_restitution::effective::{
    effective_modulus, effective_radius, reduced_mass, sphere_mass,
};
use tabor_restitution::{validate, ElasticMaterial, Error};
use tabor_viscoadhesive::{DampingModel, NormalDamping};

/// The default requested relative accuracy.
pub const DEFAULT_ACCURACY: f64 = tabor_numerics::tolerance::ACCURACY;

/// A body of the scene, validated.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Body {
    /// Radius (m); `None` for a flat half-space target.
    pub radius: Option<f64>,
    /// Mass (kg); `None` for an immovable half-space target.
    pub mass: Option<f64>,
    /// Density (kg/m³), when given or derivable from mass and radius.
    pub density: Option<f64>,
    /// Elastic constants.
    pub material: ElasticMaterial,
    /// Yield stress (Pa), when plastic.
    pub yield_stress: Option<f64>,
    /// Shear viscosity (Pa·s), when viscoelastic.
    pub viscosity: Option<f64>,
    /// Gradation `(k, c_N)`, when graded.
    pub gradation: Option<(f64, f64)>,
}

/// How the adhesive stress is specified.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "kind", content = "value")]
pub enum AdhesionRange {
    /// No range given: the JKR limit.
    Jkr,
    /// The seed's Tabor parameter Λ (derived or given).
    TaborParameter(f64),
}

/// The adhesive interface, validated.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Adhesion {
    /// Work of adhesion Δγ (J/m²), ≥ 0.
    pub work_of_adhesion: f64,
    /// The Tabor parameter, when a range, cohesive stress, Λ, λ or μ was given.
    pub range: AdhesionRange,
    /// The JKR separation rule.
    pub separation: SeparationRule,
}

/// How adhesion and plasticity combine (the menu of `tabor-plastic`).
pub use tabor_plastic::AdhesivePlasticity;
/// The plastic-model menu (`tabor-plastic`); a scene's `[plasticity] model` is one
/// of [`PlasticModel::NON_ADHESIVE`], or `auto` (`None`: the interpolation model
/// (5.107), the most complete, beyond the fully plastic onset too).
pub use tabor_plastic::PlasticModel;

/// The validated physics of a scene (what its models are built from): equal
/// inputs build equal models.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Inputs {
    pub sphere: Body,
    pub target: Body,
    pub adhesion: Option<Adhesion>,
    pub plasticity: Option<PlasticModel>,
    pub adhesive_plasticity: AdhesivePlasticity,
    pub accuracy: f64,
    pub effective_modulus: f64,
    pub effective_radius: f64,
    pub effective_mass: f64,
    /// The DEM normal damping law of `[damping]`, when given.
    pub damping: Option<NormalDamping>,
}

impl Inputs {
    /// Validates the physics of scene data (everything but its name and speed).
    pub(crate) fn validate(data: &SceneFile) -> Result<Inputs, SceneError> {
        let accuracy = match data.accuracy {
            None => DEFAULT_ACCURACY,
            Some(a) => validate::tolerance("accuracy", a)
                .map_err(|e| SceneError::field("accuracy", in_field("", "accuracy")(e).message))?,
        };
        let sphere = body("sphere", &data.sphere, false)?;
        let target = body("target", &data.target, true)?;
        if target.radius.is_some() && target.mass.is_none() {
            return Err(SceneError::field(
                "target.density",
                "a spherical target needs density or mass",
            ));
        }
        if target.gradation.is_some() && target.radius.is_some() {
            return Err(SceneError::field(
                "target.gradation",
                "a graded target must be a half-space (no radius)",
            ));
        }
        let e = effective_modulus(&sphere.material, &target.material)
            .map_err(in_field("sphere", "youngs_modulus"))?;
        let r_sphere = sphere.radius.unwrap_or(f64::NAN);
        let r = effective_radius(r_sphere, target.radius).map_err(in_field("sphere", "radius"))?;
        let m = reduced_mass(sphere.mass.unwrap_or(f64::NAN), target.mass)
            .map_err(in_field("sphere", "mass"))?;
        let adhesion = match &data.adhesion {
            None => None,
            Some(a) => Some(adhesion(a, e, r)?),
        };
        let (plasticity, adhesive_plasticity) = plasticity(data.plasticity.as_ref())?;
        if data.plasticity.is_some()
            && sphere.yield_stress.is_none()
            && target.yield_stress.is_none()
        {
            return Err(SceneError::field(
                "plasticity",
                "a [plasticity] section needs a yield_stress on the sphere or the target (Pa)",
            ));
        }
        if let Some(a) = &adhesion {
            if a.separation == SeparationRule::LoadControlled
                && matches!(a.range, AdhesionRange::TaborParameter(_))
            {
                return Err(SceneError::field(
                    "adhesion.separation",
                    "\"load-controlled\" applies to JKR only (no range): a Maugis-Dugdale contact separates at its own instability; remove separation or the range",
                ));
            }
        }
        let damping = match &data.damping {
            None => None,
            Some(d) => Some(damping(d, e, &sphere, &target)?),
        };
        Ok(Inputs {
            sphere,
            target,
            adhesion,
            plasticity,
            adhesive_plasticity,
            accuracy,
            effective_modulus: e,
            effective_radius: r,
            effective_mass: m,
            damping,
        })
    }

    /// The Tabor parameter Λ, when the interface has a range.
    pub(crate) fn tabor_parameter(&self) -> Option<f64> {
        match self.adhesion.as_ref()?.range {
            AdhesionRange::Jkr => None,
            AdhesionRange::TaborParameter(l) => Some(l),
        }
    }

    /// The yield stress of the softer plastic body (the smaller one given).
    pub(crate) fn yield_stress(&self) -> Option<f64> {
        match (self.sphere.yield_stress, self.target.yield_stress) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// The field of the yield stress that [`Inputs::yield_stress`] uses.
    pub(crate) fn yield_stress_field(&self) -> &'static str {
        match (self.sphere.yield_stress, self.target.yield_stress) {
            (Some(a), Some(b)) if a < b => "sphere.yield_stress",
            (Some(_), None) => "sphere.yield_stress",
            _ => "target.yield_stress",
        }
    }

    /// The Poisson's ratio of the plastic body (the target if it has a yield
    /// stress, else the sphere).
    pub(crate) fn plastic_poisson_ratio(&self) -> f64 {
        if self.target.yield_stress.is_some() {
            self.target.material.poisson_ratio()
        } else {
            self.sphere.material.poisson_ratio()
        }
    }

    /// The slowest elastic wave speed √(E/ρ) of the bodies whose density is known,
    /// as (E, ρ).
    pub(crate) fn wave_speed_body(&self) -> Option<(f64, f64)> {
        [&self.sphere, &self.target]
            .iter()
            .filter_map(|b| b.density.map(|rho| (b.material.youngs_modulus(), rho)))
            .min_by(|a, b| (a.0 / a.1).total_cmp(&(b.0 / b.1)))
    }
}

fn body(section: &str, b: &BodyFile, is_target: bool) -> Result<Body, SceneError> {
    let material =
        ElasticMaterial::new(b.youngs_modulus, b.poisson_ratio).map_err(|e| match e {
            Error::InvalidParameter { parameter, .. } => in_field(section, parameter)(e),
            other => SceneError::model(other),
        })?;
    let radius = match b.radius {
        Some(r) => Some(validate::positive("radius", r).map_err(in_field(section, "radius"))?),
        None if is_target => None,
        None => {
            return Err(SceneError::field(
                format!("{section}.radius"),
                "is required (m)",
            ))
        }
    };
    if b.mass.is_some() && b.density.is_some() {
        return Err(SceneError::field(
            format!("{section}.mass"),
            "give either mass or density, not both",
        ));
    }
    let density = b
        .density
        .map(|d| validate::positive("density", d).map_err(in_field(section, "density")))
        .transpose()?;
    let mass = match (b.mass, density, radius) {
        (Some(m), _, _) => Some(validate::positive("mass", m).map_err(in_field(section, "mass"))?),
        (None, Some(rho), Some(r)) => Some(sphere_mass(r, rho).map_err(|_| {
            SceneError::field(
                format!("{section}.radius"),
                format!("= {r:e} with density {rho:e} kg/m^3: the mass (4/3) pi R^3 rho = {:e} kg is not representable", 4.0 / 3.0 * std::f64::consts::PI * r * r * r * rho),
            )
        })?),
        (None, _, None) => None,
        (None, None, Some(_)) => {
            return Err(SceneError::field(
                format!("{section}.density"),
                "is required (kg/m^3), or give mass (kg)",
            ))
        }
    };
    let density = density.or(match (mass, radius) {
        (Some(m), Some(r)) => Some(m / (4.0 / 3.0 * std::f64::consts::PI * r * r * r)),
        _ => None,
    });
    let yield_stress = b
        .yield_stress
        .map(|s| validate::positive("yield_stress", s).map_err(in_field(section, "yield_stress")))
        .transpose()?;
    let viscosity = b
        .viscosity
        .map(|s| validate::positive("viscosity", s).map_err(in_field(section, "viscosity")))
        .transpose()?;
    let gradation = match &b.gradation {
        None => None,
        Some(GradationFile {
            exponent,
            modulus_factor,
        }) => {
            if !is_target {
                return Err(SceneError::field(
                    format!("{section}.gradation"),
                    "only the target (a half-space) can be graded",
                ));
            }
            let k = validate::in_open_interval(
                "exponent",
                *exponent,
                -1.0,
                1.0,
                "must satisfy -1 < k < 1",
            )
            .map_err(in_field(section, "gradation.exponent"))?;
            let c = validate::positive("modulus_factor", *modulus_factor)
                .map_err(in_field(section, "gradation.modulus_factor"))?;
            Some((k, c))
        }
    };
    Ok(Body {
        radius,
        mass,
        density,
        material,
        yield_stress,
        viscosity,
        gradation,
    })
}

fn adhesion(a: &AdhesionFile, e: f64, r: f64) -> Result<Adhesion, SceneError> {
    let w = validate::non_negative("work_of_adhesion", a.work_of_adhesion)
        .map_err(in_field("adhesion", "work_of_adhesion"))?;
    let given = [
        a.range.is_some(),
        a.cohesive_stress.is_some(),
        a.tabor_parameter.is_some(),
        a.maugis_parameter.is_some(),
        a.tabor_mu.is_some(),
    ]
    .iter()
    .filter(|x| **x)
    .count();
    if given > 1 {
        return Err(SceneError::field(
            "adhesion",
            "give at most one of range, cohesive_stress, tabor_parameter, maugis_parameter, tabor_mu",
        ));
    }
    // every number given is checked, also where it does not enter (Δγ = 0)
    for (key, value) in [
        ("range", a.range),
        ("cohesive_stress", a.cohesive_stress),
        ("tabor_parameter", a.tabor_parameter),
        ("maugis_parameter", a.maugis_parameter),
        ("tabor_mu", a.tabor_mu),
    ] {
        if let Some(x) = value {
            validate::positive(key, x).map_err(in_field("adhesion", key))?;
        }
    }
    let range = if w == 0.0 || given == 0 {
        AdhesionRange::Jkr
    } else if let Some(h) = a.range {
        AdhesionRange::TaborParameter(
            tabor_parameter_from_range(h, w, e, r).map_err(in_field("adhesion", "range"))?,
        )
    } else if let Some(s) = a.cohesive_stress {
        AdhesionRange::TaborParameter(
            tabor_parameter_from_cohesive_stress(s, w, e, r)
                .map_err(in_field("adhesion", "cohesive_stress"))?,
        )
    } else if let Some(l) = a.tabor_parameter {
        AdhesionRange::TaborParameter(
            validate::positive("tabor_parameter", l)
                .map_err(in_field("adhesion", "tabor_parameter"))?,
        )
    } else if let Some(l) = a.maugis_parameter {
        AdhesionRange::TaborParameter(
            tabor_parameter_from_maugis(l).map_err(in_field("adhesion", "maugis_parameter"))?,
        )
    } else if let Some(mu) = a.tabor_mu {
        AdhesionRange::TaborParameter(
            tabor_parameter_from_tabor_mu(mu).map_err(in_field("adhesion", "tabor_mu"))?,
        )
    } else {
        AdhesionRange::Jkr
    };
    let separation = choice(a.separation.as_deref(), "adhesion.separation")?;
    Ok(Adhesion {
        work_of_adhesion: w,
        range,
        separation,
    })
}

/// The `[damping]` section: the model's name (its menu), its one value
/// (`coefficient` for `viscoelastic` and `tsuji`, `restitution` for
/// `coeff_restitution`) and the refusal of a scene that also gives a viscosity
/// (a DEM damping law is not a material model: the two would damp twice).
/// LAMMPS documentation `pair_granular`, "Damping".
fn damping(
    d: &DampingFile,
    effective_modulus: f64,
    sphere: &Body,
    target: &Body,
) -> Result<NormalDamping, SceneError> {
    let model: DampingModel = choice(Some(d.model.as_str()), "damping.model")?;
    if let Some(body) = [("sphere", sphere), ("target", target)]
        .iter()
        .find_map(|(name, b)| b.viscosity.is_some().then_some(*name))
    {
        return Err(SceneError::field(
            "damping",
            format!(
                "[damping] (a DEM damping law, model \"{model}\") and {body}.viscosity (a viscoelastic material model) are both given: each damps the normal contact, together they would damp it twice; keep one"
            ),
        ));
    }
    let (key, value, other) = match model {
        DampingModel::CoeffRestitution => {
            ("restitution", d.restitution, ("coefficient", d.coefficient))
        }
        DampingModel::Viscoelastic | DampingModel::Tsuji => {
            ("coefficient", d.coefficient, ("restitution", d.restitution))
        }
    };
    if other.1.is_some() {
        return Err(SceneError::field(
            format!("damping.{}", other.0),
            format!("does not apply to model \"{model}\": give {key}"),
        ));
    }
    let value = value.ok_or_else(|| {
        SceneError::field(
            "damping",
            format!(
                "{key} is required for model \"{model}\" ({})",
                match model {
                    DampingModel::Viscoelastic => "eta_n0 in 1/(m s): F = eta_n0 m* a v_n",
                    DampingModel::Tsuji =>
                        "the damping value in (0, 1], read by Tsuji's polynomial",
                    DampingModel::CoeffRestitution => "the restitution e in (0, 1]",
                }
            ),
        )
    })?;
    NormalDamping::dem(model, value, effective_modulus).map_err(in_field("damping", key))
}

fn plasticity(
    p: Option<&PlasticityFile>,
) -> Result<(Option<PlasticModel>, AdhesivePlasticity), SceneError> {
    let model = match p.and_then(|p| p.model.as_deref()) {
        None | Some("auto") => None,
        Some(name) => match name.parse::<PlasticModel>() {
            Ok(m) if !m.is_adhesive() => Some(m),
            _ => {
                let names: Vec<&str> = PlasticModel::NON_ADHESIVE
                    .iter()
                    .map(|m| m.as_str())
                    .collect();
                return Err(SceneError::field(
                    "plasticity.model",
                    format!(
                        "unknown model \"{name}\": expected auto, {} (adhesion and plasticity combine by adhesive_model)",
                        names.join(", ")
                    ),
                ));
            }
        },
    };
    let adhesive: AdhesivePlasticity = choice(
        p.and_then(|p| p.adhesive_model.as_deref()),
        "plasticity.adhesive_model",
    )?;
    Ok((model, adhesive))
}

/// The menu choice named at scene field `field` (`None`: the menu's default),
/// parsed by its menu's `FromStr`; an unknown name is an input error naming the
/// field and listing the menu.
fn choice<T>(name: Option<&str>, field: &str) -> Result<T, SceneError>
where
    T: Default + std::str::FromStr<Err = tabor_restitution::UnknownChoice>,
{
    match name {
        None => Ok(T::default()),
        Some(name) => name
            .parse()
            .map_err(|e: tabor_restitution::UnknownChoice| SceneError::field(field, e.to_string())),
    }
}
