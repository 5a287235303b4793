//! `slamtool sweep SWEEP.toml` and `slamtool merge DIR...`: design-space sweeps. The work is
//! `slamtool::sweep`; this file parses the arguments, picks the shard and prints the summary.

use std::path::{Path, PathBuf};
use std::time::Instant;

use clap::Args;
use slamtool::sweep::{self, SweepResult, output, results};
use slamtool::{Error, Result};

use super::global::{self, JsonArg};
use super::progress_bar;

/// Examples at the end of `slamtool sweep --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool sweep sweeps/ochi-speed-flare.toml
  slamtool sweep sweeps/ochi-speed-flare.toml -o reports/flare --shard 0/4
  SLURM_ARRAY_TASK_ID=1 SLURM_ARRAY_TASK_COUNT=4 slamtool sweep sweeps/ochi-speed-flare.toml -o reports/flare
  slamtool merge reports/flare/shard-*-of-4 -o reports/flare";

/// Examples at the end of `slamtool merge --help`.
pub const MERGE_EXAMPLES: &str = "\
Examples:
  slamtool merge reports/flare
  slamtool merge reports/flare/shard-0-of-2 reports/flare/shard-1-of-2 -o reports/flare";

#[derive(Debug, Args)]
pub struct SweepArgs {
    /// Sweep file (sweep.toml): base hull, sea state, fidelity and the parameters to vary.
    sweep: PathBuf,
    /// Output folder [default: reports/sweeps/<sweep file name>/]; a shard writes into
    /// DIR/shard-<i>-of-<n>/.
    #[arg(short, long, value_name = "DIR", alias = "output")]
    out: Option<PathBuf>,
    /// Parallel threads, 1 to 256 [default: one per core].
    #[arg(
        short = 'j',
        long,
        value_name = "N",
        value_parser = clap::value_parser!(u16).range(1..=global::MAX_THREADS)
    )]
    threads: Option<u16>,
    /// Run only shard i of n (0-based; case k belongs to shard k mod n). Without it the shard is read
    /// from SLURM_ARRAY_TASK_ID/SLURM_ARRAY_TASK_COUNT(/SLURM_ARRAY_TASK_MIN) or JOB_COMPLETION_INDEX.
    #[arg(long, value_name = "i/n")]
    shard: Option<String>,
    /// Number of shards with JOB_COMPLETION_INDEX (Kubernetes Indexed Job) [default: $SLAMTOOL_SHARD_COUNT].
    #[arg(long, value_name = "N")]
    shard_count: Option<usize>,
    /// Write into an output folder that holds files a sweep did not write.
    #[arg(long)]
    force: bool,
    /// Stop after computing K cases (to test resuming).
    #[arg(long, value_name = "K", hide = true)]
    stop_after: Option<usize>,
    #[command(flatten)]
    json: JsonArg,
}

#[derive(Debug, Args)]
pub struct MergeArgs {
    /// Result folders of the shards (each with its sweep.json), or the folder holding them (the --out
    /// every shard wrote into: its shard-<i>-of-<n> folders are merged).
    #[arg(required = true, value_name = "DIR")]
    dirs: Vec<PathBuf>,
    /// Output folder [default: the folder holding the first DIR].
    #[arg(short, long, value_name = "DIR", alias = "output")]
    out: Option<PathBuf>,
    /// Write into an output folder that is one of the shards, or holds files a sweep did not write.
    #[arg(long)]
    force: bool,
    #[command(flatten)]
    json: JsonArg,
}

/// Refuse a folder that holds other things than a sweep's files, unless --force (the rule of every
/// command, [`slamtool::output_policy::check_out_folder`]).
fn check_out(dir: &Path, force: bool) -> Result<()> {
    slamtool::output_policy::check_out_folder(
        dir,
        &|n| output::KNOWN.contains(&n) || n.starts_with("shard-"),
        "a sweep",
        force,
    )
}

/// The text summary: counts, failures and the best variants.
fn summary(r: &SweepResult) -> String {
    let mut s = format!(
        "sweep '{}' ({} fidelity): {} of {} cases{}",
        r.name,
        r.fidelity,
        r.cases.len(),
        r.total_cases,
        r.shard.map_or(String::new(), |sh| format!(
            " (shard {}/{})",
            sh.index, sh.count
        ))
    );
    s += &format!(", {} failed\n", r.failed_cases);
    for c in r.cases.iter().filter(|c| c.failed.is_some()) {
        s += &format!(
            "  FAILED {} ({}): {}\n",
            c.id,
            c.parameters
                .iter()
                .map(|p| format!("{}={}", p.name, p.value))
                .collect::<Vec<_>>()
                .join(", "),
            c.failed.as_deref().unwrap_or("")
        );
    }
    let content = match output::report_content(r) {
        Ok(c) => c,
        Err(e) => return s + &format!("(no best-variants table: {e})\n"),
    };
    s += &format!("\nbest variants ({}):\n", content.best_rule);
    if content.best_rows.is_empty() {
        s += &format!("  {}\n", content.no_best);
    } else {
        s += &format!("  {}\n", content.best_header.join("  "));
        for row in &content.best_rows {
            s += &format!("  {}\n", row.join("  "));
        }
    }
    s
}

/// The sweep's warnings on the terminal: each in full when there are few; otherwise each kind once
/// (warnings that differ only in their numbers, with each number's range over the kind:
/// [`results::warning_kinds`]) with the number of cases that gave it, and where all of them are.
fn print_warnings(r: &SweepResult) {
    if r.warnings.len() <= results::WARNINGS_IN_FULL {
        for w in &r.warnings {
            println!("{}", global::warning_line(w));
        }
        return;
    }
    let kinds = results::warning_kinds(&r.cases);
    println!(
        "\n{} distinct warnings of {} kinds (warnings that differ only in their numbers are one kind; each number \
         below is its range over the kind, lowest..highest); all of them, with their cases, are in sweep.json \
         (\"warnings\") and the report:",
        r.warnings.len(),
        kinds.len()
    );
    for k in &kinds {
        println!("{}", global::warning_line(&results::kind_line(k)));
    }
}

fn report(r: &SweepResult, out: &Path, extra: serde_json::Value, json: bool) -> Result<()> {
    if json {
        for w in &r.warnings {
            global::warn_stderr(w);
        }
        let mut v = serde_json::to_value(r).map_err(|e| Error::Invalid(format!("sweep: {e}")))?;
        v["outputs"] = serde_json::json!({ "folder": out.display().to_string() });
        v["best_variants"] = serde_json::json!(
            results::best(r, &r.best)
                .iter()
                .map(|c| c.id.clone())
                .collect::<Vec<_>>()
        );
        if let (Some(o), Some(e)) = (v.as_object_mut(), extra.as_object()) {
            o.extend(e.clone());
        }
        global::print_json(v);
    } else {
        print!("{}", summary(r));
        print_warnings(r);
        println!("\n{}", global::files_written_line(out));
    }
    if r.failed_cases > 0 {
        return Err(Error::Numerical(format!(
            "{} of {} cases failed (their reasons are in sweep.json and above); the others finished",
            r.failed_cases,
            r.cases.len()
        )));
    }
    Ok(())
}

pub fn run(a: SweepArgs) -> Result<()> {
    let shard = sweep::shard::resolve(a.shard.as_deref(), a.shard_count, &|k| {
        std::env::var(k).ok().filter(|v| !v.is_empty())
    })?;
    let base = a.out.clone().unwrap_or_else(|| {
        let stem = a
            .sweep
            .file_stem()
            .map_or("sweep".into(), |s| s.to_string_lossy().into_owned());
        Path::new("reports").join("sweeps").join(stem)
    });
    check_out(&base, a.force)?;
    let out = match shard {
        Some(s) => base.join(format!("shard-{}-of-{}", s.index, s.count)),
        None => base,
    };
    let opts = sweep::Options {
        out: out.clone(),
        threads: a.threads.map(usize::from),
        shard,
        stop_after: a.stop_after,
    };
    let t0 = Instant::now();
    let r = sweep::run(&a.sweep, &opts, &progress_bar::handle())?;
    let secs = t0.elapsed().as_secs_f64();
    let rate = r.cases.len() as f64 / secs.max(1e-9);
    if !a.json.json {
        global::note(&format!(
            "{} cases in {secs:.2} s ({rate:.1} cases/s, cached cases included)",
            r.cases.len()
        ));
    }
    report(
        &r,
        &out,
        serde_json::json!({ "wall_time_s": secs, "cases_per_s": rate }),
        a.json.json,
    )
}

pub fn run_merge(a: MergeArgs) -> Result<()> {
    // A folder holding shard-<i>-of-<n> folders (one --out for every shard) stands for its shards.
    let (dirs, parents) = sweep::merge::shard_folders(&a.dirs)?;
    let r = sweep::merge::merge(&dirs)?;
    let out = a.out.clone().unwrap_or_else(|| match parents.first() {
        Some(p) => p.clone(),
        None => dirs[0]
            .parent()
            .map_or(PathBuf::from("."), Path::to_path_buf),
    });
    // A shard given as its sweep.json file stands for its folder.
    let inputs: Vec<&Path> = dirs
        .iter()
        .map(|d| match d.parent() {
            Some(p) if d.is_file() && !p.as_os_str().is_empty() => p,
            Some(_) if d.is_file() => Path::new("."),
            _ => d.as_path(),
        })
        .collect();
    slamtool::output_policy::refuse_input_target(&out, &inputs, "-o", a.force)?;
    check_out(&out, a.force)?;
    output::write(&out, &r)?;
    report(&r, &out, serde_json::json!({}), a.json.json)
}
