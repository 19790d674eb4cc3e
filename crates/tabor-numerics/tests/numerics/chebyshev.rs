//! Chebyshev interpolation and the uniform table.

use super::*;

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
