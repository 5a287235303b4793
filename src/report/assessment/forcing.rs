//! The measured-forcing section of the assessment report: which stations were driven by a measured or
//! externally computed relative-motion record instead of strip theory, from which file, with the file's
//! provenance lines and the keel entry found in it ([`crate::assess::measured`]).

use serde_json::Value;

use super::Report;
use super::data::{list, num, text};
use crate::report::document::Block;

/// The section, when the summary has measured forcing (nothing otherwise).
pub fn section(r: &mut Report, summary: &Value) {
    let records = list(summary, "measured_forcing");
    if records.is_empty() {
        return;
    }
    r.heading(2, "Measured forcing");
    r.para(
        "These stations are driven by a measured or externally computed relative-motion record instead of \
         strip theory: the keel-entry instant is found in the record and the section enters with the \
         record's velocity from then on. Their strip-theory events are replaced.",
    );
    let f = |v: Option<f64>, d: usize| v.map_or("-".into(), |x| format!("{x:.d$}"));
    let rows = records
        .iter()
        .map(|m| {
            vec![
                f(num(m, "station"), 3),
                text(m, "file").to_string(),
                text(m, "column").to_string(),
                f(num(m, "entry_time_s"), 4),
                f(num(m, "entry_velocity_m_per_s"), 3),
                f(num(m, "profile_duration_s"), 3),
            ]
        })
        .collect();
    r.push(Block::Table {
        caption: "Stations driven by a measured record".into(),
        header: [
            "station (Lpp aft of FP)",
            "record",
            "column",
            "keel entry in record (s)",
            "entry velocity (m/s)",
            "profile (s)",
        ]
        .map(String::from)
        .to_vec(),
        rows,
    });
    for m in records {
        let mut items = vec![
            format!("velocity: {}", text(m, "velocity_from")),
            format!("profile ends: {}", text(m, "profile_end")),
        ];
        items.extend(
            list(m, "provenance")
                .iter()
                .filter_map(Value::as_str)
                .map(|p| format!("record: {p}")),
        );
        r.para(&format!(
            "{} at station {} Lpp:",
            text(m, "file"),
            f(num(m, "station"), 3)
        ));
        r.push(Block::List(items));
    }
}
