//! The DEM damping laws behind the C ABI (`TABOR_DAMPING_*`, LAMMPS `pair
//! granular`'s `viscoelastic`, `tsuji`, `coeff_restitution`): `coeff_restitution`
//! on Hertz gives the nominal e at every speed (the self-similar β = 1/4 damping of
//! `F = K δ^{3/2}`; LAMMPS documentation `pair_granular`), in a velocity-Verlet run
//! of two spheres written here; the damping force is the library's definition
//! (`tabor_viscoadhesive::NormalDamping`); bad combinations are named errors.
#![allow(missing_docs, clippy::unwrap_used, clippy::expect_used)]

use tabor_ffi::*;

const E_STAR: f64 = 54e9 / (2.0 * (1.0 - 0.17 * 0.17));
const R_STAR: f64 = 0.5e-6;
const M_STAR: f64 = 0.5 * 2650.0 * 4.0 / 3.0 * std::f64::consts::PI * 1e-18;

fn params(model: i32, value: f64) -> TaborLawParams {
    TaborLawParams {
        model: TABOR_MODEL_HERTZ,
        effective_modulus: E_STAR,
        effective_radius: R_STAR,
        work_of_adhesion: 0.0,
        tabor_parameter: 0.0,
        damping_time: 0.0,
        damping_model: model,
        damping_value: value,
        dugdale_range: 0.0,
        cohesive_stress: 0.0,
    }
}

/// Velocity Verlet (LAMMPS's `nve`: half kick, drift, force at the half-step
/// velocity, half kick) of the overlap from first touch at speed v; returns the
/// rebound speed over v, and the largest |F| seen.
fn rebound(law: &ContactLaw, v: f64, steps_per_contact: f64) -> (f64, f64) {
    let t_c = 2.87 * (M_STAR * M_STAR / (R_STAR * E_STAR * E_STAR * v)).powf(0.2);
    let dt = t_c / steps_per_contact;
    let (mut d, mut rate, mut f) = (0.0, v, 0.0);
    let mut h = TaborHistory::default();
    let s = law.scales(R_STAR).unwrap();
    let mut f_max: f64 = 0.0;
    loop {
        rate -= 0.5 * dt * f / M_STAR;
        d += dt * rate;
        f = law
            .evaluate_with_mass(&s, d, rate, M_STAR, &mut h)
            .unwrap()
            .force;
        f_max = f_max.max(f.abs());
        rate -= 0.5 * dt * f / M_STAR;
        if d < 0.0 && h.contact == 0.0 {
            return (-rate / v, f_max);
        }
    }
}

/// Tolerance from the time step: the contact's end falls within one step, an
/// impulse of at most `2 dt F_max` (EVENTS = 2 as in the LAMMPS tests) on m* v.
#[test]
fn coeff_restitution_gives_e_for_hertz_at_every_speed() {
    for e in [0.3, 0.5, 0.9] {
        let law = law_from_params(&params(TABOR_DAMPING_COEFF_RESTITUTION, e)).expect("law");
        for v in [1e-3, 0.3, 10.0] {
            let steps = 5000.0;
            let (got, f_max) = rebound(&law, v, steps);
            let t_c = 2.87 * (M_STAR * M_STAR / (R_STAR * E_STAR * E_STAR * v)).powf(0.2);
            let tol = 2.0 * (t_c / steps) * f_max / (M_STAR * v);
            assert!((got - e).abs() < tol, "e {e} v {v}: {got} (tol {tol:.1e})");
        }
    }
}

/// The force is the elastic force plus `NormalDamping::force`, unclipped (the
/// contact of a damped Hertz law ends with a tension, as `pair granular` without
/// `limit_damping`); a DEM law needs the effective mass.
#[test]
fn the_force_is_the_library_definition() {
    use tabor_viscoadhesive::{DampingModel, NormalDamping};
    for (model, kind, value) in [
        (TABOR_DAMPING_VISCOELASTIC, DampingModel::Viscoelastic, 3e15),
        (TABOR_DAMPING_TSUJI, DampingModel::Tsuji, 0.7),
        (
            TABOR_DAMPING_COEFF_RESTITUTION,
            DampingModel::CoeffRestitution,
            0.5,
        ),
    ] {
        let law = law_from_params(&params(model, value)).unwrap();
        let s = law.scales(R_STAR).unwrap();
        let d = 1e-10;
        let a = (R_STAR * d).sqrt();
        let elastic = 4.0 / 3.0 * E_STAR * R_STAR.sqrt() * d.powf(1.5);
        let lib = NormalDamping::dem(kind, value, E_STAR).unwrap();
        for rate in [0.3, -0.3] {
            let mut h = TaborHistory::default();
            let f = law.evaluate_with_mass(&s, d, rate, M_STAR, &mut h).unwrap();
            let expected = elastic + lib.force(M_STAR, a, rate);
            assert!(
                (f.force / expected - 1.0).abs() < 1e-12,
                "{model}: {} vs {expected}",
                f.force
            );
        }
        let mut h = TaborHistory::default();
        let e = law.evaluate_scaled(&s, d, 0.3, &mut h).unwrap_err();
        assert!(e.to_string().contains("effective_mass"), "{e}");
    }
    // unclipped: receding fast at a small overlap, the force is tensile
    let law = law_from_params(&params(TABOR_DAMPING_COEFF_RESTITUTION, 0.5)).unwrap();
    let s = law.scales(R_STAR).unwrap();
    let mut h = TaborHistory::default();
    let f = law
        .evaluate_with_mass(&s, 1e-13, -1.0, M_STAR, &mut h)
        .unwrap();
    assert!(f.force < 0.0, "{}", f.force);
}

#[test]
fn bad_damping_is_a_named_error() {
    let e = law_from_params(&params(TABOR_DAMPING_COEFF_RESTITUTION, 1.5)).unwrap_err();
    assert!(e.to_string().contains("restitution"), "{e}");
    let e = law_from_params(&params(7, 0.5)).unwrap_err();
    assert!(e.to_string().contains("damping_model"), "{e}");
    let mut p = params(TABOR_DAMPING_TSUJI, 0.5);
    p.damping_time = 1e-9;
    let e = law_from_params(&p).unwrap_err();
    assert!(e.to_string().contains("damping_time"), "{e}");
}
