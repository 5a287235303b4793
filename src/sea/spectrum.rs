//! Wave spectra S(ω) (one-sided, m²·s/rad) and their moments.
//!
//! * Pierson-Moskowitz (1964): S = α g² ω⁻⁵ exp(−1.25 (ω_p/ω)⁴), α = 0.0081; one parameter, so
//!   ω_p = (16 α g² / (5 H_s²))^{1/4} follows from H_s (m0 = α g²/(5 ω_p⁴) = H_s²/16).
//! * ITTC / Bretschneider two-parameter: S = (5/16) H_s² ω_p⁴ ω⁻⁵ exp(−1.25 (ω_p/ω)⁴) (ITTC 1978; DNV-RP-C205 §3.5.5).
//! * JONSWAP (Hasselmann et al. 1973): S_PM(H_s, ω_p) γ^r, r = exp(−(ω − ω_p)²/(2 σ² ω_p²)),
//!   σ = 0.07 (ω ≤ ω_p) / 0.09 (ω > ω_p), normalised numerically so that m0 = H_s²/16 exactly
//!   (DNV-RP-C205 §3.5.5 gives the approximate factor 1 − 0.287 ln γ instead).
//!
//! Moments m_n = ∫ ω^n S dω are integrated numerically on a dense grid with the ω⁻⁵ tail added in closed
//! form; zero-crossing period T_z = 2π sqrt(m0/m2), mean period T_1 = 2π m0/m1.

use serde::Serialize;

use super::waves::G;

const ALPHA_PM: f64 = 0.0081;

/// A wave spectrum with its parameters resolved (peak frequency ω_p in rad/s).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "snake_case")]
pub enum Spectrum {
    PiersonMoskowitz {
        hs_m: f64,
        omega_p: f64,
    },
    Bretschneider {
        hs_m: f64,
        omega_p: f64,
    },
    Jonswap {
        hs_m: f64,
        omega_p: f64,
        gamma: f64,
        norm: f64,
    },
}

/// Summary numbers of a spectrum.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SpectrumSummary {
    pub hs_m: f64,
    pub tp_s: f64,
    pub tz_s: f64,
    pub t1_s: f64,
    pub m0: f64,
    pub m1: f64,
    pub m2: f64,
}

impl Spectrum {
    /// Pierson-Moskowitz spectrum of significant height `hs`.
    pub fn pierson_moskowitz(hs: f64) -> Self {
        let omega_p = (16.0 * ALPHA_PM * G * G / (5.0 * hs * hs)).powf(0.25);
        Spectrum::PiersonMoskowitz { hs_m: hs, omega_p }
    }

    /// ITTC / Bretschneider spectrum from H_s and peak period T_p.
    pub fn bretschneider(hs: f64, tp: f64) -> Self {
        Spectrum::Bretschneider {
            hs_m: hs,
            omega_p: 2.0 * std::f64::consts::PI / tp,
        }
    }

    /// JONSWAP spectrum from H_s, T_p and peak enhancement γ, normalised to m0 = H_s²/16.
    pub fn jonswap(hs: f64, tp: f64, gamma: f64) -> Self {
        let omega_p = 2.0 * std::f64::consts::PI / tp;
        let raw = Spectrum::Jonswap {
            hs_m: hs,
            omega_p,
            gamma,
            norm: 1.0,
        };
        let norm = hs * hs / 16.0 / raw.moment(0);
        Spectrum::Jonswap {
            hs_m: hs,
            omega_p,
            gamma,
            norm,
        }
    }

    /// The spectrum with the same shape whose zero-crossing period is `tz` (T_p found from the shape's
    /// constant ratio T_z/T_p, which is computed, not tabulated).
    pub fn with_tz(self, tz: f64) -> Self {
        let ratio = self.summary().tz_s / self.peak_period();
        let tp = tz / ratio;
        match self {
            Spectrum::PiersonMoskowitz { hs_m, .. } | Spectrum::Bretschneider { hs_m, .. } => {
                Spectrum::bretschneider(hs_m, tp)
            }
            Spectrum::Jonswap { hs_m, gamma, .. } => Spectrum::jonswap(hs_m, tp, gamma),
        }
    }

    pub fn hs(&self) -> f64 {
        match *self {
            Spectrum::PiersonMoskowitz { hs_m, .. }
            | Spectrum::Bretschneider { hs_m, .. }
            | Spectrum::Jonswap { hs_m, .. } => hs_m,
        }
    }

    pub fn peak_frequency(&self) -> f64 {
        match *self {
            Spectrum::PiersonMoskowitz { omega_p, .. }
            | Spectrum::Bretschneider { omega_p, .. }
            | Spectrum::Jonswap { omega_p, .. } => omega_p,
        }
    }

    pub fn peak_period(&self) -> f64 {
        2.0 * std::f64::consts::PI / self.peak_frequency()
    }

    /// Spectral density S(ω), m²s.
    pub fn density(&self, omega: f64) -> f64 {
        if omega <= 0.0 {
            return 0.0;
        }
        let hs = self.hs();
        let wp = self.peak_frequency();
        let base = 5.0 / 16.0 * hs * hs * wp.powi(4) / omega.powi(5)
            * (-1.25 * (wp / omega).powi(4)).exp();
        match *self {
            Spectrum::PiersonMoskowitz { .. } | Spectrum::Bretschneider { .. } => base,
            Spectrum::Jonswap { gamma, norm, .. } => {
                let sigma = if omega <= wp { 0.07 } else { 0.09 };
                let r = (-(omega - wp).powi(2) / (2.0 * sigma * sigma * wp * wp)).exp();
                norm * base * gamma.powf(r)
            }
        }
    }

    /// Spectral moment m_n = ∫ ω^n S(ω) dω (n < 4).
    pub fn moment(&self, n: i32) -> f64 {
        let wp = self.peak_frequency();
        let (lo, hi) = (0.15 * wp, 40.0 * wp);
        let m = 20_000;
        let h = (hi - lo) / m as f64;
        // Simpson's rule
        let f = |w: f64| w.powi(n) * self.density(w);
        let mut s = f(lo) + f(hi);
        for i in 1..m {
            let w = lo + i as f64 * h;
            s += if i % 2 == 1 { 4.0 } else { 2.0 } * f(w);
        }
        let body = s * h / 3.0;
        // ω⁻⁵ tail beyond `hi`: S ≈ C ω⁻⁵ with C = S(hi) hi⁵ → ∫ C ω^{n−5} = C hi^{n−4}/(4−n)
        let c = self.density(hi) * hi.powi(5);
        body + c * hi.powi(n - 4) / (4 - n) as f64
    }

    /// H_s, T_p, T_z, T_1 and the first moments.
    pub fn summary(&self) -> SpectrumSummary {
        let (m0, m1, m2) = (self.moment(0), self.moment(1), self.moment(2));
        let two_pi = 2.0 * std::f64::consts::PI;
        SpectrumSummary {
            hs_m: 4.0 * m0.sqrt(),
            tp_s: self.peak_period(),
            tz_s: two_pi * (m0 / m2).sqrt(),
            t1_s: two_pi * m0 / m1,
            m0,
            m1,
            m2,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn significant_height_is_reproduced() {
        for s in [
            Spectrum::pierson_moskowitz(3.0),
            Spectrum::bretschneider(3.0, 9.0),
            Spectrum::jonswap(3.0, 9.0, 3.3),
        ] {
            let hs = s.summary().hs_m;
            assert!((hs - 3.0).abs() < 3e-3, "{s:?}: Hs {hs}");
        }
    }

    #[test]
    fn bretschneider_period_ratios_match_closed_form() {
        // Closed form for the ω⁻⁵ exp(−B ω⁻⁴) shape, B = 1.25 ω_p⁴: m_n ∝ B^{(n−4)/4} Γ((4−n)/4), so
        // T_z/T_p = (1.25 π)^{−1/4} = 0.7104 and T_1/T_p = 1/(1.25^{1/4} Γ(3/4)) = 0.7717.
        let s = Spectrum::bretschneider(2.0, 10.0).summary();
        assert!(
            (s.tz_s / s.tp_s - 0.710).abs() < 2e-3,
            "{}",
            s.tz_s / s.tp_s
        );
        assert!(
            (s.t1_s / s.tp_s - 0.772).abs() < 2e-3,
            "{}",
            s.t1_s / s.tp_s
        );
        // JONSWAP: DNV-RP-C205 (2010) §3.5.5.5 fit T_z/T_p = 0.6673 + 0.05037γ − 0.006230γ² + 0.0003341γ³.
        let j = Spectrum::jonswap(2.0, 10.0, 3.3).summary();
        let dnv = 0.6673 + 0.05037 * 3.3 - 0.006230 * 3.3f64.powi(2) + 0.0003341 * 3.3f64.powi(3);
        assert!(
            (j.tz_s / j.tp_s - dnv).abs() < 5e-3,
            "{} vs {dnv}",
            j.tz_s / j.tp_s
        );
    }

    #[test]
    fn tz_parameterisation_round_trips() {
        let s = Spectrum::jonswap(2.0, 10.0, 2.0).with_tz(6.0);
        assert!((s.summary().tz_s - 6.0).abs() < 1e-6);
    }
}
