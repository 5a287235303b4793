//! Where a result came from: tool version, the git commit it was built from, the SHA-256 of every input
//! file, and all settings. Every result file slamtool writes carries one of these (as a JSON object, or as
//! `#` comment lines at the top of a CSV).

use std::path::Path;

use serde::Serialize;
use sha2::{Digest, Sha256};

use crate::error::{Error, Result};

/// "slamtool" and the version of this build.
pub const TOOL: &str = concat!("slamtool ", env!("CARGO_PKG_VERSION"));

/// The git commit this build was made from, or "unknown" (set by `build.rs`).
pub const GIT_COMMIT: &str = env!("SLAMTOOL_GIT_COMMIT");

#[path = "source_hash.rs"]
pub mod source_hash;

/// SHA-256 of the solver sources this build was made from ([`source_hash::SOLVER_SOURCES`], set by
/// `build.rs` with [`source_hash::source_hash`]): part of the run cache's key.
pub const SOLVER_SOURCES_SHA256: &str = env!("SLAMTOOL_SOLVER_SOURCES_SHA256");

/// Round every number in `v` to 10 significant digits, so that values computed from round inputs print
/// as such (`0.093`, not `0.09299999999999999`).
pub fn tidy_numbers(v: serde_json::Value) -> serde_json::Value {
    use serde_json::Value;
    match v {
        Value::Number(n) if !(n.is_i64() || n.is_u64()) => n
            .as_f64()
            .and_then(|x| format!("{x:.9e}").parse::<f64>().ok())
            .and_then(serde_json::Number::from_f64)
            .map_or(Value::Number(n), Value::Number),
        Value::Array(a) => Value::Array(a.into_iter().map(tidy_numbers).collect()),
        Value::Object(o) => {
            Value::Object(o.into_iter().map(|(k, x)| (k, tidy_numbers(x))).collect())
        }
        other => other,
    }
}

/// One input file and its content hash.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InputFile {
    pub path: String,
    pub sha256: String,
}

/// Provenance of a result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Provenance {
    /// "slamtool" and its version.
    pub tool: String,
    /// The git commit the tool was built from, with "-modified" when the sources differed from it
    /// ("unknown" for a build outside a git checkout).
    pub commit: String,
    pub inputs: Vec<InputFile>,
    pub settings: serde_json::Value,
}

impl Provenance {
    /// Hash the given input files and record the settings.
    pub fn new(inputs: &[&Path], settings: serde_json::Value) -> Result<Self> {
        let mut files = Vec::with_capacity(inputs.len());
        for p in inputs {
            let bytes = std::fs::read(p).map_err(|e| Error::io(p, e))?;
            files.push(InputFile {
                path: lexically_normal(p).display().to_string(),
                sha256: sha256_hex(&bytes),
            });
        }
        Ok(Self {
            tool: TOOL.to_string(),
            commit: GIT_COMMIT.to_string(),
            inputs: files,
            settings: tidy_numbers(settings),
        })
    }

    /// The provenance as `# ` comment lines, for the head of a CSV file.
    pub fn csv_header(&self) -> String {
        let mut s = format!("# {}\n# commit {}\n", self.tool, self.commit);
        for f in &self.inputs {
            s += &format!("# input {} sha256 {}\n", f.path, f.sha256);
        }
        s += &format!("# settings {}\n", self.settings);
        s
    }
}

/// A path with its `.` components dropped and each `name/..` pair removed, without touching the file
/// system (so `validation/../data/x.toml` is named `data/x.toml`; a leading `..` stays). Provenance names
/// a file the way a reader would look for it.
pub fn lexically_normal(p: &Path) -> std::path::PathBuf {
    use std::path::Component;
    let mut out: Vec<Component> = Vec::new();
    for c in p.components() {
        match c {
            Component::CurDir => {}
            Component::ParentDir => match out.last() {
                Some(Component::Normal(_)) => {
                    out.pop();
                }
                Some(Component::RootDir | Component::Prefix(_)) => {}
                _ => out.push(c),
            },
            _ => out.push(c),
        }
    }
    if out.is_empty() {
        return std::path::PathBuf::from(".");
    }
    out.iter().collect()
}

/// Lower-case hex SHA-256 of some bytes.
pub fn sha256_hex(bytes: &[u8]) -> String {
    Sha256::digest(bytes)
        .iter()
        .map(|b| format!("{b:02x}"))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn settings_lose_float_noise() {
        let v = tidy_numbers(
            serde_json::json!({"a": [0.1 + 0.2, 3], "b": 0.093_f64 * 1.0000000000000002}),
        );
        assert_eq!(v.to_string(), r#"{"a":[0.3,3],"b":0.093}"#);
    }

    #[test]
    fn sha256_of_abc() {
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
    }

    #[test]
    fn paths_are_named_without_dot_dot() {
        let n = |s: &str| lexically_normal(Path::new(s)).display().to_string();
        assert_eq!(n("validation/../data/x.toml"), "data/x.toml");
        assert_eq!(n("./a/./b/../c"), "a/c");
        assert_eq!(n("../shared/r.toml"), "../shared/r.toml");
        assert_eq!(n("a/.."), ".");
        assert_eq!(n("/x/../y"), "/y");
    }
}
