//! Joining the results of a sweep's shards (`slamtool merge`). Shards are accepted only when they come
//! from the same sweep (the same `sweep_hash`: the sweep file and the hull and sea files it names) and the
//! same tool version; a case present in two shards must have the same content key in both. The merged
//! result is the one an unsharded run gives (the same cases in the same order, the same tables).

use std::path::{Path, PathBuf};

use super::results::SweepResult;
use crate::error::{Error, Result};

/// Read the `sweep.json` of a shard's folder.
pub fn read(dir: &Path) -> Result<SweepResult> {
    let p = if dir.is_dir() {
        dir.join("sweep.json")
    } else {
        dir.to_path_buf()
    };
    let text = std::fs::read_to_string(&p).map_err(|e| Error::io(&p, e))?;
    serde_json::from_str(&text).map_err(|e| {
        Error::Invalid(format!(
            "{}: not the sweep.json of a slamtool sweep ({e})",
            p.display()
        ))
    })
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
                &r.sweep_hash[..12],
                &first.sweep_hash[..12]
            )));
        }
    }
    let mut slots: Vec<Option<super::results::CaseResult>> = vec![None; first.total_cases];
    for (d, r) in dirs.iter().zip(&parts) {
        for c in &r.cases {
            let slot = slots.get_mut(c.index).ok_or_else(|| {
                Error::Invalid(format!(
                    "{}: case {} is outside the sweep's {} cases",
                    d.display(),
                    c.id,
                    first.total_cases
                ))
            })?;
            match slot {
                Some(old) if old.key != c.key => {
                    return Err(Error::Invalid(format!(
                        "{}: case {} differs from the same case in another shard (content key {}… vs {}…)",
                        d.display(),
                        c.id,
                        &c.key[..12],
                        &old.key[..12]
                    )));
                }
                Some(_) => {}
                None => *slot = Some(c.clone()),
            }
        }
    }
    let missing: Vec<usize> = (0..slots.len()).filter(|&i| slots[i].is_none()).collect();
    let cases: Vec<_> = slots.into_iter().flatten().collect();
    let mut warnings: Vec<String> = Vec::new();
    for c in &cases {
        for w in &c.warnings {
            if !warnings.contains(w) {
                warnings.push(w.clone());
            }
        }
    }
    if !missing.is_empty() {
        warnings.push(format!(
            "{} of the sweep's {} cases are missing from the shards given (first missing: case index {}): \
             is a shard missing or unfinished?",
            missing.len(),
            first.total_cases,
            missing[0]
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
