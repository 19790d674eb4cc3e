//! The MDR model of a sphere on an incompressible medium with one Maxwell branch,
//! seed 000 eqs. (5.84)-(5.91), shared by [`crate::standard_sphere`] and
//! [`crate::kelvin_maxwell_sphere`].
//!
//! Scaling (5.74) with G = G∞: x = d/d0, times in d0/v0, element coordinates
//! ξ = x_MDR/√(R d0) (profile g = ξ², (5.84)), internal variables ũ/d0. Each of
//! [`ELEMENTS`] elements at the midpoints ξ_k of a uniform grid on [0, L] carries
//! the line load (5.89)/(5.91), scaled by 4G∞d0:
//! `q_k = (x − ξ_k²) + ũ_k/β + τ̂0 ẋ` and the internal variable (5.88),
//! `ũ_k' = ẋ − ũ_k/τ̂` while in contact. The force is
//! `F̂ = (15/16) · 2 Δξ · Σ q_k` over the elements in contact, `ẍ = −F̂`.
//!
//! Contact: during compression an element is in contact once x > ξ_k²; during
//! restitution while also q_k > 0 (it leaves when its line load vanishes, (5.89)).
//! An element out of contact relaxes freely: with q = 0 the standard element obeys
//! `ũ' = −ũ/(τ̂ (1 + 1/β))`, and its free surface sits at u = −ũ/β, so the test
//! q_k > 0 is also exactly the test for renewed contact. (The Kelvin-Maxwell
//! element uses the same free relaxation; renewed contact does not occur in the
//! cases tested.) The grid length L is 1.1 √x_max from a first, coarser pass.

use crate::scaled::{ode_tolerance, restitution_from_rebound, run_phase, ScaledImpact};
use tabor_numerics::ode::EventDirection;
use tabor_restitution::Result;

/// Number of MDR elements on the half-axis.
pub const ELEMENTS: usize = 200;
const STATE: usize = ELEMENTS + 2;

/// A medium in scaled form.
#[derive(Clone, Copy, Debug)]
pub(crate) struct ScaledMedium {
    /// β = G∞/G1.
    pub beta: f64,
    /// Relaxation time of the Maxwell branch, scaled by d0/v0.
    pub tau: f64,
    /// Viscosity of the parallel dashpot (Kelvin-Maxwell), as τ̂0 = v0 η0/(G∞ d0).
    pub tau0: f64,
}

struct Grid {
    /// ξ_k² for the element midpoints.
    profile: [f64; ELEMENTS],
    /// (15/16) · 2Δξ.
    weight: f64,
}

impl Grid {
    fn new(length: f64) -> Self {
        let h = length / ELEMENTS as f64;
        let mut profile = [0.0; ELEMENTS];
        for (k, p) in profile.iter_mut().enumerate() {
            let xi = (k as f64 + 0.5) * h;
            *p = xi * xi;
        }
        Grid {
            profile,
            weight: 15.0 / 16.0 * 2.0 * h,
        }
    }
}

fn line_load(m: &ScaledMedium, y: &[f64; STATE], k: usize, grid: &Grid) -> f64 {
    (y[0] - grid.profile[k]) + y[k + 2] / m.beta + m.tau0 * y[1]
}

fn rhs(m: &ScaledMedium, grid: &Grid, y: &[f64; STATE], restitution: bool) -> [f64; STATE] {
    let mut out = [0.0; STATE];
    let mut force = 0.0;
    let free = 1.0 / (m.tau * (1.0 + 1.0 / m.beta));
    for k in 0..ELEMENTS {
        let geometric = y[0] > grid.profile[k];
        let q = line_load(m, y, k, grid);
        let contact = geometric && (!restitution || q > 0.0);
        if contact {
            force += q;
            out[k + 2] = y[1] - y[k + 2] / m.tau;
        } else {
            out[k + 2] = -y[k + 2] * free;
        }
    }
    out[0] = y[1];
    out[1] = -grid.weight * force;
    out
}

/// max_k min(q_k, x − ξ_k²): positive while any element is in contact.
fn contact_indicator(m: &ScaledMedium, grid: &Grid, y: &[f64; STATE]) -> f64 {
    (0..ELEMENTS)
        .map(|k| line_load(m, y, k, grid).min(y[0] - grid.profile[k]))
        .fold(f64::NEG_INFINITY, f64::max)
}

fn run(m: &ScaledMedium, length: f64, tolerance: f64, full: bool) -> Result<ScaledImpact> {
    let grid = Grid::new(length);
    let tol = ode_tolerance(tolerance, 0.05)?;
    let t_max = 1e4 * (1.0 + m.tau + m.tau0);
    let mut y0 = [0.0; STATE];
    y0[1] = 1.0;
    let mut f1 = |_t: f64, y: &[f64; STATE]| rhs(m, &grid, y, false);
    let first = run_phase(
        &mut f1,
        &mut |_t: f64, y: &[f64; STATE]| y[1],
        EventDirection::Falling,
        0.0,
        y0,
        t_max,
        tol,
        None,
    )?;
    if !full {
        return Ok(ScaledImpact {
            restitution: 1.0,
            contact_time: first.t,
            max_overlap: first.y[0],
            cost: first.cost,
        });
    }
    let mut f2 = |_t: f64, y: &[f64; STATE]| rhs(m, &grid, y, true);
    let second = run_phase(
        &mut f2,
        &mut |_t: f64, y: &[f64; STATE]| contact_indicator(m, &grid, y),
        EventDirection::Falling,
        first.t,
        first.y,
        first.t + t_max,
        tol,
        None,
    )?;
    Ok(ScaledImpact {
        restitution: restitution_from_rebound(-second.y[1])?,
        contact_time: second.t,
        max_overlap: first.y[0],
        cost: first.cost + second.cost,
    })
}

/// The impact: a coarse compression pass to size the grid, then the full run.
pub(crate) fn solve(m: &ScaledMedium, tolerance: f64) -> Result<ScaledImpact> {
    let coarse = run(m, 1.0, tolerance.max(1e-6), false)?;
    let length = (1.1 * coarse.max_overlap.max(0.0).sqrt()).clamp(1e-6, 1.0);
    let full = run(m, length, tolerance, true)?;
    Ok(ScaledImpact {
        cost: full.cost + coarse.cost,
        ..full
    })
}
