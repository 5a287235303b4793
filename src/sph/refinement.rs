//! A refined tank: particles at the base spacing dp in a band around the body, and at 2 dp (four
//! times the mass, twice the smoothing length) in the far field, where the flow of a water entry is a
//! slowly varying, nearly potential field that carries the outgoing pressure wave to the absorbing
//! layer. The far field holds most of the water of a tank a few beams wide, so the run costs about a
//! third of a uniform one.
//!
//! The two resolutions interact through one symmetric kernel per pair, with the mean smoothing length
//!
//! h_ij = (h_i + h_j) / 2,   grad_i W_ij = grad W(r_ij, h_ij),
//!
//! in the unchanged momentum and continuity sums (the particles' masses and volumes enter those sums
//! already), which keeps the pair forces antisymmetric, so momentum is conserved across the interface.
//! This is the variable-mass SPH of Omidvar, Stansby & Rogers (2012), "Wave body interaction in 2D using
//! smoothed particle hydrodynamics (SPH) with variable particle mass", Int. J. Numer. Meth. Fluids 68,
//! 686-705, with the averaged smoothing length of Hernquist & Katz (1989), ApJS 70, 419. The particles
//! keep their mass: the interface is Lagrangian, and the band is wide enough that the water near the
//! body, where the jet and the pressure peak are, stays at the base resolution for the whole run.
//!
//! Refinement needs the Riemann pair terms (their dissipation uses r_ij and the volumes only). Particle
//! shifting works with it, each pair with its own kernel and each particle with its own spacing
//! ([`crate::sph::shifting`]).

use crate::sph::eos::Eos;
use crate::sph::kernel::WendlandC2;
use crate::sph::particles::Particles;
use crate::sph::tank::{Tank, push_water_at_rest};

/// Kernels of the pairs of a two-level run: index l_i + l_j (0 base-base, 1 mixed, 2 coarse-coarse),
/// with smoothing lengths h, 1.5 h and 2 h.
#[derive(Debug, Clone, Copy)]
pub struct PairKernels {
    k: [WendlandC2; 3],
}

impl PairKernels {
    /// The kernels for the base smoothing length `h`.
    pub fn new(h: f64) -> Self {
        Self {
            k: [
                WendlandC2::new(h),
                WendlandC2::new(1.5 * h),
                WendlandC2::new(2.0 * h),
            ],
        }
    }

    /// The kernel of a pair of levels `li` and `lj` (0 or 1).
    #[inline(always)]
    pub fn pair(&self, li: u8, lj: u8) -> &WendlandC2 {
        &self.k[(li + lj) as usize]
    }

    /// The kernels of a level-`li` particle's pairs with a base-resolution and with a coarse neighbour;
    /// with one resolution (`MULTI` false) the `uniform` kernel for both.
    #[inline(always)]
    pub fn of_particle<const MULTI: bool>(
        &self,
        uniform: WendlandC2,
        li: u8,
    ) -> (WendlandC2, WendlandC2) {
        if MULTI {
            (*self.pair(li, 0), *self.pair(li, 1))
        } else {
            (uniform, uniform)
        }
    }

    /// The largest squared support of any pair of a particle of `level`: (2 h_ij)^2 with a coarse
    /// partner.
    #[inline(always)]
    pub fn widest_support2(&self, level: u8) -> f64 {
        self.k[level as usize + 1].support2()
    }

    /// The squared supports of the pairs of a particle of `level`: with a base-resolution partner
    /// (index 0) and with a coarse one (index 1). A neighbour search filtered by these keeps no pair
    /// whose kernel is zero.
    #[inline(always)]
    pub fn supports2(&self, level: u8) -> [f64; 2] {
        [
            self.k[level as usize].support2(),
            self.k[level as usize + 1].support2(),
        ]
    }
}

/// The band of base resolution: |y| <= `half_width` and z >= -`depth` (the calm surface at z = 0).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Band {
    #[serde(rename = "half_width_m")]
    pub half_width: f64,
    #[serde(rename = "depth_m")]
    pub depth: f64,
}

impl Band {
    /// Whether the lattice cell centred at (y, z) of a coarse particle lies in the band.
    fn holds(&self, y: f64, z: f64) -> bool {
        y.abs() < self.half_width && z > -self.depth
    }
}

/// Round `x` to a whole number of coarse spacings 2 dp (at least one).
pub fn to_coarse_lattice(x: f64, dp: f64) -> f64 {
    ((x / (2.0 * dp)).round()).max(1.0) * 2.0 * dp
}

/// Fill `tank` (half-width and depth whole numbers of 2 dp) with water at rest under hydrostatic
/// pressure: a dp lattice in `band` and a 2 dp lattice (level 1) elsewhere, whose cells are the 2 x 2
/// blocks of the fine one; then `layers` layers of 2 dp wall dummies (level 1) under the bottom and
/// beside the side walls ([`Tank::fill_walls`]). Fluid is placed only where `keep(y, z)`.
#[allow(clippy::too_many_arguments)]
pub fn fill(
    pt: &mut Particles,
    tank: &Tank,
    band: &Band,
    dp: f64,
    layers: usize,
    mirror: bool,
    eos: &Eos,
    g: f64,
    keep: &dyn Fn(f64, f64) -> bool,
) {
    let dc = 2.0 * dp;
    let ny = (tank.half_width / dc).round() as i64;
    let nz = (tank.depth / dc).round() as i64;
    let y_start = if mirror { 0 } else { -ny };
    for kz in 0..nz {
        for iy in y_start..ny {
            let (yc, zc) = ((iy as f64 + 0.5) * dc, -(kz as f64 + 0.5) * dc);
            if band.holds(yc, zc) {
                // The 2 x 2 block of the base lattice, row by row from the top.
                for (dz, dy) in [(-0.5, -0.5), (-0.5, 0.5), (0.5, -0.5), (0.5, 0.5)] {
                    let (y, z) = (yc + dy * dp, zc - dz * dp);
                    if keep(y, z) {
                        push_water_at_rest(pt, eos, g, y, z, dp, 0);
                    }
                }
            } else if keep(yc, zc) {
                push_water_at_rest(pt, eos, g, yc, zc, dc, 1);
            }
        }
    }
    tank.fill_walls(pt, dc, layers, mirror, eos, g, 1);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::eos::EosKind;
    use crate::sph::particles::Kind;

    #[test]
    fn the_two_lattices_fill_the_tank_with_its_water_mass() {
        let eos = Eos {
            kind: EosKind::Linear,
            rho0: 1000.0,
            c0: 20.0,
        };
        let band = Band {
            half_width: 0.2,
            depth: 0.16,
        };
        let mut pt = Particles::default();
        let dp = 0.01;
        let tank = Tank {
            half_width: 0.5,
            depth: 0.4,
            wall_height: 0.1,
        };
        fill(&mut pt, &tank, &band, dp, 3, true, &eos, 0.0, &|_, _| true);
        let fluid: Vec<usize> = (0..pt.len())
            .filter(|&i| pt.kind[i] == Kind::Fluid)
            .collect();
        let volume: f64 = fluid.iter().map(|&i| pt.vol[i]).sum();
        assert!((volume - 0.5 * 0.4).abs() < 1e-9, "{volume}");
        let fine = fluid.iter().filter(|&&i| pt.level[i] == 0).count();
        assert_eq!(fine, 20 * 16);
        assert!(pt.multi_resolution());
        // No two fluid particles closer than dp.
        for (a, &i) in fluid.iter().enumerate() {
            for &j in &fluid[a + 1..] {
                let d = (pt.y[i] - pt.y[j]).hypot(pt.z[i] - pt.z[j]);
                assert!(d > 0.99 * dp, "{i} {j} {d}");
            }
        }
    }
}
