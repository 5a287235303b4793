//! The tank: a rectangle of water at rest (hydrostatic pressure) with dummy-particle walls at the sides and
//! the bottom. With a symmetry plane only the half y >= 0 is built.

use crate::sph::eos::Eos;
use crate::sph::particles::{Kind, Particles};

/// Tank geometry in the 2D water-entry frame (free surface at z = 0).
#[derive(Debug, Clone, Copy)]
pub struct Tank {
    /// Half-width of the water (m): the side walls are at y = +-half_width.
    pub half_width: f64,
    /// Water depth (m): the bottom is at z = -depth.
    pub depth: f64,
    /// Height of the side walls above the calm water surface (m).
    pub wall_height: f64,
}

impl Tank {
    /// Fill with fluid on a square lattice of spacing dp (cell centres) and add `layers` layers of wall
    /// dummy particles. Pressures and densities are hydrostatic, p = rho0 g (-z); each fluid particle's mass
    /// is its initial density times dp^2, so the lattice is in equilibrium from the start (a uniform mass
    /// rho0 dp^2 with hydrostatic densities gives particle volumes smaller than the lattice cells, and a
    /// still tank then settles to a bottom pressure about rho g D (1 + rho0 g D / (rho0 c0^2)) too high).
    pub fn fill(
        &self,
        pt: &mut Particles,
        dp: f64,
        layers: usize,
        mirror: bool,
        eos: &Eos,
        g: f64,
    ) {
        self.fill_where(pt, dp, layers, mirror, eos, g, &|_, _| true);
    }

    /// [`Tank::fill`] with only the fluid particles at (y, z) for which `keep` is true (a body immersed
    /// at the start takes the place of the others).
    #[allow(clippy::too_many_arguments)]
    pub fn fill_where(
        &self,
        pt: &mut Particles,
        dp: f64,
        layers: usize,
        mirror: bool,
        eos: &Eos,
        g: f64,
        keep: &dyn Fn(f64, f64) -> bool,
    ) {
        let ny = (self.half_width / dp).round() as i64;
        let nz = (self.depth / dp).round() as i64;
        let y_start = if mirror { 0 } else { -ny };
        for k in 0..nz {
            let z = -(k as f64 + 0.5) * dp;
            for i in y_start..ny {
                let y = (i as f64 + 0.5) * dp;
                if keep(y, z) {
                    push_water_at_rest(pt, eos, g, y, z, dp, 0);
                }
            }
        }
        self.fill_walls(pt, dp, layers, mirror, eos, g, 0);
    }

    /// The wall dummies of a tank filled on a lattice of spacing `spacing` (whole cells across the
    /// half-width and the depth): `layers` layers under the bottom and beside the side walls up to
    /// `wall_height` above the surface, at resolution `level` ([`Particles::level`]).
    #[allow(clippy::too_many_arguments)]
    pub fn fill_walls(
        &self,
        pt: &mut Particles,
        spacing: f64,
        layers: usize,
        mirror: bool,
        eos: &Eos,
        g: f64,
        level: u8,
    ) {
        let ny = (self.half_width / spacing).round() as i64;
        let nz = (self.depth / spacing).round() as i64;
        let hydro = |z: f64| eos.rho0 * g * (-z);
        let mut wall = |y: f64, z: f64, p: f64| {
            pt.push(
                Kind::Wall,
                y,
                z,
                0.0,
                0.0,
                eos.density(p),
                p,
                spacing * spacing,
            );
            pt.set_last_level(level);
        };
        let l = layers as i64;
        let zb = -(nz as f64) * spacing;
        let y_lo = if mirror { 0 } else { -ny - l };
        // Bottom (under the water and the side walls).
        for k in 0..l {
            let z = zb - (k as f64 + 0.5) * spacing;
            for i in y_lo..ny + l {
                wall((i as f64 + 0.5) * spacing, z, hydro(z));
            }
        }
        // Side walls from the bottom up to wall_height.
        let n_up = nz + (self.wall_height / spacing).ceil() as i64;
        for k in 0..n_up {
            let z = zb + (k as f64 + 0.5) * spacing;
            let p = hydro(z).max(0.0);
            for m in 0..l {
                let y = (ny + m) as f64 * spacing + 0.5 * spacing;
                wall(y, z, p);
                if !mirror {
                    wall(-y, z, p);
                }
            }
        }
    }
}

/// Push a fluid particle at rest at (y, z) under hydrostatic pressure p = rho0 g (-z), on a lattice
/// cell of side `spacing` (its volume) at resolution `level` ([`Particles::level`]).
pub fn push_water_at_rest(
    pt: &mut Particles,
    eos: &Eos,
    g: f64,
    y: f64,
    z: f64,
    spacing: f64,
    level: u8,
) {
    let p = eos.rho0 * g * (-z);
    pt.push(
        Kind::Fluid,
        y,
        z,
        0.0,
        0.0,
        eos.density(p),
        p,
        spacing * spacing,
    );
    if level > 0 {
        pt.set_last_level(level);
    }
}
