//! `slamtool completions SHELL`.

use clap::Args;
use clap_complete::Shell;

/// Examples at the end of `slamtool completions --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool completions bash > ~/.local/share/bash-completion/completions/slamtool
  slamtool completions zsh > ~/.zfunc/_slamtool
  slamtool completions fish > ~/.config/fish/completions/slamtool.fish";

#[derive(Debug, Args)]
pub struct CompletionsArgs {
    /// Shell to generate completions for.
    shell: Shell,
}

pub fn run(args: CompletionsArgs, cmd: &mut clap::Command) -> slamtool::Result<()> {
    clap_complete::generate(args.shell, cmd, "slamtool", &mut std::io::stdout());
    Ok(())
}
