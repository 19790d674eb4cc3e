//! One module per subcommand.

pub mod effective;
