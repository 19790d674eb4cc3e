//! The commit of the planar spring bed: the return map of a step (or of the
//! straight pieces of its path) becomes the profile; the frame, the accumulated
//! integral and the slack that let an evaluation skip the stuck breakpoints are
//! kept up to date; and the test of whether a step's state depends on its path.

use super::{clip, piece_integral, piece_integral_r, LineBed, LineProbe, Regime};
use crate::oblique::limits::FRAME_STEPS;
use nalgebra::Vector3;

/// The return map of a profile's tail `tail` (breakpoints `(z, w)` from a stuck
/// one to the edge, where `w = 0`) by the increment `d` at squared radius and
/// slope `(a², φ)`, into `out`: points with the regime of the sub-interval
/// ending at them, the first the tail's first; a point between two runs on one
/// cap is dropped (the cap is one line). The committed pieces are cut where the
/// contact shrank below them; the springs it reached carry `d` after a² passed
/// them.
fn map_tail(tail: &[(f64, f64)], d: f64, (a2, phi): (f64, f64), out: &mut Vec<(f64, f64, Regime)>) {
    out.clear();
    let cap = |z: f64| phi * (a2 - z);
    let (z0, w0) = tail[0];
    let c0 = cap(z0);
    out.push((z0, (w0 + d).clamp(-c0, c0), Regime::Free));
    let mut emit = |_: f64, z1: f64, _: f64, f1: f64, regime: Regime| {
        if out.len() > 1 && regime != Regime::Free && out.last().is_some_and(|l| l.2 == regime) {
            out.pop();
        }
        out.push((z1, f1, regime));
    };
    for piece in tail.windows(2) {
        let ((zp, vp), (zq, mut vq)) = (piece[0], piece[1]);
        if zp >= a2 {
            break;
        }
        let q = if zq > a2 {
            vq = vp + (vq - vp) * (a2 - zp) / (zq - zp);
            a2
        } else {
            zq
        };
        clip(zp, q, (vp + d, vq + d), (cap(zp), cap(q)), &mut emit);
    }
    let edge = tail[tail.len() - 1].0;
    if a2 > edge {
        clip(edge, a2, (d, 0.0), (phi * (a2 - edge), 0.0), &mut emit);
    }
}

impl LineBed {
    /// Recomputes the accumulated integral from the frame's last breakpoint on.
    fn accumulate(&mut self) {
        let from = self.frame.saturating_sub(1);
        self.acc_from = from;
        self.acc.resize(self.z.len(), 0.0);
        self.acc[from] = 0.0;
        self.accumulate_from(from, 0.0);
    }

    /// The accumulated integral and slack after a commit that translated the
    /// committed profile up to breakpoint `upto` (at least `acc_from`) by
    /// `shift`: there the integral from `z[acc_from]` gains
    /// `shift · 2(√z_k − √z[acc_from])` (`∫ z^{−1/2} dz`); beyond, it is summed
    /// piece by piece. The slack (limit less displacement: the limits changed)
    /// is taken again throughout.
    fn accumulate_from(&mut self, upto: usize, shift: f64) {
        let from = self.acc_from;
        self.acc.resize(self.z.len(), 0.0);
        if shift != 0.0 {
            for k in from + 1..=upto {
                self.acc[k] += shift * 2.0 * (self.root[k] - self.root[from]);
            }
        }
        self.slack.resize(self.z.len(), f64::NEG_INFINITY);
        let mut least = f64::INFINITY;
        for k in from..self.z.len() {
            let slack = self.phi0 * (self.a0_sq - self.z[k]) - self.value(k).abs();
            least = least.min(slack);
            self.slack[k] = least;
        }
        for k in upto..self.z.len() - 1 {
            let piece = piece_integral_r(
                self.z[k],
                self.z[k + 1],
                self.root[k],
                self.root[k + 1],
                self.value(k),
                self.value(k + 1),
            );
            self.acc[k + 1] = self.acc[k] + piece;
        }
    }

    /// Whether the return map to the probe depends on the path of the step, not
    /// only on its ends: where springs stop slipping or enter the contact stuck
    /// within it. A spring that is within its limit at both ends of the step was
    /// stuck along it (the straight path's trial and limit are linear in its
    /// parameter), and one that ends on its cap sits there whatever the path;
    /// but one that was on its cap at the start (or entered during the step) and
    /// ends within it froze at a moment and a value the path decides, which the
    /// straight path of the return map puts wrong by the path's deviation from
    /// it (second order in the step). The entering springs' trial
    /// `Δs (a² − z)/(a² − a₀²)` and limit `φ(a² − z)` are in a fixed ratio: all
    /// within it, or all on it.
    pub(in crate::oblique) fn path_dependent(&self, p: &LineProbe) -> bool {
        let edge = self.z[self.z.len() - 1];
        if p.a2 > edge && p.d.abs() < p.phi * (p.a2 - edge) {
            return true;
        }
        // a committed piece on its cap (both ends, one side; the edge, where the
        // cap is 0, on either) that leaves it
        let on_cap = |k: usize| {
            let cap = self.phi0 * (self.a0_sq - self.z[k]);
            let v = self.value(k);
            match cap > 0.0 {
                true => (v.abs() >= cap * (1.0 - 1e-12)).then_some(v.signum()),
                false => Some(0.0),
            }
        };
        // none before the first breakpoint whose committed slack (a prefix
        // minimum from the frame's last one, the frame's all positive) is within
        // the on-cap margin of the largest limit: visited from there
        let margin = 1e-12 * self.phi0 * self.a0_sq;
        let from = self.acc_from;
        let first = from + self.slack[from..].partition_point(|&s| s > margin);
        let first = first.min(self.z.len() - 1);
        let mut side = on_cap(first);
        for k in first + 1..self.z.len() {
            let here = on_cap(k);
            if let (Some(b0), Some(b1)) = (side, here) {
                let a = if b0 != 0.0 { b0 } else { b1 };
                if a != 0.0 && (b0 == b1 || b0 == 0.0 || b1 == 0.0) && self.z[k - 1] < p.a2 {
                    let leaves = |j: usize| {
                        let z = self.z[j].min(p.a2);
                        a * (self.value(j) + p.d) < p.phi * (p.a2 - z)
                    };
                    if leaves(k - 1) || leaves(k) {
                        return true;
                    }
                }
            }
            side = here;
        }
        false
    }

    /// Whether any spring may be strained (else every direction is the bed's:
    /// a probe takes the increment's).
    pub(in crate::oblique) fn is_strained(&self) -> bool {
        self.strained
    }

    /// Commits the probe's state (n, s the probe's): the return map becomes the
    /// profile (slipping runs merged into one piece), the frame moves or is
    /// rebuilt.
    pub(in crate::oblique) fn commit(&mut self, p: &LineProbe, n: &Vector3<f64>, s: &Vector3<f64>) {
        self.commit_along(&[(*p, *n, *s)]);
    }

    /// Commits the states of `path` in turn (each probe's `(n, s)` given, every
    /// increment measured from the committed state, the last one the step's
    /// end): the return map along the straight pieces between them, the bed's
    /// bookkeeping once. The leading breakpoints within their limits at every
    /// probe by the committed slack ([`LineBed::untested`]) were stuck along
    /// the whole path (trial and limit are linear along each piece): they
    /// translate by the last increment; only the tail beyond them is mapped
    /// piece by piece. For more than one probe the bed must be strained
    /// ([`LineBed::is_strained`]): an unstrained one takes its direction from
    /// each increment, so its probes hold only one at a time.
    pub(in crate::oblique) fn commit_along(
        &mut self,
        path: &[(LineProbe, Vector3<f64>, Vector3<f64>)],
    ) {
        let Some(&(p, n, s)) = path.last() else {
            return;
        };
        // the frame holds along the whole path (its path length the pieces')
        let mut travelled = self.path;
        let mut holds = self.frame >= 2;
        let mut before = 0.0;
        for (q, _, _) in path {
            travelled += (q.d - before).abs();
            before = q.d;
            let limits =
                (q.phi - self.phi_r).abs() * self.a_r_sq + q.phi * (q.a2 - self.a_r_sq).abs();
            holds = holds && self.z[self.frame - 1] <= q.a2 && travelled + limits <= self.budget;
        }
        if !holds {
            self.flatten();
        }
        let start = if holds { self.frame - 1 } else { 0 };
        // the leading pieces within their limits by the committed slack keep
        // their breakpoints, translated: the map starts at the last of them
        let begin = match start == self.acc_from {
            true => path
                .iter()
                .map(|(q, _, _)| self.untested(start, q))
                .min()
                .unwrap_or(start),
            false => start,
        };
        // the new profile beyond `begin`, mapped along the pieces
        let mut points = std::mem::take(&mut self.scratch);
        let mut tail = std::mem::take(&mut self.tail);
        tail.clear();
        tail.extend((begin..self.z.len()).map(|k| (self.z[k], self.value(k))));
        let mut before = 0.0;
        for (k, (q, _, _)) in path.iter().enumerate() {
            map_tail(&tail, q.d - before, (q.a2, q.phi), &mut points);
            before = q.d;
            if k + 1 < path.len() {
                tail.clear();
                tail.extend(points.iter().map(|&(z, f, _)| (z, f)));
            }
        }
        self.tail = tail;
        // the frame's last point moves with the frame (its value is not stored)
        let keep = if holds { start + 1 } else { start };
        // the accumulated integral up to `begin` only translates with the
        // profile where the frame holds and starts it
        let translated = (holds && begin > start && start == self.acc_from).then_some(begin);
        let (keep, skip) = if begin > start {
            // beyond the frame (`frame ≤ keep`), as the map would translate them
            for k in keep..=begin {
                self.u[k] = self.value(k) + p.d;
            }
            (begin + 1, 1)
        } else {
            (keep, if holds { 1 } else { 0 })
        };
        self.z.truncate(keep);
        self.root.truncate(keep);
        self.u.truncate(keep);
        for &(z, f, _) in &points[skip..] {
            self.z.push(z);
            self.root.push(z.sqrt());
            self.u.push(f);
        }
        self.scratch = points;
        let limits = (p.phi - self.phi0).abs() * self.a0_sq + p.phi * (p.a2 - self.a0_sq).abs();
        let change = p.d.abs() + limits;
        if holds {
            self.sigma += p.d;
            self.path = travelled;
        }
        self.strained |= path.iter().any(|(q, _, _)| q.d != 0.0);
        let e = p.e - n * n.dot(&p.e);
        let length = e.norm();
        // unit in the tangent plane (the probe's direction lies in it to rounding)
        if length > 0.5 {
            self.e = e / length;
        }
        self.s0 = s;
        self.s0_norm = s.norm();
        self.n0 = n;
        self.a0_sq = p.a2;
        self.phi0 = p.phi;
        let spent = self.path
            + (p.phi - self.phi_r).abs() * self.a_r_sq
            + p.phi * (p.a2 - self.a_r_sq).abs();
        match translated {
            Some(upto) if 2.0 * spent <= self.budget => self.accumulate_from(upto, p.d),
            _ => {
                if !holds || 2.0 * spent > self.budget {
                    self.rebuild(&p, FRAME_STEPS * change);
                }
                self.accumulate();
            }
        }
    }

    /// The frame's shift moved into its values; no frame.
    fn flatten(&mut self) {
        for k in 0..self.frame {
            self.u[k] += self.sigma;
        }
        self.clear_frame();
    }

    /// A new frame of the leading breakpoints whose slack exceeds `budget`.
    fn rebuild(&mut self, p: &LineProbe, budget: f64) {
        self.flatten();
        self.budget = budget;
        self.phi_r = p.phi;
        self.a_r_sq = p.a2;
        if budget <= 0.0 {
            return;
        }
        let count = self
            .z
            .iter()
            .zip(&self.u)
            .take_while(|&(&z, &u)| p.phi * (p.a2 - z) - u.abs() > budget)
            .count();
        if count < 2 {
            return;
        }
        self.frame = count;
        self.frame_sum = (0..count - 1)
            .map(|k| piece_integral(self.z[k], self.z[k + 1], self.u[k], self.u[k + 1]))
            .sum();
    }
}
