//! Options every command takes (`-q/--quiet`, `--color`), the `--json` switch of the commands that produce
//! results, and the few ways a command talks to the user besides its results: notes, warnings, errors and
//! "files written to ...". New commands flatten [`JsonArg`] and use these functions, so that all commands
//! behave alike.

use std::io::IsTerminal;
use std::path::Path;
use std::sync::OnceLock;

use clap::{Args, ValueEnum};
use slamtool::sph::TankLayout;
use slamtool::sph::air::AirChoice;

/// Largest `-j N` accepted (threads or parallel runs): more than any machine slamtool runs on has cores,
/// and few enough that a typing slip (`-j 100000`) cannot start a hundred thousand threads. 0 is refused:
/// leave `-j` out for one per core.
pub const MAX_THREADS: i64 = 256;

/// When to colour the output.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, ValueEnum)]
pub enum ColorWhen {
    /// Colour when writing to a terminal and NO_COLOR is not set.
    #[default]
    Auto,
    /// Always colour.
    Always,
    /// Never colour.
    Never,
}

/// Options accepted by every command, before or after the subcommand.
#[derive(Debug, Clone, Args)]
pub struct GlobalArgs {
    /// No progress bars or notes on stderr; results and errors are still printed, and warnings too
    /// except with --json, whose output carries them.
    #[arg(short, long, global = true, help_heading = "Global options")]
    pub quiet: bool,
    /// Colour the help, warnings and errors.
    #[arg(
        long,
        value_enum,
        global = true,
        default_value_t = ColorWhen::Auto,
        value_name = "WHEN",
        help_heading = "Global options"
    )]
    pub color: ColorWhen,
}

/// `--json` for the commands that produce results.
#[derive(Debug, Clone, Args)]
pub struct JsonArg {
    /// Print the results as one JSON object on stdout instead of tables (schema in docs/guide/conventions.md).
    #[arg(long)]
    pub json: bool,
}

#[derive(Debug, Clone, Copy)]
struct Ui {
    quiet: bool,
    color_stderr: bool,
    color_stdout: bool,
}

static UI: OnceLock<Ui> = OnceLock::new();

/// Whether `--color WHEN` colours a stream that is (or is not) a terminal.
pub fn colours(when: ColorWhen, is_terminal: bool) -> bool {
    match when {
        ColorWhen::Always => true,
        ColorWhen::Never => false,
        ColorWhen::Auto => is_terminal && std::env::var_os("NO_COLOR").is_none_or(|v| v.is_empty()),
    }
}

/// Record the global options; call once, before any output.
pub fn init(g: &GlobalArgs) {
    let _ = UI.set(Ui {
        quiet: g.quiet,
        color_stderr: colours(g.color, std::io::stderr().is_terminal()),
        color_stdout: colours(g.color, std::io::stdout().is_terminal()),
    });
}

fn ui() -> Ui {
    *UI.get().unwrap_or(&Ui {
        quiet: false,
        color_stderr: false,
        color_stdout: false,
    })
}

/// Whether `-q` was given.
pub fn quiet() -> bool {
    ui().quiet
}

/// Whether progress bars may be drawn: stderr is a terminal and `-q` was not given.
pub fn progress_visible() -> bool {
    !quiet() && std::io::stderr().is_terminal()
}

fn paint(on: bool, code: &str, text: &str) -> String {
    if on {
        format!("\x1b[{code}m{text}\x1b[0m")
    } else {
        text.to_string()
    }
}

/// A note on stderr (what is being run, with which settings); suppressed by `-q`.
pub fn note(msg: &str) {
    if !quiet() {
        eprintln!("{}", terminal_safe(msg));
    }
}

/// `msg` with its control characters escaped (line breaks and tabs kept), so that a name read from a
/// file never reaches the terminal as a raw escape sequence.
pub fn terminal_safe(msg: &str) -> String {
    if !msg
        .chars()
        .any(|c| c.is_control() && c != '\n' && c != '\t')
    {
        return msg.to_string();
    }
    msg.split('\n')
        .map(|line| {
            line.split('\t')
                .map(slamtool::output_policy::escape_control)
                .collect::<Vec<_>>()
                .join("\t")
        })
        .collect::<Vec<_>>()
        .join("\n")
}

/// A warning on stderr, for output modes where stdout carries JSON (the JSON holds the warnings too);
/// silent with `-q`.
pub fn warn_stderr(msg: &str) {
    if quiet() {
        return;
    }
    eprintln!(
        "{} {}",
        paint(ui().color_stderr, "1;33", "warning:"),
        terminal_safe(msg)
    );
}

/// A warning line in a text report on stdout.
pub fn warning_line(msg: &str) -> String {
    format!(
        "{} {}",
        paint(ui().color_stdout, "1;33", "warning:"),
        terminal_safe(msg)
    )
}

/// An error on stderr.
pub fn error(msg: &str) {
    eprintln!(
        "{} {}",
        paint(ui().color_stderr, "1;31", "error:"),
        terminal_safe(msg)
    );
}

/// Print a `--json` result on stdout: pretty-printed, numbers rounded to 10 significant digits (no
/// `5.499999999999962` for 5.5).
pub fn print_json(value: serde_json::Value) {
    let tidy = slamtool::provenance::tidy_numbers(value);
    println!(
        "{}",
        serde_json::to_string_pretty(&tidy).expect("a JSON value serialises")
    );
}

/// The line every text report ends with when it wrote files.
pub fn files_written_line(dir: &Path) -> String {
    format!("files written to {}", dir.display())
}

/// The SPH numerics options that `entry wedge`, `entry section` and `assess` share.
#[derive(Debug, Args)]
pub struct SphOptions {
    /// Particle layout of the automatic tank: `refined` has the spacing in a band around the body
    /// (1.5 half-breadths beside it and under the keel's deepest position) and twice the spacing
    /// beyond, for about a third of the particles; `uniform` has one spacing throughout
    /// [default: refined; uniform with numerics a refined tank does not support].
    #[arg(long, value_enum, value_name = "LAYOUT")]
    pub tank: Option<TankLayout>,
    /// The spelling of the previous release for `--tank refined`.
    #[arg(long, hide = true, conflicts_with = "tank")]
    pub refined_tank: bool,
    /// Kernel-gradient-corrected velocity divergence in the continuity equation (Bonet & Lok 1999):
    /// removes the spurious compression of free-surface particles ahead of the jet root and the void it
    /// traps there. Part of the default scheme of single-phase runs (with `--shifting` and
    /// `--wall-wetness`); `--divergence-correction=false` turns it off. Read the sensors as force panels
    /// with it (the default `--sensor-method`: the interpolated wall pressure reads the root peak low).
    #[arg(long, value_name = "BOOL", num_args = 0..=1, require_equals = true, default_missing_value = "true")]
    pub divergence_correction: Option<bool>,
    /// Particle shifting with free-surface treatment (the shifting of delta+-SPH, Sun et al. 2017), in the
    /// uniform or the refined tank. Part of the default scheme of single-phase runs; `--shifting=false`
    /// turns it off. With the corrected divergence, the wall's wetness and force-panel sensors, the sensor
    /// peaks of the 20, 30 and 45 deg wedges fall toward the similarity solution with refinement
    /// (docs/numerics/wedge-convergence.md, items 29 and 33).
    #[arg(long, value_name = "BOOL", num_args = 0..=1, require_equals = true, default_missing_value = "true")]
    pub shifting: Option<bool>,
    /// Body dummies weighted by the wetness of the body's face: a dummy beside a spray root that water has
    /// only begun to reach counts only as far as the water fills the space outside the wall there. Part of
    /// the default scheme of single-phase runs; `--wall-wetness=false` turns it off. With it every sensor of
    /// the 20, 30 and 45 deg wedges reads within 10 % of the exact solution at 80 particles per half-beam,
    /// and the section force 4-5 % low (docs/numerics/wedge-convergence.md, item 29). A run with air takes
    /// none of the three.
    #[arg(long, value_name = "BOOL", num_args = 0..=1, require_equals = true, default_missing_value = "true")]
    pub wall_wetness: Option<bool>,
    /// Air as a second phase (two-phase SPH, for the air cushion of flat and low-deadrise sections):
    /// off, on, or auto (on where the deadrise within the expected wetted half-width is below 15 deg;
    /// docs/guide/air.md).
    #[arg(long, value_enum, default_value = "off")]
    pub air: AirChoice,
}

impl SphOptions {
    /// The `refinement` override from `--tank` (or the hidden `--refined-tank` of the previous
    /// release): None leaves the library's default.
    pub fn refinement(&self) -> Option<bool> {
        self.tank
            .map(|t| t == TankLayout::Refined)
            .or(self.refined_tank.then_some(true))
    }

    /// The `divergence_correction` override: None (the library's default) unless the flag is given.
    pub fn divergence_correction(&self) -> Option<bool> {
        self.divergence_correction
    }

    /// The `shifting` override: None (the library's default) unless the flag is given.
    pub fn shifting(&self) -> Option<bool> {
        self.shifting
    }

    /// The `wall_wetness` override: None (the library's default) unless the flag is given.
    pub fn wall_wetness(&self) -> Option<bool> {
        self.wall_wetness
    }
}
