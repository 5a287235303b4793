//! `slamtool entry ...`: one 2D water-entry run (SPH), with Wagner theory beside it.

use std::path::PathBuf;

use clap::{Args, Subcommand};
use slamtool::provenance::{Provenance, TOOL};
use slamtool::sph::{
    self, Level, MotionSpec, Overrides, RunOptions, RunResult, SensorMethod, SensorSpec,
    body::Section,
};

use super::global::{self, JsonArg, SphOptions};
use super::progress_bar;
use super::station::StationArg;

/// Examples at the end of `slamtool entry --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool entry wedge --deadrise-deg 30 --speed 5 -o out/wedge30
  slamtool entry section hulls/ochi-vform.toml --station 0.1 --speed 2.0
  slamtool entry case data/cases/zhao1996_wedge30_drop.toml -o out/zhao";

const WEDGE_EXAMPLES: &str = "\
Examples:
  slamtool entry wedge --deadrise-deg 30 --speed 5 -o out/wedge30
  slamtool entry wedge --deadrise-deg 20 --speed 3 --resolution medium --convergence-levels 3
  slamtool entry wedge --deadrise-deg 30 --speed 5 --convergence-levels 1 --frames 0 --json";

const SECTION_EXAMPLES: &str = "\
Examples:
  slamtool entry section hulls/ochi-vform.toml --station 0.1 --speed 2.0 -o out/ochi-st0.1
  slamtool entry section hulls/ochi-vform.toml --x-m 2.4 --speed 1.5 --keel-stages --json
  slamtool entry section hulls/car-carrier-hm2005.toml --station 0.05 \\
      --forcing data/forcing/hermundstad2005-flare-reconstructed.csv --t-end 0.4";

const CASE_EXAMPLES: &str = "\
Examples:
  slamtool entry case data/cases/zhao1996_wedge30_drop.toml -o out/zhao
  slamtool entry case my-case.toml --filter-hz 2000 --frames 0
  slamtool entry case my-case.toml --convergence-levels 1 --json > summary.json";

#[derive(Debug, Subcommand)]
pub enum EntryCommand {
    /// A wedge entering calm water at constant speed.
    #[command(after_long_help = WEDGE_EXAMPLES)]
    Wedge(WedgeArgs),
    /// A case file (TOML) with full control of section, motion, resolution and numerics.
    #[command(after_long_help = CASE_EXAMPLES)]
    Case(CaseArgs),
    /// A hull section (from a hull file) entering calm water keel first, at constant speed or with a
    /// measured relative-motion record (--forcing).
    #[command(after_long_help = SECTION_EXAMPLES)]
    Section(SectionArgs),
}

#[derive(Debug, Args)]
pub struct SectionArgs {
    /// The hull file.
    hull: PathBuf,
    #[command(flatten)]
    station: StationArg,
    /// Constant entry speed (m/s); or give --forcing.
    #[arg(long, required_unless_present = "forcing", conflicts_with = "forcing")]
    speed: Option<f64>,
    /// A measured or externally computed relative-motion record of the station (CSV: `time [s]` and
    /// `relative_elevation [m]`, `relative_velocity [m/s]` or `entry_velocity [m/s]`, `#` provenance
    /// lines): the keel-entry instant is found from it and the section enters with its velocity
    /// (docs/guide/measured-forcing.md).
    #[arg(long, value_name = "FILE.csv")]
    forcing: Option<PathBuf>,
    /// Loading condition whose local draft at the station places the keel for --forcing [default: the
    /// hull's first].
    #[arg(long, requires = "forcing")]
    loading: Option<String>,
    #[command(flatten)]
    numerics: Numerics,
    #[command(flatten)]
    common: Common,
}

/// Resolution and domain of a wedge or section run (a case file sets these itself).
#[derive(Debug, Args)]
pub struct Numerics {
    /// Resolution level: particles across the largest half-breadth.
    #[arg(long, value_enum, default_value = "coarse")]
    resolution: Level,
    /// Particle spacing (m); overrides --resolution.
    #[arg(long)]
    dp: Option<f64>,
    /// Sound speed (m/s) [default: from the expected peak pressure].
    #[arg(long)]
    c0: Option<f64>,
    /// End time (s) [default: when the keel reaches the chine depth].
    #[arg(long)]
    t_end: Option<f64>,
    /// Whole tank instead of a half tank with a symmetry plane.
    #[arg(long)]
    full_domain: bool,
    #[command(flatten)]
    sph: SphOptions,
}

/// Options shared by every entry run.
#[derive(Debug, Args)]
pub struct Common {
    /// Cut-off (Hz) of the zero-phase low-pass filter for the reported filtered peaks [default: none].
    #[arg(long)]
    filter_hz: Option<f64>,
    /// How the sensor pressures are computed [default: force-panel, or the case file's choice].
    #[arg(long, value_enum)]
    sensor_method: Option<SensorMethod>,
    /// Resolutions run for the convergence statement of every peak, the requested one included: 2 adds a
    /// companion run at twice the particle spacing (about 1/8 of the cost), 3 adds one at four times;
    /// 1 runs the requested resolution only (the statements then say "not assessed").
    #[arg(long, default_value_t = 2, value_parser = clap::value_parser!(u8).range(1..=3))]
    convergence_levels: u8,
    /// Number of particle snapshots (VTK and PNG) over the run; 0 for none.
    #[arg(long, default_value_t = 10)]
    frames: u32,
    /// Output folder [default: out/<case name>, printed at the end].
    #[arg(short, long, value_name = "DIR")]
    out: Option<PathBuf>,
    #[command(flatten)]
    json: JsonArg,
    /// Run even when the estimated wall time exceeds the one-hour bound.
    #[arg(long)]
    force: bool,
    /// After the run, resolve the sensors it crossed too early (in the contact transient, or with fewer
    /// than 10 particles across the wetted half-width) with fine runs of the section's lower part at 20
    /// particles across, as `assess` does (keel stages, `slamtool::sph::keel_stage`).
    #[arg(long)]
    keel_stages: bool,
}

#[derive(Debug, Args)]
pub struct WedgeArgs {
    /// Deadrise angle (deg).
    #[arg(long)]
    deadrise_deg: f64,
    /// Constant entry speed (m/s).
    #[arg(long)]
    speed: f64,
    /// Half-beam at the knuckle (m).
    #[arg(long, default_value_t = 0.25)]
    half_beam: f64,
    /// Width of the five pressure sensors along the wedge side (m).
    #[arg(long, default_value_t = 0.005)]
    sensor_width: f64,
    #[command(flatten)]
    numerics: Numerics,
    #[command(flatten)]
    common: Common,
}

#[derive(Debug, Args)]
pub struct CaseArgs {
    /// The case file.
    file: PathBuf,
    #[command(flatten)]
    common: Common,
}

pub fn run(c: EntryCommand) -> slamtool::Result<()> {
    match c {
        EntryCommand::Wedge(a) => wedge(a),
        EntryCommand::Case(a) => case(a),
        EntryCommand::Section(a) => hull_section(a),
    }
}

fn overrides(n: &Numerics, c: &Common) -> Overrides {
    Overrides {
        level: Some(n.resolution),
        dp: n.dp,
        c0: n.c0,
        t_end: n.t_end,
        mirror: n.full_domain.then_some(false),
        air: Some(n.sph.air),
        refinement: n.sph.refinement(),
        divergence_correction: n.sph.divergence_correction(),
        shifting: n.sph.shifting(),
        wall_wetness: n.sph.wall_wetness(),
        filter_cutoff_hz: c.filter_hz,
        sensor_method: c.sensor_method,
        ..Default::default()
    }
}

/// The settings of a run as given on the command line, for its provenance.
fn settings(n: Option<&Numerics>, c: &Common) -> serde_json::Value {
    let mut v = serde_json::json!({
        "filter_hz": c.filter_hz,
        "sensor_method": c.sensor_method,
        "convergence_levels": c.convergence_levels,
        "frames": c.frames,
    });
    if let Some(n) = n {
        v["resolution"] = serde_json::json!(n.resolution);
        v["dp_m"] = serde_json::json!(n.dp);
        v["c0_m_per_s"] = serde_json::json!(n.c0);
        v["t_end_s"] = serde_json::json!(n.t_end);
        v["full_domain"] = serde_json::json!(n.full_domain);
        v["air"] = serde_json::json!(n.sph.air);
        v["tank"] = serde_json::json!(n.sph.tank);
        v["refined_tank"] = serde_json::json!(n.sph.refined_tank);
        v["divergence_correction"] = serde_json::json!(n.sph.divergence_correction);
        v["shifting"] = serde_json::json!(n.sph.shifting);
        v["wall_wetness"] = serde_json::json!(n.sph.wall_wetness);
    }
    v
}

fn wedge(a: WedgeArgs) -> slamtool::Result<()> {
    for (what, v) in [
        ("--speed", a.speed),
        ("--half-beam", a.half_beam),
        ("--sensor-width", a.sensor_width),
    ] {
        if !(v.is_finite() && v > 0.0) {
            return Err(slamtool::Error::Invalid(format!(
                "{what} must be a positive number, got {v}"
            )));
        }
    }
    if !(a.deadrise_deg > 1.0 && a.deadrise_deg < 89.0) {
        return Err(slamtool::Error::Invalid(format!(
            "--deadrise-deg must lie between 1 and 89, got {}",
            a.deadrise_deg
        )));
    }
    check_common(&a.common)?;
    let beta = a.deadrise_deg.to_radians();
    let chine = a.half_beam * beta.tan();
    let section = Section::wedge(beta, a.half_beam, 1.5 * chine)?;
    let side = a.half_beam / beta.cos();
    let width = a.sensor_width.min(0.19 * side);
    let mut warnings = Vec::new();
    if a.sensor_width > width {
        warnings.push(format!(
            "--sensor-width {} m is wider than the wedge allows (five sensors on a side of {side:.4} m): the \
             sensors are {width:.4} m wide",
            a.sensor_width
        ));
    }
    let sensors = [0.1, 0.3, 0.5, 0.7, 0.9]
        .iter()
        .enumerate()
        .map(|(k, f)| SensorSpec {
            name: format!("p{}", k + 1),
            s_m: f * side,
            width_m: width,
        })
        .collect();
    let name = format!("wedge_{}deg_{}ms", a.deadrise_deg, a.speed);
    let mut set = settings(Some(&a.numerics), &a.common);
    set["deadrise_deg"] = serde_json::json!(a.deadrise_deg);
    set["speed_m_per_s"] = serde_json::json!(a.speed);
    set["half_beam_m"] = serde_json::json!(a.half_beam);
    set["sensor_width_m"] = serde_json::json!(a.sensor_width);
    let prov = Provenance::new(&[], set)?;
    let run = Run {
        common: &a.common,
        prov,
        warnings,
    };
    constant_speed(&name, &section, a.speed, sensors, &a.numerics, run)
}

/// The options every entry run shares, checked before anything is computed.
fn check_common(c: &Common) -> slamtool::Result<()> {
    if let Some(f) = c.filter_hz
        && !(f.is_finite() && f > 0.0)
    {
        return Err(slamtool::Error::Invalid(format!(
            "--filter-hz must be a positive cut-off frequency in Hz, got {f} (leave it out for raw peaks only)"
        )));
    }
    Ok(())
}

/// What every entry run carries besides its setup: the shared options, provenance and warnings found
/// before the run.
struct Run<'a> {
    common: &'a Common,
    prov: Provenance,
    warnings: Vec<String>,
}

/// Resolve and run a constant-speed entry of `section`.
fn constant_speed(
    name: &str,
    section: &Section,
    speed: f64,
    sensors: Vec<SensorSpec>,
    numerics: &Numerics,
    run: Run,
) -> slamtool::Result<()> {
    let setup = sph::case::resolve(
        name,
        section,
        &MotionSpec::Constant { speed_m_s: speed },
        sensors,
        &overrides(numerics, run.common),
    )?;
    go(setup, run, name)
}

fn hull_section(a: SectionArgs) -> slamtool::Result<()> {
    if let Some(speed) = a.speed
        && !(speed.is_finite() && speed > 0.0)
    {
        return Err(slamtool::Error::Invalid(format!(
            "--speed must be a positive number, got {speed}"
        )));
    }
    check_common(&a.common)?;
    let hull = slamtool::hull::Hull::from_file(&a.hull)?;
    let st = a.station.resolve(&hull)?;
    let x = st.x;
    let section = slamtool::impact::entry_section(&hull, x)?;
    let sensors = slamtool::impact::station_sensors(&hull, x);
    let stem = a
        .hull
        .file_stem()
        .map_or("hull".into(), |s| s.to_string_lossy().into_owned());
    let mut set = settings(Some(&a.numerics), &a.common);
    set["x_m"] = serde_json::json!(x);
    set["station"] = serde_json::json!(hull.aft_of_fp(x));
    let mut inputs: Vec<PathBuf> = hull.input_files().iter().map(|p| p.to_path_buf()).collect();
    let (name, motion) = match (&a.forcing, a.speed) {
        (Some(file), _) => {
            let loading = hull.loading(a.loading.as_deref())?;
            let station = slamtool::impact::seakeeping_station(&hull, loading, hull.aft_of_fp(x))?;
            let record = slamtool::forcing::read_record(file)?;
            let entry = slamtool::forcing::measured_entry(&record, station.draft, station.height)?;
            global::note(&format!(
                "{}: keel entry at {:.4} s of the record (local draft {:.4} m at loading '{}') at {:.3} m/s; \
                 {}; {} samples until {}",
                file.display(),
                entry.t_entry,
                entry.draft,
                loading.name,
                entry.entry_velocity,
                entry.velocity_from,
                entry.samples.len(),
                entry.profile_end
            ));
            for p in &entry.provenance {
                global::note(&format!("  record: {p}"));
            }
            set["loading"] = serde_json::json!(loading.name);
            set["forcing"] = serde_json::to_value(&entry).unwrap_or_default();
            inputs.push(file.clone());
            let rec = file
                .file_stem()
                .map_or("forcing".into(), |s| s.to_string_lossy().into_owned());
            (format!("{stem}_x{x:.3}m_{rec}"), entry.motion())
        }
        (None, Some(speed)) => {
            set["speed_m_per_s"] = serde_json::json!(speed);
            (
                format!("{stem}_x{x:.3}m_{speed}ms"),
                MotionSpec::Constant { speed_m_s: speed },
            )
        }
        (None, None) => {
            return Err(slamtool::Error::Invalid("give --speed or --forcing".into()));
        }
    };
    let input_refs: Vec<&std::path::Path> = inputs.iter().map(PathBuf::as_path).collect();
    let run = Run {
        common: &a.common,
        prov: Provenance::new(&input_refs, set)?,
        warnings: st.warning.into_iter().collect(),
    };
    let setup = sph::case::resolve(
        &name,
        &section,
        &motion,
        sensors,
        &overrides(&a.numerics, run.common),
    )?;
    go(setup, run, &name)
}

fn case(a: CaseArgs) -> slamtool::Result<()> {
    check_common(&a.common)?;
    let mut setup = sph::case::from_file(&a.file)?;
    // Command-line options take precedence over the file for the few they share; resolution, c0, t_end
    // and the domain are set in the file only.
    if let Some(f) = a.common.filter_hz {
        setup.filter_cutoff_hz = Some(f);
    }
    if let Some(m) = a.common.sensor_method {
        setup.sensor_method = m;
    }
    let name = setup.name.clone();
    let run = Run {
        common: &a.common,
        prov: Provenance::new(&[a.file.as_path()], settings(None, &a.common))?,
        warnings: Vec::new(),
    };
    go(setup, run, &name)
}

fn go(mut setup: sph::Setup, run: Run, name: &str) -> slamtool::Result<()> {
    let c = run.common;
    // A name from a case file becomes one folder name under out/, never a path of its own.
    let out = match &c.out {
        Some(o) => o.clone(),
        None => {
            let folder = slamtool::output_policy::safe_component(name, "the case name")?;
            if folder != name {
                global::note(&format!(
                    "the case name '{name}' is not a plain folder name; writing to out/{folder}"
                ));
            }
            PathBuf::from("out").join(folder)
        }
    };
    // An automatic end time that ran out before the keel got deep enough means no impact at all.
    if setup.t_end >= sph::automatic::T_END_MAX_S
        && let Some(n) = setup
            .notes
            .iter()
            .find(|n| n.contains(sph::automatic::NEVER_DEEP_ENOUGH))
    {
        return Err(slamtool::Error::Invalid(format!(
            "{name}: the body does not enter the water far enough for an impact within the longest automatic \
             run ({n}); the entry speed is too small or the motion does not go down (slamming entry speeds \
             are of the order of 0.1 to 20 m/s): give a larger speed, a downward motion, or an explicit t_end"
        )));
    }
    if c.frames > 0 && setup.snapshot_interval.is_none() {
        setup.snapshot_interval = Some(setup.t_end / c.frames as f64);
    }
    let plan = sph::StudyPlan {
        levels: c.convergence_levels as usize,
        ..Default::default()
    };
    let cost = sph::cost::estimate(&setup, plan, rayon::current_num_threads());
    global::note(&format!(
        "{name}: dp {:.2} mm, c0 {:.1} m/s, t_end {:.2} ms; {}",
        setup.dp * 1e3,
        setup.c0,
        setup.t_end * 1e3,
        cost.describe()
    ));
    sph::cost::check(&cost, c.force)?;
    let cleared = sph::output_dir::prepare(&out)?;
    if cleared > 0 {
        global::note(&format!(
            "removed {cleared} output(s) of an earlier run from {}",
            out.display()
        ));
    }
    let opts = RunOptions {
        out_dir: Some(out.clone()),
        progress: progress_bar::handle(),
        vtk: c.frames > 0,
        png: c.frames > 0,
        provenance: Some(run.prov.clone()),
    };
    let RunResult { summary, history } = if c.keel_stages {
        sph::run_staged(setup, &opts, plan)?
    } else {
        sph::run_with_convergence(setup, &opts, plan)?
    };
    let mut warnings = run.warnings;
    warnings.extend(summary.warnings.iter().cloned());
    let analytic = analytic_force(&summary, &history);
    if c.json.json {
        for w in &warnings {
            global::warn_stderr(w);
        }
        let json = serde_json::json!({
            "tool": TOOL,
            "provenance": run.prov,
            "warnings": warnings,
            "outputs": { "folder": out.display().to_string() },
            "summary": summary,
            "analytic_force": analytic.as_ref().map(|a| serde_json::json!({
                "model": a.model,
                "peak_n_per_m": a.peak.map(|p| p.0),
                "peak_time_s": a.peak.map(|p| p.1),
                "notes": a.notes,
            })),
        });
        global::print_json(json);
        return Ok(());
    }
    let f = &summary.force.summary.raw;
    println!("case            {}", summary.name);
    println!(
        "resolution      dp {:.2} mm, h {:.2} mm, c0 {:.1} m/s, {} fluid particles, {} steps, {:.1} s",
        summary.dp_m * 1e3,
        summary.h_m * 1e3,
        summary.c0_m_s,
        summary.fluid_particles,
        summary.steps,
        summary.wall_time_s
    );
    println!(
        "peak force      {:.1} N/m at {:.3} ms (impulse {:.3} N s/m)",
        f.value,
        f.time * 1e3,
        f.impulse
    );
    if let Some(ff) = &summary.force.summary.filtered {
        let cut = summary
            .force
            .summary
            .filter
            .as_ref()
            .map_or(0.0, |x| x.cutoff_hz);
        println!(
            "  filtered      {:.1} N/m at {:.3} ms ({cut} Hz zero-phase low-pass)",
            ff.value,
            ff.time * 1e3
        );
    }
    print_slamming_peaks(&summary.force, 1.0, "N/m");
    println!(
        "peak pressure   {:.1} kPa at {:.3} ms, {:.1} mm from the keel along the contour",
        summary.peak_contour_pressure_pa * 1e-3,
        summary.peak_contour_pressure_time_s * 1e3,
        summary.peak_contour_pressure_s_m * 1e3
    );
    for s in &summary.sensors {
        let span = s
            .integration_span_m
            .filter(|sp| s.width_m.is_some_and(|w| sp[1] - sp[0] > w * (1.0 + 1e-9)))
            .map_or(String::new(), |sp| {
                format!(" (integrated over {:.1} mm)", (sp[1] - sp[0]) * 1e3)
            });
        let staged = s.stage.map_or(String::new(), |r| {
            format!(" (keel stage {}, dp {:.3} mm)", r.stage, r.dp_m * 1e3)
        });
        if s.summary.raw.value > 0.0 {
            println!(
                "  sensor {:8} {:.1} kPa at {:.3} ms{span}{staged}",
                s.name,
                s.summary.raw.value * 1e-3,
                s.summary.raw.time * 1e3
            );
            print_slamming_peaks(s, 1e-3, "kPa");
        } else {
            println!("  sensor {:8} not wetted during the run", s.name);
        }
    }
    // a flat keel with air has none: its transient ends at the run's (negative) start
    if summary.setup.air.is_some() && summary.contact_transient_end_s < 0.0 {
        println!(
            "contact transient: none (a flat keel with air meets the water through the air cushion; its \
             impact is read from the start of the run)"
        );
    } else {
        print_contact_transient(&summary);
    }
    if let (Some(wf), Some(wt), Some(wp)) = (
        summary.wagner_peak_force_n_per_m,
        summary.wagner_peak_force_time_s,
        summary.wagner_peak_pressure_pa,
    ) {
        println!(
            "Wagner (flat-plate, same v(t), up to full wetting): force {:.1} N/m at {:.3} ms, peak pressure {:.1} kPa",
            wf,
            wt * 1e3,
            wp * 1e-3
        );
    }
    if let Some(a) = &analytic {
        match a.peak {
            Some((f, t)) => println!(
                "analytic force  {f:.1} N/m at {:.3} ms ({}, same v(t))",
                t * 1e3,
                a.model
            ),
            None => println!("analytic force  no peak ({}, same v(t))", a.model),
        }
    }
    if let Some(conv) = &summary.convergence {
        println!(
            "convergence     (Roache GCI; companions in {}/convergence)",
            out.display()
        );
        for c in &conv.companions {
            if let Some(why) = &c.left_out {
                println!("  dp {:.3} mm left out: {why}", c.dp_m * 1e3);
            }
        }
        for p in &conv.peaks {
            println!("  {}", p.statement);
        }
    }
    for (k, st) in summary.stages.iter().enumerate() {
        println!(
            "keel stage {k}      {}: section cut at half-breadth {:.1} mm, dp {:.3} mm, {} fluid particles, \
             {} steps, {:.1} s{}",
            st.sensors.join(", "),
            st.cut_half_breadth_m * 1e3,
            st.dp_m * 1e3,
            st.fluid_particles,
            st.steps,
            st.wall_time_s,
            st.left_out
                .as_ref()
                .map_or(String::new(), |w| format!("; not used: {w}"))
        );
    }
    for w in &warnings {
        println!("{}", global::warning_line(w));
    }
    println!("{}", global::files_written_line(&out));
    Ok(())
}

/// The analytic section force of the run's section along its own downward velocity (the assessment's
/// estimate, [`slamtool::assess::analytic::section_force`]), or `None` for a tank without a body or where
/// the models do not take the section.
fn analytic_force(
    summary: &sph::RunSummary,
    h: &sph::sensors::History,
) -> Option<slamtool::assess::analytic::SectionForce> {
    let points = summary.setup.section_points.as_ref()?;
    let section = sph::body::Section::from_half_points(points.clone()).ok()?;
    let half = section.half_points();
    let rho = summary.setup.rho0;
    let w = slamtool::analytic::generalised_wagner::estimate(half, &h.t, &h.v_down, rho).ok()?;
    let m = slamtool::analytic::logvinovich_mlm::Mlm::new(half, &h.t, &h.v_down, rho).ok()?;
    Some(slamtool::assess::analytic::section_force(&w, &m))
}

/// The contact transient's line of an entry report.
fn print_contact_transient(summary: &sph::RunSummary) {
    println!(
        "contact transient (keel less than {} dp deep, up to {:.3} ms; acoustic, not a slamming load): \
         contour pressure up to {:.1} kPa at {:.3} ms, force up to {:.1} N/m",
        sph::CONTACT_TRANSIENT_DP,
        summary.contact_transient_end_s * 1e3,
        summary.contact_transient_pressure_pa * 1e-3,
        summary.contact_transient_pressure_time_s * 1e3,
        summary
            .force
            .summary
            .contact_transient
            .map_or(0.0, |p| p.value)
    );
}

/// The slamming peaks of a section run's record, raw and low-passed, in its impact window
/// ([`slamtool::loads::anatomy`]): the filtered one is the design quantity of an assessment.
fn print_slamming_peaks(s: &slamtool::sph::NamedSummary, scale: f64, unit: &str) {
    let peak_of =
        |a: &Option<slamtool::loads::anatomy::Anatomy>| a.as_ref().and_then(|a| a.slamming_peak);
    let Some(raw) = peak_of(&s.anatomy) else {
        return;
    };
    let filtered = match (peak_of(&s.filtered_anatomy), &s.summary.filter) {
        (Some(f), Some(lp)) => format!(
            "; filtered {:.1} {unit} at {:.3} ms ({:.0} Hz)",
            f.value * scale,
            f.time * 1e3,
            lp.cutoff_hz
        ),
        _ => String::new(),
    };
    println!(
        "    slamming peak in the impact window: raw {:.1} {unit} at {:.3} ms{filtered}",
        raw.value * scale,
        raw.time * 1e3
    );
}
