//! Like-for-like references of the wedge sensors: what theory says a sensor of the same span reads,
//! filtered as the SPH history is.
//!
//! * The reference: the nonlinear similarity solution ([`crate::analytic::similarity`]) averaged over the
//!   sensor's span as the flow passes it and filtered with the same zero-phase low-pass filter as the
//!   SPH sensor history ([`similarity_sensor_reference`]).
//! * The second line, labelled as such: Wagner's composite distribution (outer flat-plate solution and
//!   jet-root solution, [`WagnerWedge`]) averaged and filtered the same way. It carries more load than
//!   the nonlinear flow (Cp_max 5 % above the similarity solution at 20 deg, 7 % at 30 deg).
//!
//! Until issue 28 the reference was that Wagner composite at every deadrise but 20 deg, and at 20 deg
//! the tabulated Zhao & Faltinsen Cp_max 17.77 lowered by the ratio of the averaged, filtered Wagner
//! peak to Wagner's point peak (the similarity distribution was not available).

use crate::analytic::similarity_sensor::{SensorSpan, similarity_sensor_reference, solution};
use crate::analytic::wagner_pressure::WagnerWedge;
use crate::error::{Error, Result};
use crate::loads::peaks::summarise;
use crate::sph::NamedSummary;
use crate::sph::sensors::SensorSpec;
use std::f64::consts::PI;

use super::conditions::WATER_DENSITY;

/// Filtered peak (value, time) of a history.
pub(super) fn filtered_peak(t: &[f64], x: &[f64], cutoff: f64) -> Result<(f64, f64)> {
    let s = summarise(t, x, Some(cutoff))?
        .filtered
        .ok_or_else(|| Error::Numerical("a history too short to filter".into()))?;
    Ok((s.value, s.time))
}

/// Like-for-like reference of a sensor (centre `s`, `width` along the side) on a wedge of deadrise
/// `beta` (rad) at constant speed `v` over [0, t_end]: the similarity solution averaged over the span
/// and filtered at `cutoff` Hz ([`similarity_sensor_reference`]); its peak Cp = 2 p / (rho V^2) and the
/// time of that peak (s).
pub fn like_for_like(
    beta: f64,
    v: f64,
    s: f64,
    width: f64,
    t_end: f64,
    cutoff: f64,
) -> Result<(f64, f64)> {
    let r = similarity_sensor_reference(
        beta.to_degrees(),
        v,
        WATER_DENSITY,
        SensorSpan {
            s_m: s,
            width_m: width,
        },
        t_end,
        Some(cutoff),
    )?;
    Ok((r.peak_pa / (0.5 * WATER_DENSITY * v * v), r.peak_time_s))
}

/// Centre and width (m) of the contour span a sensor's reference is averaged over: the span the SPH
/// sensor integrates (its own width, or the narrowest span of [`crate::sph::sensors::integration_span`]
/// when it is narrower), so that reference and SPH cover the same wall.
pub fn reference_span(s: &SensorSpec, named: &NamedSummary) -> (f64, f64) {
    named
        .integration_span_m
        .map_or((s.s_m, s.width_m), |[a, b]| (0.5 * (a + b), b - a))
}

/// The peak Cp of [`like_for_like`].
pub fn like_for_like_cp(
    beta: f64,
    v: f64,
    s: f64,
    width: f64,
    t_end: f64,
    cutoff: f64,
) -> Result<f64> {
    Ok(like_for_like(beta, v, s, width, t_end, cutoff)?.0)
}

/// The second line: Wagner's composite distribution averaged over the sensor width (sampled every
/// t_end / 4000) and filtered like the SPH history; its peak Cp.
pub fn wagner_like_for_like_cp(
    beta: f64,
    v: f64,
    s: f64,
    width: f64,
    t_end: f64,
    cutoff: f64,
) -> Result<f64> {
    let w = WagnerWedge::new(beta, WATER_DENSITY, v)?;
    let n = 4000;
    let t: Vec<f64> = (0..=n).map(|k| t_end * k as f64 / n as f64).collect();
    let (p, _) = filtered_peak(&t, &w.sensor_history(s, width, &t), cutoff)?;
    Ok(p / (0.5 * WATER_DENSITY * v * v))
}

/// Time at which the reference pressure peak passes arc length `s` from the keel of a wedge of deadrise
/// `beta` (rad) at constant speed `v`: the peak is at height (1 + z/Vt) V t above the keel, with z/Vt
/// the similarity solution's height of Cp_max; Wagner's pi/2 - 1 where the similarity solution has no
/// peak near the spray root (from 45 deg up its largest pressure is at the keel) or cannot be solved
/// (outside 5-55 deg).
pub fn reference_peak_time(beta: f64, v: f64, s: f64) -> f64 {
    let rise = solution(beta.to_degrees())
        .ok()
        .map(|sol| sol.z_cp_max)
        .filter(|&z| z > -0.5)
        .map_or(0.5 * PI, |z| 1.0 + z);
    s * beta.sin() / (rise * v)
}
