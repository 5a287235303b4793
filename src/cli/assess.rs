//! `slamtool assess HULL --sea SEA`: the 2D+t assessment (Veen 2010, ch. 6). The work is
//! `slamtool::assess`; this file parses the arguments, prints the tables and applies the limit gate.

use std::path::{Path, PathBuf};

use clap::Args;
use slamtool::assess::{self, Fidelity, Settings};
use slamtool::hull::Hull;
use slamtool::sea::SeaState;
use slamtool::sph::{Level, Overrides, SensorMethod, StudyPlan};
use slamtool::{Error, Result};

use super::global::{self, JsonArg, SphOptions};
use super::progress_bar;
use super::station;

/// Examples at the end of `slamtool assess --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool assess hulls/ochi-vform.toml --sea sea_states/ochi-1958.toml
  slamtool assess hulls/ochi-vform.toml --sea sea_states/ochi-1958.toml --fidelity analytic
  slamtool assess hulls/ochi-vform.toml --sea sea_states/ochi-1958.toml --station 0.093,0.133 \\
      --speeds 2.0,2.4 --max-pressure-kpa 20 -o reports/ochi-gate
  slamtool assess hulls/car-carrier-hm2005.toml --sea sea_states/car-carrier-hm2005.toml --fidelity analytic \\
      --forcing 0.05=data/forcing/hermundstad2005-flare-reconstructed.csv";

#[derive(Debug, Args)]
pub struct AssessArgs {
    /// Hull file (hull.toml), with the sensors of each station.
    hull: PathBuf,
    /// Sea-state file (sea_state.toml): regular waves, spectra, speeds.
    #[arg(long)]
    sea: PathBuf,
    /// Loading condition (default: the first in the hull file).
    #[arg(long)]
    loading: Option<String>,
    /// Stations as fractions of Lpp aft of the FP, comma-separated [default: the hull's sensor stations].
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "F",
        allow_negative_numbers = true
    )]
    station: Vec<f64>,
    /// Stations as x in m from midship (positive forward), comma-separated (with or instead of --station).
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "X",
        allow_negative_numbers = true
    )]
    x_m: Vec<f64>,
    /// Speeds in m/s, comma-separated (replaces the sea file's speeds).
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "U",
        allow_negative_numbers = true
    )]
    speeds: Vec<f64>,
    /// A measured or externally computed relative-motion record of a station, STATION=FILE.csv (station
    /// as a fraction of Lpp aft of the FP; repeatable): that station is driven by the record instead of
    /// strip theory (docs/guide/measured-forcing.md). Needs a single speed (the record's).
    #[arg(long, value_name = "STATION=FILE.csv")]
    forcing: Vec<String>,
    /// screen: analytic everywhere, then SPH for the governing event of each station (highest analytic
    /// sensor pressure); sph: SPH for every event, with the analytic estimate and a convergence statement
    /// beside each peak; analytic: corrected MLM force and pressures for every event (seconds).
    #[arg(long, value_enum, default_value = "screen")]
    fidelity: Fidelity,
    /// Resolution of the SPH runs.
    #[arg(long, value_enum, default_value = "coarse")]
    resolution: Level,
    /// Particles across the largest half-breadth (overrides --resolution; for quick checks).
    #[arg(long, value_name = "N")]
    particles_per_half_beam: Option<f64>,
    #[command(flatten)]
    sph: SphOptions,
    /// How the SPH sensor pressures are computed [default: force-panel, the design method and the
    /// method of the default scheme].
    #[arg(long, value_enum)]
    sensor_method: Option<SensorMethod>,
    /// Resolutions per SPH run including the reported one (1 = no convergence statement, 2 or 3).
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u8).range(1..=3))]
    convergence_levels: u8,
    /// Parallel SPH runs, 1 to 256 [default: one per core].
    #[arg(
        short = 'j',
        long,
        value_name = "N",
        value_parser = clap::value_parser!(u16).range(1..=global::MAX_THREADS)
    )]
    threads: Option<u16>,
    /// Design events of irregular seas at risk level alpha: the entry velocity the largest of the N slams
    /// of the exposure exceeds with probability alpha [default: the most probable largest in N slams].
    #[arg(long, value_name = "ALPHA")]
    risk_level: Option<f64>,
    /// Add the keel-slope term U dz_k/dx to the keel-entry velocities: the sinking of a section whose keel
    /// rises towards the bow through the earth-fixed plane of the 2D+t method (off by default, as in Veen
    /// 2010; without it a warning names the stations where it is 5 % or more of an entry velocity).
    #[arg(long)]
    keel_slope_term: bool,
    /// Design gate: every sensor design pressure above this (kPa) is a violation (exit status 4).
    #[arg(long, value_name = "P")]
    max_pressure_kpa: Option<f64>,
    /// Run every SPH case again instead of reusing finished runs from OUT/cache (the new runs replace
    /// the cached ones).
    #[arg(long)]
    no_cache: bool,
    /// Remove the runs in OUT/cache that this assessment did not use (other stations, speeds, numerics or
    /// tool versions). Without it they are kept, and a note gives their number and size.
    #[arg(long)]
    prune_cache: bool,
    /// Write into an output folder that holds files of something other than an assessment, and run an
    /// assessment whose SPH runs are estimated to take more than an hour.
    #[arg(long)]
    force: bool,
    /// Do not write the report (report.pdf, figures/) at the end; `slamtool report OUT` writes it later.
    #[arg(long)]
    no_report: bool,
    /// Print today's date under the report's title (without it the PDF has no date).
    #[arg(long)]
    stamp: bool,
    #[command(flatten)]
    json: JsonArg,
    /// Output folder [default: reports/<hull file name without .toml>/].
    #[arg(short, long, value_name = "DIR", alias = "output")]
    out: Option<PathBuf>,
}

/// The default output folder: `reports/<hull file stem>/` (`hulls/ochi-vform.toml` -> `reports/ochi-vform`).
pub fn default_out(hull_file: &Path) -> PathBuf {
    let stem = hull_file
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .filter(|s| !s.is_empty())
        .unwrap_or_else(|| "hull".into());
    Path::new("reports").join(stem)
}

/// Refuse a folder that holds other things than an earlier assessment, unless --force (the rule of
/// every command, [`slamtool::output_policy::check_out_folder`]).
fn check_out(dir: &Path, force: bool) -> Result<()> {
    let known = [
        "summary.json",
        "pressures.csv",
        "bow_force.csv",
        "cache",
        "motions.json",
        "report.pdf",
        "figures",
        slamtool::report::assessment::TIMING_FILE,
    ];
    slamtool::output_policy::check_out_folder(dir, &|n| known.contains(&n), "an assessment", force)
}

/// Largest `--particles-per-half-beam` accepted: four times the fine resolution (160).
const MAX_PARTICLES_PER_HALF_BEAM: f64 = 640.0;

/// Largest Froude number accepted in `--speeds` (the bound of `motions --fn` and of a sea file's
/// `froude_numbers`): strip theory means nothing far beyond it.
const MAX_FROUDE: f64 = 1.0;

/// Speeds (`--speeds`, or the sea file's, named by `what`) checked before anything is computed: finite,
/// not negative, Froude number at most [`MAX_FROUDE`] for this hull; the message gives the accepted range
/// in m/s.
fn check_speeds(speeds: &[f64], lpp: f64, what: &str) -> Result<()> {
    let vmax = MAX_FROUDE * (slamtool::sea::waves::G * lpp).sqrt();
    for &u in speeds {
        if !(u.is_finite() && (0.0..=vmax).contains(&u)) {
            return Err(Error::Invalid(format!(
                "{what}: {u} m/s is outside the accepted range 0 to {vmax:.2} m/s for this hull (Froude \
                 number at most {MAX_FROUDE} with Lpp = {lpp} m); speeds are in m/s"
            )));
        }
    }
    Ok(())
}

pub fn run(a: AssessArgs) -> Result<()> {
    let hull = Hull::from_file(&a.hull)?;
    let sea = SeaState::from_file(&a.sea)?;
    if let Some(n) = a.particles_per_half_beam
        && !(n.is_finite() && (4.0..=MAX_PARTICLES_PER_HALF_BEAM).contains(&n))
    {
        return Err(Error::Invalid(format!(
            "--particles-per-half-beam must lie between 4 and {MAX_PARTICLES_PER_HALF_BEAM} (--resolution \
             fine is 160), got {n}"
        )));
    }
    if a.speeds.is_empty() {
        let from = format!("the speeds of {}", a.sea.display());
        check_speeds(&sea.speeds.resolve(hull.lpp), hull.lpp, &from)?;
    } else {
        check_speeds(&a.speeds, hull.lpp, "--speeds")?;
    }
    if let Some(p) = a.max_pressure_kpa
        && !(p.is_finite() && p > 0.0)
    {
        return Err(Error::Invalid(format!(
            "--max-pressure-kpa must be a positive number, got {p}"
        )));
    }
    let out = a.out.clone().unwrap_or_else(|| default_out(&a.hull));
    check_out(&out, a.force)?;
    if let Some(r) = a.risk_level
        && !(r.is_finite() && r > 0.0 && r < 1.0)
    {
        return Err(Error::Invalid(format!(
            "--risk-level must be a probability between 0 and 1 (exclusive), got {r}"
        )));
    }
    let (stations, station_warnings) = station::resolve_list(&hull, &a.station, &a.x_m)?;
    let mut limits = assess::limits::of_hull(&hull)?;
    if let Some(p) = a.max_pressure_kpa {
        limits.push(assess::limits::Limit {
            scope: assess::limits::Scope::All,
            pressure_pa: p * 1e3,
            origin: "--max-pressure-kpa".into(),
        });
    }
    let forcing = a
        .forcing
        .iter()
        .map(|t| assess::measured::StationRecord::parse(t))
        .collect::<Result<Vec<_>>>()?;
    let settings = Settings {
        forcing,
        loading: a.loading.clone(),
        stations,
        speeds: (!a.speeds.is_empty()).then(|| a.speeds.clone()),
        fidelity: a.fidelity,
        overrides: Overrides {
            level: Some(a.resolution),
            particles_per_half_beam: a.particles_per_half_beam,
            refinement: a.sph.refinement(),
            divergence_correction: a.sph.divergence_correction(),
            shifting: a.sph.shifting(),
            wall_wetness: a.sph.wall_wetness(),
            air: Some(a.sph.air),
            sensor_method: a.sensor_method,
            ..Default::default()
        },
        study: StudyPlan {
            levels: a.convergence_levels as usize,
            ..StudyPlan::default()
        },
        use_cache: !a.no_cache,
        unused_cache: if a.prune_cache {
            assess::cache::Unused::Prune
        } else {
            assess::cache::Unused::Report
        },
        warnings: station_warnings,
        limits,
        design_basis: a
            .risk_level
            .map_or(assess::design_event::Basis::MostProbableLargest, |r| {
                assess::design_event::Basis::RiskLevel(r)
            }),
        threads: a.threads.map(usize::from),
        keel_slope_term: a.keel_slope_term,
        max_wall_s: (!a.force).then_some(slamtool::sph::cost::MAX_WALL_S),
        ..Settings::default()
    };
    let (result, _written) = assess::run(&hull, &sea, &settings, &out, &progress_bar::handle())?;
    let report = if a.no_report {
        None
    } else {
        Some(super::report::write_report(&out, &out, a.stamp)?)
    };
    let violations = result.limit_violations.clone();
    if a.json.json {
        for w in &result.warnings {
            global::warn_stderr(w);
        }
        let mut v =
            serde_json::to_value(&result).map_err(|e| Error::Invalid(format!("summary: {e}")))?;
        v["outputs"] = serde_json::json!({ "folder": out.display().to_string() });
        v["report_time_s"] = serde_json::json!(report.as_ref().map(|g| g.time_s));
        global::print_json(v);
    } else {
        print!("{}", super::assess_tables::tables(&result));
        for w in &result.warnings {
            println!("{}", global::warning_line(w));
        }
        if let Some(g) = &report {
            println!(
                "\nreport written in {:.2} s: {}",
                g.time_s,
                out.join("report.pdf").display()
            );
        }
        println!("\n{}", global::files_written_line(&out));
    }
    for v in &violations {
        println!("{v}");
    }
    if !violations.is_empty() {
        return Err(Error::DesignLimit(format!(
            "{} design pressure limit violation(s) (listed above and in summary.json)",
            violations.len()
        )));
    }
    if result.failed_runs > 0 {
        return Err(Error::Numerical(format!(
            "{} of the assessment's runs failed (their reasons are in summary.json and above); the others \
             finished",
            result.failed_runs
        )));
    }
    Ok(())
}
