//! The files of a sweep: `sweep.json`, the tidy `results.csv`, `cases.csv`, `best.csv`, the response plots
//! (`plots/<quantity>_vs_<parameter>.svg`, each with its CSV twin), all written atomically; and
//! [`report_content`], the figures and tables a sweep report is made of.

use std::path::{Path, PathBuf};

use plotters::prelude::*;

use super::results::{self, SweepResult};
use crate::error::{Error, Result};
use crate::files::write_text_atomic;
use crate::plot::{FONT, draw_error, register_font};
use crate::provenance::tidy_numbers;
use crate::report::csv_number;

/// A response plot: one quantity of every case against one parameter.
#[derive(Debug, Clone)]
pub struct ResponsePlot {
    /// File stem, e.g. `design_pressure_vs_speed_m_s`.
    pub stem: String,
    pub title: String,
    pub parameter: String,
    pub quantity: String,
    /// (parameter value, quantity, case id), in case order.
    pub points: Vec<(f64, f64, String)>,
    pub svg: String,
    pub csv: String,
}

/// The content of a sweep report: response plots, the best-variants table (header and rows) and its rule
/// in words, and the case table.
#[derive(Debug, Clone)]
pub struct ReportContent {
    pub title: String,
    pub plots: Vec<ResponsePlot>,
    pub best_rule: String,
    pub best_header: Vec<String>,
    pub best_rows: Vec<Vec<String>>,
    /// Why `best_rows` is empty, when it is ([`results::why_no_best`]).
    pub no_best: String,
    pub cases: usize,
    pub failed_cases: usize,
}

fn scatter_svg(title: &str, xdesc: &str, ydesc: &str, pts: &[(f64, f64)]) -> Result<String> {
    register_font();
    let (mut x0, mut x1) = pts.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| {
        (a.0.min(p.0), a.1.max(p.0))
    });
    let (mut y0, mut y1) = pts.iter().fold((0.0f64, f64::NEG_INFINITY), |a, p| {
        (a.0.min(p.1), a.1.max(p.1))
    });
    if x1.partial_cmp(&x0) != Some(std::cmp::Ordering::Greater) {
        x0 -= 0.5 * x0.abs().max(1.0);
        x1 += 0.5 * x1.abs().max(1.0);
    }
    if y1.partial_cmp(&y0) != Some(std::cmp::Ordering::Greater) {
        y1 = y0 + 1.0;
    }
    let px = 0.05 * (x1 - x0);
    let py = 0.08 * (y1 - y0);
    (x0, x1, y0, y1) = (x0 - px, x1 + px, y0, y1 + py);
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (800, 520)).into_drawing_area();
        root.fill(&WHITE).map_err(draw_error)?;
        let mut chart = ChartBuilder::on(&root)
            .margin(20)
            .caption(title, (FONT, 17))
            .x_label_area_size(50)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(draw_error)?;
        chart
            .configure_mesh()
            .x_desc(xdesc)
            .y_desc(ydesc)
            .label_style((FONT, 13))
            .axis_desc_style((FONT, 14))
            .draw()
            .map_err(draw_error)?;
        chart
            .draw_series(
                pts.iter()
                    .map(|p| Circle::new((p.0, p.1), 3, RGBColor(0, 90, 200).filled())),
            )
            .map_err(draw_error)?;
    }
    Ok(svg)
}

/// A plotted quantity: file stem, axis text, CSV column and how to get it from a case.
type Quantity = (
    &'static str,
    &'static str,
    &'static str,
    fn(&results::CaseResult) -> Option<f64>,
);

/// The response plots of a sweep: the largest design pressure (kPa) and, with an irregular sea, the
/// largest slam probability of each case against each numeric parameter varied.
pub fn response_plots(r: &SweepResult) -> Result<Vec<ResponsePlot>> {
    let prov = r.provenance.provenance();
    let mut out = Vec::new();
    let quantities: [Quantity; 2] = [
        (
            "design_pressure",
            "largest sensor design pressure (kPa)",
            "design_pressure_kpa",
            |c| c.max_design_pressure_pa.map(|p| p / 1e3),
        ),
        (
            "slam_probability",
            "largest slam probability per encounter",
            "slam_probability",
            |c| c.max_slam_probability,
        ),
    ];
    for p in r.parameters.iter().filter(|p| *p != "wave") {
        for (stem, desc, column, get) in &quantities {
            let points: Vec<(f64, f64, String)> = r
                .cases
                .iter()
                .filter(|c| c.failed.is_none())
                .filter_map(|c| Some((c.param(p)?, get(c)?, c.id.clone())))
                .collect();
            if points.is_empty() {
                continue;
            }
            let title = format!("{}: {desc} against {p}", r.name);
            let xy: Vec<(f64, f64)> = points.iter().map(|q| (q.0, q.1)).collect();
            let svg = scatter_svg(&title, p, desc, &xy)?;
            let rows: Vec<Vec<String>> = points
                .iter()
                .map(|q| vec![q.2.clone(), csv_number(q.0), csv_number(q.1)])
                .collect();
            let header = vec!["case".to_string(), p.clone(), column.to_string()];
            let csv = crate::sph::output::csv_text(Some(&prov), &header, &rows)?;
            out.push(ResponsePlot {
                stem: format!("{stem}_vs_{p}"),
                title,
                parameter: p.clone(),
                quantity: column.to_string(),
                points,
                svg,
                csv,
            });
        }
    }
    Ok(out)
}

/// Figures and tables of a sweep report (the report generator lays them out).
pub fn report_content(r: &SweepResult) -> Result<ReportContent> {
    let chosen = results::best(r, &r.best);
    let mut best_header = vec!["rank".to_string(), "case".to_string()];
    best_header.extend(r.parameters.iter().cloned());
    best_header.extend(
        [
            "max design pressure (kPa)",
            "max slam probability",
            "max section force (N/m)",
        ]
        .map(String::from),
    );
    let f = |v: Option<f64>, k: f64, d: usize| v.map_or("-".into(), |x| format!("{:.d$}", x * k));
    let best_rows = chosen
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let mut row = vec![(i + 1).to_string(), c.id.clone()];
            for p in &r.parameters {
                row.push(if p == "wave" {
                    c.wave.clone().unwrap_or_default()
                } else {
                    c.param(p).map_or("-".into(), |v| format!("{v:.4}"))
                });
            }
            row.push(f(c.max_design_pressure_pa, 1e-3, 2));
            row.push(f(c.max_slam_probability, 1.0, 4));
            row.push(f(c.max_section_force_n_per_m, 1.0, 1));
            row
        })
        .collect();
    Ok(ReportContent {
        title: format!("Design-space sweep: {}", r.name),
        plots: response_plots(r)?,
        best_rule: results::rule_text(&r.best),
        best_header,
        best_rows,
        no_best: results::why_no_best(r, &r.best),
        cases: r.cases.len(),
        failed_cases: r.failed_cases,
    })
}

/// Names a sweep writes into its folder (anything else there is refused unless forced).
pub const KNOWN: [&str; 9] = [
    "sweep.json",
    "report.pdf",
    "results.csv",
    "cases.csv",
    "best.csv",
    "plots",
    "hulls",
    "cache",
    "runs",
];

/// Write every file of a sweep result into `dir`; returns the paths.
pub fn write(dir: &Path, r: &SweepResult) -> Result<Vec<PathBuf>> {
    let mut written = Vec::new();
    let v = serde_json::to_value(r).map_err(|e| Error::Invalid(format!("sweep.json: {e}")))?;
    let json = serde_json::to_string_pretty(&tidy_numbers(v))
        .map_err(|e| Error::Invalid(format!("sweep.json: {e}")))?;
    for (name, text) in [
        ("sweep.json", json + "\n"),
        ("results.csv", results::results_csv(r)?),
        ("cases.csv", results::cases_csv(r)?),
        ("best.csv", results::best_csv(r)?),
    ] {
        let p = dir.join(name);
        write_text_atomic(&p, &text)?;
        written.push(p);
    }
    let plots = dir.join("plots");
    if plots.is_dir() {
        // Plots of an earlier run whose parameters are gone would mislead.
        for e in std::fs::read_dir(&plots)
            .map_err(|e| Error::io(&plots, e))?
            .flatten()
        {
            let _ = std::fs::remove_file(e.path());
        }
    }
    for p in response_plots(r)? {
        for (ext, text) in [("svg", &p.svg), ("csv", &p.csv)] {
            let path = plots.join(format!("{}.{ext}", p.stem));
            write_text_atomic(&path, text)?;
            written.push(path);
        }
    }
    written.push(super::report::write_pdf(dir, r)?);
    Ok(written)
}
