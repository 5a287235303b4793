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
