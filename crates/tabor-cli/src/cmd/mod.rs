//! One module per subcommand.

pub mod effective;
pub mod maugis_loss;
