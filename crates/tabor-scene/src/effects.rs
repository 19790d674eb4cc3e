//! Effect selection: which physical effects a scene calls for, which model
//! computes each, and the combined outcome.

use crate::scene::{AdhesionRange, AdhesivePlasticity, PlasticityModel, Scene, SceneError};
use serde::Serialize;
use tabor_dynamics::{simulate_impact, ForceLaw, ImpactSimulation, SimulationSettings};
use tabor_elastic::ElasticContact;
use tabor_jkr::{GradedSphere, JkrForceLaw, JkrImpact, JkrSphere, SeparationRule};
use tabor_maugis::{normalized_loss, MaugisDugdaleForceLaw, MaugisDugdaleImpact, LAMBDA_1};
use tabor_numerics::Cost;
use tabor_plastic::{
    AdhesiveInterpolationImpact, DimensionlessFit, Interpolation, JacksonGreen, JacksonGreenImpact,
    PlasticContact, PlasticImpact, Superposition, Thornton,
};
use tabor_restitution::checks::{elastic_limit_check, quasi_static_check};
use tabor_restitution::{
    impact, sticking_velocity, EnergyLoss, Error, ImpactModel, StickingMethod, Warning,
};
use tabor_visco::models::KelvinVoigtSphere;
use tabor_visco::SphereModel;

/// One physical effect and whether the scene uses it.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Effect {
    /// "elasticity", "adhesion", "plasticity" or "viscoelasticity".
    pub name: &'static str,
    /// Whether the effect enters the result.
    pub used: bool,
    /// Why it is used or skipped.
    pub reason: String,
    /// The model computing it (when used).
    pub model: Option<String>,
    /// Its energy loss on its own at the impact speed (J), when computed: the
    /// model's loss, at most the kinetic energy (an effect that alone would make
    /// the bodies stick takes all of it).
    pub energy_loss: Option<f64>,
}

/// The result of a scene at one impact speed.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Outcome {
    /// The scene's name.
    pub scene: String,
    /// Impact speed (m/s).
    pub impact_speed: f64,
    /// Coefficient of restitution (5.37).
    pub restitution: f64,
    /// Whether the bodies stick.
    pub sticks: bool,
    /// The sticking velocity (m/s) of the scene's full model (all effects whose
    /// parameters are given); `None` when the bodies never stick.
    pub sticking_velocity: Option<f64>,
    /// Kinetic energy lost (J), total.
    pub energy_loss: f64,
    /// Kinetic energy before impact (J).
    pub kinetic_energy: f64,
    /// The model that produced the result.
    pub model: String,
    /// The formula or branch inside that model.
    pub branch: String,
    /// The Tabor parameter Λ, when the interface has a range.
    pub tabor_parameter: Option<f64>,
    /// Effects used and skipped, with their reasons and separate losses.
    pub effects: Vec<Effect>,
    /// The requested relative accuracy.
    pub accuracy: f64,
    /// Estimated absolute error of the energy loss (J).
    pub energy_loss_error: f64,
    /// Work spent: evaluations and iterations.
    pub cost: Cost,
    /// Validity warnings.
    pub warnings: Vec<Warning>,
}

/// The non-adhesive plastic models, dispatched by value.
#[derive(Clone, Debug)]
enum Plastic {
    Thornton(PlasticImpact<Thornton>),
    Interpolation(PlasticImpact<Interpolation>),
    JacksonGreen(Box<JacksonGreenImpact>),
    Fit(DimensionlessFit),
}

impl Plastic {
    fn model(&self) -> &dyn ImpactModel {
        match self {
            Plastic::Thornton(m) => m,
            Plastic::Interpolation(m) => m,
            Plastic::JacksonGreen(m) => m.as_ref(),
            Plastic::Fit(m) => m,
        }
    }
    fn yield_velocity(&self) -> f64 {
        match self {
            Plastic::Thornton(m) => m.yield_velocity(),
            Plastic::Interpolation(m) => m.yield_velocity(),
            Plastic::JacksonGreen(m) => m.yield_velocity(),
            Plastic::Fit(m) => m.yield_velocity(),
        }
    }
}

impl ImpactModel for Plastic {
    fn name(&self) -> String {
        self.model().name()
    }
    fn effective_mass(&self) -> f64 {
        self.model().effective_mass()
    }
    fn energy_loss(&self, v: f64) -> tabor_restitution::Result<EnergyLoss> {
        self.model().energy_loss(v)
    }
    fn loss_is_speed_independent(&self) -> bool {
        self.model().loss_is_speed_independent()
    }
    fn speed_scale(&self) -> f64 {
        self.model().speed_scale()
    }
}

/// The elastic adhesive models.
#[derive(Clone, Debug)]
enum Adhesive {
    Jkr(JkrImpact<JkrSphere>),
    Graded(JkrImpact<GradedSphere>),
    Maugis(MaugisDugdaleImpact),
}

impl Adhesive {
    fn model(&self) -> &dyn ImpactModel {
        match self {
            Adhesive::Jkr(m) => m,
            Adhesive::Graded(m) => m,
            Adhesive::Maugis(m) => m,
        }
    }
}

/// The sum of the losses of several models with the same mass: the superposition
/// used where tabor has no combined model (flagged by a warning).
struct SumOfLosses<'a> {
    parts: Vec<&'a dyn ImpactModel>,
}

impl ImpactModel for SumOfLosses<'_> {
    fn name(&self) -> String {
        let names: Vec<String> = self.parts.iter().map(|p| p.name()).collect();
        format!("sum of losses: {}", names.join(" + "))
    }
    fn effective_mass(&self) -> f64 {
        self.parts.first().map_or(f64::NAN, |p| p.effective_mass())
    }
    fn energy_loss(&self, v: f64) -> tabor_restitution::Result<EnergyLoss> {
        let mut total = EnergyLoss {
            joules: 0.0,
            error_estimate: 0.0,
            branch: String::new(),
            cost: Cost::ZERO,
        };
        let mut branches = Vec::new();
        for p in &self.parts {
            let l = p.energy_loss(v)?;
            total.joules += l.joules;
            total.error_estimate += l.error_estimate;
            total.cost += l.cost;
            branches.push(l.branch);
        }
        total.branch = branches.join(" + ");
        Ok(total)
    }
    fn loss_is_speed_independent(&self) -> bool {
        self.parts.iter().all(|p| p.loss_is_speed_independent())
    }
    fn speed_scale(&self) -> f64 {
        self.parts.first().map_or(1.0, |p| p.speed_scale())
    }
}

/// All the models a scene can use, built once.
struct Models {
    adhesive: Option<(Adhesive, String)>,
    plastic: Option<Plastic>,
    adhesive_plastic: Option<AdhesiveInterpolationImpact>,
    superposed: Option<Superposition<Plastic>>,
    visco: Option<KelvinVoigtSphere>,
}

fn err(e: Error) -> SceneError {
    SceneError::model(e)
}

fn build_models(scene: &Scene) -> Result<Models, SceneError> {
    let (e, r, m) = (
        scene.effective_modulus,
        scene.effective_radius,
        scene.effective_mass,
    );
    let acc = scene.accuracy;
    let adhesive = match &scene.adhesion {
        Some(a) if a.work_of_adhesion > 0.0 => Some(match (scene.target.gradation, a.range) {
            (Some((k, c)), _) => {
                let g = GradedSphere::new(c, k, r, a.work_of_adhesion).map_err(err)?;
                let model = JkrImpact::new(g, m)
                    .map_err(err)?
                    .with_separation(a.separation)
                    .with_tolerance(acc)
                    .map_err(err)?;
                (
                    Adhesive::Graded(model),
                    "JKR on a power-law graded medium (5.47)-(5.51); Maugis-Dugdale is not available for graded media".to_string(),
                )
            }
            (None, AdhesionRange::Jkr) => {
                let s = JkrSphere::new(e, r, a.work_of_adhesion).map_err(err)?;
                let model = JkrImpact::new(s, m)
                    .map_err(err)?
                    .with_separation(a.separation)
                    .with_tolerance(acc)
                    .map_err(err)?;
                (
                    Adhesive::Jkr(model),
                    "JKR: no range of adhesion given".to_string(),
                )
            }
            (None, AdhesionRange::TaborParameter(lambda)) => {
                let md = MaugisDugdaleImpact::new(e, r, a.work_of_adhesion, lambda, m)
                    .map_err(err)?
                    .with_tolerance(acc)
                    .map_err(err)?;
                if lambda <= LAMBDA_1 {
                    (
                        Adhesive::Maugis(md),
                        format!("Maugis-Dugdale case-1 closed form (5.44): Lambda = {lambda:.4e} <= Lambda1"),
                    )
                } else {
                    let w = normalized_loss(lambda, acc).map_err(err)?;
                    // relative to the fixed-grip JKR loss, the Λ → ∞ limit of the
                    // Maugis-Dugdale loss (seed 000 Fig. 5.2)
                    let difference = (1.0 - w.loss_over_jkr).abs();
                    if difference < acc {
                        // The substitute must be that limit: the fixed-grip rule, whatever
                        // `separation` says (the Maugis-Dugdale path has its own snap-off;
                        // the load-controlled JKR loss is about half of it).
                        let s = JkrSphere::new(e, r, a.work_of_adhesion).map_err(err)?;
                        let model = JkrImpact::new(s, m)
                            .map_err(err)?
                            .with_separation(SeparationRule::FixedGrip)
                            .with_tolerance(acc)
                            .map_err(err)?;
                        let rule_note = if a.separation == SeparationRule::FixedGrip {
                            ""
                        } else {
                            " (fixed grip, the Maugis-Dugdale limit; the separation rule applies only without a range)"
                        };
                        (
                            Adhesive::Jkr(model),
                            format!("JKR closed form{rule_note}: the Maugis-Dugdale loss at Lambda = {lambda:.4e} differs from JKR by {difference:.2e} < accuracy {acc:.1e}"),
                        )
                    } else {
                        (
                            Adhesive::Maugis(md),
                            format!("Maugis-Dugdale, numerical (case {}): Lambda = {lambda:.4e}, differs from JKR by {difference:.2e} >= accuracy {acc:.1e}", w.case.number()),
                        )
                    }
                }
            }
        }),
        _ => None,
    };
    let plastic = match scene.yield_stress() {
        None => None,
        Some(sy) => Some(match scene.plasticity {
            PlasticityModel::Thornton => Plastic::Thornton(
                PlasticImpact::new(PlasticContact::new(e, r, sy).map_err(err)?, Thornton, m)
                    .map_err(err)?,
            ),
            PlasticityModel::Auto | PlasticityModel::Interpolation => Plastic::Interpolation(
                PlasticImpact::new(
                    PlasticContact::new(e, r, sy).map_err(err)?,
                    Interpolation::default(),
                    m,
                )
                .map_err(err)?,
            ),
            PlasticityModel::JacksonGreen => Plastic::JacksonGreen(Box::new(
                JacksonGreen::new(e, r, sy, scene.plastic_poisson_ratio())
                    .map_err(err)?
                    .impact(m, SimulationSettings::default())
                    .map_err(err)?,
            )),
            PlasticityModel::DimensionlessFit => {
                let rho = scene.sphere.density.ok_or_else(|| {
                    SceneError::field(
                        "sphere.density",
                        "the dimensionless fit needs the sphere's density",
                    )
                })?;
                Plastic::Fit(DimensionlessFit::new(e, sy, rho, m).map_err(err)?)
            }
        }),
    };
    let (adhesive_plastic, superposed) = match (&scene.adhesion, scene.yield_stress(), &plastic) {
        (Some(a), Some(sy), Some(p)) if a.work_of_adhesion > 0.0 => match scene.adhesive_plasticity
        {
            AdhesivePlasticity::Interpolation => (
                Some(
                    AdhesiveInterpolationImpact::from_yield_stress(e, r, sy, a.work_of_adhesion, m)
                        .map_err(err)?,
                ),
                None,
            ),
            AdhesivePlasticity::Superposition => (
                None,
                Some(
                    Superposition::new(
                        p.clone(),
                        JkrSphere::new(e, r, a.work_of_adhesion).map_err(err)?,
                    )
                    .map_err(err)?,
                ),
            ),
        },
        _ => (None, None),
    };
    let visco = match scene.viscosity() {
        None => None,
        Some(eta) => {
            // incompressible Kelvin-Voigt half-space: E* = 4G
            Some(KelvinVoigtSphere::new(e / 4.0, eta, r, m, SphereModel::Rigorous).map_err(err)?)
        }
    };
    Ok(Models {
        adhesive,
        plastic,
        adhesive_plastic,
        superposed,
        visco,
    })
}

/// Which models the scene uses at one speed (or, without a speed, all whose
/// parameters are given), with the reasons.
struct Selection<'a> {
    effects: Vec<Effect>,
    parts: Vec<&'a dyn ImpactModel>,
    superposed_warning: bool,
    law: LawChoice,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum LawChoice {
    Elastic,
    Adhesive,
    Plastic,
    AdhesivePlastic,
    None,
}

fn loss_at(model: &dyn ImpactModel, v: f64) -> Result<f64, SceneError> {
    Ok(model.energy_loss(v).map_err(err)?.joules)
}

fn select<'a>(
    scene: &Scene,
    models: &'a Models,
    speed: Option<f64>,
) -> Result<Selection<'a>, SceneError> {
    let acc = scene.accuracy;
    let kinetic = speed.map(|v| 0.5 * scene.effective_mass * v * v);
    let mut effects = vec![Effect {
        name: "elasticity",
        used: true,
        reason: "always: the elastic contact (Hertz) carries the load; it loses no energy".into(),
        model: Some(if scene.target.gradation.is_some() {
            "elastic sphere on a graded medium (5.20)-(5.23)".into()
        } else {
            "Hertz (5.5)-(5.12)".into()
        }),
        energy_loss: Some(0.0),
    }];
    // adhesion
    let adhesion_used = match (&scene.adhesion, &models.adhesive) {
        (None, _) => {
            effects.push(Effect {
                name: "adhesion",
                used: false,
                reason: "no [adhesion] section: the surfaces do not adhere".into(),
                model: None,
                energy_loss: None,
            });
            false
        }
        (Some(_), None) => {
            effects.push(Effect {
                name: "adhesion",
                used: false,
                reason: "the work of adhesion is 0".into(),
                model: None,
                energy_loss: None,
            });
            false
        }
        (Some(_), Some((model, why))) => {
            let (used, reason, loss) = match (speed, kinetic) {
                (Some(v), Some(k)) => {
                    let loss = loss_at(model.model(), v)?;
                    if loss < acc * k {
                        (
                            false,
                            format!("its loss {loss:.3e} J is {:.2e} of the kinetic energy, below the requested accuracy {acc:.1e}", loss / k),
                            Some(loss),
                        )
                    } else {
                        (true, why.clone(), Some(loss.min(k)))
                    }
                }
                _ => (true, why.clone(), None),
            };
            effects.push(Effect {
                name: "adhesion",
                used,
                reason,
                model: Some(model.model().name()),
                energy_loss: loss,
            });
            used
        }
    };
    // plasticity
    let plastic_used = match &models.plastic {
        None => {
            effects.push(Effect {
                name: "plasticity",
                used: false,
                reason: "no yield_stress given: the bodies stay elastic".into(),
                model: None,
                energy_loss: None,
            });
            false
        }
        Some(p) => {
            let onset = match (adhesion_used, &models.adhesive_plastic) {
                (true, Some(a)) => (a.yield_velocity(), "adhesive yield onset (5.111)"),
                _ => (p.yield_velocity(), "yield onset v_Y (5.103)"),
            };
            let (used, reason, loss) = match (speed, kinetic) {
                (Some(v), _) if v <= onset.0 => (
                    false,
                    format!(
                        "impact speed {v:.4e} m/s does not exceed the {} {:.4e} m/s",
                        onset.1, onset.0
                    ),
                    None,
                ),
                (Some(v), Some(k)) => (
                    true,
                    format!(
                        "impact speed {v:.4e} m/s exceeds the {} {:.4e} m/s",
                        onset.1, onset.0
                    ),
                    Some(loss_at(p, v)?.min(k)),
                ),
                _ => (
                    true,
                    format!("yield stress given ({} {:.4e} m/s)", onset.1, onset.0),
                    None,
                ),
            };
            effects.push(Effect {
                name: "plasticity",
                used,
                reason,
                model: Some(p.name()),
                energy_loss: loss,
            });
            used
        }
    };
    // viscoelasticity
    let visco_used = match &models.visco {
        None => {
            effects.push(Effect {
                name: "viscoelasticity",
                used: false,
                reason: "no viscosity given".into(),
                model: None,
                energy_loss: None,
            });
            false
        }
        Some(vm) => {
            let (used, reason, loss) = match (speed, kinetic) {
                (Some(v), Some(k)) => {
                    let loss = loss_at(vm, v)?;
                    if loss < acc * k {
                        (false, format!("its loss is {:.2e} of the kinetic energy, below the requested accuracy", loss / k), Some(loss))
                    } else {
                        (
                            true,
                            "viscosity given and its loss matters at the requested accuracy".into(),
                            Some(loss.min(k)),
                        )
                    }
                }
                _ => (true, "viscosity given".into(), None),
            };
            effects.push(Effect {
                name: "viscoelasticity",
                used,
                reason,
                model: Some(vm.name()),
                energy_loss: loss,
            });
            used
        }
    };
    let mut parts: Vec<&dyn ImpactModel> = Vec::new();
    let law;
    match (adhesion_used, plastic_used) {
        (true, true) => {
            if let Some(a) = &models.adhesive_plastic {
                parts.push(a);
                law = LawChoice::AdhesivePlastic;
            } else if let Some(s) = &models.superposed {
                parts.push(s);
                law = LawChoice::None;
            } else {
                return Err(SceneError::model(Error::Model {
                    model: "scene",
                    message: "no combined adhesive-plastic model".into(),
                }));
            }
        }
        (true, false) => {
            if let Some((a, _)) = &models.adhesive {
                parts.push(a.model());
            }
            law = LawChoice::Adhesive;
        }
        (false, true) => {
            if let Some(p) = &models.plastic {
                parts.push(p);
            }
            law = if matches!(models.plastic, Some(Plastic::Fit(_))) {
                LawChoice::None
            } else {
                LawChoice::Plastic
            };
        }
        (false, false) => law = LawChoice::Elastic,
    }
    let mut superposed_warning = false;
    let mut law = law;
    if visco_used {
        if let Some(vm) = &models.visco {
            superposed_warning = !parts.is_empty();
            parts.push(vm);
            law = LawChoice::None;
        }
    }
    Ok(Selection {
        effects,
        parts,
        superposed_warning,
        law,
    })
}

/// A model that loses nothing (the elastic contact).
struct Elastic {
    mass: f64,
}

impl ImpactModel for Elastic {
    fn name(&self) -> String {
        "elastic (Hertz)".into()
    }
    fn effective_mass(&self) -> f64 {
        self.mass
    }
    fn energy_loss(&self, _v: f64) -> tabor_restitution::Result<EnergyLoss> {
        Ok(EnergyLoss::closed_form(
            0.0,
            "elastic impact: no loss (5.5)-(5.12)",
        ))
    }
    fn loss_is_speed_independent(&self) -> bool {
        true
    }
}

fn sticking_of(scene: &Scene, models: &Models) -> Result<(Option<f64>, Cost), SceneError> {
    let all = select(scene, models, None)?;
    let elastic = Elastic {
        mass: scene.effective_mass,
    };
    let combined = SumOfLosses { parts: all.parts };
    let model: &dyn ImpactModel = if combined.parts.is_empty() {
        &elastic
    } else {
        &combined
    };
    let vc = sticking_velocity(model, scene.accuracy.max(1e-14)).map_err(err)?;
    Ok(match vc.method {
        StickingMethod::NeverSticks => (None, vc.cost),
        _ => (Some(vc.speed), vc.cost),
    })
}

impl Scene {
    /// The outcome at the scene's impact speed (an error names `impact.speed` when
    /// the scene has none).
    pub fn outcome(&self) -> Result<Outcome, SceneError> {
        let v = self
            .speed
            .ok_or_else(|| SceneError::field("impact.speed", "is required for an impact (m/s)"))?;
        self.outcome_at(v)
    }

    /// The outcome at impact speed `speed` (m/s).
    pub fn outcome_at(&self, speed: f64) -> Result<Outcome, SceneError> {
        let v = tabor_restitution::validate::positive("speed", speed)
            .map_err(|e| SceneError::field("impact.speed", e.to_string()))?;
        let models = build_models(self)?;
        let selection = select(self, &models, Some(v))?;
        let elastic = Elastic {
            mass: self.effective_mass,
        };
        let combined = SumOfLosses {
            parts: selection.parts.clone(),
        };
        let model: &dyn ImpactModel = match selection.parts.len() {
            0 => &elastic,
            1 => selection.parts[0],
            _ => &combined,
        };
        let o = impact(model, v).map_err(err)?;
        let (sticking, sticking_cost) = sticking_of(self, &models)?;
        let mut warnings = Vec::new();
        if let Some((e, rho)) = self.wave_speed_body() {
            if let Some(w) = quasi_static_check(v, e, rho).map_err(err)?.warning() {
                warnings.push(w);
            }
        }
        if let (Some(sy), false) = (
            self.yield_stress(),
            selection
                .effects
                .iter()
                .any(|e| e.name == "plasticity" && e.used),
        ) {
            let check = elastic_limit_check(
                self.effective_modulus,
                self.effective_radius,
                self.effective_mass,
                v,
                sy,
            )
            .map_err(err)?;
            if let Some(w) = check.warning() {
                warnings.push(w);
            }
        }
        if selection.superposed_warning {
            warnings.push(Warning {
                code: "superposed-losses",
                message: "tabor has no combined model for viscoelasticity with adhesion or plasticity: their losses are added".into(),
            });
        }
        Ok(Outcome {
            scene: self.name.clone(),
            impact_speed: v,
            restitution: o.restitution,
            sticks: o.sticks,
            sticking_velocity: sticking,
            energy_loss: o.energy_loss,
            kinetic_energy: o.kinetic_energy,
            model: o.model,
            branch: o.branch,
            tabor_parameter: self.tabor_parameter(),
            effects: selection.effects,
            accuracy: self.accuracy,
            energy_loss_error: o.energy_loss_error,
            cost: o.cost + sticking_cost,
            warnings,
        })
    }

    /// The sticking velocity (m/s) of the scene's full model (every effect whose
    /// parameters are given), or `None` when the bodies never stick.
    pub fn sticking_velocity(&self) -> Result<Option<f64>, SceneError> {
        let models = build_models(self)?;
        Ok(sticking_of(self, &models)?.0)
    }

    /// Simulates the impact at `speed` in the time domain with the force law of the
    /// model the scene selects at that speed, and returns the simulation with the
    /// analytic outcome of the same model.
    pub fn simulate(
        &self,
        speed: f64,
        settings: &SimulationSettings,
    ) -> Result<(ImpactSimulation, Outcome), SceneError> {
        let outcome = self.outcome_at(speed)?;
        let models = build_models(self)?;
        let selection = select(self, &models, Some(speed))?;
        let m = self.effective_mass;
        let no_law = |what: &str| {
            SceneError::model(Error::Model {
                model: "scene",
                message: format!("no time-domain force law for {what}"),
            })
        };
        let mut law: Box<dyn ForceLaw> =
            match selection.law {
                LawChoice::Elastic => Box::new(match self.target.gradation {
                    Some((k, c)) => {
                        ElasticContact::graded_sphere(c, k, self.effective_radius).map_err(err)?
                    }
                    None => ElasticContact::hertz(self.effective_modulus, self.effective_radius)
                        .map_err(err)?,
                }),
                LawChoice::Adhesive => match &models.adhesive {
                    // the rule of the selected model (fixed grip when it stands in
                    // for Maugis-Dugdale)
                    Some((Adhesive::Jkr(j), _)) => {
                        Box::new(JkrForceLaw::new(*j.contact(), j.separation()))
                    }
                    None => return Err(no_law("this scene")),
                    Some((Adhesive::Maugis(md), _)) => {
                        Box::new(MaugisDugdaleForceLaw::new(md).map_err(err)?)
                    }
                    Some((Adhesive::Graded(_), _)) => return Err(no_law("JKR on a graded medium")),
                },
                LawChoice::Plastic => match &models.plastic {
                    Some(Plastic::Thornton(p)) => Box::new(p.force_law()),
                    Some(Plastic::Interpolation(p)) => Box::new(p.force_law()),
                    Some(Plastic::JacksonGreen(_)) => Box::new(
                        JacksonGreen::new(
                            self.effective_modulus,
                            self.effective_radius,
                            self.yield_stress().unwrap_or(f64::NAN),
                            self.plastic_poisson_ratio(),
                        )
                        .map_err(err)?
                        .force_law(),
                    ),
                    _ => return Err(no_law("seed 001's dimensionless fit")),
                },
                LawChoice::AdhesivePlastic => match &models.adhesive_plastic {
                    Some(a) => Box::new(a.force_law()),
                    None => return Err(no_law("this combination")),
                },
                LawChoice::None => return Err(no_law(
                    "superposed or fitted models (viscoelastic, superposition, dimensionless fit)",
                )),
            };
        let sim = simulate_impact(law.as_mut(), m, speed, settings).map_err(err)?;
        Ok((sim, outcome))
    }
}
