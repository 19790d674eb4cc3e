//! Selecting, at one impact speed, the effects that matter, and the scene's model
//! as a whole (the model that answers at every speed, whose root of ε(v) = 0 is the
//! sticking velocity).

use crate::combination::{Combination, EffectKind, EffectSet, Rule};
use crate::error::{located, SceneError, Source};
use crate::inputs::Inputs;
use crate::models::{Evaluation, Models};
use serde::Serialize;
use std::fmt;
use std::sync::{Arc, OnceLock};
use tabor_numerics::tolerance::STICKING_ACCURACY_FLOOR;
use tabor_numerics::Cost;
use tabor_restitution::{sticking_velocity, EnergyLoss, ImpactModel, SpeedLimit, StickingMethod};

/// Why an effect given by the scene does not enter the result at one speed.
pub(crate) struct Dropped {
    pub effect: EffectKind,
    pub reason: String,
}

/// The effects used at one speed and their combined loss.
pub(crate) struct Selection {
    pub used: EffectSet,
    pub evaluation: Evaluation,
    pub dropped: Vec<Dropped>,
}

impl Selection {
    pub(crate) fn combination(&self) -> Combination {
        Combination::of(self.evaluation.rule, &self.used)
    }
}

/// Sweeps shorter than this simulate every point (a speed table costs about 150
/// simulations).
pub(crate) const SPEED_TABLE_MIN_POINTS: usize = 500;

/// A scene's models, built once from its inputs, and its sticking velocity,
/// computed on first use and kept.
pub(crate) struct Built {
    inputs: Inputs,
    models: Models,
    sticking: OnceLock<Result<(Sticking, Cost), SceneError>>,
}

impl Built {
    fn new(inputs: Inputs) -> Result<Arc<Built>, SceneError> {
        Ok(Arc::new(Built {
            models: Models::build(&inputs)?,
            inputs,
            sticking: OnceLock::new(),
        }))
    }
}

/// The models of a scene, built on first use and shared by every call on the scene
/// and its copies at other speeds (the models do not depend on the speed). Keyed by
/// the inputs they were built from: a scene whose inputs differ builds its own.
#[derive(Clone, Default)]
pub(crate) struct Cache(Arc<OnceLock<Entry>>);

/// The inputs a cache entry was built from, and what was built.
type Entry = (Inputs, Result<Arc<Built>, SceneError>);

impl Cache {
    /// The models of `inputs` (the cached ones when they were built from equal
    /// inputs); errors not yet located.
    pub(crate) fn get(&self, inputs: Inputs) -> Result<Arc<Built>, SceneError> {
        let (key, built) = self
            .0
            .get_or_init(|| (inputs.clone(), Built::new(inputs.clone())));
        if *key == inputs {
            built.clone()
        } else {
            Built::new(inputs)
        }
    }
}

impl fmt::Debug for Cache {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let state = if self.0.get().is_some() {
            "built"
        } else {
            "empty"
        };
        write!(f, "Cache({state})")
    }
}

impl PartialEq for Cache {
    /// A cache is derived data: it never makes two scenes differ.
    fn eq(&self, _: &Self) -> bool {
        true
    }
}

/// A scene ready to answer: its name, where its text came from (to locate errors)
/// and its models.
pub(crate) struct Prepared<'a> {
    pub name: &'a str,
    source: Option<&'a Source>,
    built: Arc<Built>,
}

impl<'a> Prepared<'a> {
    /// The scene named `name` read from `source`, with the models of `inputs`
    /// (from `cache`).
    pub(crate) fn new(
        name: &'a str,
        source: Option<&'a Source>,
        cache: &Cache,
        inputs: Inputs,
    ) -> Result<Self, SceneError> {
        Ok(Prepared {
            name,
            source,
            built: cache.get(inputs).map_err(|e| located(source, e))?,
        })
    }

    /// For a sweep over `count` speeds from `lower` to `upper` (m/s; the finite,
    /// positive ones): this scene with its coupled viscous-adhesive
    /// model answering from a speed table certified against its simulation
    /// (`tabor_viscoadhesive::table`) over the sweep's range (sticking below the
    /// sticking velocity, the tabulated loss above), and its sticking velocity
    /// the one found without the table. Unchanged
    /// when the scene has no such model, the sweep is too short for a table to pay
    /// ([`SPEED_TABLE_MIN_POINTS`]) or the table cannot be built or certified.
    pub(crate) fn with_speed_table(self, lower: f64, upper: f64, count: usize) -> Self {
        let Some(model) = self.models().viscous_adhesive.as_ref() else {
            return self;
        };
        let sticking = match self.sticking() {
            Ok(s) if count >= SPEED_TABLE_MIN_POINTS && upper > lower => s,
            _ => return self,
        };
        let velocity = match sticking.0 {
            Sticking::Below { velocity, .. } => Some(velocity),
            Sticking::Never => None,
            Sticking::UpToLimit { .. } => return self,
        };
        let upper = upper.min(model.small_strain_limit());
        let (Ok(tabled), Ok(mut models)) = (
            model.clone().with_speed_table(lower, upper, velocity),
            Models::build(self.inputs()),
        ) else {
            return self;
        };
        models.viscous_adhesive = Some(tabled);
        let built = Built {
            inputs: self.inputs().clone(),
            models,
            sticking: OnceLock::from(Ok(sticking)),
        };
        Prepared {
            built: Arc::new(built),
            ..self
        }
    }

    /// The validated inputs the models were built from.
    pub(crate) fn inputs(&self) -> &Inputs {
        &self.built.inputs
    }

    /// The scene's models.
    pub(crate) fn models(&self) -> &Models {
        &self.built.models
    }

    /// `e` with the line of its field in the scene text, when known.
    pub(crate) fn locate(&self, e: SceneError) -> SceneError {
        located(self.source, e)
    }

    /// The effects that enter the result at `speed`, by these rules in this order:
    /// plasticity only above its yield onset (below it the elastic model of the
    /// other effects is exact); then viscoelasticity and adhesion are dropped when
    /// leaving them out changes the combined loss by less than the requested
    /// accuracy times the kinetic energy (so a drop changes ε by at most about the
    /// accuracy).
    pub(crate) fn select(&self, speed: f64) -> Result<Selection, SceneError> {
        let models = self.models();
        let kinetic = 0.5 * models.mass * speed * speed;
        let threshold = models.accuracy * kinetic;
        let mut used = models.candidates;
        let mut dropped = Vec::new();
        if let Some((onset, name)) = models.yield_onset(&used) {
            if speed <= onset {
                used = used.without(EffectKind::Plasticity);
                dropped.push(Dropped {
                    effect: EffectKind::Plasticity,
                    reason: format!(
                        "impact speed {speed:e} m/s does not exceed the {name} {onset:e} m/s: below it the contact stays elastic"
                    ),
                });
            }
        }
        let locate = |e| self.locate(e);
        let mut evaluation = models.evaluate(&used, speed).map_err(locate)?;
        for effect in [EffectKind::Viscoelasticity, EffectKind::Adhesion] {
            if !used.contains(effect) {
                continue;
            }
            let without = used.without(effect);
            // a reduced set its models cannot answer (the Kelvin-Voigt sphere of a
            // coupled viscous-adhesive scene beyond its range) does not show the
            // effect negligible: the effect stays
            let Ok(reduced) = models.evaluate(&without, speed) else {
                continue;
            };
            let marginal = evaluation.loss.joules - reduced.loss.joules;
            if marginal.abs() < threshold {
                dropped.push(Dropped {
                    effect,
                    reason: format!(
                        "leaving it out changes the loss by {marginal:e} J, {:e} of the kinetic energy, below the requested accuracy {:e}",
                        marginal.abs() / kinetic,
                        models.accuracy
                    ),
                });
                used = without;
                evaluation = reduced;
            }
        }
        Ok(Selection {
            used,
            evaluation,
            dropped,
        })
    }

    /// The combination an oblique impact at normal speed `speed` simulates: the
    /// central one there (`central`, [`Prepared::select`]'s), but with the
    /// scene's adhesion where that dropped it as negligible. The drop is judged on
    /// the central loss; adhesion also sets the friction limits (the pull-off
    /// force in `F_n + 2 F_pull-off`) and the contact at first touch (a finite
    /// radius, the tangential spring sticking from the start, where a law
    /// without adhesion runs a friction-free warm-up), which the central loss
    /// does not measure: two stiff 9 mm spheres with w = 2.8e-3 J/m² at 0.032 m/s
    /// and 42.6°, e_t 0.4028 without adhesion (its drop at accuracy 1e-8), 0.4008
    /// with it.
    pub(crate) fn oblique_combination(
        &self,
        central: &Combination,
        speed: f64,
    ) -> Result<Combination, SceneError> {
        let candidates = self.models().candidates;
        let used_centrally = |e: EffectKind| central.effects.contains(&e);
        if !candidates.contains(EffectKind::Adhesion) || used_centrally(EffectKind::Adhesion) {
            return Ok(central.clone());
        }
        // the central set (the other drops kept), adhesion back in
        let mut used = candidates;
        for effect in [
            EffectKind::Plasticity,
            EffectKind::Viscoelasticity,
            EffectKind::Damping,
        ] {
            if !used_centrally(effect) {
                used = used.without(effect);
            }
        }
        let evaluation = self
            .models()
            .evaluate(&used, speed)
            .map_err(|e| self.locate(e))?;
        Ok(Combination::of(evaluation.rule, &used))
    }

    /// Where the scene's model sticks (the root of ε(v) = 0 of the model that
    /// answers at each speed, searched within the model's validity), with the
    /// work spent.
    pub(crate) fn sticking(&self) -> Result<(Sticking, Cost), SceneError> {
        self.built
            .sticking
            .get_or_init(|| {
                if self.models().candidates.adhesion.is_none() {
                    // without adhesion nothing holds the bodies together: every
                    // model of tabor rebounds (ε > 0)
                    return Ok((Sticking::Never, Cost::ZERO));
                }
                let whole = SceneModel { prepared: self };
                let vc =
                    sticking_velocity(&whole, self.inputs().accuracy.max(STICKING_ACCURACY_FLOOR))
                        .map_err(SceneError::model)?;
                let sticking = match vc.method {
                    StickingMethod::NeverSticks => Sticking::Never,
                    StickingMethod::SticksUpToLimit => Sticking::UpToLimit {
                        limit: vc.speed,
                        reason: whole.speed_limit().map_or("validity limit", |l| l.reason),
                    },
                    StickingMethod::ClosedForm => Sticking::Below {
                        velocity: vc.speed,
                        rebounds_from: None,
                    },
                    StickingMethod::Root => {
                        return upper_edge(&whole, self.inputs().accuracy, vc.speed, vc.cost)
                    }
                };
                Ok((sticking, vc.cost))
            })
            .clone()
    }
}

/// Where a scene's bodies stick, as far as its model is valid.
#[derive(Clone, Debug, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum Sticking {
    /// The bodies stick below the sticking velocity `velocity` (m/s) and rebound
    /// above it (the root of ε(v) = 0, (5.38) for a speed-independent loss; the
    /// upper edge of the sticking set where ε(v) is not monotone).
    Below {
        /// The sticking velocity (m/s): above it the bodies rebound (checked on a
        /// geometric grid of ratio 2^(1/4) up to `STICKING_CHECK_SPAN` (1024) times
        /// it, within validity: a narrower sticking window above it can be missed).
        velocity: f64,
        /// Where ε(v) is not monotone: `[lower, again]`, the bodies rebound just
        /// above the lower root `lower` of ε(v) = 0 (m/s) and stick again at
        /// `again` (m/s), below `velocity`.
        #[serde(skip_serializing_if = "Option::is_none")]
        rebounds_from: Option<[f64; 2]>,
    },
    /// The bodies never stick (no adhesion, or ε > 0 down to 1e-12 of the speed
    /// scale).
    Never,
    /// The bodies stick at every speed up to `limit` (m/s), where the model's
    /// validity ends: no sticking velocity exists within it.
    UpToLimit {
        /// The highest speed at which the model is valid (m/s).
        limit: f64,
        /// What ends the validity ("small-strain limit").
        reason: &'static str,
    },
}

impl Sticking {
    /// The sticking velocity, when one exists within the model's validity.
    pub fn velocity(&self) -> Option<f64> {
        match self {
            Sticking::Below { velocity, .. } => Some(*velocity),
            Sticking::Never | Sticking::UpToLimit { .. } => None,
        }
    }

    /// Whether the bodies stick at some speed.
    pub fn sticks_ever(&self) -> bool {
        !matches!(self, Sticking::Never)
    }
}

/// How far above a root of ε(v) = 0 the sticking search checks that the bodies
/// rebound (a factor on the root; grid step [`STICKING_CHECK_STEP`]), within the
/// model's validity: the sticking velocity is the upper edge of the sticking set.
pub const STICKING_CHECK_SPAN: f64 = 1024.0;

/// The ratio of neighbouring speeds of the check above a root of ε(v) = 0,
/// 2^(1/4): a sticking window above the root wider than this factor is found.
/// (At 2, the 10⁵-case property run drew a superposition scene, JKR + plasticity +
/// Kelvin-Voigt, that rebounds from 0.161 to 0.23 m/s and sticks again up to
/// 0.31 m/s: a window of a factor 1.35 between 0.161·2^k.)
pub const STICKING_CHECK_STEP: f64 = 1.189_207_115_002_721;

/// Most speeds the check above a root evaluates (over every span it continues).
const STICKING_CHECK_MOST: u32 = 400;

/// The upper edge of the sticking set from the root `root` of ε(v) = 0 that the
/// search of tabor-restitution found (the root nearest the speed scale): speeds
/// `root·s^k` (s = [`STICKING_CHECK_STEP`]) up to [`STICKING_CHECK_SPAN`]·root (and the validity limit) are
/// checked; where one sticks, the search continues from the highest sticking
/// speed and the sticking velocity is the root of ε(v) = 0 above it (Brent). A
/// speed the model cannot answer ends the check (the end of its validity).
/// In the usual monotone case this costs 4 log2(span) = 40 loss evaluations.
fn upper_edge<M: ImpactModel + ?Sized>(
    model: &M,
    accuracy: f64,
    root: f64,
    cost: Cost,
) -> Result<(Sticking, Cost), SceneError> {
    let mass = model.effective_mass();
    let mut cost = cost;
    let evaluations = std::cell::Cell::new(0u64);
    let g = |v: f64, cost: &mut Cost| -> Option<f64> {
        evaluations.set(evaluations.get() + 1);
        let loss = model.energy_loss(v).ok()?;
        *cost += loss.cost;
        Some(1.0 - 2.0 * loss.joules / (mass * v * v))
    };
    let limit = model.speed_limit();
    let mut velocity = root;
    let mut rebounds_from: Option<[f64; 2]> = None;
    // a sticking speed above `velocity` and the rebounding speed above it
    let mut start = root;
    // `start` is a sticking speed of the grid (the search continues above it)
    let mut start_sticks = false;
    let mut steps = 0u32;
    loop {
        let top = limit.map_or(start * STICKING_CHECK_SPAN, |l| {
            (start * STICKING_CHECK_SPAN).min(l.speed)
        });
        let mut v = start;
        let mut highest_stick: Option<f64> = start_sticks.then_some(start);
        let mut rebound_above: Option<f64> = None;
        let mut at_end_sticks = false;
        let mut answered = true;
        while v < top && steps < STICKING_CHECK_MOST {
            v = (v * STICKING_CHECK_STEP).min(top);
            steps += 1;
            let Some(gv) = g(v, &mut cost) else {
                answered = false;
                break;
            };
            if gv <= 0.0 {
                highest_stick = Some(v);
                rebound_above = None;
                at_end_sticks = true;
            } else {
                if highest_stick.is_some() && rebound_above.is_none() {
                    rebound_above = Some(v);
                }
                at_end_sticks = false;
            }
        }
        let Some(stick) = highest_stick else {
            break;
        };
        if rebounds_from.is_none() {
            rebounds_from = Some([root, stick]);
        }
        match rebound_above {
            Some(hi) => {
                let r = tabor_numerics::root_finding::brent(
                    |x| g(x, &mut cost).unwrap_or(f64::NAN),
                    stick,
                    hi,
                    tabor_numerics::root_finding::RootTolerance {
                        absolute: 0.0,
                        relative: accuracy.max(STICKING_ACCURACY_FLOOR),
                        max_iterations: 200,
                    },
                )
                .map_err(|e| SceneError::model(tabor_restitution::Error::from(e)))?;
                cost += Cost::new(0, r.iterations as u64);
                velocity = r.value;
                start = velocity;
                start_sticks = false;
            }
            None if !answered || limit.is_some_and(|l| stick >= l.speed) => {
                // sticks up to the validity limit, or up to the last speed the
                // model answers
                let (limit, reason) = match limit {
                    Some(l) if answered => (l.speed, l.reason),
                    _ => (stick, "highest speed the model answers"),
                };
                return Ok((
                    Sticking::UpToLimit { limit, reason },
                    cost + Cost::new(evaluations.get(), 0),
                ));
            }
            None => {
                // sticks at the end of the span: continue from there
                debug_assert!(at_end_sticks);
                start = stick;
                start_sticks = true;
                if steps >= STICKING_CHECK_MOST {
                    break;
                }
            }
        }
    }
    Ok((
        Sticking::Below {
            velocity,
            rebounds_from,
        },
        cost + Cost::new(evaluations.get(), 0),
    ))
}

/// The scene as one [`ImpactModel`]: at each speed, the loss of the effects that
/// matter there, combined by the table's rule.
pub(crate) struct SceneModel<'p, 'a> {
    pub prepared: &'p Prepared<'a>,
}

impl ImpactModel for SceneModel<'_, '_> {
    fn name(&self) -> String {
        format!("scene {}", self.prepared.name)
    }
    fn effective_mass(&self) -> f64 {
        self.prepared.models().mass
    }
    fn energy_loss(&self, impact_speed: f64) -> tabor_restitution::Result<EnergyLoss> {
        self.prepared
            .select(impact_speed)
            .map(|s| s.evaluation.loss)
            .map_err(|e| tabor_restitution::Error::Model {
                model: "scene",
                message: e.to_string(),
            })
    }
    fn loss_is_speed_independent(&self) -> bool {
        let m = self.prepared.models();
        let c = m.candidates;
        c.plasticity.is_none()
            && c.viscoelasticity.is_none()
            && !c.damping
            && m.adhesive
                .as_ref()
                .is_some_and(|a| a.model.model().loss_is_speed_independent())
    }
    fn speed_scale(&self) -> f64 {
        let m = self.prepared.models();
        if let Some(a) = &m.adhesive {
            a.model.model().speed_scale()
        } else if let Some(p) = &m.plastic {
            p.model().speed_scale()
        } else if let Some(v) = &m.visco {
            v.model.speed_scale()
        } else {
            1.0
        }
    }
    /// The lowest validity limit of the models the scene can use (the
    /// small-strain limit of the simulated viscous-adhesive model, or of the
    /// damped adhesive one).
    fn speed_limit(&self) -> Option<SpeedLimit> {
        let m = self.prepared.models();
        m.viscous_adhesive
            .as_ref()
            .or(m.damped.as_ref().and_then(|d| d.adhesive.as_ref()))
            .and_then(|v| v.speed_limit())
    }
}

/// Whether a rule's result is a superposition that deserves a warning.
pub(crate) fn is_superposed(rule: Rule) -> bool {
    matches!(rule, Rule::Superposition | Rule::SuperpositionBound)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// ε(v) of the property run's scene (#22): sticks below 0.0403 m/s, rebounds
    /// up to 0.045, sticks again up to 0.2 and rebounds above; here the loss
    /// (1 − ε²)·m v²/2 with that ε(v) written out.
    struct NonMonotone;
    const WINDOW: (f64, f64, f64) = (0.0403, 0.045, 0.2);
    impl ImpactModel for NonMonotone {
        fn name(&self) -> String {
            "non-monotone".into()
        }
        fn effective_mass(&self) -> f64 {
            2.0
        }
        fn energy_loss(&self, v: f64) -> tabor_restitution::Result<EnergyLoss> {
            let (a, b, c) = WINDOW;
            // g = 1 − 2ΔU/(m v²) (ε² where > 0): roots at a and c, a bump of
            // ε² ≤ 3e-3 in (a, b), sticking (g < 0) below a and in [b, c)
            let g = if v <= a {
                (v - a) / v
            } else if v < b {
                3e-3 * (v - a).min(b - v) / (b - a)
            } else {
                (v - c) / v
            };
            Ok(EnergyLoss::closed_form((1.0 - g) * v * v, "test"))
        }
    }

    #[test]
    fn the_sticking_velocity_is_the_upper_edge_of_the_sticking_set() {
        let (a, _, c) = WINDOW;
        let (s, _) = upper_edge(&NonMonotone, 1e-12, a, Cost::ZERO).unwrap();
        let Sticking::Below {
            velocity,
            rebounds_from: Some([lower, again]),
        } = s
        else {
            panic!("{s:?}");
        };
        assert!((velocity / c - 1.0).abs() < 1e-9, "{velocity}");
        assert_eq!(lower, a);
        assert!(again > 0.045 && again <= c, "{again}");
    }
}
