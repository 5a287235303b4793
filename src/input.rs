//! Reading input files with positions: every value that is validated after parsing keeps its byte span
//! (through [`toml::Spanned`]) so that an error can name the line and column it comes from.

use std::ops::Range;
use std::path::{Path, PathBuf};

use serde::de::DeserializeOwned;
use toml::Spanned;

use crate::error::{Error, InputError, Result};

/// Largest input text file read (hull, sea state, case, sweep, offsets), bytes: a hull of 100,000
/// stations is about 10 MB.
pub const MAX_INPUT_BYTES: u64 = 256 << 20;

/// The text of an input file, kept to turn byte offsets into line and column numbers.
#[derive(Debug, Clone)]
pub struct SourceText {
    pub path: PathBuf,
    pub text: String,
}

impl SourceText {
    /// Read a file from disk. Text that is not UTF-8 is an [`InputError`] at the first bad byte.
    pub fn read(path: &Path) -> Result<Self> {
        // A size bound before reading: every reader's memory is then bounded by a multiple of it.
        if let Ok(m) = std::fs::metadata(path)
            && m.is_file()
            && m.len() > MAX_INPUT_BYTES
        {
            return Err(Error::Invalid(format!(
                "{}: {} bytes is larger than the {MAX_INPUT_BYTES} bytes an input text file may have; is it the \
                 right file?",
                path.display(),
                m.len()
            )));
        }
        let bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
        match String::from_utf8(bytes) {
            Ok(text) => Ok(Self {
                path: path.to_path_buf(),
                text,
            }),
            Err(e) => {
                let valid = e.utf8_error().valid_up_to();
                let bytes = e.into_bytes();
                // Everything before the bad byte is valid UTF-8, so it can be counted in characters.
                let good = Self {
                    path: path.to_path_buf(),
                    text: String::from_utf8_lossy(&bytes[..valid]).into_owned(),
                };
                let (line, column) = good.line_column(valid);
                Err(Error::Input(good.error_line(
                    line,
                    column,
                    format!(
                        "the file is not UTF-8 text (byte 0x{:02x}); save it as UTF-8",
                        bytes[valid]
                    ),
                )))
            }
        }
    }

    /// Wrap text that did not come from disk (tests, generated inputs).
    pub fn from_string(path: impl Into<PathBuf>, text: impl Into<String>) -> Self {
        Self {
            path: path.into(),
            text: text.into(),
        }
    }

    /// 1-based (line, column) of a byte offset; columns count characters.
    pub fn line_column(&self, offset: usize) -> (usize, usize) {
        let offset = offset.min(self.text.len());
        let before = &self.text[..offset];
        let line = before.matches('\n').count() + 1;
        let line_start = before.rfind('\n').map_or(0, |i| i + 1);
        // A byte-order mark at the start of the file is not a column an editor shows.
        let line_text = self.text[line_start..offset].trim_start_matches('\u{feff}');
        let column = line_text.chars().count() + 1;
        (line, column)
    }

    /// An error located at the start of a byte span.
    pub fn error_at(&self, span: Range<usize>, message: impl Into<String>) -> InputError {
        let (line, column) = self.line_column(span.start);
        InputError {
            file: self.path.clone(),
            line,
            column,
            message: message.into(),
        }
    }

    /// An error located at a spanned value.
    pub fn error<T>(&self, value: &Spanned<T>, message: impl Into<String>) -> InputError {
        self.error_at(value.span(), message)
    }

    /// An error at a given 1-based line and column (for line-oriented formats such as CSV).
    pub fn error_line(&self, line: usize, column: usize, message: impl Into<String>) -> InputError {
        InputError {
            file: self.path.clone(),
            line,
            column,
            message: message.into(),
        }
    }

    /// Parse the text as TOML into `T`. Syntax errors, unknown keys, wrong types and missing fields come
    /// back located; the message is toml's own, which names the key.
    pub fn parse_toml<T: DeserializeOwned>(&self) -> Result<T, InputError> {
        toml::from_str::<T>(&self.text).map_err(|e| {
            let span = e.span().unwrap_or(0..0);
            let mut message = e.message().trim().to_string();
            if message.contains("invalid type: map, expected a sequence")
                && self
                    .text
                    .get(span.clone())
                    .is_some_and(|t| t.trim_start().starts_with('['))
            {
                // `[loading]` written for `[[loading]]`
                message += " (a list of tables is written with double brackets, e.g. [[loading]])";
            }
            self.error_at(span, message)
        })
    }
}

/// Check that a spanned number is finite and strictly positive.
pub fn positive(src: &SourceText, v: &Spanned<f64>, what: &str) -> Result<f64, InputError> {
    let x = *v.get_ref();
    if !x.is_finite() || x <= 0.0 {
        return Err(src.error(
            v,
            format!("{what} must be a positive number, got {}", num(x)),
        ));
    }
    Ok(x)
}

/// Check that a spanned number is finite (any sign).
pub fn finite(src: &SourceText, v: &Spanned<f64>, what: &str) -> Result<f64, InputError> {
    let x = *v.get_ref();
    if !x.is_finite() {
        return Err(src.error(v, format!("{what} must be a finite number, got {}", num(x))));
    }
    Ok(x)
}

/// Check that a spanned number lies in a closed range.
pub fn in_range(
    src: &SourceText,
    v: &Spanned<f64>,
    lo: f64,
    hi: f64,
    what: &str,
) -> Result<f64, InputError> {
    let x = finite(src, v, what)?;
    if x < lo || x > hi {
        return Err(src.error(
            v,
            format!(
                "{what} must lie in [{}, {}], got {}",
                num(lo),
                num(hi),
                num(x)
            ),
        ));
    }
    Ok(x)
}

/// A pair of numbers written as a two-element TOML array, e.g. a `(y, z)` offset `[0.12, 0.10]`.
/// Integers are accepted as numbers; arrays of any other length are an error located at the array
/// (serde's fixed-size arrays silently ignore extra elements in toml).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Pair(pub [f64; 2]);

impl<'de> serde::Deserialize<'de> for Pair {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct V;
        impl<'de> serde::de::Visitor<'de> for V {
            type Value = Pair;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str("a pair of numbers [y, z]")
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> std::result::Result<Pair, A::Error> {
                use serde::de::Error as _;
                let mut v = Vec::with_capacity(2);
                while let Some(x) = seq.next_element::<f64>()? {
                    v.push(x);
                }
                match v[..] {
                    [a, b] => Ok(Pair([a, b])),
                    _ => Err(A::Error::custom(format!(
                        "expected a pair of numbers [y, z], got {} number{}",
                        v.len(),
                        if v.len() == 1 { "" } else { "s" }
                    ))),
                }
            }
        }
        d.deserialize_seq(V)
    }
}

/// A number as the user wrote it (shortest form that reads back the same), in exponent form when very
/// small or very large so that a message never shows hundreds of digits.
pub fn num(x: f64) -> String {
    let a = x.abs();
    if x == 0.0 || !x.is_finite() || (1e-4..1e9).contains(&a) {
        format!("{x}")
    } else {
        format!("{x:e}")
    }
}
