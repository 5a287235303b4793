//! The SHA-256 of the sources that determine an SPH run and the record the assessment keeps of it, for
//! the run cache's key ([`crate::assess::cache`]). `build.rs` compiles this same file (`#[path]`) and
//! sets `SLAMTOOL_SOLVER_SOURCES_SHA256` from it, so the hash the binary carries and the function the
//! tests exercise are one implementation.
//!
//! Only the solver's own sources are hashed, not the git commit: a commit that changes the report, the
//! command line or the documentation keeps the committed cache valid, while any edit of a file listed in
//! [`SOLVER_SOURCES`] (a constant of the SPH scheme, a filter, an analytic model the run's filter rule
//! uses, the code that turns a run into its record) makes every earlier entry miss. Dependency versions
//! (`Cargo.lock`) are not hashed, because unrelated dev-dependencies change that file; a change of a
//! numerical dependency must bump `RECORD_FORMAT` by hand.

use std::path::{Path, PathBuf};

use sha2::{Digest, Sha256};

/// Files and folders (relative to the crate root, folders taken recursively) whose content determines an
/// SPH run of an assessment and its cache record: the SPH solver, the load post-processing (peaks,
/// filters, convergence verdicts), the analytic models and numerics the run's setup and filter rule use,
/// the impact sensors, and the assessment code that keys, runs and records a run.
pub const SOLVER_SOURCES: &[&str] = &[
    "src/sph",
    "src/loads",
    "src/analytic",
    "src/numerics",
    "src/impact",
    "src/source_hash.rs",
    "src/assess/cache.rs",
    "src/assess/execute.rs",
    "src/assess/results.rs",
];

/// The files under `paths` (relative to `root`; a missing path is an error), recursively, as paths
/// relative to `root` with `/` separators, in sorted order.
pub fn source_files(root: &Path, paths: &[&str]) -> std::io::Result<Vec<String>> {
    fn walk(dir: &Path, out: &mut Vec<PathBuf>) -> std::io::Result<()> {
        for e in std::fs::read_dir(dir)? {
            let p = e?.path();
            if p.is_dir() {
                walk(&p, out)?;
            } else {
                out.push(p);
            }
        }
        Ok(())
    }
    let mut found = Vec::new();
    for rel in paths {
        let p = root.join(rel);
        if p.is_dir() {
            walk(&p, &mut found)?;
        } else if p.is_file() {
            found.push(p);
        } else {
            return Err(std::io::Error::new(
                std::io::ErrorKind::NotFound,
                format!("solver source {} not found", p.display()),
            ));
        }
    }
    let mut rel: Vec<String> = found
        .iter()
        .filter_map(|p| p.strip_prefix(root).ok())
        .map(|p| {
            p.components()
                .map(|c| c.as_os_str().to_string_lossy().into_owned())
                .collect::<Vec<_>>()
                .join("/")
        })
        .collect();
    rel.sort();
    rel.dedup();
    Ok(rel)
}

/// Lower-case hex SHA-256 over the files under `paths`: for each file in sorted order its relative
/// path, a zero byte, its length and its content with CRLF line ends read as LF (so that a Windows
/// checkout of the same commit gives the same hash).
pub fn source_hash(root: &Path, paths: &[&str]) -> std::io::Result<String> {
    let mut h = Sha256::new();
    for rel in source_files(root, paths)? {
        let bytes = std::fs::read(root.join(&rel))?;
        let mut text = Vec::with_capacity(bytes.len());
        for (i, &b) in bytes.iter().enumerate() {
            if !(b == b'\r' && bytes.get(i + 1) == Some(&b'\n')) {
                text.push(b);
            }
        }
        h.update(rel.as_bytes());
        h.update([0u8]);
        h.update((text.len() as u64).to_le_bytes());
        h.update(&text);
    }
    Ok(h.finalize().iter().map(|b| format!("{b:02x}")).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn tree(files: &[(&str, &str)]) -> tempfile::TempDir {
        let d = tempfile::tempdir().unwrap();
        for (rel, text) in files {
            let p = d.path().join(rel);
            std::fs::create_dir_all(p.parent().unwrap()).unwrap();
            std::fs::write(p, text).unwrap();
        }
        d
    }

    const SOLVER: &[&str] = &["src/sph", "src/loads/peaks.rs"];

    #[test]
    fn a_changed_solver_constant_changes_the_hash_and_other_files_do_not() {
        let d = tree(&[
            ("src/sph/eos.rs", "pub const GAMMA: f64 = 7.0;\n"),
            ("src/sph/kernel/mod.rs", "pub fn w() {}\n"),
            ("src/loads/peaks.rs", "pub fn peak() {}\n"),
            ("src/report/mod.rs", "pub fn page() {}\n"),
        ]);
        let before = source_hash(d.path(), SOLVER).unwrap();
        assert_eq!(before.len(), 64);
        assert_eq!(before, source_hash(d.path(), SOLVER).unwrap(), "stable");
        // An unrelated file: the hash stays.
        std::fs::write(d.path().join("src/report/mod.rs"), "pub fn page2() {}\n").unwrap();
        assert_eq!(before, source_hash(d.path(), SOLVER).unwrap());
        // A solver constant: the hash moves.
        let eos = d.path().join("src/sph/eos.rs");
        std::fs::write(&eos, "pub const GAMMA: f64 = 7.1;\n").unwrap();
        let changed = source_hash(d.path(), SOLVER).unwrap();
        assert_ne!(before, changed);
        // A file nested deeper, and a new file, count too; CRLF line ends do not.
        std::fs::write(&eos, "pub const GAMMA: f64 = 7.1;\r\n").unwrap();
        assert_eq!(changed, source_hash(d.path(), SOLVER).unwrap(), "CRLF");
        std::fs::write(d.path().join("src/sph/kernel/new.rs"), "").unwrap();
        assert_ne!(changed, source_hash(d.path(), SOLVER).unwrap(), "new file");
    }

    #[test]
    fn a_moved_file_changes_the_hash_and_a_missing_source_is_an_error() {
        let a = tree(&[("src/sph/a.rs", "x"), ("src/loads/peaks.rs", "")]);
        let b = tree(&[("src/sph/b.rs", "x"), ("src/loads/peaks.rs", "")]);
        assert_ne!(
            source_hash(a.path(), SOLVER).unwrap(),
            source_hash(b.path(), SOLVER).unwrap()
        );
        let c = tree(&[("src/sph/a.rs", "x")]);
        let err = source_hash(c.path(), SOLVER).unwrap_err().to_string();
        assert!(
            err.contains("peaks.rs") && err.contains("not found"),
            "{err}"
        );
    }

    #[test]
    fn the_hash_compiled_in_is_the_hash_of_the_solver_sources_of_this_tree() {
        let root = Path::new(env!("CARGO_MANIFEST_DIR"));
        assert_eq!(
            source_hash(root, SOLVER_SOURCES).unwrap(),
            env!("SLAMTOOL_SOLVER_SOURCES_SHA256")
        );
        let files = source_files(root, SOLVER_SOURCES).unwrap();
        assert!(files.contains(&"src/sph/eos.rs".to_string()), "{files:?}");
    }
}
