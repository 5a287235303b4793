//! The validation report: the one-table summary (one row per case: quantity, computed, reference,
//! error, tolerance, verdict) as CSV, JSON and Markdown, and per case a folder with its numbers
//! (`table.csv`, `case.json`) and its overlay plots (`<figure>.svg` with a `<figure>.csv` twin).
//! [`summary_rows`] and [`markdown`] are the content a PDF document is built from.

use std::path::{Path, PathBuf};

use serde::Serialize;

use super::compare::{self, Reference, trim, with_unit};
use super::{CaseResult, Suite, plot};
use crate::error::Result;
use crate::files::write_text_atomic;
use crate::provenance::Provenance;

/// One row of the front-page table, as text.
#[derive(Debug, Clone, Serialize)]
pub struct SummaryRow {
    pub case: String,
    pub quantity: String,
    pub computed: String,
    pub reference: String,
    pub error: String,
    pub tolerance: String,
    pub verdict: String,
}

/// The reference as text.
pub fn reference_text(r: Option<&Reference>, unit: &str) -> String {
    match r {
        None => "–".into(),
        Some(Reference::Value { value }) => with_unit(&trim(*value), unit),
        Some(Reference::Range { lower, upper }) if lower == upper => with_unit(&trim(*lower), unit),
        Some(Reference::Range { lower, upper }) => {
            with_unit(&format!("{} – {}", trim(*lower), trim(*upper)), unit)
        }
        Some(Reference::Pending { .. }) => "pending data".into(),
    }
}

/// The summary row of a case.
pub fn summary_row(c: &CaseResult) -> SummaryRow {
    SummaryRow {
        case: c.name.clone(),
        quantity: format!("{} ({})", c.quantity, c.unit),
        computed: c
            .computed
            .filter(|x| x.is_finite())
            .map_or("–".into(), |x| with_unit(&trim(x), &c.unit)),
        reference: reference_text(c.reference.as_ref(), &c.unit),
        error: compare::error_text(c.error, c.tolerance, &c.unit),
        tolerance: compare::tolerance_text(c.tolerance, &c.unit),
        verdict: c.verdict.label().into(),
    }
}

/// One row per case.
pub fn summary_rows(s: &Suite) -> Vec<SummaryRow> {
    s.cases.iter().map(summary_row).collect()
}

fn csv_cell(x: &str) -> String {
    if x.contains([',', '"', '\n']) {
        format!("\"{}\"", x.replace('"', "\"\""))
    } else {
        x.to_string()
    }
}

/// The summary table as CSV (with `#` provenance lines first).
pub fn summary_csv(s: &Suite, header: &str) -> String {
    let mut out = header.to_string();
    out += "case,quantity,computed,reference,error,tolerance,verdict,wall_time_s\n";
    for (r, c) in summary_rows(s).iter().zip(&s.cases) {
        let cells = [
            &r.case,
            &r.quantity,
            &r.computed,
            &r.reference,
            &r.error,
            &r.tolerance,
            &r.verdict,
            &format!("{:.1}", c.wall_time_s),
        ];
        out += &cells.map(|x| csv_cell(x)).join(",");
        out.push('\n');
    }
    out
}

fn md(x: &str) -> String {
    x.replace('|', "\\|").replace('\n', " ")
}

/// The mode as the reports state it: `--full` runs each case at its finer resolution, which is not a
/// claim of convergence (only a convergence case can show that, for its own quantity).
pub fn mode_text(mode: super::Mode) -> &'static str {
    match mode {
        super::Mode::Quick => "quick (coarse resolution, for CI)",
        super::Mode::Full => {
            "full (each case at its finer resolution; convergence is claimed only where a convergence \
             case shows it)"
        }
    }
}

/// The tally of verdicts: (label, count), every verdict listed, zeros included.
pub fn tally(s: &Suite) -> Vec<(&'static str, usize)> {
    use super::Verdict as V;
    vec![
        ("pass", count(s, &[V::Pass])),
        ("pass of a known failure", count(s, &[V::UnexpectedPass])),
        ("known failure", count(s, &[V::KnownFailure])),
        ("pending data", count(s, &[V::Pending])),
        ("fail", count(s, &[V::Fail])),
        ("error", count(s, &[V::Error])),
    ]
}

/// The tally as one line: "30 cases: 20 pass, 1 pass of a known failure, ...".
pub fn tally_text(s: &Suite) -> String {
    format!(
        "{} cases: {}",
        s.cases.len(),
        tally(s)
            .iter()
            .map(|(l, n)| format!("{n} {l}"))
            .collect::<Vec<_>>()
            .join(", ")
    )
}

/// The physical conditions and input files of a case as one line each.
pub fn case_inputs(c: &CaseResult) -> Vec<String> {
    let mut out: Vec<String> = c
        .conditions
        .iter()
        .map(|(k, v)| format!("{k}: {v}"))
        .collect();
    out.extend(
        c.inputs
            .iter()
            .map(|f| format!("input {} sha256 {}", f.path, f.sha256)),
    );
    out
}

/// The report as Markdown: the tally and the summary table, then one section per case (verdict, numbers,
/// tolerance and its reason, known failure, provenance, conditions and inputs, notes, figures, wall time).
pub fn markdown(s: &Suite) -> String {
    let mut out = format!(
        "# slamtool validation report\n\nMode: {}. Wall time {:.0} s. {}.\n\n| case | quantity | computed \
         | reference | error | tolerance | verdict |\n|---|---|---|---|---|---|---|\n",
        mode_text(s.mode),
        s.wall_time_s,
        tally_text(s),
    );
    for r in summary_rows(s) {
        out += &format!(
            "| {} | {} | {} | {} | {} | {} | {} |\n",
            md(&r.case),
            md(&r.quantity),
            md(&r.computed),
            md(&r.reference),
            md(&r.error),
            md(&r.tolerance),
            md(&r.verdict)
        );
    }
    for c in &s.cases {
        out += &format!("\n## {}: {}\n\n", c.name, c.title);
        out += &format!("**Verdict: {}.** ", c.verdict.label());
        let r = summary_row(c);
        out += &format!(
            "{}: computed {}, reference {}, error {}, tolerance {}.\n\n",
            c.quantity, r.computed, r.reference, r.error, r.tolerance
        );
        out += &format!(
            "*{}:* {}\n\n",
            c.tolerance_stated.lead(),
            c.tolerance_reason
        );
        if let Some(k) = &c.known_failure {
            out += &format!("*Known failure:* {k}\n\n");
        }
        if let Some(Reference::Pending { reason }) = &c.reference {
            out += &format!("*Pending data:* {reason}\n\n");
        }
        out += &format!(
            "*Provenance:* {}\n\n",
            super::document::sentence(&c.provenance)
        );
        for n in case_inputs(c) {
            out += &format!("- {n}\n");
        }
        for n in &c.notes {
            out += &format!("- {n}\n");
        }
        if let Some(p) = c.particles_per_half_beam {
            out += &format!("- {p} particles over the half-beam\n");
        }
        out += &format!("- wall time {:.1} s\n", c.wall_time_s);
        for f in &c.figures {
            out += &format!("\n![{}]({}/{}.svg)\n", md(&f.title), c.name, f.name);
        }
        if let Some(t) = &c.table {
            // A short table (a comparison of a few sources) is written out here; a long one is linked.
            if t.rows.len() <= INLINE_TABLE_ROWS {
                out += &format!(
                    "\n| {} |\n|{}\n",
                    t.header
                        .iter()
                        .map(|h| md(h))
                        .collect::<Vec<_>>()
                        .join(" | "),
                    "---|".repeat(t.header.len())
                );
                for row in &t.rows {
                    out += &format!(
                        "| {} |\n",
                        row.iter().map(|x| md(x)).collect::<Vec<_>>().join(" | ")
                    );
                }
            }
            out += &format!("\nNumbers: [{0}/table.csv]({0}/table.csv)\n", c.name);
        }
    }
    out
}

/// Largest case table written out in the Markdown report (longer ones are linked only).
const INLINE_TABLE_ROWS: usize = 8;

fn count(s: &Suite, v: &[super::Verdict]) -> usize {
    s.cases.iter().filter(|c| v.contains(&c.verdict)).count()
}

/// The provenance of one case's CSV files as `#` lines: the suite's tool, commit and settings, with the
/// suite's list of cases replaced by this case's name and its inputs by the case's own (its case file and
/// what it reads, [`CaseResult::inputs`]), so that each file says what it depends on and not what the
/// rest of the suite read.
pub fn case_header(suite: &Provenance, c: &CaseResult) -> String {
    let mut settings = suite.settings.clone();
    if let Some(o) = settings.as_object_mut() {
        o.remove("cases");
        o.insert("case".into(), c.name.clone().into());
    }
    Provenance {
        tool: suite.tool.clone(),
        commit: suite.commit.clone(),
        inputs: c.inputs.clone(),
        settings,
    }
    .csv_header()
}

/// Write the report into `dir`; returns the files written. `suite_provenance` heads the suite's files
/// (summary.csv, summary.json); each case's CSV files carry [`case_header`].
pub fn write(s: &Suite, dir: &Path, suite_provenance: &Provenance) -> Result<Vec<PathBuf>> {
    let header = suite_provenance.csv_header();
    let provenance = serde_json::to_value(suite_provenance).unwrap_or_default();
    std::fs::create_dir_all(dir).map_err(|e| crate::Error::io(dir, e))?;
    let mut files = Vec::new();
    let mut put = |p: PathBuf, text: &str| -> Result<()> {
        write_text_atomic(&p, text)?;
        files.push(p);
        Ok(())
    };
    put(dir.join("summary.csv"), &summary_csv(s, &header))?;
    put(dir.join("summary.md"), &markdown(s))?;
    let json = serde_json::json!({
        "tool": format!("slamtool {}", env!("CARGO_PKG_VERSION")),
        "provenance": provenance,
        "mode": s.mode,
        "wall_time_s": s.wall_time_s,
        "failed": s.failed(),
        "tally": tally(s).into_iter().collect::<std::collections::BTreeMap<_, _>>(),
        "summary": summary_rows(s),
        "cases": s.cases,
    });
    put(
        dir.join("summary.json"),
        &(serde_json::to_string_pretty(&json).unwrap_or_default() + "\n"),
    )?;
    for c in &s.cases {
        let cd = dir.join(&c.name);
        std::fs::create_dir_all(&cd).map_err(|e| crate::Error::io(&cd, e))?;
        put(
            cd.join("case.json"),
            &(serde_json::to_string_pretty(c).unwrap_or_default() + "\n"),
        )?;
        let header = case_header(suite_provenance, c);
        if let Some(t) = &c.table {
            let mut text = header.clone();
            text += &t.header.join(",");
            text.push('\n');
            for row in &t.rows {
                text += &row
                    .iter()
                    .map(|x| csv_cell(x))
                    .collect::<Vec<_>>()
                    .join(",");
                text.push('\n');
            }
            put(cd.join("table.csv"), &text)?;
        }
        for f in &c.figures {
            // A figure that cannot be drawn honestly is left out here; the PDF says why.
            if let (Ok(svg), Ok(csv)) = (plot::svg(f), plot::csv(f)) {
                put(cd.join(format!("{}.svg", f.name)), &svg)?;
                put(
                    cd.join(format!("{}.csv", f.name)),
                    &(header.to_string() + &csv),
                )?;
            }
        }
    }
    Ok(files)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ratio_s_cells_carry_no_unit_and_no_stray_space() {
        use crate::validate::compare::{Tolerance, error_text, tolerance_text};
        assert_eq!(with_unit("1.983", "-"), "1.983");
        assert_eq!(with_unit("1.983", ""), "1.983");
        assert_eq!(with_unit("3.4", "kPa"), "3.4 kPa");
        assert_eq!(
            tolerance_text(Tolerance::UpperBound { value: 1.0 }, "-"),
            "≤ 1 (one-sided bound)"
        );
        let range = Reference::Range {
            lower: 0.4,
            upper: 1.0,
        };
        assert_eq!(reference_text(Some(&range), "-"), "0.4 – 1");
        assert_eq!(
            error_text(Some(0.041), Tolerance::Relative { value: 0.15 }, "-"),
            "+4.1 %"
        );
    }
}
