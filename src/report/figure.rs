//! Report figures: x-y charts drawn with plotters as SVG, each with a CSV twin of every plotted number.
//!
//! A [`Figure`] is data (axis labels with units, series of points, reference lines); [`Figure::svg`]
//! draws it and [`Figure::csv`] lists what was drawn. A figure with no series, a series with no points,
//! or a non-finite number anywhere is **refused** with an error naming the figure and the series: the
//! report never shows a blank or misleading plot.
//!
//! Legends are drawn below the plot area, never over the data. Colours come from one palette
//! ([`PALETTE`]) indexed by the caller, so a sensor keeps its colour on every page. Text is set in the
//! bundled DejaVu Sans ([`crate::plot::FONT`]).

use plotters::prelude::*;
use plotters::style::text_anchor::{HPos, Pos, VPos};

use crate::error::{Error, Result};
use crate::plot::{FONT, draw_error, register_font};

/// Colours by index (the colour-blind-safe set of Wong 2011, then grey, dark red, olive, navy); index
/// modulo the length.
pub const PALETTE: [RGBColor; 11] = [
    RGBColor(0, 114, 178),
    RGBColor(213, 94, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(230, 159, 0),
    RGBColor(86, 180, 233),
    RGBColor(0, 0, 0),
    RGBColor(120, 120, 120),
    RGBColor(150, 20, 20),
    RGBColor(120, 120, 0),
    RGBColor(20, 30, 120),
];

/// A colour of the palette.
pub fn colour(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Mark {
    /// A line through the points.
    Line,
    /// A thin line through the points.
    ThinLine,
    /// A line with a small marker at each point.
    LineDots,
    /// Filled circles.
    Dot,
    /// Open circles.
    Ring,
    /// Open triangles.
    Triangle,
    /// Crosses.
    Cross,
    /// Open squares.
    Square,
}

/// One named series of (x, y) points.
#[derive(Debug, Clone)]
pub struct Series {
    pub name: String,
    pub points: Vec<(f64, f64)>,
    /// Palette index ([`colour`]).
    pub colour: usize,
    pub mark: Mark,
}

impl Series {
    pub fn new(
        name: impl Into<String>,
        points: Vec<(f64, f64)>,
        colour: usize,
        mark: Mark,
    ) -> Self {
        Self {
            name: name.into(),
            points,
            colour,
            mark,
        }
    }
}

/// A horizontal reference line (e.g. Ochi's threshold velocity) with its label.
#[derive(Debug, Clone)]
pub struct RefLine {
    pub y: f64,
    pub label: String,
}

/// An x-y chart.
#[derive(Debug, Clone)]
pub struct Figure {
    /// File stem of the SVG and CSV files (e.g. `peak_pressure_vs_speed_0.093`).
    pub id: String,
    pub title: String,
    /// Axis labels with units, e.g. "speed U (m/s)".
    pub x_label: String,
    pub y_label: String,
    pub series: Vec<Series>,
    pub ref_lines: Vec<RefLine>,
    /// Start the y axis at zero (pressures, probabilities).
    pub y_from_zero: bool,
    /// Width and height of the plot in pixels (legend rows are added below).
    pub size: (u32, u32),
    /// Top of the y axis, below the data's largest value: lines above it run along the top of the frame
    /// and markers above it are left out (the caption must say what is cut; the CSV keeps every point).
    pub y_max: Option<f64>,
}

impl Figure {
    pub fn new(id: &str, title: &str, x_label: &str, y_label: &str) -> Self {
        Self {
            id: id.into(),
            title: title.into(),
            x_label: x_label.into(),
            y_label: y_label.into(),
            series: Vec::new(),
            ref_lines: Vec::new(),
            y_from_zero: false,
            size: (800, 420),
            y_max: None,
        }
    }

    /// Refuse what cannot be drawn honestly: no series, an empty series, a non-finite number.
    pub fn check(&self) -> Result<()> {
        let refuse = |why: String| {
            Err(Error::Invalid(format!(
                "figure '{}' ({}) not drawn: {why}",
                self.id, self.title
            )))
        };
        if self.series.is_empty() {
            return refuse("it has no data series".into());
        }
        for s in &self.series {
            if s.points.is_empty() {
                return refuse(format!("series '{}' is empty", s.name));
            }
            if let Some((i, p)) = s
                .points
                .iter()
                .enumerate()
                .find(|(_, p)| !(p.0.is_finite() && p.1.is_finite()))
            {
                return refuse(format!(
                    "series '{}' has a non-finite value at point {} ({}, {})",
                    s.name,
                    i + 1,
                    p.0,
                    p.1
                ));
            }
        }
        if let Some(r) = self.ref_lines.iter().find(|r| !r.y.is_finite()) {
            return refuse(format!("reference line '{}' is not finite", r.label));
        }
        Ok(())
    }

    /// Axis ranges with 5 % padding (and a non-zero span).
    fn ranges(&self) -> ((f64, f64), (f64, f64)) {
        let pts = self.series.iter().flat_map(|s| s.points.iter());
        let (mut x0, mut x1, mut y0, mut y1) = (f64::MAX, f64::MIN, f64::MAX, f64::MIN);
        for &(x, y) in pts {
            x0 = x0.min(x);
            x1 = x1.max(x);
            y0 = y0.min(y);
            y1 = y1.max(y);
        }
        for r in &self.ref_lines {
            y0 = y0.min(r.y);
            y1 = y1.max(r.y);
        }
        if self.y_from_zero {
            y0 = y0.min(0.0);
        }
        if let Some(m) = self.y_max.filter(|&m| m > y0) {
            y1 = y1.min(m);
        }
        let pad = |a: f64, b: f64| {
            let span = if b > a { b - a } else { a.abs().max(1.0) * 0.1 };
            (a - 0.05 * span, b + 0.05 * span)
        };
        let (mut ya, yb) = pad(y0, y1);
        if self.y_from_zero && y0 >= 0.0 {
            ya = 0.0;
        }
        (pad(x0, x1), (ya, yb))
    }

    /// Legend entries (series, then reference lines) laid out in rows of `per_row`.
    fn legend_rows(&self) -> usize {
        let n = self.series.len() + self.ref_lines.len();
        n.div_ceil(self.per_row())
    }

    fn per_row(&self) -> usize {
        let longest = self
            .series
            .iter()
            .map(|s| s.name.chars().count())
            .chain(self.ref_lines.iter().map(|r| r.label.chars().count()))
            .max()
            .unwrap_or(1);
        // About 7.5 px per character at 13 px, plus the sample.
        ((self.size.0 as usize - 40) / (longest * 8 + 50)).clamp(1, 4)
    }

    /// The figure as an SVG document (after [`Figure::check`]).
    pub fn svg(&self) -> Result<String> {
        self.check()?;
        register_font();
        let legend_h = 20 * self.legend_rows() as u32 + 10;
        let size = (self.size.0, self.size.1 + legend_h);
        let ((x0, x1), (y0, y1)) = self.ranges();
        let mut out = String::new();
        {
            let root = SVGBackend::with_string(&mut out, size).into_drawing_area();
            root.fill(&WHITE).map_err(draw_error)?;
            let (plot, legend) = root.split_vertically(self.size.1);
            let mut chart = ChartBuilder::on(&plot)
                .margin(12)
                .margin_right(24)
                .caption(&self.title, (FONT, 17))
                .x_label_area_size(48)
                .y_label_area_size(72)
                .build_cartesian_2d(x0..x1, y0..y1)
                .map_err(draw_error)?;
            chart
                .configure_mesh()
                .x_desc(&self.x_label)
                .y_desc(&self.y_label)
                .x_labels(7)
                .y_labels(7)
                .x_label_formatter(&|v| tick(*v, x1 - x0))
                .y_label_formatter(&|v| tick(*v, y1 - y0))
                .label_style((FONT, 13))
                .axis_desc_style((FONT, 14))
                .light_line_style(RGBColor(235, 235, 235))
                .bold_line_style(RGBColor(215, 215, 215))
                .draw()
                .map_err(draw_error)?;
            for r in &self.ref_lines {
                chart
                    .draw_series(LineSeries::new(
                        [(x0, r.y), (x1, r.y)],
                        ShapeStyle::from(&RGBColor(200, 0, 0)).stroke_width(1),
                    ))
                    .map_err(draw_error)?;
            }
            // with a cut axis, lines run along the top of the frame and markers above it are left out
            let top = if self.y_max.is_some() {
                y1
            } else {
                f64::INFINITY
            };
            for s in &self.series {
                let c = colour(s.colour);
                let pts = s.points.iter().copied().filter(|p| p.1 <= top);
                let e = draw_error;
                match s.mark {
                    Mark::Line | Mark::ThinLine | Mark::LineDots => {
                        let w = if s.mark == Mark::ThinLine { 1 } else { 2 };
                        let clamped = s.points.iter().map(|&(x, y)| (x, y.min(top)));
                        chart
                            .draw_series(LineSeries::new(clamped, c.stroke_width(w)))
                            .map_err(e)?;
                        if s.mark == Mark::LineDots {
                            chart
                                .draw_series(pts.map(|p| Circle::new(p, 3, c.filled())))
                                .map_err(e)?;
                        }
                    }
                    Mark::Dot => {
                        chart
                            .draw_series(pts.map(|p| Circle::new(p, 5, c.filled())))
                            .map_err(e)?;
                    }
                    Mark::Ring => {
                        chart
                            .draw_series(pts.map(|p| Circle::new(p, 5, c.stroke_width(2))))
                            .map_err(e)?;
                    }
                    Mark::Triangle => {
                        chart
                            .draw_series(pts.map(|p| TriangleMarker::new(p, 6, c.stroke_width(2))))
                            .map_err(e)?;
                    }
                    Mark::Cross => {
                        chart
                            .draw_series(pts.map(|p| Cross::new(p, 5, c.stroke_width(2))))
                            .map_err(e)?;
                    }
                    Mark::Square => {
                        chart
                            .draw_series(pts.map(|p| {
                                EmptyElement::at(p)
                                    + Rectangle::new([(-5, -5), (5, 5)], c.stroke_width(2))
                            }))
                            .map_err(e)?;
                    }
                }
            }
            draw_legend(self, &legend)?;
            root.present().map_err(draw_error)?;
        }
        Ok(out)
    }

    /// Every plotted number: one row per point (series, x, y), headed by the axis labels.
    pub fn csv(&self) -> Result<String> {
        self.check()?;
        let mut w = csv::Writer::from_writer(Vec::new());
        let err = |e: csv::Error| Error::Invalid(format!("figure '{}' CSV: {e}", self.id));
        w.write_record(["series", &self.x_label, &self.y_label])
            .map_err(err)?;
        for s in &self.series {
            for &(x, y) in &s.points {
                w.write_record([
                    s.name.as_str(),
                    &crate::report::csv_number(x),
                    &crate::report::csv_number(y),
                ])
                .map_err(err)?;
            }
        }
        for r in &self.ref_lines {
            w.write_record([r.label.as_str(), "", &crate::report::csv_number(r.y)])
                .map_err(err)?;
        }
        let body = w
            .into_inner()
            .map_err(|e| Error::Invalid(format!("figure '{}' CSV: {e}", self.id)))?;
        Ok(format!(
            "# figure {}: {}\n{}",
            self.id,
            self.title.replace('\n', " "),
            String::from_utf8_lossy(&body)
        ))
    }
}

/// Tick label with as many decimals as the tick step needs (no long float tails). Ticks are at multiples
/// of 1, 2 or 5 times a power of ten, at least span/7 apart, so -floor(log10(span/7)) decimals are enough.
fn tick(v: f64, span: f64) -> String {
    let d = if span > 0.0 {
        (-(span / 7.0).log10().floor()).clamp(0.0, 6.0) as usize
    } else {
        2
    };
    let s = format!("{v:.d$}");
    if s.starts_with('-') && s[1..].chars().all(|c| c == '0' || c == '.') {
        s[1..].to_string()
    } else {
        s
    }
}

fn draw_legend(
    f: &Figure,
    area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
) -> Result<()> {
    let per_row = f.per_row();
    let col_w = (f.size.0 as i32 - 40) / per_row as i32;
    let style = TextStyle::from((FONT, 13).into_font()).pos(Pos::new(HPos::Left, VPos::Center));
    let mut entries: Vec<(String, Option<(RGBColor, Mark)>)> = f
        .series
        .iter()
        .map(|s| (s.name.clone(), Some((colour(s.colour), s.mark))))
        .collect();
    entries.extend(f.ref_lines.iter().map(|r| (r.label.clone(), None)));
    for (k, (name, how)) in entries.iter().enumerate() {
        let x = 30 + (k % per_row) as i32 * col_w;
        let y = 12 + (k / per_row) as i32 * 20;
        let (c, m) = how.unwrap_or((RGBColor(200, 0, 0), Mark::ThinLine));
        match m {
            Mark::Line | Mark::ThinLine | Mark::LineDots => {
                let w = if m == Mark::ThinLine { 1 } else { 2 };
                area.draw(&PathElement::new(
                    vec![(x, y), (x + 30, y)],
                    c.stroke_width(w),
                ))
                .map_err(draw_error)?;
                if m == Mark::LineDots {
                    area.draw(&Circle::new((x + 15, y), 3, c.filled()))
                        .map_err(draw_error)?;
                }
            }
            _ => draw_pixel_marker(area, (x + 15, y), m, c)?,
        }
        area.draw(&Text::new(name.clone(), (x + 38, y), style.clone()))
            .map_err(draw_error)?;
    }
    Ok(())
}

fn draw_pixel_marker(
    area: &DrawingArea<SVGBackend<'_>, plotters::coord::Shift>,
    (x, y): (i32, i32),
    m: Mark,
    c: RGBColor,
) -> Result<()> {
    let r = match m {
        Mark::Ring => area.draw(&Circle::new((x, y), 5, c.stroke_width(2))),
        Mark::Triangle => area.draw(&TriangleMarker::new((x, y), 6, c.stroke_width(2))),
        Mark::Cross => area
            .draw(&PathElement::new(
                vec![(x - 5, y - 5), (x + 5, y + 5)],
                c.stroke_width(2),
            ))
            .and_then(|_| {
                area.draw(&PathElement::new(
                    vec![(x - 5, y + 5), (x + 5, y - 5)],
                    c.stroke_width(2),
                ))
            }),
        Mark::Square => area.draw(&Rectangle::new(
            [(x - 5, y - 5), (x + 5, y + 5)],
            c.stroke_width(2),
        )),
        _ => area.draw(&Circle::new((x, y), 5, c.filled())),
    };
    r.map_err(draw_error)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn fig() -> Figure {
        let mut f = Figure::new("t", "test", "x (m)", "y (Pa)");
        f.series.push(Series::new(
            "a",
            vec![(0.0, 1.0), (1.0, 2.0)],
            0,
            Mark::Line,
        ));
        f
    }

    #[test]
    fn a_nan_series_is_refused_with_figure_and_series_named() {
        let mut f = fig();
        f.series
            .push(Series::new("S1 raw", vec![(0.0, f64::NAN)], 1, Mark::Dot));
        let e = f.svg().unwrap_err().to_string();
        assert!(e.contains("figure 't'") && e.contains("'S1 raw'"), "{e}");
        assert!(f.csv().is_err());
    }

    #[test]
    fn empty_figure_and_empty_series_are_refused() {
        let mut f = Figure::new("e", "empty", "x", "y");
        assert!(f.svg().unwrap_err().to_string().contains("no data series"));
        f.series.push(Series::new("none", vec![], 0, Mark::Line));
        assert!(f.svg().unwrap_err().to_string().contains("'none' is empty"));
    }

    #[test]
    fn ticks_have_sensible_decimals() {
        assert_eq!(tick(2.0, 10.0), "2");
        assert_eq!(tick(2.05, 0.44), "2.05");
        assert_eq!(tick(-0.0001, 1.0), "0.0");
        assert_eq!(tick(1500.0, 4000.0), "1500");
    }
}
