//! The continuity pass: the density rate of every fluid particle over the neighbour lists of the last
//! momentum pass ([`crate::sph::rates`]; equations in [`crate::sph::solver`]). A gather over the
//! neighbours of one particle in the fixed cell-sorted order, so bit-identical on any number of threads.
//!
//! With the Riemann scheme the density rate is rho_i (sum_j (u_i - u_j) . grad_i W_ij V_j + D_i), with
//! D_i the dissipation sum of [`riemann::continuity_term`]. The continuity pass runs at the positions and
//! densities of the last momentum pass (only the velocities have been kicked since,
//! [`crate::sph::integrator`]), and D_i needs no velocities, so the momentum pass sums it (from the pair
//! distances, kernel factors, pressures and densities it has at hand) and leaves it in the density
//! rate's slot; this pass then reads only the neighbours' positions, velocities and volumes, in batches
//! that the compiler vectorises ([`crate::sph::pair_batch`]). The terms and the order of the sums are
//! those of one pair at a time, so the rates are bit-identical to a separate dissipation loop.

use rayon::prelude::*;

use crate::sph::case::Setup;
use crate::sph::diffusion::antuono2010;
use crate::sph::kernel::WendlandC2;
use crate::sph::kernel_correction;
use crate::sph::neighbour_lists::{ChunkLists, LIST_CHUNK, NeighbourLists, is_fluid, neighbour};
use crate::sph::pair_batch::{KINEMATIC_BATCH, KinematicTerms, Kinematics, avx2_twin, has_avx2};
use crate::sph::particles::{Kind, Particles, View};
use crate::sph::refinement::PairKernels;

/// Density rate of every fluid particle (continuity with delta-SPH diffusion) into `rate[i][2]`, over the
/// neighbour lists of the last momentum pass (which must have run at the current positions and storage
/// order; only the velocities have changed since).
pub fn continuity_rates(
    lists: &NeighbourLists,
    pt: &mut Particles,
    kernel: &WendlandC2,
    s: &Setup,
) {
    // A refined tank runs the Riemann scheme (checked by the momentum pass), with the corrected
    // divergence or without.
    if pt.multi_resolution() {
        return match s.divergence_correction {
            false => continuity_pass::<true, false, true>(lists, pt, kernel, s),
            true => continuity_pass::<true, true, true>(lists, pt, kernel, s),
        };
    }
    match (s.riemann, s.divergence_correction) {
        (true, false) => continuity_pass::<true, false, false>(lists, pt, kernel, s),
        (false, false) => continuity_pass::<false, false, false>(lists, pt, kernel, s),
        (true, true) => continuity_pass::<true, true, false>(lists, pt, kernel, s),
        (false, true) => continuity_pass::<false, true, false>(lists, pt, kernel, s),
    }
}

/// [`continuity_rates`] with the Riemann dissipation (else the delta-SPH diffusion), with the
/// kernel-gradient-corrected divergence ([`kernel_correction`]) or without, and with two resolutions,
/// compiled separately so that the pair loop carries no test of the scheme. Distances and kernel factors
/// are recomputed from the positions as in the momentum pass ([`crate::sph::neighbour_lists`]).
fn continuity_pass<const RIEMANN: bool, const CORRECTED: bool, const MULTI: bool>(
    lists: &NeighbourLists,
    pt: &mut Particles,
    kernel: &WendlandC2,
    s: &Setup,
) {
    let delta_term = s.delta * kernel.h() * s.c0;
    let kernel = *kernel;
    let pairs = PairKernels::new(kernel.h());
    let avx2 = has_avx2();
    let mut out = std::mem::take(&mut pt.rate);
    {
        let grad_rho = &pt.grad_rho[..pt.len()];
        let level = &pt.level[..];
        let pt = pt.view();
        out.par_chunks_mut(LIST_CHUNK)
            .zip(lists.chunks.par_iter())
            .enumerate()
            .for_each(|(c, (out, list))| {
                let ctx = ContinuityChunk {
                    c,
                    pt,
                    grad_rho,
                    level,
                    kernel,
                    pairs,
                    delta_term,
                };
                #[cfg(target_arch = "x86_64")]
                if avx2 {
                    // SAFETY: the CPU has AVX2 (checked at run time above).
                    unsafe { continuity_chunk_avx2::<RIEMANN, CORRECTED, MULTI>(&ctx, out, list) };
                    return;
                }
                continuity_chunk::<RIEMANN, CORRECTED, MULTI>(&ctx, out, list);
            });
    }
    pt.rate = out;
}

/// What a chunk of the continuity pass reads.
#[derive(Clone, Copy)]
struct ContinuityChunk<'a> {
    c: usize,
    pt: View<'a>,
    grad_rho: &'a [[f64; 2]],
    level: &'a [u8],
    kernel: WendlandC2,
    pairs: PairKernels,
    delta_term: f64,
}

avx2_twin!(continuity_chunk_avx2 = continuity_chunk<const RIEMANN: bool, const CORRECTED: bool, const MULTI: bool>(
    ctx: &ContinuityChunk,
    out: &mut [[f64; 3]],
    list: &ChunkLists,
));

/// The continuity pass over chunk `ctx.c` of the particles, for the scheme.
#[inline(always)]
fn continuity_chunk<const RIEMANN: bool, const CORRECTED: bool, const MULTI: bool>(
    ctx: &ContinuityChunk,
    out: &mut [[f64; 3]],
    list: &ChunkLists,
) {
    if RIEMANN {
        riemann_continuity_chunk::<CORRECTED, MULTI>(ctx, out, list)
    } else {
        delta_sph_continuity_chunk::<CORRECTED, MULTI>(ctx, out, list)
    }
}

/// The continuity pass of the Riemann scheme over chunk `ctx.c` of the particles: the velocity
/// divergence in batches of neighbours, plus the dissipation sum the momentum pass left in `out[2]`.
#[inline(always)]
fn riemann_continuity_chunk<const CORRECTED: bool, const MULTI: bool>(
    ctx: &ContinuityChunk,
    out: &mut [[f64; 3]],
    list: &ChunkLists,
) {
    let ContinuityChunk {
        c,
        pt,
        level,
        kernel,
        pairs,
        ..
    } = *ctx;
    let mut b = Kinematics::default();
    let mut t = KinematicTerms::default();
    for (k, out) in out.iter_mut().enumerate() {
        let i = c * LIST_CHUNK + k;
        if pt.kind[i] != Kind::Fluid {
            out[2] = 0.0;
            continue;
        }
        let (yi, zi, vyi, vzi, rho_i) = (pt.y[i], pt.z[i], pt.vy[i], pt.vz[i], pt.rho[i]);
        let (k0, k1) = pairs.of_particle::<MULTI>(kernel, level[i]);
        let mut corrected = kernel_correction::DivergenceSums::default();
        let mut div = 0.0;
        for tags in list.tags(k).chunks(KINEMATIC_BATCH) {
            b.gather::<MULTI>(tags, &pt, level);
            for l in 0..KINEMATIC_BATCH {
                let dy = yi - b.y[l];
                let dz = zi - b.z[l];
                let r = (dy * dy + dz * dz).sqrt();
                let f = if MULTI && b.coarse[l] {
                    k1.grad_factor_lane(r)
                } else {
                    k0.grad_factor_lane(r)
                };
                let fw = f * b.vol[l];
                let (dvy, dvz) = (vyi - b.vy[l], vzi - b.vz[l]);
                let (m, g) = (&mut t.moment, &mut t.gradient);
                if CORRECTED {
                    let (fy, fz) = (fw * dy, fw * dz);
                    (m[0][l], m[1][l], m[2][l]) = (fy * dy, fy * dz, fz * dz);
                    (g[0][l], g[1][l], g[2][l], g[3][l]) = (fy * dvy, fy * dvz, fz * dvy, fz * dvz);
                } else {
                    m[0][l] = fw * (dvy * dy + dvz * dz);
                }
            }
            let (m, g) = (&t.moment, &t.gradient);
            for l in 0..tags.len() {
                if CORRECTED {
                    corrected.add_products(
                        [m[0][l], m[1][l], m[2][l]],
                        [g[0][l], g[1][l], g[2][l], g[3][l]],
                    );
                } else {
                    div += m[0][l];
                }
            }
        }
        if CORRECTED {
            div = corrected.corrected();
        }
        out[2] = rho_i * div + rho_i * out[2];
    }
}

/// The continuity pass of the delta-SPH scheme over chunk `ctx.c` of the particles.
#[inline(always)]
fn delta_sph_continuity_chunk<const CORRECTED: bool, const MULTI: bool>(
    ctx: &ContinuityChunk,
    out: &mut [[f64; 3]],
    list: &ChunkLists,
) {
    let ContinuityChunk {
        c,
        pt,
        grad_rho,
        level,
        kernel,
        pairs,
        delta_term,
    } = *ctx;
    for (k, out) in out.iter_mut().enumerate() {
        let i = c * LIST_CHUNK + k;
        if pt.kind[i] != Kind::Fluid {
            out[2] = 0.0;
            continue;
        }
        let (yi, zi, vyi, vzi, rho_i) = (pt.y[i], pt.z[i], pt.vy[i], pt.vz[i], pt.rho[i]);
        // The kernels of i's pairs with a base-resolution and with a coarse neighbour.
        let (k0, k1) = pairs.of_particle::<MULTI>(kernel, level[i]);
        let gi = grad_rho[i];
        let mut corrected = kernel_correction::DivergenceSums::default();
        let (mut div, mut diff) = (0.0, 0.0);
        for &tag in list.tags(k) {
            let (j, mirrored) = neighbour(tag);
            let dz = zi - pt.z[j];
            let (dy, vyj) = if mirrored {
                (yi + pt.y[j], -pt.vy[j])
            } else {
                (yi - pt.y[j], pt.vy[j])
            };
            let r = (dy * dy + dz * dz).sqrt();
            let f = if MULTI && level[j] != 0 {
                k1.grad_factor(r)
            } else {
                k0.grad_factor(r)
            };
            let fw = f * pt.vol[j];
            if CORRECTED {
                corrected.add(fw, dy, dz, vyi - vyj, vzi - pt.vz[j]);
            } else {
                div += fw * ((vyi - vyj) * dy + (vzi - pt.vz[j]) * dz);
            }
            // Diffusion only between fluid particles: a flux to a dummy particle would be a mass
            // flux through the wall.
            if is_fluid(tag) {
                let gj = if mirrored {
                    [-grad_rho[j][0], grad_rho[j][1]]
                } else {
                    grad_rho[j]
                };
                let gsum = [gi[0] + gj[0], gi[1] + gj[1]];
                diff += antuono2010::pair_term(fw, dy, dz, rho_i, pt.rho[j], gsum);
            }
        }
        if CORRECTED {
            div = corrected.corrected();
        }
        out[2] = rho_i * div + delta_term * diff;
    }
}
