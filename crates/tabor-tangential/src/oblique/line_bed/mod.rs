//! The spring bed of a planar history, kept exactly: its profile as breakpoints.
//!
//! Where every spring's displacement and every increment of `s` lie on one line of
//! the tangent plane (turned with the normal), the bed is a scalar field `w(z)`
//! (`z = x²`) along a unit vector `e`. The return map of [`super::node_bed`] is
//! then, spring by spring, `w ← clamp(w + Δs, −φ(a² − z), φ(a² − z))`, with the
//! springs the contact reached during the step entering at `Δs (a² − z)/(a² − a₀²)`.
//! The cap `φ(a² − z)` and the entry profile are linear in z, so a profile that is
//! piecewise linear in z stays piecewise linear: a piece is cut where its trial
//! value crosses a cap (at most twice), the part beyond the cap is the cap (a
//! line), the rest translates. The bed keeps the breakpoints `(z_k, w_k)` from the
//! centre `z = 0` to the edge `a₀²` (where `w = 0`), and the force
//! `−k' ∫ w z^{−1/2} dz` is integrated in closed form piece by piece. This is the
//! node bed's own update without its spacing: exact for the straight path within a
//! step (the same path the node bed takes), and no discretization in z at all.
//!
//! Slipping runs lie on one cap line: their interior breakpoints are dropped, so a
//! slipping annulus is one piece. A stick zone keeps the breakpoints its entry left
//! (one per step of a growing contact that sticks at its edge).
//!
//! **The frame.** The leading breakpoints (from the centre) whose slack (limit less
//! displacement) exceeds [`super::limits::FRAME_STEPS`] steps' change translate
//! rigidly: they are kept as `u_k + σ` with one shift `σ`, and their pieces'
//! integral `∫ u z^{−1/2} dz` once; an evaluation visits only the pieces beyond.
//! The bound is that of the node bed's frame (checked at every evaluation; the
//! frame is flattened and rebuilt where it fails or half its budget is spent).

use nalgebra::Vector3;

mod commit;

#[cfg(test)]
thread_local! {
    /// Tests: `.0` makes every piece tested ([`LineBed::untested`] skips none),
    /// the reference; `.1` counts the calls that skipped some.
    pub(super) static UNTESTED: std::cell::Cell<(bool, usize)> =
        const { std::cell::Cell::new((false, 0)) };
}

/// `∫_p^q f z^{−1/2} dz` for `f` linear in z with `f(p) = fp`, `f(q) = fq`
/// (with `z = r²`: `2 ∫ f(r²) dr`, in a form without cancellation).
pub(super) fn piece_integral(p: f64, q: f64, fp: f64, fq: f64) -> f64 {
    piece_integral_r(p, q, p.sqrt(), q.sqrt(), fp, fq)
}

/// [`piece_integral`] with the roots `rp = √p`, `rq = √q` given.
fn piece_integral_r(p: f64, q: f64, rp: f64, rq: f64, fp: f64, fq: f64) -> f64 {
    let sum = rp + rq;
    if sum == 0.0 {
        return 0.0;
    }
    let d = (q - p) / sum;
    2.0 * d / (3.0 * sum) * (fp * (2.0 * rq + rp) + fq * (rq + 2.0 * rp))
}

/// `∫_p^q f² z^{−1/2} dz` for `f` linear in z: `2 ∫ f(r²)² dr`, a polynomial of
/// degree 4 in r, which three-point Gauss-Legendre in r integrates exactly.
fn piece_square_integral(p: f64, q: f64, fp: f64, fq: f64) -> f64 {
    if q <= p {
        return 0.0;
    }
    let (rp, rq) = (p.sqrt(), q.sqrt());
    let (mid, half) = (0.5 * (rq + rp), 0.5 * (rq - rp));
    let x = 0.6f64.sqrt();
    let sum: f64 = [(-x, 5.0 / 9.0), (0.0, 8.0 / 9.0), (x, 5.0 / 9.0)]
        .iter()
        .map(|&(xi, wi)| {
            let r = mid + half * xi;
            let f = fp + (fq - fp) * (r * r - p) / (q - p);
            wi * f * f
        })
        .sum();
    2.0 * half * sum
}

/// `v` turned by the rotation taking the unit vector `from` to `to` about their
/// common normal (Rodrigues, as [`super::node_bed::rotation`]; `v` where they are
/// equal or opposite).
fn turned(from: &Vector3<f64>, to: &Vector3<f64>, v: &Vector3<f64>) -> Vector3<f64> {
    let c = from.dot(to);
    if from == to || c <= -1.0 + 1e-12 {
        return *v;
    }
    let k = from.cross(to);
    let kv = k.cross(v);
    v + kv + k.cross(&kv) / (1.0 + c)
}

/// Where a sub-interval of a clipped piece lies: within the limits, or on the
/// upper or lower cap.
#[derive(Clone, Copy, PartialEq, Debug)]
enum Regime {
    Free,
    Upper,
    Lower,
}

/// `clamp(t, −c, c)` on `[p, q]` for `t`, `c` linear (`t(p) = tp`, …, `c ≥ 0`):
/// calls `emit(z0, z1, f0, f1, regime)` for each sub-interval, in order, on which
/// the clamped value is linear (at most three: the trial crosses each cap once).
fn clip<F: FnMut(f64, f64, f64, f64, Regime)>(
    p: f64,
    q: f64,
    (tp, tq): (f64, f64),
    (cp, cq): (f64, f64),
    mut emit: F,
) {
    let (gp, gq) = (tp - cp, tq - cq);
    let (hp, hq) = (tp + cp, tq + cq);
    if gp <= 0.0 && gq <= 0.0 && hp >= 0.0 && hq >= 0.0 {
        emit(p, q, tp, tq, Regime::Free);
        return;
    }
    let at = |z: f64| {
        let l = if q > p { (z - p) / (q - p) } else { 0.0 };
        (tp + (tq - tp) * l, cp + (cq - cp) * l)
    };
    let value = |z: f64| {
        let (t, c) = at(z);
        t.clamp(-c, c)
    };
    let regime = |z0: f64, z1: f64| {
        let (t, c) = at(0.5 * (z0 + z1));
        if t > c {
            Regime::Upper
        } else if t < -c {
            Regime::Lower
        } else {
            Regime::Free
        }
    };
    if (gp > 0.0 && gq > 0.0) || (hp < 0.0 && hq < 0.0) {
        // beyond one cap at both ends: no cut (what the search below finds)
        emit(p, q, value(p), value(q), regime(p, q));
        return;
    }
    let mut cuts = [p, q, q, q];
    let mut n = 1;
    for (a, b) in [(gp, gq), (hp, hq)] {
        if (a > 0.0) != (b > 0.0) && a != b {
            let z = p + (q - p) * (a / (a - b));
            if z > p && z < q {
                cuts[n] = z;
                n += 1;
            }
        }
    }
    cuts[n] = q;
    // at most two cuts, both in (p, q): in order by one exchange
    if n == 3 && cuts[2] < cuts[1] {
        cuts.swap(1, 2);
    }
    for j in 0..n {
        let (z0, z1) = (cuts[j], cuts[j + 1]);
        if z1 <= z0 && n > 1 {
            continue;
        }
        emit(z0, z1, value(z0), value(z1), regime(z0, z1));
    }
}

/// What an evaluation of a planar bed needs of the state given: the direction
/// `e` turned into the current tangent plane, the increment along it, a², φ.
#[derive(Clone, Copy, Debug)]
pub(super) struct LineProbe {
    e: Vector3<f64>,
    d: f64,
    a2: f64,
    phi: f64,
}

/// The spring bed of a planar history as breakpoints (see the module doc).
#[derive(Clone, Debug)]
pub(super) struct LineBed {
    /// Breakpoints in z (m²), from 0 to the committed a₀², and their roots √z.
    z: Vec<f64>,
    root: Vec<f64>,
    /// The displacement at each breakpoint along `e` (m): `u_k + sigma` for the
    /// first `frame` breakpoints, `u_k` beyond.
    u: Vec<f64>,
    /// From breakpoint `acc_from` (the frame's last, or 0) on, `acc[k]` is
    /// `∫ w z^{−1/2} dz` of the committed profile from `z[acc_from]` to `z[k]`:
    /// a run of pieces that stick at the probe costs one difference.
    acc: Vec<f64>,
    acc_from: usize,
    /// From breakpoint `acc_from` on, `slack[k]` is the least committed slack
    /// (limit less |displacement|) of the breakpoints from `acc_from` to k: the
    /// pieces up to the last whose slack exceeds a probe's change bound are
    /// within their limits there, untested.
    slack: Vec<f64>,
    /// The commit's new points (kept to spare an allocation per step).
    scratch: Vec<(f64, f64, Regime)>,
    /// The profile's mapped tail between the pieces of a commit along a path
    /// (kept to spare an allocation per step).
    tail: Vec<(f64, f64)>,
    /// The committed direction (unit, in the committed tangent plane).
    e: Vector3<f64>,
    /// Whether any spring may be strained (else every direction is the bed's).
    strained: bool,
    /// The frame: its breakpoint count, shift, `∫ u z^{−1/2} dz` over its pieces,
    /// slack budget, path of `s` since the rebuild, and slope and squared radius
    /// at the rebuild.
    frame: usize,
    sigma: f64,
    frame_sum: f64,
    budget: f64,
    path: f64,
    phi_r: f64,
    a_r_sq: f64,
    /// `s`, the normal, a² and φ at the last commit.
    s0: Vector3<f64>,
    s0_norm: f64,
    n0: Vector3<f64>,
    a0_sq: f64,
    phi0: f64,
}

impl LineBed {
    /// An unstrained bed.
    pub(super) fn new() -> Self {
        LineBed {
            z: vec![0.0],
            root: vec![0.0],
            u: vec![0.0],
            acc: vec![0.0],
            acc_from: 0,
            slack: vec![f64::NEG_INFINITY],
            scratch: Vec::new(),
            tail: Vec::new(),
            e: Vector3::y(),
            strained: false,
            frame: 0,
            sigma: 0.0,
            frame_sum: 0.0,
            budget: 0.0,
            path: 0.0,
            phi_r: 0.0,
            a_r_sq: 0.0,
            s0: Vector3::zeros(),
            s0_norm: 0.0,
            n0: -Vector3::x(),
            a0_sq: 0.0,
            phi0: 0.0,
        }
    }

    /// Resets the bed at contact onset (contact radius `a`): no spring strained.
    pub(super) fn reset(&mut self, s: &Vector3<f64>, n: &Vector3<f64>, a: f64) {
        let a2 = a * a;
        self.z = if a2 > 0.0 { vec![0.0, a2] } else { vec![0.0] };
        self.root = self.z.iter().map(|z| z.sqrt()).collect();
        self.u = vec![0.0; self.z.len()];
        self.acc = vec![0.0; self.z.len()];
        self.acc_from = 0;
        self.slack = vec![f64::NEG_INFINITY; self.z.len()];
        self.strained = false;
        // a unit direction in the new tangent plane (the old one, or an axis,
        // projected): the default of an unstrained bed
        self.e = [self.e, Vector3::y(), Vector3::z()]
            .into_iter()
            .map(|v| v - n * n.dot(&v))
            .find(|v| v.norm() > 0.5)
            .map_or(self.e, |v| v.normalize());
        self.clear_frame();
        self.s0 = *s;
        self.s0_norm = s.norm();
        self.n0 = *n;
        self.a0_sq = a2;
        self.phi0 = 0.0;
    }

    fn clear_frame(&mut self) {
        self.frame = 0;
        self.sigma = 0.0;
        self.frame_sum = 0.0;
        self.budget = 0.0;
        self.path = 0.0;
    }

    /// The committed displacement at breakpoint k (along `e`).
    fn value(&self, k: usize) -> f64 {
        if k < self.frame {
            self.u[k] + self.sigma
        } else {
            self.u[k]
        }
    }

    /// The committed `(s₀, n₀, a₀², φ₀)`, for a node bed taking the state over.
    pub(super) fn committed(&self) -> (Vector3<f64>, Vector3<f64>, f64, f64) {
        (self.s0, self.n0, self.a0_sq, self.phi0)
    }

    /// The committed displacements at the increasing points `zs` (0 beyond the
    /// edge), linear between breakpoints.
    pub(super) fn sample(&self, zs: impl Iterator<Item = f64>) -> Vec<Vector3<f64>> {
        let mut k = 0;
        let last = self.z.len() - 1;
        zs.map(|z| {
            if z >= self.z[last] {
                return Vector3::zeros();
            }
            while k + 1 < last && self.z[k + 1] <= z {
                k += 1;
            }
            let (p, q) = (self.z[k], self.z[k + 1]);
            let l = (z - p) / (q - p);
            self.e * (self.value(k) + (self.value(k + 1) - self.value(k)) * l)
        })
        .collect()
    }

    /// The probe at (n, s, a², φ), `None` where the increment leaves the line of
    /// the bed (a non-planar history: the caller takes the node bed).
    pub(super) fn probe(
        &self,
        n: &Vector3<f64>,
        s: &Vector3<f64>,
        a2: f64,
        phi: f64,
    ) -> Option<LineProbe> {
        let mut ds = s - self.s0;
        ds -= n * n.dot(&ds);
        let size = ds.norm();
        // the committed direction turned with the normal: unit and in the new
        // tangent plane to rounding (it is renormalized at the commit). An
        // unstrained bed takes the direction of the increment, where it is more
        // than rounding: an increment of 1e-13 of the displacements and the cap
        // (a normal component of s rounded into the tangent plane, as where two
        // spheres' contact points move together) has no direction of its own.
        let e = if self.strained {
            turned(&self.n0, n, &self.e)
        } else if size > 1e-13 * (s.norm() + self.s0_norm + phi * a2) {
            ds / size
        } else {
            turned(&self.n0, n, &self.e)
        };
        let d = ds.dot(&e);
        // rounding leaves ~1e-16 of |s| and |Δs| off the line of a planar history
        let off = (ds - e * d).norm();
        let scale = size + self.s0_norm + phi * a2;
        (off <= 1e-11 * scale).then_some(LineProbe { e, d, a2, phi })
    }

    /// Whether the frame holds at the probe (the node bed's bound).
    fn frame_holds(&self, p: &LineProbe) -> bool {
        if self.frame < 2 {
            return false;
        }
        let limits = (p.phi - self.phi_r).abs() * self.a_r_sq + p.phi * (p.a2 - self.a_r_sq).abs();
        self.z[self.frame - 1] <= p.a2 && self.path + p.d.abs() + limits <= self.budget
    }

    /// Calls `emit` for every clipped sub-interval of the return-mapped profile
    /// of the committed pieces from breakpoint `start` to `end` at the probe.
    fn map_range<F: FnMut(f64, f64, f64, f64, Regime)>(
        &self,
        start: usize,
        end: usize,
        p: &LineProbe,
        emit: &mut F,
    ) {
        let cap = |z: f64| p.phi * (p.a2 - z);
        for k in start..end {
            let (zp, zq) = (self.z[k], self.z[k + 1]);
            if zp >= p.a2 {
                break;
            }
            let (vp, mut vq) = (self.value(k), self.value(k + 1));
            let q = if zq > p.a2 {
                vq = vp + (vq - vp) * (p.a2 - zp) / (zq - zp);
                p.a2
            } else {
                zq
            };
            clip(zp, q, (vp + p.d, vq + p.d), (cap(zp), cap(q)), &mut *emit);
        }
    }

    /// [`LineBed::map_range`] for the springs the contact reached during the
    /// step: `Δs` after a² passed them.
    fn map_entry<F: FnMut(f64, f64, f64, f64, Regime)>(&self, p: &LineProbe, emit: &mut F) {
        let edge = self.z[self.z.len() - 1];
        if p.a2 > edge {
            clip(
                edge,
                p.a2,
                (p.d, 0.0),
                (p.phi * (p.a2 - edge), 0.0),
                &mut *emit,
            );
        }
    }

    /// `∫ w z^{−1/2} dz` of the return-mapped bed at the probe, along `p.e`.
    pub(super) fn integral(&self, p: &LineProbe) -> f64 {
        let mut runs = 0.0;
        let start = if self.frame_holds(p) {
            runs += self.frame_sum + (self.sigma + p.d) * 2.0 * self.root[self.frame - 1];
            self.frame - 1
        } else {
            0
        };
        let mut clipped = 0.0;
        let mut add = |z0, z1, f0, f1, _| clipped += piece_integral(z0, z1, f0, f1);
        // below the accumulated breakpoints (a frame that failed): piece by piece
        let from = self.acc_from.max(start);
        if start < from {
            self.map_range(start, from, p, &mut add);
        }
        // then runs of pieces within their limits from the accumulated integral,
        // the others clipped
        let last = self.z.len() - 1;
        let mut run = from;
        let mut k = self.untested(from, p);
        while k < last && self.z[k + 1] <= p.a2 {
            let (tp, tq) = (self.value(k) + p.d, self.value(k + 1) + p.d);
            let (cp, cq) = (p.phi * (p.a2 - self.z[k]), p.phi * (p.a2 - self.z[k + 1]));
            if tp.abs() > cp || tq.abs() > cq {
                runs += self.run_integral(run, k, p.d);
                self.map_range(k, k + 1, p, &mut add);
                run = k + 1;
            }
            k += 1;
        }
        runs += self.run_integral(run, k, p.d);
        // the piece the shrinking contact cuts, and the springs it reached
        if k < last {
            self.map_range(k, last, p, &mut add);
        }
        self.map_entry(p, &mut add);
        runs + clipped
    }

    /// The last breakpoint (at least `from`, itself at least `acc_from`) up to
    /// which every piece is within its limits at the probe, by the committed
    /// slack alone: at a breakpoint within both contacts `|w + d|` is at most
    /// `|w| + |d|` and the limit `φ(a² − z)` at least `φ₀(a₀² − z) − B` with
    /// `B = |φ − φ₀| a₀² + φ |a² − a₀²|` (the frame's bound), so a committed
    /// slack above `|d| + B` (with a margin of 1e-9 of the terms' size, far
    /// above their rounding) leaves the piece unclipped; the pieces the loop of
    /// [`LineBed::integral`] would test and pass.
    fn untested(&self, from: usize, p: &LineProbe) -> usize {
        #[cfg(test)]
        let (all, skipped) = UNTESTED.get();
        #[cfg(test)]
        if all {
            return from;
        }
        let bound =
            p.d.abs() + (p.phi - self.phi0).abs() * self.a0_sq + p.phi * (p.a2 - self.a0_sq).abs();
        let size = bound + p.d.abs() + p.phi * p.a2 + self.phi0 * self.a0_sq;
        let threshold = bound + 1e-9 * size;
        let count = self.slack[from..].partition_point(|&s| s > threshold);
        // every breakpoint lies within the committed contact
        let inside = if p.a2 >= self.a0_sq {
            self.z.len()
        } else {
            self.z.partition_point(|&z| z <= p.a2)
        };
        let last = (from + count).min(inside).saturating_sub(1).max(from);
        #[cfg(test)]
        UNTESTED.set((all, skipped + usize::from(last > from)));
        last
    }

    /// `∫ (w + d) z^{−1/2} dz` over the committed pieces from breakpoint `a` to
    /// `b` (both at least `acc_from`).
    fn run_integral(&self, a: usize, b: usize, d: f64) -> f64 {
        if b <= a {
            return 0.0;
        }
        self.acc[b] - self.acc[a] + d * 2.0 * (self.root[b] - self.root[a])
    }

    /// The direction of the force at the probe.
    pub(super) fn direction(p: &LineProbe) -> Vector3<f64> {
        p.e
    }

    /// `∫ |w|² z^{−1/2} dz` of the committed bed within squared radius `a2`.
    pub(super) fn square_integral(&self, a2: f64) -> f64 {
        let mut sum = 0.0;
        for k in 0..self.z.len() - 1 {
            let (zp, zq) = (self.z[k], self.z[k + 1]);
            if zp >= a2 {
                break;
            }
            let (vp, mut vq) = (self.value(k), self.value(k + 1));
            let q = if zq > a2 {
                vq = vp + (vq - vp) * (a2 - zp) / (zq - zp);
                a2
            } else {
                zq
            };
            sum += piece_square_integral(zp, q, vp, vq);
        }
        sum
    }
}
