//! Where a result came from: tool version, the SHA-256 of every input file, and all settings. Every result
//! file slamtool writes carries one of these (as a JSON object, or as `#` comment lines at the top of a CSV).

use std::path::Path;

use serde::Serialize;
use sha2::{Digest, Sha256};

use crate::error::{Error, Result};

/// One input file and its content hash.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct InputFile {
    pub path: String,
    pub sha256: String,
}

/// Provenance of a result.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Provenance {
    pub tool: String,
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
                path: p.display().to_string(),
                sha256: sha256_hex(&bytes),
            });
        }
        Ok(Self {
            tool: concat!("slamtool ", env!("CARGO_PKG_VERSION")).to_string(),
            inputs: files,
            settings,
        })
    }

    /// The provenance as `# ` comment lines, for the head of a CSV file.
    pub fn csv_header(&self) -> String {
        let mut s = format!("# {}\n", self.tool);
        for f in &self.inputs {
            s += &format!("# input {} sha256 {}\n", f.path, f.sha256);
        }
        s += &format!("# settings {}\n", self.settings);
        s
    }
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
    fn sha256_of_abc() {
        assert_eq!(
            sha256_hex(b"abc"),
            "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad"
        );
    }
}
