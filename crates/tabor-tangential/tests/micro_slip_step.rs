//! The per-contact micro-slip form (`Friction::step` with `tangential
//! mindlin_deresiewicz`: the compact spring bed of `tabor_tangential::micro_slip`)
//! against Mindlin & Deresiewicz's closed forms at constant normal load, against
//! Maw, Barber & Fawcett's figure values in a collision integrated here step by
//! step (the DEM engine's use), against the library's 1024-node bed (`oblique`)
//! over MBF's range of angles, its convergence in the number of springs, and the
//! energy it dissipates.

#![allow(clippy::unwrap_used, clippy::expect_used)]

use nalgebra::Vector3;
use tabor_dynamics::SimulationSettings;
use tabor_elastic::ElasticContact;
use tabor_tangential::micro_slip::{self, SPRINGS};
use tabor_tangential::oblique::{Body, NormalContact, ObliqueImpact};
use tabor_tangential::{
    ContactHistory, ContactKinematics, EffectiveShear, Friction, NormalResponse, Tangential,
    TangentialModel,
};

// Maw, Barber & Fawcett (1976): steel, ν = 0.3, a solid sphere on a flat
const R: f64 = 1e-3;
const RHO: f64 = 7800.0;
const E_Y: f64 = 200e9;
const NU: f64 = 0.3;
const MU: f64 = 0.3;

fn e_star() -> f64 {
    E_Y / (2.0 * (1.0 - NU * NU))
}

fn k_t() -> f64 {
    8.0 * EffectiveShear::of_pair(E_Y, NU, E_Y, NU).unwrap().modulus()
}

/// κ = k_t/(2E*) = 4G*/E*.
fn kappa() -> f64 {
    k_t() / (2.0 * e_star())
}

fn friction(mu: f64) -> Friction {
    Friction::sliding(Tangential::new(TangentialModel::MindlinDeresiewicz, k_t(), 0.0, mu).unwrap())
}

fn response(a: f64, f: f64) -> NormalResponse {
    NormalResponse {
        contact_radius: a,
        elastic_force: f,
        total_force: f,
        pull_off_force: 0.0,
        damping_coefficient: 0.0,
    }
}

fn slide(v: f64) -> ContactKinematics {
    ContactKinematics {
        normal: Vector3::x(),
        overlap: 1e-6,
        radius_i: R,
        radius_j: f64::INFINITY,
        relative_velocity: Vector3::new(0.0, v, 0.0),
        angular_velocity_i: Vector3::zeros(),
        angular_velocity_j: Vector3::zeros(),
    }
}

/// The interpolation error of the bed's force at one kink of the profile (a
/// stick/slip boundary at `z = c2`, a jump `φ` of the slope): the profile is
/// exact at the nodes (the return map is exact in one dimension) and linear
/// between them, so the error is at most `φ Δz/4` over the cell `[p, q]` holding
/// the kink, weighted by `k' z^{−1/2}`: `|ΔT| ≤ k' (φ Δz/4) 2(√q − √p)`, with
/// `L = (4/3) a³ k' φ`: `|ΔT|/L ≤ (3/8) Δz (√q − √p)/a³`.
fn kink_bound(c2: f64, dz: f64, a: f64) -> f64 {
    if !(c2 > 0.0 && c2 < a * a) {
        return 0.0;
    }
    let p = (c2 / dz).floor() * dz;
    0.375 * dz * ((p + dz).sqrt() - p.sqrt()) / a.powi(3)
}

/// At constant N the bed follows Mindlin & Deresiewicz (1953)'s curves (derived
/// for the bed in the module docs of `micro_slip`): loading
/// `T = L(1 − (1 − 2k s/(3L))^{3/2})` (k = k_t a, L = μN) with the stick zone
/// `c² = a² − s/φ`, `φ a² = 3L/(2k)`; unloading from T*
/// `T = T* − 2L(1 − (1 − k (s* − s)/(3L))^{3/2})`; reloading from T** the mirror
/// image, which closes the loop at T*. Each stick/slip boundary present costs at
/// most [`kink_bound`]; nothing else is discretized (the return map is exact in
/// one dimension, so the step count does not matter).
#[test]
fn constant_load_follows_mindlin_deresiewicz() {
    let (a, n) = (1e-4, 10.0);
    let f = friction(MU);
    let (k, l) = (k_t() * a, MU * n);
    let phi_a2 = 1.5 * l / k;
    let s_slide = phi_a2;
    let steps = 2000;
    let dt = 1.0;
    let ds = 0.7 * s_slide / steps as f64;
    let mut h = ContactHistory::default();
    // the contact forms without slip: the bed's spacing is set
    f.step(&slide(0.0), &response(a, n), dt, true, &mut h);
    let dz = h.micro_slip[3];
    assert!(dz > 0.0 && a * a / dz <= (SPRINGS - 1) as f64);
    let kink = |c2: f64| kink_bound(c2 * a * a, dz, a);
    let mut s = 0.0;
    let mut worst: f64 = 0.0;
    for _ in 0..steps {
        let out = f.step(&slide(ds / dt), &response(a, n), dt, true, &mut h);
        s += ds;
        let exact = l * (1.0 - (1.0 - 2.0 * k * s / (3.0 * l)).powf(1.5));
        let tol = kink(1.0 - s / phi_a2) + 1e-12;
        worst = worst.max((-out.tangential_force[1] - exact).abs() / l / tol);
    }
    println!("loading: worst error / bound {worst:.3}");
    assert!(worst <= 1.0, "loading: {worst} of the bound");
    let (s_star, t_star) = (s, h.tangential[1]);
    let c_star = 1.0 - s_star / phi_a2;
    worst = 0.0;
    for _ in 0..steps {
        let out = f.step(&slide(-ds / dt), &response(a, n), dt, true, &mut h);
        s -= ds;
        let exact = t_star - 2.0 * l * (1.0 - (1.0 - k * (s_star - s) / (3.0 * l)).powf(1.5));
        let c_un = 1.0 - (s_star - s) / (2.0 * phi_a2);
        let tol = kink(c_star) + kink(c_un) + 1e-12;
        worst = worst.max((-out.tangential_force[1] - exact).abs() / l / tol);
    }
    println!("unloading: worst error / bound {worst:.3}");
    assert!(worst <= 1.0, "unloading: {worst} of the bound");
    let (s_2, t_2) = (s, h.tangential[1]);
    let c_2 = 1.0 - (s_star - s_2) / (2.0 * phi_a2);
    worst = 0.0;
    let mut closed = 0.0;
    for _ in 0..steps {
        let out = f.step(&slide(ds / dt), &response(a, n), dt, true, &mut h);
        s += ds;
        let exact = t_2 + 2.0 * l * (1.0 - (1.0 - k * (s - s_2) / (3.0 * l)).powf(1.5));
        let c_re = 1.0 - (s - s_2) / (2.0 * phi_a2);
        let tol = kink(c_star) + kink(c_2) + kink(c_re) + 1e-12;
        worst = worst.max((-out.tangential_force[1] - exact).abs() / l / tol);
        closed = -out.tangential_force[1];
    }
    println!("reloading: worst error / bound {worst:.3}");
    assert!(worst <= 1.0, "reloading: {worst} of the bound");
    // the loop closes at T* (Masing): the profile is the loading one again
    assert!(
        (closed - t_star).abs() <= kink(c_star) * l + 1e-12 * l,
        "{closed} vs {t_star}"
    );
}

/// Beyond the slip distance every spring slides on its cap: the bed integrates
/// the caps exactly (linear in z, zero at the edge), `|T| = μN` to round-off.
#[test]
fn gross_sliding_is_the_limit() {
    let f = friction(MU);
    let a = 1e-4;
    let n = 10.0;
    let mut h = ContactHistory::default();
    f.step(&slide(0.0), &response(a, n), 1.0, true, &mut h);
    let out = f.step(&slide(1.0), &response(a, n), 1.0, true, &mut h);
    assert!(out.sliding);
    assert!((out.tangential_force.norm() - MU * n).abs() < 1e-12 * MU * n);
    assert!(out.tangential_force[1] < 0.0);
}

/// A sphere on a flat, integrated as a DEM engine does (symplectic Euler, `steps`
/// per Hertz contact time) with the per-contact bed of `springs` nodes
/// (`micro_slip::advance`, what `Friction::step` calls with [`SPRINGS`]): the
/// tangential restitution of the contact point at MBF's Ψ = κ tan α/μ, 1 m/s,
/// and the work done on the bed, `Σ T·Δs` (J).
fn dem_beta(psi: f64, steps: usize, springs: usize) -> (f64, f64) {
    let alpha = (psi * MU / kappa()).atan();
    let m = 4.0 / 3.0 * std::f64::consts::PI * RHO * R.powi(3);
    let inertia = 0.4 * m * R * R;
    let (vn0, vt0) = (alpha.cos(), alpha.sin());
    let stiff = 4.0 / 3.0 * e_star() * R.sqrt();
    let d_max = (1.25 * m * vn0 * vn0 / stiff).powf(0.4);
    let dt = 2.9432 * d_max / vn0 / steps as f64;
    let mut bed = vec![0.0; micro_slip::bed_len(springs)];
    let (mut d, mut vn, mut vt, mut w) = (0.0, vn0, vt0, 0.0);
    let mut work = 0.0;
    loop {
        d += vn * dt;
        if d <= 0.0 {
            break;
        }
        let fe = stiff * d.powf(1.5);
        let a = (R * d).sqrt();
        // the contact point's slip v_t − ω R (LAMMPS's vtr)
        let ds = Vector3::new(0.0, (vt - w * R) * dt, 0.0);
        let (t, _) = micro_slip::advance(&mut bed, &Vector3::x(), &ds, 0.5 * k_t(), a, MU * fe);
        work += t.dot(&ds);
        let f = -t[1];
        vn -= fe / m * dt;
        vt += f / m * dt;
        w -= f * R / inertia * dt;
    }
    (-(vt - w * R) / vt0, work)
}

/// The time-step tolerance of a collision in β, as `test_plugin_friction.py`
/// derives it for LAMMPS: an event (a stick/slip switch) can fall one step apart
/// in two schemes, changing the contact point's slip by χ dt F_max/m per event
/// (χ = 7/2), two events: `2 χ dt F_max/(m v_t0)`.
fn step_tolerance(psi: f64, steps: usize) -> f64 {
    let alpha = (psi * MU / kappa()).atan();
    let m = 4.0 / 3.0 * std::f64::consts::PI * RHO * R.powi(3);
    let (vn0, vt0) = (alpha.cos(), alpha.sin());
    let stiff = 4.0 / 3.0 * e_star() * R.sqrt();
    let d_max = (1.25 * m * vn0 * vn0 / stiff).powf(0.4);
    let dt = 2.9432 * d_max / vn0 / steps as f64;
    2.0 * 3.5 * dt * stiff * d_max.powf(1.5) / (m * vt0)
}

fn exact_beta(psi: f64) -> f64 {
    let angle = (psi * MU / kappa()).atan().to_degrees();
    let imp = ObliqueImpact {
        sphere: Body::solid_sphere(R, RHO).unwrap(),
        target: Body::flat(),
        normal: NormalContact::ELASTIC,
        friction: Some(friction(MU)),
        sphere_spin: [0.0; 3],
        target_spin: [0.0; 3],
    };
    let mut law = ElasticContact::hertz(e_star(), R).unwrap();
    imp.simulate(
        &mut law,
        1.0,
        angle,
        &SimulationSettings::with_tolerance(1e-9).unwrap(),
    )
    .unwrap()
    .tangential_restitution
    .unwrap()
}

/// Maw, Barber & Fawcett (1976), Wear 38:101, Fig. 5 (read to about ±0.02 in β,
/// ±0.1 in Ψ, as `micro_slip.rs` reads it): β → about −0.21 as Ψ → 0, a maximum
/// ≈ 0.46 near Ψ ≈ 3, and the gross-sliding line β = −1 + 7κ/Ψ beyond Ψ = 7κ.
/// The per-contact bed at 4000 steps per contact time: the no-slip limit and the
/// maximum within 0.03 (the reading of the figure plus the bed's error, below
/// 2e-3 as measured against the library below), the sliding line within the
/// time-step tolerance.
#[test]
fn dem_form_on_maw_barber_fawcett() {
    let steps = 4000;
    let (b0, _) = dem_beta(0.02, steps, SPRINGS);
    println!("β(0.02) = {b0:.4}");
    assert!((b0 - -0.21).abs() < 0.03, "no-slip limit β(0.02) = {b0}");
    let maximum = [2.5, 3.0, 3.5]
        .iter()
        .map(|&p| dem_beta(p, steps, SPRINGS).0)
        .fold(f64::NEG_INFINITY, f64::max);
    println!("maximum β = {maximum:.4}");
    assert!((maximum - 0.46).abs() < 0.03, "maximum β = {maximum}");
    for psi in [7.5 * kappa(), 10.0] {
        let line = -1.0 + 7.0 * kappa() / psi;
        let (b, _) = dem_beta(psi, steps, SPRINGS);
        let tol = step_tolerance(psi, steps);
        assert!(
            (b - line).abs() < tol,
            "sliding line Ψ {psi}: {b} vs {line}"
        );
    }
}

/// The per-contact bed of [`SPRINGS`] nodes against the library's bed (planar
/// here: exact in z; the tolerance was set against its 1024-node bed) over MBF's
/// range Ψ = 0.1…10, in a DEM integration of 4000 steps per contact
/// time: within a tenth of the time-step tolerance ([`step_tolerance`], the
/// tolerance of the LAMMPS comparison) at every Ψ, so the bed's error is well
/// below what a DEM step resolves. The micro-slip work `Σ T·Δs` over the
/// collision is non-negative (the bed's springs are unstrained after it: the
/// work is all dissipated). The differences are printed.
#[test]
fn dem_form_against_the_library_bed() {
    let steps = 4000;
    for psi in [
        0.1, 0.3, 0.6, 0.85, 1.2, 1.7, 2.0, 2.5, 3.0, 3.5, 5.0, 6.0, 8.0, 10.0,
    ] {
        let ((d, work), e) = (dem_beta(psi, steps, SPRINGS), exact_beta(psi));
        let tol = 0.1 * step_tolerance(psi, steps);
        println!(
            "Ψ {psi:4.2}: β per-contact bed {d:+.5}, library bed {e:+.5}, difference {:+.1e} \
             (a tenth of the time-step tolerance {tol:.1e}); micro-slip work {work:.3e} J",
            d - e
        );
        assert!((d - e).abs() < tol, "Ψ {psi}: difference {}", d - e);
        assert!(work >= 0.0, "Ψ {psi}: micro-slip work {work}");
    }
}

/// The bed's error falls as the square of its spacing: against the library's
/// bed (planar here, exact in z; the bound was set against its 1024-node bed) at
/// Ψ = 1.2 (where it is largest), 16, 32 and 64 springs; each doubling divides
/// the difference by at least 3 (4 for an error ∝ 1/N², less where the
/// library's own error, its path at the integration tolerance, is approached).
#[test]
fn the_bed_converges_as_the_square_of_its_spacing() {
    let e = exact_beta(1.2);
    let err: Vec<f64> = [16, 32, 64]
        .iter()
        .map(|&n| (dem_beta(1.2, 4000, n).0 - e).abs())
        .collect();
    println!("Ψ 1.2: |β_N − β_library| for N = 16, 32, 64: {err:?}");
    assert!(err[0] > 3.0 * err[1] && err[1] > 3.0 * err[2], "{err:?}");
}

proptest::proptest! {
    /// Any history of 3-D slip increments, contact radii (zero included: the
    /// no-contact branch) and limits (growing, shrinking), with a turning normal:
    /// the force stays finite and within the Coulomb limit, the bed finite.
    #[test]
    fn any_history_stays_within_the_limit(
        steps in proptest::collection::vec(
            (-1.0f64..1.0, -1.0f64..1.0, -1.0f64..1.0, 0.0f64..2e-4, 0.0f64..20.0, 0.0f64..1.0),
            1..200,
        )
    ) {
        let f = friction(MU);
        let mut h = ContactHistory::default();
        for (vx, vy, vz, a, n, turn) in steps {
            // a normal that turns a little: (cos, sin, 0) about the start x
            let phi = 0.1 * turn;
            let k = ContactKinematics {
                normal: Vector3::new(phi.cos(), phi.sin(), 0.0),
                overlap: 1e-6,
                radius_i: R,
                radius_j: R,
                relative_velocity: Vector3::new(vx, vy, vz) * 1e-6,
                angular_velocity_i: Vector3::zeros(),
                angular_velocity_j: Vector3::zeros(),
            };
            let out = f.step(&k, &response(a, n), 1.0, true, &mut h);
            let limit = MU * n;
            let t = out.tangential_force.norm();
            proptest::prop_assert!(t.is_finite());
            proptest::prop_assert!(t <= limit * (1.0 + 1e-12) + 1e-300, "{} > {}", t, limit);
            proptest::prop_assert!(h.tangential.iter().all(|x| x.is_finite()));
            proptest::prop_assert!(h.micro_slip.iter().all(|x| x.is_finite()));
        }
    }

    /// The micro-slip work is non-negative step by step: at a fixed contact
    /// radius (the springs fixed, their caps moving with the limit), any history
    /// of 2-D slip increments and limits, the work done on the bed `Σ T·Δs` never
    /// falls below the energy it stores (for each spring the return map gives
    /// `T·Δs − ΔE = ½k|Δw|² + k w·Δp ≥ 0`, Δp the slip, along w).
    #[test]
    fn the_micro_slip_work_is_never_below_the_stored_energy(
        steps in proptest::collection::vec((-1.0f64..1.0, -1.0f64..1.0, 0.1f64..20.0), 1..200)
    ) {
        let (a, k_line) = (1e-4, 0.5 * k_t());
        let mut bed = [0.0; micro_slip::BED_LEN];
        let n = Vector3::x();
        let mut work = 0.0;
        for (dy, dz, load) in steps {
            let ds = Vector3::new(0.0, dy, dz) * 1e-8;
            let (t, _) = micro_slip::advance(&mut bed, &n, &ds, k_line, a, MU * load);
            work += t.dot(&ds);
            let stored = micro_slip::stored_energy(&bed, k_line, a);
            proptest::prop_assert!(stored >= 0.0);
            proptest::prop_assert!(work >= stored * (1.0 - 1e-12) - 1e-24, "work {} stored {}", work, stored);
        }
    }
}
