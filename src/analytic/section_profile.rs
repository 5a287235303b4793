//! The body surface z = f(y) that the Wagner-type models (generalised Wagner, modified Logvinovich)
//! see, built from a section's starboard half (keel first, y >= 0, z up), and the Wagner condition on it.
//!
//! # Which f(y)
//!
//! The water rises from below, so at each half-breadth y it meets the lowest body point first. Walking
//! up the contour from the keel, f is the polyline of the points reached while the half-breadth does not
//! decrease:
//!
//! * a **flat keel** (z = 0 for 0 <= y <= c_f) is kept: f = 0 there and [`Profile::flat_keel_half_width`]
//!   is c_f;
//! * a **vertical segment** (at the keel, a keel bar, or in the middle, a step or spray rail) is a jump
//!   of f at that y. f takes the lower value there (the lowest body point). No slope dz/dy is ever formed
//!   for it: the Wagner integral below is evaluated segment by segment and handles the jump exactly;
//! * where the half-breadth first **decreases** (a bulb's widest point, tumblehome, the inside of a
//!   knuckle) f ends: the flow separates from the widest point and neither Wagner's model nor the MLM
//!   applies beyond it (it would need, e.g., the fictitious body continuation of Tassin et al. 2014).
//!   A bulbous section is therefore treated up to the widest point of the bulb;
//! * a trailing vertical side (a chine or knuckle followed by a vertical side) ends f at the chine.
//!
//! A contour that goes below its keel point (z < z_keel) on this part is refused: the first contact would
//! then be off the centre line, which the symmetric Wagner model does not cover.
//!
//! # Wagner condition
//!
//! d(c) = (2/pi) integral_0^{pi/2} f(c sin theta) d theta is the penetration at which the wetted
//! half-width is c (Wagner 1932; Faltinsen 2005, Hydrodynamics of High-Speed Marine Vehicles, ch. 8).
//! On a segment y in [y_a, y_b] with f = z_a + s (y - y_a) and theta = asin(y/c),
//!
//! integral f d theta = (z_a - s y_a)(theta_b - theta_a) + s c (cos theta_a - cos theta_b),
//!
//! exact for the polyline. Its derivative (used for dc/dt = V / d'(c)) is
//!
//! d'(c) = (2/pi) [ sum_segments s (cos theta_a - cos theta_b) + sum_steps dz_j y_j / (c sqrt(c^2 - y_j^2)) ],
//!
//! the second sum over the jumps dz_j of f at y_j < c (boundary terms of consecutive segments cancel
//! where f is continuous). On a flat keel d(c) = 0 and d'(c) = 0: the wetted width jumps to c_f at
//! contact (flat-plate impact), handled by the callers.

use crate::error::{Error, Result};
use std::f64::consts::FRAC_2_PI;

/// Where f(y) ends.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum ProfileEnd {
    /// At the last point of the contour or at a chine followed by a vertical side.
    Widest,
    /// Where the half-breadth first decreases going up (bulb, tumblehome): flow separation.
    Separation,
}

/// The polyline z = f(y) above the keel, y in [0, y_end], y non-decreasing (equal y = a vertical step).
#[derive(Debug, Clone)]
pub struct Profile {
    pts: Vec<[f64; 2]>,
    flat: f64,
    end: ProfileEnd,
}

impl Profile {
    /// f(y) from the starboard half `half` (keel first, y >= 0). Heights are measured from the keel point.
    pub fn from_half_points(half: &[[f64; 2]]) -> Result<Self> {
        if half.len() < 2 {
            return Err(Error::Invalid(
                "section needs at least two points (keel and one more)".into(),
            ));
        }
        if let Some((i, p)) = half
            .iter()
            .enumerate()
            .find(|(_, p)| !(p[0].is_finite() && p[1].is_finite()) || p[0] < 0.0)
        {
            return Err(Error::Invalid(format!(
                "section point {i} {p:?} is not finite or has a negative half-breadth"
            )));
        }
        if half[0][0] != 0.0 {
            return Err(Error::Invalid(format!(
                "the first section point must be the keel on the centre line (y = 0), got y = {}",
                half[0][0]
            )));
        }
        let scale = half
            .iter()
            .map(|p| p[0].abs().max((p[1] - half[0][1]).abs()))
            .fold(0.0, f64::max);
        let tol = 1e-12 * scale.max(1e-300);
        let z0 = half[0][1];
        let mut pts = vec![[0.0, 0.0]];
        let mut end = ProfileEnd::Widest;
        for p in &half[1..] {
            let q = [p[0], p[1] - z0];
            let last = *pts.last().unwrap();
            if (q[0] - last[0]).abs() <= tol && (q[1] - last[1]).abs() <= tol {
                continue; // repeated point
            }
            if q[0] < last[0] - tol {
                end = ProfileEnd::Separation;
                break;
            }
            let q = [q[0].max(last[0]), q[1]];
            if q[1] < -tol {
                return Err(Error::Invalid(format!(
                    "the section goes below its keel (z = {:.6} m below at y = {:.6} m): the first contact \
                     would be off the centre line, which the Wagner/Logvinovich models do not cover",
                    -q[1], q[0]
                )));
            }
            pts.push(q);
        }
        // A vertical side after the chine adds nothing: f ends at the chine.
        while pts.len() > 1 && pts[pts.len() - 1][0] <= pts[pts.len() - 2][0] {
            pts.pop();
        }
        if pts.len() < 2 || pts[pts.len() - 1][0] <= 0.0 {
            return Err(Error::Invalid(
                "the section has no breadth below its first vertical side or widest point".into(),
            ));
        }
        let mut flat = 0.0;
        for w in pts.windows(2) {
            if w[0][1].abs() <= tol && w[1][1].abs() <= tol {
                flat = w[1][0];
            } else {
                break;
            }
        }
        Ok(Self { pts, flat, end })
    }

    /// Vertices of f, keel first.
    pub fn points(&self) -> &[[f64; 2]] {
        &self.pts
    }

    /// Half-width of the flat keel (0 when the keel has deadrise).
    pub fn flat_keel_half_width(&self) -> f64 {
        self.flat
    }

    /// Largest half-breadth covered by f (chine, widest point of a bulb, or last point).
    pub fn y_end(&self) -> f64 {
        self.pts[self.pts.len() - 1][0]
    }

    /// Why f ends at [`Profile::y_end`].
    pub fn end(&self) -> ProfileEnd {
        self.end
    }

    /// f(y): height of the lowest body point above the keel at half-breadth |y|, or `None` past y_end.
    pub fn height(&self, y: f64) -> Option<f64> {
        self.height_and_slope(y).0
    }

    /// [`Profile::height`] and [`Profile::slope`] at |y| from one search for the segment.
    pub fn height_and_slope(&self, y: f64) -> (Option<f64>, f64) {
        let y = y.abs();
        let seg = self.segment(y);
        let slope = seg.map_or(0.0, |(a, b)| (b[1] - a[1]) / (b[0] - a[0]));
        let height = if y > self.y_end() {
            None
        } else if y == 0.0 {
            Some(0.0) // the keel, also under a vertical keel bar
        } else {
            seg.map(|(a, b)| {
                let s = (y - a[0]) / (b[0] - a[0]);
                a[1] + s * (b[1] - a[1])
            })
        };
        (height, slope)
    }

    /// f'(|y|) on the (non-vertical) segment holding |y|: the local deadrise slope tan(beta). 0 past y_end.
    pub fn slope(&self, y: f64) -> f64 {
        self.height_and_slope(y).1
    }

    /// The first non-vertical segment with a[0] <= y <= b[0]. The half-breadths of f do not decrease
    /// ([`Profile::from_half_points`]), so the segments with b[0] >= y start at a binary-searched index
    /// and the first that also has a[0] <= y and b[0] > a[0] is the one a scan from the keel finds.
    fn segment(&self, y: f64) -> Option<([f64; 2], [f64; 2])> {
        let first = self.pts[1..].partition_point(|p| p[0] < y);
        self.pts[first..]
            .windows(2)
            .take_while(|w| w[0][0] <= y)
            .find(|w| w[1][0] > w[0][0] && y <= w[1][0])
            .map(|w| (w[0], w[1]))
    }

    /// Wagner condition: the penetration d(c) at which the wetted half-width is c, or `None` past y_end.
    pub fn wagner_depth(&self, c: f64) -> Option<f64> {
        if c.is_nan() || c < 0.0 || c > self.y_end() {
            return None;
        }
        if c == 0.0 {
            return Some(0.0);
        }
        let mut sum = 0.0;
        for w in self.pts.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b[0] <= a[0] || a[0] >= c {
                continue;
            }
            let s = (b[1] - a[1]) / (b[0] - a[0]);
            let ta = (a[0] / c).min(1.0).asin();
            let tb = (b[0] / c).min(1.0).asin();
            sum += (a[1] - s * a[0]) * (tb - ta) + s * c * (ta.cos() - tb.cos());
        }
        Some(FRAC_2_PI * sum)
    }

    /// d'(c) = dd/dc of the Wagner condition (0 on a flat keel; +inf at c = 0 under a vertical keel bar,
    /// which has no wetted width), or `None` past y_end.
    pub fn wagner_depth_rate(&self, c: f64) -> Option<f64> {
        if c.is_nan() || c < 0.0 || c > self.y_end() {
            return None;
        }
        if c == 0.0 {
            let (a, b) = (self.pts[0], self.pts[1]);
            return Some(if b[0] > a[0] {
                FRAC_2_PI * (b[1] - a[1]) / (b[0] - a[0])
            } else {
                f64::INFINITY
            });
        }
        let mut sum = 0.0;
        for w in self.pts.windows(2) {
            let (a, b) = (w[0], w[1]);
            if a[0] >= c {
                break;
            }
            if b[0] > a[0] {
                let s = (b[1] - a[1]) / (b[0] - a[0]);
                let ca = (1.0 - (a[0] / c).powi(2)).max(0.0).sqrt();
                let cb = (1.0 - (b[0] / c).min(1.0).powi(2)).max(0.0).sqrt();
                sum += s * (ca - cb);
            } else {
                // Vertical step of height dz at y_j = a[0] < c.
                let r = c * c - a[0] * a[0];
                if r > 0.0 {
                    sum += (b[1] - a[1]) * a[0] / (c * r.sqrt());
                }
            }
        }
        Some(FRAC_2_PI * sum)
    }

    /// The body above an initial waterline d0 above the keel, for a section that starts immersed to d0:
    /// f~(y) = max(f(y) - d0, 0), heights from the initial waterline. The part below it is a flat "keel"
    /// of half-width b0 (the waterline half-breadth at d0, where f crosses d0): in the linearised (Wagner)
    /// problem the wetted part of a body immersed at rest is the flat plate |y| < b0 on the initial
    /// surface. d0 = 0 gives f itself. Errors where d0 is negative or not below the top of f.
    pub fn above(&self, d0: f64) -> Result<Self> {
        if !(d0.is_finite() && d0 >= 0.0) {
            return Err(Error::Invalid(format!(
                "initial immersion must be a finite depth >= 0 m, got {d0}"
            )));
        }
        if d0 == 0.0 {
            return Ok(self.clone());
        }
        let top = self.pts[self.pts.len() - 1][1];
        if d0 >= top {
            return Err(Error::Invalid(format!(
                "initial immersion {d0} m is not below the top of the section's profile ({top:.6} m above \
                 the keel at y = {:.6} m): nothing is left to enter",
                self.y_end()
            )));
        }
        let mut pts: Vec<[f64; 2]> = vec![[0.0, 0.0]];
        let mut push = |q: [f64; 2]| {
            if pts.last().is_none_or(|l| l[0] != q[0] || l[1] != q[1]) {
                pts.push(q);
            }
        };
        for w in self.pts.windows(2) {
            let (a, b) = (w[0], w[1]);
            if (a[1] - d0) * (b[1] - d0) < 0.0 {
                let f = (d0 - a[1]) / (b[1] - a[1]);
                push([a[0] + f * (b[0] - a[0]), 0.0]);
            }
            push([b[0], (b[1] - d0).max(0.0)]);
        }
        let mut flat = 0.0;
        for w in pts.windows(2) {
            if w[0][1] == 0.0 && w[1][1] == 0.0 {
                flat = w[1][0];
            } else {
                break;
            }
        }
        Ok(Self {
            pts,
            flat,
            end: self.end,
        })
    }

    /// Arc length from the keel along f to half-breadth y (vertical steps included).
    pub fn arc_length_to(&self, y: f64) -> f64 {
        let mut s = 0.0;
        for w in self.pts.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b[0] <= y {
                s += (b[0] - a[0]).hypot(b[1] - a[1]);
            } else {
                if y > a[0] {
                    let f = (y - a[0]) / (b[0] - a[0]);
                    s += f * (b[0] - a[0]).hypot(b[1] - a[1]);
                }
                break;
            }
        }
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wedge_condition_is_wagner() {
        let beta = 20f64.to_radians();
        let p = Profile::from_half_points(&[[0.0, 0.0], [0.3, 0.3 * beta.tan()]]).unwrap();
        let c = 0.1;
        let d = p.wagner_depth(c).unwrap();
        assert!((d - c * beta.tan() * FRAC_2_PI).abs() < 1e-14);
        let r = p.wagner_depth_rate(c).unwrap();
        assert!((r - beta.tan() * FRAC_2_PI).abs() < 1e-14);
        assert_eq!(p.wagner_depth(0.31), None);
    }

    #[test]
    fn rate_matches_a_difference_with_steps_and_flats() {
        let p = Profile::from_half_points(&[
            [0.0, 0.0],
            [0.05, 0.0],
            [0.1, 0.03],
            [0.1, 0.06],
            [0.2, 0.12],
            [0.25, 0.3],
        ])
        .unwrap();
        assert_eq!(p.flat_keel_half_width(), 0.05);
        for c in [0.07, 0.12, 0.18, 0.22] {
            let h = 1e-7;
            let num = (p.wagner_depth(c + h).unwrap() - p.wagner_depth(c - h).unwrap()) / (2.0 * h);
            let r = p.wagner_depth_rate(c).unwrap();
            assert!((num / r - 1.0).abs() < 1e-5, "{c}: {num} vs {r}");
        }
    }

    #[test]
    fn bulb_ends_at_its_widest_point_and_vertical_sides_are_dropped() {
        let bulb = [
            [0.0, 0.0],
            [0.1, 0.02],
            [0.15, 0.08],
            [0.12, 0.15],
            [0.08, 0.2],
            [0.3, 0.4],
        ];
        let p = Profile::from_half_points(&bulb).unwrap();
        assert_eq!(p.y_end(), 0.15);
        assert_eq!(p.end(), ProfileEnd::Separation);
        let r = Profile::from_half_points(&[[0.0, 0.0], [0.2, 0.0], [0.2, 0.2]]).unwrap();
        assert_eq!(r.y_end(), 0.2);
        assert_eq!(r.flat_keel_half_width(), 0.2);
        assert_eq!(r.wagner_depth(0.2), Some(0.0));
        assert_eq!(r.wagner_depth_rate(0.1), Some(0.0));
        let keel_bar = Profile::from_half_points(&[[0.0, 0.0], [0.0, 0.05], [0.2, 0.1]]).unwrap();
        assert_eq!(keel_bar.height(0.0), Some(0.0));
        assert!((keel_bar.height(1e-9).unwrap() - 0.05).abs() < 1e-9);
        assert!(keel_bar.wagner_depth_rate(0.0).unwrap().is_infinite());
        assert!((keel_bar.wagner_depth(1e-9).unwrap() - 0.05).abs() < 1e-6);
    }

    #[test]
    fn the_body_above_an_initial_waterline() {
        // 45 deg flank to y = 0.2, then a vertical step 0.2 -> 0.3, then flat-ish to y = 0.4
        let p =
            Profile::from_half_points(&[[0.0, 0.0], [0.2, 0.2], [0.2, 0.3], [0.4, 0.4]]).unwrap();
        assert_eq!(p.above(0.0).unwrap().points(), p.points());
        let a = p.above(0.1).unwrap();
        assert_eq!(a.flat_keel_half_width(), 0.1);
        assert!((a.height(0.3).unwrap() - 0.25).abs() < 1e-12);
        assert_eq!(a.height(0.05), Some(0.0));
        // across the step: f~ jumps from 0.1 to 0.2 at y = 0.2
        let b = p.above(0.25).unwrap();
        assert_eq!(b.flat_keel_half_width(), 0.2);
        assert!((b.height(0.4).unwrap() - 0.15).abs() < 1e-12);
        assert!(p.above(0.4).is_err() && p.above(-0.1).is_err());
    }

    #[test]
    fn refuses_a_contour_below_its_keel() {
        assert!(Profile::from_half_points(&[[0.0, 0.1], [0.1, 0.0], [0.2, 0.3]]).is_err());
        assert!(Profile::from_half_points(&[[0.1, 0.0], [0.2, 0.3]]).is_err());
        assert!(Profile::from_half_points(&[[0.0, 0.0], [0.0, 0.3]]).is_err());
    }
}
