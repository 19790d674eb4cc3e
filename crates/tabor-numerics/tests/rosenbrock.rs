#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Tests of the Rosenbrock integrators (Rodas5P, RODAS4): order, stiff problems against
//! closed forms and against the explicit integrator, dense output, events, errors.

use tabor_numerics::ode::{self, EventDirection, OdeTolerance};
use tabor_numerics::rosenbrock::{
    finite_difference_jacobian, solve, solve_until_event, Jacobian, Matrix, Rosenbrock, Scheme,
};
use tabor_numerics::NumericsError;

/// Prothero-Robinson: `y' = λ (y − φ(t)) + φ'(t)`, φ = cos t, exact y = cos t.
fn prothero_robinson(lambda: f64) -> impl FnMut(f64, &[f64; 1]) -> [f64; 1] {
    move |t, y| [lambda * (y[0] - t.cos()) - t.sin()]
}

/// Integrates with a constant step h (max_step = initial_step = h, loose
/// tolerance so that every step is accepted) and returns the error at t = 1.
fn constant_step_error(lambda: f64, h: f64, scheme: Scheme) -> f64 {
    let mut tol = OdeTolerance::new(0.5, 0.5).with_max_step(h);
    tol.initial_step = Some(h);
    let mut f = prothero_robinson(lambda);
    let mut s = Rosenbrock::new(
        &mut f,
        0.0,
        [1.0],
        1.0,
        tol,
        Jacobian::NonAutonomous,
        scheme,
    )
    .unwrap();
    while s.t() < 1.0 {
        s.step(&mut f, 1.0).unwrap();
    }
    assert_eq!(s.steps().1, 0);
    (s.y()[0] - 1.0_f64.cos()).abs()
}

#[test]
fn orders_on_a_nonautonomous_problem() {
    // λ = −2 (not stiff): halving h divides the error by ≈ 2^p, p = 5 (Rodas5P),
    // 4 (RODAS4), which also checks the ∂f/∂t coefficients. Asserted ratio within
    // [0.75, 1.4] · 2^p.
    for (scheme, p) in [(Scheme::Rodas5P, 5), (Scheme::Rodas4, 4)] {
        let mut last = None;
        for k in 2..6 {
            let h = 0.5_f64.powi(k);
            let e = constant_step_error(-2.0, h, scheme);
            if let Some(prev) = last {
                let ratio: f64 = prev / e / 2f64.powi(p);
                println!("{scheme:?} h = {h}: error {e:e}, ratio / 2^p {ratio:.2}");
                assert!((0.75..1.4).contains(&ratio), "{scheme:?} h = {h}: {ratio}");
            }
            last = Some(e);
        }
    }
}

#[test]
fn stiffly_accurate_on_prothero_robinson() {
    // λ = −1e8, h ≫ 1/|λ|: an L-stable, stiffly accurate method stays on y = φ with
    // an error far below the step's nominal h^p (observed ≤ 1e-12); an explicit
    // method would need h < 3.3e-8.
    for scheme in [Scheme::Rodas5P, Scheme::Rodas4] {
        for &h in &[0.1, 0.05, 0.025] {
            let e = constant_step_error(-1e8, h, scheme);
            assert!(e < 1e-9, "{scheme:?} h = {h}: error {e:e}");
        }
    }
}

#[test]
fn rodas5p_keeps_its_order_at_moderate_stiffness() {
    // Prothero-Robinson with λ = −1e4 and h λ ~ 1-100: RODAS4 (stage order 1)
    // loses order and needs ~100 times the steps from tolerance 1e-6 to 1e-9,
    // Rodas5P about twice (observed 10 → 22 against 18 → 1697). Asserted: Rodas5P
    // under 100 steps at 1e-9 and fewer than a fifth of RODAS4's.
    let count = |scheme, rel: f64| {
        let mut f = prothero_robinson(-1e4);
        let tol = OdeTolerance::new(rel, rel);
        let mut s = Rosenbrock::new(
            &mut f,
            0.0,
            [1.0],
            1.0,
            tol,
            Jacobian::NonAutonomous,
            scheme,
        )
        .unwrap();
        while s.t() < 1.0 {
            s.step(&mut f, 1.0).unwrap();
        }
        assert!((s.y()[0] - 1.0_f64.cos()).abs() < 100.0 * rel);
        s.steps().0 + s.steps().1
    };
    let (p6, p9) = (count(Scheme::Rodas5P, 1e-6), count(Scheme::Rodas5P, 1e-9));
    let (r6, r9) = (count(Scheme::Rodas4, 1e-6), count(Scheme::Rodas4, 1e-9));
    println!("steps: Rodas5P {p6} → {p9}, RODAS4 {r6} → {r9}");
    assert!(p9 < 100 && 5 * p9 < r9, "Rodas5P {p9}, RODAS4 {r9}");
}

#[test]
fn stiff_linear_system_matches_closed_form() {
    // y1' = −y1 + y2, y2' = −1e6 (y2 − cos t) − sin t: y2 = cos t + (y2(0) − 1) e^{−1e6 t},
    // y1 = e^{−t} y1(0) + ∫ e^{−(t−s)} y2(s) ds. With y2(0) = 1, y1(0) = 0.5:
    // y1 = 0.5 e^{−t} + (cos t + sin t − e^{−t})/2. Relative tolerance 1e-8:
    // errors below 1e-7 in a few hundred steps (the explicit method: ~1e6 steps).
    let f = |t: f64, y: &[f64; 2]| [-y[0] + y[1], -1e6 * (y[1] - t.cos()) - t.sin()];
    let tol = OdeTolerance::new(1e-8, 1e-10);
    let t_end = 5.0;
    let sol = solve(f, 0.0, [0.5, 1.0], t_end, tol, Jacobian::NonAutonomous).unwrap();
    let y1 = 0.5 * (-t_end).exp() + 0.5 * (t_end.cos() + t_end.sin() - (-t_end).exp());
    assert!((sol.y[0] - y1).abs() < 1e-7, "{} vs {y1}", sol.y[0]);
    assert!((sol.y[1] - t_end.cos()).abs() < 1e-7, "{}", sol.y[1]);
    println!(
        "steps {} + {} rejected, evaluations {}",
        sol.accepted_steps, sol.rejected_steps, sol.cost.evaluations
    );
    assert!(sol.accepted_steps < 500, "{}", sol.accepted_steps);
}

#[test]
fn transient_then_slow_manifold_against_the_explicit_method() {
    // y' = −γ (y − x^{3/2}), x' = −x y / 10 with γ = 1e3: a fast transient from
    // y(0) = 1 onto the slow manifold. Compared with Dormand-Prince at 1e-12 (which
    // needs ~1e4 steps at its stability limit): agreement to 1e-7 at tol 1e-9, in far
    // fewer steps.
    let gamma = 1e3;
    let f = move |_t: f64, y: &[f64; 2]| [-y[0] * y[1] / 10.0, -gamma * (y[1] - y[0].powf(1.5))];
    let t_end = 20.0;
    let reference = ode::solve(f, 0.0, [0.8, 1.0], t_end, OdeTolerance::new(1e-12, 1e-14)).unwrap();
    let sol = solve(
        f,
        0.0,
        [0.8, 1.0],
        t_end,
        OdeTolerance::new(1e-9, 1e-12),
        Jacobian::Autonomous,
    )
    .unwrap();
    for i in 0..2 {
        assert!(
            (sol.y[i] - reference.y[i]).abs() < 1e-7 * reference.y[i].abs(),
            "{:?} vs {:?}",
            sol.y,
            reference.y
        );
    }
    println!(
        "Rodas5P {} steps / {} evaluations, DOPRI5 {} steps",
        sol.accepted_steps + sol.rejected_steps,
        sol.cost.evaluations,
        reference.accepted_steps + reference.rejected_steps
    );
    assert!(sol.accepted_steps * 10 < reference.accepted_steps);
}

#[test]
fn dense_output_is_accurate_inside_steps() {
    // Harmonic oscillator at tolerance 1e-10: the continuous extension (order 4)
    // stays within 1e-7 of sin, cos inside the steps.
    let mut f = |_t: f64, y: &[f64; 2]| [y[1], -y[0]];
    let tol = OdeTolerance::new(1e-10, 1e-12);
    let mut s = Rosenbrock::new(
        &mut f,
        0.0,
        [0.0, 1.0],
        10.0,
        tol,
        Jacobian::Autonomous,
        Scheme::Rodas5P,
    )
    .unwrap();
    let mut worst: f64 = 0.0;
    while s.t() < 10.0 {
        s.step(&mut f, 10.0).unwrap();
        let (a, b) = (s.previous_t(), s.t());
        for j in 0..=10 {
            let t = a + (b - a) * j as f64 / 10.0;
            let y = s.dense_output(t);
            worst = worst
                .max((y[0] - t.sin()).abs())
                .max((y[1] - t.cos()).abs());
        }
    }
    println!("dense output error {worst:e}");
    assert!(worst < 1e-7, "dense output error {worst:e}");
    // The ends of the step are reproduced exactly.
    let y = s.dense_output(s.t());
    assert_eq!(y, s.y());
}

#[test]
fn event_on_a_stiff_problem() {
    // y' = −1e5 (y − e^{−t}) − e^{−t}, y(0) = 1: y = e^{−t}; the event y = 1/2 at
    // t = ln 2, located on the dense output to 1e-8.
    let sol = solve_until_event(
        |t: f64, y: &[f64; 1]| [-1e5 * (y[0] - (-t).exp()) - (-t).exp()],
        |_t, y: &[f64; 1]| y[0] - 0.5,
        EventDirection::Falling,
        0.0,
        [1.0],
        10.0,
        OdeTolerance::new(1e-10, 1e-12),
        Jacobian::NonAutonomous,
    )
    .unwrap();
    assert!(sol.event_found);
    assert!((sol.t - 2.0_f64.ln()).abs() < 1e-8, "{}", sol.t);
    assert!((sol.y[0] - 0.5).abs() < 1e-9);
}

#[test]
fn analytic_and_difference_jacobians_agree() {
    let lambda = -1e4;
    let mut f = |_t: f64, y: &[f64; 2]| [y[1], lambda * y[1] - y[0]];
    let jac: Matrix<2> = [[0.0, 1.0], [-1.0, lambda]];
    let f0 = f(0.0, &[0.3, -0.2]);
    let fd = finite_difference_jacobian(&mut f, 0.0, &[0.3, -0.2], &f0);
    for i in 0..2 {
        for j in 0..2 {
            // Forward differences: rounding error ~ ε |f| / √ε relative to the
            // row's largest entry.
            assert!(
                (fd[i][j] - jac[i][j]).abs() <= 1e-7 * (1.0 - lambda),
                "{fd:?}"
            );
        }
    }
    let tol = OdeTolerance::new(1e-9, 1e-12);
    let mut a = Rosenbrock::new(
        &mut f,
        0.0,
        [1.0, 0.0],
        50.0,
        tol,
        Jacobian::Autonomous,
        Scheme::Rodas5P,
    )
    .unwrap();
    while a.t() < 50.0 {
        a.step_with_jacobian(
            &mut f,
            &mut |_f: &mut _, _t, _y: &[f64; 2], _fy: &[f64; 2]| (jac, [0.0; 2]),
            50.0,
        )
        .unwrap();
    }
    let b = solve(f, 0.0, [1.0, 0.0], 50.0, tol, Jacobian::Autonomous).unwrap();
    // Overdamped: x ≈ e^{−t/|λ|}, reached with steps of order 1.
    let exact = (-50.0 / 1e4_f64).exp();
    assert!((a.y()[0] - exact).abs() < 1e-6, "{}", a.y()[0]);
    assert!((b.y[0] - a.y()[0]).abs() < 1e-8);
}

#[test]
fn errors_are_typed() {
    let tol = OdeTolerance::new(1e-8, 1e-10);
    let mut f = |_t: f64, y: &[f64; 1]| [-y[0]];
    // Invalid tolerance, start and limits.
    let bad = OdeTolerance::new(f64::NAN, 1e-10);
    assert!(matches!(
        Rosenbrock::new(
            &mut f,
            0.0,
            [1.0],
            1.0,
            bad,
            Jacobian::Autonomous,
            Scheme::Rodas5P
        ),
        Err(NumericsError::InvalidArgument { .. })
    ));
    assert!(matches!(
        Rosenbrock::new(
            &mut f,
            0.0,
            [f64::NAN],
            1.0,
            tol,
            Jacobian::Autonomous,
            Scheme::Rodas5P
        ),
        Err(NumericsError::InvalidArgument { .. })
    ));
    let mut s = Rosenbrock::new(
        &mut f,
        0.0,
        [1.0],
        1.0,
        tol,
        Jacobian::Autonomous,
        Scheme::Rodas5P,
    )
    .unwrap();
    assert!(matches!(
        s.step(&mut f, 0.0),
        Err(NumericsError::InvalidArgument { .. })
    ));
    // Step limit.
    let few = OdeTolerance::new(1e-12, 1e-14).with_max_steps(3);
    assert!(matches!(
        solve(f, 0.0, [1.0], 100.0, few, Jacobian::Autonomous),
        Err(NumericsError::NoConvergence { .. })
    ));
    // A right-hand side that blows up in finite time (y' = y², y(0) = 1, t = 1).
    let r = solve(
        |_t, y: &[f64; 1]| [y[0] * y[0]],
        0.0,
        [1.0],
        2.0,
        tol,
        Jacobian::Autonomous,
    );
    assert!(r.is_err(), "{r:?}");
}
