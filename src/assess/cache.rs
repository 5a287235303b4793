//! The run cache of an assessment: each SPH run is keyed by the SHA-256 of a canonical JSON of everything
//! that determines it (the resolved setup: section polyline, entry-velocity table, sensors and numerics;
//! the convergence plan; the SHA-256 of the solver sources the build was made from,
//! [`crate::provenance::SOLVER_SOURCES_SHA256`]; the record format), and lives in `OUT/cache/<key>/`
//! with its `summary.json`, `history.csv`, convergence companions and the assessment's record of it
//! (`event.json`, written last). A run is written into a temporary folder and renamed into place when
//! complete, so an assessment that is killed (even with SIGKILL) leaves either a finished entry or
//! nothing, and resumes where it stopped.
//!
//! The tool version (`0.1.0`) is not what determines a run: a changed solver keeps it. The solver
//! sources' hash is, so a build whose SPH scheme, filters or record code differ never reuses a run of
//! another, while a commit that touches only reports or the command line keeps the cache.
//!
//! Each record carries the SHA-256 of its own text (`event.json`: `{"sha256": ..., "record": ...}`),
//! checked on reuse: a record edited by hand, or damaged, is recomputed, and the assessment says so.

use std::path::{Path, PathBuf};

use serde::Serialize;

use crate::error::{Error, Result};
use crate::provenance::{SOLVER_SOURCES_SHA256, sha256_hex};
use crate::sph::{Setup, StudyPlan};

use super::results::SphRecord;

/// The record of a run inside its cache entry.
pub const RECORD: &str = "event.json";

/// Version of what a cache entry's record holds and means; part of every key, so that a change to the
/// record makes earlier entries miss instead of being read with defaults. 2: sensors carry `wetted` and
/// `still_rising`; 3: the key holds the solver sources' hash, and the record its own checksum.
pub const RECORD_FORMAT: u32 = 3;

/// The cache key of a run made by this build.
pub fn key(setup: &Setup, study: &StudyPlan) -> Result<String> {
    key_with(setup, study, SOLVER_SOURCES_SHA256)
}

/// The cache key of a run of `setup` and `study` by a build whose solver sources hash to
/// `solver_sources` (the record format is always this build's).
pub fn key_with(
    setup: &impl Serialize,
    study: &impl Serialize,
    solver_sources: &str,
) -> Result<String> {
    let canonical = serde_json::to_string(&serde_json::json!({
        "solver_sources_sha256": solver_sources,
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

/// What a finished entry's `event.json` gives on reuse.
#[derive(Debug)]
pub enum Stored {
    /// No entry, or no record in it (a run not finished): computed as usual, nothing to say.
    Missing,
    /// The record, its checksum verified.
    Verified(Box<SphRecord>),
    /// A record whose checksum or format does not hold: it is recomputed, and this says why.
    Rejected(String),
}

/// The text of `event.json` for a record: its SHA-256 on the first line, then the record's own text,
/// which is what the checksum covers byte for byte.
fn stored_text(record: &impl Serialize) -> Result<String> {
    let body = serde_json::to_string_pretty(record)
        .map_err(|e| Error::Invalid(format!("cache record: {e}")))?;
    Ok(format!(
        "{{\n  \"sha256\": \"{}\",\n  \"record\": {body}\n}}\n",
        sha256_hex(body.as_bytes())
    ))
}

/// Read `event.json`'s text: the record if its checksum holds, else why not.
fn verify<T: serde::de::DeserializeOwned>(text: &str) -> std::result::Result<T, String> {
    let head: serde_json::Value =
        serde_json::from_str(text).map_err(|e| format!("it is not valid JSON ({e})"))?;
    let Some(want) = head.get("sha256").and_then(|v| v.as_str()) else {
        return Err("it carries no checksum (written by an earlier version)".into());
    };
    const MARK: &str = "\n  \"record\": ";
    let body = text
        .find(MARK)
        .map(|i| &text[i + MARK.len()..])
        .and_then(|rest| rest.trim_end().strip_suffix('}'))
        .map(str::trim_end)
        .ok_or_else(|| "its layout is not the one this tool writes".to_string())?;
    let got = sha256_hex(body.as_bytes());
    if got != want {
        return Err(format!(
            "its content does not match its checksum (sha256 {}…, stored {}…): it was edited or damaged",
            &got[..12],
            want.chars()
                .take(12)
                .filter(char::is_ascii_hexdigit)
                .collect::<String>()
        ));
    }
    serde_json::from_str(body).map_err(|e| format!("its record cannot be read ({e})"))
}

/// A finished entry's record, verified against its checksum.
pub fn load(out: &Path, key: &str) -> Stored {
    let path = entry(out, key).join(RECORD);
    let Ok(text) = std::fs::read_to_string(&path) else {
        return Stored::Missing;
    };
    match verify(&text) {
        Ok(r) => Stored::Verified(Box::new(r)),
        Err(why) => Stored::Rejected(format!(
            "cache record {} is not reused: {why}; the run is computed again",
            path.display()
        )),
    }
}

/// A finished entry's record, if there is one whose checksum holds.
pub fn lookup(out: &Path, key: &str) -> Option<SphRecord> {
    match load(out, key) {
        Stored::Verified(r) => Some(*r),
        _ => None,
    }
}

/// Why a finished entry of `key` is not reused, if it exists and fails its check.
pub fn rejection(out: &Path, key: &str) -> Option<String> {
    match load(out, key) {
        Stored::Rejected(why) => Some(why),
        _ => None,
    }
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
pub fn commit(out: &Path, key: &str, tmp: &Path, record: &impl Serialize) -> Result<()> {
    crate::files::write_text_atomic(&tmp.join(RECORD), &stored_text(record)?)?;
    let _ = std::fs::remove_dir_all(failed_dir(out, key));
    let dest = entry(out, key);
    if dest.exists() {
        std::fs::remove_dir_all(&dest).map_err(|e| Error::io(&dest, e))?;
    }
    std::fs::rename(tmp, &dest).map_err(|e| Error::io(&dest, e))
}

/// The folder kept for the histories of the failed run of `key`: hidden (a dot name), so it is never
/// read as a cache entry, reported as unused or pruned; replaced by the next failure of the same key and
/// removed when the key's run succeeds.
pub fn failed_dir(out: &Path, key: &str) -> PathBuf {
    out.join("cache").join(format!(".failed-{key}"))
}

/// Keep what a failed run of `key` wrote in its temporary folder `tmp` (its histories up to the stop and
/// its summary) under [`failed_dir`], and name that folder in the error instead of the temporary one, which
/// the next assessment sweeps away. If the move fails, the temporary folder is removed and the error says
/// that nothing was kept.
pub fn keep_failed(out: &Path, key: &str, tmp: &Path, err: Error) -> Error {
    let kept = failed_dir(out, key);
    let _ = std::fs::remove_dir_all(&kept);
    let moved = std::fs::rename(tmp, &kept).is_ok();
    if !moved {
        let _ = std::fs::remove_dir_all(tmp);
    }
    let from = crate::sph::histories_kept_in(tmp);
    let to = if moved {
        crate::sph::histories_kept_in(&kept)
    } else {
        "; its histories could not be kept".to_string()
    };
    let name = |m: String| m.replace(&from, &to);
    match err {
        Error::Numerical(m) => Error::Numerical(name(m)),
        Error::Invalid(m) => Error::Invalid(name(m)),
        other => other,
    }
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
    fn another_solver_gives_another_key() {
        let setup = serde_json::json!({"section": [[0.0, 0.0], [0.1, 0.05]], "c0": 40.0});
        let study = StudyPlan::default();
        let a = key_with(&setup, &study, "aaaa").unwrap();
        assert_eq!(
            a,
            key_with(&setup, &study, "aaaa").unwrap(),
            "deterministic"
        );
        assert_ne!(
            a,
            key_with(&setup, &study, "aaab").unwrap(),
            "solver sources"
        );
        let other = serde_json::json!({"section": [[0.0, 0.0], [0.1, 0.05]], "c0": 41.0});
        assert_ne!(a, key_with(&other, &study, "aaaa").unwrap(), "setup");
        assert_eq!(a.len(), 64);
    }

    #[test]
    fn a_record_is_reused_only_while_its_checksum_holds() {
        let record =
            serde_json::json!({"key": "k", "force_peak_n_per_m": 3300.5, "sensors": [1.25e3]});
        let text = stored_text(&record).unwrap();
        let head: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(
            head["record"], record,
            "event.json is JSON holding the record"
        );
        assert_eq!(verify::<serde_json::Value>(&text), Ok(record.clone()));
        // A well-formed number changed by hand.
        let tampered = text.replace("3300.5", "330050.0");
        let why = verify::<serde_json::Value>(&tampered).unwrap_err();
        assert!(why.contains("does not match its checksum"), "{why}");
        // A record of an earlier format (no checksum), and one that is not JSON.
        let why = verify::<serde_json::Value>(&record.to_string()).unwrap_err();
        assert!(why.contains("no checksum"), "{why}");
        assert!(verify::<serde_json::Value>("{\"sha256\": ").is_err());
        // Through the cache folder: the entry is rejected with a message naming the file.
        let out = tempfile::tempdir().unwrap();
        std::fs::create_dir_all(entry(out.path(), "k")).unwrap();
        std::fs::write(entry(out.path(), "k").join(RECORD), &tampered).unwrap();
        let note = rejection(out.path(), "k").unwrap();
        assert!(
            note.contains("event.json") && note.contains("computed again"),
            "{note}"
        );
        assert!(lookup(out.path(), "k").is_none());
        assert!(
            rejection(out.path(), "none").is_none(),
            "a missing entry is no rejection"
        );
    }

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

    /// A failed run's histories stay under `.failed-<key>`, the error names that folder, the sweep of
    /// temporary folders and the pruning of unused entries leave it, and the key's next successful run
    /// removes it.
    #[test]
    fn a_failed_run_keeps_its_histories_where_the_error_says() {
        let out =
            std::env::temp_dir().join(format!("slamtool-cache-failed-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&out);
        let tmp = temporary(&out, "kkk").unwrap();
        std::fs::write(tmp.join("history.csv"), "t,p\n0,1\n").unwrap();
        let err = Error::Numerical(format!(
            "SPH run 'x' stopped at t = 0.1 s: diverged{}",
            crate::sph::histories_kept_in(&tmp)
        ));
        let err = keep_failed(&out, "kkk", &tmp, err).to_string();
        let kept = failed_dir(&out, "kkk");
        assert!(err.contains(&kept.display().to_string()), "{err}");
        assert!(kept.join("history.csv").is_file() && !tmp.exists());
        sweep(&out);
        let used: std::collections::BTreeSet<String> = std::collections::BTreeSet::new();
        assert_eq!(tidy(&out, &used, Unused::Prune).unwrap(), None);
        assert!(kept.join("history.csv").is_file());
        let tmp = temporary(&out, "kkk").unwrap();
        commit(&out, "kkk", &tmp, &serde_json::json!({"key": "kkk"})).unwrap();
        assert!(!kept.exists() && entry(&out, "kkk").exists());
        std::fs::remove_dir_all(&out).unwrap();
    }
}
