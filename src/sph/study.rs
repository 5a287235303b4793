//! A water-entry run with its convergence statement: the case is also run at coarser particle spacings
//! (dp r, dp r^2, ...; r = 2 by default, so each companion costs about 1/r^3 of the run itself in 2D) and
//! every reported peak gets a Grid Convergence Index and a verdict ([`crate::loads::convergence`]).
//!
//! The companions are run first, coarsest first, into `convergence/dp_<mm>/` under the output folder
//! (histories and summaries, no snapshots). A companion that cannot be set up or that stops early is
//! recorded with the reason and left out of the estimate; the statement then rests on the levels that
//! did finish. The run at the requested spacing is the one reported; its `summary.json` carries the
//! statements, and `convergence.csv` lists them one per row.

use std::path::PathBuf;

use serde::Serialize;

use crate::error::{Error, Result};
use crate::files::write_text_atomic;
use crate::loads::convergence::{PeakConvergence, Verdict, assess};
use crate::sph::{RunOptions, RunResult, RunSummary, Setup, case, run};

/// Fewest particles across the largest half-breadth for a companion run to take part in the estimate: below
/// this the jet root and the wetted contour are not represented at all.
pub const MIN_PARTICLES_ACROSS: f64 = 8.0;

fn half_breadth(s: &Setup) -> f64 {
    s.section_points.as_ref().map_or(s.tank_half_width, |p| {
        p.iter().fold(0.0, |m, q| q[0].abs().max(m))
    })
}

/// How many resolutions to run and how far apart.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct StudyPlan {
    /// Number of resolutions including the reported one (1 = no study, 2 or 3).
    pub levels: usize,
    /// Ratio of successive particle spacings (> 1).
    pub ratio: f64,
}

impl Default for StudyPlan {
    fn default() -> Self {
        Self {
            levels: 2,
            ratio: 2.0,
        }
    }
}

/// A coarser companion run.
#[derive(Debug, Clone, Serialize)]
pub struct Companion {
    pub dp_m: f64,
    /// Folder of its histories and summary.
    pub folder: Option<PathBuf>,
    /// Why it is not part of the estimate, if it is not.
    pub left_out: Option<String>,
    #[serde(skip)]
    pub summary: Option<RunSummary>,
}

/// The statements of a study, also stored in the reported run's summary.
#[derive(Debug, Clone, Serialize, Default)]
pub struct ConvergenceReport {
    pub plan_levels: usize,
    pub plan_ratio: f64,
    pub companions: Vec<Companion>,
    pub peaks: Vec<PeakConvergence>,
}

/// One peak a summary reports.
#[derive(Debug, Clone)]
pub struct ReportedPeak {
    pub name: String,
    pub unit: String,
    pub value: f64,
    /// The peak is the first sample after the contact transient: the tail of the transient.
    pub transient_tail: bool,
    /// The peak is the last sample of the run: the quantity was still rising.
    pub at_end: bool,
    /// The record's phases, for the slamming peak of a section run's sensor or force: then `value` is the
    /// slamming peak (0 when there is none) and the levels are compared only when their peaks are the
    /// same event ([`crate::loads::anatomy::matched`]).
    pub anatomy: Option<crate::loads::anatomy::Anatomy>,
}

/// The peaks a summary reports: force and contour peak pressure, and every sensor, raw and (when a
/// filter was applied) filtered, all after the contact transient; for a section run's records, the
/// slamming peaks of their impact windows, raw and filtered.
pub fn reported_peaks(s: &RunSummary) -> Vec<ReportedPeak> {
    let mut out = Vec::new();
    let mut add = |name: &str, unit: &str, ns: &crate::sph::NamedSummary| {
        let sm = &ns.summary;
        let (tail, at_end) = (sm.at_transient_end, sm.at_record_end);
        // The slamming peak of the impact phase where the record has its anatomy.
        let value = match &ns.anatomy {
            Some(a) => a.slamming_peak.map_or(0.0, |p| p.value),
            None => sm.raw.value,
        };
        out.push(ReportedPeak {
            name: format!("{name} raw"),
            unit: unit.to_string(),
            value,
            transient_tail: tail && ns.anatomy.is_none(),
            at_end: at_end && ns.anatomy.is_none(),
            anatomy: ns.anatomy.clone(),
        });
        if let (Some(f), Some(lp)) = (&sm.filtered, &sm.filter) {
            // the filtered slamming peak where the record has its anatomy: the same impact window as
            // the raw one, so that the levels compare the same event, not the whole records' maxima
            let value = match &ns.filtered_anatomy {
                Some(a) => a.slamming_peak.map_or(0.0, |p| p.value),
                None => f.value,
            };
            out.push(ReportedPeak {
                name: format!("{name} filtered {:.0} Hz", lp.cutoff_hz),
                unit: unit.to_string(),
                value,
                transient_tail: tail && ns.filtered_anatomy.is_none(),
                at_end: at_end && ns.filtered_anatomy.is_none(),
                anatomy: ns.filtered_anatomy.clone(),
            });
        }
    };
    add("section force", "N/m", &s.force);
    for sen in &s.sensors {
        add(&format!("sensor {}", sen.name), "Pa", sen);
    }
    out.push(ReportedPeak {
        name: "contour peak pressure".into(),
        unit: "Pa".into(),
        value: s.peak_contour_pressure_pa,
        transient_tail: s.peak_contour_at_transient_end,
        at_end: false,
        anatomy: None,
    });
    out
}

/// The statement of a slamming peak (a record with its anatomy): the levels are compared from the finest
/// down for as long as each companion's peak is the same event as the reported one; a companion whose
/// peak is another event (or that has none) ends the comparison, and the statement says why.
fn slamming_statement(levels: &[&ReportedPeak], dp: &[f64]) -> PeakConvergence {
    let (name, unit) = (&levels[0].name, &levels[0].unit);
    let fine = levels[0]
        .anatomy
        .as_ref()
        .expect("slamming statement of a record with anatomy");
    if fine.slamming_peak.is_none() {
        let mut c = assess(name, unit, &dp[..1], &[0.0]);
        c.dp_m = dp.to_vec();
        c.values = levels.iter().map(|p| p.value).collect();
        c.verdict = Verdict::NotAssessed;
        c.statement = format!(
            "{name}: no slamming peak at the reported resolution ({}); nothing to assess",
            fine.status.describe()
        );
        return c;
    }
    let mut n = 1;
    let mut why = None;
    // whether the first level left out has no slamming peak at all (rather than another event's)
    let mut unresolved = false;
    for l in &levels[1..] {
        match l
            .anatomy
            .as_ref()
            .map(|a| (a, crate::loads::anatomy::matched(fine, a)))
        {
            Some((_, Ok(()))) => n += 1,
            Some((a, Err(e))) => {
                unresolved = a.slamming_peak.is_none();
                why = Some(e);
                break;
            }
            None => break,
        }
    }
    let values: Vec<f64> = levels[..n].iter().map(|p| p.value).collect();
    let mut c = assess(name, unit, &dp[..n], &values);
    c.dp_m = dp.to_vec();
    c.values = levels.iter().map(|p| p.value).collect();
    if n > 1
        && fine.without_pulse()
        && let Some(b) = fine.local_deadrise_deg
    {
        c.statement.push_str(&format!(
            "; a side of {b:.1} deg local deadrise (at least {:.1}): no impact pulse crosses it, so the \
             levels' largest values in the impact window are compared, not their times",
            crate::loads::anatomy::KEEL_MAXIMUM_FROM_DEG
        ));
    }
    if let Some(why) = why {
        let at = dp[n] * 1e3;
        if n == 1 && unresolved {
            c.verdict = Verdict::CompanionUnresolved;
            c.statement = format!(
                "{name}: not assessed: the companion at dp {at:.3} mm does not resolve the impact ({why})"
            );
        } else if n == 1 {
            c.verdict = Verdict::Mismatched;
            c.statement = format!(
                "{name}: not assessed: the companion at dp {at:.3} mm does not show the same impact ({why})"
            );
        } else {
            c.statement
                .push_str(&format!("; the level at dp {at:.3} mm is left out: {why}"));
        }
    }
    c
}

/// The convergence statement of one peak from its values at every level (finest first), with two
/// guards against a quantity that is resolution-independent for the wrong reason: a peak that is the
/// tail of the contact transient at some level is not a hydrodynamic peak there, and values identical
/// at every spacing come from something the resolution does not touch (an initial state, a clamp).
fn statement(levels: &[&ReportedPeak], dp: &[f64]) -> PeakConvergence {
    if levels[0].anatomy.is_some() {
        return slamming_statement(levels, dp);
    }
    let values: Vec<f64> = levels.iter().map(|p| p.value).collect();
    let (name, unit) = (&levels[0].name, &levels[0].unit);
    let mut c = assess(name, unit, dp, &values);
    if let Some(k) = levels.iter().position(|p| p.transient_tail) {
        c.verdict = Verdict::NotConverged;
        c.statement = format!(
            "not converged: at dp {:.3} mm the peak is the tail of the contact transient (the first sample \
             after the keel is {} dp deep), not a hydrodynamic peak; a finer resolution is needed",
            dp[k] * 1e3,
            crate::sph::CONTACT_TRANSIENT_DP
        );
    } else if let Some(k) = levels.iter().position(|p| p.at_end) {
        c.verdict = Verdict::NotAssessed;
        c.statement = format!(
            "not assessed: at dp {:.3} mm the largest value is at the end of the run, still rising (a steady \
             or hydrostatic load growing with the immersion), not an impact peak",
            dp[k] * 1e3
        );
    } else if values.len() > 1
        && values[0] != 0.0
        && values
            .iter()
            .all(|v| (v - values[0]).abs() <= 1e-12 * values[0].abs())
    {
        c.verdict = Verdict::NotAssessed;
        c.statement = format!(
            "not assessed: the value is identical at every spacing ({}), so it is set by something the \
             resolution does not change, and says nothing about convergence",
            dp.iter()
                .map(|d| format!("{:.3} mm", d * 1e3))
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    c
}

/// Run `setup` as asked and at the coarser companion spacings of `plan`, and attach the convergence
/// statement of every peak to the summary of the reported run.
pub fn run_with_convergence(setup: Setup, opts: &RunOptions, plan: StudyPlan) -> Result<RunResult> {
    if !(plan.levels >= 1 && plan.levels <= 3) {
        return Err(Error::Invalid(format!(
            "a convergence study uses 1 to 3 resolutions, got {}",
            plan.levels
        )));
    }
    if !(plan.ratio.is_finite() && plan.ratio >= 1.2) {
        return Err(Error::Invalid(format!(
            "the ratio of particle spacings must be at least 1.2, got {}",
            plan.ratio
        )));
    }
    let mut companions = Vec::new();
    for k in (1..plan.levels).rev() {
        let mut s = setup.clone();
        s.dp *= plan.ratio.powi(k as i32);
        s.snapshot_interval = None;
        s.notes.push(format!(
            "convergence companion: dp = {:.3} mm, {} x the reported run's spacing",
            s.dp * 1e3,
            plan.ratio.powi(k as i32)
        ));
        let folder = opts.out_dir.as_ref().map(|d| {
            d.join("convergence")
                .join(format!("dp_{:.3}mm", s.dp * 1e3))
        });
        let mut c = Companion {
            dp_m: s.dp,
            folder: folder.clone(),
            left_out: None,
            summary: None,
        };
        let across = half_breadth(&s) / s.dp;
        if across < MIN_PARTICLES_ACROSS {
            c.left_out = Some(format!(
                "too coarse to inform the estimate: {across:.1} particles across the half-breadth (at least \
                 {MIN_PARTICLES_ACROSS} needed)"
            ));
            companions.push(c);
            continue;
        }
        if let Err(e) = case::check(&s) {
            c.left_out = Some(format!("cannot be set up: {e}"));
            companions.push(c);
            continue;
        }
        opts.progress
            .note(&format!("convergence companion at dp {:.3} mm", s.dp * 1e3));
        let o = RunOptions {
            out_dir: folder,
            progress: opts.progress.clone(),
            vtk: false,
            png: false,
            provenance: opts.provenance.clone(),
        };
        match run(s, &o) {
            Ok(r) => c.summary = Some(r.summary),
            Err(e) => c.left_out = Some(format!("stopped: {e}")),
        }
        companions.push(c);
    }
    let mut result = run(setup, opts)?;
    // Finest first: the reported run, then the companions from fine to coarse.
    let mut finished: Vec<&RunSummary> = vec![&result.summary];
    finished.extend(companions.iter().rev().filter_map(|c| c.summary.as_ref()));
    let dp: Vec<f64> = finished.iter().map(|s| s.dp_m).collect();
    let per_level: Vec<Vec<ReportedPeak>> = finished.iter().map(|s| reported_peaks(s)).collect();
    let peaks = (0..per_level[0].len())
        .map(|i| {
            let levels: Vec<&ReportedPeak> = per_level.iter().map(|l| &l[i]).collect();
            statement(&levels, &dp)
        })
        .collect();
    let report = ConvergenceReport {
        plan_levels: plan.levels,
        plan_ratio: plan.ratio,
        companions,
        peaks,
    };
    if let Some(dir) = &opts.out_dir {
        let csv = convergence_csv(&report, opts.provenance.as_ref())?;
        write_text_atomic(&dir.join("convergence.csv"), &csv)?;
    }
    result.summary.convergence = Some(report);
    if let Some(dir) = &opts.out_dir {
        let json = serde_json::to_string_pretty(&result.summary).expect("summary serialises");
        write_text_atomic(&dir.join("summary.json"), &json)?;
    }
    Ok(result)
}

/// One row per peak: the values at each spacing (`;`-separated), the estimate and the statement, headed by
/// the provenance (when given).
pub fn convergence_csv(
    r: &ConvergenceReport,
    prov: Option<&crate::provenance::Provenance>,
) -> Result<String> {
    let header: Vec<String> = [
        "quantity",
        "unit",
        "dp_m",
        "values",
        "relative_change",
        "observed_order",
        "order_used",
        "extrapolated",
        "gci",
        "verdict",
        "statement",
    ]
    .iter()
    .map(|c| c.to_string())
    .collect();
    let opt = |v: Option<f64>| v.map_or(String::new(), |x| format!("{x:.6e}"));
    let list = |v: &[f64]| {
        v.iter()
            .map(|x| format!("{x:.6e}"))
            .collect::<Vec<_>>()
            .join(";")
    };
    let rows: Vec<Vec<String>> = r
        .peaks
        .iter()
        .map(|p| {
            let verdict = serde_json::to_value(p.verdict)
                .ok()
                .and_then(|v| v.as_str().map(str::to_string))
                .unwrap_or_default();
            vec![
                p.name.clone(),
                p.unit.clone(),
                list(&p.dp_m),
                list(&p.values),
                opt(p.relative_change),
                opt(p.observed_order),
                opt(p.order_used),
                opt(p.extrapolated),
                opt(p.gci),
                verdict,
                p.statement.clone(),
            ]
        })
        .collect();
    crate::sph::output::csv_text(prov, &header, &rows)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::loads::anatomy::{Anatomy, ImpactStatus, ImpactWindow, Phase};
    use crate::loads::peaks::Peak;

    fn slam(value: f64, time: f64) -> ReportedPeak {
        let p = Peak {
            value,
            time,
            impulse: 0.0,
        };
        ReportedPeak {
            name: "sensor S raw".into(),
            unit: "Pa".into(),
            value,
            transient_tail: false,
            at_end: false,
            anatomy: Some(Anatomy {
                status: ImpactStatus::Resolved,
                window: Some(ImpactWindow::around(0.06, 0.09, 0.002, 1.0)),
                record_end_from_s: 0.17,
                slamming_peak: Some(p),
                hydrostatic_at_peak: Some(0.0),
                at_window_end: false,
                largest: p,
                largest_phase: Phase::Impact,
                hydrostatic_at_largest: None,
                spikes: 0,
                crossing_half_width_m: None,
                rise_time_s: None,
                local_deadrise_deg: None,
            }),
        }
    }

    #[test]
    fn peaks_of_different_events_get_no_verdict() {
        // S174-2 of the committed Ochi report: fine peak at 134.9 ms, companion at 177.9 ms
        let (a, b) = (slam(2602.0, 0.1349), slam(2600.0, 0.1779));
        let c = statement(&[&a, &b], &[0.004, 0.008]);
        assert_eq!(c.verdict, Verdict::Mismatched, "{}", c.statement);
        assert!(c.statement.contains("same impact"), "{}", c.statement);
        // the same values at matching times are compared
        let b = slam(2600.0, 0.136);
        let c = statement(&[&a, &b], &[0.004, 0.008]);
        assert_eq!(c.verdict, Verdict::Converged, "{}", c.statement);
    }

    #[test]
    fn a_companion_without_a_peak_is_told_apart_from_another_event() {
        // S093-1 raw of the committed Ochi report: the coarser level's contact crosses the sensor
        // inside its contact transient
        let a = slam(2871.0, 0.0147);
        let mut b = slam(0.0, 0.0);
        if let Some(an) = &mut b.anatomy {
            an.slamming_peak = None;
            an.status = ImpactStatus::InTransient;
        }
        let c = statement(&[&a, &b], &[0.007, 0.014]);
        assert_eq!(c.verdict, Verdict::CompanionUnresolved, "{}", c.statement);
        assert!(c.statement.contains("does not resolve"), "{}", c.statement);
    }

    #[test]
    fn a_third_level_of_another_event_is_left_out_with_the_reason() {
        let (a, b, c3) = (slam(2000.0, 0.1), slam(1900.0, 0.101), slam(500.0, 0.17));
        let c = statement(&[&a, &b, &c3], &[0.002, 0.004, 0.008]);
        assert_eq!(c.order_used, Some(1.0));
        assert!(c.statement.contains("left out"), "{}", c.statement);
        assert_eq!(c.values.len(), 3);
    }

    #[test]
    fn no_slamming_peak_is_not_assessed() {
        let mut a = slam(0.0, 0.0);
        if let Some(an) = &mut a.anatomy {
            an.slamming_peak = None;
            an.status = ImpactStatus::InTransient;
        }
        let b = slam(1000.0, 0.05);
        let c = statement(&[&a, &b], &[0.002, 0.004]);
        assert_eq!(c.verdict, Verdict::NotAssessed);
        assert!(c.statement.contains("contact transient"), "{}", c.statement);
    }
}
