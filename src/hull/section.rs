//! A hull cross-section: the half-breadth contour (y, z) from the keel on the centreline up to the deck.
//!
//! All section properties below come from the contour alone. With z non-decreasing along the contour
//! (checked when a hull is read), the half-section area under a waterline z_w is
//!
//! A/2 = ∫_{z_keel}^{z_w} y(z) dz,
//!
//! evaluated exactly for the polyline by the shoelace formula on the polygon closed along the waterline and
//! the centreline.

/// Half-breadth contour of one section, keel (y = 0) first, deck last.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// (y, z) points, m: y half-breadth (≥ 0), z above baseline.
    pub points: Vec<[f64; 2]>,
}

/// Area properties of the immersed part of a section (both sides).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SectionProperties {
    /// Immersed area of the full section (port + starboard), m².
    pub area: f64,
    /// Height of the centroid of the immersed area above baseline, m (0 where the area is 0).
    pub centroid_z: f64,
    /// Waterline half-breadth, m.
    pub half_breadth: f64,
}

impl Section {
    pub fn new(points: Vec<[f64; 2]>) -> Self {
        Self { points }
    }

    /// Lowest point of the section (the keel height above baseline).
    pub fn keel_z(&self) -> f64 {
        self.points[0][1]
    }

    /// Highest point of the section (the deck at side).
    pub fn deck_z(&self) -> f64 {
        self.points[self.points.len() - 1][1]
    }

    /// Largest half-breadth anywhere on the contour.
    pub fn max_half_breadth(&self) -> f64 {
        self.points.iter().map(|p| p[0]).fold(0.0, f64::max)
    }

    /// Half-breadth where the contour crosses height `z` (first crossing from the keel, so a flat bottom
    /// at exactly `z` counts with its outer end). Zero below the keel; the deck half-breadth above the deck.
    pub fn half_breadth_at(&self, z: f64) -> f64 {
        let p = &self.points;
        if z < p[0][1] {
            return 0.0;
        }
        for w in p.windows(2) {
            let (a, b) = (w[0], w[1]);
            if z >= a[1] && z <= b[1] {
                if b[1] > a[1] {
                    // On a horizontal run at height z take the outer end: the loop continues to it.
                    if z == b[1] {
                        continue;
                    }
                    let s = (z - a[1]) / (b[1] - a[1]);
                    return a[0] + s * (b[0] - a[0]);
                }
            } else if z < a[1] {
                break;
            }
        }
        // z at or above the last point that reaches it: the outer point at that height
        let mut y = 0.0;
        for q in p {
            if q[1] <= z {
                y = q[0];
            } else {
                break;
            }
        }
        y
    }

    /// The part of the contour below height `z_w`, ending on the waterline (empty if the keel is above it).
    pub fn wetted(&self, z_w: f64) -> Vec<[f64; 2]> {
        let p = &self.points;
        let mut out = Vec::with_capacity(p.len() + 1);
        if p[0][1] >= z_w {
            return out;
        }
        out.push(p[0]);
        for w in p.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b[1] < z_w {
                out.push(b);
            } else {
                let s = if b[1] > a[1] {
                    (z_w - a[1]) / (b[1] - a[1])
                } else {
                    1.0
                };
                out.push([a[0] + s * (b[0] - a[0]), z_w]);
                return out;
            }
        }
        // Contour ends below the waterline (deck under water): continue vertically to the waterline.
        let last = *out.last().expect("non-empty");
        out.push([last[0], z_w]);
        out
    }

    /// Immersed area, centroid height and waterline half-breadth for waterline height `z_w` (baseline frame).
    pub fn properties(&self, z_w: f64) -> SectionProperties {
        let wet = self.wetted(z_w);
        if wet.len() < 2 {
            return SectionProperties::default();
        }
        // Close the half-section polygon along the waterline back to the centreline, then down it.
        let mut poly = wet.clone();
        poly.push([0.0, z_w]);
        let (mut a2, mut mz) = (0.0, 0.0);
        let n = poly.len();
        for i in 0..n {
            let [y0, z0] = poly[i];
            let [y1, z1] = poly[(i + 1) % n];
            // Shoelace in the (y, z) plane; keel→waterline→centreline runs anticlockwise for y ≥ 0.
            let cross = y0 * z1 - y1 * z0;
            a2 += cross;
            mz += (z0 + z1) * cross;
        }
        let half_area = 0.5 * a2;
        let centroid_z = if half_area.abs() > 1e-15 {
            mz / (6.0 * half_area)
        } else {
            0.0
        };
        SectionProperties {
            area: 2.0 * half_area,
            centroid_z,
            half_breadth: wet.last().map_or(0.0, |q| q[0]),
        }
    }

    /// Cumulative girth (arc length from the keel) at each point.
    pub fn girths(&self) -> Vec<f64> {
        let mut g = Vec::with_capacity(self.points.len());
        let mut s = 0.0;
        g.push(0.0);
        for w in self.points.windows(2) {
            s += ((w[1][0] - w[0][0]).powi(2) + (w[1][1] - w[0][1]).powi(2)).sqrt();
            g.push(s);
        }
        g
    }

    /// Total girth from keel to deck.
    pub fn girth(&self) -> f64 {
        *self.girths().last().unwrap_or(&0.0)
    }

    /// The point at girth `s` from the keel (clamped to the ends of the contour by the caller's checks).
    pub fn point_at_girth(&self, s: f64) -> [f64; 2] {
        let g = self.girths();
        let p = &self.points;
        for k in 0..p.len() - 1 {
            if s <= g[k + 1] || k == p.len() - 2 {
                let len = g[k + 1] - g[k];
                let t = if len > 0.0 {
                    ((s - g[k]) / len).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                return [
                    p[k][0] + t * (p[k + 1][0] - p[k][0]),
                    p[k][1] + t * (p[k + 1][1] - p[k][1]),
                ];
            }
        }
        p[0]
    }

    /// Closest point on the contour to `q`: (girth from keel, distance).
    pub fn project(&self, q: [f64; 2]) -> (f64, f64) {
        let g = self.girths();
        let mut best = (0.0, f64::INFINITY);
        for (k, w) in self.points.windows(2).enumerate() {
            let (a, b) = (w[0], w[1]);
            let d = [b[0] - a[0], b[1] - a[1]];
            let len2 = d[0] * d[0] + d[1] * d[1];
            let t = if len2 > 0.0 {
                (((q[0] - a[0]) * d[0] + (q[1] - a[1]) * d[1]) / len2).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let c = [a[0] + t * d[0], a[1] + t * d[1]];
            let dist = ((q[0] - c[0]).powi(2) + (q[1] - c[1]).powi(2)).sqrt();
            if dist < best.1 {
                best = (g[k] + t * len2.sqrt(), dist);
            }
        }
        best
    }

    /// The section in a waterline frame: z measured from the local waterline `z_w` (negative below).
    pub fn relative_to_waterline(&self, z_w: f64) -> Section {
        Section::new(self.points.iter().map(|p| [p[0], p[1] - z_w]).collect())
    }

    /// Both sides as one closed-at-the-deck polyline, starboard deck → keel → port deck (y from −b to +b),
    /// the form a 2D water-entry solver wants.
    pub fn full_contour(&self) -> Vec<[f64; 2]> {
        let mut out: Vec<[f64; 2]> = self.points.iter().rev().map(|p| [-p[0], p[1]]).collect();
        let start = if self.points[0][0] == 0.0 { 1 } else { 0 };
        out.extend(self.points[start..].iter().copied());
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn box_section() -> Section {
        Section::new(vec![[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]])
    }

    #[test]
    fn box_properties() {
        let p = box_section().properties(1.0);
        assert!((p.area - 2.0).abs() < 1e-12);
        assert!((p.centroid_z - 0.5).abs() < 1e-12);
        assert!((p.half_breadth - 1.0).abs() < 1e-12);
    }

    #[test]
    fn triangle_properties() {
        // V section, 45 deg: y = z
        let s = Section::new(vec![[0.0, 0.0], [2.0, 2.0]]);
        let p = s.properties(1.0);
        assert!((p.area - 1.0).abs() < 1e-12);
        assert!((p.centroid_z - 2.0 / 3.0).abs() < 1e-12);
        assert!((s.half_breadth_at(0.5) - 0.5).abs() < 1e-12);
    }

    #[test]
    fn flat_bottom_half_breadth_takes_outer_end() {
        let s = box_section();
        assert!((s.half_breadth_at(0.0) - 1.0).abs() < 1e-12);
        assert_eq!(s.half_breadth_at(-0.1), 0.0);
    }

    #[test]
    fn dry_section_has_no_area() {
        let s = Section::new(vec![[0.0, 0.5], [1.0, 1.0]]);
        assert_eq!(s.properties(0.3).area, 0.0);
    }

    #[test]
    fn girth_and_projection() {
        let s = box_section();
        assert!((s.girth() - 3.0).abs() < 1e-12);
        let q = s.point_at_girth(1.5);
        assert!((q[0] - 1.0).abs() < 1e-12 && (q[1] - 0.5).abs() < 1e-12);
        let (g, d) = s.project([1.1, 0.5]);
        assert!((g - 1.5).abs() < 1e-12 && (d - 0.1).abs() < 1e-12);
    }

    #[test]
    fn full_contour_is_symmetric() {
        let c = box_section().full_contour();
        assert_eq!(c.len(), 5);
        assert_eq!(c[0], [-1.0, 2.0]);
        assert_eq!(c[2], [0.0, 0.0]);
        assert_eq!(c[4], [1.0, 2.0]);
    }
}
