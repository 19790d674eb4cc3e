//! Special functions: gamma, the (incomplete) beta functions.

use super::*;

#[test]
fn gamma_known_values() {
    // Abramowitz & Stegun Table 6.1 / exact values
    assert_relative_eq!(gamma(0.5).unwrap(), PI.sqrt(), max_relative = 1e-14);
    assert_relative_eq!(gamma(5.0).unwrap(), 24.0, max_relative = 1e-14);
    assert_relative_eq!(
        gamma(0.4).unwrap(),
        2.218_159_543_757_688,
        max_relative = 1e-14
    );
    assert_relative_eq!(
        gamma(0.9).unwrap(),
        1.068_628_702_119_319_4,
        max_relative = 1e-14
    );
    assert_relative_eq!(
        gamma_ratio(300.5, 300.0).unwrap(),
        300f64.sqrt() * (1.0 - 1.0 / 2400.0),
        max_relative = 1e-6
    );
    assert!(gamma(-1.0).is_err());
    assert!(gamma(f64::NAN).is_err());
}

#[test]
fn incomplete_beta_known_values() {
    // I_{1/2}(2, 3) = 11/16 (polynomial case)
    assert_relative_eq!(
        regularized_incomplete_beta(0.5, 2.0, 3.0).unwrap(),
        11.0 / 16.0,
        max_relative = 1e-14
    );
    // (5.19): B(z²; 1/2, 1/2) = 2 arcsin z
    for z in [0.01, 0.3, 0.5, 0.9, 0.999] {
        assert_relative_eq!(
            incomplete_beta(z * z, 0.5, 0.5).unwrap(),
            2.0 * f64::asin(z),
            max_relative = 1e-13
        );
    }
    // I_x(a, 1) = x^a and I_x(1, b) = 1 − (1−x)^b
    for x in [0.1, 0.5, 0.77] {
        assert_relative_eq!(
            regularized_incomplete_beta(x, 0.4, 1.0).unwrap(),
            x.powf(0.4),
            max_relative = 1e-13
        );
        assert_relative_eq!(
            regularized_incomplete_beta(x, 1.0, 2.5).unwrap(),
            1.0 - (1.0 - x).powf(2.5),
            max_relative = 1e-13
        );
    }
    // B(1; 2/5, 1/2) = Γ(2/5)Γ(1/2)/Γ(9/10), the Hertz contact time factor of (5.12)
    let b = 2.218_159_543_757_688 * PI.sqrt() / 1.068_628_702_119_319_4;
    assert_relative_eq!(
        incomplete_beta(1.0, 0.4, 0.5).unwrap(),
        b,
        max_relative = 1e-13
    );
    assert_relative_eq!(beta(0.4, 0.5).unwrap(), b, max_relative = 1e-13);
    assert!(incomplete_beta(1.5, 0.4, 0.5).is_err());
    assert!(incomplete_beta(0.5, 0.0, 0.5).is_err());
}

#[test]
fn incomplete_beta_against_quadrature() {
    // an independent path: tanh-sinh of the defining integral
    for &(x, a, b) in &[
        (0.3, 0.4, 0.5),
        (0.9, 2.0 / 3.0, 0.5),
        (0.5, 0.25, 0.5),
        (0.99, 5.0 / 11.0, 0.5),
    ] {
        let q = integrate_singular(
            |t: f64| t.powf(a - 1.0) * (1.0 - t).powf(b - 1.0),
            0.0,
            x,
            QuadTolerance::relative(1e-13),
        )
        .unwrap();
        assert_relative_eq!(
            incomplete_beta(x, a, b).unwrap(),
            q.value,
            max_relative = 1e-12
        );
    }
}

#[test]
fn power_law_beta_known_values() {
    // statrs' Gamma is good to a few ulp (see statrs_gamma_accuracy), hence 1e-14
    assert_relative_eq!(
        power_law_beta(1.0).unwrap(),
        FRAC_PI_2,
        max_relative = 1e-14
    );
    assert_relative_eq!(power_law_beta(2.0).unwrap(), 2.0, max_relative = 1e-14);
    assert_relative_eq!(
        power_law_beta(3.0).unwrap(),
        0.75 * PI,
        max_relative = 1e-14
    );
    assert_relative_eq!(
        power_law_beta(4.0).unwrap(),
        8.0 / 3.0,
        max_relative = 1e-14
    );
    // large n: β(n) ≈ √(π n / 2) (Stirling), no overflow
    let n = 1e4;
    assert_relative_eq!(
        power_law_beta(n).unwrap(),
        (PI * n / 2.0).sqrt(),
        max_relative = 1e-4
    );
    assert!(power_law_beta(0.0).is_err());
    for k in [-0.9, -0.5, 0.0, 0.3, 0.99] {
        assert_relative_eq!(
            graded_power_law_beta(2.0, k).unwrap(),
            2.0 / (1.0 + k),
            max_relative = 1e-13
        );
    }
    for n in [0.7, 1.0, 2.5, 7.0] {
        assert_relative_eq!(
            graded_power_law_beta(n, 0.0).unwrap(),
            power_law_beta(n).unwrap(),
            max_relative = 1e-14
        );
    }
    assert!(graded_power_law_beta(2.0, 1.0).is_err());
    assert!(graded_power_law_beta(2.0, -1.0).is_err());
}

#[test]
fn statrs_gamma_accuracy() {
    // measured precision of the Gamma function we rely on
    let mut worst: f64 = 0.0;
    for (x, exact) in [
        (1.5, PI.sqrt() / 2.0),
        (2.5, 0.75 * PI.sqrt()),
        (3.0, 2.0),
        (1.0, 1.0),
        (6.0, 120.0),
    ] {
        worst = worst.max((gamma(x).unwrap() / exact - 1.0).abs());
    }
    eprintln!("worst relative Gamma error {worst:e}");
    assert!(worst < 1e-13);
}
