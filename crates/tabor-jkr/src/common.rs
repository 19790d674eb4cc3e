//! Types shared by all contacts, and the two numerical procedures every contact uses
//! (quadrature of the work along the contact relations, and the energy balance).

use serde::Serialize;
use std::cell::RefCell;
use tabor_numerics::quadrature::integrate_smooth;
use tabor_numerics::root_finding::{brent_expanding, BracketExpansion, RootTolerance};
use tabor_numerics::{Cost, QuadTolerance};
use tabor_restitution::{Error, Result};

/// Where an adhesive contact breaks on the way out of an impact.
///
/// Seed 000, eq. (5.36) and footnote to (3.60): an impact is displacement-driven, so
/// the contact breaks where it loses stability under displacement control, `dd/da = 0`
/// (the seed's `d_c^WS`). Some DEM codes break it earlier, at the load-controlled
/// pull-off point `dF/da = 0`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SeparationRule {
    /// Displacement-controlled instability `dd/da = 0` (fixed grip). Sphere: force
    /// −(5/6)πΔγR, `â = (1/3)^(2/3)`, `d̂ = −3^(2/3)`. The seed's choice (5.36).
    #[default]
    FixedGrip,
    /// Load-controlled pull-off point `dF/da = 0`. Sphere: force −(3/2)πΔγR, `â = 1`,
    /// `d̂ = −1`. Gives about half the fixed-grip loss for a sphere.
    LoadControlled,
}

tabor_restitution::menu! {
    SeparationRule, "separation rule";
    FixedGrip => "fixed-grip",
        "displacement-controlled instability dd/da = 0, force -(5/6)πΔγR (5.36): physical for an impact";
    LoadControlled => "load-controlled",
        "load-controlled pull-off dF/da = 0, force -(3/2)πΔγR, as some DEM codes do: about half the loss";
}

/// One equilibrium state of an adhesive contact: contact radius `a`, depth `d`
/// (negative when separated by adhesion) and force `F` (positive in compression).
///
/// In physical units (m, m, N) from the contact types, in their normalized units
/// from [`crate::normalized`]. (The Maugis-Dugdale states of `tabor-maugis`, which
/// also carry the cohesive zone, are `ContactBranchState` and `PathState`.)
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct JkrContactState {
    /// Contact radius a.
    pub contact_radius: f64,
    /// Indentation depth d.
    pub depth: f64,
    /// Normal force F (compression positive).
    pub force: f64,
}

/// The maximum contact radius of an impact, from the energy balance (seed 000,
/// eqs. (5.35), (5.49)).
#[derive(Clone, Copy, Debug, PartialEq, Serialize)]
pub struct MaxContactRadius {
    /// The maximum contact radius `a_max` (m; in [`crate::normalized`]: `â_max`).
    pub contact_radius: f64,
    /// The residual of the energy balance, |work(a_max) − m v0²/2|, relative to
    /// `m v0²/2 + |ΔU_0|` (the terms that must balance, ΔU_0 being the constant term
    /// of (5.35), (5.49); for the power law, which has no closed form, the depth of the
    /// adhesive well between first touch and zero force); below the requested
    /// tolerance. It cannot go below the rounding error of evaluating the work (a few
    /// 1e-15, up to about 3e-14 measured for k → −1 or n → 1/2), so tolerances under
    /// 1e-13 are met only to that level.
    pub energy_residual: f64,
    /// Work spent (root finding and, where the work is a quadrature, integration).
    pub cost: Cost,
}

/// An adhesive energy loss in normalized units (a multiple of the model's energy
/// scale), with its error estimate and cost. The physical shells turn it into a
/// [`tabor_restitution::EnergyLoss`].
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct JkrNormalizedLoss {
    /// |ΔU_kin| in units of the model's energy scale (≥ 0).
    pub value: f64,
    /// Estimated absolute error of `value` (0 for closed forms).
    pub error_estimate: f64,
    /// Which formula produced it.
    pub branch: &'static str,
    /// What the computation spent ([`Cost::ZERO`] for closed forms).
    pub cost: Cost,
}

pub(crate) use tabor_restitution::validate::{finite_output, positive_output};

/// The quadrature tolerance used for a requested relative tolerance: the
/// Clenshaw-Curtis error estimate cannot go below a few ulps.
fn quad_relative(tolerance: f64) -> f64 {
    tolerance.max(4.0 * f64::EPSILON)
}

/// `∫_{x_from}^{x_to} g(x) dx` (0 < x_from, x_to) by adaptive Clenshaw-Curtis in the
/// variable `u = ln x`, in which sums of powers of x are smooth over any number of
/// decades (the energy balance of a power law near n = 1/2 spans ten).
fn integrate_powers<F: Fn(f64) -> f64>(
    integrand: F,
    x_from: f64,
    x_to: f64,
    tol: QuadTolerance,
) -> Result<tabor_numerics::Integral> {
    Ok(integrate_smooth(
        |u| {
            let x = u.exp();
            integrand(x) * x
        },
        x_from.ln(),
        x_to.ln(),
        tol,
    )?)
}

/// The loss `∫_{x_start}^{x_end} F̂ (dd̂/dx̂) dx̂` (first touch to separation) by
/// adaptive Clenshaw-Curtis in `ln x`; `integrand(x) = F̂(x) d̂'(x)` is smooth on the
/// interval (it is bounded away from x = 0).
pub(crate) fn loss_by_quadrature<F: Fn(f64) -> f64>(
    integrand: F,
    x_start: f64,
    x_end: f64,
    tolerance: f64,
    branch: &'static str,
) -> Result<JkrNormalizedLoss> {
    let integral = integrate_powers(
        integrand,
        x_start,
        x_end,
        QuadTolerance::relative(quad_relative(tolerance)),
    )?;
    Ok(JkrNormalizedLoss {
        value: integral.value,
        error_estimate: integral.error_estimate,
        branch,
        cost: integral.cost(),
    })
}

/// The work `∫_{x_start}^{x} F̂ d̂' dx̂` by quadrature in `ln x`, with an absolute floor
/// `scale·tolerance` (the integral crosses zero on its way).
pub(crate) fn work_by_quadrature<F: Fn(f64) -> f64>(
    integrand: F,
    x_start: f64,
    x: f64,
    scale: f64,
    tolerance: f64,
) -> Result<(f64, Cost)> {
    let t = quad_relative(tolerance);
    let integral = integrate_powers(
        integrand,
        x_start,
        x,
        QuadTolerance {
            absolute: t * scale,
            relative: t,
        },
    )?;
    Ok((integral.value, integral.cost()))
}

/// Everything the energy balance needs to know about a contact, in its normalized
/// units.
pub(crate) struct Balance<W, S> {
    /// Work done on the body between first touch and contact radius x, i.e. the
    /// kinetic energy it takes to reach x (seed (5.35), (5.49)), with its cost.
    pub work: W,
    /// d(work)/dx = F̂(x) d̂'(x).
    pub slope: S,
    /// The contact radius of zero force: beyond it the work grows monotonically, and
    /// the work there is below the work at first touch.
    pub zero_force_radius: f64,
    /// A first guess for the upper end of the bracket.
    pub upper_guess: f64,
    /// |constant term| of the balance (the work from the force-free state to first
    /// touch, ΔU_0), the scale the residual is measured against.
    pub offset: f64,
}

/// Solves `work(x) = kinetic` for the maximum contact radius so that the residual is
/// below `tolerance · (kinetic + offset)`.
///
/// Two Brent passes: a relative 1e-9 on x, then, in a bracket around that root, the
/// absolute width on x that the slope of the work translates into the requested
/// energy tolerance.
pub(crate) fn solve_energy_balance<W, S>(
    balance: Balance<W, S>,
    kinetic: f64,
    tolerance: f64,
) -> Result<MaxContactRadius>
where
    W: Fn(f64) -> Result<(f64, Cost)>,
    S: Fn(f64) -> f64,
{
    let failure: RefCell<Option<Error>> = RefCell::new(None);
    let quad_cost = RefCell::new(Cost::ZERO);
    let g = |x: f64| match (balance.work)(x) {
        Ok((w, c)) => {
            *quad_cost.borrow_mut() += c;
            w - kinetic
        }
        Err(e) => {
            failure.borrow_mut().get_or_insert(e);
            f64::NAN
        }
    };
    let take_failure = |e: tabor_numerics::NumericsError| -> Error {
        failure.borrow_mut().take().unwrap_or(Error::Numerics(e))
    };
    let lower = balance.zero_force_radius;
    let upper = balance.upper_guess.max(2.0 * lower);
    let expansion = BracketExpansion::Linear {
        factor: 1.0,
        min: lower,
        max: f64::MAX,
        max_steps: 400,
    };
    let first = brent_expanding(g, lower, upper, expansion, RootTolerance::relative(1e-9))
        .map_err(take_failure)?;
    let mut cost = first.cost();
    let mut x = first.value;
    let target = tolerance * (kinetic + balance.offset);
    let slope = (balance.slope)(x);
    let needed = if slope > 0.0 && slope.is_finite() {
        0.25 * target / slope
    } else {
        0.0
    };
    if needed < 4e-9 * x {
        let width = 4e-9 * x;
        let second = brent_expanding(
            g,
            (x - width).max(lower),
            x + width,
            expansion,
            RootTolerance {
                absolute: needed,
                relative: 0.0,
                max_iterations: 200,
            },
        )
        .map_err(take_failure)?;
        cost += second.cost();
        x = second.value;
    }
    let (w, c) = (balance.work)(x)?;
    cost += c;
    cost += *quad_cost.borrow();
    let scale = kinetic + balance.offset;
    Ok(MaxContactRadius {
        contact_radius: x,
        energy_residual: if scale > 0.0 {
            (w - kinetic).abs() / scale
        } else {
            0.0
        },
        cost,
    })
}

impl JkrNormalizedLoss {
    /// The loss in joules for the energy scale `energy` (`F_n d_n` or the contact's
    /// own scale), with its error estimate, branch and cost; non-finite products are
    /// errors naming `model`.
    pub(crate) fn in_joules(
        self,
        model: &'static str,
        energy: f64,
    ) -> Result<tabor_restitution::EnergyLoss> {
        Ok(tabor_restitution::EnergyLoss {
            joules: finite_output(model, "energy loss", self.value * energy)?,
            error_estimate: finite_output(model, "error estimate", self.error_estimate * energy)?,
            branch: self.branch.into(),
            cost: self.cost,
        })
    }
}
