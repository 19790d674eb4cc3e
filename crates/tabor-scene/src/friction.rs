//! What a scene file says about the tangential contact, validated: the
//! `[friction]` section (tangential, rolling and twisting models of
//! `tabor-tangential`) and the oblique keys of `[impact]` (angle, initial spins).
//! Data only: the oblique impact itself is `oblique.rs`.

use crate::error::SceneError;
use crate::file::{FrictionFile, SceneFile, TwistingFile};
use tabor_restitution::{validate, Error};
use tabor_tangential::{
    EffectiveShear, Friction, Rolling, Tangential, TangentialModel, Twisting, TwistingModel,
};

fn field_error(field: &str) -> impl Fn(Error) -> SceneError + '_ {
    move |e| SceneError::field_model(field.to_string(), e)
}

/// The validated friction of scene data (`None` without a `[friction]` section),
/// with the Mindlin stiffness `8 G*` from the bodies' materials unless
/// `tangential_stiffness` is given.
pub(crate) fn friction_of(data: &SceneFile) -> Result<Option<Friction>, SceneError> {
    let Some(f) = &data.friction else {
        return Ok(None);
    };
    let model = match &f.tangential {
        None => TangentialModel::Mindlin,
        Some(name) => name
            .parse::<TangentialModel>()
            .map_err(|e| SceneError::field("friction.tangential", e.to_string()))?,
    };
    let stiffness = match (model, f.tangential_stiffness) {
        (_, Some(k)) => k,
        (TangentialModel::LinearHistory, None) => {
            return Err(SceneError::field(
                "friction.tangential_stiffness",
                "is required for linear_history (N/m)",
            ))
        }
        (_, None) => 8.0 * shear_of(data)?.modulus(),
    };
    let tangential = Tangential::new(
        model,
        stiffness,
        f.tangential_damping.unwrap_or(0.0),
        f.coefficient,
    )
    .map_err(|e| friction_field(f, e))?;
    let mut friction = Friction::sliding(tangential);
    if let Some(r) = &f.rolling {
        friction = friction.with_rolling(
            Rolling::sds(r.stiffness, r.damping.unwrap_or(0.0), r.coefficient)
                .map_err(field_error("friction.rolling"))?,
        );
    }
    friction.twisting = match &f.twisting {
        None => None,
        Some(TwistingFile::Name(name)) => {
            match name
                .parse::<TwistingModel>()
                .map_err(|e| SceneError::field("friction.twisting", e.to_string()))?
            {
                TwistingModel::Marshall => Some(Twisting::Marshall),
                TwistingModel::Sds => {
                    return Err(SceneError::field(
                        "friction.twisting",
                        "sds needs { stiffness, damping, coefficient }",
                    ))
                }
            }
        }
        Some(TwistingFile::Sds(t)) => Some(
            Twisting::sds(t.stiffness, t.damping.unwrap_or(0.0), t.coefficient)
                .map_err(field_error("friction.twisting"))?,
        ),
    };
    Ok(Some(friction))
}

fn friction_field(f: &FrictionFile, e: Error) -> SceneError {
    let field = match &e {
        Error::InvalidParameter { parameter, .. } if *parameter == "coefficient" => {
            "friction.coefficient"
        }
        Error::InvalidParameter { parameter, .. } if *parameter == "tangential_damping" => {
            "friction.tangential_damping"
        }
        _ if f.tangential_stiffness.is_some() => "friction.tangential_stiffness",
        _ => "friction",
    };
    SceneError::field_model(field, e)
}

/// G* of the two bodies (Mindlin), the flat of its own material.
fn shear_of(data: &SceneFile) -> Result<EffectiveShear, SceneError> {
    EffectiveShear::of_pair(
        data.sphere.youngs_modulus,
        data.sphere.poisson_ratio,
        data.target.youngs_modulus,
        data.target.poisson_ratio,
    )
    .map_err(field_error("friction"))
}

/// Checks the oblique keys of scene data (for the load-time validation).
pub(crate) fn validate_data(data: &SceneFile) -> Result<(), SceneError> {
    friction_of(data)?;
    if let Some(i) = &data.impact {
        if let Some(a) = i.angle {
            check_angle(a).map_err(|e| SceneError::field("impact.angle", e.to_string()))?;
        }
        for (name, spin) in [
            ("impact.sphere_spin", i.sphere_spin),
            ("impact.target_spin", i.target_spin),
        ] {
            if let Some(s) = spin {
                for v in s {
                    validate::finite("spin", v).map_err(field_error(name))?;
                }
            }
        }
    }
    Ok(())
}

pub(crate) fn check_angle(angle: f64) -> Result<f64, Error> {
    if angle.is_finite() && (0.0..90.0).contains(&angle) {
        Ok(angle)
    } else {
        Err(Error::invalid(
            "angle",
            angle,
            "must be in [0, 90) degrees between the relative velocity and the line of centres",
        ))
    }
}
