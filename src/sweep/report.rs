//! The sweep report (`report.pdf`), laid out with the report document API (`report::document`): the
//! sweep's settings and inputs, the best variants under the sweep file's rule, the response plots (each
//! case's largest design pressure and slam probability against each parameter; the same figures as
//! `plots/*.svg`, whose CSV twins hold the plotted numbers), the failed cases with their reasons and the
//! warnings. Nothing is recomputed: the report is made from a [`SweepResult`], so `merge` writes the same
//! report as an unsharded run.

use std::path::{Path, PathBuf};

use super::output::report_content;
use super::results::SweepResult;
use crate::error::Result;
use crate::files::write_atomic;
use crate::report::document::{Block, Document};

/// Width of a response plot on the page, mm.
const FIGURE_MM: f64 = 165.0;

/// The report of a sweep as a document.
pub fn document(r: &SweepResult) -> Result<Document> {
    let content = report_content(r)?;
    let mut blocks = Vec::new();
    let shard = r.shard.map_or("whole sweep".to_string(), |s| {
        format!("shard {} of {} (0-based)", s.index, s.count)
    });
    let mut settings: Vec<(String, String)> = vec![
        ("fidelity".into(), r.fidelity.clone()),
        (
            "cases".into(),
            format!(
                "{} of {} ({shard}), {} failed",
                r.cases.len(),
                r.total_cases,
                r.failed_cases
            ),
        ),
        ("parameters varied".into(), r.parameters.join(", ")),
        ("sweep hash".into(), r.sweep_hash.clone()),
        (
            "tool".into(),
            format!("{} (commit {})", r.tool, r.provenance.commit),
        ),
    ];
    for i in &r.provenance.inputs {
        settings.push((
            "input".into(),
            format!("{} (SHA-256 {})", i.path, &i.sha256[..16]),
        ));
    }
    blocks.push(Block::Heading {
        level: 1,
        text: "Sweep".into(),
    });
    blocks.push(Block::KeyValue(settings));
    blocks.push(Block::Paragraph(
        "Each case is one variant (hull transformation and operating condition) assessed as `slamtool assess` \
         does at the sweep's fidelity; its design pressure is the largest over its sensors and events, its \
         slam probability (Ochi's criterion, per encounter) the largest over its stations, speeds and \
         irregular seas. The hull transformations are defined in docs/guide/sweeps.md."
            .into(),
    ));
    blocks.push(Block::Heading {
        level: 1,
        text: "Best variants".into(),
    });
    blocks.push(Block::Strong(content.best_rule.clone()));
    if content.best_rows.is_empty() {
        blocks.push(Block::Paragraph(content.no_best.clone()));
    } else {
        blocks.push(Block::Table {
            caption: format!("The best variants ({}).", content.best_rule),
            header: content.best_header.clone(),
            rows: content.best_rows.clone(),
        });
    }
    blocks.push(Block::Heading {
        level: 1,
        text: "Responses".into(),
    });
    if content.plots.is_empty() {
        blocks.push(Block::Paragraph(
            "No response plots: no case finished with a numeric parameter varied.".into(),
        ));
    }
    for p in &content.plots {
        blocks.push(Block::Svg {
            svg: p.svg.clone(),
            caption: format!(
                "{} ({} cases; plotted values in plots/{}.csv).",
                p.title,
                p.points.len(),
                p.stem
            ),
            width_mm: FIGURE_MM,
        });
    }
    let failed: Vec<Vec<String>> = r
        .cases
        .iter()
        .filter_map(|c| c.failed.as_ref().map(|f| vec![c.id.clone(), f.clone()]))
        .collect();
    if !failed.is_empty() || !r.warnings.is_empty() {
        blocks.push(Block::Heading {
            level: 1,
            text: "Failed cases and warnings".into(),
        });
    }
    if !failed.is_empty() {
        blocks.push(Block::Table {
            caption: "Cases that failed, with the reason.".into(),
            header: vec!["case".into(), "reason".into()],
            rows: failed,
        });
    }
    if r.warnings.len() > super::results::WARNINGS_IN_FULL {
        let kinds = super::results::warning_kinds(&r.cases);
        blocks.push(Block::Paragraph(format!(
            "{} distinct warnings of {} kinds. Warnings that differ only in their numbers are one kind; \
             each kind is given once, with the number of cases that gave it and each number as its range \
             over the kind (lowest..highest, number by number). Every warning follows, with its cases.",
            r.warnings.len(),
            kinds.len()
        )));
        blocks.push(Block::List(
            kinds.iter().map(super::results::kind_line).collect(),
        ));
    }
    if !r.warnings.is_empty() {
        blocks.push(Block::List(r.warnings.clone()));
    }
    Ok(Document {
        title: content.title,
        subtitle: vec![format!("{} cases, {} fidelity", r.total_cases, r.fidelity)],
        stamp: None,
        footer: format!("slamtool sweep: {}", r.name),
        blocks,
    })
}

/// Write `report.pdf` into `dir`.
pub fn write_pdf(dir: &Path, r: &SweepResult) -> Result<PathBuf> {
    let pdf = document(r)?.pdf()?;
    let path = dir.join("report.pdf");
    write_atomic(&path, &pdf)?;
    Ok(path)
}
