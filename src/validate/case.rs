//! Validation case files (`validation/<case>.toml`): what to run, the quantity compared, the tolerance
//! with its reason, the reference files with their provenance, and an optional `known_failure` reason.
//!
//! ```toml
//! title = "Zhao et al. (1996) 30 deg wedge, measured velocity imposed"
//! kind = "zhao1996-prescribed"          # the computation (see `run::KINDS`)
//! quantity = "peak force on the 0.2 m measuring section"
//! unit = "N"
//! reference_files = ["../data/reference/zhao1996_wedge30_drop.csv"]
//! provenance = "Zhao, Faltinsen & Aarsnes (1996), Fig. 15, eye-digitised by a third party"
//! # known_failure = "why the tolerance is not met ({computed} against {reference}), and why expected"
//!
//! [tolerance]
//! kind = "relative"     # relative | absolute | at-most | upper-bound | below-reference | within-range
//! value = 0.10
//! reason = "why this tolerance"
//! stated = "before-results"             # or "after-results", with `revision`: what changed, when, why
//!
//! [resolution]                          # SPH cases: particles over the half-beam
//! quick = 25.0
//! full = 40.0
//!
//! [parameters]                          # what the kind needs (numbers, strings, lists of numbers)
//! deadrise_deg = 30.0
//! ```
//!
//! `known_failure` quotes numbers only as placeholders filled from the run ([`super::known`]); a literal
//! number in it is refused. `stated` records whether the tolerance and its reason are as written before
//! any result was seen (`before-results`) or were revised after (`after-results`, with `revision`, as the
//! git history of the case file shows): the report prints which, never "set before the result was seen"
//! for a revised one.
//!
//! Every problem is reported as `file:line:column: reason`.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use toml::Spanned;

use super::compare::Tolerance;
use crate::error::{Error, Result};
use crate::input::SourceText;

/// Run mode of the suite.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Mode {
    /// Coarse resolution, for CI.
    Quick,
    /// Each case at its finer resolution, for the committed report (not a claim of convergence).
    Full,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCase {
    title: Spanned<String>,
    kind: Spanned<String>,
    quantity: Spanned<String>,
    unit: String,
    reference_files: Vec<Spanned<String>>,
    provenance: Spanned<String>,
    known_failure: Option<Spanned<String>>,
    /// The modes the known-failure mark applies in ("quick", "full"); all when absent.
    known_failure_modes: Option<Vec<Spanned<String>>>,
    #[serde(default)]
    notes: Vec<String>,
    tolerance: RawTolerance,
    resolution: Option<RawResolution>,
    #[serde(default)]
    parameters: BTreeMap<String, Spanned<toml::Value>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawTolerance {
    kind: Spanned<String>,
    value: Option<Spanned<f64>>,
    reason: Spanned<String>,
    stated: Spanned<String>,
    revision: Option<Spanned<String>>,
}

/// When a case's tolerance and its reason were written.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(tag = "stated", content = "revision", rename_all = "kebab-case")]
pub enum Stated {
    /// As written before any result of the case was seen.
    BeforeResults,
    /// Revised after results were seen: what changed, when and why.
    AfterResults(String),
}

impl Stated {
    /// The lead of the tolerance's reason in the report.
    pub fn lead(&self) -> String {
        match self {
            Stated::BeforeResults => "Tolerance, set before the result was seen".into(),
            Stated::AfterResults(r) => format!("Tolerance, revised after results were seen ({r})"),
        }
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawResolution {
    quick: Spanned<f64>,
    full: Spanned<f64>,
}

/// One validation case, read and checked.
#[derive(Debug, Clone)]
pub struct Case {
    /// The file name without `.toml`.
    pub name: String,
    pub path: PathBuf,
    pub title: String,
    pub kind: String,
    pub quantity: String,
    pub unit: String,
    /// Reference files, resolved against the case file's folder (each exists).
    pub reference_files: Vec<PathBuf>,
    pub provenance: String,
    pub known_failure: Option<String>,
    /// The modes `known_failure` applies in (both when the case file does not restrict it): a case
    /// can be expected to fail at the quick level only, where its resolution is too coarse.
    pub known_failure_modes: Vec<Mode>,
    pub notes: Vec<String>,
    pub tolerance: Tolerance,
    pub tolerance_reason: String,
    pub tolerance_stated: Stated,
    /// Particles over the half-beam at (quick, full).
    pub resolution: Option<(f64, f64)>,
    params: BTreeMap<String, Spanned<toml::Value>>,
    src: SourceText,
}

fn non_empty(src: &SourceText, v: &Spanned<String>, what: &str) -> Result<String> {
    if v.get_ref().trim().is_empty() {
        return Err(Error::Input(
            src.error(v, format!("{what} must not be empty")),
        ));
    }
    Ok(v.get_ref().trim().to_string())
}

impl Case {
    /// Read a case file from disk.
    pub fn from_file(path: &Path) -> Result<Self> {
        Self::from_source(SourceText::read(path)?)
    }

    /// Read a case from its text (`src.path` names it and is the base of relative paths).
    pub fn from_source(src: SourceText) -> Result<Self> {
        let raw: RawCase = src.parse_toml().map_err(Error::Input)?;
        let name = src
            .path
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let kind = raw.kind.get_ref().clone();
        if !super::run::KINDS.contains(&kind.as_str()) {
            return Err(Error::Input(src.error(
                &raw.kind,
                format!(
                    "unknown kind `{kind}`; one of: {}",
                    super::run::KINDS.join(", ")
                ),
            )));
        }
        let t = &raw.tolerance;
        let value = |what: &str| -> Result<f64> {
            match &t.value {
                Some(v) if v.get_ref().is_finite() && *v.get_ref() > 0.0 => Ok(*v.get_ref()),
                Some(v) => Err(Error::Input(
                    src.error(v, format!("the {what} tolerance must be a positive number")),
                )),
                None => Err(Error::Input(
                    src.error(&t.kind, format!("a `{what}` tolerance needs `value`")),
                )),
            }
        };
        let tolerance = match t.kind.get_ref().as_str() {
            "relative" => Tolerance::Relative {
                value: value("relative")?,
            },
            "absolute" => Tolerance::Absolute {
                value: value("absolute")?,
            },
            "at-most" => Tolerance::AtMost {
                value: value("at-most")?,
            },
            "upper-bound" => Tolerance::UpperBound {
                value: value("upper-bound")?,
            },
            "below-reference" => Tolerance::BelowReference,
            "within-range" => Tolerance::WithinRange,
            other => {
                return Err(Error::Input(src.error(
                    &t.kind,
                    format!(
                        "unknown tolerance kind `{other}`; one of: relative, absolute, at-most, \
                         upper-bound, below-reference, within-range"
                    ),
                )));
            }
        };
        let tolerance_reason = non_empty(&src, &t.reason, "the tolerance's reason")?;
        let tolerance_stated = match (t.stated.get_ref().as_str(), &t.revision) {
            ("before-results", None) => Stated::BeforeResults,
            ("before-results", Some(r)) => {
                return Err(Error::Input(src.error(
                    r,
                    "a `revision` belongs to a tolerance stated \"after-results\"",
                )));
            }
            ("after-results", Some(r)) => {
                Stated::AfterResults(non_empty(&src, r, "the tolerance's revision")?)
            }
            ("after-results", None) => {
                return Err(Error::Input(src.error(
                    &t.stated,
                    "a tolerance revised after results needs `revision`: what changed, when and why",
                )));
            }
            (other, _) => {
                return Err(Error::Input(src.error(
                    &t.stated,
                    format!("`stated` is \"before-results\" or \"after-results\", not `{other}`"),
                )));
            }
        };
        let base = src.path.parent().unwrap_or(Path::new(".")).to_path_buf();
        let mut reference_files = Vec::new();
        for f in &raw.reference_files {
            let p = base.join(f.get_ref());
            if !p.is_file() {
                return Err(Error::Input(
                    src.error(f, format!("reference file {} not found", p.display())),
                ));
            }
            reference_files.push(p);
        }
        let resolution = match &raw.resolution {
            Some(r) => {
                for v in [&r.quick, &r.full] {
                    if !(v.get_ref().is_finite() && *v.get_ref() >= 4.0 && *v.get_ref() <= 400.0) {
                        return Err(Error::Input(src.error(
                            v,
                            "particles over the half-beam must be between 4 and 400",
                        )));
                    }
                }
                Some((*r.quick.get_ref(), *r.full.get_ref()))
            }
            None => None,
        };
        let known_failure = match &raw.known_failure {
            Some(k) => {
                if let Some((_, n)) = super::known::literal_number(k.get_ref()) {
                    return Err(Error::Input(src.error(
                        k,
                        format!(
                            "known_failure quotes the number {n} as text: quote the run's numbers as \
                             placeholders ({{computed}}, {{reference}}, {{error}}, {{tolerance}} or a fact \
                             of the computation), so that the text cannot go stale"
                        ),
                    )));
                }
                Some(non_empty(&src, k, "known_failure")?)
            }
            None => None,
        };
        let known_failure_modes = match &raw.known_failure_modes {
            None => vec![Mode::Quick, Mode::Full],
            Some(list) => {
                if known_failure.is_none() {
                    return Err(Error::Input(src.error(
                        &list[0],
                        "known_failure_modes without a known_failure text".to_string(),
                    )));
                }
                let mut modes = Vec::new();
                for m in list {
                    modes.push(match m.get_ref().as_str() {
                        "quick" => Mode::Quick,
                        "full" => Mode::Full,
                        other => {
                            return Err(Error::Input(src.error(
                                m,
                                format!("unknown mode '{other}': use \"quick\" or \"full\""),
                            )));
                        }
                    });
                }
                modes
            }
        };
        Ok(Case {
            name,
            title: non_empty(&src, &raw.title, "title")?,
            kind,
            quantity: non_empty(&src, &raw.quantity, "quantity")?,
            unit: raw.unit,
            reference_files,
            provenance: non_empty(&src, &raw.provenance, "provenance")?,
            known_failure,
            known_failure_modes,
            notes: raw.notes,
            tolerance,
            tolerance_reason,
            tolerance_stated,
            resolution,
            params: raw.parameters,
            path: src.path.clone(),
            src,
        })
    }

    /// An error located at a parameter (or at the top of the file when it is missing).
    fn param_error(&self, key: &str, message: String) -> Error {
        match self.params.get(key) {
            Some(v) => Error::Input(self.src.error(v, message)),
            None => Error::Input(self.src.error_line(1, 1, message)),
        }
    }

    /// A number parameter.
    pub fn number(&self, key: &str) -> Result<f64> {
        let v = self.params.get(key).ok_or_else(|| {
            self.param_error(
                key,
                format!("kind `{}` needs `parameters.{key}` (a number)", self.kind),
            )
        })?;
        let x = match v.get_ref() {
            toml::Value::Float(x) => *x,
            toml::Value::Integer(i) => *i as f64,
            _ => f64::NAN,
        };
        if !x.is_finite() {
            return Err(self.param_error(key, format!("`{key}` must be a finite number")));
        }
        Ok(x)
    }

    /// A number parameter that must lie in the open interval (lo, hi) (`hi` infinite for "positive");
    /// outside it, an error located at the parameter says what it must be.
    pub fn number_between(&self, key: &str, lo: f64, hi: f64) -> Result<f64> {
        let x = self.number(key)?;
        if x > lo && x < hi {
            return Ok(x);
        }
        let must = if hi.is_infinite() {
            format!("above {lo}")
        } else {
            format!("between {lo} and {hi} (exclusive)")
        };
        Err(self.param_error(key, format!("`{key}` is {x}: it must be {must}")))
    }

    /// A list of numbers.
    pub fn numbers(&self, key: &str) -> Result<Vec<f64>> {
        let v = self.params.get(key).ok_or_else(|| {
            self.param_error(
                key,
                format!(
                    "kind `{}` needs `parameters.{key}` (a list of numbers)",
                    self.kind
                ),
            )
        })?;
        let bad = || self.param_error(key, format!("`{key}` must be a list of numbers"));
        let arr = v.get_ref().as_array().ok_or_else(bad)?;
        arr.iter()
            .map(|x| match x {
                toml::Value::Float(x) if x.is_finite() => Ok(*x),
                toml::Value::Integer(i) => Ok(*i as f64),
                _ => Err(bad()),
            })
            .collect()
    }

    /// A text parameter.
    pub fn text(&self, key: &str) -> Result<String> {
        let v = self.params.get(key).ok_or_else(|| {
            self.param_error(
                key,
                format!("kind `{}` needs `parameters.{key}` (text)", self.kind),
            )
        })?;
        v.get_ref()
            .as_str()
            .map(str::to_string)
            .ok_or_else(|| self.param_error(key, format!("`{key}` must be text")))
    }

    /// A path parameter, resolved against the case file's folder; the file must exist.
    pub fn file(&self, key: &str) -> Result<PathBuf> {
        let p = self
            .path
            .parent()
            .unwrap_or(Path::new("."))
            .join(self.text(key)?);
        if !p.is_file() {
            return Err(self.param_error(key, format!("file {} not found", p.display())));
        }
        Ok(p)
    }

    /// The declared reference file whose name is `file_name`.
    pub fn reference(&self, file_name: &str) -> Result<&Path> {
        self.reference_files
            .iter()
            .find(|p| p.file_name().is_some_and(|n| n == file_name))
            .map(PathBuf::as_path)
            .ok_or_else(|| {
                Error::Input(self.src.error_line(
                    1,
                    1,
                    format!(
                        "kind `{}` reads {file_name}: list it in `reference_files`",
                        self.kind
                    ),
                ))
            })
    }

    /// Every file the case reads: its reference files and each text parameter naming an existing file
    /// (hull, sea state, drop-in data), resolved against the case file's folder.
    pub fn input_files(&self) -> Vec<PathBuf> {
        let base = self.path.parent().unwrap_or(Path::new("."));
        let mut out = self.reference_files.clone();
        for v in self.params.values() {
            if let Some(t) = v.get_ref().as_str() {
                let p = base.join(t);
                if p.is_file() && !out.contains(&p) {
                    out.push(p);
                }
            }
        }
        out
    }

    /// Particles over the half-beam for the mode.
    /// The case's known-failure text when its mark applies in `mode`.
    pub fn known_failure_in(&self, mode: Mode) -> Option<&String> {
        self.known_failure
            .as_ref()
            .filter(|_| self.known_failure_modes.contains(&mode))
    }

    /// The list of resolution levels (particles over the half-beam) for the mode: `levels_quick` or
    /// `levels_full`.
    pub fn levels(&self, mode: Mode) -> Result<Vec<f64>> {
        self.numbers(match mode {
            Mode::Quick => "levels_quick",
            Mode::Full => "levels_full",
        })
    }

    pub fn particles(&self, mode: Mode) -> Result<f64> {
        match (self.resolution, mode) {
            (Some((q, _)), Mode::Quick) => Ok(q),
            (Some((_, f)), Mode::Full) => Ok(f),
            (None, _) => Err(Error::Input(self.src.error_line(
                1,
                1,
                format!(
                    "kind `{}` runs SPH: it needs a [resolution] table",
                    self.kind
                ),
            ))),
        }
    }
}

/// Every case file (`*.toml`) in a folder, in name order.
pub fn case_files(dir: &Path) -> Result<Vec<PathBuf>> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).map_err(|e| Error::io(dir, e))? {
        let p = e.map_err(|e| Error::io(dir, e))?.path();
        if p.extension().is_some_and(|x| x == "toml") && p.is_file() {
            out.push(p);
        }
    }
    out.sort();
    Ok(out)
}
