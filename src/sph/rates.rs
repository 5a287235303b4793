//! The two passes over the neighbour lists that give the time derivatives of the fluid particles: the
//! momentum pass (with the neighbour search that fills the lists; here) and the continuity pass (which
//! reuses them; [`crate::sph::continuity_pass`]). With the Riemann scheme the momentum pass also sums the
//! velocity-free dissipation term of the continuity equation, whose pair distances, kernel factors,
//! pressures and densities it has at hand, for the continuity pass that follows at the same state. The
//! equations are stated in [`crate::sph::solver`]. Every sum is a gather over the neighbours of one
//! particle in the fixed cell-sorted order, so the results are bit-identical on any number of threads.
//!
//! (Evaluating each fluid pair once and scattering its share to the neighbour, in band-coloured phases
//! to stay deterministic, was tried and measured: it was no faster here, because the neighbour search and
//! the scattered writes cost what the halved pair arithmetic saves.) The pair loops run over batches of
//! neighbours ([`crate::sph::pair_batch`]) so that the compiler vectorises the pair arithmetic.

use rayon::prelude::*;

use crate::sph::case::Setup;
pub use crate::sph::continuity_pass::continuity_rates;
use crate::sph::diffusion::antuono2010;
use crate::sph::kernel::WendlandC2;
use crate::sph::neighbour_lists::{ChunkLists, LIST_CHUNK, NeighbourLists, PairKernel};
use crate::sph::neighbours::Grid;
use crate::sph::pair_batch::{BATCH, Gathered, Terms, avx2_twin, has_avx2};
use crate::sph::particles::{Kind, Particles, View};
use crate::sph::refinement::PairKernels;
use crate::sph::riemann;

/// Acceleration of every fluid particle into `rate[i][0..2]` and its renormalised density gradient (zero
/// when neither the delta-SPH diffusion nor shifting uses it) into `grad_rho[i]`, with one neighbour
/// search per fluid particle whose pairs are kept in `lists` for the next continuity pass; returns the
/// number of pair interactions.
pub fn momentum_rates(
    grid: &Grid,
    lists: &mut NeighbourLists,
    pt: &mut Particles,
    kernel: &WendlandC2,
    s: &Setup,
) -> u64 {
    // With the Riemann scheme its dissipation replaces the artificial viscosity. The renormalised
    // density gradient serves the delta-SPH diffusion and the shifting's density correction only; the
    // Riemann scheme without shifting needs none. Each combination gets its own compiled pass, so the
    // pair loop carries no tests of the configuration.
    //
    // A refined tank (two resolutions, [`crate::sph::refinement`]) has its own pass: each particle
    // searches as far as its widest pair reaches, and each pair takes the kernel of its mean smoothing
    // length. It is built for the Riemann scheme only (checked with the setup).
    let need_grad = !s.riemann || s.shifting;
    let viscous = !s.riemann && s.alpha != 0.0;
    lists.kernel = Some(PairKernel::new(kernel, pt.multi_resolution()));
    if pt.multi_resolution() {
        assert!(s.riemann, "a refined tank needs the Riemann scheme");
        return if need_grad {
            momentum_pass::<true, true, false, true>(grid, lists, pt, kernel, s)
        } else {
            momentum_pass::<true, false, false, true>(grid, lists, pt, kernel, s)
        };
    }
    match (s.riemann, need_grad, viscous) {
        (true, false, _) => momentum_pass::<true, false, false, false>(grid, lists, pt, kernel, s),
        (true, true, _) => momentum_pass::<true, true, false, false>(grid, lists, pt, kernel, s),
        (false, _, true) => momentum_pass::<false, true, true, false>(grid, lists, pt, kernel, s),
        (false, _, false) => momentum_pass::<false, true, false, false>(grid, lists, pt, kernel, s),
    }
}

/// [`momentum_rates`] for one configuration: the Riemann scheme (else the standard pressure sum),
/// the density gradient wanted, the artificial viscosity on, two resolutions.
fn momentum_pass<const RIEMANN: bool, const GRAD: bool, const VISCOUS: bool, const MULTI: bool>(
    grid: &Grid,
    lists: &mut NeighbourLists,
    pt: &mut Particles,
    kernel: &WendlandC2,
    s: &Setup,
) -> u64 {
    let kernel = *kernel;
    let h = kernel.h();
    let pairs = PairKernels::new(h);
    let visc = if VISCOUS {
        s.alpha * h * s.c0 * s.rho0
    } else {
        0.0
    };
    let c0 = s.c0;
    let eps2 = 0.01 * h * h;
    let g = s.g;
    let rho0_g = s.rho0 * s.g;
    lists.resize(pt.len());
    let avx2 = has_avx2();
    let mut out = std::mem::take(&mut pt.rate);
    let mut grad = std::mem::take(&mut pt.grad_rho);
    let n = {
        let level = &pt.level[..];
        let pt = pt.view();
        out.par_chunks_mut(LIST_CHUNK)
            .zip(grad.par_chunks_mut(LIST_CHUNK))
            .zip(lists.chunks.par_iter_mut())
            .enumerate()
            .map(|(c, ((out, grad), list))| {
                let ctx = MomentumChunk {
                    c,
                    grid,
                    pt,
                    level,
                    kernel,
                    pairs,
                    visc,
                    c0,
                    eps2,
                    g,
                    rho0_g,
                };
                #[cfg(target_arch = "x86_64")]
                if avx2 {
                    // SAFETY: the CPU has AVX2 (checked at run time above).
                    return unsafe {
                        momentum_chunk_avx2::<RIEMANN, GRAD, VISCOUS, MULTI>(&ctx, out, grad, list)
                    };
                }
                momentum_chunk::<RIEMANN, GRAD, VISCOUS, MULTI>(&ctx, out, grad, list)
            })
            .sum()
    };
    pt.grad_rho = grad;
    pt.rate = out;
    n
}

/// What a chunk of the momentum pass reads.
#[derive(Clone, Copy)]
struct MomentumChunk<'a> {
    c: usize,
    grid: &'a Grid,
    pt: View<'a>,
    level: &'a [u8],
    kernel: WendlandC2,
    pairs: PairKernels,
    visc: f64,
    c0: f64,
    eps2: f64,
    g: f64,
    rho0_g: f64,
}

avx2_twin!(momentum_chunk_avx2 = momentum_chunk<const RIEMANN: bool, const GRAD: bool, const VISCOUS: bool, const MULTI: bool>(
    ctx: &MomentumChunk,
    out: &mut [[f64; 3]],
    grad: &mut [[f64; 2]],
    list: &mut ChunkLists,
) -> u64);

/// The momentum pass over chunk `ctx.c` of the particles: search, list, pair sums.
#[inline(always)]
fn momentum_chunk<const RIEMANN: bool, const GRAD: bool, const VISCOUS: bool, const MULTI: bool>(
    ctx: &MomentumChunk,
    out: &mut [[f64; 3]],
    grad: &mut [[f64; 2]],
    list: &mut ChunkLists,
) -> u64 {
    let MomentumChunk {
        c,
        grid,
        pt,
        level,
        kernel,
        pairs,
        visc,
        c0,
        eps2,
        g,
        rho0_g,
    } = *ctx;
    list.clear();
    let mut count = 0u64;
    let mut b = Gathered::default();
    let mut t = Terms::default();
    for (k, (out, grad)) in out.iter_mut().zip(grad.iter_mut()).enumerate() {
        let i = c * LIST_CHUNK + k;
        if pt.kind[i] != Kind::Fluid {
            *out = [0.0; 3];
            *grad = [0.0; 2];
            list.end_particle();
            continue;
        }
        let (yi, zi, vyi, vzi) = (pt.y[i], pt.z[i], pt.vy[i], pt.vz[i]);
        let (rho_i, p_i) = (pt.rho[i], pt.p[i]);
        // Search first (the candidates into the list), then the batched pair loop
        // ([`crate::sph::pair_batch`]), which also flags the fluid neighbours in the list.
        let li = if MULTI { level[i] } else { 0 };
        if MULTI {
            let reach = grid.reach(li, yi, zi);
            let support2 = pairs.supports2(li);
            list.push_candidates_within(grid, pt.y, pt.z, level, yi, zi, i, support2, reach);
        } else {
            list.push_candidates(grid, pt.y, pt.z, yi, zi, i, kernel.support2());
        }
        // The kernels of i's pairs with a base-resolution and with a coarse neighbour.
        let (k0, k1) = pairs.of_particle::<MULTI>(kernel, li);
        let entries = list.last_entries();
        let (mut ay, mut az, mut vy_acc, mut vz_acc) = (0.0, 0.0, 0.0, 0.0);
        // The Riemann continuity dissipation (see `out[2]` below).
        let mut diff = 0.0;
        let mut sums = antuono2010::GradientSums::default();
        count += entries.len() as u64;
        for tags in entries.chunks_mut(BATCH) {
            let nb = tags.len();
            b.gather::<true, MULTI>(tags, &pt, level);
            for l in 0..BATCH {
                let dz = zi - b.z[l];
                let dy = yi - b.y[l];
                let r2 = dy * dy + dz * dz;
                let r = r2.sqrt();
                let f = if MULTI && b.coarse[l] {
                    k1.grad_factor(r)
                } else {
                    k0.grad_factor(r)
                };
                let fw = f * b.vol[l];
                let (dvy, dvz) = (vyi - b.vy[l], vzi - b.vz[l]);
                let psum = if RIEMANN {
                    let vdotr = dvy * dy + dvz * dz;
                    riemann::pressure_sum(p_i, b.p[l], rho_i, b.rho[l], vdotr, r, c0, b.fluid[l])
                } else {
                    p_i + b.p[l]
                };
                let pf = psum * fw;
                t.a[l] = pf * dy;
                t.b[l] = pf * dz;
                if VISCOUS {
                    let vdotd = dvy * dy + dvz * dz;
                    t.c[l] = vdotd / (r2 + eps2) * fw;
                }
                if RIEMANN {
                    let dp_hydro = -rho0_g * dz;
                    t.c[l] =
                        riemann::continuity_term(p_i, b.p[l], rho_i, b.rho[l], fw, r, c0, dp_hydro);
                }
                (t.dy[l], t.dz[l], t.fw[l]) = (dy, dz, fw);
            }
            for l in 0..nb {
                ay -= t.a[l];
                az -= t.b[l];
                if GRAD {
                    sums.add(t.fw[l], t.dy[l], t.dz[l], b.rho[l] - rho_i);
                }
                if VISCOUS && b.fluid[l] {
                    vy_acc += t.c[l] * t.dy[l];
                    vz_acc += t.c[l] * t.dz[l];
                }
                if RIEMANN && b.fluid[l] {
                    diff += t.c[l];
                }
            }
        }
        list.end_particle();
        let inv_rho = 1.0 / rho_i;
        out[0] = (ay + visc * vy_acc) * inv_rho;
        out[1] = (az + visc * vz_acc) * inv_rho - g;
        // The density rate's slot holds, until the next continuity pass (which runs at these same
        // positions and densities, [`crate::sph::integrator`]), the Riemann dissipation sum of its
        // density rate, which needs no velocities ([`crate::sph::continuity_pass`]).
        if RIEMANN {
            out[2] = diff;
        }
        *grad = if GRAD { sums.gradient() } else { [0.0; 2] };
    }
    count
}
