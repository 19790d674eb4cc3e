#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Time-domain simulation (tabor-dynamics) of the plastic force laws against the
//! analytic restitution of the same model; Jackson-Green against an independent
//! quadrature + root-finding path.

use proptest::prelude::*;
use tabor_dynamics::{simulate_impact, EventKind, SimulationSettings};
use tabor_jkr::JkrSphere;
use tabor_numerics::quadrature::{integrate_smooth, QuadTolerance};
use tabor_numerics::root_finding::{brent, RootTolerance};
use tabor_plastic::{
    AdhesiveInterpolation, AdhesiveInterpolationImpact, AdhesivePlasticContact, Interpolation,
    JacksonGreen, PlasticContact, PlasticImpact, Thornton, FIT_ONSET,
};
use tabor_restitution::{impact, ImpactModel};

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]
    /// Simulated vs analytic (5.105) restitution, 1e-6 relative (observed ~1e-10),
    /// over decades of E*, R, m, sigma_Y/E*, v0/v_Y (0.3 ... 3e3).
    #[test]
    fn simulated_restitution_equals_the_closed_form(
        log_s in -0.5f64..3.5, thornton in any::<bool>(), log_e in 9.0f64..12.0,
        log_r in -6.0f64..-1.0, log_m in -12.0f64..-2.0, log_strain in -3.5f64..-1.5) {
        let (e, r, m) = (10f64.powf(log_e), 10f64.powf(log_r), 10f64.powf(log_m));
        let contact = PlasticContact::new(e, r, 10f64.powf(log_strain) * e).unwrap();
        let v0 = 10f64.powf(log_s) * contact.yield_velocity(m).unwrap();
        let settings = SimulationSettings::default();
        let (analytic, sim) = if thornton {
            let model = PlasticImpact::new(contact, Thornton, m).unwrap();
            let mut law = model.force_law();
            (model.restitution(v0).unwrap(), simulate_impact(&mut law, m, v0, &settings).unwrap())
        } else {
            let model = PlasticImpact::new(contact, Interpolation::default(), m).unwrap();
            let mut law = model.force_law();
            (model.restitution(v0).unwrap(), simulate_impact(&mut law, m, v0, &settings).unwrap())
        };
        prop_assert!(!sim.sticks);
        prop_assert!(((sim.restitution - analytic) / analytic).abs() < 1e-6,
            "sim {} vs analytic {analytic}", sim.restitution);
        prop_assert!(sim.energy_error < 1e-8);
        let kinds: Vec<_> = sim.events.iter().map(|ev| ev.kind).collect();
        prop_assert_eq!(kinds, vec![EventKind::MaxCompression, EventKind::BranchEnd]);
    }
}

#[test]
fn simulated_residual_depth_equals_the_closed_form() {
    // The separation event sits at d_res (5.105)/(3.274); 1e-8 relative.
    let contact = PlasticContact::new(1e11, 1e-3, 3e8).unwrap();
    let model = PlasticImpact::new(contact, Interpolation::default(), 1e-5).unwrap();
    let v0 = 20.0 * model.yield_velocity();
    let mut law = model.force_law();
    let sim = simulate_impact(&mut law, 1e-5, v0, &SimulationSettings::default()).unwrap();
    let d_res = model.residual_depth(v0).unwrap();
    let end = sim.events.last().unwrap().overlap;
    assert!(((end - d_res) / d_res).abs() < 1e-8, "{end} vs {d_res}");
    let d_max = model.max_depth(v0).unwrap();
    assert!(((sim.max_overlap - d_max) / d_max).abs() < 1e-8);
}

/// Jackson-Green by quadrature: W(d_max) = m v0²/2 (Brent on the quadrature of the
/// loading law), rebound (2/5) F_max (d_max − d_res), restitution sqrt(rebound/kinetic).
fn jackson_green_by_quadrature(jg: &JacksonGreen, m: f64, v0: f64) -> f64 {
    let onset = FIT_ONSET * jg.yield_depth();
    let f = |d: f64| jg.loading_force(d).unwrap();
    let tol = QuadTolerance::relative(1e-13);
    let work = |d: f64| {
        if d <= onset {
            integrate_smooth(f, 0.0, d, tol).unwrap().value
        } else {
            integrate_smooth(f, 0.0, onset, tol).unwrap().value
                + integrate_smooth(f, onset, d, tol).unwrap().value
        }
    };
    let kinetic = 0.5 * m * v0 * v0;
    let mut hi = jg.yield_depth();
    while work(hi) < kinetic {
        hi *= 2.0;
    }
    let d_max = brent(
        |d| work(d) - kinetic,
        0.0,
        hi,
        RootTolerance::relative(1e-14),
    )
    .unwrap()
    .value;
    let d_res = jg.residual_depth(d_max).unwrap();
    let rebound = 0.4 * f(d_max) * (d_max - d_res);
    (rebound / kinetic).sqrt()
}

#[test]
fn jackson_green_simulation_equals_quadrature() {
    // Tolerance 1e-7 relative (both paths are converged to ~1e-10).
    let jg = PlasticContact::new(1.4e11, 2.5e-3, 1.03e9)
        .and_then(|contact| JacksonGreen::new(contact, 0.29))
        .unwrap();
    let m = 2.5e-4;
    let model = jg.impact(m, SimulationSettings::default()).unwrap();
    let v_y = model.yield_velocity();
    for &s in &[0.5, 1.2, 1.9, 3.0, 10.0, 100.0, 1000.0] {
        let v0 = s * v_y;
        let sim = impact(&model, v0).unwrap().restitution;
        let quad = jackson_green_by_quadrature(&jg, m, v0);
        assert!(
            ((sim - quad) / quad).abs() < 1e-7,
            "v0/v*_Y = {s}: {sim} vs {quad}"
        );
    }
    // Below v*_Y the impact is elastic: eps = 1 within the integration error.
    let e = impact(&model, 0.9 * v_y).unwrap().restitution;
    assert!((1.0 - e).abs() < 1e-9, "{e}");
}

#[test]
fn jackson_green_yield_velocity_is_the_hertz_speed_at_the_critical_depth() {
    // (5.108) v*_Y = v_Y (5C/8)^(5/2) vs m v*²/2 = (2/5) F*_Y d*_Y. 1e-12 relative.
    let jg = PlasticContact::new(7e10, 1e-3, 3.8e8)
        .and_then(|contact| JacksonGreen::new(contact, 0.33))
        .unwrap();
    let m = 1e-5;
    let v = jg.yield_velocity(m).unwrap();
    let direct = (0.8 * jg.yield_force() * jg.yield_depth() / m).sqrt();
    assert!(((v - direct) / direct).abs() < 1e-12);
}

#[test]
fn jackson_green_restitution_depends_on_v0_over_v_star_only() {
    // Seed 000: independent of R and m, almost independent of sigma_Y/E and nu.
    // Exact invariance in R and m (1e-8), weak dependence on sigma_Y/E (< 3 %).
    let base = |e: f64, r: f64, s: f64, m: f64, ratio: f64| {
        let jg = PlasticContact::new(e, r, s)
            .and_then(|contact| JacksonGreen::new(contact, 0.3))
            .unwrap();
        let model = jg.impact(m, SimulationSettings::default()).unwrap();
        impact(&model, ratio * model.yield_velocity())
            .unwrap()
            .restitution
    };
    for &ratio in &[3.0, 30.0] {
        let a = base(1e11, 1e-3, 2e8, 1e-5, ratio);
        let b = base(1e11, 7e-2, 2e8, 3e-1, ratio);
        assert!(((a - b) / a).abs() < 1e-8, "{a} vs {b}");
        let c = base(1e11, 1e-3, 4e8, 1e-5, ratio);
        assert!(((a - c) / a).abs() < 3e-2, "{a} vs {c}");
    }
}

#[test]
fn adhesive_interpolation_simulation_equals_analytic() {
    // The adhesive force law (JKR loading with jump-in, cubic, plastic; JKR unloading,
    // snap-off at (5.125)) vs the analytic restitution. 1e-6 relative.
    for &(phi, ratio) in &[
        (0.5, 3.0),
        (1.0, 1.5),
        (1.0, 10.0),
        (0.3, 100.0),
        (2.5, 5.0),
    ] {
        let model = AdhesiveInterpolationImpact::new(
            AdhesivePlasticContact::new(JkrSphere::new(1e11, 1e-5, 0.5).unwrap(), phi).unwrap(),
            1e-13,
        )
        .unwrap();
        let v0 = ratio * model.elastic_sticking_velocity();
        let analytic = impact(&model, v0).unwrap().restitution;
        let mut law = model.force_law();
        let sim = simulate_impact(&mut law, 1e-13, v0, &SimulationSettings::default()).unwrap();
        assert!(
            ((sim.restitution - analytic) / analytic).abs() < 1e-6,
            "phi = {phi}, v0/v_c = {ratio}: sim {} vs {analytic}",
            sim.restitution
        );
        let _ = model.effective_mass();
    }
    let _ = AdhesiveInterpolation::new(1.0).unwrap();
}
