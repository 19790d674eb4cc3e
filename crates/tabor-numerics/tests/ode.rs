#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Tests of the Dormand-Prince integrator against closed-form solutions.

use tabor_numerics::ode::{solve, solve_until_event, DormandPrince, EventDirection, OdeTolerance};
use tabor_numerics::NumericsError;

fn oscillator(_t: f64, y: &[f64; 2]) -> [f64; 2] {
    [y[1], -y[0]]
}

#[test]
fn harmonic_oscillator_matches_sin_cos_to_1e_10() {
    // y'' = -y, y(0) = 0, y'(0) = 1: y = sin t, y' = cos t. Tolerance 1e-10 absolute
    // over ten periods with rtol = atol = 1e-13.
    let tol = OdeTolerance::new(1e-13, 1e-13);
    for &t_end in &[1.0, 10.0, 20.0 * std::f64::consts::PI] {
        let sol = solve(oscillator, 0.0, [0.0, 1.0], t_end, tol).unwrap();
        assert!(!sol.event_found);
        assert_eq!(sol.t, t_end);
        assert!(
            (sol.y[0] - t_end.sin()).abs() < 1e-10,
            "{t_end}: {:?}",
            sol.y
        );
        assert!(
            (sol.y[1] - t_end.cos()).abs() < 1e-10,
            "{t_end}: {:?}",
            sol.y
        );
        assert!(sol.cost.evaluations > 0 && sol.accepted_steps > 0);
    }
}

#[test]
fn dense_output_is_accurate_inside_steps() {
    // The continuous extension is 4th order: with a tight tolerance it follows
    // sin t within 1e-9 at points inside each step.
    let tol = OdeTolerance::new(1e-12, 1e-12);
    let mut f = oscillator;
    let mut s = DormandPrince::new(&mut f, 0.0, [0.0, 1.0], 10.0, tol).unwrap();
    let mut worst: f64 = 0.0;
    while s.t() < 10.0 {
        s.step(&mut f, 10.0).unwrap();
        let (a, b) = (s.previous_t(), s.t());
        for j in 1..10 {
            let t = a + (b - a) * j as f64 / 10.0;
            let y = s.dense_output(t);
            worst = worst
                .max((y[0] - t.sin()).abs())
                .max((y[1] - t.cos()).abs());
        }
    }
    assert!(worst < 1e-9, "dense output error {worst:e}");
}

#[test]
fn exponential_decay_relative_accuracy() {
    // y' = -λ y over 30 decay times; relative error of y below 1e-8 with rtol 1e-11,
    // atol tiny against the smallest value (e^-30 ≈ 1e-13).
    let lambda = 3.7;
    let tol = OdeTolerance::new(1e-11, 1e-30);
    let t_end = 30.0 / lambda;
    let sol = solve(|_, y: &[f64; 1]| [-lambda * y[0]], 0.0, [2.5], t_end, tol).unwrap();
    let exact = 2.5 * (-lambda * t_end).exp();
    assert!(
        ((sol.y[0] - exact) / exact).abs() < 1e-8,
        "{} vs {exact}",
        sol.y[0]
    );
}

#[test]
fn falling_body_event_time_matches_closed_form() {
    // z'' = -g from z0 with upward speed u0: ground contact z = 0 at
    // t = (u0 + sqrt(u0^2 + 2 g z0)) / g. Tolerance 1e-12 relative on t, 1e-10 on the
    // impact speed.
    let g = 9.81;
    for &(z0, u0) in &[(1.0, 0.0), (10.0, 3.0), (0.01, -0.5), (1e-6, 2.0)] {
        let tol = OdeTolerance::new(1e-12, 1e-14);
        let sol = solve_until_event(
            |_, _y: &[f64; 2]| [_y[1], -g],
            |_, y: &[f64; 2]| y[0],
            EventDirection::Falling,
            0.0,
            [z0, u0],
            1e3,
            tol,
        )
        .unwrap();
        let t_exact = (u0 + (u0 * u0 + 2.0 * g * z0).sqrt()) / g;
        assert!(sol.event_found);
        assert!(
            ((sol.t - t_exact) / t_exact).abs() < 1e-12,
            "z0 = {z0}: {} vs {t_exact}",
            sol.t
        );
        let v_exact = -(u0 * u0 + 2.0 * g * z0).sqrt();
        assert!(((sol.y[1] - v_exact) / v_exact).abs() < 1e-10);
        assert!(sol.y[0].abs() < 1e-12 * z0.max(1.0));
    }
}

#[test]
fn rising_and_either_directions() {
    // sin t crosses 0.5 rising at π/6 and falling at 5π/6.
    let tol = OdeTolerance::new(1e-12, 1e-12);
    let rising = solve_until_event(
        oscillator,
        |_, y: &[f64; 2]| y[0] - 0.5,
        EventDirection::Rising,
        0.0,
        [0.0, 1.0],
        10.0,
        tol,
    )
    .unwrap();
    assert!((rising.t - std::f64::consts::PI / 6.0).abs() < 1e-11);
    let falling = solve_until_event(
        oscillator,
        |_, y: &[f64; 2]| y[0] - 0.5,
        EventDirection::Falling,
        0.0,
        [0.0, 1.0],
        10.0,
        tol,
    )
    .unwrap();
    assert!((falling.t - 5.0 * std::f64::consts::PI / 6.0).abs() < 1e-11);
    let either = solve_until_event(
        oscillator,
        |_, y: &[f64; 2]| y[1],
        EventDirection::Either,
        0.0,
        [0.0, 1.0],
        10.0,
        tol,
    )
    .unwrap();
    assert!((either.t - std::f64::consts::FRAC_PI_2).abs() < 1e-11);
}

#[test]
fn hertz_oscillator_energy_drift() {
    // x'' = -x^(3/2) for x > 0, free flight for x <= 0 (a Hertzian bouncer between two
    // walls is not needed: one contact cycle suffices). Energy
    // E = v^2/2 + (2/5) x^(5/2) is conserved; drift below 1e-10 relative at rtol 1e-12.
    let f = |_: f64, y: &[f64; 2]| [y[1], -(y[0].max(0.0)).powf(1.5)];
    let energy = |y: &[f64; 2]| 0.5 * y[1] * y[1] + 0.4 * y[0].max(0.0).powf(2.5);
    let tol = OdeTolerance::new(1e-12, 1e-14);
    let y0 = [0.0, 1.0];
    let sol = solve_until_event(
        f,
        |_, y: &[f64; 2]| y[0],
        EventDirection::Falling,
        0.0,
        y0,
        100.0,
        tol,
    )
    .unwrap();
    assert!(sol.event_found);
    let drift = (energy(&sol.y) - energy(&y0)).abs() / energy(&y0);
    assert!(drift < 1e-10, "drift {drift:e}");
    assert!((sol.y[1] + 1.0).abs() < 1e-10);
}

#[test]
fn kepler_orbit_energy_and_period() {
    // Planar Kepler problem, eccentricity 0.5: after one period T = 2π (a = 1) the
    // state returns within 1e-8 and the energy drift is below 1e-10.
    let e: f64 = 0.5;
    let y0 = [1.0 - e, 0.0, 0.0, ((1.0 + e) / (1.0 - e)).sqrt()];
    let f = |_: f64, y: &[f64; 4]| {
        let r3 = (y[0] * y[0] + y[1] * y[1]).powf(1.5);
        [y[2], y[3], -y[0] / r3, -y[1] / r3]
    };
    let energy =
        |y: &[f64; 4]| 0.5 * (y[2] * y[2] + y[3] * y[3]) - 1.0 / (y[0] * y[0] + y[1] * y[1]).sqrt();
    let sol = solve(
        f,
        0.0,
        y0,
        2.0 * std::f64::consts::PI,
        OdeTolerance::new(1e-13, 1e-15),
    )
    .unwrap();
    for (got, start) in sol.y.iter().zip(y0) {
        assert!((got - start).abs() < 1e-8, "{:?}", sol.y);
    }
    let drift = ((energy(&sol.y) - energy(&y0)) / energy(&y0)).abs();
    assert!(drift < 1e-10, "{drift:e}");
}

#[test]
fn error_types() {
    let tol = OdeTolerance::default();
    // Non-finite derivative at the start.
    let err = solve(|_, _: &[f64; 1]| [f64::NAN], 0.0, [1.0], 1.0, tol).unwrap_err();
    assert!(matches!(err, NumericsError::NonFinite { .. }), "{err:?}");
    // Non-finite initial value.
    let err = solve(|_, y: &[f64; 1]| [y[0]], 0.0, [f64::INFINITY], 1.0, tol).unwrap_err();
    assert!(
        matches!(err, NumericsError::InvalidArgument { .. }),
        "{err:?}"
    );
    // Blow-up: y' = y^2, y(0) = 1 explodes at t = 1: the derivative becomes
    // non-finite or the step underflows before t = 2.
    let err = solve(|_, y: &[f64; 1]| [y[0] * y[0]], 0.0, [1.0], 2.0, tol).unwrap_err();
    assert!(
        matches!(
            err,
            NumericsError::NonFinite { .. } | NumericsError::NoConvergence { .. }
        ),
        "{err:?}"
    );
    // Step limit.
    let err = solve(oscillator, 0.0, [0.0, 1.0], 100.0, tol.with_max_steps(5)).unwrap_err();
    assert!(
        matches!(err, NumericsError::NoConvergence { method, .. } if method.contains("step limit")),
        "{err:?}"
    );
    // Bad tolerances and end time.
    for bad in [
        OdeTolerance::new(f64::NAN, 1e-12),
        OdeTolerance::new(1e-8, -1.0),
        OdeTolerance::new(0.0, 0.0),
        OdeTolerance::new(1e-8, 1e-8).with_max_step(0.0),
    ] {
        let err = solve(oscillator, 0.0, [0.0, 1.0], 1.0, bad).unwrap_err();
        assert!(
            matches!(err, NumericsError::InvalidArgument { .. }),
            "{err:?}"
        );
    }
    let err = solve(oscillator, 0.0, [0.0, 1.0], -1.0, tol).unwrap_err();
    assert!(
        matches!(err, NumericsError::InvalidArgument { .. }),
        "{err:?}"
    );
}

#[test]
fn step_underflow_is_reported() {
    // y' = -sign(y) * 1e6 chatters around 0 (a discontinuous right-hand side): the
    // controller cannot meet a tight tolerance and must report underflow or step limit
    // instead of looping forever.
    let tol = OdeTolerance::new(1e-14, 1e-300).with_max_steps(100_000);
    let res = solve(
        |_, y: &[f64; 1]| [if y[0] > 0.0 { -1.0 } else { 1.0 }],
        1.0,
        [1e-3],
        1e6,
        tol,
    );
    match res {
        Err(NumericsError::NoConvergence { .. }) => {}
        other => panic!("expected NoConvergence, got {other:?}"),
    }
}

#[test]
fn stepper_restart_after_discontinuity() {
    // y' = 1 until y = 1 (event), then y' = -2: at t = 1.5, y = 0.
    let tol = OdeTolerance::new(1e-12, 1e-12);
    let mut slope = 1.0;
    let mut f = |_: f64, _: &[f64; 1]| [slope];
    let mut s = DormandPrince::new(&mut f, 0.0, [0.0], 10.0, tol).unwrap();
    let mut g_prev = -1.0;
    let hit = loop {
        s.step(&mut f, 10.0).unwrap();
        let g_new = s.y()[0] - 1.0;
        if let Some((hit, _)) = s
            .locate_event(
                |_, y| y[0] - 1.0,
                EventDirection::Rising,
                g_prev,
                g_new,
                0.0,
            )
            .unwrap()
        {
            break hit;
        }
        g_prev = g_new;
    };
    assert!((hit.t - 1.0).abs() < 1e-12);
    slope = -2.0;
    let mut f = |_: f64, _: &[f64; 1]| [slope];
    s.restart(&mut f, hit.t, hit.y, 1.5).unwrap();
    while s.t() < 1.5 {
        s.step(&mut f, 1.5).unwrap();
    }
    assert!(s.y()[0].abs() < 1e-11, "{:?}", s.y());
}
