//! Known values, failure modes and property tests of the numerical layer.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use approx::assert_relative_eq;
use proptest::prelude::*;
use std::f64::consts::{FRAC_PI_2, PI};
use tabor_numerics::quadrature::{
    integrate_singular, integrate_singular_by_distance, integrate_smooth, GaussLegendrePair,
};
use tabor_numerics::root_finding::{brent, brent_expanding, expand_bracket, newton_safeguarded};
use tabor_numerics::special::{
    beta, gamma, gamma_ratio, graded_power_law_beta, incomplete_beta, power_law_beta,
    regularized_incomplete_beta,
};
use tabor_numerics::{
    BracketExpansion, GaussLegendre, NumericsError, QuadTolerance, RootTolerance,
};

// ---------------------------------------------------------------- quadrature

#[test]
fn inverse_square_root_singularity() {
    // ∫₀¹ x^(-1/2) dx = 2
    let i = integrate_singular(|x| x.powf(-0.5), 0.0, 1.0, QuadTolerance::relative(1e-12)).unwrap();
    assert_relative_eq!(i.value, 2.0, max_relative = 1e-13);
    assert!(i.error_estimate <= 2e-12);
    assert!(i.evaluations > 0);
}

#[test]
fn strong_endpoint_singularity() {
    // ∫₀¹ x^(-0.9) dx = 10: most of the mass sits within 1e-10 of 0.
    let i = integrate_singular(|x| x.powf(-0.9), 0.0, 1.0, QuadTolerance::relative(1e-10)).unwrap();
    assert_relative_eq!(i.value, 10.0, max_relative = 1e-9);
}

#[test]
fn log_and_semicircle() {
    let tol = QuadTolerance::relative(1e-13);
    let i = integrate_singular(f64::ln, 0.0, 1.0, tol).unwrap();
    assert_relative_eq!(i.value, -1.0, max_relative = 1e-13);
    let i = integrate_singular(|x| (1.0 - x * x).sqrt(), -1.0, 1.0, tol).unwrap();
    assert_relative_eq!(i.value, FRAC_PI_2, max_relative = 1e-13);
    // both endpoints singular: ∫₀¹ dx/√(x(1−x)) = π
    let i =
        integrate_singular_by_distance(|_, da, db| 1.0 / (da * db).sqrt(), 0.0, 1.0, tol).unwrap();
    assert_relative_eq!(i.value, PI, max_relative = 1e-13);
    // the same on a shifted interval, where 1 − x and x − a both lose digits
    let i = integrate_singular_by_distance(|_, da, db| 1.0 / (da * db).sqrt(), 10.0, 12.0, tol)
        .unwrap();
    assert_relative_eq!(i.value, PI, max_relative = 1e-13);
}

#[test]
fn crate_de_rule_is_not_enough_for_singular_endpoints() {
    // Documents why integrate_singular does not delegate to the quadrature crate's
    // double-exponential rule: it misses ∫₀¹ x^(-1/2) = 2 by more than 1e-7.
    let o = quadrature::integrate(|x: f64| x.powf(-0.5), 0.0, 1.0, 1e-14);
    assert!((o.integral - 2.0).abs() > 1e-8);
}

#[test]
fn smooth_integrals() {
    let tol = QuadTolerance::relative(1e-13);
    let i = integrate_smooth(f64::sin, 0.0, PI, tol).unwrap();
    assert_relative_eq!(i.value, 2.0, max_relative = 1e-13);
    let i = integrate_smooth(f64::exp, 0.0, 1.0, tol).unwrap();
    assert_relative_eq!(i.value, 1f64.exp() - 1.0, max_relative = 1e-14);
    // Runge's function needs subdivision: 2/5 · atan 5
    let i = integrate_smooth(|x| 1.0 / (1.0 + 25.0 * x * x), -1.0, 1.0, tol).unwrap();
    assert_relative_eq!(i.value, 0.4 * 5f64.atan(), max_relative = 1e-13);
    // a sharp peak
    let i = integrate_smooth(|x| 1.0 / (1e-4 + x * x), -1.0, 1.0, tol).unwrap();
    assert_relative_eq!(i.value, 2.0 * 100.0 * 100f64.atan(), max_relative = 1e-12);
}

#[test]
fn reversed_and_empty_intervals() {
    let tol = QuadTolerance::relative(1e-12);
    let i = integrate_smooth(f64::exp, 1.0, 0.0, tol).unwrap();
    assert_relative_eq!(i.value, -(1f64.exp() - 1.0), max_relative = 1e-13);
    let i = integrate_singular(|x| x.powf(-0.5), 1.0, 0.0, tol).unwrap();
    assert_relative_eq!(i.value, -2.0, max_relative = 1e-12);
    assert_eq!(
        integrate_smooth(f64::exp, 2.0, 2.0, tol).unwrap().value,
        0.0
    );
}

#[test]
fn quadrature_failure_modes() {
    let tol = QuadTolerance::relative(1e-10);
    let e = integrate_smooth(|x| 1.0 / (x - 0.5), 0.0, 1.0, tol).unwrap_err();
    assert!(matches!(e, NumericsError::NonFinite { .. }), "{e:?}");
    let e = integrate_singular(|_| f64::NAN, 0.0, 1.0, tol).unwrap_err();
    assert!(matches!(e, NumericsError::NonFinite { .. }), "{e:?}");
    let e = integrate_smooth(f64::exp, f64::NAN, 1.0, tol).unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }), "{e:?}");
    let e = integrate_smooth(f64::exp, 0.0, 1.0, QuadTolerance::relative(-1.0)).unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }), "{e:?}");
    // a divergent integral cannot converge
    let e = integrate_singular(|x| 1.0 / x, 0.0, 1.0, tol).unwrap_err();
    assert!(matches!(e, NumericsError::NoConvergence { .. }), "{e:?}");
    assert!(e.to_string().contains("tanh-sinh"));
}

#[test]
fn gauss_legendre_known_rules() {
    let g2 = GaussLegendre::new(2).unwrap();
    assert_relative_eq!(g2.nodes()[1], 1.0 / 3f64.sqrt(), max_relative = 1e-15);
    assert_relative_eq!(g2.weights()[0], 1.0, max_relative = 1e-15);
    let g3 = GaussLegendre::new(3).unwrap();
    assert_relative_eq!(g3.nodes()[2], (0.6f64).sqrt(), max_relative = 1e-15);
    assert_relative_eq!(g3.weights()[1], 8.0 / 9.0, max_relative = 1e-15);
    assert_relative_eq!(g3.weights()[0], 5.0 / 9.0, max_relative = 1e-15);
    assert!(GaussLegendre::new(0).is_err());
    for n in [5usize, 16, 40, 101] {
        let g = GaussLegendre::new(n).unwrap();
        let wsum: f64 = g.weights().iter().sum();
        assert_relative_eq!(wsum, 2.0, max_relative = 1e-14);
        // exact for x^(2n-2) on [0, 1]
        let p = (2 * n - 2) as i32;
        let v = g.integrate(|x| x.powi(p), 0.0, 1.0);
        assert_relative_eq!(v, 1.0 / (p as f64 + 1.0), max_relative = 1e-13);
    }
}

#[test]
fn gauss_legendre_pair_value_and_estimate() {
    let pair = GaussLegendrePair::new(12, 16).unwrap();
    // both rules exact to degree 23: estimate 0; degree 24..31 only the higher one
    for p in 0..=31 {
        let i = pair.integrate(|x| x.powi(p), 0.0, 1.0).unwrap();
        let exact = 1.0 / (f64::from(p) + 1.0);
        assert_relative_eq!(i.value, exact, max_relative = 2e-15);
        assert_eq!(i.evaluations, 28);
        if p <= 23 {
            assert!(i.error_estimate <= 1e-15 * exact, "p = {p}: {i:?}");
        } else {
            assert!(i.error_estimate > 1e-13 * exact, "p = {p}: {i:?}");
        }
    }
    // ∫_{-1}^{2} e^x dx = e² − e⁻¹: the estimate is the lower rule's error, which
    // covers the higher rule's many times over
    let exact = 2f64.exp() - (-1f64).exp();
    let i = GaussLegendrePair::new(3, 5)
        .unwrap()
        .integrate(f64::exp, -1.0, 2.0)
        .unwrap();
    let low = GaussLegendre::new(3)
        .unwrap()
        .integrate(f64::exp, -1.0, 2.0);
    assert_relative_eq!(i.error_estimate, (low - exact).abs(), max_relative = 1e-2);
    assert!((i.value - exact).abs() < 1e-2 * i.error_estimate, "{i:?}");
    // a pole at a node (the centre of the odd-point rule) is an error naming where
    let e = GaussLegendrePair::new(2, 3)
        .unwrap()
        .integrate(|x| 1.0 / x, -1.0, 1.0)
        .unwrap_err();
    assert!(
        matches!(e, NumericsError::NonFinite { at, .. } if at == 0.0),
        "{e:?}"
    );
    assert!(pair.integrate(f64::exp, 0.0, f64::NAN).is_err());
    assert!(GaussLegendrePair::new(16, 12).is_err());
    assert!(GaussLegendrePair::new(0, 12).is_err());
}

proptest! {
    #[test]
    fn smooth_polynomials_match_antiderivative(a in -10.0f64..10.0, w in 1e-3f64..10.0, c3 in -5.0f64..5.0, c0 in -5.0f64..5.0) {
        let b = a + w;
        let f = |x: f64| c3 * x * x * x + x * x + c0;
        let anti = |x: f64| c3 * x.powi(4) / 4.0 + x.powi(3) / 3.0 + c0 * x;
        let exact = anti(b) - anti(a);
        let i = integrate_smooth(f, a, b, QuadTolerance { absolute: 1e-12, relative: 1e-12 }).unwrap();
        prop_assert!((i.value - exact).abs() <= 1e-10 * (1.0 + exact.abs()));
    }

    #[test]
    fn singular_powers_match_closed_form(p in -0.8f64..3.0, b in 1e-3f64..1e3) {
        // ∫₀^b x^p dx = b^(p+1)/(p+1)
        let exact = b.powf(p + 1.0) / (p + 1.0);
        let i = integrate_singular(|x| x.powf(p), 0.0, b, QuadTolerance::relative(1e-11)).unwrap();
        prop_assert!((i.value / exact - 1.0).abs() <= 1e-9, "p={p} b={b} got {} want {exact}", i.value);
    }
}

// ------------------------------------------------------------------ roots

#[test]
fn brent_known_roots() {
    let tol = RootTolerance::relative(1e-15);
    let r = brent(|x| x * x - 2.0, 0.0, 2.0, tol).unwrap();
    assert_relative_eq!(r.value, 2f64.sqrt(), max_relative = 4e-16);
    assert!(r.iterations > 0 && r.evaluations >= r.iterations);
    // the Dottie number, the fixed point of cos
    let r = brent(|x| x.cos() - x, 0.0, 1.0, tol).unwrap();
    assert_relative_eq!(r.value, 0.739_085_133_215_160_7, max_relative = 1e-15);
    // reversed bracket, exact zero at an end
    let r = brent(|x| x - 3.0, 3.0, -1.0, tol).unwrap();
    assert_eq!(r.value, 3.0);
}

#[test]
fn brent_failure_modes() {
    let tol = RootTolerance::relative(1e-12);
    let e = brent(|x| x * x + 1.0, -1.0, 1.0, tol).unwrap_err();
    assert!(matches!(e, NumericsError::NoBracket { .. }), "{e:?}");
    let e = brent(|x| if x > 0.5 { f64::NAN } else { x - 0.7 }, 0.0, 1.0, tol).unwrap_err();
    assert!(matches!(e, NumericsError::NonFinite { .. }), "{e:?}");
    let e = brent(
        |x| (x - 0.3).powi(3) * 1e-3 + (x - 0.3),
        0.0,
        1.0,
        RootTolerance {
            absolute: 0.0,
            relative: 1e-15,
            max_iterations: 2,
        },
    )
    .unwrap_err();
    assert!(matches!(e, NumericsError::NoConvergence { .. }), "{e:?}");
    let e = brent(|x| x, f64::INFINITY, 1.0, tol).unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }), "{e:?}");
    let e = brent(
        |x| x,
        -1.0,
        1.0,
        RootTolerance {
            absolute: f64::NAN,
            relative: 0.0,
            max_iterations: 10,
        },
    )
    .unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }), "{e:?}");
}

#[test]
fn bracket_expansion() {
    // geometric: the root at 1e5 is found from [0.1, 0.2]
    let r = brent_expanding(
        |v| v - 1e5,
        0.1,
        0.2,
        BracketExpansion::default(),
        RootTolerance::relative(1e-14),
    )
    .unwrap();
    assert_relative_eq!(r.value, 1e5, max_relative = 1e-14);
    // and a root at 1e-6 downwards
    let r = brent_expanding(
        |v| v.ln() - (1e-6f64).ln(),
        0.1,
        0.2,
        BracketExpansion::default(),
        RootTolerance::relative(1e-14),
    )
    .unwrap();
    assert_relative_eq!(r.value, 1e-6, max_relative = 1e-13);
    // linear within limits
    let (lo, hi, _) = expand_bracket(
        |x| x + 50.0,
        0.0,
        1.0,
        BracketExpansion::Linear {
            factor: 1.6,
            min: -1e3,
            max: 1e3,
            max_steps: 50,
        },
    )
    .unwrap();
    assert!(lo <= -50.0 && hi >= -50.0);
    let e = expand_bracket(
        |x| x * x + 1.0,
        0.0,
        1.0,
        BracketExpansion::Linear {
            factor: 1.6,
            min: -10.0,
            max: 10.0,
            max_steps: 50,
        },
    )
    .unwrap_err();
    assert!(matches!(e, NumericsError::NoBracket { .. }));
    let e = expand_bracket(
        |x| x,
        -1.0,
        1.0,
        BracketExpansion::Geometric {
            factor: 2.0,
            max_steps: 5,
        },
    )
    .unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }));
}

#[test]
fn newton_known_roots() {
    // Wallis' cubic x³ − 2x − 5 = 0
    let r = newton_safeguarded(
        |x| (x * x * x - 2.0 * x - 5.0, 3.0 * x * x - 2.0),
        2.0,
        3.0,
        2.5,
        RootTolerance::relative(1e-15),
    )
    .unwrap();
    assert_relative_eq!(r.value, 2.094_551_481_542_326_5, max_relative = 1e-15);
    // a bad start (derivative 0) falls back to bisection
    let r = newton_safeguarded(
        |x| (x * x - 4.0, 2.0 * x),
        -1.0,
        5.0,
        0.0,
        RootTolerance::relative(1e-14),
    )
    .unwrap();
    assert_relative_eq!(r.value, 2.0, max_relative = 1e-14);
    let e = newton_safeguarded(
        |x| (x * x + 1.0, 2.0 * x),
        -1.0,
        1.0,
        0.0,
        RootTolerance::relative(1e-14),
    )
    .unwrap_err();
    assert!(matches!(e, NumericsError::NoBracket { .. }));
}

proptest! {
    #[test]
    fn brent_finds_random_roots(r in -1e3f64..1e3, below in 1e-3f64..1e3, above in 1e-3f64..1e3) {
        let f = |x: f64| (x - r) * (1.0 + 0.1 * x * x);
        let root = brent(f, r - below, r + above, RootTolerance { absolute: 1e-12, relative: 1e-14, max_iterations: 200 }).unwrap();
        prop_assert!((root.value - r).abs() <= 2e-12 + 2e-14 * r.abs());
    }

    #[test]
    fn newton_finds_random_roots(r in 0.01f64..100.0, lo_f in 0.0f64..0.99, hi_f in 1.01f64..10.0) {
        let f = |x: f64| (x.powi(3) - r.powi(3), 3.0 * x * x);
        let root = newton_safeguarded(f, lo_f * r, hi_f * r, hi_f * r, RootTolerance::relative(1e-14)).unwrap();
        prop_assert!((root.value / r - 1.0).abs() <= 1e-13);
    }
}

// --------------------------------------------------------- special functions

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

// ----------------------------------------------------------- Chebyshev

#[test]
fn chebyshev_interpolation() {
    use tabor_numerics::chebyshev::{ChebyshevSeries, PiecewiseChebyshev};
    // a cubic is reproduced exactly by 4 points
    let s = ChebyshevSeries::fit(
        |x| Ok::<f64, NumericsError>(x * x * x - 2.0 * x + 1.0),
        -1.0,
        3.0,
        4,
    )
    .unwrap();
    for x in [-1.0, 0.0, 0.7, 3.0] {
        assert_relative_eq!(
            s.eval(x),
            x * x * x - 2.0 * x + 1.0,
            max_relative = 1e-13,
            epsilon = 1e-14
        );
    }
    // exp on [0, 1] with 20 points: error near machine precision
    let s = ChebyshevSeries::fit(|x: f64| Ok::<f64, NumericsError>(x.exp()), 0.0, 1.0, 20).unwrap();
    assert!(s.tail() < 1e-14); // rounding level of the cosine sums
    for i in 0..=100 {
        let x = i as f64 / 100.0;
        assert_relative_eq!(s.eval(x), x.exp(), max_relative = 5e-15);
    }
    // √x on [1e-6, 1] needs pieces
    let p = PiecewiseChebyshev::fit(
        |x: f64| Ok::<f64, NumericsError>(x.sqrt()),
        1e-6,
        1.0,
        24,
        1e-14,
        200,
    )
    .unwrap();
    assert!(p.pieces().len() > 1);
    for i in 0..=1000 {
        let x = 1e-6 * (1e6f64).powf(i as f64 / 1000.0);
        assert_relative_eq!(p.eval(x), x.sqrt(), max_relative = 1e-12);
    }
    assert!(p.cost().evaluations >= 24);
    // failures
    assert!(ChebyshevSeries::fit(|x: f64| Ok::<f64, NumericsError>(x), 1.0, 0.0, 8).is_err());
    assert!(ChebyshevSeries::fit(|x: f64| Ok::<f64, NumericsError>(1.0 / x), -1.0, 1.0, 8).is_ok());
    assert!(ChebyshevSeries::fit(|_| Ok::<f64, NumericsError>(f64::NAN), -1.0, 1.0, 8).is_err());
    assert!(PiecewiseChebyshev::fit(
        |x: f64| Ok::<f64, NumericsError>(x.abs().sqrt()),
        -1.0,
        1.0,
        8,
        1e-14,
        4
    )
    .is_err());
}

#[test]
fn uniform_chebyshev_table() {
    use tabor_numerics::chebyshev::UniformChebyshevTable;
    // a cubic is reproduced by 4 points per piece, on every piece
    let cubic = |x: f64| x * x * x - 2.0 * x + 1.0;
    let t =
        UniformChebyshevTable::<4>::fit(|x| Ok::<f64, NumericsError>(cubic(x)), -1.0, 3.0, 5, 1.0)
            .unwrap();
    for i in 0..=400 {
        let x = -1.0 + 4.0 * i as f64 / 400.0;
        assert_relative_eq!(t.eval(x), cubic(x), max_relative = 1e-13, epsilon = 1e-13);
    }
    // outside the interval: the end values
    assert_relative_eq!(t.eval(-7.0), cubic(-1.0), max_relative = 1e-13);
    assert_relative_eq!(t.eval(9.0), cubic(3.0), max_relative = 1e-13);
    // exp on [0, 2], 16 pieces of 8 points: error at rounding level, as the tail says
    let t = UniformChebyshevTable::<8>::fit(
        |x: f64| Ok::<f64, NumericsError>(x.exp()),
        0.0,
        2.0,
        16,
        1e-11,
    )
    .unwrap();
    assert_eq!(t.pieces(), 16);
    assert_eq!(t.cost().evaluations, 128);
    assert!(t.tail() < 1e-11);
    let mut worst: f64 = 0.0;
    for i in 0..=10_000 {
        let x = 2.0 * i as f64 / 10_000.0;
        worst = worst.max((t.eval(x) / x.exp() - 1.0).abs());
    }
    assert!(worst < 2e-15, "worst {worst:e}");
    // too few pieces for the tolerance, a failing sample, bad arguments
    assert!(UniformChebyshevTable::<6>::fit(
        |x: f64| Ok::<f64, NumericsError>(x.sqrt()),
        0.0,
        1.0,
        4,
        1e-12
    )
    .is_err());
    assert!(UniformChebyshevTable::<6>::fit(
        |_| Ok::<f64, NumericsError>(f64::NAN),
        0.0,
        1.0,
        4,
        1e-12
    )
    .is_err());
    assert!(UniformChebyshevTable::<6>::fit(
        |x: f64| Ok::<f64, NumericsError>(x),
        1.0,
        0.0,
        4,
        1e-12
    )
    .is_err());
    assert!(UniformChebyshevTable::<6>::fit(
        |x: f64| Ok::<f64, NumericsError>(x),
        0.0,
        1.0,
        0,
        1e-12
    )
    .is_err());
    assert!(UniformChebyshevTable::<1>::fit(
        |x: f64| Ok::<f64, NumericsError>(x),
        0.0,
        1.0,
        4,
        1e-12
    )
    .is_err());
}

// ------------------------------------------- tabulated values, failure modes

#[test]
fn incomplete_beta_tabulated_values() {
    // Reference values from an independent arbitrary-precision implementation:
    // mpmath 1.3 `betainc(a, b, 0, x)` (and `regularized=True`) at 30 digits, rounded
    // to the nearest f64. The points are those of the seed's trajectories
    // (b = 1/2, a = n/(2n+1) < 1/2), where statrs is good to a few ulp (tolerance
    // 1e-14), plus two generic ones with a larger parameter, where its ln Γ prefactor
    // limits it to about 1e-13 (tolerance 5e-13).
    for &(x, a, b, full, regularized) in &[
        (0.3, 0.4, 0.5, 1.621316416684018, 0.44068360996452527),
        (0.9, 0.4, 0.5, 3.0333417483977536, 0.8244806369591876),
        (0.999, 0.4, 0.5, 3.615835772016538, 0.9828060362887594),
        (0.5, 1.0 / 3.0, 0.5, 2.576132313983458, 0.6124103053850539),
        (
            0.99,
            5.0 / 11.0,
            0.5,
            3.1577676162307835,
            0.9403343060993195,
        ),
        (0.2, 2.5, 3.5, 0.004889740835956394, 0.13281730977804912),
        (0.75, 10.0, 0.5, 0.0101060479761303, 0.017806558607844636),
    ] {
        let tol = if a < 0.5 && b == 0.5 { 1e-14 } else { 5e-13 };
        let got = incomplete_beta(x, a, b).unwrap();
        assert!((got / full - 1.0).abs() < tol, "B({x}; {a}, {b}) = {got}");
        let got = regularized_incomplete_beta(x, a, b).unwrap();
        assert!(
            (got / regularized - 1.0).abs() < tol,
            "I_{x}({a}, {b}) = {got}"
        );
    }
    // Symmetry I_{1/2}(a, a) = 1/2 for non-integer a (same two accuracy regimes).
    for (a, tol) in [(0.3, 1e-14), (0.5, 1e-14), (1.7, 1e-14), (12.5, 5e-13)] {
        assert_relative_eq!(
            regularized_incomplete_beta(0.5, a, a).unwrap(),
            0.5,
            max_relative = tol
        );
    }
}

#[test]
fn every_failure_mode_is_typed() {
    let tol = RootTolerance::relative(1e-14);
    // safeguarded Newton: non-finite value inside the bracket, iteration limit,
    // invalid start, invalid tolerance
    let e = newton_safeguarded(
        |x| {
            if x > 0.4 {
                (f64::NAN, 1.0)
            } else {
                (x - 0.7, 1.0)
            }
        },
        0.0,
        1.0,
        0.5,
        tol,
    )
    .unwrap_err();
    assert!(matches!(e, NumericsError::NonFinite { .. }), "{e:?}");
    let e = newton_safeguarded(
        |x| (x.powi(3) - 2.0 * x - 5.0, 3.0 * x * x - 2.0),
        2.0,
        3.0,
        2.9,
        RootTolerance {
            absolute: 0.0,
            relative: 1e-15,
            max_iterations: 1,
        },
    )
    .unwrap_err();
    assert!(
        matches!(e, NumericsError::NoConvergence { method, .. } if method.contains("Newton")),
        "{e:?}"
    );
    let e = newton_safeguarded(|x| (x, 1.0), -1.0, 1.0, f64::NAN, tol).unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }), "{e:?}");
    let e = newton_safeguarded(
        |x| (x, 1.0),
        -1.0,
        1.0,
        0.5,
        RootTolerance {
            absolute: 0.0,
            relative: 1e-14,
            max_iterations: 0,
        },
    )
    .unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }), "{e:?}");
    // bracket expansion: non-finite value at an expanded end, no sign change in the
    // allowed steps, invalid factor
    let e = expand_bracket(
        |x| if x > 3.0 { f64::INFINITY } else { 5.0 - x },
        1.0,
        2.0,
        BracketExpansion::default(),
    )
    .unwrap_err();
    assert!(matches!(e, NumericsError::NonFinite { .. }), "{e:?}");
    let e = brent_expanding(
        |x| x * x + 1.0,
        1.0,
        2.0,
        BracketExpansion::Geometric {
            factor: 2.0,
            max_steps: 10,
        },
        tol,
    )
    .unwrap_err();
    assert!(matches!(e, NumericsError::NoBracket { .. }), "{e:?}");
    let e = expand_bracket(
        |x| x - 10.0,
        1.0,
        2.0,
        BracketExpansion::Geometric {
            factor: 1.0,
            max_steps: 10,
        },
    )
    .unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }), "{e:?}");
    // adaptive Clenshaw-Curtis: too many oscillations for the subinterval limit, and
    // an integral that overflows
    let e = integrate_smooth(
        |x| (1e6 * x).sin(),
        0.0,
        1e3,
        QuadTolerance::relative(1e-12),
    )
    .unwrap_err();
    assert!(
        matches!(e, NumericsError::NoConvergence { method, .. } if method.contains("Clenshaw")),
        "{e:?}"
    );
    let e = integrate_smooth(|_| 1e308, 0.0, 10.0, QuadTolerance::relative(1e-12)).unwrap_err();
    assert!(
        matches!(
            e,
            NumericsError::NoConvergence { .. } | NumericsError::NonFinite { .. }
        ),
        "{e:?}"
    );
    // tanh-sinh: invalid limits and tolerance
    let e = integrate_singular(
        f64::sqrt,
        0.0,
        f64::INFINITY,
        QuadTolerance::relative(1e-10),
    )
    .unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }), "{e:?}");
    let e = integrate_singular(f64::sqrt, 0.0, 1.0, QuadTolerance::relative(0.0)).unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }), "{e:?}");
    // special functions: overflow is NonFinite, outside the domain InvalidArgument
    let e = gamma(200.0).unwrap_err();
    assert!(matches!(e, NumericsError::NonFinite { .. }), "{e:?}");
    let e = regularized_incomplete_beta(f64::NAN, 0.5, 0.5).unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }), "{e:?}");
    let e = gamma_ratio(-1.0, 2.0).unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }), "{e:?}");
    let e = GaussLegendre::new(1001).unwrap_err();
    assert!(matches!(e, NumericsError::InvalidArgument { .. }), "{e:?}");
}

proptest! {
    #[test]
    fn expanding_brent_from_random_starting_brackets(
        log_root in -8.0f64..8.0, log_start in -8.0f64..8.0, width in 1.01f64..4.0,
    ) {
        // geometric expansion for a positive variable, roots over 16 decades
        let r = 10f64.powf(log_root);
        let s = 10f64.powf(log_start);
        let root = brent_expanding(
            |v: f64| v.ln() - r.ln(),
            s,
            width * s,
            BracketExpansion::default(),
            RootTolerance::relative(1e-14),
        )
        .unwrap();
        prop_assert!((root.value / r - 1.0).abs() <= 1e-13, "{} vs {r}", root.value);
    }

    #[test]
    fn linear_expansion_from_random_starting_brackets(
        r in -1e3f64..1e3, lo in -1e3f64..1e3, w in 1e-3f64..10.0,
    ) {
        let root = brent_expanding(
            |x: f64| (x - r) * (2.0 + x.sin()),
            lo,
            lo + w,
            BracketExpansion::Linear { factor: 1.6, min: -1e4, max: 1e4, max_steps: 100 },
            RootTolerance { absolute: 1e-12, relative: 1e-14, max_iterations: 200 },
        )
        .unwrap();
        prop_assert!((root.value - r).abs() <= 2e-12 + 2e-14 * r.abs());
    }
}
