//! Sections between stations by shape-preserving interpolation.
//!
//! Each station contour is resampled at the same set of normalised girths s ∈ [0, 1] (arc length from the
//! keel over total girth): a uniform set together with the normalised girth of every vertex of every
//! station, so knuckles and chines are kept sharp. For every s, the offsets y(x; s) and z(x; s) are interpolated along the ship by
//! PCHIP (Fritsch & Carlson 1980): monotone where the offsets are monotone and without new extrema, so the
//! interpolated hull never bulges beyond the lines plan. At a station the given contour is returned as is.
//! Because z must rise from keel to deck, the interpolated heights are made non-decreasing along the contour
//! (a running maximum), which only acts where PCHIP rounding would otherwise make a contour dip by round-off.
//!
//! The cost is linear in the number of stations. For a hull of ordinary size the girth set is shared by
//! the whole hull (the union of every station's vertices) and one interpolant per girth is built once.
//! When that set times the number of stations would exceed [`GLOBAL_SAMPLE_LIMIT`] (thousands of stations,
//! as an imported scan gives), the section at x is built from the four stations around x instead, with
//! the girths of those stations only: PCHIP slopes at a knot depend on its neighbours alone, so this is
//! the same interpolant on the same girths, and the cost per section no longer grows with the hull.

use super::{Section, Station};
use crate::numerics::Pchip;
use crate::numerics::pchip::{hermite_basis, slope_from};

/// Number of uniformly spaced girth samples per contour (vertices are added to these).
const UNIFORM_SAMPLES: usize = 161;

/// Largest (stations × shared girth samples) kept as one set of interpolants for the whole hull: about
/// 48 MB of knots, values and slopes. Larger hulls interpolate from the four stations around x.
pub(crate) const GLOBAL_SAMPLE_LIMIT: usize = 1_000_000;

#[derive(Debug, Clone)]
pub(crate) struct SectionInterpolator {
    /// Station positions, aft to forward.
    xs: Vec<f64>,
    /// One interpolant per shared girth sample (y and z), or `None` for the local (windowed) mode.
    global: Option<(Vec<Pchip>, Vec<Pchip>)>,
    /// Girths of every station's vertices from the keel (local mode only; empty otherwise).
    girths: Vec<Vec<f64>>,
}

impl SectionInterpolator {
    pub fn new(stations: &[Station]) -> Self {
        Self::with_limit(stations, GLOBAL_SAMPLE_LIMIT)
    }

    /// The interpolator with the shared girth set only when stations × samples is at most `limit`.
    fn with_limit(stations: &[Station], limit: usize) -> Self {
        let xs: Vec<f64> = stations.iter().map(|s| s.x).collect();
        let vertices: usize = stations.iter().map(|s| s.section.points.len()).sum();
        // The shared set is only built when it is known to be small enough: a cheap bound first.
        let bound = stations.len().saturating_mul(UNIFORM_SAMPLES + vertices);
        let params = if bound <= limit {
            Some(sample_girths(stations))
        } else {
            None
        };
        let global = params.map(|params| {
            let resampled: Vec<Vec<[f64; 2]>> = stations
                .iter()
                .map(|s| resample(&s.section, &params))
                .collect();
            let mut y = Vec::with_capacity(params.len());
            let mut z = Vec::with_capacity(params.len());
            for j in 0..params.len() {
                let yj: Vec<f64> = resampled.iter().map(|r| r[j][0]).collect();
                let zj: Vec<f64> = resampled.iter().map(|r| r[j][1]).collect();
                y.push(Pchip::new(&xs, &yj));
                z.push(Pchip::new(&xs, &zj));
            }
            (y, z)
        });
        let girths = if global.is_some() {
            Vec::new()
        } else {
            stations.iter().map(|s| s.section.girths()).collect()
        };
        Self { xs, global, girths }
    }

    /// The station at `x` (within 1e-12 m), if any.
    fn station_index(&self, x: f64) -> Option<usize> {
        let i = self.xs.partition_point(|&v| v < x - 1e-12);
        (i < self.xs.len() && (self.xs[i] - x).abs() <= 1e-12).then_some(i)
    }

    pub fn section_at(&self, stations: &[Station], x: f64) -> Section {
        if let Some(i) = self.station_index(x) {
            return stations[i].section.clone();
        }
        match &self.global {
            Some((y, z)) => {
                // Every interpolant has the stations' x as knots: one search for all of them.
                let at = y[0].locate(x);
                assemble((0..y.len()).map(|j| (y[j].eval_at(at), z[j].eval_at(at))))
            }
            None => self.local(stations, x),
        }
    }

    /// The sections at `xs`, all within station interval `k` (between stations k and k + 1): the same as
    /// [`SectionInterpolator::section_at`] at each, with the work shared by the interval done once.
    pub fn sections_in_interval(&self, stations: &[Station], k: usize, xs: &[f64]) -> Vec<Section> {
        if self.global.is_some() || self.xs.len() < 2 {
            return xs.iter().map(|&x| self.section_at(stations, x)).collect();
        }
        let w = Window::new(self, stations, k.min(self.xs.len() - 2));
        xs.iter()
            .map(|&x| match self.station_index(x) {
                Some(i) => stations[i].section.clone(),
                None => w.at(x),
            })
            .collect()
    }

    /// The section at `x` from the (up to) four stations around it, on their own girths.
    fn local(&self, stations: &[Station], x: f64) -> Section {
        let n = self.xs.len();
        if n < 2 {
            return stations[0].section.clone();
        }
        let k = self
            .xs
            .partition_point(|&v| v <= x)
            .saturating_sub(1)
            .min(n - 2);
        Window::new(self, stations, k).at(x)
    }
}

/// The interpolant on one station interval, from the (up to) four stations around it: per girth sample,
/// the values and PCHIP slopes of y and z at both ends of the interval.
struct Window {
    x0: f64,
    x1: f64,
    /// Per girth sample: [y0, y1, dy0, dy1, z0, z1, dz0, dz1].
    ends: Vec<[f64; 8]>,
}

impl Window {
    fn new(it: &SectionInterpolator, stations: &[Station], k: usize) -> Self {
        let n = it.xs.len();
        let lo = k.saturating_sub(1);
        let hi = (k + 2).min(n - 1);
        let window = &stations[lo..=hi];
        let wx = &it.xs[lo..=hi];
        let girths = &it.girths[lo..=hi];
        let params = sample_girths_of(girths);
        let resampled: Vec<Vec<[f64; 2]>> = window
            .iter()
            .zip(girths)
            .map(|(s, g)| resample_sorted(&s.section, g, &params))
            .collect();
        let (a, b) = (k - lo, k - lo + 1);
        let m = window.len();
        let mut h = [0.0; 3];
        for i in 0..m - 1 {
            h[i] = wx[i + 1] - wx[i];
        }
        let h = &h[..m - 1];
        let (two, first, last) = (n == 2, k == 0, k + 1 == n - 1);
        // Values and slopes at both ends of the interval, from the secants of the window.
        let ends_of = |v: &[f64; 4]| {
            let mut del = [0.0; 3];
            for i in 0..m - 1 {
                del[i] = (v[i + 1] - v[i]) / h[i];
            }
            let del = &del[..m - 1];
            (
                v[a],
                v[b],
                slope_from(h, del, a, two, first, false),
                slope_from(h, del, b, two, false, last),
            )
        };
        let mut vy = [0.0; 4];
        let mut vz = [0.0; 4];
        let ends = (0..params.len())
            .map(|j| {
                for i in 0..m {
                    vy[i] = resampled[i][j][0];
                    vz[i] = resampled[i][j][1];
                }
                let (y0, y1, dy0, dy1) = ends_of(&vy);
                let (z0, z1, dz0, dz1) = ends_of(&vz);
                [y0, y1, dy0, dy1, z0, z1, dz0, dz1]
            })
            .collect();
        Self {
            x0: wx[a],
            x1: wx[b],
            ends,
        }
    }

    /// The section at `x` (in or near the interval).
    fn at(&self, x: f64) -> Section {
        // The Hermite cubic of every girth sample, with the basis at x computed once.
        let h = self.x1 - self.x0;
        let (h00, h10, h01, h11) = hermite_basis((x - self.x0) / h);
        assemble(self.ends.iter().map(|e| {
            (
                h00 * e[0] + h10 * h * e[2] + h01 * e[1] + h11 * h * e[3],
                h00 * e[4] + h10 * h * e[6] + h01 * e[5] + h11 * h * e[7],
            )
        }))
    }
}

/// A contour from interpolated (y, z) samples, keel first: y ≥ 0 and on the centreline at the keel, z made
/// non-decreasing (a running maximum), repeated points dropped, at least two points.
fn assemble(samples: impl Iterator<Item = (f64, f64)>) -> Section {
    let mut pts: Vec<[f64; 2]> = Vec::new();
    let mut zmax = f64::NEG_INFINITY;
    for (j, (yv, zv)) in samples.enumerate() {
        let yv = yv.max(0.0);
        let zv = zv.max(zmax);
        zmax = zv;
        let p = [if j == 0 { 0.0 } else { yv }, zv];
        if pts
            .last()
            .is_none_or(|q| (q[0] - p[0]).abs() > 1e-12 || (q[1] - p[1]).abs() > 1e-12)
        {
            pts.push(p);
        }
    }
    if pts.len() < 2 {
        pts.push([0.0, pts[0][1] + 1e-9]);
    }
    Section::new(pts)
}

/// Normalised girths to sample: uniform ones plus every station's vertices, sorted and de-duplicated.
fn sample_girths(stations: &[Station]) -> Vec<f64> {
    let girths: Vec<Vec<f64>> = stations.iter().map(|s| s.section.girths()).collect();
    sample_girths_of(&girths)
}

/// [`sample_girths`] from the stations' vertex girths.
fn sample_girths_of(girths: &[Vec<f64>]) -> Vec<f64> {
    let mut s: Vec<f64> = (0..UNIFORM_SAMPLES)
        .map(|j| j as f64 / (UNIFORM_SAMPLES - 1) as f64)
        .collect();
    for g in girths {
        let total = g[g.len() - 1];
        if total > 0.0 {
            s.extend(g.iter().map(|gi| gi / total));
        }
    }
    s.sort_by(f64::total_cmp);
    s.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    s
}

/// The contour at the given normalised girths.
fn resample(section: &Section, params: &[f64]) -> Vec<[f64; 2]> {
    let total = section.girth();
    params
        .iter()
        .map(|s| section.point_at_girth(s * total))
        .collect()
}

/// [`resample`] for sorted girths in one pass along the contour (linear in points plus girths), giving
/// the same points as [`Section::point_at_girth`]; `g` are the girths of the section's vertices.
fn resample_sorted(section: &Section, g: &[f64], params: &[f64]) -> Vec<[f64; 2]> {
    let p = &section.points;
    let total = g[g.len() - 1];
    if p.len() < 2 {
        return vec![p[0]; params.len()];
    }
    let mut k = 0;
    params
        .iter()
        .map(|s| {
            let s = s * total;
            while k < p.len() - 2 && s > g[k + 1] {
                k += 1;
            }
            let len = g[k + 1] - g[k];
            let t = if len > 0.0 {
                ((s - g[k]) / len).clamp(0.0, 1.0)
            } else {
                0.0
            };
            [
                p[k][0] + t * (p[k + 1][0] - p[k][0]),
                p[k][1] + t * (p[k + 1][1] - p[k][1]),
            ]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn wedge(x: f64, half: f64) -> Station {
        Station {
            x,
            section: Section::new(vec![[0.0, 0.0], [half, 1.0]]),
        }
    }

    #[test]
    fn returns_stations_exactly_and_interpolates_between() {
        let st = vec![wedge(0.0, 1.0), wedge(1.0, 2.0), wedge(2.0, 3.0)];
        let it = SectionInterpolator::new(&st);
        assert_eq!(it.section_at(&st, 1.0), st[1].section);
        let mid = it.section_at(&st, 0.5);
        assert!((mid.half_breadth_at(1.0) - 1.5).abs() < 1e-9);
        assert!((mid.half_breadth_at(0.5) - 0.75).abs() < 1e-9);
    }

    /// The four-station window is the same interpolant as the whole-hull one: identical where both use
    /// the same girths (contours of two points), and within a fraction of a millimetre per metre where the
    /// window has fewer girth samples (contours with vertices at different girths).
    #[test]
    fn windowed_sections_are_the_whole_hull_interpolant() {
        let st: Vec<Station> = (0..9)
            .map(|i| wedge(i as f64, 1.0 + 0.3 * (i as f64).sin()))
            .collect();
        let (whole, window) = (
            SectionInterpolator::with_limit(&st, usize::MAX),
            SectionInterpolator::with_limit(&st, 0),
        );
        assert!(whole.global.is_some() && window.global.is_none());
        for i in 0..=80 {
            let x = i as f64 * 0.1;
            assert_eq!(
                whole.section_at(&st, x),
                window.section_at(&st, x),
                "x = {x}"
            );
        }
        let knuckled: Vec<Station> = (0..9)
            .map(|i| {
                let b = 1.0 + 0.2 * i as f64;
                let k = 0.2 + 0.07 * i as f64;
                Station {
                    x: i as f64,
                    section: Section::new(vec![[0.0, 0.0], [0.6 * b, k], [b, 1.0], [1.1 * b, 1.5]]),
                }
            })
            .collect();
        let (whole, window) = (
            SectionInterpolator::with_limit(&knuckled, usize::MAX),
            SectionInterpolator::with_limit(&knuckled, 0),
        );
        for i in 0..=80 {
            let x = i as f64 * 0.1;
            let (a, b) = (
                whole.section_at(&knuckled, x),
                window.section_at(&knuckled, x),
            );
            for z in [0.05, 0.3, 0.7, 1.0, 1.4] {
                let d = (a.half_breadth_at(z) - b.half_breadth_at(z)).abs();
                assert!(d < 2e-3, "x = {x}, z = {z}: {d}");
            }
            let ks = whole.sections_in_interval(&knuckled, (x as usize).min(7), &[x]);
            assert_eq!(ks[0], a);
            let kw = window.sections_in_interval(&knuckled, (x as usize).min(7), &[x]);
            assert_eq!(kw[0], b);
        }
    }

    #[test]
    fn no_overshoot_between_unequal_stations() {
        let st = vec![
            wedge(0.0, 1.0),
            wedge(1.0, 1.0),
            wedge(2.0, 3.0),
            wedge(3.0, 3.0),
        ];
        let it = SectionInterpolator::new(&st);
        for i in 0..=300 {
            let b = it.section_at(&st, i as f64 * 0.01).max_half_breadth();
            assert!((1.0 - 1e-9..=3.0 + 1e-9).contains(&b), "overshoot {b}");
        }
    }
}

#[cfg(test)]
mod bundled {
    use crate::hull::Hull;
    use crate::hull::generate::GeneratedHull;
    use crate::hull::validate::check_section;

    /// Every interpolated section of the bundled hulls is itself a valid contour (keel on the centreline,
    /// z never falling, no self-intersection), including next to stems that degenerate to a line.
    #[test]
    fn interpolated_sections_of_bundled_hulls_are_valid_contours() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("hulls");
        for bundled in GeneratedHull::ALL {
            let name = bundled.file_name();
            let hull = Hull::from_file(&dir.join(name)).unwrap();
            let (xa, xf) = hull.x_range();
            for i in 0..=500 {
                let x = xa + (xf - xa) * i as f64 / 500.0;
                let s = hull.section_at(x).unwrap();
                if let Err(f) = check_section(&s.points) {
                    panic!("{name} at x = {x}: {}", f.message);
                }
            }
            for x in [xa + 1e-7, xf - 1e-7] {
                check_section(&hull.section_at(x).unwrap().points).unwrap();
            }
        }
    }
}
