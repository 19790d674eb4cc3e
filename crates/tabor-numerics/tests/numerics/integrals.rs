//! Quadrature: singular and smooth integrals, Gauss-Legendre rules, failure modes.

use super::*;

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
