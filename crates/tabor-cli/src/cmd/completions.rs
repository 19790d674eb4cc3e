//! `tabor completions <shell>`: a shell completion script on stdout (clap_complete).

use crate::output::{stdout, Outcome};
use clap_complete::Shell;
use std::io::Write;

/// Arguments of `tabor completions`.
#[derive(clap::Args)]
#[command(
    after_help = "Examples:\n  tabor completions bash > ~/.local/share/bash-completion/completions/tabor\n  \
    tabor completions zsh > ~/.zfunc/_tabor\n  tabor completions fish > ~/.config/fish/completions/tabor.fish"
)]
pub struct Args {
    /// The shell
    #[arg(value_enum)]
    shell: Shell,
}

/// Runs `tabor completions`.
pub fn run(args: &Args, command: &mut clap::Command) -> Outcome {
    // clap_complete panics on a failed write: generate into memory, then write.
    let mut script = Vec::new();
    clap_complete::generate(args.shell, command, "tabor", &mut script);
    let mut out = stdout();
    out.write_all(&script)?;
    out.finish()
}
