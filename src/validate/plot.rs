//! A validation case's overlay plot, drawn by the report machinery ([`crate::report::figure`]):
//! computed curves as lines, reference data as open circles, with the bundled font; the same data as a
//! CSV twin. A figure with an empty or non-finite series is refused with the figure's and the series'
//! names, never drawn blank or with points silently left out.

use super::Figure;
use crate::error::Result;
use crate::report::figure::{self, Mark, Series};

/// The case figure as a report figure: series k in palette colour k.
pub fn figure(fig: &Figure) -> figure::Figure {
    let mut f = figure::Figure::new(&fig.name, &fig.title, &fig.x_label, &fig.y_label);
    f.size = (800, 460);
    for (k, s) in fig.series.iter().enumerate() {
        let mark = if s.reference { Mark::Ring } else { Mark::Line };
        let pts = s.points.iter().map(|p| (p[0], p[1])).collect();
        f.series.push(Series::new(s.label.clone(), pts, k, mark));
    }
    f
}

/// The figure as SVG text.
pub fn svg(fig: &Figure) -> Result<String> {
    figure(fig).svg()
}

/// The figure's data as CSV (`series`, x, y, one row per point), with a `#` line naming the series that
/// are reference data (drawn as markers); the others are computed (drawn as lines).
pub fn csv(fig: &Figure) -> Result<String> {
    let refs: Vec<&str> = fig
        .series
        .iter()
        .filter(|s| s.reference)
        .map(|s| s.label.as_str())
        .collect();
    Ok(format!(
        "# reference series (markers): {}; the others are computed (lines)\n{}",
        if refs.is_empty() {
            "none".to_string()
        } else {
            refs.join(" | ")
        },
        figure(fig).csv()?
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::validate::Series as CaseSeries;

    fn case_figure(y: f64) -> Figure {
        Figure {
            name: "f".into(),
            title: "a case".into(),
            x_label: "t (s)".into(),
            y_label: "F (N)".into(),
            series: vec![
                CaseSeries {
                    label: "SPH".into(),
                    reference: false,
                    points: vec![[0.0, 1.0], [1.0, y]],
                },
                CaseSeries {
                    label: "BEM".into(),
                    reference: true,
                    points: vec![[0.5, 1.5]],
                },
            ],
        }
    }

    #[test]
    fn a_case_figure_draws_and_names_its_reference_series() {
        let f = case_figure(2.0);
        assert!(svg(&f).unwrap().contains("BEM"));
        let c = csv(&f).unwrap();
        assert!(c.starts_with("# reference series (markers): BEM;"));
        let rows: Vec<&str> = c.lines().filter(|l| !l.starts_with('#')).collect();
        assert_eq!(rows.len(), 4, "{c}");
        assert!(
            rows[1].starts_with("SPH,") && rows[3].starts_with("BEM,"),
            "{c}"
        );
    }

    #[test]
    fn a_non_finite_point_is_refused_by_name() {
        let e = svg(&case_figure(f64::NAN)).unwrap_err().to_string();
        assert!(e.contains("'f'") && e.contains("SPH"), "{e}");
    }
}
