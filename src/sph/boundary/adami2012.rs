//! Dummy-particle walls with extrapolated pressure (Adami, Hu & Adams 2012, J. Comput. Phys. 231,
//! 7057-7075, eq. 27):
//!
//! p_w = [ sum_f p_f W_wf + (g - a_w) . sum_f rho_f r_wf W_wf ] / sum_f W_wf,   r_wf = r_w - r_f
//!
//! summed over the fluid particles f near the wall particle w, with g the gravity vector and a_w the
//! acceleration of the wall. The dummy density follows from the equation of state, rho_w = rho(p_w). The
//! same formula gives the wall pressure at any point of the body contour (sensors, section force).
//!
//! In a run with air ([`crate::sph::air`]) the dummies' pressure is extrapolated from the water alone
//! (an air particle meets a dummy with its own pressure). The pressure sampled at a point of the contour
//! (the interpolated sensors, the contour pressure) is the water's where the water wets the point
//! (Shepard sum of the water at least [`crate::sph::solver::DRY_SHEPARD`]) and the air's, from the air
//! particles alone, where only air does (the cushion under a flat bottom). A Shepard average over both
//! phases would mix the water's pressure with the air's near the contact line, where the water's is
//! what loads the wall (on a 30 deg wedge at 6.25 mm spacing the mixed average moved one of four
//! sensors by 2.5 %; the larger difference first seen there came from the continuity equation,
//! [`crate::sph::air`]).

use rayon::prelude::*;

use crate::sph::air::AirPhase;
use crate::sph::eos::Eos;
use crate::sph::kernel::WendlandC2;
use crate::sph::neighbours::{Grid, for_each_neighbour, for_each_neighbour_within};
use crate::sph::particles::{Kind, Particles};
use crate::sph::refinement::PairKernels;

/// The sums of eq. 27 over the fluid neighbours of a wall point: sum W, sum p W, sum rho r W (two
/// components), and the Shepard sum sum V W.
#[derive(Default)]
struct WallSums {
    w: f64,
    pw: f64,
    rho_y: f64,
    rho_z: f64,
    shepard: f64,
}

impl WallSums {
    /// Add fluid particle `j` at offset (dy, dz) from the wall point, with kernel value `w` and pressure
    /// `p` (from its density and its phase's equation of state).
    #[inline(always)]
    fn add(&mut self, pt: &Particles, p: f64, j: usize, dy: f64, dz: f64, w: f64) {
        let rho = pt.rho[j];
        self.w += w;
        self.pw += p * w;
        self.rho_y += rho * dy * w;
        self.rho_z += rho * dz * w;
        self.shepard += pt.mass[j] / rho * w;
    }

    /// The wall pressure of eq. 27 for gravity `g` and wall acceleration `accel`, and the Shepard sum;
    /// (0, 0) with no fluid near.
    #[inline(always)]
    fn pressure(&self, g: f64, accel: [f64; 2]) -> (f64, f64) {
        if self.w <= 0.0 {
            return (0.0, 0.0);
        }
        let (gy, gz) = (-accel[0], -g - accel[1]);
        (
            (self.pw + gy * self.rho_y + gz * self.rho_z) / self.w,
            self.shepard,
        )
    }
}

/// The sums of eq. 27 of a wall point over the water and over the air.
#[derive(Default)]
struct PhaseSums {
    water: WallSums,
    air: WallSums,
}

impl PhaseSums {
    /// Add particle j (water always, air when `air` is given) at offset (dy, dz), kernel value `w`.
    #[inline(always)]
    #[allow(clippy::too_many_arguments)]
    fn add(
        &mut self,
        pt: &Particles,
        eos: &Eos,
        air: Option<&AirPhase>,
        j: usize,
        dy: f64,
        dz: f64,
        w: f64,
    ) {
        match (pt.kind[j], air) {
            (Kind::Fluid, _) => self.water.add(pt, eos.pressure(pt.rho[j]), j, dy, dz, w),
            (Kind::Air, Some(a)) => self.air.add(pt, a.pressure(pt.rho[j]), j, dy, dz, w),
            _ => {}
        }
    }

    /// The water's wall pressure and Shepard sum where the water wets the point, else the air's.
    #[inline(always)]
    fn pressure(&self, g: f64, accel: [f64; 2]) -> (f64, f64) {
        if self.water.shepard >= crate::sph::solver::DRY_SHEPARD || self.air.w <= 0.0 {
            self.water.pressure(g, accel)
        } else {
            self.air.pressure(g, accel)
        }
    }
}

/// Wall pressure at point (y, z) of a wall moving with acceleration (ay, az), and the Shepard sum
/// sum_f V_f W_wf of the fluid around it (0 when no fluid is near; about 1/2 for a fully wetted flat wall).
/// `g` is the (downward-positive) gravitational acceleration. With `air`, air particles count too.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn wall_pressure(
    grid: &Grid,
    pt: &Particles,
    kernel: &WendlandC2,
    eos: &Eos,
    air: Option<&AirPhase>,
    g: f64,
    y: f64,
    z: f64,
    accel: [f64; 2],
) -> (f64, f64) {
    let mut sums = PhaseSums::default();
    for_each_neighbour(
        grid,
        &pt.y,
        &pt.z,
        y,
        z,
        usize::MAX,
        kernel.support2(),
        |j, dy, dz, r2, _| {
            if pt.kind[j].is_fluid() {
                let w = kernel.w(r2.sqrt());
                sums.add(pt, eos, air, j, dy, dz, w);
            }
        },
    );
    sums.pressure(g, accel)
}

/// [`wall_pressure`] in a refined tank ([`crate::sph::refinement`]): at a point of resolution `level`,
/// each fluid neighbour weighted with the kernel of the pair's mean smoothing length.
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn wall_pressure_at_level(
    grid: &Grid,
    pt: &Particles,
    kernels: &PairKernels,
    level: u8,
    eos: &Eos,
    air: Option<&AirPhase>,
    g: f64,
    y: f64,
    z: f64,
    accel: [f64; 2],
) -> (f64, f64) {
    let mut sums = PhaseSums::default();
    let reach = grid.reach(level, y, z);
    let support2 = if reach == 2 {
        kernels.pair(0, 0).support2()
    } else {
        kernels.widest_support2(level)
    };
    for_each_neighbour_within(
        grid,
        &pt.y,
        &pt.z,
        y,
        z,
        usize::MAX,
        support2,
        reach,
        |j, dy, dz, r2, _| {
            if pt.kind[j].is_fluid() {
                let w = kernels.pair(level, pt.level[j]).w(r2.sqrt());
                sums.add(pt, eos, air, j, dy, dz, w);
            }
        },
    );
    sums.pressure(g, accel)
}

/// Set the pressure of every particle: equation of state for water (`eos`) and air (`air`), extrapolation
/// from the water for dummies (wall
/// acceleration zero for tank walls, `body_accel` for body particles). Then set the dummy densities from
/// their pressures, and the volumes used in the sums: m / rho for fluid, the fixed lattice volume
/// `dummy_vol` (dp^2) for dummies, whose layout does not compress. Reads the fluid densities only, so the result does not depend on the visiting order.
#[allow(clippy::too_many_arguments)]
pub fn update_pressures(
    grid: &Grid,
    pt: &mut Particles,
    kernel: &WendlandC2,
    eos: &Eos,
    air: Option<&AirPhase>,
    dummy_vol: f64,
    g: f64,
    body_accel: [f64; 2],
) {
    let mut p = std::mem::take(&mut pt.p);
    let multi = pt.multi_resolution();
    let kernels = PairKernels::new(kernel.h());
    {
        let ptr: &Particles = pt;
        p.par_iter_mut()
            .with_min_len(1024)
            .enumerate()
            .for_each(|(i, pi)| {
                if multi && !ptr.kind[i].is_fluid() {
                    let accel = if ptr.kind[i] == Kind::Body {
                        body_accel
                    } else {
                        [0.0; 2]
                    };
                    let (y, z) = (ptr.y[i], ptr.z[i]);
                    *pi = wall_pressure_at_level(
                        grid,
                        ptr,
                        &kernels,
                        ptr.level[i],
                        eos,
                        None,
                        g,
                        y,
                        z,
                        accel,
                    )
                    .0;
                    return;
                }
                *pi = match ptr.kind[i] {
                    Kind::Fluid => eos.pressure(ptr.rho[i]),
                    Kind::Air => air.map_or(0.0, |a| a.pressure(ptr.rho[i])),
                    Kind::Wall => {
                        let (y, z) = (ptr.y[i], ptr.z[i]);
                        wall_pressure(grid, ptr, kernel, eos, None, g, y, z, [0.0; 2]).0
                    }
                    Kind::Body => {
                        let (y, z) = (ptr.y[i], ptr.z[i]);
                        wall_pressure(grid, ptr, kernel, eos, None, g, y, z, body_accel).0
                    }
                };
            });
    }
    pt.p = p;
    (
        pt.rho.par_iter_mut(),
        pt.vol.par_iter_mut(),
        pt.kind.par_iter(),
        pt.p.par_iter(),
        pt.mass.par_iter(),
        pt.level.par_iter(),
    )
        .into_par_iter()
        .with_min_len(4096)
        .for_each(|(rho, vol, kind, p, m, level)| {
            if kind.is_fluid() {
                *vol = m / *rho;
            } else {
                *rho = eos.density(*p);
                // A coarse dummy stands for a 2 dp x 2 dp cell.
                *vol = if *level > 0 {
                    4.0 * dummy_vol
                } else {
                    dummy_vol
                };
            }
        });
}
