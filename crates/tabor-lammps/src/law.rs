//! LAMMPS's `pair_style granular` normal force, written out in tabor's terms and
//! integrated by `tabor_dynamics::simulate_impact`: the restitution LAMMPS will
//! produce for a given model line, before LAMMPS is run.
//!
//! The equations are those of the LAMMPS documentation of `pair_style granular`
//! (normal models `hooke`, `hertz`, `hertz/material`, `dmt`, `jkr`; damping models
//! `none`, `velocity`, `mass_velocity`, `viscoelastic`, `tsuji`,
//! `coeff_restitution`; the `limit_damping` keyword), written independently here.
//! Overlap δ > 0 in contact, δ̇ > 0 while approaching; the force is positive when
//! repulsive; `m` is the reduced mass, `R` the effective radius.

use serde::Serialize;
use std::f64::consts::PI;
use tabor_dynamics::{BranchChange, ForceLaw};
use tabor_jkr::{normalized, JkrScales};
use tabor_restitution::validate::{self, non_negative, positive};
use tabor_restitution::{Error, Result};

/// A LAMMPS granular normal model with its coefficients (SI units).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "model")]
pub enum NormalModel {
    /// `hooke k damp`: F = k δ.
    Hooke {
        /// Stiffness k (N/m).
        stiffness: f64,
    },
    /// `hertz k damp`: F = k a δ, a = √(Rδ).
    Hertz {
        /// Stiffness k (Pa); (4/3)E* for a Hertzian contact (seed 000 eq. (5.5)).
        stiffness: f64,
    },
    /// `hertz/material E damp ν`: F = (4/3) E_mix a δ.
    HertzMaterial {
        /// Young's modulus E (Pa).
        youngs_modulus: f64,
        /// Poisson's ratio ν.
        poisson_ratio: f64,
    },
    /// `dmt E damp ν γ`: F = (4/3) E_mix a δ − 4πγR while δ > 0.
    Dmt {
        /// Young's modulus E (Pa).
        youngs_modulus: f64,
        /// Poisson's ratio ν.
        poisson_ratio: f64,
        /// Surface energy γ per surface (J/m²).
        surface_energy: f64,
    },
    /// `jkr E damp ν γ`: F = (4/3) E_mix a³/R − √(16πγ E_mix a³), with
    /// δ = a²/R − 2√(πγa/E_mix) (JKR with work of adhesion w = 2γ, seed 000
    /// eqs. (5.33)-(5.34)); the contact is kept until δ = −δ_pull-off, the
    /// load-controlled point.
    Jkr {
        /// Young's modulus E (Pa).
        youngs_modulus: f64,
        /// Poisson's ratio ν.
        poisson_ratio: f64,
        /// Surface energy γ per surface (J/m²): the work of adhesion is 2γ.
        surface_energy: f64,
    },
}

impl NormalModel {
    /// The LAMMPS keyword of the model.
    pub fn keyword(&self) -> &'static str {
        match self {
            NormalModel::Hooke { .. } => "hooke",
            NormalModel::Hertz { .. } => "hertz",
            NormalModel::HertzMaterial { .. } => "hertz/material",
            NormalModel::Dmt { .. } => "dmt",
            NormalModel::Jkr { .. } => "jkr",
        }
    }

    /// The effective modulus LAMMPS uses for one `pair_coeff * *` (both bodies of the
    /// same material) and for a `wall/gran` wall: E_mix = E/(2(1 − ν²)), i.e.
    /// 1/E* = (1 − ν²)/E + (1 − ν²)/E (seed 000, the E* of (5.5)). `None` for the
    /// models with a stiffness instead of a modulus.
    pub fn mixed_modulus(&self) -> Option<f64> {
        match *self {
            NormalModel::HertzMaterial {
                youngs_modulus,
                poisson_ratio,
            }
            | NormalModel::Dmt {
                youngs_modulus,
                poisson_ratio,
                ..
            }
            | NormalModel::Jkr {
                youngs_modulus,
                poisson_ratio,
                ..
            } => Some(mixed_modulus(youngs_modulus, poisson_ratio)),
            _ => None,
        }
    }

    /// The Hertzian effective modulus E* the model acts with: E_mix, or (3/4)k for
    /// `hertz`; `None` for `hooke`.
    pub fn hertz_modulus(&self) -> Option<f64> {
        match *self {
            NormalModel::Hertz { stiffness } => Some(0.75 * stiffness),
            NormalModel::Hooke { .. } => None,
            _ => self.mixed_modulus(),
        }
    }
}

/// A LAMMPS granular damping model (the `damping` keyword; `viscoelastic` is
/// LAMMPS's default).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum DampingModel {
    /// No damping force (LAMMPS 22 Jul 2025 has no `damping none` keyword: it is
    /// `viscoelastic` with coefficient 0; kept for the predictor).
    None,
    /// `velocity`: F_d = η ḋ.
    Velocity,
    /// `mass_velocity`: F_d = η m ḋ.
    MassVelocity,
    /// `viscoelastic`: F_d = η m a ḋ (Kuwabara-Kono, seed 000 eq. (5.66), (5.72)
    /// with β = 1/2).
    Viscoelastic,
    /// `tsuji`: the normal model's damping coefficient is a restitution e, turned
    /// into α(e) by Tsuji's polynomial; F_d = α √(m F_e/δ) ḋ (seed 000 eq. (5.73),
    /// β = 1/4 for Hertz).
    Tsuji,
    /// `coeff_restitution`: the damping coefficient is a restitution e;
    /// α = −√5 ln e / √(π² + ln² e) (Hertz) or −2 ln e / √(π² + ln² e) (Hooke),
    /// then the force of `tsuji`.
    CoeffRestitution,
}

impl DampingModel {
    /// The LAMMPS keyword.
    pub fn keyword(&self) -> &'static str {
        match self {
            DampingModel::None => "none",
            DampingModel::Velocity => "velocity",
            DampingModel::MassVelocity => "mass_velocity",
            DampingModel::Viscoelastic => "viscoelastic",
            DampingModel::Tsuji => "tsuji",
            DampingModel::CoeffRestitution => "coeff_restitution",
        }
    }

    /// Whether the normal model's damping coefficient is read as a restitution
    /// (a *nominal* restitution, which is not what LAMMPS achieves in general).
    pub fn takes_restitution(&self) -> bool {
        matches!(self, DampingModel::Tsuji | DampingModel::CoeffRestitution)
    }
}

/// A LAMMPS granular normal contact: normal model, its damping coefficient, the
/// damping model and the `limit_damping` keyword.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct GranularModel {
    /// The normal model.
    pub normal: NormalModel,
    /// The normal model's damping coefficient as written (η_n0 for `viscoelastic`,
    /// a restitution for `tsuji` and `coeff_restitution`, …).
    pub damp: f64,
    /// The damping model.
    pub damping: DampingModel,
    /// `limit_damping`: the total normal force is set to 0 where it would be
    /// attractive (LAMMPS refuses it with `jkr` and `dmt`).
    pub limit_damping: bool,
}

/// Tsuji's polynomial α(e) (Marshall 2009, eq. 53) and the α of
/// `coeff_restitution` (LAMMPS `gran_sub_mod_damping.cpp`): one home, the damping
/// laws of `tabor-viscoadhesive` that scenes use too.
pub use tabor_viscoadhesive::{coeff_restitution_alpha, tsuji_alpha};

impl GranularModel {
    /// Validates the coefficients as LAMMPS does (and refuses what LAMMPS refuses:
    /// `tsuji` and `coeff_restitution` with `jkr` or `dmt`).
    pub fn validate(&self) -> Result<()> {
        match self.normal {
            NormalModel::Hooke { stiffness } | NormalModel::Hertz { stiffness } => {
                positive("stiffness", stiffness)?;
            }
            NormalModel::HertzMaterial {
                youngs_modulus,
                poisson_ratio,
            } => {
                positive("youngs_modulus", youngs_modulus)?;
                validate::poisson_ratio("poisson_ratio", poisson_ratio)?;
            }
            NormalModel::Dmt {
                youngs_modulus,
                poisson_ratio,
                surface_energy,
            }
            | NormalModel::Jkr {
                youngs_modulus,
                poisson_ratio,
                surface_energy,
            } => {
                positive("youngs_modulus", youngs_modulus)?;
                validate::poisson_ratio("poisson_ratio", poisson_ratio)?;
                non_negative("surface_energy", surface_energy)?;
            }
        }
        non_negative("damp", self.damp)?;
        if self.limit_damping
            && matches!(
                self.normal,
                NormalModel::Jkr { .. } | NormalModel::Dmt { .. }
            )
        {
            return Err(Error::Model {
                model: "LAMMPS granular",
                message: format!(
                    "limit_damping cannot be used with the cohesive normal model {} (LAMMPS refuses it: \"Cannot limit damping with a cohesive normal model\")",
                    self.normal.keyword()
                ),
            });
        }
        if self.damping.takes_restitution() {
            if matches!(
                self.normal,
                NormalModel::Jkr { .. } | NormalModel::Dmt { .. }
            ) {
                return Err(Error::Model {
                    model: "LAMMPS granular",
                    message: format!(
                        "damping {} cannot be used with the cohesive normal model {} (LAMMPS refuses it at pair_coeff)",
                        self.damping.keyword(),
                        self.normal.keyword()
                    ),
                });
            }
            if !(self.damp > 0.0 && self.damp <= 1.0) {
                return Err(Error::invalid(
                    "damp",
                    self.damp,
                    "is the nominal restitution of damping tsuji/coeff_restitution: must be in (0, 1]",
                ));
            }
        }
        Ok(())
    }

    /// The damping prefactor coefficient LAMMPS derives at setup: `damp` itself,
    /// or α(e) for `tsuji` and `coeff_restitution`.
    pub fn damping_coefficient(&self) -> f64 {
        match self.damping {
            DampingModel::Tsuji => tsuji_alpha(self.damp),
            DampingModel::CoeffRestitution => {
                coeff_restitution_alpha(self.damp, matches!(self.normal, NormalModel::Hooke { .. }))
            }
            DampingModel::None => 0.0,
            _ => self.damp,
        }
    }

    /// The nominal restitution of the line (`tsuji`, `coeff_restitution`).
    pub fn nominal_restitution(&self) -> Option<f64> {
        self.damping.takes_restitution().then_some(self.damp)
    }

    /// The force law for a contact of effective radius `effective_radius` (m) and
    /// reduced mass `effective_mass` (kg).
    pub fn law(&self, effective_radius: f64, effective_mass: f64) -> Result<LammpsLaw> {
        self.validate()?;
        let r = positive("effective_radius", effective_radius)?;
        let m = positive("effective_mass", effective_mass)?;
        Ok(LammpsLaw {
            model: *self,
            radius: r,
            mass: m,
            alpha: self.damping_coefficient(),
            jkr: match self.normal {
                NormalModel::Jkr {
                    surface_energy,
                    youngs_modulus,
                    poisson_ratio,
                } => jkr_scales(
                    surface_energy,
                    r,
                    mixed_modulus(youngs_modulus, poisson_ratio),
                )?,
                _ => None,
            },
            unloading: false,
            length_scale: 1.0,
            force_scale: 1.0,
        })
    }
}

/// The pull-off distance of LAMMPS's `jkr`: δ_f = (3π²γ²R/(16E_mix²))^(1/3)
/// = (3π²w²R/(64E*²))^(1/3) with w = 2γ, the load-controlled JKR point d = −d_n
/// (seed 000's JKR scales, `tabor_jkr::JkrSphere`).
pub fn jkr_pulloff_distance(surface_energy: f64, effective_radius: f64, modulus: f64) -> f64 {
    (3.0 * PI * PI * surface_energy * surface_energy * effective_radius
        / (16.0 * modulus * modulus))
        .cbrt()
}

/// The JKR scales of LAMMPS's `jkr` with surface energy γ (w = 2γ) for effective
/// radius `r` and mixed modulus `e`; `None` without adhesion (γ = 0).
fn jkr_scales(gamma: f64, r: f64, e: f64) -> Result<Option<JkrScales>> {
    if gamma == 0.0 {
        return Ok(None);
    }
    JkrScales::new(e, r, 2.0 * gamma).map(Some)
}

/// LAMMPS's `E_mix` of two equal materials, `E / (2 (1 − ν²))` (its
/// `mix_stiffnessE`): the effective modulus E* of two bodies of `E`, `ν`.
fn mixed_modulus(youngs_modulus: f64, poisson_ratio: f64) -> f64 {
    youngs_modulus / (2.0 * (1.0 - poisson_ratio * poisson_ratio))
}

/// The contact radius of LAMMPS's `jkr` at overlap δ: on the stable branch
/// (dδ/da > 0) of δ = a²/R − 2√(πγa/E), which is seed 000 (5.34) with w = 2γ, by
/// tabor-jkr's quartic inversion in the normalized units a_c, d_n; below the
/// branch's lowest overlap it is clamped to the branch end (the integrator may probe
/// there). √(Rδ) without adhesion.
fn jkr_contact_radius(delta: f64, r: f64, scales: Option<&JkrScales>) -> f64 {
    let Some(s) = scales else {
        return (r * delta.max(0.0)).sqrt();
    };
    match normalized::sqrt_contact_radius_at_depth(delta / s.depth) {
        Ok(x) => s.contact_radius * x * x,
        Err(_) => f64::NAN,
    }
}

/// A [`GranularModel`] bound to one contact (effective radius and mass), as a
/// `tabor_dynamics::ForceLaw`: one branch from first touch (δ = 0) to separation at
/// δ = 0 (`jkr`: δ = −δ_pull-off), or, with `limit_damping`, where the total force
/// reaches 0 after the turning point (from there LAMMPS applies no force).
#[derive(Clone, Debug)]
pub struct LammpsLaw {
    model: GranularModel,
    radius: f64,
    mass: f64,
    alpha: f64,
    jkr: Option<JkrScales>,
    unloading: bool,
    length_scale: f64,
    force_scale: f64,
}

impl LammpsLaw {
    /// The contact radius LAMMPS uses at overlap δ (m): √(Rδ), or the JKR radius.
    pub fn contact_radius_at(&self, overlap: f64) -> f64 {
        match self.model.normal {
            NormalModel::Jkr { .. } => jkr_contact_radius(overlap, self.radius, self.jkr.as_ref()),
            _ => (self.radius * overlap.max(0.0)).sqrt(),
        }
    }

    /// The elastic (and adhesive) part of the normal force at overlap δ (N).
    pub fn elastic_force(&self, overlap: f64) -> f64 {
        let a = self.contact_radius_at(overlap);
        let d = overlap;
        match self.model.normal {
            NormalModel::Hooke { stiffness } => stiffness * d,
            NormalModel::Hertz { stiffness } => stiffness * a * d,
            NormalModel::HertzMaterial {
                youngs_modulus,
                poisson_ratio,
            } => 4.0 / 3.0 * mixed_modulus(youngs_modulus, poisson_ratio) * a * d,
            NormalModel::Dmt {
                youngs_modulus,
                poisson_ratio,
                surface_energy,
            } => {
                4.0 / 3.0 * mixed_modulus(youngs_modulus, poisson_ratio) * a * d
                    - 4.0 * PI * surface_energy * self.radius
            }
            NormalModel::Jkr {
                youngs_modulus,
                poisson_ratio,
                surface_energy,
            } => {
                let e = mixed_modulus(youngs_modulus, poisson_ratio);
                4.0 / 3.0 * e * a * a * a / self.radius
                    - (16.0 * PI * surface_energy * e * a * a * a).sqrt()
            }
        }
    }

    /// The total normal force LAMMPS applies at overlap δ and overlap rate δ̇ (N).
    pub fn total_force(&self, overlap: f64, overlap_rate: f64) -> f64 {
        let fe = self.elastic_force(overlap);
        let a = self.contact_radius_at(overlap);
        let prefactor = match self.model.damping {
            DampingModel::None => 0.0,
            DampingModel::Velocity => self.alpha,
            DampingModel::MassVelocity => self.alpha * self.mass,
            DampingModel::Viscoelastic => self.alpha * self.mass * a,
            DampingModel::Tsuji | DampingModel::CoeffRestitution => {
                if overlap > 0.0 {
                    self.alpha * (self.mass * fe / overlap).max(0.0).sqrt()
                } else {
                    0.0
                }
            }
        };
        let f = fe + prefactor * overlap_rate;
        if self.model.limit_damping && f < 0.0 {
            0.0
        } else {
            f
        }
    }

    fn is_jkr(&self) -> bool {
        matches!(self.model.normal, NormalModel::Jkr { surface_energy, .. } if surface_energy > 0.0)
    }

    /// The overlap at which LAMMPS drops the contact (m): 0, or −δ_pull-off for `jkr`.
    pub fn separation_overlap(&self) -> f64 {
        match self.model.normal {
            NormalModel::Jkr {
                surface_energy,
                youngs_modulus,
                poisson_ratio,
            } => -jkr_pulloff_distance(
                surface_energy,
                self.radius,
                mixed_modulus(youngs_modulus, poisson_ratio),
            ),
            _ => 0.0,
        }
    }
}

impl ForceLaw for LammpsLaw {
    fn name(&self) -> String {
        format!(
            "LAMMPS granular {} + damping {}{}",
            self.model.normal.keyword(),
            self.model.damping.keyword(),
            if self.model.limit_damping {
                " + limit_damping"
            } else {
                ""
            }
        )
    }

    /// The Hertzian d_max (seed 000 eq. (5.8)) or v0 √(m/k) for `hooke`.
    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64> {
        let v = impact_speed;
        let scale = match (self.model.normal, self.model.normal.hertz_modulus()) {
            (NormalModel::Hooke { stiffness }, _) => v * (effective_mass / stiffness).sqrt(),
            (_, Some(e)) => {
                (15.0 * effective_mass * v * v / (16.0 * e * self.radius.sqrt())).powf(0.4)
            }
            _ => f64::NAN,
        };
        positive("overlap_scale", scale)
    }

    fn begin_impact(&mut self, effective_mass: f64, impact_speed: f64) -> Result<()> {
        self.unloading = false;
        self.length_scale = self.overlap_scale(effective_mass, impact_speed)?;
        self.force_scale = effective_mass * impact_speed * impact_speed / self.length_scale;
        Ok(())
    }

    fn force(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        let f = self.total_force(overlap, overlap_rate);
        if f.is_finite() {
            Ok(f)
        } else {
            Err(Error::Model {
                model: "LAMMPS granular",
                message: format!(
                    "non-finite force at overlap {overlap:e} m, overlap rate {overlap_rate:e} m/s"
                ),
            })
        }
    }

    fn contact_radius(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        Ok(self.contact_radius_at(overlap))
    }

    fn branch_end(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        if self.unloading && self.model.limit_damping {
            // from where the clipped force vanishes LAMMPS applies none: the
            // rebound speed is reached there
            let f = self.total_force_unclipped(overlap, overlap_rate);
            return Ok((f / self.force_scale)
                .min((overlap - self.separation_overlap()) / self.length_scale));
        }
        Ok((overlap - self.separation_overlap()) / self.length_scale)
    }

    fn on_max_compression(&mut self, _overlap: f64) -> Result<BranchChange> {
        self.unloading = true;
        Ok(BranchChange::Continue)
    }

    fn on_branch_end(&mut self, _overlap: f64, _overlap_rate: f64) -> Result<BranchChange> {
        Ok(BranchChange::Separate)
    }
}

impl LammpsLaw {
    fn total_force_unclipped(&self, overlap: f64, overlap_rate: f64) -> f64 {
        let mut m = self.clone();
        m.model.limit_damping = false;
        m.total_force(overlap, overlap_rate)
    }

    /// Whether the law is adhesive (LAMMPS `jkr` with γ > 0).
    pub fn adhesive(&self) -> bool {
        self.is_jkr()
    }
}
