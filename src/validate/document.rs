//! The validation report as a document ([`crate::report::document`]), typeset to `validation.pdf`.
//!
//! Front page: the tally of verdicts under the title (pass, pass of a known failure, known failure,
//! pending data, fail, error, zeros included), then one table, one row per case (quantity, computed,
//! reference, error, tolerance, verdict).
//! Then one section per case: verdict, numbers, tolerance and its reason, known failure or pending data,
//! provenance, notes, wall time, the table of numbers and the overlay plots.

use super::compare::Reference;
use super::report::{case_inputs, mode_text, summary_row, summary_rows, tally_text};
use super::{Suite, plot};
use crate::error::Result;
use crate::report::document::{Block, Document};

/// Title, subtitle lines, footer and blocks of the validation report.
#[derive(Debug, Clone)]
pub struct Outline {
    pub title: String,
    pub subtitle: Vec<String>,
    pub footer: String,
    pub blocks: Vec<Block>,
}

/// The outline of the report of a suite; `commit` is the tool's git commit.
pub fn outline(s: &Suite, commit: &str) -> Result<Outline> {
    let mode = mode_text(s.mode);
    let mut blocks = vec![Block::Table {
        caption: "Validation summary: one row per case".into(),
        header: [
            "case: quantity",
            "computed",
            "reference",
            "error",
            "tolerance",
            "verdict",
        ]
        .map(String::from)
        .to_vec(),
        rows: summary_rows(s)
            .into_iter()
            .map(|r| {
                vec![
                    format!("{}: {}", r.case, r.quantity),
                    r.computed,
                    r.reference,
                    r.error,
                    r.tolerance,
                    r.verdict,
                ]
            })
            .collect(),
    }];
    let failed: Vec<&str> = s
        .cases
        .iter()
        .filter(|c| c.verdict.is_failure())
        .map(|c| c.name.as_str())
        .collect();
    blocks.push(Block::Strong(if failed.is_empty() {
        "No case fails its tolerance (known failures and pending data are listed with their reasons)."
            .into()
    } else {
        format!("Failing cases: {}.", failed.join(", "))
    }));
    for c in &s.cases {
        let r = summary_row(c);
        blocks.push(Block::Heading {
            level: 1,
            text: format!("{}: {}", c.name, c.title),
        });
        blocks.push(Block::Strong(format!("Verdict: {}", c.verdict.label())));
        let mut kv = vec![
            (
                "quantity".to_string(),
                format!("{} ({})", c.quantity, c.unit),
            ),
            ("computed".into(), r.computed),
            ("reference".into(), r.reference),
            ("error".into(), r.error),
            ("tolerance".into(), r.tolerance),
            ("wall time".into(), format!("{:.1} s", c.wall_time_s)),
        ];
        if let Some(p) = c.particles_per_half_beam {
            kv.push(("particles over the half-beam".into(), format!("{p}")));
        }
        blocks.push(Block::KeyValue(kv));
        blocks.push(Block::Paragraph(format!(
            "{}: {}",
            c.tolerance_stated.lead(),
            c.tolerance_reason
        )));
        if let Some(k) = &c.known_failure {
            blocks.push(Block::Paragraph(format!("Known failure: {k}")));
        }
        if let Some(Reference::Pending { reason }) = &c.reference {
            blocks.push(Block::Paragraph(format!("Pending data: {reason}")));
        }
        blocks.push(Block::Paragraph(sentence(&format!(
            "Provenance: {}",
            c.provenance
        ))));
        blocks.push(Block::List(case_inputs(c)));
        if !c.notes.is_empty() {
            blocks.push(Block::List(c.notes.clone()));
        }
        if let Some(t) = &c.table {
            blocks.push(Block::Table {
                caption: format!("{}: numbers", c.name),
                header: t.header.clone(),
                rows: t.rows.clone(),
            });
        }
        for f in &c.figures {
            match plot::svg(f) {
                Ok(svg) => blocks.push(Block::Svg {
                    svg,
                    caption: f.title.clone(),
                    width_mm: 160.0,
                }),
                Err(e) => blocks.push(Block::Strong(format!("Not drawn: {e}"))),
            }
        }
    }
    Ok(Outline {
        title: "slamtool validation report".into(),
        subtitle: vec![
            format!("Mode: {mode}; wall time {:.0} s", s.wall_time_s),
            tally_text(s),
            format!("slamtool {}, commit {commit}", env!("CARGO_PKG_VERSION")),
        ],
        footer: "slamtool validation report".into(),
        blocks,
    })
}

/// The validation report as a PDF (no date: identical results give an identical file).
pub fn pdf(s: &Suite, commit: &str) -> Result<Vec<u8>> {
    let o = outline(s, commit)?;
    Document {
        title: o.title,
        subtitle: o.subtitle,
        stamp: None,
        footer: o.footer,
        blocks: o.blocks,
    }
    .pdf()
}

/// `text` as a sentence: with a full stop at its end unless it already ends with one (a provenance that
/// ends in an abbreviation or a sentence of its own).
fn sentence(text: &str) -> String {
    let t = text.trim_end();
    if t.ends_with('.') {
        t.to_string()
    } else {
        format!("{t}.")
    }
}
