//! delta-SPH density diffusion (Antuono, Colagrossi, Marrone & Molteni 2010, Comput. Phys. Commun. 181,
//! 532-549; Antuono et al. 2012, eq. 4):
//!
//! D_i = delta h c0 sum_j psi_ij . grad_i W_ij V_j,
//! psi_ij = 2 (rho_j - rho_i) r_ji / |r_ji|^2 - (\<grad rho\>_i^L + \<grad rho\>_j^L)
//!
//! with the renormalised density gradient
//!
//! \<grad rho\>_i^L = sum_j (rho_j - rho_i) L_i grad_i W_ij V_j,   L_i = [ sum_j grad_i W_ij (x) r_ji V_j ]^-1.
//!
//! The gradient correction removes the diffusion of the hydrostatic density gradient in the interior. The
//! renormalised gradient sums include the wall and body dummy particles (their density comes from the
//! extrapolated pressure, which carries the hydrostatic gradient), so L_i stays well conditioned and the
//! term stays active up to the walls; the diffusive flux itself is exchanged between fluid particles only
//! (a flux to a dummy particle would carry mass through the wall, and was seen to compress a still tank).
//! Where L_i is close to singular (a particle with very few neighbours in the spray), the uncorrected
//! gradient is used.

/// Smallest determinant of the renormalisation matrix (which is the identity in a full kernel support)
/// for which the renormalisation is applied.
const MIN_DET: f64 = 0.05;

/// Sums for the renormalised density gradient of one particle, accumulated over its neighbours (the
/// solver does this inside its momentum pass, so the gradient costs no extra neighbour loop).
#[derive(Debug, Clone, Copy, Default)]
pub struct GradientSums {
    m11: f64,
    m12: f64,
    m22: f64,
    gy: f64,
    gz: f64,
}

impl GradientSums {
    /// Add neighbour j: `fv` = F(r) V_j (so grad_i W_ij V_j = fv r_ij), r_ij = (dy, dz), `drho` = rho_j - rho_i.
    #[inline(always)]
    pub fn add(&mut self, fv: f64, dy: f64, dz: f64, drho: f64) {
        // L^-1 = sum_j grad_i W_ij (x) r_ji V_j with r_ji = -(dy, dz).
        self.m11 -= fv * dy * dy;
        self.m12 -= fv * dy * dz;
        self.m22 -= fv * dz * dz;
        self.gy += drho * fv * dy;
        self.gz += drho * fv * dz;
    }

    /// The renormalised gradient L_i sum_j (rho_j - rho_i) grad_i W_ij V_j (uncorrected where L_i is near
    /// singular).
    #[inline(always)]
    pub fn gradient(&self) -> [f64; 2] {
        let det = self.m11 * self.m22 - self.m12 * self.m12;
        if det > MIN_DET && det.is_finite() {
            [
                (self.m22 * self.gy - self.m12 * self.gz) / det,
                (self.m11 * self.gz - self.m12 * self.gy) / det,
            ]
        } else {
            [self.gy, self.gz]
        }
    }
}

/// psi_ij . grad_i W_ij for one pair, given F (grad_i W_ij = F r_ij), r_ij = (dy, dz), and the sum of the
/// two renormalised gradients.
#[inline(always)]
pub fn pair_term(f: f64, dy: f64, dz: f64, rho_i: f64, rho_j: f64, grad_sum: [f64; 2]) -> f64 {
    // psi . grad W = 2 (rho_j - rho_i) (r_ji . F r_ij) / r^2 - F (g_i + g_j) . r_ij
    //             = -2 F (rho_j - rho_i) - F (g_i + g_j) . r_ij
    -f * (2.0 * (rho_j - rho_i) + grad_sum[0] * dy + grad_sum[1] * dz)
}
