//! A lines-plan offsets table as CSV: stations × waterlines → half-breadths.
//!
//! ```text
//! # comments start with '#'
//! x_m,   0.0,  0.5,  1.0,  2.0      <- header: what the first column holds, then waterline heights z (m)
//! -60.0, -,    0.8,  2.1,  3.0      <- one row per station: its position, then the half-breadth y (m)
//!   0.0, 2.9,  4.8,  5.0,  5.0         on each waterline; blank or '-' where the station has no offset
//! ```
//!
//! The first header cell is `x_m` (station positions in m, any origin, positive forward) or `aft_of_fp`
//! (fractions of Lpp aft of the FP). A row's offsets must be one unbroken run of waterlines: blanks may
//! only stand below the lowest offset (a keel that rises towards the ends) or above the highest (a
//! section that ends below the top waterline). The contour of a station runs from the centreline at its
//! lowest offset (a flat bottom there if that offset has breadth) up through the offsets in z order.

use super::SourceStation;
use crate::error::Result;
use crate::hull::offsets_csv::{cell_error, record_line};
use crate::hull::schema::StationColumn;
use crate::hull::validate::check_section;
use crate::input::SourceText;

/// The stations of a grid table, in file order, with what their positions mean.
#[derive(Debug, Clone)]
pub(crate) struct GridTable {
    pub column: StationColumn,
    pub stations: Vec<SourceStation>,
}

/// A number cell: `None` for a blank or `-`, an error for anything else that is not a finite number.
fn cell(text: &str) -> Result<Option<f64>, String> {
    let t = text.trim();
    if t.is_empty() || t == "-" {
        return Ok(None);
    }
    match t.parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(Some(v)),
        _ => Err(format!(
            "'{t}' is not a finite number (or blank / '-' for no offset)"
        )),
    }
}

/// Parse a grid offsets table. Every error names the line and column of the cell at fault.
pub(crate) fn parse(src: &SourceText) -> Result<GridTable> {
    let err = |line: usize, field: usize, msg: String| cell_error(src, line, field, msg);
    let line_of = |p: &csv::Position| record_line(src, p);
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .from_reader(src.text.as_bytes());
    let mut records = reader.records();
    let header = match records.next() {
        Some(Ok(h)) => h,
        Some(Err(e)) => return Err(err(1, 0, format!("cannot read the header row: {e}")).into()),
        None => {
            return Err(err(
                1,
                0,
                "empty table: the header row is 'x_m' or 'aft_of_fp', then waterline heights z in m".into(),
            )
            .into());
        }
    };
    let hline = header.position().map_or(1, line_of);
    let column = match header.get(0).map(|s| s.trim_start_matches('\u{feff}')) {
        Some("x_m") => StationColumn::XM,
        Some("aft_of_fp") => StationColumn::AftOfFp,
        other => {
            return Err(err(
                hline,
                0,
                format!(
                    "the header's first cell must be 'x_m' (station positions in m) or 'aft_of_fp' (fractions of Lpp aft of the FP), got '{}'",
                    other.unwrap_or("")
                ),
            )
            .into());
        }
    };
    let mut waterlines = Vec::with_capacity(header.len());
    for k in 1..header.len() {
        let z = match cell(&header[k]) {
            Ok(Some(z)) => z,
            Ok(None) => return Err(err(hline, k, "a waterline height is missing".into()).into()),
            Err(m) => return Err(err(hline, k, format!("waterline height: {m}")).into()),
        };
        if let Some(&prev) = waterlines.last()
            && z <= prev
        {
            return Err(err(
                hline,
                k,
                format!("waterline heights must increase from left to right: {z} after {prev}"),
            )
            .into());
        }
        waterlines.push(z);
    }
    if waterlines.len() < 2 {
        return Err(err(
            hline,
            header.len(),
            "the header needs at least two waterline heights after the station column".into(),
        )
        .into());
    }
    let mut stations: Vec<SourceStation> = Vec::new();
    for rec in records {
        let rec = rec.map_err(|e| {
            let line = e.position().map_or(1, &line_of);
            err(line, 0, format!("malformed CSV row: {e}"))
        })?;
        let line = rec.position().map_or(1, line_of);
        if rec.len() > waterlines.len() + 1 {
            return Err(err(
                line,
                waterlines.len() + 1,
                format!(
                    "{} values after the station, but the header has {} waterlines",
                    rec.len() - 1,
                    waterlines.len()
                ),
            )
            .into());
        }
        let value = match cell(&rec[0]) {
            Ok(Some(v)) => v,
            Ok(None) => return Err(err(line, 0, "the station position is missing".into()).into()),
            Err(m) => return Err(err(line, 0, format!("station position: {m}")).into()),
        };
        // (y, z, field) of the offsets on this row
        let mut offsets: Vec<(f64, f64, usize)> = Vec::new();
        let mut gap_at = None;
        for k in 1..rec.len() {
            match cell(&rec[k]).map_err(|m| err(line, k, m))? {
                Some(y) => {
                    if let Some(g) = gap_at
                        && !offsets.is_empty()
                    {
                        return Err(err(
                            line,
                            g,
                            "a blank between two offsets: the offsets of a station must be one unbroken run of waterlines".into(),
                        )
                        .into());
                    }
                    if y < 0.0 {
                        return Err(err(
                            line,
                            k,
                            format!("negative half-breadth {y} (offsets are half-breadths, y ≥ 0)"),
                        )
                        .into());
                    }
                    offsets.push((y, waterlines[k - 1], k));
                    gap_at = None;
                }
                None => {
                    if gap_at.is_none() {
                        gap_at = Some(k);
                    }
                }
            }
        }
        if offsets.is_empty() {
            return Err(err(line, 1, "the station has no offsets".into()).into());
        }
        let mut points = Vec::with_capacity(offsets.len() + 1);
        let mut fields = Vec::with_capacity(offsets.len() + 1);
        if offsets[0].0 > 0.0 {
            // Flat bottom at the lowest offset: start on the centreline.
            points.push([0.0, offsets[0].1]);
            fields.push(offsets[0].2);
        }
        for &(y, z, k) in &offsets {
            points.push([y, z]);
            fields.push(k);
        }
        if points.len() < 2 {
            return Err(err(
                line,
                offsets[0].2,
                "a single offset on the centreline is not a section: give at least two waterlines"
                    .into(),
            )
            .into());
        }
        check_section(&points)
            .map_err(|f| err(line, fields[f.point.min(fields.len() - 1)], f.message))?;
        stations.push(SourceStation {
            value,
            points,
            line,
        });
    }
    if stations.len() < 2 {
        return Err(err(
            src.text.lines().count().max(1),
            0,
            "a hull needs at least two stations (rows after the header)".into(),
        )
        .into());
    }
    Ok(GridTable { column, stations })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table(text: &str) -> Result<GridTable> {
        parse(&SourceText::from_string("g.csv", text))
    }

    #[test]
    fn reads_a_grid_with_gaps_at_the_ends() {
        let t = table("x_m,0,0.5,1\n# midship\n0, 0.2, 0.4, 0.5\n-1,-,0.1,0.2\n").unwrap();
        assert_eq!(t.column, StationColumn::XM);
        assert_eq!(t.stations.len(), 2);
        assert_eq!(t.stations[0].points[0], [0.0, 0.0]);
        assert_eq!(t.stations[0].points.len(), 4);
        assert_eq!(t.stations[1].points[0], [0.0, 0.5]);
        assert_eq!(t.stations[1].line, 4);
    }

    #[test]
    fn errors_name_line_and_column() {
        let e = |s: &str| table(s).unwrap_err().to_string();
        assert!(e("y,0,1\n").starts_with("g.csv:1:1:"), "{}", e("y,0,1\n"));
        assert!(e("x_m,0,1\n0,0.1,abc\n1,0,0\n").starts_with("g.csv:2:7:"));
        assert!(e("x_m,0,1,2\n0,0.1,,0.3\n1,0,0\n").starts_with("g.csv:2:7:"));
        assert!(e("x_m,0,1\n0,0.1,-0.2\n1,0,0\n").starts_with("g.csv:2:7:"));
        assert!(e("x_m,1,0\n").starts_with("g.csv:1:7:"));
        assert!(e("x_m,0,1\n0,0.1,0.2,0.3\n").starts_with("g.csv:2:11:"));
    }
}
