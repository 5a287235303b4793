//! The analytic estimate of an event: the section force and the mean pressure on every sensor panel by
//! the modified Logvinovich model (MLM; Korobkin 2004), both corrected to the nonlinear similarity
//! solution of the equivalent wedge, along the event's entry-velocity history v(t), with the wetting of
//! generalised Wagner theory (Wagner 1932 with the wetting condition for the actual shape), whose
//! flat-plate force is kept beside the corrected one for comparison. A flare event (keel immersed to
//! d0 at the start) uses the same models with the initial immersion
//! ([`generalised_wagner::estimate_immersed`], [`Mlm::new_immersed`]): wetted to the waterline
//! half-breadth at the start, water at rest, the Wagner condition applied to the body above.
//!
//! The sensor pressures are the MLM's with the wedge-equivalent correction
//! ([`crate::analytic::similarity_table`]): at each instant the MLM pressure is scaled by the ratio of
//! the similarity solution's wedge peak to the MLM's own wedge peak at the local deadrise of the contact
//! point. Its error is stated in [`correction_note`]; the uncorrected MLM peak is kept beside it.

use serde::{Deserialize, Serialize};

use super::plan::EntryCase;
use crate::analytic::entry_kinematics::EntryHistory;
use crate::analytic::generalised_wagner;
use crate::analytic::logvinovich_mlm::Mlm;
use crate::analytic::peak::peak_candidates;
use crate::analytic::section_profile::Profile;
use crate::error::{Error, Result};
use crate::loads::peaks::peak;
use crate::sph::MotionSpec;

/// Fresh-water density (kg/m3), the SPH runs' default; an assessment (and a sweep) passes its loading's
/// density to [`estimate_in`].
pub const RHO: f64 = 1000.0;

/// One sensor's analytic peak.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct SensorEstimate {
    pub name: String,
    /// Corrected MLM peak outside the acoustic stage (Pa), time and impulse over the whole history.
    pub peak_pa: f64,
    pub peak_time_s: f64,
    pub impulse_pa_s: f64,
    /// Largest water-hammer pressure rho c_w V of the acoustic stage (a flat keel at contact), when there
    /// is one: an upper bound without air cushioning, not a slamming pressure, and kept out of `peak_pa`.
    pub acoustic_bound_pa: Option<f64>,
    /// The MLM peak without the wedge-equivalent correction (Pa).
    #[serde(default)]
    pub uncorrected_peak_pa: Option<f64>,
    /// Whether the panel's only values are the decay of a singular start (a panel on a flat keel, or
    /// below the waterline of an immersed start: wetted at once, its pressure falls from infinity), so
    /// that the models give it no peak; `peak_pa` is then 0.
    #[serde(default)]
    pub no_peak_after_start: bool,
}

impl SensorEstimate {
    /// The analytic peak (Pa), `None` where the models give none ([`SensorEstimate::no_peak_after_start`]).
    pub fn peak(&self) -> Option<f64> {
        (!self.no_peak_after_start).then_some(self.peak_pa)
    }
}

/// What the reports say of the corrected analytic sensor pressures (the errors measured in
/// `analytic::similarity_table::tests::measure_corrected_mlm_against_similarity`, the stated one
/// asserted in `analytic::similarity::tests`).
pub fn correction_note() -> String {
    format!(
        "analytic sensor pressures: modified Logvinovich model (Korobkin 2004) with the wedge-equivalent \
         correction (each instant scaled by the similarity solution's wedge peak over the model's own, \
         at the local deadrise of the contact point; analytic::similarity_table). For a wedge at \
         constant speed its peak is within {:.1} % of the nonlinear similarity solution from 5 to 55 deg \
         (uncorrected: 5 % high at 10 deg, 18 % at 20, 40 % at 30, 71 % at 40, 75 % at 55 deg). On other \
         sections and at varying speed it assumes local-wedge equivalence at the contact point and \
         constant speed, and its error there is not measured against an exact solution",
        100.0 * crate::analytic::similarity_table::STATED_ERROR
    )
}

/// What the reports say of the corrected analytic section force (the errors measured in
/// `analytic::similarity_force::tests`).
pub fn force_correction_note() -> String {
    format!(
        "analytic section force: modified Logvinovich model (Korobkin 2004) with the wedge-equivalent \
         correction (each instant scaled by the similarity solution's wedge force over the model's own, \
         for the wedge with the same penetration and Wagner wetted half-width; \
         analytic::similarity_force). For a wedge at constant speed it is within {:.1} % of the nonlinear \
         similarity force from 5 to 55 deg (the flat-plate Wagner force, kept beside it, is 8 % high at 5 \
         deg, 38 % at 20, 66 % at 30, 126 % at 45 deg; the uncorrected MLM force 1 % high at 20, 7 % at 30, \
         22 % at 45 deg). On other sections and at varying speed its error is not measured against an \
         exact solution",
        100.0 * crate::analytic::similarity_force::FORCE_STATED_ERROR
    )
}

/// What the estimate says of its section force after a singular start (a flat keel, or a section that
/// starts immersed).
pub const SINGULAR_START_FORCE_NOTE: &str = "analytic section force after a singular start (a flat keel, \
or a section that starts immersed): the flat-plate Wagner force, not the corrected modified Logvinovich \
force. The similarity solution is that of a wedge entering from its apex, which such a section has no \
equivalent of, and the MLM force falls from the start with no distinct peak of its own (on a 150 m hull's \
flat-bottomed section at 10.3 m/s its first later rise came at 0.58 s, 175 kN/m, after 1 MN/m at 50 ms). \
The flat-plate force over-predicts the load of the sides beyond a flat (Ochi's 0.174 Lpp section at 2.4 \
m/s: 1847 N/m against 1129 N/m of SPH hydrodynamic force), so it is kept as the conservative estimate";

/// The analytic estimate of one event.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct Estimate {
    /// Analytic section force (N/m): peak and time of the MLM force with the wedge-equivalent correction
    /// ([`crate::analytic::similarity_force`]); after a singular start (a flat keel or an immersed
    /// start) the flat-plate Wagner force's ([`SINGULAR_START_FORCE_NOTE`]), `None` where that only
    /// decays (the rule of [`crate::analytic::peak`]).
    pub force_peak_n_per_m: Option<f64>,
    pub force_peak_time_s: Option<f64>,
    /// The flat-plate (generalised) Wagner force's peak (N/m), for comparison: it over-predicts a
    /// wedge's similarity force, increasingly with the deadrise (module notes of
    /// [`crate::analytic::similarity_force`]).
    #[serde(default)]
    pub wagner_force_peak_n_per_m: Option<f64>,
    /// MLM mean pressure on each sensor panel.
    pub sensors: Vec<SensorEstimate>,
    /// Where the models stop or switch to acoustic values.
    pub notes: Vec<String>,
    /// The analytic force history [t since keel entry (s), F (N/m)] without the samples at the acoustic
    /// limit (for the time-coincident bow force; not written to summary.json).
    #[serde(skip)]
    pub force_history: Vec<[f64; 2]>,
}

impl Estimate {
    /// The largest sensor peak, or the force peak when there are no sensors (to rank events).
    pub fn ranking(&self) -> f64 {
        if self.sensors.is_empty() {
            self.force_peak_n_per_m.unwrap_or(0.0)
        } else {
            self.sensors.iter().map(|s| s.peak_pa).fold(0.0, f64::max)
        }
    }
}

/// The (t, v) samples of a prescribed entry motion.
pub(super) fn samples(motion: &MotionSpec) -> Result<(Vec<f64>, Vec<f64>)> {
    match motion {
        MotionSpec::Prescribed { table } => Ok((
            table.iter().map(|r| r[0]).collect(),
            table.iter().map(|r| r[1]).collect(),
        )),
        _ => Err(Error::Invalid(
            "the analytic estimate of an assessment event needs a prescribed entry-velocity table"
                .into(),
        )),
    }
}

/// Peak of (t, x) over the samples not flagged `acoustic`, with the impulse over the whole record.
/// After a `singular` start (a flat keel, or an immersed start) a record that starts wetted falls from
/// infinity, and only the samples from its first rise on can carry a peak (the rule of
/// [`crate::analytic::peak`], as for the Wagner force); the flag is true when none is left. Such a
/// panel's impact is the contact crossing the part of it that was dry at the start, so its peak is
/// looked for only up to `passed`, the first sample at which the contact point has passed the panel's
/// outer edge (`None`: it never does): a panel wetted over its whole width at the start has no impact
/// peak, and a later rise of its pressure (the velocity history acting on water already wetted, a few
/// pascals on the Ochi flat keels, found once the samples were fine enough to show it) is not one. A
/// panel still dry at the start (first kept value not positive) does not fall from infinity and keeps
/// all its samples.
fn peak_outside(
    t: &[f64],
    x: &[f64],
    acoustic: &[bool],
    singular: bool,
    passed: Option<usize>,
) -> (crate::loads::peaks::Peak, bool) {
    let mut p = peak(t, x);
    let mut kept: Vec<usize> = (0..t.len().min(x.len()))
        .filter(|&k| !acoustic.get(k).copied().unwrap_or(false))
        .collect();
    let falls_from_start = singular && kept.first().is_some_and(|&k| x[k] > 0.0);
    if falls_from_start && let Some(l) = passed {
        kept.retain(|&k| k <= l);
    }
    let candidates = peak_candidates(x, &kept, falls_from_start);
    let best = candidates
        .unwrap_or_default()
        .iter()
        .copied()
        .max_by(|&a, &b| x[a].total_cmp(&x[b]));
    match best {
        Some(k) => {
            p.value = x[k];
            p.time = t[k];
        }
        None => {
            p.value = 0.0;
            p.time = 0.0;
        }
    }
    (p, candidates.is_none())
}

/// Largest number of samples of an event's analytic histories after [`densify`] (the estimate's notes
/// say when it binds).
const MAX_SAMPLES: usize = 4000;

/// Samples per sensor crossing: the contact point may move along the contour by at most 1/32 of the
/// narrowest sensor's width between two samples. Measured on panels up a steep flare (the test
/// `panels_on_a_steep_side_do_not_depend_on_the_sampling`): 4 samples a crossing left the peaks up to
/// 10 % low and dependent on the table's sampling, 16 within 2.5 % of the 48-sample value, 32 within
/// 0.6 %.
const SAMPLES_PER_SENSOR: f64 = 32.0;

/// The velocity samples (`t`, `v`) with samples added (v from the shape-preserving cubic through the
/// table) wherever the contact point of a first Wagner pass (its arc length `c` from the keel along the
/// contour, at times `tc`) moves by more than `dc` between two of them, so that the peak of a sensor's
/// mean pressure, which lasts while the contact crosses the sensor, is not missed between samples (the
/// event tables have a few tens of samples, and the contact can cross a narrow sensor between two). The
/// distance is measured along the contour, as the sensor widths are: on a steep side the wetted
/// half-width hardly grows while the contact climbs across several panels, and counting the half-width
/// instead left such panels with one sample or none in their crossing, so their peaks depended on where
/// the samples fell (neighbouring panels of a steep flare read 1.3 and 6.1 kPa alternately). At most
/// [`MAX_SAMPLES`] in all.
fn densify(t: &[f64], v: &[f64], tc: &[f64], c: &[f64], dc: f64) -> (Vec<f64>, Vec<f64>, bool) {
    if t.len() < 2 || tc.len() < 2 || dc.is_nan() || dc <= 0.0 {
        return (t.to_vec(), v.to_vec(), false);
    }
    let table = crate::numerics::pchip::Pchip::new(t, v);
    let grown = |a: f64, b: f64| -> f64 {
        // growth of c between times a and b (c is sampled at tc; piecewise linear)
        let at = |x: f64| -> f64 {
            let k = tc.partition_point(|&s| s <= x);
            if k == 0 {
                c[0]
            } else if k >= tc.len() {
                c[c.len() - 1]
            } else {
                let f = (x - tc[k - 1]) / (tc[k] - tc[k - 1]);
                c[k - 1] + f * (c[k] - c[k - 1])
            }
        };
        (at(b) - at(a)).max(0.0)
    };
    let extra: Vec<usize> = t
        .windows(2)
        .map(|w| ((grown(w[0], w[1]) / dc).ceil() as usize).saturating_sub(1))
        .collect();
    let total: usize = t.len() + extra.iter().sum::<usize>();
    let scale = if total > MAX_SAMPLES {
        (MAX_SAMPLES - t.len()) as f64 / (total - t.len()) as f64
    } else {
        1.0
    };
    let (mut ts, mut vs) = (vec![t[0]], vec![v[0]]);
    for (k, w) in t.windows(2).enumerate() {
        let n = (extra[k] as f64 * scale).floor() as usize;
        for j in 1..=n {
            let x = w[0] + (w[1] - w[0]) * j as f64 / (n + 1) as f64;
            ts.push(x);
            vs.push(table.eval(x));
        }
        ts.push(w[1]);
        vs.push(v[k + 1]);
    }
    (ts, vs, scale < 1.0)
}

/// Estimate an event's force and sensor pressures in water of density `rho` (kg/m3).
pub fn estimate_in(case: &EntryCase, rho: f64) -> Result<Estimate> {
    let (t0, v0) = samples(&case.motion)?;
    let d0 = case.immersion_m;
    let first = generalised_wagner::estimate_immersed(&case.half_points, d0, &t0, &v0, rho)?;
    let narrowest = case
        .sensors
        .iter()
        .map(|s| s.width_m)
        .fold(f64::INFINITY, f64::min);
    let profile = Profile::from_half_points(&case.half_points)?;
    let (t, v, capped) = if narrowest.is_finite() {
        let contact_arc: Vec<f64> = first
            .half_width
            .iter()
            .map(|&c| profile.arc_length_to(c))
            .collect();
        densify(
            &t0,
            &v0,
            &first.t,
            &contact_arc,
            narrowest / SAMPLES_PER_SENSOR,
        )
    } else {
        (t0, v0, false)
    };
    // One entry history for the Wagner estimate and the MLM along the same samples.
    let hist = EntryHistory::new_immersed(&case.half_points, d0, &t, &v)?;
    let w = generalised_wagner::estimate_from_history(&hist, d0, rho);
    let mut notes = w.notes.clone();
    if capped {
        notes.push(format!(
            "analytic sensor peaks: the samples were capped at {MAX_SAMPLES}, fewer than {SAMPLES_PER_SENSOR} \
             per crossing of the narrowest sensor ({:.1} mm), so a peak between two samples may be read low",
            narrowest * 1e3
        ));
    }
    if let Some(why) = &w.stopped {
        notes.push(format!("Wagner estimate stops early: {why}"));
    }
    let mlm = Mlm::with_history(&case.half_points, hist, rho);
    let times = mlm.times();
    let acoustic = mlm.acoustic();
    if d0 > 0.0 {
        notes.push(
            "immersed start: the first sample (impulsive start of the linearised flow) is left out of the \
             sensor peaks; it is not an impact and no water-hammer bound is given"
                .into(),
        );
    } else if acoustic.iter().any(|&a| a) {
        notes.push(
            "flat keel: the first samples are in the acoustic stage, where the MLM gives the water-hammer \
             pressure rho c_w V (an upper bound without air cushioning, not a slamming pressure)"
                .into(),
        );
    }
    // All panels at once, one cumulative pressure integral along the arc per sample (samples in
    // parallel, collected in order, so the result does not depend on threads).
    let panels: Vec<(f64, f64)> = case
        .sensors
        .iter()
        .map(|s| ((s.s_m - 0.5 * s.width_m).max(0.0), s.s_m + 0.5 * s.width_m))
        .collect();
    let raw_histories = mlm.sensor_histories(&panels);
    let corrections = mlm.corrections();
    let histories: Vec<Vec<f64>> = raw_histories
        .iter()
        .map(|h| {
            h.iter()
                .zip(&corrections)
                .map(|(p, c)| p * c.factor)
                .collect()
        })
        .collect();
    notes.push(correction_note());
    if corrections.iter().any(|c| c.above_table) {
        let above = corrections.iter().filter(|c| c.above_table).count();
        notes.push(format!(
            "analytic sensor pressures: at {above} of {} samples the local deadrise at the contact point \
             is above {} deg, where no similarity solution is tabulated; the correction of {} deg is used \
             there (the MLM over-prediction grows with the deadrise, so this under-corrects)",
            corrections.len(),
            crate::analytic::similarity_table::MAX_DEG,
            crate::analytic::similarity_table::MAX_DEG
        ));
    }
    // Arc length of the contact point from the keel at each sample.
    let contact_arc: Vec<f64> = mlm
        .history()
        .states
        .iter()
        .map(|st| profile.arc_length_to(st.c))
        .collect();
    let sensors = case
        .sensors
        .iter()
        .zip(histories.iter().zip(&raw_histories))
        .map(|(s, (history, raw))| {
            let outer_edge = s.s_m + 0.5 * s.width_m;
            let passed = contact_arc.iter().position(|&a| a > outer_edge);
            let (p, no_peak) = peak_outside(&times, history, &acoustic, w.singular_start, passed);
            let (p_raw, _) = peak_outside(&times, raw, &acoustic, w.singular_start, passed);
            let bound = history
                .iter()
                .zip(&acoustic)
                .filter(|(_, a)| **a && d0 == 0.0)
                .map(|(p, _)| *p)
                .reduce(f64::max);
            SensorEstimate {
                name: s.name.clone(),
                peak_pa: p.value,
                peak_time_s: p.time,
                impulse_pa_s: p.impulse,
                acoustic_bound_pa: bound,
                uncorrected_peak_pa: Some(p_raw.value),
                no_peak_after_start: no_peak,
            }
        })
        .collect();
    let f = section_force(&w, &mlm);
    notes.extend(f.notes);
    let force = f.peak;
    Ok(Estimate {
        force_peak_n_per_m: force.map(|f| f.0),
        force_peak_time_s: force.map(|f| f.1),
        wagner_force_peak_n_per_m: w.force_peak().map(|f| f.0),
        sensors,
        notes,
        force_history: f.history,
    })
}

/// The analytic section force of an entry: its peak (N/m, s), the history it was taken from and what the
/// estimate says of it.
#[derive(Debug, Clone, PartialEq)]
pub struct SectionForce {
    /// Peak and its time; `None` where the force has no peak (the rule of [`crate::analytic::peak`]).
    pub peak: Option<(f64, f64)>,
    /// [t (s), F (N/m)] without the samples at the acoustic limit.
    pub history: Vec<[f64; 2]>,
    /// The model: [`MLM_FORCE_MODEL`] or [`WAGNER_FORCE_MODEL`].
    pub model: &'static str,
    /// Which model, and its stated error.
    pub notes: Vec<String>,
}

/// The corrected MLM force's name in outputs.
pub const MLM_FORCE_MODEL: &str =
    "modified Logvinovich, corrected to the similarity force of the equivalent wedge";
/// The flat-plate Wagner force's name in outputs (after a singular start).
pub const WAGNER_FORCE_MODEL: &str = "flat-plate Wagner (after a flat keel's or an immersed start)";

/// The analytic section force from the Wagner estimate `w` and the MLM `mlm` of the same entry: the MLM
/// force corrected to the similarity force of the equivalent wedge, its peak by the rule of the panels
/// (no contact-passing limit: the force has no panel); after a singular start (a flat keel, or a section
/// that starts immersed) there is no equivalent wedge and the MLM force has no distinct peak of its own,
/// so the flat-plate Wagner force stays the estimate ([`SINGULAR_START_FORCE_NOTE`]).
pub fn section_force(w: &generalised_wagner::WagnerEstimate, mlm: &Mlm) -> SectionForce {
    let mut notes = Vec::new();
    if w.singular_start {
        notes.push(SINGULAR_START_FORCE_NOTE.into());
        let history = (0..w.t.len().min(w.force.len()))
            .filter(|&k| !w.acoustic_limited.get(k).copied().unwrap_or(false))
            .map(|k| [w.t[k], w.force[k]])
            .collect();
        return SectionForce {
            peak: w.force_peak(),
            history,
            model: WAGNER_FORCE_MODEL,
            notes,
        };
    }
    notes.push(force_correction_note());
    let times = mlm.times();
    let acoustic = mlm.acoustic();
    let (series, k) = mlm.corrected_force_history();
    let (fp, no_peak) = peak_outside(&times, &series, &acoustic, false, None);
    if k.iter().any(|c| c.above_table) {
        notes.push(format!(
            "analytic section force: at {} of {} samples the equivalent wedge's deadrise is above {} deg; \
             the correction of {} deg is used there (this under-corrects: the force stays on the high side)",
            k.iter().filter(|c| c.above_table).count(),
            k.len(),
            crate::analytic::similarity_table::MAX_DEG,
            crate::analytic::similarity_table::MAX_DEG
        ));
    }
    SectionForce {
        peak: (!no_peak && fp.value > 0.0).then_some((fp.value, fp.time)),
        history: (0..times.len().min(series.len()))
            .filter(|&j| !acoustic.get(j).copied().unwrap_or(false))
            .map(|j| [times[j], series[j]])
            .collect(),
        model: MLM_FORCE_MODEL,
        notes,
    }
}

#[cfg(test)]
mod peak_tests {
    use super::peak_outside;

    #[test]
    fn a_record_falling_from_a_singular_start_has_no_peak() {
        let t = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
        let acoustic = [true, false, false, false, false, false];
        // wetted at once and only decaying: no peak after the start
        let decay = [9e9, 500.0, 300.0, 200.0, 150.0, 120.0];
        let (_, none) = peak_outside(&t, &decay, &acoustic, true, None);
        assert!(none);
        // decaying, then the contact loads the panel again: the peak is the later one
        let later = [9e9, 500.0, 300.0, 200.0, 350.0, 280.0];
        let (p, none) = peak_outside(&t, &later, &acoustic, true, None);
        assert!(!none);
        assert_eq!((p.value, p.time), (350.0, 4.0));
        // a panel dry at the start is not affected
        let dry = [0.0, 0.0, 100.0, 400.0, 300.0, 200.0];
        let (p, none) = peak_outside(&t, &dry, &acoustic, true, None);
        assert!(!none && p.value == 400.0);
        // a rise after the contact has passed the panel's outer edge (sample 2 here) is not its impact
        let (_, none) = peak_outside(&t, &later, &acoustic, true, Some(2));
        assert!(none);
        // a rise before it is
        let (p, none) = peak_outside(&t, &later, &acoustic, true, Some(4));
        assert!(!none && p.value == 350.0);
        // a panel dry at the start keeps all its samples whatever the contact does
        let (p, _) = peak_outside(&t, &dry, &acoustic, true, Some(1));
        assert_eq!(p.value, 400.0);
        // without a singular start the largest kept sample is the peak, as before
        let (p, _) = peak_outside(&t, &decay, &acoustic, false, None);
        assert_eq!(p.value, 500.0);
    }
}

#[cfg(test)]
mod densify_tests {
    use super::{RHO, densify, estimate_in};
    use crate::assess::plan::EntryCase;
    use crate::sph::MotionSpec;
    use crate::sph::sensors::SensorSpec;

    /// Panels up a steep flare (83 deg of deadrise above a 20 deg bottom) are crossed while the wetted
    /// half-width hardly grows: their peaks must not depend on the entry table's sampling (they did when
    /// the samples were added by the growth of the half-width rather than of the arc length).
    #[test]
    fn panels_on_a_steep_side_do_not_depend_on_the_sampling() {
        let half = vec![[0.0, 0.0], [0.1, 0.0364], [0.13, 0.3]];
        let flare_start = 0.1f64.hypot(0.0364);
        let sensors: Vec<SensorSpec> = (0..10)
            .map(|k| SensorSpec {
                name: format!("F{k}"),
                s_m: flare_start + 0.02 + 0.02 * k as f64,
                width_m: 0.01,
            })
            .collect();
        let case = |n: usize| EntryCase {
            half_points: half.clone(),
            motion: MotionSpec::Prescribed {
                table: (0..n)
                    .map(|k| {
                        let f = k as f64 / (n - 1) as f64;
                        [0.2 * f, 2.0 - f]
                    })
                    .collect(),
            },
            sensors: sensors.clone(),
            immersion_m: 0.0,
        };
        let a = estimate_in(&case(21), RHO).unwrap();
        let b = estimate_in(&case(47), RHO).unwrap();
        for (x, y) in a.sensors.iter().zip(&b.sensors) {
            assert!(x.peak_pa > 0.0, "{}: no peak", x.name);
            let r = x.peak_pa / y.peak_pa;
            assert!(
                (r - 1.0).abs() < 0.02,
                "{}: {} against {} Pa",
                x.name,
                x.peak_pa,
                y.peak_pa
            );
        }
    }

    #[test]
    fn samples_are_added_where_the_wetted_width_grows_fast() {
        // c grows by 0.1 m over the first interval and not at all over the second
        let t = [0.0, 1.0, 2.0];
        let v = [1.0, 2.0, 1.0];
        let (ts, vs, capped) = densify(&t, &v, &t, &[0.0, 0.1, 0.1], 0.01);
        assert!(!capped);
        assert_eq!(ts.len(), 3 + 9);
        assert!(ts.windows(2).all(|w| w[1] > w[0]));
        // the table's own samples are kept exactly
        for (x, y) in t.iter().zip(&v) {
            let k = ts.iter().position(|s| s == x).unwrap();
            assert_eq!(vs[k], *y);
        }
        // nothing is added over the second interval
        assert_eq!(ts[ts.len() - 2], 1.0);
    }
}

#[cfg(test)]
mod section_force_tests {
    use super::*;

    /// A wedge at constant speed gets the similarity force (within the stated 0.5 %) by the corrected MLM;
    /// a flat keel keeps the flat-plate Wagner force.
    #[test]
    fn a_wedge_gets_the_similarity_force_and_a_flat_keel_wagner_s() {
        let b = 30f64.to_radians();
        let t: Vec<f64> = (0..=200).map(|k| k as f64 * 1e-4).collect();
        let v = vec![5.0; t.len()];
        let wedge = [[0.0, 0.0], [0.25, 0.25 * b.tan()], [0.25, 0.5]];
        let w = generalised_wagner::estimate(&wedge, &t, &v, 1000.0).unwrap();
        let m = Mlm::new(&wedge, &t, &v, 1000.0).unwrap();
        let f = section_force(&w, &m);
        assert_eq!(f.model, MLM_FORCE_MODEL);
        let (peak, at) = f.peak.unwrap();
        let exact = crate::analytic::similarity_force::FORCE[5] * 1000.0 * 125.0 * at;
        assert!((peak / exact - 1.0).abs() < 0.005, "{peak} against {exact}");
        // the flat-plate force of the same wedge is 66 % above it
        let (wagner, _) = w.force_peak().unwrap();
        assert!(wagner > 1.6 * peak);
        let flat = [[0.0, 0.0], [0.1, 0.0], [0.25, 0.15], [0.25, 0.5]];
        let w = generalised_wagner::estimate(&flat, &t, &v, 1000.0).unwrap();
        let m = Mlm::new(&flat, &t, &v, 1000.0).unwrap();
        let f = section_force(&w, &m);
        assert!(w.singular_start);
        assert_eq!(f.model, WAGNER_FORCE_MODEL);
        assert_eq!(f.peak, w.force_peak());
        assert!(f.notes.iter().any(|n| n.contains("flat-plate Wagner")));
    }
}
