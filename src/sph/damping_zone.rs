//! An absorbing (sponge) layer along the tank walls and bottom, so that the tank can be a few beams wide
//! instead of wide enough for the acoustic echo of the impact (c0 t_end / 2 per side) to stay away from
//! the body.
//!
//! In a layer of thickness L next to the side walls and the bottom, the fluid is relaxed towards the
//! undisturbed state, the hydrostatic density rho_h(z) (from p = rho0 g (-z) through the equation of
//! state) and rest, at the rate
//!
//! sigma(xi) = sigma_max xi^2,   xi = (distance into the layer) / L in [0, 1],
//!
//! applied exactly over a step: q <- q_rest + (q - q_rest) exp(-sigma dt) for the density and the
//! velocity. This is the sponge layer of Israeli & Orszag (1981), "Approximate radiation boundary
//! conditions", J. Comput. Phys. 41, 115-135, with the quadratic ramp they recommend so that the layer
//! itself reflects little; the velocity part is the SPH damping zone of Altomare et al. (2017),
//! "Long-crested wave generation and absorption for SPH-based DualSPHysics model", Coastal Eng. 127,
//! 37-54. Damping density and velocity together absorbs both halves of an acoustic wave's energy.
//!
//! A normally incident wave that crosses the layer and comes back is attenuated by
//! exp(-2 int sigma / c0 dx) = exp(-2 sigma_max L / (3 c0)); [`SIGMA_L_OVER_C0`] = 9 makes that e^-6,
//! 0.25 %, for waves shorter than the layer. Longer waves are the quasi-incompressible flow, which a
//! finite tank changes only through the added mass of its far walls (checked against echo-free tanks in
//! `tests/sph_tank.rs`).

use rayon::prelude::*;

use crate::sph::eos::Eos;
use crate::sph::particles::{Kind, Particles};

/// sigma_max L / c0 of the layer (see the module docs).
pub const SIGMA_L_OVER_C0: f64 = 9.0;

/// The layer of a tank with side walls at |y| = `half_width` and the bottom at z = -`depth`.
#[derive(Debug, Clone, Copy)]
pub struct DampingZone {
    pub half_width: f64,
    pub depth: f64,
    /// Thickness L of the layer (m); 0 for none.
    pub thickness: f64,
    /// sigma_max (1/s).
    pub sigma_max: f64,
}

impl DampingZone {
    /// A layer of thickness `thickness` with sigma_max = [`SIGMA_L_OVER_C0`] c0 / L.
    pub fn new(half_width: f64, depth: f64, thickness: f64, c0: f64) -> Self {
        let sigma_max = if thickness > 0.0 {
            SIGMA_L_OVER_C0 * c0 / thickness
        } else {
            0.0
        };
        Self {
            half_width,
            depth,
            thickness,
            sigma_max,
        }
    }

    /// Relaxation rate at (y, z) (1/s): zero outside the layer.
    #[inline]
    pub fn sigma(&self, y: f64, z: f64) -> f64 {
        if self.thickness <= 0.0 {
            return 0.0;
        }
        let into_side = y.abs() - (self.half_width - self.thickness);
        let into_bottom = (-self.depth + self.thickness) - z;
        let xi = (into_side.max(into_bottom) / self.thickness).clamp(0.0, 1.0);
        self.sigma_max * xi * xi
    }

    /// Relax the fluid in the layer over a step dt.
    pub fn apply(&self, pt: &mut Particles, dt: f64, eos: &Eos, g: f64) {
        if self.thickness <= 0.0 {
            return;
        }
        (
            pt.y.par_iter(),
            pt.z.par_iter(),
            pt.vy.par_iter_mut(),
            pt.vz.par_iter_mut(),
            pt.rho.par_iter_mut(),
            pt.kind.par_iter(),
        )
            .into_par_iter()
            .with_min_len(4096)
            .for_each(|(y, z, vy, vz, rho, kind)| {
                if *kind != Kind::Fluid {
                    return;
                }
                let s = self.sigma(*y, *z);
                if s == 0.0 {
                    return;
                }
                let f = (-s * dt).exp();
                let rho_h = eos.density(eos.rho0 * g * (-z).max(0.0));
                *rho = rho_h + (*rho - rho_h) * f;
                *vy *= f;
                *vz *= f;
            });
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rate_ramps_quadratically_into_the_layer() {
        let z = DampingZone::new(2.0, 1.5, 0.5, 50.0);
        assert_eq!(z.sigma(0.0, -0.2), 0.0);
        assert_eq!(z.sigma(1.5, -0.2), 0.0);
        let s_mid = z.sigma(1.75, -0.2);
        assert!((s_mid / z.sigma_max - 0.25).abs() < 1e-12);
        assert!((z.sigma(2.0, -0.2) / z.sigma_max - 1.0).abs() < 1e-12);
        // Bottom layer and the corner (the deeper of the two wins).
        assert!((z.sigma(0.0, -1.25) / z.sigma_max - 0.25).abs() < 1e-12);
        assert!((z.sigma(1.75, -1.5) / z.sigma_max - 1.0).abs() < 1e-12);
        assert_eq!(DampingZone::new(2.0, 1.5, 0.0, 50.0).sigma(2.0, -1.5), 0.0);
    }
}
