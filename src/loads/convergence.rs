//! How converged a peak is in particle spacing: the Grid Convergence Index of Roache (1994), in the
//! procedure of Celik et al. (2008), applied to a result computed at two or three particle spacings.
//!
//! With spacings dp_1 < dp_2 < dp_3 (dp_1 the run being reported), refinement ratio r = dp_2/dp_1 and
//! results f_1, f_2 (, f_3):
//!
//! * relative change   e_21 = |f_2 - f_1| / |f_1|;
//! * observed order (three levels, constant r, monotone):  p = ln((f_3 - f_2)/(f_2 - f_1)) / ln r;
//! * Richardson estimate of the converged value:  f_ext = f_1 + (f_1 - f_2)/(r^p - 1);
//! * GCI_fine = F_s e_21 / (r^p - 1), with the safety factor F_s = 1.25 for three levels with an observed
//!   order and F_s = 3 for two levels, where p is assumed (Roache 1994, 1998).
//!
//! For two levels the order cannot be observed; it is taken as 1, the order SPH with boundary
//! particles shows in practice for wall pressures and forces at the resolutions used here (the kernel
//! and boundary errors are O(dp) near a moving wall). The statement says that the order was assumed.
//!
//! References: P. J. Roache (1994), "Perspective: a method for uniform reporting of grid refinement
//! studies", J. Fluids Eng. 116, 405-413; I. B. Celik, U. Ghia, P. J. Roache, C. J. Freitas, H. Coleman,
//! P. E. Raad (2008), "Procedure for estimation and reporting of uncertainty due to discretization in CFD
//! applications", J. Fluids Eng. 130, 078001.

use serde::Serialize;

/// Order assumed when only two resolutions are available.
pub const ASSUMED_ORDER: f64 = 1.0;
/// Roache's safety factor with an assumed order (two levels).
pub const SAFETY_TWO_LEVELS: f64 = 3.0;
/// Roache's safety factor with an observed order (three levels).
pub const SAFETY_THREE_LEVELS: f64 = 1.25;
/// Observed orders outside this range are not trusted (the results are not in the asymptotic range);
/// the assumed order is used instead, with the two-level safety factor.
pub const ORDER_RANGE: (f64, f64) = (0.5, 4.0);

/// Verdict on one peak.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Verdict {
    /// GCI of the reported value at most 5 %.
    Converged,
    /// GCI between 5 % and 20 %.
    Acceptable,
    /// GCI above 20 %, or the results oscillate: a finer run is needed before the value is relied on.
    NotConverged,
    /// Only one resolution was run.
    NotAssessed,
    /// The quantity is zero (e.g. a sensor never wetted) at the reported resolution.
    NotWetted,
    /// The coarser run's peak is another event than the reported one (another phase, or a peak time
    /// outside the matching window; [`crate::loads::anatomy::matched`]), so the two are not compared.
    Mismatched,
    /// The coarser run does not resolve the impact the reported run resolves (no slamming peak in its
    /// impact window: the contact crosses the sensor inside that run's contact transient, or not at
    /// all), so there is nothing to compare the reported peak with.
    CompanionUnresolved,
}

impl Verdict {
    fn from_gci(gci: f64) -> Self {
        if gci <= 0.05 {
            Verdict::Converged
        } else if gci <= 0.20 {
            Verdict::Acceptable
        } else {
            Verdict::NotConverged
        }
    }
}

/// Convergence of one peak value over particle spacings, finest (reported) first.
#[derive(Debug, Clone, Serialize)]
pub struct PeakConvergence {
    pub name: String,
    pub unit: String,
    /// Particle spacings (m), finest first.
    pub dp_m: Vec<f64>,
    /// The peak at each spacing, finest first.
    pub values: Vec<f64>,
    /// |f_2 - f_1| / |f_1|.
    pub relative_change: Option<f64>,
    /// Observed order of convergence (three monotone levels only).
    pub observed_order: Option<f64>,
    /// Order used in the estimate (observed, or assumed).
    pub order_used: Option<f64>,
    /// Richardson-extrapolated value.
    pub extrapolated: Option<f64>,
    /// Grid Convergence Index of the reported (finest) value, as a fraction.
    pub gci: Option<f64>,
    pub verdict: Verdict,
    /// One sentence for reports.
    pub statement: String,
}

/// Assess one peak from its values at spacings `dp` (finest first, constant ratio expected but not
/// required for two levels). Values must be finite.
pub fn assess(name: &str, unit: &str, dp: &[f64], values: &[f64]) -> PeakConvergence {
    let mut out = PeakConvergence {
        name: name.into(),
        unit: unit.into(),
        dp_m: dp.to_vec(),
        values: values.to_vec(),
        relative_change: None,
        observed_order: None,
        order_used: None,
        extrapolated: None,
        gci: None,
        verdict: Verdict::NotAssessed,
        statement: String::new(),
    };
    let f1 = values.first().copied().unwrap_or(0.0);
    if values.len() < 2 || dp.len() < 2 {
        out.statement = format!(
            "{name}: convergence not assessed (one resolution, dp {:.3} mm)",
            dp.first().copied().unwrap_or(0.0) * 1e3
        );
        return out;
    }
    if f1 == 0.0 {
        out.verdict = Verdict::NotWetted;
        out.statement =
            format!("{name}: zero at the reported resolution (not wetted); nothing to assess");
        return out;
    }
    let f2 = values[1];
    let r = dp[1] / dp[0];
    let e21 = (f2 - f1).abs() / f1.abs();
    out.relative_change = Some(e21);
    // Observed order from three levels when they converge monotonically.
    let mut order = None;
    let mut oscillating = false;
    if values.len() >= 3 && dp.len() >= 3 {
        let (d21, d32) = (f2 - f1, values[2] - f2);
        let r32 = dp[2] / dp[1];
        if d21 == 0.0 {
            order = None;
        } else if d32 / d21 > 0.0 && (r32 - r).abs() < 1e-6 * r {
            let p = (d32 / d21).ln() / r.ln();
            out.observed_order = Some(p);
            if p >= ORDER_RANGE.0 && p <= ORDER_RANGE.1 {
                order = Some(p);
            }
        } else if d32 / d21 < 0.0 {
            oscillating = true;
        }
    }
    let (p, fs) = match order {
        Some(p) => (p, SAFETY_THREE_LEVELS),
        None => (ASSUMED_ORDER, SAFETY_TWO_LEVELS),
    };
    let denom = r.powf(p) - 1.0;
    let gci = fs * e21 / denom;
    out.order_used = Some(p);
    out.extrapolated = Some(f1 + (f1 - f2) / denom);
    out.gci = Some(gci);
    out.verdict = if oscillating {
        Verdict::NotConverged
    } else {
        Verdict::from_gci(gci)
    };
    let levels: Vec<String> = dp.iter().map(|d| format!("{:.3}", d * 1e3)).collect();
    let how = match (order, oscillating) {
        (_, true) => "results oscillate with refinement: not in the asymptotic range".to_string(),
        (Some(p), _) => format!("observed order {p:.2}"),
        (None, _) => match out.observed_order {
            Some(p) => format!("observed order {p:.2} outside [0.5, 4], order 1 assumed"),
            None => "order 1 assumed".to_string(),
        },
    };
    out.statement = format!(
        "{name}: {:+.1} % change from dp {} mm; {how}; GCI {:.1} % ({})",
        100.0 * (f1 - f2) / f1.abs(),
        levels.join(" / "),
        100.0 * gci,
        match out.verdict {
            Verdict::Converged => "converged",
            Verdict::Acceptable => "acceptable",
            _ => "not converged: refine before relying on it",
        }
    );
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn recovers_order_and_limit_of_a_power_law() {
        // f = 10 + 3 dp^2 at dp = 1, 2, 4.
        let dp = [1.0, 2.0, 4.0];
        let f: Vec<f64> = dp.iter().map(|d| 10.0 + 3.0 * d * d).collect();
        let c = assess("x", "-", &dp, &f);
        assert!((c.observed_order.unwrap() - 2.0).abs() < 1e-12);
        assert!((c.extrapolated.unwrap() - 10.0).abs() < 1e-12);
        // GCI = 1.25 * (9/13) / 3.
        assert!((c.gci.unwrap() - 1.25 * (9.0 / 13.0) / 3.0).abs() < 1e-12);
        assert_eq!(c.verdict, Verdict::NotConverged);
    }

    #[test]
    fn two_levels_assume_first_order_with_safety_three() {
        let c = assess("force", "N/m", &[0.001, 0.002], &[100.0, 101.0]);
        assert_eq!(c.order_used, Some(1.0));
        assert!((c.gci.unwrap() - 0.03).abs() < 1e-12);
        assert_eq!(c.verdict, Verdict::Converged);
        assert!((c.extrapolated.unwrap() - 99.0).abs() < 1e-12);
        assert!(c.statement.contains("order 1 assumed"), "{}", c.statement);
    }

    #[test]
    fn oscillation_and_zero_and_single_level_are_said() {
        let c = assess("p1", "Pa", &[1.0, 2.0, 4.0], &[10.0, 11.0, 10.5]);
        assert_eq!(c.verdict, Verdict::NotConverged);
        assert!(c.statement.contains("oscillate"));
        assert_eq!(
            assess("p2", "Pa", &[1.0, 2.0], &[0.0, 3.0]).verdict,
            Verdict::NotWetted
        );
        assert_eq!(
            assess("p3", "Pa", &[1.0], &[3.0]).verdict,
            Verdict::NotAssessed
        );
    }
}
