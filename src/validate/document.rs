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
        blocks.extend(note_blocks(&c.name, &c.notes));
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

/// A case's notes as blocks: a list, broken where a note carries a Markdown table (the strip-theory
/// readings of a ship case, `seakeeping::wave_readings`), which becomes a typeset table between the
/// note's text before it (in the list) and after it (a paragraph).
fn note_blocks(case: &str, notes: &[String]) -> Vec<Block> {
    let mut out = Vec::new();
    let mut items: Vec<String> = Vec::new();
    for note in notes {
        let Some((before, header, rows, after)) = markdown_table(note) else {
            items.push(note.clone());
            continue;
        };
        items.push(before);
        out.push(Block::List(std::mem::take(&mut items)));
        out.push(Block::Table {
            caption: format!("{case}: the table of the note above"),
            header,
            rows,
        });
        if !after.is_empty() {
            out.push(Block::Paragraph(after));
        }
    }
    if !items.is_empty() {
        out.push(Block::List(items));
    }
    out
}

/// The first Markdown table of `text` (lines starting with `|`: a header, the `|---|` line, rows), as the
/// text before it, the header cells, the rows and the text after it; None without one. Cells are
/// unescaped (`\|` is a bar).
#[allow(clippy::type_complexity)]
fn markdown_table(text: &str) -> Option<(String, Vec<String>, Vec<Vec<String>>, String)> {
    let lines: Vec<&str> = text.lines().collect();
    let start = lines.iter().position(|l| l.trim_start().starts_with('|'))?;
    let len = lines[start..]
        .iter()
        .take_while(|l| l.trim_start().starts_with('|'))
        .count();
    let separator = lines.get(start + 1)?;
    if len < 2 || !separator.trim().trim_matches('|').split('|').all(is_rule) {
        return None;
    }
    let cells = |l: &str| -> Vec<String> {
        let l = l.trim().strip_prefix('|').unwrap_or(l.trim());
        let l = l.strip_suffix('|').unwrap_or(l);
        let mut out = Vec::new();
        let mut cell = String::new();
        let mut chars = l.chars().peekable();
        while let Some(ch) = chars.next() {
            match ch {
                '\\' if chars.peek() == Some(&'|') => {
                    cell.push('|');
                    chars.next();
                }
                '|' => out.push(std::mem::take(&mut cell).trim().to_string()),
                _ => cell.push(ch),
            }
        }
        out.push(cell.trim().to_string());
        out
    };
    let join = |ls: &[&str]| ls.join("\n").trim().to_string();
    Some((
        join(&lines[..start]),
        cells(lines[start]),
        lines[start + 2..start + len]
            .iter()
            .map(|l| cells(l))
            .collect(),
        join(&lines[start + len..]),
    ))
}

/// Whether a cell of a Markdown table's rule line is a rule (`---`, `:--`, `--:`, `:-:`).
fn is_rule(cell: &str) -> bool {
    let c = cell.trim();
    c.len() >= 3 && c.trim_matches(':').chars().all(|ch| ch == '-')
}

/// `text` as a sentence: with a full stop at its end unless it already ends with one (a provenance that
/// ends in an abbreviation or a sentence of its own).
pub(super) fn sentence(text: &str) -> String {
    let t = text.trim_end();
    if t.ends_with('.') {
        t.to_string()
    } else {
        format!("{t}.")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_note_with_a_markdown_table_is_split_into_text_table_and_text() {
        let notes = vec![
            "first".to_string(),
            "the chain:\n\n| a | \\|s\\| (m) |\n|---|---:|\n| x | 1 |\n| y | 2 |\n\nAfter it."
                .to_string(),
            "last".to_string(),
        ];
        let b = note_blocks("c", &notes);
        assert_eq!(b.len(), 4, "{b:?}");
        match &b[0] {
            Block::List(items) => assert_eq!(items, &["first".to_string(), "the chain:".into()]),
            x => panic!("{x:?}"),
        }
        match &b[1] {
            Block::Table { header, rows, .. } => {
                assert_eq!(header, &["a".to_string(), "|s| (m)".into()]);
                assert_eq!(
                    rows,
                    &[
                        vec!["x".to_string(), "1".into()],
                        vec!["y".into(), "2".into()]
                    ]
                );
            }
            x => panic!("{x:?}"),
        }
        assert!(matches!(&b[2], Block::Paragraph(t) if t == "After it."));
        assert!(matches!(&b[3], Block::List(items) if items == &["last".to_string()]));
        // no table: one list, as before
        assert!(matches!(
            &note_blocks("c", &notes[..1])[..],
            [Block::List(_)]
        ));
        // bars in text without a rule line are not a table
        assert!(markdown_table("| a |\n| b |").is_none());
    }
}
