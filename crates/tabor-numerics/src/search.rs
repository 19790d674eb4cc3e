//! Where a yes/no property of a positive argument stops holding: bisection on the
//! logarithm of the argument between a point where it holds and one where it does
//! not (for example the highest impact speed at which two models still agree
//! within a bound). No physics; the property may be expensive and may fail.

use crate::error::NumericsError;
use crate::Cost;

/// The two points that bracket the edge of a property after bisection: `inside`
/// (the property holds) and `outside` (it does not), within the requested ratio.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Edge {
    /// The last point found where the property holds.
    pub inside: f64,
    /// The nearest point found where it does not.
    pub outside: f64,
    /// Evaluations of the property (the ends given are not evaluated).
    pub cost: Cost,
}

/// Bisects the edge of a property between `inside` (where `holds` is true) and
/// `outside` (where it is false), both finite and > 0, in geometric means
/// √(inside · outside), until max/min of the two is at most 1 + `relative`
/// (finite, > 0). The ends are taken as given, not evaluated; `holds` is called
/// about log₂(ln(outside/inside)/relative) times, and its first error is returned.
///
/// Where the property switches more than once between the ends, one of the edges
/// is found (bisection keeps a bracket, not the first switch).
pub fn geometric_edge<E, F>(
    mut holds: F,
    inside: f64,
    outside: f64,
    relative: f64,
) -> Result<Edge, E>
where
    F: FnMut(f64) -> Result<bool, E>,
    E: From<NumericsError>,
{
    for (name, value) in [("inside", inside), ("outside", outside)] {
        if !(value.is_finite() && value > 0.0) {
            return Err(NumericsError::InvalidArgument {
                name,
                value,
                requirement: "must be finite and > 0",
            }
            .into());
        }
    }
    if !(relative.is_finite() && relative > 0.0) {
        return Err(NumericsError::InvalidArgument {
            name: "relative",
            value: relative,
            requirement: "must be finite and > 0",
        }
        .into());
    }
    let (mut good, mut bad) = (inside, outside);
    let mut evaluations = 0;
    while good.max(bad) / good.min(bad) > 1.0 + relative {
        let trial = (good * bad).sqrt();
        // the geometric mean of two neighbouring floats is one of them: done
        if trial == good || trial == bad {
            break;
        }
        evaluations += 1;
        if holds(trial)? {
            good = trial;
        } else {
            bad = trial;
        }
    }
    Ok(Edge {
        inside: good,
        outside: bad,
        cost: Cost::new(evaluations, evaluations),
    })
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn finds_a_known_edge_from_either_side() {
        // the property x² < 2 ends at √2 (a closed form independent of the search)
        let up = geometric_edge::<NumericsError, _>(|x| Ok(x * x < 2.0), 1.0, 4.0, 1e-12).unwrap();
        assert!(up.inside < 2f64.sqrt() && up.outside >= 2f64.sqrt());
        assert!((up.outside / up.inside - 1.0) <= 1e-12);
        let down =
            geometric_edge::<NumericsError, _>(|x| Ok(x * x > 2.0), 4.0, 1e-3, 1e-9).unwrap();
        assert!(down.inside > 2f64.sqrt() && down.outside <= 2f64.sqrt());
        assert!((down.inside / 2f64.sqrt() - 1.0) < 1e-9);
        // ~log2(ln(4)/1e-12) = 41 evaluations
        assert!(up.cost.evaluations <= 42, "{}", up.cost.evaluations);
    }

    #[test]
    fn errors_pass_through_and_bad_ends_are_refused() {
        let e = geometric_edge::<NumericsError, _>(
            |x| {
                Err(NumericsError::NonFinite {
                    at: x,
                    value: f64::NAN,
                })
            },
            1.0,
            2.0,
            1e-6,
        );
        assert!(matches!(e, Err(NumericsError::NonFinite { .. })));
        for (a, b, r) in [(0.0, 1.0, 1e-3), (1.0, f64::NAN, 1e-3), (1.0, 2.0, 0.0)] {
            assert!(matches!(
                geometric_edge::<NumericsError, _>(|_| Ok(true), a, b, r),
                Err(NumericsError::InvalidArgument { .. })
            ));
        }
    }
}
