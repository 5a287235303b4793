//! Overlay plots of computed curves (lines) and reference data (markers) as SVG, with the bundled font
//! ([`crate::plot`]), and the same data as a CSV twin (one block of rows per series).

use plotters::prelude::*;

use super::Figure;
use crate::error::Result;
use crate::plot::{FONT, draw_error, register_font};

const COLOURS: [RGBColor; 6] = [
    RGBColor(31, 119, 180),
    RGBColor(214, 39, 40),
    RGBColor(44, 160, 44),
    RGBColor(148, 103, 189),
    RGBColor(255, 127, 14),
    RGBColor(23, 190, 207),
];

/// The plotted range of the finite points, padded by 5 % (a flat range gets ±1).
fn range(v: impl Iterator<Item = f64>) -> (f64, f64) {
    let (lo, hi) = v
        .filter(|x| x.is_finite())
        .fold((f64::MAX, f64::MIN), |(a, b), x| (a.min(x), b.max(x)));
    if lo > hi {
        return (0.0, 1.0);
    }
    if hi - lo < 1e-12 * (1.0 + hi.abs()) {
        return (lo - 1.0, hi + 1.0);
    }
    let pad = 0.05 * (hi - lo);
    (lo - pad, hi + pad)
}

/// The figure as SVG text.
pub fn svg(fig: &Figure) -> Result<String> {
    register_font();
    let mut out = String::new();
    {
        let root = SVGBackend::with_string(&mut out, (800, 500)).into_drawing_area();
        root.fill(&WHITE).map_err(draw_error)?;
        let (x0, x1) = range(
            fig.series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p[0])),
        );
        let (y0, y1) = range(
            fig.series
                .iter()
                .flat_map(|s| s.points.iter().map(|p| p[1])),
        );
        let mut chart = ChartBuilder::on(&root)
            .caption(&fig.title, (FONT, 18))
            .margin(12)
            .x_label_area_size(40)
            .y_label_area_size(70)
            .build_cartesian_2d(x0..x1, y0..y1)
            .map_err(draw_error)?;
        chart
            .configure_mesh()
            .x_desc(fig.x_label.as_str())
            .y_desc(fig.y_label.as_str())
            .label_style((FONT, 13))
            .draw()
            .map_err(draw_error)?;
        for (k, s) in fig.series.iter().enumerate() {
            let c = COLOURS[k % COLOURS.len()];
            let pts: Vec<(f64, f64)> = s
                .points
                .iter()
                .filter(|p| p[0].is_finite() && p[1].is_finite())
                .map(|p| (p[0], p[1]))
                .collect();
            if s.reference {
                chart
                    .draw_series(pts.iter().map(|&p| Circle::new(p, 4, c.stroke_width(2))))
                    .map_err(draw_error)?
                    .label(s.label.as_str())
                    .legend(move |(x, y)| Circle::new((x + 10, y), 4, c.stroke_width(2)));
            } else {
                chart
                    .draw_series(LineSeries::new(pts, c.stroke_width(2)))
                    .map_err(draw_error)?
                    .label(s.label.as_str())
                    .legend(move |(x, y)| {
                        PathElement::new(vec![(x, y), (x + 20, y)], c.stroke_width(2))
                    });
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .label_font((FONT, 13))
            .position(SeriesLabelPosition::UpperRight)
            .draw()
            .map_err(draw_error)?;
        root.present().map_err(draw_error)?;
    }
    Ok(out)
}

/// The figure's data as CSV: `series,kind,x,y` with the axis labels in `#` lines.
pub fn csv(fig: &Figure) -> String {
    let mut s = format!(
        "# {}\n# x: {}\n# y: {}\n# kind: computed (line) or reference (markers)\nseries,kind,x,y\n",
        fig.title, fig.x_label, fig.y_label
    );
    for ser in &fig.series {
        let label = ser.label.replace('"', "'");
        let kind = if ser.reference {
            "reference"
        } else {
            "computed"
        };
        for p in &ser.points {
            s += &format!("\"{label}\",{kind},{},{}\n", p[0], p[1]);
        }
    }
    s
}
