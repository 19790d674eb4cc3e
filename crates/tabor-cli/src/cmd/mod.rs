//! One module per subcommand.

pub mod completions;
pub mod effective;
pub mod export;
pub mod jkr;
pub mod maugis_loss;
pub mod penalty;
pub mod plastic;
pub mod scene;
pub mod sweep;
pub mod visco;
