//! Mindlin-Deresiewicz micro-slip by the method of dimensionality reduction
//! (Popov & Heß 2015, ch. 2 and 8; the tangential MDR of Heß & Popov 2016,
//! Lyashenko & Popov 2015 reproduce Maw, Barber & Fawcett with it): a 1-D bed of
//! independent springs at `−a ≤ x ≤ a`, each with tangential stiffness `k' = k_t/2`
//! per unit length (so the no-slip stiffness of the whole bed is `k_t a`:
//! Mindlin's `8 G* a` with the default `k_t = 8 G*`), each sliding by Coulomb's
//! law on its own normal load. A spring enters the contact unstrained where the
//! contact radius grows over it and leaves it where the radius shrinks below it
//! (having slid to zero on its vanishing load first).
//!
//! **The normal load of a spring.** For Hertz the MDR load density is
//! `E* (a² − x²)/R`, which integrates to the Hertz force. For every other normal
//! law (adhesive, plastic) the rule of Thornton & Yin (1991, Powder Technol. 65,
//! 153) is used: the Coulomb limit of the whole contact is `μ F_n0` (`F_n0` of
//! [`crate::critical_force`]: `F_n + 2 F_pulloff` for a cohesive law), spread over
//! the law's own contact radius `a` in the Hertzian shape:
//! `q(x) = μ F_n0 · 3 (a² − x²)/(4 a³)`. This is exact for Hertz and the stated
//! rule elsewhere. It neglects the peeling that precedes sliding in an adhesive
//! contact (Savkoor & Briggs 1977: the tangential load lowers the contact radius
//! until the contact slides), and the true adhesive pressure (infinite at the JKR
//! edge, where the springs then could not slip at all); with adhesion the split
//! between micro-slip and stick is therefore uncertain by the shape of `q(x)`,
//! while the gross-sliding limit `μ F_n0` is that of LAMMPS's `jkr`.
//!
//! **The update.** The law is rate-independent: a spring's state at the end of a
//! step depends only on the path of the tangential displacement `s` and of its
//! limit. Within a step the path is taken straight from the last committed state
//! (the start of the integrator's step) to the state evaluated: the trial
//! displacement `w₀ + (s − s₀)` is projected onto the disc of the current limit.
//! Along a straight path with a limit linear in the path parameter this return map
//! is exact (`|w₀ + λΔs| − W(λ)` is convex in λ: a spring that is inside its limit
//! at both ends was inside all along, and one that reached its limit slides on to
//! the end, in one dimension); in the plane it is the radial return, whose error in
//! the direction of a turning slip vanishes with the step. A spring that the
//! growing contact reaches during the step enters unstrained where `a²` (taken
//! linear along the path, as the overlap of Hertz's `a² = R δ`) passes it, and
//! carries only the part of `Δs` after that point. After every accepted step the
//! state is committed at the step's end: by this one straight path where no
//! spring stopped slipping or entered stuck within the step (then the state
//! depends on the step's ends alone), else along the integrator's continuous
//! solution in [`PATH_CHORDS`](super::limits::PATH_CHORDS) straight pieces (the
//! values of those springs depend on the path; the pieces' error is second order
//! in their length: `Setup::commit_bed_along`).
//!
//! **Two forms.** A planar history (every displacement on one line of the tangent
//! plane turned with the normal, as in an impact whose spins are normal to its
//! plane) is kept exactly as breakpoints of a profile piecewise linear in
//! `z = x²` ([`super::line_bed`]): no discretization in z, the cost of an
//! evaluation the breakpoints near the stick/slip boundaries. Any other history
//! takes the nodes uniform in z of [`super::node_bed`] (the planar bed hands its
//! profile over, sampled at the nodes, at the first increment off its line: the
//! first evaluation off the line, even the trial of a step the integrator then
//! rejects, so the rest of that contact keeps the node bed's 1/nodes² accuracy).
//! [`ObliqueImpact::simulate_with_nodes`] takes the node bed throughout.

use super::bodies::ObliqueImpact;
use super::line_bed::LineBed;
use super::node_bed::NodeBed;
use crate::model::TangentialModel;
use nalgebra::Vector3;
use std::cell::{Cell, RefCell};
use tabor_dynamics::ForceLaw;

/// The number of nodes of the node bed, which takes a history off the planar
/// bed's line in [`ObliqueImpact::simulate`], in `z = x²` per `a_ref²`, the
/// square of the contact-radius scale of the impact (the grid grows with the same
/// spacing where the contact outgrows it). The error of the stick zone's profile
/// falls as `1/nodes²`: for steel on steel (Maw, Barber & Fawcett's case) the
/// tangential restitution at 1024 nodes is within 2e-5 of its limit
/// (`tests/micro_slip.rs` measures it).
pub const MICRO_SLIP_NODES: usize = 1024;

/// What the spring bed sees of the contact at one moment: the normal (unit), the
/// tangential displacement `s` (m; its part along the normal is ignored), the
/// contact radius `a` (m) and the Coulomb limit `μ F_n0` (N).
#[derive(Clone, Copy, Debug)]
pub(super) struct BedState {
    /// The unit normal of the contact.
    pub(super) normal: Vector3<f64>,
    /// The tangential displacement `s` (m).
    pub(super) displacement: Vector3<f64>,
    /// The contact radius `a` (m).
    pub(super) radius: f64,
    /// The Coulomb limit `μ F_n0` (N).
    pub(super) limit: f64,
}

impl BedState {
    /// The state of normal `normal`, displacement `displacement`, contact radius
    /// `radius` and Coulomb limit `limit`.
    pub(super) fn new(
        normal: Vector3<f64>,
        displacement: Vector3<f64>,
        radius: f64,
        limit: f64,
    ) -> Self {
        BedState {
            normal,
            displacement,
            radius,
            limit,
        }
    }
}

/// The MDR spring bed of a contact under Mindlin-Deresiewicz micro-slip: the
/// planar form while the history allows it, else the node bed.
#[derive(Clone, Debug)]
pub(super) struct MicroSlipBed {
    /// k' = k_t/2 (N/m²): tangential stiffness per unit length of the bed.
    k_line: f64,
    /// The planar bed (`None`: the node bed throughout).
    line: Option<LineBed>,
    /// Whether the planar bed holds the state (else the node bed does).
    planar: Cell<bool>,
    /// The node bed, loaded from the planar one where a history leaves its line
    /// (built then: a planar impact never pays for its grid).
    nodes: RefCell<Option<NodeBed>>,
    /// `(k_t, a_ref, nodes)` of the node bed, for building it.
    grid: (f64, f64, usize),
}

impl MicroSlipBed {
    /// An unstrained bed of stiffness `k_t` (N/m² per unit radius: the no-slip
    /// stiffness is `k_t a`), planar where the history allows (`exact`), with
    /// nodes spaced `a_ref²/nodes` in z otherwise.
    pub(super) fn new(k_t: f64, a_ref: f64, nodes: usize, exact: bool) -> Self {
        MicroSlipBed {
            k_line: 0.5 * k_t,
            line: exact.then(LineBed::new),
            planar: Cell::new(exact),
            nodes: RefCell::new((!exact).then(|| NodeBed::new(k_t, a_ref, nodes))),
            grid: (k_t, a_ref, nodes),
        }
    }

    /// The node bed, built (unstrained) where it was not yet.
    fn node_bed(
        nodes: &mut Option<NodeBed>,
        (k_t, a_ref, count): (f64, f64, usize),
    ) -> &mut NodeBed {
        nodes.get_or_insert_with(|| NodeBed::new(k_t, a_ref, count))
    }

    /// Resets the bed at contact onset (contact radius `a`): no spring strained,
    /// `s` and `n` the reference.
    pub(super) fn reset(&mut self, s: &Vector3<f64>, n: &Vector3<f64>, a: f64) {
        if let Some(line) = self.line.as_mut() {
            line.reset(s, n, a);
            self.planar.set(true);
        }
        if self.line.is_none() || self.nodes.get_mut().is_some() {
            Self::node_bed(self.nodes.get_mut(), self.grid).reset(s, n, a);
        }
    }

    /// The slip displacement per unit of `a² − z` at contact radius `a` (m) and
    /// Coulomb limit `limit = μ F_n0` (N): `W(z) = φ (a² − z)`.
    fn slope(&self, a: f64, limit: f64) -> f64 {
        0.75 * limit / (a * a * a * self.k_line)
    }

    /// The planar bed and its probe at the state given, where it holds the state
    /// and the increment stays on its line; hands the state to the node bed at
    /// the first increment off the line. `Err(())` where there is no contact.
    fn planar_probe(
        &self,
        state: &BedState,
    ) -> Result<Option<(&LineBed, super::line_bed::LineProbe)>, ()> {
        let (n, s, a, limit) = (
            &state.normal,
            &state.displacement,
            state.radius,
            state.limit,
        );
        let Some(line) = self.line.as_ref().filter(|_| self.planar.get()) else {
            return Ok(None);
        };
        if a <= 0.0 || limit.is_nan() || limit <= 0.0 {
            return Err(());
        }
        match line.probe(n, s, a * a, self.slope(a, limit)) {
            Some(p) => Ok(Some((line, p))),
            None => {
                Self::node_bed(&mut self.nodes.borrow_mut(), self.grid).load(line);
                self.planar.set(false);
                Ok(None)
            }
        }
    }

    /// The force of the bed on body i (N) at the state given (not committed):
    /// `−k' ∫₀^{a²} w z^{−1/2} dz`.
    pub(super) fn force(&self, state: &BedState) -> Vector3<f64> {
        match self.planar_probe(state) {
            Err(()) => Vector3::zeros(),
            Ok(Some((line, p))) => -LineBed::direction(&p) * (self.k_line * line.integral(&p)),
            Ok(None) => Self::node_bed(&mut self.nodes.borrow_mut(), self.grid).force(state),
        }
    }

    /// Whether committing `state` would depend on the path of the step, not
    /// only on its ends ([`LineBed::path_dependent`],
    /// [`NodeBed::path_dependent`]).
    pub(super) fn path_dependent(&self, state: &BedState) -> bool {
        match self.planar_probe(state) {
            Err(()) => false,
            Ok(Some((line, p))) => line.path_dependent(&p),
            Ok(None) => {
                Self::node_bed(&mut self.nodes.borrow_mut(), self.grid).path_dependent(state)
            }
        }
    }

    /// Commits `state`: the return map becomes the bed's state; springs out of
    /// contact are unstrained.
    pub(super) fn commit(&mut self, state: &BedState) {
        let probe = match self.planar_probe(state) {
            Err(()) => {
                // no contact (or no limit): every spring unstrained
                self.reset(&state.displacement, &state.normal, 0.0);
                return;
            }
            Ok(found) => found.map(|(_, p)| p),
        };
        match (probe, self.line.as_mut()) {
            (Some(p), Some(line)) => line.commit(&p, &state.normal, &state.displacement),
            _ => Self::node_bed(self.nodes.get_mut(), self.grid).commit(state),
        }
    }

    /// Commits the states of `path` in turn, the last the step's end: on a
    /// strained planar bed at once along the straight pieces between them
    /// ([`LineBed::commit_along`]); one by one where the bed is unstrained (it
    /// takes its direction from each increment), where a state has no contact
    /// or leaves the bed's line, and on the node bed.
    pub(super) fn commit_along(&mut self, path: &[BedState]) {
        if self.planar.get() && self.line.as_ref().is_some_and(LineBed::is_strained) {
            let mut probes = Vec::with_capacity(path.len());
            for state in path {
                match self.planar_probe(state) {
                    Ok(Some((_, p))) => probes.push((p, state.normal, state.displacement)),
                    _ => break,
                }
            }
            if let (Some(line), true) = (self.line.as_mut(), probes.len() == path.len()) {
                line.commit_along(&probes);
                return;
            }
        }
        for state in path {
            self.commit(state);
        }
    }

    /// Whether the planar bed holds the state (exact; else the node bed).
    pub(super) fn is_planar(&self) -> bool {
        self.planar.get()
    }

    /// The elastic energy stored in the committed bed (J):
    /// `½ k' ∫ |w|² z^{−1/2} dz` (exact for the planar bed; the nodal values of
    /// `|w|²` interpolated as `w` for the node bed).
    pub(super) fn stored_energy(&self, a: f64) -> f64 {
        match self.line.as_ref().filter(|_| self.planar.get()) {
            Some(line) => 0.5 * self.k_line * line.square_integral(a * a),
            None => Self::node_bed(&mut self.nodes.borrow_mut(), self.grid).stored_energy(a),
        }
    }
}

impl ObliqueImpact {
    /// The spring bed of `mindlin_deresiewicz`: planar where the history allows
    /// and `nodes` is `None`, its node grid (`nodes`, or [`MICRO_SLIP_NODES`])
    /// scaled by the contact radius at the overlap scale (the Hertz radius
    /// `√(R δ)` or the law's own, whichever is larger); `None` for the other
    /// tangential models.
    pub(super) fn micro_slip_bed(
        &self,
        law: &dyn ForceLaw,
        r_eff: f64,
        length: f64,
        v_n: f64,
        nodes: Option<usize>,
    ) -> Option<RefCell<MicroSlipBed>> {
        let f = self.friction.as_ref()?;
        if f.tangential.model != TangentialModel::MindlinDeresiewicz {
            return None;
        }
        let hertz = (r_eff * length).sqrt();
        let own = law.contact_radius(length, v_n).unwrap_or(0.0);
        let a_ref = if own.is_finite() {
            hertz.max(own)
        } else {
            hertz
        };
        Some(RefCell::new(MicroSlipBed::new(
            f.tangential.stiffness,
            a_ref,
            nodes.unwrap_or(MICRO_SLIP_NODES),
            nodes.is_none(),
        )))
    }
}
