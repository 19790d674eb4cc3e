//! The menus (which tangential, rolling and twisting model) and their parameters,
//! with the names and coefficients of LAMMPS's `pair_style granular`.

use serde::Serialize;
use tabor_restitution::{validate, Result};

/// The tangential (sliding friction) model, LAMMPS `pair granular` keyword
/// `tangential`. Every one is a spring in the tangent plane with a Coulomb limit
/// `μ F_n0` (see [`crate::critical_force`]) and viscous damping `x_γ,t η_n`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TangentialModel {
    /// `mindlin`: the spring stiffness is `k_t a` with `k_t = 8 G*` (Mindlin 1949,
    /// the no-slip stiffness `8 G* a` of a circular contact of radius `a`), acting
    /// on the accumulated tangential displacement (so the force follows the
    /// contact radius up and down: a total-displacement form, no micro-slip).
    #[default]
    Mindlin,
    /// `mindlin_rescale`: `mindlin`, with the stored displacement scaled by
    /// `a/a_old` whenever the contact radius shrinks (Thornton & Yin 1991's
    /// unloading correction as LAMMPS implements it).
    MindlinRescale,
    /// `mindlin_deresiewicz`: Mindlin-Deresiewicz micro-slip (Cattaneo 1938,
    /// Mindlin & Deresiewicz 1953): the contact sticks in its centre and slips in
    /// an annulus, with memory of every turning point of the loading history;
    /// computed exactly in the oblique impact by the method of dimensionality
    /// reduction (a bed of springs of stiffness `k_t/2` per unit length, each
    /// with its own Coulomb limit; Popov & Heß 2015), `k_t = 8 G*` as for
    /// `mindlin`. Not a LAMMPS `pair granular` model.
    MindlinDeresiewicz,
    /// `linear_history`: a constant stiffness `k_t` (N/m) on the accumulated
    /// displacement (Cundall & Strack 1979; LAMMPS's `gran/hooke/history`).
    LinearHistory,
}

tabor_restitution::menu! {
    TangentialModel, "tangential model";
    LinearHistory => "linear_history", "a constant spring k_t (N/m) on the accumulated tangential displacement (Cundall & Strack 1979)";
    Mindlin => "mindlin", "the spring k_t a, k_t = 8 G*, on the accumulated tangential displacement (Mindlin 1949)";
    MindlinRescale => "mindlin_rescale", "mindlin, the stored displacement scaled by a/a_old as the contact shrinks";
    MindlinDeresiewicz => "mindlin_deresiewicz", "Mindlin-Deresiewicz micro-slip: a stick centre and a slipping annulus, with memory of the loading history (exact by the method of dimensionality reduction)";
}

/// The rolling resistance model, LAMMPS keyword `rolling`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum RollingModel {
    /// `sds`: spring-dashpot-slider on the rolling displacement (Luding 2008;
    /// Wang et al. 2015's rolling velocity `R (ω_i − ω_j) × n`).
    #[default]
    Sds,
}

tabor_restitution::menu! {
    RollingModel, "rolling model";
    Sds => "sds", "spring-dashpot-slider on the rolling displacement (Luding 2008)";
}

/// The twisting resistance model, LAMMPS keyword `twisting`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum TwistingModel {
    /// `marshall`: coefficients from the tangential model and the contact radius
    /// (Marshall 2009, eq. 32): stiffness `½ k_t a²`, damping `½ η_t a²`, limit
    /// `(2/3) μ a F_n0`, with LAMMPS's `k_t` (for `mindlin`: `8 G*`, not `8 G* a`).
    #[default]
    Marshall,
    /// `sds`: spring-dashpot-slider with its own stiffness, damping and
    /// coefficient (limit `μ_tw F_n0`).
    Sds,
}

tabor_restitution::menu! {
    TwistingModel, "twisting model";
    Marshall => "marshall", "stiffness k_t a²/2, damping η_t a²/2, limit (2/3) μ a F_n0 (Marshall 2009, eq. 32)";
    Sds => "sds", "spring-dashpot-slider with its own stiffness, damping and coefficient";
}

/// The tangential contact: model, stiffness, damping ratio and friction
/// coefficient (LAMMPS `tangential <model> k_t x_γ,t μ_s`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Tangential {
    /// Which model.
    pub model: TangentialModel,
    /// `k_t`: for `mindlin` and `mindlin_rescale` the coefficient of the contact
    /// radius, `8 G*` (Pa = N/m², the spring is `k_t a`); for `linear_history` the
    /// spring itself (N/m).
    pub stiffness: f64,
    /// `x_γ,t` (dimensionless): the tangential damping is `x_γ,t` times the normal
    /// damping coefficient (LAMMPS's `damp_prefactor`).
    pub damping_ratio: f64,
    /// The sliding friction coefficient μ_s.
    pub coefficient: f64,
}

impl Tangential {
    /// A validated tangential contact (`stiffness`, `damping_ratio`,
    /// `coefficient` finite and ≥ 0; stiffness > 0).
    pub fn new(
        model: TangentialModel,
        stiffness: f64,
        damping_ratio: f64,
        coefficient: f64,
    ) -> Result<Self> {
        Ok(Tangential {
            model,
            stiffness: validate::positive("tangential stiffness", stiffness)?,
            damping_ratio: validate::non_negative("tangential_damping", damping_ratio)?,
            coefficient: validate::non_negative("coefficient", coefficient)?,
        })
    }

    /// `mindlin` with `k_t = 8 G*` from the materials (LAMMPS `mindlin NULL`).
    pub fn mindlin(shear: EffectiveShear, damping_ratio: f64, coefficient: f64) -> Result<Self> {
        Tangential::new(
            TangentialModel::Mindlin,
            8.0 * shear.modulus(),
            damping_ratio,
            coefficient,
        )
    }

    /// The spring stiffness (N/m) at contact radius `contact_radius` (m):
    /// `k_t a` for the Mindlin models, `k_t` for `linear_history`.
    pub fn spring(&self, contact_radius: f64) -> f64 {
        match self.model {
            TangentialModel::Mindlin
            | TangentialModel::MindlinRescale
            | TangentialModel::MindlinDeresiewicz => self.stiffness * contact_radius,
            TangentialModel::LinearHistory => self.stiffness,
        }
    }

    /// True when the spring's stiffness vanishes with the contact radius (`k_t a`:
    /// the Mindlin models). Where the contact has no area (a = 0: the no-contact
    /// part of Maugis-Dugdale) such a spring stores no displacement: a contact
    /// area that forms again starts from zero displacement, as a new contact.
    pub fn vanishes_without_area(&self) -> bool {
        self.model != TangentialModel::LinearHistory
    }
}

/// The effective shear modulus of a contact, Mindlin (1949):
/// `1/G* = (2 − ν1)/G1 + (2 − ν2)/G2` with `G = E/(2(1 + ν))`; LAMMPS's
/// `mix_stiffnessG`. The Mindlin no-slip tangential stiffness is `8 G* a`.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct EffectiveShear(f64);

impl EffectiveShear {
    /// From Young's moduli (Pa) and Poisson ratios of the two bodies.
    pub fn of_pair(
        youngs_modulus_1: f64,
        poisson_ratio_1: f64,
        youngs_modulus_2: f64,
        poisson_ratio_2: f64,
    ) -> Result<Self> {
        let e1 = validate::positive("youngs_modulus", youngs_modulus_1)?;
        let n1 = validate::poisson_ratio("poisson_ratio", poisson_ratio_1)?;
        let e2 = validate::positive("youngs_modulus", youngs_modulus_2)?;
        let n2 = validate::poisson_ratio("poisson_ratio", poisson_ratio_2)?;
        let compliance = 2.0 * (2.0 - n1) * (1.0 + n1) / e1 + 2.0 * (2.0 - n2) * (1.0 + n2) / e2;
        Ok(EffectiveShear(1.0 / compliance))
    }

    /// For a rigid second body (`G2 → ∞`): `1/G* = (2 − ν)/G`.
    pub fn of_rigid_partner(youngs_modulus: f64, poisson_ratio: f64) -> Result<Self> {
        let e = validate::positive("youngs_modulus", youngs_modulus)?;
        let n = validate::poisson_ratio("poisson_ratio", poisson_ratio)?;
        Ok(EffectiveShear(e / (2.0 * (2.0 - n) * (1.0 + n))))
    }

    /// G* (Pa).
    pub fn modulus(self) -> f64 {
        self.0
    }
}

/// Rolling resistance `sds`: stiffness k_roll (N/m), damping γ_roll (N s/m) and
/// coefficient μ_roll (LAMMPS `rolling sds k_roll γ_roll μ_roll`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Rolling {
    /// Which model.
    pub model: RollingModel,
    /// k_roll (N/m) on the rolling displacement.
    pub stiffness: f64,
    /// γ_roll (N s/m) on the rolling velocity.
    pub damping: f64,
    /// μ_roll: the limit is `μ_roll F_n0`.
    pub coefficient: f64,
}

impl Rolling {
    /// A validated `sds` rolling resistance (stiffness > 0; damping, coefficient ≥ 0).
    pub fn sds(stiffness: f64, damping: f64, coefficient: f64) -> Result<Self> {
        Ok(Rolling {
            model: RollingModel::Sds,
            stiffness: validate::positive("rolling stiffness", stiffness)?,
            damping: validate::non_negative("rolling damping", damping)?,
            coefficient: validate::non_negative("rolling coefficient", coefficient)?,
        })
    }
}

/// Twisting resistance (LAMMPS `twisting marshall` or `twisting sds k γ μ`).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
#[serde(tag = "model", rename_all = "snake_case")]
pub enum Twisting {
    /// `marshall`: everything from the tangential model (see
    /// [`TwistingModel::Marshall`]).
    Marshall,
    /// `sds`.
    Sds {
        /// k_twist (N m/rad).
        stiffness: f64,
        /// γ_twist (N m s/rad).
        damping: f64,
        /// μ_twist (m): the limit torque is `μ_twist F_n0`.
        coefficient: f64,
    },
}

impl Twisting {
    /// A validated `sds` twisting resistance (stiffness > 0; damping,
    /// coefficient ≥ 0).
    pub fn sds(stiffness: f64, damping: f64, coefficient: f64) -> Result<Self> {
        Ok(Twisting::Sds {
            stiffness: validate::positive("twisting stiffness", stiffness)?,
            damping: validate::non_negative("twisting damping", damping)?,
            coefficient: validate::non_negative("twisting coefficient", coefficient)?,
        })
    }

    /// Which model.
    pub fn model(&self) -> TwistingModel {
        match self {
            Twisting::Marshall => TwistingModel::Marshall,
            Twisting::Sds { .. } => TwistingModel::Sds,
        }
    }

    /// True when the twisting stiffness vanishes with the contact radius
    /// (`marshall`: `½ k_t a²`); see [`Tangential::vanishes_without_area`].
    pub fn vanishes_without_area(&self) -> bool {
        matches!(self, Twisting::Marshall)
    }
}

/// The complete friction of a contact: tangential, and optionally rolling and
/// twisting resistance. The value the per-contact step ([`crate::step`]) and the
/// oblique impact ([`crate::oblique`]) take.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct Friction {
    /// Sliding friction.
    pub tangential: Tangential,
    /// Rolling resistance, if any.
    pub rolling: Option<Rolling>,
    /// Twisting resistance, if any.
    pub twisting: Option<Twisting>,
}

impl Friction {
    /// Tangential friction only.
    pub fn sliding(tangential: Tangential) -> Self {
        Friction {
            tangential,
            rolling: None,
            twisting: None,
        }
    }

    /// With rolling resistance.
    pub fn with_rolling(mut self, rolling: Rolling) -> Self {
        self.rolling = Some(rolling);
        self
    }

    /// With twisting resistance.
    pub fn with_twisting(mut self, twisting: Twisting) -> Self {
        self.twisting = Some(twisting);
        self
    }

    /// Checks the values again (for values built field by field).
    pub fn validate(&self) -> Result<()> {
        let t = &self.tangential;
        Tangential::new(t.model, t.stiffness, t.damping_ratio, t.coefficient)?;
        if let Some(r) = &self.rolling {
            Rolling::sds(r.stiffness, r.damping, r.coefficient)?;
        }
        if let Some(Twisting::Sds {
            stiffness,
            damping,
            coefficient,
        }) = self.twisting
        {
            Twisting::sds(stiffness, damping, coefficient)?;
        }
        Ok(())
    }

    /// The LAMMPS `pair_coeff` sub-model keywords of this friction (`pair
    /// granular`'s syntax, which `pair_style tabor` reads too), e.g.
    /// `tangential mindlin 1.8e10 0 0.3 rolling sds 50 0 0.1 twisting marshall`.
    /// `null_stiffness` writes the Mindlin stiffness as `NULL` (LAMMPS then
    /// computes `8 G*` from the materials itself; only for `mindlin` and
    /// `mindlin_rescale`), else the stiffness is written out, so that it holds for
    /// any normal model. Every number is written so that it reads back exactly
    /// ([`lammps_number`]).
    pub fn lammps_keywords(&self, null_stiffness: bool) -> String {
        let t = &self.tangential;
        let stiffness = if null_stiffness && t.model != TangentialModel::LinearHistory {
            "NULL".to_string()
        } else {
            lammps_number(t.stiffness)
        };
        let mut s = format!(
            "tangential {} {stiffness} {} {}",
            t.model,
            lammps_number(t.damping_ratio),
            lammps_number(t.coefficient)
        );
        if let Some(r) = &self.rolling {
            s += &format!(
                " rolling {} {} {} {}",
                r.model,
                lammps_number(r.stiffness),
                lammps_number(r.damping),
                lammps_number(r.coefficient)
            );
        }
        match self.twisting {
            Some(Twisting::Marshall) => s += " twisting marshall",
            Some(Twisting::Sds {
                stiffness,
                damping,
                coefficient,
            }) => {
                s += &format!(
                    " twisting sds {} {} {}",
                    lammps_number(stiffness),
                    lammps_number(damping),
                    lammps_number(coefficient)
                )
            }
            None => {}
        }
        s
    }
}

/// A number for a LAMMPS input line that reads back to the same `f64`: the
/// shortest round-trip form, plain (`50`, `0.3`, `0`) between 10⁻³ and 10⁷, else
/// with an exponent (`1.8461538461538462e10`, `1e-9`).
pub fn lammps_number(x: f64) -> String {
    if x == 0.0 || (1e-3..1e7).contains(&x.abs()) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}

/// `F_n0`, the normal force that scales every Coulomb limit, as LAMMPS's
/// `set_fncrit` defines it: for a cohesive normal model (pull-off force
/// `pull_off_force` > 0) `|F_n,elastic + 2 F_pulloff|` (Thornton 1991; LAMMPS's
/// `jkr` and `dmt`), else `|F_n,total|` (elastic plus damping).
///
/// tabor's choice for each normal model: Hertz `F_pulloff = 0`; JKR (either
/// separation rule) `F_pulloff = (3/2)π w R`, the load-controlled pull-off force,
/// exactly as LAMMPS's `jkr`; Maugis-Dugdale the model's own pull-off force (the
/// most tensile force on its impact branch, which tends to the JKR value as Λ → ∞
/// and to the DMT value `2π w R` as Λ → 0).
pub fn critical_force(elastic_force: f64, total_force: f64, pull_off_force: f64) -> f64 {
    if pull_off_force > 0.0 {
        (elastic_force + 2.0 * pull_off_force).abs()
    } else {
        total_force.abs()
    }
}
