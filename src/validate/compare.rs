//! Comparison of a computed quantity with its reference under the tolerance stated in the case file,
//! and the verdict that follows.
//!
//! The tolerance is written in the case file with its reason (and whether it was revised after results
//! were seen, [`super::case::Stated`]); nothing here widens it. A case whose reference is not available (pending data) gets the verdict
//! [`Verdict::Pending`], which is neither a pass nor a failure.

use serde::Serialize;

/// How a computed value is compared with its reference.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Tolerance {
    /// |computed / reference - 1| <= value.
    Relative { value: f64 },
    /// |computed - reference| <= value (in the case's unit).
    Absolute { value: f64 },
    /// computed <= value (in the case's unit); the reference is the ideal value shown beside it.
    AtMost { value: f64 },
    /// computed <= value, a one-sided bound of theory: any value below it passes, however far below
    /// (shown as such in every table, so a pass is not read as agreement).
    UpperBound { value: f64 },
    /// computed < reference (e.g. an error that must fall as the particle spacing is refined).
    BelowReference,
    /// lower <= computed <= upper, the bounds given by the reference (theory).
    WithinRange,
}

/// What the computation is compared with.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "kind", rename_all = "kebab-case")]
pub enum Reference {
    /// One published or theoretical value.
    Value { value: f64 },
    /// Bounds (e.g. von Karman below, Wagner above).
    Range { lower: f64, upper: f64 },
    /// No number is available yet; the reason says what is missing and how to add it.
    Pending { reason: String },
}

/// The verdict of one case.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Verdict {
    Pass,
    Fail,
    /// Outside the tolerance, and the case file says why this is expected (`known_failure`).
    KnownFailure,
    /// Marked `known_failure` but within the tolerance: the reason should be revisited.
    UnexpectedPass,
    /// The reference data are not available yet.
    Pending,
    /// The computation itself failed (the message is in the case's notes).
    Error,
}

impl Verdict {
    /// Whether this verdict makes `slamtool validate` exit with a failure status.
    pub fn is_failure(self) -> bool {
        matches!(self, Verdict::Fail | Verdict::Error)
    }

    pub fn label(self) -> &'static str {
        match self {
            Verdict::Pass => "pass",
            Verdict::Fail => "FAIL",
            Verdict::KnownFailure => "known failure",
            Verdict::UnexpectedPass => "pass (known failure)",
            Verdict::Pending => "pending data",
            Verdict::Error => "ERROR",
        }
    }
}

/// The error measure shown in the summary, and whether the computation is within the tolerance
/// (`None` when the reference is pending).
pub fn assess(computed: f64, reference: &Reference, tol: Tolerance) -> (Option<f64>, Option<bool>) {
    if let Reference::Pending { .. } = reference {
        return (None, None);
    }
    if !computed.is_finite() {
        return (None, Some(false));
    }
    match (reference, tol) {
        (Reference::Pending { .. }, _) => (None, None),
        (Reference::Value { value }, Tolerance::Relative { value: t }) => {
            let e = computed / value - 1.0;
            (Some(e), Some(e.abs() <= t))
        }
        (Reference::Value { value }, Tolerance::Absolute { value: t }) => {
            let e = computed - value;
            (Some(e), Some(e.abs() <= t))
        }
        (
            Reference::Value { value },
            Tolerance::AtMost { value: t } | Tolerance::UpperBound { value: t },
        ) => (Some(computed - value), Some(computed <= t)),
        (Reference::Value { value }, Tolerance::BelowReference) => {
            (Some(computed - value), Some(computed < *value))
        }
        (Reference::Range { lower, upper }, _) => {
            let e = if computed < *lower {
                computed - lower
            } else if computed > *upper {
                computed - upper
            } else {
                0.0
            };
            (Some(e), Some(e == 0.0))
        }
        (Reference::Value { .. }, Tolerance::WithinRange) => (None, Some(false)),
    }
}

/// The verdict from the comparison and the case's `known_failure` mark.
pub fn verdict(within: Option<bool>, known_failure: bool) -> Verdict {
    match (within, known_failure) {
        (None, _) => Verdict::Pending,
        (Some(true), false) => Verdict::Pass,
        (Some(true), true) => Verdict::UnexpectedPass,
        (Some(false), false) => Verdict::Fail,
        (Some(false), true) => Verdict::KnownFailure,
    }
}

/// `number` followed by its unit, or alone for a ratio (unit "-", or none), whose unit only the quantity
/// column names.
pub fn with_unit(number: &str, unit: &str) -> String {
    if unit.is_empty() || unit == "-" {
        number.to_string()
    } else {
        format!("{number} {unit}")
    }
}

/// The tolerance as text for the summary table.
pub fn tolerance_text(tol: Tolerance, unit: &str) -> String {
    match tol {
        Tolerance::Relative { value } => format!("±{} %", trim(value * 100.0)),
        Tolerance::Absolute { value } => format!("±{}", with_unit(&trim(value), unit)),
        Tolerance::AtMost { value } => format!("≤ {}", with_unit(&trim(value), unit)),
        Tolerance::UpperBound { value } => {
            format!("≤ {} (one-sided bound)", with_unit(&trim(value), unit))
        }
        Tolerance::BelowReference => "< reference".into(),
        Tolerance::WithinRange => "within range".into(),
    }
}

/// The error as text for the summary table, in the measure of the tolerance.
pub fn error_text(error: Option<f64>, tol: Tolerance, unit: &str) -> String {
    match (error, tol) {
        (None, _) => "–".into(),
        (Some(e), Tolerance::Relative { .. }) => format!("{:+.1} %", e * 100.0),
        (Some(e), _) => with_unit(&signed(e), unit),
    }
}

/// A number with four significant digits, without trailing zeros.
pub fn trim(x: f64) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let digits = (4 - 1 - x.abs().log10().floor() as i32).clamp(0, 8) as usize;
    let s = format!("{x:.digits$}");
    if s.contains('.') {
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        s
    }
}

fn signed(x: f64) -> String {
    if x >= 0.0 {
        format!("+{}", trim(x))
    } else {
        trim(x)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn relative_and_range_comparisons() {
        let r = Reference::Value { value: 100.0 };
        let t = Tolerance::Relative { value: 0.1 };
        assert_eq!(assess(109.0, &r, t).1, Some(true));
        assert_eq!(assess(111.0, &r, t).1, Some(false));
        assert_eq!(assess(f64::NAN, &r, t).1, Some(false));
        // A one-sided bound passes far below its value, and says it is one-sided.
        let one = Reference::Value { value: 1.0 };
        let ub = Tolerance::UpperBound { value: 1.0 };
        assert_eq!(assess(0.5, &one, ub).1, Some(true));
        assert_eq!(assess(1.01, &one, ub).1, Some(false));
        assert!(tolerance_text(ub, "-").contains("one-sided"));
        let range = Reference::Range {
            lower: 0.4,
            upper: 1.0,
        };
        assert_eq!(
            assess(0.7, &range, Tolerance::WithinRange),
            (Some(0.0), Some(true))
        );
        assert_eq!(assess(1.2, &range, Tolerance::WithinRange).1, Some(false));
        let pending = Reference::Pending { reason: "x".into() };
        assert_eq!(assess(1.0, &pending, t), (None, None));
    }

    #[test]
    fn verdicts_and_failure() {
        assert_eq!(verdict(Some(true), false), Verdict::Pass);
        assert_eq!(verdict(Some(false), false), Verdict::Fail);
        assert_eq!(verdict(Some(false), true), Verdict::KnownFailure);
        assert_eq!(verdict(Some(true), true), Verdict::UnexpectedPass);
        assert_eq!(verdict(None, false), Verdict::Pending);
        assert!(Verdict::Fail.is_failure() && Verdict::Error.is_failure());
        assert!(!Verdict::KnownFailure.is_failure() && !Verdict::Pending.is_failure());
    }

    #[test]
    fn numbers_are_trimmed() {
        assert_eq!(trim(6650.0), "6650");
        assert_eq!(trim(0.15), "0.15");
        assert_eq!(trim(1.52534), "1.525");
    }
}
