//! `slamtool validate`: run the validation cases of `validation/` and write the report. The work is
//! `slamtool::validate`; this file parses the arguments, prints the summary table and sets the exit
//! status (6 when a case fails, known failures excepted).

use std::path::PathBuf;

use clap::Args;
use slamtool::provenance::Provenance;
use slamtool::validate::{self, Case, Mode, report};
use slamtool::{Error, Result};

use super::global::{self, JsonArg};

/// Examples at the end of `slamtool validate --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool validate --quick
  slamtool validate --case zhao1996-prescribed --case yettou2006-drop -o target/validation
  slamtool validate --full -o reports/validation";

#[derive(Debug, Args)]
pub struct ValidateArgs {
    /// Coarse resolution, for CI (the default).
    #[arg(long, conflicts_with = "full")]
    quick: bool,
    /// Each case at its finer resolution (long: tens of minutes); not a claim of convergence.
    #[arg(long)]
    full: bool,
    /// Run only these cases (file names in the cases folder without `.toml`); repeat or comma-separate.
    #[arg(long = "case", value_name = "NAME", value_delimiter = ',')]
    cases: Vec<String>,
    /// Folder of the case files.
    #[arg(long, value_name = "DIR", default_value = "validation")]
    cases_dir: PathBuf,
    #[command(flatten)]
    json: JsonArg,
    /// Output folder.
    #[arg(short, long, value_name = "DIR", default_value = "reports/validation")]
    out: PathBuf,
}

pub fn run(a: ValidateArgs) -> Result<()> {
    let mode = if a.full { Mode::Full } else { Mode::Quick };
    let files = validate::case::case_files(&a.cases_dir)?;
    for name in &a.cases {
        if !files
            .iter()
            .any(|f| f.file_stem().is_some_and(|s| s == name.as_str()))
        {
            return Err(Error::Invalid(format!(
                "--case {name}: no {name}.toml in {}",
                a.cases_dir.display()
            )));
        }
    }
    let selected: Vec<PathBuf> = files
        .into_iter()
        .filter(|f| {
            a.cases.is_empty()
                || f.file_stem()
                    .is_some_and(|s| a.cases.iter().any(|n| s == n.as_str()))
        })
        .collect();
    let cases = selected
        .iter()
        .map(|p| Case::from_file(p))
        .collect::<Result<Vec<_>>>()?;
    if cases.is_empty() {
        return Err(Error::Invalid(format!(
            "no case files in {}",
            a.cases_dir.display()
        )));
    }
    std::fs::create_dir_all(&a.out).map_err(|e| Error::io(&a.out, e))?;
    let mut inputs: Vec<PathBuf> = selected.clone();
    for c in &cases {
        inputs.extend(c.input_files());
    }
    inputs.sort();
    inputs.dedup();
    let input_refs: Vec<&std::path::Path> = inputs.iter().map(PathBuf::as_path).collect();
    let prov = Provenance::new(
        &input_refs,
        serde_json::json!({
            "mode": mode,
            "cases": cases.iter().map(|c| &c.name).collect::<Vec<_>>(),
            "solver_sources_sha256": slamtool::provenance::SOLVER_SOURCES_SHA256,
        }),
    )?;
    let total = cases.len();
    let mut k = 0;
    let suite = validate::run_suite(&cases, mode, a.out.join("work"), &mut |c| {
        k += 1;
        global::note(&format!("[{k}/{total}] {}", c.name));
    });
    let mut written = report::write(&suite, &a.out, &prov)?;
    let pdf = a.out.join("validation.pdf");
    slamtool::files::write_atomic(&pdf, &validate::document::pdf(&suite, &prov.commit)?)?;
    written.push(pdf);
    if a.json.json {
        global::print_json(serde_json::json!({
            "tool": prov.tool,
            "provenance": &prov,
            "warnings": [],
            "outputs": {"folder": a.out, "files": written},
            "mode": mode,
            "failed": suite.failed(),
            "tally": report::tally(&suite).into_iter().collect::<std::collections::BTreeMap<_, _>>(),
            "wall_time_s": suite.wall_time_s,
            "summary": report::summary_rows(&suite),
        }));
    } else {
        let rows = report::summary_rows(&suite);
        let w = |f: &dyn Fn(&report::SummaryRow) -> usize, h: &str| {
            rows.iter().map(f).max().unwrap_or(0).max(h.chars().count())
        };
        let wc = w(&|r| r.case.chars().count(), "case");
        let wp = w(&|r| r.computed.chars().count(), "computed");
        let wr = w(&|r| r.reference.chars().count(), "reference");
        let we = w(&|r| r.error.chars().count(), "error");
        let wt = w(&|r| r.tolerance.chars().count(), "tolerance");
        let pad =
            |s: &str, n: usize| format!("{s}{}", " ".repeat(n.saturating_sub(s.chars().count())));
        println!(
            "{}  {}  {}  {}  {}  verdict",
            pad("case", wc),
            pad("computed", wp),
            pad("reference", wr),
            pad("error", we),
            pad("tolerance", wt)
        );
        for r in &rows {
            println!(
                "{}  {}  {}  {}  {}  {}",
                pad(&r.case, wc),
                pad(&r.computed, wp),
                pad(&r.reference, wr),
                pad(&r.error, we),
                pad(&r.tolerance, wt),
                r.verdict
            );
        }
        println!("{}", report::tally_text(&suite));
        println!("wall time {:.0} s", suite.wall_time_s);
        println!("{}", global::files_written_line(&a.out));
        // A case that could not be computed shows ERROR in the table; its reason is said here, not only
        // in its case.json.
        for c in &suite.cases {
            if c.verdict == validate::Verdict::Error {
                let why = c
                    .notes
                    .iter()
                    .find(|n| n.starts_with("the computation failed"))
                    .map_or("no reason recorded", String::as_str);
                println!(
                    "{}",
                    global::terminal_safe(&format!("ERROR {}: {why}", c.name))
                );
            }
        }
    }
    let failed: Vec<&str> = suite
        .cases
        .iter()
        .filter(|c| c.verdict.is_failure())
        .map(|c| c.name.as_str())
        .collect();
    if failed.is_empty() {
        Ok(())
    } else {
        Err(Error::ValidationFailed(format!(
            "{} of {} cases failed: {}",
            failed.len(),
            total,
            failed.join(", ")
        )))
    }
}
