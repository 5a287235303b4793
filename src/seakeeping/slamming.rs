//! Slamming statistics in irregular head seas by Ochi's (1964) criterion.
//!
//! A slam at a station needs the keel to emerge (relative motion above the local draft T) and the
//! re-entry relative velocity to exceed v_th = 0.093 sqrt(g Lpp). For a Gaussian sea with the spectral
//! moments m0 (relative motion variance) and m2 (relative velocity variance):
//!
//! P(slam per encounter) = exp(-T^2/(2 m0) - v_th^2/(2 m2)),
//! slams per hour = 3600/(2 pi) sqrt(m2/m0) P
//!
//! (Ochi 1964, as given in ../reference/water_entry_theory.md). Given a slam, the entry velocity is Rayleigh
//! distributed above v_th: P(V > v | slam) = exp(-(v^2 - v_th^2)/(2 m2)), so the most probable largest of
//! N slams is sqrt(v_th^2 + 2 m2 ln N). With the keel-slope term of the 2D+t plane, a steady velocity V_s
//! added to every keel entry, the oscillating part's threshold is max(v_th - V_s, 0) and every slam's
//! velocity is V_s more ([`SlamStatistics::with_steady_velocity`]). The operability limit is the highest
//! speed at which the slam probability stays below a limit (3 % per encounter by default, ship-handling
//! practice).

use super::ShipModel;
use super::relative_motion;
use super::strip_theory::{self, SectionSolutions, StripSettings};
use crate::error::{Error, Result};

/// Ochi's (1964) threshold velocity 0.093 sqrt(g Lpp) (m/s).
pub fn threshold_velocity(g: f64, lpp: f64) -> f64 {
    0.093 * (g * lpp).sqrt()
}

/// Default operability limit on the slam probability per encounter.
pub const DEFAULT_SLAM_PROBABILITY_LIMIT: f64 = 0.03;

/// Wave spectrum sampled on increasing wave frequencies: (w0, S(w0)) in (rad/s, m^2 s).
#[derive(Debug, Clone)]
pub struct SampledSpectrum {
    pub omega: Vec<f64>,
    pub density: Vec<f64>,
}

impl SampledSpectrum {
    pub fn new(omega: Vec<f64>, density: Vec<f64>) -> Result<Self> {
        if omega.len() < 3 || omega.len() != density.len() {
            return Err(Error::Invalid(
                "spectrum needs at least three (omega, S) samples".into(),
            ));
        }
        if omega
            .windows(2)
            .any(|w| w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater))
            || omega[0] <= 0.0
            || density.iter().any(|s| !s.is_finite() || *s < 0.0)
        {
            return Err(Error::Invalid(
                "spectrum frequencies must increase from > 0, densities be >= 0".into(),
            ));
        }
        Ok(Self { omega, density })
    }

    /// Sample a spectral density function between w_min and w_max with n points.
    pub fn from_fn(f: impl Fn(f64) -> f64, w_min: f64, w_max: f64, n: usize) -> Result<Self> {
        let omega: Vec<f64> = (0..n)
            .map(|i| w_min + (w_max - w_min) * i as f64 / (n - 1) as f64)
            .collect();
        let density = omega.iter().map(|&w| f(w)).collect();
        Self::new(omega, density)
    }

    /// Zeroth moment (wave elevation variance).
    pub fn m0(&self) -> f64 {
        crate::numerics::quadrature::trapezoid(&self.omega, &self.density)
    }
}

/// Slam statistics at one station and speed.
#[derive(Debug, Clone, Copy, serde::Serialize)]
pub struct SlamStatistics {
    #[serde(rename = "x_m")]
    pub x: f64,
    #[serde(rename = "speed_m_per_s")]
    pub speed: f64,
    #[serde(rename = "draft_m")]
    pub draft: f64,
    /// Relative-motion variance m0 (m^2).
    #[serde(rename = "relative_motion_variance_m2")]
    pub m0: f64,
    /// Relative-velocity variance m2 (m^2/s^2).
    #[serde(rename = "relative_velocity_variance_m2_per_s2")]
    pub m2: f64,
    #[serde(rename = "threshold_velocity_m_per_s")]
    pub threshold_velocity: f64,
    #[serde(rename = "slam_probability")]
    pub probability: f64,
    pub slams_per_hour: f64,
    /// Steady downward velocity added to the oscillating relative velocity at keel entry (m/s): the
    /// keel-slope term U dz_k/dx when it is on ([`SlamStatistics::with_steady_velocity`]), else 0.
    #[serde(rename = "keel_slope_velocity_m_per_s")]
    pub steady_velocity: f64,
}

impl SlamStatistics {
    /// The threshold the oscillating part of the entry velocity has to exceed for a slam (m/s):
    /// max(v_th - V_s, 0) with the steady velocity V_s.
    pub fn oscillating_threshold(&self) -> f64 {
        (self.threshold_velocity - self.steady_velocity).max(0.0)
    }

    /// Most probable largest entry velocity in `n` slams (m/s): sqrt(v'^2 + 2 m2 ln n) + V_s with the
    /// oscillating threshold v' ([`SlamStatistics::oscillating_threshold`]).
    pub fn most_probable_extreme_velocity(&self, n: f64) -> f64 {
        (self.oscillating_threshold().powi(2) + 2.0 * self.m2 * n.max(1.0).ln()).sqrt()
            + self.steady_velocity
    }

    /// The entry velocity a slam exceeds with probability `q` (0 < q <= 1; m/s): sqrt(v'^2 - 2 m2 ln q) +
    /// V_s, from the Rayleigh tail P(v > u | slam) = exp(-(u^2 - v'^2) / (2 m2)) of the oscillating part.
    pub fn velocity_exceeded_with(&self, q: f64) -> f64 {
        (self.oscillating_threshold().powi(2) - 2.0 * self.m2 * q.ln()).sqrt()
            + self.steady_velocity
    }

    /// The statistics with a steady downward velocity `v_s` (m/s; the keel-slope term U dz_k/dx of the
    /// 2D+t plane) added to the oscillating relative velocity at every keel entry. A slam is an entry whose
    /// total velocity v + V_s exceeds v_th, so the oscillating part's threshold becomes v' = max(v_th -
    /// V_s, 0) in Ochi's probability: P = exp(-T^2/(2 m0) - v'^2/(2 m2)). Entries are still the relative
    /// motion's up-crossings of the draft (the steady sinking does not change when the water reaches
    /// the keel), so the rate of entries is unchanged.
    pub fn with_steady_velocity(self, v_s: f64) -> Self {
        let shifted = Self {
            steady_velocity: v_s,
            ..self
        };
        let base = ochi(
            self.x,
            self.speed,
            self.draft,
            self.m0,
            self.m2,
            shifted.oscillating_threshold(),
        );
        Self {
            probability: base.probability,
            slams_per_hour: base.slams_per_hour,
            ..shifted
        }
    }
}

/// Ochi statistics from the moments.
pub fn ochi(x: f64, speed: f64, draft: f64, m0: f64, m2: f64, v_th: f64) -> SlamStatistics {
    let (probability, rate) = if m0 > 0.0 && m2 > 0.0 {
        let p = (-draft * draft / (2.0 * m0) - v_th * v_th / (2.0 * m2)).exp();
        (
            p,
            3600.0 / (2.0 * std::f64::consts::PI) * (m2 / m0).sqrt() * p,
        )
    } else {
        (0.0, 0.0)
    };
    SlamStatistics {
        x,
        speed,
        draft,
        m0,
        m2,
        threshold_velocity: v_th,
        probability,
        slams_per_hour: rate,
        steady_velocity: 0.0,
    }
}

/// Response spectra of relative motion and velocity at one station, on the encounter frequencies of the
/// sampled wave spectrum: S_s(w_e) = |s(w0)|^2 S(w0) / (dw_e/dw0), dw_e/dw0 = 1 + 2 w0 U / g (head seas).
#[derive(Debug, Clone, serde::Serialize)]
pub struct ResponseSpectrum {
    #[serde(rename = "x_m")]
    pub x: f64,
    #[serde(rename = "speed_m_per_s")]
    pub speed: f64,
    #[serde(rename = "wave_frequency_rad_per_s")]
    pub omega0: Vec<f64>,
    #[serde(rename = "encounter_frequency_rad_per_s")]
    pub omega_e: Vec<f64>,
    /// Relative motion spectral density per unit encounter frequency (m^2 s).
    #[serde(rename = "relative_motion_m2_s")]
    pub motion: Vec<f64>,
    /// Relative velocity spectral density per unit encounter frequency (m^2/s).
    #[serde(rename = "relative_velocity_m2_per_s")]
    pub velocity: Vec<f64>,
}

impl ResponseSpectrum {
    /// (m0, m2): variances of relative motion and relative velocity. Integrated over w0 (same value as over
    /// w_e, without the Jacobian's discretisation error).
    pub fn moments(&self, g: f64) -> (f64, f64) {
        let jac: Vec<f64> = self
            .omega0
            .iter()
            .map(|w| 1.0 + 2.0 * w * self.speed / g)
            .collect();
        let s: Vec<f64> = self.motion.iter().zip(&jac).map(|(a, j)| a * j).collect();
        let v: Vec<f64> = self.velocity.iter().zip(&jac).map(|(a, j)| a * j).collect();
        (
            crate::numerics::quadrature::trapezoid(&self.omega0, &s),
            crate::numerics::quadrature::trapezoid(&self.omega0, &v),
        )
    }
}

/// Response spectra at stations `xs` for one speed in a sampled head-sea spectrum.
pub fn response_spectra<S: SectionSolutions + ?Sized>(
    model: &ShipModel,
    spectrum: &SampledSpectrum,
    speed: f64,
    xs: &[f64],
    swell_up: f64,
    sections: &S,
) -> Result<Vec<ResponseSpectrum>> {
    let n = spectrum.omega.len();
    let mut out: Vec<ResponseSpectrum> = xs
        .iter()
        .map(|&x| ResponseSpectrum {
            x,
            speed,
            omega0: spectrum.omega.clone(),
            omega_e: vec![0.0; n],
            motion: vec![0.0; n],
            velocity: vec![0.0; n],
        })
        .collect();
    for (j, &w0) in spectrum.omega.iter().enumerate() {
        let r = strip_theory::respond(model, w0, speed, sections)?;
        let jac = 1.0 + 2.0 * w0 * speed / model.g;
        for rs in out.iter_mut() {
            let rm = relative_motion::at_station(&r, rs.x, swell_up)?;
            rs.omega_e[j] = r.omega_e;
            rs.motion[j] = rm.motion.norm_sqr() * spectrum.density[j] / jac;
            rs.velocity[j] = rm.velocity.norm_sqr() * spectrum.density[j] / jac;
        }
    }
    Ok(out)
}

/// Slam statistics at the given stations (x, local draft) for one speed in a sampled head-sea spectrum.
pub fn statistics(
    model: &ShipModel,
    spectrum: &SampledSpectrum,
    speed: f64,
    stations: &[(f64, f64)],
    swell_up: f64,
    settings: &StripSettings,
) -> Result<Vec<SlamStatistics>> {
    let xs: Vec<f64> = stations.iter().map(|s| s.0).collect();
    let spectra = response_spectra(model, spectrum, speed, &xs, swell_up, settings)?;
    Ok(statistics_from_spectra(model, &spectra, stations))
}

/// Ochi statistics from response spectra computed by [`response_spectra`] for the same stations.
pub fn statistics_from_spectra(
    model: &ShipModel,
    spectra: &[ResponseSpectrum],
    stations: &[(f64, f64)],
) -> Vec<SlamStatistics> {
    let v_th = threshold_velocity(model.g, model.lpp);
    spectra
        .iter()
        .zip(stations)
        .map(|(rs, &(x, draft))| {
            let (m0, m2) = rs.moments(model.g);
            ochi(x, rs.speed, draft, m0, m2, v_th)
        })
        .collect()
}

/// Operability: slam probability (highest over the stations) per speed and the speed limit.
#[derive(Debug, Clone, serde::Serialize)]
pub struct Operability {
    #[serde(rename = "slam_probability_limit")]
    pub limit: f64,
    #[serde(rename = "speeds_m_per_s")]
    pub speeds: Vec<f64>,
    #[serde(rename = "max_slam_probability")]
    pub max_probability: Vec<f64>,
    /// Highest speed with the slam probability below the limit (linear interpolation between the last
    /// acceptable and the first unacceptable speed); None when even the lowest speed exceeds the limit.
    #[serde(rename = "limit_speed_m_per_s")]
    pub limit_speed: Option<f64>,
}

/// The operability limit from the probabilities at increasing speeds.
pub fn operability_limit(
    speeds: &[f64],
    max_probability: &[f64],
    limit: f64,
) -> Result<Operability> {
    if !(limit > 0.0 && limit < 1.0) {
        return Err(Error::Invalid(format!(
            "slam probability limit must be in (0, 1), got {limit}"
        )));
    }
    if speeds.is_empty() || speeds.len() != max_probability.len() {
        return Err(Error::Invalid(
            "operability needs one probability per speed".into(),
        ));
    }
    if speeds
        .windows(2)
        .any(|w| w[1].partial_cmp(&w[0]) != Some(std::cmp::Ordering::Greater))
    {
        return Err(Error::Invalid("speeds must increase".into()));
    }
    let mut limit_speed = None;
    for i in 0..speeds.len() {
        if max_probability[i] <= limit {
            limit_speed = Some(speeds[i]);
        } else {
            if i > 0 && limit_speed.is_some() {
                let (p0, p1) = (max_probability[i - 1], max_probability[i]);
                let f = (limit - p0) / (p1 - p0);
                limit_speed = Some(speeds[i - 1] + f * (speeds[i] - speeds[i - 1]));
            }
            break;
        }
    }
    Ok(Operability {
        limit,
        speeds: speeds.to_vec(),
        max_probability: max_probability.to_vec(),
        limit_speed,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stats() -> SlamStatistics {
        // T = 0.3 m, m0 = 0.09 m^2, m2 = 0.36 m^2/s^2, v_th = 0.9 m/s
        ochi(5.0, 8.0, 0.3, 0.09, 0.36, 0.9)
    }

    #[test]
    fn no_steady_velocity_changes_nothing() {
        let a = stats();
        let b = a.with_steady_velocity(0.0);
        assert_eq!(a.probability, b.probability);
        assert_eq!(a.slams_per_hour, b.slams_per_hour);
        assert_eq!(
            a.most_probable_extreme_velocity(20.0),
            b.most_probable_extreme_velocity(20.0)
        );
    }

    #[test]
    fn a_steady_velocity_lowers_the_oscillating_threshold_and_adds_to_every_slam() {
        let a = stats();
        // V_s = 0.4 m/s: the oscillating part has to exceed 0.5 m/s.
        let b = a.with_steady_velocity(0.4);
        let p = (-0.09f64 / 0.18 - 0.25 / 0.72).exp();
        assert!((b.probability - p).abs() < 1e-15, "{}", b.probability);
        assert!((b.slams_per_hour / b.probability - a.slams_per_hour / a.probability).abs() < 1e-9);
        assert_eq!(b.threshold_velocity, 0.9);
        let v = (0.25f64 + 0.72 * 20f64.ln()).sqrt() + 0.4;
        assert!((b.most_probable_extreme_velocity(20.0) - v).abs() < 1e-12);
        let q = 0.1f64;
        let v = (0.25 - 0.72 * q.ln()).sqrt() + 0.4;
        assert!((b.velocity_exceeded_with(q) - v).abs() < 1e-12);
        // A steady velocity above v_th makes every keel entry a slam ...
        let c = a.with_steady_velocity(1.2);
        assert!((c.probability - (-0.5f64).exp()).abs() < 1e-15);
        // ... and the most probable largest of the N' = N e^{v_th^2/(2 m2)} entries is the oscillating
        // part's largest over all entries plus V_s: the same oscillating part as without it, for the
        // same exposure.
        let n = 20.0;
        let n_all = n * c.slams_per_hour / a.slams_per_hour;
        assert!(
            (c.most_probable_extreme_velocity(n_all) - 1.2 - a.most_probable_extreme_velocity(n))
                .abs()
                < 1e-12
        );
    }
}
