//! Joining the results of a sweep's shards (`slamtool merge`). Shards are accepted only when they come
//! from the same sweep (the same `sweep_hash`: the sweep file and the hull and sea files it names) and the
//! same tool version; a case present in two shards must have the same content key in both. The merged
//! result is the one an unsharded run gives (the same cases in the same order, the same tables).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use super::cases::MAX_CASES;
use super::results::SweepResult;
use crate::error::{Error, Result};

/// Largest shard file read, bytes (a million cases at a few hundred bytes each, with room).
pub const MAX_SHARD_BYTES: u64 = 4 << 30;

/// Read the `sweep.json` of a shard's folder.
pub fn read(dir: &Path) -> Result<SweepResult> {
    let p = if dir.is_dir() {
        dir.join("sweep.json")
    } else {
        dir.to_path_buf()
    };
    if let Ok(m) = std::fs::metadata(&p)
        && m.len() > MAX_SHARD_BYTES
    {
        return Err(Error::Invalid(format!(
            "{}: {} bytes is more than the sweep.json of a sweep of at most {MAX_CASES} cases can be \
             ({MAX_SHARD_BYTES} bytes accepted)",
            p.display(),
            m.len()
        )));
    }
    let text = std::fs::read_to_string(&p).map_err(|e| Error::io(&p, e))?;
    serde_json::from_str(&text).map_err(|e| {
        Error::Invalid(format!(
            "{}: not the sweep.json of a slamtool sweep ({e})",
            p.display()
        ))
    })
}

/// The shard folders a `merge` argument stands for: a folder holding `shard-<i>-of-<n>` folders (the `--out`
/// every shard of a cluster job writes into) stands for those folders, in shard order; any other folder or
/// `sweep.json` file stands for itself. Returns the shard folders and, for each argument that was expanded,
/// that folder (the default output of the merge).
pub fn shard_folders(args: &[PathBuf]) -> Result<(Vec<PathBuf>, Vec<PathBuf>)> {
    let mut dirs = Vec::new();
    let mut parents = Vec::new();
    for a in args {
        let mut shards: Vec<(usize, usize, PathBuf)> = Vec::new();
        if a.is_dir() {
            for e in std::fs::read_dir(a).map_err(|e| Error::io(a, e))? {
                let e = e.map_err(|e| Error::io(a, e))?;
                let name = e.file_name().to_string_lossy().into_owned();
                let Some((i, n)) = name
                    .strip_prefix("shard-")
                    .and_then(|r| r.split_once("-of-"))
                    .and_then(|(i, n)| Some((i.parse().ok()?, n.parse().ok()?)))
                else {
                    continue;
                };
                if e.path().join("sweep.json").is_file() {
                    shards.push((n, i, e.path()));
                }
            }
        }
        if shards.is_empty() {
            dirs.push(a.clone());
            continue;
        }
        shards.sort();
        let counts: Vec<usize> = shards.iter().map(|s| s.0).collect();
        if counts.iter().any(|&n| n != counts[0]) {
            return Err(Error::Invalid(format!(
                "{}: holds shards of different splits ({}): name the shard folders of one split, e.g. {}/shard-*-of-{}",
                a.display(),
                shards
                    .iter()
                    .map(|s| format!("shard-{}-of-{}", s.1, s.0))
                    .collect::<Vec<_>>()
                    .join(", "),
                a.display(),
                counts[counts.len() - 1]
            )));
        }
        parents.push(a.clone());
        dirs.extend(shards.into_iter().map(|s| s.2));
    }
    Ok((dirs, parents))
}

/// The first 12 characters of a hash or key from a file, for a message (a short or tampered value is
/// shown as it is, never cut inside a character).
fn short(s: &str) -> String {
    crate::output_policy::escape_control(&s.chars().take(12).collect::<String>())
}

/// Merge shard results; returns the merged result and the warnings (missing cases).
pub fn merge(dirs: &[PathBuf]) -> Result<SweepResult> {
    if dirs.is_empty() {
        return Err(Error::Invalid("merge needs at least one folder".into()));
    }
    let parts: Vec<SweepResult> = dirs.iter().map(|d| read(d)).collect::<Result<_>>()?;
    let first = &parts[0];
    for (d, r) in dirs.iter().zip(&parts).skip(1) {
        if r.tool != first.tool {
            return Err(Error::Invalid(format!(
                "{} was written by {} but {} by {}: shards of different tool versions cannot be merged (run \
                 every shard with one version)",
                d.display(),
                r.tool,
                dirs[0].display(),
                first.tool
            )));
        }
        if r.sweep_hash != first.sweep_hash {
            return Err(Error::Invalid(format!(
                "{} ('{}') and {} ('{}') come from different sweeps (sweep hash {}… vs {}…: the sweep file or \
                 the hull or sea file it names differ): only shards of one sweep can be merged",
                d.display(),
                r.name,
                dirs[0].display(),
                first.name,
                short(&r.sweep_hash),
                short(&first.sweep_hash)
            )));
        }
    }
    for (d, r) in dirs.iter().zip(&parts) {
        if r.total_cases > MAX_CASES || r.total_cases != first.total_cases {
            return Err(Error::Invalid(format!(
                "{}: total_cases = {} {}: the sweep.json is damaged or from another sweep",
                d.display(),
                r.total_cases,
                if r.total_cases > MAX_CASES {
                    format!("is more than a sweep can have ({MAX_CASES})")
                } else {
                    format!(
                        "differs from {} in {}",
                        first.total_cases,
                        dirs[0].display()
                    )
                }
            )));
        }
    }
    // Only the cases present are held (a damaged count never allocates).
    let mut slots: BTreeMap<usize, super::results::CaseResult> = BTreeMap::new();
    for (d, r) in dirs.iter().zip(&parts) {
        for c in &r.cases {
            if c.index >= first.total_cases {
                return Err(Error::Invalid(format!(
                    "{}: case {} (index {}) is outside the sweep's {} cases",
                    d.display(),
                    crate::output_policy::escape_control(&c.id),
                    c.index,
                    first.total_cases
                )));
            }
            match slots.get(&c.index) {
                Some(old) if old.key != c.key => {
                    return Err(Error::Invalid(format!(
                        "{}: case {} differs from the same case in another shard (content key {}… vs {}…)",
                        d.display(),
                        c.id,
                        short(&c.key),
                        short(&old.key)
                    )));
                }
                Some(_) => {}
                None => {
                    slots.insert(c.index, c.clone());
                }
            }
        }
    }
    let missing_count = first.total_cases - slots.len();
    let first_missing = (0..first.total_cases).find(|i| !slots.contains_key(i));
    let cases: Vec<_> = slots.into_values().collect();
    let mut warnings = super::results::warnings_of(&cases);
    if let Some(first_missing) = first_missing {
        warnings.push(format!(
            "{missing_count} of the sweep's {} cases are missing from the shards given (first missing: case \
             index {first_missing}): is a shard missing or unfinished?",
            first.total_cases,
        ));
    }
    Ok(SweepResult {
        tool: first.tool.clone(),
        provenance: first.provenance.clone(),
        sweep_hash: first.sweep_hash.clone(),
        name: first.name.clone(),
        fidelity: first.fidelity.clone(),
        parameters: first.parameters.clone(),
        best: first.best.clone(),
        total_cases: first.total_cases,
        shard: None,
        failed_cases: cases.iter().filter(|c| c.failed.is_some()).count(),
        cases,
        warnings,
    })
}
