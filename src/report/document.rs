//! A report document — title block, headings, paragraphs, tables, figures — typeset to PDF with typst.
//!
//! The document is plain data ([`Document`], [`Block`]); [`Document::typst_source`] turns it into typst
//! markup and [`Document::pdf`] compiles that with the bundled DejaVu Sans as the only font (no system
//! fonts are looked at), so a report looks the same on every machine. Every piece of text that comes
//! from a user (hull, wave and sensor names, file paths) enters the markup as a typst string literal,
//! never as markup, so no character in it can change the layout. The PDF carries no date: unchanged
//! inputs give a byte-identical file; a date appears only where the caller puts one in (`stamp`).
//!
//! Pages are A4 with 20 mm margins; text is 9.5 pt, tables 8 pt, so that printed pages are readable.

use crate::error::{Error, Result};

/// The bundled font (the same file the figures use, see [`crate::plot`]).
static FONT_BYTES: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// A report: a title block, then blocks in reading order.
#[derive(Debug, Clone, Default)]
pub struct Document {
    pub title: String,
    /// Lines under the title (e.g. hull, loading, tool version).
    pub subtitle: Vec<String>,
    /// A date or other stamp printed under the title; `None` keeps the PDF free of dates.
    pub stamp: Option<String>,
    /// Text in the page footer, left of the page number (e.g. the report's name).
    pub footer: String,
    pub blocks: Vec<Block>,
}

/// One element of a document.
#[derive(Debug, Clone)]
pub enum Block {
    /// A numbered heading; level 1 starts a new page.
    Heading {
        level: u8,
        text: String,
    },
    /// A paragraph of plain text.
    Paragraph(String),
    /// A paragraph in bold (a verdict, a warning headline).
    Strong(String),
    /// A bulleted list of plain-text items.
    List(Vec<String>),
    /// Label-value pairs in two columns.
    KeyValue(Vec<(String, String)>),
    /// A table with a header row; columns whose cells all parse as numbers are right-aligned.
    Table {
        caption: String,
        header: Vec<String>,
        rows: Vec<Vec<String>>,
    },
    /// An SVG picture (e.g. from [`crate::report::figure`]) with a caption, `width_mm` wide.
    Svg {
        svg: String,
        caption: String,
        width_mm: f64,
    },
    /// A PNG picture with a caption, `width_mm` wide.
    Png {
        png: Vec<u8>,
        caption: String,
        width_mm: f64,
    },
    PageBreak,
}

/// A typst string literal holding `s` exactly: `"..."` with `\` and `"` escaped and control characters
/// written as escapes. In markup it is used as `#"..."`, which typesets the text without interpreting it.
pub fn typst_string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '\\' => out.push_str("\\\\"),
            '"' => out.push_str("\\\""),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if c.is_control() => out.push_str(&format!("\\u{{{:x}}}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

fn is_number(s: &str) -> bool {
    let t = s.trim().trim_end_matches('%');
    !t.is_empty() && (t.parse::<f64>().is_ok() || t == "-")
}

/// Characters in the widest cells of a table's columns, summed, above which it is set to the text width.
const WIDE_TABLE_CHARS: usize = 110;

/// Characters in the widest cell of a text column above which it may take the remaining width.
const WIDE_TEXT_CHARS: usize = 40;

/// Characters of a wide table's columns (narrow columns at their widest cell, headers wrapped; text
/// columns at [`LEAST_TEXT_CHARS`]), summed, above which it does not fit the portrait text width at
/// 7.2 pt: it gets a landscape page of its own.
const PORTRAIT_TABLE_CHARS: usize = 125;

/// The least width, in characters, a wrapping text column of a wide table is given room for.
const LEAST_TEXT_CHARS: usize = 20;

/// Characters a header line of a wide table holds (a longer word keeps its own line).
const HEADER_LINE_CHARS: usize = 12;

/// `h` broken into lines of at most [`HEADER_LINE_CHARS`] characters at its spaces (a longer word on a
/// line of its own), so that a narrow column's header wraps instead of widening the column.
fn wrap_header(h: &str) -> String {
    let mut lines: Vec<String> = Vec::new();
    for word in h.split_whitespace() {
        match lines.last_mut() {
            Some(l) if l.chars().count() + 1 + word.chars().count() <= HEADER_LINE_CHARS => {
                l.push(' ');
                l.push_str(word);
            }
            _ => lines.push(word.to_string()),
        }
    }
    lines.join("\n")
}

/// The typst preamble: A4, margins, the bundled font, numbered headings, table style.
const PREAMBLE: &str = r#"#set document(date: none)
#set page(paper: "a4", margin: (x: 20mm, top: 20mm, bottom: 22mm))
#set text(font: "DejaVu Sans", size: 9.5pt, lang: "en", fallback: false)
#set par(justify: false, leading: 0.55em)
#set heading(numbering: "1.1")
#show heading.where(level: 1): it => { pagebreak(weak: true); block(below: 1em, text(size: 15pt, it)) }
#show heading.where(level: 2): it => block(above: 1.4em, below: 0.8em, text(size: 11.5pt, it))
#show heading.where(level: 3): it => block(above: 1.2em, below: 0.6em, text(size: 10pt, it))
#show figure.caption: it => text(size: 8.5pt, it)
#show table: set text(size: 8pt)
#set table(stroke: (x, y) => if y == 0 { (bottom: 0.6pt) } else { none }, inset: (x: 4pt, y: 2.5pt))
#set figure(gap: 0.6em)
#show figure: set block(breakable: true)
#show figure.where(kind: image): set block(breakable: false)
"#;

impl Document {
    /// The typst markup of the document and the binary files it refers to (name, bytes).
    pub fn typst_source(&self) -> (String, Vec<(String, Vec<u8>)>) {
        let mut s = String::from(PREAMBLE);
        let mut files: Vec<(String, Vec<u8>)> = Vec::new();
        s += &format!(
            "#set page(footer: context [#set text(size: 8pt); #{} #h(1fr) #counter(page).display(\"1 / 1\", both: true)])\n",
            typst_string(&self.footer)
        );
        s += &format!(
            "#align(left, block(below: 1.2em)[#text(size: 18pt, weight: \"bold\", {})])\n",
            typst_string(&self.title)
        );
        for line in &self.subtitle {
            s += &format!("#text(size: 10pt, {})\\\n", typst_string(line));
        }
        if let Some(st) = &self.stamp {
            s += &format!("#text(size: 10pt, {})\\\n", typst_string(st));
        }
        s += "#v(0.8em)\n";
        for b in &self.blocks {
            block_source(b, &mut s, &mut files);
        }
        (s, files)
    }

    /// The document as PDF bytes (deterministic for an unchanged document).
    pub fn pdf(&self) -> Result<Vec<u8>> {
        let (source, files) = self.typst_source();
        let engine = typst_as_lib::TypstEngine::builder()
            .main_file(source)
            .fonts([FONT_BYTES])
            .with_static_file_resolver(files.iter().map(|(n, b)| (n.as_str(), b.clone())))
            .build();
        let compiled = engine.compile::<typst_layout::PagedDocument>();
        let doc = compiled
            .output
            .map_err(|e| Error::Invalid(format!("typesetting the report failed: {e}")))?;
        let options = typst_pdf::PdfOptions::default();
        typst_pdf::pdf(&doc, &options).map_err(|diags| {
            let text: Vec<String> = diags.iter().map(|d| d.message.to_string()).collect();
            Error::Invalid(format!(
                "writing the report PDF failed: {}",
                text.join("; ")
            ))
        })
    }
}

fn block_source(b: &Block, s: &mut String, files: &mut Vec<(String, Vec<u8>)>) {
    match b {
        Block::Heading { level, text } => {
            let l = (*level).clamp(1, 4) as usize;
            s.push_str(&format!("#heading(level: {l}, {})\n", typst_string(text)));
        }
        Block::Paragraph(t) => s.push_str(&format!("#par({})\n\n", typst_string(t))),
        Block::Strong(t) => s.push_str(&format!("#par(strong({}))\n\n", typst_string(t))),
        Block::List(items) => {
            if items.is_empty() {
                return;
            }
            let body: Vec<String> = items.iter().map(|i| typst_string(i)).collect();
            s.push_str(&format!("#list(tight: true, {})\n\n", body.join(", ")));
        }
        Block::KeyValue(pairs) => {
            if pairs.is_empty() {
                return;
            }
            let cells: Vec<String> = pairs
                .iter()
                .map(|(k, v)| format!("{}, {}", typst_string(k), typst_string(v)))
                .collect();
            s.push_str(&format!(
                "#block(table(columns: (auto, 1fr), stroke: none, inset: (x: 3pt, y: 2pt), {}))\n\n",
                cells.join(", ")
            ));
        }
        Block::Table {
            caption,
            header,
            rows,
        } => {
            let n = header.len().max(1);
            let align: Vec<&str> = (0..n)
                .map(|j| {
                    let numeric = !rows.is_empty()
                        && rows
                            .iter()
                            .all(|r| r.get(j).is_none_or(|c| c.is_empty() || is_number(c)));
                    if numeric { "right" } else { "left" }
                })
                .collect();
            // The widest cell of column j in characters, its header counted whole or wrapped.
            let widest = |j: usize, wrapped: bool| {
                let body = rows
                    .iter()
                    .map(|r| r.get(j).map_or(0, |c| c.chars().count()))
                    .max()
                    .unwrap_or(0);
                let head = match wrapped {
                    true => wrap_header(&header[j])
                        .lines()
                        .map(|l| l.chars().count())
                        .max(),
                    false => Some(header[j].chars().count()),
                };
                body.max(head.unwrap_or(0))
            };
            // A table too wide for the text width is set a little smaller, with its headers wrapped so
            // that a narrow column is as wide as its cells, and its wide text columns share the width
            // the others leave (so that they wrap, and the others do not). One that does not fit even
            // so, its text columns at their least, gets a landscape page of its own.
            let wide = !header.is_empty()
                && (0..header.len()).map(|j| widest(j, false)).sum::<usize>() > WIDE_TABLE_CHARS;
            let text_column = |j: usize| align[j] == "left" && widest(j, true) > WIDE_TEXT_CHARS;
            let least: usize = (0..header.len())
                .map(|j| match text_column(j) {
                    true => LEAST_TEXT_CHARS,
                    false => widest(j, true),
                })
                .sum();
            let landscape = wide && least > PORTRAIT_TABLE_CHARS;
            let mut cells: Vec<String> = header
                .iter()
                .map(|h| if wide { wrap_header(h) } else { h.clone() })
                // a zero-width space after each underscore lets snake_case headers wrap
                .map(|h| format!("strong({})", typst_string(&h.replace('_', "_\u{200B}"))))
                .collect();
            for r in rows {
                for j in 0..n {
                    cells.push(typst_string(r.get(j).map_or("", String::as_str)));
                }
            }
            let columns = if wide {
                // Each wide text column gets a share of the free width in proportion to its text.
                let cols: Vec<String> = (0..n)
                    .map(|j| match j < header.len() && text_column(j) {
                        true => format!("{}fr", widest(j, true)),
                        false => "auto".to_string(),
                    })
                    .collect();
                format!("({}), inset: (x: 3pt, y: 1.6pt)", cols.join(", "))
            } else {
                n.to_string()
            };
            // (the smaller text is a scoped show rule after the preamble's)
            let (open, close) = match (landscape, wide) {
                (true, _) => (
                    "#page(flipped: true)[#show table: set text(size: 7.2pt)\n",
                    "]",
                ),
                (false, true) => ("#[#show table: set text(size: 7.2pt)\n", "]"),
                (false, false) => ("", ""),
            };
            s.push_str(&format!(
                "{open}#figure(kind: table, caption: {}, table(columns: {columns}, align: ({}), table.header({}), {})){close}\n\n",
                typst_string(caption),
                align.join(", "),
                cells[..n].join(", "),
                cells[n..].join(", ")
            ));
        }
        Block::Svg {
            svg,
            caption,
            width_mm,
        } => {
            let name = format!("figure-{}.svg", files.len() + 1);
            files.push((name.clone(), svg.as_bytes().to_vec()));
            s.push_str(&image_source(&name, caption, *width_mm));
        }
        Block::Png {
            png,
            caption,
            width_mm,
        } => {
            let name = format!("image-{}.png", files.len() + 1);
            files.push((name.clone(), png.clone()));
            s.push_str(&image_source(&name, caption, *width_mm));
        }
        Block::PageBreak => s.push_str("#pagebreak()\n"),
    }
}

fn image_source(name: &str, caption: &str, width_mm: f64) -> String {
    format!(
        "#figure(image({}, width: {:.1}mm), caption: {})\n\n",
        typst_string(name),
        width_mm.clamp(10.0, 170.0),
        typst_string(caption)
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_wide_table_s_header_wraps_at_twelve_characters_and_keeps_long_words_whole() {
        assert_eq!(
            wrap_header("Ochi P1 0.093 Lpp keel entry (m/s)"),
            "Ochi P1\n0.093 Lpp\nkeel entry\n(m/s)"
        );
        assert_eq!(
            wrap_header("impact_velocity_m_per_s (m)"),
            "impact_velocity_m_per_s\n(m)"
        );
        assert_eq!(wrap_header("gap closed"), "gap closed");
    }

    #[test]
    fn user_text_is_a_string_literal_not_markup() {
        assert_eq!(typst_string(r#"a "b" \c"#), r#""a \"b\" \\c""#);
        assert_eq!(typst_string("x\ny"), "\"x\\ny\"");
        let d = Document {
            title: "#set page(width: 1mm) *bold* $x$ ] [".into(),
            blocks: vec![Block::Paragraph("_under_ @ref <lab> // comment".into())],
            ..Default::default()
        };
        let (src, _) = d.typst_source();
        assert!(src.contains(r##""#set page(width: 1mm) *bold* $x$ ] [""##));
        assert!(src.contains(r#"#par("_under_ @ref <lab> // comment")"#));
    }
}
