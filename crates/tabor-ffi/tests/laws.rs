//! The C ABI's force laws against independent references: Hertz's closed form,
//! JKR's parametric relations in physical units, the Maugis-Dugdale no-contact
//! branch in closed form and tabor-maugis' exact equilibrium states, the DMT and
//! JKR limits of the pull-off force, and a time integration of whole impacts
//! through `tabor_law_evaluate` against tabor's quasi-static restitution
//! (seed 000 (5.37) with the loss (5.36)/(5.43)).
#![allow(missing_docs)]

use std::f64::consts::PI;
use tabor_ffi::*;
use tabor_restitution::ImpactModel;

const E: f64 = 54e9 / (2.0 * (1.0 - 0.17 * 0.17));
const R: f64 = 0.5e-6;
const W: f64 = 0.05;

fn params(model: i32, lambda: f64) -> TaborLawParams {
    TaborLawParams {
        model,
        effective_modulus: E,
        effective_radius: R,
        work_of_adhesion: W,
        tabor_parameter: lambda,
        damping_time: 0.0,
        damping_model: TABOR_DAMPING_KUWABARA_KONO,
        damping_value: 0.0,
        dugdale_range: 0.0,
        cohesive_stress: 0.0,
    }
}

fn new_law(p: TaborLawParams) -> *mut TaborLaw {
    let mut law = std::ptr::null_mut();
    let status = unsafe { tabor_law_new(&p, &mut law) };
    assert_eq!(status, TABOR_OK, "{p:?}");
    law
}

fn eval(law: *const TaborLaw, d: f64, rate: f64, h: &mut TaborHistory) -> TaborForce {
    let mut out = TaborForce::default();
    assert_eq!(
        unsafe { tabor_law_evaluate(law, d, rate, h, &mut out) },
        TABOR_OK
    );
    out
}

fn info(law: *const TaborLaw) -> TaborLawInfo {
    let mut i = TaborLawInfo::default();
    assert_eq!(unsafe { tabor_law_info(law, &mut i) }, TABOR_OK);
    i
}

#[test]
fn hertz_is_the_closed_form_and_never_pulls() {
    let law = new_law(params(TABOR_MODEL_HERTZ, 0.0));
    let mut h = TaborHistory::default();
    assert_eq!(eval(law, -1e-9, 1.0, &mut h).force, 0.0);
    for d in [1e-12, 1e-10, 3e-9, 1e-7] {
        let f = eval(law, d, 0.0, &mut h).force;
        let exact = 4.0 / 3.0 * E * R.sqrt() * d.powf(1.5);
        assert!((f / exact - 1.0).abs() < 1e-14, "{d}: {f} vs {exact}");
    }
    // Kuwabara-Kono (5.66): F = (4/3)E*√R (δ^(3/2) + (3/2) A δ^(1/2) δ̇), clipped at 0
    let p = TaborLawParams {
        damping_time: 1e-9,
        ..params(TABOR_MODEL_HERTZ, 0.0)
    };
    let damped = new_law(p);
    let (d, v) = (2e-9, 0.3);
    let f = eval(damped, d, v, &mut TaborHistory::default()).force;
    let exact = 4.0 / 3.0 * E * R.sqrt() * (d.powf(1.5) + 1.5 * 1e-9 * d.sqrt() * v);
    assert!((f / exact - 1.0).abs() < 1e-13);
    assert_eq!(
        eval(
            damped,
            d,
            -1e3,
            &mut TaborHistory {
                contact: 1.0,
                max_overlap: d
            }
        )
        .force,
        0.0
    );
    unsafe { tabor_law_free(law) };
    unsafe { tabor_law_free(damped) };
}

#[test]
fn jkr_matches_the_parametric_relations_and_separates_by_its_rule() {
    // δ(a) = a²/R − √(2πwa/E*), F(a) = 4E*a³/(3R) − √(8πwE*a³) (seed 000 (5.33)-(5.34))
    let a_c = (9.0 * PI * W * R * R / (8.0 * E)).cbrt();
    let f_n = 1.5 * PI * W * R;
    for (model, a_sep) in [
        (TABOR_MODEL_JKR_FIXED_GRIP, (1.0f64 / 3.0).powf(2.0 / 3.0)),
        (TABOR_MODEL_JKR_LOAD_CONTROLLED, 1.0),
    ] {
        let law = new_law(params(model, 0.0));
        let i = info(law);
        assert!((i.pull_off_force / -f_n - 1.0).abs() < 1e-12);
        let delta = |a: f64| a * a / R - (2.0 * PI * W * a / E).sqrt();
        let force =
            |a: f64| 4.0 * E * a.powi(3) / (3.0 * R) - (8.0 * PI * W * E * a.powi(3)).sqrt();
        assert!((i.snap_off_overlap / delta(a_sep * a_c) - 1.0).abs() < 1e-9);
        let mut worst = 0.0f64;
        for k in 0..400 {
            let a = a_c * (a_sep + 6.0 * (k as f64 + 0.5) / 400.0);
            let mut h = TaborHistory {
                contact: 1.0,
                max_overlap: 1e-6,
            };
            let f = eval(law, delta(a), 0.0, &mut h);
            worst = worst.max((f.force - force(a)).abs() / f_n);
            assert!(
                (f.contact_radius - a).abs() < 1e-7 * a_c,
                "k {k}: a {} vs {a}",
                f.contact_radius
            );
        }
        assert!(worst < 1e-7, "JKR table error {worst:e} F_n");
        // jump-in at δ = 0 onto F(a0) = −(8/9) F_n, snap-off below the rule's depth
        let mut h = TaborHistory::default();
        assert_eq!(eval(law, -1e-12, 1.0, &mut h).force, 0.0);
        let f = eval(law, 0.0, 1.0, &mut h);
        assert_eq!(f.event, 1);
        assert!((f.force / f_n + 8.0 / 9.0).abs() < 1e-7);
        let f = eval(law, i.snap_off_overlap * 0.999, -1.0, &mut h);
        assert!(f.force < 0.0 && f.event == 0);
        let f = eval(law, i.snap_off_overlap * 1.001, -1.0, &mut h);
        assert_eq!((f.force, f.event), (0.0, 2));
        assert_eq!(h, TaborHistory::default());
        unsafe { tabor_law_free(law) };
    }
}

#[test]
fn maugis_dugdale_matches_exact_states_and_the_closed_form_no_contact_branch() {
    let a_c = (9.0 * PI * W * R * R / (8.0 * E)).cbrt();
    let f_n = 1.5 * PI * W * R;
    let d_n = a_c * a_c / (3.0 * R);
    for lambda in [0.05, 0.3, 0.55, 1.5, 10.0] {
        let law = new_law(params(TABOR_MODEL_MAUGIS_DUGDALE, lambda));
        let i = info(law);
        assert!((i.jump_in_overlap / (-d_n / lambda) - 1.0).abs() < 1e-12);
        let path = tabor_maugis::impact_path(lambda).unwrap();
        let mut worst = 0.0f64;
        for k in 0..300 {
            let d_hat = path.pull_off.depth + (k as f64 + 0.37) * 0.05 * (1.0 / lambda).max(1.0);
            let exact = tabor_maugis::equilibrium_state(lambda, d_hat).unwrap();
            let mut h = TaborHistory {
                contact: 1.0,
                max_overlap: 1.0,
            };
            let f = eval(law, d_hat * d_n, 0.0, &mut h);
            worst = worst.max((f.force / f_n - exact.force).abs());
        }
        assert!(worst < 1e-6, "Lambda {lambda}: table error {worst:e} F_n");
        if lambda < tabor_maugis::LAMBDA_1 {
            // no-contact branch in closed form: d̂ = (3/2)b̂² − (32Λ/π²)b̂ − 1/Λ, F̂ = −2Λb̂²
            let bc = 32.0 * lambda / (3.0 * PI * PI);
            for b in [1.01 * bc, 1.5 * bc, 1.99 * bc] {
                let d_hat = 1.5 * b * b - 32.0 * lambda / (PI * PI) * b - 1.0 / lambda;
                let mut h = TaborHistory {
                    contact: 1.0,
                    max_overlap: 1.0,
                };
                let f = eval(law, d_hat * d_n, 0.0, &mut h);
                assert!((f.force / f_n + 2.0 * lambda * b * b).abs() < 1e-7);
                assert_eq!(f.contact_radius, 0.0);
            }
        }
        unsafe { tabor_law_free(law) };
    }
}

fn eval_at(law: *const TaborLaw, r: f64, d: f64, rate: f64, h: &mut TaborHistory) -> TaborForce {
    let mut out = TaborForce::default();
    assert_eq!(
        unsafe { tabor_law_evaluate_at(law, r, d, rate, h, &mut out) },
        TABOR_OK
    );
    out
}

#[test]
fn one_law_serves_every_radius() {
    // a law built at R = 0.5 µm, evaluated at other radii, against the closed forms
    // at those radii: JKR's parametric relations (5.33)-(5.34), Hertz (5.5), and
    // tabor-maugis' exact normalized states with the scales of each radius
    for r2 in [0.013e-6, 0.31e-6, 2.7e-6, 41e-6] {
        let a_c = (9.0 * PI * W * r2 * r2 / (8.0 * E)).cbrt();
        let f_n = 1.5 * PI * W * r2;
        let d_n = a_c * a_c / (3.0 * r2);
        let law = new_law(params(TABOR_MODEL_JKR_FIXED_GRIP, 0.0));
        let delta = |a: f64| a * a / r2 - (2.0 * PI * W * a / E).sqrt();
        let force =
            |a: f64| 4.0 * E * a.powi(3) / (3.0 * r2) - (8.0 * PI * W * E * a.powi(3)).sqrt();
        for k in 0..50 {
            let a = a_c * (0.49 + 5.0 * (k as f64 + 0.5) / 50.0);
            let mut h = TaborHistory {
                contact: 1.0,
                max_overlap: 1.0,
            };
            let f = eval_at(law, r2, delta(a), 0.0, &mut h);
            assert!((f.force - force(a)).abs() < 1e-7 * f_n, "R {r2} a {a}");
            assert!((f.contact_radius - a).abs() < 1e-7 * a_c);
        }
        let mut i = TaborLawInfo::default();
        assert_eq!(unsafe { tabor_law_info_at(law, r2, &mut i) }, TABOR_OK);
        assert!((i.pull_off_force / -f_n - 1.0).abs() < 1e-12);
        unsafe { tabor_law_free(law) };

        let law = new_law(params(TABOR_MODEL_HERTZ, 0.0));
        let d = 1e-3 * r2;
        let f = eval_at(law, r2, d, 0.0, &mut TaborHistory::default()).force;
        assert!((f / (4.0 / 3.0 * E * r2.sqrt() * d.powf(1.5)) - 1.0).abs() < 1e-14);
        unsafe { tabor_law_free(law) };

        for lambda in [0.3, 1.5] {
            let law = new_law(params(TABOR_MODEL_MAUGIS_DUGDALE, lambda));
            assert_eq!(unsafe { tabor_law_info_at(law, r2, &mut i) }, TABOR_OK);
            assert!((i.jump_in_overlap / (-d_n / lambda) - 1.0).abs() < 1e-12);
            let path = tabor_maugis::impact_path(lambda).unwrap();
            for k in 0..40 {
                let d_hat = path.pull_off.depth + (k as f64 + 0.37) * 0.1 * (1.0 / lambda).max(1.0);
                let exact = tabor_maugis::equilibrium_state(lambda, d_hat).unwrap();
                let mut h = TaborHistory {
                    contact: 1.0,
                    max_overlap: 1.0,
                };
                let f = eval_at(law, r2, d_hat * d_n, 0.0, &mut h);
                assert!(
                    (f.force / f_n - exact.force).abs() < 1e-6,
                    "R {r2} Λ {lambda}"
                );
            }
            unsafe { tabor_law_free(law) };
        }
    }
    let law = new_law(params(TABOR_MODEL_HERTZ, 0.0));
    let mut out = TaborForce::default();
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert_eq!(
            unsafe {
                tabor_law_evaluate_at(law, bad, 1e-9, 0.0, &mut TaborHistory::default(), &mut out)
            },
            TABOR_ERR_INVALID
        );
    }
    unsafe { tabor_law_free(law) };
}

#[test]
fn pull_off_force_goes_from_dmt_to_jkr() {
    // DMT 2πwR as Λ → 0, JKR (3/2)πwR as Λ → ∞, monotone in between (Maugis 1992)
    let mut last = f64::INFINITY;
    for lambda in [1e-3, 0.01, 0.1, 0.3, 0.5, 1.0, 3.0, 100.0, 1e4] {
        let law = new_law(params(TABOR_MODEL_MAUGIS_DUGDALE, lambda));
        let p = -info(law).pull_off_force / (PI * W * R);
        assert!(p < last + 1e-12, "not monotone at {lambda}");
        last = p;
        if lambda <= 1e-3 {
            assert!((p / 2.0 - 1.0).abs() < 1e-3, "DMT limit: {p}");
        }
        if lambda >= 1e4 {
            assert!((p / 1.5 - 1.0).abs() < 1e-4, "JKR limit: {p}");
        }
        unsafe { tabor_law_free(law) };
    }
}

/// Velocity Verlet through the C entry point; returns the restitution (0 if stuck).
fn integrate(law: *const TaborLaw, mass: f64, speed: f64, dt: f64) -> f64 {
    let i = info(law);
    let mut d = i.jump_in_overlap.min(0.0) - 20.0 * speed * dt;
    let mut v = speed;
    let mut h = TaborHistory::default();
    let mut f = eval(law, d, v, &mut h).force;
    for _ in 0..50_000_000u64 {
        v -= 0.5 * dt * f / mass;
        d += dt * v;
        f = eval(law, d, v, &mut h).force;
        v -= 0.5 * dt * f / mass;
        if h.contact == 0.0 && v < 0.0 && d < i.jump_in_overlap.min(i.snap_off_overlap) {
            return -v / speed;
        }
    }
    0.0
}

#[test]
fn time_integration_reproduces_tabors_quasi_static_restitution() {
    let mass = 0.5 * 2650.0 * 4.0 / 3.0 * PI * 1e-18;
    for (model, lambda) in [
        (TABOR_MODEL_JKR_FIXED_GRIP, 0.0),
        (TABOR_MODEL_JKR_LOAD_CONTROLLED, 0.0),
        (TABOR_MODEL_MAUGIS_DUGDALE, 0.3),
        (TABOR_MODEL_MAUGIS_DUGDALE, 0.55),
        (TABOR_MODEL_MAUGIS_DUGDALE, 1.5),
    ] {
        let loss = match model {
            TABOR_MODEL_MAUGIS_DUGDALE => tabor_maugis::MaugisDugdaleImpact::new(
                tabor_maugis::MaugisContact::new(
                    tabor_jkr::JkrSphere::new(E, R, W).unwrap(),
                    lambda,
                )
                .unwrap(),
                mass,
            )
            .unwrap()
            .energy_loss_joules()
            .unwrap(),
            _ => {
                let rule = if model == TABOR_MODEL_JKR_FIXED_GRIP {
                    tabor_jkr::SeparationRule::FixedGrip
                } else {
                    tabor_jkr::SeparationRule::LoadControlled
                };
                tabor_jkr::JkrImpact::new(tabor_jkr::JkrSphere::new(E, R, W).unwrap(), mass)
                    .unwrap()
                    .with_separation(rule)
                    .energy_loss(1.0)
                    .unwrap()
                    .joules
            }
        };
        let v_stick = (2.0 * loss / mass).sqrt();
        let law = new_law(params(model, lambda));
        for factor in [1.5, 4.0] {
            let v = factor * v_stick;
            let e_ref = (1.0 - 2.0 * loss / (mass * v * v)).sqrt();
            // time step: the Hertz contact time / 20000
            let tc = 2.87 * (mass * mass / (R * E * E * v)).powf(0.2);
            let e = integrate(law, mass, v, tc / 20000.0);
            assert!(
                (e - e_ref).abs() < 2e-4,
                "model {model} Lambda {lambda} v {v}: {e} vs {e_ref}"
            );
        }
        unsafe { tabor_law_free(law) };
    }
}

#[test]
fn errors_are_status_codes_never_unwinding() {
    let mut law = std::ptr::null_mut();
    assert_eq!(
        unsafe { tabor_law_new(std::ptr::null(), &mut law) },
        TABOR_ERR_NULL
    );
    let bad = TaborLawParams {
        model: 17,
        ..params(TABOR_MODEL_HERTZ, 0.0)
    };
    assert_eq!(unsafe { tabor_law_new(&bad, &mut law) }, TABOR_ERR_INVALID);
    let n = unsafe { tabor_last_error(std::ptr::null_mut(), 0) };
    let mut buf = vec![0 as std::ffi::c_char; n + 1];
    assert_eq!(unsafe { tabor_last_error(buf.as_mut_ptr(), buf.len()) }, n);
    let msg = unsafe { std::ffi::CStr::from_ptr(buf.as_ptr()) }
        .to_string_lossy()
        .into_owned();
    assert!(msg.contains("model"), "{msg}");
    for p in [
        TaborLawParams {
            effective_modulus: -1.0,
            ..params(TABOR_MODEL_JKR_FIXED_GRIP, 0.0)
        },
        TaborLawParams {
            work_of_adhesion: f64::NAN,
            ..params(TABOR_MODEL_JKR_FIXED_GRIP, 0.0)
        },
        TaborLawParams {
            tabor_parameter: 0.0,
            ..params(TABOR_MODEL_MAUGIS_DUGDALE, 0.0)
        },
        TaborLawParams {
            damping_time: -1.0,
            ..params(TABOR_MODEL_HERTZ, 0.0)
        },
    ] {
        assert_eq!(
            unsafe { tabor_law_new(&p, &mut law) },
            TABOR_ERR_INVALID,
            "{p:?}"
        );
    }
    let law = new_law(params(TABOR_MODEL_JKR_FIXED_GRIP, 0.0));
    let mut h = TaborHistory {
        contact: 1.0,
        max_overlap: 1e-9,
    };
    let mut out = TaborForce {
        force: 5.0,
        elastic_force: 5.0,
        contact_radius: 1.0,
        event: 9,
    };
    assert_eq!(
        unsafe { tabor_law_evaluate(law, f64::NAN, 0.0, &mut h, &mut out) },
        TABOR_ERR_INVALID
    );
    assert_eq!(out, TaborForce::default());
    assert_eq!(
        h,
        TaborHistory {
            contact: 1.0,
            max_overlap: 1e-9
        }
    );
    assert_eq!(
        unsafe { tabor_law_evaluate(law, 0.0, 0.0, std::ptr::null_mut(), &mut out) },
        TABOR_ERR_NULL
    );
    assert_eq!(
        unsafe { tabor_law_info(std::ptr::null(), &mut TaborLawInfo::default()) },
        TABOR_ERR_NULL
    );
    unsafe { tabor_law_free(law) };
    unsafe { tabor_law_free(std::ptr::null_mut()) };
    let v = unsafe { std::ffi::CStr::from_ptr(tabor_ffi_version()) };
    assert_eq!(v.to_str().unwrap(), env!("CARGO_PKG_VERSION"));
}

#[test]
fn header_is_current() {
    let generated = std::fs::read_to_string(concat!(env!("OUT_DIR"), "/tabor_ffi.h"));
    let committed =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/include/tabor_ffi.h"))
            .unwrap();
    if let Ok(generated) = generated {
        assert_eq!(
            generated, committed,
            "include/tabor_ffi.h is stale: TABOR_FFI_WRITE_HEADER=1 cargo build -p tabor-ffi"
        );
    }
    for name in [
        "tabor_law_new",
        "tabor_law_evaluate",
        "tabor_law_evaluate_at",
        "tabor_law_info",
        "tabor_law_info_at",
        "tabor_law_free",
        "tabor_last_error",
        "TABOR_HISTORY_LEN",
    ] {
        assert!(committed.contains(name), "{name}");
    }
}
