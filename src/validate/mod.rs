//! `slamtool validate`: the validation suite against published data (issue 12).
//!
//! Each case is data in the project: a case file in `validation/` ([`case`]) names the computation,
//! the quantity, the reference files (copied unchanged, with their provenance, into `data/reference/`)
//! and the tolerance with its reason, written before the result was seen. [`run`] computes each case
//! with the library functions the tool itself uses, [`compare`] gives the verdict, and [`report`]
//! writes the summary table (CSV, JSON, Markdown), one folder per case with its numbers, its
//! overlay plots of computed against reference curves (SVG with a CSV twin), its provenance and wall
//! time.

pub mod air;
pub mod case;
pub mod compare;
pub mod conditions;
pub mod document;
pub mod drops;
pub mod entry_velocities;
pub mod hermundstad_forcing;
pub mod known;
pub mod ochi_trends;
pub mod plot;
pub mod quoted;
pub mod report;
pub mod run;
pub mod seakeeping;
pub mod ships;
pub mod wedge_bounds;
pub mod wedge_references;
pub mod wedge_table;
pub mod wedges;

use std::time::Instant;

use serde::Serialize;

pub use case::{Case, Mode, Stated};
pub use compare::{Reference, Tolerance, Verdict};

/// One line or set of markers on a figure.
#[derive(Debug, Clone, Serialize)]
pub struct Series {
    pub label: String,
    /// Computed series are drawn as lines, reference data as markers.
    pub reference: bool,
    pub points: Vec<[f64; 2]>,
}

/// An overlay plot of computed and reference curves.
#[derive(Debug, Clone, Serialize)]
pub struct Figure {
    /// File stem of the SVG and CSV files.
    pub name: String,
    pub title: String,
    pub x_label: String,
    pub y_label: String,
    pub series: Vec<Series>,
}

/// A table of numbers (first row the header).
#[derive(Debug, Clone, Default, Serialize)]
pub struct Table {
    pub header: Vec<String>,
    pub rows: Vec<Vec<String>>,
}

/// What a case's computation gives.
#[derive(Debug, Clone)]
pub struct Outcome {
    pub computed: f64,
    pub reference: Reference,
    pub table: Option<Table>,
    pub figures: Vec<Figure>,
    /// Findings and caveats worked out during the run (printed in the case's section).
    pub notes: Vec<String>,
    /// Named numbers of the run, formatted with their units, that a case file's `known_failure` text
    /// quotes as `{name}` ([`known::explain`]), so that the explanation is made from this run's numbers.
    pub facts: Vec<(String, String)>,
}

impl Outcome {
    /// An outcome with no table, figure, note or fact yet.
    pub fn new(computed: f64, reference: Reference) -> Self {
        Outcome {
            computed,
            reference,
            table: None,
            figures: Vec::new(),
            notes: Vec::new(),
            facts: Vec::new(),
        }
    }

    /// Record a named number (already formatted, with its unit) for the known-failure text.
    pub fn fact(&mut self, name: &str, value: impl Into<String>) {
        self.facts.push((name.to_string(), value.into()));
    }
}

/// The result of one case.
#[derive(Debug, Clone, Serialize)]
pub struct CaseResult {
    pub name: String,
    pub title: String,
    pub kind: String,
    pub quantity: String,
    pub unit: String,
    pub computed: Option<f64>,
    pub reference: Option<Reference>,
    pub error: Option<f64>,
    pub tolerance: Tolerance,
    pub tolerance_reason: String,
    /// Whether the tolerance is as written before results were seen, or revised after.
    #[serde(flatten)]
    pub tolerance_stated: Stated,
    pub verdict: Verdict,
    /// The known-failure text, made from this run's numbers ([`known`]).
    pub known_failure: Option<String>,
    pub provenance: String,
    pub reference_files: Vec<String>,
    /// Every file the case reads (reference files, hull, sea state, drop-in data) with its SHA-256.
    pub inputs: Vec<crate::provenance::InputFile>,
    /// The physical conditions of the computation: water density, scale ([`conditions`]).
    pub conditions: Vec<(String, String)>,
    pub notes: Vec<String>,
    pub table: Option<Table>,
    #[serde(skip)]
    pub figures: Vec<Figure>,
    pub particles_per_half_beam: Option<f64>,
    pub wall_time_s: f64,
}

/// The whole suite.
#[derive(Debug, Clone, Serialize)]
pub struct Suite {
    pub mode: Mode,
    pub cases: Vec<CaseResult>,
    pub wall_time_s: f64,
}

impl Suite {
    /// Whether any case failed (a known failure does not count).
    pub fn failed(&self) -> bool {
        self.cases.iter().any(|c| c.verdict.is_failure())
    }
}

/// Run one case and compare it with its reference. A computation that fails gives the verdict
/// [`Verdict::Error`] with its message, and the other cases go on.
pub fn run_case(case: &Case, mode: Mode, memo: &run::Memo) -> CaseResult {
    let start = Instant::now();
    let outcome = run::run(case, mode, memo);
    let wall_time_s = start.elapsed().as_secs_f64();
    let root = std::env::current_dir().unwrap_or_default();
    let shown = |p: &std::path::Path| {
        let p = crate::provenance::lexically_normal(p);
        p.strip_prefix(&root)
            .unwrap_or(&p)
            .display()
            .to_string()
            .replace("\\", "/")
    };
    let mut notes = case.notes.clone();
    let marked = case.known_failure_in(mode);
    let mut known_failure = marked.map(|_| {
        "(the known-failure text quotes the run's numbers: the computation failed)".into()
    });
    let (computed, reference, error, mut verdict, table, figures) = match outcome {
        Ok(o) => {
            notes.extend(o.notes);
            let (error, within) = compare::assess(o.computed, &o.reference, case.tolerance);
            let mut v = compare::verdict(within, marked.is_some());
            if let Some(template) = marked {
                match known::text(template, &o.facts, o.computed, &o.reference, error, case, v) {
                    Ok(t) => known_failure = Some(t),
                    Err(e) => {
                        notes.push(e);
                        v = Verdict::Error;
                    }
                }
            }
            (
                Some(o.computed),
                Some(o.reference),
                error,
                v,
                o.table,
                o.figures,
            )
        }
        Err(e) => {
            notes.push(format!("the computation failed: {e}"));
            (None, None, None, Verdict::Error, None, Vec::new())
        }
    };
    // The case file first (unless the case was built from text in memory), then every file it reads:
    // what a CSV of this case depends on.
    let mut inputs = Vec::new();
    let own = Some(case.path.clone()).filter(|p| p.is_file());
    for p in own.into_iter().chain(case.input_files()) {
        match std::fs::read(&p) {
            Ok(bytes) => inputs.push(crate::provenance::InputFile {
                path: shown(&p),
                sha256: crate::provenance::sha256_hex(&bytes),
            }),
            Err(e) => {
                notes.push(format!("input {} cannot be read: {e}", shown(&p)));
                verdict = Verdict::Error;
            }
        }
    }
    CaseResult {
        name: case.name.clone(),
        title: case.title.clone(),
        kind: case.kind.clone(),
        quantity: case.quantity.clone(),
        unit: case.unit.clone(),
        computed,
        reference,
        error,
        tolerance: case.tolerance,
        tolerance_reason: case.tolerance_reason.clone(),
        tolerance_stated: case.tolerance_stated.clone(),
        verdict,
        known_failure,
        provenance: case.provenance.clone(),
        reference_files: case.reference_files.iter().map(|p| shown(p)).collect(),
        inputs,
        conditions: conditions::of(case),
        notes,
        table,
        figures,
        particles_per_half_beam: case.particles(mode).ok(),
        wall_time_s,
    }
}

/// Run the cases in order (each SPH run uses every core; the cases themselves run one after another,
/// so results do not depend on the thread count). `progress` is told each case's name before it runs.
pub fn run_suite(
    cases: &[Case],
    mode: Mode,
    work: std::path::PathBuf,
    progress: &mut dyn FnMut(&Case),
) -> Suite {
    let start = Instant::now();
    let memo = run::Memo::new(work, mode);
    let results = cases
        .iter()
        .map(|c| {
            progress(c);
            run_case(c, mode, &memo)
        })
        .collect();
    Suite {
        mode,
        cases: results,
        wall_time_s: start.elapsed().as_secs_f64(),
    }
}
