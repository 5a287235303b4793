//! `slamtool motions HULL --sea SEA`: strip-theory motions, relative motion at the bow stations, slam
//! statistics and the operability limit. Tables on stdout (or JSON with --json); plot data to CSV in -o DIR.
//! The analysis is `seakeeping::analysis`, the tables and CSV files are `report`: this file only parses the
//! arguments and builds the request.

use std::path::PathBuf;

use clap::Args;
use slamtool::hull::{Hull, Hydrostatics};
use slamtool::impact;
use slamtool::provenance::{Provenance, TOOL};
use slamtool::report::{self, sanity};
use slamtool::sea::SeaState;
use slamtool::seakeeping::ShipModel;
use slamtool::seakeeping::analysis::{self, Request};
use slamtool::seakeeping::section::SectionMethod;
use slamtool::seakeeping::slamming::DEFAULT_SLAM_PROBABILITY_LIMIT;
use slamtool::{Error, Result};

use super::global::{self, JsonArg};
use super::station;

/// Examples at the end of `slamtool motions --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool motions hulls/ochi-vform.toml --sea sea_states/ochi-1958.toml -o reports/ochi-motions
  slamtool motions hulls/ochi-vform.toml --sea sea_states/ochi-1958.toml --loading max-draft
  slamtool motions hulls/wigley-iii.toml --sea sea.toml --fn 0.2,0.3 --station 0.05,0.1 --json";

#[derive(Debug, Clone, Copy, clap::ValueEnum)]
enum Method {
    /// Frank (1967) close-fit pulsating sources.
    CloseFit,
    /// Lewis conformal mapping with Ursell-Tasai multipoles.
    Lewis,
}

#[derive(Debug, Args)]
pub struct MotionsArgs {
    /// Hull file (hull.toml).
    hull: PathBuf,
    /// Sea-state file (sea_state.toml): regular waves, spectra, speeds.
    #[arg(long)]
    sea: PathBuf,
    /// Loading condition (default: the first in the hull file).
    #[arg(long)]
    loading: Option<String>,
    /// Speeds as Froude numbers, comma-separated (replaces the sea file's speeds).
    #[arg(long = "fn", value_delimiter = ',', conflicts_with = "speed")]
    froude: Vec<f64>,
    /// Speeds in m/s, comma-separated (replaces the sea file's speeds).
    #[arg(long, value_delimiter = ',', value_name = "U")]
    speed: Vec<f64>,
    /// Wavelength ratios lambda/Lpp for the RAO table, comma-separated.
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "0.5,0.75,1.0,1.25,1.5,1.75,2.0,2.5,3.0"
    )]
    lambda_over_l: Vec<f64>,
    /// Bow stations as fractions of Lpp aft of the FP, comma-separated [default: the hull's sensor
    /// stations, or 0.05,0.1,0.15,0.2].
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "F",
        alias = "at",
        conflicts_with = "x_m",
        allow_negative_numbers = true
    )]
    station: Vec<f64>,
    /// Bow stations as x in m from midship (positive forward), comma-separated.
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "X",
        allow_negative_numbers = true
    )]
    x_m: Vec<f64>,
    /// Sectional hydrodynamics.
    #[arg(long, value_enum, default_value = "close-fit")]
    method: Method,
    /// Number of strips (sections) along the hull for strip theory.
    #[arg(long, default_value_t = 31, alias = "stations", value_name = "N")]
    strips: usize,
    /// Dynamic swell-up factor on relative motion and velocity (1 = none), a constant: no dynamic
    /// swell-up formulation (e.g. Tasaki 1963) is in the project.
    #[arg(long, default_value_t = 1.0)]
    swell_up: f64,
    /// Add the keel-slope term U dz_k/dx to the keel-entry velocities: the sinking, in an earth-fixed
    /// transverse plane, of a keel that is not parallel to the calm waterline (keel rise or trim).
    #[arg(long)]
    keel_slope_term: bool,
    /// Instead of the motion tables, print (Markdown) the keel-entry velocity at each station and speed in
    /// the first regular wave under each alternative definition of the chain (wave, drafts, heave of G,
    /// velocity definition, k_yy, swell-up, keel slope), with Veen's (2010) values where the hull and sea
    /// are his Ochi case.
    #[arg(long)]
    entry_definitions: bool,
    /// Operability limit on the slam probability per encounter.
    #[arg(long, default_value_t = DEFAULT_SLAM_PROBABILITY_LIMIT)]
    slam_limit: f64,
    /// Frequencies sampled per wave spectrum for the slam statistics.
    #[arg(long, default_value_t = 30)]
    spectrum_samples: usize,
    /// Sectional solutions are interpolated from a table with this spacing in ln(frequency) (0: solve
    /// every encounter frequency directly). At 0.1 the RAOs differ from direct solves by about 1e-4.
    #[arg(long, default_value_t = 0.1)]
    frequency_spacing: f64,
    #[command(flatten)]
    json: JsonArg,
    /// Write CSV plot data (RAOs, relative motion, entry profiles, response spectra, slam statistics,
    /// operability) into this folder [default: no files, tables only].
    #[arg(short, long, value_name = "DIR", alias = "output")]
    out: Option<PathBuf>,
}

/// Largest `--swell-up` accepted: measured dynamic swell-up factors lie between 1 and about 1.5.
const MAX_SWELL_UP: f64 = 3.0;
/// Largest `--strips` accepted (strip theory converges with a few dozen).
const MAX_STRIPS: usize = 1000;
/// Largest `--spectrum-samples` accepted.
const MAX_SPECTRUM_SAMPLES: usize = 100_000;

fn bad(what: &str, requirement: &str, v: f64) -> Error {
    Error::Invalid(format!("{what} must be {requirement}, got {v}"))
}

pub fn run(a: MotionsArgs) -> Result<()> {
    let hull = Hull::from_file(&a.hull)?;
    let sea = SeaState::from_file(&a.sea)?;
    let loading = hull.loading(a.loading.as_deref())?;
    // Fn 0 (zero speed) is a valid request; a wavelength must be positive.
    for &v in &a.froude {
        if !(v.is_finite() && (0.0..=1.0).contains(&v)) {
            return Err(bad("--fn values", "between 0 and 1", v));
        }
    }
    for &v in &a.lambda_over_l {
        if !(v.is_finite() && v > 0.0) {
            return Err(bad("--lambda-over-l values", "positive finite numbers", v));
        }
    }
    if !(a.swell_up.is_finite() && (1.0..=MAX_SWELL_UP).contains(&a.swell_up)) {
        return Err(bad(
            "--swell-up",
            &format!("between 1 (no swell-up) and {MAX_SWELL_UP}"),
            a.swell_up,
        ));
    }
    if !(a.slam_limit.is_finite() && a.slam_limit > 0.0 && a.slam_limit < 1.0) {
        return Err(bad(
            "--slam-limit",
            "a probability between 0 and 1 (exclusive)",
            a.slam_limit,
        ));
    }
    if !(3..=MAX_STRIPS).contains(&a.strips) {
        return Err(bad(
            "--strips",
            &format!("between 3 and {MAX_STRIPS}"),
            a.strips as f64,
        ));
    }
    if a.spectrum_samples > MAX_SPECTRUM_SAMPLES {
        return Err(bad(
            "--spectrum-samples",
            &format!("at most {MAX_SPECTRUM_SAMPLES}"),
            a.spectrum_samples as f64,
        ));
    }
    // The output folder is checked before the computation, not after it.
    if let Some(dir) = &a.out {
        slamtool::output_policy::check_out_folder(dir, &|_| true, "motions", false)?;
    }
    if !(a.frequency_spacing.is_finite() && (0.0..=0.5).contains(&a.frequency_spacing)) {
        return Err(bad(
            "--frequency-spacing",
            "between 0 (direct solves) and 0.5",
            a.frequency_spacing,
        ));
    }
    let model = ShipModel::from_hull(&hull, loading, a.strips)?;
    for &v in &a.speed {
        if !(v.is_finite() && v >= 0.0) {
            return Err(bad("--speed values", "finite and >= 0 m/s", v));
        }
    }
    let speeds = if !a.speed.is_empty() {
        a.speed.clone()
    } else if a.froude.is_empty() {
        sea.speeds.resolve(hull.lpp)
    } else {
        a.froude
            .iter()
            .map(|f| f * (model.g * hull.lpp).sqrt())
            .collect()
    };
    let mut warnings: Vec<String> = Vec::new();
    let mut at: Vec<f64> = if a.x_m.is_empty() {
        a.station.clone()
    } else {
        a.x_m.iter().map(|&x| hull.aft_of_fp(x)).collect()
    };
    if at.is_empty() {
        at = impact::sensor_stations(&hull);
    }
    let mut stations = Vec::new();
    let mut seen: Vec<f64> = Vec::new();
    at.retain(|&f| {
        let key = (f * 1e9).round() / 1e9;
        if seen.contains(&key) {
            let given = if a.x_m.is_empty() {
                format!("--station {f}")
            } else {
                format!("--x-m {}", hull.station_x(f))
            };
            warnings.push(station::duplicate(&given, key));
            false
        } else {
            seen.push(key);
            true
        }
    });
    for &f in &at {
        let x = hull.station_x(f);
        let given = if a.x_m.is_empty() {
            format!("--station {f}")
        } else {
            format!("--x-m {x}")
        };
        let st = station::check(&hull, x, given)?;
        warnings.extend(st.warning);
        stations.push(
            impact::seakeeping_station(&hull, loading, f)
                .map_err(|e| Error::Invalid(format!("{}: {e}", st.given)))?,
        );
    }
    if a.entry_definitions {
        return entry_definitions(&hull, loading, &sea, &at, &speeds);
    }
    let method = match a.method {
        Method::CloseFit => SectionMethod::FrankCloseFit,
        Method::Lewis => SectionMethod::Lewis,
    };
    let req = Request {
        lambda_over_l: a.lambda_over_l.clone(),
        swell_up: a.swell_up,
        keel_slope_term: a.keel_slope_term,
        slam_probability_limit: a.slam_limit,
        method,
        spectrum_samples: a.spectrum_samples.max(3),
        frequency_table_spacing: (a.frequency_spacing > 0.0).then_some(a.frequency_spacing),
        ..Request::for_sea(&sea, speeds, stations)
    };
    let report = analysis::run(&model, &req)?;
    warnings.extend(sanity::negative_gm(&Hydrostatics::compute(&hull, loading)));
    warnings.extend(
        sea.irregular
            .iter()
            .filter_map(|ir| sanity::spectrum_samples(ir, req.spectrum_samples)),
    );
    warnings.extend(sanity::operability_limits(&report));
    warnings.extend(report.warnings.iter().cloned());
    let settings = serde_json::json!({
        "loading": loading.name, "method": method.name(), "strips": a.strips,
        "swell_up": a.swell_up, "keel_slope_term": a.keel_slope_term, "slam_limit": a.slam_limit, "lambda_over_l": a.lambda_over_l,
        "speeds_m_per_s": req.speeds, "stations": at, "spectrum_samples": req.spectrum_samples,
        "frequency_spacing": a.frequency_spacing,
    });
    let mut inputs = hull.input_files();
    inputs.push(a.sea.as_path());
    let prov = Provenance::new(&inputs, settings)?;
    let written = match &a.out {
        Some(dir) => {
            report::write_csv_tables(dir, &report::motions_csv::tables(&report, &warnings), &prov)?
        }
        None => Vec::new(),
    };
    if a.json.json {
        for w in &warnings {
            global::warn_stderr(w);
        }
        let outputs = a.out.as_ref().map(|d| {
            serde_json::json!({
                "folder": d.display().to_string(),
                "files": written.iter().map(|p| p.display().to_string()).collect::<Vec<_>>(),
            })
        });
        let out = serde_json::json!({
            "tool": TOOL,
            "provenance": prov,
            "warnings": warnings,
            "outputs": outputs,
            "hull": hull.name,
            "loading": loading.name,
            "motions": report,
            "regular_slam_flags": sanity::regular_slam_flags(&report),
        });
        global::print_json(out);
    } else {
        print!(
            "{}",
            report::motions_text::tables(&hull.name, &loading.name, &report, &warnings)
        );
        match &a.out {
            Some(dir) => println!("\n{}", global::files_written_line(dir)),
            None => println!("\nno files written (give -o DIR for the CSV plot data)"),
        }
    }
    Ok(())
}

/// `--entry-definitions`: the definitions table (Markdown) at every station and speed in the first regular
/// wave of the sea file.
fn entry_definitions(
    hull: &Hull,
    loading: &slamtool::hull::LoadingCondition,
    sea: &SeaState,
    at: &[f64],
    speeds: &[f64],
) -> Result<()> {
    use slamtool::seakeeping::entry_definitions::{self as defs, Published, Target};
    let wave = sea.regular.first().ok_or_else(|| {
        Error::Invalid(format!(
            "{}: --entry-definitions needs a regular wave in the sea file",
            sea.source.display()
        ))
    })?;
    let mut targets = Vec::new();
    for &u in speeds {
        for &f in at {
            targets.push(Target::keel_entry(
                format!("{f} Lpp, {u} m/s"),
                hull,
                loading,
                wave,
                u,
                f,
            ));
        }
    }
    let rows = defs::table(&targets, &defs::standard_variants(loading))?;
    let published =
        match slamtool::assess::comparisons::reference_kind(&hull.name, &sea.name)?.as_deref() {
            Some("ochi1958") => {
                let veen = slamtool::assess::comparisons::veen_ochi_entry_speeds()?;
                let values: Vec<Option<f64>> = targets
                    .iter()
                    .map(|t| {
                        veen.iter()
                            .find(|(f, u, _)| {
                                (f - t.aft_of_fp).abs() < 1e-6 && (u - t.speed).abs() < 1e-6
                            })
                            .map(|v| v.2)
                    })
                    .collect();
                values.iter().any(Option::is_some).then(|| Published {
                    label: "Veen (2010), SEAWAY strip theory (reference)".into(),
                    values,
                })
            }
            _ => None,
        };
    println!(
        "Keel-entry velocity (m/s, downward) of {} at loading '{}' in wave {} (H {} m, T {:.3} s, \
         lambda {:.3} m) of {}, under each definition of the strip-theory chain ({} strips, Frank close-fit; \
         'change' from the first row{}). Generated by slamtool {}.\n",
        hull.name,
        loading.name,
        wave.name,
        wave.height_m,
        wave.period_s,
        wave.wavelength_m,
        sea.name,
        defs::STRIPS,
        if published.is_some() {
            "; 'gap closed': the change as a share of the gap from the first row to the published value"
        } else {
            ""
        },
        env!("CARGO_PKG_VERSION"),
    );
    print!("{}", defs::markdown(&targets, &rows, published.as_ref()));
    Ok(())
}
