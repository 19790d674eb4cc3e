//! The Maugis-Dugdale impact as a time-domain force law for `tabor-dynamics`.

use crate::branch::{contact_state, junction_factor, no_contact_pull_off_radius, no_contact_state};
use crate::impact::TaborCase;
use crate::impact::{impact_path, ImpactPath};
use crate::model::MaugisDugdaleImpact;
use crate::trace::{equilibrium_state_near, BranchPoint};
use crate::units::JkrScales;
use std::sync::atomic::{AtomicU64, Ordering};
use tabor_dynamics::{BranchChange, BranchCurve, CurvePoint, ForceLaw};
use tabor_numerics::Cost;
use tabor_restitution::{validate, Result};

/// The Maugis-Dugdale contact as a force law `F(d)` following the traced branch
/// (seed 000 section 5.3.2): the sphere approaches with `F = 0` from
/// `d = −(3/2)h` until the gap at the first point equals the range h
/// (`d̂ = −1/Λ`, (5.40)), jumps onto the stable equilibrium state with that depth
/// (no contact, b̂0 = 2b̂_c (5.41), in case 1), loads and unloads along the
/// equilibrium branch, and snaps off at its minimum depth (the
/// displacement-controlled instability) with the speed it has there.
///
/// The state at a depth is solved from the last one solved (Newton's method on the
/// branch from its tangent, module `trace`), which the law keeps as a hint; the
/// hint changes the start of the solve, not its result (to the solve's tolerance,
/// 1e-15 in θ), and the law stays `Sync`.
///
/// The path has two parts in cases 1 and 2: the contact branch and the branch
/// without contact (â = 0), which meet at the junction â = 0, b̂ = K b̂_c (5.46),
/// where F(d) has a kink. The junction is a branch end, located as an event, where
/// the law switches part and goes on ([`BranchChange::Continue`]).
///
/// Where the path ends in a snap-off, the simulator integrates it in a coordinate
/// of its own ([`BranchCurve`]): the contact branch of case 3 in θ
/// (`branch::contact_state`), the no-contact part of cases 1 and 2 in b̂
/// (`branch::no_contact_state`: d̂ = (3/2)b̂² − (32Λ/π²)b̂ − 1/Λ, F̂ = −2Λb̂²).
/// Depth and force are explicit there, so nothing is solved per force
/// evaluation, and the snap-off, the fold of d̂ where F(d) has a square-root
/// singularity (θ_c, b̂_c), is a regular point; so is the junction seen from the
/// contact part, where d̂ − d̂_j ∝ (π/2 − θ)² (and the contact radius, which the
/// viscous force of `tabor-viscoadhesive` grows with, ∝ √(d̂ − d̂_j)).
#[derive(Clone, Debug)]
pub struct MaugisDugdaleForceLaw {
    scales: JkrScales,
    path: ImpactPath,
    part: Part,
    /// b̂_c and K b̂_c (5.46): the no-contact branch's snap-off and junction radii.
    no_contact_radii: (f64, f64),
    /// Cases 1 and 2: the depth of the junction of the parts (normalized), where
    /// b̂ = K b̂_c on the no-contact branch.
    junction: Option<f64>,
    hint: Hint,
}

/// The shortest no-contact part, `K − 1`, that the path follows after the
/// junction (as Λ → Λ2, K → 1); below it the bodies separate at the junction.
const NO_CONTACT_SHORTEST: f64 = 1e-6;

/// Where on the impact path the law is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Part {
    /// Before jump-in: F = 0.
    Approaching,
    /// On the branch without direct contact (â = 0), cases 1 and 2.
    NoContact,
    /// On the contact branch (â > 0).
    Contact,
}

impl PartialEq for MaugisDugdaleForceLaw {
    /// Equal laws: the same scales, path and branch (the hint does not count).
    fn eq(&self, other: &Self) -> bool {
        self.scales == other.scales && self.path == other.path && self.part == other.part
    }
}

/// The last solved contact-branch state (depth, θ, dd̂/dθ) as bits of `f64`s, NaN
/// when there is none: atomics, so that the law is `Sync`; a torn or stale value
/// only gives the solve a worse start.
#[derive(Debug)]
struct Hint([AtomicU64; 3]);

impl Hint {
    fn empty() -> Self {
        let nan = f64::NAN.to_bits();
        Hint([
            AtomicU64::new(nan),
            AtomicU64::new(nan),
            AtomicU64::new(nan),
        ])
    }

    fn get(&self) -> Option<BranchPoint> {
        let [d, t, s] = &self.0;
        let p = BranchPoint {
            depth: f64::from_bits(d.load(Ordering::Relaxed)),
            theta: f64::from_bits(t.load(Ordering::Relaxed)),
            depth_slope: f64::from_bits(s.load(Ordering::Relaxed)),
        };
        (p.depth.is_finite() && p.theta.is_finite() && p.depth_slope.is_finite()).then_some(p)
    }

    fn set(&self, p: BranchPoint) {
        let [d, t, s] = &self.0;
        d.store(p.depth.to_bits(), Ordering::Relaxed);
        t.store(p.theta.to_bits(), Ordering::Relaxed);
        s.store(p.depth_slope.to_bits(), Ordering::Relaxed);
    }
}

impl Clone for Hint {
    fn clone(&self) -> Self {
        let h = Hint::empty();
        if let Some(p) = self.get() {
            h.set(p);
        }
        h
    }
}

impl MaugisDugdaleForceLaw {
    /// The force law of a Maugis-Dugdale impact.
    pub fn new(model: &MaugisDugdaleImpact) -> Result<Self> {
        let path = impact_path(model.tabor_parameter())?;
        let lambda = path.lambda;
        let bc = no_contact_pull_off_radius(lambda);
        let b_junction = junction_factor(lambda) * bc;
        Ok(MaugisDugdaleForceLaw {
            scales: model.scales(),
            no_contact_radii: (bc, b_junction),
            junction: (path.case != TaborCase::Contact)
                .then(|| no_contact_state(lambda, b_junction).depth),
            path,
            part: Part::Approaching,
            hint: Hint::empty(),
        })
    }

    /// Whether the no-contact part (b̂ from b̂_c to K b̂_c) is longer than
    /// [`NO_CONTACT_SHORTEST`] relative to b̂_c.
    fn no_contact_part_is_long(&self) -> bool {
        let (bc, b_junction) = self.no_contact_radii;
        b_junction / bc - 1.0 > NO_CONTACT_SHORTEST
    }

    /// The range of adhesion h = d_n/Λ (m).
    pub fn range(&self) -> f64 {
        self.scales.depth / self.path.lambda
    }

    /// The depth of jump-in −h and of snap-off (m).
    pub fn jump_in_and_pull_off_depths(&self) -> (f64, f64) {
        (
            self.path.jump_in.depth * self.scales.depth,
            self.path.pull_off.depth * self.scales.depth,
        )
    }

    /// The pull-off force of the impact (N, a magnitude): the most tensile force
    /// on the equilibrium branch the impact unloads along, from the snap-off depth
    /// inwards (Maugis 1992, J. Colloid Interface Sci. 150, 243: `(3/2)π w R` as
    /// Λ → ∞ (JKR), `2π w R` as Λ → 0 (DMT)). The branch is searched over
    /// `d̂ = d̂_off + L x²`, `0 ≤ x ≤ 8` (`L = max(1/Λ, 1)`, the depth the adhesive
    /// features span), on a grid of 4096 cells refined by golden-section search
    /// to 10⁻¹⁴ in x (`tabor_numerics::minimize::grid_then_golden`; the branch
    /// has a kink where the no-contact branch meets the contact branch). Used as
    /// `F_pulloff` of the friction models' Coulomb limit by the scene's oblique
    /// impact and by the LAMMPS plugin alike.
    pub fn pull_off_force(&self) -> Result<f64> {
        let (_, pull_off) = self.jump_in_and_pull_off_depths();
        let step = (1.0 / self.path.lambda).max(1.0) * self.scales.depth;
        let force = |x: f64| -> Result<f64> {
            let d = pull_off + x * x * step;
            // exactly at the junction, rounding can leave the contact-branch root
            // unbracketed: the state a hair shallower is the same
            self.state(d)
                .or_else(|_| self.state(d - 1e-12 * step))
                .map(|s| s.force * self.scales.force)
        };
        let min = tabor_numerics::minimize::grid_then_golden(force, 0.0, 8.0, 4096, 1e-14)?;
        Ok(-min.value)
    }

    fn state(&self, overlap: f64) -> Result<crate::impact::PathState> {
        // clamp trial points beyond the snap-off to the snap-off state
        let d = (overlap / self.scales.depth).max(self.path.pull_off.depth);
        let mut cost = Cost::ZERO;
        let (state, next) = equilibrium_state_near(&self.path, d, self.hint.get(), &mut cost)?;
        if let Some(p) = next {
            self.hint.set(p);
        }
        Ok(state)
    }
}

impl ForceLaw for MaugisDugdaleForceLaw {
    fn name(&self) -> String {
        format!("Maugis-Dugdale (Lambda = {:.6e})", self.path.lambda)
    }

    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64> {
        let m = validate::positive("effective_mass", effective_mass)?;
        let v = validate::positive("impact_speed", impact_speed)?;
        // R and E* from the scales: d_n = a_c²/(3R), F_n = 1.5πΔγR; the Hertz
        // d_max (5.8) needs E*√R = (9π/8)Δγ R²/a_c³ · √R
        let s = self.scales;
        let r_times_dg = s.force / (1.5 * std::f64::consts::PI);
        let r = s.contact_radius * s.contact_radius / (3.0 * s.depth);
        let dg = r_times_dg / r;
        let e = 9.0 * std::f64::consts::PI * dg * r * r / (8.0 * s.contact_radius.powi(3));
        let hertz = (15.0 * m * v * v / (16.0 * e * r.sqrt())).powf(0.4);
        let scale = hertz.max(s.depth).max(self.range());
        validate::positive("overlap_scale", scale)
    }

    fn begin_impact(&mut self, _effective_mass: f64, _impact_speed: f64) -> Result<()> {
        self.part = Part::Approaching;
        Ok(())
    }

    fn start_overlap(&self) -> f64 {
        -1.5 * self.range()
    }

    fn in_contact(&self) -> bool {
        self.part != Part::Approaching
    }

    /// 0 before jump-in; then the equilibrium state's force on the path at the
    /// depth, whichever part holds there (so that the potential along the path is
    /// its integral: `tabor-viscoadhesive` tabulates it).
    fn force(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        if self.part == Part::Approaching {
            return Ok(0.0);
        }
        Ok(self.state(overlap)?.force * self.scales.force)
    }

    fn contact_radius(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        if self.part == Part::Approaching {
            return Ok(0.0);
        }
        Ok(self.state(overlap)?.contact_radius * self.scales.contact_radius)
    }

    /// Before jump-in `−h − d`; on the contact part `d − d_off` (case 3) or, while
    /// unloading (ḋ ≤ 0), `d − d_j` (the junction, cases 1 and 2); on the
    /// no-contact part `d − d_off`, or while loading (ḋ > 0) the nearer of that
    /// and `d_j − d`. The junction the motion moves away from is no end (the
    /// largest double instead: the law has just switched there, at distance 0);
    /// the jump where ḋ changes sign stays above 0, so it is no event.
    fn branch_end(&self, overlap: f64, overlap_rate: f64) -> Result<f64> {
        let (jump_in, pull_off) = self.jump_in_and_pull_off_depths();
        let junction = self.junction.map(|j| j * self.scales.depth);
        let loading = overlap_rate > 0.0;
        Ok(match (self.part, junction) {
            (Part::Approaching, _) => jump_in - overlap,
            (Part::Contact, Some(_)) if loading => f64::MAX,
            (Part::Contact, Some(junction)) => overlap - junction,
            (Part::NoContact, Some(junction)) if loading => {
                (overlap - pull_off).min(junction - overlap)
            }
            _ => overlap - pull_off,
        })
    }

    /// Jump-in at the end of the approach (onto the contact part, or in case 1 onto
    /// the no-contact part); at the junction the other part; at a snap-off,
    /// separation.
    fn on_branch_end(&mut self, overlap: f64, _overlap_rate: f64) -> Result<BranchChange> {
        let (jump_in, pull_off) = self.jump_in_and_pull_off_depths();
        let junction = self.junction.map(|j| j * self.scales.depth);
        let (next, decision) = match (self.part, junction) {
            (Part::Approaching, _) => {
                let onto_contact =
                    self.path.jump_in.theta.is_some() || junction.is_some_and(|j| jump_in >= j);
                let part = if onto_contact {
                    Part::Contact
                } else {
                    Part::NoContact
                };
                (part, BranchChange::Continue)
            }
            // the no-contact part shrinks to nothing as Λ → Λ2 (K → 1): where it is
            // shorter than NO_CONTACT_SHORTEST in b̂, the bodies separate at the
            // junction (the work along it, ∝ (K − 1)², is below 1e-12 F_n d_n)
            (Part::Contact, Some(_)) if self.no_contact_part_is_long() && overlap > pull_off => {
                (Part::NoContact, BranchChange::Continue)
            }
            (Part::NoContact, Some(j)) if overlap - pull_off > j - overlap => {
                (Part::Contact, BranchChange::Continue)
            }
            (part, _) => (part, BranchChange::Separate),
        };
        self.part = next;
        Ok(decision)
    }

    /// The contact part in θ, the no-contact part in b̂.
    fn curve(&self) -> Option<&dyn BranchCurve> {
        (self.part != Part::Approaching).then_some(self as _)
    }
}

/// The part of the path the law is on, in its coordinate: θ on the contact branch,
/// b̂ on the no-contact branch.
impl BranchCurve for MaugisDugdaleForceLaw {
    /// θ (contact branch; π/2 at the junction and below it) or b̂ (no-contact
    /// branch, the larger root of d̂(b̂) = d̂, closed form) of the state at the
    /// overlap.
    fn coordinate(&self, overlap: f64) -> Result<f64> {
        let lambda = self.path.lambda;
        let depth = overlap / self.scales.depth;
        if self.part == Part::NoContact {
            // (3/2)b² − 3 b_c b − (1/Λ + d) = 0, larger root, on the part
            // [b̂_c, K b̂_c] (rounding at its ends)
            let (bc, b_junction) = self.no_contact_radii;
            let c = 1.0 / lambda + depth;
            let disc = (9.0 * bc * bc + 6.0 * c).max(0.0);
            return Ok(((3.0 * bc + disc.sqrt()) / 3.0).clamp(bc, b_junction));
        }
        // at or below the junction the traced path answers with the no-contact
        // state (the contact part starts there, θ = π/2)
        Ok(self
            .state(overlap)?
            .theta
            .unwrap_or(std::f64::consts::FRAC_PI_2))
    }

    /// The state at θ ([`contact_state`], seed 000 section 5.3.2) or at b̂
    /// ([`no_contact_state`], (5.41), (5.44); dd̂/db̂ = 3b̂ − 32Λ/π², â = 0), in SI
    /// units, with the slopes of force and contact radius in the coordinate in
    /// closed form (θ: [`contact_state`]'s implicit derivatives; b̂: dF̂/db̂ =
    /// −4Λb̂, dâ/db̂ = 0). Near the junction θ → π/2 both the overlap and the
    /// force are even in π/2 − θ: a central difference in θ of the step the
    /// overlap asks for crosses π/2 (the oblique impact's slip conditions read
    /// garbage there), the closed form does not.
    fn point(&self, coordinate: f64, _overlap_rate: f64) -> Result<CurvePoint> {
        let lambda = self.path.lambda;
        // (d̂, dd̂/dq, F̂, â, dF̂/dq, dâ/dq)
        let (depth, slope, force, contact_radius, force_slope, radius_slope) =
            if self.part == Part::NoContact {
                let b = coordinate;
                let s = no_contact_state(lambda, b);
                let slope = 3.0 * (b - self.no_contact_radii.0);
                (s.depth, slope, s.force, 0.0, -4.0 * lambda * b, 0.0)
            } else {
                let s = contact_state(lambda, coordinate);
                let (d, a) = (s.depth, s.contact_radius);
                (
                    d,
                    s.depth_slope,
                    s.force,
                    a,
                    s.force_slope,
                    s.contact_radius_slope,
                )
            };
        Ok(CurvePoint {
            overlap: depth * self.scales.depth,
            overlap_slope: slope * self.scales.depth,
            force: force * self.scales.force,
            contact_radius: contact_radius * self.scales.contact_radius,
            slopes: Some((
                force_slope * self.scales.force,
                radius_slope * self.scales.contact_radius,
            )),
        })
    }

    /// Contact branch: `θ_top − θ` (θ grows as the depth falls), θ_top the snap-off
    /// θ_c in case 3, the junction π/2 in cases 1 and 2. No-contact branch: the
    /// nearer of the snap-off `b̂ − b̂_c` and the junction `K b̂_c − b̂`. At a fold
    /// (the snap-offs), `d − d_off` would touch 0 without a sign change.
    fn end(&self, coordinate: f64, overlap_rate: f64) -> Result<f64> {
        let loading = overlap_rate > 0.0;
        Ok(match (self.part, self.path.pull_off.theta) {
            (Part::NoContact, _) => {
                let (bc, b_junction) = self.no_contact_radii;
                if loading {
                    (coordinate - bc).min(b_junction - coordinate)
                } else {
                    coordinate - bc
                }
            }
            (_, Some(theta_c)) => theta_c - coordinate,
            (_, None) if loading => f64::MAX,
            (_, None) => std::f64::consts::FRAC_PI_2 - coordinate,
        })
    }

    /// dd/dq where the motion enters the path, at jump-in: `dd̂/dθ` there (cases
    /// 2 and 3) or `dd̂/db̂ = 3(2b̂_c − b̂_c)` (case 1), times d_n.
    fn slope_scale(&self) -> f64 {
        let slope = match self.path.jump_in.theta {
            Some(theta) => contact_state(self.path.lambda, theta).depth_slope.abs(),
            None => 3.0 * self.no_contact_radii.0,
        };
        slope * self.scales.depth
    }
}
