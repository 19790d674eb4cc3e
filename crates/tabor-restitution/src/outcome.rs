use crate::checks::Warning;
use crate::model::ImpactModel;
use crate::{validate, Error, Result};
use serde::Serialize;
use tabor_numerics::root_finding::{brent, RootTolerance};
use tabor_numerics::Cost;

/// The coefficient of restitution from an energy loss, seed 000 eq. (5.37):
/// `ε = √(1 − 2|ΔU|/(m v0²))` when `|ΔU| ≤ m v0²/2`, else 0 (the bodies stick).
///
/// `energy_loss` is the magnitude |ΔU_kin| (J, ≥ 0), `mass` the effective mass (kg),
/// `impact_speed` v0 > 0 (m/s).
pub fn restitution_from_loss(energy_loss: f64, mass: f64, impact_speed: f64) -> Result<f64> {
    let loss = validate::non_negative("energy_loss", energy_loss)?;
    let m = validate::positive("mass", mass)?;
    let v = validate::positive("impact_speed", impact_speed)?;
    let kinetic = 0.5 * m * v * v;
    if !kinetic.is_finite() || kinetic == 0.0 {
        return Err(Error::invalid(
            "impact_speed",
            v,
            "gives a kinetic energy m v0^2/2 that is zero or overflows",
        ));
    }
    let ratio = loss / kinetic;
    Ok(if ratio >= 1.0 {
        0.0
    } else {
        (1.0 - ratio).sqrt()
    })
}

/// What happened in one impact, as a model computed it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct ImpactOutcome {
    /// The model's name.
    pub model: String,
    /// The formula or branch that produced the loss.
    pub branch: String,
    /// Impact speed v0 (m/s).
    pub impact_speed: f64,
    /// Kinetic energy before impact, m v0²/2 (J).
    pub kinetic_energy: f64,
    /// Kinetic energy lost, |ΔU_kin| (J); capped at the kinetic energy when the
    /// bodies stick.
    pub energy_loss: f64,
    /// Estimated absolute error of the energy loss (J).
    pub energy_loss_error: f64,
    /// Coefficient of restitution ε (5.37), in [0, 1].
    pub restitution: f64,
    /// Rebound speed ε v0 (m/s).
    pub rebound_speed: f64,
    /// True when the loss reaches the kinetic energy: the bodies stay together.
    pub sticks: bool,
    /// Work spent computing the loss.
    pub cost: Cost,
    /// Validity warnings (quasi-static, elastic limit, ...), added by callers.
    pub warnings: Vec<Warning>,
}

/// Runs a model at one impact speed and derives the restitution from its loss
/// (seed 000 eq. (5.37)).
pub fn impact<M: ImpactModel + ?Sized>(model: &M, impact_speed: f64) -> Result<ImpactOutcome> {
    let v = validate::positive("impact_speed", impact_speed)?;
    let m = validate::positive("mass", model.effective_mass())?;
    let loss = model.energy_loss(v)?;
    let joules = validate::non_negative("energy_loss", loss.joules)?;
    let restitution = restitution_from_loss(joules, m, v)?;
    let kinetic = 0.5 * m * v * v;
    let sticks = joules >= kinetic;
    Ok(ImpactOutcome {
        model: model.name(),
        branch: loss.branch,
        impact_speed: v,
        kinetic_energy: kinetic,
        energy_loss: joules.min(kinetic),
        energy_loss_error: loss.error_estimate,
        restitution,
        rebound_speed: restitution * v,
        sticks,
        cost: loss.cost,
        warnings: Vec::new(),
    })
}

/// How a sticking velocity was obtained.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum StickingMethod {
    /// Closed form (5.38): the loss does not depend on the speed.
    ClosedForm,
    /// Root of ε(v) = 0 found numerically.
    Root,
    /// The model never sticks at any speed down to 1e-12 of its speed scale; the
    /// reported speed is 0.
    NeverSticks,
    /// The model sticks at every speed up to its validity limit
    /// ([`ImpactModel::speed_limit`]); the reported speed is that limit, and no
    /// sticking velocity exists within the model's validity.
    SticksUpToLimit,
}

/// The speed below which the bodies stick (ε = 0).
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct StickingVelocity {
    /// The sticking velocity v_c (m/s).
    pub speed: f64,
    /// How it was found.
    pub method: StickingMethod,
    /// Work spent (loss evaluations are counted as evaluations).
    pub cost: Cost,
}

/// The sticking velocity of a model: below it the bodies stick (ε = 0).
///
/// When the loss does not depend on the speed it is the closed form
/// `v_c = √(2|ΔU|/m)` of seed 000 eq. (5.38); otherwise the root of
/// `g(v) = 1 − 2|ΔU(v)|/(m v²)` (which is ε² where the bodies separate), searched
/// geometrically from [`ImpactModel::speed_scale`] and refined with Brent's method
/// to the relative tolerance `tolerance`. If several bands of sticking exist, the
/// crossing nearest the speed scale is returned. The search stays at or below the
/// model's [`ImpactModel::speed_limit`]: when the model sticks there too, the
/// result is [`StickingMethod::SticksUpToLimit`] at the limit.
pub fn sticking_velocity<M: ImpactModel + ?Sized>(
    model: &M,
    tolerance: f64,
) -> Result<StickingVelocity> {
    let tol = validate::tolerance("tolerance", tolerance)?;
    let m = validate::positive("mass", model.effective_mass())?;
    let scale = validate::positive("speed_scale", model.speed_scale())?;
    let mut cost = Cost::ZERO;
    if model.loss_is_speed_independent() {
        let loss = model.energy_loss(scale)?;
        let joules = validate::non_negative("energy_loss", loss.joules)?;
        cost += loss.cost;
        if joules == 0.0 {
            // no loss at any speed: the bodies never stick (not "stick below 0 m/s")
            return Ok(StickingVelocity {
                speed: 0.0,
                method: StickingMethod::NeverSticks,
                cost,
            });
        }
        let speed = (2.0 * joules / m).sqrt();
        if !speed.is_finite() {
            return Err(Error::invalid(
                "mass",
                m,
                "gives a sticking velocity sqrt(2|dU|/m) that overflows",
            ));
        }
        return Ok(StickingVelocity {
            speed,
            method: StickingMethod::ClosedForm,
            cost,
        });
    }
    let mut probe = Probe {
        model,
        mass: m,
        cost,
        evaluations: 0,
        failure: None,
    };
    // Geometric search for a sign change around the speed scale, at or below the
    // model's validity limit.
    const FACTOR: f64 = 2.0;
    const MAX_STEPS: u32 = 90; // 2^90 ≈ 1e27 either way
    let limit = model
        .speed_limit()
        .map(|l| validate::positive("speed_limit", l.speed))
        .transpose()?;
    let start = limit.map_or(scale, |l| scale.min(l));
    let g0 = probe.g(start)?;
    let (lo, hi) = if g0 > 0.0 {
        // separates at the start: go down until it sticks
        let mut hi = start;
        let mut bracket = None;
        for _ in 0..MAX_STEPS {
            let lo = hi / FACTOR;
            if probe.g(lo)? <= 0.0 {
                bracket = Some((lo, hi));
                break;
            }
            hi = lo;
            if lo < 1e-12 * scale {
                break;
            }
        }
        match bracket {
            Some(b) => b,
            None => {
                return Ok(StickingVelocity {
                    speed: 0.0,
                    method: StickingMethod::NeverSticks,
                    cost: probe.cost + Cost::new(probe.evaluations, 0),
                })
            }
        }
    } else {
        let mut lo = start;
        let mut bracket = None;
        for _ in 0..MAX_STEPS {
            if limit == Some(lo) {
                // sticks at the validity limit: no root within it
                return Ok(StickingVelocity {
                    speed: lo,
                    method: StickingMethod::SticksUpToLimit,
                    cost: probe.cost + Cost::new(probe.evaluations, 0),
                });
            }
            let hi = limit.map_or(lo * FACTOR, |l| (lo * FACTOR).min(l));
            if probe.g(hi)? > 0.0 {
                bracket = Some((lo, hi));
                break;
            }
            lo = hi;
        }
        match bracket {
            Some(b) => b,
            None => {
                return Err(Error::Model {
                    model: "sticking velocity",
                    message: format!(
                        "{} sticks at every speed up to {lo:e} m/s; no sticking velocity found",
                        model.name()
                    ),
                })
            }
        }
    };
    let root = brent(
        |v| probe.g(v).unwrap_or(f64::NAN),
        lo,
        hi,
        RootTolerance {
            absolute: 0.0,
            relative: tol,
            max_iterations: 200,
        },
    );
    if let Some(e) = probe.failure.take() {
        return Err(e);
    }
    let root = root?;
    Ok(StickingVelocity {
        speed: root.value,
        method: StickingMethod::Root,
        cost: probe.cost + Cost::new(probe.evaluations, root.iterations),
    })
}

/// `g(v) = 1 − 2|ΔU(v)|/(m v²)` with bookkeeping of cost and the first failure.
struct Probe<'a, M: ?Sized> {
    model: &'a M,
    mass: f64,
    cost: Cost,
    evaluations: u64,
    failure: Option<Error>,
}

impl<M: ImpactModel + ?Sized> Probe<'_, M> {
    fn g(&mut self, v: f64) -> Result<f64> {
        self.evaluations += 1;
        let outcome = self.model.energy_loss(v).and_then(|loss| {
            self.cost += loss.cost;
            validate::non_negative("energy_loss", loss.joules)
        });
        match outcome {
            Ok(joules) => Ok(1.0 - 2.0 * joules / (self.mass * v * v)),
            Err(e) => {
                self.failure.get_or_insert(e.clone());
                Err(e)
            }
        }
    }
}
