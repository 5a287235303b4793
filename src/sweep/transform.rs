//! Hull transformations of a sweep. Each one maps the base hull's offsets, sensors and loading condition to
//! a variant, which is written out as an ordinary hull file and read back through every check of
//! `hull::load` (sections, waterline, immersion, sensors on the contour), so a variant that is not a valid
//! hull is refused the same way a hand-made file would be.
//!
//! Applied in this order:
//!
//! 1. **Length and beam** (`length_scale` s_L, `beam_scale` s_B > 0): x' = s_L x, y' = s_B y, z' = z;
//!    Lpp' = s_L Lpp. Drafts, depth and KG stay; k_yy' = s_L k_yy; LCG (if given) scales with s_L; the
//!    displacement is recomputed as the buoyancy at the waterline (volume ∝ s_L s_B).
//! 2. **Bow flare and deadrise** (`flare_scale` k_f, `deadrise_scale` k_d > 0), over the `[bow_region]`:
//!    the change at a station is k(x) = 1 + (k − 1) w(x), with w the smooth step of
//!    [`super::file::BowRegion::weight`] (1 forward of `full_aft_of_fp`, 0 aft of `zero_aft_of_fp`). Each
//!    section is split at the local design waterline z_w of the base loading; the contour is rebuilt from
//!    the keel (y = 0) segment by segment with the heights kept:
//!    - above z_w every sloping segment's half-breadth increase Δy becomes k_f(x) Δy, so the tangent of the
//!      flare angle (from the vertical, tan φ = dy/dz) is multiplied by k_f;
//!    - below z_w every sloping segment's Δy becomes Δy / k_d(x), so the tangent of the deadrise angle (from
//!      the horizontal, tan β = dz/dy) is multiplied by k_d; the part above the waterline moves in or out
//!      with the waterline half-breadth, keeping its flare;
//!    - horizontal segments (a flat of bottom, a deck step) keep their length.
//!      Heights never change, so z stays non-decreasing; a variant can still be invalid (a tumblehome or a
//!      bulb scaled through the centreline), and the hull checks then refuse it.
//! 3. **Loading** (`draft_m` T, mean draft at midship, and `trim_m` t, by the stern): draft_FP = T − t/2,
//!    draft_AP = T + t/2, each defaulting to the base loading's. KG and k_yy stay; the displacement and LCG
//!    become the buoyancy and LCB of the new waterline (the ship floats at the drafts given).
//!
//! Sensors follow their plating: a sensor's point on the section at its x is moved by the same map as the
//! contour (on the segment it lies on), and the variant hull file places it there (`y_m`, `z_m`), where
//! the hull checks project it onto the variant's contour (within half its diameter).
//!
//! The displacement and LCG of the base loading are kept only when nothing below the waterline changes
//! (no length, beam, deadrise, draft or trim change).

use crate::error::{Error, Result};
use crate::hull::{Hull, LoadingCondition, Section};
use crate::input::SourceText;

use super::file::BowRegion;

/// The hull parameters of one case (None: unchanged).
#[derive(Debug, Clone, Copy, Default, PartialEq, serde::Serialize)]
pub struct HullParams {
    pub draft_m: Option<f64>,
    pub trim_m: Option<f64>,
    pub flare_scale: Option<f64>,
    pub deadrise_scale: Option<f64>,
    pub length_scale: Option<f64>,
    pub beam_scale: Option<f64>,
}

impl HullParams {
    /// No transformation at all: the base hull is used as it is.
    pub fn is_identity(&self) -> bool {
        *self == HullParams::default()
    }

    /// Whether the underwater form or the waterline changes.
    fn changes_underwater(&self) -> bool {
        self.draft_m.is_some()
            || self.trim_m.is_some()
            || self.deadrise_scale.is_some()
            || self.length_scale.is_some()
            || self.beam_scale.is_some()
    }
}

/// `points` with a vertex inserted where a sloping segment crosses height `z` (if none is there), and at
/// the point `at` (segment index, parameter in (0, 1)) if given. Returns the points and the index of the
/// inserted `at` point.
fn split(points: &[[f64; 2]], z: f64, at: Option<(usize, f64)>) -> (Vec<[f64; 2]>, Option<usize>) {
    let mut out = Vec::with_capacity(points.len() + 2);
    let mut marked = None;
    for k in 0..points.len() {
        let a = points[k];
        out.push(a);
        if k + 1 == points.len() {
            break;
        }
        let b = points[k + 1];
        let mut cuts: Vec<(f64, bool)> = Vec::new();
        if a[1] < z && z < b[1] {
            cuts.push(((z - a[1]) / (b[1] - a[1]), false));
        }
        if let Some((seg, t)) = at
            && seg == k
        {
            if t <= 0.0 {
                marked = Some(out.len() - 1);
            } else if t < 1.0 {
                cuts.push((t, true));
            }
        }
        cuts.sort_by(|p, q| p.0.total_cmp(&q.0));
        for (t, is_at) in cuts {
            // On the waterline exactly (as `Section::wetted` cuts it), elsewhere on the segment.
            let zp = if is_at { a[1] + t * (b[1] - a[1]) } else { z };
            let p = [a[0] + t * (b[0] - a[0]), zp];
            let last = out[out.len() - 1];
            if (p[0] - last[0]).abs() > 1e-12 || (p[1] - last[1]).abs() > 1e-12 {
                out.push(p);
            }
            if is_at {
                marked = Some(out.len() - 1);
            }
        }
    }
    if let Some((seg, t)) = at
        && marked.is_none()
        && t >= 1.0
    {
        marked = Some(out.iter().position(|p| *p == points[seg + 1]).unwrap_or(0));
    }
    (out, marked)
}

/// Rebuild a contour with flare factor `kf` above `z_w` and deadrise factor `kd` below it (module docs).
fn reshape(points: &[[f64; 2]], z_w: f64, kf: f64, kd: f64) -> Vec<[f64; 2]> {
    let mut out = Vec::with_capacity(points.len());
    out.push(points[0]);
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        let (dy, dz) = (b[0] - a[0], b[1] - a[1]);
        let dy2 = if dz <= 0.0 {
            dy
        } else if b[1] <= z_w {
            dy / kd
        } else {
            kf * dy
        };
        let last = out[out.len() - 1];
        out.push([last[0] + dy2, b[1]]);
    }
    out
}

/// The segment and parameter of the point of `section` nearest to `p`.
fn locate(section: &Section, p: [f64; 2]) -> (usize, f64) {
    let pts = &section.points;
    let mut best = (0, 0.0, f64::INFINITY);
    for k in 0..pts.len().saturating_sub(1) {
        let (a, b) = (pts[k], pts[k + 1]);
        let d = [b[0] - a[0], b[1] - a[1]];
        let l2 = d[0] * d[0] + d[1] * d[1];
        let t = if l2 > 0.0 {
            (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / l2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let q = [a[0] + t * d[0], a[1] + t * d[1]];
        let dist = (q[0] - p[0]).hypot(q[1] - p[1]);
        if dist < best.2 {
            best = (k, t, dist);
        }
    }
    (best.0, best.1)
}

/// A number in TOML (shortest form that reads back the same).
fn t(x: f64) -> String {
    let s = format!("{x:?}");
    if s.contains('.') || s.contains('e') || s.contains("inf") || s.contains("NaN") {
        s
    } else {
        format!("{s}.0")
    }
}

/// A TOML basic string.
fn q(s: &str) -> String {
    serde_json::to_string(s).unwrap_or_else(|_| "\"\"".into())
}

/// The variant hull file of `base` under loading `loading` with the parameters `p` (module docs), as TOML
/// text. `region` is needed for flare and deadrise changes.
pub fn variant_toml(
    base: &Hull,
    loading: &LoadingCondition,
    p: &HullParams,
    region: Option<BowRegion>,
    label: &str,
) -> Result<String> {
    let sl = p.length_scale.unwrap_or(1.0);
    let sb = p.beam_scale.unwrap_or(1.0);
    let lpp = base.lpp * sl;
    let kf = p.flare_scale.unwrap_or(1.0);
    let kd = p.deadrise_scale.unwrap_or(1.0);
    if (kf != 1.0 || kd != 1.0) && region.is_none() {
        return Err(Error::Invalid(
            "flare_scale and deadrise_scale need a [bow_region] (full_aft_of_fp, zero_aft_of_fp)"
                .into(),
        ));
    }
    let factor = |x_scaled: f64, k: f64| -> f64 {
        let f = (0.5 * lpp - x_scaled) / lpp;
        region.map_or(1.0, |r| 1.0 + (k - 1.0) * r.weight(f))
    };
    // The design waterline of the base loading at a (scaled) x: the drafts do not scale.
    let z_w = |x_scaled: f64| loading.draft_at(x_scaled, lpp);
    let map_section = |x: f64, pts: &[[f64; 2]], at: Option<[f64; 2]>| {
        let xs = x * sl;
        let scaled: Vec<[f64; 2]> = pts.iter().map(|p| [p[0] * sb, p[1]]).collect();
        let at_scaled = at.map(|a| [a[0] * sb, a[1]]);
        let loc = at_scaled.map(|a| locate(&Section::new(scaled.clone()), a));
        let (pts2, mark) = split(&scaled, z_w(xs), loc);
        let out = reshape(&pts2, z_w(xs), factor(xs, kf), factor(xs, kd));
        let marked = mark.map(|m| out[m]);
        (xs, out, marked)
    };

    let mut s = String::new();
    s += &format!("name = {}\n", q(&format!("{} [{label}]", base.name)));
    s += &format!(
        "description = {}\n",
        q(&format!(
            "Sweep variant of {} (loading '{}'): {label}. Written by slamtool sweep; see docs/guide/sweeps.md \
             (hull transformations) for the definitions.",
            base.source.display(),
            loading.name
        ))
    );
    s += &format!("lpp_m = {}\ndepth_m = {}\n\n", t(lpp), t(base.depth));
    let mean = p.draft_m.unwrap_or(loading.mean_draft());
    let trim = p.trim_m.unwrap_or(loading.trim_by_stern());
    let (dfp, dap) = if p.draft_m.is_some() || p.trim_m.is_some() {
        (mean - 0.5 * trim, mean + 0.5 * trim)
    } else {
        (loading.draft_fp, loading.draft_ap)
    };
    s += &format!(
        "[[loading]]\nname = {}\ndraft_fp_m = {}\ndraft_ap_m = {}\nwater_density_kg_m3 = {}\nkg_m = {}\nk_yy_m = {}\n",
        q(&loading.name),
        t(dfp),
        t(dap),
        t(loading.rho),
        t(loading.kg),
        t(loading.k_yy * sl)
    );
    if !p.changes_underwater() {
        if let Some(m) = loading.displacement_kg {
            s += &format!("displacement_kg = {}\n", t(m));
        }
        if let Some(g) = loading.lcg {
            s += &format!("lcg_m = {}\n", t(g));
        }
    }
    s += "\n";
    for st in &base.stations {
        let (xs, pts, _) = map_section(st.x, &st.section.points, None);
        s += &format!("[[station]]\nx_m = {}\npoints = [", t(xs));
        let body: Vec<String> = pts
            .iter()
            .map(|p| format!("[{}, {}]", t(p[0]), t(p[1])))
            .collect();
        s += &body.join(", ");
        s += "]\n\n";
    }
    for sensor in &base.sensors {
        let section = base.section_at(sensor.x)?;
        let (xs, _, at) = map_section(sensor.x, &section.points, Some(sensor.position));
        let at = at.ok_or_else(|| {
            Error::Invalid(format!(
                "sensor '{}': its point was lost in the map",
                sensor.name
            ))
        })?;
        s += &format!(
            "[[sensor]]\nname = {}\nx_m = {}\ny_m = {}\nz_m = {}\ndiameter_m = {}\n\n",
            q(&sensor.name),
            t(xs),
            t(at[0]),
            t(at[1]),
            t(sensor.diameter)
        );
    }
    Ok(s)
}

/// Build and check a variant: the hull file text and the hull read back from it (as if from `path`).
pub fn variant(
    base: &Hull,
    loading: &LoadingCondition,
    p: &HullParams,
    region: Option<BowRegion>,
    label: &str,
    path: &std::path::Path,
) -> Result<(String, Hull)> {
    let text = variant_toml(base, loading, p, region, label)?;
    let hull = Hull::from_source(&SourceText::from_string(path, text.clone()))?;
    Ok((text, hull))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reshape_scales_the_tangents_and_keeps_heights() {
        // A V bottom to the waterline at z = 1, then a flared side.
        let pts = [[0.0, 0.0], [1.0, 1.0], [1.5, 2.0]];
        let out = reshape(&pts, 1.0, 2.0, 1.0);
        assert_eq!(out, vec![[0.0, 0.0], [1.0, 1.0], [2.0, 2.0]]);
        let out = reshape(&pts, 1.0, 1.0, 2.0);
        assert_eq!(out, vec![[0.0, 0.0], [0.5, 1.0], [1.0, 2.0]]);
        // A flat of bottom keeps its width.
        let flat = [[0.0, 0.0], [0.3, 0.0], [1.0, 1.0]];
        assert_eq!(reshape(&flat, 1.0, 1.0, 2.0)[1], [0.3, 0.0]);
    }

    #[test]
    fn split_inserts_the_waterline_and_the_marked_point() {
        let pts = [[0.0, 0.0], [1.0, 2.0]];
        let (out, m) = split(&pts, 1.0, Some((0, 0.25)));
        assert_eq!(out, vec![[0.0, 0.0], [0.25, 0.5], [0.5, 1.0], [1.0, 2.0]]);
        assert_eq!(m, Some(1));
    }
}
