//! `slamtool diff OLD/summary.json NEW/summary.json`: what moved between two assessments
//! ([`slamtool::assess::diff`]).

use std::path::PathBuf;

use clap::Args;
use slamtool::assess::diff;

use super::global::{self, JsonArg};

/// Examples at the end of `slamtool diff --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool diff previous/summary.json reports/ochi-vform/summary.json
  slamtool diff previous/summary.json reports/ochi-vform/summary.json --tolerance-percent 2 --json

Values count as moved when they change by more than the tolerance (relative), or when their
source or convergence verdict changes. The exit status is 0 whether or not anything moved.";

#[derive(Debug, Args)]
pub struct DiffArgs {
    /// The earlier assessment's summary.json (or its results folder).
    old: PathBuf,
    /// The later assessment's summary.json (or its results folder).
    new: PathBuf,
    /// Smallest relative change reported, percent.
    #[arg(long, value_name = "PCT", default_value_t = 0.5,
          value_parser = parse_percent)]
    tolerance_percent: f64,
    #[command(flatten)]
    json: JsonArg,
}

fn parse_percent(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if v.is_finite() && (0.0..=100.0).contains(&v) => Ok(v),
        _ => Err(format!("'{s}' is not a percentage from 0 to 100")),
    }
}

/// A results folder stands for its summary.json.
fn summary_path(p: PathBuf) -> PathBuf {
    if p.is_dir() {
        p.join("summary.json")
    } else {
        p
    }
}

pub fn run(a: DiffArgs) -> slamtool::Result<()> {
    let (po, pn) = (summary_path(a.old), summary_path(a.new));
    let (old, new) = (diff::read(&po)?, diff::read(&pn)?);
    let changes = diff::diff(&old, &new, a.tolerance_percent / 100.0);
    if a.json.json {
        let provenance = slamtool::provenance::Provenance::new(
            &[po.as_path(), pn.as_path()],
            serde_json::json!({ "tolerance_percent": a.tolerance_percent }),
        )?;
        global::print_json(serde_json::json!({
            "tool": slamtool::provenance::TOOL,
            "provenance": provenance,
            "warnings": [],
            "outputs": null,
            "old": po.display().to_string(),
            "new": pn.display().to_string(),
            "tolerance_percent": a.tolerance_percent,
            "changes": changes,
        }));
        return Ok(());
    }
    for c in &changes {
        println!("{}", global::terminal_safe(&diff::line(c)));
    }
    println!(
        "{} change(s) beyond {} % between {} and {}",
        changes.len(),
        a.tolerance_percent,
        po.display(),
        pn.display()
    );
    Ok(())
}
