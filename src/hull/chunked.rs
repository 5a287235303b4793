//! Reading a large hull file station by station.
//!
//! The TOML reader holds every token of a file at once, some twenty times the file's size: 700 MB for a
//! hull of 100,000 stations. A hull file above [`CHUNKED_BYTES`] is therefore read in two steps with the
//! same result: each `[[station]]` table on its own (tokens of one table at a time), then the rest of the
//! file with the station tables blanked out (spaces, line breaks kept, so that every position in the rest
//! is the position in the file). Spans of the station values are shifted to their place in the file, so
//! errors name the same line and column as a whole-file read.
//!
//! The split is by lines: a table header is a line whose first non-blank character is `[` followed by a
//! name (a letter, `_` or a quote; a line of numbers such as `[[0.0, 1.0],` is not). A file with
//! multi-line strings after its first table header (where such a line could be text) is read whole;
//! multi-line strings before it, such as a description, are allowed.

use std::ops::Range;

use toml::Spanned;

use super::schema::{HullFile, StationRaw};
use crate::error::InputError;
use crate::input::{Pair, SourceText};

/// Hull files at least this large are read station by station.
pub const CHUNKED_BYTES: usize = 1 << 20;

/// The table name of a header line (`[[station]]` -> `station`), or `None` for any other line.
fn header_name(line: &str) -> Option<&str> {
    let t = line.trim_start();
    let inner = t.strip_prefix('[')?;
    let inner = inner.strip_prefix('[').unwrap_or(inner).trim_start();
    let first = inner.chars().next()?;
    if !(first.is_ascii_alphabetic() || first == '_' || first == '"' || first == '\'') {
        return None;
    }
    let end = inner.find(']')?;
    Some(inner[..end].trim())
}

/// Parse a hull file, station by station when it is large (same result and error positions as
/// [`SourceText::parse_toml`]).
pub(crate) fn parse(src: &SourceText) -> Result<HullFile, InputError> {
    let text = &src.text;
    if text.len() < CHUNKED_BYTES {
        return src.parse_toml();
    }
    // Line starts of every table header, with whether it is a station.
    let mut headers: Vec<(usize, bool)> = Vec::new();
    let mut offset = 0;
    for line in text.split_inclusive('\n') {
        if let Some(name) = header_name(line) {
            headers.push((
                offset,
                line.trim_start().starts_with("[[") && name == "station",
            ));
        }
        offset += line.len();
    }
    // Multi-line strings are allowed only before the first header, and closed there (a description):
    // from the first header on, a header-like line is then a header.
    let first = headers.first().map_or(text.len(), |h| h.0);
    let (head, tail) = text.split_at(first);
    for q in ["\"\"\"", "'''"] {
        if tail.contains(q) || head.matches(q).count() % 2 == 1 {
            return src.parse_toml();
        }
    }
    let chunks: Vec<Range<usize>> = headers
        .iter()
        .enumerate()
        .filter(|(_, h)| h.1)
        .map(|(i, h)| h.0..headers.get(i + 1).map_or(text.len(), |n| n.0))
        .collect();
    if chunks.is_empty() {
        return src.parse_toml();
    }
    let mut stations = Vec::with_capacity(chunks.len());
    for c in &chunks {
        stations.push(station(src, c.clone())?);
    }
    let mut rest = text.clone().into_bytes();
    for c in &chunks {
        for b in &mut rest[c.clone()] {
            if *b != b'\n' && *b != b'\r' {
                *b = b' ';
            }
        }
    }
    let rest =
        String::from_utf8(rest).expect("blanking keeps UTF-8: only whole characters become spaces");
    let mut raw: HullFile = SourceText::from_string(src.path.clone(), rest).parse_toml()?;
    if raw.station.is_some() {
        // Stations also given some other way (an inline array): let the whole-file reader decide.
        return src.parse_toml();
    }
    let all = chunks[0].start..chunks[chunks.len() - 1].end;
    raw.station = Some(Spanned::new(all, stations));
    Ok(raw)
}

/// One `[[station]]` table (its header line and body at `range` of the file), spans in file positions.
fn station(src: &SourceText, range: Range<usize>) -> Result<Spanned<StationRaw>, InputError> {
    let chunk = &src.text[range.clone()];
    let body_at = chunk.find('\n').map_or(chunk.len(), |i| i + 1);
    let base = range.start + body_at;
    let body = &chunk[body_at..];
    let shift = |r: Range<usize>| r.start + base..r.end + base;
    let s: StationRaw = toml::from_str(body).map_err(|e| {
        let at = e.span().map_or(base..base, shift);
        src.error_at(at, e.message().trim().to_string())
    })?;
    let move_f = |v: Option<Spanned<f64>>| v.map(|v| Spanned::new(shift(v.span()), *v.get_ref()));
    let points = Spanned::new(
        shift(s.points.span()),
        s.points
            .get_ref()
            .iter()
            .map(|p| Spanned::new(shift(p.span()), Pair(p.get_ref().0)))
            .collect(),
    );
    Ok(Spanned::new(
        range,
        StationRaw {
            x_m: move_f(s.x_m),
            aft_of_fp: move_f(s.aft_of_fp),
            points,
        },
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A file made large with comment padding, read both ways: the same stations at the same positions,
    /// and the same located error.
    #[test]
    fn chunked_and_whole_reads_agree() {
        let pad = format!("# {}\n", "x".repeat(200)).repeat(CHUNKED_BYTES / 200 + 1);
        let text = format!(
            "name = \"b\"\ndescription = \"\"\"\nmulti-line\n[1] text\n\"\"\"\nlpp_m = 10.0\n{pad}\n[[loading]]\nname = \"d\"\ndraft_fp_m = 1.0\ndraft_ap_m = 1.0\n\
             kg_m = 1.0\nk_yy_m = 2.5\n\n[[station]]\nx_m = -5.0\npoints = [\n  [0.0, 0.0],\n  [1.0, 0.0], [1.0, 2.0]]\n\n\
             [[station]]\nx_m = 5.0 # fwd\npoints = [[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]\n"
        );
        let src = SourceText::from_string("h.toml", text.clone());
        let whole: HullFile = src.parse_toml().unwrap();
        let chunked = parse(&src).unwrap();
        /// Spans of a station: x_m, points, each point.
        type StationSpans = (Range<usize>, Range<usize>, Vec<Range<usize>>);
        let spans = |h: &HullFile| -> Vec<StationSpans> {
            h.station
                .as_ref()
                .unwrap()
                .get_ref()
                .iter()
                .map(|s| {
                    let r = s.get_ref();
                    (
                        r.x_m.as_ref().unwrap().span(),
                        r.points.span(),
                        r.points.get_ref().iter().map(|p| p.span()).collect(),
                    )
                })
                .collect()
        };
        assert_eq!(spans(&whole), spans(&chunked));
        assert_eq!(
            whole.loading.get_ref().len(),
            chunked.loading.get_ref().len()
        );
        let bad = SourceText::from_string("h.toml", text.replace("x_m = 5.0", "x_m = \"five\""));
        let (a, b) = (
            bad.parse_toml::<HullFile>().unwrap_err(),
            parse(&bad).unwrap_err(),
        );
        assert_eq!((a.line, a.column), (b.line, b.column), "{a} vs {b}");
    }
}
