//! The relative-motion record of a station as a CSV file.
//!
//! ```text
//! # source: Hermundstad & Moan (2005) basin test, optical gauge at 0.05 Lpp
//! # sampling: 500 Hz; filter: none
//! time [s], relative_elevation [m]
//! 0.000, 0.2712
//! 0.002, 0.2709
//! ```
//!
//! * Lines starting with `#` are provenance (source, sampling, filter, ...): kept verbatim, in order, and
//!   written with every output made from the record. Blank lines are skipped.
//! * The first other line is the header: `name [unit]` per column. Exactly two columns: the time
//!   (`time [s]` or `[ms]`) and one motion column whose name fixes the sign convention:
//!   - `relative_elevation [m]` (or `[mm]`): s, the height of the station's still-water-line point above
//!     the local water surface, positive with the hull above the water (keel out while s > draft);
//!   - `relative_velocity [m/s]` (or `[mm/s]`): Ds/Dt, positive with the hull moving up relative to the
//!     water;
//!   - `entry_velocity [m/s]` (or `[mm/s]`): V = -Ds/Dt, positive with the hull moving down into the water.
//! * Then one row per sample: finite numbers, times strictly increasing, at least [`MIN_SAMPLES`] rows.
//!
//! Every rejection names the file, line and column.

use std::path::{Path, PathBuf};

use crate::error::{Error, InputError, Result};
use crate::input::SourceText;

/// Fewest samples a record may have (central differences need three; a record of a water entry has
/// many more).
pub const MIN_SAMPLES: usize = 5;

/// The motion column of a record; its name fixes the sign convention.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "snake_case")]
pub enum Column {
    /// s (m), positive with the hull above the water.
    RelativeElevation,
    /// Ds/Dt (m/s), positive with the hull moving up relative to the water.
    RelativeVelocity,
    /// V = -Ds/Dt (m/s), positive with the hull moving down into the water.
    EntryVelocity,
}

impl Column {
    /// The column's name in the header.
    pub fn name(self) -> &'static str {
        match self {
            Column::RelativeElevation => "relative_elevation",
            Column::RelativeVelocity => "relative_velocity",
            Column::EntryVelocity => "entry_velocity",
        }
    }

    /// The accepted units and their factor to SI.
    fn units(self) -> &'static [(&'static str, f64)] {
        match self {
            Column::RelativeElevation => &[("m", 1.0), ("mm", 1e-3)],
            Column::RelativeVelocity | Column::EntryVelocity => &[("m/s", 1.0), ("mm/s", 1e-3)],
        }
    }
}

const TIME_UNITS: &[(&str, f64)] = &[("s", 1.0), ("ms", 1e-3)];

/// A relative-motion record as read, in SI units.
#[derive(Debug, Clone)]
pub struct ForcingRecord {
    pub path: PathBuf,
    /// The `#` lines, without the `#`, in order.
    pub provenance: Vec<String>,
    pub column: Column,
    /// Times (s), strictly increasing.
    pub time_s: Vec<f64>,
    /// The motion column in SI units (m or m/s), in its own sign convention.
    pub values: Vec<f64>,
    /// The 1-based line of each sample in the file (for errors found later).
    pub lines: Vec<usize>,
    /// The 1-based line of the header.
    pub header_line: usize,
}

impl ForcingRecord {
    /// An error located at the sample `k`'s line, column `column`.
    pub fn error_at_sample(&self, k: usize, column: usize, message: impl Into<String>) -> Error {
        let line = self.lines.get(k).copied().unwrap_or(self.header_line);
        Error::Input(InputError {
            file: self.path.clone(),
            line,
            column,
            message: message.into(),
        })
    }
}

/// Read a record from a file ([`parse_record`]).
pub fn read_record(path: &Path) -> Result<ForcingRecord> {
    parse_record(&SourceText::read(path)?)
}

/// Parse a record from text that did not come from disk (tests, generated records); `name` stands for
/// the file in errors.
pub fn parse_record_text(name: &str, text: &str) -> Result<ForcingRecord> {
    parse_record(&SourceText::from_string(name, text))
}

/// Split a line into its cells with the 1-based character column where each (trimmed) cell starts.
fn cells(line: &str) -> Vec<(usize, &str)> {
    let mut out = Vec::new();
    let mut start = 0usize;
    for part in line.split(',') {
        let lead = part.len() - part.trim_start().len();
        let col = line[..start + lead].chars().count() + 1;
        out.push((col, part.trim()));
        start += part.len() + 1;
    }
    out
}

/// `name [unit]` of a header cell.
fn name_unit(cell: &str) -> Option<(&str, &str)> {
    let open = cell.find('[')?;
    let close = cell.rfind(']')?;
    (close > open && cell[close + 1..].trim().is_empty())
        .then(|| (cell[..open].trim(), cell[open + 1..close].trim()))
}

/// Parse a record from text.
pub fn parse_record(src: &SourceText) -> Result<ForcingRecord> {
    let err = |line: usize, col: usize, msg: String| Error::Input(src.error_line(line, col, msg));
    let mut provenance = Vec::new();
    let mut header: Option<(usize, Column, f64, f64)> = None;
    let (mut time_s, mut values, mut lines) = (Vec::new(), Vec::new(), Vec::new());
    for (i, raw) in src.text.lines().enumerate() {
        let n = i + 1;
        let line = raw.trim_start_matches('\u{feff}');
        let t = line.trim();
        if t.is_empty() {
            continue;
        }
        if let Some(c) = t.strip_prefix('#') {
            provenance.push(c.trim().to_string());
            continue;
        }
        let row = cells(line);
        let Some((_, column, tf, vf)) = header else {
            header = Some(parse_header(&row, n, &err)?);
            continue;
        };
        if row.len() != 2 {
            return Err(err(
                n,
                row.get(2).map_or(1, |c| c.0),
                format!(
                    "a row needs 2 numbers (time and {}), this one has {}",
                    column.name(),
                    row.len()
                ),
            ));
        }
        let mut nums = [0.0; 2];
        for (k, (col, cell)) in row.iter().enumerate() {
            let x: f64 = cell
                .parse()
                .map_err(|_| err(n, *col, format!("`{cell}` is not a number")))?;
            if !x.is_finite() {
                return Err(err(
                    n,
                    *col,
                    format!("`{cell}` is not a finite number (NaN and infinity are not samples)"),
                ));
            }
            nums[k] = x * if k == 0 { tf } else { vf };
        }
        if let Some(&prev) = time_s.last()
            && nums[0] <= prev
        {
            return Err(err(
                n,
                row[0].0,
                format!(
                    "time {} s does not follow {prev} s of line {}: times must increase strictly (no repeated \
                     or out-of-order samples)",
                    nums[0],
                    lines.last().copied().unwrap_or(n)
                ),
            ));
        }
        time_s.push(nums[0]);
        values.push(nums[1]);
        lines.push(n);
    }
    let Some((header_line, column, _, _)) = header else {
        return Err(err(
            1,
            1,
            "no header: the first line that is not a `#` comment must name the columns with units, e.g. \
             `time [s], relative_elevation [m]`"
                .into(),
        ));
    };
    if time_s.len() < MIN_SAMPLES {
        let line = lines.last().copied().unwrap_or(header_line);
        return Err(err(
            line,
            1,
            format!(
                "{} sample(s): a record needs at least {MIN_SAMPLES}",
                time_s.len()
            ),
        ));
    }
    Ok(ForcingRecord {
        path: src.path.clone(),
        provenance,
        column,
        time_s,
        values,
        lines,
        header_line,
    })
}

/// The header: (line, motion column, time factor to s, value factor to SI).
fn parse_header(
    row: &[(usize, &str)],
    n: usize,
    err: &dyn Fn(usize, usize, String) -> Error,
) -> Result<(usize, Column, f64, f64)> {
    const ALL: [Column; 3] = [
        Column::RelativeElevation,
        Column::RelativeVelocity,
        Column::EntryVelocity,
    ];
    let expected = "`time [s]` and one of `relative_elevation [m]` (hull above the water positive), \
                    `relative_velocity [m/s]` (hull moving up positive) or `entry_velocity [m/s]` (hull \
                    moving down positive)";
    if row.len() != 2 {
        return Err(err(
            n,
            row.get(2).map_or(1, |c| c.0),
            format!(
                "the header names {} column(s); a record has two: {expected}",
                row.len()
            ),
        ));
    }
    let unit_of = |(col, cell): (usize, &str), accepted: &[(&str, f64)]| -> Result<(String, f64)> {
        let Some((name, unit)) = name_unit(cell) else {
            return Err(err(
                n,
                col,
                format!("column `{cell}` has no unit: write it as `name [unit]` ({expected})"),
            ));
        };
        let f = accepted
            .iter()
            .find(|(u, _)| *u == unit)
            .map(|(_, f)| *f)
            .ok_or_else(|| {
                let list: Vec<&str> = accepted.iter().map(|(u, _)| *u).collect();
                err(
                    n,
                    col,
                    format!(
                        "unknown unit `[{unit}]` for `{name}`: use one of [{}]",
                        list.join("], [")
                    ),
                )
            })?;
        Ok((name.to_string(), f))
    };
    let (tc, tcell) = row[0];
    let tname = name_unit(tcell).map_or(tcell, |(n, _)| n);
    if tname != "time" {
        return Err(err(
            n,
            tc,
            format!("the first column must be the time, `time [s]`, not `{tcell}`"),
        ));
    }
    let (_, tf) = unit_of(row[0], TIME_UNITS)?;
    let (vc, vcell) = row[1];
    let vname = name_unit(vcell).map_or(vcell, |(n, _)| n);
    let Some(column) = ALL.iter().copied().find(|c| c.name() == vname) else {
        return Err(err(
            n,
            vc,
            format!("unknown column `{vname}`: the second column is one of {expected}"),
        ));
    };
    let (_, vf) = unit_of(row[1], column.units())?;
    Ok((n, column, tf, vf))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> std::result::Result<ForcingRecord, String> {
        parse_record(&SourceText::from_string("r.csv", text)).map_err(|e| e.to_string())
    }

    #[test]
    fn units_are_converted_and_provenance_kept() {
        let r = parse("# source: test\n#filter: none\ntime [ms], entry_velocity [mm/s]\n0,1000\n1,1100\n2,1200\n3,1300\n4,1400\n")
            .unwrap();
        assert_eq!(r.provenance, vec!["source: test", "filter: none"]);
        assert_eq!(r.column, Column::EntryVelocity);
        assert!((r.time_s[4] - 0.004).abs() < 1e-15);
        assert!((r.values[4] - 1.4).abs() < 1e-12);
        assert_eq!(r.lines[0], 4);
    }

    #[test]
    fn header_errors_are_located() {
        let e = parse("time [s], relative_elevation\n").unwrap_err();
        assert!(
            e.starts_with("r.csv:1:11:") && e.contains("has no unit"),
            "{e}"
        );
        let e = parse("time [s], relative_elevation [ft]\n").unwrap_err();
        assert!(
            e.starts_with("r.csv:1:11:") && e.contains("unknown unit"),
            "{e}"
        );
        let e = parse("t [s], relative_elevation [m]\n").unwrap_err();
        assert!(e.starts_with("r.csv:1:1:"), "{e}");
        let e = parse("time [s], heave [m]\n").unwrap_err();
        assert!(e.contains("unknown column `heave`"), "{e}");
    }
}
