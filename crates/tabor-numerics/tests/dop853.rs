#![allow(clippy::unwrap_used, clippy::expect_used)]
//! Tests of DOP853 and of the multi-event driver against closed-form solutions.

use tabor_numerics::ode::{
    drive, drive_events, DenseStepper, DormandPrince, DormandPrince853, EventDirection,
    OdeTolerance,
};

/// y' = t y², y(0) = 1: y = 2/(2 − t²) (nonlinear and non-autonomous, so every
/// coupling coefficient and node of the tableau takes part).
fn riccati(t: f64, y: &[f64; 1]) -> [f64; 1] {
    [t * y[0] * y[0]]
}

fn riccati_exact(t: f64) -> f64 {
    2.0 / (2.0 - t * t)
}

/// Fixed steps of size h (a loose tolerance accepts every step; the first and the
/// largest step are h) of `f` from (0, y0) to `t_end`: the error at the end and
/// the worst error of the dense output at 3/10, 1/2 and 7/10 of each step.
fn fixed_step_errors<F, E, const N: usize>(
    mut f: F,
    exact: E,
    y0: [f64; N],
    t_end: f64,
    h: f64,
) -> (f64, f64)
where
    F: FnMut(f64, &[f64; N]) -> [f64; N],
    E: Fn(f64) -> f64,
{
    let mut tol = OdeTolerance::new(1.0, 1.0).with_max_step(h);
    tol.initial_step = Some(h);
    let mut s = DormandPrince853::new(&mut f, 0.0, y0, t_end, tol).unwrap();
    let mut dense: f64 = 0.0;
    while s.t() < t_end - 1e-12 {
        s.step(&mut f, t_end).unwrap();
        s.prepare_dense_output(&mut f).unwrap();
        for q in [0.3, 0.5, 0.7] {
            let t = s.previous_t() + q * (s.t() - s.previous_t());
            dense = dense.max((s.dense_output(t)[0] - exact(t)).abs());
        }
    }
    assert_eq!(s.steps().1, 0, "no step may be rejected");
    ((s.y()[0] - exact(t_end)).abs(), dense)
}

#[test]
fn order_eight_solution_and_order_seven_dense_output() {
    // Halving h divides the global error by 2^8 = 256 (order 8; window [180, 360]
    // on the Riccati equation up to t = 1, measured 195 and 246 from h = 0.2) and the
    // error of the dense output inside the steps by as much (its local error is
    // O(h^8); on y'' + y = cos t, y = (1 + t/2) sin t, measured 275 and 258 from
    // h = 0.8; window above 200).
    let riccati_run = |h| fixed_step_errors(riccati, riccati_exact, [1.0], 1.0, h);
    let (e1, _) = riccati_run(0.1);
    let (e2, _) = riccati_run(0.05);
    let ratio = e1 / e2;
    assert!((180.0..360.0).contains(&ratio), "{e1:e} / {e2:e} = {ratio}");
    let forced = |t: f64, y: &[f64; 2]| [y[1], -y[0] + t.cos()];
    let exact = |t: f64| (1.0 + 0.5 * t) * t.sin();
    let (_, d1) = fixed_step_errors(forced, exact, [0.0, 1.0], 4.0, 0.4);
    let (_, d2) = fixed_step_errors(forced, exact, [0.0, 1.0], 4.0, 0.2);
    let dense_ratio = d1 / d2;
    assert!(dense_ratio > 200.0, "{d1:e} / {d2:e} = {dense_ratio}");
    assert!(e2 < 1e-11 && d2 < 1e-11);
}

#[test]
fn tight_tolerance_with_fewer_evaluations_than_dormand_prince() {
    // The harmonic oscillator over ten periods at rtol = atol = 1e-12: both within
    // 1e-9 of sin/cos; DOP853 with fewer than half the evaluations.
    let tol = OdeTolerance::new(1e-12, 1e-12);
    let t_end = 20.0 * std::f64::consts::PI;
    let mut f = |_: f64, y: &[f64; 2]| [y[1], -y[0]];
    let mut a = DormandPrince853::new(&mut f, 0.0, [0.0, 1.0], t_end, tol).unwrap();
    let mut b = DormandPrince::new(&mut f, 0.0, [0.0, 1.0], t_end, tol).unwrap();
    while a.t() < t_end {
        a.step(&mut f, t_end).unwrap();
    }
    while b.t() < t_end {
        b.step(&mut f, t_end).unwrap();
    }
    for y in [a.y(), b.y()] {
        assert!(y[0].abs() < 1e-9 && (y[1] - 1.0).abs() < 1e-9, "{y:?}");
    }
    assert!(
        2 * a.cost().evaluations < b.cost().evaluations,
        "{:?} vs {:?}",
        a.cost(),
        b.cost()
    );
}

#[test]
fn drive_events_stops_at_the_earliest_of_several_events() {
    // y'' = −y from (0, 1): y = sin t. Events: y falls to 0.5 (t = 5π/6) and y'
    // falls through 0 (t = π/2); the second comes first. With the order swapped the
    // index follows. Located to 1e-12.
    let tol = OdeTolerance::new(1e-12, 1e-12);
    let mut f = |_: f64, y: &[f64; 2]| [y[1], -y[0]];
    for swap in [false, true] {
        let mut s = DormandPrince853::new(&mut f, 0.0, [0.0, 1.0], 10.0, tol).unwrap();
        let mut g = |_: f64, y: &[f64; 2]| {
            let e = [y[0] - 0.5, y[1]];
            if swap {
                [e[1], e[0]]
            } else {
                e
            }
        };
        let mut seen = 0;
        let dirs = [EventDirection::Falling; 2];
        let run = drive_events(&mut s, &mut f, &mut g, dirs, 10.0, &mut |_, _| seen += 1).unwrap();
        assert_eq!(run.event, Some(if swap { 0 } else { 1 }));
        assert!(run.solution.event_found);
        assert!((run.solution.t - std::f64::consts::FRAC_PI_2).abs() < 1e-12);
        assert!((run.solution.y[0] - 1.0).abs() < 1e-12);
        assert!(seen > 0 && seen < run.solution.accepted_steps as usize);
        // the rising crossing of y = 0.5 at π/6 does not count (falling only)
        assert!(run.solution.t > 1.0);
    }
}

#[test]
fn single_event_driver_prepares_the_dense_output_for_its_observer() {
    // The observer samples the dense output of every step: with DOP853 it is the
    // order-7 extension (prepared by drive), within 1e-10 of sin t.
    let tol = OdeTolerance::new(1e-12, 1e-12);
    let mut f = |_: f64, y: &[f64; 2]| [y[1], -y[0]];
    let mut s = DormandPrince853::new(&mut f, 0.0, [0.0, 1.0], 10.0, tol).unwrap();
    let mut worst: f64 = 0.0;
    let run = drive(
        &mut s,
        &mut f,
        &mut |_, y: &[f64; 2]| y[0] + 0.5,
        EventDirection::Falling,
        10.0,
        &mut |st: &DormandPrince853<2>, stop: f64| {
            let a = st.step_start();
            let t = 0.5 * (a + stop);
            worst = worst.max((st.dense(t)[0] - t.sin()).abs());
        },
    )
    .unwrap();
    let t_event = std::f64::consts::PI + std::f64::consts::FRAC_PI_6;
    assert!((run.solution.t - t_event).abs() < 1e-12);
    assert!(worst < 1e-10, "{worst:e}");
}

/// `error_components`: the components after the first m are integrated with the
/// steps the first m choose. The Riccati equation with a quadrature appended
/// takes exactly the steps of the Riccati equation alone (the same time points
/// and values, bit for bit: the error norm and `HINIT` see only y), whatever the
/// quadrature: `w' = y + 10⁴ sin(10³ t)` (fast and large: under full control it
/// takes over ten times the steps) as well as `w' = y`, which the steps of the
/// motion resolve: w is `∫ 2/(2 − s²) ds = √2 artanh(t/√2)` to 10⁻⁹ (tolerance
/// 10⁻¹⁰ per step, ~20 steps).
#[test]
fn error_components_leave_trailing_quadratures_out_of_step_control() {
    let tol = OdeTolerance::new(1e-10, 1e-12);
    let t_end = 1.0;
    let mut f = riccati;
    let mut s = DormandPrince853::new(&mut f, 0.0, [1.0], t_end, tol).unwrap();
    let mut alone = vec![];
    while s.t() < t_end {
        s.step(&mut f, t_end).unwrap();
        alone.push((s.t(), s.y()[0]));
    }
    let steps_alone = s.steps();
    let with_quadrature = |fast: f64, controlled: Option<usize>| {
        let mut f = |t: f64, y: &[f64; 2]| [t * y[0] * y[0], y[0] + fast * (1e3 * t).sin()];
        let tol = OdeTolerance {
            error_components: controlled,
            ..tol
        };
        let mut s = DormandPrince853::new(&mut f, 0.0, [1.0, 0.0], t_end, tol).unwrap();
        let mut points = vec![];
        while s.t() < t_end {
            s.step(&mut f, t_end).unwrap();
            points.push((s.t(), s.y()[0]));
        }
        (points, s.steps(), s.y()[1])
    };
    for fast in [0.0, 1e4] {
        let (points, steps, _) = with_quadrature(fast, Some(1));
        assert_eq!(points, alone, "the same steps and values ({fast})");
        assert_eq!(steps, steps_alone);
    }
    let (_, steps_full, _) = with_quadrature(1e4, None);
    assert!(
        steps_full.0 > 10 * steps_alone.0,
        "under full control the fast quadrature chooses the steps: {steps_full:?} vs {steps_alone:?}"
    );
    let (_, _, w) = with_quadrature(0.0, Some(1));
    let exact = 2f64.sqrt() * (t_end / 2f64.sqrt()).atanh();
    assert!((w - exact).abs() < 1e-9, "{w} vs {exact}");
    // zero components: refused
    let bad = OdeTolerance::new(1e-10, 1e-12).with_error_components(0);
    assert!(DormandPrince853::new(&mut f, 0.0, [1.0], 1.0, bad).is_err());
}
