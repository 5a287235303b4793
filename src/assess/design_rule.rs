//! The design value of one sensor (or one section force) in one event: which number the report may call
//! a slamming load, and how it says so.
//!
//! The SPH value considered is the **slamming peak** of the record, the largest value in its impact
//! window ([`crate::loads::anatomy`]), never a value of the contact transient, of the immersion after the
//! impact or of the record's end. Where the run has a physical low-pass cut-off
//! ([`crate::loads::cutoff`]: f_c = 2 / tau_min, tau_min the quickest analytic crossing of a panel, which
//! keeps at least 90 % of a pulse rising that fast), the record is the low-passed one and its
//! convergence statement that of the filtered slamming peaks at every level; the raw slamming peak is
//! reported beside it. Content faster than the quickest physical rise is the acoustic and particle noise
//! of weakly compressible SPH: its amplitude is set by the artificial sound speed and the particle
//! disorder, it does not converge with the spacing, and a single burst of it in one level's record would
//! otherwise decide P, its GCI and the verdict (the thirty-fourth session's sensor S133-2 at 0.133 Lpp:
//! 7119 Pa raw at the finest of three levels against 5654 Pa filtered). With P that peak, U = GCI P its discretisation uncertainty (Roache's
//! Grid Convergence Index of the matched peaks at two or three spacings, [`crate::loads::convergence`])
//! and A the analytic estimate of the same sensor and event (modified Logvinovich mean panel pressure,
//! or section force, each corrected to the similarity solution of the equivalent wedge):
//!
//! * SPH shown converged (verdict converged or acceptable, the companion's peak the same event):
//!   design = P + U, the upper end of the uncertainty band (source `sph (converged)` where
//!   GCI <= 5 %, `sph (acceptable)` where 5 % < GCI <= 20 %, the verdicts of
//!   [`crate::loads::convergence::Verdict`]: the label never calls a peak converged that its verdict
//!   calls acceptable);
//! * SPH resolved but not shown converged (not converged, companion peak another event, or one
//!   level only): design = max(P + U, A), whichever is larger (source `sph (not converged)` or
//!   `analytic (SPH not converged)`): an unconverged SPH peak never lowers the design below the
//!   analytic estimate. Where the companion's peak is another event (verdict `mismatched`) there is
//!   no GCI; U is then the difference between the two levels' peaks, |P - P_2|, so that the design
//!   value is at least the larger of the two (a rule of this tool: an unconverged value must not
//!   carry less margin than a converged one);
//! * SPH record still rising where the impact window closes (no distinct impact peak: the value is the
//!   window's last sample, and the levels' values are samples at different window ends, so their GCI
//!   does not measure a peak's convergence): design = max(P + U, A), source `sph (no distinct impact
//!   peak)` or `analytic (SPH: no distinct impact peak)`, whatever the verdict;
//! * SPH does not compute the impact (the contact crosses the sensor inside the contact transient, at an
//!   acoustic speed on a flat keel, after the run, or never): design = A, labelled with the reason; on a
//!   flat keel the water-hammer pressure rho c_w V (c_w the real sound speed of water) is stated beside it
//!   as the upper bound of an impact without air, and the air cushion is left to the two-phase model;
//!   where the analytic models give no peak either (a panel on a flat keel is wetted at once, and
//!   their pressure only falls from the singular start), there is **no design value**: source
//!   [`NO_VALUE_FLAT_KEEL`], value `None`, and the reports say so rather than print a number;
//! * a sensor the SPH water did not reach with a slamming pressure ([`super::results::DRY_FRACTION`]):
//!   design = A (source `analytic (dry in SPH)`);
//! * no SPH run: design = A (source `analytic`); where the analytic models give no peak (a panel
//!   wetted at once on a flat keel or below an immersed start's waterline, whose pressure only falls
//!   from the singular start), there is no design value: source [`NO_VALUE_WETTED_AT_START`], value
//!   `None`; where they give the panel no pressure at all (a vertical side, or above the contact's
//!   reach), the value is 0 and its source says so ([`ANALYTIC_NO_PRESSURE`]), so that a zero is not
//!   read as a computed impact.
//!
//! Why this rule: the analytic sensor pressure is the modified Logvinovich model corrected to the
//! nonlinear similarity solution of the local wedge (within the stated error of
//! [`crate::analytic::similarity_table::STATED_ERROR`] for a wedge at constant speed; the uncorrected
//! MLM peak is 18 % above the similarity maximum at 20 deg and 71 % at 40 deg), an estimate of the
//! converged value rather than a bound; where SPH has not shown that it resolves a peak the larger of the
//! two is taken, and where SPH has shown it, its own uncertainty band is added, so that the design value
//! is an upper estimate of the converged value either way.

use serde::{Deserialize, Serialize};

use super::analytic::SensorEstimate;
use crate::loads::anatomy::ImpactStatus;

/// What the rule needs of one SPH quantity.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SphQuantity<'a> {
    pub status: Option<ImpactStatus>,
    /// The slamming peak (total, hydrostatic included).
    pub slamming: Option<f64>,
    /// GCI of the slamming peak, as a fraction.
    pub gci: Option<f64>,
    /// Convergence verdict (`converged`, `acceptable`, ...).
    pub verdict: Option<&'a str>,
    /// Whether the SPH water reached the sensor with a slamming pressure.
    pub wetted: bool,
    /// Where the convergence levels' peaks are different events (verdict `mismatched`): the difference
    /// between the reported peak and the next level's, as a fraction of the reported one, which stands
    /// in for the GCI (`None` when that level has no slamming peak).
    pub spread: Option<f64>,
    /// The record still rises where the impact window closes: the slamming value is the window's last
    /// sample, not a distinct impact peak ([`crate::loads::anatomy::Anatomy::at_window_end`]).
    pub rising_at_window_end: bool,
}

/// The analytic estimate A of one quantity, as the rule takes it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum AnalyticPeak {
    /// The models' peak.
    Peak(f64),
    /// The models give the panel no pressure at any time of the event (peak and impulse both zero): it
    /// is on a vertical part of the contour, which they wet without advancing their contact across it
    /// (the half-breadth does not grow there, so the impact term c c' / sqrt(c^2 - y^2) has no
    /// counterpart), or above the contact's reach in the event. Its value is 0, said as such
    /// ([`ANALYTIC_NO_PRESSURE`]).
    Zero,
    /// The models compute the quantity, but its values are only the decay of a singular start (a panel
    /// wetted at once on a flat keel or below an immersed start's waterline): no peak
    /// ([`SensorEstimate::no_peak_after_start`]).
    NoPeakAfterStart,
    /// No analytic estimate of the quantity.
    Absent,
}

impl AnalyticPeak {
    /// The peak, where there is one.
    pub fn value(self) -> Option<f64> {
        match self {
            AnalyticPeak::Peak(v) => Some(v),
            AnalyticPeak::Zero => Some(0.0),
            AnalyticPeak::NoPeakAfterStart | AnalyticPeak::Absent => None,
        }
    }

    /// The analytic estimate of a sensor panel (`None`: the event has no estimate of that sensor).
    pub fn of_sensor(estimate: Option<&SensorEstimate>) -> Self {
        match estimate {
            None => AnalyticPeak::Absent,
            Some(e) => match e.peak() {
                None => AnalyticPeak::NoPeakAfterStart,
                Some(p) if p == 0.0 && e.impulse_pa_s == 0.0 => AnalyticPeak::Zero,
                Some(p) => AnalyticPeak::Peak(p),
            },
        }
    }
}

impl From<Option<f64>> for AnalyticPeak {
    /// A peak, or no estimate at all.
    fn from(a: Option<f64>) -> Self {
        a.map_or(AnalyticPeak::Absent, AnalyticPeak::Peak)
    }
}

/// A design value and where it comes from.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Decision {
    /// `None` where no model here computes the load (a flat-keel impact: SPH without air and the
    /// analytic models both leave it out); `source` then says why.
    pub value: Option<f64>,
    pub source: &'static str,
    /// The SPH discretisation uncertainty U = GCI P, where there is one.
    pub uncertainty: Option<f64>,
}

/// Whether a verdict shows convergence.
pub fn shown_converged(verdict: Option<&str>) -> bool {
    matches!(verdict, Some("converged") | Some("acceptable"))
}

/// The source label of an analytic design value standing in for SPH with `status`.
fn analytic_label(status: Option<ImpactStatus>) -> &'static str {
    match status {
        Some(ImpactStatus::InTransient) => "analytic (SPH: impact in the contact transient)",
        Some(ImpactStatus::Acoustic) => "analytic (flat keel: acoustic impact, no air)",
        Some(ImpactStatus::NotCrossed) => "analytic (SPH: contact does not reach it)",
        Some(ImpactStatus::WettedAtStart) => "analytic (SPH: wetted at the start)",
        Some(ImpactStatus::AfterRecord) => "analytic (SPH: impact after the run)",
        _ => "analytic (SPH not converged)",
    }
}

/// The source of a panel without a design value: single-phase SPH does not compute its impact
/// (`status`) and the analytic models give no peak there (`--air auto` or `on` computes a two-phase peak,
/// which is no design value either: [`NO_VALUE_CUSHIONED`]).
pub const NO_VALUE_FLAT_KEEL: &str =
    "none (flat keel: air-cushion impact, not computed without air)";

/// The source of a design value that no model gives: SPH does not resolve the impact (`status`) and
/// the analytic models have no peak for the panel.
fn none_label(status: Option<ImpactStatus>) -> &'static str {
    match status {
        Some(ImpactStatus::Acoustic) => NO_VALUE_FLAT_KEEL,
        Some(ImpactStatus::Cushioned) => "none (flat keel with air: no cushion peak in the run)",
        Some(ImpactStatus::InTransient) => {
            "none (SPH: impact in the contact transient; no analytic peak on a panel wetted at contact)"
        }
        _ => "none (no SPH impact and no analytic peak)",
    }
}

/// The source of a panel without an SPH run whose analytic values are only the decay of a singular
/// start (wetted at once on a flat keel or below an immersed start's waterline).
pub const NO_VALUE_WETTED_AT_START: &str =
    "none (wetted at contact: no analytic peak, and no SPH run in this event)";

/// The source of a design value from the analytic estimate alone, where no SPH ran in the event.
pub const ANALYTIC_WITHOUT_SPH: &str = "analytic";

/// The source of a zero design value from the analytic estimate alone ([`AnalyticPeak::Zero`]): no SPH
/// run, and no pressure from the models at any time of the event.
pub const ANALYTIC_NO_PRESSURE: &str =
    "analytic (0: vertical side or out of reach, no impact pressure in the 2D models)";

/// The design value without an SPH run: the analytic peak (source `analytic`), 0 with its reason where
/// the models give no pressure at all ([`ANALYTIC_NO_PRESSURE`]), no value where the analytic values
/// are only the decay of a singular start ([`NO_VALUE_WETTED_AT_START`]), `None` without an analytic
/// estimate.
fn without_sph(a: AnalyticPeak) -> Option<Decision> {
    match a {
        AnalyticPeak::Peak(v) => Some(Decision {
            value: Some(v),
            source: ANALYTIC_WITHOUT_SPH,
            uncertainty: None,
        }),
        AnalyticPeak::Zero => Some(Decision {
            value: Some(0.0),
            source: ANALYTIC_NO_PRESSURE,
            uncertainty: None,
        }),
        AnalyticPeak::NoPeakAfterStart => Some(Decision {
            value: None,
            source: NO_VALUE_WETTED_AT_START,
            uncertainty: None,
        }),
        AnalyticPeak::Absent => None,
    }
}

/// The design value from the SPH quantity `q` (none without an SPH run) and the analytic estimate `a`
/// (no peak for a panel wetted at once on a flat keel, or at an immersed start). `None` when neither
/// SPH nor the analytic estimate has the quantity.
pub fn decide(q: Option<SphQuantity>, a: AnalyticPeak) -> Option<Decision> {
    let Some(q) = q else {
        return without_sph(a);
    };
    let a = a.value();
    let analytic = |source| {
        a.map(|v| Decision {
            value: Some(v),
            source,
            uncertainty: None,
        })
    };
    if !q.wetted {
        return analytic(super::results::DRY_SOURCE);
    }
    let p = match (q.status, q.slamming) {
        (Some(ImpactStatus::Cushioned), _) => {
            return Some(Decision {
                value: None,
                source: NO_VALUE_CUSHIONED,
                uncertainty: None,
            });
        }
        (Some(ImpactStatus::Resolved), Some(p)) | (None, Some(p)) => p,
        (status, _) => {
            return analytic(analytic_label(status)).or(Some(Decision {
                value: None,
                source: none_label(status),
                uncertainty: None,
            }));
        }
    };
    let u = q.gci.or(q.spread).map(|g| g * p.abs());
    let upper = p + u.unwrap_or(0.0);
    // the larger of the SPH upper end and the analytic peak, labelled by which one it is
    let larger = |sph: &'static str, analytic: &'static str| {
        Some(match a {
            Some(av) if av > upper => Decision {
                value: Some(av),
                source: analytic,
                uncertainty: u,
            },
            _ => Decision {
                value: Some(upper),
                source: sph,
                uncertainty: u,
            },
        })
    };
    if q.rising_at_window_end {
        return larger(
            "sph (no distinct impact peak)",
            "analytic (SPH: no distinct impact peak)",
        );
    }
    if shown_converged(q.verdict) {
        return Some(Decision {
            value: Some(upper),
            source: if q.verdict == Some("converged") {
                "sph (converged)"
            } else {
                "sph (acceptable)"
            },
            uncertainty: u,
        });
    }
    larger("sph (not converged)", "analytic (SPH not converged)")
}

/// The source of a panel on a flat keel in a run with air ([`ImpactStatus::Cushioned`]): no design
/// value. The two-phase peak there grows with the water's artificial sound speed (a flat bottom at
/// 2 m/s read 101, 185 and 275 kPa at c0 = 126, 252 and 504 m/s; Ochi's 0.174 Lpp keel 20.5 and
/// 30.6 kPa at 63 and 126 m/s; docs/guide/air.md), so at the tool's c0 it is a property of the numerical
/// water's compressibility, not of the air cushion. The peak is reported with the run, not used.
pub const NO_VALUE_CUSHIONED: &str = "none (air-cushioned flat keel: the two-phase peak grows with the \
     artificial sound speed, so it is not a design value; docs/guide/air.md)";

#[cfg(test)]
mod tests {
    use super::*;

    fn q<'a>(p: f64, gci: Option<f64>, verdict: &'a str) -> SphQuantity<'a> {
        SphQuantity {
            status: Some(ImpactStatus::Resolved),
            slamming: Some(p),
            gci,
            verdict: Some(verdict),
            wetted: true,
            spread: None,
            rising_at_window_end: false,
        }
    }

    #[test]
    fn a_cushioned_flat_keel_has_no_design_value_from_its_two_phase_peak() {
        let mut c = q(20_000.0, Some(0.1), "acceptable");
        c.status = Some(ImpactStatus::Cushioned);
        // converged or not, with or without an analytic value: the peak depends on the sound speed
        for verdict in ["acceptable", "not_converged"] {
            c.verdict = Some(verdict);
            for a in [AnalyticPeak::NoPeakAfterStart, AnalyticPeak::Peak(30_000.0)] {
                let d = decide(Some(c), a).unwrap();
                assert_eq!((d.value, d.source), (None, NO_VALUE_CUSHIONED));
            }
        }
        // without air the same panel has no value
        c.status = Some(ImpactStatus::Acoustic);
        let d = decide(Some(c), AnalyticPeak::NoPeakAfterStart).unwrap();
        assert_eq!((d.value, d.source), (None, NO_VALUE_FLAT_KEEL));
    }

    #[test]
    fn unconverged_sph_never_lowers_the_design_below_analytic() {
        // S093-4 of the committed Ochi report: SPH 1.79 kPa, analytic 3.58 kPa, not converged
        let d = decide(
            Some(q(1790.0, Some(0.4), "not_converged")),
            AnalyticPeak::Peak(3580.0),
        )
        .unwrap();
        assert_eq!(d.value, Some(3580.0));
        assert_eq!(d.source, "analytic (SPH not converged)");
        // a mismatched companion is not converged either
        let d = decide(
            Some(q(970.0, None, "mismatched")),
            AnalyticPeak::Peak(2860.0),
        )
        .unwrap();
        assert_eq!(d.value, Some(2860.0));
        // an unconverged SPH peak above analytic keeps its uncertainty
        let d = decide(
            Some(q(5000.0, Some(0.3), "not_converged")),
            AnalyticPeak::Peak(3000.0),
        )
        .unwrap();
        assert!((d.value.unwrap() - 6500.0).abs() < 1e-9);
        assert_eq!(d.source, "sph (not converged)");
    }

    #[test]
    fn a_mismatched_peak_carries_the_spread_of_its_levels() {
        // S093-2 of the committed Ochi report (bceb623): 2.78 kPa at the keel stage, 3.92 kPa at its companion,
        // another event; the design value is at least the larger of the two
        let mut m = q(2778.0, None, "mismatched");
        m.spread = Some((3921.6 - 2778.0) / 2778.0);
        let d = decide(Some(m), AnalyticPeak::Peak(2250.0)).unwrap();
        assert!((d.value.unwrap() - 3921.6).abs() < 1e-6, "{d:?}");
        assert!((d.uncertainty.unwrap() - 1143.6).abs() < 1e-6);
        assert_eq!(d.source, "sph (not converged)");
        // without a companion peak there is no spread, and the rule is max(P, A)
        let d = decide(
            Some(q(2190.0, None, "mismatched")),
            AnalyticPeak::Peak(2620.0),
        )
        .unwrap();
        assert_eq!(d.value, Some(2620.0));
        assert!(d.uncertainty.is_none());
    }

    #[test]
    fn a_value_still_rising_at_the_window_end_is_not_a_converged_peak() {
        // an acceptable GCI between two window-end samples does not make a peak: max(P + U, A)
        let mut r = q(1250.0, Some(0.08), "acceptable");
        r.rising_at_window_end = true;
        let d = decide(Some(r), AnalyticPeak::Peak(1500.0)).unwrap();
        assert_eq!(d.value, Some(1500.0));
        assert_eq!(d.source, "analytic (SPH: no distinct impact peak)");
        let d = decide(Some(r), AnalyticPeak::Peak(800.0)).unwrap();
        assert!((d.value.unwrap() - 1350.0).abs() < 1e-9, "{d:?}");
        assert_eq!(d.source, "sph (no distinct impact peak)");
    }

    #[test]
    fn converged_sph_carries_its_band() {
        let d = decide(
            Some(q(2000.0, Some(0.04), "converged")),
            AnalyticPeak::Peak(3000.0),
        )
        .unwrap();
        assert!((d.value.unwrap() - 2080.0).abs() < 1e-9);
        assert_eq!(d.source, "sph (converged)");
        assert!((d.uncertainty.unwrap() - 80.0).abs() < 1e-9);
        // a GCI between 5 and 20 % is acceptable, and the label says so rather than "converged"
        let d = decide(
            Some(q(2000.0, Some(0.15), "acceptable")),
            AnalyticPeak::Peak(3000.0),
        )
        .unwrap();
        assert!((d.value.unwrap() - 2300.0).abs() < 1e-9);
        assert_eq!(d.source, "sph (acceptable)");
    }

    #[test]
    fn a_panel_the_models_give_no_pressure_reads_zero_with_its_reason() {
        let e = SensorEstimate {
            name: "G65".into(),
            peak_pa: 0.0,
            peak_time_s: 0.22,
            impulse_pa_s: 0.0,
            acoustic_bound_pa: None,
            uncorrected_peak_pa: Some(0.0),
            no_peak_after_start: false,
        };
        let a = AnalyticPeak::of_sensor(Some(&e));
        assert_eq!(a, AnalyticPeak::Zero);
        let d = decide(None, a).unwrap();
        assert_eq!((d.value, d.source), (Some(0.0), ANALYTIC_NO_PRESSURE));
        // beside an SPH peak it is an analytic value of 0, which never governs
        let d = decide(Some(q(1500.0, Some(0.3), "not_converged")), a).unwrap();
        assert_eq!(d.source, "sph (not converged)");
        // a pressure at some time (an impulse) is a peak, however small
        let e = SensorEstimate {
            impulse_pa_s: 1e-6,
            ..e
        };
        assert_eq!(AnalyticPeak::of_sensor(Some(&e)), AnalyticPeak::Peak(0.0));
    }

    #[test]
    fn unresolved_impacts_take_the_labelled_analytic_value() {
        for (s, label) in [
            (ImpactStatus::InTransient, "contact transient"),
            (ImpactStatus::Acoustic, "flat keel"),
        ] {
            let d = decide(
                Some(SphQuantity {
                    status: Some(s),
                    slamming: None,
                    gci: None,
                    verdict: None,
                    wetted: true,
                    spread: None,
                    rising_at_window_end: false,
                }),
                AnalyticPeak::Peak(4000.0),
            )
            .unwrap();
            assert_eq!(d.value, Some(4000.0));
            assert!(d.source.contains(label), "{}", d.source);
        }
        // a flat keel with no analytic peak either: no design value, and the source says why
        let flat = SphQuantity {
            status: Some(ImpactStatus::Acoustic),
            slamming: None,
            gci: None,
            verdict: None,
            wetted: true,
            spread: None,
            rising_at_window_end: false,
        };
        let d = decide(Some(flat), AnalyticPeak::Absent).unwrap();
        assert_eq!(d.value, None);
        assert_eq!(d.source, NO_VALUE_FLAT_KEEL);
        assert_eq!(
            decide(Some(flat), AnalyticPeak::NoPeakAfterStart),
            decide(Some(flat), AnalyticPeak::Absent)
        );
        assert_eq!(
            decide(None, AnalyticPeak::Peak(1.0)).unwrap().source,
            "analytic"
        );
    }

    #[test]
    fn without_an_sph_run_a_panel_wetted_at_contact_has_no_design_value() {
        let d = decide(None, AnalyticPeak::NoPeakAfterStart).unwrap();
        assert_eq!(d.value, None);
        assert_eq!(d.source, NO_VALUE_WETTED_AT_START);
        assert!(d.uncertainty.is_none());
        assert_eq!(decide(None, AnalyticPeak::Absent), None);
        // the estimate of a sensor maps onto the rule's input
        let mut e = SensorEstimate {
            name: "S1".into(),
            peak_pa: 1200.0,
            peak_time_s: 0.01,
            impulse_pa_s: 1.0,
            acoustic_bound_pa: None,
            uncorrected_peak_pa: None,
            no_peak_after_start: false,
        };
        assert_eq!(
            AnalyticPeak::of_sensor(Some(&e)),
            AnalyticPeak::Peak(1200.0)
        );
        e.no_peak_after_start = true;
        assert_eq!(
            AnalyticPeak::of_sensor(Some(&e)),
            AnalyticPeak::NoPeakAfterStart
        );
        assert_eq!(AnalyticPeak::of_sensor(None), AnalyticPeak::Absent);
    }
}
