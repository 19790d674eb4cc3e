//! The per-contact form of `tangential mindlin_deresiewicz` that a DEM engine
//! keeps ([`crate::Friction::step`], the LAMMPS plugin): a compact spring bed of
//! the method of dimensionality reduction, the same bed the oblique impact
//! integrates ([`crate::oblique`], 1024 nodes), with [`SPRINGS`] nodes in a
//! history of [`BED_LEN`] doubles.
//!
//! **The bed** (Popov & Heß 2015; module docs of `crate::oblique`'s bed): springs
//! of tangential stiffness `k' = k_t/2` per unit length at `−a ≤ x ≤ a`, each
//! with the Coulomb limit of its share of the normal load,
//! `q(x) = μ F_n0 · 3(a² − x²)/(4a³)` (exact for Hertz, Thornton & Yin's rule
//! for the adhesive laws: `F_n0 = F_n + 2 F_pull-off` spread over the law's own
//! contact radius). A spring's elastic displacement `w` (a vector in the tangent
//! plane) is capped at `φ (a² − z)`, `z = x²`, `φ = 3 μ F_n0/(4 a³ k')`; a spring
//! enters the contact unstrained where `a²` passes it and leaves it where `a²`
//! falls below it. The elastic tangential force is `T = k' ∫₀^{a²} w z^{−1/2} dz`
//! (the force on body `i` is `−T`).
//!
//! **The nodes.** `w` is kept at nodes uniform in `z`, `z_i = i Δz`, linear in
//! `z` between them and zero at the edge `z = a²`; the integral is exact for that
//! interpolation and a slipping zone (`w` on its cap, linear in `z`) is
//! represented exactly: the error is that of the stick zone's profile between
//! nodes and falls as `Δz²` (measured against the library's 1024-node bed in
//! `tests/micro_slip_step.rs`). The spacing follows the contact: set at onset
//! so that `a²` spans three quarters of the nodes; where the contact outgrows
//! the last node, every second node is dropped (`Δz` doubles); where it shrinks
//! below half of them, a node is put midway between every two (`Δz` halves: the
//! profile is unchanged, it is linear between nodes; a contact that hovers there
//! and is refined and coarsened in turn keeps its nodes, the midpoints dropped
//! are the ones refining added). So between half and all of the [`SPRINGS`]
//! nodes are in contact at every step after the first.
//!
//! **The step** (the return map of the library's bed): over a step with
//! tangential displacement `Δs`, every node in contact becomes `w + Δs`, a node
//! the growing contact reached during the step only the part of `Δs` after `a²`
//! (linear along the step) passed it, and is then projected onto the disc of its
//! cap (the radial return: exact along a straight path in one dimension; in the
//! plane its error in the direction of a turning slip vanishes with the step).
//! Each spring dissipates `cap · |slip|` ≥ 0 (tested: the work of the bed never
//! falls below its stored energy).
//!
//! **The frame.** The displacements are stored as components in an orthonormal
//! basis `(e₁, n × e₁)` of the tangent plane; each step `e₁` is projected into
//! the current tangent plane and normalized (to first order the rotation taking
//! the old normal to the new one, as LAMMPS turns its stored displacement).
//!
//! **Layout** of the [`BED_LEN`] doubles: `e₁` (3), `Δz` (m², 0 for a fresh
//! contact), `a²` of the last step (m²), then the two components of `w` (m) of
//! every node from the centre outwards.

use nalgebra::Vector3;
use std::sync::OnceLock;

/// The number of nodes of the per-contact spring bed. Chosen from the measured
/// error against the library's 1024-node bed (`tests/micro_slip_step.rs`):
/// the tangential restitution of Maw, Barber & Fawcett's impact within the
/// bound stated there, below the time-step error of a DEM step of `t_c/4000`.
pub const SPRINGS: usize = 32;

/// The doubles of the per-contact bed of [`SPRINGS`] nodes (module docs:
/// layout).
pub const BED_LEN: usize = bed_len(SPRINGS);

const HEAD: usize = 5;

/// The doubles of a bed of `springs` nodes: a header of 5, two per node.
pub const fn bed_len(springs: usize) -> usize {
    HEAD + 2 * springs
}

/// The nodes whose unit-spacing weights are tabulated (beds of up to this many
/// nodes read them from the table; larger ones compute them).
const TABLE: usize = 1024;

/// Per node `i` of a bed of unit spacing, its full weight in `∫ w z^{−1/2} dz`
/// (the cells `[i − 1, i]` and `[i, i + 1]`, [`cell`]); the weights scale with
/// `√Δz`.
fn table() -> &'static [f64] {
    static WEIGHTS: OnceLock<Vec<f64>> = OnceLock::new();
    WEIGHTS.get_or_init(|| (0..TABLE).map(full_weight).collect())
}

fn root(i: usize) -> f64 {
    (i as f64).sqrt()
}

fn full_weight(i: usize) -> f64 {
    let below = if i > 0 {
        cell(root(i - 1), root(i)).1
    } else {
        0.0
    };
    below + cell(root(i), root(i + 1)).0
}

/// The weight of the outermost node `i` in contact (unit spacing) with the edge
/// at `√(a²/Δz) = ra`: the cell below plus the edge cell `[i, ra²]`, where `w`
/// falls linearly to 0.
fn edge_weight(i: usize, ra: f64) -> f64 {
    let below = if i > 0 {
        cell(root(i - 1), root(i)).1
    } else {
        0.0
    };
    below + cell(root(i), ra).0
}

/// `∫_p^q (q − z)/(q − p) z^{−1/2} dz` and `∫_p^q (z − p)/(q − p) z^{−1/2} dz`
/// from `√p`, `√q`: the weights of the values at `p` and at `q` of a function
/// linear in `z` on `[p, q]`.
fn cell(rp: f64, rq: f64) -> (f64, f64) {
    let s = rq + rp;
    if s <= 0.0 {
        return (0.0, 0.0);
    }
    let f = 2.0 / 3.0 * (rq - rp) / s;
    (f * (2.0 * rq + rp), f * (rq + 2.0 * rp))
}

/// Zeroes the bed (no contact, or no limit).
pub fn wipe(bed: &mut [f64]) {
    bed.iter_mut().for_each(|x| *x = 0.0);
}

/// A unit vector in the plane normal to `n` (the direction of `hint` there if it
/// has one, else the axis least aligned with `n` projected).
fn basis(n: &Vector3<f64>, hint: &Vector3<f64>) -> Vector3<f64> {
    let p = hint - n * n.dot(hint);
    let size = p.norm();
    if size > 1e-6 * hint.norm() && size > 0.0 {
        return p / size;
    }
    let axis = if n.x.abs() <= n.y.abs() && n.x.abs() <= n.z.abs() {
        Vector3::x()
    } else if n.y.abs() <= n.z.abs() {
        Vector3::y()
    } else {
        Vector3::z()
    };
    let p = axis - n * n.dot(&axis);
    p / p.norm()
}

/// Doubles the spacing: node `i` takes the value of node `2i`.
fn coarsen(w: &mut [f64], nodes: usize) {
    for i in 0..nodes {
        let (u, v) = if 2 * i < nodes {
            (w[4 * i], w[4 * i + 1])
        } else {
            (0.0, 0.0)
        };
        w[2 * i] = u;
        w[2 * i + 1] = v;
    }
}

/// Halves the spacing: the piecewise-linear profile sampled at the midpoints too.
fn refine(w: &mut [f64], nodes: usize) {
    for i in (0..nodes).rev() {
        let j = i / 2;
        let (u, v) = if i % 2 == 0 {
            (w[2 * j], w[2 * j + 1])
        } else if j + 1 < nodes {
            (
                0.5 * (w[2 * j] + w[2 * j + 2]),
                0.5 * (w[2 * j + 1] + w[2 * j + 3]),
            )
        } else {
            (0.5 * w[2 * j], 0.5 * w[2 * j + 1])
        };
        w[2 * i] = u;
        w[2 * i + 1] = v;
    }
}

/// Advances the bed `bed` (`bed_len(N)` doubles for N ≥ 4 nodes, zero for a new
/// contact) by the step's tangential displacement `ds` (m; its part along `n` is
/// ignored) at the contact radius `a` (m) and Coulomb limit `limit = μ F_n0` (N)
/// at the step's end, with `k_line = k'`, the tangential stiffness per unit
/// length of the bed (`k_t/2`, Pa). Returns the elastic force `T` (N; the force on
/// body `i` is `−T`), `|T| ≤ limit`, and whether every spring slips (gross
/// sliding). A contact radius (or its square) or limit that is zero, negative or not finite
/// releases every spring (`T = 0`). Module docs.
pub fn advance(
    bed: &mut [f64],
    n: &Vector3<f64>,
    ds: &Vector3<f64>,
    k_line: f64,
    a: f64,
    limit: f64,
) -> (Vector3<f64>, bool) {
    let nodes = (bed.len() - HEAD) / 2;
    let ok = |x: f64| x.is_finite() && x > 0.0;
    // a² must be finite too: at a² = ∞ the spacing doubles to ∞ and never halves back
    if !(ok(a) && ok(a * a) && ok(limit) && ok(k_line)) || nodes < 4 {
        wipe(bed);
        return (Vector3::zeros(), false);
    }
    let (head, w) = bed.split_at_mut(HEAD);
    let a2 = a * a;
    let top = (nodes - 1) as f64;
    let e1 = basis(n, &Vector3::new(head[0], head[1], head[2]));
    let e1 = if head[3] == 0.0 {
        // a fresh contact: the axis of the first displacement, the spacing
        // with a² at three quarters of the nodes
        head[3] = a2 / (0.75 * top);
        head[4] = 0.0;
        basis(n, ds)
    } else {
        e1
    };
    let e2 = n.cross(&e1);
    head[0] = e1.x;
    head[1] = e1.y;
    head[2] = e1.z;
    let mut dz = head[3];
    while a2 > top * dz {
        coarsen(w, nodes);
        dz *= 2.0;
    }
    while a2 <= 0.5 * top * dz && dz > 0.0 {
        refine(w, nodes);
        dz *= 0.5;
    }
    head[3] = dz;
    let a0_sq = head[4];
    head[4] = a2;
    let (du, dv) = (ds.dot(&e1), ds.dot(&e2));
    let phi = 0.75 * limit / (a2 * a * k_line);
    let scale = dz.sqrt();
    let ra = a2.sqrt() / scale;
    // the nodes in contact: z_i < a²; the last of them borders the edge
    let inside = ((a2 / dz).ceil() as usize).clamp(1, nodes);
    let last = inside - 1;
    let growth = if a2 > a0_sq { 1.0 / (a2 - a0_sq) } else { 0.0 };
    let table = table();
    let (mut su, mut sv) = (0.0, 0.0);
    let mut slipping = 0;
    for i in 0..inside {
        let z = i as f64 * dz;
        // a node the contact reached during the step takes the part of Δs
        // after a² (linear along the step) passed it
        let share = if z >= a0_sq && growth > 0.0 {
            (a2 - z) * growth
        } else {
            1.0
        };
        let (mut u, mut v) = (w[2 * i] + du * share, w[2 * i + 1] + dv * share);
        let cap = phi * (a2 - z);
        let size2 = u * u + v * v;
        if size2 >= cap * cap {
            let f = cap / size2.sqrt();
            u *= f;
            v *= f;
            slipping += 1;
        }
        w[2 * i] = u;
        w[2 * i + 1] = v;
        // the weight of node i in ∫ w z^{−1/2} dz (unit spacing, times √Δz)
        let c = if i < last {
            table.get(i).copied().unwrap_or_else(|| full_weight(i))
        } else {
            edge_weight(i, ra)
        };
        su += u * c;
        sv += v * c;
    }
    // the nodes the contact left are released (one more: a refinement may have
    // put a midpoint just beyond the last edge); those beyond were already
    // (saturating: a contact that shrank by more than 2^64 in area in one step)
    let before = ((a0_sq / dz).ceil() as usize)
        .saturating_add(1)
        .clamp(inside, nodes);
    for x in &mut w[2 * inside..2 * before] {
        *x = 0.0;
    }
    let t = (e1 * su + e2 * sv) * (k_line * scale);
    let size = t.norm();
    if size > limit {
        return (t * (limit / size), true);
    }
    (t, slipping == inside && inside > 0)
}

/// The elastic energy stored in the bed at contact radius `a` (J):
/// `½ k' ∫₀^{a²} |w|² z^{−1/2} dz` with the nodal `|w|²` interpolated as `w`.
pub fn stored_energy(bed: &[f64], k_line: f64, a: f64) -> f64 {
    let nodes = (bed.len() - HEAD) / 2;
    let dz = bed[3];
    if dz <= 0.0 || a.is_nan() || a <= 0.0 {
        return 0.0;
    }
    let w = &bed[HEAD..];
    let a2 = a * a;
    let inside = ((a2 / dz).ceil() as usize).clamp(1, nodes);
    let ra = a2.sqrt() / dz.sqrt();
    let mut sum = 0.0;
    for i in 0..inside {
        let c = if i + 1 < inside {
            full_weight(i)
        } else {
            edge_weight(i, ra)
        };
        sum += (w[2 * i] * w[2 * i] + w[2 * i + 1] * w[2 * i + 1]) * c;
    }
    0.5 * k_line * dz.sqrt() * sum
}
