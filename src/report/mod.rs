//! Reports: the results of a pipeline step written out for people (text tables) and for plots (CSV with a
//! provenance header). The analysis modules compute; this module only formats, and the CLI only calls it.

pub mod assessment;
pub mod document;
pub mod figure;
pub mod motions_csv;
pub mod motions_text;
pub mod sanity;

use std::path::Path;

use crate::error::{Error, Result};
use crate::provenance::Provenance;

/// One CSV output: file name, column names, notes and rows (already formatted).
#[derive(Debug, Clone, PartialEq)]
pub struct CsvTable {
    pub file_name: &'static str,
    pub header: &'static [&'static str],
    /// What empty fields or an empty table mean, and any warnings; written as `# note` lines.
    pub notes: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

impl CsvTable {
    /// The table as CSV text, headed by the provenance and the notes as `#` comment lines. Fields are
    /// quoted where needed (names come from users).
    pub fn to_text(&self, prov: &Provenance) -> Result<String> {
        let err = |e: &dyn std::fmt::Display| Error::Invalid(e.to_string());
        let mut w = csv::Writer::from_writer(Vec::new());
        w.write_record(self.header).map_err(|e| err(&e))?;
        for r in &self.rows {
            w.write_record(r).map_err(|e| err(&e))?;
        }
        let body = w.into_inner().map_err(|e| err(&e))?;
        let mut head = prov.csv_header();
        for n in &self.notes {
            for line in n.lines() {
                head += &format!("# note {line}\n");
            }
        }
        Ok(head + &String::from_utf8_lossy(&body))
    }
}

/// Write each table to `dir/<file_name>` (atomically, creating `dir` if needed); returns the paths.
pub fn write_csv_tables(
    dir: &Path,
    tables: &[CsvTable],
    prov: &Provenance,
) -> Result<Vec<std::path::PathBuf>> {
    let mut written = Vec::new();
    for t in tables {
        let path = dir.join(t.file_name);
        crate::files::write_text_atomic(&path, &t.to_text(prov)?)?;
        written.push(path);
    }
    Ok(written)
}

/// A mass in kg for text reports, in tonnes as well when it is large ("7070.6 t (7.0706e6 kg)").
pub fn mass_text(kg: f64) -> String {
    if kg.abs() >= 1e4 {
        format!("{:.1} t ({kg:.4e} kg)", kg * 1e-3)
    } else {
        format!("{kg:.3} kg")
    }
}

/// The number format of every CSV value: six significant digits after the point, exponent form.
pub fn csv_number(v: f64) -> String {
    format!("{v:.6e}")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csv_table_text_has_provenance_header_columns_and_quoted_fields() {
        let prov = Provenance {
            tool: "slamtool test".into(),
            commit: "abc".into(),
            inputs: vec![],
            settings: serde_json::json!({"a": 1}),
        };
        let t = CsvTable {
            file_name: "t.csv",
            header: &["name", "value"],
            notes: vec!["empty: none".into()],
            rows: vec![
                vec!["wave, long".into(), csv_number(1.5)],
                vec!["b".into(), csv_number(-0.000125)],
            ],
        };
        assert_eq!(
            t.to_text(&prov).unwrap(),
            "# slamtool test\n# commit abc\n# settings {\"a\":1}\n# note empty: none\nname,value\n\"wave, long\",1.500000e0\nb,-1.250000e-4\n"
        );
    }
}
