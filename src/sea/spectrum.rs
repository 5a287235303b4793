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
        #[serde(rename = "peak_frequency_rad_per_s")]
        omega_p: f64,
    },
    Bretschneider {
        hs_m: f64,
        #[serde(rename = "peak_frequency_rad_per_s")]
        omega_p: f64,
    },
    Jonswap {
        hs_m: f64,
        #[serde(rename = "peak_frequency_rad_per_s")]
        omega_p: f64,
        gamma: f64,
        #[serde(skip)]
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
    #[serde(rename = "m0_m2")]
    pub m0: f64,
    #[serde(rename = "m1_m2_per_s")]
    pub m1: f64,
    #[serde(rename = "m2_m2_per_s2")]
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

    /// JONSWAP spectrum from H_s, T_p and peak enhancement γ, normalised to m0 = H_s²/16. The factor
    /// depends on the shape only (γ), so it is found for H_s = 1 (no underflow for small H_s).
    pub fn jonswap(hs: f64, tp: f64, gamma: f64) -> Self {
        let omega_p = 2.0 * std::f64::consts::PI / tp;
        let unit = Spectrum::Jonswap {
            hs_m: 1.0,
            omega_p,
            gamma,
            norm: 1.0,
        };
        let norm = 1.0 / 16.0 / unit.moment(0);
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
        let tz_tp = (1.25 * std::f64::consts::PI).powf(-0.25);
        // Γ(3/4) = 1.2254167024651776
        let t1_tp = 1.0 / (1.25f64.powf(0.25) * 1.225_416_702_465_177_6);
        assert!(
            (s.tz_s / s.tp_s - tz_tp).abs() < 1e-6,
            "{}",
            s.tz_s / s.tp_s
        );
        assert!(
            (s.t1_s / s.tp_s - t1_tp).abs() < 1e-6,
            "{}",
            s.t1_s / s.tp_s
        );
        // m0 = H_s²/16 in closed form for this shape.
        assert!((s.m0 - 0.25).abs() < 1e-7, "{}", s.m0);
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
    fn jonswap_normalisation() {
        // Normalised numerically to m0 = H_s²/16; the factor is close to DNV-RP-C205 (2010) eq. 3.5.5.4's
        // approximation A_γ = 1 − 0.287 ln γ (stated there as an approximation, so within 2 %).
        for gamma in [1.0, 2.0, 3.3, 5.0, 7.0] {
            let s = Spectrum::jonswap(4.0, 12.0, gamma);
            let Spectrum::Jonswap { norm, .. } = s else {
                unreachable!()
            };
            assert!((s.summary().m0 - 1.0).abs() < 1e-9, "γ {gamma}");
            let dnv = 1.0 - 0.287 * gamma.ln();
            assert!(
                (norm - dnv).abs() / dnv < 0.02,
                "γ {gamma}: {norm} vs {dnv}"
            );
            if gamma == 1.0 {
                assert!(
                    (norm - 1.0).abs() < 1e-9,
                    "γ = 1 is the Bretschneider shape"
                );
            }
        }
        // Independent of H_s, including small model-scale seas.
        let small = Spectrum::jonswap(1e-3, 1.0, 3.3).summary();
        assert!((small.hs_m - 1e-3).abs() < 1e-12);
    }

    #[test]
    fn pierson_moskowitz_peak_follows_from_hs() {
        // ω_p = (16 α g² / (5 H_s²))^{1/4}, so that m0 = α g²/(5 ω_p⁴) = H_s²/16.
        let s = Spectrum::pierson_moskowitz(5.0);
        let wp = s.peak_frequency();
        let m0 = ALPHA_PM * G * G / (5.0 * wp.powi(4));
        assert!((m0 - 25.0 / 16.0).abs() < 1e-12);
        assert!((s.summary().m0 - m0).abs() / m0 < 1e-7);
        // S at the peak: α g² ω_p⁻⁵ e^{−5/4}
        let peak = ALPHA_PM * G * G / wp.powi(5) * (-1.25f64).exp();
        assert!((s.density(wp) - peak).abs() / peak < 1e-12);
    }

    #[test]
    fn tz_parameterisation_round_trips() {
        let s = Spectrum::jonswap(2.0, 10.0, 2.0).with_tz(6.0);
        assert!((s.summary().tz_s - 6.0).abs() < 1e-6);
        let b = Spectrum::bretschneider(2.0, 10.0).with_tz(6.0);
        let tp = 6.0 * (1.25 * std::f64::consts::PI).powf(0.25);
        assert!((b.peak_period() - tp).abs() < 1e-5, "{}", b.peak_period());
    }
}
