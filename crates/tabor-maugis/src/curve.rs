//! The Maugis-Dugdale equilibrium curve at a given contact radius, in Maugis'
//! (1992) own units: the contact branch of [`crate::branch`] is parametrized by
//! θ = arccos(a/b), so a contact radius is reached by inverting â(θ) (monotone).
//!
//! Maugis' units (K = 4E*/3): contact radius A = a/(πΔγR²/K)^(1/3), load
//! P̄ = F/(πΔγR), penetration Δ̄ = δ/(π²Δγ²R/K²)^(1/3), and his parameter
//! λ = 2σ0 (R/(πΔγK²))^(1/3) (Λ = [`LAMBDA_PER_MAUGIS_PARAMETER`] λ). From the
//! seed's units: A = (3/2)^(1/3) â, P̄ = (3/2) F̂, Δ̄ = (3/2)^(2/3)/3 · d̂. These
//! are the quantities of `Adhesion.ReferenceSolutions.MaugisDugdale.
//! _load_and_displacement(A, λ)`.
//!
//! [`MaugisDugdaleSphere`] carries the curve into SI units for a sphere (E*, R,
//! Δγ, σ0), and [`dmt_curve_point`] gives its λ → 0 limit, the DMT curve (the
//! functions of `Adhesion.ReferenceSolutions.{MaugisDugdale,DMT}`).
//!
//! [`LAMBDA_PER_MAUGIS_PARAMETER`]: crate::units::LAMBDA_PER_MAUGIS_PARAMETER

use crate::branch::{contact_state, ContactBranchState};
use crate::units::tabor_parameter_from_maugis;
use std::f64::consts::{FRAC_PI_2, PI};
use tabor_numerics::root_finding::{brent, RootTolerance};
use tabor_restitution::{validate, Error, Result};

const MODEL: &str = "Maugis-Dugdale curve";

/// Below this Maugis parameter λ the θ-parametrized branch loses digits (its terms
/// cancel): at λ = 1e-15 the load is off by 1e-8 relative, at 1e-30 by 23 %. The
/// curve is refused there; its DMT limit differs from it by O(λ) in the load and
/// O(λ^(1/2)) in the penetration (at 1e-10: 3e-10 and 1.5e-5 in Maugis' units).
pub const MIN_MAUGIS_PARAMETER: f64 = 1e-10;

/// `A / â = (3/2)^(1/3)`: Maugis' contact radius per the seed's `a/a_c`.
fn radius_factor() -> f64 {
    1.5f64.cbrt()
}

/// One point of the curve in Maugis' units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MaugisCurvePoint {
    /// P̄ = F/(πΔγR), positive in compression.
    pub load: f64,
    /// Δ̄ = δ/(π²Δγ²R/K²)^(1/3).
    pub penetration: f64,
}

/// The contact-branch state at normalized contact radius `contact_radius` (â =
/// a/a_c, ≥ 0) for Tabor parameter `lambda` (Λ): the θ ∈ (0, π/2] with
/// â(θ) = â, by bracket expansion towards θ → 0 (â grows without bound there)
/// and Brent's method to full precision; â = 0 is θ = π/2, the junction with the
/// no-contact branch.
///
/// Seed 000 section 3.3.3 (the branch used by eqs. (5.43)-(5.46)).
pub fn contact_state_at_radius(lambda: f64, contact_radius: f64) -> Result<ContactBranchState> {
    let lambda = validate::positive("lambda", lambda)?;
    let a_hat = validate::non_negative("contact_radius", contact_radius)?;
    if a_hat == 0.0 {
        return Ok(contact_state(lambda, FRAC_PI_2));
    }
    // â(θ) falls monotonically from +∞ (θ → 0) to 0 (θ = π/2): bracket from below
    let f = |t: f64| contact_state(lambda, t).contact_radius - a_hat;
    let mut lo = 0.5;
    while f(lo) <= 0.0 {
        lo *= 0.125;
        if lo < 1e-300 {
            return Err(Error::invalid(
                "contact_radius",
                contact_radius,
                "is too large for this Tabor parameter (no contact-branch state reaches it)",
            ));
        }
    }
    let hi = FRAC_PI_2;
    let theta = if f(hi) >= 0.0 {
        hi
    } else {
        brent(f, lo, hi, RootTolerance::relative(0.0))?.value
    };
    Ok(contact_state(lambda, theta))
}

/// The curve at Maugis' contact radius A (≥ 0) and Maugis parameter λ
/// (≥ [`MIN_MAUGIS_PARAMETER`]), in Maugis' units (module docs): the contact
/// branch at â = A/(3/2)^(1/3), converted. Below the minimum λ an error points to
/// the DMT limit.
///
/// Maugis (1992); seed 000 section 3.3.3.
pub fn maugis_curve_point(maugis_parameter: f64, contact_radius: f64) -> Result<MaugisCurvePoint> {
    let lambda = tabor_parameter_from_maugis(maugis_parameter)?;
    if maugis_parameter < MIN_MAUGIS_PARAMETER {
        return Err(Error::Model {
            model: MODEL,
            message: format!(
                "maugis_parameter = {maugis_parameter:e} is below {MIN_MAUGIS_PARAMETER:e}, where the \
                 Maugis-Dugdale branch can no longer be evaluated to full precision; the DMT limit \
                 (force_displacement(\"dmt\", ...)) is off from it by O(maugis_parameter^(1/2)) in the penetration"
            ),
        });
    }
    let a = validate::non_negative("contact_radius", contact_radius)?;
    let s = contact_state_at_radius(lambda, a / radius_factor())?;
    // F̂ = F/F_n with F_n = (3/2)πΔγR; d̂ = d/d_n with d_n = (3/2)^(2/3)/3 (π²Δγ²R/K²)^(1/3)
    let load = 1.5 * s.force;
    let penetration = s.depth * radius_factor() * radius_factor() / 3.0;
    if !(load.is_finite() && penetration.is_finite()) {
        return Err(Error::Model {
            model: MODEL,
            message: format!(
                "load or penetration overflows at contact_radius = {contact_radius:e}, maugis_parameter = {maugis_parameter:e}"
            ),
        });
    }
    Ok(MaugisCurvePoint { load, penetration })
}

/// The force-displacement curves of an adhesive sphere in SI units, by name
/// (Python's `tabor.force_displacement(model, …)`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum CurveModel {
    /// JKR, seed 000 eqs. (5.33), (5.34) (`tabor_jkr::JkrSphere`).
    Jkr,
    /// DMT, [`dmt_curve_point`].
    Dmt,
    /// Maugis-Dugdale, [`MaugisDugdaleSphere::curve_point`].
    MaugisDugdale,
}

tabor_restitution::menu! {
    CurveModel, "force-displacement model";
    Jkr => "jkr", "JKR (Willert 2020, (5.33)-(5.34)): F = K a³/R − √(8πa³E*Δγ), δ = a²/R − √(2πaΔγ/E*)";
    Dmt => "dmt", "DMT, the Maugis-Dugdale limit λ → 0: F = K a³/R − 2πΔγR, δ = a²/R";
    MaugisDugdale => "maugis-dugdale", "Maugis-Dugdale (Maugis 1992), needs the cohesive stress σ0";
}

/// One point of a force-displacement curve of a sphere in SI units.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SphereCurvePoint {
    /// Normal force (N), positive in compression.
    pub force: f64,
    /// Penetration (m), positive when the bodies overlap.
    pub penetration: f64,
}

fn finite_point(force: f64, penetration: f64, contact_radius: f64) -> Result<SphereCurvePoint> {
    if force.is_finite() && penetration.is_finite() {
        Ok(SphereCurvePoint { force, penetration })
    } else {
        Err(Error::Model {
            model: MODEL,
            message: format!(
                "force or penetration overflows at contact_radius = {contact_radius:e}"
            ),
        })
    }
}

/// The DMT curve, the λ → 0 limit of Maugis-Dugdale: the Hertz contact plus the
/// constant adhesive force 2πΔγR, `F = 4E*a³/(3R) − 2πΔγR`, `δ = a²/R`, for
/// effective modulus E* (Pa), effective radius R (m), work of adhesion Δγ (J/m²)
/// and contact radius `a` (m, ≥ 0).
///
/// Derjaguin, Muller & Toporov (1975); Maugis (1992) as λ → 0 (the README's
/// bibliography).
pub fn dmt_curve_point(
    effective_modulus: f64,
    effective_radius: f64,
    work_of_adhesion: f64,
    contact_radius: f64,
) -> Result<SphereCurvePoint> {
    let e = validate::positive("effective_modulus", effective_modulus)?;
    let r = validate::positive("effective_radius", effective_radius)?;
    let w = validate::positive("work_of_adhesion", work_of_adhesion)?;
    let a = validate::non_negative("contact_radius", contact_radius)?;
    let force = 4.0 * e * a.powi(3) / (3.0 * r) - 2.0 * PI * w * r;
    finite_point(force, a * a / r, a)
}

/// A Maugis-Dugdale sphere in SI units: its Maugis parameter and the scales of
/// Maugis' units (module docs), K = 4E*/3.
///
/// Maugis (1992); seed 000 section 3.3.3.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MaugisDugdaleSphere {
    maugis_parameter: f64,
    /// (πΔγR²/K)^(1/3) (m).
    radius_unit: f64,
    /// πΔγR (N).
    force_unit: f64,
    /// (π²Δγ²R/K²)^(1/3) (m).
    depth_unit: f64,
}

impl MaugisDugdaleSphere {
    /// The sphere of effective modulus E* (Pa), effective radius R (m), work of
    /// adhesion Δγ (J/m²) and Dugdale cohesive stress σ0 (Pa), all finite and > 0;
    /// fails when λ = 2σ0 (R/(πΔγK²))^(1/3) or a scale is not representable.
    pub fn new(
        effective_modulus: f64,
        effective_radius: f64,
        work_of_adhesion: f64,
        cohesive_stress: f64,
    ) -> Result<Self> {
        let e = validate::positive("effective_modulus", effective_modulus)?;
        let r = validate::positive("effective_radius", effective_radius)?;
        let w = validate::positive("work_of_adhesion", work_of_adhesion)?;
        let s0 = validate::positive("cohesive_stress", cohesive_stress)?;
        let k = 4.0 * e / 3.0;
        let sphere = MaugisDugdaleSphere {
            maugis_parameter: 2.0 * s0 / (PI * w * k * k / r).cbrt(),
            radius_unit: (PI * w * r * r / k).cbrt(),
            force_unit: PI * w * r,
            depth_unit: (PI * PI * w * w * r / (k * k)).cbrt(),
        };
        let all = [
            sphere.maugis_parameter,
            sphere.radius_unit,
            sphere.force_unit,
            sphere.depth_unit,
        ];
        if all.iter().all(|x| x.is_finite() && *x > 0.0) {
            Ok(sphere)
        } else {
            Err(Error::Model {
                model: MODEL,
                message: format!(
                    "Maugis' lambda 2σ0/(πΔγK²/R)^(1/3) = {:e} or a scale of Maugis' units is not \
                     representable (E* = {e:e}, R = {r:e}, Δγ = {w:e}, σ0 = {s0:e})",
                    sphere.maugis_parameter
                ),
            })
        }
    }

    /// Maugis' λ = 2σ0 (R/(πΔγK²))^(1/3) (Maugis 1992; the argument order and
    /// meaning of `Adhesion.ReferenceSolutions.MaugisDugdale.maugis_parameter`).
    pub fn maugis_parameter(&self) -> f64 {
        self.maugis_parameter
    }

    /// Force and penetration at contact radius `a` (m, ≥ 0): [`maugis_curve_point`]
    /// at A = a/(πΔγR²/K)^(1/3), times πΔγR and (π²Δγ²R/K²)^(1/3).
    pub fn curve_point(&self, contact_radius: f64) -> Result<SphereCurvePoint> {
        let a = validate::non_negative("contact_radius", contact_radius)?;
        let p = maugis_curve_point(self.maugis_parameter, a / self.radius_unit)?;
        finite_point(
            p.load * self.force_unit,
            p.penetration * self.depth_unit,
            contact_radius,
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// θ → state → â → θ again, over the branch, for small to large Λ.
    #[test]
    fn the_inversion_returns_the_branch_parameter() {
        for lambda in [1e-6, 0.05, 0.3, 1.0, 3.0, 100.0] {
            for k in 1..=40 {
                let theta = FRAC_PI_2 * f64::from(k) / 40.0;
                let s = contact_state(lambda, theta);
                let back = contact_state_at_radius(lambda, s.contact_radius).unwrap();
                let scale = s.force.abs().max(1.0);
                assert!(
                    (back.force - s.force).abs() <= 1e-9 * scale,
                    "Λ {lambda} θ {theta}: {back:?} vs {s:?}"
                );
                assert!((back.contact_radius / s.contact_radius - 1.0).abs() < 1e-12);
            }
        }
    }

    /// `Adhesion` 0.93, `ReferenceSolutions.MaugisDugdale._load_and_displacement(A, λ)`
    /// (its own brentq on Maugis' equations, run once in the Python test venv):
    /// (λ, A, P̄, Δ̄).
    const ADHESION: [(f64, f64, f64, f64); 9] = [
        (0.3, 0.5, -1.8155450993492535, -0.5393806485530551),
        (0.3, 1.0, -1.4269046016902966, 0.16620328141296892),
        (0.3, 2.0, 4.155839648164514, 3.0664431438402513),
        (1.0, 0.5, -1.3273331699027757, -0.8914213056753271),
        (1.0, 1.0, -1.5796270206018663, -0.33662777827243584),
        (1.0, 2.0, 2.456207783072534, 2.3490363584811425),
        (3.0, 0.5, -0.849404041031669, -0.922856345632334),
        (3.0, 1.0, -1.493517581179725, -0.5822442345607097),
        (3.0, 2.0, 1.3730808033427593, 1.842588548630629),
    ];

    #[test]
    fn agrees_with_adhesion_to_1e8() {
        for (lam, a, load, pen) in ADHESION {
            let p = maugis_curve_point(lam, a).unwrap();
            assert!(
                (p.load / load - 1.0).abs() < 1e-8,
                "λ {lam} A {a}: {p:?} vs {load}"
            );
            assert!(
                (p.penetration / pen - 1.0).abs() < 1e-8,
                "λ {lam} A {a}: {p:?} vs {pen}"
            );
        }
    }

    /// Maugis' DMT limit (λ → 0): P̄ = A³ − 2, Δ̄ = A². In Maugis' equations
    /// Δ̄ = A² − (4/3)λ√(C² − A²) and P̄ = A³ − λA²(√(m²−1) + m² arctan√(m²−1)),
    /// m = C/A; the load tends to A³ − (π/2)λC², so the cohesive zone grows like
    /// C = 2/√(πλ) and the penetration gap is (8/3)(λ/π)^(1/2) to O(λ). The load
    /// gap is O(λ): it shrinks by 100 from λ = 1e-6 to 1e-8.
    #[test]
    fn dmt_limit_for_small_maugis_parameter() {
        for a in [0.5, 1.0, 2.0] {
            let gap = |lam: f64| {
                let p = maugis_curve_point(lam, a).unwrap();
                (a * a * a - 2.0 - p.load, a * a - p.penetration)
            };
            let (l6, _) = gap(1e-6);
            let (l8, d8) = gap(1e-8);
            let expected = 8.0 / 3.0 * (1e-8 / PI).sqrt();
            assert!(
                (d8 / expected - 1.0).abs() < 1e-3,
                "A {a}: {d8} vs {expected}"
            );
            assert!(
                (l6 / l8 / 100.0 - 1.0).abs() < 1e-2,
                "A {a}: load gap {l6} -> {l8}"
            );
        }
    }

    /// Maugis' JKR limit (large λ): P̄ = A³ − √(6A³), Δ̄ = A² − (2/3)√(6A)
    /// (Maugis 1992 eq. (6.5)), to the O(1/λ) of a finite range.
    #[test]
    fn jkr_limit_for_large_maugis_parameter() {
        for a in [0.5, 1.0, 2.0, 4.0] {
            let p = maugis_curve_point(1e6, a).unwrap();
            let load = a * a * a - (6.0 * a * a * a).sqrt();
            let pen = a * a - 2.0 / 3.0 * (6.0 * a).sqrt();
            assert!(
                (p.load - load).abs() < 1e-4 * load.abs().max(1.0),
                "{a}: {p:?} vs {load}"
            );
            assert!(
                (p.penetration - pen).abs() < 1e-4 * pen.abs().max(1.0),
                "{a}: {p:?} vs {pen}"
            );
        }
    }

    /// The SI sphere: λ against the route through the seed's Λ (JKR scales, (5.43)),
    /// its large-λ curve against the JKR sphere's (5.33)/(5.34), its small-λ curve
    /// against DMT.
    #[test]
    fn si_sphere_limits() {
        let (e, r, w) = (1e9, 1e-6, 0.05);
        // σ0 for λ = 1e6 and λ = 1e-8
        let lam_one = MaugisDugdaleSphere::new(e, r, w, 1.0)
            .unwrap()
            .maugis_parameter();
        let via_lambda = crate::units::tabor_parameter_from_cohesive_stress(1.0, w, e, r).unwrap()
            / crate::units::LAMBDA_PER_MAUGIS_PARAMETER;
        assert!((lam_one / via_lambda - 1.0).abs() < 1e-14);
        let jkr = tabor_jkr::JkrSphere::new(e, r, w).unwrap();
        let big = MaugisDugdaleSphere::new(e, r, w, 1e6 / lam_one).unwrap();
        let small = MaugisDugdaleSphere::new(e, r, w, 1e-8 / lam_one).unwrap();
        let a_c = jkr.scales().contact_radius;
        for a in [0.5 * a_c, a_c, 2.0 * a_c] {
            let p = big.curve_point(a).unwrap();
            let (f, d) = (jkr.force(a).unwrap(), jkr.depth(a).unwrap());
            let (fs, ds) = (jkr.scales().force, jkr.scales().depth);
            assert!((p.force - f).abs() < 1e-4 * fs, "{a}: {p:?} vs {f}");
            assert!((p.penetration - d).abs() < 1e-4 * ds, "{a}: {p:?} vs {d}");
            let p = small.curve_point(a).unwrap();
            let dmt = dmt_curve_point(e, r, w, a).unwrap();
            assert!(
                (p.force - dmt.force).abs() < 1e-6 * fs,
                "{a}: {p:?} vs {dmt:?}"
            );
            assert!(
                (p.penetration - dmt.penetration).abs() < 1e-3 * ds,
                "{a}: {p:?} vs {dmt:?}"
            );
        }
    }

    #[test]
    fn errors_name_the_parameter() {
        let msg = |r: Result<MaugisCurvePoint>| r.unwrap_err().to_string();
        assert!(msg(maugis_curve_point(1e-11, 1.0)).contains("DMT"));
        assert!(msg(maugis_curve_point(1.0, -1.0)).contains("contact_radius"));
        assert!(msg(maugis_curve_point(f64::NAN, 1.0)).contains("maugis_parameter"));
        assert!(maugis_curve_point(1.0, f64::NAN).is_err());
        assert!(maugis_curve_point(1.0, f64::INFINITY).is_err());
        let e = MaugisDugdaleSphere::new(1e9, 1e-6, 0.05, 0.0).unwrap_err();
        assert!(e.to_string().contains("cohesive_stress"));
        let e = dmt_curve_point(-1.0, 1e-6, 0.05, 1e-7).unwrap_err();
        assert!(e.to_string().contains("effective_modulus"));
    }
}
