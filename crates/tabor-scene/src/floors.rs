//! The accuracy floors of a scene's paths (`tabor_numerics::tolerance`): a path
//! that computes at a floor coarser than the scene's `accuracy` says so in a
//! warning with the code `accuracy-floor`, naming the floor.

use crate::models::Plastic;
use crate::select::{Prepared, Selection};
use tabor_numerics::tolerance::{
    MICRO_SLIP_RESOLUTION, MODEL_ACCURACY_FLOOR, SIMULATION_ACCURACY_FLOOR, STICKING_ACCURACY_FLOOR,
};
use tabor_restitution::Warning;

/// The code of every floor's warning.
const ACCURACY_FLOOR: &str = "accuracy-floor";

/// The warning of `what`, computed at `floor` (the constant `name` of
/// `tabor_numerics::tolerance`) where the scene asked for `accuracy`; `None`
/// when the floor is not above the request.
fn floor_warning(accuracy: f64, floor: f64, name: &str, what: &str) -> Option<Warning> {
    (accuracy < floor).then(|| Warning {
        code: ACCURACY_FLOOR,
        message: format!(
            "{what} is computed at accuracy {floor:e} (tabor_numerics::tolerance::{name}), \
             coarser than the requested {accuracy:e}"
        ),
    })
}

/// The floors the outcome at one speed met: the viscoelastic models (built at
/// [`MODEL_ACCURACY_FLOOR`] at the finest), a simulated plastic model (its
/// per-step tolerance floored: [`SIMULATION_ACCURACY_FLOOR`]) and the
/// sticking-velocity search ([`STICKING_ACCURACY_FLOOR`]).
pub(crate) fn outcome_floors(prepared: &Prepared, selection: &Selection) -> Vec<Warning> {
    let accuracy = prepared.inputs().accuracy;
    let models = prepared.models();
    let simulated_plastic = selection.used.plasticity.is_some()
        && matches!(models.plastic, Some(Plastic::JacksonGreen(_)));
    [
        selection.used.viscoelasticity.and_then(|_| {
            floor_warning(
                accuracy,
                MODEL_ACCURACY_FLOOR,
                "MODEL_ACCURACY_FLOOR",
                "the viscoelastic model",
            )
        }),
        simulated_plastic
            .then(|| {
                floor_warning(
                    accuracy,
                    SIMULATION_ACCURACY_FLOOR,
                    "SIMULATION_ACCURACY_FLOOR",
                    "the simulated Jackson-Green impact",
                )
            })
            .flatten(),
        models.candidates.adhesion.and_then(|_| {
            floor_warning(
                accuracy,
                STICKING_ACCURACY_FLOOR,
                "STICKING_ACCURACY_FLOOR",
                "the sticking velocity",
            )
        }),
    ]
    .into_iter()
    .flatten()
    .collect()
}

/// The floors of an oblique impact ([`crate::Scene::oblique`]) finer than the
/// scene's `accuracy`: the simulation ([`SIMULATION_ACCURACY_FLOOR`], 1e-13) and,
/// with `mindlin_deresiewicz` (`micro_slip`), its spring bed
/// ([`MICRO_SLIP_RESOLUTION`], 1e-4).
pub(crate) fn oblique_floors(accuracy: f64, micro_slip: bool) -> Vec<Warning> {
    [
        floor_warning(
            accuracy,
            SIMULATION_ACCURACY_FLOOR,
            "SIMULATION_ACCURACY_FLOOR",
            "the oblique impact's simulation",
        ),
        micro_slip
            .then(|| {
                floor_warning(
                    accuracy,
                    MICRO_SLIP_RESOLUTION,
                    "MICRO_SLIP_RESOLUTION",
                    "the micro-slip of mindlin_deresiewicz (its spring bed)",
                )
            })
            .flatten(),
    ]
    .into_iter()
    .flatten()
    .collect()
}
