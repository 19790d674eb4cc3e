use serde::Serialize;
use std::ops::{Add, AddAssign};

/// What a numerical computation spent: function evaluations and solver iterations.
///
/// Costs add up (`+`, `+=`), so a model can report the total work of a result that
/// needed several root searches and integrals. Closed forms cost [`Cost::ZERO`].
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Serialize)]
pub struct Cost {
    /// Number of evaluations of the function being solved or integrated.
    pub evaluations: u64,
    /// Number of iterations (root finding) or refinement levels (quadrature).
    pub iterations: u64,
}

impl Cost {
    /// Nothing spent: the cost of a closed form.
    pub const ZERO: Cost = Cost {
        evaluations: 0,
        iterations: 0,
    };

    /// A cost of `evaluations` function evaluations and `iterations` iterations.
    pub const fn new(evaluations: u64, iterations: u64) -> Self {
        Cost {
            evaluations,
            iterations,
        }
    }
}

impl Add for Cost {
    type Output = Cost;
    fn add(self, rhs: Cost) -> Cost {
        Cost {
            evaluations: self.evaluations.saturating_add(rhs.evaluations),
            iterations: self.iterations.saturating_add(rhs.iterations),
        }
    }
}

impl AddAssign for Cost {
    fn add_assign(&mut self, rhs: Cost) {
        *self = *self + rhs;
    }
}

impl std::iter::Sum for Cost {
    fn sum<I: Iterator<Item = Cost>>(iter: I) -> Cost {
        iter.fold(Cost::ZERO, |a, b| a + b)
    }
}
