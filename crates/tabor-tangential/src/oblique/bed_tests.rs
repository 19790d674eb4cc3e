//! The planar spring bed against closed forms (Cattaneo-Mindlin loading and
//! Mindlin-Deresiewicz unloading at constant normal load, where the MDR bed is
//! exact), against the node bed (whose error falls as 1/nodes²) on a history
//! with a growing and shrinking contact and reversals, and the hand-over to the
//! node bed where a history leaves its line.

use super::bed::{BedState, MicroSlipBed};
use super::line_bed::piece_integral;
use nalgebra::Vector3;

const K_T: f64 = 2.0e10;
const A: f64 = 1e-5;
const LIMIT: f64 = 1e-3;

fn n() -> Vector3<f64> {
    -Vector3::x()
}

fn along(s: f64) -> Vector3<f64> {
    Vector3::y() * s
}

/// Cattaneo-Mindlin: `F = L (1 − (1 − x/x*)^{3/2})` for a monotone tangential
/// displacement `x ≤ x* = φ a²` (`φ = 3 L/(4 a³ k')`) at constant normal load.
fn cattaneo(x: f64) -> f64 {
    let x_star = 0.75 * LIMIT / (A * A * A * 0.5 * K_T) * A * A;
    LIMIT * (1.0 - (1.0 - (x / x_star).min(1.0)).powf(1.5))
}

#[test]
fn piece_integrals_are_exact_for_a_linear_profile() {
    // ∫_p^q (α + β z) z^{−1/2} dz = 2α(√q − √p) + (2/3)β(q^{3/2} − p^{3/2})
    let (p, q, alpha, beta): (f64, f64, f64, f64) = (0.3, 2.5, 1.7, -0.4);
    let exact =
        2.0 * alpha * (q.sqrt() - p.sqrt()) + 2.0 / 3.0 * beta * (q.powf(1.5) - p.powf(1.5));
    let value = piece_integral(p, q, alpha + beta * p, alpha + beta * q);
    assert!(
        (value - exact).abs() < 1e-14 * exact.abs(),
        "{value} vs {exact}"
    );
}

/// Loading in 7 steps and unloading in 9, committed after each: the force is
/// Cattaneo-Mindlin's on loading and Mindlin-Deresiewicz's (Masing's rule,
/// `F(x_max) − 2 F_C((x_max − x)/2)`) on unloading, to rounding, and its stored
/// energy is the closed form of the slipping and sticking zones.
#[test]
fn the_planar_bed_is_exact_at_constant_normal_load() {
    let x_star = 0.75 * LIMIT / (A * 0.5 * K_T);
    let mut bed = MicroSlipBed::new(K_T, A, 64, true);
    bed.reset(&along(0.0), &n(), A);
    let x_max = 0.7 * x_star;
    for j in 1..=7 {
        let x = x_max * j as f64 / 7.0;
        let f = -bed.force(&BedState::new(n(), along(x), A, LIMIT)).y;
        assert!(
            (f - cattaneo(x)).abs() < 1e-12 * LIMIT,
            "{x}: {f} vs {}",
            cattaneo(x)
        );
        bed.commit(&BedState::new(n(), along(x), A, LIMIT));
    }
    // the energy: ½ k' (x² 2√z_c + φ² ∫_{z_c}^{a²} (a² − z)² z^{−1/2} dz)
    let phi = x_star / (A * A);
    let rc = (A * A - x_max / phi).sqrt();
    let slip = |r: f64| 2.0 * A.powi(4) * r - 4.0 / 3.0 * A * A * r.powi(3) + 0.4 * r.powi(5);
    let energy = 0.25 * K_T * (x_max * x_max * 2.0 * rc + phi * phi * (slip(A) - slip(rc)));
    let stored = bed.stored_energy(A);
    assert!(
        (stored - energy).abs() < 1e-12 * energy,
        "{stored} vs {energy}"
    );
    for j in 1..=9 {
        let x = x_max - 1.8 * x_max * j as f64 / 9.0;
        let f = -bed.force(&BedState::new(n(), along(x), A, LIMIT)).y;
        let expected = cattaneo(x_max) - 2.0 * cattaneo(0.5 * (x_max - x));
        assert!(
            (f - expected).abs() < 1e-12 * LIMIT,
            "{x}: {f} vs {expected}"
        );
        bed.commit(&BedState::new(n(), along(x), A, LIMIT));
    }
}

/// A history with a contact growing and shrinking, a limit that changes with
/// it, and two reversals, in 400 committed steps: the planar bed and node beds of
/// 256 … 16384 nodes. The nodes' RMS distance to the planar bed (in units of the
/// limit) falls with the spacing to zero: measured 4.1e-5, 6.3e-6, 1.1e-6,
/// 3.2e-8 (a factor 1265 over 64 times the nodes; 1/nodes² would be 4096, its
/// steps irregular where a boundary and a node nearly meet): the planar bed is
/// their limit.
#[test]
fn the_node_beds_converge_to_the_planar_bed() {
    let x_star = 0.75 * LIMIT / (A * 0.5 * K_T);
    let history = |t: f64| {
        let a = A * (0.2 + (std::f64::consts::PI * t).sin());
        let s = 1.5 * x_star * (3.0 * std::f64::consts::PI * t).sin() * t;
        let limit = LIMIT * (a / A).powi(3);
        (a, s, limit)
    };
    let run = |bed: &mut MicroSlipBed| -> Vec<f64> {
        let (a, s, _) = history(0.0);
        bed.reset(&along(s), &n(), a);
        let mut forces = Vec::new();
        for j in 1..=400 {
            let (a, s, limit) = history(j as f64 / 400.0);
            forces.push(bed.force(&BedState::new(n(), along(s), a, limit)).y);
            bed.commit(&BedState::new(n(), along(s), a, limit));
        }
        forces
    };
    let line = run(&mut MicroSlipBed::new(K_T, A, 1024, true));
    let distance = |nodes: usize| {
        let f = run(&mut MicroSlipBed::new(K_T, A, nodes, false));
        f.iter()
            .zip(&line)
            .map(|(a, b)| (a - b).powi(2))
            .sum::<f64>()
            .sqrt()
            / LIMIT
    };
    let d: Vec<f64> = [256, 1024, 4096, 16384]
        .iter()
        .map(|&n| distance(n))
        .collect();
    assert!(
        line.iter().any(|f| f.abs() > 0.1 * LIMIT),
        "a history that loads the bed"
    );
    for w in d.windows(2) {
        assert!(w[1] < w[0] / 4.0, "{d:?}");
    }
    assert!(d[3] < d[0] / 1000.0 && d[3] < 1e-7, "{d:?}");
}

/// An increment off the bed's line hands the state to the node bed: the force
/// at the hand-over is the node bed's of the same history (to its 1/nodes²
/// error), and the bed goes on in three dimensions.
#[test]
fn a_history_off_the_line_takes_the_node_bed() {
    let x_star = 0.75 * LIMIT / (A * 0.5 * K_T);
    let mut planar = MicroSlipBed::new(K_T, A, 4096, true);
    let mut nodes = MicroSlipBed::new(K_T, A, 4096, false);
    for bed in [&mut planar, &mut nodes] {
        bed.reset(&along(0.0), &n(), A);
        for j in 1..=5 {
            bed.commit(&BedState::new(
                n(),
                along(0.1 * x_star * j as f64),
                A,
                LIMIT,
            ));
        }
    }
    let off = along(0.5 * x_star) + Vector3::z() * 0.2 * x_star;
    let (fp, fnodes) = (
        planar.force(&BedState::new(n(), off, A, LIMIT)),
        nodes.force(&BedState::new(n(), off, A, LIMIT)),
    );
    assert!(fp.z.abs() > 0.01 * LIMIT, "{fp}");
    assert!((fp - fnodes).norm() < 1e-6 * LIMIT, "{fp} vs {fnodes}");
    planar.commit(&BedState::new(n(), off, A, LIMIT));
    nodes.commit(&BedState::new(n(), off, A, LIMIT));
    let back = along(0.2 * x_star);
    let (fp, fnodes) = (
        planar.force(&BedState::new(n(), back, A, LIMIT)),
        nodes.force(&BedState::new(n(), back, A, LIMIT)),
    );
    assert!((fp - fnodes).norm() < 1e-6 * LIMIT, "{fp} vs {fnodes}");
}

/// An unstrained bed whose displacement moves only by rounding (a normal
/// component of `s` of 1e-24 m, projected on a normal a rounding short of unit
/// length, as where two spheres' contact points move together: Chung & Ooi's
/// Test 7) has no force and stays finite: the rounding has no direction of its
/// own. The planar bed took it for the bed's line (the normal itself), and the
/// commit's projection of that line into the tangent plane, 0/0, made every
/// later force NaN.
#[test]
fn rounding_of_an_unmoved_contact_is_no_direction() {
    let mut bed = MicroSlipBed::new(K_T, A, 64, true);
    bed.reset(&Vector3::zeros(), &n(), A);
    // the states of Test 7's first steps: s along the normal by rounding, the
    // normal once a rounding short of unit length (its projection leaves
    // 1.5e-39 m of s in the tangent plane, along the normal)
    let short = -Vector3::x() * 0.9999999999999999;
    let steps = [
        (n(), 4.398249653002504e-28),
        (short, 3.849109048073003e-24),
        (n(), 6.150267843089653e-24),
        (n(), 6.150267843089653e-24),
    ];
    for (normal, along_normal) in steps {
        let s = Vector3::x() * along_normal;
        let f = bed.force(&BedState::new(normal, s, A, LIMIT));
        assert!(f.iter().all(|c| c.is_finite()), "{f:?}");
        assert!(f.norm() < 1e-12 * LIMIT, "{f:?}");
        bed.commit(&BedState::new(normal, s, A, LIMIT));
    }
    let s = Vector3::x() * 6.150267843089653e-24;
    // and the bed still loads along the first real increment, exactly
    let x = 1e-3 * 0.75 * LIMIT / (A * 0.5 * K_T);
    let f = bed.force(&BedState::new(n(), s + Vector3::y() * x, A, LIMIT));
    assert!(f.iter().all(|c| c.is_finite()), "{f:?}");
    assert!(
        (f.norm() - cattaneo(x)).abs() < 1e-9 * cattaneo(x),
        "{} vs {}",
        f.norm(),
        cattaneo(x)
    );
}

/// The pieces that the committed slack alone shows within their limits
/// (`LineBed::untested`) give the forces and commits of testing every piece,
/// bit for bit: two beds in step through a contact that grows sticking at its
/// edge (a breakpoint per step), reverses, slips and shrinks, probed within
/// every step, one of them testing every piece. The shortcut is taken (count).
#[test]
fn pieces_within_their_limits_by_their_slack_need_no_test() {
    use super::line_bed::UNTESTED;
    let x_star = 0.75 * LIMIT / (A * 0.5 * K_T);
    // Hertz-like: the limit ∝ a³ (φ constant); s then a² at the step's end
    let state = |j: usize| -> (f64, f64) {
        let t = j as f64;
        match j {
            0..=40 => (0.2 + 0.02 * t, 0.5 * x_star * t / 40.0),
            41..=60 => (1.0, 0.5 * x_star - 0.06 * x_star * (t - 40.0)),
            _ => (
                1.0 - 0.03 * (t - 60.0),
                -0.7 * x_star + 0.02 * x_star * (t - 60.0),
            ),
        }
    };
    let limit = |a: f64| LIMIT * a * a * a;
    let mut fast = MicroSlipBed::new(K_T, A, 64, true);
    let (a0, s0) = state(0);
    fast.reset(&along(s0), &n(), a0 * A);
    let mut reference = fast.clone();
    let all = |on: bool| UNTESTED.set((on, UNTESTED.get().1));
    UNTESTED.set((false, 0));
    for j in 1..=80 {
        let (a_prev, s_prev) = state(j - 1);
        let (a_next, s_next) = state(j);
        for lambda in [0.2, 0.5, 0.9, 1.0] {
            let a = A * (a_prev + lambda * (a_next - a_prev));
            let s = along(s_prev + lambda * (s_next - s_prev));
            let f = fast.force(&BedState::new(n(), s, a, limit(a / A)));
            all(true);
            let g = reference.force(&BedState::new(n(), s, a, limit(a / A)));
            all(false);
            assert_eq!(f, g, "step {j}, λ = {lambda}");
        }
        let a = A * a_next;
        fast.commit(&BedState::new(n(), along(s_next), a, limit(a_next)));
        all(true);
        reference.commit(&BedState::new(n(), along(s_next), a, limit(a_next)));
        all(false);
        assert_eq!(
            fast.stored_energy(a),
            reference.stored_energy(a),
            "step {j}"
        );
    }
    assert!(
        UNTESTED.get().1 > 100,
        "shortcut taken {} times",
        UNTESTED.get().1
    );
}
