//! The analytic estimate of an event: the generalised Wagner force of the section (Wagner 1932 with the
//! wetting condition for the actual shape) and the modified Logvinovich (MLM; Korobkin 2004) mean pressure
//! on every sensor panel, along the event's entry-velocity history v(t). A flare event (keel immersed to
//! d0 at the start) uses the same models with the initial immersion
//! ([`generalised_wagner::estimate_immersed`], [`Mlm::new_immersed`]): wetted to the waterline
//! half-breadth at the start, water at rest, the Wagner condition applied to the body above.

use serde::{Deserialize, Serialize};

use super::plan::EntryCase;
use crate::analytic::generalised_wagner;
use crate::analytic::logvinovich_mlm::Mlm;
use crate::error::{Error, Result};
use crate::loads::peaks::peak;
use crate::sph::MotionSpec;

/// Water density of the estimates (kg/m3), as the SPH runs use by default.
pub const RHO: f64 = 1000.0;

/// One sensor's analytic peak.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct SensorEstimate {
    pub name: String,
    /// MLM peak outside the acoustic stage (Pa), time and impulse over the whole history.
    pub peak_pa: f64,
    pub peak_time_s: f64,
    pub impulse_pa_s: f64,
    /// Largest water-hammer pressure rho c_w V of the acoustic stage (a flat keel at contact), when there
    /// is one: an upper bound without air cushioning, not a slamming pressure, and kept out of `peak_pa`.
    pub acoustic_bound_pa: Option<f64>,
}

/// The analytic estimate of one event.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct Estimate {
    /// Generalised Wagner section force (N/m): peak and time.
    pub force_peak_n_per_m: f64,
    pub force_peak_time_s: f64,
    /// MLM mean pressure on each sensor panel.
    pub sensors: Vec<SensorEstimate>,
    /// Where the models stop or switch to acoustic values.
    pub notes: Vec<String>,
    /// The generalised Wagner force history [t since keel entry (s), F (N/m)] without the samples at the
    /// acoustic limit (for the time-coincident bow force; not written to summary.json).
    #[serde(skip)]
    pub force_history: Vec<[f64; 2]>,
}

impl Estimate {
    /// The largest sensor peak, or the force peak when there are no sensors (to rank events).
    pub fn ranking(&self) -> f64 {
        if self.sensors.is_empty() {
            self.force_peak_n_per_m
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
fn peak_outside(t: &[f64], x: &[f64], acoustic: &[bool]) -> crate::loads::peaks::Peak {
    let mut p = peak(t, x);
    let best = (0..t.len().min(x.len()))
        .filter(|&k| !acoustic.get(k).copied().unwrap_or(false))
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
    p
}

/// Estimate an event's force and sensor pressures.
pub fn estimate(case: &EntryCase) -> Result<Estimate> {
    let (t, v) = samples(&case.motion)?;
    let d0 = case.immersion_m;
    let w = generalised_wagner::estimate_immersed(&case.half_points, d0, &t, &v, RHO)?;
    // Peaks of the models' own values: samples at the acoustic limit are the water-hammer bound.
    let (force_peak, force_time) = w.force_peak().unwrap_or((0.0, 0.0));
    let mut notes = w.notes.clone();
    if let Some(why) = &w.stopped {
        notes.push(format!("Wagner estimate stops early: {why}"));
    }
    let mlm = Mlm::new_immersed(&case.half_points, d0, &t, &v, RHO)?;
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
    let histories = mlm.sensor_histories(&panels);
    let sensors = case
        .sensors
        .iter()
        .zip(&histories)
        .map(|(s, history)| {
            let p = peak_outside(&times, history, &acoustic);
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
            }
        })
        .collect();
    let force_history = (0..w.t.len().min(w.force.len()))
        .filter(|&k| !w.acoustic_limited.get(k).copied().unwrap_or(false))
        .map(|k| [w.t[k], w.force[k]])
        .collect();
    Ok(Estimate {
        force_peak_n_per_m: force_peak,
        force_peak_time_s: force_time,
        sensors,
        notes,
        force_history,
    })
}
