//! Energy balance of the time-domain simulation against the analytic losses of the
//! same models (issue: simulated rebound energy equals the analytic restitution to
//! 1e-6 relative), and the sticking boundary against the analytic sticking velocity.
//!
//! The Maugis-Dugdale property test covers Λ ∈ [0.2, 50] (all three cases). Below
//! Λ ≈ 0.2 the loss, 11.6 Λ⁵ F_n d_n, is less than 1e-3 of the depth of the adhesive
//! well the sphere falls through on its way in and climbs out of on its way back:
//! the simulated restitution is then a small difference of two large energies and
//! needs an integrator tolerance of about 1e-6 × (loss / well depth) to reach 1e-6.
//! `small_lambda_needs_a_tighter_tolerance` shows that explicitly; the property
//! test therefore asks the integrator for 1e-13 below Λ = 0.5 (at the default 1e-11
//! a draw at Λ = 0.217 near sticking was 1.8e-6 off while the kink of F(d) at the
//! junction of the contact and no-contact branches was stepped over; located as an
//! event since, it is 1.6e-9 off).
#![allow(clippy::unwrap_used, clippy::expect_used)]

use proptest::prelude::*;
use tabor::dynamics::{simulate_impact, SimulationSettings};
use tabor::jkr::{JkrForceLaw, JkrImpact, JkrSphere, SeparationRule};
use tabor::maugis::{MaugisContact, MaugisDugdaleForceLaw, MaugisDugdaleImpact};
use tabor::restitution::{impact, sticking_velocity, ImpactModel};

fn sphere_mass(radius: f64, density: f64) -> f64 {
    4.0 / 3.0 * std::f64::consts::PI * radius.powi(3) * density
}

fn settings() -> SimulationSettings {
    SimulationSettings {
        record_trajectory: false,
        ..SimulationSettings::default()
    }
}

/// Simulated vs analytic restitution of a model at `factor` × its sticking velocity.
fn compare<L: tabor::dynamics::ForceLaw, M: ImpactModel>(
    law: &mut L,
    model: &M,
    factor: f64,
) -> (f64, f64) {
    compare_at(law, model, factor, None)
}

/// [`compare`] with the integrator's relative tolerance `tolerance` (absolute a
/// hundredth of it) instead of the default.
fn compare_at<L: tabor::dynamics::ForceLaw, M: ImpactModel>(
    law: &mut L,
    model: &M,
    factor: f64,
    tolerance: Option<f64>,
) -> (f64, f64) {
    let vc = sticking_velocity(model, 1e-12).unwrap().speed;
    let v0 = factor * vc;
    let analytic = impact(model, v0).unwrap().restitution;
    let mut s = settings();
    if let Some(t) = tolerance {
        s.tolerance.relative = t;
        s.tolerance.absolute = t / 100.0;
    }
    let sim = simulate_impact(law, model.effective_mass(), v0, &s).unwrap();
    assert!(!sim.sticks);
    (sim.restitution, analytic)
}

proptest! {
    #![proptest_config(ProptestConfig { cases: std::env::var("PROPTEST_CASES").ok().and_then(|c| c.parse().ok()).unwrap_or(32), ..ProptestConfig::default() })]

    #[test]
    fn jkr_simulation_matches_the_analytic_restitution(
        log_e in 6.0f64..12.0, log_r in -8.0f64..-2.0, log_w in -3.0f64..0.0,
        density in 500.0f64..10000.0, factor in 1.05f64..20.0, load_controlled in any::<bool>(),
    ) {
        let (e, r, w) = (10f64.powf(log_e), 10f64.powf(log_r), 10f64.powf(log_w));
        let rule = if load_controlled { SeparationRule::LoadControlled } else { SeparationRule::FixedGrip };
        let sphere = JkrSphere::new(e, r, w).unwrap();
        let model = JkrImpact::new(sphere, sphere_mass(r, density)).unwrap().with_separation(rule);
        let mut law = JkrForceLaw::new(sphere, rule);
        let (sim, analytic) = compare(&mut law, &model, factor);
        prop_assert!((sim / analytic - 1.0).abs() <= 1e-6, "sim {sim} analytic {analytic}");
    }

    #[test]
    fn maugis_simulation_matches_the_analytic_restitution(
        log_e in 6.0f64..12.0, log_r in -8.0f64..-2.0, log_w in -3.0f64..0.0,
        log_lambda in -0.7f64..1.7, density in 500.0f64..10000.0, factor in 1.05f64..20.0,
    ) {
        let (e, r, w, l) = (10f64.powf(log_e), 10f64.powf(log_r), 10f64.powf(log_w), 10f64.powf(log_lambda));
        let model = MaugisDugdaleImpact::new(MaugisContact::new(JkrSphere::new(e, r, w).unwrap(), l).unwrap(), sphere_mass(r, density)).unwrap();
        let mut law = MaugisDugdaleForceLaw::new(&model).unwrap();
        // below Λ = 0.5 the loss is a small difference of the well's energies (see
        // the module docs): the integrator is asked for 1e-13 there, as
        // `small_lambda_needs_a_tighter_tolerance` shows it must be; at the default
        // 1e-11, Λ = 0.2172, E = 1e6 Pa, R = 1 cm, w = 1 J/m², 1.13 v_c is 1.8e-6 off
        // (`the_default_tolerance_misses_at_small_lambda_near_sticking`)
        let tolerance = if l < 0.5 { Some(1e-13) } else { None };
        let (sim, analytic) = compare_at(&mut law, &model, factor, tolerance);
        prop_assert!((sim / analytic - 1.0).abs() <= 1e-6, "Λ={l}: sim {sim} analytic {analytic}");
    }
}

#[test]
fn maugis_all_three_cases_and_the_sticking_boundary() {
    // two silica spheres, Λ chosen in each case
    let (e, r, w) = (2.78e10, 0.5e-6, 0.05);
    let m = 5.55e-15;
    for lambda in [0.3, 0.55, 2.0, 50.0] {
        let model = MaugisDugdaleImpact::new(
            MaugisContact::new(JkrSphere::new(e, r, w).unwrap(), lambda).unwrap(),
            m,
        )
        .unwrap();
        let mut law = MaugisDugdaleForceLaw::new(&model).unwrap();
        let vc = sticking_velocity(&model, 1e-12).unwrap().speed;
        let below = simulate_impact(&mut law, m, vc * (1.0 - 1e-4), &settings()).unwrap();
        let above = simulate_impact(&mut law, m, vc * (1.0 + 1e-4), &settings()).unwrap();
        assert!(below.sticks, "Λ={lambda}");
        assert!(!above.sticks, "Λ={lambda}");
        // ε(v_c(1+δ)) ≈ √(2δ)
        let expected = (1.0 - 1.0 / (1.0f64 + 1e-4).powi(2)).sqrt();
        assert!(
            (above.restitution / expected - 1.0).abs() < 1e-3,
            "Λ={lambda}: {}",
            above.restitution
        );
        let (sim, analytic) = compare(&mut law, &model, 3.0);
        assert!(
            (sim / analytic - 1.0).abs() <= 1e-7,
            "Λ={lambda}: {sim} vs {analytic}"
        );
    }
}

#[test]
fn jkr_sticking_boundary_both_rules() {
    let sphere = JkrSphere::new(2.78e10, 0.5e-6, 0.05).unwrap();
    let m = 5.55e-15;
    for rule in [SeparationRule::FixedGrip, SeparationRule::LoadControlled] {
        let model = JkrImpact::new(sphere, m).unwrap().with_separation(rule);
        let mut law = JkrForceLaw::new(sphere, rule);
        let vc = sticking_velocity(&model, 1e-12).unwrap().speed;
        assert!(
            simulate_impact(&mut law, m, vc * (1.0 - 1e-4), &settings())
                .unwrap()
                .sticks
        );
        assert!(
            !simulate_impact(&mut law, m, vc * (1.0 + 1e-4), &settings())
                .unwrap()
                .sticks
        );
    }
}

#[test]
fn small_lambda_needs_a_tighter_tolerance() {
    // Λ = 0.05: W ≈ 3.6e-6 F_n d_n; at the default tolerance 1e-11 the error is
    // percent-level, at 1e-13 it is below 1e-3 (a hard case documented above)
    let (e, r, w) = (1e6, 1e-2, 1.0);
    let m = sphere_mass(r, 500.0);
    let model = MaugisDugdaleImpact::new(
        MaugisContact::new(JkrSphere::new(e, r, w).unwrap(), 0.0505).unwrap(),
        m,
    )
    .unwrap();
    let mut law = MaugisDugdaleForceLaw::new(&model).unwrap();
    let v0 = 1.05 * sticking_velocity(&model, 1e-12).unwrap().speed;
    let analytic = impact(&model, v0).unwrap().restitution;
    let mut s = settings();
    s.tolerance.relative = 1e-13;
    s.tolerance.absolute = 1e-15;
    let sim = simulate_impact(&mut law, m, v0, &s).unwrap();
    assert!(
        (sim.restitution / analytic - 1.0).abs() < 1e-3,
        "{} vs {analytic}",
        sim.restitution
    );
}

#[test]
fn penalty_bridge_reproduces_plastic_and_viscoelastic_restitution() {
    // Issue 11's bridge for the non-adhesive models: the calibrated Hunt-Crossley
    // form with the Hertz stiffness of the same bodies, and seed 002's
    // characteristic, rebound in a simulated impact with the model's restitution
    // at the calibration speed (1e-6; the first integrals are exact).
    use tabor::penalty::{calibrate_characteristic, calibrate_damped_law, PenaltyStiffness};
    use tabor::plastic::{Interpolation, PlasticContact, PlasticImpact, Thornton};
    use tabor::visco::models::KelvinVoigtSphere;
    use tabor::visco::SphereModel;

    let check = |model: &dyn ImpactModel, v0: f64, e: f64, r: f64| {
        let target = impact(model, v0).unwrap().restitution;
        assert!(target > 0.0 && target < 1.0, "{}: {target}", model.name());
        let hertz = PenaltyStiffness::hertz(e, r).unwrap();
        let c = calibrate_damped_law(model, v0, hertz, &settings()).unwrap();
        assert!(
            (c.achieved_restitution - target).abs() < 1e-6,
            "{}: {} vs {target}",
            model.name(),
            c.achieved_restitution
        );
        let c = calibrate_characteristic(model, v0, 1e6, 1e-9, &settings()).unwrap();
        assert!(
            (c.achieved_restitution - target).abs() < 1e-6,
            "{}: {} vs {target}",
            model.name(),
            c.achieved_restitution
        );
    };
    // alumina on steel (seed 000 Table 5.2)
    let (e, r, m) = (1.4e11, 2.5e-3, 2.5e-4);
    let contact = PlasticContact::new(e, r, 1.03e9).unwrap();
    for v0 in [0.5, 3.0] {
        check(&PlasticImpact::new(contact, Thornton, m).unwrap(), v0, e, r);
        check(
            &PlasticImpact::new(contact, Interpolation::default(), m).unwrap(),
            v0,
            e,
            r,
        );
    }
    // steel ball on a Kelvin-Voigt rubber half-space
    let (e, r) = (2e7, 5e-3);
    let visco = KelvinVoigtSphere::new(
        e / 4.0,
        50.0,
        r,
        sphere_mass(r, 7850.0),
        SphereModel::Rigorous,
    )
    .unwrap();
    check(&visco, 1.0, e, r);
}

#[test]
fn the_junction_of_the_branches_is_located_at_small_lambda_near_sticking() {
    // the case the property test drew (CI, 2026-11-24): at the default integrator
    // tolerance the simulated restitution was 1.8e-6 off the analytic one while the
    // kink of F(d) at the junction of the contact and no-contact branches was
    // stepped over; located as an event (tabor-maugis, the law's parts), it agrees
    // to 1.6e-9 at the default tolerance (ε = 0.47 at 1.13 v_c: the loss is
    // 0.78 of the kinetic energy), and at 1e-13 to 1e-9
    let (e, r, w) = (1e6, 1e-2, 1.0);
    let model = MaugisDugdaleImpact::new(
        MaugisContact::new(JkrSphere::new(e, r, w).unwrap(), 0.2171940525330137).unwrap(),
        sphere_mass(r, 500.0),
    )
    .unwrap();
    let mut law = MaugisDugdaleForceLaw::new(&model).unwrap();
    let (sim, analytic) = compare(&mut law, &model, 1.1322904158807994);
    assert!(
        (sim / analytic - 1.0).abs() < 1e-8,
        "sim {sim} analytic {analytic}"
    );
    let mut law = MaugisDugdaleForceLaw::new(&model).unwrap();
    let (sim, analytic) = compare_at(&mut law, &model, 1.1322904158807994, Some(1e-13));
    assert!(
        (sim / analytic - 1.0).abs() < 1e-9,
        "sim {sim} analytic {analytic}"
    );
}
