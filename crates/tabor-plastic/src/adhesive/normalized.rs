//! The normalized core of the adhesive interpolation model (units of the JKR
//! force-controlled critical state): the yield fit, the loading curve, the turning
//! point and the JKR unloading. Seed 000, eqs. (5.111)-(5.125).

use super::MODEL;
use crate::util::{exceeds, finite_output, positive_output, Hermite};
use serde::Serialize;
use tabor_jkr::normalized as jkr;
use tabor_jkr::{JkrContactState, SeparationRule};
use tabor_numerics::root_finding::{brent, RootTolerance};
use tabor_restitution::{restitution_from_loss, validate, Error, Result};

/// `2 · 1.2429`: the weak-adhesion limit of (5.111), `F̂_Y → 2·1.2429/Φ³` as Φ → 0.
///
/// Seed 000, eq. (5.111) (the coefficient of `1/Φ³`).
pub const WEAK_ADHESION_YIELD_COEFFICIENT: f64 = 2.0 * 1.2429;

/// `Q̃`: fully plastic `F̂ = (Q̃/Φ) â² = (2Q̃/(3Φ)) d̂`. Derived, not the seed's rounded
/// `Q̃ ≈ 3.5`: as Φ → 0 the model in units of its yield onset is the interpolation
/// model with `Q = 2Q̃/c^(1/3)`, `c` = [`WEAK_ADHESION_YIELD_COEFFICIENT`]; `Q̃ =
/// (Q/2) c^(1/3)` with `Q = 5` ([`crate::DEFAULT_PLASTIC_SLOPE`]) gives 3.3865857.
///
/// Seed 000, eq. (5.114) (`Q̃ ≈ 3.5`).
pub const ADHESIVE_PLASTIC_SLOPE: f64 = 3.386_585_697_520_309;
/// `D̃`: fully plastic for `d̂ > D̃/Φ²`. Derived, not the seed's rounded `D̃ ≈ 400`:
/// as Φ → 0 the onset in units of the yield depth `d̂_Y → 3 c^(2/3)/Φ²` is
/// `D = D̃/(3 c^(2/3))`; `D̃ = 3 D c^(2/3)` with `D = 80`
/// ([`crate::DEFAULT_PLASTIC_ONSET`]) gives 440.40817.
///
/// Seed 000, eq. (5.114) (`D̃ ≈ 400`).
pub const ADHESIVE_PLASTIC_ONSET: f64 = 440.408_167_167_326_1;
/// `κ` of `Φ = κ (Δγ E*²/(σ_Y³ R))^(1/3)`, derived so that the weak-adhesion yield
/// load `c F_n/Φ³` ((5.111), `F_n = (3/2)πΔγR`) equals Thornton's Hertz yield load
/// `F_Y = (4/3)E* R² (π p_Y/(2E*))³` of (5.102) exactly (`p_Y = 1.6 σ_Y`):
/// `κ = (9c/(π² 1.6³))^(1/3) = 0.82101231`. With it (5.126) reads
/// `v_c²/v_Y² = 0.35550 Φ⁵` (the seed's "≈ 0.37 Φ⁵"; `K/κ⁵` with
/// `K = Û_JKR (3∛3/8) π^(5/3) / ((8/15)(4π/5)⁵)`, Û_JKR the normalized fixed-grip
/// loss). The book's own definition (3.293) is not available.
///
/// Seed 000, the Φ of (5.111), (5.126) (derivation in the crate README).
pub const ADHESION_PARAMETER_FACTOR: f64 = 0.821_012_305_737_916_4;

/// The adhesion parameter `Φ = κ (Δγ E*²/(σ_Y³ R))^(1/3)` from material data:
/// effective modulus `E*` (Pa), effective radius `R` (m), yield stress `σ_Y` (Pa),
/// work of adhesion `Δγ` (J/m²), all finite and > 0.
///
/// Seed 000, the parameter Φ of (5.111) (the book's (3.293)); κ =
/// [`ADHESION_PARAMETER_FACTOR`] matches the weak-adhesion yield load to (5.102).
pub fn adhesion_parameter(
    effective_modulus: f64,
    effective_radius: f64,
    yield_stress: f64,
    work_of_adhesion: f64,
) -> Result<f64> {
    let e = validate::positive("effective_modulus", effective_modulus)?;
    let r = validate::positive("effective_radius", effective_radius)?;
    let s = validate::positive("yield_stress", yield_stress)?;
    let dg = validate::positive("work_of_adhesion", work_of_adhesion)?;
    // (Δγ/R)^(1/3) (E/σ)^(2/3) / σ^(1/3), ordered against overflow.
    let phi = ADHESION_PARAMETER_FACTOR * (dg / r).cbrt() * (e / s).powf(2.0 / 3.0) / s.cbrt();
    positive_output(MODEL, "adhesion parameter", phi)
}

/// The adhesive yield force `F̂_Y(Φ) = 2(0.111Φ − 0.8236 − 0.0636/Φ + 0.0087/Φ² +
/// 1.2429/Φ³)` (units of `F_n`, compression positive), for ν = 0.3.
///
/// Seed 000, eq. (5.111) (from ref. \[51\]).
pub fn adhesive_yield_force(adhesion_parameter: f64) -> Result<f64> {
    let p = validate::positive("adhesion_parameter", adhesion_parameter)?;
    let f = 2.0 * (0.111 * p - 0.8236 - 0.0636 / p + 0.0087 / (p * p))
        + WEAK_ADHESION_YIELD_COEFFICIENT / (p * p * p);
    finite_output(MODEL, "yield force", f)
}

/// The state at maximum compression and the JKR unloading it sets up (normalized).
///
/// Seed 000, eqs. (5.121)-(5.125).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct AdhesiveTurningPoint {
    /// `d̂_max`.
    pub max_depth: f64,
    /// `F̂_max` (compression positive).
    pub max_force: f64,
    /// `â_max`.
    pub max_contact_radius: f64,
    /// `R_p/R` (corrected (5.123), see [`AdhesiveInterpolation::turning_point`]).
    pub unloading_radius_ratio: f64,
    /// `d̂_res`, seed 000 eq. (5.124).
    pub residual_depth: f64,
    /// `d̂` where contact breaks, `d̂_res + d̂_c^WS(R_p)`, seed 000 eq. (5.125).
    pub separation_depth: f64,
    /// The kinetic energy left at separation (units of `F_n d_n`, < 0: the body
    /// cannot get there and sticks).
    pub rebound_energy: f64,
}

/// The adhesive interpolation model in normalized units, for one adhesion parameter
/// Φ and the constants `Q̃`, `D̃` (by default [`ADHESIVE_PLASTIC_SLOPE`],
/// [`ADHESIVE_PLASTIC_ONSET`], derived so that Φ → 0 gives the interpolation model
/// with Q = 5, D = 80).
///
/// Loading from first touch (`d̂ = 0`): JKR (`F̂ = â³ − 2â^(3/2)`,
/// `d̂ = 3â² − 4â^(1/2)`) up to the yield state `(â_Y, d̂_Y, F̂_Y)` of
/// (5.111)-(5.113); the cubics (5.115)-(5.120) to `d̂_0 = D̃/Φ²`; beyond, the fully
/// plastic law (5.114). If `d̂_Y < 0` (for Φ between about 1.8 and 3.3 the yield
/// load lies below the JKR first-touch force −8/9) the contact yields at first touch
/// and loading starts on the cubic.
///
/// Seed 000, eqs. (5.111)-(5.125).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AdhesiveInterpolation {
    phi: f64,
    plastic_slope: f64,
    plastic_onset: f64,
    yield_state: JkrContactState,
    onset_depth: f64,
    force: Hermite,
    radius: Hermite,
    work_at_yield: f64,
    work_at_onset: f64,
}

impl AdhesiveInterpolation {
    /// The model for adhesion parameter Φ (finite, > 0) with `Q̃` =
    /// [`ADHESIVE_PLASTIC_SLOPE`] ≈ 3.387, `D̃` = [`ADHESIVE_PLASTIC_ONSET`] ≈ 440.4.
    ///
    /// Seed 000, eqs. (5.111)-(5.120).
    pub fn new(adhesion_parameter: f64) -> Result<Self> {
        Self::with_constants(
            adhesion_parameter,
            ADHESIVE_PLASTIC_SLOPE,
            ADHESIVE_PLASTIC_ONSET,
        )
    }

    /// The model with explicit `Q̃` (> 0) and `D̃` (> 0). Fails when the elasto-plastic
    /// range is empty (`d̂_0 ≤ max(d̂_Y, 0)`, Φ above about 9.70 for the defaults) or its
    /// cubics do not increase monotonically.
    ///
    /// Seed 000, eqs. (5.111)-(5.120).
    pub fn with_constants(
        adhesion_parameter: f64,
        plastic_slope: f64,
        plastic_onset: f64,
    ) -> Result<Self> {
        let phi = validate::positive("adhesion_parameter", adhesion_parameter)?;
        let q = validate::positive("plastic_slope", plastic_slope)?;
        let dd = validate::positive("plastic_onset", plastic_onset)?;
        if !(1e-4..=1e4).contains(&phi) {
            return Err(Error::invalid(
                "adhesion_parameter",
                phi,
                "must lie in [1e-4, 1e4]",
            ));
        }
        if q > 1e6 || dd > 1e8 {
            return Err(Error::invalid(
                if q > 1e6 {
                    "plastic_slope"
                } else {
                    "plastic_onset"
                },
                if q > 1e6 { q } else { dd },
                "must be <= 1e6 (Q) and <= 1e8 (D)",
            ));
        }
        // (5.111)-(5.113)
        let f_y = adhesive_yield_force(phi)?;
        if f_y <= -1.0 {
            return Err(Error::invalid(
                "adhesion_parameter",
                phi,
                "gives a yield force F_Y <= -F_n, outside the fit (5.111)",
            ));
        }
        let a_y = (1.0 + (1.0 + f_y).sqrt()).powf(2.0 / 3.0);
        let d_y = jkr::depth(a_y)?;
        // (5.114), (5.117), (5.120)
        let d0 = dd / (phi * phi);
        let f0 = 2.0 * q * dd / (3.0 * phi * phi * phi);
        let f0p = 2.0 * q / (3.0 * phi);
        let a0 = (2.0 * dd / (3.0 * phi * phi)).sqrt();
        let a0p = (phi * phi / (6.0 * dd)).sqrt();
        if !exceeds(d0, d_y.max(0.0)) {
            return Err(Error::invalid(
                "adhesion_parameter",
                phi,
                "leaves no elasto-plastic range: the fully plastic onset D/Phi^2 lies \
                 below the yield depth",
            ));
        }
        // (5.116), (5.119): slopes of the JKR branch at the yield state.
        let slope = 6.0 * a_y - 2.0 / a_y.sqrt();
        let c1 = (3.0 * a_y * a_y - 3.0 * a_y.sqrt()) / slope;
        let c4 = 1.0 / slope;
        let length = d0 - d_y;
        let force = Hermite::new(f_y, c1, f0, f0p, length);
        let radius = Hermite::new(a_y, c4, a0, a0p, length);
        let start = (-d_y).max(0.0);
        if !exceeds(force.min_slope(start), 0.0) || !exceeds(radius.min_slope(start), 0.0) {
            return Err(Error::invalid(
                "adhesion_parameter",
                phi,
                "gives an elasto-plastic interpolation (5.115)/(5.118) that is not increasing",
            ));
        }
        let work_at_yield = if d_y > 0.0 {
            jkr::kinetic_energy_to_reach(a_y)?
        } else {
            0.0
        };
        let work_at_onset = work_at_yield + force.integral(length) - force.integral(start);
        let model = AdhesiveInterpolation {
            phi,
            plastic_slope: q,
            plastic_onset: dd,
            yield_state: JkrContactState {
                contact_radius: a_y,
                depth: d_y,
                force: f_y,
            },
            onset_depth: d0,
            force,
            radius,
            work_at_yield,
            work_at_onset,
        };
        finite_output(MODEL, "loading work", work_at_onset)?;
        Ok(model)
    }

    /// The adhesion parameter Φ.
    ///
    /// Seed 000, the Φ of (5.111).
    pub fn adhesion_parameter(&self) -> f64 {
        self.phi
    }

    /// The yield state `(â_Y, d̂_Y, F̂_Y)` on the JKR branch.
    ///
    /// Seed 000, eqs. (5.111)-(5.113).
    pub fn yield_state(&self) -> JkrContactState {
        self.yield_state
    }

    /// The onset of the fully plastic range `d̂_0 = D̃/Φ²`.
    ///
    /// Seed 000, eq. (5.114).
    pub fn plastic_onset_depth(&self) -> f64 {
        self.onset_depth
    }

    /// The loading work from first touch to the yield state (units of `F_n d_n`; 0
    /// when the contact yields at first touch, negative when the yield state lies in
    /// the adhesive well, so that even a vanishing impact speed reaches it).
    ///
    /// Seed 000, (5.35) (the JKR loading work, `tabor_jkr`) up to (5.113).
    pub fn yield_kinetic_energy(&self) -> f64 {
        self.work_at_yield
    }

    /// The loading force `F̂(d̂)` at `d̂ ≥ 0` (finite).
    ///
    /// Seed 000, eqs. (5.111), (5.114), (5.115).
    pub fn loading_force(&self, depth: f64) -> Result<f64> {
        let d = validate::non_negative("depth", depth)?;
        finite_output(MODEL, "loading force", self.loading_state(d)?.force)
    }

    /// The loading contact radius `â(d̂)` at `d̂ ≥ 0` (finite).
    ///
    /// Seed 000, eqs. (5.112), (5.114), (5.118).
    pub fn loading_contact_radius(&self, depth: f64) -> Result<f64> {
        let d = validate::non_negative("depth", depth)?;
        finite_output(
            MODEL,
            "loading contact radius",
            self.loading_state(d)?.contact_radius,
        )
    }

    /// The loading work `∫_0^d̂ F̂ dd̂` (units of `F_n d_n`) at `d̂ ≥ 0`.
    ///
    /// Seed 000, (5.35) on the JKR part, integrals of (5.115) and (5.114) beyond.
    pub fn loading_work(&self, depth: f64) -> Result<f64> {
        let d = validate::non_negative("depth", depth)?;
        let w = if d <= self.yield_state.depth {
            jkr::kinetic_energy_to_reach(jkr::contact_radius_at_depth(d)?)?
        } else if d <= self.onset_depth {
            self.cubic_work(d)
        } else {
            self.plastic_work(d)
        };
        finite_output(MODEL, "loading work", w)
    }

    /// State on the loading curve at `d̂` (≥ 0, or slightly below for the simulator).
    pub(crate) fn loading_state(&self, d: f64) -> Result<JkrContactState> {
        let y = self.yield_state;
        let (a, f) = if d <= y.depth {
            let a = jkr::contact_radius_at_depth(d)?;
            (a, jkr::force(a)?)
        } else if d <= self.onset_depth {
            let t = d - y.depth;
            (self.radius.value(t), self.force.value(t))
        } else {
            (
                (2.0 * d / 3.0).sqrt(),
                2.0 * self.plastic_slope * d / (3.0 * self.phi),
            )
        };
        Ok(JkrContactState {
            contact_radius: a,
            depth: d,
            force: f,
        })
    }

    fn cubic_work(&self, d: f64) -> f64 {
        let start = (-self.yield_state.depth).max(0.0);
        self.work_at_yield + self.force.integral(d - self.yield_state.depth)
            - self.force.integral(start)
    }

    fn plastic_work(&self, d: f64) -> f64 {
        let d0 = self.onset_depth;
        self.work_at_onset + self.plastic_slope / (3.0 * self.phi) * (d - d0) * (d + d0)
    }

    /// The maximum depth `d̂_max` reached with kinetic energy `kinetic_energy`
    /// (units of `F_n d_n`, finite, > 0): the root of `Ŵ(d̂_max) = Ê` (JKR energy
    /// balance (5.35) by `tabor_jkr`, Brent on the quartic of the cubic range,
    /// closed form in the plastic range).
    ///
    /// Seed 000, eqs. (5.35), (5.114), (5.115).
    pub fn max_depth(&self, kinetic_energy: f64) -> Result<f64> {
        let k = validate::positive("kinetic_energy", kinetic_energy)?;
        Ok(self.max_state(k)?.depth)
    }

    fn max_state(&self, k: f64) -> Result<JkrContactState> {
        let d = if k <= self.work_at_yield {
            let a = jkr::max_contact_radius(k, 1e-14)?.contact_radius;
            return Ok(JkrContactState {
                contact_radius: a,
                depth: jkr::depth(a)?,
                force: jkr::force(a)?,
            });
        } else if k <= self.work_at_onset {
            let lo = self.yield_state.depth.max(0.0);
            brent(
                |d| self.cubic_work(d) - k,
                lo,
                self.onset_depth,
                RootTolerance::relative(4.0 * f64::EPSILON),
            )?
            .value
        } else {
            let d0 = self.onset_depth;
            (d0 * d0 + 3.0 * self.phi * (k - self.work_at_onset) / self.plastic_slope).sqrt()
        };
        self.loading_state(finite_output(MODEL, "maximum depth", d)?)
    }

    /// The turning point of an impact with kinetic energy `kinetic_energy` (units of
    /// `F_n d_n`, > 0) and the JKR unloading it sets up: `R_p` from continuity of the
    /// force, `d_res` (5.124), separation depth (5.125), and the rebound energy
    /// `(R_p/R)^(4/3) [Ŵ_JKR(â'_max) − Ŵ_JKR(â'_c)]` with `â' = â (R/R_p)^(2/3)`.
    ///
    /// `R_p`: continuity of (5.122) at the turning point gives
    /// `R_p = 4E* a_max³ / (3(F_max + √(8π a_max³ Δγ E*)))` (compression positive);
    /// the printed (5.123) lacks the factor 3 on the root (proved by a test: only the
    /// corrected form makes the unloading force equal `F_max` at `a_max`).
    ///
    /// Seed 000, eqs. (5.121)-(5.125).
    pub fn turning_point(&self, kinetic_energy: f64) -> Result<AdhesiveTurningPoint> {
        let k = validate::positive("kinetic_energy", kinetic_energy)?;
        let s = self.max_state(k)?;
        let u = JkrUnloading::from_turning_point(s)?;
        let critical = jkr::critical_state(SeparationRule::FixedGrip);
        let rebound = u.rho.powf(4.0 / 3.0)
            * (jkr::kinetic_energy_to_reach(s.contact_radius / u.rho.powf(2.0 / 3.0))?
                - jkr::kinetic_energy_to_reach(critical.contact_radius)?);
        Ok(AdhesiveTurningPoint {
            max_depth: s.depth,
            max_force: s.force,
            max_contact_radius: s.contact_radius,
            unloading_radius_ratio: u.rho,
            residual_depth: u.residual,
            separation_depth: u.separation,
            rebound_energy: finite_output(MODEL, "rebound energy", rebound)?,
        })
    }

    /// The kinetic energy lost (units of `F_n d_n`) by an impact with kinetic energy
    /// `kinetic_energy` (> 0): `Ê − Ê_rebound`. When the body cannot reach the
    /// separation point (`Ê_rebound < 0`) this exceeds `Ê` and the core reports
    /// sticking (as the constant elastic JKR loss does below `v_c`).
    ///
    /// Seed 000, eqs. (5.111)-(5.125).
    pub fn energy_loss(&self, kinetic_energy: f64) -> Result<f64> {
        let t = self.turning_point(kinetic_energy)?;
        Ok((kinetic_energy - t.rebound_energy).max(0.0))
    }

    /// The restitution at `v0/v_c` (> 0), `v_c` the elastic JKR sticking velocity
    /// (5.38): kinetic energy `Û_JKR (v0/v_c)²`, restitution by (5.37) from the core.
    ///
    /// Seed 000, text after (5.125): ε depends on `v0/v_c` and Φ only.
    pub fn restitution(&self, speed_ratio: f64) -> Result<f64> {
        let s = validate::positive("speed_ratio", speed_ratio)?;
        let u_jkr = jkr::energy_loss(
            SeparationRule::FixedGrip,
            tabor_numerics::tolerance::DEFAULT_TOLERANCE,
        )?
        .value;
        let kinetic = finite_output(MODEL, "kinetic energy", u_jkr * s * s)?;
        // Units: v_c = 1, energy F_n d_n, so the mass is 2 Û_JKR.
        restitution_from_loss(self.energy_loss(kinetic)?, 2.0 * u_jkr, s)
    }
}

/// JKR unloading with radius `R_p = ρ R` (normalized): (5.121)-(5.125).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct JkrUnloading {
    /// `ρ = R_p/R`.
    pub(super) rho: f64,
    /// `d̂_res`.
    pub(super) residual: f64,
    /// `d̂` where contact breaks.
    pub(super) separation: f64,
}

impl JkrUnloading {
    /// `ρ` from continuity of the force, `F̂ = â³/ρ − 2â^(3/2)` (corrected (5.123));
    /// `d̂_res` (5.124): `d̂ − d̂_res = ρ^(1/3) d̂_JKR(â/ρ^(2/3))`; separation (5.125).
    pub(super) fn from_turning_point(s: JkrContactState) -> Result<Self> {
        let a = s.contact_radius;
        let rho = positive_output(MODEL, "R_p/R", a * a * a / (s.force + 2.0 * a * a.sqrt()))?;
        let scaled = a / rho.powf(2.0 / 3.0);
        let residual = s.depth - rho.cbrt() * jkr::depth(scaled)?;
        let critical = jkr::critical_state(SeparationRule::FixedGrip);
        Ok(JkrUnloading {
            rho,
            residual,
            separation: residual + rho.cbrt() * critical.depth,
        })
    }

    /// `(â, F̂)` at depth `d̂` on the unloading branch (clamped at the instability).
    pub(super) fn state(&self, d: f64) -> Result<(f64, f64)> {
        let scaled = jkr::contact_radius_at_depth((d - self.residual) / self.rho.cbrt())?;
        Ok((
            scaled * self.rho.powf(2.0 / 3.0),
            self.rho * jkr::force(scaled)?,
        ))
    }
}
