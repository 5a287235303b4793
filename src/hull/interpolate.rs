//! Sections between stations by shape-preserving interpolation.
//!
//! Each station contour is resampled at the same set of normalised girths s ∈ [0, 1] (arc length from the
//! keel over total girth): a uniform set together with the normalised girth of every vertex of every
//! station, so knuckles and chines are kept sharp. For every s, the offsets y(x; s) and z(x; s) are interpolated along the ship by
//! PCHIP (Fritsch & Carlson 1980): monotone where the offsets are monotone and without new extrema, so the
//! interpolated hull never bulges beyond the lines plan. At a station the given contour is returned as is.
//! Because z must rise from keel to deck, the interpolated heights are made non-decreasing along the contour
//! (a running maximum), which only acts where PCHIP rounding would otherwise make a contour dip by round-off.

use super::{Section, Station};
use crate::numerics::Pchip;

/// Number of uniformly spaced girth samples per contour (vertices are added to these).
const UNIFORM_SAMPLES: usize = 161;

#[derive(Debug, Clone)]
pub(crate) struct SectionInterpolator {
    y: Vec<Pchip>,
    z: Vec<Pchip>,
}

impl SectionInterpolator {
    pub fn new(stations: &[Station]) -> Self {
        let xs: Vec<f64> = stations.iter().map(|s| s.x).collect();
        let params = sample_girths(stations);
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
        Self { y, z }
    }

    pub fn section_at(&self, stations: &[Station], x: f64) -> Section {
        if let Some(s) = stations.iter().find(|s| (s.x - x).abs() <= 1e-12) {
            return s.section.clone();
        }
        let mut pts: Vec<[f64; 2]> = Vec::with_capacity(self.y.len());
        let mut zmax = f64::NEG_INFINITY;
        // Every interpolant has the stations' x as knots: one search for all of them.
        let at = self.y[0].locate(x);
        for j in 0..self.y.len() {
            let yv = self.y[j].eval_at(at).max(0.0);
            let zv = self.z[j].eval_at(at).max(zmax);
            zmax = zv;
            let p = [if j == 0 { 0.0 } else { yv }, zv];
            if pts.last().is_none_or(|q: &[f64; 2]| {
                (q[0] - p[0]).abs() > 1e-12 || (q[1] - p[1]).abs() > 1e-12
            }) {
                pts.push(p);
            }
        }
        if pts.len() < 2 {
            pts.push([0.0, pts[0][1] + 1e-9]);
        }
        Section::new(pts)
    }
}

/// Normalised girths to sample: uniform ones plus every station's vertices, sorted and de-duplicated.
fn sample_girths(stations: &[Station]) -> Vec<f64> {
    let mut s: Vec<f64> = (0..UNIFORM_SAMPLES)
        .map(|j| j as f64 / (UNIFORM_SAMPLES - 1) as f64)
        .collect();
    for st in stations {
        let g = st.section.girths();
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
    use crate::hull::validate::check_section;

    /// Every interpolated section of the bundled hulls is itself a valid contour (keel on the centreline,
    /// z never falling, no self-intersection), including next to stems that degenerate to a line.
    #[test]
    fn interpolated_sections_of_bundled_hulls_are_valid_contours() {
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("hulls");
        for name in [
            "wigley-iii.toml",
            "ochi-vform.toml",
            "car-carrier-hm2005.toml",
        ] {
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
