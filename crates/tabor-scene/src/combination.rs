//! The combination table: which model answers for every subset of effects a scene
//! can call for, stated once ([`rule`]) and reported in every outcome
//! ([`Combination`]). `examples/scenes/README.md` prints the same table.

use serde::Serialize;
use std::fmt;

/// One physical effect of a scene.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum EffectKind {
    /// The elastic contact (Hertz, seed 000 eqs. (5.5)-(5.12), or the graded medium
    /// (5.20)-(5.23)): always present, loses nothing.
    Elasticity,
    /// Adhesion: JKR (5.31)-(5.38), Maugis-Dugdale (5.39)-(5.46) or graded JKR
    /// (5.47)-(5.51).
    Adhesion,
    /// Plasticity above the yield onset (5.101)-(5.126), seed 001.
    Plasticity,
    /// Viscoelasticity (5.54)-(5.100), by the correspondence principle.
    Viscoelasticity,
    /// A DEM normal damping law of LAMMPS's `pair granular` (`[damping]`:
    /// `viscoelastic`, `tsuji`, `coeff_restitution`) on the scene's force law
    /// (`tabor_viscoadhesive::NormalDamping`).
    Damping,
}

impl EffectKind {
    /// The name used in files and outputs ("adhesion", ...).
    pub fn as_str(self) -> &'static str {
        match self {
            EffectKind::Elasticity => "elasticity",
            EffectKind::Adhesion => "adhesion",
            EffectKind::Plasticity => "plasticity",
            EffectKind::Viscoelasticity => "viscoelasticity",
            EffectKind::Damping => "damping",
        }
    }
}

impl fmt::Display for EffectKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.pad(self.as_str())
    }
}

impl PartialEq<&str> for EffectKind {
    fn eq(&self, other: &&str) -> bool {
        self.as_str() == *other
    }
}

/// The kind of adhesive interface (fixed by the scene, whatever the speed).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum AdhesionKind {
    /// JKR, no range, fixed-grip separation (5.36).
    JkrFixedGrip,
    /// JKR, no range, load-controlled separation.
    JkrLoadControlled,
    /// Maugis-Dugdale with a range (Tabor parameter Λ), (5.39)-(5.46).
    MaugisDugdale,
    /// JKR on a power-law graded half-space (5.47)-(5.51).
    GradedJkr,
}

/// The kind of plastic model.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PlasticityKind {
    /// The interpolation model (5.107), which the adhesive interpolation model
    /// (5.111)-(5.126) extends.
    Interpolation,
    /// Thornton (5.104)-(5.106), Jackson-Green (5.108) or seed 001's fit: no
    /// adhesive counterpart.
    WithoutAdhesiveCounterpart,
}

/// The kind of viscoelastic contact, from both bodies by the correspondence
/// principle (the contact compliance is the sum of the bodies' (1 − ν²)/E(s)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum ViscoKind {
    /// One Kelvin-Voigt body on an elastic one: a standard linear medium
    /// (5.75), (5.84)-(5.90).
    StandardMedium,
    /// Two Kelvin-Voigt bodies with equal relaxation times: a Kelvin-Voigt contact
    /// (5.64)-(5.68).
    KelvinVoigt,
    /// Two Kelvin-Voigt bodies with different relaxation times: a four-parameter
    /// medium no tabor model solves.
    TwoRelaxationTimes,
}

/// The effects a model must combine, with the kinds that decide the rule.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub struct EffectSet {
    /// Adhesion, when used.
    pub adhesion: Option<AdhesionKind>,
    /// Plasticity, when used.
    pub plasticity: Option<PlasticityKind>,
    /// Viscoelasticity, when used.
    pub viscoelasticity: Option<ViscoKind>,
    /// Whether the target is a graded medium.
    pub graded: bool,
    /// Whether the scene asks for the superposition of adhesion and plasticity
    /// (`[plasticity] adhesive_model = "superposition"`).
    pub superposition_requested: bool,
    /// Whether a DEM damping law damps the normal force (`[damping]`).
    pub damping: bool,
}

impl EffectSet {
    /// The set without `effect`.
    pub fn without(mut self, effect: EffectKind) -> Self {
        match effect {
            EffectKind::Adhesion => self.adhesion = None,
            EffectKind::Plasticity => self.plasticity = None,
            EffectKind::Viscoelasticity => self.viscoelasticity = None,
            EffectKind::Damping => self.damping = false,
            EffectKind::Elasticity => {}
        }
        self
    }

    /// Whether `effect` is in the set.
    pub fn contains(&self, effect: EffectKind) -> bool {
        match effect {
            EffectKind::Elasticity => true,
            EffectKind::Adhesion => self.adhesion.is_some(),
            EffectKind::Plasticity => self.plasticity.is_some(),
            EffectKind::Viscoelasticity => self.viscoelasticity.is_some(),
            EffectKind::Damping => self.damping,
        }
    }
}

/// How a set of effects is combined into one energy loss. Serialized as its
/// [`Rule::as_str`] name (the name `FromStr` reads and the text output prints).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rule {
    /// No dissipative effect: the elastic impact, ε = 1 (5.5)-(5.12).
    Elastic,
    /// One effect: its own model, exact within the model.
    Single,
    /// Adhesion (JKR, fixed grip) + plasticity (interpolation model): the adhesive
    /// interpolation model, seed 000 (5.111)-(5.126), bounded below by the
    /// superposition (5.109): max(L_AI, L_JKR + L_plastic).
    AdhesiveInterpolation,
    /// Adhesion with a range or the load-controlled rule + plasticity
    /// (interpolation model): the scene's elastic adhesive loss plus the plastic part
    /// max(L_AI − L_JKR,fg, L_plastic) of the adhesive interpolation model; a coupled
    /// model of ours (crate README).
    AdhesivePlasticExcess,
    /// Adhesion (JKR or Maugis-Dugdale) + viscoelasticity on a Kelvin-Voigt
    /// contact: the adhesive force plus the Kuwabara-Kono viscous force (5.66) with
    /// the adhesive contact radius, simulated; a coupled model of ours
    /// (tabor-viscoadhesive).
    ViscousAdhesive,
    /// The sum of the effects' losses, seed 000 (5.109) generalized; reported with
    /// a warning.
    Superposition,
    /// A DEM damping law (`[damping]`) on the scene's normal force law (Hertz,
    /// JKR, Maugis-Dugdale, an elasto-plastic law, or the adhesive interpolation
    /// law), simulated: `F + c(m, a) ḋ` with the law's own contact radius
    /// (tabor-viscoadhesive, "DEM damping laws").
    Damped,
    /// Adhesion + plasticity where the adhesive-interpolation or
    /// adhesive-plastic-excess rule takes its lower bound: the superposition (5.109)
    /// of the adhesive and the non-adhesive plastic losses, which dissipates more
    /// than the adhesive interpolation model there; reported with the
    /// superposition's warning. Never returned by [`rule`] (it depends on the
    /// speed), only in outcomes.
    SuperpositionBound,
}

tabor_restitution::menu! {
    Rule, "combination rule";
    Elastic => "elastic", "no dissipative effect: the elastic impact (5.5)-(5.12)";
    Single => "single-effect", "one effect: its own model";
    AdhesiveInterpolation => "adhesive-interpolation",
        "JKR fixed grip + interpolation plasticity: (5.111)-(5.126), at least the superposition (5.109)";
    AdhesivePlasticExcess => "adhesive-plastic-excess",
        "a range or load-controlled adhesion + plasticity: elastic adhesive loss + the plastic part of (5.111)-(5.126)";
    ViscousAdhesive => "viscous-adhesive",
        "adhesion + Kelvin-Voigt viscosity: adhesive force + Kuwabara-Kono force (5.66), simulated";
    Superposition => "superposition", "the sum of the effects' losses (5.109)";
    Damped => "dem-damping",
        "a DEM damping law on the scene's force law: F + c(m, a) v_n with its contact radius, simulated";
    SuperpositionBound => "superposition-bound",
        "adhesion + plasticity where the adhesive interpolation model dissipates less: the superposition (5.109) as its lower bound";
}

impl Serialize for Rule {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        serializer.serialize_str(self.as_str())
    }
}

impl Rule {
    /// Where the rule comes from.
    pub fn source(self) -> &'static str {
        match self {
            Rule::Elastic => "Willert 2020 (5.5)-(5.12): an elastic impact loses nothing",
            Rule::Single => "the effect's own model (exact reduction: no other effect is used)",
            Rule::AdhesiveInterpolation => {
                "Willert 2020 (5.111)-(5.126) (constants in tabor-plastic's README), at least the superposition (5.109) (crates/tabor-scene/README.md)"
            }
            Rule::AdhesivePlasticExcess => {
                "tabor (crates/tabor-scene/README.md): elastic adhesive loss + the plastic part of (5.111)-(5.126), at least the non-adhesive plastic loss"
            }
            Rule::ViscousAdhesive => {
                "tabor (crates/tabor-viscoadhesive/README.md): adhesive force + Kuwabara-Kono force (5.66) with the adhesive contact radius"
            }
            Rule::Superposition => "Willert 2020 (5.109): the losses are added",
            Rule::Damped => {
                "LAMMPS pair granular damping (viscoelastic, tsuji, coeff_restitution) on the scene's force law with its own contact radius, k_n = (4/3) E* a for the Tsuji form (crates/tabor-viscoadhesive/README.md)"
            }
            Rule::SuperpositionBound => {
                "Willert 2020 (5.109): the adhesive and plastic losses added, the lower bound of the adhesive interpolation rules where the adhesive interpolation model (5.111)-(5.126) dissipates less (crates/tabor-scene/README.md)"
            }
        }
    }
}

/// Why no model exists for a combination of effects.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Refusal {
    /// The effect whose parameter makes the combination impossible.
    pub effect: EffectKind,
    /// The combination and why no model exists.
    pub message: String,
}

/// The combination table: the one rule for a set of effects, or a refusal.
///
/// | adhesion | plasticity | viscoelasticity | rule |
/// |---|---|---|---|
/// | – | – | – | elastic |
/// | one effect alone | | | single (the effect's model) |
/// | JKR fixed grip | interpolation | – | adhesive interpolation (5.111)-(5.126) |
/// | JKR load-controlled, Maugis-Dugdale | interpolation | – | adhesive-plastic excess (ours) |
/// | any | Thornton, Jackson-Green, fit, or superposition requested | – | superposition (5.109) |
/// | JKR, Maugis-Dugdale | – | Kelvin-Voigt contact | viscous-adhesive (ours) |
/// | any | – | standard medium | superposition |
/// | any | any | any (plasticity and viscoelasticity) | superposition |
/// | graded | any | – or any | refused (no plastic or viscoelastic model of graded media) |
/// | – or any | – or any | two relaxation times | refused |
///
/// With a DEM damping law (`[damping]`) every set is `dem-damping` (the damped
/// force law of the other effects, simulated), except those without one force
/// law (adhesion + plasticity other than JKR fixed grip + interpolation, graded
/// targets), which are refused.
pub fn rule(set: &EffectSet) -> Result<Rule, Refusal> {
    use AdhesionKind::*;
    use PlasticityKind::*;
    use ViscoKind::*;
    if set.graded && set.plasticity.is_some() {
        return Err(Refusal {
            effect: EffectKind::Plasticity,
            message: "plasticity on a graded target: no model exists (the plastic models of Willert 2020 section 5.5 and the dimensionless FEM fit assume a homogeneous half-space)".into(),
        });
    }
    if set.graded && set.viscoelasticity.is_some() {
        return Err(Refusal {
            effect: EffectKind::Viscoelasticity,
            message: "viscoelasticity with a graded target: no model exists (the viscoelastic models of Willert 2020 section 5.4 assume homogeneous bodies)".into(),
        });
    }
    if set.viscoelasticity == Some(TwoRelaxationTimes) {
        return Err(Refusal {
            effect: EffectKind::Viscoelasticity,
            message: "two viscous bodies with different relaxation times 4η/M: the contact is a four-parameter medium that no tabor model solves; give equal relaxation times, or drop the viscosity of the body whose relaxation time is negligible against the contact time".into(),
        });
    }
    if set.damping {
        return damped_rule(set);
    }
    let n = usize::from(set.adhesion.is_some())
        + usize::from(set.plasticity.is_some())
        + usize::from(set.viscoelasticity.is_some());
    Ok(match (set.adhesion, set.plasticity, set.viscoelasticity) {
        (None, None, None) => Rule::Elastic,
        _ if n == 1 => Rule::Single,
        (Some(JkrFixedGrip), Some(Interpolation), None) if !set.superposition_requested => {
            Rule::AdhesiveInterpolation
        }
        (Some(JkrLoadControlled | MaugisDugdale), Some(Interpolation), None)
            if !set.superposition_requested =>
        {
            Rule::AdhesivePlasticExcess
        }
        (Some(JkrFixedGrip | JkrLoadControlled | MaugisDugdale), None, Some(KelvinVoigt)) => {
            Rule::ViscousAdhesive
        }
        _ => Rule::Superposition,
    })
}

/// The rule of a scene with a DEM damping law: the damped force law of its other
/// effects, when they have one (Hertz, JKR, Maugis-Dugdale, an elasto-plastic
/// law, JKR fixed grip + the interpolation model's adhesive law); else refused.
fn damped_rule(set: &EffectSet) -> Result<Rule, Refusal> {
    use AdhesionKind::*;
    if set.viscoelasticity.is_some() {
        return Err(Refusal {
            effect: EffectKind::Damping,
            message: "a DEM damping law with a viscosity: each damps the normal contact; keep one"
                .into(),
        });
    }
    if set.graded {
        return Err(Refusal {
            effect: EffectKind::Damping,
            message: "a DEM damping law on a graded target: JKR on a graded medium has no time-domain force law to damp".into(),
        });
    }
    match (set.adhesion, set.plasticity) {
        (_, None) | (None, Some(_)) => Ok(Rule::Damped),
        (Some(JkrFixedGrip), Some(PlasticityKind::Interpolation)) if !set.superposition_requested => {
            Ok(Rule::Damped)
        }
        _ => Err(Refusal {
            effect: EffectKind::Damping,
            message: "a DEM damping law with adhesion and plasticity needs one force law of both: only JKR (fixed grip) with the interpolation model has one (the adhesive interpolation model (5.111)-(5.126)); the other combinations are sums of losses".into(),
        }),
    }
}

/// The rule that produced an outcome, as reported.
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Combination {
    /// The rule.
    pub rule: Rule,
    /// The effects it combines.
    pub effects: Vec<EffectKind>,
    /// Where the rule comes from.
    pub source: &'static str,
}

impl Combination {
    /// The report of `rule` over `set`.
    pub fn of(rule: Rule, set: &EffectSet) -> Self {
        let effects = [
            EffectKind::Adhesion,
            EffectKind::Plasticity,
            EffectKind::Viscoelasticity,
            EffectKind::Damping,
        ]
        .into_iter()
        .filter(|e| set.contains(*e))
        .collect();
        Combination {
            rule,
            effects,
            source: rule.source(),
        }
    }
}

#[cfg(test)]
mod tests {
    #![allow(clippy::unwrap_used)]
    use super::*;

    #[test]
    fn rules_serialize_as_the_names_they_are_read_by() {
        // JSON gave "single" (serde's kebab-case) where the text output and FromStr
        // say "single-effect".
        for rule in Rule::ALL {
            let json = serde_json::to_string(&rule).unwrap();
            assert_eq!(json, format!("\"{}\"", rule.as_str()));
            assert_eq!(rule.as_str().parse::<Rule>().unwrap(), rule);
        }
        assert_eq!(
            serde_json::to_string(&Rule::Single).unwrap(),
            "\"single-effect\""
        );
    }
}
