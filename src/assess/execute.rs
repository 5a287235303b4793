//! Running an assessment: the analytic estimate of every event, then the SPH runs the fidelity asks for,
//! in parallel over events (rayon; each run is deterministic and results are collected in plan order, so
//! they do not depend on the number of threads), each through the [`cache`]. A run that fails is recorded
//! with its reason and the others finish.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

use rayon::prelude::*;

use super::analytic;
use super::cache;
use super::plan::{self, Event, Fidelity, Plan, Settings};
use super::results::{self, Assessment, EventResult, SphRecord, SphSensor};
use crate::error::{Error, Result};
use crate::hull::Hull;
use crate::loads::anatomy::ImpactStatus;
use crate::loads::cutoff;
use crate::progress::ProgressHandle;
use crate::provenance::Provenance;
use crate::sea::SeaState;
use crate::sph::body::Section;
use crate::sph::{self, RunOptions, RunSummary, StudyPlan};

/// The convergence of the peak called `name` in a run's convergence report.
fn convergence_of<'a>(
    s: &'a RunSummary,
    name: &str,
) -> Option<&'a crate::loads::convergence::PeakConvergence> {
    s.convergence
        .as_ref()?
        .peaks
        .iter()
        .find(|p| p.name == name)
}

/// For a peak whose convergence levels show different events (verdict `mismatched`): |P_2 - P| / |P|,
/// with P the reported peak and P_2 the next level's ([`crate::assess::design_rule`]); `None` otherwise
/// or when either has no peak.
fn mismatch_spread(s: &RunSummary, name: &str) -> Option<f64> {
    let p = convergence_of(s, name)?;
    if p.verdict != crate::loads::convergence::Verdict::Mismatched {
        return None;
    }
    match p.values.as_slice() {
        [v, v2, ..] if *v > 0.0 && *v2 > 0.0 => Some((v2 - v).abs() / v),
        _ => None,
    }
}

/// The verdict and statement of the peak called `name` in a run's convergence report.
fn verdict(s: &RunSummary, name: &str) -> (Option<String>, Option<String>) {
    match convergence_of(s, name) {
        Some(p) => (
            serde_json::to_value(p.verdict)
                .ok()
                .and_then(|v| v.as_str().map(str::to_string)),
            Some(p.statement.clone()),
        ),
        None => (None, None),
    }
}

/// The record of one quantity the design rule reads ([`crate::assess::design_rule`]): the slamming peak
/// of the low-passed record where the run has a physical cut-off ([`cutoff::slamming_cutoff`]) and the
/// record an anatomy, with the convergence statement of that filtered slamming peak; otherwise the raw
/// record's. Content faster than the quickest physical rise of the event is the acoustic and particle
/// noise of weakly compressible SPH, which does not converge with the spacing: a single spike of one
/// level would otherwise decide the peak, its GCI and its verdict.
struct DesignRecord<'a> {
    anatomy: Option<&'a crate::loads::anatomy::Anatomy>,
    /// The name of the peak in the run's convergence report.
    name: String,
    filtered: bool,
}

impl<'a> DesignRecord<'a> {
    fn of(label: &str, q: &'a sph::NamedSummary) -> Self {
        match (&q.filtered_anatomy, &q.summary.filter) {
            (Some(a), Some(lp)) => Self {
                anatomy: Some(a),
                name: format!("{label} filtered {:.0} Hz", lp.cutoff_hz),
                filtered: true,
            },
            _ => Self {
                anatomy: q.anatomy.as_ref(),
                name: format!("{label} raw"),
                filtered: false,
            },
        }
    }
}

/// What the assessment keeps of a finished run.
fn record(key: &str, s: &RunSummary) -> SphRecord {
    let v_max = s
        .setup
        .motion
        .as_ref()
        .and_then(|m| m.build().ok())
        .map_or(0.0, |m| m.max_speed(s.t_end_s));
    let dry_below = results::DRY_FRACTION * 0.5 * s.setup.rho0 * v_max * v_max;
    let gci = |name: &str| convergence_of(s, name).and_then(|p| p.gci);
    let fd = DesignRecord::of("section force", &s.force);
    let fa = fd.anatomy;
    let (force_convergence, force_statement) = verdict(s, &fd.name);
    SphRecord {
        key: key.to_string(),
        dp_m: s.dp_m,
        filter_cutoff_hz: s.setup.filter_cutoff_hz,
        filter_rule: s
            .setup
            .notes
            .iter()
            .find(|n| n.contains("low-pass"))
            .cloned(),
        force_peak_n_per_m: s.force.summary.raw.value,
        force_peak_time_s: s.force.summary.raw.time,
        force_convergence,
        force_slamming_peak_n_per_m: fa.and_then(|a| a.slamming_peak.map(|p| p.value)),
        force_slamming_time_s: fa.and_then(|a| a.slamming_peak.map(|p| p.time)),
        force_hydrostatic_n_per_m: fa.and_then(|a| a.hydrostatic_at_peak),
        force_gci: gci(&fd.name),
        force_spread: mismatch_spread(s, &fd.name),
        force_convergence_statement: force_statement,
        force_slamming_filtered: fd.filtered,
        force_raw_slamming_peak_n_per_m: s
            .force
            .anatomy
            .as_ref()
            .and_then(|a| a.slamming_peak.map(|p| p.value)),
        sensors: s
            .sensors
            .iter()
            .map(|q| {
                let label = format!("sensor {}", q.name);
                let d = DesignRecord::of(&label, q);
                let (c, st) = verdict(s, &d.name);
                let a = d.anatomy;
                let slam = a.and_then(|a| a.slamming_peak);
                let raw_slam = q.anatomy.as_ref().and_then(|a| a.slamming_peak);
                // wetted: the raw slamming peak (or, without an anatomy, the largest value) reaches a
                // slamming pressure
                let reached = raw_slam.map_or(q.summary.raw.value, |p| p.value);
                // A keel stage's record covers the early entry only: the main run's later load, when
                // larger, is the largest value the panel carries.
                let later = q
                    .main_run_later_load
                    .filter(|l| l.value > q.summary.raw.value);
                SphSensor {
                    name: q.name.clone(),
                    raw_peak_pa: later.map_or(q.summary.raw.value, |l| l.value),
                    filtered_peak_pa: q.summary.filtered.map(|f| f.value),
                    peak_time_s: later.map_or(q.summary.raw.time, |l| l.time_s),
                    impulse_pa_s: q.summary.raw.impulse,
                    convergence: c,
                    convergence_statement: st,
                    wetted: reached >= dry_below
                        || a.is_some_and(|a| {
                            !matches!(a.status, ImpactStatus::Resolved | ImpactStatus::Cushioned)
                        }),
                    still_rising: q.summary.at_record_end,
                    impact: a.map(|a| a.status),
                    impact_window_s: a.and_then(|a| a.window.map(|w| [w.start_s, w.end_s])),
                    slamming_peak_pa: slam.map(|p| p.value),
                    slamming_peak_time_s: slam.map(|p| p.time),
                    slamming_impulse_pa_s: slam.map(|p| p.impulse),
                    slamming_filtered: d.filtered,
                    raw_slamming_peak_pa: raw_slam.map(|p| p.value),
                    raw_convergence: verdict(s, &format!("{label} raw")).0,
                    rising_at_window_end: a.is_some_and(|a| a.at_window_end),
                    rise_time_s: a.and_then(|a| a.rise_time_s),
                    hydrostatic_pa: a.and_then(|a| a.hydrostatic_at_peak),
                    largest_phase: match later {
                        Some(_) => Some(crate::loads::anatomy::Phase::Immersion),
                        None => q.anatomy.as_ref().map(|a| a.largest_phase),
                    },
                    largest_hydrostatic_pa: match later {
                        Some(l) => l.hydrostatic,
                        None => q.anatomy.as_ref().and_then(|a| a.hydrostatic_at_largest),
                    },
                    gci: gci(&d.name),
                    spread: mismatch_spread(s, &d.name),
                    particles_across_wetted: a.and_then(|a| {
                        a.crossing_half_width_m
                            .map(|c| c / q.stage.map_or(s.dp_m, |r| r.dp_m))
                    }),
                    stage_dp_m: q.stage.map(|r| r.dp_m),
                    local_deadrise_deg: a.and_then(|a| a.local_deadrise_deg),
                }
            })
            .collect(),
        stopped_early: s.stopped_early.clone(),
        warnings: s.warnings.clone(),
        air: air_statement(s),
    }
}

/// Whether a run had air, and why: the air choice's note and the layer's (None when air was off; with
/// `--air auto` on a section that did not need it, the note that says so).
fn air_statement(s: &RunSummary) -> Option<String> {
    let notes: Vec<&str> = sph::air::notes(&s.setup.notes).collect();
    (!notes.is_empty()).then(|| notes.join("; "))
}

/// The sensor method of an assessment's SPH runs unless `--sensor-method` says otherwise: the force
/// panel, the method whose wedge pressures the validation suite measures (every wedge pressure case of
/// `validate` uses it), so that the design rests on what is validated.
pub const DESIGN_SENSOR_METHOD: sph::SensorMethod = sph::SensorMethod::ForcePanel;

/// An option of the wall-resolved scheme as the settings record it: the value given, else the default
/// ([`crate::sph::case::single_phase_default`]: on in single-phase runs, off in runs with air).
fn scheme_setting(given: Option<bool>) -> serde_json::Value {
    match given {
        Some(b) => serde_json::json!(b),
        None => serde_json::json!("default: on in single-phase runs, off in runs with air"),
    }
}

/// The SPH setup of an event: the section, its v(t) and sensors, the automatic choices of the solver
/// (resolution, tank, sound speed, end time) and the physical low-pass cut-off of its sensor records
/// ([`cutoff::slamming_cutoff`]) unless the overrides give one.
fn event_setup(
    e: &Event,
    overrides: &sph::Overrides,
    study: StudyPlan,
    rho: f64,
) -> Result<sph::case::Setup> {
    let case = e
        .entry
        .as_ref()
        .ok_or_else(|| Error::Invalid("no water entry to run".into()))?;
    let section = Section::from_half_points(case.half_points.clone())?;
    let overrides = sph::Overrides {
        initial_immersion: (case.immersion_m > 0.0).then_some(case.immersion_m),
        ..overrides.clone()
    };
    let mut setup = sph::case::resolve(
        &e.label(),
        &section,
        &case.motion,
        case.sensors.clone(),
        &overrides,
    )?;
    setup.rho0 = rho;
    setup.sensor_method = overrides.sensor_method.unwrap_or(DESIGN_SENSOR_METHOD);
    if setup.filter_cutoff_hz.is_none() {
        let (t, v) = analytic::samples(&case.motion)?;
        let coarsest = setup.nominal_sample_hz() / study.ratio.powi(study.levels as i32 - 1);
        let c = cutoff::slamming_cutoff(
            &section,
            case.immersion_m,
            &t,
            &v,
            &setup.sensors,
            setup.c0,
            coarsest,
        );
        setup.filter_cutoff_hz = c.hz;
        setup.notes.push(c.note);
    }
    Ok(setup)
}

/// One SPH run of an event's `setup` (cache key `key`), committed to the cache.
fn sph_event(
    setup: sph::case::Setup,
    key: &str,
    out: &Path,
    study: StudyPlan,
) -> Result<SphRecord> {
    let tmp = cache::temporary(out, key)?;
    let opts = RunOptions {
        out_dir: Some(tmp.clone()),
        ..Default::default()
    };
    let r = match sph::run_staged(setup, &opts, study) {
        Ok(r) => r,
        Err(err) => return Err(cache::keep_failed(out, key, &tmp, err)),
    };
    let rec = record(key, &r.summary);
    cache::commit(out, key, &tmp, &rec)?;
    Ok(rec)
}

/// An SPH run the assessment will make: its event, setup and cache key, and its record when the cache
/// already holds it (and may be used).
struct Job {
    event: usize,
    setup: Result<(sph::case::Setup, String)>,
    cached: Option<SphRecord>,
}

/// The up-front cost of the SPH runs of an assessment that are not in the cache: how many, their
/// particle-steps (with the convergence companions) and the estimated wall time on `threads` threads.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cost {
    pub runs: usize,
    pub cached: usize,
    pub particle_steps: f64,
    pub wall_s: f64,
    pub threads: usize,
}

impl Cost {
    /// One line for the terminal.
    pub fn describe(&self) -> String {
        format!(
            "{} SPH run(s) to make ({} already in the cache): {:.2e} particle-steps with the convergence \
             companions, estimated wall time {} on {} thread(s), not counting the keel stages a run may add \
             once it has shown which sensors it leaves unresolved",
            self.runs,
            self.cached,
            self.particle_steps,
            sph::cost::human_time(self.wall_s),
            self.threads
        )
    }
}

fn cost_of(jobs: &[Job], study: StudyPlan, threads: usize) -> Cost {
    let mut c = Cost {
        runs: 0,
        cached: 0,
        particle_steps: 0.0,
        wall_s: 0.0,
        threads: threads.max(1),
    };
    let mut work = 0.0;
    for j in jobs {
        match (&j.setup, &j.cached) {
            (Ok(_), Some(_)) => c.cached += 1,
            (Ok((setup, _)), None) => {
                c.runs += 1;
                let e = sph::cost::estimate(setup, study, 1);
                c.particle_steps += e.particle_steps;
                work += e.uniform_equivalent;
            }
            (Err(_), _) => {}
        }
    }
    c.wall_s = sph::cost::wall_time(work, c.threads);
    c
}

/// What the SPH section force of a flare event holds besides the slam: the hydrostatic buoyancy of the
/// section immersed at the start (rho g A, A the immersed area at the keel depth, from the hull
/// section), which the analytic force leaves out; its value at the start and at the SPH force
/// peak (keel depth d0 + integral of V).
fn buoyancy_note(d0: f64, case: &plan::EntryCase, t_peak: f64, rho: f64) -> String {
    let sec = crate::hull::Section::new(case.half_points.clone());
    let table = match &case.motion {
        sph::MotionSpec::Prescribed { table } => table.as_slice(),
        _ => &[],
    };
    let mut depth = d0;
    for w in table.windows(2) {
        let (a, b) = (w[0], w[1]);
        if a[0] >= t_peak {
            break;
        }
        let tb = b[0].min(t_peak);
        let vb = a[1] + (b[1] - a[1]) * (tb - a[0]) / (b[0] - a[0]).max(f64::MIN_POSITIVE);
        depth += 0.5 * (a[1] + vb) * (tb - a[0]);
    }
    let rho_g = rho * 9.81;
    let at = |d: f64| rho_g * sec.properties(sec.keel_z() + d).area;
    format!(
        "flare event: the SPH section force includes the hydrostatic buoyancy of the immersed section, rho g A \
         = {:.1} N/m at the start (keel {d0:.4} m deep) and {:.1} N/m at the force peak (keel {depth:.4} m \
         deep, t = {t_peak:.4} s); the slamming part is the difference, and the analytic force has no \
         buoyancy",
        at(d0),
        at(depth)
    )
}

/// Whether the analytic estimate stopping early matters to the design: a sensor of the event has no
/// analytic peak (the models stopped before reaching it).
fn stop_matters(e: &Event, a: &analytic::Estimate) -> bool {
    e.entry.as_ref().is_some_and(|c| {
        c.sensors.iter().any(|q| {
            a.sensors
                .iter()
                .find(|s| s.name == q.name)
                .is_none_or(|s| s.peak_pa <= 0.0)
        })
    })
}

/// The events that get an SPH run: every emerging one (`sph`), the governing one of each station by the
/// analytic estimate (`screen`), or none (`analytic`).
fn sph_events(plan: &Plan, estimates: &[Option<analytic::Estimate>], f: Fidelity) -> Vec<usize> {
    let emerging = (0..plan.events.len()).filter(|&i| plan.events[i].entry.is_some());
    match f {
        Fidelity::Analytic => Vec::new(),
        Fidelity::Sph => emerging.collect(),
        Fidelity::Screen => {
            let mut out = Vec::new();
            for &st in &plan.stations {
                let best = (0..plan.events.len())
                    .filter(|&i| {
                        plan.events[i].entry.is_some() && (plan.events[i].station - st).abs() < 1e-9
                    })
                    .max_by(|&a, &b| {
                        let r = |i: usize| estimates[i].as_ref().map_or(0.0, |e| e.ranking());
                        r(a).total_cmp(&r(b)).then(b.cmp(&a))
                    });
                out.extend(best);
            }
            out.sort_unstable();
            out
        }
    }
}

/// Run an assessment of `hull` in `sea` into the folder `out` (created if needed), with progress (runs
/// done of the total) on `progress`, and write its `summary.json` and `pressures.csv` there.
pub fn run(
    hull: &Hull,
    sea: &SeaState,
    s: &Settings,
    out: &Path,
    progress: &ProgressHandle,
) -> Result<(Assessment, Vec<PathBuf>)> {
    let plan = plan::plan(hull, sea, s)?;
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    cache::sweep(out);
    // In parallel over events, collected in plan order (independent of the thread count).
    let computed: Vec<Option<Result<analytic::Estimate>>> = plan
        .events
        .par_iter()
        .map(|e| e.entry.as_ref().map(|c| analytic::estimate_in(c, plan.rho)))
        .collect();
    let analytic_errors: Vec<Option<String>> = computed
        .iter()
        .map(|r| match r {
            Some(Err(err)) => Some(format!("no analytic estimate: {err}")),
            _ => None,
        })
        .collect();
    let estimates: Vec<Option<analytic::Estimate>> = computed
        .into_iter()
        .map(|r| r.and_then(|x| x.ok()))
        .collect();
    let jobs: Vec<Job> = sph_events(&plan, &estimates, s.fidelity)
        .into_par_iter()
        .map(|i| {
            let setup = event_setup(&plan.events[i], &s.overrides, s.study, plan.rho)
                .and_then(|st| cache::key(&st, &s.study).map(|k| (st, k)));
            let cached = match &setup {
                Ok((_, k)) if s.use_cache => cache::lookup(out, k),
                _ => None,
            };
            Job {
                event: i,
                setup,
                cached,
            }
        })
        .collect();
    // Cache records whose checksum fails are computed again, and the assessment says so.
    let rejected: Vec<(usize, String)> = jobs
        .iter()
        .filter(|j| j.cached.is_none() && s.use_cache)
        .filter_map(|j| cache::rejection(out, &j.setup.as_ref().ok()?.1).map(|m| (j.event, m)))
        .collect();
    rejected.iter().for_each(|r| progress.note(&r.1));
    let threads = s.threads.unwrap_or_else(rayon::current_num_threads).max(1);
    let cost = cost_of(&jobs, s.study, threads);
    if !jobs.is_empty() {
        progress.note(&cost.describe());
    }
    if let Some(bound) = s.max_wall_s
        && cost.wall_s > bound
    {
        return Err(Error::Invalid(format!(
            "this assessment would take about {} ({}): more than the {} bound. Choose a coarser \
             --resolution, fewer --station or --speeds, or --fidelity screen, or give --force to run it anyway",
            sph::cost::human_time(cost.wall_s),
            cost.describe(),
            sph::cost::human_time(bound)
        )));
    }
    let used: std::collections::BTreeSet<String> = jobs
        .iter()
        .filter_map(|j| j.setup.as_ref().ok().map(|(_, k)| k.clone()))
        .collect();
    let done = AtomicUsize::new(0);
    if !jobs.is_empty() {
        progress.start("assessment runs", jobs.len() as f64, "runs");
    }
    let work = || -> Vec<(usize, Result<SphRecord>)> {
        jobs.into_par_iter()
            .map(|j| {
                let r = match j.cached {
                    Some(rec) => Ok(rec),
                    None => j
                        .setup
                        .and_then(|(st, key)| sph_event(st, &key, out, s.study)),
                };
                let n = done.fetch_add(1, Ordering::Relaxed) + 1;
                progress.update(n as f64, &plan.events[j.event].label());
                (j.event, r)
            })
            .collect()
    };
    let ran = match s.threads {
        Some(n) => rayon::ThreadPoolBuilder::new()
            .num_threads(n.max(1))
            .build()
            .map_err(|e| Error::Invalid(format!("thread pool: {e}")))?
            .install(work),
        None => work(),
    };
    if !ran.is_empty() {
        progress.finish();
    }
    if let Some(note) = cache::tidy(out, &used, s.unused_cache)? {
        progress.note(&note);
    }
    let mut sph_of: Vec<Option<Result<SphRecord>>> = plan.events.iter().map(|_| None).collect();
    for (i, r) in ran {
        sph_of[i] = Some(r);
    }
    let mut events = Vec::new();
    for (i, e) in plan.events.iter().enumerate() {
        let mut warnings = Vec::new();
        warnings.extend(analytic_errors[i].clone());
        warnings.extend(rejected.iter().filter(|r| r.0 == i).map(|r| r.1.clone()));
        let (sph, failed) = match sph_of[i].take() {
            Some(Ok(r)) => {
                if let Some(why) = &r.stopped_early {
                    warnings.push(format!("the SPH run stopped early: {why}"));
                }
                // the run's Wagner notes repeat the analytic estimate's (in `analytic.notes`)
                warnings.extend(
                    r.warnings
                        .iter()
                        .filter(|w| !w.starts_with("Wagner estimate:"))
                        .cloned(),
                );
                (Some(r), None)
            }
            Some(Err(err)) => (None, Some(format!("SPH run failed: {err}"))),
            None => (None, None),
        };
        // The analytic estimate's notes (where the models stop, the acoustic stage of a flat keel) stay
        // in `analytic.notes`: they explain the model, and ask nothing of the reader; the stop before the
        // end of the entry does, where a sensor lies beyond it.
        if let Some(a) = &estimates[i] {
            warnings.extend(
                a.notes
                    .iter()
                    .filter(|n| n.starts_with("Wagner estimate stops early") && stop_matters(e, a))
                    .map(|n| format!("analytic: {n}")),
            );
        }
        if let Some(r) = &sph {
            warnings.extend(results::sensor_warnings(r, estimates[i].as_ref()));
        }
        if let (Some(f), Some(r), Some(case)) = (&e.flare, &sph, &e.entry) {
            warnings.push(buoyancy_note(
                f.immersion_m,
                case,
                r.force_peak_time_s,
                plan.rho,
            ));
        }
        let mut result = EventResult::of_event(e, estimates[i].clone(), warnings);
        result.run_folder = sph.as_ref().map(|r| format!("cache/{}", r.key));
        result.sph = sph;
        result.failed = failed;
        events.push(result);
    }
    let failed_runs = events.iter().filter(|e| e.failed.is_some()).count();
    let mut bow_force = Vec::new();
    let mut k = 0;
    while k < events.len() {
        let same = |j: usize| {
            events[j].speed_m_per_s == events[k].speed_m_per_s && events[j].wave == events[k].wave
        };
        let end = (k..events.len())
            .find(|&j| !same(j))
            .unwrap_or(events.len());
        let group: Vec<&EventResult> = events[k..end].iter().collect();
        let entry: Vec<Option<f64>> = plan.events[k..end].iter().map(|e| e.entry_time_s).collect();
        bow_force.extend(super::bow_force::of_events(
            &group,
            &entry,
            plan.events[k].encounter_period_s,
        ));
        k = end;
    }
    let at: Vec<(f64, f64)> = plan
        .stations
        .iter()
        .map(|&f| (f, hull.station_x(f)))
        .collect();
    let mut stations = results::stations(&events, &at);
    for (st, q) in stations.iter_mut().zip(&plan.sensors) {
        st.default_sensors = q.default;
        st.sensors = q
            .sensors
            .iter()
            .map(|s| results::SensorInfo {
                name: s.name.clone(),
                girth_m: s.s_m,
                width_m: s.width_m,
            })
            .collect();
    }
    let settings = serde_json::json!({
        "loading": plan.loading,
        "water_density_kg_m3": plan.rho,
        "stations": plan.stations,
        "speeds_m_per_s": plan.speeds,
        "fidelity": s.fidelity.name(),
        "resolution": s.overrides.level,
        "particles_per_half_beam": s.overrides.particles_per_half_beam,
        "tank": match s.overrides.refinement {
            Some(true) => "refined",
            Some(false) => "uniform",
            None => "default: refined (dp in a band around the body, 2 dp beyond)",
        },
        "divergence_correction": scheme_setting(s.overrides.divergence_correction),
        "shifting": scheme_setting(s.overrides.shifting),
        "wall_wetness": scheme_setting(s.overrides.wall_wetness),
        "air": s.overrides.air.unwrap_or_default(),
        "sensor_method": s.overrides.sensor_method.unwrap_or(DESIGN_SENSOR_METHOD),
        "convergence_levels": s.study.levels,
        "convergence_ratio": s.study.ratio,
        "strips": s.strips,
        "keel_slope_term": s.keel_slope_term,
        "measured_forcing": s
            .forcing
            .iter()
            .map(|r| serde_json::json!({"station": r.station, "file": r.file.display().to_string()}))
            .collect::<Vec<_>>(),
        "design_value": "per sensor and station, the largest design value over the events with an SPH run at \
                         that station (all events where none has one); per event: SPH slamming peak + its GCI \
                         uncertainty where converged or acceptable (GCI at most 20 %), else the larger of that and the \
                         analytic (MLM) peak \
                         (where the levels' peaks are different events, U is the difference between them), \
                         or the analytic peak where SPH does not resolve the impact, and no value where \
                         neither computes it (a flat keel's air-cushion impact without --air; with air the \
                         two-phase run's cushion peak) (src/assess/design_rule.rs)",
    });
    let mut inputs = hull.input_files();
    inputs.push(sea.source.as_path());
    inputs.extend(s.forcing.iter().map(|r| r.file.as_path()));
    let provenance = Provenance::new(&inputs, settings.clone())?;
    let irregular = plan
        .motions
        .speeds
        .iter()
        .flat_map(|sp| {
            sp.irregular.iter().map(move |ir| {
                serde_json::json!({
                    "speed_m_per_s": sp.speed_m_s,
                    "sea": ir.sea,
                    "hs_m": ir.hs_m,
                    "tp_s": ir.tp_s,
                    "duration_h": ir.duration_h,
                    "stations": ir.stations,
                    "extreme_entry_velocity_m_per_s": ir.extreme_velocity_m_s,
                    "extreme_definition": "most probable largest entry velocity in the expected number of \
                                           slams over duration_h",
                    "design_events": "events[] with wave = \"<sea>/design\" and a design_event record (its \
                                      definition), one per station with at least one slam expected",
                })
            })
        })
        .collect();
    let mut a = Assessment {
        tool: results::tool(),
        provenance,
        hull: hull.name.clone(),
        loading: plan.loading.clone(),
        fidelity: s.fidelity.name().to_string(),
        settings,
        slam_threshold_velocity_m_per_s: plan.motions.slam_threshold_velocity_m_s,
        events,
        stations,
        irregular,
        bow_force_definition: super::bow_force::DEFINITION,
        bow_force,
        validation: Default::default(),
        failed_runs,
        limits: s.limits.clone(),
        limit_violations: Vec::new(),
        warnings: plan.warnings.clone(),
        measured_forcing: plan.forcing.clone(),
    };
    a.validation = super::comparisons::validate(hull, &sea.name, &plan, &a)?;
    a.limit_violations = super::limits::check(&a, &s.limits);
    let unchecked = super::limits::unchecked(&a, &s.limits);
    a.warnings.extend(unchecked);
    let sensors_of =
        |f: f64| -> Vec<String> { plan.sensors_at(f).iter().map(|q| q.name.clone()).collect() };
    let mut written = results::write(out, &a, &sensors_of)?;
    written.push(results::write_motions(out, &plan.motions)?);
    Ok((a, written))
}
