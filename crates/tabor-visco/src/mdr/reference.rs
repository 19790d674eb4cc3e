//! The discrete MDR of the seed (the crate's former solver), kept as an
//! independent reference for the tests: `S − 2` elements at the midpoints ξ_k of a
//! uniform grid on [0, L], each with its own internal variable; state
//! (x, ẋ, ũ_1 … ũ_n), one Dormand-Prince integration per phase (the driver of
//! `tabor_numerics::ode`).
//!
//! Element k carries `q_k = (x − ξ_k²) + ũ_k/β + τ̂0 ẋ` (5.89)/(5.91) and obeys
//! `ũ_k' = ẋ − ũ_k/τ̂` (5.88) while in contact; `F̂ = (15/16) · 2Δξ · Σ q_k` over the
//! elements in contact. During compression an element is in contact once
//! x > ξ_k²; during restitution while also q_k > 0. Out of contact it relaxes
//! freely, `ũ' = −ũ/(τ̂ (1 + 1/β))` (q = 0 with τ̂0 = 0), and it is in contact
//! again as soon as q_k > 0: renewed contact is allowed, and counted at the step
//! ends. For the standard medium (τ̂0 = 0) the free relaxation and the renewed
//! contact test are exact; for the Kelvin-Maxwell medium the free relaxation
//! ignores the dashpot η0, as the former solver did.

use super::ScaledMedium;
use crate::scaled::ode_tolerance;
use tabor_numerics::ode::{drive, DormandPrince, EventDirection};
use tabor_restitution::{Error, Result};

/// What the discrete model gives.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Discrete {
    pub restitution: f64,
    pub contact_time: f64,
    pub max_overlap: f64,
    pub evaluations: u64,
    /// Elements found in contact again (at a step end) after having left it.
    pub renewed_contacts: usize,
}

struct Grid<const S: usize> {
    /// ξ_k² for the element midpoints, in slots 2..S.
    profile: [f64; S],
    /// (15/16) · 2Δξ.
    weight: f64,
}

impl<const S: usize> Grid<S> {
    fn new(length: f64) -> Self {
        let n = S - 2;
        let h = length / n as f64;
        let mut profile = [0.0; S];
        for (k, p) in profile.iter_mut().skip(2).enumerate() {
            let xi = (k as f64 + 0.5) * h;
            *p = xi * xi;
        }
        Grid {
            profile,
            weight: 15.0 / 16.0 * 2.0 * h,
        }
    }

    fn line_load(&self, m: &ScaledMedium, y: &[f64; S], k: usize) -> f64 {
        (y[0] - self.profile[k]) + y[k] / m.beta + m.tau0 * y[1]
    }

    fn in_contact(&self, m: &ScaledMedium, y: &[f64; S], k: usize, restitution: bool) -> bool {
        y[0] > self.profile[k] && (!restitution || self.line_load(m, y, k) > 0.0)
    }

    fn rhs(&self, m: &ScaledMedium, y: &[f64; S], restitution: bool) -> [f64; S] {
        let mut out = [0.0; S];
        let mut force = 0.0;
        let free = 1.0 / (m.tau * (1.0 + 1.0 / m.beta));
        for k in 2..S {
            if self.in_contact(m, y, k, restitution) {
                force += self.line_load(m, y, k);
                out[k] = y[1] - y[k] / m.tau;
            } else {
                out[k] = -y[k] * free;
            }
        }
        out[0] = y[1];
        out[1] = -self.weight * force;
        out
    }

    /// max_k min(q_k, x − ξ_k²): positive while any element is in contact.
    fn contact_indicator(&self, m: &ScaledMedium, y: &[f64; S]) -> f64 {
        (2..S)
            .map(|k| self.line_load(m, y, k).min(y[0] - self.profile[k]))
            .fold(f64::NEG_INFINITY, f64::max)
    }
}

/// The discrete MDR with `S − 2` elements on [0, `length`] (which must exceed
/// √x_max), relative tolerance `tolerance`.
pub(crate) fn solve<const S: usize>(
    m: &ScaledMedium,
    length: f64,
    tolerance: f64,
) -> Result<Discrete> {
    let grid = Grid::<S>::new(length);
    let tol = ode_tolerance(tolerance, 0.05)?.with_max_steps(40_000_000);
    let t_max = 1e4 * (1.0 + m.tau + m.tau0);
    let mut y0 = [0.0; S];
    y0[1] = 1.0;
    // Compression: until ẋ = 0.
    let mut f1 = |_t: f64, y: &[f64; S]| grid.rhs(m, y, false);
    let mut stepper = DormandPrince::new(&mut f1, 0.0, y0, t_max, tol)?;
    let turn = drive(
        &mut stepper,
        &mut f1,
        &mut |_t: f64, y: &[f64; S]| y[1],
        EventDirection::Falling,
        t_max,
        &mut |_: &DormandPrince<S>, _: f64| {},
    )?
    .solution;
    if !turn.event_found {
        return Err(Error::Model {
            model: "discrete MDR",
            message: "no turning point".into(),
        });
    }
    let mut evaluations = turn.cost.evaluations;
    // Restitution: until no element is in contact; the observer counts the
    // elements in contact again at a step end after having left.
    let mut f2 = |_t: f64, y: &[f64; S]| grid.rhs(m, y, true);
    let t_end = turn.t + t_max;
    let mut stepper = DormandPrince::new(&mut f2, turn.t, turn.y, t_end, tol)?;
    let mut contact: Vec<bool> = (2..S)
        .map(|k| grid.in_contact(m, &turn.y, k, true))
        .collect();
    let mut left = vec![false; S - 2];
    let mut renewed_contacts = 0;
    let mut watch_contacts = |s: &DormandPrince<S>, _: f64| {
        let y = s.y();
        for (i, k) in (2..S).enumerate() {
            let now = grid.in_contact(m, &y, k, true);
            if contact[i] && !now {
                left[i] = true;
            } else if !contact[i] && now && left[i] {
                renewed_contacts += 1;
            }
            contact[i] = now;
        }
    };
    let end = drive(
        &mut stepper,
        &mut f2,
        &mut |_t: f64, y: &[f64; S]| grid.contact_indicator(m, y),
        EventDirection::Falling,
        t_end,
        &mut watch_contacts,
    )?
    .solution;
    if !end.event_found {
        return Err(Error::Model {
            model: "discrete MDR",
            message: "the contact did not end".into(),
        });
    }
    evaluations += end.cost.evaluations;
    Ok(Discrete {
        restitution: -end.y[1],
        contact_time: end.t,
        max_overlap: turn.y[0],
        evaluations,
        renewed_contacts,
    })
}
