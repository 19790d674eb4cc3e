//! The viscoelastic-model menu: every model of this crate a front end can name
//! (`tabor visco --model`, Python's `tabor.visco(model=…)`).

use serde::Serialize;

/// A viscoelastic impact model without adhesion, by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ViscoModel {
    /// Flat punch, Kelvin-Voigt, closed form, seed 000 eqs. (5.61)-(5.63)
    /// ([`kelvin_voigt_flat`](crate::kelvin_voigt_flat)).
    KelvinVoigtFlat,
    /// Sphere, Kelvin-Voigt, Kuwabara-Kono, seed 000 eq. (5.66)
    /// ([`SphereModel::KuwabaraKono`](crate::SphereModel::KuwabaraKono)).
    KuwabaraKono,
    /// Sphere, Kelvin-Voigt, compression and restitution apart, seed 000 eqs.
    /// (5.64)-(5.67) ([`SphereModel::Rigorous`](crate::SphereModel::Rigorous)).
    KelvinVoigtSphere,
    /// Sphere, linear damping β = 0, seed 000 eq. (5.72)
    /// ([`DampingLaw::LeeHerrmann`](crate::damping_law::DampingLaw::LeeHerrmann)).
    LeeHerrmann,
    /// Sphere, β = 1/4 with seed 000 eq. (5.73)
    /// ([`DampingLaw::Tsuji`](crate::damping_law::DampingLaw::Tsuji)).
    Tsuji,
    /// Sphere, β = 3/2, seed 000 eq. (5.72)
    /// ([`DampingLaw::HuntCrossley`](crate::damping_law::DampingLaw::HuntCrossley)).
    HuntCrossley,
    /// Sphere, a damping exponent β of the user's choice, seed 000 eq. (5.72)
    /// ([`damping_law`](crate::damping_law)).
    PowerDamping,
    /// Flat punch, standard medium, seed 000 eqs. (5.76)-(5.81), with the
    /// equivalent Kelvin-Voigt value (5.83) ([`standard_flat`](crate::standard_flat)).
    StandardFlat,
    /// Sphere, standard medium, MDR, seed 000 eqs. (5.84)-(5.90)
    /// ([`standard_sphere`](crate::standard_sphere)).
    StandardSphere,
    /// Sphere, Kelvin-Maxwell medium, MDR, seed 000 eqs. (5.91)-(5.92)
    /// ([`kelvin_maxwell_sphere`](crate::kelvin_maxwell_sphere)).
    KelvinMaxwellSphere,
    /// Flat punch, compressible Kelvin-Voigt, seed 000 eqs. (5.96)-(5.100)
    /// ([`compressible_flat`](crate::compressible_flat)).
    CompressibleFlat,
}

tabor_restitution::menu! {
    ViscoModel, "viscoelastic model";
    KelvinVoigtFlat => "kelvin-voigt-flat", "flat punch, Kelvin-Voigt, closed form (5.61)-(5.63)";
    KuwabaraKono => "kuwabara-kono", "sphere, Kelvin-Voigt, Kuwabara-Kono (5.66)";
    KelvinVoigtSphere => "kelvin-voigt-sphere",
        "sphere, Kelvin-Voigt, compression and restitution apart (5.64)-(5.67)";
    LeeHerrmann => "lee-herrmann", "sphere, linear damping β = 0 (5.72)";
    Tsuji => "tsuji", "sphere, β = 1/4 with (5.73)";
    HuntCrossley => "hunt-crossley", "sphere, β = 3/2 (5.72)";
    PowerDamping => "power-damping", "sphere, damping exponent of your choice (5.72)";
    StandardFlat => "standard-flat",
        "flat punch, standard medium (5.76)-(5.81), with the equivalent Kelvin-Voigt value (5.83)";
    StandardSphere => "standard-sphere", "sphere, standard medium, MDR (5.84)-(5.90)";
    KelvinMaxwellSphere => "kelvin-maxwell-sphere", "sphere, Kelvin-Maxwell medium, MDR (5.91)-(5.92)";
    CompressibleFlat => "compressible-flat",
        "flat punch, compressible Kelvin-Voigt (5.96)-(5.99), bulk damping default (5.100)";
}
