//! The models a scene can use: their types (`types.rs`), how they are built once
//! per scene from its validated inputs (`build.rs`), and how the loss of a set of
//! effects is evaluated by the rule of the combination table (`evaluate.rs`).

mod build;
mod damped;
mod evaluate;
mod types;

pub(crate) use types::{AdhesiveModel, Evaluation, Models, Plastic};
