//! Running a sweep: the cases of this shard that are not in the case cache, in parallel (rayon), each
//! written to the cache the moment it finishes, so a sweep killed at any point (SIGKILL included) resumes
//! with every finished case kept.
//!
//! * `analytic` fidelity: many small cases. The hull variants the remaining cases need get their strip
//!   theory ([`super::motions::VariantModel`]) in parallel, then the cases run in parallel: relative
//!   motion and keel entry at each speed and wave, and the analytic estimate of every emerging event
//!   (`assess::analytic`), with the per-station design values of `assess::results`.
//! * `screen` and `sph` fidelity: few large cases. They run one after the other through `assess::run`
//!   (which runs its SPH events in parallel), all with one run cache `OUT/runs/cache/`, so a run shared by
//!   two cases is made once and a killed sweep keeps every finished run.
//!
//! A case that fails is recorded with its reason; the others go on.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicUsize, Ordering};

use rayon::prelude::*;

use super::motions::{self, StripModel, VariantModel};
use super::prepare::{CaseSea, Prepared, Variant};
use super::results::{self, CaseResult, Param, Prov, Shard, Stats, SweepResult};
use crate::assess::{self, EventResult, Fidelity};
use crate::error::{Error, Result};
use crate::files::write_text_atomic;
use crate::progress::{ProgressHandle, Silent};
use crate::provenance::{Provenance, TOOL};
use crate::sea::{SeaState, Speeds};
use crate::sph::{Overrides, StudyPlan};

/// How to run a sweep.
#[derive(Debug, Clone, Default)]
pub struct Options {
    /// Output folder (created if needed).
    pub out: PathBuf,
    /// Threads (None: one per core).
    pub threads: Option<usize>,
    /// Run only this shard's cases (case index mod count = index).
    pub shard: Option<Shard>,
    /// Test hook: stop (with an error) once this many cases have been computed in this call.
    pub stop_after: Option<usize>,
}

/// The case cache entry of a key.
pub fn case_file(out: &Path, key: &str) -> PathBuf {
    out.join("cache").join("cases").join(format!("{key}.json"))
}

fn cached(out: &Path, key: &str) -> Option<CaseResult> {
    let text = std::fs::read_to_string(case_file(out, key)).ok()?;
    let c: CaseResult = serde_json::from_str(&text).ok()?;
    (c.key == key).then_some(c)
}

fn store(out: &Path, c: &CaseResult) -> Result<()> {
    let json = serde_json::to_string(c).map_err(|e| Error::Invalid(format!("case cache: {e}")))?;
    write_text_atomic(&case_file(out, &c.key), &json)
}

/// The case record before it has results.
fn blank(p: &Prepared, i: usize) -> CaseResult {
    let c = &p.cases[i];
    let v = &p.variants[p.case_variant[i]];
    CaseResult {
        index: c.index,
        id: c.id.clone(),
        key: p.case_keys[i].clone(),
        parameters: c
            .values
            .iter()
            .map(|v| Param {
                name: v.name.to_string(),
                value: v.value,
            })
            .collect(),
        wave: c.wave.as_ref().map(|w| w.0.clone()),
        hull_file: v.file.clone(),
        lpp_m: v.hull.lpp,
        speeds_m_per_s: p.case_sea[i].speeds.clone(),
        stations: Vec::new(),
        max_design_pressure_pa: None,
        max_section_force_n_per_m: None,
        max_slam_probability: None,
        failed: None,
        warnings: Vec::new(),
    }
}

/// What a case computes for one speed in one irregular sea, which does not depend on its regular waves:
/// the stations' slam statistics, the design events (as planned, and with their analytic estimates),
/// the lines on stations without one, and the oversized profile waves.
#[derive(Clone)]
struct SeaSpeedPart {
    stats: Vec<crate::seakeeping::slamming::SlamStatistics>,
    planned: Vec<assess::Event>,
    events: Vec<EventResult>,
    notes: Vec<String>,
    oversized: Vec<assess::design_event::Oversized>,
}

/// The [`SeaSpeedPart`]s already computed, by (variant, speed, irregular sea): the cases that differ
/// only in their regular waves share them.
type SeaSpeedMemo = std::sync::Mutex<std::collections::HashMap<(usize, u64, String), SeaSpeedPart>>;

/// An event of a sweep's analytic case with its analytic estimate in the loading's water of density
/// `rho`, as `assess` makes it.
fn estimated(e: &assess::Event, rho: f64) -> EventResult {
    // in the loading's water, as `assess` does (sea water 1025 kg/m3 for most hulls)
    let est = e
        .entry
        .as_ref()
        .map(|c| assess::analytic::estimate_in(c, rho));
    let mut warnings = Vec::new();
    let analytic = match est {
        Some(Ok(a)) => {
            warnings.extend(a.notes.iter().map(|n| format!("analytic: {n}")));
            Some(a)
        }
        Some(Err(err)) => {
            warnings.push(format!("no analytic estimate: {err}"));
            None
        }
        None => None,
    };
    EventResult::of_event(e, analytic, warnings)
}

/// An analytic case from its variant's strip theory: its events, its stations' slam statistics and the
/// case's warnings (the keel-slope term's, as `assess` gives them: [`assess::keel_slope::lines`]; the
/// irregular seas' design events').
fn analytic_case(
    p: &Prepared,
    i: usize,
    v: &Variant,
    vm: &VariantModel,
    cs: &CaseSea,
    memo: &SeaSpeedMemo,
) -> Result<(Vec<EventResult>, Vec<Stats>, Vec<String>)> {
    let rho = v.loading.rho;
    let mut planned = Vec::new();
    for &u in &cs.speeds {
        planned.extend(vm.events(&v.hull, u, &cs.regular)?);
    }
    let regular = planned.len();
    // the irregular seas' slam statistics and design events, after the regular waves' as in `assess`
    let mut design = Vec::new();
    let mut stats: Vec<Stats> = vec![None; p.stations.len()];
    let (mut notes, mut oversized) = (Vec::new(), Vec::new());
    for &u in &cs.speeds {
        for sea in &cs.irregular {
            let key = (p.case_variant[i], u.to_bits(), sea.name.clone());
            let known = memo.lock().ok().and_then(|m| m.get(&key).cloned());
            let part = match known {
                Some(part) => part,
                None => {
                    let stats = vm.statistics(u, sea)?;
                    let (mut notes, mut oversized) = (Vec::new(), Vec::new());
                    let planned =
                        vm.design_events(&v.hull, u, sea, &stats, &mut notes, &mut oversized)?;
                    let events = planned.iter().map(|e| estimated(e, rho)).collect();
                    let part = SeaSpeedPart {
                        stats,
                        planned,
                        events,
                        notes,
                        oversized,
                    };
                    if let Ok(mut m) = memo.lock() {
                        m.insert(key, part.clone());
                    }
                    part
                }
            };
            for (k, s) in part.stats.iter().enumerate() {
                if stats[k].is_none_or(|(pr, _)| s.probability > pr) {
                    stats[k] = Some((s.probability, s.slams_per_hour));
                }
            }
            planned.extend(part.planned);
            design.extend(part.events);
            notes.extend(part.notes);
            assess::design_event::merge_oversized(&mut oversized, &part.oversized);
        }
    }
    notes.extend(assess::design_event::oversized_warnings(&oversized));
    // over all the case's speeds at once, as `assess` states them
    let mut case_warnings = assess::keel_slope::lines(&vm.stations, &planned, vm.keel_slope_term);
    case_warnings.extend(notes);
    // the regular waves' events get their estimates here; the design events have theirs from the memo
    planned.truncate(regular);
    let mut events: Vec<EventResult> = planned.iter().map(|e| estimated(e, rho)).collect();
    events.extend(design);
    Ok((events, stats, case_warnings))
}

/// The stations' slam statistics from an assessment's `irregular` records.
fn stats_of(a: &assess::Assessment, n: usize) -> Vec<Stats> {
    let mut stats: Vec<Stats> = vec![None; n];
    for ir in &a.irregular {
        for (k, st) in ir["stations"].as_array().into_iter().flatten().enumerate() {
            let (Some(pr), Some(sph)) = (
                st["slam_probability"].as_f64(),
                st["slams_per_hour"].as_f64(),
            ) else {
                continue;
            };
            if k < n && stats[k].is_none_or(|(q, _)| pr > q) {
                stats[k] = Some((pr, sph));
            }
        }
    }
    stats
}

/// A screen or SPH case through `assess::run`.
fn assess_case(p: &Prepared, i: usize, out: &Path, threads: Option<usize>) -> Result<CaseResult> {
    let v = &p.variants[p.case_variant[i]];
    let cs = &p.case_sea[i];
    let sea = SeaState {
        name: p.sea.name.clone(),
        description: None,
        water_depth_m: p.sea.water_depth_m,
        speeds: Speeds::MetresPerSecond(cs.speeds.clone()),
        regular: cs.regular.clone(),
        irregular: cs.irregular.clone(),
        source: p.common.sea_path.clone(),
    };
    let settings = assess::Settings {
        loading: Some(v.loading.name.clone()),
        stations: p.stations.clone(),
        speeds: Some(cs.speeds.clone()),
        fidelity: p.common.fidelity,
        overrides: Overrides {
            level: Some(p.common.resolution),
            air: Some(p.common.air),
            ..Default::default()
        },
        study: StudyPlan {
            levels: p.common.convergence_levels,
            ..StudyPlan::default()
        },
        strips: p.common.strips,
        keel_slope_term: p.common.keel_slope_term,
        use_cache: true,
        // The variants share one cache: each would otherwise walk the others' entries for a silent note.
        unused_cache: assess::cache::Unused::Ignore,
        threads,
        ..assess::Settings::default()
    };
    let runs = out.join("runs");
    let mut c = blank(p, i);
    match assess::run(
        &v.hull,
        &sea,
        &settings,
        &runs,
        &ProgressHandle::new(Silent),
    ) {
        Ok((a, _)) => {
            // Keep this case's summary beside the shared run cache.
            for (from, to) in [("summary.json", "json"), ("pressures.csv", "csv")] {
                let src = runs.join(from);
                let dst = runs.join(format!("{}.{to}", c.key));
                std::fs::rename(&src, &dst).map_err(|e| Error::io(&dst, e))?;
            }
            let stats = stats_of(&a, p.stations.len());
            c.stations = results::stations(&a.events, &a.stations, &stats);
            c.warnings = a.warnings.clone();
            if a.failed_runs > 0 {
                c.failed = Some(format!(
                    "{} SPH run(s) failed (runs/{}.json gives the reasons)",
                    a.failed_runs, c.key
                ));
            }
        }
        Err(e) => c.failed = Some(e.to_string()),
    }
    results::summarise(&mut c);
    Ok(c)
}

/// Run the sweep `p` (this shard of it) and write its results into `opts.out`.
pub fn run(p: &Prepared, opts: &Options, progress: &ProgressHandle) -> Result<SweepResult> {
    let out = &opts.out;
    std::fs::create_dir_all(out).map_err(|e| Error::io(out, e))?;
    for v in &p.variants {
        if let (Some(rel), Some(text)) = (&v.file, &v.text) {
            let path = out.join(rel);
            if std::fs::read_to_string(&path).ok().as_deref() != Some(text.as_str()) {
                write_text_atomic(&path, text)?;
            }
        }
    }
    let mine: Vec<usize> = (0..p.cases.len())
        .filter(|&i| opts.shard.is_none_or(|s| i % s.count == s.index))
        .collect();
    let mut done: Vec<Option<CaseResult>> = vec![None; p.cases.len()];
    let mut todo = Vec::new();
    for &i in &mine {
        match cached(out, &p.case_keys[i]) {
            Some(mut c) => {
                // The same content under this sweep's numbering.
                c.index = p.cases[i].index;
                c.id = p.cases[i].id.clone();
                done[i] = Some(c);
            }
            None => todo.push(i),
        }
    }
    let computed = AtomicUsize::new(0);
    let stopped = AtomicUsize::new(0);
    let limit = opts.stop_after.unwrap_or(usize::MAX);
    let total = mine.len();
    let already = total - todo.len();
    if !todo.is_empty() {
        progress.start("sweep cases", total as f64, "cases");
        progress.update(already as f64, "from the case cache");
    }
    let tick = |label: &str| {
        let n = computed.fetch_add(1, Ordering::SeqCst) + 1;
        progress.update((already + n) as f64, label);
    };
    let fresh: Vec<(usize, Result<CaseResult>)> = if p.common.fidelity == Fidelity::Analytic {
        let work = || -> Result<Vec<(usize, Result<CaseResult>)>> {
            // Strip theory of the models still needed, in parallel, then the variants' stations.
            let mut need: Vec<usize> = todo
                .iter()
                .map(|&i| p.variants[p.case_variant[i]].model)
                .collect();
            need.sort_unstable();
            need.dedup();
            let strips: Vec<(usize, Result<StripModel>)> = need
                .par_iter()
                .map(|&k| {
                    let m = &p.models[k];
                    (k, StripModel::new(m.model.clone(), m.band))
                })
                .collect();
            let mut vneed: Vec<usize> = todo.iter().map(|&i| p.case_variant[i]).collect();
            vneed.sort_unstable();
            vneed.dedup();
            let models: Vec<(usize, Result<VariantModel>)> = vneed
                .par_iter()
                .map(|&k| {
                    let v = &p.variants[k];
                    let vm = match strips.iter().find(|s| s.0 == v.model).map(|s| &s.1) {
                        Some(Ok(sm)) => VariantModel::new(
                            sm,
                            &v.hull,
                            &v.loading,
                            &p.stations,
                            p.common.keel_slope_term,
                        ),
                        Some(Err(e)) => Err(Error::Numerical(e.to_string())),
                        None => Err(Error::Invalid("no strip theory for this variant".into())),
                    };
                    (k, vm)
                })
                .collect();
            let model_of = |k: usize| models.iter().find(|m| m.0 == k).map(|m| &m.1);
            let memo = SeaSpeedMemo::default();
            Ok(todo
                .par_iter()
                .filter_map(|&i| {
                    if computed.load(Ordering::SeqCst) >= limit {
                        stopped.fetch_add(1, Ordering::SeqCst);
                        return None;
                    }
                    let v = &p.variants[p.case_variant[i]];
                    let mut c = blank(p, i);
                    match model_of(p.case_variant[i]) {
                        Some(Ok(vm)) => match analytic_case(p, i, v, vm, &p.case_sea[i], &memo) {
                            Ok((events, stats, warnings)) => {
                                c.warnings = warnings;
                                let at: Vec<(f64, f64)> = p
                                    .stations
                                    .iter()
                                    .map(|&f| (f, v.hull.station_x(f)))
                                    .collect();
                                let st = assess::results::stations(&events, &at);
                                c.stations = results::stations(&events, &st, &stats);
                            }
                            Err(e) => c.failed = Some(e.to_string()),
                        },
                        Some(Err(e)) => c.failed = Some(format!("strip theory: {e}")),
                        None => c.failed = Some("no strip theory for this variant".into()),
                    }
                    results::summarise(&mut c);
                    let r = store(out, &c).map(|_| c);
                    tick(&p.cases[i].id);
                    Some((i, r))
                })
                .collect())
        };
        match opts.threads {
            Some(n) => rayon::ThreadPoolBuilder::new()
                .num_threads(n.max(1))
                .build()
                .map_err(|e| Error::Invalid(format!("thread pool: {e}")))?
                .install(work)?,
            None => work()?,
        }
    } else {
        let mut v = Vec::new();
        for &i in &todo {
            if computed.load(Ordering::SeqCst) >= limit {
                stopped.fetch_add(1, Ordering::SeqCst);
                continue;
            }
            let r = assess_case(p, i, out, opts.threads).and_then(|c| store(out, &c).map(|_| c));
            tick(&p.cases[i].id);
            v.push((i, r));
        }
        v
    };
    if !todo.is_empty() {
        progress.finish();
    }
    for (i, r) in fresh {
        done[i] = Some(r?);
    }
    if stopped.load(Ordering::SeqCst) > 0 {
        return Err(Error::Invalid(format!(
            "stopped after {} cases as asked (test hook); run again to finish",
            computed.load(Ordering::SeqCst)
        )));
    }
    let cases: Vec<CaseResult> = done.into_iter().flatten().collect();
    let result = assemble(p, opts.shard, cases)?;
    super::output::write(out, &result)?;
    Ok(result)
}

/// The sweep result of a list of finished cases.
pub fn assemble(p: &Prepared, shard: Option<Shard>, cases: Vec<CaseResult>) -> Result<SweepResult> {
    let inputs = p.inputs();
    let refs: Vec<&Path> = inputs.iter().map(|p| p.as_path()).collect();
    let settings = serde_json::json!({
        "hull": p.common.hull_path.display().to_string(),
        "sea": p.common.sea_path.display().to_string(),
        "loading": p.variants.first().map(|v| v.loading.name.clone()),
        "stations": p.stations,
        "fidelity": p.common.fidelity.name(),
        "resolution": p.common.resolution,
        "air": p.common.air,
        "keel_slope_term": p.common.keel_slope_term,
        "convergence_levels": p.common.convergence_levels,
        "strips": p.common.strips,
        "bow_region": p.common.region,
        "strip_table_spacing_ln_omega": motions::TABLE_SPACING,
    });
    let prov = Provenance::new(&refs, settings)?;
    let warnings = results::warnings_of(&cases);
    Ok(SweepResult {
        tool: TOOL.to_string(),
        provenance: Prov::from_provenance(&prov),
        sweep_hash: p.sweep_hash.clone(),
        name: p.file.raw.name.get_ref().trim().to_string(),
        fidelity: p.common.fidelity.name().to_string(),
        parameters: p.parameters.clone(),
        best: p.common.best.clone(),
        total_cases: p.cases.len(),
        shard,
        failed_cases: cases.iter().filter(|c| c.failed.is_some()).count(),
        cases,
        warnings,
    })
}
