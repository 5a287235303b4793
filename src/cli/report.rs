//! `slamtool report RESULTS_DIR [-o OUT] [--stamp]`: the assessment report (PDF, SVG figures with CSV
//! twins) from the saved results of `slamtool assess`, without recomputing them. The work is
//! `slamtool::report::assessment`.

use std::path::{Path, PathBuf};

use clap::Args;
use slamtool::output_policy as policy;
use slamtool::report::assessment;

use super::global::{self, JsonArg};

/// Examples at the end of `slamtool report --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool report reports/ochi-1958-v-form-model-reconstruction
  slamtool report reports/ochi-gate -o /tmp/ochi-report --stamp";

#[derive(Debug, Args)]
pub struct ReportArgs {
    /// Output folder of `slamtool assess` (with summary.json).
    results: PathBuf,
    /// Folder for report.pdf and figures/ [default: RESULTS].
    #[arg(short, long, value_name = "DIR", alias = "output")]
    out: Option<PathBuf>,
    /// Print today's date (UTC) under the title; without it the PDF has no date, so unchanged results
    /// give a byte-identical report.
    #[arg(long)]
    stamp: bool,
    /// Write into an output folder (or its figures/) that holds files a report or an assessment did not
    /// write. Such files are never removed.
    #[arg(long)]
    force: bool,
    #[command(flatten)]
    json: JsonArg,
}

/// Refuse an output folder, or a `figures/` in it, that holds files neither an assessment nor a report
/// wrote, unless --force (the rule of every command).
fn check_out(out: &Path, force: bool) -> slamtool::Result<()> {
    let known = [
        "summary.json",
        "pressures.csv",
        "bow_force.csv",
        "cache",
        "motions.json",
        "report.pdf",
        "figures",
        assessment::TIMING_FILE,
    ];
    policy::check_out_folder(out, &|n| known.contains(&n), "a report", force)?;
    policy::check_out_folder(
        &out.join("figures"),
        &assessment::is_report_figure,
        "a report",
        force,
    )
}

/// Today's date (UTC) as YYYY-MM-DD, from the system clock.
pub fn today() -> String {
    let days = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_secs() / 86_400) as i64;
    // Civil date from days since 1970-01-01 (H. Hinnant's algorithm).
    let z = days + 719_468;
    let era = z.div_euclid(146_097);
    let doe = z - era * 146_097;
    let yoe = (doe - doe / 1460 + doe / 36_524 - doe / 146_096) / 365;
    let doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    let mp = (5 * doy + 2) / 153;
    let d = doy - (153 * mp + 2) / 5 + 1;
    let m = if mp < 10 { mp + 3 } else { mp - 9 };
    let y = yoe + era * 400 + i64::from(m <= 2);
    format!("{y:04}-{m:02}-{d:02}")
}

/// Write the report of `results` into `out`, print what was refused, and return the files.
pub fn write_report(
    results: &std::path::Path,
    out: &std::path::Path,
    stamp: bool,
) -> slamtool::Result<assessment::Generated> {
    let stamp = stamp.then(|| format!("Generated {} (UTC)", today()));
    let g = assessment::generate(results, out, stamp)?;
    for r in &g.refused {
        global::warn_stderr(r);
    }
    Ok(g)
}

pub fn run(a: ReportArgs) -> slamtool::Result<()> {
    let out = a.out.clone().unwrap_or_else(|| a.results.clone());
    check_out(&out, a.force)?;
    let g = write_report(&a.results, &out, a.stamp)?;
    if a.json.json {
        let files: Vec<String> = g.files.iter().map(|p| p.display().to_string()).collect();
        // The provenance of the results the report was drawn from.
        let provenance = std::fs::read_to_string(a.results.join("summary.json"))
            .ok()
            .and_then(|t| serde_json::from_str::<serde_json::Value>(&t).ok())
            .map_or(serde_json::Value::Null, |v| v["provenance"].clone());
        global::print_json(serde_json::json!({
            "tool": slamtool::provenance::TOOL,
            "provenance": provenance,
            "report_time_s": g.time_s,
            "refused_figures": g.refused,
            "warnings": g.refused,
            "outputs": {"folder": out.display().to_string(), "files": files},
        }));
    } else {
        println!(
            "report written in {:.2} s: {} ({} figures)",
            g.time_s,
            out.join("report.pdf").display(),
            g.files
                .iter()
                .filter(|p| p.extension().is_some_and(|e| e == "svg"))
                .count()
        );
        println!("{}", global::files_written_line(&out));
    }
    Ok(())
}
