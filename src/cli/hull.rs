//! `slamtool hull ...`

use clap::Subcommand;

#[derive(Debug, Subcommand)]
pub enum HullCommand {}

pub fn run(c: HullCommand) -> slamtool::Result<()> {
    match c {}
}
