//! delta-SPH density diffusion (Antuono, Colagrossi, Marrone & Molteni 2010, Comput. Phys. Commun. 181,
//! 532-549; Antuono et al. 2012, eq. 4):
//!
//! D_i = delta h c0 sum_j psi_ij . grad_i W_ij V_j,
//! psi_ij = 2 (rho_j - rho_i) r_ji / |r_ji|^2 - (<grad rho>_i^L + <grad rho>_j^L)
//!
//! with the renormalised density gradient
//!
//! <grad rho>_i^L = sum_j (rho_j - rho_i) L_i grad_i W_ij V_j,   L_i = [ sum_j grad_i W_ij (x) r_ji V_j ]^-1.
//!
//! The gradient correction removes the diffusion of the hydrostatic density gradient in the interior. The
//! renormalised gradient sums include the wall and body dummy particles (their density comes from the
//! extrapolated pressure, which carries the hydrostatic gradient), so L_i stays well conditioned and the
//! term stays active up to the walls; the diffusive flux itself is exchanged between fluid particles only
//! (a flux to a dummy particle would carry mass through the wall, and was seen to compress a still tank).
//! Where L_i is close to singular (a particle with very few neighbours in the spray), the uncorrected
//! gradient is used.

use rayon::prelude::*;

use crate::sph::kernel::WendlandC2;
use crate::sph::neighbours::{Grid, for_each_neighbour};
use crate::sph::particles::{Kind, Particles};

/// Smallest determinant of the renormalisation matrix (which is the identity in a full kernel support)
/// for which the renormalisation is applied.
const MIN_DET: f64 = 0.05;

/// Compute the renormalised density gradient of every fluid particle into `pt.grad_rho`.
pub fn density_gradients(grid: &Grid, pt: &mut Particles, kernel: &WendlandC2, mass: f64) {
    let mut out = std::mem::take(&mut pt.grad_rho);
    {
        let ptr: &Particles = pt;
        out.par_iter_mut()
            .with_min_len(512)
            .enumerate()
            .for_each(|(i, g)| {
                if ptr.kind[i] != Kind::Fluid {
                    *g = [0.0; 2];
                    return;
                }
                let rho_i = ptr.rho[i];
                let (mut m11, mut m12, mut m22, mut gy, mut gz) = (0.0, 0.0, 0.0, 0.0, 0.0);
                for_each_neighbour(
                    grid,
                    &ptr.y,
                    &ptr.z,
                    ptr.y[i],
                    ptr.z[i],
                    i,
                    kernel.support2(),
                    |j, dy, dz, r2, _| {
                        let rho_j = ptr.rho[j];
                        let f = kernel.grad_factor(r2.sqrt()) * mass / rho_j;
                        // grad_i W V_j = f (dy, dz); r_ji = -(dy, dz).
                        m11 -= f * dy * dy;
                        m12 -= f * dy * dz;
                        m22 -= f * dz * dz;
                        let d = rho_j - rho_i;
                        gy += d * f * dy;
                        gz += d * f * dz;
                    },
                );
                let det = m11 * m22 - m12 * m12;
                *g = if det > MIN_DET && det.is_finite() {
                    [(m22 * gy - m12 * gz) / det, (m11 * gz - m12 * gy) / det]
                } else {
                    [gy, gz]
                };
            });
    }
    pt.grad_rho = out;
}

/// psi_ij . grad_i W_ij for one pair, given F (grad_i W_ij = F r_ij), r_ij = (dy, dz), and the sum of the
/// two renormalised gradients.
#[inline(always)]
pub fn pair_term(f: f64, dy: f64, dz: f64, rho_i: f64, rho_j: f64, grad_sum: [f64; 2]) -> f64 {
    // psi . grad W = 2 (rho_j - rho_i) (r_ji . F r_ij) / r^2 - F (g_i + g_j) . r_ij
    //             = -2 F (rho_j - rho_i) - F (g_i + g_j) . r_ij
    -f * (2.0 * (rho_j - rho_i) + grad_sum[0] * dy + grad_sum[1] * dz)
}
