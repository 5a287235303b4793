//! The output folder of a run, checked before anything is computed: it must be a folder (or creatable
//! as one) that can be written to, and the files of an earlier run in it are removed first, so that
//! stale frames or convergence companions never mix with the new ones.

use std::path::Path;

use crate::error::{Error, Result};

/// Files a run writes directly in its folder.
const RUN_FILES: [&str; 6] = [
    "peak_pressure.png",
    "summary.json",
    "history.csv",
    "convergence.csv",
    "particles.pvd",
    "setup.json",
];

/// Whether `name` is a snapshot a run writes (`particles_0003.vtu`, `frame_0003.png`).
fn is_snapshot(name: &str) -> bool {
    (name.starts_with("particles_") && name.ends_with(".vtu"))
        || (name.starts_with("frame_") && name.ends_with(".png"))
}

/// Make `dir` ready for a run: create it, check that it can be written to, and remove the outputs of an
/// earlier run (and nothing else). Returns how many earlier files were removed.
pub fn prepare(dir: &Path) -> Result<usize> {
    if dir.exists() && !dir.is_dir() {
        return Err(Error::Invalid(format!(
            "the output folder {} is a file, not a folder",
            dir.display()
        )));
    }
    std::fs::create_dir_all(dir).map_err(|e| Error::io(dir, e))?;
    let probe = dir.join(format!(".slamtool-write-test-{}", std::process::id()));
    std::fs::write(&probe, b"").map_err(|e| Error::io(dir, e))?;
    let _ = std::fs::remove_file(&probe);
    let mut removed = 0;
    for entry in std::fs::read_dir(dir).map_err(|e| Error::io(dir, e))? {
        let entry = entry.map_err(|e| Error::io(dir, e))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        let path = entry.path();
        if path.is_file() && (RUN_FILES.contains(&name.as_str()) || is_snapshot(&name)) {
            std::fs::remove_file(&path).map_err(|e| Error::io(&path, e))?;
            removed += 1;
        } else if path.is_dir() && name == "convergence" {
            std::fs::remove_dir_all(&path).map_err(|e| Error::io(&path, e))?;
            removed += 1;
        }
    }
    Ok(removed)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_file_is_refused_and_earlier_outputs_are_cleared() {
        let d = tempfile::tempdir().unwrap();
        let f = d.path().join("x");
        std::fs::write(&f, "x").unwrap();
        assert!(prepare(&f).unwrap_err().to_string().contains("is a file"));
        let out = d.path().join("run");
        std::fs::create_dir_all(out.join("convergence/dp_1mm")).unwrap();
        for n in [
            "summary.json",
            "frame_0007.png",
            "particles_0001.vtu",
            "notes.txt",
        ] {
            std::fs::write(out.join(n), "x").unwrap();
        }
        assert_eq!(prepare(&out).unwrap(), 4);
        let left: Vec<String> = std::fs::read_dir(&out)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        assert_eq!(left, vec!["notes.txt".to_string()]);
    }
}
