//! Arbitrary inputs: every public function returns a finite value (restitution in
//! [0, 1]) or an error naming the parameter; none panics.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use proptest::prelude::*;
use tabor_restitution::{Error, ImpactModel};
use tabor_visco::models::{KelvinVoigtFlatPunch, KelvinVoigtSphere, MaxwellBranchSphere};
use tabor_visco::*;

fn check_eps(r: tabor_restitution::Result<f64>) {
    match r {
        Ok(e) => assert!(e.is_finite() && (0.0..=1.0).contains(&e), "{e}"),
        Err(Error::InvalidParameter { parameter, .. }) => assert!(!parameter.is_empty()),
        Err(_) => {}
    }
}

fn check_value(r: tabor_restitution::Result<f64>) {
    if let Ok(v) = r {
        assert!(v.is_finite(), "{v}");
    }
}

fn any() -> impl Strategy<Value = f64> {
    prop_oneof![
        proptest::num::f64::ANY,
        -10.0..10.0f64,
        1e-6..1e3f64,
        Just(0.0),
        Just(1.0),
        Just(0.5),
    ]
}

proptest! {
    #[test]
    fn closed_forms_never_panic(a in any(), b in any(), c in any(), d in any()) {
        check_eps(kelvin_voigt_flat::restitution(a));
        check_value(kelvin_voigt_flat::contact_time(a));
        check_value(kelvin_voigt_flat::damping_ratio(a, b, c, d));
        check_value(kelvin_voigt_flat::natural_frequency(a, b, c));
        check_eps(kelvin_voigt_sphere::first_order_restitution(a));
        check_value(kelvin_voigt_sphere::viscous_parameter(a, b, c, d, a));
        check_value(kelvin_voigt_sphere::overlap_scale(a, b, c, d));
        check_value(standard_flat::equivalent_damping_ratio(a, b));
        check_eps(standard_flat::equivalent_restitution(a, b));
        check_value(standard_flat::parameters(a, b, c, d, a).map(|p| p.0 + p.1));
        check_value(standard_sphere::parameters(a, b, c, d, a, b).map(|p| p.0 + p.1));
        check_value(compressible_flat::poisson_ratio(a, b));
        check_value(compressible_flat::bulk_damping_ratio_equal_viscosities(a, b));
        check_value(compressible_flat::damping_ratios(a, b, c, d, a, b).map(|p| p.0 + p.1));
        check_value(damping_law::tsuji_damping(a));
        check_value(damping_law::scaled_damping(a, b, c, d, a, b));
    }

    #[test]
    fn integrated_models_never_panic(a in any(), b in any(), c in any()) {
        check_eps(kelvin_voigt_sphere::restitution(a, SphereModel::KuwabaraKono));
        check_eps(kelvin_voigt_sphere::restitution(a, SphereModel::Rigorous));
        check_eps(kelvin_voigt_sphere::solve(a, SphereModel::Rigorous, b).map(|s| s.restitution));
        check_eps(damping_law::restitution(a, b));
        check_eps(standard_flat::restitution(a, b));
        check_eps(compressible_flat::restitution(a, b, c));
        check_eps(compressible_flat::solve(a, b, c, c).map(|s| s.restitution));
    }

    #[test]
    fn physical_models_never_panic(a in any(), b in any(), c in any(), d in any(), v in any()) {
        if let Ok(m) = KelvinVoigtFlatPunch::new(a, b, c, d) {
            check_eps(tabor_restitution::impact(&m, v).map(|o| o.restitution));
        }
        if let Ok(m) = KelvinVoigtSphere::new(a, b, c, d, SphereModel::KuwabaraKono) {
            check_eps(tabor_restitution::impact(&m, v).map(|o| o.restitution));
        }
        if let Ok(m) = MaxwellBranchSphere::standard(a, b, c, d, a) {
            let _ = m.name();
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 16, ..ProptestConfig::default() })]
    #[test]
    fn mdr_models_never_panic(a in any(), b in any(), t in any()) {
        check_eps(standard_sphere::restitution(a, b));
        check_eps(kelvin_maxwell_sphere::restitution(a, b));
        check_eps(standard_sphere::solve(a, b, t).map(|s| s.restitution));
        check_eps(kelvin_maxwell_sphere::solve(a, b, t).map(|s| s.restitution));
    }

    /// Valid parameters (log-uniform over the accepted ranges, any tolerance):
    /// a finite result, never an integration failure.
    #[test]
    fn mdr_models_solve_their_whole_range(
        log_beta in -5.0..4.0f64,
        log_delta in -8.0..3.0f64,
        log_tol in -15.0..-0.4f64,
    ) {
        let (b, d, t) = (10f64.powf(log_beta), 10f64.powf(log_delta), 10f64.powf(log_tol));
        for r in [standard_sphere::solve(b, d, t), kelvin_maxwell_sphere::solve(b, d, t)] {
            match r {
                Ok(s) => {
                    prop_assert!((0.0..=1.0).contains(&s.restitution));
                    prop_assert!(s.contact_time.is_finite() && s.contact_time > 0.0);
                    prop_assert!(s.max_overlap.is_finite() && s.max_overlap > 0.0);
                }
                Err(Error::InvalidParameter { parameter, .. }) => {
                    prop_assert_eq!(parameter, "viscous_parameter");
                }
                Err(e) => prop_assert!(false, "β {b}, δ {d}, tol {t}: {e}"),
            }
        }
    }
}

proptest! {
    /// The damping law (5.72) over its whole accepted range (β ∈ [0, 3/2],
    /// γ ∈ (0, 1e3], any tolerance): a finite result, never an integration failure.
    #[test]
    fn damping_law_solves_its_whole_range(
        beta in 0.0..=1.5f64,
        log_gamma in -300.0..3.0f64,
        log_tol in -15.0..-0.302f64,
    ) {
        let (g, t) = (10f64.powf(log_gamma), 10f64.powf(log_tol));
        match damping_law::solve(beta, g, t) {
            Ok(s) => {
                prop_assert!(s.restitution > 0.0 && s.restitution <= 1.0);
                prop_assert!(s.contact_time.is_finite() && s.contact_time > 0.0);
                prop_assert!(s.max_overlap.is_finite() && s.max_overlap > 0.0);
                prop_assert!(s.cost.evaluations < 200_000);
            }
            Err(e) => prop_assert!(false, "β {beta}, γ {g}, tol {t}: {e}"),
        }
    }

    /// The Kelvin-Voigt sphere over δ ∈ (0, 1e9], both models, any tolerance.
    #[test]
    fn kelvin_voigt_sphere_solves_its_whole_range(
        log_delta in -300.0..9.0f64,
        log_tol in -15.0..-0.302f64,
    ) {
        let (d, t) = (10f64.powf(log_delta), 10f64.powf(log_tol));
        for model in [SphereModel::KuwabaraKono, SphereModel::Rigorous] {
            match kelvin_voigt_sphere::solve(d, model, t) {
                Ok(s) => {
                    prop_assert!(s.restitution > 0.0 && s.restitution <= 1.0);
                    prop_assert!(s.contact_time.is_finite() && s.contact_time > 0.0);
                    prop_assert!(s.cost.evaluations < 200_000);
                }
                Err(e) => prop_assert!(false, "{model:?} δ {d}, tol {t}: {e}"),
            }
        }
    }

    /// The inverse over its accepted range (ε(δ_max) < ε < 1: log-uniform towards
    /// both ends): a δ in (0, 1e9], never an integration failure.
    #[test]
    fn inverse_covers_its_whole_range(
        u in 0.0..1.0f64,
        near_one in proptest::bool::ANY,
        log_tol in -15.0..-0.302f64,
    ) {
        let t = 10f64.powf(log_tol);
        // log-uniform in (3.3e-16, 1) or 1 − ε log-uniform in (1e-16, 1)
        let eps = if near_one { 1.0 - 10f64.powf(-16.0 * u) } else { 10f64.powf(-15.48 * u) };
        prop_assume!(eps > 3.3e-16 && eps < 1.0);
        for model in [SphereModel::KuwabaraKono, SphereModel::Rigorous] {
            match kelvin_voigt_sphere::viscous_parameter_for_restitution(eps, model, t) {
                Ok(d) => prop_assert!(d > 0.0 && d <= 1e9, "{d}"),
                Err(e) => prop_assert!(false, "{model:?} ε {eps}, tol {t}: {e}"),
            }
        }
    }
}

#[test]
fn errors_name_the_parameter() {
    let cases: Vec<(tabor_restitution::Result<f64>, &str)> = vec![
        (kelvin_voigt_flat::restitution(f64::NAN), "damping_ratio"),
        (kelvin_voigt_flat::restitution(0.0), "damping_ratio"),
        (kelvin_voigt_flat::restitution(-1.0), "damping_ratio"),
        (
            kelvin_voigt_flat::restitution(f64::INFINITY),
            "damping_ratio",
        ),
        (
            kelvin_voigt_sphere::restitution(2e9, SphereModel::Rigorous),
            "viscous_parameter",
        ),
        (standard_flat::restitution(0.0, 1.0), "modulus_ratio"),
        (standard_flat::restitution(1.0, -1.0), "viscous_parameter"),
        (
            compressible_flat::restitution(0.5, 1.0, 1.0),
            "poisson_ratio",
        ),
        (
            compressible_flat::restitution(0.3, 1.0, f64::NAN),
            "bulk_damping_ratio",
        ),
        (damping_law::restitution(2.0, 1.0), "damping_exponent"),
        (damping_law::restitution(0.5, 0.0), "damping"),
        (
            damping_law::restitution(0.5, 1e3 * (1.0 + 1e-15)),
            "damping",
        ),
        (
            kelvin_voigt_sphere::viscous_parameter_for_restitution(
                1e-17,
                SphereModel::KuwabaraKono,
                1e-8,
            ),
            "restitution",
        ),
        (
            kelvin_voigt_sphere::solve(0.1, SphereModel::Rigorous, 0.0).map(|s| s.restitution),
            "tolerance",
        ),
    ];
    for (r, name) in cases {
        match r {
            Err(Error::InvalidParameter { parameter, .. }) => assert_eq!(parameter, name),
            other => panic!("expected an error naming {name}, got {other:?}"),
        }
    }
}
