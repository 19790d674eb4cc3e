#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Thornton's model against the seed's published numbers, its asymptote and limits.

use tabor_plastic::{LoadingLaw, PlasticContact, PlasticImpact, Thornton};
use tabor_restitution::{impact, ImpactModel};

#[test]
fn restitution_matches_the_published_values() {
    // Seed 000 / spec: eps at v_Y/v0 = 1, 0.5, 0.2, 0.1. Tolerance 5e-5 (the table
    // is rounded to 4 digits).
    for &(x, expected) in &[(1.0, 1.0), (0.5, 0.9306), (0.2, 0.7733), (0.1, 0.6586)] {
        let e = Thornton.restitution(1.0 / x).unwrap();
        assert!(
            (e - expected).abs() < 5e-5,
            "v_Y/v0 = {x}: {e} vs {expected}"
        );
    }
}

#[test]
fn generic_restitution_from_the_loss_equals_the_closed_form() {
    // Independent paths: (5.37) applied to loading work minus unloading work (core)
    // vs (5.105). Tolerance 1e-12 relative.
    let contact = PlasticContact::new(2e11, 2e-3, 8e8).unwrap();
    let model = PlasticImpact::new(contact, Thornton, 3e-5).unwrap();
    let v_y = model.yield_velocity();
    for &s in &[0.3, 1.0, 1.0001, 2.0, 5.0, 10.0, 1e3, 1e6] {
        let core = impact(&model, s * v_y).unwrap().restitution;
        let closed = model.restitution(s * v_y).unwrap();
        assert!(
            ((core - closed) / closed).abs() < 1e-12,
            "s = {s}: {core} vs {closed}"
        );
    }
}

#[test]
fn high_speed_asymptote_is_approached() {
    // (5.106): eps -> 1.185 (v0/v_Y)^(-1/4). Relative deviation falls like (v_Y/v0)^(1/2)
    // ... check it is below 1e-2 at 1e4 and below 1e-3 at 1e7, and that the constant
    // is 1.185 to the printed digits.
    let c = Thornton::high_speed_restitution(1.0).unwrap();
    assert!((c - 1.185).abs() < 5e-4, "{c}");
    for &(s, tol) in &[(1e4, 1e-2), (1e7, 1e-3), (1e10, 1e-4)] {
        let e = Thornton.restitution(s).unwrap();
        let a = Thornton::high_speed_restitution(s).unwrap();
        assert!(((e - a) / a).abs() < tol, "s = {s}: {e} vs {a}");
    }
}

#[test]
fn restitution_is_one_below_yield_and_continuous_there() {
    for &s in &[1e-6, 0.1, 0.5, 0.999, 1.0] {
        assert_eq!(Thornton.restitution(s).unwrap(), 1.0);
    }
    // Just above v_Y: 1 - eps = O(s - 1); tolerance 1e-5 at s - 1 = 1e-6.
    let e = Thornton.restitution(1.0 + 1e-6).unwrap();
    assert!(e <= 1.0 && 1.0 - e < 1e-5, "{e}");
    // Loading work at d_Y equals the Hertz work (2/5) F_Y d_Y from both sides.
    let below = Thornton.loading_work_ratio(1.0 - 1e-12).unwrap();
    let above = Thornton.loading_work_ratio(1.0 + 1e-12).unwrap();
    assert!((below - 0.4).abs() < 1e-11 && (above - 0.4).abs() < 1e-11);
}

#[test]
fn max_depth_is_the_root_of_the_energy_balance() {
    // (5.104) vs (5.101) solved the other way round: (5/2) W(x) = s^2. 1e-13 relative.
    for &s in &[1.0, 1.5, 3.0, 100.0] {
        let x = Thornton.max_depth_ratio(s).unwrap();
        let w = Thornton.loading_work_ratio(x).unwrap();
        assert!((2.5 * w / (s * s) - 1.0).abs() < 1e-13, "s = {s}");
    }
}

#[test]
fn yield_velocity_is_eq_5_103() {
    // (5.103) written out directly: v_Y^2 = (16/15)(4 pi/5)^5 (s/E)^5 E R^3/m. 1e-13.
    let (e, r, s, m) = (1.5e11, 3e-3, 7e8, 2e-4);
    let contact = PlasticContact::new(e, r, s).unwrap();
    let v = contact.yield_velocity(m).unwrap();
    let direct =
        (16.0 / 15.0 * (0.8 * std::f64::consts::PI).powi(5) * (s / e).powi(5) * e * r.powi(3) / m)
            .sqrt();
    assert!(((v - direct) / direct).abs() < 1e-13);
    let model = PlasticImpact::new(contact, Thornton, m).unwrap();
    assert_eq!(model.energy_loss(0.5 * v).unwrap().joules, 0.0);
}
