//! The plastic-model menu: every elasto-plastic model a front end can name
//! (`tabor plastic --model`, the scene file's `[plasticity] model`, Python's
//! `tabor.plastic(model=…)`), and how adhesion and plasticity combine
//! (`[plasticity] adhesive_model`).

use serde::Serialize;

/// An elasto-plastic impact model, by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PlasticModel {
    /// [`Thornton`](crate::Thornton), seed 000 eqs. (5.101)-(5.106).
    Thornton,
    /// The [`Interpolation`](crate::Interpolation) model, Q = 5, D = 80, seed 000
    /// eq. (5.107).
    Interpolation,
    /// The [`JacksonGreen`](crate::JacksonGreen) FEM-based law, simulated, seed 000
    /// eq. (5.108).
    JacksonGreen,
    /// Seed 001's fitted restitution ([`DimensionlessFit`](crate::DimensionlessFit)),
    /// seed 001 eqs. (12), (18), (19).
    DimensionlessFit,
    /// The adhesive interpolation model
    /// ([`AdhesiveInterpolation`](crate::AdhesiveInterpolation)), seed 000 eqs.
    /// (5.111)-(5.126).
    AdhesiveInterpolation,
    /// A plastic model's loss plus the JKR loss
    /// ([`Superposition`](crate::Superposition)), seed 000 eqs. (5.109)-(5.110).
    Superposition,
}

tabor_restitution::menu! {
    PlasticModel, "plastic model";
    Thornton => "thornton", "Thornton (5.101)-(5.106)";
    Interpolation => "interpolation", "interpolation model, Q = 5, D = 80 (5.107)";
    JacksonGreen => "jackson-green", "Jackson-Green FEM-based law, time-domain simulation (5.108)";
    DimensionlessFit => "dimensionless-fit", "dimensionless FEM fit of the restitution (Chin. J. Theor. Appl. Mech.), its eqs. (12), (18), (19)";
    AdhesiveInterpolation => "adhesive-interpolation", "adhesive interpolation model (5.111)-(5.126)";
    Superposition => "superposition", "a non-adhesive model's loss plus the JKR loss (5.109)-(5.110)";
}

impl PlasticModel {
    /// The models without adhesion (a rigid sphere on an elastic-perfectly plastic
    /// half-space).
    pub const NON_ADHESIVE: &'static [PlasticModel] = &[
        PlasticModel::Thornton,
        PlasticModel::Interpolation,
        PlasticModel::JacksonGreen,
        PlasticModel::DimensionlessFit,
    ];

    /// Whether the model includes adhesion.
    pub fn is_adhesive(self) -> bool {
        matches!(
            self,
            PlasticModel::AdhesiveInterpolation | PlasticModel::Superposition
        )
    }

    /// Whether a non-adhesive model has an adhesive counterpart: only the
    /// interpolation model (5.107), which the adhesive interpolation model
    /// (5.111)-(5.126) extends.
    pub fn has_adhesive_counterpart(self) -> bool {
        self == PlasticModel::Interpolation
    }
}

/// How adhesion and plasticity combine when both act (a scene's
/// `[plasticity] adhesive_model`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum AdhesivePlasticity {
    /// The adhesive interpolation model, seed 000 eqs. (5.111)-(5.126).
    #[default]
    Interpolation,
    /// The superposition of the plastic and the JKR losses, seed 000 eqs.
    /// (5.109)-(5.110).
    Superposition,
}

tabor_restitution::menu! {
    AdhesivePlasticity, "adhesive plasticity model";
    Interpolation => "interpolation", "adhesive interpolation model (5.111)-(5.126)";
    Superposition => "superposition", "plastic plus JKR losses (5.109)-(5.110)";
}

impl AdhesivePlasticity {
    /// The plastic model this combination stands for.
    pub fn model(self) -> PlasticModel {
        match self {
            AdhesivePlasticity::Interpolation => PlasticModel::AdhesiveInterpolation,
            AdhesivePlasticity::Superposition => PlasticModel::Superposition,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_subsets_partition_the_menu() {
        let adhesive: Vec<_> = PlasticModel::ALL
            .iter()
            .filter(|m| m.is_adhesive())
            .collect();
        assert_eq!(adhesive.len() + PlasticModel::NON_ADHESIVE.len(), 6);
        assert!(PlasticModel::NON_ADHESIVE.iter().all(|m| !m.is_adhesive()));
        for a in AdhesivePlasticity::ALL {
            assert!(a.model().is_adhesive());
        }
        assert_eq!("jackson-green".parse(), Ok(PlasticModel::JacksonGreen));
        assert!("auto".parse::<PlasticModel>().is_err());
    }
}
