//! The per-contact normal force laws behind the C ABI, in Rust.
//!
//! Conventions (those of `tabor_dynamics::ForceLaw`, seed 000 eq. (5.5)): overlap
//! δ > 0 in contact (negative: a gap), overlap rate δ̇ > 0 while approaching, force
//! F > 0 when repulsive.

pub use crate::state::{TaborForce, TaborHistory};
use crate::table::{Table, TableError};
use std::sync::{Arc, OnceLock};
use tabor_dynamics::ForceLaw;
use tabor_jkr::{JkrForceLaw, JkrSphere, SeparationRule};
use tabor_maugis::branch::{junction_factor, no_contact_pull_off_radius, no_contact_state};
use tabor_maugis::{MaugisContact, MaugisDugdaleForceLaw, MaugisDugdaleImpact};
use tabor_restitution::{validate, Error, Result};
use tabor_viscoadhesive::{DampingModel, NormalDamping};

/// Which elastic-adhesive law a [`ContactLaw`] follows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum LawKind {
    /// Hertz, seed 000 eq. (5.5): F = (4/3)E*√R δ^(3/2), a = √(Rδ).
    Hertz,
    /// JKR, seed 000 eqs. (5.33)-(5.34), separating by `rule` (fixed grip: the
    /// seed's (5.36); load-controlled: LAMMPS's `jkr`).
    Jkr(SeparationRule),
    /// Maugis-Dugdale at Tabor parameter Λ, the impact path of seed 000 section
    /// 5.3.2 ((5.40)-(5.46)): jump-in at δ = −h, snap-off at the path's minimum depth.
    MaugisDugdale(f64),
    /// Maugis-Dugdale at a fixed Dugdale range h (m): each contact's Λ = d_n(R*)/h
    /// (module [`crate::lambda`]).
    MaugisDugdaleRange(f64),
}

/// The exact law at the reference radius, for overlaps beyond the table.
#[derive(Clone, Debug)]
pub(crate) enum Exact {
    Hertz,
    Jkr(JkrForceLaw),
    Maugis(Box<MaugisDugdaleForceLaw>),
    /// A per-contact-Λ law has no single exact law.
    PerContact,
}

/// The scales of a law at one effective radius R*: what turns the normalized
/// branch (F̂, â, d̂) into newtons and metres. F_n = (3/2)πwR* ∝ R*,
/// a_c = (9πwR*²/(8E*))^(1/3) ∝ R*^(2/3), d_n = a_c²/(3R*) ∝ R*^(1/3) (seed 000
/// (5.43), `tabor_jkr::JkrScales`); at a fixed Tabor parameter Λ the normalized
/// Maugis-Dugdale branch is the same for every radius, so one table serves them
/// all. Computing them costs one cube root ([`ContactLaw::scales`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RadiusScales {
    /// R* (m).
    pub effective_radius: f64,
    /// F_n (N; 1 for Hertz).
    pub force: f64,
    /// d_n (m; 1 for Hertz).
    pub depth: f64,
    /// 1/d_n (1/m).
    pub inv_depth: f64,
    /// a_c (m; 1 for Hertz).
    pub contact_radius: f64,
    /// √R* (Hertz's factor, seed 000 (5.5)).
    pub sqrt_radius: f64,
}

/// A normal contact law for one pair of particle types: elastic adhesion
/// ([`LawKind`]) plus optional Kuwabara-Kono viscous damping `F_d = 2E*A a δ̇`
/// (seed 000 eq. (5.66) with the contact radius a of the law, the form LAMMPS's
/// `damping viscoelastic` also uses), evaluated from a precomputed [`Table`] of
/// the branch in normalized variables. The table does not depend on the effective
/// radius (JKR; Maugis-Dugdale at a fixed Λ), so one law serves every radius
/// ([`ContactLaw::evaluate_scaled`]); the radius given at construction is the
/// reference the single-radius accessors report at.
#[derive(Clone, Debug)]
pub struct ContactLaw {
    pub(crate) kind: LawKind,
    pub(crate) effective_modulus: f64,
    pub(crate) damping_time: f64,
    /// A DEM damping law of LAMMPS's `pair granular` instead of Kuwabara-Kono.
    pub(crate) dem_damping: Option<NormalDamping>,
    /// The scales at the reference radius.
    pub(crate) reference: RadiusScales,
    /// F_n/R*, d_n/R*^(1/3), a_c/R*^(2/3): the scales at unit radius.
    pub(crate) unit_force: f64,
    pub(crate) unit_depth: f64,
    pub(crate) unit_contact_radius: f64,
    /// d̂₀: normalized depth at the table origin s = 0 (the branch minimum).
    pub(crate) table_origin: f64,
    /// 1/L: the table coordinate is s = √((d̂ − d̂₀)/L).
    pub(crate) inv_table_length: f64,
    /// Normalized overlap d̂ at which a contact forms.
    pub(crate) jump_in: f64,
    /// Normalized overlap below which a formed contact breaks.
    pub(crate) snap_off: f64,
    /// The most tensile force on the branch, F̂ (≤ 0).
    pub(crate) pull_off_force: f64,
    pub(crate) table: Option<Arc<Table>>,
    /// The table over Λ of a per-contact-Λ law (then `table` is `None`).
    pub(crate) per_contact: Option<(f64, Arc<crate::lambda_table::LambdaTable>)>,
    pub(crate) exact: Exact,
}

fn jkr_table() -> Result<Arc<Table>> {
    static TABLE: OnceLock<std::result::Result<Arc<Table>, String>> = OnceLock::new();
    TABLE
        .get_or_init(|| {
            let sphere = JkrSphere::new(1.0, 1.0, 1.0).map_err(|e| e.to_string())?;
            let s = sphere.scales();
            let law = JkrForceLaw::new(sphere, SeparationRule::FixedGrip);
            let d0 = law.separation_depth();
            Table::build(
                &|x: f64| -> Result<(f64, f64)> {
                    let d = d0 + x * x * s.depth;
                    Ok((
                        law.force(d, 0.0)? / s.force,
                        law.contact_radius(d, 0.0)? / s.contact_radius,
                    ))
                },
                None,
            )
            .map(Arc::new)
            .map_err(|e| e.to_string())
        })
        .clone()
        .map_err(|message| Error::Model {
            model: "tabor-ffi JKR table",
            message,
        })
}

impl ContactLaw {
    /// Hertz (seed 000 (5.5)) with effective modulus E* (Pa) and reference
    /// effective radius R* (m).
    pub fn hertz(effective_modulus: f64, effective_radius: f64) -> Result<Self> {
        let e = validate::positive("effective_modulus", effective_modulus)?;
        let r = validate::positive("effective_radius", effective_radius)?;
        Ok(ContactLaw {
            kind: LawKind::Hertz,
            effective_modulus: e,
            damping_time: 0.0,
            dem_damping: None,
            reference: RadiusScales {
                effective_radius: r,
                force: 1.0,
                depth: 1.0,
                inv_depth: 1.0,
                contact_radius: 1.0,
                sqrt_radius: r.sqrt(),
            },
            unit_force: 1.0,
            unit_depth: 1.0,
            unit_contact_radius: 1.0,
            table_origin: 0.0,
            inv_table_length: 1.0,
            jump_in: 0.0,
            snap_off: 0.0,
            pull_off_force: 0.0,
            table: None,
            per_contact: None,
            exact: Exact::Hertz,
        })
    }

    /// Sets the adhesive scales from `s`, the JKR scales at the reference radius.
    pub(crate) fn with_scales(mut self, s: &tabor_jkr::JkrScales) -> Self {
        let r = self.reference.effective_radius;
        let c = r.cbrt();
        self.reference.force = s.force;
        self.reference.depth = s.depth;
        self.reference.inv_depth = 1.0 / s.depth;
        self.reference.contact_radius = s.contact_radius;
        self.unit_force = s.force / r;
        self.unit_depth = s.depth / c;
        self.unit_contact_radius = s.contact_radius / (c * c);
        self
    }

    /// JKR (seed 000 (5.33)-(5.34)) with work of adhesion w (J/m², LAMMPS's 2γ)
    /// separating by `rule`.
    pub fn jkr(
        effective_modulus: f64,
        effective_radius: f64,
        work_of_adhesion: f64,
        rule: SeparationRule,
    ) -> Result<Self> {
        let sphere = JkrSphere::new(effective_modulus, effective_radius, work_of_adhesion)?;
        let s = sphere.scales();
        let fixed = JkrForceLaw::new(sphere, SeparationRule::FixedGrip);
        let law = JkrForceLaw::new(sphere, rule);
        let mut out = Self::hertz(effective_modulus, effective_radius)?.with_scales(&s);
        out.kind = LawKind::Jkr(rule);
        out.table_origin = fixed.separation_depth() / s.depth;
        out.jump_in = 0.0;
        out.snap_off = law.separation_depth() / s.depth;
        // the minimum of F̂ = â³ − 2â^(3/2) is −1 at â = 1 (the load-controlled point)
        out.pull_off_force = -1.0;
        out.table = Some(jkr_table()?);
        out.exact = Exact::Jkr(fixed);
        Ok(out)
    }

    /// Maugis-Dugdale at Tabor parameter Λ (seed 000 section 5.3.2) with work of
    /// adhesion w (J/m²): the range is h = d_n/Λ at every radius (Λ is held fixed,
    /// so h ∝ R*^(1/3)).
    pub fn maugis_dugdale(
        effective_modulus: f64,
        effective_radius: f64,
        work_of_adhesion: f64,
        tabor_parameter: f64,
    ) -> Result<Self> {
        let model = MaugisDugdaleImpact::new(
            MaugisContact::new(
                JkrSphere::new(effective_modulus, effective_radius, work_of_adhesion)?,
                tabor_parameter,
            )?,
            1.0,
        )?;
        let s = model.scales();
        let mut law = MaugisDugdaleForceLaw::new(&model)?;
        // leave the approach: the law now follows the equilibrium branch
        law.begin_impact(1.0, 1.0)?;
        law.on_branch_end(law.start_overlap(), 0.0)?;
        let (jump_in, pull_off) = law.jump_in_and_pull_off_depths();
        let lambda = model.tabor_parameter();
        // the adhesive features span a depth ~ 1/Λ (the range) when Λ < 1
        let length = (1.0 / lambda).max(1.0);
        let step = length * s.depth;
        // cases 1 and 2: the no-contact branch meets the contact branch at
        // b̂ = K b̂_c (seed 000 (5.46)), a kink of F̂(d̂)
        let kink = match tabor_maugis::TaborCase::of(lambda) {
            tabor_maugis::TaborCase::Contact => None,
            _ => {
                let b = junction_factor(lambda) * no_contact_pull_off_radius(lambda);
                let dj = no_contact_state(lambda, b).depth * s.depth;
                Some(((dj - pull_off) / step).max(0.0).sqrt())
            }
        };
        let table = {
            let law = &law;
            Table::build(
                &|x: f64| -> Result<(f64, f64)> {
                    let d = pull_off + x * x * step;
                    let at = |d: f64| -> Result<(f64, f64)> {
                        Ok((
                            law.force(d, 0.0)? / s.force,
                            law.contact_radius(d, 0.0)? / s.contact_radius,
                        ))
                    };
                    // exactly at the junction, rounding can leave the contact-branch
                    // root unbracketed: the state a hair shallower is the same
                    at(d).or_else(|_| at(d - 1e-12 * step))
                },
                kink,
            )?
        };
        let mut out = Self::hertz(effective_modulus, effective_radius)?.with_scales(&s);
        out.kind = LawKind::MaugisDugdale(model.tabor_parameter());
        out.table_origin = pull_off / s.depth;
        out.inv_table_length = 1.0 / length;
        out.jump_in = jump_in / s.depth;
        out.snap_off = pull_off / s.depth;
        out.pull_off_force = -law.pull_off_force()? / s.force;
        out.table = Some(Arc::new(table));
        out.exact = Exact::Maugis(Box::new(law));
        Ok(out)
    }

    /// Adds Kuwabara-Kono damping with dissipative time A (s): F_d = 2E*A a δ̇
    /// (seed 000 (5.66): F = (4/3)E*√R (δ^(3/2) + (3/2)A δ^(1/2) δ̇) for Hertz).
    pub fn with_damping(mut self, damping_time: f64) -> Result<Self> {
        self.damping_time = validate::non_negative("damping_time", damping_time)?;
        Ok(self)
    }

    /// Adds a DEM damping law of LAMMPS's `pair granular` (`damping viscoelastic |
    /// tsuji | coeff_restitution`) with its value (η_n0 in 1/(m s), the damping
    /// value, the restitution e), exactly `tabor_viscoadhesive::NormalDamping::dem`
    /// (the library's definitions: `c = η_n0 m* a`, or `α(e) √(m* (4/3) E* a)` on the
    /// law's own contact radius a, adhesive ones too). Replaces a Kuwabara-Kono time;
    /// the force then needs the effective mass ([`ContactLaw::evaluate_with_mass`]).
    pub fn with_dem_damping(mut self, model: DampingModel, value: f64) -> Result<Self> {
        self.dem_damping = Some(NormalDamping::dem(model, value, self.effective_modulus)?);
        self.damping_time = 0.0;
        Ok(self)
    }

    /// The DEM damping law, if any ([`ContactLaw::with_dem_damping`]).
    pub fn dem_damping(&self) -> Option<&NormalDamping> {
        self.dem_damping.as_ref()
    }

    /// The normal damping coefficient `c` (N s/m) of `F_d = c δ̇` at contact radius
    /// `contact_radius` (m) and effective mass `effective_mass` (kg; used by the DEM
    /// laws only): `2 E* A a` (Kuwabara-Kono, seed 000 (5.66)) or the DEM law's
    /// (`NormalDamping::coefficient`). LAMMPS's `damp_prefactor`, which the
    /// tangential damping `x_γ,t` multiplies.
    pub fn damping_coefficient(&self, effective_mass: f64, contact_radius: f64) -> f64 {
        match &self.dem_damping {
            Some(d) => d.coefficient(effective_mass, contact_radius),
            None => 2.0 * self.effective_modulus * self.damping_time * contact_radius.max(0.0),
        }
    }

    /// The elastic-adhesive law.
    pub fn kind(&self) -> LawKind {
        self.kind
    }

    /// The effective modulus E* (Pa).
    pub fn effective_modulus(&self) -> f64 {
        self.effective_modulus
    }

    /// The Kuwabara-Kono dissipative time A (s; 0 without damping).
    pub fn damping_time(&self) -> f64 {
        self.damping_time
    }

    /// The reference effective radius R* (m), the one given at construction.
    pub fn effective_radius(&self) -> f64 {
        self.reference.effective_radius
    }

    /// The scales at effective radius R* (m): one cube root (and a square root).
    /// Errors for R* not finite and > 0.
    pub fn scales(&self, effective_radius: f64) -> Result<RadiusScales> {
        let r = validate::positive("effective_radius", effective_radius)?;
        if r == self.reference.effective_radius {
            return Ok(self.reference);
        }
        Ok(self.scales_unchecked(r))
    }

    #[inline]
    pub(crate) fn scales_unchecked(&self, r: f64) -> RadiusScales {
        if !self.adhesive() {
            return RadiusScales {
                effective_radius: r,
                sqrt_radius: r.sqrt(),
                ..self.reference
            };
        }
        let c = r.cbrt();
        let depth = self.unit_depth * c;
        RadiusScales {
            effective_radius: r,
            force: self.unit_force * r,
            depth,
            inv_depth: 1.0 / depth,
            contact_radius: self.unit_contact_radius * c * c,
            sqrt_radius: r.sqrt(),
        }
    }

    /// The overlap at which a contact forms at the reference radius (m): 0, or
    /// −h for Maugis-Dugdale.
    pub fn jump_in_overlap(&self) -> f64 {
        self.jump_in_overlap_at(&self.reference)
    }

    /// The overlap at which a contact forms at the radius of `s` (m).
    pub fn jump_in_overlap_at(&self, s: &RadiusScales) -> f64 {
        if let Some((h, _)) = self.per_contact {
            return -h;
        }
        self.jump_in * s.depth
    }

    /// The overlap below which a formed contact breaks at the reference radius
    /// (m): 0 for Hertz, the separation depth of the rule for JKR, the pull-off
    /// depth of the path for Maugis-Dugdale.
    pub fn snap_off_overlap(&self) -> f64 {
        self.snap_off_overlap_at(&self.reference)
    }

    /// The snap-off overlap at the radius of `s` (m).
    pub fn snap_off_overlap_at(&self, s: &RadiusScales) -> f64 {
        if self.per_contact.is_some() {
            return self.local_at(s).map_or(f64::NAN, |l| l.snap_off * s.depth);
        }
        self.snap_off * s.depth
    }

    /// The largest gap (m, ≥ 0) at which the law can act at the reference radius:
    /// max(−jump-in, −snap-off). A DEM engine must keep pairs this far apart in its
    /// neighbor lists.
    pub fn interaction_range(&self) -> f64 {
        self.interaction_range_at(&self.reference)
    }

    /// The interaction range at the radius of `s` (m, ≥ 0; grows as R*^(1/3)).
    pub fn interaction_range_at(&self, s: &RadiusScales) -> f64 {
        if let Some((h, _)) = self.per_contact {
            return h.max(-self.snap_off_overlap_at(s));
        }
        (-self.jump_in).max(-self.snap_off).max(0.0) * s.depth
    }

    /// The most tensile force along the branch at the reference radius (N, ≤ 0):
    /// −(3/2)πwR for JKR (both rules pass through it), the minimum of the
    /// Maugis-Dugdale path (→ −2πwR as Λ → 0, DMT), 0 for Hertz.
    pub fn pull_off_force(&self) -> f64 {
        self.pull_off_force_at(&self.reference)
    }

    /// The pull-off force at the radius of `s` (N, ≤ 0; ∝ R*).
    pub fn pull_off_force_at(&self, s: &RadiusScales) -> f64 {
        if self.per_contact.is_some() {
            return self
                .local_at(s)
                .map_or(f64::NAN, |l| l.pull_off_force * s.force);
        }
        self.pull_off_force * s.force
    }

    /// The measured interpolation errors of the table (zero for Hertz).
    pub fn table_error(&self) -> TableError {
        if let Some((_, t)) = &self.per_contact {
            return t.node_error();
        }
        self.table.as_ref().map(|t| t.error()).unwrap_or_default()
    }

    /// The force scale F_n = (3/2)πwR at the reference radius (N; 1 for Hertz).
    pub fn force_scale(&self) -> f64 {
        self.reference.force
    }

    /// The elastic-adhesive force and contact radius on the branch at `overlap`
    /// (m) at the radius of `sc`, assuming the contact has formed; exact beyond
    /// the table.
    #[inline]
    fn branch(&self, sc: &RadiusScales, overlap: f64) -> Result<(f64, f64)> {
        match &self.table {
            None => {
                let d = overlap.max(0.0);
                let a = sc.sqrt_radius * d.sqrt();
                Ok((
                    tabor_elastic::hertz_force(self.effective_modulus, sc.sqrt_radius, d),
                    a,
                ))
            }
            Some(table) => {
                let d_hat = overlap * sc.inv_depth;
                let x = (d_hat - self.table_origin) * self.inv_table_length;
                let s = x.max(0.0).sqrt();
                match table.eval(s) {
                    Some((f, a)) => Ok((f * sc.force, a * sc.contact_radius)),
                    None => {
                        // the exact law at the reference radius, rescaled
                        let r = &self.reference;
                        let (f, a) = self.exact_branch(d_hat * r.depth)?;
                        Ok((
                            f / r.force * sc.force,
                            a / r.contact_radius * sc.contact_radius,
                        ))
                    }
                }
            }
        }
    }

    /// The exact (root-finding) law on the branch at the reference radius: the
    /// reference of the table.
    pub fn exact_branch(&self, overlap: f64) -> Result<(f64, f64)> {
        let overlap = validate::finite("overlap", overlap)?;
        match &self.exact {
            Exact::Hertz => {
                let d = overlap.max(0.0);
                let sqrt_r = self.reference.sqrt_radius;
                Ok((
                    tabor_elastic::hertz_force(self.effective_modulus, sqrt_r, d),
                    sqrt_r * d.sqrt(),
                ))
            }
            Exact::Jkr(law) => {
                let d = overlap.max(law.separation_depth());
                Ok((law.force(d, 0.0)?, law.contact_radius(d, 0.0)?))
            }
            Exact::Maugis(law) => Ok((law.force(overlap, 0.0)?, law.contact_radius(overlap, 0.0)?)),
            Exact::PerContact => Err(Error::Model {
                model: "tabor-ffi per-contact Lambda law",
                message:
                    "no single exact law: build ContactLaw::maugis_dugdale at the contact's Lambda"
                        .into(),
            }),
        }
    }

    /// One time step of a contact at the reference radius (see
    /// [`ContactLaw::evaluate_scaled`]).
    #[inline]
    pub fn evaluate(
        &self,
        overlap: f64,
        overlap_rate: f64,
        history: &mut TaborHistory,
    ) -> Result<TaborForce> {
        self.evaluate_scaled(&self.reference, overlap, overlap_rate, history)
    }

    /// One time step of a contact at the radius of `scales` ([`ContactLaw::scales`]):
    /// updates `history` (jump-in, turning point, snap-off) and returns the normal
    /// force at `overlap` (m) and `overlap_rate` (m/s, > 0 approaching).
    ///
    /// While not in contact the force is 0 until δ reaches the jump-in overlap;
    /// in contact it follows the branch until δ falls below the snap-off overlap.
    /// Hertz with damping never pulls (F = max(F_e + F_d, 0), the convention of
    /// seed 000 (5.72) and LAMMPS's `limit_damping`); adhesive laws add the damping
    /// force unclipped.
    #[inline]
    pub fn evaluate_scaled(
        &self,
        scales: &RadiusScales,
        overlap: f64,
        overlap_rate: f64,
        history: &mut TaborHistory,
    ) -> Result<TaborForce> {
        self.evaluate_with_mass(scales, overlap, overlap_rate, f64::NAN, history)
    }

    /// [`ContactLaw::evaluate_scaled`] with the effective mass m* (kg) of the
    /// contact, which a DEM damping law needs (an error names `effective_mass`
    /// when it is not finite and > 0 there; ignored otherwise). A DEM damping law
    /// acts unclipped on every law, Hertz too: the contact lasts until δ = 0 with a
    /// tensile force at its end, as LAMMPS's `pair granular` without
    /// `limit_damping` and the library's damped force law
    /// (`tabor_viscoadhesive::ViscousDamping`); Kuwabara-Kono damping keeps the
    /// Hertz clip.
    #[inline]
    pub fn evaluate_with_mass(
        &self,
        scales: &RadiusScales,
        overlap: f64,
        overlap_rate: f64,
        effective_mass: f64,
        history: &mut TaborHistory,
    ) -> Result<TaborForce> {
        if self.dem_damping.is_some() {
            validate::positive("effective_mass", effective_mass)?;
        }
        if !overlap.is_finite() || !overlap_rate.is_finite() {
            return Err(Error::invalid(
                "overlap",
                if overlap.is_finite() {
                    overlap_rate
                } else {
                    overlap
                },
                "overlap and overlap rate must be finite",
            ));
        }
        if let Some((h, table)) = &self.per_contact {
            return self.evaluate_per_contact(
                *h,
                table,
                scales,
                overlap,
                overlap_rate,
                effective_mass,
                history,
            );
        }
        let mut event = 0;
        let hertz = self.table.is_none();
        if history.contact == 0.0 {
            if overlap < self.jump_in * scales.depth || (hertz && overlap <= 0.0) {
                return Ok(TaborForce::default());
            }
            history.contact = 1.0;
            history.max_overlap = overlap;
            event = 1;
        }
        if overlap < self.snap_off * scales.depth || (hertz && overlap <= 0.0) {
            *history = TaborHistory::default();
            return Ok(TaborForce {
                event: event | 2,
                ..TaborForce::default()
            });
        }
        if overlap > history.max_overlap {
            history.max_overlap = overlap;
        }
        let (f, a) = self.branch(scales, overlap)?;
        Ok(TaborForce {
            force: self.total_force(f, a, overlap_rate, effective_mass),
            elastic_force: f,
            contact_radius: a,
            event,
        })
    }

    /// The elastic-adhesive force `f` (N) at contact radius `a` (m) plus the
    /// damping force at `overlap_rate` (Hertz with Kuwabara-Kono damping clipped
    /// at 0, see [`ContactLaw::evaluate_with_mass`]).
    #[inline]
    pub(crate) fn total_force(
        &self,
        f: f64,
        a: f64,
        overlap_rate: f64,
        effective_mass: f64,
    ) -> f64 {
        match &self.dem_damping {
            Some(d) => f + d.force(effective_mass, a, overlap_rate),
            None => {
                let damping = tabor_visco::kuwabara_kono::viscous_force(
                    self.effective_modulus * self.damping_time,
                    a,
                    overlap_rate,
                );
                let force = f + damping;
                if !self.adhesive() && force < 0.0 {
                    0.0
                } else {
                    force
                }
            }
        }
    }

    /// Whether the law is adhesive (tabulated: JKR, Maugis-Dugdale).
    #[inline]
    pub(crate) fn adhesive(&self) -> bool {
        self.table.is_some() || self.per_contact.is_some()
    }
}
