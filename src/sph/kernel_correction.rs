//! Kernel-gradient correction of the velocity divergence in the continuity equation (Bonet & Lok 1999,
//! Comput. Methods Appl. Mech. Engrg. 180, 97-115, eq. 40; the renormalised gradient of Randles &
//! Libersky 1996), the option `divergence_correction` of a case's `[numerics]`.
//!
//! With grad_i W_ij = F_ij r_ij (r_ij = r_i - r_j) the moment matrix of particle i is
//!
//! B_i = - sum_j V_j F_ij r_ij (x) r_ij,
//!
//! the identity for a full, regular kernel support. The corrected divergence term replaces r_ij by
//! B_i^-1 r_ij in sum_j V_j F_ij (u_i - u_j) . r_ij, so that a linear velocity field has its exact
//! divergence also where the support is cut off, at the free surface and at the jet root.
//!
//! Why: without it, a free-surface particle sees only the neighbours below it, and where the surface is
//! stretched along itself and squeezed across (ahead of the jet root of a wedge) the uncorrected sum
//! reads a compression that is not there. On a 30 deg wedge at 5 m/s (80 particles over the half-beam)
//! the surface particles 1-4 dp ahead of the wetted point reached 96-128 kPa, the Wagner peak pressure
//! being 93 kPa; their pressure then launched the surface layer against the side as a sheet, which trapped
//! a void at the jet root once the root was about 8.5 dp deep in penetration (the "jet-root lift-off" of
//! issue #9). With the correction those particles read 31-41 kPa and no void forms. Measured effects are
//! in the README (numerics) and `tests/sph_kernel_correction.rs`.
//!
//! **Not the default yet** (`[numerics] divergence_correction = true` turns it on). With it, the
//! fluid particles next to the wall at the root no longer carry the spurious pressure, and the root's
//! impact pressure is carried by the Riemann interface pressure of the fluid-body pairs. The force-panel
//! sensors (pair forces) read it: at 40 particles over the half-beam their like-for-like error is 3.3 %
//! at 30 deg and 13.2 % at 20 deg. The default interpolated sensors (the Adami wall pressure, a kernel
//! average of the particle pressures) do not: 25.3 % and 25.0 %, with their maximum long after the root
//! has passed (peak-time error 55 % at 30 deg), against 11.7 % and 3.3 % without the correction. The
//! interpolated sensors' good agreement without the correction thus rests partly on the spurious
//! surface pressure. Making the correction the default needs the force-panel sensors as the default
//! too, checked on the hull sections of `assess`; that is left for a later stop.
//!
//! Where the support is too thin for B_i to be inverted reliably (det B_i at most [`MIN_DET`]: a lone
//! particle or a single row of them in the spray) the uncorrected term is kept.
//!
//! The sum is linear in B_i^-1, so it is gathered in the same single pass over the neighbours as the
//! uncorrected one: with G_i = sum_j V_j F_ij r_ij (x) (u_i - u_j), the corrected term is
//! tr(B_i^-1 G_i) (the uncorrected one is tr G_i). Every fluid particle is corrected. Correcting only
//! those with a cut support (fewer than 3/4 of the neighbours of a full one) was tried: the 30 deg wedge's
//! last two sensors then read 13 % and 23 % high.

/// B^-1 = I as (yy, yz, zz).
const IDENTITY: [f64; 3] = [1.0, 0.0, 1.0];

/// Smallest determinant of B_i (1 for a full support) for which the correction is applied.
pub const MIN_DET: f64 = 0.25;

/// Running sums of the moment matrix B_i of one particle.
#[derive(Default, Clone, Copy)]
pub struct MomentSums {
    yy: f64,
    yz: f64,
    zz: f64,
}

impl MomentSums {
    /// Add neighbour j at offset r_ij = (dy, dz), with `fv` = F_ij V_j.
    #[inline(always)]
    pub fn add(&mut self, fv: f64, dy: f64, dz: f64) {
        self.yy -= fv * dy * dy;
        self.yz -= fv * dy * dz;
        self.zz -= fv * dz * dz;
    }

    /// B_i^-1 as (yy, yz, zz), or the identity when det B_i is at most [`MIN_DET`].
    #[inline(always)]
    pub fn inverse(&self) -> [f64; 3] {
        let det = self.yy * self.zz - self.yz * self.yz;
        if det > MIN_DET {
            [self.zz / det, -self.yz / det, self.yy / det]
        } else {
            IDENTITY
        }
    }
}

/// Running sums of B_i and G_i of one particle: the velocity divergence term with the correction.
#[derive(Default, Clone, Copy)]
pub struct DivergenceSums {
    b: MomentSums,
    yy: f64,
    yz: f64,
    zy: f64,
    zz: f64,
}

impl DivergenceSums {
    /// Add neighbour j at offset r_ij = (dy, dz) with velocity difference u_i - u_j = (dvy, dvz), `fv`
    /// = F_ij V_j.
    #[inline(always)]
    pub fn add(&mut self, fv: f64, dy: f64, dz: f64, dvy: f64, dvz: f64) {
        let (fy, fz) = (fv * dy, fv * dz);
        self.add_products(
            [fy * dy, fy * dz, fz * dz],
            [fy * dvy, fy * dvz, fz * dvy, fz * dvz],
        );
    }

    /// [`DivergenceSums::add`] with its products computed beforehand (by the batched pair loop):
    /// `moment` = F V_j (dy dy, dy dz, dz dz), `gradient` = F V_j (dy dvy, dy dvz, dz dvy, dz dvz), each
    /// product formed as (F V_j dy) dvy etc.
    #[inline(always)]
    pub fn add_products(&mut self, moment: [f64; 3], gradient: [f64; 4]) {
        self.b.yy -= moment[0];
        self.b.yz -= moment[1];
        self.b.zz -= moment[2];
        self.yy += gradient[0];
        self.yz += gradient[1];
        self.zy += gradient[2];
        self.zz += gradient[3];
    }

    /// sum_j V_j F_ij (u_i - u_j) . B_i^-1 r_ij = tr(B_i^-1 G_i).
    #[inline(always)]
    pub fn corrected(&self) -> f64 {
        let inv = self.b.inverse();
        inv[0] * self.yy + inv[1] * (self.yz + self.zy) + inv[2] * self.zz
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_full_regular_support_gives_nearly_the_identity_and_a_cut_one_is_corrected() {
        use crate::sph::kernel::WendlandC2;
        let dp = 0.01;
        let k = WendlandC2::new(1.5 * dp);
        let mut full = MomentSums::default();
        let mut half = MomentSums::default();
        for a in -5..=5 {
            for b in -5..=5 {
                if a == 0 && b == 0 {
                    continue;
                }
                // r_ij = r_i - r_j with i at the origin.
                let (dy, dz) = (-(a as f64) * dp, -(b as f64) * dp);
                let r = (dy * dy + dz * dz).sqrt();
                if r >= k.support() {
                    continue;
                }
                let fv = k.grad_factor(r) * dp * dp;
                full.add(fv, dy, dz);
                if b <= 0 {
                    half.add(fv, dy, dz);
                }
            }
        }
        let inv = full.inverse();
        assert!((inv[0] - 1.0).abs() < 0.02 && inv[1].abs() < 1e-12 && (inv[2] - 1.0).abs() < 0.02);
        // A free-surface particle (its own row and the rows below) has B_zz about half of the full
        // support's: the correction doubles the weight of the vertical offsets (and raises the
        // horizontal ones by about a third, the row above being missing from B_yy too).
        let inv = half.inverse();
        assert!(
            inv[2] > 1.9 && inv[2] < 2.1 && inv[0] > 1.2 && inv[0] < 1.5,
            "{inv:?}"
        );
        // Too thin a support keeps the uncorrected sum.
        let mut lone = MomentSums::default();
        lone.add(k.grad_factor(dp) * dp * dp, dp, 0.0);
        assert_eq!(lone.inverse(), IDENTITY);
    }
}
