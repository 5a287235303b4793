//! `slamtool motions HULL --sea SEA`: strip-theory motions, relative motion at the bow stations, slam
//! statistics and the operability limit. Tables on stdout (or JSON with --json); plot data to CSV in -o DIR.

use std::path::{Path, PathBuf};

use clap::Args;
use slamtool::hull::Hull;
use slamtool::provenance::Provenance;
use slamtool::sea::SeaState;
use slamtool::seakeeping::ShipModel;
use slamtool::seakeeping::analysis::{self, Report, Request, Station};
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
    });
    let prov = Provenance::new(&[a.hull.as_path(), a.sea.as_path()], settings)?;
    if let Some(dir) = &a.output {
        write_csv(dir, &report, &prov)?;
    }
    if a.json {
        let out = serde_json::json!({ "provenance": prov, "hull": hull.name, "loading": loading.name, "motions": report });
        println!(
            "{}",
            serde_json::to_string_pretty(&out).map_err(|e| Error::Invalid(e.to_string()))?
        );
    } else {
        print_tables(&hull.name, &loading.name, &report);
    }
    Ok(())
}

fn print_tables(hull: &str, loading: &str, r: &Report) {
    println!(
        "{hull}, loading '{loading}': Lpp {:.3} m, mass {:.1} kg, {:?}, {} strips",
        r.lpp_m, r.mass_kg, r.method, r.strip_stations
    );
    println!(
        "natural periods (uncoupled, zero speed): heave {:.3} s, pitch {:.3} s",
        r.heave_natural_period_s, r.pitch_natural_period_s
    );
    println!(
        "Ochi slam threshold velocity 0.093 sqrt(g Lpp) = {:.3} m/s",
        r.slam_threshold_velocity_m_s
    );
    println!("note: {}", r.limitation);
    for w in &r.warnings {
        println!("WARNING: {w}");
    }
    for s in &r.speeds {
        println!(
            "\n== U = {:.3} m/s (Fn {:.3})",
            s.speed_m_s, s.froude_number
        );
        println!(
            "{:>8} {:>8} {:>8} {:>8} {:>9} {:>9} {:>9} {:>9}",
            "lam/L", "w0", "we", "z/za", "ph_z deg", "thL/2pza", "th/kza", "ph_t deg"
        );
        for q in &s.raos {
            println!(
                "{:8.3} {:8.3} {:8.3} {:8.3} {:9.1} {:9.3} {:9.3} {:9.1}",
                q.lambda_over_l,
                q.omega0,
                q.omega_e,
                q.heave,
                q.heave_phase_deg,
                q.pitch_nd,
                q.pitch_over_k,
                q.pitch_phase_deg
            );
        }
        for w in &s.regular {
            println!(
                "-- regular wave '{}' H {:.3} m: heave {:.4} m, pitch {:.3} deg",
                w.wave, w.height_m, w.heave_m, w.pitch_deg
            );
            println!(
                "{:>8} {:>8} {:>8} {:>9} {:>9} {:>9} {:>10}",
                "aft_FP", "x", "draft", "s_amp", "v_amp", "t_entry", "V_entry"
            );
            for t in &w.stations {
                let (te, ve) =
                    t.keel_entry
                        .as_ref()
                        .map_or(("-".to_string(), "no entry".to_string()), |k| {
                            (
                                format!("{:.3}", k.t_entry),
                                format!("{:.3}", k.entry_velocity),
                            )
                        });
                println!(
                    "{:8.3} {:8.3} {:8.3} {:9.4} {:9.4} {:>9} {:>10}",
                    t.aft_of_fp, t.x, t.draft, t.relative_motion_m, t.relative_velocity_m_s, te, ve
                );
            }
        }
        for ir in &s.irregular {
            println!(
                "-- irregular sea '{}' Hs {:.3} m Tp {:.2} s",
                ir.sea, ir.hs_m, ir.tp_s
            );
            println!(
                "{:>8} {:>9} {:>9} {:>10} {:>9} {:>12}",
                "x", "sd_s", "sd_v", "P(slam)", "per hour", "V_extreme"
            );
            for (t, e) in ir.stations.iter().zip(&ir.extreme_velocity_m_s) {
                let e = e.map_or("-".to_string(), |v| format!("{v:.3}"));
                println!(
                    "{:8.3} {:9.4} {:9.4} {:10.3e} {:9.2} {:>12}",
                    t.x,
                    t.m0.sqrt(),
                    t.m2.sqrt(),
                    t.probability,
                    t.slams_per_hour,
                    e
                );
            }
        }
    }
    for o in &r.operability {
        let lim = o
            .operability
            .limit_speed
            .map_or("below the lowest speed".to_string(), |u| {
                format!("{u:.3} m/s")
            });
        println!(
            "\noperability in '{}' (slam probability <= {}): {lim}",
            o.sea, o.operability.limit
        );
    }
}

fn csv_text(prov: &Provenance, header: &[&str], rows: Vec<Vec<String>>) -> Result<String> {
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header)
        .map_err(|e| Error::Invalid(e.to_string()))?;
    for r in rows {
        w.write_record(&r)
            .map_err(|e| Error::Invalid(e.to_string()))?;
    }
    let body = w.into_inner().map_err(|e| Error::Invalid(e.to_string()))?;
    Ok(prov.csv_header() + &String::from_utf8_lossy(&body))
}

/// File name, header and rows of one CSV output.
type CsvFile<'a> = (&'a str, &'a [&'a str], Vec<Vec<String>>);

fn write_csv(dir: &Path, r: &Report, prov: &Provenance) -> Result<()> {
    let f = |v: f64| format!("{v:.6e}");
    let mut raos = Vec::new();
    let mut rel = Vec::new();
    let mut prof = Vec::new();
    let mut slam = Vec::new();
    let mut spec = Vec::new();
    for s in &r.speeds {
        for q in &s.raos {
            raos.push(vec![
                f(s.speed_m_s),
                f(s.froude_number),
                f(q.lambda_over_l),
                f(q.omega0),
                f(q.omega_e),
                f(q.heave),
                f(q.heave_phase_deg),
                f(q.pitch_nd),
                f(q.pitch_over_k),
                f(q.pitch_phase_deg),
            ]);
        }
        for w in &s.regular {
            for t in &w.stations {
                let (te, ve) = t
                    .keel_entry
                    .as_ref()
                    .map_or((String::new(), String::new()), |k| {
                        (f(k.t_entry), f(k.entry_velocity))
                    });
                rel.push(vec![
                    f(s.speed_m_s),
                    w.wave.clone(),
                    f(t.aft_of_fp),
                    f(t.x),
                    f(t.draft),
                    f(t.relative_motion_m),
                    f(t.relative_velocity_m_s),
                    te,
                    ve,
                ]);
                if let Some(k) = &t.keel_entry {
                    for p in &k.samples {
                        prof.push(vec![
                            f(s.speed_m_s),
                            w.wave.clone(),
                            f(t.aft_of_fp),
                            f(p.t),
                            f(p.velocity),
                            f(p.penetration),
                        ]);
                    }
                }
            }
        }
        for ir in &s.irregular {
            for rs in &ir.response_spectra {
                for j in 0..rs.omega0.len() {
                    spec.push(vec![
                        ir.sea.clone(),
                        f(s.speed_m_s),
                        f(rs.x),
                        f(rs.omega0[j]),
                        f(rs.omega_e[j]),
                        f(rs.motion[j]),
                        f(rs.velocity[j]),
                    ]);
                }
            }
            for (t, e) in ir.stations.iter().zip(&ir.extreme_velocity_m_s) {
                slam.push(vec![
                    ir.sea.clone(),
                    f(s.speed_m_s),
                    f(t.x),
                    f(t.draft),
                    f(t.m0),
                    f(t.m2),
                    f(t.threshold_velocity),
                    f(t.probability),
                    f(t.slams_per_hour),
                    e.map(f).unwrap_or_default(),
                ]);
            }
        }
    }
    let mut oper = Vec::new();
    for o in &r.operability {
        for (u, p) in o
            .operability
            .speeds
            .iter()
            .zip(&o.operability.max_probability)
        {
            oper.push(vec![
                o.sea.clone(),
                f(*u),
                f(*p),
                f(o.operability.limit),
                o.operability.limit_speed.map(f).unwrap_or_default(),
            ]);
        }
    }
    let files: [CsvFile; 6] = [
        (
            "raos.csv",
            &[
                "speed_m_s",
                "froude",
                "lambda_over_l",
                "omega0",
                "omega_e",
                "heave_over_za",
                "heave_phase_deg",
                "pitch_l_over_2pi_za",
                "pitch_over_k_za",
                "pitch_phase_deg",
            ],
            raos,
        ),
        (
            "relative_motion.csv",
            &[
                "speed_m_s",
                "wave",
                "aft_of_fp",
                "x_m",
                "draft_m",
                "relative_motion_m",
                "relative_velocity_m_s",
                "t_entry_s",
                "entry_velocity_m_s",
            ],
            rel,
        ),
        (
            "entry_profiles.csv",
            &[
                "speed_m_s",
                "wave",
                "aft_of_fp",
                "t_since_entry_s",
                "velocity_m_s",
                "penetration_m",
            ],
            prof,
        ),
        (
            "slam_statistics.csv",
            &[
                "sea",
                "speed_m_s",
                "x_m",
                "draft_m",
                "m0_m2",
                "m2_m2_s2",
                "threshold_m_s",
                "probability",
                "slams_per_hour",
                "extreme_velocity_m_s",
            ],
            slam,
        ),
        (
            "response_spectra.csv",
            &[
                "sea",
                "speed_m_s",
                "x_m",
                "omega0",
                "omega_e",
                "relative_motion_m2_s",
                "relative_velocity_m2_per_s",
            ],
            spec,
        ),
        (
            "operability.csv",
            &[
                "sea",
                "speed_m_s",
                "max_probability",
                "limit",
                "limit_speed_m_s",
            ],
            oper,
        ),
    ];
    for (name, header, rows) in files {
        slamtool::files::write_text_atomic(&dir.join(name), &csv_text(prov, header, rows)?)?;
    }
    Ok(())
}
