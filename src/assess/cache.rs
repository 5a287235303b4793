//! The run cache of an assessment: each SPH run is keyed by the SHA-256 of a canonical JSON of everything
//! that determines it (the resolved setup: section polyline, entry-velocity table, sensors and numerics;
//! the convergence plan; the tool version), and lives in `OUT/cache/<key>/` with its `summary.json`,
//! `history.csv`, convergence companions and the assessment's record of it (`event.json`, written last).
//! A run is written into a temporary folder and renamed into place when complete, so an assessment that
//! is killed (even with SIGKILL) leaves either a finished entry or nothing, and resumes where it stopped.

use std::path::{Path, PathBuf};

use crate::error::{Error, Result};
use crate::provenance::{TOOL, sha256_hex};
use crate::sph::{Setup, StudyPlan};

use super::results::SphRecord;

/// The record of a run inside its cache entry.
pub const RECORD: &str = "event.json";

/// Version of what a cache entry's record holds and means; part of every key, so that a change to the
/// record (2: sensors carry `wetted` and `still_rising`) makes earlier entries miss instead of being
/// read with defaults.
pub const RECORD_FORMAT: u32 = 2;

/// The cache key of a run.
pub fn key(setup: &Setup, study: &StudyPlan) -> Result<String> {
    let canonical = serde_json::to_string(&serde_json::json!({
        "tool": TOOL,
        "record_format": RECORD_FORMAT,
        "setup": setup,
        "study": study,
    }))
    .map_err(|e| Error::Invalid(format!("cache key: {e}")))?;
    Ok(sha256_hex(canonical.as_bytes()))
}

/// The folder of an entry.
pub fn entry(out: &Path, key: &str) -> PathBuf {
    out.join("cache").join(key)
}

/// A finished entry's record, if there is one that can be read.
pub fn lookup(out: &Path, key: &str) -> Option<SphRecord> {
    let text = std::fs::read_to_string(entry(out, key).join(RECORD)).ok()?;
    serde_json::from_str(&text).ok()
}

/// A fresh temporary folder for the run of `key` (left-overs of a killed run removed).
pub fn temporary(out: &Path, key: &str) -> Result<PathBuf> {
    let tmp = out
        .join("cache")
        .join(format!(".tmp-{key}-{}", std::process::id()));
    if tmp.exists() {
        std::fs::remove_dir_all(&tmp).map_err(|e| Error::io(&tmp, e))?;
    }
    std::fs::create_dir_all(&tmp).map_err(|e| Error::io(&tmp, e))?;
    Ok(tmp)
}

/// Complete an entry: write the record into the temporary folder, then rename it into place (replacing an
/// earlier entry of the same key).
pub fn commit(out: &Path, key: &str, tmp: &Path, record: &SphRecord) -> Result<()> {
    let json = serde_json::to_string_pretty(record)
        .map_err(|e| Error::Invalid(format!("cache record: {e}")))?;
    crate::files::write_text_atomic(&tmp.join(RECORD), &json)?;
    let dest = entry(out, key);
    if dest.exists() {
        std::fs::remove_dir_all(&dest).map_err(|e| Error::io(&dest, e))?;
    }
    std::fs::rename(tmp, &dest).map_err(|e| Error::io(&dest, e))
}

/// Remove the temporary folders that killed runs left behind.
pub fn sweep(out: &Path) {
    let Ok(dir) = std::fs::read_dir(out.join("cache")) else {
        return;
    };
    for e in dir.flatten() {
        if e.file_name().to_string_lossy().starts_with(".tmp-") {
            let _ = std::fs::remove_dir_all(e.path());
        }
    }
}

/// What an assessment does with the cache entries it did not use.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Unused {
    /// Count them in a note (the command line without `--prune-cache`).
    Report,
    /// Remove them (`--prune-cache`).
    Prune,
    /// Leave them unlooked at: a sweep's variants share one cache and run silently, so each variant
    /// would walk the others' entries for a note nobody sees.
    Ignore,
}

/// The finished entries of the cache of `out` whose key is not in `used`, as (folder, size in bytes).
pub fn unused(out: &Path, used: &std::collections::BTreeSet<String>) -> Vec<(PathBuf, u64)> {
    let Ok(dir) = std::fs::read_dir(out.join("cache")) else {
        return Vec::new();
    };
    let mut found: Vec<(PathBuf, u64)> = dir
        .flatten()
        .filter(|e| e.path().is_dir())
        .filter(|e| {
            let name = e.file_name().to_string_lossy().into_owned();
            !name.starts_with('.') && !used.contains(&name)
        })
        .map(|e| (e.path(), size_of(&e.path())))
        .collect();
    found.sort();
    found
}

/// Bytes in the files under `dir`.
fn size_of(dir: &Path) -> u64 {
    std::fs::read_dir(dir).map_or(0, |d| {
        d.flatten()
            .map(|e| match e.file_type() {
                Ok(t) if t.is_dir() => size_of(&e.path()),
                _ => e.metadata().map_or(0, |m| m.len()),
            })
            .sum()
    })
}

/// Deal with the entries the assessment did not use as `mode` says. Returns the note for the user, if there
/// is anything to say.
pub fn tidy(
    out: &Path,
    used: &std::collections::BTreeSet<String>,
    mode: Unused,
) -> Result<Option<String>> {
    if mode == Unused::Ignore {
        return Ok(None);
    }
    let unused = unused(out, used);
    if unused.is_empty() {
        return Ok(None);
    }
    let bytes: u64 = unused.iter().map(|u| u.1).sum();
    let size = format!("{:.1} MB", bytes as f64 / 1e6);
    if mode == Unused::Prune {
        for (dir, _) in &unused {
            std::fs::remove_dir_all(dir).map_err(|e| Error::io(dir, e))?;
        }
        return Ok(Some(format!(
            "removed {} this assessment did not use ({size})",
            entries(unused.len())
        )));
    }
    Ok(Some(format!(
        "{} ({size}) in {} {} not used by this assessment (other stations, speeds, numerics or tool \
         versions); --prune-cache removes them",
        entries(unused.len()),
        out.join("cache").display(),
        if unused.len() == 1 { "was" } else { "were" }
    )))
}

/// "1 cache entry", "2 cache entries".
fn entries(n: usize) -> String {
    if n == 1 {
        "1 cache entry".to_string()
    } else {
        format!("{n} cache entries")
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn entries_the_assessment_did_not_use_are_counted_and_pruned_only_when_asked() {
        let out = std::env::temp_dir().join(format!("slamtool-cache-tidy-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&out);
        for k in ["aaa", "bbb", ".tmp-ccc-1"] {
            std::fs::create_dir_all(out.join("cache").join(k)).unwrap();
            std::fs::write(out.join("cache").join(k).join(RECORD), "0123456789").unwrap();
        }
        let used: std::collections::BTreeSet<String> = ["aaa".to_string()].into();
        let note = tidy(&out, &used, Unused::Report).unwrap().unwrap();
        assert!(note.starts_with("1 cache entry (0.0 MB)"), "{note}");
        assert!(out.join("cache/bbb").exists());
        let note = tidy(&out, &used, Unused::Prune).unwrap().unwrap();
        assert!(note.starts_with("removed 1 cache entry"), "{note}");
        assert!(!out.join("cache/bbb").exists());
        assert!(out.join("cache/aaa").exists());
        assert_eq!(tidy(&out, &used, Unused::Prune).unwrap(), None);
        std::fs::create_dir_all(out.join("cache/ddd")).unwrap();
        assert_eq!(tidy(&out, &used, Unused::Ignore).unwrap(), None);
        assert!(out.join("cache/ddd").exists());
        std::fs::remove_dir_all(&out).unwrap();
    }
}
