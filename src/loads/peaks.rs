//! Peak value, time of peak and impulse of a time history; raw and after an optional zero-phase low-pass
//! filter (the cut-off is part of the result).

use serde::Serialize;

use crate::loads::butterworth::{LowPass, resample_uniform};
use crate::numerics::quadrature::trapezoid;

/// Peak of a history.
#[derive(Debug, Clone, Copy, Serialize, PartialEq)]
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
    pub raw: Peak,
    /// After the zero-phase low-pass filter (on a uniform resampling of the record).
    pub filtered: Option<Peak>,
    pub filter: Option<LowPass>,
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
        });
    };
    if t.len() < 4 {
        return Ok(Summary {
            raw,
            filtered: None,
            filter: None,
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
