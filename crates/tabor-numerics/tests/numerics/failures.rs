//! Tabulated values and failure modes: every error is typed.

use super::*;

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
