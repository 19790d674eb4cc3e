//! The scene parameters a sweep can vary.

use serde::Serialize;

/// A scene parameter that a sweep varies.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SweepParameter {
    /// The impact speed (m/s).
    Speed,
    /// The sphere's radius (m).
    SphereRadius,
    /// The work of adhesion (J/m²).
    WorkOfAdhesion,
    /// The Tabor parameter Λ (replaces any range given).
    TaborParameter,
    /// The target's yield stress (Pa).
    YieldStress,
    /// The impact angle (degrees; the oblique impact, [`crate::Scene::oblique`]).
    Angle,
}

impl SweepParameter {
    /// Every parameter, in the order of the help texts.
    pub const ALL: [SweepParameter; 6] = [
        SweepParameter::Speed,
        SweepParameter::SphereRadius,
        SweepParameter::WorkOfAdhesion,
        SweepParameter::TaborParameter,
        SweepParameter::YieldStress,
        SweepParameter::Angle,
    ];

    /// The parameter named as on the command line (`speed`, `sphere-radius`,
    /// `work-of-adhesion`, `tabor-parameter`, `yield-stress`, `angle`).
    pub fn from_name(name: &str) -> Option<Self> {
        Some(match name {
            "speed" => SweepParameter::Speed,
            "sphere-radius" => SweepParameter::SphereRadius,
            "work-of-adhesion" => SweepParameter::WorkOfAdhesion,
            "tabor-parameter" => SweepParameter::TaborParameter,
            "yield-stress" => SweepParameter::YieldStress,
            "angle" => SweepParameter::Angle,
            _ => return None,
        })
    }

    /// The name as on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            SweepParameter::Speed => "speed",
            SweepParameter::SphereRadius => "sphere-radius",
            SweepParameter::WorkOfAdhesion => "work-of-adhesion",
            SweepParameter::TaborParameter => "tabor-parameter",
            SweepParameter::YieldStress => "yield-stress",
            SweepParameter::Angle => "angle",
        }
    }
}
