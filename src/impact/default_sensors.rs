//! The default pressure panels of a station that carries no sensors in the hull file (issue #10): a panel
//! every 5 % of the girth from the keel to the design waterline, continued at the same spacing up the
//! side and flare to the deck edge.
//!
//! With g_wl the girth from the keel to the loading's waterline at the station, panel k (k = 1, 2, ...)
//! is centred at girth s_k = 0.05 k g_wl and is 0.05 g_wl wide, so the panels tile the contour without
//! gaps or overlap. A panel is kept while it lies on the contour (s_k + 0.025 g_wl <= total girth). Its
//! name is `G` and the percentage of g_wl at its centre, three digits wide from 100 %: `G05`, `G10`, ...,
//! `G100` (at the waterline), `G105`, ... (above it).

use crate::error::{Error, Result};
use crate::hull::{Hull, LoadingCondition};
use crate::sph::SensorSpec;

/// Spacing and width of the default panels as a fraction of the keel-to-waterline girth.
pub const SPACING: f64 = 0.05;

/// Girth along the contour `points` (y, z; keel first) from the keel to height `z_w` (the whole contour
/// when it ends below z_w).
pub fn girth_to_height(points: &[[f64; 2]], z_w: f64) -> f64 {
    let mut s = 0.0;
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        let len = (b[0] - a[0]).hypot(b[1] - a[1]);
        if b[1] >= z_w {
            let f = if b[1] > a[1] {
                ((z_w - a[1]) / (b[1] - a[1])).clamp(0.0, 1.0)
            } else {
                1.0
            };
            return s + f * len;
        }
        s += len;
    }
    s
}

/// The default panels of the station at x (m from midship) in `loading`.
pub fn default_sensors(hull: &Hull, loading: &LoadingCondition, x: f64) -> Result<Vec<SensorSpec>> {
    let sec = hull.section_at(x)?;
    let z_w = loading.draft_at(x, hull.lpp);
    let g_wl = girth_to_height(&sec.points, z_w);
    let total = sec.girth();
    if g_wl.is_nan() || g_wl <= 0.0 {
        return Err(Error::Invalid(format!(
            "station {:.4} Lpp aft of the FP: the keel is above the waterline at loading '{}', so it has \
             no girth below the waterline to place default sensors on",
            hull.aft_of_fp(x),
            loading.name
        )));
    }
    let w = SPACING * g_wl;
    let mut out = Vec::new();
    for k in 1.. {
        let s = k as f64 * w;
        if s + 0.5 * w > total + 1e-9 {
            break;
        }
        out.push(SensorSpec {
            name: format!("G{:02}", k * 5),
            s_m: s,
            width_m: w,
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn girth_to_a_height_on_a_wedge_side() {
        // 3-4-5 triangle side: z rises 0.8 per unit girth
        let pts = [[0.0, 0.0], [0.6, 0.8], [1.2, 1.6]];
        assert!((girth_to_height(&pts, 0.4) - 0.5).abs() < 1e-12);
        assert!((girth_to_height(&pts, 1.2) - 1.5).abs() < 1e-12);
        assert!((girth_to_height(&pts, 5.0) - 2.0).abs() < 1e-12);
    }
}
