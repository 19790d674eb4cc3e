//! The curve F̂(d̂) along a Maugis-Dugdale impact, with â and b̂: approach, jump-in,
//! loading, unloading, pull-off. For plots, and as the force law of a time-domain
//! simulation ([`equilibrium_state`]).

use crate::branch::{
    contact_state, junction_factor, no_contact_pull_off_radius, no_contact_state,
    ContactBranchState,
};
use crate::impact::{check_lambda, impact_path, theta_at_depth, PathState, TaborCase};
use serde::Serialize;
use std::f64::consts::FRAC_PI_2;
use tabor_numerics::Cost;
use tabor_restitution::{validate, Error, Result};

/// The stage of the impact a traced point belongs to.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Phase {
    /// Approach without force, d̂ < −1/Λ.
    Approach,
    /// The jump onto the equilibrium branch at d̂ = −1/Λ (5.40).
    JumpIn,
    /// Loading along the equilibrium branch.
    Loading,
    /// Unloading along the same branch down to the pull-off depth.
    Unloading,
    /// The snap-off at the displacement-controlled instability.
    PullOff,
}

/// One point of the traced curve, normalized.
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct TracePoint {
    /// The stage of the impact.
    pub phase: Phase,
    /// Depth d̂.
    pub depth: f64,
    /// Force F̂ (compression positive).
    pub force: f64,
    /// Contact radius â.
    pub contact_radius: f64,
    /// Cohesive-zone radius b̂ (0 when no adhesive zone exists).
    pub cohesive_radius: f64,
}

/// The equilibrium state at depth d̂ on the stable branch that the impact follows
/// between jump-in and pull-off (and above, for deeper indentation). Depths below
/// the pull-off depth have no such state: an error names `depth`.
///
/// Seed 000 section 5.3.2: the no-contact branch `d̂ = (3/2)b̂² − (32Λ/π²)b̂ − 1/Λ`
/// for `b̂_c ≤ b̂ ≤ K b̂_c` (solved in closed form), else the contact branch.
pub fn equilibrium_state(lambda: f64, depth: f64) -> Result<PathState> {
    let lambda = check_lambda(lambda)?;
    let depth = validate::finite("depth", depth)?;
    let path = impact_path(lambda)?;
    let mut cost = Cost::ZERO;
    let s = equilibrium_state_on(&path, depth, &mut cost)?;
    if !state_is_finite(&s) {
        return Err(Error::invalid(
            "depth",
            depth,
            "is so large that the equilibrium state overflows",
        ));
    }
    Ok(s)
}

fn state_is_finite(s: &PathState) -> bool {
    [s.depth, s.force, s.contact_radius, s.cohesive_radius]
        .iter()
        .all(|v| v.is_finite())
}

/// Most points per stage of [`trace_impact`] (bounds its memory and time).
const MAX_TRACE_POINTS: usize = 1_000_000;

pub(crate) fn equilibrium_state_on(
    path: &crate::impact::ImpactPath,
    depth: f64,
    cost: &mut Cost,
) -> Result<PathState> {
    equilibrium_state_near(path, depth, None, cost).map(|(s, _)| s)
}

/// A state on the contact branch where the solve for θ may start: its depth d̂,
/// θ and the slope dd̂/dθ there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct BranchPoint {
    pub(crate) depth: f64,
    pub(crate) theta: f64,
    pub(crate) depth_slope: f64,
}

/// [`equilibrium_state_on`] warm-started from `near`, a solved state at a nearby
/// depth: on the contact branch, Newton's method for `d̂(θ) = depth` starts from
/// the tangent prediction `θ + (depth − d̂)/(dd̂/dθ)` of `near` (one Newton step
/// for free) and is kept in the bracket `(0, θ_top]` by bisection; it stops when the
/// Newton correction is below 1e-15 θ and returns the state evaluated there (two or
/// three evaluations of the branch for the steps of an ODE integrator, against
/// eight to ten from a cold start). Also returns the point to start the next solve
/// from (`None` on the no-contact part, which is solved in closed form).
pub(crate) fn equilibrium_state_near(
    path: &crate::impact::ImpactPath,
    depth: f64,
    near: Option<BranchPoint>,
    cost: &mut Cost,
) -> Result<(PathState, Option<BranchPoint>)> {
    let lambda = path.lambda;
    if depth < path.pull_off.depth {
        return Err(Error::invalid(
            "depth",
            depth,
            "is below the pull-off depth: no equilibrium state with adhesive contact",
        ));
    }
    if path.case != TaborCase::Contact {
        let bc = no_contact_pull_off_radius(lambda);
        let k = junction_factor(lambda);
        // the no-contact part of the stable path: b̂ from b̂_c to K b̂_c
        let junction = no_contact_state(lambda, k * bc);
        if depth <= junction.depth {
            // (3/2)b² − 3 b_c b − (1/Λ + d) = 0, larger root
            let c = 1.0 / lambda + depth;
            let disc = (9.0 * bc * bc + 6.0 * c).max(0.0);
            let b = (3.0 * bc + disc.sqrt()) / 3.0;
            let s = no_contact_state(lambda, b);
            return Ok((
                PathState {
                    contact_radius: 0.0,
                    cohesive_radius: b,
                    depth: s.depth,
                    force: s.force,
                    theta: None,
                },
                None,
            ));
        }
    }
    let theta_top = path.pull_off.theta.unwrap_or(FRAC_PI_2);
    if depth == path.pull_off.depth && path.pull_off.theta.is_some() {
        return Ok((path.pull_off, None));
    }
    let s = match near.and_then(|p| theta_near(lambda, depth, theta_top, p, cost)) {
        Some(s) => s,
        None => match theta_at_depth(lambda, depth, theta_top, cost) {
            Ok(theta) => contact_state(lambda, theta),
            // cases 1 and 2: a depth between the junction's depth as the no-contact
            // branch gives it (taken as no contact above) and as the contact branch
            // gives it at θ = π/2 (they differ by rounding, up to ~1e-14, as the
            // contact branch's depth cancels there) has no θ below π/2: it is the
            // junction (â = 0)
            Err(e) => {
                let junction = contact_state(lambda, FRAC_PI_2);
                if path.case == TaborCase::Contact || junction.depth < depth {
                    return Err(e);
                }
                junction
            }
        },
    };
    let state = PathState {
        contact_radius: s.contact_radius,
        cohesive_radius: s.cohesive_radius,
        depth: s.depth,
        force: s.force,
        theta: Some(s.theta),
    };
    let next = BranchPoint {
        depth: s.depth,
        theta: s.theta,
        depth_slope: s.depth_slope,
    };
    Ok((state, Some(next)))
}

/// The contact-branch state at depth `target` by Newton's method from the tangent
/// prediction of `near`, in the bracket `(0, θ_top]` where d̂ decreases in θ; `None`
/// when the start is unusable or the iteration does not settle (the caller then
/// starts cold).
///
/// It stops when the Newton correction δ is below 1e-15 θ, returning the state
/// evaluated there, or earlier, when δ ≤ 1e-8 θ and the error left after the step,
/// estimated from the quadratic convergence as `C δ²` with `C = |δ|/δ_prev²` (δ_prev
/// the previous correction, or the tangent prediction's step), is below 1e-17 θ:
/// then the state at `θ − δ` is the evaluated one moved along its slopes by −δ (an
/// error of order δ² ≤ 1e-16 θ², below the rounding of the branch itself).
fn theta_near(
    lambda: f64,
    target: f64,
    theta_top: f64,
    near: BranchPoint,
    cost: &mut Cost,
) -> Option<ContactBranchState> {
    let (mut lo, mut hi) = (0.0, theta_top);
    let mut theta = near.theta + (target - near.depth) / near.depth_slope;
    if !(theta > lo && theta < hi) {
        theta = near.theta;
    }
    if !(theta > lo && theta <= hi) {
        return None;
    }
    let mut previous = theta - near.theta;
    for _ in 0..WARM_MAX_STEPS {
        let s = contact_state(lambda, theta);
        *cost += Cost::new(1, 1);
        let residual = s.depth - target;
        if residual > 0.0 {
            lo = theta;
        } else {
            hi = theta;
        }
        let step = residual / s.depth_slope;
        if residual == 0.0 || step.abs() <= 1e-15 * theta {
            return Some(s);
        }
        let left = step * step * step.abs() / (previous * previous);
        if step.abs() <= 1e-8 * theta
            && left <= 1e-17 * theta
            && theta - step < hi
            && theta - step > lo
        {
            return Some(moved(&s, -step, target));
        }
        previous = step;
        theta -= step;
        if !(theta > lo && theta < hi) {
            theta = 0.5 * (lo + hi);
        }
        if !step.is_finite() || hi - lo <= 1e-15 * theta {
            return None;
        }
    }
    None
}

/// The state `s` moved along the branch by `delta` in θ (first order), with its
/// depth set to `depth` (where the move lands by construction).
fn moved(s: &ContactBranchState, delta: f64, depth: f64) -> ContactBranchState {
    ContactBranchState {
        theta: s.theta + delta,
        contact_radius: s.contact_radius + s.contact_radius_slope * delta,
        cohesive_radius: s.cohesive_radius + s.cohesive_radius_slope * delta,
        depth,
        force: s.force + s.force_slope * delta,
        ..*s
    }
}

/// Steps of [`theta_near`] before it gives up (Newton from a nearby state takes a
/// handful; bisection would need about 50 to reach 1e-15).
const WARM_MAX_STEPS: usize = 60;

/// Traces F̂(d̂), â and b̂ along an impact at Tabor parameter Λ that reaches the
/// maximum depth `max_depth` (d̂ ≥ −1/Λ), with `points` points on each of the
/// loading and unloading stages (≥ 2).
///
/// Seed 000 section 5.3.2: approach without force to d̂ = −1/Λ (5.40), jump-in onto
/// the equilibrium branch ((5.41) without contact), loading and unloading along it,
/// snap-off at its minimum depth; the enclosed area is the loss (5.43).
pub fn trace_impact(lambda: f64, max_depth: f64, points: usize) -> Result<Vec<TracePoint>> {
    let lambda = check_lambda(lambda)?;
    let max_depth = validate::finite("max_depth", max_depth)?;
    if !(2..=MAX_TRACE_POINTS).contains(&points) {
        return Err(Error::invalid(
            "points",
            points as f64,
            "must be at least 2 and at most 1e6",
        ));
    }
    let path = impact_path(lambda)?;
    let d_in = path.jump_in.depth;
    if max_depth < d_in {
        return Err(Error::invalid(
            "max_depth",
            max_depth,
            "must be at least the jump-in depth -1/Lambda",
        ));
    }
    let mut cost = Cost::ZERO;
    let point = |phase: Phase, s: &PathState| TracePoint {
        phase,
        depth: s.depth,
        force: s.force,
        contact_radius: s.contact_radius,
        cohesive_radius: s.cohesive_radius,
    };
    let mut out = Vec::with_capacity(2 * points + 6);
    let approach_start = d_in - (max_depth - d_in).max(1.0 / lambda) * 0.25;
    for d in [approach_start, d_in] {
        out.push(TracePoint {
            phase: Phase::Approach,
            depth: d,
            force: 0.0,
            contact_radius: 0.0,
            cohesive_radius: 0.0,
        });
    }
    out.push(point(Phase::JumpIn, &path.jump_in));
    for i in 1..points {
        let d = d_in + (max_depth - d_in) * i as f64 / (points - 1) as f64;
        let s = equilibrium_state_on(&path, d, &mut cost)?;
        out.push(point(Phase::Loading, &s));
    }
    let d_off = path.pull_off.depth;
    for i in 1..points {
        let d = max_depth + (d_off - max_depth) * i as f64 / (points - 1) as f64;
        let s = if i == points - 1 {
            path.pull_off
        } else {
            equilibrium_state_on(&path, d, &mut cost)?
        };
        out.push(point(Phase::Unloading, &s));
    }
    out.push(TracePoint {
        phase: Phase::PullOff,
        depth: d_off,
        force: 0.0,
        contact_radius: 0.0,
        cohesive_radius: 0.0,
    });
    if !out.iter().all(|p| {
        [p.depth, p.force, p.contact_radius, p.cohesive_radius]
            .iter()
            .all(|v| v.is_finite())
    }) {
        return Err(Error::invalid(
            "max_depth",
            max_depth,
            "is so large that the traced states overflow",
        ));
    }
    Ok(out)
}

#[cfg(test)]
mod warm_start_tests {
    use super::*;

    #[test]
    fn warm_started_states_equal_the_cold_ones() {
        // Depths as an integrator visits them (steps of 1e-3 ... 0.3 of the range,
        // both ways): each state solved from the previous one equals the cold
        // solve to 1e-13 of the force and radius scales plus what the rounding of
        // the depth leaves open near pull-off, where d → θ is ill-conditioned.
        for lambda in [0.5, 1.0, 3.0, 100.0] {
            let path = impact_path(lambda).unwrap();
            let (lo, hi) = (path.pull_off.depth, path.pull_off.depth + 6.0);
            for step in [1e-3, 3e-2, 0.3] {
                let mut near = None;
                let mut d = hi;
                let mut cost = Cost::ZERO;
                while d > lo {
                    let (warm, next) = equilibrium_state_near(&path, d, near, &mut cost).unwrap();
                    let cold = equilibrium_state_on(&path, d, &mut cost).unwrap();
                    // θ is fixed by d̂ to 8 ε |d̂| / |dd̂/dθ| (rounding of the depth)
                    let c = contact_state(lambda, cold.theta.unwrap_or(FRAC_PI_2));
                    let dtheta = 8.0 * f64::EPSILON * d.abs().max(1.0) / c.depth_slope.abs();
                    let scale = 1e-13 * (1.0 + cold.force.abs()) + c.force_slope.abs() * dtheta;
                    let radius_scale =
                        1e-13 * (1.0 + cold.contact_radius) + c.contact_radius_slope.abs() * dtheta;
                    assert!(
                        (warm.force - cold.force).abs() <= scale,
                        "Λ = {lambda}, d = {d}: {} vs {}",
                        warm.force,
                        cold.force
                    );
                    assert!(
                        (warm.contact_radius - cold.contact_radius).abs() <= radius_scale,
                        "Λ = {lambda}, d = {d}"
                    );
                    near = next;
                    d -= step * (hi - lo);
                }
            }
        }
    }
}
