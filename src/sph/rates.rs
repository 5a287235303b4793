//! The two passes over the neighbour lists that give the time derivatives of the fluid particles: the
//! momentum pass (with the neighbour search that fills the lists) and the continuity pass (which reuses
//! them). The equations are stated in [`crate::sph::solver`]. Every sum is a gather over the neighbours
//! of one particle in the fixed cell-sorted order, so the results are bit-identical on any number of
//! threads.
//!
//! (Evaluating each fluid pair once and scattering its share to the neighbour, in band-coloured phases
//! to stay deterministic, was tried and measured: it was no faster here, because the neighbour search and
//! the scattered writes cost what the halved pair arithmetic saves.)

use rayon::prelude::*;

use crate::sph::case::Setup;
use crate::sph::diffusion::antuono2010;
use crate::sph::kernel::WendlandC2;
use crate::sph::kernel_correction;
use crate::sph::neighbours::{Grid, LIST_CHUNK, NeighbourLists};
use crate::sph::particles::{Kind, Particles};
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
    match (s.riemann, s.divergence_correction) {
        (true, false) => continuity_pass::<true, false>(lists, pt, kernel, s),
        (false, false) => continuity_pass::<false, false>(lists, pt, kernel, s),
        (true, true) => continuity_pass::<true, true>(lists, pt, kernel, s),
        (false, true) => continuity_pass::<false, true>(lists, pt, kernel, s),
    }
}

/// [`continuity_rates`] with the Riemann dissipation (else the delta-SPH diffusion) and with the
/// kernel-gradient-corrected divergence ([`kernel_correction`]) or without, compiled separately so that
/// the pair loop carries no test of the scheme.
fn continuity_pass<const RIEMANN: bool, const CORRECTED: bool>(
    lists: &NeighbourLists,
    pt: &mut Particles,
    kernel: &WendlandC2,
    s: &Setup,
) {
    let delta_term = s.delta * kernel.h() * s.c0;
    let (c0, rho0_g) = (s.c0, s.rho0 * s.g);
    let mut out = std::mem::take(&mut pt.rate);
    {
        let grad_rho = &pt.grad_rho[..pt.len()];
        let pt = pt.view();
        out.par_chunks_mut(LIST_CHUNK)
            .zip(lists.chunks.par_iter())
            .enumerate()
            .for_each(|(c, (out, list))| {
                for (k, out) in out.iter_mut().enumerate() {
                    let i = c * LIST_CHUNK + k;
                    if pt.kind[i] != Kind::Fluid {
                        out[2] = 0.0;
                        continue;
                    }
                    let (yi, zi, vyi, vzi, rho_i, p_i) =
                        (pt.y[i], pt.z[i], pt.vy[i], pt.vz[i], pt.rho[i], pt.p[i]);
                    // Riemann dissipation is scaled by rho_i, delta-SPH by delta h c0.
                    let diff_scale = if RIEMANN { rho_i } else { delta_term };
                    let gi = grad_rho[i];
                    let mut corrected = kernel_correction::DivergenceSums::default();
                    let (mut div, mut diff) = (0.0, 0.0);
                    for e in list.of(k) {
                        let j = e.j;
                        let fw = e.f * pt.vol[j];
                        let dz = zi - pt.z[j];
                        let (dy, vyj) = if e.mirrored {
                            (yi + pt.y[j], -pt.vy[j])
                        } else {
                            (yi - pt.y[j], pt.vy[j])
                        };
                        if CORRECTED {
                            corrected.add(fw, dy, dz, vyi - vyj, vzi - pt.vz[j]);
                        } else {
                            div += fw * ((vyi - vyj) * dy + (vzi - pt.vz[j]) * dz);
                        }
                        // Diffusion only between fluid particles: a flux to a dummy particle would
                        // be a mass flux through the wall.
                        if e.fluid && RIEMANN {
                            diff += riemann::continuity_term(
                                p_i,
                                pt.p[j],
                                rho_i,
                                pt.rho[j],
                                fw,
                                e.r,
                                c0,
                                -rho0_g * dz,
                            );
                        } else if e.fluid {
                            let gj = if e.mirrored {
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
            });
    }
    pt.rate = out;
}

/// Acceleration of every fluid particle into `rate[i][0..2]` and its renormalised density gradient (zero when neither the delta-SPH diffusion nor shifting uses it) into
/// `grad_rho[i]`, with one neighbour search per fluid particle whose pairs and kernel gradient factors are
/// kept in `lists` for the next continuity pass; returns the number of pair interactions.
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
    // length. It is built for the Riemann scheme without shifting only (checked with the setup).
    let need_grad = !s.riemann || s.shifting;
    let viscous = !s.riemann && s.alpha != 0.0;
    if pt.multi_resolution() {
        assert!(
            s.riemann && !need_grad,
            "a refined tank needs the Riemann scheme without shifting"
        );
        return momentum_pass::<true, false, false, true>(grid, lists, pt, kernel, s);
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
    lists.resize(pt.len());
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
                list.clear();
                let mut count = 0u64;
                for (k, (out, grad)) in out.iter_mut().zip(grad.iter_mut()).enumerate() {
                    let i = c * LIST_CHUNK + k;
                    if pt.kind[i] != Kind::Fluid {
                        out[0] = 0.0;
                        out[1] = 0.0;
                        *grad = [0.0; 2];
                        list.end_particle();
                        continue;
                    }
                    let (yi, zi, vyi, vzi) = (pt.y[i], pt.z[i], pt.vy[i], pt.vz[i]);
                    let (rho_i, p_i) = (pt.rho[i], pt.p[i]);
                    // Search first (the candidates into the list), then one loop that completes
                    // each entry (distance, kernel factor, fluid flag, kept for the continuity pass)
                    // and sums its terms: the accumulators stay in registers, and the neighbour's
                    // position is loaded once.
                    let li = if MULTI { level[i] } else { 0 };
                    if MULTI {
                        let reach = grid.reach(li, yi, zi);
                        let support2 = pairs.supports2(li);
                        list.push_candidates_within(
                            grid, pt.y, pt.z, level, yi, zi, i, support2, reach,
                        );
                    } else {
                        list.push_candidates(grid, pt.y, pt.z, yi, zi, i, kernel.support2());
                    }
                    let mut entries = list.last_entries();
                    let (mut ay, mut az, mut vy_acc, mut vz_acc) = (0.0, 0.0, 0.0, 0.0);
                    let mut sums = antuono2010::GradientSums::default();
                    let m = entries.len() as u64;
                    for k in 0..entries.len() {
                        let (j, mirrored) = entries.neighbour(k);
                        let dz = zi - pt.z[j];
                        let (dy, vyj) = if mirrored {
                            (yi + pt.y[j], -pt.vy[j])
                        } else {
                            (yi - pt.y[j], pt.vy[j])
                        };
                        let r2 = dy * dy + dz * dz;
                        let r = r2.sqrt();
                        let f = if MULTI {
                            pairs.pair(li, level[j]).grad_factor(r)
                        } else {
                            kernel.grad_factor(r)
                        };
                        let fluid = pt.kind[j] == Kind::Fluid;
                        entries.complete(k, r, f, fluid);
                        let rho_j = pt.rho[j];
                        let fw = f * pt.vol[j];
                        let psum = if RIEMANN {
                            let vdotr = (vyi - vyj) * dy + (vzi - pt.vz[j]) * dz;
                            riemann::pressure_sum(p_i, pt.p[j], rho_i, rho_j, vdotr, r, c0, fluid)
                        } else {
                            p_i + pt.p[j]
                        };
                        let pf = psum * fw;
                        ay -= pf * dy;
                        az -= pf * dz;
                        if GRAD {
                            sums.add(fw, dy, dz, rho_j - rho_i);
                        }
                        if VISCOUS && fluid {
                            let vdotd = (vyi - vyj) * dy + (vzi - pt.vz[j]) * dz;
                            let pi = vdotd / (r2 + eps2) * fw;
                            vy_acc += pi * dy;
                            vz_acc += pi * dz;
                        }
                    }
                    count += m;
                    list.end_particle();
                    let inv_rho = 1.0 / rho_i;
                    out[0] = (ay + visc * vy_acc) * inv_rho;
                    out[1] = (az + visc * vz_acc) * inv_rho - g;
                    *grad = if GRAD { sums.gradient() } else { [0.0; 2] };
                }
                count
            })
            .sum()
    };
    pt.grad_rho = grad;
    pt.rate = out;
    n
}
