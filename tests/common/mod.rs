//! Shared by the fuzzing tests of the public API (`fuzz_api.rs`,
//! `fuzz_api_dissipative.rs`, `fuzz_api_scenes.rs`): the harness (case counts, the
//! runner, the strategies of arbitrary and physical values), the checks of the
//! contract (finite results, restitution in [0, 1], one-line typed errors) and
//! `fuzz_tests!`, which makes each group's CI and full-run tests.
#![allow(dead_code)]

use proptest::prelude::*;
use proptest::test_runner::{Config, TestCaseError, TestRunner};
use std::fmt::{Debug, Display};
use tabor::restitution::{self, Error, ImpactModel};

// ---------------------------------------------------------------------------
// Harness

pub fn env_cases(default: u32) -> u32 {
    std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.trim().parse().ok())
        .unwrap_or(default)
}

/// Runs `test` on `cases` values of `strategy`; a panic inside `test` is a failure.
pub fn run<S: Strategy>(
    name: &str,
    cases: u32,
    strategy: S,
    test: impl Fn(S::Value) -> Result<(), TestCaseError>,
) {
    let mut runner = TestRunner::new(Config {
        cases,
        failure_persistence: None,
        ..Config::default()
    });
    if let Err(e) = runner.run(&strategy, test) {
        panic!("{name}: {e}");
    }
}

/// Any f64: every class (NaN, ±∞, subnormal, ±0), edge values, and log-uniform
/// magnitudes of either sign (mostly positive: physical inputs).
pub fn x() -> BoxedStrategy<f64> {
    prop_oneof![
        3 => any::<f64>(),
        2 => prop::sample::select(vec![
            f64::NAN,
            f64::INFINITY,
            f64::NEG_INFINITY,
            0.0,
            -0.0,
            f64::MIN_POSITIVE,
            5e-324,
            -5e-324,
            f64::MAX,
            -f64::MAX,
            f64::EPSILON,
            1.0,
            -1.0,
            0.5,
            -0.5,
            1e-300,
            1e300,
        ]),
        6 => (-30.0f64..30.0).prop_map(|e| 10f64.powf(e)),
        1 => (-30.0f64..30.0).prop_map(|e| -(10f64.powf(e))),
    ]
    .boxed()
}

/// Values around the unit interval (exponents, ratios), plus anything.
pub fn u() -> BoxedStrategy<f64> {
    prop_oneof![
        2 => x(),
        3 => -2.0f64..2.0,
        1 => prop::sample::select(vec![-1.0, -0.999_999_999_999, 0.5, 0.500_000_000_001, 1.0, 0.999_999_999_999]),
    ]
    .boxed()
}

/// A relative tolerance: mostly valid (1e-12..1e-3), sometimes anything.
pub fn tol() -> BoxedStrategy<f64> {
    prop_oneof![
        4 => (-12.0f64..-3.0).prop_map(|e| 10f64.powf(e)),
        1 => x(),
    ]
    .boxed()
}

/// Physical magnitudes, positive and plausible, with a chance of anything.
pub fn phys(lo: f64, hi: f64) -> BoxedStrategy<f64> {
    prop_oneof![
        5 => (lo.log10()..hi.log10()).prop_map(|e| 10f64.powf(e)),
        1 => x(),
    ]
    .boxed()
}

/// The variant a dispatching group runs: all of `0..n` at random (CI), or only
/// `fixed` (the full run goes through every variant with its own case count, so
/// each public entry point gets at least that many cases).
pub fn variant(n: u8, fixed: Option<u8>) -> BoxedStrategy<u8> {
    match fixed {
        Some(v) => Just(v).boxed(),
        None => (0..n).boxed(),
    }
}

pub fn is_nonfinite_token(t: &str) -> bool {
    matches!(t, "NaN" | "inf" | "-inf")
}

/// Every number printed by `Debug` is finite (f64 prints as `NaN`, `inf`, `-inf`).
pub fn debug_is_finite(s: &str) -> bool {
    !s.split(|c: char| !(c.is_ascii_alphanumeric() || c == '-' || c == '.' || c == '+'))
        .any(is_nonfinite_token)
}

pub fn one_line(what: &str, message: &str) -> Result<(), TestCaseError> {
    prop_assert!(
        !message.trim().is_empty() && !message.contains('\n'),
        "{what}: error message is not one non-empty line: {message:?}"
    );
    Ok(())
}

/// The model error contract: non-finite inputs give `InvalidParameter`; an
/// `InvalidParameter` names its parameter in the message; messages are one line.
pub fn check_error(what: &str, inputs: &[f64], e: &Error) -> Result<(), TestCaseError> {
    let message = e.to_string();
    one_line(what, &message)?;
    if let Error::InvalidParameter { parameter, .. } = e {
        prop_assert!(!parameter.is_empty(), "{what}: unnamed parameter");
        prop_assert!(
            message.contains(parameter),
            "{what}: message {message:?} does not name {parameter}"
        );
    } else if let Error::Numerics(_) = e {
        // a model error may concern another (finite but extreme) parameter; a
        // numerical failure must not be what a non-finite input leads to
        prop_assert!(
            inputs.iter().all(|v| v.is_finite()),
            "{what}{inputs:?}: non-finite input answered with {e:?} instead of InvalidParameter"
        );
    }
    Ok(())
}

pub fn check<T: Debug>(
    what: &str,
    inputs: &[f64],
    r: &Result<T, Error>,
) -> Result<(), TestCaseError> {
    match r {
        Ok(v) => {
            let s = format!("{v:?}");
            prop_assert!(
                debug_is_finite(&s),
                "{what}{inputs:?}: non-finite result {s}"
            );
            prop_assert!(
                inputs.iter().all(|v| v.is_finite()),
                "{what}{inputs:?}: a non-finite input was accepted: {s}"
            );
            Ok(())
        }
        Err(e) => check_error(what, inputs, e),
    }
}

/// As `check`, and the value is a restitution coefficient in [0, 1].
pub fn check_e(what: &str, inputs: &[f64], r: &Result<f64, Error>) -> Result<(), TestCaseError> {
    check(what, inputs, r)?;
    if let Ok(e) = r {
        prop_assert!((0.0..=1.0).contains(e), "{what}{inputs:?}: restitution {e}");
    }
    Ok(())
}

/// An impact outcome and sticking velocity of a model that was built from `inputs`.
pub fn check_model<M: ImpactModel>(
    what: &str,
    inputs: &[f64],
    model: &M,
    speed: f64,
    tolerance: f64,
) -> Result<(), TestCaseError> {
    let mut all = inputs.to_vec();
    all.push(speed);
    let o = restitution::impact(model, speed);
    check(&format!("{what} impact"), &all, &o)?;
    if let Ok(o) = &o {
        prop_assert!(
            (0.0..=1.0).contains(&o.restitution),
            "{what}: e = {}",
            o.restitution
        );
        prop_assert!(o.energy_loss >= 0.0 && o.energy_loss <= o.kinetic_energy);
    }
    let mut all = inputs.to_vec();
    all.push(tolerance);
    let s = restitution::sticking_velocity(model, tolerance);
    check(&format!("{what} sticking_velocity"), &all, &s)?;
    if let Ok(s) = &s {
        prop_assert!(s.speed >= 0.0);
    }
    Ok(())
}

/// The result without its value (for results whose value is not `Debug`).
pub fn unit<T, E: Clone>(r: &Result<T, E>) -> Result<(), E> {
    r.as_ref().map(|_| ()).map_err(Clone::clone)
}

/// Errors of other types (numerics, scenes): one line, and the result finite.
pub fn check_other<T: Debug, E: Display + Debug>(
    what: &str,
    inputs: &[f64],
    r: &Result<T, E>,
) -> Result<(), TestCaseError> {
    match r {
        Ok(v) => {
            let s = format!("{v:?}");
            prop_assert!(
                debug_is_finite(&s),
                "{what}{inputs:?}: non-finite result {s}"
            );
            Ok(())
        }
        Err(e) => one_line(what, &e.to_string()),
    }
}

// ---------------------------------------------------------------------------
// Tests: `fuzz_tests!` makes each group's CI variant (`PROPTEST_CASES`, default 256)
// and its full run (ignored).

macro_rules! fuzz_tests {
    ($($group:ident: $ci:ident, $full:ident, $variants:expr;)*) => {
        $(
            #[test]
            fn $ci() {
                $group($crate::common::env_cases(256).max(1), None);
            }

            /// Full fuzzing run: `PROPTEST_CASES=100000 cargo test --release --test
            /// 'fuzz_api*' -- --ignored` (default 100000 cases when the variable is unset),
            /// that many cases for each variant of the group, so for every entry point.
            #[test]
            #[ignore = "fuzzing run: PROPTEST_CASES=100000 cargo test --release --test 'fuzz_api*' -- --ignored"]
            fn $full() {
                let cases = $crate::common::env_cases(100_000).max(1);
                if $variants > 1 {
                    for v in 0..$variants {
                        let start = std::time::Instant::now();
                        $group(cases, Some(v));
                        eprintln!(
                            "{} variant {v}: {cases} cases in {:.1?}",
                            stringify!($group),
                            start.elapsed()
                        );
                    }
                } else {
                    $group(cases, None);
                }
            }
        )*
    };
}

pub(crate) use fuzz_tests;
