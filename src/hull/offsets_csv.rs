//! Offsets from a CSV table, one row per point, `station,y_m,z_m`, the way lines plans leave naval
//! architecture software. Rows of one station are consecutive and run from keel to deck; stations run
//! monotonically (aft to forward or forward to aft).

use std::path::Path;

use toml::Spanned;

use super::Station;
use super::load::order_stations;
use super::schema::{OffsetsCsvRaw, StationColumn};
use super::station_x;
use super::validate::check_section;
use crate::error::{Error, InputError, Result};
use crate::input::SourceText;

/// Read the stations named by an `[offsets_csv]` table. Errors point into the CSV file (line, column).
pub(crate) fn read_stations(
    toml_src: &SourceText,
    lpp: f64,
    raw: &Spanned<OffsetsCsvRaw>,
) -> Result<Vec<Station>> {
    let r = raw.get_ref();
    let base = toml_src.path.parent().unwrap_or(Path::new("."));
    let path = base.join(r.file.get_ref());
    let csv_src = SourceText::read(&path).map_err(|e| match e {
        Error::Io { source, .. } => Error::Input(toml_src.error(
            &r.file,
            format!("cannot read offsets file {}: {source}", path.display()),
        )),
        other => other,
    })?;
    parse(&csv_src, lpp, r.station)
}

/// Column (1-based) where field `field` starts on a CSV line (plain comma-separated fields).
fn column_of(line: &str, field: usize) -> usize {
    let line = line.trim_start_matches('\u{feff}');
    let mut col = 1;
    for (i, part) in line.split(',').enumerate() {
        if i == field {
            return col;
        }
        col += part.chars().count() + 1;
    }
    // Past the last field: the end of the line.
    line.trim_end().chars().count() + 1
}

/// An error at field `field` (0-based) of line `line` (1-based) of a CSV source, located to the column.
pub(crate) fn cell_error(src: &SourceText, line: usize, field: usize, msg: String) -> InputError {
    let text = src.text.lines().nth(line.saturating_sub(1)).unwrap_or("");
    src.error_line(line, column_of(text, field), msg)
}

/// The line of a CSV record from its byte offset: with CRLF line ends the reader counts lines one short
/// and starts a record on the '\n' that ends the line before, so skip line-end bytes first.
pub(crate) fn record_line(src: &SourceText, p: &csv::Position) -> usize {
    let bytes = src.text.as_bytes();
    let mut b = p.byte() as usize;
    while matches!(bytes.get(b), Some(b'\r' | b'\n')) {
        b += 1;
    }
    src.line_column(b).0
}

fn parse(src: &SourceText, lpp: f64, column: StationColumn) -> Result<Vec<Station>> {
    let err = |line: usize, field: usize, msg: String| cell_error(src, line, field, msg);
    let line_of = |p: &csv::Position| record_line(src, p);
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(true)
        .flexible(true)
        .comment(Some(b'#'))
        .trim(csv::Trim::All)
        .from_reader(src.text.as_bytes());
    let headers = reader
        .headers()
        .map_err(|e| err(1, 0, format!("cannot read the header row: {e}")))?
        .clone();
    let expected = ["station", "y_m", "z_m"];
    if headers.len() != 3 || headers.iter().zip(expected).any(|(h, e)| h != e) {
        return Err(err(
            1,
            0,
            format!(
                "header must be 'station,y_m,z_m', got '{}'",
                headers.iter().collect::<Vec<_>>().join(",")
            ),
        )
        .into());
    }
    // (station value, points, line of each point)
    let mut groups: Vec<(f64, Vec<[f64; 2]>, Vec<usize>)> = Vec::new();
    for rec in reader.records() {
        let rec = rec.map_err(|e| {
            let line = e.position().map_or(1, &line_of);
            err(line, 0, format!("malformed CSV row: {e}"))
        })?;
        let line = rec.position().map_or(1, line_of);
        if rec.len() != 3 {
            return Err(err(
                line,
                rec.len().min(3),
                format!(
                    "expected 3 fields (station, y_m, z_m), got {}: {}",
                    rec.len(),
                    if rec.len() < 3 {
                        "a value is missing"
                    } else {
                        "remove the extra values"
                    }
                ),
            )
            .into());
        }
        let mut vals = [0.0; 3];
        for (k, v) in vals.iter_mut().enumerate() {
            *v = rec[k]
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| {
                    err(
                        line,
                        k,
                        format!("'{}' is not a finite number ({})", &rec[k], expected[k]),
                    )
                })?;
        }
        match groups.last_mut() {
            Some(g) if g.0 == vals[0] => {
                g.1.push([vals[1], vals[2]]);
                g.2.push(line);
            }
            _ => {
                if groups.iter().any(|g| g.0 == vals[0]) {
                    return Err(err(
                        line,
                        0,
                        format!(
                            "station {} appears again; keep the rows of each station together",
                            vals[0]
                        ),
                    )
                    .into());
                }
                groups.push((vals[0], vec![[vals[1], vals[2]]], vec![line]));
            }
        }
    }
    if groups.len() < 2 {
        return Err(err(1, 0, "a hull needs at least two stations".into()).into());
    }
    let mut stations = Vec::with_capacity(groups.len());
    for (value, points, at) in groups {
        let x = match column {
            StationColumn::XM => value,
            StationColumn::AftOfFp => station_x(lpp, value),
        };
        if x.abs() > 1.5 * lpp {
            return Err(err(
                at[0],
                0,
                format!("station {value} lies far outside the hull (x = {x:.3} m, Lpp = {lpp} m)"),
            )
            .into());
        }
        check_section(&points).map_err(|f| {
            err(
                at[f.point.min(at.len() - 1)],
                f.coord.map_or(1, |c| c + 1),
                f.message,
            )
        })?;
        stations.push((x, points, at[0]));
    }
    order_stations(stations, |line, msg| err(line, 0, msg).into())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_and_locates_errors() {
        let ok = SourceText::from_string(
            "o.csv",
            "station,y_m,z_m\n0.0,0,0\n0.0,0.1,0.2\n1.0,0,0\n1.0,0.2,0.2\n",
        );
        let st = parse(&ok, 2.0, StationColumn::XM).unwrap();
        assert_eq!(st.len(), 2);
        let bad = SourceText::from_string("o.csv", "station,y_m,z_m\n0.0,0,0\n0.0,abc,0.2\n");
        let e = parse(&bad, 2.0, StationColumn::XM).unwrap_err().to_string();
        assert!(e.starts_with("o.csv:3:5:"), "{e}");
    }
}
