//! The verification of an export: tabor against the calibrated LAMMPS law on a
//! grid of speeds inside small strain, the onsets of the effects the LAMMPS model
//! leaves out, and the claim drawn from both (which speeds, which error).

use crate::calibrate::Setup;
use crate::impact::LammpsImpact;
use crate::law::GranularModel;
use crate::report::{
    model_err, time_step_error, Claim, ExportError, Limit, RangeEnd, Scope, SpeedComparison,
    CALIBRATED_RELATIVE_ERROR, REPRODUCES, TIME_STEP_ERROR,
};
use tabor_numerics::search::geometric_edge;
use tabor_scene::EffectKind;

/// Grid points per decade of speed.
const PER_DECADE: i32 = 8;
/// Decades of speed on each side of the reference.
const DECADES: i32 = 2;
/// The relative resolution of a claimed range's edges (bisection in log speed).
const EDGE_RESOLUTION: f64 = 1e-3;

/// tabor and the LAMMPS law at one speed, and the claim's test there.
struct Probe<'a> {
    s: &'a Setup<'a>,
    lammps: LammpsImpact,
    scope: Scope,
}

impl Probe<'_> {
    fn compare(&self, v: f64) -> Result<SpeedComparison, ExportError> {
        let (tabor, _) = self.s.scene.restitution_with_error(v).map_err(model_err)?;
        let lammps = self.lammps.restitution(v).map_err(model_err)?;
        let both_stick = lammps == 0.0 && tabor == 0.0;
        Ok(SpeedComparison {
            speed: v,
            tabor,
            lammps,
            difference: lammps - tabor,
            tolerance: (lammps - tabor).abs()
                + if both_stick {
                    0.0
                } else {
                    time_step_error(lammps.max(tabor), self.s.adhesive)
                },
            claimed: false,
        })
    }

    /// Whether the difference at `c` is within the claim's bound.
    fn within(&self, c: &SpeedComparison) -> bool {
        if c.tabor == 0.0 && c.lammps == 0.0 {
            return true;
        }
        match self.scope {
            Scope::SpeedIndependent => c.difference.abs() <= REPRODUCES,
            Scope::CalibrationSpeed => {
                c.difference.abs() <= CALIBRATED_RELATIVE_ERROR * c.tabor.max(1e-300)
            }
        }
    }
}

/// The comparison speeds: v_ref 10^(k/8) for k = −16 … 16 below the small-strain
/// speed, and that speed itself when the grid reaches it. Returns the grid and the
/// index of v_ref.
fn grid(v_ref: f64, v_max: f64) -> (Vec<f64>, usize) {
    let top = v_max * (1.0 - 1e-9);
    let mut speeds: Vec<f64> = (-DECADES * PER_DECADE..=DECADES * PER_DECADE)
        .map(|k| v_ref * 10f64.powf(f64::from(k) / f64::from(PER_DECADE)))
        .filter(|&v| v < top)
        .collect();
    if v_ref * 10f64.powi(DECADES) >= top {
        speeds.push(top);
    }
    let mid = (DECADES * PER_DECADE) as usize;
    let last = speeds.len() - 1;
    (speeds, mid.min(last))
}

/// The lowest speed in (`from`, `to`] at which the scene uses `effect`, when it
/// does at `to` and not at `from` (bisection in log speed to 1e-3).
fn onset(s: &Setup, effect: EffectKind, from: f64, to: f64) -> Result<Option<f64>, ExportError> {
    let uses = |v: f64| -> Result<bool, ExportError> {
        Ok(s.scene
            .combination_at(v)
            .map_err(model_err)?
            .effects
            .contains(&effect))
    };
    if uses(from)? || !uses(to)? {
        return Ok(None);
    }
    let edge = geometric_edge(|v| uses(v).map(|u| !u), from, to, EDGE_RESOLUTION)?;
    Ok(Some(edge.outside))
}

/// The verification's result.
pub(crate) struct Verification {
    pub comparison: Vec<SpeedComparison>,
    pub claim: Claim,
    pub limits: Vec<Limit>,
}

/// The relative difference of tabor's and the LAMMPS model's sticking velocities
/// up to which a claim may span them: LAMMPS resolves a sticking velocity to about
/// its time-step error.
const STICKING_AGREEMENT: f64 = 1e-3;

/// Compares tabor with `model` around `v_ref`, finds the onsets of the effects the
/// model leaves out, and draws the claim. `(sticking_velocity, lammps_sticking)`
/// are tabor's and the model's sticking velocities: where they differ (or tabor's
/// is unknown) the claim starts above both, since between them one model sticks
/// and the other rebounds.
pub(crate) fn verify(
    s: &Setup,
    model: &GranularModel,
    scope: Scope,
    v_ref: f64,
    (sticking_velocity, lammps_sticking): (Option<f64>, Option<f64>),
) -> Result<Verification, ExportError> {
    let probe = Probe {
        s,
        lammps: LammpsImpact::new(*model, s.r, s.m).map_err(model_err)?,
        scope,
    };
    let (mut speeds, mid) = grid(v_ref, s.v_small_strain);
    // the grid stops, on each side, before the first speed where tabor's scene
    // has no answer (named in the limits); at the reference speed it must answer
    let mut answers: Vec<Result<SpeedComparison, ExportError>> =
        speeds.iter().map(|&v| probe.compare(v)).collect();
    if let Err(e) = &answers[mid] {
        return Err(e.clone());
    }
    let first = answers[..mid]
        .iter()
        .rposition(|a| a.is_err())
        .map_or(0, |i| i + 1);
    let last = answers[mid..]
        .iter()
        .position(|a| a.is_err())
        .map_or(speeds.len(), |i| mid + i);
    let mut no_answer = Vec::new();
    for (i, side) in [(first.checked_sub(1), "below"), (Some(last), "above")] {
        if let Some(Err(e)) = i.and_then(|i| answers.get(i)) {
            no_answer.push((side, speeds[i.unwrap_or(0)], e.to_string()));
        }
    }
    let cut = [first > 0, last < speeds.len()];
    answers.truncate(last);
    let mut comparison = answers.drain(first..).collect::<Result<Vec<_>, _>>()?;
    speeds = speeds[first..last].to_vec();
    let mid = mid - first;
    let (mut limits, cap) = effect_limits(s, v_ref, speeds[speeds.len() - 1])?;
    for (side, v, e) in &no_answer {
        limits.push(Limit {
            effect: "no tabor answer".into(),
            from_speed: (*side == "above").then_some(*v),
            note: format!(
                "the comparison stops {side} {v:.4e} m/s, where tabor's scene gives no outcome ({e})"
            ),
        });
    }
    let ok: Vec<bool> = comparison.iter().map(|c| probe.within(c)).collect();
    let mut extra_error: f64 = 0.0;
    let mut range = [v_ref, v_ref];
    let mut ends = [RangeEnd::ErrorBound, RangeEnd::ErrorBound];
    if ok[mid] {
        // downwards
        let mut lo = mid;
        while lo > 0 && ok[lo - 1] {
            lo -= 1;
        }
        range[0] = speeds[lo];
        if lo == 0 {
            ends[0] = if cut[0] {
                RangeEnd::NoAnswer
            } else {
                RangeEnd::Grid
            };
        } else {
            let (edge, err) = refine(&probe, speeds[lo], speeds[lo - 1])?;
            range[0] = edge;
            extra_error = extra_error.max(err);
        }
        // upwards, at most to the onset of an effect left out
        let mut hi = mid;
        while hi + 1 < speeds.len() && ok[hi + 1] && speeds[hi + 1] <= cap {
            hi += 1;
        }
        range[1] = speeds[hi];
        if hi + 1 == speeds.len() {
            ends[1] = if cut[1] {
                RangeEnd::NoAnswer
            } else if speeds[hi] < v_ref * 10f64.powi(DECADES) * (1.0 - 1e-12) {
                RangeEnd::SmallStrain
            } else {
                RangeEnd::Grid
            };
        } else if speeds[hi + 1] > cap {
            let at_cap = probe.compare(cap).ok().filter(|c| probe.within(c));
            if let Some(at_cap) = at_cap {
                range[1] = cap;
                ends[1] = RangeEnd::EffectOnset;
                extra_error = extra_error.max(at_cap.difference.abs());
            } else {
                let (edge, err) = refine(&probe, speeds[hi], cap)?;
                range[1] = edge;
                extra_error = extra_error.max(err);
            }
        } else {
            let (edge, err) = refine(&probe, speeds[hi], speeds[hi + 1])?;
            range[1] = edge;
            extra_error = extra_error.max(err);
        }
    }
    if let Some(v_l) = lammps_sticking {
        let agree =
            sticking_velocity.is_some_and(|v_t| (v_l / v_t - 1.0).abs() <= STICKING_AGREEMENT);
        let above = v_l.max(sticking_velocity.unwrap_or(0.0));
        if ok[mid] && !agree && range[0] <= above && above < v_ref {
            let (edge, err) = refine(&probe, v_ref, above)?;
            range[0] = edge;
            ends[0] = RangeEnd::ErrorBound;
            extra_error = extra_error.max(err);
        }
    }
    let in_range = |v: f64| v >= range[0] * (1.0 - 1e-12) && v <= range[1] * (1.0 + 1e-12);
    for c in comparison.iter_mut() {
        c.claimed = in_range(c.speed);
    }
    let error = comparison
        .iter()
        .filter(|c| c.claimed)
        .map(|c| c.difference.abs())
        .fold(extra_error, f64::max);
    let decade = [v_ref / 10f64.sqrt(), v_ref * 10f64.sqrt()];
    let decade_error = comparison
        .iter()
        .filter(|c| c.speed >= decade[0] * (1.0 - 1e-12) && c.speed <= decade[1] * (1.0 + 1e-12))
        .map(|c| c.difference.abs())
        .fold(0.0, f64::max);
    let at_ref = comparison[mid];
    let statement = statement(
        scope,
        (v_ref, at_ref),
        (range, ends, error),
        (decade, decade_error),
        s.adhesive,
        sticking_velocity.filter(|&vc| in_range(vc)),
    );
    Ok(Verification {
        comparison,
        claim: Claim {
            scope,
            speed: v_ref,
            range,
            range_ends: ends,
            bound: match scope {
                Scope::SpeedIndependent => REPRODUCES,
                Scope::CalibrationSpeed => CALIBRATED_RELATIVE_ERROR,
            },
            error,
            decade_error,
            statement,
        },
        limits,
    })
}

/// The edge of the claim between `good` (within the bound) and `bad` (not), to
/// [`EDGE_RESOLUTION`]; returns it with the largest difference met inside.
fn refine(probe: &Probe, good: f64, bad: f64) -> Result<(f64, f64), ExportError> {
    let mut worst: f64 = 0.0;
    // a speed without an answer is outside the claim
    let edge = geometric_edge(
        |v| {
            let Ok(c) = probe.compare(v) else {
                return Ok::<bool, ExportError>(false);
            };
            let ok = probe.within(&c);
            if ok {
                worst = worst.max(c.difference.abs());
            }
            Ok(ok)
        },
        good,
        bad,
        EDGE_RESOLUTION,
    )?;
    Ok((edge.inside, worst))
}

/// The effects of the scene the LAMMPS model carries only at the calibration speed
/// or not at all, with their onset speeds inside small strain; and the speed above
/// which the claim may not reach (the onset of plasticity the model leaves out).
fn effect_limits(s: &Setup, v_ref: f64, v_top: f64) -> Result<(Vec<Limit>, f64), ExportError> {
    let mut limits = Vec::new();
    let mut cap = f64::INFINITY;
    let calibrated = |e: &str| s.lossy.contains(&e);
    if let Some(sy) = s.scene.yield_stress() {
        let field = s.scene.yield_stress_field();
        if calibrated("plasticity") {
            let below = onset(
                s,
                EffectKind::Plasticity,
                v_ref / 10f64.powi(DECADES),
                v_ref,
            )?;
            limits.push(Limit {
                effect: "plasticity".into(),
                from_speed: below,
                note: format!(
                    "the speed dependence of the plastic loss (restitution ~ v^(-1/4) above the yield onset; the damping is calibrated at {v_ref:.4e} m/s), the residual indentation and the plastic force history{}",
                    below.map_or(String::new(), |v| format!("; tabor's scene yields from {v:.4e} m/s on ({field} = {sy:e} Pa), below it the damping still acts"))
                ),
            });
        } else {
            match onset(s, EffectKind::Plasticity, v_ref, v_top)? {
                Some(v) => {
                    cap = v;
                    limits.push(Limit {
                        effect: "plasticity".into(),
                        from_speed: Some(v),
                        note: format!(
                            "plastic deformation and its loss above the yield onset {v:.4e} m/s ({field} = {sy:e} Pa): tabor's scene yields there, this LAMMPS model stays elastic, so the claim ends at the onset"
                        ),
                    });
                }
                None => limits.push(Limit {
                    effect: "plasticity".into(),
                    from_speed: None,
                    note: format!(
                        "plasticity ({field} = {sy:e} Pa): tabor's scene does not yield between {v_ref:.4e} and {v_top:.4e} m/s (the small-strain or grid end); this LAMMPS model never does"
                    ),
                }),
            }
        }
    }
    if calibrated("viscoelasticity") {
        limits.push(Limit {
            effect: "viscoelasticity".into(),
            from_speed: None,
            note: format!(
                "the speed dependence of the viscous loss away from {v_ref:.4e} m/s: LAMMPS's damping viscoelastic is the Kuwabara-Kono force, calibrated there (see the claimed range and the comparison)"
            ),
        });
    }
    if s.geometry == crate::report::Geometry::Pair
        && s.scene.sphere.material != s.scene.target.material
    {
        limits.push(Limit {
            effect: "materials".into(),
            from_speed: None,
            note: "the individual moduli of two different materials: one pair_coeff * * carries the equivalent modulus E = 2 E* (1 - nu^2)".into(),
        });
    }
    Ok((limits, cap))
}

fn end_phrase(end: RangeEnd) -> &'static str {
    match end {
        RangeEnd::Grid => "the comparison grid ends (two decades from the reference)",
        RangeEnd::SmallStrain => "small strain ends (Hertz d_max = R*)",
        RangeEnd::EffectOnset => "an effect this model leaves out sets in (see DOES NOT REPRODUCE)",
        RangeEnd::ErrorBound => "the difference leaves the bound",
        RangeEnd::NoAnswer => "tabor's scene gives no outcome (see DOES NOT REPRODUCE)",
    }
}

fn statement(
    scope: Scope,
    (v_ref, at_ref): (f64, SpeedComparison),
    (range, ends, error): ([f64; 2], [RangeEnd; 2], f64),
    (decade, decade_error): ([f64; 2], f64),
    adhesive: bool,
    sticking_velocity: Option<f64>,
) -> String {
    let step = format!(
        "plus LAMMPS's time-step error (<= {TIME_STEP_ERROR:.0e} at timestep <= contact time/5000{})",
        if adhesive {
            "; near the sticking velocity 2e-3 (1 - e^2)/(2e)"
        } else {
            ""
        }
    );
    let ends = format!(
        "the range ends below where {} and above where {}",
        end_phrase(ends[0]),
        end_phrase(ends[1])
    );
    match scope {
        Scope::SpeedIndependent => format!(
            "tabor's restitution e(v){} for {:.4e} ... {:.4e} m/s: |e_LAMMPS - e_tabor| <= {error:.1e} there (claim bound {REPRODUCES:.0e}), {step}; {ends}",
            if sticking_velocity.is_some() { " and the sticking velocity" } else { "" },
            range[0],
            range[1],
        ),
        Scope::CalibrationSpeed => format!(
            "tabor's restitution {:.6} at {v_ref:.4e} m/s (calibration error {:.1e}) and within 1 % of tabor for {:.4e} ... {:.4e} m/s: |e_LAMMPS - e_tabor| <= {error:.2e} there, {step}; {ends}; over a decade ({:.4e} ... {:.4e} m/s) the difference reaches {decade_error:.2e}",
            at_ref.tabor,
            at_ref.difference.abs(),
            range[0],
            range[1],
            decade[0],
            decade[1],
        ),
    }
}
