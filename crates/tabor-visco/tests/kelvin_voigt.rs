//! Kelvin-Voigt medium: flat-punch closed forms against direct integration of
//! (5.54), continuity through D = 1, the sphere models against (5.71), the
//! generalized damping law and the seed's statements.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use tabor_numerics::ode::{solve_until_event, EventDirection, OdeTolerance};
use tabor_restitution::{impact, ImpactModel};
use tabor_visco::models::{KelvinVoigtFlatPunch, KelvinVoigtSphere};
use tabor_visco::{damping_law, kelvin_voigt_flat, kelvin_voigt_sphere, SphereModel};

/// Direct integration of the scaled (5.54), ẍ + 2Dẋ + x = 0, x(0) = 0, ẋ(0) = 1,
/// to the zero of the force x + 2Dẋ: (ε, ω0 T_S). Independent of the closed form.
fn flat_punch_by_ode(d: f64) -> (f64, f64) {
    let sol = solve_until_event(
        |_t, y: &[f64; 2]| [y[1], -y[0] - 2.0 * d * y[1]],
        |_t, y: &[f64; 2]| y[0] + 2.0 * d * y[1],
        EventDirection::Falling,
        0.0,
        [0.0, 1.0],
        1e4,
        OdeTolerance::new(1e-12, 1e-14).with_max_step(0.01),
    )
    .unwrap();
    assert!(sol.event_found, "D = {d}: no separation");
    (-sol.y[1], sol.t)
}

#[test]
fn flat_punch_closed_forms_match_direct_integration() {
    // Tolerance 1e-8 absolute on ε and relative on T_S (ODE at 1e-12).
    for &d in &[
        1e-3, 0.01, 0.1, 0.3, 0.5, 0.9, 0.99, 0.999, 1.0, 1.001, 1.01, 1.1, 1.5, 2.0, 5.0, 20.0,
    ] {
        let (eps_ode, t_ode) = flat_punch_by_ode(d);
        let eps = kelvin_voigt_flat::restitution(d).unwrap();
        let t = kelvin_voigt_flat::contact_time(d).unwrap();
        assert!(
            (eps - eps_ode).abs() < 1e-8,
            "D = {d}: {eps} vs ODE {eps_ode}"
        );
        assert!(
            (t - t_ode).abs() < 1e-8 * t_ode,
            "D = {d}: T {t} vs ODE {t_ode}"
        );
        // (5.61): ε = exp(−D ω0 T_S).
        assert!((eps - (-d * t).exp()).abs() < 1e-14);
    }
}

#[test]
fn flat_punch_limits() {
    // D → 0: ε ≈ exp(−πD); D → ∞: ε ≈ 1/(4D²) (from (5.62)).
    let d = 1e-8;
    let e = kelvin_voigt_flat::restitution(d).unwrap();
    assert!((e - (-std::f64::consts::PI * d).exp()).abs() < 1e-15);
    let d = 1e6;
    let e = kelvin_voigt_flat::restitution(d).unwrap();
    assert!((e * 4.0 * d * d - 1.0).abs() < 1e-4, "{e}");
    let e = kelvin_voigt_flat::restitution(1e150).unwrap();
    assert!(e.is_finite() && e >= 0.0);
}

#[test]
fn flat_punch_is_continuous_through_critical_damping() {
    let e1 = kelvin_voigt_flat::restitution(1.0).unwrap();
    // (5.63): ε(1) = e⁻², to rounding.
    assert!((e1 - (-2.0_f64).exp()).abs() < 1e-16, "{e1}");
    // dε/dD at 1 is −(4/3) e⁻² ≈ −0.18 (series of (5.61)): a step of 1e-9 moves ε
    // by ~1.8e-10. Tolerance 3e-10.
    for &h in &[1e-9, 1e-12, 1e-15] {
        for &d in &[1.0 - h, 1.0 + h] {
            let e = kelvin_voigt_flat::restitution(d).unwrap();
            assert!(e.is_finite());
            assert!(
                (e - e1).abs() < 3e-10 * (h / 1e-9).max(1e-6),
                "D = {d}: {e}"
            );
        }
    }
    // Slope from both sides equals −(4/3)e⁻² to 5e-5 (no kink at the switch to the
    // series, |1 − D²|/D² = 0.05).
    let slope = -4.0 / 3.0 * (-2.0_f64).exp();
    for &d in &[1.0 - 1e-4, 1.0 + 1e-4] {
        let s = (kelvin_voigt_flat::restitution(d).unwrap() - e1) / (d - 1.0);
        // One-sided quotient: O(h) curvature error, observed 1.7e-5.
        assert!((s - slope).abs() < 5e-5, "slope {s} vs {slope}");
    }
    // Across the series/closed-form switch: smooth to 1e-12 (compare with ODE).
    for &d in &[0.975, 0.976, 1.024, 1.025, 1.026] {
        let (eps_ode, _) = flat_punch_by_ode(d);
        assert!((kelvin_voigt_flat::restitution(d).unwrap() - eps_ode).abs() < 1e-8);
    }
}

#[test]
fn flat_punch_physical_front_agrees_with_core() {
    // G = 1 MPa, η = 100 Pa s, a = 1 cm, m = 0.1 kg: D = η √(2a/(mG)) ≈ 0.0447.
    let model = KelvinVoigtFlatPunch::new(1e6, 100.0, 0.01, 0.1).unwrap();
    let d = 100.0 * (2.0 * 0.01 / (0.1 * 1e6_f64)).sqrt();
    assert!((model.damping_ratio() - d).abs() < 1e-15);
    for v in [0.01, 1.0, 30.0] {
        let out = impact(&model, v).unwrap();
        let core = kelvin_voigt_flat::restitution(d).unwrap();
        assert!((out.restitution - core).abs() < 1e-12);
    }
}

#[test]
fn kuwabara_kono_matches_first_order_for_small_delta() {
    // (5.71) is the first-order term: the remainder is O(δ²) (observed remainder/loss
    // ≈ 2δ). Tolerance: remainder/loss below 3δ, i.e. below 3 % for δ ≤ 0.01.
    for &delta in &[1e-4, 1e-3, 3e-3, 1e-2] {
        let e = kelvin_voigt_sphere::restitution(delta, SphereModel::KuwabaraKono).unwrap();
        let lin = kelvin_voigt_sphere::first_order_restitution(delta).unwrap();
        let loss = 1.0 - lin;
        let rel = (e - lin).abs() / loss;
        println!("delta {delta:e}: KK {e:.9}, (5.71) {lin:.9}, remainder/loss {rel:.2e}");
        assert!(rel < 3.0 * delta, "δ = {delta}: {e} vs {lin}");
        // Seed: to first order Kuwabara-Kono equals the rigorous description, so
        // (5.71) is the first-order term of the rigorous model too (observed
        // remainder/loss ≈ 2.7δ; asserted < 4δ).
        let rig = kelvin_voigt_sphere::restitution(delta, SphereModel::Rigorous).unwrap();
        let rel_rig = (rig - lin).abs() / loss;
        println!("           rigorous {rig:.9}, remainder/loss {rel_rig:.2e}");
        assert!(
            rel_rig < 4.0 * delta,
            "δ = {delta}: rigorous {rig} vs {lin}"
        );
    }
}

#[test]
fn rigorous_model_gives_slightly_higher_restitution_than_kuwabara_kono() {
    // Seed, Fig. 5.4: Kuwabara-Kono underestimates ε systematically, but only slightly.
    // Observed largest gap ≈ 0.025 near δ ≈ 1; asserted < 0.04.
    for &delta in &[1e-3, 1e-2, 0.1, 0.3, 1.0, 3.0, 10.0] {
        let kk = kelvin_voigt_sphere::restitution(delta, SphereModel::KuwabaraKono).unwrap();
        let rig = kelvin_voigt_sphere::restitution(delta, SphereModel::Rigorous).unwrap();
        println!("delta {delta:e}: KK {kk:.6}, rigorous {rig:.6}");
        assert!(rig > kk, "δ = {delta}: rigorous {rig} <= KK {kk}");
        assert!(rig - kk < 0.04, "δ = {delta}");
    }
}

#[test]
fn kuwabara_kono_equals_damping_law_with_exponent_one_half() {
    // (5.72) with β = 1/2, λ = 8η√R is (5.66); γ = 8 (15/64)^(3/5) δ. A separate code
    // path (generic exponent, event on F/x^β). Tolerance 1e-8.
    for &delta in &[1e-3, 0.1, 1.0, 5.0] {
        let kk = kelvin_voigt_sphere::restitution(delta, SphereModel::KuwabaraKono).unwrap();
        let gamma = 8.0 * (15.0_f64 / 64.0).powf(0.6) * delta;
        let law = damping_law::restitution(0.5, gamma).unwrap();
        assert!((kk - law).abs() < 1e-8, "δ = {delta}: {kk} vs {law}");
    }
}

#[test]
fn tsuji_restitution_depends_on_alpha_only() {
    // (5.73): λ = α (m G √R)^(1/2) gives a γ independent of m, v0, G, R.
    let alpha = 0.7;
    let expected = damping_law::tsuji_damping(alpha).unwrap();
    for &(m, v, g, r) in &[
        (1e-3, 0.1, 1e6, 1e-3),
        (10.0, 5.0, 1e9, 0.2),
        (0.2, 1e-3, 3e4, 0.05),
    ] {
        let lambda = alpha * (m * g * f64::sqrt(r)).sqrt();
        let gamma = damping_law::scaled_damping(lambda, 0.25, m, v, g, r).unwrap();
        assert!(
            (gamma - expected).abs() < 1e-12 * expected,
            "{gamma} vs {expected}"
        );
    }
    let e = damping_law::restitution(0.25, expected).unwrap();
    assert!(e > 0.0 && e < 1.0);
}

#[test]
fn damping_laws_separate_and_lose_energy() {
    // Small damping: every law ~ elastic; ε decreases with γ.
    for law in [
        damping_law::DampingLaw::LeeHerrmann,
        damping_law::DampingLaw::Tsuji,
        damping_law::DampingLaw::HuntCrossley,
    ] {
        let b = law.exponent();
        let mut last = 1.0;
        for &g in &[1e-4, 1e-2, 0.1, 1.0, 10.0] {
            let e = damping_law::restitution(b, g).unwrap();
            assert!(e < last && e >= 0.0, "{law:?} γ = {g}: {e}");
            last = e;
        }
        assert!(damping_law::restitution(b, 1e-4).unwrap() > 0.999);
    }
}

#[test]
fn sphere_physical_front_uses_delta() {
    // δ from (5.68) and ε of the core, through ImpactModel.
    let model = KelvinVoigtSphere::new(1e6, 50.0, 0.02, 0.05, SphereModel::Rigorous).unwrap();
    for v in [0.1, 1.0] {
        let delta = 50.0 * (0.02 * v / (0.05_f64.powi(2) * 1e18)).powf(0.2);
        assert!((model.viscous_parameter(v).unwrap() - delta).abs() < 1e-12 * delta);
        let out = impact(&model, v).unwrap();
        // The physical front integrates at 1e-9 and takes the loss from the
        // dissipated energy (1 − ε accurate relative to itself), the core's ε from the
        // rebound speed: the two agree to the tolerance (3.4e-11 observed at v = 1),
        // and within 1e-6 of the core at its default 1e-10.
        let front_delta = model.viscous_parameter(v).unwrap();
        let core = kelvin_voigt_sphere::solve(front_delta, SphereModel::Rigorous, 1e-9).unwrap();
        assert!(
            (out.restitution - core.restitution).abs() < 1e-9,
            "{} vs {}",
            out.restitution,
            core.restitution
        );
        let fine = kelvin_voigt_sphere::restitution(delta, SphereModel::Rigorous).unwrap();
        assert!(
            (out.restitution - fine).abs() < 1e-6,
            "{} vs {fine}",
            out.restitution
        );
        assert!(model.name().contains("rigorous"));
    }
}

#[test]
fn scaled_trajectory_starts_elastic_and_ends_at_zero_force() {
    let pts = kelvin_voigt_sphere::trajectory(0.05, SphereModel::Rigorous, 1e-10).unwrap();
    let first = pts[0];
    assert_eq!(
        (first.time, first.overlap, first.overlap_rate),
        (0.0, 0.0, 1.0)
    );
    let last = pts[pts.len() - 1];
    assert!(last.force.abs() < 1e-8, "{}", last.force);
    let imp = kelvin_voigt_sphere::solve(0.05, SphereModel::Rigorous, 1e-10).unwrap();
    assert!((last.time - imp.contact_time).abs() < 1e-12);
    assert!((-last.overlap_rate - imp.restitution).abs() < 1e-12);
    // Largest overlap below the elastic d0 = 1.
    let max = pts.iter().map(|p| p.overlap).fold(0.0, f64::max);
    assert!(max < 1.0 && (max - imp.max_overlap).abs() < 1e-9);
}

#[test]
fn inverse_recovers_delta() {
    for model in [SphereModel::KuwabaraKono, SphereModel::Rigorous] {
        for &eps in &[0.71, 0.56] {
            let delta =
                kelvin_voigt_sphere::viscous_parameter_for_restitution(eps, model, 1e-10).unwrap();
            let back = kelvin_voigt_sphere::restitution(delta, model).unwrap();
            assert!((back - eps).abs() < 1e-8, "{model:?}: {back} vs {eps}");
        }
    }
}
