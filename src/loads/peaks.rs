//! Peak value, time of peak and impulse of a time history; raw and after an optional zero-phase low-pass
//! filter (the cut-off is part of the result).

use serde::{Deserialize, Serialize};

use crate::loads::butterworth::{LowPass, resample_uniform};
use crate::numerics::quadrature::trapezoid;

/// Peak of a history.
#[derive(Debug, Clone, Copy, Serialize, Deserialize, PartialEq)]
pub struct Peak {
    /// Largest value.
    pub value: f64,
    /// Time of the largest value (s).
    #[serde(rename = "time_s")]
    pub time: f64,
    /// Integral over the whole record (trapezoidal rule), e.g. N s/m for a force per metre.
    pub impulse: f64,
}

/// Peak, time of peak and impulse of (t, x). Returns zeros for an empty record.
pub fn peak(t: &[f64], x: &[f64]) -> Peak {
    let mut best = (f64::NEG_INFINITY, 0.0);
    for (&ti, &xi) in t.iter().zip(x) {
        if xi > best.0 {
            best = (xi, ti);
        }
    }
    if t.is_empty() {
        return Peak {
            value: 0.0,
            time: 0.0,
            impulse: 0.0,
        };
    }
    Peak {
        value: best.0,
        time: best.1,
        impulse: trapezoid(t, x),
    }
}

/// Raw and filtered peaks of one history.
#[derive(Debug, Clone, Serialize)]
pub struct Summary {
    /// The peak after the contact transient (the whole record when there is none); the impulse is over
    /// the whole record.
    pub raw: Peak,
    /// After the zero-phase low-pass filter (on a uniform resampling of the record), after the contact
    /// transient.
    pub filtered: Option<Peak>,
    pub filter: Option<LowPass>,
    /// The largest raw value during the contact transient, kept apart from the peak: at first contact
    /// a weakly compressible fluid carries an acoustic pressure of order rho c0 V over the first few
    /// particle spacings of penetration, the same at every resolution, which is not the slamming load.
    pub contact_transient: Option<Peak>,
    /// Whether the peak is the first sample after the contact transient: the record was still falling
    /// from the transient, so the value is its tail rather than a hydrodynamic peak.
    pub at_transient_end: bool,
    /// Whether the peak is the last sample of the record: the quantity was still rising when the run
    /// ended (a steady or hydrostatic load growing with the immersion), so the value is no impact peak.
    pub at_record_end: bool,
}

/// Peak of (t, x) over the samples with t >= t0, with the impulse over the whole record; the index of
/// the peak sample.
fn peak_from(t: &[f64], x: &[f64], t0: f64) -> (Peak, Option<usize>) {
    let k0 = t.partition_point(|&ti| ti < t0);
    let mut best: Option<usize> = None;
    for k in k0..t.len().min(x.len()) {
        if best.is_none_or(|b| x[k] > x[b]) {
            best = Some(k);
        }
    }
    let p = match best {
        Some(k) => Peak {
            value: x[k],
            time: t[k],
            impulse: trapezoid(t, x),
        },
        None => Peak {
            value: 0.0,
            time: 0.0,
            impulse: trapezoid(t, x),
        },
    };
    (p, best.map(|b| b - k0))
}

/// Summarise a history whose first part, t < `transient_end`, is the contact transient: the peaks are
/// taken after it, and the transient's own largest value is kept apart (see [`Summary`]).
pub fn summarise_after(
    t: &[f64],
    x: &[f64],
    cutoff_hz: Option<f64>,
    transient_end: f64,
) -> crate::error::Result<Summary> {
    let mut s = summarise(t, x, cutoff_hz)?;
    if transient_end <= t.first().copied().unwrap_or(0.0) {
        return Ok(s);
    }
    let (raw, k) = peak_from(t, x, transient_end);
    let k0 = t.partition_point(|&ti| ti < transient_end);
    s.contact_transient = (k0 > 0).then(|| peak(&t[..k0], &x[..k0]));
    if let Some(tr) = &mut s.contact_transient {
        tr.impulse = trapezoid(&t[..k0], &x[..k0]);
    }
    s.at_transient_end = k == Some(0) && k0 + 1 < t.len();
    s.at_record_end = k.is_some_and(|k| k0 + k + 1 == t.len().min(x.len())) && k != Some(0);
    s.raw = raw;
    if let (Some(f), Some(lp)) = (&mut s.filtered, &s.filter) {
        let (tu, y) = filtered_record(t, x, lp);
        *f = peak_from(&tu, &y, transient_end).0;
    }
    Ok(s)
}

/// The record (`t`, `x`) low-passed by `lp`: resampled uniformly at `lp`'s sampling rate, then filtered
/// forward and back (zero phase), as [`summarise`] filters it.
pub fn filtered_record(t: &[f64], x: &[f64], lp: &LowPass) -> (Vec<f64>, Vec<f64>) {
    let (tu, xu) = resample_uniform(t, x, 1.0 / lp.sample_hz);
    let y = lp.filtfilt(&xu);
    (tu, y)
}

/// Summarise a history: raw peak, and the filtered one when a cut-off is given. The record is resampled
/// uniformly at its mean time step before filtering with a 2nd-order Butterworth run forward and back.
pub fn summarise(t: &[f64], x: &[f64], cutoff_hz: Option<f64>) -> crate::error::Result<Summary> {
    let raw = peak(t, x);
    let Some(fc) = cutoff_hz else {
        return Ok(Summary {
            raw,
            filtered: None,
            filter: None,
            contact_transient: None,
            at_transient_end: false,
            at_record_end: false,
        });
    };
    if t.len() < 4 {
        return Ok(Summary {
            raw,
            filtered: None,
            filter: None,
            contact_transient: None,
            at_transient_end: false,
            at_record_end: false,
        });
    }
    let dt = (t[t.len() - 1] - t[0]) / (t.len() - 1) as f64;
    let (tu, xu) = resample_uniform(t, x, dt);
    let f = LowPass::new(fc, 1.0 / dt, 2)?;
    let y = f.filtfilt(&xu);
    Ok(Summary {
        raw,
        filtered: Some(peak(&tu, &y)),
        filter: Some(f),
        contact_transient: None,
        at_transient_end: false,
        at_record_end: false,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn peak_time_and_impulse() {
        let t: Vec<f64> = (0..=100).map(|k| k as f64 * 0.01).collect();
        let x: Vec<f64> = t.iter().map(|&t| t * (1.0 - t)).collect();
        let p = peak(&t, &x);
        assert!((p.value - 0.25).abs() < 1e-12);
        assert!((p.time - 0.5).abs() < 1e-12);
        assert!((p.impulse - 1.0 / 6.0).abs() < 1e-4);
    }
}
