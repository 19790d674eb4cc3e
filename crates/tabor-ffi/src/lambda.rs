//! Maugis-Dugdale with a Tabor parameter from each contact's own size: the
//! material constant is the Dugdale range h (or the cohesive stress σ0 = w/h,
//! spec `maugis-dugdale.md`: σ0 h = Δγ), and each contact's
//! Λ = d_n(R*)/h = σ0 a_c²/(3R*w) (seed 000 section 5.3.2; `tabor_maugis::units::
//! tabor_parameter_from_range`), so Λ ∝ R*^(1/3).
//!
//! The branch of every Λ is read from a table over Λ and the branch coordinate,
//! never a root solve per contact:
//!
//! - nodes Λ_k = Λ1 e^{kq}, uniform in ln Λ, with q = ln(Λ2/Λ1)/[`TABOR_LAMBDA_CASE_2_INTERVALS`]
//!   so that the case boundaries Λ1 (k = 0) and Λ2 (k = [`TABOR_LAMBDA_CASE_2_INTERVALS`]) are
//!   nodes; at each node the fixed-Λ table of [`crate::table`] (the same one
//!   `ContactLaw::maugis_dugdale` builds), built on first use (or by
//!   [`LambdaTable::prepare`]) and kept;
//! - a contact's (F̂, â) is the 4-point Lagrange interpolation in ln Λ of the
//!   values of the nodes around its Λ *within its own Tabor case* (the stencil never
//!   straddles Λ1 or Λ2, where the branch changes its form), each node evaluated at
//!   the same *kink-aligned* branch coordinate ξ: ξ = u/u_k on the no-contact part
//!   (u = d̂ − d̂₀ above the snap-off depth d̂₀, u_k the junction with the contact
//!   branch, seed 000 (5.46)), ξ = 1 + (u − u_k)/(U − u_k) above it, U = 64(1 + 1/Λ);
//!   so the kink of F̂(d̂) sits at ξ = 1 for every node;
//! - d̂₀ and u_k are closed forms in cases 1 and 2 (the no-contact branch, seed 000
//!   (5.41), (5.44), (5.46)); in case 3 d̂₀, and everywhere the pull-off force, are
//!   interpolated like the branch. The jump-in overlap is −h exactly.
//!
//! The interpolation error is measured against the exact law
//! ([`LambdaTable::measure_error`]; tests/lambda.rs, examples/lambda_table.rs):
//! midway between nodes |ΔF̂| ≤ 1e-6 F_n (relative where |F| > F_n), |Δâ| ≤ 1e-6
//! a_c, |Δd̂₀| ≤ 1e-7 d_n, except for 0.58 < Λ < 0.75 around Λ2, where the branch
//! is not a smooth function of Λ: there |ΔF̂| ≤ 3e-5, |Δâ| ≤ 7e-5, |Δd̂₀| ≤ 2e-6.
//! A node takes 165 kB and about 5 ms to build (release); a factor 10 in R* (2.15
//! in Λ) needs 47 nodes, 7.7 MB, 0.2-0.4 s, once per process (every pair of
//! types shares them).

pub use crate::lambda_table::LambdaTable;
use crate::lambda_table::Node;
use crate::law::{ContactLaw, RadiusScales};
use crate::table::{Table, TableError};
use std::sync::{Arc, OnceLock};
use tabor_maugis::branch::{junction_factor, no_contact_pull_off_radius, no_contact_state};
use tabor_maugis::{TaborCase, LAMBDA_1, LAMBDA_2};
use tabor_restitution::{Error, Result};

/// Intervals of the node grid in ln Λ between the case boundaries Λ1 and Λ2
/// (q = ln(Λ2/Λ1)/18 ≈ 0.0199: 116 nodes per decade of Λ).
pub const TABOR_LAMBDA_CASE_2_INTERVALS: i32 = 18;
/// The smallest Λ the grid reaches (deep DMT: the range is 10⁴ d_n).
pub const TABOR_LAMBDA_MIN: f64 = 1e-4;
/// The largest Λ the grid reaches (JKR to within 10⁻⁶ of every scale).
pub const TABOR_LAMBDA_MAX: f64 = 1e6;

/// The normalized branch at one contact's Λ, ready to evaluate.
#[derive(Clone, Copy, Debug)]
pub struct LocalBranch {
    /// The contact's Λ.
    pub lambda: f64,
    /// Normalized jump-in overlap −1/Λ.
    pub jump_in: f64,
    /// Normalized snap-off overlap d̂₀.
    pub snap_off: f64,
    /// The most tensile force F̂ (≤ 0), interpolated.
    pub pull_off_force: f64,
    kink: f64,
    span: f64,
    nodes: [i32; 4],
    weights: [f64; 4],
}

fn step() -> f64 {
    (LAMBDA_2 / LAMBDA_1).ln() / f64::from(TABOR_LAMBDA_CASE_2_INTERVALS)
}

/// The Λ of node k (Λ1 and Λ2 exactly at their nodes).
fn node_lambda(k: i32) -> f64 {
    if k == TABOR_LAMBDA_CASE_2_INTERVALS {
        LAMBDA_2
    } else {
        LAMBDA_1 * (f64::from(k) * step()).exp()
    }
}

/// (d̂₀, u_k) in closed form for cases 1 and 2 (the no-contact branch ends at
/// b̂ = K b̂_c, seed 000 (5.46); snap-off at its depth minimum b̂_c).
fn no_contact_origin_and_kink(lambda: f64) -> (f64, f64) {
    let bc = no_contact_pull_off_radius(lambda);
    let d0 = no_contact_state(lambda, bc).depth;
    let dj = no_contact_state(lambda, junction_factor(lambda) * bc).depth;
    (d0, (dj - d0).max(0.0))
}

fn span_end(lambda: f64) -> f64 {
    64.0 * (1.0 + 1.0 / lambda)
}

impl Default for LambdaTable {
    fn default() -> Self {
        Self::new()
    }
}

impl LambdaTable {
    /// An empty table over [`TABOR_LAMBDA_MIN`, `TABOR_LAMBDA_MAX`] (nodes built on use).
    pub fn new() -> Self {
        let q = step();
        let k_min = ((TABOR_LAMBDA_MIN / LAMBDA_1).ln() / q).floor() as i32 - 1;
        let k_max = ((TABOR_LAMBDA_MAX / LAMBDA_1).ln() / q).ceil() as i32 + 1;
        LambdaTable {
            k_min,
            nodes: (k_min..=k_max).map(|_| OnceLock::new()).collect(),
        }
    }

    fn node(&self, k: i32) -> Result<&Node> {
        let slot = &self.nodes[(k - self.k_min) as usize];
        if let Some(n) = slot.get() {
            return Ok(n);
        }
        let lambda = node_lambda(k);
        let law = ContactLaw::maugis_dugdale(1.0, 1.0, 1.0, lambda)?;
        let (origin, inv_length, pull_off, table) = law.normalized_branch();
        let kink = match TaborCase::of(lambda) {
            TaborCase::Contact => 0.0,
            _ => no_contact_origin_and_kink(lambda).1,
        };
        let node = Node {
            table: table.ok_or_else(|| Error::Model {
                model: "tabor-ffi per-contact Lambda table",
                message: format!("no table at Lambda = {lambda}"),
            })?,
            origin,
            inv_length,
            kink,
            span: span_end(lambda) - kink,
            pull_off,
        };
        // a racing thread may have set it first: either value is the same
        Ok(slot.get_or_init(|| node))
    }

    /// The grid nodes whose stencils cover every Λ in [lo, hi] (within the grid).
    fn stencil_span(lo: f64, hi: f64) -> (i32, i32) {
        let q = step();
        let a = ((lo / LAMBDA_1).ln() / q).floor() as i32 - 3;
        let b = ((hi / LAMBDA_1).ln() / q).ceil() as i32 + 3;
        (a, b)
    }

    /// Builds now every node that contacts with Λ in [lo, hi] need (so that the
    /// cost falls at setup, not inside a time step). Returns the number of nodes
    /// built by this call.
    pub fn prepare(&self, lo: f64, hi: f64) -> Result<usize> {
        let (lo, hi) = (check(lo)?, check(hi)?);
        let (a, b) = Self::stencil_span(lo.min(hi), lo.max(hi));
        let mut built = 0;
        for k in a.max(self.k_min)..=b.min(self.k_min + self.nodes.len() as i32 - 1) {
            if self.nodes[(k - self.k_min) as usize].get().is_none() {
                self.node(k)?;
                built += 1;
            }
        }
        Ok(built)
    }

    /// Number of nodes built so far (each ≈ 165 kB).
    pub fn built_nodes(&self) -> usize {
        self.nodes.iter().filter(|n| n.get().is_some()).count()
    }

    /// The bytes the built nodes' tables take.
    pub fn memory_bytes(&self) -> usize {
        self.nodes
            .iter()
            .filter_map(|n| n.get())
            .map(|n| n.table.memory_bytes() + std::mem::size_of::<Node>())
            .sum()
    }

    /// The largest measured fixed-Λ table error over the built nodes.
    pub fn node_error(&self) -> TableError {
        let mut e = TableError::default();
        for n in self.nodes.iter().filter_map(|n| n.get()) {
            let t = n.table.error();
            e.fine_force_abs = e.fine_force_abs.max(t.fine_force_abs);
            e.hertz_force_rel = e.hertz_force_rel.max(t.hertz_force_rel);
            e.fine_radius_abs = e.fine_radius_abs.max(t.fine_radius_abs);
        }
        e
    }

    /// The branch at Tabor parameter `lambda`: the stencil, its weights and the
    /// scalars (one logarithm, a few square roots; builds missing nodes).
    #[inline]
    pub fn local(&self, lambda: f64) -> Result<LocalBranch> {
        let lambda = check(lambda)?;
        let u = (lambda / LAMBDA_1).ln() / step();
        let case = TaborCase::of(lambda);
        let (seg_lo, seg_hi) = match case {
            TaborCase::NoContact => (self.k_min, 0),
            TaborCase::ContactThenNoContact => (0, TABOR_LAMBDA_CASE_2_INTERVALS),
            TaborCase::Contact => (
                TABOR_LAMBDA_CASE_2_INTERVALS,
                self.k_min + self.nodes.len() as i32 - 1,
            ),
        };
        let mut lo = (u.floor() as i32 - 1).max(seg_lo);
        if lo + 3 > seg_hi {
            lo = seg_hi - 3;
        }
        let nodes = [lo, lo + 1, lo + 2, lo + 3];
        // 4-point Lagrange weights at t = u − lo on the nodes 0, 1, 2, 3
        let t = u - f64::from(lo);
        let (a, b, c, d) = (t, t - 1.0, t - 2.0, t - 3.0);
        let weights = [
            -b * c * d / 6.0,
            a * c * d / 2.0,
            -a * b * d / 2.0,
            a * b * c / 6.0,
        ];
        let mut origin = 0.0;
        let mut pull_off = 0.0;
        for (k, w) in nodes.iter().zip(weights) {
            let n = self.node(*k)?;
            origin += w * n.origin;
            pull_off += w * n.pull_off;
        }
        let (origin, kink) = match case {
            TaborCase::Contact => (origin, 0.0),
            _ => no_contact_origin_and_kink(lambda),
        };
        Ok(LocalBranch {
            lambda,
            jump_in: -1.0 / lambda,
            snap_off: origin,
            pull_off_force: pull_off.min(0.0),
            kink,
            span: span_end(lambda) - kink,
            nodes,
            weights,
        })
    }

    /// (F̂, â) on the branch at normalized overlap `d_hat` ≥ the snap-off depth
    /// (the contact has formed). Errors beyond the tables (an overlap 10⁶ adhesive
    /// depths deep).
    #[inline]
    pub fn branch(&self, at: &LocalBranch, d_hat: f64) -> Result<(f64, f64)> {
        let u = (d_hat - at.snap_off).max(0.0);
        let xi = if u < at.kink {
            u / at.kink
        } else {
            1.0 + (u - at.kink) / at.span
        };
        let (mut f, mut a) = (0.0, 0.0);
        for (k, w) in at.nodes.iter().zip(at.weights) {
            let n = self.node(*k)?;
            let un = if xi < 1.0 {
                xi * n.kink
            } else {
                n.kink + (xi - 1.0) * n.span
            };
            let (fn_, an) = n.table.eval((un * n.inv_length).sqrt()).ok_or_else(|| {
                Error::invalid(
                    "overlap",
                    d_hat,
                    "is beyond the per-contact Maugis-Dugdale table (10^6 adhesive depths)",
                )
            })?;
            f += w * fn_;
            a += w * an;
        }
        Ok((f, a.max(0.0)))
    }

    /// Measures the interpolation error at `lambda` against the exact law
    /// (`tabor_maugis::MaugisDugdaleForceLaw` at that Λ, a root solve per point,
    /// built and tabulated at that Λ by [`ContactLaw::maugis_dugdale`]): the branch
    /// is compared at the same distance u above each law's own snap-off depth, at
    /// `points` + 1 values of u over the adhesive part ((u/L) ≤ 64) and `points`/4
    /// beyond it up to u/L = 10⁴. The snap-off depth itself is compared apart: the
    /// force has a square-root singularity there, F̂ ≈ F̂₀ + c√u, so a shift Δd̂₀ of
    /// the snap-off moves the force by up to c√Δd̂₀ within Δd̂₀ of it.
    pub fn measure_error(&self, lambda: f64, points: usize) -> Result<LambdaTableError> {
        let exact = ContactLaw::maugis_dugdale(1.0, 1.0, 1.0, lambda)?;
        let (f_n, a_c, d_n) = exact.reference_scales();
        let (d0, inv_length, pull_off, _) = exact.normalized_branch();
        let at = self.local(lambda)?;
        let mut err = LambdaTableError {
            snap_off_abs: (at.snap_off - d0).abs(),
            pull_off_abs: (at.pull_off_force - pull_off).abs(),
            ..LambdaTableError::default()
        };
        let points = points.max(4);
        for i in 0..=points {
            let s = 8.0 * i as f64 / points as f64;
            let u = s * s / inv_length;
            let (fe, ae) = exact.exact_branch((d0 + u) * d_n)?;
            let (f, a) = self.branch(&at, at.snap_off + u)?;
            err.force_abs = err
                .force_abs
                .max((f - fe / f_n).abs() / (fe / f_n).abs().max(1.0));
            err.radius_abs = err.radius_abs.max((a - ae / a_c).abs());
        }
        for i in 1..=points / 4 {
            let s = 8.0 * (100.0f64 / 8.0).powf(i as f64 / (points / 4) as f64);
            let u = s * s / inv_length;
            let (fe, _) = exact.exact_branch((d0 + u) * d_n)?;
            let (f, _) = self.branch(&at, at.snap_off + u)?;
            err.hertz_force_rel = err.hertz_force_rel.max((f * f_n / fe - 1.0).abs());
        }
        Ok(err)
    }
}

/// The measured error of the per-contact table at one Λ
/// ([`LambdaTable::measure_error`]), normalized by the JKR scales of that contact.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LambdaTableError {
    /// Largest |ΔF̂| on the adhesive part (units of F_n; relative where |F| > F_n).
    pub force_abs: f64,
    /// Largest |Δâ| on the adhesive part (units of a_c).
    pub radius_abs: f64,
    /// Largest |ΔF/F| beyond it.
    pub hertz_force_rel: f64,
    /// |Δd̂₀|: the snap-off depth (units of d_n).
    pub snap_off_abs: f64,
    /// |ΔF̂| of the pull-off force (units of F_n).
    pub pull_off_abs: f64,
}

fn check(lambda: f64) -> Result<f64> {
    if !(TABOR_LAMBDA_MIN..=TABOR_LAMBDA_MAX).contains(&lambda) {
        return Err(Error::invalid(
            "tabor_parameter",
            lambda,
            "a contact's Lambda = d_n(R*)/h must lie in [1e-4, 1e6] for the per-contact table \
             (the range h is too large or too small for this effective radius)",
        ));
    }
    Ok(lambda)
}

/// The one table of the process: it is normalized (depends on Λ only), so every
/// per-contact law of every pair of types shares its nodes.
pub fn shared_table() -> Arc<LambdaTable> {
    static TABLE: OnceLock<Arc<LambdaTable>> = OnceLock::new();
    TABLE.get_or_init(|| Arc::new(LambdaTable::new())).clone()
}

impl ContactLaw {
    /// Maugis-Dugdale at a fixed Dugdale range h (m) with work of adhesion w
    /// (J/m²): each contact's Tabor parameter is Λ = d_n(R*)/h (spec
    /// `maugis-dugdale.md`, `tabor_maugis::units::tabor_parameter_from_range`), so
    /// Λ ∝ R*^(1/3); the branch comes from the shared [`LambdaTable`]. The
    /// reference radius R* only sets what the single-radius accessors report.
    pub fn maugis_dugdale_range(
        effective_modulus: f64,
        effective_radius: f64,
        work_of_adhesion: f64,
        range: f64,
    ) -> Result<Self> {
        let h = tabor_restitution::validate::positive("range", range)?;
        let sphere =
            tabor_jkr::JkrSphere::new(effective_modulus, effective_radius, work_of_adhesion)?;
        let mut out =
            Self::hertz(effective_modulus, effective_radius)?.with_scales(&sphere.scales());
        out.kind = crate::law::LawKind::MaugisDugdaleRange(h);
        out.per_contact = Some((h, shared_table()));
        out.exact = crate::law::Exact::PerContact;
        // a contact's Λ is checked against the table's domain when it is met
        // ([`ContactLaw::prepare_radii`], or its first evaluation)
        Ok(out)
    }

    /// Maugis-Dugdale at a fixed Dugdale cohesive stress σ0 (Pa): the range is
    /// h = w/σ0 (spec `maugis-dugdale.md`: σ0 h = Δγ), then as
    /// [`ContactLaw::maugis_dugdale_range`].
    pub fn maugis_dugdale_stress(
        effective_modulus: f64,
        effective_radius: f64,
        work_of_adhesion: f64,
        cohesive_stress: f64,
    ) -> Result<Self> {
        let s0 = tabor_restitution::validate::positive("cohesive_stress", cohesive_stress)?;
        let w = tabor_restitution::validate::positive("work_of_adhesion", work_of_adhesion)?;
        Self::maugis_dugdale_range(effective_modulus, effective_radius, w, w / s0)
    }

    /// The Tabor parameter of a contact at the radius of `s`: Λ = d_n/h for a
    /// per-contact law, the law's own Λ for fixed-Λ Maugis-Dugdale, `None` else.
    pub fn tabor_parameter_at(&self, s: &RadiusScales) -> Option<f64> {
        match self.kind {
            crate::law::LawKind::MaugisDugdale(l) => Some(l),
            crate::law::LawKind::MaugisDugdaleRange(h) => Some(s.depth / h),
            _ => None,
        }
    }

    /// Builds the table nodes that contacts with effective radii in
    /// [r_min, r_max] (m) need, so that the cost falls at setup (no-op for the
    /// other laws). Returns the number of nodes built.
    pub fn prepare_radii(&self, r_min: f64, r_max: f64) -> Result<usize> {
        let Some((h, table)) = &self.per_contact else {
            return Ok(0);
        };
        let lo = self.scales(r_min)?.depth / h;
        let hi = self.scales(r_max)?.depth / h;
        table.prepare(lo, hi)
    }

    /// The largest interaction range (m) over effective radii in [r_min, r_max]
    /// (m): at r_max for the fixed laws (∝ R*^(1/3)); for a per-contact law the
    /// larger of h and the snap-off gap, searched over the grid of the radii.
    pub fn interaction_range_over(&self, r_min: f64, r_max: f64) -> Result<f64> {
        let hi = self.scales(r_max)?;
        if self.per_contact.is_none() {
            return Ok(self.interaction_range_at(&hi));
        }
        let lo = self.scales(r_min)?;
        let mut reach = 0.0f64;
        for i in 0..=64 {
            let r = lo.effective_radius
                * (hi.effective_radius / lo.effective_radius).powf(f64::from(i) / 64.0);
            let s = self.scales(r)?;
            self.local_at(&s)?;
            reach = reach.max(self.interaction_range_at(&s));
        }
        Ok(reach)
    }

    /// The normalized branch at the contact's Λ (per-contact laws only).
    pub(crate) fn local_at(&self, s: &RadiusScales) -> Result<LocalBranch> {
        let (h, table) = self.per_contact.as_ref().ok_or_else(|| Error::Model {
            model: "tabor-ffi",
            message: "not a per-contact Lambda law".into(),
        })?;
        table.local(s.depth / h)
    }

    /// The fixed-Λ law's normalized branch: (d̂₀, 1/L, F̂ pull-off, table).
    pub(crate) fn normalized_branch(&self) -> (f64, f64, f64, Option<Arc<Table>>) {
        (
            self.table_origin,
            self.inv_table_length,
            self.pull_off_force,
            self.table.clone(),
        )
    }

    /// (F_n, a_c, d_n) at the reference radius.
    pub(crate) fn reference_scales(&self) -> (f64, f64, f64) {
        let r = &self.reference;
        (r.force, r.contact_radius, r.depth)
    }

    /// [`ContactLaw::evaluate_with_mass`] of a per-contact law.
    #[allow(clippy::too_many_arguments)]
    pub(crate) fn evaluate_per_contact(
        &self,
        h: f64,
        table: &LambdaTable,
        scales: &RadiusScales,
        overlap: f64,
        overlap_rate: f64,
        effective_mass: f64,
        history: &mut crate::law::TaborHistory,
    ) -> Result<crate::law::TaborForce> {
        let mut event = 0;
        if history.contact == 0.0 {
            // jump-in at δ = −h exactly (seed 000 (5.40)): nothing to look up before
            if overlap < -h {
                return Ok(crate::law::TaborForce::default());
            }
            history.contact = 1.0;
            history.max_overlap = overlap;
            event = 1;
        }
        let at = table.local(scales.depth / h)?;
        if overlap < at.snap_off * scales.depth {
            *history = crate::law::TaborHistory::default();
            return Ok(crate::law::TaborForce {
                event: event | 2,
                ..Default::default()
            });
        }
        if overlap > history.max_overlap {
            history.max_overlap = overlap;
        }
        let (f, a) = table.branch(&at, overlap * scales.inv_depth)?;
        let (f, a) = (f * scales.force, a * scales.contact_radius);
        Ok(crate::law::TaborForce {
            force: self.total_force(f, a, overlap_rate, effective_mass),
            elastic_force: f,
            contact_radius: a,
            event,
        })
    }
}
