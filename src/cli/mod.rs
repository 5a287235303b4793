//! clap command definitions; one file per command family.

use std::process::ExitCode;

use clap::{CommandFactory, Parser, Subcommand};

mod bench;
mod completions;
mod entry;
mod hull;
mod hull_generate;
mod hull_import;
mod hull_plot;
mod motions;
mod sea;

/// 2D+t ship-slamming design tool: strip theory, SPH water entry, analytic cross-checks, design reports.
#[derive(Debug, Parser)]
#[command(name = "slamtool", version, about, long_about = None, propagate_version = true)]
pub struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Hull definition: hydrostatics, form coefficients, sections.
    #[command(subcommand)]
    Hull(hull::HullCommand),
    /// One 2D water-entry run with SPH (wedge, hull section or case file).
    #[command(subcommand)]
    Entry(entry::EntryCommand),
    /// SPH throughput benchmark (particle-steps per second).
    Bench(bench::BenchArgs),
    /// Sea states: regular waves, spectra, speeds.
    #[command(subcommand)]
    Sea(sea::SeaCommand),
    /// Strip-theory motions, relative motion at the bow, slam statistics and operability.
    Motions(motions::MotionsArgs),
    /// Print a shell completion script.
    Completions(completions::CompletionsArgs),
    /// Print the manual page (roff) on stdout.
    Man,
}

pub fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Hull(c) => hull::run(c),
        Command::Entry(c) => entry::run(c),
        Command::Bench(a) => bench::run(a),
        Command::Sea(c) => sea::run(c),
        Command::Motions(a) => motions::run(a),
        Command::Completions(a) => completions::run(a, &mut Cli::command()),
        Command::Man => completions::man(&Cli::command()),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::FAILURE
        }
    }
}
