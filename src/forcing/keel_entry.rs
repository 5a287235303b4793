//! Keel entry from a measured relative-motion record, and the entry-velocity profile V(t) after it.
//!
//! * Velocity. An elevation record s(t_k) is differentiated by second-order central differences on the
//!   record's own (possibly uneven) sampling,
//!
//!   ds/dt(t_k) = [h_-^2 s_{k+1} - h_+^2 s_{k-1} + (h_+^2 - h_-^2) s_k] / [h_+ h_- (h_+ + h_-)],
//!   h_- = t_k - t_{k-1}, h_+ = t_{k+1} - t_k
//!
//!   (the three-point Lagrange derivative; (s_{k+1} - s_{k-1}) / 2h for even sampling), and by one-sided
//!   first differences at the first and last samples. **No smoothing**: a noisy record gives a noisy
//!   velocity, so filter it before (and say so in its `#` lines). V = -ds/dt. A velocity record is used
//!   as given (`relative_velocity` negated, `entry_velocity` as is).
//! * Keel entry. For an elevation record: the first instant the relative elevation falls through the
//!   local draft T after having been above it (the keel out of the water), linearly interpolated between
//!   the two samples. A velocity record carries no elevation, so it **must start at the instant of keel
//!   entry**: its first sample is the entry, and its entry velocity there must be positive.
//! * Profile. From keel entry until V first falls to zero or below (the section stops going down; that
//!   sample included), or the keel is `max_depth` below the surface, or the record ends: the record's own
//!   samples, times counted from the entry, the keel depth T - s(t) (elevation) or the integral of V by
//!   the trapezoidal rule (velocity). As for strip theory ([`crate::seakeeping::relative_motion`]), the
//!   2D run is driven by max(V, 0) ([`crate::impact::entry_motion_of`]).

use serde::Serialize;

use super::record_csv::{Column, ForcingRecord};
use crate::error::{Error, Result};
use crate::seakeeping::relative_motion::EntrySample;
use crate::sph::MotionSpec;

/// How the velocity of an elevation record is obtained, as written with every output.
pub const DIFFERENTIATION: &str = "velocity from the relative elevation by second-order central \
differences on the record's sampling (one-sided first differences at its ends), no smoothing";

/// The keel entry found in a measured record and the velocity profile after it.
#[derive(Debug, Clone, Serialize)]
pub struct MeasuredEntry {
    /// The record's file as given.
    pub file: String,
    /// The record's `#` lines (source, sampling, filter), in order.
    pub provenance: Vec<String>,
    /// The record's motion column (fixes the sign convention).
    pub column: Column,
    /// How the velocity was obtained.
    pub velocity_from: String,
    /// Local draft of the station (m).
    #[serde(rename = "draft_m")]
    pub draft: f64,
    /// Instant of keel entry on the record's clock (s).
    #[serde(rename = "entry_time_s")]
    pub t_entry: f64,
    /// Downward velocity at keel entry (m/s).
    #[serde(rename = "entry_velocity_m_per_s")]
    pub entry_velocity: f64,
    /// Why the profile ends.
    pub profile_end: String,
    pub samples: Vec<EntrySample>,
}

impl MeasuredEntry {
    /// The prescribed motion of the 2D run: [t since entry, max(V, 0)].
    pub fn motion(&self) -> MotionSpec {
        crate::impact::entry_motion_of(&self.samples)
    }

    /// Downward velocity at `t` s after keel entry, linear between the profile's samples (None outside
    /// the profile).
    pub fn velocity_at(&self, t: f64) -> Option<f64> {
        let s = &self.samples;
        let k = s.partition_point(|q| q.t <= t);
        if k == 0 || k > s.len() || (k == s.len() && t > s[k - 1].t) {
            return None;
        }
        if k == s.len() {
            return Some(s[k - 1].velocity);
        }
        let (a, b) = (&s[k - 1], &s[k]);
        Some(a.velocity + (b.velocity - a.velocity) * (t - a.t) / (b.t - a.t))
    }
}

/// The downward velocity V = -Ds/Dt at every sample of the record.
pub fn entry_velocities(r: &ForcingRecord) -> Vec<f64> {
    match r.column {
        Column::EntryVelocity => r.values.clone(),
        Column::RelativeVelocity => r.values.iter().map(|v| -v).collect(),
        Column::RelativeElevation => central_differences(&r.time_s, &r.values)
            .iter()
            .map(|d| -d)
            .collect(),
    }
}

/// ds/dt by the three-point (second-order) central difference inside, first differences at the ends.
pub fn central_differences(t: &[f64], s: &[f64]) -> Vec<f64> {
    let n = t.len().min(s.len());
    if n < 2 {
        return vec![0.0; n];
    }
    (0..n)
        .map(|k| {
            if k == 0 {
                (s[1] - s[0]) / (t[1] - t[0])
            } else if k == n - 1 {
                (s[k] - s[k - 1]) / (t[k] - t[k - 1])
            } else {
                let (hm, hp) = (t[k] - t[k - 1], t[k + 1] - t[k]);
                (hm * hm * s[k + 1] - hp * hp * s[k - 1] + (hp * hp - hm * hm) * s[k])
                    / (hp * hm * (hp + hm))
            }
        })
        .collect()
}

/// The keel entry of a station of local draft `draft` (m) in the record, and the profile after it until
/// V reverses or the keel is `max_depth` (m) deep.
pub fn measured_entry(r: &ForcingRecord, draft: f64, max_depth: f64) -> Result<MeasuredEntry> {
    // A dry station (keel above the calm waterline) has a negative draft: its keel is out while s > draft
    // as well.
    if !(draft.is_finite() && max_depth.is_finite() && max_depth > 0.0) {
        return Err(Error::Invalid(format!(
            "a measured entry needs a finite local draft and a positive depth, got {draft} m and {max_depth} m"
        )));
    }
    let t = &r.time_s;
    let v = entry_velocities(r);
    let n = t.len();
    // (index of the first sample after the entry, entry time, entry velocity, keel depth function)
    let (first, t_e, v_e) = match r.column {
        Column::RelativeElevation => {
            let s = &r.values;
            let (top, s_max) = s
                .iter()
                .enumerate()
                .fold((0, f64::MIN), |a, (k, &x)| if x > a.1 { (k, x) } else { a });
            if s_max <= draft {
                return Err(r.error_at_sample(
                    top,
                    1,
                    format!(
                        "the keel never leaves the water in this record, so it never enters: the largest \
                         relative elevation is {s_max} m (this line) against the local draft {draft} m \
                         (relative_elevation is the height of the still-water-line point above the water; \
                         the keel is out while it exceeds the draft)"
                    ),
                ));
            }
            let Some(k) = (top..n - 1).find(|&k| s[k] > draft && s[k + 1] <= draft) else {
                return Err(r.error_at_sample(
                    n - 1,
                    1,
                    format!(
                        "the keel never enters in this record: the relative elevation is above the local \
                         draft {draft} m at line {} and does not fall through it before the record ends",
                        r.lines[top]
                    ),
                ));
            };
            let f = (s[k] - draft) / (s[k] - s[k + 1]);
            (
                k + 1,
                t[k] + f * (t[k + 1] - t[k]),
                v[k] + f * (v[k + 1] - v[k]),
            )
        }
        Column::RelativeVelocity | Column::EntryVelocity => {
            if v[0] <= 0.0 {
                return Err(r.error_at_sample(
                    0,
                    1,
                    format!(
                        "a velocity record must start at the instant of keel entry, with the hull going \
                         down; its first sample gives the downward velocity {} m/s (give the relative \
                         elevation instead to have the entry found from the record)",
                        v[0]
                    ),
                ));
            }
            (1, t[0], v[0])
        }
    };
    let mut samples = vec![EntrySample {
        t: 0.0,
        velocity: v_e,
        penetration: 0.0,
    }];
    let mut end = "the record ends".to_string();
    let mut depth = 0.0;
    // Samples closer to the entry than this are the entry itself (a crossing exactly at a sample).
    let same = 1e-9 * (t[n - 1] - t[0]);
    for k in first..n {
        if t[k] - t_e <= same {
            continue;
        }
        let prev = samples[samples.len() - 1];
        depth = match r.column {
            Column::RelativeElevation => draft - r.values[k],
            _ => depth + 0.5 * (prev.velocity + v[k]) * (t[k] - t_e - prev.t),
        };
        samples.push(EntrySample {
            t: t[k] - t_e,
            velocity: v[k],
            penetration: depth,
        });
        if v[k] <= 0.0 {
            end = "the entry velocity falls to zero (the section stops going down)".into();
            break;
        }
        if depth >= max_depth {
            end = format!("the keel is {max_depth} m deep (the section's height)");
            break;
        }
    }
    if samples.len() < 2 {
        return Err(r.error_at_sample(
            n - 1,
            1,
            "the record ends at the instant of keel entry: it needs samples after the entry",
        ));
    }
    Ok(MeasuredEntry {
        file: r.path.display().to_string(),
        provenance: r.provenance.clone(),
        column: r.column,
        velocity_from: match r.column {
            Column::RelativeElevation => DIFFERENTIATION.into(),
            Column::RelativeVelocity => {
                "relative velocity as recorded, negated (V = -Ds/Dt)".into()
            }
            Column::EntryVelocity => "entry velocity as recorded".into(),
        },
        draft,
        t_entry: t_e,
        entry_velocity: v_e,
        profile_end: end,
        samples,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn central_differences_are_exact_for_a_parabola_on_uneven_sampling() {
        let t = [0.0, 0.1, 0.25, 0.3, 0.5];
        let s: Vec<f64> = t.iter().map(|x| 2.0 * x * x - x + 1.0).collect();
        let d = central_differences(&t, &s);
        for k in 1..4 {
            assert!((d[k] - (4.0 * t[k] - 1.0)).abs() < 1e-12, "{k}: {}", d[k]);
        }
    }
}
