//! The viscous wrapper: any [`ForceLaw`] plus the Kuwabara-Kono viscous force of
//! its own contact radius, and the energy criterion for sticking.

use crate::damping::NormalDamping;
use tabor_dynamics::{BranchChange, BranchCurve, CurvePoint, ForceLaw};
use tabor_jkr::JkrForceLaw;
use tabor_maugis::MaugisDugdaleForceLaw;
use tabor_restitution::{validate, Error, Result};

/// What [`ViscousDamping`] needs of its inner law beyond [`ForceLaw`] to
/// recognise an impact that can no longer separate: the depth of the adhesive
/// well and the equilibrium of the contact branch (the trap test, README eq.
/// (V5)). The potential relative to separation (README eq. (V4)) is
/// [`ForceLaw::separation_barrier`].
///
/// `U(d) − U(d_sep) = ∫_{d_sep}^{d} F dd'` (J). On the branch that ends in
/// separation the mechanical energy `½ m ḋ² + U(d) − U(d_sep)` is the kinetic
/// energy the body would have left at the separation point; damping only lowers
/// it (README eq. (V4)), so once it is ≤ 0 the body can never separate: it sticks.
///
/// Where the inner law does not know its barrier the wrapper never sticks
/// early, and an overdamped body that creeps into the equilibrium runs into the
/// simulator's time limit (an error). `tabor-jkr`'s [`JkrForceLaw`] knows its
/// barrier but neither the well depth nor the equilibrium, `tabor-maugis`'
/// [`MaugisDugdaleForceLaw`] none of the three; the model's own
/// [`crate::AdhesiveForceLaw`] knows all three.
pub trait SeparationPotential: ForceLaw {
    /// The depth of the adhesive well below the separation point,
    /// `U(d_sep) − min U ≥ 0` (J), or `None` when not known.
    fn well_depth(&self) -> Option<f64> {
        None
    }

    /// The equilibrium overlap `d_eq` (F = 0) of the current contact branch, below
    /// `upper` (m) where the force is compressive, or `None` when not known.
    fn equilibrium_overlap(&self, _upper: f64) -> Result<Option<f64>> {
        Ok(None)
    }
}

/// Samples of `F(d)/(d − d_eq)` over `[d_eq, d*]` in the trap test of
/// [`ViscousDamping`] (their maximum, taken twice, bounds the secant stiffness).
const TRAP_SAMPLES: usize = 32;

impl SeparationPotential for JkrForceLaw {}
impl SeparationPotential for MaugisDugdaleForceLaw {}
/// Any boxed law: the boxed law's barrier where it knows one (Hertz and the
/// elasto-plastic laws do not, so the wrapper sticks only where the inner law
/// does: README eq. (V4) unused); no well depth or equilibrium.
impl SeparationPotential for Box<dyn ForceLaw> {}

/// An impact that starts without the energy to separate (README eq. (V4)) can never
/// separate: its record ends once the kinetic energy has fallen below this fraction
/// of the impact's (at once when damping dominates, else when the body decelerates
/// back through its impact speed, before the first turning point). The outcome,
/// sticking, does not depend on it; a strongly damped body would otherwise creep
/// into the adhesive well on the viscous time scale, with steps limited by the
/// far shorter inertial one.
const CREEP_END: f64 = 1.0 - 1e-6;

/// An inner force law plus a normal damping force `c(m, a) ḋ` over the inner
/// law's contact radius ([`NormalDamping`]): the viscous force of a Kelvin-Voigt
/// contact modulus `E*(s) = E* + η_c s`,
///
/// ```text
/// F(d, ḋ) = F_inner(d, ḋ; history) + 2 η_c a_inner(d, ḋ) ḋ      (README, (V1))
/// ```
///
/// or one of LAMMPS's DEM damping laws (`viscoelastic`, `tsuji`,
/// `coeff_restitution`; README, "DEM damping laws"), with every convention below
/// unchanged (the trap test needs only that `c` grows with the contact radius).
///
/// For the Hertz law (`a = √(Rd)`) and an incompressible Kelvin-Voigt half-space
/// (`E* = 4G`, `η_c = 4η`) this is exactly the Kuwabara-Kono force of seed 000
/// eq. (5.66), `(16/3)G√R d^(3/2) + 8η√(Rd) ḋ`; the factor `2 a` is the
/// incremental (flat-punch) stiffness `dF/dd = 2E*a` of a contact of radius `a`
/// divided by `E*`, i.e. the number of method-of-dimensionality-reduction
/// elements in contact, each moving with ḋ (README).
///
/// Conventions (README, "Conventions"):
///
/// - the viscous force acts only while [`ForceLaw::in_contact`] of the inner law
///   is true (zero during the Maugis-Dugdale approach before jump-in) and is
///   proportional to the inner law's [`ForceLaw::contact_radius`] (zero on the
///   Maugis-Dugdale no-contact branch, where only the cohesive zone carries load);
/// - every hook and branch is the inner law's: the bodies separate where the inner
///   law separates (JKR snap-off `d_c` or the load-controlled `d = −d_n`,
///   Maugis-Dugdale snap-off), stick where it sticks (by default when ḋ turns
///   inward again before separation, [`ForceLaw::on_min_compression`]);
/// - additionally, when the inner law knows its [`SeparationPotential`], the
///   bodies stick as soon as `½ m ḋ² + U(d) − U(d_sep)` falls to 0 (an extra
///   branch end): from there on they can never separate (README eq. (V4)). This
///   ends the overdamped creep into the equilibrium, which never turns;
/// - a total force that vanishes or turns tensile before separation does *not*
///   end the contact: the adhesive contact still holds, and the viscous term keeps
///   acting (as a tension while ḋ < 0). This is where the model differs from
///   Kuwabara-Kono's restitution, which ends where the total force vanishes
///   (README, "The Δγ → 0 limit").
#[derive(Clone, Debug, PartialEq)]
pub struct ViscousDamping<L> {
    inner: L,
    damping: NormalDamping,
    /// m (kg), set by `begin_impact`.
    mass: f64,
    /// length per energy for the energy branch end: L / (m v0²/2) (m/J).
    length_per_energy: f64,
    /// m v0²/2 (J), set by `begin_impact`.
    kinetic_energy: f64,
    /// The impact starts in contact without the energy to separate: it sticks, at
    /// the first turning point at the latest.
    doomed: bool,
}

impl<L: SeparationPotential> ViscousDamping<L> {
    /// Wraps `inner` with the viscous coefficient `η_c` (Pa s) of the contact
    /// modulus `E*(s) = E* + η_c s` (finite, > 0; incompressible Kelvin-Voigt
    /// half-space: `η_c = 4η`). Seed 000 eq. (5.66) with `8η = 2η_c`.
    pub fn new(inner: L, contact_viscosity: f64) -> Result<Self> {
        Self::damped(
            inner,
            NormalDamping::KuwabaraKono {
                contact_viscosity: validate::positive("contact_viscosity", contact_viscosity)?,
            },
        )
    }

    /// Wraps `inner` with the normal damping `damping` (Kuwabara-Kono, or a DEM
    /// law of LAMMPS's `pair granular`; its values checked again). README
    /// eq. (V1) and "DEM damping laws".
    pub fn damped(inner: L, damping: NormalDamping) -> Result<Self> {
        Ok(Self::from_validated(inner, damping.validated()?))
    }

    /// `damped` for a damping validated before.
    pub(crate) fn from_validated(inner: L, damping: NormalDamping) -> Self {
        ViscousDamping {
            inner,
            damping,
            mass: f64::NAN,
            length_per_energy: f64::NAN,
            kinetic_energy: f64::NAN,
            doomed: false,
        }
    }

    /// The inner (elastic adhesive) law.
    pub fn inner(&self) -> &L {
        &self.inner
    }

    /// The normal damping law (Kuwabara-Kono (5.66) or a LAMMPS DEM law, README
    /// "DEM damping laws").
    pub fn damping(&self) -> NormalDamping {
        self.damping
    }

    /// The damping coefficient `c` (N s/m) of the force `c ḋ` at contact radius
    /// `contact_radius` (m), in the effective mass of the current impact (NaN
    /// before [`ForceLaw::begin_impact`] for the laws that need the mass); seed 000
    /// eq. (5.72), [`NormalDamping::coefficient`].
    pub fn damping_coefficient(&self, contact_radius: f64) -> f64 {
        self.damping.coefficient(self.mass, contact_radius)
    }

    /// The viscous force `c ḋ` (N, repulsive > 0; `2 η_c a ḋ` for Kuwabara-Kono) at
    /// overlap `overlap` (m) and rate `overlap_rate` (m/s) on the current branch;
    /// 0 out of contact. README eq. (V1), seed 000 eq. (5.66).
    pub fn viscous_force(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        if !self.inner.in_contact() {
            return Ok(0.0);
        }
        let a = self.inner.contact_radius(overlap, overlap_rate)?;
        Ok(self.viscous_force_at(a, overlap_rate))
    }

    /// The kinetic energy the body would have left at the separation point
    /// without further damping, `½ m ḋ² + U(d) − U(d_sep)` (J), README eq. (V4);
    /// `None` out of contact, before [`ForceLaw::begin_impact`], or when the inner
    /// law does not know its potential.
    pub fn escape_energy(&self, overlap: f64, overlap_rate: f64) -> Result<Option<f64>> {
        if !self.inner.in_contact() || self.mass.is_nan() {
            return Ok(None);
        }
        Ok(self
            .inner
            .separation_barrier(overlap)?
            .map(|b| 0.5 * self.mass * overlap_rate * overlap_rate + b.potential))
    }

    fn viscous_force_at(&self, contact_radius: f64, overlap_rate: f64) -> f64 {
        match self.damping {
            NormalDamping::KuwabaraKono { contact_viscosity } => {
                tabor_visco::kuwabara_kono::viscous_force(
                    contact_viscosity,
                    contact_radius,
                    overlap_rate,
                )
            }
            other => other.force(self.mass, contact_radius, overlap_rate),
        }
    }

    /// The energy criterion as a length (> 0 while the body can still separate).
    /// An impact that started without the energy to separate (`doomed`) instead
    /// ends when its kinetic energy has fallen below [`CREEP_END`] of the impact's:
    /// it can never separate, whatever it does next (README eq. (V4)).
    fn energy_branch_end(&self, overlap: f64, overlap_rate: f64) -> Result<Option<f64>> {
        if self.doomed {
            let kinetic = 0.5 * self.mass * overlap_rate * overlap_rate;
            return Ok(Some(
                kinetic * self.length_per_energy - CREEP_END * self.length_scale(),
            ));
        }
        Ok(self
            .escape_energy(overlap, overlap_rate)?
            .map(|e| e * self.length_per_energy))
    }

    /// Whether the body, at rest at its turning point `d*` (m), is trapped between
    /// the equilibrium d_eq of the contact branch and d*, so that it never reaches
    /// the separation point (README eq. (V5)). With `s = d − d_eq`,
    /// `m s̈ = −F − c ṡ`, `c = c(a(d)) ≥ c0 = c(a(d_eq))` (a grows with d, c with a;
    /// `2 η_c a` for Kuwabara-Kono)
    /// and `0 ≤ F ≤ k s` on [d_eq, d*]: if `c0² ≥ 4 m k`, a λ with
    /// `(c0/m − λ) λ ≥ k/m` exists, on the line `ṡ = −λ s` the field gives
    /// `d(ṡ + λs)/dt ≥ −F/m + (c0/m − λ) λ s ≥ 0`, so the body (starting at
    /// ṡ = 0 above the line) stays above it: `s ≥ s* e^{−λ t} > 0`; and it never
    /// passes d* again (the energy `½ m ṡ² + U` only falls and U grows on
    /// [d_eq, d*]). It creeps into the equilibrium and sticks, which the
    /// simulation would otherwise follow on the viscous time scale with steps
    /// bounded by the far shorter inertial one. k is the largest of
    /// [`TRAP_SAMPLES`] samples of `F/s`, taken twice (the test asks
    /// `c0² ≥ 8 m k_sampled`); false when the inner law does not know d_eq.
    fn trapped(&self, turning_overlap: f64) -> Result<bool> {
        if !self.inner.in_contact() || self.mass.is_nan() {
            return Ok(false);
        }
        let Some(d_eq) = self.inner.equilibrium_overlap(turning_overlap)? else {
            return Ok(false);
        };
        let span = turning_overlap - d_eq;
        if span.is_nan() || span <= 0.0 {
            return Ok(false);
        }
        let damping = self.damping_coefficient(self.inner.contact_radius(d_eq, 0.0)?);
        let mut stiffness = 0.0f64;
        for i in 1..=TRAP_SAMPLES {
            let s = span * i as f64 / TRAP_SAMPLES as f64;
            let f = self.inner.force(d_eq + s, 0.0)?;
            if f.is_nan() || f < 0.0 {
                return Ok(false);
            }
            stiffness = stiffness.max(f / s);
        }
        Ok(damping * damping >= 8.0 * self.mass * stiffness)
    }

    /// The overlap scale L of the impact (m), with `length_per_energy`
    /// = L/(m v0²/2).
    fn length_scale(&self) -> f64 {
        self.length_per_energy * self.kinetic_energy
    }

    /// `decision`, but a stick when it continues onto a branch (Maugis-Dugdale
    /// jump-in, or the junction of its parts) without the energy to separate.
    fn stick_if_doomed(
        &self,
        decision: BranchChange,
        overlap: f64,
        overlap_rate: f64,
    ) -> Result<BranchChange> {
        if decision == BranchChange::Continue {
            if let Some(e) = self.energy_branch_end(overlap, overlap_rate)? {
                if e <= 0.0 {
                    return Ok(BranchChange::Stick);
                }
            }
        }
        Ok(decision)
    }

    /// At coordinate `coordinate` of the inner curve: its end, and the energy
    /// criterion as a fraction of the impact's kinetic energy (if known).
    fn curve_ends(&self, coordinate: f64, overlap_rate: f64) -> Result<(f64, Option<f64>)> {
        let curve = self.inner_curve()?;
        let g = curve.end(coordinate, overlap_rate)?;
        let overlap = curve.point(coordinate, overlap_rate)?.overlap;
        let e = self.energy_branch_end(overlap, overlap_rate)?;
        Ok((g, e.map(|e| e / self.length_scale())))
    }

    /// The inner law's curve (present whenever [`ForceLaw::curve`] of the wrapper
    /// is).
    fn inner_curve(&self) -> Result<&dyn BranchCurve> {
        self.inner.curve().ok_or_else(|| Error::Model {
            model: "viscous damping",
            message: "the inner law has no branch curve here".into(),
        })
    }
}

/// `force` (N) when finite, else an error naming the state.
fn representable(force: f64, overlap: f64, overlap_rate: f64) -> Result<f64> {
    if force.is_finite() {
        Ok(force)
    } else {
        Err(Error::Model {
            model: "viscous damping",
            message: format!(
                "the force is not representable ({force}) at d = {overlap:e} m, d' = \
                 {overlap_rate:e} m/s"
            ),
        })
    }
}

/// The wrapper on the inner law's branch curve (JKR in `x = √â`, Maugis-Dugdale
/// case 3 in θ): the same point with the viscous force of its contact radius added
/// (README eq. (V1)), and the branch ending at the inner curve's end or where the
/// energy criterion (V4) falls to 0, whichever comes first.
impl<L: SeparationPotential> BranchCurve for ViscousDamping<L> {
    fn coordinate(&self, overlap: f64) -> Result<f64> {
        self.inner_curve()?.coordinate(overlap)
    }

    fn point(&self, coordinate: f64, overlap_rate: f64) -> Result<CurvePoint> {
        let mut p = self.inner_curve()?.point(coordinate, overlap_rate)?;
        let total = p.force + self.viscous_force_at(p.contact_radius, overlap_rate);
        p.force = representable(total, p.overlap, overlap_rate)?;
        Ok(p)
    }

    /// The smaller of the inner curve's end and the energy criterion as a fraction
    /// of the impact's kinetic energy (both of order 1 away from their ends; only
    /// where they cross 0 counts).
    fn end(&self, coordinate: f64, overlap_rate: f64) -> Result<f64> {
        let (g, e) = self.curve_ends(coordinate, overlap_rate)?;
        Ok(e.map_or(g, |e| g.min(e)))
    }

    fn slope_scale(&self) -> f64 {
        self.inner.curve().map_or(f64::NAN, |c| c.slope_scale())
    }
}

impl<L: SeparationPotential> ForceLaw for ViscousDamping<L> {
    fn name(&self) -> String {
        format!("{} + {}", self.inner.name(), self.damping.describe())
    }

    /// The inner law's scale (the elastic d_max or the adhesive depth scale):
    /// damping only shortens the overlap.
    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64> {
        self.inner.overlap_scale(effective_mass, impact_speed)
    }

    fn begin_impact(&mut self, effective_mass: f64, impact_speed: f64) -> Result<()> {
        self.inner.begin_impact(effective_mass, impact_speed)?;
        let m = validate::positive("effective_mass", effective_mass)?;
        let v = validate::positive("impact_speed", impact_speed)?;
        let scale = self.inner.overlap_scale(m, v)?;
        self.mass = m;
        self.kinetic_energy = 0.5 * m * v * v;
        self.length_per_energy = scale / self.kinetic_energy;
        self.doomed = false;
        let start = self.inner.start_overlap();
        if let Some(e) = self.escape_energy(start, v)? {
            // starts in contact inside the well (JKR below its elastic sticking
            // velocity): a negative branch end at the start would be an error
            self.doomed = e <= 0.0;
        }
        Ok(())
    }

    fn start_overlap(&self) -> f64 {
        self.inner.start_overlap()
    }

    fn in_contact(&self) -> bool {
        self.inner.in_contact()
    }

    /// `F_inner + 2 η_c a ḋ`, README eq. (V1) (seed 000 eq. (5.66) for Hertz).
    fn force(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        let elastic = self.inner.force(overlap, overlap_rate)?;
        if !self.inner.in_contact() {
            return Ok(elastic);
        }
        let a = self.inner.contact_radius(overlap, overlap_rate)?;
        representable(
            elastic + self.viscous_force_at(a, overlap_rate),
            overlap,
            overlap_rate,
        )
    }

    fn contact_radius(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        self.inner.contact_radius(overlap, overlap_rate)
    }

    /// The smaller of the inner law's branch end and the energy criterion
    /// `(½ m ḋ² + U(d) − U(d_sep)) · L/(m v0²/2)` (README eq. (V4)).
    fn branch_end(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        let g = self.inner.branch_end(overlap, overlap_rate)?;
        Ok(match self.energy_branch_end(overlap, overlap_rate)? {
            Some(e) => g.min(e),
            None => g,
        })
    }

    /// Stick when the energy criterion ended the branch; otherwise the inner
    /// law's decision, turned into a stick when the branch it switched to
    /// (Maugis-Dugdale jump-in) starts without the energy to separate.
    fn on_branch_end(&mut self, overlap: f64, overlap_rate: f64) -> Result<BranchChange> {
        let g = self.inner.branch_end(overlap, overlap_rate)?;
        if let Some(e) = self.energy_branch_end(overlap, overlap_rate)? {
            if e <= g {
                return Ok(BranchChange::Stick);
            }
        }
        let decision = self.inner.on_branch_end(overlap, overlap_rate)?;
        self.stick_if_doomed(decision, overlap, overlap_rate)
    }

    /// [`ForceLaw::on_branch_end`] on the inner curve: stick when the energy
    /// criterion, not the inner curve's end, ended the branch (compared as in
    /// [`BranchCurve::end`]); otherwise the inner law's decision at the coordinate
    /// (which of its ends it met), turned into a stick as there.
    fn on_curve_end(
        &mut self,
        coordinate: f64,
        overlap: f64,
        overlap_rate: f64,
    ) -> Result<BranchChange> {
        if let (g, Some(e)) = self.curve_ends(coordinate, overlap_rate)? {
            if e <= g {
                return Ok(BranchChange::Stick);
            }
        }
        let decision = self.inner.on_curve_end(coordinate, overlap, overlap_rate)?;
        self.stick_if_doomed(decision, overlap, overlap_rate)
    }

    /// The inner law's decision; [`BranchChange::Stick`] when the impact started in
    /// contact without the energy to separate (README eq. (V4)), or when the body
    /// turns overdamped and can never leave the equilibrium's neighbourhood
    /// (`ViscousDamping::trapped`, README eq. (V5)).
    fn on_max_compression(&mut self, overlap: f64) -> Result<BranchChange> {
        let decision = self.inner.on_max_compression(overlap)?;
        if decision == BranchChange::Continue && (self.doomed || self.trapped(overlap)?) {
            return Ok(BranchChange::Stick);
        }
        Ok(decision)
    }

    fn on_min_compression(&mut self, overlap: f64) -> Result<BranchChange> {
        self.inner.on_min_compression(overlap)
    }

    /// On the inner law's branch curve while in contact (the viscous force needs
    /// the contact radius, which the curve gives).
    fn curve(&self) -> Option<&dyn BranchCurve> {
        (self.inner.in_contact() && self.inner.curve().is_some()).then_some(self as _)
    }
}
