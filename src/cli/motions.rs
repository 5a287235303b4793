//! `slamtool motions HULL --sea SEA`: strip-theory motions, relative motion at the bow stations, slam
//! statistics and the operability limit. Tables on stdout (or JSON with --json); plot data to CSV in -o DIR.
//! The analysis is `seakeeping::analysis`, the tables and CSV files are `report`: this file only parses the
//! arguments and builds the request.

use std::path::PathBuf;

use clap::Args;
use slamtool::hull::Hull;
use slamtool::provenance::Provenance;
use slamtool::report;
use slamtool::sea::SeaState;
use slamtool::seakeeping::ShipModel;
use slamtool::seakeeping::analysis::{self, Request, Station};
use slamtool::seakeeping::section::{HalfSection, SectionMethod};
use slamtool::seakeeping::slamming::DEFAULT_SLAM_PROBABILITY_LIMIT;
use slamtool::{Error, Result};

#[derive(Debug, Clone, Copy, clap::ValueEnum)]
enum Method {
    /// Frank (1967) close-fit pulsating sources (default).
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
    #[arg(long = "fn", value_delimiter = ',')]
    froude: Vec<f64>,
    /// Wavelength ratios lambda/Lpp for the RAO table, comma-separated.
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "0.5,0.75,1.0,1.25,1.5,1.75,2.0,2.5,3.0"
    )]
    lambda_over_l: Vec<f64>,
    /// Stations as fractions of Lpp aft of the FP, comma-separated (default: the hull's sensor stations, or
    /// 0.05,0.1,0.15,0.2).
    #[arg(long, value_delimiter = ',')]
    at: Vec<f64>,
    /// Sectional hydrodynamics.
    #[arg(long, value_enum, default_value = "close-fit")]
    method: Method,
    /// Number of strip-theory stations.
    #[arg(long, default_value_t = 31)]
    stations: usize,
    /// Dynamic swell-up factor on relative motion and velocity (1 = none).
    #[arg(long, default_value_t = 1.0)]
    swell_up: f64,
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
    /// Print JSON instead of tables.
    #[arg(long)]
    json: bool,
    /// Write CSV plot data (RAOs, relative motion, entry profiles, response spectra, slam statistics,
    /// operability) here.
    #[arg(short, long)]
    output: Option<PathBuf>,
}

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
    if !(a.frequency_spacing.is_finite() && (0.0..=0.5).contains(&a.frequency_spacing)) {
        return Err(bad(
            "--frequency-spacing",
            "between 0 (direct solves) and 0.5",
            a.frequency_spacing,
        ));
    }
    let model = ShipModel::from_hull(&hull, loading, a.stations)?;
    let speeds = if a.froude.is_empty() {
        sea.speeds.resolve(hull.lpp)
    } else {
        a.froude
            .iter()
            .map(|f| f * (model.g * hull.lpp).sqrt())
            .collect()
    };
    let mut at = a.at.clone();
    if at.is_empty() {
        at = hull.sensors.iter().map(|s| hull.aft_of_fp(s.x)).collect();
        at.sort_by(f64::total_cmp);
        at.dedup_by(|p, q| (*p - *q).abs() < 1e-6);
        if at.is_empty() {
            at = vec![0.05, 0.1, 0.15, 0.2];
        }
    }
    let mut stations = Vec::new();
    for &f in &at {
        if !(f.is_finite() && (0.0..=1.0).contains(&f)) {
            return Err(Error::Invalid(format!(
                "--at values are fractions of Lpp aft of the FP in [0, 1], got {f}"
            )));
        }
        let x = hull.station_x(f);
        let sec = hull.section_at(x)?;
        let z_w = loading.draft_at(x, hull.lpp);
        let wet: Vec<[f64; 2]> = sec.wetted(z_w).iter().map(|p| [p[0], p[1] - z_w]).collect();
        let mut pts: Vec<[f64; 2]> = Vec::new();
        for q in wet {
            if pts
                .last()
                .is_none_or(|l: &[f64; 2]| (l[0] - q[0]).hypot(l[1] - q[1]) > 1e-9)
            {
                pts.push(q);
            }
        }
        if pts.len() < 2 {
            return Err(Error::Invalid(format!(
                "station {f} Lpp aft of FP is dry at loading '{}'",
                loading.name
            )));
        }
        let h = HalfSection::new(pts)?;
        stations.push(Station::new(hull.lpp, f, &h, sec.deck_z() - sec.keel_z()));
    }
    let method = match a.method {
        Method::CloseFit => SectionMethod::FrankCloseFit,
        Method::Lewis => SectionMethod::Lewis,
    };
    let req = Request {
        speeds,
        lambda_over_l: a.lambda_over_l.clone(),
        regular: sea.regular.clone(),
        irregular: sea.irregular.clone(),
        stations,
        swell_up: a.swell_up,
        slam_probability_limit: a.slam_limit,
        method,
        spectrum_samples: a.spectrum_samples.max(3),
        profile_samples: 41,
        frequency_table_spacing: (a.frequency_spacing > 0.0).then_some(a.frequency_spacing),
        water_depth: sea.water_depth_m,
    };
    let report = analysis::run(&model, &req)?;
    if a.json {
        for w in &report.warnings {
            eprintln!("warning: {w}");
        }
    }
    let settings = serde_json::json!({
        "loading": loading.name, "method": format!("{:?}", method), "strip_stations": a.stations,
        "swell_up": a.swell_up, "slam_limit": a.slam_limit, "lambda_over_l": a.lambda_over_l,
        "speeds_m_s": req.speeds, "stations_aft_of_fp": at,
        "frequency_spacing": a.frequency_spacing,
    });
    let prov = Provenance::new(&[a.hull.as_path(), a.sea.as_path()], settings)?;
    if let Some(dir) = &a.output {
        report::write_csv_tables(dir, &report::motions_csv::tables(&report), &prov)?;
    }
    if a.json {
        let out = serde_json::json!({ "provenance": prov, "hull": hull.name, "loading": loading.name, "motions": report });
        println!(
            "{}",
            serde_json::to_string_pretty(&out).map_err(|e| Error::Invalid(e.to_string()))?
        );
    } else {
        print!(
            "{}",
            report::motions_text::tables(&hull.name, &loading.name, &report)
        );
    }
    Ok(())
}
