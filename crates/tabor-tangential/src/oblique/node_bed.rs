//! The spring bed as nodes: the general (non-planar) form of the bed.
//!
//! **The state.** Every spring's elastic displacement `w(x)` (a vector in the
//! tangent plane). The springs are nodes uniform in `z = x²` (the load and the
//! slip profile `q(x)/k'` are linear in `z`, so a slipping zone is integrated
//! exactly); `w` is linear in `z` between nodes, and the force
//! `F = −2 k' ∫₀^a w dx = −k' ∫₀^{a²} w(z) z^{−1/2} dz` is integrated exactly for
//! that interpolation, with `w = 0` at the edge `z = a²` (a spring there is at its
//! zero limit). What is discretized is the stick zone's profile between nodes;
//! its error falls as the square of the node spacing (measured in
//! `tests/micro_slip.rs`).
//!
//! **The frame.** Most springs cannot slip within a few steps: a spring whose
//! slack (its limit less its displacement) exceeds the path length of `s` plus
//! the change of the limits since the last rebuild follows `s` rigidly. Such
//! springs are kept in a frame: their displacements at the rebuild `u_i`, and
//! the common transform since, `w_i = Q u_i + σ` (the rotation of the tangent
//! plane and the shift); their force is `Q Σ c_i u_i + σ Σ c_i`, one sum. Only
//! the other springs (near the edge, in the slipping annuli) are visited one by
//! one. The frame is exact (no spring in it could have slipped: the bound is
//! checked at every evaluation, and the bed falls back to visiting every spring
//! where it fails) and is rebuilt when its budget is half spent.

use super::bed::BedState;
use super::limits::FRAME_STEPS;
use super::line_bed::LineBed;
use nalgebra::{Matrix3, Vector3};

/// The MDR spring bed as nodes uniform in z (see the module doc).
#[derive(Clone, Debug)]
pub(super) struct NodeBed {
    /// k' = k_t/2 (N/m²): tangential stiffness per unit length of the bed.
    k_line: f64,
    /// Node spacing in z = x² (m²).
    dz: f64,
    /// The committed displacements of the nodes `z_i = i dz` outside the frame;
    /// for a node in the frame, its displacement `u_i` at the last rebuild.
    w: Vec<Vector3<f64>>,
    /// Whether a node is in the frame.
    in_frame: Vec<bool>,
    /// The nodes outside the frame in contact at the last commit.
    explicit: Vec<usize>,
    /// Per cell `[z_i, z_{i+1}]`: the weights of `w_i` and `w_{i+1}` in
    /// `∫ w z^{−1/2} dz` for `w` linear in z.
    left: Vec<f64>,
    right: Vec<f64>,
    /// The full-cell weight of each node, `left_i + right_{i−1}`.
    full: Vec<f64>,
    /// The frame: `w_i = q u_i + sigma` for its nodes, `Σ c_i u_i`, `Σ c_i`
    /// (full-cell weights), its slack `budget`, the path length of `s` since the
    /// rebuild, and the slope φ, squared radius and highest cell top at the
    /// rebuild.
    q: Matrix3<f64>,
    sigma: Vector3<f64>,
    sum_u: Vector3<f64>,
    sum_c: f64,
    budget: f64,
    path: f64,
    phi_r: f64,
    a_r_sq: f64,
    frame_top: f64,
    /// The tangential displacement `s` at the last commit.
    s0: Vector3<f64>,
    /// The normal at the last commit (the committed `w` lie in its tangent plane).
    n0: Vector3<f64>,
    /// The squared contact radius and slope φ at the last commit.
    a0_sq: f64,
    phi0: f64,
}

/// `√q − √p` without cancellation.
fn root_difference(p: f64, q: f64) -> f64 {
    (q - p) / (q.sqrt() + p.sqrt())
}

/// The rotation taking the unit vector `from` to `to` about their common normal
/// (Rodrigues; the identity where they are equal).
pub(super) fn rotation(from: &Vector3<f64>, to: &Vector3<f64>) -> Option<Matrix3<f64>> {
    if from == to {
        return None;
    }
    let k = from.cross(to);
    let c = from.dot(to);
    if c <= -1.0 + 1e-12 {
        return None;
    }
    let kx = k.cross_matrix();
    Some(Matrix3::identity() + kx + kx * kx / (1.0 + c))
}

/// What an evaluation needs of the state given: the rotation since the commit,
/// the tangential increment, a², φ and the entering nodes' range.
struct Probe {
    turn: Option<Matrix3<f64>>,
    ds: Vector3<f64>,
    a2: f64,
    phi: f64,
}

impl NodeBed {
    /// An unstrained bed of stiffness `k_t` (N/m² per unit radius: the no-slip
    /// stiffness is `k_t a`) with nodes spaced `a_ref²/nodes` in z.
    pub(super) fn new(k_t: f64, a_ref: f64, nodes: usize) -> Self {
        let mut bed = NodeBed {
            k_line: 0.5 * k_t,
            dz: a_ref * a_ref / nodes as f64,
            w: Vec::new(),
            in_frame: Vec::new(),
            explicit: Vec::new(),
            left: Vec::new(),
            right: Vec::new(),
            full: Vec::new(),
            q: Matrix3::identity(),
            sigma: Vector3::zeros(),
            sum_u: Vector3::zeros(),
            sum_c: 0.0,
            budget: 0.0,
            path: 0.0,
            phi_r: 0.0,
            a_r_sq: 0.0,
            frame_top: 0.0,
            s0: Vector3::zeros(),
            n0: -Vector3::x(),
            a0_sq: 0.0,
            phi0: 0.0,
        };
        bed.grow(nodes + 1);
        bed
    }

    /// Extends the grid to at least `nodes` nodes.
    fn grow(&mut self, nodes: usize) {
        while self.w.len() < nodes {
            let i = self.w.len();
            self.w.push(Vector3::zeros());
            self.in_frame.push(false);
            if i > 0 {
                let (p, q) = ((i - 1) as f64 * self.dz, i as f64 * self.dz);
                let (rp, rq) = (p.sqrt(), q.sqrt());
                let d = root_difference(p, q);
                // ∫(z − p) z^{−1/2} dz / dz and ∫(q − z) z^{−1/2} dz / dz
                let up = 2.0 / 3.0 * d * d * (rq + 2.0 * rp) / self.dz;
                let down = 2.0 / 3.0 * d * d * (2.0 * rq + rp) / self.dz;
                self.left.push(down);
                self.right.push(up);
                // node i−1 is complete now
                let below = if i > 1 { self.right[i - 2] } else { 0.0 };
                self.full.push(down + below);
            }
        }
    }

    /// Resets the bed at contact onset (contact radius `a`): no spring strained,
    /// `s` and `n` the reference, the frame empty.
    pub(super) fn reset(&mut self, s: &Vector3<f64>, n: &Vector3<f64>, a: f64) {
        let needed = 2 * (a * a / self.dz).ceil() as usize + 8;
        if needed > self.w.len() {
            self.grow(needed);
        }
        self.unstrain();
        self.explicit
            .extend((0..self.w.len()).take_while(|&i| (i as f64) * self.dz < a * a));
        self.s0 = *s;
        self.n0 = *n;
        self.a0_sq = a * a;
        self.phi0 = 0.0;
    }

    /// Takes over the committed state of a planar bed: `(s₀, n₀, a₀², φ₀)` and
    /// its displacements, sampled at the nodes in contact (no frame).
    pub(super) fn load(&mut self, line: &LineBed) {
        let (s0, n0, a0_sq, phi0) = line.committed();
        let needed = 2 * (a0_sq / self.dz).ceil() as usize + 8;
        if needed > self.w.len() {
            self.grow(needed);
        }
        self.unstrain();
        let inside = (0..self.w.len())
            .take_while(|&i| (i as f64) * self.dz < a0_sq)
            .count();
        let values = line.sample((0..inside).map(|i| i as f64 * self.dz));
        for (i, w) in values.into_iter().enumerate() {
            self.w[i] = w;
            self.explicit.push(i);
        }
        self.s0 = s0;
        self.n0 = n0;
        self.a0_sq = a0_sq;
        self.phi0 = phi0;
    }

    /// Every spring unstrained and outside the frame, the frame empty.
    fn unstrain(&mut self) {
        self.w.iter_mut().for_each(|w| *w = Vector3::zeros());
        self.in_frame.iter_mut().for_each(|f| *f = false);
        self.explicit.clear();
        self.clear_frame();
    }

    fn clear_frame(&mut self) {
        self.q = Matrix3::identity();
        self.sigma = Vector3::zeros();
        self.sum_u = Vector3::zeros();
        self.sum_c = 0.0;
        self.budget = 0.0;
        self.path = 0.0;
        self.frame_top = 0.0;
    }

    /// The slip displacement per unit of `a² − z` at contact radius `a` (m) and
    /// Coulomb limit `limit = μ F_n0` (N): `W(z) = φ (a² − z)`.
    fn slope(&self, a: f64, limit: f64) -> f64 {
        0.75 * limit / (a * a * a * self.k_line)
    }

    /// The full-cell weight of node i in `∫ w z^{−1/2} dz`.
    fn full_weight(&self, i: usize) -> f64 {
        self.full[i]
    }

    /// The weight of node i at squared radius `a2`: full where the cell above it
    /// is in contact, else the cell below plus the edge cell `[z_i, a²]` (w = 0
    /// at a²).
    fn weight(&self, i: usize, a2: f64) -> f64 {
        let z = i as f64 * self.dz;
        if z + self.dz <= a2 && i < self.full.len() {
            return self.full_weight(i);
        }
        let below = if i > 0 { self.right[i - 1] } else { 0.0 };
        let (rp, re) = (z.sqrt(), a2.sqrt());
        below + 2.0 / 3.0 * root_difference(z, a2) * (2.0 * re + rp) / (re + rp)
    }

    /// The committed displacement of node i.
    fn committed(&self, i: usize) -> Vector3<f64> {
        if self.in_frame[i] {
            self.q * self.w[i] + self.sigma
        } else {
            self.w[i]
        }
    }

    fn probe(&self, state: &BedState) -> Option<Probe> {
        let (n, s, a, limit) = (
            &state.normal,
            &state.displacement,
            state.radius,
            state.limit,
        );
        if a <= 0.0 || limit.is_nan() || limit <= 0.0 {
            return None;
        }
        // the increment in the current tangent plane (s0 lies in the plane of
        // the last commit: the difference has a normal part of order |s| |Δn|,
        // which would otherwise act on the normal motion)
        let mut ds = s - self.s0;
        ds -= n * n.dot(&ds);
        Some(Probe {
            turn: rotation(&self.n0, n),
            ds,
            a2: a * a,
            phi: self.slope(a, limit),
        })
    }

    /// Whether the frame holds at the probe: no spring in it can have reached
    /// its limit, and every one has its cell above in contact.
    fn frame_holds(&self, p: &Probe) -> bool {
        if self.sum_c == 0.0 {
            return true;
        }
        let limits = (p.phi - self.phi_r).abs() * self.a_r_sq + p.phi * (p.a2 - self.a_r_sq).abs();
        self.frame_top <= p.a2 && self.path + p.ds.norm() + limits <= self.budget
    }

    /// The trial displacement of node i at the probe (before the return map),
    /// its limit there, and whether it entered the contact during the step.
    fn unmapped(&self, i: usize, p: &Probe) -> (Vector3<f64>, f64, bool) {
        let z = i as f64 * self.dz;
        let base = self.committed(i);
        let base = p.turn.map_or(base, |r| r * base);
        // a spring the contact reached during the step entered unstrained where
        // a² (linear along the path) passed its z: it carries the part of Δs
        // after that point
        let entered = z >= self.a0_sq && p.a2 > self.a0_sq;
        let t = if entered {
            base + p.ds * ((p.a2 - z) / (p.a2 - self.a0_sq))
        } else {
            base + p.ds
        };
        (t, p.phi * (p.a2 - z), entered)
    }

    /// The returned-mapped displacement of node i at the probe.
    fn trial(&self, i: usize, p: &Probe) -> Vector3<f64> {
        let (mut t, cap, _) = self.unmapped(i, p);
        let size2 = t.norm_squared();
        if size2 > cap * cap {
            t *= cap / size2.sqrt();
        }
        t
    }

    /// Whether committing `state` depends on the path of
    /// the step, not only on its ends (as the planar bed's
    /// [`LineBed::path_dependent`](super::line_bed::LineBed::path_dependent)): a
    /// node that entered the contact during the step or was on its limit at the
    /// start, and ends within its limit (the frame's nodes are stuck throughout).
    pub(super) fn path_dependent(&self, state: &BedState) -> bool {
        let Some(p) = self.probe(state) else {
            return false;
        };
        let dependent = |i: usize| {
            let (t, cap, entered) = self.unmapped(i, &p);
            if t.norm_squared() >= cap * cap {
                return false;
            }
            let cap0 = self.phi0 * (self.a0_sq - i as f64 * self.dz);
            entered || (cap0 > 0.0 && self.committed(i).norm() >= cap0 * (1.0 - 1e-12))
        };
        let all = !self.frame_holds(&p);
        self.outside(&p, all).any(dependent)
    }

    /// The nodes in contact at the probe that the frame does not carry (every
    /// node when `all`): those outside it at the last commit, then those the
    /// contact reached since.
    fn outside(&self, p: &Probe, all: bool) -> impl Iterator<Item = usize> + '_ {
        let inside = ((p.a2 / self.dz).ceil() as usize).min(self.w.len());
        let (a2, first_new) = (p.a2, (self.a0_sq / self.dz).ceil() as usize);
        let (every, explicit, new) = match all {
            true => (0..inside, &[][..], 0..0),
            false => (0..0, &self.explicit[..], first_new..inside),
        };
        every
            .chain(
                explicit
                    .iter()
                    .copied()
                    .filter(move |&i| (i as f64) * self.dz < a2),
            )
            .chain(new)
    }

    /// Calls `visit(i, w_i)` for every node in contact at the probe that the
    /// frame does not carry (every node when `all`).
    fn visit_outside<F: FnMut(usize, Vector3<f64>)>(&self, p: &Probe, all: bool, mut visit: F) {
        for i in self.outside(p, all) {
            visit(i, self.trial(i, p));
        }
    }

    /// The force of the bed on body i (N) at the state given (not committed):
    /// `−k' ∫₀^{a²} w z^{−1/2} dz`, exact for `w` linear in z between nodes and 0
    /// at the edge.
    pub(super) fn force(&self, state: &BedState) -> Vector3<f64> {
        let Some(p) = self.probe(state) else {
            return Vector3::zeros();
        };
        let holds = self.frame_holds(&p);
        let mut sum = Vector3::zeros();
        if holds && self.sum_c > 0.0 {
            let frame = self.q * self.sum_u + self.sigma * self.sum_c;
            sum += p.turn.map_or(frame, |r| r * frame) + p.ds * self.sum_c;
        }
        self.visit_outside(&p, !holds, |i, w| sum += w * self.weight(i, p.a2));
        -sum * self.k_line
    }

    /// Commits the state at (n, s, a, limit): the return map becomes the bed's
    /// displacements (the frame moves as a whole); springs out of contact are
    /// unstrained. The frame is rebuilt when it no longer holds or half its
    /// budget is spent.
    pub(super) fn commit(&mut self, state: &BedState) {
        let (n, s, a) = (&state.normal, &state.displacement, state.radius);
        // room for the contact to double its area within the next step
        let needed = 2 * (a * a / self.dz).ceil() as usize + 8;
        if needed > self.w.len() {
            self.grow(needed);
        }
        let Some(p) = self.probe(state) else {
            // no contact (or no limit): every spring unstrained
            self.reset(s, n, 0.0);
            self.phi0 = 0.0;
            return;
        };
        let holds = self.frame_holds(&p);
        let mut updated = Vec::with_capacity(self.explicit.len() + 16);
        self.visit_outside(&p, !holds, |i, w| updated.push((i, w)));
        // the step's change, for the budget
        let limits = (p.phi - self.phi0).abs() * self.a0_sq + p.phi * (p.a2 - self.a0_sq).abs();
        let change = p.ds.norm() + limits;
        // a frame that no longer holds is rebuilt from the springs just mapped
        // (every one in contact, in order)
        let fresh = if holds {
            for &i in &self.explicit {
                self.w[i] = Vector3::zeros();
            }
            self.explicit.clear();
            for (i, w) in updated {
                self.w[i] = w;
                self.in_frame[i] = false;
                self.explicit.push(i);
            }
            if let Some(r) = p.turn {
                self.q = r * self.q;
                self.sigma = r * self.sigma;
            }
            self.sigma += p.ds;
            self.path += p.ds.norm();
            None
        } else {
            Some(updated.into_iter().map(|(_, w)| w).collect())
        };
        self.s0 = *s;
        self.n0 = *n;
        self.a0_sq = p.a2;
        self.phi0 = p.phi;
        let spent = self.path
            + (p.phi - self.phi_r).abs() * self.a_r_sq
            + p.phi * (p.a2 - self.a_r_sq).abs();
        let budget = FRAME_STEPS * change;
        match fresh {
            Some(actual) => self.rebuild(&p, budget, actual),
            None if self.sum_c == 0.0 || 2.0 * spent > self.budget => {
                let inside = ((p.a2 / self.dz).ceil() as usize).min(self.w.len());
                let actual = (0..inside).map(|i| self.committed(i)).collect();
                self.rebuild(&p, budget, actual);
            }
            None => {}
        }
    }

    /// Sets the springs in contact to `actual` (from the centre outwards; the rest
    /// unstrained) and puts every one whose slack exceeds `budget` (and whose cell
    /// above is in contact) into a new frame.
    fn rebuild(&mut self, p: &Probe, budget: f64, actual: Vec<Vector3<f64>>) {
        self.unstrain();
        self.budget = budget;
        self.phi_r = p.phi;
        self.a_r_sq = p.a2;
        for (i, w) in actual.into_iter().enumerate() {
            let z = i as f64 * self.dz;
            self.w[i] = w;
            let slack = p.phi * (p.a2 - z) - w.norm();
            if budget > 0.0 && z + self.dz <= p.a2 && slack > budget {
                self.in_frame[i] = true;
                let c = self.full_weight(i);
                self.sum_u += w * c;
                self.sum_c += c;
                self.frame_top = self.frame_top.max(z + self.dz);
            } else {
                self.explicit.push(i);
            }
        }
    }

    /// The elastic energy stored in the committed bed (J):
    /// `½ k' ∫ |w|² z^{−1/2} dz` (the nodal values of `|w|²` interpolated as `w`).
    pub(super) fn stored_energy(&self, a: f64) -> f64 {
        let a2 = a * a;
        let inside = ((a2 / self.dz).ceil() as usize).min(self.w.len());
        let sum: f64 = (0..inside)
            .map(|i| self.committed(i).norm_squared() * self.weight(i, a2))
            .sum();
        0.5 * self.k_line * sum
    }
}
