//! The rigid body: a 2D section polyline, its contour samples, and its motion (its band of dummy
//! particles: [`crate::sph::dummy_band`]).
//!
//! The section is given as its starboard half, (y, z) points from the keel (y = 0) up to the deck edge, in
//! a body frame with the keel at z = 0 (so the keel touches the calm water surface at t = 0). The full
//! section is that half and its mirror image; the body is closed by a straight line across the top.

use crate::error::{Error, Result};
use crate::numerics::Pchip;

/// A symmetric section shape.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    /// Starboard half, keel first: (y >= 0, z), body frame, keel at (0, 0).
    points: Vec<[f64; 2]>,
    /// Full open contour, port deck edge through the keel to the starboard deck edge.
    full: Vec<[f64; 2]>,
}

impl Section {
    /// A wedge of deadrise `beta` (rad) with knuckles at half-breadth `half_beam` and vertical sides up to
    /// `height` above the keel (the shape of the Zhao et al. 1996 drop-test wedge).
    pub fn wedge(beta: f64, half_beam: f64, height: f64) -> Result<Self> {
        if !(beta > 0.0 && beta < std::f64::consts::FRAC_PI_2) {
            return Err(Error::Invalid(format!(
                "wedge deadrise must lie between 0 and 90 deg, got {} deg",
                beta.to_degrees()
            )));
        }
        let zk = half_beam * beta.tan();
        let mut pts = vec![[0.0, 0.0], [half_beam, zk]];
        if height > zk * (1.0 + 1e-9) {
            pts.push([half_beam, height]);
        }
        Self::from_half_points(pts)
    }

    /// A section from its starboard half, keel first. The points are shifted so that the lowest point is at
    /// z = 0. The first point must lie on the centre line (y = 0).
    pub fn from_half_points(mut points: Vec<[f64; 2]>) -> Result<Self> {
        if points.len() < 2 {
            return Err(Error::Invalid(
                "a section needs at least two points (keel and one more)".into(),
            ));
        }
        for (i, p) in points.iter().enumerate() {
            if !p[0].is_finite() || !p[1].is_finite() {
                return Err(Error::Invalid(format!(
                    "section point {i} is not finite: ({}, {})",
                    p[0], p[1]
                )));
            }
            if p[0] < 0.0 {
                return Err(Error::Invalid(format!(
                    "section point {i} has negative half-breadth {} m",
                    p[0]
                )));
            }
        }
        if points[0][0] != 0.0 {
            points.insert(0, [0.0, points[0][1]]);
        }
        points.dedup_by(|a, b| (a[0] - b[0]).hypot(a[1] - b[1]) < 1e-12);
        let zmin = points.iter().map(|p| p[1]).fold(f64::INFINITY, f64::min);
        for p in &mut points {
            p[1] -= zmin;
        }
        if points.len() < 2 || points.iter().all(|p| p[0] == 0.0) {
            return Err(Error::Invalid("the section has no breadth".into()));
        }
        let mut full: Vec<[f64; 2]> = points.iter().rev().map(|p| [-p[0], p[1]]).collect();
        full.extend_from_slice(&points[1..]); // points[0] is on the centre line
        Ok(Self { points, full })
    }

    /// Starboard half, keel first.
    pub fn half_points(&self) -> &[[f64; 2]] {
        &self.points
    }

    /// Full open contour from the port deck edge through the keel to the starboard deck edge.
    pub fn full_contour(&self) -> &[[f64; 2]] {
        &self.full
    }

    /// The full contour closed by the straight line across the top (port deck edge back to the start).
    /// Dummy particles line the whole of it, so a jet that rises past the deck edge cannot fall into the
    /// body.
    pub fn closed_contour(&self) -> Vec<[f64; 2]> {
        let mut c = self.full.clone();
        c.push(c[0]);
        c
    }

    /// Height of the section above the keel (m).
    pub fn height(&self) -> f64 {
        self.points.iter().map(|p| p[1]).fold(0.0, f64::max)
    }

    /// Largest half-breadth (m).
    pub fn half_breadth(&self) -> f64 {
        self.points.iter().map(|p| p[0]).fold(0.0, f64::max)
    }

    /// Half-breadth of the waterline at height `z` above the keel (m): the largest y of the starboard
    /// half at or below that height (the flat of a flat keel at z = 0).
    pub fn half_breadth_at(&self, z: f64) -> f64 {
        let mut y: f64 = 0.0;
        for w in self.points.windows(2) {
            let (a, b) = (w[0], w[1]);
            if a[1] <= z {
                y = y.max(a[0]);
            }
            if b[1] <= z {
                y = y.max(b[0]);
            }
            if (a[1] - z) * (b[1] - z) < 0.0 {
                y = y.max(a[0] + (z - a[1]) / (b[1] - a[1]) * (b[0] - a[0]));
            }
        }
        y
    }

    /// Smallest local deadrise angle (rad) of the contour segments below `z_max`: the angle of each
    /// segment with the horizontal, in [0, pi/2]. Drives the expected peak pressure.
    pub fn min_deadrise_below(&self, z_max: f64) -> f64 {
        let mut beta = std::f64::consts::FRAC_PI_2;
        for w in self.points.windows(2) {
            if w[0][1].min(w[1][1]) > z_max {
                continue;
            }
            let dy = (w[1][0] - w[0][0]).abs();
            let dz = (w[1][1] - w[0][1]).abs();
            if dy > 0.0 {
                beta = beta.min(dz.atan2(dy));
            }
        }
        beta
    }

    /// Whether a body-frame point lies inside the closed section (even-odd rule).
    pub fn contains(&self, y: f64, z: f64) -> bool {
        let c = &self.full;
        let n = c.len();
        let mut inside = false;
        for i in 0..n {
            let a = c[i];
            let b = c[(i + 1) % n];
            if (a[1] > z) != (b[1] > z) {
                let yc = a[0] + (z - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                if y < yc {
                    inside = !inside;
                }
            }
        }
        inside
    }
}

/// Nearest point of an open polyline to (y, z): the segment index k, the fraction f along it (0 at point
/// k, 1 at point k + 1) and the squared distance. The first nearest segment wins ties; `None` for fewer
/// than two points.
pub fn nearest_on_polyline(c: &[[f64; 2]], y: f64, z: f64) -> Option<(usize, f64, f64)> {
    let mut best: Option<(usize, f64, f64)> = None;
    for (k, w) in c.windows(2).enumerate() {
        let (ay, az, by, bz) = (w[0][0], w[0][1], w[1][0], w[1][1]);
        let (ty, tz) = (by - ay, bz - az);
        let l2 = ty * ty + tz * tz;
        let f = if l2 > 0.0 {
            (((y - ay) * ty + (z - az) * tz) / l2).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let (py, pz) = (ay + f * ty - y, az + f * tz - z);
        let d2 = py * py + pz * pz;
        if best.is_none_or(|b| d2 < b.2) {
            best = Some((k, f, d2));
        }
    }
    best
}

/// Distance from a point to an open polyline.
pub fn distance_to_polyline(c: &[[f64; 2]], y: f64, z: f64) -> f64 {
    nearest_on_polyline(c, y, z).map_or(f64::INFINITY, |b| b.2.sqrt())
}

/// A point on the body contour used for sensors and the section force.
#[derive(Debug, Clone, Copy)]
pub struct ContourPoint {
    /// Body-frame position.
    pub y: f64,
    pub z: f64,
    /// Outward unit normal (from the body into the water).
    pub ny: f64,
    pub nz: f64,
    /// Length of contour this point stands for (m).
    pub ds: f64,
    /// Arc length from the keel along the starboard half, at the point (m); negative on the port half.
    pub s: f64,
}

/// Outward unit normal (from the body into the water) of the starboard-half segment from `a` to `b`, and
/// the segment's length: the starboard half runs keel -> deck with the water on its right, so the normal
/// of the unit tangent (t_y, t_z) is (t_z, -t_y). `None` for a segment of zero length.
pub fn outward_normal(a: [f64; 2], b: [f64; 2]) -> Option<([f64; 2], f64)> {
    let (ty, tz) = (b[0] - a[0], b[1] - a[1]);
    let l = ty.hypot(tz);
    (l > 0.0).then(|| ([tz / l, -ty / l], l))
}

/// Contour samples at spacing at most `spacing`, starboard half (and the port half when `both_sides`).
pub fn contour_points(section: &Section, spacing: f64, both_sides: bool) -> Vec<ContourPoint> {
    let half = section.half_points();
    let mut out = Vec::new();
    let mut s0 = 0.0;
    for w in half.windows(2) {
        let Some(([ny, nz], l)) = outward_normal(w[0], w[1]) else {
            continue;
        };
        let (ty, tz) = (w[1][0] - w[0][0], w[1][1] - w[0][1]);
        let m = ((l / spacing).ceil() as usize).max(1);
        let ds = l / m as f64;
        for i in 0..m {
            let f = (i as f64 + 0.5) / m as f64;
            let p = ContourPoint {
                y: w[0][0] + f * ty,
                z: w[0][1] + f * tz,
                ny,
                nz,
                ds,
                s: s0 + f * l,
            };
            out.push(p);
            if both_sides {
                out.push(ContourPoint {
                    y: -p.y,
                    ny: -p.ny,
                    s: -p.s,
                    ..p
                });
            }
        }
        s0 += l;
    }
    out
}

/// Arc length of the starboard half contour (m).
pub fn half_contour_length(section: &Section) -> f64 {
    section
        .half_points()
        .windows(2)
        .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
        .sum()
}

/// The body-frame point at arc length `s` from the keel along the starboard half.
pub fn point_at_arc(section: &Section, s: f64) -> Option<[f64; 2]> {
    let mut acc = 0.0;
    for w in section.half_points().windows(2) {
        let l = (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]);
        if s <= acc + l && l > 0.0 {
            let f = ((s - acc) / l).clamp(0.0, 1.0);
            return Some([
                w[0][0] + f * (w[1][0] - w[0][0]),
                w[0][1] + f * (w[1][1] - w[0][1]),
            ]);
        }
        acc += l;
    }
    None
}

/// How the body moves vertically. Speeds are downward-positive (entry speed).
#[derive(Debug, Clone)]
pub enum Motion {
    /// Constant downward speed (m/s).
    Constant { speed: f64 },
    /// Downward speed as a function of time, from a table (shape-preserving cubic in between; the last
    /// value is held after the table ends).
    Prescribed {
        table: Pchip,
        t_end: f64,
        v_end: f64,
    },
    /// Free fall in heave under gravity and the water force, mass per metre of section (kg/m), starting
    /// at downward speed `speed0`.
    FreeHeave { mass_per_m: f64, speed0: f64 },
}

impl Motion {
    /// A prescribed-velocity motion from a table of (t, v_down).
    pub fn prescribed(t: &[f64], v: &[f64]) -> Result<Self> {
        if t.len() < 2 || t.len() != v.len() {
            return Err(Error::Invalid(
                "a velocity table needs at least two (t, v) rows".into(),
            ));
        }
        if t.windows(2).any(|w| w[1] <= w[0]) {
            return Err(Error::Invalid(
                "velocity table times must increase strictly".into(),
            ));
        }
        Ok(Motion::Prescribed {
            table: Pchip::new(t, v),
            t_end: *t.last().unwrap(),
            v_end: *v.last().unwrap(),
        })
    }

    /// Downward speed at time t for kinematic motions; `None` for free heave.
    pub fn speed_at(&self, t: f64) -> Option<f64> {
        match self {
            Motion::Constant { speed } => Some(*speed),
            Motion::Prescribed {
                table,
                t_end,
                v_end,
            } => Some(if t >= *t_end {
                *v_end
            } else {
                table.eval(t.max(0.0))
            }),
            Motion::FreeHeave { .. } => None,
        }
    }

    /// Downward acceleration at time t for kinematic motions.
    pub fn accel_at(&self, t: f64) -> Option<f64> {
        match self {
            Motion::Constant { .. } => Some(0.0),
            Motion::Prescribed { table, t_end, .. } => Some(if t >= *t_end {
                0.0
            } else {
                table.derivative(t.max(0.0))
            }),
            Motion::FreeHeave { .. } => None,
        }
    }

    /// The entry speed at t = 0.
    pub fn initial_speed(&self) -> f64 {
        match self {
            Motion::FreeHeave { speed0, .. } => *speed0,
            m => m.speed_at(0.0).unwrap_or(0.0),
        }
    }

    /// The largest downward speed over [0, t_end] (the initial speed for free fall).
    pub fn max_speed(&self, t_end: f64) -> f64 {
        match self {
            Motion::FreeHeave { speed0, .. } => *speed0,
            m => (0..=200)
                .map(|k| m.speed_at(t_end * k as f64 / 200.0).unwrap_or(0.0).abs())
                .fold(0.0, f64::max),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn waterline_half_breadth() {
        let s = Section::from_half_points(vec![[0.0, 0.0], [0.1, 0.0], [0.2, 0.1], [0.2, 0.3]])
            .unwrap();
        assert_eq!(s.half_breadth_at(0.0), 0.1);
        assert!((s.half_breadth_at(0.05) - 0.15).abs() < 1e-12);
        assert_eq!(s.half_breadth_at(0.2), 0.2);
        assert_eq!(s.half_breadth_at(-0.01), 0.0);
    }

    #[test]
    fn wedge_contains() {
        let s = Section::wedge(30f64.to_radians(), 0.25, 0.29).unwrap();
        assert!(s.contains(0.0, 0.1));
        assert!(!s.contains(0.2, 0.05));
        assert!(s.contains(0.2, 0.2));
    }

    #[test]
    fn contour_normals_point_into_the_water() {
        let s = Section::wedge(30f64.to_radians(), 0.25, 0.29).unwrap();
        for c in contour_points(&s, 0.01, true) {
            let (y, z) = (c.y + 1e-3 * c.ny, c.z + 1e-3 * c.nz);
            assert!(!s.contains(y, z), "{c:?}");
        }
    }
}
