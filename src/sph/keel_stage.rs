//! Resolution that follows the impact: staged runs for the sensors the contact crosses early.
//!
//! A sensor's slamming peak is made by the flow at the spray root when the wetted contact crosses it.
//! What resolves it is the number of particles across the wetted half-width c at that moment,
//! N = c(t_cross) / dp, not the number across the section's half-breadth: near the keel c is small, so
//! a spacing that resolves the sensors at mid-side leaves the keel sensors with a few particles across,
//! or crosses them inside the contact transient (the first [`crate::sph::CONTACT_TRANSIENT_DP`] spacings
//! of penetration), where no spacing-independent pressure exists.
//!
//! Wagner's flow is self-similar in the early stage of an entry (c grows with the penetration; Wagner
//! 1932, and the similarity solution of Dobrovol'skaya 1969 for a wedge): what happens near the keel up
//! to a wetted half-width c depends only on the hull below the height where its half-breadth is a few c.
//! A **keel stage** uses that. For the under-resolved sensors, sorted by their crossing half-width
//! c_i (Wagner's condition along the run's own velocity history), the stages are built greedily:
//!
//! * the sensors staged are those crossed inside the main run's contact transient and those with
//!   fewer than [`STAGE_BELOW`] particles across their crossing half-width (both numbers, N and this,
//!   are for the default level of 40 particles per half-breadth, and scale with the main run's level:
//!   a quick run at 10 particles per half-breadth stages below 2.5 particles across, at 5);
//! * a stage starts at the smallest remaining c_min and covers every sensor with c_i <= R c_min
//!   ([`STAGE_SPAN`]);
//! * its spacing is dp_s = c_min / N ([`PARTICLES_ACROSS_RESOLVED`]), so every sensor it covers has at
//!   least N particles across the wetted half-width at its crossing;
//! * its section is the hull section cut at the height where the half-breadth reaches K c_max
//!   ([`STAGE_BREADTH`]), with the automatic tank of that smaller body (the same clearances in its
//!   half-breadths, [`crate::sph::automatic`]), so the stage has about as many particles as a run of a
//!   whole section at up to N K R particles per half-breadth, whatever c_min is;
//! * it runs, with the same motion, sound speed and numerics as the main run and its own convergence
//!   companion, until the impact window of its last sensor is over
//!   ([`crate::loads::anatomy::ImpactWindow`]: Wagner's crossing end times (1 + 0.5) plus the lag of
//!   [`crate::loads::anatomy::LAG_SPACINGS`] spacings), well before the wetting reaches the cut
//!   (c(t_end) is about 1.5 c_max < K c_max).
//!
//! The sensors a stage covers then take their record, anatomy and convergence statement from the stage;
//! the summary lists every stage with its spacing, section cut and cost. A sensor the contact crosses at
//! an acoustic speed (a flat keel) is not staged: weakly compressible single-phase SPH does not compute
//! that impact at any spacing (an air cushion does; see the run's warnings). A section that starts
//! immersed (a flare event) is not staged either: its contact transient is the start of the motion and
//! its sensors are crossed well after it.

use std::path::PathBuf;

use serde::Serialize;

use crate::analytic::generalised_wagner;
use crate::error::Result;
use crate::loads::anatomy::{ImpactStatus, LAG_SPACINGS, WINDOW_FRACTION, time_reaching};
use crate::loads::cutoff;
use crate::sph::body::Section;
use crate::sph::case::{self, Overrides, Setup};
use crate::sph::{RunOptions, RunResult, RunSummary, StudyPlan, run_with_convergence};

/// Particles across the wetted half-width at a sensor's crossing that a keel stage gives the first
/// sensor it covers. On the Ochi 2.0 m/s assessment at the default spacing the sensors' slamming peaks
/// were converged or acceptable from 19-24 particles across and mismatched or not converged at 9-17.
pub const PARTICLES_ACROSS_RESOLVED: f64 = 20.0;

/// Particles across the wetted half-width at a sensor's crossing below which the sensor is staged
/// (besides every sensor crossed inside the contact transient). Between this and
/// [`PARTICLES_ACROSS_RESOLVED`] the main run's record is kept and its convergence verdict says how far
/// it can be trusted: staging every sensor below 20 particles multiplied the cost of an Ochi station by
/// about 8 (one stage of 84,000 particles for two mid-side sensors), against a single stage of the
/// keel sensors with this rule.
pub const STAGE_BELOW: f64 = 10.0;

/// Particles per half-breadth of the resolution level at which [`PARTICLES_ACROSS_RESOLVED`] and
/// [`STAGE_BELOW`] apply as they stand (the default, [`crate::sph::Level::Coarse`]); a main run at n
/// particles per half-breadth scales both by n / 40.
pub const REFERENCE_PARTICLES_PER_HALF_BEAM: f64 = 40.0;

/// Ratio R of the largest to the smallest crossing half-width of the sensors of one stage.
pub const STAGE_SPAN: f64 = 2.0;

/// Half-breadth K c_max, in crossing half-widths of the stage's last sensor, at which its section is
/// cut: at the end of the stage (the impact window's end, 1.5 times the crossing time plus the lag)
/// Wagner's contact of a constant-speed entry is about 1.5 c_max wide, below the cut.
pub const STAGE_BREADTH: f64 = 2.0;

/// Most stages of one run.
pub const MAX_STAGES: usize = 3;

/// Finest stage spacing, as a fraction of the main run's: a sensor that would need a finer one is left
/// unresolved, with the reason.
pub const FINEST_FRACTION: f64 = 1.0 / 16.0;

/// A stage as planned.
#[derive(Debug, Clone)]
pub struct StagePlan {
    pub setup: Setup,
    /// The sensors (names) it resolves.
    pub sensors: Vec<String>,
    /// Smallest and largest crossing half-width of its sensors (m).
    pub crossing_half_widths_m: [f64; 2],
    /// Half-breadth at which the section is cut (m).
    pub cut_half_breadth_m: f64,
}

/// A stage as run, recorded in the main run's summary.
#[derive(Debug, Clone, Serialize)]
pub struct StageRecord {
    pub sensors: Vec<String>,
    pub dp_m: f64,
    pub crossing_half_widths_m: [f64; 2],
    pub cut_half_breadth_m: f64,
    pub t_end_s: f64,
    /// Cut-off (Hz) of the low-pass filter of its records, when it has one.
    pub filter_cutoff_hz: Option<f64>,
    pub fluid_particles: usize,
    pub steps: u64,
    pub wall_time_s: f64,
    /// Folder of its histories and summary.
    pub folder: Option<PathBuf>,
    /// Why its sensors keep the main run's values, if they do.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub left_out: Option<String>,
}

/// Where a sensor's values come from when a keel stage resolved it.
#[derive(Debug, Clone, Copy, Serialize, serde::Deserialize, PartialEq)]
pub struct StageRef {
    /// Index into [`RunSummary::stages`].
    pub stage: usize,
    pub dp_m: f64,
}

/// The main run's largest value of a sensor a keel stage resolved, where it lies after the impact (the
/// immersion phase, [`crate::loads::anatomy::Phase::Immersion`]): the stage runs only the early entry of
/// the section's lower part, so the load the panel carries later is known from the main run alone.
#[derive(Debug, Clone, Copy, Serialize, serde::Deserialize, PartialEq)]
pub struct LaterLoad {
    /// The value (Pa), its time (s) and its hydrostatic part (Pa) at that time.
    pub value: f64,
    pub time_s: f64,
    pub hydrostatic: Option<f64>,
}

/// The starboard half of `section` cut at the first height where its half-breadth reaches `y`
/// (the point there interpolated); the whole section when it never does.
pub fn cut_at_half_breadth(section: &Section, y: f64) -> Result<Section> {
    let half = section.half_points();
    let mut pts = vec![half[0]];
    for w in half.windows(2) {
        let (a, b) = (w[0], w[1]);
        if b[0] >= y && a[0] < y {
            let f = (y - a[0]) / (b[0] - a[0]);
            pts.push([y, a[1] + f * (b[1] - a[1])]);
            return Section::from_half_points(pts);
        }
        pts.push(b);
    }
    Section::from_half_points(pts)
}

/// A sensor waiting for a stage: name, crossing half-width (m) and whether the main run crossed it
/// inside its contact transient.
struct Waiting {
    name: String,
    crossing: f64,
}

/// The stages that resolve the under-resolved sensors of a finished main run (`summary`, whose
/// setup it reads): sensors crossed inside the contact transient, or with fewer than [`STAGE_BELOW`]
/// particles across the wetted half-width at their crossing. Returns the
/// plans and, for every sensor that stays as it is although under-resolved, the reason.
pub fn plan(summary: &RunSummary, study: StudyPlan) -> (Vec<StagePlan>, Vec<(String, String)>) {
    let main = &summary.setup;
    let mut kept = Vec::new();
    let (Some(points), Some(motion)) = (&main.section_points, &main.motion) else {
        return (Vec::new(), kept);
    };
    if main.initial_immersion > 0.0 {
        return (Vec::new(), kept);
    }
    let Ok(section) = Section::from_half_points(points.clone()) else {
        return (Vec::new(), kept);
    };
    // the requested resolution sets the stages' too: at the default level (40 particles per
    // half-breadth) a stage gives N particles across; a coarser or finer main run scales N and the
    // staging threshold with it, so that a quick run stays quick
    let scale = section.half_breadth() / summary.dp_m / REFERENCE_PARTICLES_PER_HALF_BEAM;
    let (target, below) = (PARTICLES_ACROSS_RESOLVED * scale, STAGE_BELOW * scale);
    let mut waiting: Vec<Waiting> = summary
        .sensors
        .iter()
        .filter_map(|q| {
            let a = q.anatomy.as_ref()?;
            let c = a.crossing_half_width_m?;
            let under = match a.status {
                ImpactStatus::InTransient => true,
                ImpactStatus::Resolved => c / summary.dp_m < below,
                _ => false,
            };
            (under && c > 0.0).then(|| Waiting {
                name: q.name.clone(),
                crossing: c,
            })
        })
        .collect();
    waiting.sort_by(|a, b| a.crossing.total_cmp(&b.crossing));
    // the velocity history the stages share, and Wagner's contact along it
    let Ok(built) = motion.build() else {
        return (Vec::new(), kept);
    };
    let n = 4000;
    let t: Vec<f64> = (0..=n).map(|k| main.t_end * k as f64 / n as f64).collect();
    let v: Vec<f64> = t
        .iter()
        .map(|&s| built.speed_at(s).unwrap_or(built.initial_speed()))
        .collect();
    let Ok(wagner) = generalised_wagner::estimate_immersed(section.half_points(), 0.0, &t, &v, 1.0)
    else {
        return (Vec::new(), kept);
    };
    let mut plans = Vec::new();
    let mut k = 0;
    while k < waiting.len() {
        let c_min = waiting[k].crossing;
        let group: Vec<&Waiting> = waiting[k..]
            .iter()
            .take_while(|w| w.crossing <= STAGE_SPAN * c_min)
            .collect();
        k += group.len();
        let names: Vec<String> = group.iter().map(|w| w.name.clone()).collect();
        let c_max = group.last().map_or(c_min, |w| w.crossing);
        let dp_s = c_min / target;
        let leave = |kept: &mut Vec<(String, String)>, why: String| {
            kept.extend(names.iter().map(|n| (n.clone(), why.clone())));
        };
        if plans.len() == MAX_STAGES {
            leave(
                &mut kept,
                format!("more than {MAX_STAGES} keel stages would be needed"),
            );
            continue;
        }
        if dp_s > 0.5 * summary.dp_m {
            leave(
                &mut kept,
                format!(
                    "the main run already has {:.0} particles across the crossing half-width; the crossing \
                     falls in the contact transient because the contact spreads over a flat or nearly flat \
                     bottom at the instant of contact, which no finer spacing resolves (an air-cushion impact)",
                    c_min / summary.dp_m
                ),
            );
            continue;
        }
        if dp_s < FINEST_FRACTION * summary.dp_m {
            leave(
                &mut kept,
                format!(
                    "a keel stage would need dp = {:.3} mm, finer than 1/{:.0} of the run's {:.3} mm",
                    dp_s * 1e3,
                    1.0 / FINEST_FRACTION,
                    summary.dp_m * 1e3
                ),
            );
            continue;
        }
        let Some(t_hi) = time_reaching(&wagner.t, &wagner.half_width, c_max) else {
            leave(
                &mut kept,
                "Wagner's contact does not reach the sensor within the run".into(),
            );
            continue;
        };
        let v_hi = built
            .speed_at(t_hi)
            .unwrap_or(built.initial_speed())
            .max(1e-9);
        let t_end = (t_hi * (1.0 + WINDOW_FRACTION) + LAG_SPACINGS * dp_s / v_hi).min(main.t_end);
        let cut = STAGE_BREADTH * c_max;
        match stage_setup(main, &section, cut, dp_s, t_end, &names, study) {
            Ok(setup) => plans.push(StagePlan {
                setup,
                sensors: names,
                crossing_half_widths_m: [c_min, c_max],
                cut_half_breadth_m: cut.min(section.half_breadth()),
            }),
            Err(e) => leave(&mut kept, format!("the keel stage cannot be set up: {e}")),
        }
    }
    (plans, kept)
}

/// The setup of one stage: the main run's motion, sound speed and numerics on the section cut at the
/// half-breadth `cut`, at spacing `dp_s`, to `t_end`, with the sensors `names` only. A main run with a
/// low-pass cut-off gets the stage's own cut-off by the same rule ([`cutoff::slamming_cutoff`]), since
/// the stage's sensors rise faster than the main run's quickest.
fn stage_setup(
    main: &Setup,
    section: &Section,
    cut: f64,
    dp_s: f64,
    t_end: f64,
    names: &[String],
    study: StudyPlan,
) -> Result<Setup> {
    let sub = cut_at_half_breadth(section, cut)?;
    let sensors: Vec<_> = main
        .sensors
        .iter()
        .filter(|s| names.contains(&s.name))
        .cloned()
        .collect();
    let o = Overrides {
        dp: Some(dp_s),
        c0: Some(main.c0),
        h_over_dp: Some(main.h_over_dp),
        eos: Some(main.eos),
        delta: Some(main.delta),
        alpha: Some(main.alpha),
        cfl: Some(main.cfl),
        shifting: Some(main.shifting),
        riemann: Some(main.riemann),
        divergence_correction: Some(main.divergence_correction),
        wall_wetness: Some(main.wall_wetness),
        force: Some(main.force),
        sensor_method: Some(main.sensor_method),
        mirror: Some(main.mirror),
        t_end: Some(t_end),
        refinement: Some(main.refinement.is_some()),
        // A stage of a run with air has air too (its own layer over the sub-section).
        air: Some(if main.air.is_some() {
            crate::sph::air::AirChoice::On
        } else {
            crate::sph::air::AirChoice::Off
        }),
        ..Overrides::default()
    };
    let motion = main.motion.as_ref().expect("a section run has a motion");
    let mut s = case::resolve(
        &format!("{} keel stage", main.name),
        &sub,
        motion,
        sensors,
        &o,
    )?;
    s.rho0 = main.rho0;
    s.g = main.g;
    s.snapshot_interval = None;
    s.notes.push(format!(
        "keel stage: the section cut at half-breadth {:.4} m, dp = {:.3} mm ({:.1} x finer than the main \
         run's {:.3} mm), to t = {:.5} s",
        cut.min(section.half_breadth()),
        dp_s * 1e3,
        main.dp / dp_s,
        main.dp * 1e3,
        t_end
    ));
    if main.filter_cutoff_hz.is_some() {
        let built = motion.build()?;
        let n = 2000;
        let t: Vec<f64> = (0..=n).map(|k| t_end * k as f64 / n as f64).collect();
        let v: Vec<f64> = t
            .iter()
            .map(|&x| built.speed_at(x).unwrap_or(built.initial_speed()))
            .collect();
        let coarsest = s.nominal_sample_hz() / study.ratio.powi(study.levels as i32 - 1);
        let c = cutoff::slamming_cutoff(&sub, 0.0, &t, &v, &s.sensors, s.c0, coarsest);
        s.filter_cutoff_hz = c.hz;
        s.notes.push(c.note);
    }
    Ok(s)
}

/// Run `setup` with its convergence study, then the keel stages of its under-resolved sensors
/// ([`plan`]), each into `stage_<k>/` of the output folder, and give the sensors they resolve the
/// stages' records, anatomies and convergence statements. A stage that fails leaves its sensors as
/// the main run had them, with the reason in [`StageRecord::left_out`]. The main run's `summary.json`
/// is rewritten with the stages.
pub fn run_staged(setup: Setup, opts: &RunOptions, study: StudyPlan) -> Result<RunResult> {
    let mut result = run_with_convergence(setup, opts, study)?;
    let (plans, kept) = plan(&result.summary, study);
    for (name, why) in kept {
        result.summary.warnings.push(format!(
            "sensor '{name}' is not resolved by a keel stage: {why}"
        ));
    }
    if plans.is_empty() {
        return Ok(result);
    }
    for (k, p) in plans.into_iter().enumerate() {
        let folder = opts.out_dir.as_ref().map(|d| d.join(format!("stage_{k}")));
        opts.progress.note(&format!(
            "keel stage {k} at dp {:.3} mm for {}",
            p.setup.dp * 1e3,
            p.sensors.join(", ")
        ));
        let o = RunOptions {
            out_dir: folder.clone(),
            progress: opts.progress.clone(),
            vtk: false,
            png: false,
            provenance: opts.provenance.clone(),
        };
        let mut rec = StageRecord {
            sensors: p.sensors.clone(),
            dp_m: p.setup.dp,
            crossing_half_widths_m: p.crossing_half_widths_m,
            cut_half_breadth_m: p.cut_half_breadth_m,
            t_end_s: p.setup.t_end,
            filter_cutoff_hz: p.setup.filter_cutoff_hz,
            fluid_particles: 0,
            steps: 0,
            wall_time_s: 0.0,
            folder,
            left_out: None,
        };
        match run_with_convergence(p.setup, &o, study) {
            Ok(r) => {
                rec.fluid_particles = r.summary.fluid_particles;
                rec.steps = r.summary.steps;
                rec.wall_time_s = r.summary.wall_time_s;
                let index = result.summary.stages.len();
                adopt(&mut result.summary, &r.summary, index);
            }
            Err(e) => rec.left_out = Some(format!("the stage stopped: {e}")),
        }
        result.summary.stages.push(rec);
    }
    // The list of widened sensors, now with the records the stages gave.
    let summary = &mut result.summary;
    summary
        .warnings
        .retain(|w| !w.starts_with(crate::sph::WIDENED_SENSORS));
    if let Some(w) = crate::sph::widened_sensor_warning(&summary.sensors) {
        summary.warnings.push(w);
    }
    if let Some(dir) = &opts.out_dir {
        let json = serde_json::to_string_pretty(&result.summary).expect("summary serialises");
        crate::files::write_text_atomic(&dir.join("summary.json"), &json)?;
    }
    Ok(result)
}

/// Give the main summary's sensors the stage's record, anatomy and convergence statements.
fn adopt(main: &mut RunSummary, stage: &RunSummary, index: usize) {
    for q in &stage.sensors {
        let Some(m) = main.sensors.iter_mut().find(|m| m.name == q.name) else {
            continue;
        };
        let mut adopted = q.clone();
        adopted.stage = Some(StageRef {
            stage: index,
            dp_m: stage.dp_m,
        });
        adopted.main_run_later_load = m.anatomy.as_ref().and_then(|a| {
            (a.largest_phase == crate::loads::anatomy::Phase::Immersion).then_some(LaterLoad {
                value: a.largest.value,
                time_s: a.largest.time,
                hydrostatic: a.hydrostatic_at_largest,
            })
        });
        *m = adopted;
        if let (Some(mc), Some(sc)) = (main.convergence.as_mut(), stage.convergence.as_ref()) {
            let prefix = format!("sensor {} ", q.name);
            mc.peaks.retain(|p| !p.name.starts_with(&prefix));
            mc.peaks.extend(
                sc.peaks
                    .iter()
                    .filter(|p| p.name.starts_with(&prefix))
                    .cloned(),
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cut_section_ends_at_the_requested_half_breadth() {
        let s = Section::wedge(30f64.to_radians(), 0.3, 0.3).unwrap();
        let c = cut_at_half_breadth(&s, 0.1).unwrap();
        let last = *c.half_points().last().unwrap();
        assert!((last[0] - 0.1).abs() < 1e-12, "{last:?}");
        assert!((last[1] - 0.1 * 30f64.to_radians().tan()).abs() < 1e-12);
        // beyond the widest point: the whole section
        let whole = cut_at_half_breadth(&s, 1.0).unwrap();
        assert_eq!(whole.half_points(), s.half_points());
    }
}
