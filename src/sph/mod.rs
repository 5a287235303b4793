//! 2D weakly compressible SPH for the water entry of a rigid section (the `entry` step of the 2D+t
//! method; Veen 2010, ch. 5, with the formulation brought up to date as described in
//! `solver.rs`).
//!
//! Layers, in the order the data flows: [`case`] (what to run, automatic choices) -> [`tank`], [`body`]
//! (initial particles) -> [`solver`] (time loop: [`neighbours`], [`boundary`], [`diffusion`],
//! [`integrator`]) -> [`sensors`] (histories) -> [`output`] (files) and [`crate::loads`] (peaks).

pub mod air;
pub mod automatic;
pub mod body;
pub mod body_force;
pub mod boundary;
pub mod case;
pub mod case_file;
pub mod continuity_pass;
pub mod cost;
pub mod counters;
pub mod damping_zone;
pub mod diffusion;
pub mod dummy_band;
pub mod eos;
pub mod frame;
pub mod integrator;
pub mod keel_stage;
pub mod kernel;
pub mod kernel_correction;
pub mod neighbour_lists;
pub mod neighbours;
pub mod output;
pub mod output_dir;
pub mod pair_batch;
pub mod particles;
pub mod peak_snapshot;
pub mod phases;
pub mod rates;
pub mod refinement;
pub mod riemann;
pub mod sensors;
pub mod shifting;
pub mod solver;
pub mod study;
pub mod tank;
pub mod two_phase_pass;
pub mod vtu;
pub mod wall_wetness;

use std::path::{Path, PathBuf};
use std::time::Instant;

use serde::Serialize;

use crate::analytic::generalised_wagner;
use crate::error::{Error, Result};
use crate::files::write_text_atomic;
use crate::loads::peaks::{Summary, summarise_after};

pub use case::{Level, MotionSpec, Overrides, SensorMethod, Setup, TankLayout};
pub use counters::Counters;
pub use keel_stage::run_staged;
pub use sensors::{History, SensorSpec};
pub use solver::Simulation;
pub use study::{ConvergenceReport, StudyPlan, run_with_convergence};

/// What to write during and after a run.
#[derive(Debug, Clone, Default)]
pub struct RunOptions {
    /// Output folder; `None` writes nothing.
    pub out_dir: Option<PathBuf>,
    /// Where progress goes (nothing by default); the CLI draws it as a progress bar.
    pub progress: crate::progress::ProgressHandle,
    /// Write VTK snapshots (needs `snapshot_interval` in the setup).
    pub vtk: bool,
    /// Write PNG frames (needs `snapshot_interval` in the setup).
    pub png: bool,
    /// Provenance for the head of the CSV files (tool, commit, inputs, settings).
    pub provenance: Option<crate::provenance::Provenance>,
}

/// Peak of one recorded quantity.
#[derive(Debug, Clone, Serialize)]
pub struct NamedSummary {
    pub name: String,
    pub unit: String,
    /// A sensor's physical width along the contour (m).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub width_m: Option<f64>,
    /// A sensor's integration span [s0, s1] along the contour from the keel (m): its width, or
    /// [`sensors::MIN_WIDTH_DP`] dp when narrower.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub integration_span_m: Option<[f64; 2]>,
    #[serde(flatten)]
    pub summary: Summary,
    /// The record's phases and its slamming peak ([`crate::loads::anatomy`]), for a section run.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub anatomy: Option<crate::loads::anatomy::Anatomy>,
    /// The anatomy of the low-passed record (the run's physical cut-off, `summary.filter`), against the
    /// same impact window: its slamming peak is the filtered slamming peak, the design quantity of an
    /// assessment ([`crate::assess::design_rule`]). `None` when the run has no cut-off or no anatomy.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub filtered_anatomy: Option<crate::loads::anatomy::Anatomy>,
    /// The keel stage whose record this is, when one resolved the sensor ([`keel_stage`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stage: Option<keel_stage::StageRef>,
    /// With `stage`: the main run's largest value where it lies after the impact.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub main_run_later_load: Option<keel_stage::LaterLoad>,
}

/// The result of a run, written as `summary.json` and printed by `--json`.
#[derive(Debug, Clone, Serialize)]
pub struct RunSummary {
    pub name: String,
    pub tool_version: String,
    pub dp_m: f64,
    pub h_m: f64,
    #[serde(rename = "c0_m_per_s")]
    pub c0_m_s: f64,
    pub fluid_particles: usize,
    pub total_particles: usize,
    pub steps: u64,
    pub t_end_s: f64,
    pub wall_time_s: f64,
    /// Why the run stopped early, if it did.
    pub stopped_early: Option<String>,
    /// End of the contact transient: the time at which the keel is [`CONTACT_TRANSIENT_DP`] particle
    /// spacings deep. Every peak is taken after it; the largest values before it are reported apart.
    pub contact_transient_end_s: f64,
    /// Largest wall pressure on the contour after the contact transient (point value at the contour
    /// sampling), with time and place.
    pub peak_contour_pressure_pa: f64,
    pub peak_contour_pressure_time_s: f64,
    #[serde(rename = "peak_contour_pressure_girth_m")]
    pub peak_contour_pressure_s_m: f64,
    /// Largest contour pressure during the contact transient (the acoustic contact spike, of order
    /// rho c0 V; not a slamming pressure), with its time.
    pub contact_transient_pressure_pa: f64,
    pub contact_transient_pressure_time_s: f64,
    /// Whether the contour peak is the first sample after the contact transient (its tail).
    pub peak_contour_at_transient_end: bool,
    /// Vertical section force (N per metre of section).
    pub force: NamedSummary,
    pub sensors: Vec<NamedSummary>,
    /// Wagner theory (flat-plate approximation, Wagner condition for the actual shape) along the run's
    /// velocity history, up to full wetting: peak force (N/m) and peak pressure (Pa) with their times.
    pub wagner_peak_force_n_per_m: Option<f64>,
    pub wagner_peak_force_time_s: Option<f64>,
    pub wagner_peak_pressure_pa: Option<f64>,
    /// Caveats on what the run can represent (e.g. the single-phase limit at low deadrise).
    pub warnings: Vec<String>,
    /// The convergence statement of every peak, when the run was part of a study ([`study`]).
    pub convergence: Option<ConvergenceReport>,
    /// The keel stages run for the sensors this run crossed too early to resolve ([`keel_stage`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub stages: Vec<keel_stage::StageRecord>,
    pub counters: Counters,
    pub setup: Setup,
    /// Where the run came from (tool, commit, inputs, settings), when the caller gave it.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub provenance: Option<crate::provenance::Provenance>,
}

/// The clause that ends the error of a stopped run written to `dir`: where its histories are. Whoever
/// moves that folder (the assessment keeps a failed run's, `assess::cache::keep_failed`) rewrites the
/// clause with this same function.
pub fn histories_kept_in(dir: &std::path::Path) -> String {
    format!("; histories so far written to {}", dir.display())
}

/// The outcome of [`run`]: the summary and the full histories.
#[derive(Debug, Clone)]
pub struct RunResult {
    pub summary: RunSummary,
    pub history: History,
}

/// Run a resolved case to its end time, writing histories, summary and snapshots when an output folder is
/// given. A run that diverges stops with an error that says why; the histories up to that point are
/// written first.
///
/// The run's time loop executes on a thread of rayon's pool (already there when the caller is a
/// parallel job, such as an assessment's run): its passes are parallel loops, and each one started from
/// a thread outside the pool would hand its work to the pool and wait to be woken, about a tenth of a
/// small run's time (measured on Ochi 0.174 Lpp with air, `perf`). Where the loop runs changes no number.
pub fn run(setup: Setup, opts: &RunOptions) -> Result<RunResult> {
    rayon::scope(|_| run_in_pool(setup, opts))
}

/// [`run`], on the calling thread.
fn run_in_pool(setup: Setup, opts: &RunOptions) -> Result<RunResult> {
    let wall = Instant::now();
    let mut sim = Simulation::new(setup)?;
    let t_end = sim.setup.t_end;
    let snap = sim.setup.snapshot_interval.filter(|_| opts.vtk || opts.png);
    let mut frames: Vec<(f64, String)> = Vec::new();
    let mut next_snap = 0.0;
    let progress_sink = opts.progress.clone();
    progress_sink.start(&sim.setup.name, t_end * 1e3, "ms");
    let mut progress = |s: &Simulation| {
        progress_sink.update(
            s.time * 1e3,
            &format!("step {}, section force {:.0} N/m", s.steps, s.body.fz),
        );
    };
    let mut stopped = None;
    // The particle state at the highest sensor pressure, kept only when there is a folder to draw it in.
    let mut peak = opts
        .out_dir
        .as_ref()
        .map(|_| peak_snapshot::PeakSnapshot::default());
    loop {
        if let (Some(dt_snap), Some(dir)) = (snap, &opts.out_dir)
            && sim.time >= next_snap - 1e-12
        {
            let t0 = Instant::now();
            write_snapshot(&sim, dir, frames.len(), opts, &mut frames)?;
            next_snap += dt_snap;
            sim.counters.add(counters::Stage::Output, t0.elapsed());
        }
        if sim.time >= t_end - 1e-12 {
            break;
        }
        let stop = match snap {
            Some(_) => next_snap.min(t_end),
            None => t_end,
        };
        let watched = match &mut peak {
            Some(w) => sim.run_until_watching(stop, 50, &mut progress, &mut |s| w.observe(s)),
            None => sim.run_until(stop, 50, &mut progress),
        };
        if let Err(why) = watched {
            stopped = Some(why);
            break;
        }
    }
    opts.progress.finish();
    // The histories first: whatever fails after the time loop, they are on disk.
    if let Some(dir) = &opts.out_dir {
        let csv = output::history_csv(&sim.history, opts.provenance.as_ref())?;
        write_text_atomic(&dir.join("history.csv"), &csv)?;
        if let Some(w) = &peak {
            w.write(&sim, dir)?;
        }
    }
    let mut summary =
        summarise_run(&sim, wall.elapsed().as_secs_f64(), stopped.clone()).map_err(|e| {
            let where_ = opts.out_dir.as_ref().map_or(String::new(), |d| {
                format!(" (the histories are in {})", d.join("history.csv").display())
            });
            Error::Numerical(format!(
                "SPH run '{}' finished its time loop at t = {:.6} s, but its summary failed: {e}{where_}",
                sim.setup.name, sim.time
            ))
        })?;
    summary.provenance = opts.provenance.clone();
    if let Some(dir) = &opts.out_dir {
        let json = serde_json::to_string_pretty(&summary).expect("summary serialises");
        write_text_atomic(&dir.join("summary.json"), &json)?;
        if !frames.is_empty() && opts.vtk {
            output::write_pvd(&dir.join("particles.pvd"), &frames)?;
        }
    }
    if let Some(why) = stopped {
        let where_ = opts
            .out_dir
            .as_ref()
            .map_or(String::new(), |d| histories_kept_in(d));
        return Err(Error::Numerical(format!(
            "SPH run '{}' stopped at t = {:.6} s: {why}{where_}",
            sim.setup.name, sim.time
        )));
    }
    Ok(RunResult {
        summary,
        history: sim.history.clone(),
    })
}

fn write_snapshot(
    sim: &Simulation,
    dir: &Path,
    k: usize,
    opts: &RunOptions,
    frames: &mut Vec<(f64, String)>,
) -> Result<()> {
    if opts.vtk {
        let name = format!("particles_{k:04}.vtu");
        output::write_vtu(&dir.join(&name), &sim.pt)?;
        frames.push((sim.time, name));
    }
    if opts.png {
        let frame = peak_snapshot::frame_at(sim, sim.body.z_keel, sim.time);
        output::write_png(&dir.join(format!("frame_{k:04}.png")), &sim.pt, &frame)?;
    }
    Ok(())
}

fn summarise_run(sim: &Simulation, wall_s: f64, stopped: Option<String>) -> Result<RunSummary> {
    let h = &sim.history;
    let s = &sim.setup;
    let fc = s.filter_cutoff_hz;
    let phases = sim.section().map(|sec| {
        phases::RunPhases::new(
            sec,
            h,
            s.dp,
            s.c0,
            s.rho0,
            s.initial_immersion,
            contact_transient_end(h, s.dp),
        )
        .with_air(s.air.is_some())
    });
    // (a flat keel with air has none: [`phases::RunPhases::with_air`])
    let t_tr = phases
        .as_ref()
        .map_or_else(|| contact_transient_end(h, s.dp), |p| p.transient_end_s);
    let mut force = NamedSummary {
        name: "section force".into(),
        unit: "N/m".into(),
        width_m: None,
        integration_span_m: None,
        summary: summarise_after(&h.t, &h.fz, fc, t_tr)?,
        anatomy: phases.as_ref().map(|p| p.force()),
        filtered_anatomy: None,
        stage: None,
        main_run_later_load: None,
    };
    if let (Some(p), Some(lp)) = (&phases, &force.summary.filter) {
        let (tu, y) = crate::loads::filtered_record(&h.t, &h.fz, lp);
        force.filtered_anatomy = Some(p.force_record(&tu, &y));
    }
    let mut sensors = Vec::new();
    let spans = sim.sensors().spans();
    for (k, (name, col)) in h.sensor_names.iter().zip(&h.sensors).enumerate() {
        let span = spans.get(k).copied();
        let summary = summarise_after(&h.t, col, fc, t_tr)?;
        let filtered_anatomy = match (&phases, span, &summary.filter) {
            (Some(p), Some(span), Some(lp)) => {
                let (tu, y) = crate::loads::filtered_record(&h.t, col, lp);
                Some(p.sensor_record(span, &tu, &y))
            }
            _ => None,
        };
        sensors.push(NamedSummary {
            name: name.clone(),
            unit: "Pa".into(),
            width_m: s.sensors.get(k).map(|x| x.width_m),
            integration_span_m: span,
            summary,
            anatomy: phases
                .as_ref()
                .zip(span)
                .map(|(p, span)| p.sensor(span, col)),
            filtered_anatomy,
            stage: None,
            main_run_later_load: None,
        });
    }
    let k_tr = h.t.partition_point(|&t| t < t_tr);
    let arg_max = |r: std::ops::Range<usize>| {
        r.max_by(|&a, &b| h.p_contour_max[a].total_cmp(&h.p_contour_max[b]))
    };
    let kmax = arg_max(k_tr..h.len()).unwrap_or(0);
    let ktr = arg_max(0..k_tr);
    let (mut wf, mut wft, mut wp) = (None, None, None);
    let mut warnings: Vec<String> = single_phase_warning(sim)
        .into_iter()
        .chain(widened_sensor_warning(&sensors))
        .collect();
    if let Some(sec) = sim.section() {
        match generalised_wagner::estimate(sec.half_points(), &h.t, &h.v_down, s.rho0) {
            Ok(e) => {
                // Wagner's own values only: the acoustic-limit samples are in the warnings below.
                if let Some((f, t)) = e.force_peak() {
                    wf = Some(f);
                    wft = Some(t);
                }
                wp = e.pressure_peak();
                if e.acoustic_limited.iter().any(|&a| a) {
                    warnings.extend(e.notes.iter().map(|n| format!("Wagner estimate: {n}")));
                }
            }
            Err(err) => warnings.push(format!("no Wagner estimate: {err}")),
        }
    }
    Ok(RunSummary {
        name: s.name.clone(),
        tool_version: env!("CARGO_PKG_VERSION").into(),
        dp_m: s.dp,
        h_m: sim.kernel.h(),
        c0_m_s: s.c0,
        fluid_particles: sim.n_fluid(),
        total_particles: sim.pt.len(),
        steps: sim.steps,
        t_end_s: sim.time,
        wall_time_s: wall_s,
        stopped_early: stopped,
        contact_transient_end_s: t_tr,
        peak_contour_at_transient_end: kmax == k_tr && k_tr + 1 < h.len(),
        contact_transient_pressure_pa: ktr.map_or(0.0, |k| h.p_contour_max[k]),
        contact_transient_pressure_time_s: ktr.map_or(0.0, |k| h.t[k]),
        peak_contour_pressure_pa: h.p_contour_max.get(kmax).copied().unwrap_or(0.0),
        peak_contour_pressure_time_s: h.t.get(kmax).copied().unwrap_or(0.0),
        peak_contour_pressure_s_m: h.s_at_p_max.get(kmax).copied().unwrap_or(0.0),
        force,
        sensors,
        wagner_peak_force_n_per_m: wf,
        wagner_peak_force_time_s: wft,
        wagner_peak_pressure_pa: wp,
        warnings,
        convergence: None,
        stages: Vec::new(),
        counters: sim.counters.clone(),
        setup: s.clone(),
        provenance: None,
    })
}

/// Keel penetration, in particle spacings, up to which a run is in its contact transient (see
/// [`crate::loads::peaks::Summary::contact_transient`]). Over the first spacings of penetration the body
/// meets the water through the kernel support and the weakly compressible fluid answers with an acoustic
/// pressure of order rho c0 V that is the same at every resolution: on a 30 deg wedge at constant speed
/// the contour pressure peaks at about 0.3 rho c0 V within the first 0.2-0.5 ms, at every spacing.
pub const CONTACT_TRANSIENT_DP: f64 = 2.0;

/// The time at which the keel is [`CONTACT_TRANSIENT_DP`] dp below the calm surface (the end of the
/// record if it never gets there). For a section immersed at the start the penetration counts from
/// there: the transient is then the start of the motion, when the fluid at rest is set moving.
fn contact_transient_end(h: &History, dp: f64) -> f64 {
    let depth = CONTACT_TRANSIENT_DP * dp;
    // From the calm surface for a keel that starts above it (a run with an air gap).
    let z0 = h.z_keel.first().copied().unwrap_or(0.0).min(0.0);
    h.z_keel
        .iter()
        .position(|&z| z0 - z >= depth)
        .map_or(h.t.last().copied().unwrap_or(0.0), |k| h.t[k])
}

/// Opening of the warning that lists the sensors integrated over a span wider than themselves
/// ([`widened_sensor_warning`]).
pub const WIDENED_SENSORS: &str = "sensors integrated over a span wider than themselves";

/// One warning listing every sensor whose integration span is more than 10 % wider than the sensor (it
/// is narrower than [`sensors::MIN_WIDTH_DP`] spacings of the run that recorded it: the main run, or
/// the keel stage whose record it took), with the span; `None` when there is none. A span within 10 %
/// of the sensor's width reads the same pressure and is not listed.
pub fn widened_sensor_warning(sensors: &[NamedSummary]) -> Option<String> {
    let list: Vec<String> = sensors
        .iter()
        .filter_map(|q| {
            let (w, [a, b]) = (q.width_m?, q.integration_span_m?);
            (b - a > 1.1 * w).then(|| {
                let stage = q
                    .stage
                    .map_or(String::new(), |r| format!(", keel stage {}", r.stage));
                format!(
                    "{} ({:.1} mm wide, over {:.1} mm: s = {:.4}-{:.4} m{stage})",
                    q.name,
                    w * 1e3,
                    (b - a) * 1e3,
                    a,
                    b
                )
            })
        })
        .collect();
    (!list.is_empty()).then(|| {
        format!(
            "{WIDENED_SENSORS}: {}. A sensor narrower than {} particle spacings reads the passage of \
             single particles at the jet root and its peak is biased high, so each is integrated over {} \
             spacings about its centre (docs/guide/numerics.md)",
            list.join("; "),
            sensors::MIN_WIDTH_DP,
            sensors::MIN_WIDTH_DP
        )
    })
}

/// Deadrise below which single-phase SPH is known to over-predict the peak pressure.
pub const AIR_CUSHION_DEADRISE_DEG: f64 = 20.0;

/// Single-phase SPH has no air: below about 15-20 deg of deadrise the air trapped and compressed under
/// the body cushions the impact, and a water-only model over-predicts the peak, by about 2x for Breder's
/// 10 deg wedge and for Ochi's flat-bottomed section at 0.174 Lpp (Veen 2010, ch. 6). The warning is
/// raised when the part of the contour that was wetted (Wagner's wetted depth, pi/2 times the keel's
/// penetration) has a smaller local deadrise than [`AIR_CUSHION_DEADRISE_DEG`].
///
/// A run with air ([`air`]) has a cushion instead; its low-deadrise note then says what was run, that a
/// flat keel's cushion peak depends on the artificial sound speed, and that it is not validated against a
/// measured cushion.
fn single_phase_warning(sim: &Simulation) -> Option<String> {
    let sec = sim.section()?;
    let depth = (-sim.history.z_keel.iter().copied().fold(0.0, f64::min)).max(0.0);
    if depth <= 0.0 {
        return None;
    }
    let beta = sec
        .min_deadrise_below(std::f64::consts::FRAC_PI_2 * depth)
        .to_degrees();
    if beta < AIR_CUSHION_DEADRISE_DEG && sim.air.is_some() {
        return Some(format!(
            "the wetted contour has a local deadrise of {beta:.1} deg (below {AIR_CUSHION_DEADRISE_DEG} deg): this run \
             has air as a second phase ({} air particles, the keel starting {:.1} mm above the calm surface); on a \
             flat keel its cushion peak grows with the water's artificial sound speed (docs/guide/air.md), so \
             it is a model result, not a converged cushion pressure, and it is not checked against a measured \
             cushion",
            sim.n_air(),
            sim.setup.air.map_or(0.0, |a| a.clearance) * 1e3
        ));
    }
    (beta < AIR_CUSHION_DEADRISE_DEG).then(|| {
        format!(
            "the wetted contour has a local deadrise of {beta:.1} deg (below {AIR_CUSHION_DEADRISE_DEG} deg): \
             single-phase SPH has no air cushion and over-predicts peak pressures there (about 2x for \
             Breder's 10 deg wedge and Ochi's flat section, Veen 2010)"
        )
    })
}
