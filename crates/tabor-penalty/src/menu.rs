//! The penalty-law menu: every law a front end can name (`tabor penalty --law`,
//! Python's `tabor.penalty(law=…)`).

use crate::DampingModel;
use serde::Serialize;

/// A penalty contact law, by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PenaltyLaw {
    /// Seed 002's contact characteristic `F = k κ(h, ε) l(v, V)`
    /// ([`ContactCharacteristic`](crate::ContactCharacteristic)); the loss speed V
    /// is calibrated exactly.
    Characteristic,
    /// `F = K δⁿ (1 + χ δ̇)`, χ = 3(1 − e)/(2 v0) ([`DampingModel::HuntCrossley`]).
    HuntCrossley,
    /// χ = 3(1 − e²)/(4 v0) ([`DampingModel::LankaraniNikravesh`]).
    LankaraniNikravesh,
    /// χ = 8(1 − e)/(5 e v0) ([`DampingModel::Flores`]).
    Flores,
}

tabor_restitution::menu! {
    PenaltyLaw, "penalty law";
    Characteristic => "characteristic",
        "the numpedia contact characteristic F = k κ(h, ε) l(v, V); the loss speed V is calibrated exactly";
    HuntCrossley => "hunt-crossley", "F = K δⁿ (1 + χ δ̇), χ = 3(1 − e)/(2 v0) (Hunt & Crossley 1975)";
    LankaraniNikravesh => "lankarani-nikravesh", "χ = 3(1 − e²)/(4 v0) (Lankarani & Nikravesh 1990)";
    Flores => "flores", "χ = 8(1 − e)/(5 e v0) (Flores et al. 2011)";
}

impl PenaltyLaw {
    /// The damping model of a damped power law (`None` for the characteristic).
    pub fn damping_model(self) -> Option<DampingModel> {
        match self {
            PenaltyLaw::Characteristic => None,
            PenaltyLaw::HuntCrossley => Some(DampingModel::HuntCrossley),
            PenaltyLaw::LankaraniNikravesh => Some(DampingModel::LankaraniNikravesh),
            PenaltyLaw::Flores => Some(DampingModel::Flores),
        }
    }
}

tabor_restitution::menu! {
    DampingModel, "damping model";
    HuntCrossley => "hunt-crossley", "χ = 3(1 − e)/(2 v0) (Hunt & Crossley 1975)";
    LankaraniNikravesh => "lankarani-nikravesh", "χ = 3(1 − e²)/(4 v0) (Lankarani & Nikravesh 1990)";
    Flores => "flores", "χ = 8(1 − e)/(5 e v0) (Flores et al. 2011)";
}
