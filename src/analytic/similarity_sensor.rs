//! The similarity solution as a pressure sensor of finite span reads it: the like-for-like reference of
//! an SPH wedge sensor.
//!
//! A wedge of deadrise beta enters calm water at constant speed V from t = 0 (keel at the surface). By
//! self-similarity ([`crate::analytic::similarity`]) the pressure at arc length s from the keel along
//! the side is p(s, t) = (rho V^2 / 2) Cp(zeta), zeta = z/(V t) = -1 + s sin(beta) / (V t), with Cp(zeta)
//! the solution's distribution on the wetted side. A sensor spanning [s1, s2] reads the mean
//!
//! ```text
//! p_sensor(t) = (rho V^2 / 2) (1 / (zeta2 - zeta1)) integral_{zeta1}^{zeta2} Cp(zeta) d zeta
//! ```
//!
//! (d s = V t / sin(beta) d zeta, so the mean over s is the mean over zeta), Cp taken piecewise linear
//! between the solution's panel midpoints (exact integral of that interpolant). Above the jet cut of the
//! solution (the jet is kept to a few root thicknesses past the spray root) and on the dry side the
//! pressure is taken as zero: the jet is at nearly ambient pressure. Below the first panel midpoint the
//! first value is held. The history is sampled uniformly over [0, t_end] and passed through the same
//! zero-phase filter as an SPH sensor history ([`crate::loads::peaks::summarise`]: a 2nd-order Butterworth
//! run forward and back at the cut-off), and its peak is taken after filtering.
//!
//! Validity: the similarity solution's (symmetric wedge, constant speed, no gravity, no air, 5-55 deg).

use std::collections::BTreeMap;
use std::sync::{Arc, Mutex, OnceLock};

use crate::analytic::similarity::{self, Similarity};
use crate::error::{Error, Result};
use crate::loads::butterworth::LowPass;

/// A sensor on the wedge side: centre at arc length `s_m` from the keel, `width_m` along the side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SensorSpan {
    pub s_m: f64,
    pub width_m: f64,
}

/// The reference history of one sensor and its peak.
#[derive(Debug, Clone)]
pub struct SensorReference {
    /// Uniform sample times (s) from 0 to t_end.
    pub t: Vec<f64>,
    /// Mean pressure over the span (Pa), unfiltered.
    pub raw: Vec<f64>,
    /// After the low-pass filter (the same as `raw` without a cut-off).
    pub filtered: Vec<f64>,
    /// Peak of `filtered` (Pa) and its time (s).
    pub peak_pa: f64,
    pub peak_time_s: f64,
}

/// Samples of a reference history.
pub const SAMPLES: usize = 4000;

/// The similarity solution for a deadrise (deg), solved once per deadrise in a process (a solve costs
/// seconds) with the default grid.
pub fn solution(deadrise_deg: f64) -> Result<Arc<Similarity>> {
    static CACHE: OnceLock<Mutex<BTreeMap<u64, Arc<Similarity>>>> = OnceLock::new();
    let cache = CACHE.get_or_init(|| Mutex::new(BTreeMap::new()));
    let key = deadrise_deg.to_bits();
    if let Some(s) = cache.lock().ok().and_then(|m| m.get(&key).cloned()) {
        return Ok(s);
    }
    let s = Arc::new(similarity::solve(deadrise_deg)?);
    if let Ok(mut m) = cache.lock() {
        m.entry(key).or_insert_with(|| s.clone());
    }
    Ok(s)
}

/// Cumulative integral of the piecewise-linear Cp(zeta) of a solution, for span means.
struct Cumulative {
    z: Vec<f64>,
    cp: Vec<f64>,
    int: Vec<f64>,
}

impl Cumulative {
    fn new(s: &Similarity) -> Self {
        let z: Vec<f64> = s.pressure.iter().map(|p| p[0]).collect();
        let cp: Vec<f64> = s.pressure.iter().map(|p| p[1]).collect();
        let mut int = vec![0.0; z.len()];
        for k in 1..z.len() {
            int[k] = int[k - 1] + 0.5 * (cp[k] + cp[k - 1]) * (z[k] - z[k - 1]);
        }
        Self { z, cp, int }
    }

    /// integral_{-1}^{zeta} Cp: the first value held from the keel (-1) to the first midpoint, zero
    /// above the last.
    fn at(&self, zeta: f64) -> f64 {
        let (z0, n) = (self.z[0], self.z.len());
        if zeta <= z0 {
            return self.cp[0] * (zeta + 1.0).max(0.0);
        }
        let head = self.cp[0] * (z0 + 1.0);
        if zeta >= self.z[n - 1] {
            return head + self.int[n - 1];
        }
        let k = self.z.partition_point(|&z| z <= zeta) - 1;
        let f = (zeta - self.z[k]) / (self.z[k + 1] - self.z[k]);
        let cp = self.cp[k] + f * (self.cp[k + 1] - self.cp[k]);
        head + self.int[k] + 0.5 * (self.cp[k] + cp) * (zeta - self.z[k])
    }

    /// Mean Cp over [zeta1, zeta2] (the point value for an empty span).
    fn mean(&self, z1: f64, z2: f64) -> f64 {
        if z2 - z1 <= 1e-12 * (1.0 + z1.abs()) {
            let e = 1e-9;
            return (self.at(z1 + e) - self.at(z1 - e)) / (2.0 * e);
        }
        (self.at(z2) - self.at(z1)) / (z2 - z1)
    }
}

/// The similarity solution's mean pressure over `span` on a wedge of deadrise `deadrise_deg` entering at
/// `speed` (m/s) into water of density `rho`, sampled at [`SAMPLES`] + 1 times over [0, `t_end`] and
/// filtered at `cutoff_hz` (none: unfiltered), with its peak (module notes).
pub fn similarity_sensor_reference(
    deadrise_deg: f64,
    speed: f64,
    rho: f64,
    span: SensorSpan,
    t_end: f64,
    cutoff_hz: Option<f64>,
) -> Result<SensorReference> {
    let finite_pos = |x: f64| x.is_finite() && x > 0.0;
    let valid = finite_pos(speed)
        && finite_pos(rho)
        && finite_pos(t_end)
        && span.s_m.is_finite()
        && span.width_m.is_finite()
        && span.width_m >= 0.0;
    if !valid {
        return Err(Error::Invalid(format!(
            "similarity sensor reference: speed {speed}, density {rho}, t_end {t_end} must be positive and \
             the sensor span (centre {}, width {}) finite",
            span.s_m, span.width_m
        )));
    }
    let sol = solution(deadrise_deg)?;
    let cum = Cumulative::new(&sol);
    let sb = deadrise_deg.to_radians().sin();
    let (s1, s2) = (
        (span.s_m - 0.5 * span.width_m).max(0.0),
        span.s_m + 0.5 * span.width_m,
    );
    let q = 0.5 * rho * speed * speed;
    let t: Vec<f64> = (0..=SAMPLES)
        .map(|k| t_end * k as f64 / SAMPLES as f64)
        .collect();
    let raw: Vec<f64> = t
        .iter()
        .map(|&tk| {
            if tk <= 0.0 {
                return 0.0;
            }
            let vt = speed * tk;
            q * cum.mean(-1.0 + s1 * sb / vt, -1.0 + s2 * sb / vt)
        })
        .collect();
    let filtered = match cutoff_hz {
        Some(fc) => {
            // Already uniform: the resampling of `summarise` is the identity here.
            let dt = t_end / SAMPLES as f64;
            LowPass::new(fc, 1.0 / dt, 2)?.filtfilt(&raw)
        }
        None => raw.clone(),
    };
    let k = (0..filtered.len())
        .max_by(|&a, &b| filtered[a].total_cmp(&filtered[b]))
        .unwrap_or(0);
    Ok(SensorReference {
        peak_pa: filtered[k],
        peak_time_s: t.get(k).copied().unwrap_or(0.0),
        t,
        raw,
        filtered,
    })
}
