//! Section force from the pair forces between the fluid and the body dummies (the reaction of the
//! pressure terms of the momentum equation; e.g. Bouscasse et al. 2013, Comput. Fluids 80, eq. 14, for
//! the same idea with ghost particles).
//!
//! The momentum equation gives fluid particle i the force m_i a_i = -sum_j P_ij V_i V_j grad_i W_ij from
//! the dummies j of the body, with P_ij = p_i + p_j (or 2 P* of [`crate::sph::riemann`]). The force on the
//! body is the opposite:
//!
//! F = sum_{i fluid} sum_{j body} P_ij V_i V_j grad_i W_ij = sum_i sum_j P_ij V_i F_ij V_j r_ij.
//!
//! **The wall-normal part (the default section force).** Water without viscosity loads a body by its
//! pressure, normal to the wall: F = -integral of p n ds. The pair forces also carry a force along the
//! wall, made by the Riemann dissipation: against a body dummy it mirrors the fluid velocity along e_ij,
//! so a particle sliding along the wall at speed U_t is damped by the dummies ahead of it, a friction of
//! order rho U_t^2 that does not vanish as the spacing is refined (measured on constant-speed wedges at
//! 40 and 80 particles per half-beam, `docs/numerics/wedge-convergence.md` item 9: its vertical part is
//! 3 % of the similarity force at 20 deg, 6-7 % at 30 deg and 12-16 % at 45 deg, at both spacings). The
//! default section force therefore keeps of each pair force only its component along the outward normal
//! n of the contour at the foot of the fluid particle (mirrored for a dummy across the centreline):
//!
//! F_n = sum_i sum_j (P_ij V_i F_ij V_j r_ij . n) n,
//!
//! which is also what the force-panel sensors read ([`crate::sph::sensors`]), so the sensor pressures
//! integrated around the contour give the section force. The full pair force ([`ForceMethod::PairForces`]:
//! exactly the momentum the fluid receives from the body) stays available.
//!
//! With a symmetry plane the sums run over the starboard fluid and all body dummies (real and mirror
//! images); the port fluid gives the same vertical force, so the vertical force is doubled and the
//! horizontal one is zero. Sums run over the chunks of the neighbour lists in their fixed order, so the
//! result does not depend on the number of threads.
//!
//! [`ForceMethod::PairForces`]: crate::sph::case::ForceMethod::PairForces

use rayon::prelude::*;

use crate::sph::air::AirPhase;
use crate::sph::body::{Section, nearest_on_polyline, outward_normal};
use crate::sph::neighbour_lists::{LIST_CHUNK, ListsAt, NeighbourLists};
use crate::sph::particles::{Kind, Particles};
use crate::sph::riemann;
use crate::sph::sensors::SensorSet;

/// Per-chunk partial sums of the body forces, kept between steps so that the time loop does not allocate.
#[derive(Debug, Clone, Default)]
pub struct ForceScratch {
    chunks: Vec<[f64; 2]>,
    panels: Vec<[f64; 2]>,
    out: Vec<[f64; 2]>,
}

/// The outward unit normals (from the body into the water) of the segments of the starboard half
/// contour, body frame (keel at the origin), for the wall-normal section force.
#[derive(Debug, Clone, Default)]
pub struct WallNormals {
    half: Vec<[f64; 2]>,
    normals: Vec<[f64; 2]>,
}

impl WallNormals {
    pub fn new(section: &Section) -> Self {
        let half = section.half_points().to_vec();
        // (A section's points are distinct, so no segment has zero length; one would get no normal.)
        let normals = half
            .windows(2)
            .map(|w| outward_normal(w[0], w[1]).map_or([0.0, 0.0], |(n, _)| n))
            .collect();
        WallNormals { half, normals }
    }

    /// Outward normal of the contour at the foot of the body-frame point (y, z): on the starboard half
    /// for y >= 0, on its mirror image (n_y reversed) for y < 0.
    pub fn at(&self, y: f64, z: f64) -> Option<[f64; 2]> {
        let (k, _, _) = nearest_on_polyline(&self.half, y.abs(), z)?;
        let [ny, nz] = self.normals[k];
        Some(if y < 0.0 { [-ny, nz] } else { [ny, nz] })
    }
}

/// Force (y, z) on the body (N/m) from the neighbour lists of the last momentum pass (which must belong
/// to the current positions and storage order). `riemann` and `c0` select the pressure term as in the
/// momentum pass. `z_range` bounds the heights of the fluid particles that can touch a body dummy (the
/// body's height range widened by the dummy layers and the kernel support): the particles are sorted by
/// grid row, so a chunk whose first and last particles lie both below or both above it is skipped.
/// With `normal_part` (the contour normals and the keel height), only the wall-normal part of each pair
/// force counts (see the module doc). With `air`, the air particles' pair forces count too (with the
/// air's wall term, [`crate::sph::air`]).
#[allow(clippy::too_many_arguments)]
pub fn interaction_force(
    lists: &NeighbourLists,
    pt: &Particles,
    riemann: bool,
    c0: f64,
    air: Option<&AirPhase>,
    mirror: bool,
    z_range: [f64; 2],
    normal_part: Option<(&WallNormals, f64)>,
    scratch: &mut ForceScratch,
) -> [f64; 2] {
    let at = lists.at(pt);
    lists
        .chunks
        .par_iter()
        .enumerate()
        .map(|(c, _)| {
            let (mut fy, mut fz) = (0.0, 0.0);
            let n = LIST_CHUNK.min(pt.len().saturating_sub(c * LIST_CHUNK));
            let (first, last) = (c * LIST_CHUNK, c * LIST_CHUNK + n.max(1) - 1);
            if n == 0
                || (pt.z[first].max(pt.z[last]) < z_range[0])
                || (pt.z[first].min(pt.z[last]) > z_range[1])
            {
                return [0.0, 0.0];
            }
            for k in 0..n {
                let i = c * LIST_CHUNK + k;
                if !pt.kind[i].is_fluid() {
                    continue;
                }
                if let Some([py, pz]) =
                    body_pair_force(&at, c, k, i, pt, riemann, c0, air, normal_part)
                {
                    fy += py;
                    fz += pz;
                }
            }
            [fy, fz]
        })
        .collect_into_vec(&mut scratch.chunks);
    let (mut fy, mut fz) = (0.0, 0.0);
    for p in &scratch.chunks {
        fy += p[0];
        fz += p[1];
    }
    if mirror { [0.0, 2.0 * fz] } else { [fy, fz] }
}

/// Force (y, z) on the body (N/m) from the pair forces of [`interaction_force`], attributed to the
/// contour at the foot of each fluid particle: the force between fluid particle i and all the body
/// dummies (real and mirror images) counts for a panel of `set` with the fraction of the contour the
/// particle stands for (dp about the nearest contour point of i) that lies on the panel
/// ([`SensorSet::panel_weight`]; body frame: keel at `z_keel`; starboard fluid only, y >= 0). One entry
/// per sensor, summed per chunk and then over the chunks in their fixed order (thread-count independent).
#[allow(clippy::too_many_arguments)]
pub fn panel_forces<'a>(
    lists: &NeighbourLists,
    pt: &Particles,
    riemann: bool,
    c0: f64,
    air: Option<&AirPhase>,
    z_keel: f64,
    set: &SensorSet,
    scratch: &'a mut ForceScratch,
) -> &'a [[f64; 2]] {
    let panels = set.panels();
    let np = panels.len();
    scratch.out.clear();
    scratch.out.resize(np, [0.0; 2]);
    if np == 0 {
        return &scratch.out;
    }
    scratch.panels.clear();
    scratch.panels.resize(np * lists.chunks.len(), [0.0; 2]);
    let at = lists.at(pt);
    scratch
        .panels
        .par_chunks_mut(np)
        .zip(lists.chunks.par_iter())
        .enumerate()
        .for_each(|(c, (f, _))| {
            let n = LIST_CHUNK.min(pt.len().saturating_sub(c * LIST_CHUNK));
            for k in 0..n {
                let i = c * LIST_CHUNK + k;
                if !pt.kind[i].is_fluid() || pt.y[i] < 0.0 {
                    continue;
                }
                let Some([fy, fz]) = body_pair_force(&at, c, k, i, pt, riemann, c0, air, None)
                else {
                    continue;
                };
                let s = set.arc_of(pt.y[i], pt.z[i] - z_keel);
                for (fk, p) in f.iter_mut().zip(panels) {
                    let a = set.panel_weight(p, s);
                    fk[0] += a * fy;
                    fk[1] += a * fz;
                }
            }
        });
    for part in scratch.panels.chunks(np) {
        for (o, p) in scratch.out.iter_mut().zip(part) {
            o[0] += p[0];
            o[1] += p[1];
        }
    }
    &scratch.out
}

/// The force of fluid particle i (entry k of its list chunk) on all the body dummies it neighbours (real
/// and mirror images), sum_j P_ij V_i F_ij V_j r_ij; `None` when it touches no body dummy. With
/// `normal_part` (the contour normals and the keel height), only each pair force's component along the
/// wall normal at the particle's foot (along its mirror image for a dummy on the other side of the
/// centreline); the foot is looked up once, at the first body dummy, so particles that touch none cost
/// no search.
#[allow(clippy::too_many_arguments)]
fn body_pair_force(
    at: &ListsAt,
    c: usize,
    k: usize,
    i: usize,
    pt: &Particles,
    riemann: bool,
    c0: f64,
    air: Option<&AirPhase>,
    normal_part: Option<(&WallNormals, f64)>,
) -> Option<[f64; 2]> {
    let (yi, zi, vyi, vzi) = (pt.y[i], pt.z[i], pt.vy[i], pt.vz[i]);
    let (p_i, rho_i, vol_i) = (pt.p[i], pt.rho[i], pt.vol[i]);
    // An air particle meets the wall with its own pressure and its phase's sound speed.
    let wall_air = match (pt.kind[i], air) {
        (Kind::Air, Some(a)) => Some(a.c),
        (Kind::Air, None) => return None,
        _ => None,
    };
    let (mut fy, mut fz, mut touches) = (0.0, 0.0, false);
    // The wall normal at i's foot (body frame: keel at z_keel), once i is found to touch the body.
    let mut normal: Option<Option<[f64; 2]>> = None;
    for e in at.of(c, k, i) {
        let j = e.j;
        if e.fluid || pt.kind[j] != Kind::Body {
            continue;
        }
        touches = true;
        let (dy, dz) = e.offset(yi, zi, &pt.y, &pt.z);
        let vyj = if e.mirrored { -pt.vy[j] } else { pt.vy[j] };
        let vdotr = (vyi - vyj) * dy + (vzi - pt.vz[j]) * dz;
        let psum = if let Some(c_air) = wall_air {
            crate::sph::air::wall_pressure_sum(p_i, rho_i, vdotr, e.r, c_air)
        } else if riemann {
            riemann::pressure_sum(p_i, pt.p[j], rho_i, pt.rho[j], vdotr, e.r, c0, false)
        } else {
            p_i + pt.p[j]
        };
        let w = psum * vol_i * e.f * pt.vol[j];
        let n = *normal.get_or_insert_with(|| {
            normal_part.and_then(|(walls, z_keel)| walls.at(yi, zi - z_keel))
        });
        match n {
            Some([ny, nz]) => {
                // The dummy's side of the centreline (a mirror image lies on the other side).
                let yj = if e.mirrored { -pt.y[j] } else { pt.y[j] };
                let ny = if yj * yi < 0.0 { -ny } else { ny };
                let fn_ = w * (dy * ny + dz * nz);
                fy += fn_ * ny;
                fz += fn_ * nz;
            }
            None => {
                fy += w * dy;
                fz += w * dz;
            }
        }
    }
    touches.then_some([fy, fz])
}
