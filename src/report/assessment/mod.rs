//! The assessment report: `report.pdf` (A4) and every figure as its own SVG with a CSV twin, drawn from
//! the saved results of `slamtool assess` ([`data::Saved`]) without recomputing them.
//!
//! Contents (issue #11): title block with the SHA-256 of every input; the sign-off page (design
//! slamming loads with uncertainty, source, verdict and validity flags: [`signoff`]); summary (design pressure per
//! station and sensor, governing events, limit checks, every warning); hull (body plan, particulars);
//! motions (RAOs, natural periods, relative motion, slam statistics with Ochi's threshold); impact per
//! station (entry-velocity profile, pressure and force histories, particle snapshot at peak pressure);
//! results across the design space (peak pressure against speed and along the girth, analytic beside
//! SPH, convergence verdicts); comparison with published data (`comparisons` in summary.json, when
//! present); appendix (plotted numbers, run settings, the largest contour pressure of every run:
//! [`contour`]).

mod contour;
pub mod data;
mod forcing;
mod front;
mod impact;
mod motions;
mod signoff;
mod space;

use std::path::{Path, PathBuf};

use crate::error::Result;
use crate::files::{write_atomic, write_text_atomic};
use crate::report::document::{Block, Document};
use crate::report::figure::Figure;
pub use data::Saved;

/// A report being put together: the document, the figures drawn, and the figures refused.
#[derive(Debug, Default)]
pub struct Report {
    pub doc: Document,
    /// The figures drawn, with their SVG.
    pub figures: Vec<(Figure, String)>,
    /// Pictures written beside the figures (file name, PNG bytes).
    pub pngs: Vec<(String, Vec<u8>)>,
    /// Figures that were not drawn, with the reason (empty or non-finite data).
    pub refused: Vec<String>,
}

impl Report {
    /// Add a figure to the document, or, when its data cannot be drawn honestly, a note saying which
    /// figure and series were refused and why.
    pub fn figure(&mut self, fig: Figure, caption: &str, width_mm: f64) {
        match fig.svg() {
            Ok(svg) => {
                let n = self.figures.len() + 1;
                self.doc.blocks.push(Block::Svg {
                    svg: svg.clone(),
                    caption: format!("{caption} [figures/{:02}-{}.svg]", n, fig.id),
                    width_mm,
                });
                self.figures.push((fig, svg));
            }
            Err(e) => {
                self.doc
                    .blocks
                    .push(Block::Strong(format!("Not drawn: {e}")));
                self.refused.push(e.to_string());
            }
        }
    }

    pub fn push(&mut self, b: Block) {
        self.doc.blocks.push(b);
    }

    pub fn heading(&mut self, level: u8, text: &str) {
        self.push(Block::Heading {
            level,
            text: text.into(),
        });
    }

    pub fn para(&mut self, text: &str) {
        self.push(Block::Paragraph(text.into()));
    }
}

/// Build the report of the results in `saved`; `stamp` (e.g. a date) is printed under the title.
pub fn build(saved: &Saved, stamp: Option<String>) -> Result<Report> {
    let mut r = Report::default();
    front::title(&mut r, saved, stamp);
    signoff::page(&mut r, saved);
    front::summary(&mut r, saved);
    front::hull(&mut r, saved);
    motions::section(&mut r, saved);
    impact::section(&mut r, saved);
    space::design_space(&mut r, saved);
    space::comparison(&mut r, saved);
    space::appendix(&mut r, saved);
    Ok(r)
}

/// Whether `name` is a file a report writes in `figures/` (`NN-<id>.svg|.csv`, `peak_pressure_*.png`).
pub fn is_report_figure(name: &str) -> bool {
    let b = name.as_bytes();
    let numbered = b.len() > 3 && b[0].is_ascii_digit() && b[1].is_ascii_digit() && b[2] == b'-';
    (numbered && (name.ends_with(".svg") || name.ends_with(".csv")))
        || (name.starts_with("peak_pressure_") && name.ends_with(".png"))
}

/// The files a report writes: `report.pdf` and `figures/NN-<id>.svg|.csv|.png` in `out`.
pub fn write(r: &Report, out: &Path) -> Result<Vec<PathBuf>> {
    let figs = out.join("figures");
    std::fs::create_dir_all(&figs).map_err(|e| crate::error::Error::io(&figs, e))?;
    // Figures of an earlier report are removed first, so the folder holds this report's only; files
    // named otherwise are not a report's and are left alone.
    if let Ok(entries) = std::fs::read_dir(&figs) {
        for e in entries.flatten() {
            let name = e.file_name().to_string_lossy().into_owned();
            if is_report_figure(&name) {
                let _ = std::fs::remove_file(e.path());
            }
        }
    }
    // The figure files are written while the PDF is typeset (the typesetting is most of the time).
    let (figures, pdf_bytes) = rayon::join(
        || -> Result<Vec<PathBuf>> {
            let mut written = Vec::new();
            for (k, (f, text)) in r.figures.iter().enumerate() {
                let stem = format!("{:02}-{}", k + 1, f.id);
                let svg = figs.join(format!("{stem}.svg"));
                write_text_atomic(&svg, text)?;
                let csv = figs.join(format!("{stem}.csv"));
                write_text_atomic(&csv, &f.csv()?)?;
                written.extend([svg, csv]);
            }
            for (name, png) in &r.pngs {
                let p = figs.join(name);
                write_atomic(&p, png)?;
                written.push(p);
            }
            Ok(written)
        },
        || r.doc.pdf(),
    );
    let mut written = figures?;
    let pdf = out.join("report.pdf");
    write_atomic(&pdf, &pdf_bytes?)?;
    written.push(pdf);
    Ok(written)
}

/// What [`generate`] did.
#[derive(Debug)]
pub struct Generated {
    pub files: Vec<PathBuf>,
    /// Figures not drawn, with the reason.
    pub refused: Vec<String>,
    /// Wall time of reading the results and writing the report (s).
    pub time_s: f64,
}

/// File with the report step's wall time, beside summary.json (which stays byte-identical for
/// identical inputs; a time is not).
pub const TIMING_FILE: &str = "report_time.json";

/// Read the results in `results`, write the report into `out` (`report.pdf`, `figures/`) and the wall
/// time into `out/report_time.json`.
pub fn generate(results: &Path, out: &Path, stamp: Option<String>) -> Result<Generated> {
    let t0 = std::time::Instant::now();
    let saved = Saved::load(results)?;
    let report = build(&saved, stamp)?;
    let mut files = write(&report, out)?;
    let time_s = t0.elapsed().as_secs_f64();
    let timing = out.join(TIMING_FILE);
    let json = serde_json::json!({
        "report_time_s": (time_s * 1e3).round() / 1e3,
        "note": "wall time of `slamtool report` (reading the saved results, drawing, typesetting); kept \
                 out of summary.json so that identical inputs give a byte-identical summary",
    });
    write_text_atomic(&timing, &format!("{json:#}\n"))?;
    files.push(timing);
    Ok(Generated {
        files,
        refused: report.refused,
        time_s,
    })
}
