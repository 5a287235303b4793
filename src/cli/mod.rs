//! clap command definitions; one file per command family, plus the pieces every command shares:
//! [`global`] (quiet, colour, `--json`, notes and warnings), [`exit`] (exit statuses), [`progress_bar`]
//! (progress bars) and [`station`] (how a station is given).

use std::process::ExitCode;

use clap::{CommandFactory, FromArgMatches, Parser, Subcommand};

mod assess;
mod assess_tables;
mod bench;
mod completions;
mod diff;
mod entry;
pub mod exit;
pub mod global;
mod hull;
mod hull_generate;
mod hull_import;
mod hull_plot;
mod man;
mod motions;
pub mod progress_bar;
mod report;
mod sea;
mod similarity;
pub mod station;
mod sweep;
mod validate;

/// Examples at the end of `slamtool --help`, followed there by the exit statuses.
const TOP_EXAMPLES: &str = "\
Examples:
  slamtool hull info hulls/ochi-vform.toml --loading test-condition
  slamtool motions hulls/ochi-vform.toml --sea sea_states/ochi-1958.toml -o reports/ochi-motions
  slamtool assess hulls/ochi-vform.toml --sea sea_states/ochi-1958.toml
  slamtool entry wedge --deadrise-deg 30 --speed 5 -o out/wedge30";

/// 2D+t ship-slamming design tool: strip theory, SPH water entry, analytic cross-checks, design reports.
#[derive(Debug, Parser)]
#[command(
    name = "slamtool",
    version,
    about,
    long_about = None,
    propagate_version = true
)]
pub struct Cli {
    #[command(flatten)]
    global: global::GlobalArgs,
    #[command(subcommand)]
    command: Command,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Hull definition: hydrostatics, form coefficients, sections.
    #[command(subcommand, after_long_help = hull::EXAMPLES)]
    Hull(hull::HullCommand),
    /// One 2D water-entry run with SPH (wedge, hull section or case file).
    #[command(subcommand, after_long_help = entry::EXAMPLES)]
    Entry(entry::EntryCommand),
    /// SPH throughput benchmark (particle-steps per second).
    #[command(after_long_help = bench::EXAMPLES)]
    Bench(bench::BenchArgs),
    /// Sea states: regular waves, spectra, speeds.
    #[command(subcommand, after_long_help = sea::EXAMPLES)]
    Sea(sea::SeaCommand),
    /// Nonlinear similarity solution of constant-speed wedge entry (Cp, peak, spray root, force).
    #[command(after_long_help = similarity::EXAMPLES)]
    Similarity(similarity::SimilarityArgs),
    /// The 2D+t assessment: strip theory, water entry of every slamming station, design pressures.
    #[command(after_long_help = assess::EXAMPLES)]
    Assess(assess::AssessArgs),
    /// Strip-theory motions, relative motion at the bow, slam statistics and operability.
    #[command(after_long_help = motions::EXAMPLES)]
    Motions(motions::MotionsArgs),
    /// The validation suite against published data, with its report.
    #[command(after_long_help = validate::EXAMPLES)]
    Validate(validate::ValidateArgs),
    /// The assessment report (PDF, SVG figures with CSV twins) from the saved results of `assess`.
    #[command(after_long_help = report::EXAMPLES)]
    Report(report::ReportArgs),
    /// Design-space sweeps: many hull and operating variants, in parallel, resumable, sharded.
    #[command(after_long_help = sweep::EXAMPLES)]
    Sweep(sweep::SweepArgs),
    /// Join the results of a sweep's shards.
    #[command(after_long_help = sweep::MERGE_EXAMPLES)]
    Merge(sweep::MergeArgs),
    /// What moved between two assessments (their summary.json): design values, forces, verdicts.
    #[command(after_long_help = diff::EXAMPLES)]
    Diff(diff::DiffArgs),
    /// Print a shell completion script.
    #[command(after_long_help = completions::EXAMPLES)]
    Completions(completions::CompletionsArgs),
    /// Manual pages: the top page on stdout, or one page per command into a folder.
    #[command(after_long_help = man::EXAMPLES)]
    Man(man::ManArgs),
}

/// The `--color` value given on the command line, read before parsing so that clap's own help and usage
/// errors follow it too.
fn color_choice() -> clap::ColorChoice {
    let args: Vec<String> = std::env::args().collect();
    let mut value = None;
    for (i, a) in args.iter().enumerate() {
        if a == "--" {
            break;
        }
        if let Some(v) = a.strip_prefix("--color=") {
            value = Some(v.to_string());
        } else if a == "--color" {
            value = args.get(i + 1).cloned();
        }
    }
    match value.as_deref() {
        Some("always") => clap::ColorChoice::Always,
        Some("never") => clap::ColorChoice::Never,
        _ => clap::ColorChoice::Auto,
    }
}

/// The command tree, with the examples and exit statuses at the end of the top-level help.
pub fn command() -> clap::Command {
    negative_numbers(Cli::command()).after_long_help(format!("{TOP_EXAMPLES}\n\n{}", exit::TABLE))
}

/// Every option that takes a value, in every command, takes a negative number after a space as its
/// value (`--risk-level -0.1`, `--x-m -2.4`), so that the range check of the option answers instead of
/// the parser's "unexpected argument '-0'". No option or flag of slamtool is spelt as a number, so
/// nothing else changes.
fn negative_numbers(cmd: clap::Command) -> clap::Command {
    cmd.mut_args(|a| {
        if a.get_action().takes_values() {
            a.allow_negative_numbers(true)
        } else {
            a
        }
    })
    .mut_subcommands(negative_numbers)
}

pub fn main() -> ExitCode {
    let parsed = command()
        .color(color_choice())
        .try_get_matches()
        .and_then(|m| Cli::from_arg_matches(&m));
    let cli = match parsed {
        Ok(c) => c,
        // --help and --version come here too: they print on stdout and succeed.
        Err(e) => {
            let _ = e.print();
            return ExitCode::from(if e.use_stderr() {
                exit::USAGE
            } else {
                exit::OK
            });
        }
    };
    global::init(&cli.global);
    let result = match cli.command {
        Command::Hull(c) => hull::run(c),
        Command::Entry(c) => entry::run(c),
        Command::Bench(a) => bench::run(a),
        Command::Sea(c) => sea::run(c),
        Command::Similarity(a) => similarity::run(a),
        Command::Assess(a) => assess::run(a),
        Command::Motions(a) => motions::run(a),
        Command::Validate(a) => validate::run(a),
        Command::Report(a) => report::run(a),
        Command::Sweep(a) => sweep::run(a),
        Command::Merge(a) => sweep::run_merge(a),
        Command::Diff(a) => diff::run(a),
        Command::Completions(a) => completions::run(a, &mut command()),
        Command::Man(a) => man::run(a, command()),
    };
    match result {
        Ok(()) => ExitCode::from(exit::OK),
        Err(e) => {
            global::error(&e.to_string());
            ExitCode::from(exit::code(&e))
        }
    }
}
