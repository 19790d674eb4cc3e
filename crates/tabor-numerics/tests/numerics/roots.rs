//! Root finding: Brent, bracket expansion, safeguarded Newton.

use super::*;

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

/// Brent's method evaluates f once per point: the `roots` crate's iteration asks
/// again for the ends of the bracket it holds, and those are answered from
/// memory. On the event functions of an oblique impact (a root found to 10⁻¹⁶
/// early, then a bisection tail to a 4 ε bracket) that halved the evaluations.
/// Here: a root at a point that no bisection of [0, 1] meets, located to 4 ε,
/// with no point evaluated twice, and the evaluation count the calls made.
#[test]
fn brent_evaluates_each_point_once() {
    for c in [0.1, 1.0 / 3.0, 0.6180339887498949, 0.999] {
        let mut seen: Vec<u64> = Vec::new();
        let root = brent(
            |x: f64| {
                seen.push(x.to_bits());
                (x - c) * (1.0 + x * x)
            },
            0.0,
            1.0,
            RootTolerance {
                absolute: 0.0,
                relative: 4.0 * f64::EPSILON,
                max_iterations: 200,
            },
        )
        .unwrap();
        assert!(
            (root.value - c).abs() <= 8.0 * f64::EPSILON,
            "{} vs {c}",
            root.value
        );
        let calls = seen.len();
        seen.sort_unstable();
        seen.dedup();
        assert_eq!(seen.len(), calls, "a point evaluated twice (c = {c})");
        assert_eq!(root.evaluations, calls as u64);
    }
}
