//! The default pressure panels of a station that carries no sensors in the hull file (issue #10): a panel
//! every 5 % of the girth from the keel to the design waterline, continued at the same spacing up the
//! side and flare to the deck edge.
//!
//! With g_wl the girth from the keel to the loading's waterline at the station, panel k (k = 1, 2, ...)
//! is centred at girth s_k = 0.05 k g_wl and is 0.05 g_wl wide, so the panels tile the contour without
//! gaps or overlap. A panel is kept while it lies on the contour (s_k + 0.025 g_wl <= total girth). Its
//! name is `G` and the percentage of g_wl at its centre, three digits wide from 100 %: `G05`, `G10`, ...,
//! `G100` (at the waterline), `G105`, ... (above it).
//!
//! A dry station, whose keel is at or above the loading's calm waterline (a forefoot under a raked stem, a
//! keel rising to the bow), has no girth below the waterline, and a nearly dry one (g_wl below a quarter
//! of the keel-to-deck girth, [`SHALLOW_FRACTION`]) would get hundreds of panels a few centimetres wide;
//! their panels divide the girth g_d from the keel to the deck edge in the same way, every 5 % of g_d,
//! and are named `D05`, `D10`, ..., `D95` (the last panel that lies whole on the contour).

use crate::error::{Error, Result};
use crate::hull::{Hull, LoadingCondition};
use crate::sph::SensorSpec;

/// Spacing and width of the default panels as a fraction of the keel-to-waterline girth.
pub const SPACING: f64 = 0.05;

/// A station whose keel-to-waterline girth is below this fraction of its keel-to-deck girth (dry, or
/// nearly dry: a forefoot, a keel rising to the stem) takes its panels from the keel-to-deck girth. At
/// the threshold a station has at most 80 panels (20 below the waterline).
pub const SHALLOW_FRACTION: f64 = 0.25;

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
    let total = sec.girth();
    let g_wl = girth_to_height(&sec.points, z_w);
    if !(g_wl.is_finite() && total.is_finite() && total > 0.0) {
        return Err(Error::Invalid(format!(
            "station {:.4} Lpp aft of the FP: no girth to place default sensors on (waterline girth \
             {g_wl}, keel-to-deck girth {total})",
            hull.aft_of_fp(x)
        )));
    }
    // A dry station (keel at or above the calm waterline) has no girth below the waterline, and a nearly
    // dry one so little that its panels would be a few centimetres wide and number in the hundreds: their
    // panels divide the keel-to-deck girth instead, and are named D (for deck) instead of G.
    let (reference, prefix) = if g_wl >= SHALLOW_FRACTION * total {
        (g_wl, 'G')
    } else {
        (total, 'D')
    };
    Ok(panels(reference, total, prefix))
}

/// Panels `SPACING * reference` wide, centred every `SPACING * reference` from the keel while they lie
/// on the contour of girth `total`, named `prefix` and the percentage of `reference` at their centre.
fn panels(reference: f64, total: f64, prefix: char) -> Vec<SensorSpec> {
    let w = SPACING * reference;
    let mut out = Vec::new();
    for k in 1.. {
        let s = k as f64 * w;
        if s + 0.5 * w > total + 1e-9 {
            break;
        }
        out.push(SensorSpec {
            name: format!("{prefix}{:02}", k * 5),
            s_m: s,
            width_m: w,
        });
    }
    out
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

    #[test]
    fn panels_tile_the_reference_girth_and_stop_at_the_contour_s_end() {
        let p = panels(2.0, 2.0, 'D');
        // the last panel that lies whole on the contour is centred at 95 %
        assert_eq!(p.len(), 19);
        assert_eq!(p[0].name, "D05");
        assert_eq!(p[18].name, "D95");
        assert!((p[18].s_m - 1.9).abs() < 1e-12 && (p[0].width_m - 0.1).abs() < 1e-12);
        // a contour longer than the reference continues the panels at the same spacing
        let q = panels(1.0, 1.32, 'G');
        assert_eq!(q.last().unwrap().name, "G125");
    }
}
