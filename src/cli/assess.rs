//! `slamtool assess HULL --sea SEA`: the 2D+t assessment (Veen 2010, ch. 6). The work is
//! `slamtool::assess`; this file parses the arguments, prints the tables and applies the limit gate.

use std::path::{Path, PathBuf};

use clap::Args;
use slamtool::assess::{self, Assessment, Fidelity, Settings};
use slamtool::hull::Hull;
use slamtool::sea::SeaState;
use slamtool::sph::{Level, Overrides, StudyPlan};
use slamtool::{Error, Result};

use super::global::{self, JsonArg};
use super::progress_bar;

/// Examples at the end of `slamtool assess --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool assess hulls/ochi-vform.toml --sea sea_states/ochi-1958.toml
  slamtool assess hulls/ochi-vform.toml --sea sea_states/ochi-1958.toml --fidelity analytic
  slamtool assess hulls/ochi-vform.toml --sea sea_states/ochi-1958.toml --station 0.093,0.133 \\
      --speeds 2.0,2.4 --max-pressure-kpa 20 -o reports/ochi-gate";

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
    /// Speeds in m/s, comma-separated (replaces the sea file's speeds).
    #[arg(
        long,
        value_delimiter = ',',
        value_name = "U",
        allow_negative_numbers = true
    )]
    speeds: Vec<f64>,
    /// screen: analytic everywhere, then SPH for the governing event of each station (highest analytic
    /// sensor pressure); sph: SPH for every event, with the analytic estimate and a convergence statement
    /// beside each peak; analytic: generalised Wagner + MLM for every event (seconds).
    #[arg(long, value_enum, default_value = "screen")]
    fidelity: Fidelity,
    /// Resolution of the SPH runs.
    #[arg(long, value_enum, default_value = "coarse")]
    resolution: Level,
    /// Particles across the largest half-breadth (overrides --resolution; for quick checks).
    #[arg(long, value_name = "N")]
    particles_per_half_beam: Option<f64>,
    /// Resolutions per SPH run including the reported one (1 = no convergence statement, 2 or 3).
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u8).range(1..=3))]
    convergence_levels: u8,
    /// Parallel SPH runs [default: one per core].
    #[arg(short = 'j', long, value_name = "N")]
    threads: Option<usize>,
    /// Design gate: every sensor design pressure above this (kPa) is a violation (exit status 4).
    #[arg(long, value_name = "P")]
    max_pressure_kpa: Option<f64>,
    /// Run every SPH case again instead of reusing finished runs from OUT/cache (the new runs replace
    /// the cached ones).
    #[arg(long)]
    no_cache: bool,
    /// Write into an output folder that holds files of something other than an assessment.
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
    /// Output folder [default: reports/<hull name>/].
    #[arg(short, long, value_name = "DIR", alias = "output")]
    out: Option<PathBuf>,
}

/// A file-name-safe form of a hull name ("Ochi V-form (1958)" -> "ochi-v-form-1958").
fn slug(name: &str) -> String {
    let mut s = String::new();
    for c in name.chars() {
        if c.is_ascii_alphanumeric() {
            s.push(c.to_ascii_lowercase());
        } else if !s.ends_with('-') {
            s.push('-');
        }
    }
    let s = s.trim_matches('-').to_string();
    if s.is_empty() { "hull".into() } else { s }
}

/// Refuse a folder that holds other things than an earlier assessment, unless --force.
fn check_out(dir: &Path, force: bool) -> Result<()> {
    if dir.exists() && !dir.is_dir() {
        return Err(Error::Invalid(format!(
            "the output folder {} is a file, not a folder",
            dir.display()
        )));
    }
    let Ok(entries) = std::fs::read_dir(dir) else {
        return Ok(());
    };
    let known = [
        "summary.json",
        "pressures.csv",
        "cache",
        "motions.json",
        "report.pdf",
        "figures",
        slamtool::report::assessment::TIMING_FILE,
    ];
    let other = entries
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .find(|n| !known.contains(&n.as_str()) && !n.starts_with('.'));
    match other {
        Some(n) if !force => Err(Error::Invalid(format!(
            "the output folder {} holds '{n}', which an assessment did not write; give another -o DIR or \
             --force to write there anyway",
            dir.display()
        ))),
        _ => Ok(()),
    }
}

fn kpa(v: Option<f64>) -> String {
    v.map_or("-".into(), |p| format!("{:.2}", p / 1e3))
}

/// The text tables: events, then the design pressure per station.
fn tables(a: &Assessment) -> String {
    let mut s = format!(
        "assessment of {} ({}), fidelity {}\n\nevents (station x speed x wave):\n",
        a.hull, a.loading, a.fidelity
    );
    s += "  station  speed_m_per_s  wave             flag                     v_entry_m_per_s  max_sensor_sph_kpa  max_sensor_analytic_kpa\n";
    for e in &a.events {
        let flag = serde_json::to_value(e.slam_flag)
            .ok()
            .and_then(|v| v.as_str().map(str::to_string))
            .unwrap_or_default();
        let sph = e
            .sph
            .as_ref()
            .map(|r| r.sensors.iter().map(|q| q.raw_peak_pa).fold(0.0, f64::max));
        let an = e
            .analytic
            .as_ref()
            .map(|r| r.sensors.iter().map(|q| q.peak_pa).fold(0.0, f64::max));
        s += &format!(
            "  {:<7}  {:<13.2}  {:<15}  {:<23}  {:<15}  {:<18}  {}{}\n",
            e.station,
            e.speed_m_per_s,
            e.wave,
            flag,
            e.entry_velocity_m_per_s
                .map_or("-".into(), |v| format!("{v:.3}")),
            kpa(sph),
            kpa(an),
            e.failed
                .as_ref()
                .map_or(String::new(), |f| format!("  FAILED: {f}"))
        );
    }
    s += "\ndesign pressure per station and sensor (largest over events):\n";
    for st in &a.stations {
        s += &format!(
            "  station {} (x {:.3} m): {} of {} events emerge, {} slam by Ochi's criterion",
            st.station,
            st.x_m,
            st.emerging_events,
            a.events
                .iter()
                .filter(|e| (e.station - st.station).abs() < 1e-9)
                .count(),
            st.slamming_events
        );
        if let Some(f) = &st.section_force_peak_n_per_m {
            s += &format!(
                "; section force {:.1} N/m ({}, {} m/s)",
                f.value, f.source, f.speed_m_per_s
            );
        }
        s += "\n";
        for d in &st.design_pressure_pa {
            s += &format!(
                "    {:<10} {:>9.2} kPa  ({}, {} m/s, {})\n",
                d.name,
                d.value / 1e3,
                d.source,
                d.speed_m_per_s,
                d.wave
            );
        }
    }
    if !a.irregular.is_empty() {
        s += &format!(
            "\nirregular seas ({}):\n  speed_m_per_s  sea              station  slam_probability  slams_per_hour  extreme_entry_velocity_m_per_s\n",
            assess::plan::IRREGULAR_NOTE
        );
        for ir in &a.irregular {
            let stations = ir["stations"].as_array().cloned().unwrap_or_default();
            for (k, st) in stations.iter().enumerate() {
                let f = a.stations.get(k).map_or(f64::NAN, |s| s.station);
                s += &format!(
                    "  {:<13.3}  {:<15}  {:<7}  {:<16.4}  {:<14.1}  {}\n",
                    ir["speed_m_per_s"].as_f64().unwrap_or(f64::NAN),
                    ir["sea"].as_str().unwrap_or(""),
                    f,
                    st["slam_probability"].as_f64().unwrap_or(f64::NAN),
                    st["slams_per_hour"].as_f64().unwrap_or(f64::NAN),
                    ir["extreme_entry_velocity_m_per_s"][k]
                        .as_f64()
                        .map_or("-".into(), |v| format!("{v:.3}"))
                );
            }
        }
    }
    s
}

pub fn run(a: AssessArgs) -> Result<()> {
    let hull = Hull::from_file(&a.hull)?;
    let sea = SeaState::from_file(&a.sea)?;
    if let Some(n) = a.particles_per_half_beam
        && !(n.is_finite() && n >= 4.0)
    {
        return Err(Error::Invalid(format!(
            "--particles-per-half-beam must be at least 4, got {n}"
        )));
    }
    if let Some(p) = a.max_pressure_kpa
        && !(p.is_finite() && p > 0.0)
    {
        return Err(Error::Invalid(format!(
            "--max-pressure-kpa must be a positive number, got {p}"
        )));
    }
    let out = a
        .out
        .clone()
        .unwrap_or_else(|| Path::new("reports").join(slug(&hull.name)));
    check_out(&out, a.force)?;
    let settings = Settings {
        loading: a.loading.clone(),
        stations: a.station.clone(),
        speeds: (!a.speeds.is_empty()).then(|| a.speeds.clone()),
        fidelity: a.fidelity,
        overrides: Overrides {
            level: Some(a.resolution),
            particles_per_half_beam: a.particles_per_half_beam,
            ..Default::default()
        },
        study: StudyPlan {
            levels: a.convergence_levels as usize,
            ..StudyPlan::default()
        },
        use_cache: !a.no_cache,
        threads: a.threads,
        max_pressure_kpa: a.max_pressure_kpa,
        ..Settings::default()
    };
    let (result, _written) = assess::run(&hull, &sea, &settings, &out, &progress_bar::handle())?;
    let report = if a.no_report {
        None
    } else {
        Some(super::report::write_report(&out, &out, a.stamp)?)
    };
    let violations = a
        .max_pressure_kpa
        .map(|p| assess::limits::violations(&result, p * 1e3))
        .unwrap_or_default();
    if a.json.json {
        for w in &result.warnings {
            global::warn_stderr(w);
        }
        let mut v =
            serde_json::to_value(&result).map_err(|e| Error::Invalid(format!("summary: {e}")))?;
        v["outputs"] = serde_json::json!({ "folder": out.display().to_string() });
        v["limit_violations"] = serde_json::json!(violations);
        v["report_time_s"] = serde_json::json!(report.as_ref().map(|g| g.time_s));
        global::print_json(v);
    } else {
        print!("{}", tables(&result));
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
            "{} sensor design pressure(s) above {} kPa",
            violations.len(),
            a.max_pressure_kpa.unwrap_or_default()
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
