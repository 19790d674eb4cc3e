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
//! state is committed at the step's end.

use nalgebra::Vector3;

/// The default number of nodes of the spring bed in `z = x²` per `a_ref²`, the
/// square of the contact-radius scale of the impact (the grid grows with the same
/// spacing where the contact outgrows it). The error of the stick zone's profile
/// falls as `1/nodes²`: for steel on steel (Maw, Barber & Fawcett's case) the
/// tangential restitution at 1024 nodes is within 2e-5 of its limit
/// (`tests/micro_slip.rs` measures it).
pub const MICRO_SLIP_NODES: usize = 1024;

/// The MDR spring bed of a contact under Mindlin-Deresiewicz micro-slip.
#[derive(Clone, Debug)]
pub(super) struct MicroSlipBed {
    /// k' = k_t/2 (N/m²): tangential stiffness per unit length of the bed.
    k_line: f64,
    /// Node spacing in z = x² (m²).
    dz: f64,
    /// Elastic displacements at the nodes `z_i = i dz` (committed).
    w: Vec<Vector3<f64>>,
    /// Per cell `[z_i, z_{i+1}]`: the weights of `w_i` and `w_{i+1}` in
    /// `∫ w z^{−1/2} dz` for `w` linear in z.
    left: Vec<f64>,
    right: Vec<f64>,
    /// The tangential displacement `s` at the last commit.
    s0: Vector3<f64>,
    /// The normal at the last commit (the committed `w` lie in its tangent plane).
    n0: Vector3<f64>,
    /// The squared contact radius at the last commit (m²).
    a0_sq: f64,
}

/// `√q − √p` without cancellation.
fn root_difference(p: f64, q: f64) -> f64 {
    (q - p) / (q.sqrt() + p.sqrt())
}

impl MicroSlipBed {
    /// An unstrained bed of stiffness `k_t` (N/m² per unit radius: the no-slip
    /// stiffness is `k_t a`) with nodes spaced `a_ref²/nodes` in z.
    pub(super) fn new(k_t: f64, a_ref: f64, nodes: usize) -> Self {
        let mut bed = MicroSlipBed {
            k_line: 0.5 * k_t,
            dz: a_ref * a_ref / nodes as f64,
            w: Vec::new(),
            left: Vec::new(),
            right: Vec::new(),
            s0: Vector3::zeros(),
            n0: -Vector3::x(),
            a0_sq: 0.0,
        };
        bed.grow(nodes + 1);
        bed
    }

    /// Extends the grid to at least `nodes` nodes.
    fn grow(&mut self, nodes: usize) {
        while self.w.len() < nodes {
            let i = self.w.len();
            self.w.push(Vector3::zeros());
            if i > 0 {
                let (p, q) = ((i - 1) as f64 * self.dz, i as f64 * self.dz);
                let (rp, rq) = (p.sqrt(), q.sqrt());
                let d = root_difference(p, q);
                // ∫(z − p) z^{−1/2} dz / dz and ∫(q − z) z^{−1/2} dz / dz
                let up = 2.0 / 3.0 * d * d * (rq + 2.0 * rp) / self.dz;
                let down = 2.0 / 3.0 * d * d * (2.0 * rq + rp) / self.dz;
                self.left.push(down);
                self.right.push(up);
            }
        }
    }

    /// Resets the bed at contact onset (contact radius `a`): no spring strained,
    /// `s` and `n` the reference.
    pub(super) fn reset(&mut self, s: &Vector3<f64>, n: &Vector3<f64>, a: f64) {
        self.w.iter_mut().for_each(|w| *w = Vector3::zeros());
        self.s0 = *s;
        self.n0 = *n;
        self.a0_sq = a * a;
    }

    /// The slip displacement per unit of `a² − z` at contact radius `a` (m) and
    /// Coulomb limit `limit = μ F_n0` (N): `W(z) = φ (a² − z)`.
    fn slope(&self, a: f64, limit: f64) -> f64 {
        0.75 * limit / (a * a * a * self.k_line)
    }

    /// Calls `visit(i, w_i)` with the returned-mapped displacement of every node
    /// in contact (`z_i < a²`) at tangential displacement `s`, normal `n`, contact
    /// radius `a` and limit `limit`; returns the number of nodes in contact.
    fn map<F: FnMut(usize, Vector3<f64>)>(
        &self,
        n: &Vector3<f64>,
        s: &Vector3<f64>,
        a: f64,
        limit: f64,
        mut visit: F,
    ) -> usize {
        if a <= 0.0 || limit.is_nan() || limit <= 0.0 {
            return 0;
        }
        let a2 = a * a;
        let inside = ((a2 / self.dz).ceil() as usize).min(self.w.len());
        let phi = self.slope(a, limit);
        let turned = (n - self.n0).norm_squared() > 0.0;
        // the increment in the current tangent plane (s0 lies in the plane of
        // the last commit: the difference has a normal part of order |s| |Δn|,
        // which would otherwise act on the normal motion)
        let mut ds = s - self.s0;
        if turned {
            ds -= n * n.dot(&ds);
        }
        for i in 0..inside {
            let z = i as f64 * self.dz;
            if z >= a2 {
                break;
            }
            let mut w = self.w[i];
            if turned {
                // into the current tangent plane, keeping the length (as ξ)
                let len = w.norm();
                w -= n * n.dot(&w);
                let l2 = w.norm();
                if l2 > 0.0 {
                    w *= len / l2;
                }
            }
            // a spring the contact reached during the step entered unstrained
            // where a² (linear along the path) passed its z: it carries the
            // part of Δs after that point
            let mut trial = if z >= self.a0_sq && a2 > self.a0_sq {
                w + ds * ((a2 - z) / (a2 - self.a0_sq))
            } else {
                w + ds
            };
            let cap = phi * (a2 - z);
            let size2 = trial.norm_squared();
            if size2 > cap * cap {
                trial *= cap / size2.sqrt();
            }
            visit(i, trial);
        }
        inside
    }

    /// The force of the bed on body i (N) at the state given (not committed):
    /// `−k' ∫₀^{a²} w z^{−1/2} dz`, exact for `w` linear in z between nodes and 0
    /// at the edge.
    pub(super) fn force(
        &self,
        n: &Vector3<f64>,
        s: &Vector3<f64>,
        a: f64,
        limit: f64,
    ) -> Vector3<f64> {
        let a2 = a * a;
        let mut sum = Vector3::zeros();
        let mut last = (0, Vector3::zeros());
        let count = self.map(n, s, a, limit, |i, w| {
            // the full cell below node i
            if i > 0 {
                sum += last.1 * self.left[i - 1] + w * self.right[i - 1];
            }
            last = (i, w);
        });
        if count == 0 {
            return Vector3::zeros();
        }
        // the edge cell [z_j, a²] with w(a²) = 0
        let p = last.0 as f64 * self.dz;
        let (rp, re) = (p.sqrt(), a);
        let d = root_difference(p, a2);
        sum += last.1 * (2.0 / 3.0 * d * (2.0 * re + rp) / (re + rp));
        -sum * self.k_line
    }

    /// Commits the state at (n, s, a, limit): the return map becomes the bed's
    /// displacements; springs out of contact are unstrained.
    pub(super) fn commit(&mut self, n: &Vector3<f64>, s: &Vector3<f64>, a: f64, limit: f64) {
        // room for the contact to double its area within the next step
        let needed = 2 * (a * a / self.dz).ceil() as usize + 8;
        if needed > self.w.len() {
            self.grow(needed);
        }
        let mut fresh = vec![Vector3::zeros(); self.w.len()];
        self.map(n, s, a, limit, |i, w| fresh[i] = w);
        self.w = fresh;
        self.s0 = *s;
        self.n0 = *n;
        self.a0_sq = if a > 0.0 { a * a } else { 0.0 };
    }

    /// The elastic energy stored in the committed bed (J):
    /// `½ k' ∫ |w|² z^{−1/2} dz` (the nodal values of `|w|²` interpolated as `w`).
    pub(super) fn stored_energy(&self, a: f64) -> f64 {
        let a2 = a * a;
        let mut sum = 0.0;
        let mut last = (0usize, 0.0, false);
        for i in 0..self.w.len() {
            let z = i as f64 * self.dz;
            if z >= a2 {
                break;
            }
            let e = self.w[i].norm_squared();
            if i > 0 {
                sum += last.1 * self.left[i - 1] + e * self.right[i - 1];
            }
            last = (i, e, true);
        }
        if last.2 {
            let p = last.0 as f64 * self.dz;
            let d = root_difference(p, a2);
            sum += last.1 * (2.0 / 3.0 * d * (2.0 * a + p.sqrt()) / (a + p.sqrt()));
        }
        0.5 * self.k_line * sum
    }
}
