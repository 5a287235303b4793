//! The continuity pass: the density rate of every fluid particle over the neighbour lists of the last
//! momentum pass ([`crate::sph::rates`]; equations in [`crate::sph::solver`]). A gather over the
//! neighbours of one particle in the fixed cell-sorted order, so bit-identical on any number of threads.

use rayon::prelude::*;

use crate::sph::case::Setup;
use crate::sph::diffusion::antuono2010;
use crate::sph::kernel::WendlandC2;
use crate::sph::kernel_correction;
use crate::sph::neighbour_lists::{ChunkLists, LIST_CHUNK, NeighbourLists, is_fluid, neighbour};
use crate::sph::pair_batch::has_avx2;
use crate::sph::particles::{Kind, Particles, View};
use crate::sph::refinement::PairKernels;
use crate::sph::riemann;

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
    let (c0, rho0_g) = (s.c0, s.rho0 * s.g);
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
                    c0,
                    rho0_g,
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
    c0: f64,
    rho0_g: f64,
}

/// [`continuity_chunk`] compiled with AVX2.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2")]
fn continuity_chunk_avx2<const RIEMANN: bool, const CORRECTED: bool, const MULTI: bool>(
    ctx: &ContinuityChunk,
    out: &mut [[f64; 3]],
    list: &ChunkLists,
) {
    continuity_chunk::<RIEMANN, CORRECTED, MULTI>(ctx, out, list)
}

/// The continuity pass over chunk `ctx.c` of the particles.
#[inline(always)]
fn continuity_chunk<const RIEMANN: bool, const CORRECTED: bool, const MULTI: bool>(
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
        c0,
        rho0_g,
    } = *ctx;
    for (k, out) in out.iter_mut().enumerate() {
        let i = c * LIST_CHUNK + k;
        if pt.kind[i] != Kind::Fluid {
            out[2] = 0.0;
            continue;
        }
        let (yi, zi, vyi, vzi, rho_i, p_i) =
            (pt.y[i], pt.z[i], pt.vy[i], pt.vz[i], pt.rho[i], pt.p[i]);
        // The kernels of i's pairs with a base-resolution and with a coarse neighbour.
        let (k0, k1) = if MULTI {
            (*pairs.pair(level[i], 0), *pairs.pair(level[i], 1))
        } else {
            (kernel, kernel)
        };
        // Riemann dissipation is scaled by rho_i, delta-SPH by delta h c0.
        let diff_scale = if RIEMANN { rho_i } else { delta_term };
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
            let fluid = is_fluid(tag);
            if fluid && RIEMANN {
                diff += riemann::continuity_term(
                    p_i,
                    pt.p[j],
                    rho_i,
                    pt.rho[j],
                    fw,
                    r,
                    c0,
                    -rho0_g * dz,
                );
            } else if fluid {
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
        out[2] = rho_i * div + diff_scale * diff;
    }
}
