//! No-penetration of the moving body: a kinematic wall collision after each drift, in the spirit of the
//! particle-wall collisions of Kruisbrink, Korzilius, Pearce & Morvan (2018), "SPH particle collisions
//! for the reduction of particle clustering, interface stabilisation, and wall modelling", J. Appl.
//! Math. Phys. 6, 1815-1837.
//!
//! The dummy particles of [`crate::sph::boundary::adami2012`] keep the fluid off the body through the
//! pressure they carry; the collision is the safeguard for the rare particle that the pressure force does
//! not stop within one step (at a V keel on the symmetry plane, in a thin jet meeting a flare, at a
//! knuckle). A fluid particle found inside the section contour after the drift
//!
//! * is moved along the shortest path back out of the body, to half a particle spacing outside the
//!   contour (the distance at which the fluid sits from a wetted wall), and
//! * loses the part of its velocity relative to the body that points into the body (a perfectly
//!   inelastic collision, restitution 0, with the tangential velocity kept: the free-slip wall):
//!   u <- u - min(0, (u - u_b) . n) n, n the outward normal at the contact point, u_b the body velocity.
//!
//! Each correction is counted and reported with the run. A particle found deeper than two particle
//! spacings inside has moved further in one step than any physical flow can (the Courant limit keeps a
//! particle within 0.6 dp per step at the sound speed): that is a blow-up, and the run stops with a
//! diagnostic instead of being corrected.

use rayon::prelude::*;

use crate::sph::body::{Section, nearest_on_polyline};
use crate::sph::particles::Particles;

/// Outcome of one collision pass.
#[derive(Debug, Clone, Copy, Default, PartialEq)]
pub struct Collisions {
    /// Fluid particles moved back out of the body.
    pub corrected: u64,
    /// Deepest penetration found (m) and where, in the body frame (y, z above the keel).
    pub deepest: f64,
    pub deepest_at: [f64; 2],
}

/// Push every fluid particle that is inside the body back out (see the module docs). `closed` is the
/// closed section contour in the body frame, `z_keel` the keel height in the water-entry frame,
/// `v_down` the body's downward speed, `dp` the particle spacing. With a symmetry plane (`mirror`) a
/// particle pushed across y = 0 is reflected back like in the drift.
#[allow(clippy::too_many_arguments)]
pub fn resolve(
    pt: &mut Particles,
    section: &Section,
    closed: &[[f64; 2]],
    z_keel: f64,
    v_down: f64,
    dp: f64,
    mirror: bool,
) -> Collisions {
    let (hb, ht) = (section.half_breadth(), section.height());
    let gap = 0.5 * dp;
    (
        pt.y.par_iter_mut(),
        pt.z.par_iter_mut(),
        pt.vy.par_iter_mut(),
        pt.vz.par_iter_mut(),
        pt.kind.par_iter(),
    )
        .into_par_iter()
        .with_min_len(4096)
        .map(|(y, z, vy, vz, kind)| {
            let zb = *z - z_keel;
            if !kind.is_fluid() || y.abs() > hb || zb < 0.0 || zb > ht || !section.contains(*y, zb)
            {
                return Collisions::default();
            }
            let Some((k, f, d2)) = nearest_on_polyline(closed, *y, zb) else {
                return Collisions::default();
            };
            let (a, b) = (closed[k], closed[k + 1]);
            let q = [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])];
            let d = d2.sqrt();
            // Outward normal: from the particle to its contact point, or the segment normal when the
            // particle sits on the contour itself.
            let n = if d > 1e-12 * dp {
                [(q[0] - *y) / d, (q[1] - zb) / d]
            } else {
                let (ty, tz) = (b[0] - a[0], b[1] - a[1]);
                let l = ty.hypot(tz).max(f64::MIN_POSITIVE);
                [tz / l, -ty / l]
            };
            *y = q[0] + gap * n[0];
            *z = q[1] + gap * n[1] + z_keel;
            let un = *vy * n[0] + (*vz + v_down) * n[1];
            if un < 0.0 {
                *vy -= un * n[0];
                *vz -= un * n[1];
            }
            if mirror && *y < 0.0 {
                *y = -*y;
                *vy = -*vy;
            }
            Collisions {
                corrected: 1,
                deepest: d,
                deepest_at: [q[0] - d * n[0], q[1] - d * n[1]],
            }
        })
        .reduce(Collisions::default, |a, b| Collisions {
            corrected: a.corrected + b.corrected,
            // Ties keep the first: the reduction order is fixed by rayon's split, but equal depths
            // only arise for mirror-symmetric pairs, and either location describes the event.
            ..if b.deepest > a.deepest { b } else { a }
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::particles::Kind;

    fn one_fluid(y: f64, z: f64, vy: f64, vz: f64) -> Particles {
        let mut pt = Particles::default();
        pt.push(Kind::Fluid, y, z, vy, vz, 1000.0, 0.0, 1e-4);
        pt
    }

    #[test]
    fn a_particle_inside_a_wedge_is_put_outside_with_no_inward_speed() {
        let sec = Section::wedge(30f64.to_radians(), 0.25, 0.3).unwrap();
        let closed = sec.closed_contour();
        let zk = -0.1;
        // Body frame (0.1, 0.08) is inside (the side is at z = 0.1 tan 30 = 0.0577).
        let mut pt = one_fluid(0.1, 0.08 + zk, 0.0, 3.0);
        let c = resolve(&mut pt, &sec, &closed, zk, 1.0, 0.01, true);
        assert_eq!(c.corrected, 1);
        let (y, zb) = (pt.y[0], pt.z[0] - zk);
        assert!(!sec.contains(y, zb), "still inside at ({y}, {zb})");
        let d = crate::sph::body::distance_to_polyline(&closed, y, zb);
        assert!((d - 0.005).abs() < 1e-9, "{d}");
        // Relative normal velocity (outward normal of the side: (sin 30, -cos 30)) is now zero.
        let b = 30f64.to_radians();
        let un = pt.vy[0] * b.sin() + (pt.vz[0] + 1.0) * -b.cos();
        assert!(un.abs() < 1e-12, "{un}");
    }

    #[test]
    fn particles_outside_are_left_alone() {
        let sec = Section::wedge(30f64.to_radians(), 0.25, 0.3).unwrap();
        let closed = sec.closed_contour();
        let mut pt = one_fluid(0.1, 0.02, 0.5, -2.0);
        let before = pt.clone();
        let c = resolve(&mut pt, &sec, &closed, 0.0, 1.0, 0.01, true);
        assert_eq!(c.corrected, 0);
        assert_eq!(
            (pt.y[0], pt.z[0], pt.vy[0], pt.vz[0]),
            (before.y[0], before.z[0], before.vy[0], before.vz[0])
        );
    }

    #[test]
    fn a_particle_at_the_keel_on_the_symmetry_plane_stays_on_its_side() {
        let sec = Section::wedge(45f64.to_radians(), 0.25, 0.3).unwrap();
        let closed = sec.closed_contour();
        let mut pt = one_fluid(0.001, 0.02, 0.0, 0.0);
        let c = resolve(&mut pt, &sec, &closed, 0.0, 0.0, 0.01, true);
        assert_eq!(c.corrected, 1);
        assert!(pt.y[0] >= 0.0);
        assert!(!sec.contains(pt.y[0].abs(), pt.z[0]));
    }
}
