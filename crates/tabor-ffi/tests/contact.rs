//! The contact ABI (normal law + friction) against closed forms independent of
//! the code: JKR's parametric relations (seed 000 (5.33)-(5.34)) for the normal
//! force and the contact radius a, the Mindlin no-slip spring 8 G* a, the Coulomb
//! limit μ |F_n,elastic + 2 (3/2)πwR*| of LAMMPS's `jkr`, the torque arm R − δ/2,
//! and the exchange symmetry of bodies i and j.
#![allow(missing_docs, clippy::unwrap_used, clippy::expect_used)]

use std::f64::consts::PI;
use tabor_ffi::*;

const E: f64 = 2.78e10;
const W: f64 = 0.05;
const G: f64 = 1.2e10; // G* (Pa)
const MU: f64 = 0.3;

fn contact(friction: TaborFrictionParams) -> *mut TaborContact {
    let p = TaborLawParams {
        model: TABOR_MODEL_JKR_LOAD_CONTROLLED,
        effective_modulus: E,
        effective_radius: 1e-6,
        work_of_adhesion: W,
        tabor_parameter: 0.0,
        damping_time: 0.0,
        damping_model: TABOR_DAMPING_KUWABARA_KONO,
        damping_value: 0.0,
        dugdale_range: 0.0,
        cohesive_stress: 0.0,
    };
    let mut c = std::ptr::null_mut();
    assert_eq!(
        unsafe { tabor_contact_new(&p, &friction, &mut c) },
        TABOR_OK
    );
    c
}

fn mindlin() -> TaborFrictionParams {
    TaborFrictionParams {
        tangential_model: TABOR_TANGENTIAL_MINDLIN,
        tangential_stiffness: 8.0 * G,
        friction_coefficient: MU,
        rolling_model: TABOR_ROLLING_SDS,
        rolling_stiffness: 50.0,
        rolling_coefficient: 0.1,
        twisting_model: TABOR_TWISTING_MARSHALL,
        ..TaborFrictionParams::default()
    }
}

fn step(
    c: *const TaborContact,
    s: &TaborContactState,
    h: &mut TaborContactHistory,
) -> TaborContactForces {
    let mut out = TaborContactForces::default();
    assert_eq!(unsafe { tabor_contact_step(c, s, h, &mut out) }, TABOR_OK);
    out
}

/// JKR at contact radius a for effective radius r: (δ, F).
fn jkr(a: f64, r: f64) -> (f64, f64) {
    (
        a * a / r - (2.0 * PI * W * a / E).sqrt(),
        4.0 * E * a.powi(3) / (3.0 * r) - (8.0 * PI * W * E * a.powi(3)).sqrt(),
    )
}

#[test]
fn stick_is_the_mindlin_spring_and_slip_the_coulomb_limit_of_jkr() {
    let c = contact(mindlin());
    let (ri, rj) = (1.3e-6, 0.7e-6);
    let r = ri * rj / (ri + rj);
    let a = 0.12 * r;
    let (delta, f_n) = jkr(a, r);
    let dt = 1e-10;
    let state = |vt: f64| TaborContactState {
        normal: [1.0, 0.0, 0.0],
        overlap: delta,
        radius_i: ri,
        radius_j: rj,
        relative_velocity: [0.0, vt, 0.0],
        time_step: dt,
        update_history: 1,
        ..TaborContactState::default()
    };
    // the contact forms at δ ≥ 0 (here δ > 0 on the first call)
    let mut h = TaborContactHistory::default();
    let vt = 1e-3;
    let f = step(c, &state(vt), &mut h);
    assert!(
        (f.normal_force / f_n - 1.0).abs() < 1e-7,
        "{} vs {f_n}",
        f.normal_force
    );
    assert!((f.contact_radius / a - 1.0).abs() < 1e-7);
    // one step of sliding velocity vt: ξ = vt dt, F_t = −8 G* a ξ (stick)
    let ft = -8.0 * G * a * vt * dt;
    assert!(
        (f.force[1] / ft - 1.0).abs() < 1e-7,
        "{} vs {ft}",
        f.force[1]
    );
    assert_eq!(f.sliding, 0);
    assert!((f.force[0] / f_n - 1.0).abs() < 1e-7);
    // torque on i: −(R_i − δ/2) n × F_t, along z
    let tz = -(ri - 0.5 * delta) * f.force[1];
    assert!((f.torque_i[2] / tz - 1.0).abs() < 1e-12);
    assert!((f.torque_j[2] / (-(rj - 0.5 * delta) * f.force[1]) - 1.0).abs() < 1e-12);
    // gross sliding: the limit μ |F_n,e + 2 (3/2)πwR*| (Thornton 1991, LAMMPS jkr)
    let f = step(c, &state(1e3), &mut h);
    let limit = MU * (f_n + 3.0 * PI * W * r).abs();
    assert_eq!(f.sliding, 1);
    assert!((f.tangential_force / limit - 1.0).abs() < 1e-7);
    assert!((f.critical_force / (f_n + 3.0 * PI * W * r) - 1.0).abs() < 1e-7);
    // the stored displacement is the elastic part of the limit force
    assert!((h.tangential[1] * 8.0 * G * a / limit - 1.0).abs() < 1e-7);
    // snap-off clears the whole history
    let mut s = state(0.0);
    s.overlap = -1e-6;
    let f = step(c, &s, &mut h);
    assert_eq!((f.event, f.force), (2, [0.0; 3]));
    assert_eq!(h, TaborContactHistory::default());
    unsafe { tabor_contact_free(c) };
}

#[test]
fn swapping_the_bodies_reverses_forces_and_histories() {
    let c = contact(mindlin());
    let (ri, rj) = (1.1e-6, 0.8e-6);
    let n = [0.6, 0.0, 0.8];
    let a = TaborContactState {
        normal: n,
        overlap: 2e-9,
        radius_i: ri,
        radius_j: rj,
        relative_velocity: [0.01, -0.02, 0.003],
        angular_velocity_i: [1e3, -2e3, 5e2],
        angular_velocity_j: [-3e2, 1e3, 4e3],
        time_step: 1e-10,
        update_history: 1,
        effective_mass: 1e-15,
    };
    let b = TaborContactState {
        normal: n.map(|x| -x),
        radius_i: rj,
        radius_j: ri,
        relative_velocity: a.relative_velocity.map(|x| -x),
        angular_velocity_i: a.angular_velocity_j,
        angular_velocity_j: a.angular_velocity_i,
        ..a
    };
    let (mut ha, mut hb) = (
        TaborContactHistory::default(),
        TaborContactHistory::default(),
    );
    for _ in 0..50 {
        let fa = step(c, &a, &mut ha);
        let fb = step(c, &b, &mut hb);
        for k in 0..3 {
            let scale = fa.normal_force.abs();
            assert!((fa.force[k] + fb.force[k]).abs() <= 1e-12 * scale);
            assert!((fa.torque_i[k] - fb.torque_j[k]).abs() <= 1e-12 * scale * ri);
            assert!(
                (ha.tangential[k] + hb.tangential[k]).abs()
                    <= 1e-12 * ha.tangential[k].abs().max(1e-30)
            );
        }
    }
    unsafe { tabor_contact_free(c) };
}

#[test]
fn bad_friction_and_states_are_status_codes() {
    let p = TaborLawParams {
        model: TABOR_MODEL_HERTZ,
        effective_modulus: E,
        effective_radius: 1e-6,
        work_of_adhesion: 0.0,
        tabor_parameter: 0.0,
        damping_time: 0.0,
        damping_model: TABOR_DAMPING_KUWABARA_KONO,
        damping_value: 0.0,
        dugdale_range: 0.0,
        cohesive_stress: 0.0,
    };
    let mut c = std::ptr::null_mut();
    for f in [
        TaborFrictionParams {
            tangential_model: 9,
            ..mindlin()
        },
        TaborFrictionParams {
            friction_coefficient: -1.0,
            ..mindlin()
        },
        TaborFrictionParams {
            tangential_model: TABOR_TANGENTIAL_NONE,
            ..mindlin()
        },
    ] {
        assert_eq!(
            unsafe { tabor_contact_new(&p, &f, &mut c) },
            TABOR_ERR_INVALID
        );
    }
    // null friction: normal forces only
    assert_eq!(
        unsafe { tabor_contact_new(&p, std::ptr::null(), &mut c) },
        TABOR_OK
    );
    let mut h = TaborContactHistory::default();
    let mut out = TaborContactForces::default();
    let s = TaborContactState {
        normal: [2.0, 0.0, 0.0],
        overlap: 1e-9,
        radius_i: 1e-6,
        radius_j: 1e-6,
        ..TaborContactState::default()
    };
    assert_eq!(
        unsafe { tabor_contact_step(c, &s, &mut h, &mut out) },
        TABOR_ERR_INVALID
    );
    let s = TaborContactState {
        normal: [1.0, 0.0, 0.0],
        radius_j: f64::NAN,
        ..s
    };
    assert_eq!(
        unsafe { tabor_contact_step(c, &s, &mut h, &mut out) },
        TABOR_ERR_INVALID
    );
    assert_eq!(h, TaborContactHistory::default());
    unsafe { tabor_contact_free(c) };
}

/// `TABOR_TANGENTIAL_MINDLIN_DERESIEWICZ` through the ABI: the history is
/// `TABOR_CONTACT_HISTORY_LEN` doubles (10 + the micro-slip bed), the model says
/// so (`tabor_contact_history_len`; 10 without micro-slip); at constant JKR load a
/// steady slip follows Mindlin's monotonic loading curve
/// `T = L(1 − (1 − 2 k s/(3L))^{3/2})` (k = 8 G* a, L = μ F_n0, Mindlin &
/// Deresiewicz 1953) within the bed's interpolation error at its one stick/slip
/// boundary `c² = a²(1 − 2ks/(3L))` (`(3/8) Δz (√q − √p)/a³` of L for the cell
/// `[p, q]` holding it, `tests/micro_slip_step.rs` of tabor-tangential), where
/// `mindlin`'s spring would reach `k s`.
#[test]
fn micro_slip_through_the_abi() {
    assert_eq!(
        std::mem::size_of::<TaborContactHistory>(),
        8 * TABOR_CONTACT_HISTORY_LEN
    );
    assert_eq!(TABOR_CONTACT_HISTORY_LEN, 10 + TABOR_MICRO_SLIP_LEN);
    let plain = contact(TaborFrictionParams {
        tangential_model: TABOR_TANGENTIAL_MINDLIN,
        tangential_stiffness: 8.0 * G,
        friction_coefficient: MU,
        ..TaborFrictionParams::default()
    });
    assert_eq!(
        unsafe { tabor_contact_history_len(plain) },
        TABOR_CONTACT_HISTORY_BASE_LEN
    );
    unsafe { tabor_contact_free(plain) };
    let c = contact(TaborFrictionParams {
        tangential_model: TABOR_TANGENTIAL_MINDLIN_DERESIEWICZ,
        tangential_stiffness: 8.0 * G,
        friction_coefficient: MU,
        ..TaborFrictionParams::default()
    });
    let r = 1e-6;
    let a = 0.12 * r;
    let (delta, f_n) = jkr(a, r);
    let limit = MU * (f_n + 3.0 * PI * W * r);
    let k = 8.0 * G * a;
    let steps = 20000;
    let dt = 1e-10;
    // to 0.7 of the slip distance 3L/(2k) to sliding
    let vt = 0.7 * 1.5 * limit / k / (steps as f64 * dt);
    let state = TaborContactState {
        normal: [1.0, 0.0, 0.0],
        overlap: delta,
        radius_i: 2.0 * r,
        radius_j: 2.0 * r,
        relative_velocity: [0.0, vt, 0.0],
        time_step: dt,
        update_history: 1,
        ..TaborContactState::default()
    };
    let mut h = TaborContactHistory::default();
    // the first call forms the contact: its limit jumps from 0 (all slides)
    step(
        c,
        &TaborContactState {
            relative_velocity: [0.0; 3],
            ..state
        },
        &mut h,
    );
    let mut f = TaborContactForces::default();
    for _ in 0..steps {
        f = step(c, &state, &mut h);
    }
    assert_eq!(
        unsafe { tabor_contact_history_len(c) },
        TABOR_CONTACT_HISTORY_LEN
    );
    let s = vt * dt * steps as f64;
    let exact = limit * (1.0 - (1.0 - 2.0 * k * s / (3.0 * limit)).powf(1.5));
    // the bed's spacing (its 4th double) and the cell of the stick/slip boundary
    let dz = h.micro_slip[3];
    let c2 = a * a * (1.0 - 2.0 * k * s / (3.0 * limit));
    let p = (c2 / dz).floor() * dz;
    let bound = 0.375 * dz * ((p + dz).sqrt() - p.sqrt()) / a.powi(3);
    assert!(
        (-f.force[1] - exact).abs() <= (bound + 1e-12) * limit,
        "{} vs {exact} (bound {bound:e} of the limit)",
        -f.force[1]
    );
    assert!(-f.force[1] < 0.9 * k * s);
    unsafe { tabor_contact_free(c) };
}

/// A flat wall (`radius_j` = +∞, as `fix wall/tabor` passes it): the JKR force
/// and contact radius at R* = R_i (the closed form above), the tangential spring
/// 8 G* a, the torque arm R_i (LAMMPS `fix wall/gran`), ω_j ignored; a negative
/// or NaN `radius_j` is still refused.
#[test]
fn a_flat_wall_is_an_infinite_radius_j() {
    let c = contact(mindlin());
    let ri = 1.3e-6;
    let a = 0.12 * ri;
    let (delta, f_n) = jkr(a, ri);
    let dt = 1e-10;
    let vt = 1e-3;
    let state = |wj: [f64; 3]| TaborContactState {
        normal: [0.0, 0.0, 1.0],
        overlap: delta,
        radius_i: ri,
        radius_j: f64::INFINITY,
        relative_velocity: [vt, 0.0, 0.0],
        angular_velocity_j: wj,
        time_step: dt,
        update_history: 1,
        effective_mass: 1e-14,
        ..TaborContactState::default()
    };
    let (mut h1, mut h2) = (
        TaborContactHistory::default(),
        TaborContactHistory::default(),
    );
    let f = step(c, &state([0.0; 3]), &mut h1);
    let g = step(c, &state([1e4, -2e4, 3e4]), &mut h2);
    assert!(
        (f.normal_force / f_n - 1.0).abs() < 1e-7,
        "{} vs {f_n}",
        f.normal_force
    );
    assert!((f.contact_radius / a - 1.0).abs() < 1e-7);
    let ft = -8.0 * G * a * vt * dt;
    assert!(
        (f.force[0] / ft - 1.0).abs() < 1e-7,
        "{} vs {ft}",
        f.force[0]
    );
    // torque on i: R_i n × F_t with n = z, F_t along x: (0, R_i F_t, 0) up to sign
    // −(arm) n × F (the pair convention with arm R_i)
    let ty = -ri * f.force[0];
    assert!(
        (f.torque_i[1] / ty - 1.0).abs() < 1e-12,
        "{} vs {ty}",
        f.torque_i[1]
    );
    assert_eq!(f.torque_j, [0.0; 3]);
    assert_eq!(f.force, g.force);
    assert_eq!(h1, h2);
    for bad in [-1.0, f64::NAN, f64::NEG_INFINITY, 0.0] {
        let mut s = state([0.0; 3]);
        s.radius_j = bad;
        let mut out = TaborContactForces::default();
        let mut h = TaborContactHistory::default();
        assert_eq!(
            unsafe { tabor_contact_step(c, &s, &mut h, &mut out) },
            TABOR_ERR_INVALID
        );
    }
    unsafe { tabor_contact_free(c) };
}
