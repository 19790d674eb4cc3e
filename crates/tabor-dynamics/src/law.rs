//! The force-law interface of the simulator (every contact model implements it in
//! its own crate: `tabor-elastic`, `tabor-jkr`, `tabor-maugis`, `tabor-plastic`, ...).

use tabor_restitution::Result;

/// What the motion does after a hook ([`ForceLaw::on_branch_end`],
/// [`ForceLaw::on_max_compression`], [`ForceLaw::on_min_compression`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum BranchChange {
    /// The motion goes on (possibly on a new branch the hook switched to).
    Continue,
    /// The bodies part: the impact ends, the rebound speed is −ḋ there.
    Separate,
    /// The bodies stay together: the impact ends with restitution 0.
    Stick,
}

/// A state of a branch at a point of its own coordinate (see [`BranchCurve`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurvePoint {
    /// Overlap d(q) (m).
    pub overlap: f64,
    /// dd/dq (m per unit of q): nonzero inside the branch, of one sign along it; it
    /// may fall to 0 at the branch's end (a fold of d(q), the fixed-grip snap-off).
    pub overlap_slope: f64,
    /// Normal force F(q, ḋ) (N, repulsive > 0).
    pub force: f64,
    /// Contact radius (m), for the trajectory record.
    pub contact_radius: f64,
    /// `(dF/dq, da/dq)` (N and m per unit of q) where the law gives them in
    /// closed form (JKR's polynomials, Maugis-Dugdale's θ-derivatives); `None`: a consumer that needs the slopes
    /// of force and contact radius differences the curve (the oblique impact's
    /// slip conditions).
    pub slopes: Option<(f64, f64)>,
}

/// The barrier between a state of a conservative branch and the point where the
/// bodies separate ([`ForceLaw::separation_barrier`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SeparationBarrier {
    /// `U(d) − U(d_sep) = ∫_{d_sep}^{d} F dd'` (J): negative where the bodies
    /// need that much kinetic energy to reach the separation point d_sep.
    pub potential: f64,
    /// The overlap d_sep (m) where the branch ends in separation (the
    /// load-controlled JKR pull-off `−d_n`, the fixed-grip snap-off, the
    /// Maugis-Dugdale pull-off depth).
    pub separation_overlap: f64,
}

/// A branch of a [`ForceLaw`] in a coordinate `q` of its own in which the overlap
/// d(q) and the force F(q, ḋ) are smooth, explicit functions: the root of the JKR
/// quartic `x = √(a/a_c)`, the angle θ of the Maugis-Dugdale contact branch.
///
/// The equation of motion is seed 000 eq. (5.5), `m d̈ = −F`, as for
/// [`ForceLaw`]. Given one ([`ForceLaw::curve`]), the simulator integrates the
/// branch in `q` over a regularized time σ that is the time where |dd/dq| is
/// large and turns into the Sundman time `dt = |dd/dq| dσ` where it falls to 0
/// (there `dq/dσ ∝ ±ḋ`, `dḋ/dσ ∝ −(F/m)|dd/dq|`). This needs no solve for q at a force
/// evaluation, and the motion stays smooth in σ where d(q) has a fold at the
/// branch end (dd/dq = 0), where F(d), and with it d(t), has a square-root
/// singularity that an integrator in t can only approach with ever shorter steps.
pub trait BranchCurve {
    /// The coordinate q of the state with overlap `overlap` (m) on the current
    /// branch (one solve, at the start of a segment).
    fn coordinate(&self, overlap: f64) -> Result<f64>;

    /// The state at coordinate `coordinate` with overlap rate `overlap_rate` (m/s).
    /// Pure and smooth in `q`; it must stay finite a little beyond the branch end
    /// (trial points of the integrator), continuing the same formulas there.
    fn point(&self, coordinate: f64, overlap_rate: f64) -> Result<CurvePoint>;

    /// The signed distance to the end of the branch at coordinate `coordinate` and
    /// overlap rate `overlap_rate` (m/s): positive while the branch holds; it must
    /// cross 0 with a nonzero slope (where d(q) has a fold, measure it in q, not in
    /// d). The simulator then calls [`ForceLaw::on_branch_end`].
    fn end(&self, coordinate: f64, overlap_rate: f64) -> Result<f64>;

    /// A typical |dd/dq| of the branch (m per unit of q, > 0), such as its value
    /// where the motion enters the branch: the scale below which the simulator's
    /// regularized time turns into the Sundman time, also on a segment that starts
    /// at a fold.
    fn slope_scale(&self) -> f64;

    /// True when |dd/dq| stays at least a quarter of [`BranchCurve::slope_scale`]
    /// from the entry to the end of the branch (no fold: the end is not a
    /// fixed-grip snap-off), so that `q̇ = ḋ/(dd/dq)` stays bounded and a
    /// consumer may integrate q in time (the planar oblique impact does).
    /// Default: false (integrate in the overlap, or in the regularized time).
    fn fold_free(&self) -> bool {
        false
    }

    /// The work `∫ F dd` (J) done against the force along the branch from a
    /// fixed reference point of it to coordinate `coordinate`, where the force
    /// depends on q alone (not on the overlap rate), in closed form: a consumer
    /// books the normal elastic-adhesive work of a stretch of the branch as
    /// `W(q₁) − W(q₀)` instead of integrating `F ḋ`. Default: `None`.
    fn work(&self, _coordinate: f64) -> Option<f64> {
        None
    }
}

/// A contact force law for the equation of motion `m d̈ = −F(d, ḋ, history)`
/// (seed 000 eq. (5.5) and its generalizations), with `d` the overlap
/// (indentation, positive in contact) and `F` the normal force, positive when
/// repulsive.
///
/// # Branches and history
///
/// A law is a sequence of smooth *branches*. Within a branch, [`ForceLaw::force`]
/// must be a pure, smooth function of `(d, ḋ)`: the integrator evaluates it at
/// trial points, also at rejected steps and slightly beyond the branch end, so it
/// must return finite values there too (extend the branch, or clamp). History
/// changes only in the hooks, which the simulator calls at located events:
///
/// - [`ForceLaw::begin_impact`] once before the motion starts (reset to the first
///   branch; the law is `&mut`, so the same value can simulate many impacts);
/// - [`ForceLaw::on_max_compression`] where ḋ changes from + to − (the turning point;
///   a plastic law switches to its unloading branch and stores d_max here);
/// - [`ForceLaw::on_min_compression`] where ḋ changes from − to + while the impact
///   is still running (the body falls back inward: by default it sticks);
/// - [`ForceLaw::on_branch_end`] where [`ForceLaw::branch_end`] falls from > 0 to
///   ≤ 0 (separation at d = 0 for elastic laws; jump-in at d = −h, snap-off at a
///   negative d, or F = 0 on a plastic unloading branch for others).
///
/// After every event the integrator restarts, so force jumps (jump-in) are exact.
///
/// # How the laws still to come plug in
///
/// - **JKR** (fixed grip): [`ForceLaw::begin_impact`] puts the law on the JKR
///   branch at d = 0 (jump-in: `force(0, ·)` is already attractive);
///   `branch_end = d − d_c` with d_c < 0 the fixed-grip snap-off overlap, or, for
///   the load-controlled rule, a − a_pull-off (the minimum of F); `on_branch_end`
///   returns [`BranchChange::Separate`].
/// - **Maugis-Dugdale**: [`ForceLaw::start_overlap`] returns the approach distance
///   (< −h), [`ForceLaw::in_contact`] is false and `force` is 0 until
///   `branch_end = −h − d` reaches 0; `on_branch_end` then switches to the
///   equilibrium branch (now `in_contact`, `branch_end = d − d_min`) and returns
///   [`BranchChange::Continue`]; at d_min it returns [`BranchChange::Separate`].
/// - **Plastic**: loading law until `on_max_compression` switches to elastic
///   unloading with the residual depth (stored in the law), `branch_end = F`;
///   separation when F reaches 0.
///
/// The crate's tests contain two such toy laws (hysteretic loading/unloading, and
/// approach + jump-in + snap-off).
pub trait ForceLaw {
    /// A short name for reports.
    fn name(&self) -> String;

    /// A typical magnitude of the overlap during an impact of effective mass
    /// `effective_mass` at `impact_speed` (m), > 0: the simulation runs in units
    /// of this length and of length/v0, and the tolerances apply there. d_max of
    /// the elastic impact is a good choice; within a factor of ten is fine.
    fn overlap_scale(&self, effective_mass: f64, impact_speed: f64) -> Result<f64>;

    /// Called once before the motion starts: reset to the first branch.
    fn begin_impact(&mut self, _effective_mass: f64, _impact_speed: f64) -> Result<()> {
        Ok(())
    }

    /// The overlap at which the motion starts (m): 0 (first contact, seed 000
    /// eq. (5.6)) by default; negative for an approach from a distance.
    fn start_overlap(&self) -> f64 {
        0.0
    }

    /// Whether the bodies are in contact on the current branch (the contact time is
    /// measured from the first event after which this is true, or from the start).
    fn in_contact(&self) -> bool {
        true
    }

    /// The normal force F (N, repulsive > 0) at overlap `overlap` (m) and overlap
    /// rate `overlap_rate` (m/s) on the current branch. Pure (see the trait docs).
    fn force(&self, overlap: f64, overlap_rate: f64) -> Result<f64>;

    /// The contact radius (m) on the current branch, for the trajectory record.
    fn contact_radius(&self, overlap: f64, overlap_rate: f64) -> Result<f64>;

    /// The signed distance to the end of the current branch: positive while the
    /// branch holds; the branch ends where it falls to 0. Default: the overlap
    /// (separation at d = 0).
    fn branch_end(&self, overlap: f64, _overlap_rate: f64) -> Result<f64> {
        Ok(overlap)
    }

    /// Called where [`ForceLaw::branch_end`] reaches 0. Default: separation.
    /// Returning [`BranchChange::Continue`] requires switching to a branch whose
    /// `branch_end` is positive at this point (else the simulation reports an error).
    fn on_branch_end(&mut self, _overlap: f64, _overlap_rate: f64) -> Result<BranchChange> {
        Ok(BranchChange::Separate)
    }

    /// Called at the turning point ḋ: + → − (maximum compression) at overlap
    /// `overlap`. Default: continue on the same branch.
    fn on_max_compression(&mut self, _overlap: f64) -> Result<BranchChange> {
        Ok(BranchChange::Continue)
    }

    /// Called where ḋ: − → + (the body turns inward again before separating).
    /// Default: [`BranchChange::Stick`]: the body is caught in the potential well
    /// and, without further dissipation modelled, would oscillate forever.
    fn on_min_compression(&mut self, _overlap: f64) -> Result<BranchChange> {
        Ok(BranchChange::Stick)
    }

    /// Called where [`BranchCurve::end`] of the law's curve reaches 0, at
    /// coordinate `coordinate` (overlap `overlap`, rate `overlap_rate`): the
    /// coordinate tells a law with several ends which one was met. Default:
    /// [`ForceLaw::on_branch_end`].
    fn on_curve_end(
        &mut self,
        _coordinate: f64,
        overlap: f64,
        overlap_rate: f64,
    ) -> Result<BranchChange> {
        self.on_branch_end(overlap, overlap_rate)
    }

    /// The current branch in a coordinate of its own ([`BranchCurve`]), if the law
    /// has one there: the simulator then integrates the branch in that coordinate
    /// (its [`BranchCurve::end`] replaces [`ForceLaw::branch_end`], and
    /// [`BranchCurve::point`] replaces [`ForceLaw::force`] on that branch). Default:
    /// `None`, integration in time with [`ForceLaw::force`].
    fn curve(&self) -> Option<&dyn BranchCurve> {
        None
    }

    /// The potential of the current branch at overlap `overlap` (m) relative to
    /// the point where the bodies separate, with that point's overlap
    /// ([`SeparationBarrier`]), where the law knows it: in contact, on a
    /// branch whose force depends on the overlap alone and that ends in
    /// separation. A consumer that adds damping learns from it when the bodies
    /// can no longer separate: `½ m ḋ² + U(d) − U(d_sep)` only falls, so once it
    /// is below 0 they stick (`tabor-viscoadhesive`'s README eq. (V4); the
    /// oblique impact's capture). Default: `None` (not known).
    fn separation_barrier(&self, _overlap: f64) -> Result<Option<SeparationBarrier>> {
        Ok(None)
    }
}

/// Forwards every method of [`ForceLaw`] to the law behind a pointer: a
/// borrowed law (`&mut L`) and a boxed law (`Box<dyn ForceLaw>`) are laws (seed
/// 000 eq. (5.5) as for any [`ForceLaw`]).
macro_rules! forward_force_law {
    ($($pointer:ty),+) => {$(
        impl<L: ForceLaw + ?Sized> ForceLaw for $pointer {
    fn name(&self) -> String {
        (**self).name()
    }
    fn overlap_scale(&self, m: f64, v: f64) -> Result<f64> {
        (**self).overlap_scale(m, v)
    }
    fn begin_impact(&mut self, m: f64, v: f64) -> Result<()> {
        (**self).begin_impact(m, v)
    }
    fn start_overlap(&self) -> f64 {
        (**self).start_overlap()
    }
    fn in_contact(&self) -> bool {
        (**self).in_contact()
    }
    fn force(&self, d: f64, r: f64) -> Result<f64> {
        (**self).force(d, r)
    }
    fn contact_radius(&self, d: f64, r: f64) -> Result<f64> {
        (**self).contact_radius(d, r)
    }
    fn branch_end(&self, d: f64, r: f64) -> Result<f64> {
        (**self).branch_end(d, r)
    }
    fn on_branch_end(&mut self, d: f64, r: f64) -> Result<BranchChange> {
        (**self).on_branch_end(d, r)
    }
    fn on_max_compression(&mut self, d: f64) -> Result<BranchChange> {
        (**self).on_max_compression(d)
    }
    fn on_min_compression(&mut self, d: f64) -> Result<BranchChange> {
        (**self).on_min_compression(d)
    }
    fn on_curve_end(&mut self, q: f64, d: f64, r: f64) -> Result<BranchChange> {
        (**self).on_curve_end(q, d, r)
    }
    fn curve(&self) -> Option<&dyn BranchCurve> {
        (**self).curve()
    }
    fn separation_barrier(&self, d: f64) -> Result<Option<SeparationBarrier>> {
        (**self).separation_barrier(d)
    }}
    )+};
}

forward_force_law!(&mut L, Box<L>);
