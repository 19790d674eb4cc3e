#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Seed 002's contact characteristic: C¹ rounding, the loss factor, the impact
//! restitution against simulation, and the hysteresis area against quadrature.

use tabor_dynamics::{simulate_impact, SimulationSettings};
use tabor_numerics::quadrature::integrate_smooth;
use tabor_numerics::QuadTolerance;
use tabor_penalty::{
    characteristic_loss_speed, characteristic_restitution, contact_characteristic, loss_factor,
    ContactCharacteristic,
};

fn settings() -> SimulationSettings {
    SimulationSettings {
        record_trajectory: false,
        ..SimulationSettings::default()
    }
}

#[test]
fn rounded_characteristic_is_c1_at_plus_minus_epsilon() {
    // Values and one-sided difference quotients (step 1e-7 ε) agree across ±ε to
    // 1e-6 ε (value) and 1e-6 (slope; the quotients' own error is ~h/ε = 1e-7).
    for &eps in &[1e-3, 0.25, 0.5, 2.0] {
        let k = |h: f64| contact_characteristic(h, eps).unwrap();
        let step = 1e-7 * eps;
        for &edge in &[-eps, eps] {
            let left = (k(edge) - k(edge - step)) / step;
            let right = (k(edge + step) - k(edge)) / step;
            assert!(
                (left - right).abs() < 1e-6,
                "slope jump at {edge}: {left} vs {right}"
            );
            assert!((k(edge - step) - k(edge + step)).abs() < 3.0 * step);
            let expected_slope = if edge < 0.0 { -1.0 } else { 0.0 };
            assert!((left - expected_slope).abs() < 1e-6);
        }
        // Seed 002's matching conditions: κ(ε) = 0, κ(−ε) = ε (continuity with −h).
        assert!(k(eps).abs() < 1e-15 * eps.max(1.0));
        assert!((k(-eps) - eps).abs() < 1e-15 * eps.max(1.0));
        // Outside the rounding zone: exactly the piecewise-linear law.
        for &h in &[-10.0 * eps, -1.0001 * eps, 1.0001 * eps, 7.0 * eps] {
            let piecewise = contact_characteristic(h, 0.0).unwrap();
            assert_eq!(k(h), piecewise, "h = {h}");
            assert_eq!(piecewise, if h < 0.0 { -h } else { 0.0 });
        }
        // Inside, the rounding lies above the kink and is convex.
        for i in 1..20 {
            let h = -eps + 2.0 * eps * f64::from(i) / 20.0;
            assert!(k(h) > contact_characteristic(h, 0.0).unwrap());
        }
    }
}

#[test]
fn loss_factor_is_c1_and_matches_the_seed_branches() {
    let big_v = 3.0;
    assert_eq!(loss_factor(-1.5, big_v).unwrap(), 1.5);
    assert_eq!(loss_factor(1.5, big_v).unwrap(), 1.0 / 1.5);
    assert_eq!(loss_factor(0.0, big_v).unwrap(), 1.0);
    let step = 1e-7;
    let left = (loss_factor(0.0, big_v).unwrap() - loss_factor(-step, big_v).unwrap()) / step;
    let right = (loss_factor(step, big_v).unwrap() - loss_factor(0.0, big_v).unwrap()) / step;
    assert!((left + 1.0 / big_v).abs() < 1e-8 && (right + 1.0 / big_v).abs() < 1e-7);
    assert_eq!(loss_factor(-7.0, f64::INFINITY).unwrap(), 1.0);
}

#[test]
fn restitution_tends_to_one_and_falls_monotonically_as_v_decreases() {
    let v0 = 1.0;
    // V → ∞: 1 − e ≈ (2/3) v0/V (series of e²/2 + r e³/3 = ψ(r)), to 1e-3 relative.
    for &big_v in &[1e3, 1e6, 1e9] {
        let e = characteristic_restitution(v0, big_v).unwrap();
        let r = v0 / big_v;
        assert!(
            ((1.0 - e) / (2.0 * r / 3.0) - 1.0).abs() < 2e-3,
            "V = {big_v}: {e}"
        );
    }
    assert_eq!(characteristic_restitution(v0, f64::INFINITY).unwrap(), 1.0);
    // Monotone over 24 decades of V, strictly falling as V decreases.
    let mut previous = 1.0;
    for i in 0..=96 {
        let big_v = 10f64.powf(12.0 - 0.25 * f64::from(i));
        let e = characteristic_restitution(v0, big_v).unwrap();
        assert!(
            e < previous,
            "not falling at V = {big_v}: {e} >= {previous}"
        );
        assert!(e > 0.0);
        previous = e;
    }
    // V → 0: e ≈ (3/r²)^(1/3) to leading order (next term relative O(r^(-1/3)) ~ 1e-4·ln).
    let r: f64 = 1e12;
    let e = characteristic_restitution(r, 1.0).unwrap();
    assert!((e / (3.0 / (r * r)).cbrt() - 1.0).abs() < 1e-3, "{e}");
}

#[test]
fn simulated_impacts_reproduce_the_closed_form_restitution() {
    // Independent path: the time-domain simulator integrates F = k κ l. The closed
    // form says k, ε and m do not matter; tolerance 1e-8 (simulator at 1e-11).
    let v0 = 0.7;
    for &(k, eps, m, big_v) in &[
        (1e5, 0.0, 1.0, 2.0),
        (1e5, 1e-4, 1.0, 2.0),
        (3e2, 5e-2, 0.01, 0.1),
        (1e8, 1e-7, 5.0, 30.0),
        (1e3, 0.0, 2.0, 0.01),
    ] {
        let mut law = ContactCharacteristic::new(k, eps, big_v).unwrap();
        let sim = simulate_impact(&mut law, m, v0, &settings()).unwrap();
        let closed = law.restitution(v0).unwrap();
        assert!(
            (sim.restitution - closed).abs() < 1e-8,
            "k {k} eps {eps} m {m} V {big_v}: simulated {} closed {closed}",
            sim.restitution
        );
        // Energy bookkeeping: the simulated contact work is the lost kinetic energy.
        assert!(sim.energy_error < 1e-8);
        assert!(!sim.sticks);
    }
}

#[test]
fn calibrated_loss_speed_gives_the_target_restitution_in_simulation() {
    for &target in &[0.05, 0.2, 0.5, 0.8, 0.99] {
        let v0 = 2.5;
        let big_v = characteristic_loss_speed(target, v0).unwrap();
        let mut law = ContactCharacteristic::new(4e4, 1e-3, big_v).unwrap();
        let sim = simulate_impact(&mut law, 0.3, v0, &settings()).unwrap();
        assert!(
            (sim.restitution - target).abs() < 1e-8,
            "{target}: {}",
            sim.restitution
        );
    }
    assert_eq!(characteristic_loss_speed(1.0, 1.0).unwrap(), f64::INFINITY);
}

/// The hysteresis area ∮ F d(−h) over h = H cos φ, integrated here over the whole
/// cycle directly from the public force (closing and opening halves separately),
/// an independent path to the library's closed form and paired quadrature.
fn cycle_area_by_quadrature(law: &ContactCharacteristic, big_h: f64, omega: f64) -> f64 {
    let eps = law.rounding();
    let integrand = |phi: f64| {
        let (s, c) = phi.sin_cos();
        law.force(big_h * c, -big_h * omega * s).unwrap() * big_h * s
    };
    // Split where κ changes branch (h = ±ε) and at the turning point φ = π.
    let mut breaks = vec![0.0, std::f64::consts::PI, 2.0 * std::f64::consts::PI];
    for &h in &[eps, -eps] {
        if h.abs() < big_h {
            let phi = (h / big_h).acos();
            breaks.push(phi);
            breaks.push(2.0 * std::f64::consts::PI - phi);
        }
    }
    breaks.sort_by(f64::total_cmp);
    breaks
        .windows(2)
        .map(|w| {
            integrate_smooth(integrand, w[0], w[1], QuadTolerance::absolute(1e-15))
                .unwrap()
                .value
        })
        .sum()
}

#[test]
fn hysteresis_area_closed_form_matches_quadrature() {
    // Seed 002's figure: H = 1, ω = 2π, V = 1, k = 1; and other cases. Tolerance
    // 1e-10 k H² (absolute) on a loss of order k H².
    for &(k, big_h, omega, big_v) in &[
        (1.0, 1.0, 2.0 * std::f64::consts::PI, 1.0),
        (2e4, 1e-3, 50.0, 0.3),
        (1.0, 1.0, 1.0, 1e-3),
        (1.0, 1.0, 1e-4, 1.0),
    ] {
        let law = ContactCharacteristic::new(k, 0.0, big_v).unwrap();
        let closed = law.oscillation_loss(big_h, omega).unwrap();
        assert_eq!(closed.error_estimate, 0.0);
        let quad = cycle_area_by_quadrature(&law, big_h, omega);
        let scale = k * big_h * big_h;
        assert!(
            (closed.joules - quad).abs() < 1e-10 * scale,
            "closed {} quad {quad}",
            closed.joules
        );
        assert!(closed.joules > 0.0);
    }
    // Small a = Hω/V: W ≈ (2/3) a k H² (closing half 1/2 + a/3, opening 1/2 − a/3).
    let law = ContactCharacteristic::new(1.0, 0.0, 1.0).unwrap();
    let a = 1e-9;
    let w = law.oscillation_loss(1.0, a).unwrap().joules;
    assert!((w / (2.0 * a / 3.0) - 1.0).abs() < 1e-8, "{w}");
}

#[test]
fn rounded_hysteresis_area_matches_quadrature_and_tends_to_the_closed_form() {
    let (k, big_h, omega, big_v) = (3.0, 0.5, 2.0 * std::f64::consts::PI, 1.0);
    for &eps in &[0.01, 0.1, 0.5, 0.8] {
        let law = ContactCharacteristic::new(k, eps, big_v).unwrap();
        let lib = law.oscillation_loss(big_h, omega).unwrap();
        let quad = cycle_area_by_quadrature(&law, big_h, omega);
        assert!(
            (lib.joules - quad).abs() < 1e-10 * k * big_h * big_h,
            "eps {eps}"
        );
    }
    // ε → 0: the rounded area tends to the closed form with an O(ε²) difference.
    let closed = ContactCharacteristic::new(k, 0.0, big_v)
        .unwrap()
        .oscillation_loss(big_h, omega)
        .unwrap()
        .joules;
    let mut previous = f64::INFINITY;
    for &eps in &[1e-2, 1e-3, 1e-4] {
        let w = ContactCharacteristic::new(k, eps, big_v)
            .unwrap()
            .oscillation_loss(big_h, omega)
            .unwrap()
            .joules;
        let diff = (w - closed).abs();
        assert!(diff < previous / 50.0 || diff < 1e-12, "eps {eps}: {diff}");
        previous = diff;
    }
}

#[test]
fn impact_energy_loss_equals_the_simulated_hysteresis_area() {
    // The energy lost in the impact is m v0²(1 − e²)/2 with e from the closed form;
    // the simulator integrates the contact work ∫F ḋ dt alongside the motion.
    let (k, eps, big_v, m, v0) = (5e3, 2e-3, 0.4, 0.2, 1.3);
    let mut law = ContactCharacteristic::new(k, eps, big_v).unwrap();
    let sim = simulate_impact(&mut law, m, v0, &settings()).unwrap();
    let e = characteristic_restitution(v0, big_v).unwrap();
    let closed = 0.5 * m * v0 * v0 * (1.0 - e * e);
    assert!((sim.energy_loss - closed).abs() < 1e-9 * sim.kinetic_energy);
}
