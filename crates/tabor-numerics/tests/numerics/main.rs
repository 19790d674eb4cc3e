//! Known values, failure modes and property tests of the numerical layer, one
//! module a concern.
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

mod chebyshev;
mod failures;
mod integrals;
mod roots;
mod special;
