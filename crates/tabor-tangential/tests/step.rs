//! The per-contact step against values derived by hand from the definitions of
//! LAMMPS's `pair granular` (doc/src/pair_granular.rst, the sub-model sources).

#![allow(clippy::unwrap_used, clippy::expect_used)]

use approx::assert_relative_eq;
use nalgebra::Vector3;
use tabor_tangential::step::rotate_into_plane;
use tabor_tangential::{
    critical_force, lammps_number, ContactHistory, ContactKinematics, EffectiveShear, Friction,
    NormalResponse, Rolling, RollingModel, Tangential, TangentialModel, Twisting, TwistingModel,
};

const R: f64 = 1e-6;

fn kinematics(v: Vector3<f64>, wi: Vector3<f64>, wj: Vector3<f64>) -> ContactKinematics {
    ContactKinematics {
        normal: Vector3::x(),
        overlap: 1e-9,
        radius_i: R,
        radius_j: R,
        relative_velocity: v,
        angular_velocity_i: wi,
        angular_velocity_j: wj,
    }
}

fn hertz_response(a: f64, f: f64) -> NormalResponse {
    NormalResponse {
        contact_radius: a,
        elastic_force: f,
        total_force: f,
        pull_off_force: 0.0,
        damping_coefficient: 0.0,
    }
}

#[test]
fn effective_shear_is_mindlins() {
    // silica: G = E/(2(1+ν)) = 23.0769 GPa; 1/G* = 2 (2 − ν)/G
    let g = 54e9 / (2.0 * 1.17);
    let expected = g / (2.0 * 1.83);
    let s = EffectiveShear::of_pair(54e9, 0.17, 54e9, 0.17).unwrap();
    assert_relative_eq!(s.modulus(), expected, max_relative = 1e-15);
    // a rigid partner halves the compliance
    let rigid = EffectiveShear::of_rigid_partner(54e9, 0.17).unwrap();
    assert_relative_eq!(rigid.modulus(), 2.0 * expected, max_relative = 1e-15);
    assert!(EffectiveShear::of_pair(-1.0, 0.17, 54e9, 0.17).is_err());
    assert!(EffectiveShear::of_pair(54e9, 0.7, 54e9, 0.17).is_err());
}

#[test]
fn stick_step_is_the_spring_on_the_displacement() {
    let kt = 8.0 * 6.3e9;
    let f = Friction::sliding(Tangential::new(TangentialModel::Mindlin, kt, 0.0, 0.3).unwrap());
    let a = 3e-8;
    let dt = 1e-10;
    let v = 0.01;
    let k = kinematics(
        Vector3::new(-0.2, v, 0.0),
        Vector3::zeros(),
        Vector3::zeros(),
    );
    let mut h = ContactHistory::default();
    let out = f.step(&k, &hertz_response(a, 1e-3), dt, true, &mut h);
    // ξ = v dt ŷ (the normal part of the velocity does not enter), F = −k_t a ξ
    assert_relative_eq!(h.tangential[1], v * dt, max_relative = 1e-15);
    assert_eq!(h.tangential[0], 0.0);
    assert_relative_eq!(
        out.tangential_force[1],
        -kt * a * v * dt,
        max_relative = 1e-15
    );
    assert!(!out.sliding);
    // torque on i: −(R − δ/2) n × F_t, here +z (friction −y at the contact point −R x̂)
    let arm = R - 0.5e-9;
    assert_relative_eq!(out.torque_i[2], arm * kt * a * v * dt, max_relative = 1e-15);
    assert_relative_eq!(out.torque_j[2], arm * kt * a * v * dt, max_relative = 1e-15);
    // no update: the history stays, the force is that of the stored displacement
    let mut h2 = h;
    let again = f.step(&k, &hertz_response(a, 1e-3), dt, false, &mut h2);
    assert_eq!(h2, h);
    assert_eq!(again.tangential_force, out.tangential_force);
}

#[test]
fn spin_enters_the_sliding_velocity() {
    // v_tr = v_t − (R_i ω_i + R_j ω_j) × n; ω_i = ω ẑ: −R ω ẑ × x̂ = −R ω ŷ
    let w = 1e4;
    let k = kinematics(
        Vector3::zeros(),
        Vector3::new(0.0, 0.0, w),
        Vector3::new(0.0, 0.0, w),
    );
    assert_relative_eq!(k.sliding_velocity()[1], -2.0 * R * w, max_relative = 1e-15);
    // rolling: R_eff (ω_i − ω_j) × n vanishes for equal spins, twist is (ω_i − ω_j)·n
    assert_eq!(k.rolling_velocity(), Vector3::zeros());
    let k2 = kinematics(
        Vector3::zeros(),
        Vector3::new(3.0, 0.0, w),
        Vector3::zeros(),
    );
    assert_relative_eq!(k2.rolling_velocity()[1], 0.5 * R * w, max_relative = 1e-15);
    assert_eq!(k2.twisting_rate(), 3.0);
}

#[test]
fn slip_caps_the_force_and_resets_the_displacement() {
    let kt = 5e10;
    let mu = 0.3;
    let f = Friction::sliding(Tangential::new(TangentialModel::Mindlin, kt, 0.5, mu).unwrap());
    let a = 3e-8;
    let fn_ = 2e-4;
    let eta = 1e-6;
    let normal = NormalResponse {
        damping_coefficient: eta,
        ..hertz_response(a, fn_)
    };
    let k = kinematics(
        Vector3::new(0.0, 0.0, 1.0),
        Vector3::zeros(),
        Vector3::zeros(),
    );
    let mut h = ContactHistory {
        tangential: [0.0, 0.0, 1e-6],
        ..Default::default()
    };
    let out = f.step(&k, &normal, 1e-9, true, &mut h);
    // trial: −k a (1e-6 + 1e-9) − 0.5 η 1 > μ F_n: capped at μ F_n along −z
    assert!(out.sliding);
    assert_relative_eq!(out.tangential_force[2], -mu * fn_, max_relative = 1e-14);
    // ξ = −(F_t − F_damp)/(k a), F_damp = −x_γ η v_tr
    let expected = (mu * fn_ - 0.5 * eta) / (kt * a);
    assert_relative_eq!(h.tangential[2], expected, max_relative = 1e-12);
}

#[test]
fn a_stored_displacement_turns_with_the_normal_and_keeps_its_length() {
    let xi = Vector3::new(0.3, 1.0, 0.0);
    let turned = rotate_into_plane(xi, &Vector3::x());
    assert_relative_eq!(turned.norm(), xi.norm(), max_relative = 1e-15);
    assert_eq!(turned[0], 0.0);
    assert_eq!(
        rotate_into_plane(Vector3::x(), &Vector3::x()),
        Vector3::zeros()
    );
}

#[test]
fn mindlin_rescale_shrinks_with_the_contact() {
    let f = Friction::sliding(
        Tangential::new(TangentialModel::MindlinRescale, 5e10, 0.0, 10.0).unwrap(),
    );
    let k = kinematics(Vector3::zeros(), Vector3::zeros(), Vector3::zeros());
    let mut h = ContactHistory {
        tangential: [0.0, 2e-9, 0.0],
        tangential_contact_radius: 4e-8,
        ..Default::default()
    };
    f.step(&k, &hertz_response(3e-8, 1e-3), 1e-9, true, &mut h);
    assert_relative_eq!(h.tangential[1], 2e-9 * 0.75, max_relative = 1e-15);
    assert_eq!(h.tangential_contact_radius, 3e-8);
}

#[test]
fn linear_history_has_a_constant_spring() {
    let f =
        Friction::sliding(Tangential::new(TangentialModel::LinearHistory, 7.0, 0.0, 1.0).unwrap());
    let k = kinematics(
        Vector3::new(0.0, 1.0, 0.0),
        Vector3::zeros(),
        Vector3::zeros(),
    );
    let mut h = ContactHistory::default();
    let out = f.step(&k, &hertz_response(3e-8, 1.0), 0.01, true, &mut h);
    assert_relative_eq!(out.tangential_force[1], -0.07, max_relative = 1e-15);
}

#[test]
fn rolling_sds_spring_and_limit() {
    let kr = 50.0;
    let mur = 0.1;
    let fric =
        Friction::sliding(Tangential::new(TangentialModel::Mindlin, 5e10, 0.0, 0.3).unwrap())
            .with_rolling(Rolling::sds(kr, 0.0, mur).unwrap());
    let w = 100.0;
    let k = kinematics(
        Vector3::zeros(),
        Vector3::new(0.0, 0.0, w),
        Vector3::zeros(),
    );
    let mut h = ContactHistory::default();
    let dt = 1e-9;
    let fn_ = 1e-3;
    let out = fric.step(&k, &hertz_response(3e-8, fn_), dt, true, &mut h);
    // v_rl = R_eff ω ẑ × x̂ = (R/2) ω ŷ; ψ = v_rl dt; F_r = −k ψ; torque R_eff n × F_r
    let reff = 0.5 * R;
    assert_relative_eq!(h.rolling[1], reff * w * dt, max_relative = 1e-15);
    assert_relative_eq!(
        out.rolling_force[1],
        -kr * reff * w * dt,
        max_relative = 1e-15
    );
    let torque = reff * (-kr * reff * w * dt);
    // x̂ × (F ŷ) = F ẑ; the tangential torque is zero (no sliding velocity... but the
    // spin gives one): subtract the tangential part
    let tangential = -(R - 0.5e-9) * Vector3::x().cross(&out.tangential_force);
    assert_relative_eq!(
        out.torque_i[2] - tangential[2],
        torque,
        max_relative = 1e-12
    );
    // far beyond the limit: |F_r| = μ_r F_n0
    let mut h = ContactHistory {
        rolling: [0.0, 1.0, 0.0],
        ..Default::default()
    };
    let out = fric.step(&k, &hertz_response(3e-8, fn_), dt, true, &mut h);
    assert_relative_eq!(out.rolling_force.norm(), mur * fn_, max_relative = 1e-14);
    assert_relative_eq!(h.rolling[1], mur * fn_ / kr, max_relative = 1e-14);
}

#[test]
fn twisting_marshall_from_the_tangential_model() {
    let kt = 5e10;
    let mu = 0.3;
    let fric = Friction::sliding(Tangential::new(TangentialModel::Mindlin, kt, 0.0, mu).unwrap())
        .with_twisting(Twisting::Marshall);
    let a = 3e-8;
    let w = 1.0;
    let dt = 1e-9;
    let k = kinematics(
        Vector3::zeros(),
        Vector3::new(w, 0.0, 0.0),
        Vector3::zeros(),
    );
    let mut h = ContactHistory::default();
    let out = fric.step(&k, &hertz_response(a, 1e-3), dt, true, &mut h);
    assert_relative_eq!(h.twisting, w * dt, max_relative = 1e-15);
    assert_relative_eq!(
        out.twisting_torque,
        -0.5 * kt * a * a * w * dt,
        max_relative = 1e-15
    );
    assert_relative_eq!(out.torque_i[0], out.twisting_torque, max_relative = 1e-15);
    assert_relative_eq!(out.torque_j[0], -out.twisting_torque, max_relative = 1e-15);
    // the limit (2/3) μ a F_n0
    let mut h = ContactHistory {
        twisting: 1.0,
        ..Default::default()
    };
    let out = fric.step(&k, &hertz_response(a, 1e-3), dt, true, &mut h);
    let limit = 2.0 / 3.0 * mu * a * 1e-3;
    assert_relative_eq!(out.twisting_torque, -limit, max_relative = 1e-14);
    assert_relative_eq!(h.twisting, limit / (0.5 * kt * a * a), max_relative = 1e-14);

    let sds = Friction::sliding(Tangential::new(TangentialModel::Mindlin, kt, 0.0, mu).unwrap())
        .with_twisting(Twisting::sds(2.0, 0.5, 1e3).unwrap());
    let mut h = ContactHistory::default();
    let out = sds.step(&k, &hertz_response(a, 1e-3), dt, true, &mut h);
    assert_relative_eq!(
        out.twisting_torque,
        -2.0 * w * dt - 0.5 * w,
        max_relative = 1e-15
    );
}

#[test]
fn a_contact_without_area_stores_no_displacement() {
    // Maugis-Dugdale's no-contact part: a = 0, the bodies attract (F_n0 > 0).
    // `mindlin`'s k_t a and `marshall`'s ½ k_t a² are 0 there: the stored
    // displacement and twist are 0 after the step, so a contact area that forms
    // next starts from nothing; `linear_history` (k_t) and `sds` twisting
    // (their own stiffness) keep accumulating, as in LAMMPS
    let (kt, mu, dt) = (5e10, 0.3, 1e-9);
    let (v, w) = (Vector3::new(0.0, 0.02, 0.01), 3e5);
    let k = kinematics(v, Vector3::new(w, 0.0, 0.0), Vector3::zeros());
    // an attractive elastic force of 1e-7 N, pull-off 3e-7 N: F_n0 = 5e-7 N
    let attract = NormalResponse {
        contact_radius: 0.0,
        elastic_force: -1e-7,
        total_force: -1e-7,
        pull_off_force: 3e-7,
        damping_coefficient: 0.0,
    };
    assert_relative_eq!(attract.critical_force(), 5e-7, max_relative = 1e-15);
    let stored = Vector3::new(0.0, 1e-9, -2e-9);
    let start = || ContactHistory {
        tangential: stored.into(),
        twisting: 1e-3,
        // mindlin_rescale's radius of the last step: a contact that had area
        tangential_contact_radius: 2e-8,
        ..Default::default()
    };
    for model in [TangentialModel::Mindlin, TangentialModel::MindlinRescale] {
        let fric = Friction::sliding(Tangential::new(model, kt, 0.0, mu).unwrap())
            .with_twisting(Twisting::Marshall);
        let mut h = start();
        let out = fric.step(&k, &attract, dt, true, &mut h);
        assert_eq!(Vector3::from(h.tangential), Vector3::zeros(), "{model:?}");
        assert_eq!(h.twisting, 0.0, "{model:?}");
        assert_eq!(out.tangential_force, Vector3::zeros(), "{model:?}");
        assert_eq!(out.twisting_torque, 0.0, "{model:?}");
        assert!(!out.sliding, "{model:?}");
        // LAMMPS's setup force call (no update) leaves the history as it is
        let mut h = start();
        fric.step(&k, &attract, dt, false, &mut h);
        assert_eq!(h.twisting, 1e-3, "{model:?}");
    }
    let history = Tangential::new(TangentialModel::LinearHistory, 2.0, 0.0, mu).unwrap();
    let fric = Friction::sliding(history).with_twisting(Twisting::sds(2e-9, 0.0, 1e3).unwrap());
    let mut h = start();
    fric.step(&k, &attract, dt, true, &mut h);
    assert_relative_eq!(
        Vector3::from(h.tangential),
        stored + v * dt,
        max_relative = 1e-15
    );
    assert_relative_eq!(h.twisting, 1e-3 + w * dt, max_relative = 1e-15);
}

#[test]
fn critical_force_follows_lammps() {
    // cohesive: |F_e + 2 F_po|; otherwise |F_total|
    assert_eq!(critical_force(-1.0, -1.5, 1.5), 2.0);
    assert_eq!(critical_force(-1.0, -1.5, 0.0), 1.5);
    let r = NormalResponse {
        contact_radius: 1.0,
        elastic_force: 3.0,
        total_force: 4.0,
        pull_off_force: 0.0,
        damping_coefficient: 0.0,
    };
    assert_eq!(r.critical_force(), 4.0);
}

#[test]
fn menus_parse_their_own_names() {
    for m in TangentialModel::ALL {
        assert_eq!(m.as_str().parse::<TangentialModel>().unwrap(), m);
    }
    for m in RollingModel::ALL {
        assert_eq!(m.as_str().parse::<RollingModel>().unwrap(), m);
    }
    for m in TwistingModel::ALL {
        assert_eq!(m.as_str().parse::<TwistingModel>().unwrap(), m);
    }
    let err = "coulomb".parse::<TangentialModel>().unwrap_err();
    assert_eq!(
        err.to_string(),
        "unknown tangential model \"coulomb\": expected \"linear_history\", \"mindlin\", \"mindlin_rescale\" or \"mindlin_deresiewicz\""
    );
}

#[test]
fn lammps_keywords_spell_the_sub_models() {
    let f = Friction::sliding(Tangential::new(TangentialModel::Mindlin, 5e10, 0.0, 0.3).unwrap())
        .with_rolling(Rolling::sds(50.0, 0.0, 0.1).unwrap())
        .with_twisting(Twisting::Marshall);
    assert_eq!(
        f.lammps_keywords(false),
        "tangential mindlin 5e10 0 0.3 rolling sds 50 0 0.1 twisting marshall"
    );
    assert_eq!(
        f.lammps_keywords(true),
        "tangential mindlin NULL 0 0.3 rolling sds 50 0 0.1 twisting marshall"
    );
    // linear_history has no NULL; an sds twist; every number reads back exactly
    let k = 1.0 / 3.0 * 1e4;
    let f =
        Friction::sliding(Tangential::new(TangentialModel::LinearHistory, k, 0.5, 0.25).unwrap())
            .with_twisting(Twisting::sds(1e-9, 0.0, 0.2).unwrap());
    let line = f.lammps_keywords(true);
    assert_eq!(
        line,
        format!("tangential linear_history {k} 0.5 0.25 twisting sds 1e-9 0 0.2")
    );
    for x in [k, 1.8461538461538462e10, 1e-15, 0.1, 123456.789, -2.5e-7] {
        assert_eq!(lammps_number(x).parse::<f64>().unwrap(), x);
    }
}

#[test]
fn bad_parameters_are_named() {
    let e = Tangential::new(TangentialModel::Mindlin, 1.0, 0.0, -0.1).unwrap_err();
    assert!(e.to_string().contains("coefficient"), "{e}");
    let e = Rolling::sds(f64::NAN, 0.0, 0.1).unwrap_err();
    assert!(e.to_string().contains("rolling stiffness"), "{e}");
    assert!(Twisting::sds(1.0, -1.0, 0.1).is_err());
}
