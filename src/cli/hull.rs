//! `slamtool hull ...`

use clap::Subcommand;

use super::hull_generate;

#[derive(Debug, Subcommand)]
pub enum HullCommand {
    /// Write one of the example/reference hulls (hulls/*.toml) from its generator.
    Generate(hull_generate::GenerateArgs),
}

pub fn run(c: HullCommand) -> slamtool::Result<()> {
    match c {
        HullCommand::Generate(a) => hull_generate::run(a),
    }
}
