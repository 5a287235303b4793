//! Which part of a sweep this process runs. Case i belongs to shard i mod n, so shards are deterministic,
//! balanced to one case and need no coordination. The shard comes from `--shard i/n` (0-based i), or
//! else from a scheduler's environment:
//!
//! * Slurm job arrays: `SLURM_ARRAY_TASK_ID`, `SLURM_ARRAY_TASK_COUNT` and `SLURM_ARRAY_TASK_MIN` (the shard
//!   is ID − MIN of COUNT; the array must be contiguous, e.g. `--array=0-7` or `--array=1-8`);
//! * Kubernetes Indexed Jobs: `JOB_COMPLETION_INDEX` (0-based) with the number of completions from
//!   `--shard-count N` or the variable `SLAMTOOL_SHARD_COUNT` (Kubernetes does not expose it; the manifest
//!   sets it from the same number as `completions`).

use super::results::Shard;
use crate::error::{Error, Result};

/// Parse `i/n` (0 <= i < n).
pub fn parse(s: &str) -> Result<Shard> {
    let bad = |why: &str| {
        Error::Invalid(format!(
            "--shard {s}: {why} (write i/n with 0 <= i < n, e.g. 0/4)"
        ))
    };
    let (i, n) = s.split_once('/').ok_or_else(|| bad("no '/'"))?;
    let i: usize = i
        .trim()
        .parse()
        .map_err(|_| bad("i is not a whole number"))?;
    let n: usize = n
        .trim()
        .parse()
        .map_err(|_| bad("n is not a whole number"))?;
    if n == 0 {
        return Err(bad("n must be at least 1"));
    }
    if i >= n {
        return Err(bad("i must be less than n"));
    }
    Ok(Shard { index: i, count: n })
}

fn number(var: &str, v: &str) -> Result<usize> {
    v.trim().parse().map_err(|_| {
        Error::Invalid(format!(
            "environment variable {var} = '{v}' is not a whole number"
        ))
    })
}

/// The shard from the command line or the scheduler's environment (`get` reads a variable), or None.
pub fn resolve(
    explicit: Option<&str>,
    shard_count: Option<usize>,
    get: &dyn Fn(&str) -> Option<String>,
) -> Result<Option<Shard>> {
    if let Some(s) = explicit {
        return parse(s).map(Some);
    }
    if let Some(id) = get("SLURM_ARRAY_TASK_ID") {
        let id = number("SLURM_ARRAY_TASK_ID", &id)?;
        let count = match (shard_count, get("SLURM_ARRAY_TASK_COUNT")) {
            (Some(n), _) => n,
            (None, Some(c)) => number("SLURM_ARRAY_TASK_COUNT", &c)?,
            (None, None) => {
                return Err(Error::Invalid(
                    "SLURM_ARRAY_TASK_ID is set but SLURM_ARRAY_TASK_COUNT is not: give --shard-count N \
                     or --shard i/n"
                        .into(),
                ));
            }
        };
        let min = match get("SLURM_ARRAY_TASK_MIN") {
            Some(m) => number("SLURM_ARRAY_TASK_MIN", &m)?,
            None => 0,
        };
        let index = id.checked_sub(min).filter(|&i| i < count).ok_or_else(|| {
            Error::Invalid(format!(
                "Slurm array task {id} (min {min}) is not one of {count} contiguous tasks: use a contiguous \
                 array such as --array=0-{}",
                count.saturating_sub(1)
            ))
        })?;
        if count == 0 {
            return Err(Error::Invalid("SLURM_ARRAY_TASK_COUNT is 0".into()));
        }
        return Ok(Some(Shard { index, count }));
    }
    if let Some(ix) = get("JOB_COMPLETION_INDEX") {
        let index = number("JOB_COMPLETION_INDEX", &ix)?;
        let count = match (shard_count, get("SLAMTOOL_SHARD_COUNT")) {
            (Some(n), _) => n,
            (None, Some(c)) => number("SLAMTOOL_SHARD_COUNT", &c)?,
            (None, None) => {
                return Err(Error::Invalid(
                    "JOB_COMPLETION_INDEX is set (a Kubernetes Indexed Job) but the number of shards is not: \
                     set SLAMTOOL_SHARD_COUNT to the Job's completions, or give --shard-count N"
                        .into(),
                ));
            }
        };
        if count == 0 || index >= count {
            return Err(Error::Invalid(format!(
                "JOB_COMPLETION_INDEX = {index} is not below the shard count {count}"
            )));
        }
        return Ok(Some(Shard { index, count }));
    }
    if shard_count.is_some() {
        return Err(Error::Invalid(
            "--shard-count needs JOB_COMPLETION_INDEX or SLURM_ARRAY_TASK_ID in the environment (or use \
             --shard i/n)"
                .into(),
        ));
    }
    Ok(None)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn env<'a>(vars: &'a [(&'a str, &'a str)]) -> impl Fn(&str) -> Option<String> + 'a {
        move |k| vars.iter().find(|v| v.0 == k).map(|v| v.1.to_string())
    }

    #[test]
    fn explicit_slurm_and_kubernetes() {
        let none = env(&[]);
        assert_eq!(
            resolve(Some("1/3"), None, &none).unwrap(),
            Some(Shard { index: 1, count: 3 })
        );
        assert!(resolve(Some("3/3"), None, &none).is_err());
        assert_eq!(resolve(None, None, &none).unwrap(), None);
        let slurm = env(&[
            ("SLURM_ARRAY_TASK_ID", "5"),
            ("SLURM_ARRAY_TASK_COUNT", "4"),
            ("SLURM_ARRAY_TASK_MIN", "2"),
        ]);
        assert_eq!(
            resolve(None, None, &slurm).unwrap(),
            Some(Shard { index: 3, count: 4 })
        );
        let k8s = env(&[("JOB_COMPLETION_INDEX", "2"), ("SLAMTOOL_SHARD_COUNT", "3")]);
        assert_eq!(
            resolve(None, None, &k8s).unwrap(),
            Some(Shard { index: 2, count: 3 })
        );
        let k8s_no_count = env(&[("JOB_COMPLETION_INDEX", "2")]);
        assert!(resolve(None, None, &k8s_no_count).is_err());
        assert_eq!(
            resolve(None, Some(4), &k8s_no_count).unwrap(),
            Some(Shard { index: 2, count: 4 })
        );
    }
}
