//! What moved between two assessments (`slamtool diff OLD/summary.json NEW/summary.json`): the design
//! values per station and sensor, the section forces, the total bow force, the limit verdicts, the
//! published comparisons and trend checks, failed runs and warnings. Meant for a CI job that keeps the
//! previous run's `summary.json` and prints what a change of the hull or of the tool did to the results.
//!
//! A value counts as moved when |new − old| > `tolerance` · max(|old|, |new|) (relative change), or when its
//! `source` or convergence `verdict` changed; a sensor, station or speed present on one side only is listed
//! as added or removed. Both files are read as JSON, so a summary written by an older version of the tool
//! with fewer fields is compared on the fields both have.

use std::path::Path;

use serde::Serialize;
use serde_json::Value;

use crate::error::{Error, Result};

/// One difference between the two assessments.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Change {
    /// What it is, e.g. `design pressure, station 0.133, sensor S133-3`.
    pub what: String,
    /// The old and new value as text (with unit), `None` where absent on that side.
    pub old: Option<String>,
    pub new: Option<String>,
    /// (new − old) / |old| for numbers present on both sides.
    pub relative_change: Option<f64>,
}

/// Read a `summary.json` of `slamtool assess`, refusing anything else with the reason.
pub fn read(path: &Path) -> Result<Value> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
    let v: Value = serde_json::from_str(&text)
        .map_err(|e| Error::Invalid(format!("{}: not JSON ({e})", path.display())))?;
    if !v.get("stations").is_some_and(Value::is_array)
        || !v.get("events").is_some_and(Value::is_array)
    {
        return Err(Error::Invalid(format!(
            "{}: not the summary.json of `slamtool assess` (no `stations` and `events` arrays)",
            path.display()
        )));
    }
    Ok(v)
}

fn num(v: &Value, key: &str) -> Option<f64> {
    v.get(key).and_then(Value::as_f64)
}

fn text(v: &Value, key: &str) -> Option<String> {
    v.get(key).and_then(Value::as_str).map(str::to_string)
}

fn arr<'a>(v: &'a Value, key: &str) -> &'a [Value] {
    v.get(key)
        .and_then(Value::as_array)
        .map_or(&[], Vec::as_slice)
}

/// Compares two numbers with their unit scale (e.g. Pa shown as kPa: `scale` 1e-3, `unit` "kPa").
struct Numbers<'a> {
    tolerance: f64,
    scale: f64,
    unit: &'a str,
}

impl Numbers<'_> {
    fn show(&self, x: f64) -> String {
        format!("{:.4} {}", x * self.scale, self.unit)
            .trim_end()
            .to_string()
    }

    fn compare(&self, what: &str, old: Option<f64>, new: Option<f64>, out: &mut Vec<Change>) {
        match (old, new) {
            (Some(a), Some(b)) => {
                let m = a.abs().max(b.abs());
                if (b - a).abs() > self.tolerance * m {
                    out.push(Change {
                        what: what.to_string(),
                        old: Some(self.show(a)),
                        new: Some(self.show(b)),
                        relative_change: (a != 0.0).then(|| (b - a) / a.abs()),
                    });
                }
            }
            (None, None) => {}
            (a, b) => out.push(Change {
                what: what.to_string(),
                old: a.map(|x| self.show(x)),
                new: b.map(|x| self.show(x)),
                relative_change: None,
            }),
        }
    }
}

fn compare_text(what: &str, old: Option<String>, new: Option<String>, out: &mut Vec<Change>) {
    if old != new {
        out.push(Change {
            what: what.to_string(),
            old,
            new,
            relative_change: None,
        });
    }
}

/// A design value (`DesignValue` of `summary.json`): its value, source and verdict.
fn design_value(
    what: &str,
    old: Option<&Value>,
    new: Option<&Value>,
    n: &Numbers,
    out: &mut Vec<Change>,
) {
    n.compare(
        what,
        old.and_then(|v| num(v, "value")),
        new.and_then(|v| num(v, "value")),
        out,
    );
    if let (Some(o), Some(w)) = (old, new) {
        compare_text(
            &format!("{what}: source"),
            text(o, "source"),
            text(w, "source"),
            out,
        );
        compare_text(
            &format!("{what}: verdict"),
            text(o, "verdict"),
            text(w, "verdict"),
            out,
        );
    }
}

/// Pairs the elements of two arrays by a key, in the order of `old` then the new-only ones.
fn paired<'a>(
    old: &'a [Value],
    new: &'a [Value],
    key: impl Fn(&Value) -> String,
) -> Vec<(String, Option<&'a Value>, Option<&'a Value>)> {
    let mut out: Vec<(String, Option<&Value>, Option<&Value>)> = old
        .iter()
        .map(|o| {
            let k = key(o);
            let w = new.iter().find(|w| key(w) == k);
            (k, Some(o), w)
        })
        .collect();
    for w in new {
        let k = key(w);
        if !old.iter().any(|o| key(o) == k) {
            out.push((k, None, Some(w)));
        }
    }
    out
}

fn station_key(v: &Value) -> String {
    format!("station {}", num(v, "station").unwrap_or(f64::NAN))
}

/// The list of what moved from `old` to `new` (both `summary.json` of `assess`), values compared with the
/// relative `tolerance`.
pub fn diff(old: &Value, new: &Value, tolerance: f64) -> Vec<Change> {
    let mut out = Vec::new();
    for k in ["hull", "loading", "fidelity", "tool"] {
        compare_text(k, text(old, k), text(new, k), &mut out);
    }
    let kpa = Numbers {
        tolerance,
        scale: 1e-3,
        unit: "kPa",
    };
    let n_per_m = Numbers {
        tolerance,
        scale: 1.0,
        unit: "N/m",
    };
    let newton = Numbers {
        tolerance,
        scale: 1.0,
        unit: "N",
    };
    let count = Numbers {
        tolerance: 0.0,
        scale: 1.0,
        unit: "",
    };
    for (st, o, w) in paired(arr(old, "stations"), arr(new, "stations"), station_key) {
        let (Some(o), Some(w)) = (o, w) else {
            compare_text(
                &st,
                o.map(|_| "assessed".into()),
                w.map(|_| "assessed".into()),
                &mut out,
            );
            continue;
        };
        let name = |v: &Value| text(v, "name").unwrap_or_default();
        for (s, a, b) in paired(
            arr(o, "design_pressure_pa"),
            arr(w, "design_pressure_pa"),
            name,
        ) {
            design_value(
                &format!("design pressure, {st}, sensor {s}"),
                a,
                b,
                &kpa,
                &mut out,
            );
        }
        design_value(
            &format!("section force, {st}"),
            o.get("section_force_peak_n_per_m").filter(|v| !v.is_null()),
            w.get("section_force_peak_n_per_m").filter(|v| !v.is_null()),
            &n_per_m,
            &mut out,
        );
    }
    let speed_wave = |v: &Value| {
        format!(
            "{} m/s, {}",
            num(v, "speed_m_per_s").unwrap_or(f64::NAN),
            text(v, "wave").unwrap_or_default()
        )
    };
    for (k, a, b) in paired(arr(old, "bow_force"), arr(new, "bow_force"), speed_wave) {
        newton.compare(
            &format!("bow force (peak sum), {k}"),
            a.and_then(|v| num(v, "peak_sum_total_n")),
            b.and_then(|v| num(v, "peak_sum_total_n")),
            &mut out,
        );
    }
    let quantity = |v: &Value| text(v, "quantity").unwrap_or_default();
    for (k, a, b) in paired(arr(old, "comparisons"), arr(new, "comparisons"), quantity) {
        let unit = a.or(b).and_then(|v| text(v, "unit")).unwrap_or_default();
        Numbers {
            tolerance,
            scale: 1.0,
            unit: &unit,
        }
        .compare(
            &format!("comparison: {k}"),
            a.and_then(|v| num(v, "computed")),
            b.and_then(|v| num(v, "computed")),
            &mut out,
        );
    }
    let check = |v: &Value| text(v, "check").unwrap_or_default();
    for (k, a, b) in paired(arr(old, "trend_checks"), arr(new, "trend_checks"), check) {
        compare_text(
            &format!("trend check: {k}"),
            a.and_then(|v| text(v, "verdict")),
            b.and_then(|v| text(v, "verdict")),
            &mut out,
        );
    }
    count.compare(
        "failed runs",
        num(old, "failed_runs"),
        num(new, "failed_runs"),
        &mut out,
    );
    let lines = |v: &Value, k: &str| -> Vec<String> {
        arr(v, k)
            .iter()
            .filter_map(|x| x.as_str().map(str::to_string))
            .collect()
    };
    for (k, label) in [
        ("limit_violations", "limit violation"),
        ("warnings", "warning"),
    ] {
        let (a, b) = (lines(old, k), lines(new, k));
        for l in a.iter().filter(|l| !b.contains(l)) {
            compare_text(label, Some(l.clone()), None, &mut out);
        }
        for l in b.iter().filter(|l| !a.contains(l)) {
            compare_text(label, None, Some(l.clone()), &mut out);
        }
    }
    out
}

/// One line of text per change.
pub fn line(c: &Change) -> String {
    let side = |s: &Option<String>| s.clone().unwrap_or_else(|| "(absent)".into());
    let rel = c
        .relative_change
        .map_or(String::new(), |r| format!(" ({:+.1} %)", 100.0 * r));
    format!("{}: {} -> {}{rel}", c.what, side(&c.old), side(&c.new))
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    fn summary(p: f64, source: &str, violations: &[&str]) -> Value {
        json!({
            "hull": "h", "loading": "l", "fidelity": "analytic", "tool": "slamtool 0.1.0",
            "events": [], "failed_runs": 0, "warnings": [],
            "limit_violations": violations,
            "stations": [{"station": 0.1, "design_pressure_pa": [
                {"name": "P1", "value": p, "source": source, "verdict": null}],
                "section_force_peak_n_per_m": null}],
        })
    }

    #[test]
    fn identical_summaries_have_no_change() {
        let a = summary(3000.0, "analytic", &[]);
        assert!(diff(&a, &a, 0.0).is_empty());
    }

    #[test]
    fn a_moved_pressure_a_new_source_and_a_new_violation_are_listed() {
        let a = summary(3000.0, "analytic", &[]);
        let b = summary(3300.0, "sph (converged)", &["LIMIT EXCEEDED: x"]);
        let d = diff(&a, &b, 0.005);
        let lines: Vec<String> = d.iter().map(line).collect();
        assert_eq!(d.len(), 3, "{lines:?}");
        assert_eq!(
            lines[0],
            "design pressure, station 0.1, sensor P1: 3.0000 kPa -> 3.3000 kPa (+10.0 %)"
        );
        assert!(lines[1].contains("source: analytic -> sph (converged)"));
        assert_eq!(lines[2], "limit violation: (absent) -> LIMIT EXCEEDED: x");
        // Below the tolerance a number has not moved.
        assert!(diff(&a, &summary(3001.0, "analytic", &[]), 0.005).is_empty());
    }
}
