//! Chines: vertices of a section where the contour turns sharply steeper, so that the water jet running
//! up the bottom leaves the hull there instead of following the side above (flow separation from a
//! knuckle; Zhao, Faltinsen & Aarsnes 1996, "Water entry of arbitrary two-dimensional sections with and
//! without flow separation", 21st Symposium on Naval Hydrodynamics).
//!
//! The analytic models of the assessment (generalised Wagner and the modified Logvinovich model,
//! [`crate::analytic`]) assume the flow stays attached. Past such a chine they keep following the side:
//! with the side's slope f' and the bottom's contact speed dc/dt their pressure maximum
//! 1/2 rho (dc/dt)^2 (1 + f'^2) is that of a far steeper body hit as fast as the bottom, several times the
//! bottom's own. On the synthetic patrol boat of `tests/data/hard-chine-patrol.toml`, station 0.1 Lpp,
//! entry at 9.12 m/s (`--station 0.1 --speeds 12.35`), the default panel D55 that straddles the 30 deg
//! chine reads 128 kPa analytic against 3.5 kPa in the SPH run, whose flow separates there, and D60 above
//! it 99 kPa against a panel the SPH water never reaches; 2 cm panels read 352 kPa against 17 kPa just
//! above the chine. Continuing the bottom with a fictitious body past the chine (Tassin et al. 2014,
//! Applied Ocean Research 48, 33-41) is the published remedy; a measured prototype and what it still
//! needs are in `docs/numerics/chines.md`. These chines are found here so that the assessment can say
//! which panels it concerns.
//!
//! A vertex is a chine when the direction of the contour turns steeper by at least [`CHINE_TURN_DEG`]
//! while the contour still widens above it (a vertical side or tumblehome already ends the analytic
//! models' body there), and the segment below it is not a flat keel (the edge of a flat keel, where the
//! rising bottom is wetted as the keel sinks, is not a separation point of this kind).

/// Least turn of the contour towards the vertical (deg) at a chine. Offsets of a faired bilge turn by a
/// few degrees a point; a hard chine by 20-60 deg.
pub const CHINE_TURN_DEG: f64 = 20.0;

/// A chine of a section's half contour.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Chine {
    /// Girth from the keel along the contour (m).
    pub girth_m: f64,
    /// Half-breadth and height above the keel (m).
    pub y_m: f64,
    pub z_m: f64,
    /// Local deadrise of the contour below and above the vertex (deg from the horizontal).
    pub deadrise_below_deg: f64,
    pub deadrise_above_deg: f64,
}

impl Chine {
    /// The turn of the contour at the chine (deg).
    pub fn turn_deg(&self) -> f64 {
        self.deadrise_above_deg - self.deadrise_below_deg
    }
}

/// The chines of the half contour `points` (y, z; keel first), keel first, up to where the half-breadth
/// stops growing.
pub fn chines(points: &[[f64; 2]]) -> Vec<Chine> {
    let z0 = points.first().map_or(0.0, |p| p[1]);
    // Segments with a length: (start point, end point, deadrise in deg, girth at the start).
    let mut segs: Vec<([f64; 2], [f64; 2], f64, f64)> = Vec::new();
    let mut girth = 0.0;
    for w in points.windows(2) {
        let (dy, dz) = (w[1][0] - w[0][0], w[1][1] - w[0][1]);
        let l = dy.hypot(dz);
        if l > 0.0 {
            segs.push((w[0], w[1], dz.atan2(dy).to_degrees(), girth));
        }
        girth += l;
    }
    let mut out = Vec::new();
    for pair in segs.windows(2) {
        let (below, above) = (pair[0], pair[1]);
        // the analytic body ends where the contour stops widening
        if below.2 >= 90.0 || above.2 >= 90.0 {
            break;
        }
        let flat_keel_edge = below.2.abs() < 0.5;
        if !flat_keel_edge && above.2 - below.2 >= CHINE_TURN_DEG {
            out.push(Chine {
                girth_m: above.3,
                y_m: above.0[0],
                z_m: above.0[1] - z0,
                deadrise_below_deg: below.2,
                deadrise_above_deg: above.2,
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_hard_chine_is_found_and_a_faired_bilge_or_a_flat_keel_edge_is_not() {
        // 30 deg bottom to a chine at y = 1, then a side at 70 deg, then vertical
        let t30 = 30f64.to_radians().tan();
        let zc = t30;
        let side = [1.0 + 0.5 / 70f64.to_radians().tan(), zc + 0.5];
        let v = [
            [0.0, 0.0],
            [0.5, 0.5 * t30],
            [1.0, zc],
            side,
            [side[0], 3.0],
        ];
        let c = chines(&v);
        assert_eq!(c.len(), 1, "{c:?}");
        assert!((c[0].y_m - 1.0).abs() < 1e-12 && (c[0].z_m - zc).abs() < 1e-12);
        assert!((c[0].turn_deg() - 40.0).abs() < 1e-9);
        assert!((c[0].girth_m - 1.0 / 30f64.to_radians().cos()).abs() < 1e-12);
        // a bilge of radius 1 given every 10 deg: no vertex turns 20 deg
        let bilge: Vec<[f64; 2]> = (0..=9)
            .map(|k| {
                let a = (k as f64 * 10.0).to_radians();
                [a.sin(), 1.0 - a.cos()]
            })
            .collect();
        assert!(chines(&bilge).is_empty());
        // a flat keel then a 48 deg bottom (Ochi's flat stations): the keel's edge is not a chine
        let flat = [
            [0.0, 0.0],
            [0.13, 0.0],
            [0.3, 0.17 * 48f64.to_radians().tan()],
        ];
        assert!(chines(&flat).is_empty());
        // a chine below a vertical side: the analytic body ends there anyway
        let wall = [[0.0, 0.0], [1.0, t30], [1.0, 2.0]];
        assert!(chines(&wall).is_empty());
    }
}
