//! `slamtool sweep`: design-space sweeps. A sweep file names a base hull, a sea state, the fidelity, and
//! the parameters to vary (lists, ranges or a Latin hypercube): operating parameters (speed, regular-wave
//! height and length or a named wave, H_s and T_p of the irregular seas, draft and trim) and hull
//! transformations (bow flare and deadrise, length and beam). Every case runs through the `assess`
//! machinery; results are cached per case and per SPH run, so a killed sweep resumes, and a sweep can be
//! split into shards for a scheduler and merged back.
//!
//! The layers, in the order the data flows:
//!
//! * [`file`](mod@file): the sweep file and its checks (located errors);
//! * [`cases`] (with [`lhs`]): the cases, in a fixed order;
//! * [`transform`]: the hull variants;
//! * [`prepare`]: everything decided before running (variants checked, content keys);
//! * [`motions`] and [`execute`]: running the cases (analytic: shared strip theory per variant; screen
//!   and SPH: `assess::run`), with the case cache;
//! * [`shard`] and [`merge`]: splitting and joining;
//! * [`results`] and [`output`]: tables, plots and report content.

pub mod cases;
pub mod execute;
pub mod file;
pub mod lhs;
pub mod merge;
pub mod motions;
pub mod output;
pub mod prepare;
pub mod report;
pub mod results;
pub mod shard;
pub mod transform;

use std::path::Path;

pub use execute::Options;
pub use results::{CaseResult, Shard, SweepResult};

use crate::error::Result;
use crate::progress::ProgressHandle;

/// Read, check and run the sweep file at `path` with `opts`, writing the results into `opts.out`.
pub fn run(path: &Path, opts: &Options, progress: &ProgressHandle) -> Result<SweepResult> {
    // Say how big a large sweep is before its (possibly long) preparation starts; a small one once its
    // preparation has checked it, so that an error in the file is not preceded by its size.
    let n = cases::expand(&file::SweepFile::read(path)?)?.len();
    if n >= LARGE_SWEEP {
        progress.note(&size_note(n));
    }
    let p = prepare::prepare(path, &opts.out)?;
    if n < LARGE_SWEEP {
        progress.note(&size_note(n));
    }
    execute::run(&p, opts, progress)
}

/// Sweeps with at least this many cases get a note on their cost before they start.
pub const LARGE_SWEEP: usize = 10_000;

/// CPU seconds of one case at the analytic fidelity, for the cost note: 0.11 s measured for an eight-speed
/// analytic sweep of the Ochi hull (0.89 s of CPU, start-up included).
const ANALYTIC_CASE_CPU_S: f64 = 0.1;

/// The note printed before a sweep is prepared: its number of cases and, for a large one, what that
/// means in time.
pub fn size_note(cases: usize) -> String {
    if cases >= LARGE_SWEEP {
        format!(
            "{cases} cases to prepare and run: each case is a whole assessment (about {ANALYTIC_CASE_CPU_S} s of \
             CPU at the analytic fidelity, minutes with SPH), so this sweep takes at least {:.1} CPU hours; it can \
             be stopped and resumed (finished cases are cached), or split with --shard",
            cases as f64 * ANALYTIC_CASE_CPU_S / 3600.0
        )
    } else {
        let s = if cases == 1 { "" } else { "s" };
        format!("{cases} case{s} to prepare and run")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_large_sweep_states_its_cost() {
        assert_eq!(size_note(8), "8 cases to prepare and run");
        assert_eq!(size_note(1), "1 case to prepare and run");
        let n = size_note(1_000_000);
        assert!(n.contains("at least 27.8 CPU hours"), "{n}");
    }
}
