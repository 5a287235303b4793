//! `slamtool completions SHELL` and `slamtool man`.

use clap::Args;
use clap_complete::Shell;

#[derive(Debug, Args)]
pub struct CompletionsArgs {
    /// Shell to generate completions for.
    shell: Shell,
}

pub fn run(args: CompletionsArgs, cmd: &mut clap::Command) -> slamtool::Result<()> {
    clap_complete::generate(args.shell, cmd, "slamtool", &mut std::io::stdout());
    Ok(())
}

pub fn man(cmd: &clap::Command) -> slamtool::Result<()> {
    clap_mangen::Man::new(cmd.clone())
        .render(&mut std::io::stdout())
        .map_err(|e| slamtool::Error::io(std::path::Path::new("<stdout>"), e))
}
