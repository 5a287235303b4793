//! Reading input files with positions: every value that is validated after parsing keeps its byte span
//! (through [`toml::Spanned`]) so that an error can name the line and column it comes from.

use std::ops::Range;
use std::path::{Path, PathBuf};

use serde::de::DeserializeOwned;
use toml::Spanned;

use crate::error::{Error, InputError, Result};

/// The text of an input file, kept to turn byte offsets into line and column numbers.
#[derive(Debug, Clone)]
pub struct SourceText {
    pub path: PathBuf,
    pub text: String,
}

impl SourceText {
    /// Read a file from disk.
    pub fn read(path: &Path) -> Result<Self> {
        let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
        Ok(Self {
            path: path.to_path_buf(),
            text,
        })
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
        let column = self.text[line_start..offset].chars().count() + 1;
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
            self.error_at(span, e.message().trim().to_string())
        })
    }
}

/// Check that a spanned number is finite and strictly positive.
pub fn positive(src: &SourceText, v: &Spanned<f64>, what: &str) -> Result<f64, InputError> {
    let x = *v.get_ref();
    if !x.is_finite() || x <= 0.0 {
        return Err(src.error(v, format!("{what} must be a positive number, got {x}")));
    }
    Ok(x)
}

/// Check that a spanned number is finite (any sign).
pub fn finite(src: &SourceText, v: &Spanned<f64>, what: &str) -> Result<f64, InputError> {
    let x = *v.get_ref();
    if !x.is_finite() {
        return Err(src.error(v, format!("{what} must be a finite number, got {x}")));
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
        return Err(src.error(v, format!("{what} must lie in [{lo}, {hi}], got {x}")));
    }
    Ok(x)
}
