//! Particle shifting with a free-surface treatment (the shifting of the delta+-SPH model: Sun, Colagrossi,
//! Marrone & Zhang 2017, Comput. Methods Appl. Mech. Engrg. 315, 25-49, eq. 12; free-surface detection
//! after Marrone et al. 2010, J. Sci. Comput. 45, 309-325).
//!
//! Every step each fluid particle is displaced by
//!
//! dr_i = -C Ma (2h)^2 sum_j [1 + R (W_ij / W(dp))^n] grad_i W_ij V_j,   R = 0.2, n = 4,
//!
//! with Ma = U_max / c0 and C the Courant number of the time step (Sun et al. 2017 use their Courant
//! number, 1.5 with a fourth-order Runge-Kutta step; taking the run's own keeps the displacement per unit
//! time, about U (2h)^2 / h |sum ...|, independent of the time-stepping scheme). The sum runs over all neighbours, wall and body
//! dummies and mirror images included, so the dummies keep the particles off the walls. The term in R
//! (Monaghan 2000's anti-clustering factor) pushes apart particles closer than dp.
//!
//! Free surface: lambda_i, the smaller eigenvalue of B_i = sum_j grad_i W_ij (x) r_ji V_j (1 in a full
//! kernel support), flags the surface particles (lambda_i < 0.75, the upper bound of Marrone et al.
//! 2010). Particles that are surface particles or have one within their support are shifted only along the
//! surface, dr <- (I - n n) dr, with the outward normal n_i = -B_i^-1 sum_j grad_i W_ij V_j / |...|; isolated
//! particles (lambda_i < 0.4, spray) are not shifted. A displacement is capped at 0.2 dp per step (a safeguard
//! of this implementation, not part of the published scheme).
//!
//! After the shift the density is carried to the new position with the renormalised density gradient of the
//! delta-SPH term, rho_i <- rho_i + dr_i . \<grad rho\>_i (first-order Taylor correction, Lind et al. 2012,
//! J. Comput. Phys. 231, 1499-1523, eq. 14); velocities are not corrected.
//!
//! In a refined tank ([`crate::sph::refinement`]) each pair takes the kernel of its mean smoothing
//! length h_ij, as in the momentum and continuity sums, and the particle's own spacing and smoothing
//! length set the rest: (2h)^2 and the cap use h_i and dp_i = dp 2^level_i, and the anti-clustering
//! ratio is W_ij(r) / W_ij(dp_ij) with dp_ij = dp h_ij / h, the mean spacing of the pair (the spacing at
//! which a lattice of the pair's mean resolution would sit). With one resolution this is the formula
//! above.
//!
//! Every particle's displacement is a gather over its own neighbour list in the fixed list order, so the
//! result does not depend on the number of threads.

use rayon::prelude::*;

use crate::sph::kernel::WendlandC2;
use crate::sph::neighbours::{LIST_CHUNK, NeighbourLists};
use crate::sph::particles::{Kind, Particles};

/// Anti-clustering weight R and exponent n (Sun et al. 2017, after Monaghan 2000).
pub const R_CLUSTER: f64 = 0.2;
/// Below this lambda a particle is at the free surface (Marrone et al. 2010).
pub const LAMBDA_SURFACE: f64 = 0.75;
/// Below this lambda a particle is isolated (spray) and not shifted.
pub const LAMBDA_SPLASH: f64 = 0.4;
/// Largest displacement per step, as a fraction of dp.
pub const MAX_SHIFT_DP: f64 = 0.2;

/// Per-particle free-surface data of one step.
#[derive(Debug, Clone, Default)]
pub struct Shifting {
    /// Smaller eigenvalue of B_i (fluid particles; 1 for others).
    lambda: Vec<f64>,
    /// Outward unit normal estimate (zero where undefined).
    normal: Vec<[f64; 2]>,
    /// Displacement of each fluid particle for this step.
    pub shift: Vec<[f64; 2]>,
}

impl Shifting {
    /// Bytes allocated (zero unless shifting is on).
    pub fn bytes(&self) -> usize {
        8 * self.lambda.capacity() + 16 * (self.normal.capacity() + self.shift.capacity())
    }

    /// Compute the displacements of this step from the neighbour lists of the current positions.
    /// `dp` is the particle spacing and `cfl_mach` the product C Ma of the Courant number and U_max / c0.
    pub fn compute(
        &mut self,
        lists: &NeighbourLists,
        pt: &Particles,
        kernel: &WendlandC2,
        dp: f64,
        cfl_mach: f64,
    ) {
        let n = pt.len();
        let at = lists.at(pt);
        self.lambda.resize(n, 1.0);
        self.normal.resize(n, [0.0; 2]);
        self.shift.resize(n, [0.0; 2]);
        let mut lambda = std::mem::take(&mut self.lambda);
        let mut normal = std::mem::take(&mut self.normal);
        // Pass 1: lambda and normal.
        lambda
            .par_chunks_mut(LIST_CHUNK)
            .zip(normal.par_chunks_mut(LIST_CHUNK))
            .zip(lists.chunks.par_iter())
            .enumerate()
            .for_each(|(c, ((lam, nor), _))| {
                for (k, (lam, nor)) in lam.iter_mut().zip(nor.iter_mut()).enumerate() {
                    let i = c * LIST_CHUNK + k;
                    if pt.kind[i] != Kind::Fluid {
                        *lam = 1.0;
                        *nor = [0.0; 2];
                        continue;
                    }
                    let (yi, zi) = (pt.y[i], pt.z[i]);
                    let (mut b11, mut b12, mut b22, mut gy, mut gz) = (0.0, 0.0, 0.0, 0.0, 0.0);
                    for e in at.of(c, k, i) {
                        let j = e.j;
                        let (dy, dz) = e.offset(yi, zi, &pt.y, &pt.z);
                        let fv = e.f * pt.vol[j];
                        // B = sum grad_i W (x) r_ji V = -sum F V r_ij (x) r_ij.
                        b11 -= fv * dy * dy;
                        b12 -= fv * dy * dz;
                        b22 -= fv * dz * dz;
                        gy += fv * dy;
                        gz += fv * dz;
                    }
                    let tr = 0.5 * (b11 + b22);
                    let disc = (0.25 * (b11 - b22) * (b11 - b22) + b12 * b12).sqrt();
                    *lam = tr - disc;
                    let det = b11 * b22 - b12 * b12;
                    let (ny, nz) = if det > 1e-3 {
                        (-(b22 * gy - b12 * gz) / det, -(b11 * gz - b12 * gy) / det)
                    } else {
                        (-gy, -gz)
                    };
                    let m = ny.hypot(nz);
                    *nor = if m > 0.0 { [ny / m, nz / m] } else { [0.0; 2] };
                }
            });
        self.lambda = lambda;
        self.normal = normal;
        // Pass 2: displacements.
        let h = kernel.h();
        // W_ij(dp_ij) of the pairs of levels (0, 0), (0, 1) and (1, 1), index l_i + l_j, with the pair's
        // mean spacing dp_ij = dp h_ij / h (see the module doc).
        let w_ref = [(0, 0), (0, 1), (1, 1)].map(|(a, b)| {
            let k = at.kernel.pair(a, b);
            k.w(dp * k.h() / h)
        });
        let (lambda, normal) = (&self.lambda, &self.normal);
        self.shift
            .par_chunks_mut(LIST_CHUNK)
            .zip(lists.chunks.par_iter())
            .enumerate()
            .for_each(|(c, (out, _))| {
                for (k, out) in out.iter_mut().enumerate() {
                    let i = c * LIST_CHUNK + k;
                    *out = [0.0; 2];
                    if pt.kind[i] != Kind::Fluid || lambda[i] < LAMBDA_SPLASH {
                        continue;
                    }
                    let (yi, zi) = (pt.y[i], pt.z[i]);
                    let li = pt.level[i];
                    let scale = f64::from(1u32 << li);
                    let mut near_surface = lambda[i] < LAMBDA_SURFACE;
                    let (mut sy, mut sz) = (0.0, 0.0);
                    for e in at.of(c, k, i) {
                        let j = e.j;
                        let (dy, dz) = e.offset(yi, zi, &pt.y, &pt.z);
                        let lj = pt.level[j];
                        let q = at.kernel.pair(li, lj).w(e.r) / w_ref[usize::from(li + lj)];
                        let q2 = q * q;
                        let fac = (1.0 + R_CLUSTER * q2 * q2) * e.f * pt.vol[j];
                        sy += fac * dy;
                        sz += fac * dz;
                        if e.fluid && lambda[j] < LAMBDA_SURFACE {
                            near_surface = true;
                        }
                    }
                    let two_h = 2.0 * h * scale;
                    let (mut dy, mut dz) = (
                        -cfl_mach * two_h * two_h * sy,
                        -cfl_mach * two_h * two_h * sz,
                    );
                    if near_surface {
                        let n = normal[i];
                        let dn = dy * n[0] + dz * n[1];
                        dy -= dn * n[0];
                        dz -= dn * n[1];
                    }
                    let m = dy.hypot(dz);
                    let cap = MAX_SHIFT_DP * dp * scale;
                    if m > cap {
                        dy *= cap / m;
                        dz *= cap / m;
                    }
                    *out = [dy, dz];
                }
            });
    }

    /// Move the fluid particles by their displacements and carry their densities along (see the module
    /// doc). With a symmetry plane a particle shifted through y = 0 is reflected.
    pub fn apply(&self, pt: &mut Particles, mirror: bool) {
        (
            pt.y.par_iter_mut(),
            pt.z.par_iter_mut(),
            pt.vy.par_iter_mut(),
            pt.rho.par_iter_mut(),
            pt.kind.par_iter(),
            pt.grad_rho.par_iter(),
            self.shift.par_iter(),
        )
            .into_par_iter()
            .with_min_len(4096)
            .for_each(|(y, z, vy, rho, kind, g, d)| {
                if *kind != Kind::Fluid {
                    return;
                }
                *y += d[0];
                *z += d[1];
                *rho += d[0] * g[0] + d[1] * g[1];
                if mirror && *y < 0.0 {
                    *y = -*y;
                    *vy = -*vy;
                }
            });
    }
}
