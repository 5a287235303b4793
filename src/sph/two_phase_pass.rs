//! The momentum and continuity passes of a run with air ([`crate::sph::air`]): the pair terms of the
//! single-phase Riemann scheme between particles of one phase (water-water with the water's c0, air-air
//! with the air's sound speed), the two-phase Riemann terms between water and air, and against the wall
//! and body dummies the water's extrapolated wall pressure for a water particle and the particle's own
//! pressure for an air particle (all stated in [`crate::sph::air`]).
//!
//! One plain pair loop a particle, without the batching of the single-phase passes
//! ([`crate::sph::rates`]): a run with air is rare enough that its passes are kept simple, and the
//! single-phase passes carry no test of the phase. As there, every sum is a gather over the neighbours of
//! one particle in the fixed cell-sorted order, so the results are bit-identical on any thread count; the
//! momentum pass builds the neighbour lists (flagging water and air alike as fluid) that the continuity
//! pass, the body force and the force-panel sensors read.

use rayon::prelude::*;

use crate::sph::air::{self, AirPhase, State};
use crate::sph::case::Setup;
use crate::sph::kernel::WendlandC2;
use crate::sph::neighbour_lists::{
    ChunkLists, LIST_CHUNK, NeighbourLists, PairKernel, mark_fluid, neighbour,
};
use crate::sph::neighbours::Grid;
use crate::sph::particles::{Kind, Particles};
use crate::sph::refinement::PairKernels;
use crate::sph::riemann;

/// What a pair needs of the two phases.
#[derive(Clone, Copy)]
struct Phases {
    /// The water's sound speed and rest density.
    c0: f64,
    rho0: f64,
    air: AirPhase,
    g: f64,
}

impl Phases {
    fn new(s: &Setup, air: &AirPhase) -> Self {
        Self {
            c0: s.c0,
            rho0: s.rho0,
            air: *air,
            g: s.g,
        }
    }

    /// Sound speed and rest density of a fluid particle's phase.
    #[inline(always)]
    fn of(&self, kind: Kind) -> (f64, f64) {
        if kind == Kind::Air {
            (self.air.c, self.air.rho0)
        } else {
            (self.c0, self.rho0)
        }
    }

    /// The two sides of the Riemann problem of particle i (pressure `p_i`, density `rho_i`, sound speed
    /// `c_i`) and its neighbour `q` of another phase.
    #[inline(always)]
    fn sides(&self, p_i: f64, rho_i: f64, c_i: f64, q: &Pair) -> (State, State) {
        (
            State {
                p: p_i,
                rho: rho_i,
                c: c_i,
            },
            State {
                p: q.p,
                rho: q.rho,
                c: self.of(q.kind).0,
            },
        )
    }
}

/// One neighbour of particle i: the offset r_i - r_j, the velocity difference and the state of j.
struct Pair {
    dy: f64,
    dz: f64,
    r: f64,
    vdotr: f64,
    kind: Kind,
    p: f64,
    rho: f64,
    vol: f64,
}

/// The neighbour of list entry `tag` as seen from particle i at (yi, zi) moving at (vyi, vzi).
#[inline(always)]
fn pair_of(tag: u32, pt: &Particles, yi: f64, zi: f64, vyi: f64, vzi: f64) -> (usize, Pair) {
    let (j, mirrored) = neighbour(tag);
    let (dy, vyj) = if mirrored {
        (yi + pt.y[j], -pt.vy[j])
    } else {
        (yi - pt.y[j], pt.vy[j])
    };
    let dz = zi - pt.z[j];
    let r = (dy * dy + dz * dz).sqrt();
    let vdotr = (vyi - vyj) * dy + (vzi - pt.vz[j]) * dz;
    (
        j,
        Pair {
            dy,
            dz,
            r,
            vdotr,
            kind: pt.kind[j],
            p: pt.p[j],
            rho: pt.rho[j],
            vol: pt.vol[j],
        },
    )
}

/// 2 P* of the pair (i, j) for the momentum sum.
#[inline(always)]
fn pressure_sum(ph: &Phases, ki: Kind, p_i: f64, rho_i: f64, q: &Pair) -> f64 {
    let (ci, _) = ph.of(ki);
    match q.kind {
        Kind::Wall | Kind::Body => {
            if ki == Kind::Air {
                air::wall_pressure_sum(p_i, rho_i, q.vdotr, q.r, ci)
            } else {
                riemann::pressure_sum(p_i, q.p, rho_i, q.rho, q.vdotr, q.r, ci, false)
            }
        }
        kj if kj == ki => riemann::pressure_sum(p_i, q.p, rho_i, q.rho, q.vdotr, q.r, ci, true),
        _ => {
            let (i, j) = ph.sides(p_i, rho_i, ci, q);
            air::interface_pressure_sum(i, j, q.vdotr, q.r)
        }
    }
}

/// Which particles a pass computes: every fluid particle, or the air alone (the air's substeps,
/// [`crate::sph::solver`]), whose rows of the other particles are left as they were and whose lists
/// are empty for them.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Rows {
    AllFluid,
    AirOnly,
}

impl Rows {
    #[inline(always)]
    fn skips(self, k: Kind) -> bool {
        match self {
            Rows::AllFluid => !k.is_fluid(),
            Rows::AirOnly => k != Kind::Air,
        }
    }
}

/// Accelerations of the water and air particles into `rate[i][0..2]` (the density gradients are not
/// used with air and are zeroed), with one neighbour search a particle whose pairs are kept in `lists`;
/// returns the number of pair interactions. With [`Rows::AirOnly`] only the air's rows are computed
/// and searched, the other rows of `rate` are left as they were.
pub fn momentum_rates(
    grid: &Grid,
    lists: &mut NeighbourLists,
    pt: &mut Particles,
    kernel: &WendlandC2,
    s: &Setup,
    air: &AirPhase,
    rows: Rows,
) -> u64 {
    let multi = pt.multi_resolution();
    let pair_kernel = PairKernel::new(kernel, multi);
    lists.kernel = Some(pair_kernel);
    lists.resize(pt.len());
    let ph = Phases::new(s, air);
    let pairs = PairKernels::new(kernel.h());
    let mut out = std::mem::take(&mut pt.rate);
    let n = {
        let pt: &Particles = pt;
        out.par_chunks_mut(LIST_CHUNK)
            .zip(lists.chunks.par_iter_mut())
            .enumerate()
            .map(|(c, (out, list))| {
                list.clear();
                let mut count = 0u64;
                for (k, out) in out.iter_mut().enumerate() {
                    let i = c * LIST_CHUNK + k;
                    let ki = pt.kind[i];
                    if rows.skips(ki) {
                        if !ki.is_fluid() {
                            *out = [0.0; 3];
                        }
                        list.end_particle();
                        continue;
                    }
                    search(list, grid, pt, i, kernel, &pairs, multi);
                    let (yi, zi, vyi, vzi) = (pt.y[i], pt.z[i], pt.vy[i], pt.vz[i]);
                    let (rho_i, p_i, li) = (pt.rho[i], pt.p[i], pt.level[i]);
                    let (mut ay, mut az) = (0.0, 0.0);
                    let entries = list.last_entries();
                    count += entries.len() as u64;
                    for t in entries.iter_mut() {
                        let (j, q) = pair_of(*t, pt, yi, zi, vyi, vzi);
                        mark_fluid(t, q.kind.is_fluid());
                        let fw = pair_kernel.grad_factor(li, pt.level[j], q.r) * q.vol;
                        let pf = pressure_sum(&ph, ki, p_i, rho_i, &q) * fw;
                        ay -= pf * q.dy;
                        az -= pf * q.dz;
                    }
                    list.end_particle();
                    *out = [ay / rho_i, az / rho_i - ph.g, 0.0];
                }
                count
            })
            .sum()
    };
    pt.rate = out;
    if rows == Rows::AllFluid {
        for g in pt.grad_rho.iter_mut() {
            *g = [0.0; 2];
        }
    }
    n
}

/// The neighbour search of particle i into `list` (as the single-phase momentum pass searches).
#[inline(always)]
fn search(
    list: &mut ChunkLists,
    grid: &Grid,
    pt: &Particles,
    i: usize,
    kernel: &WendlandC2,
    pairs: &PairKernels,
    multi: bool,
) {
    let (yi, zi) = (pt.y[i], pt.z[i]);
    if multi {
        let li = pt.level[i];
        let reach = grid.reach(li, yi, zi);
        list.push_candidates_within(
            grid,
            &pt.y,
            &pt.z,
            &pt.level,
            yi,
            zi,
            i,
            pairs.supports2(li),
            reach,
        );
    } else {
        list.push_candidates(grid, &pt.y, &pt.z, yi, zi, i, kernel.support2());
    }
}

/// Density rates of the water and air particles into `rate[i][2]`, over the neighbour lists of the last
/// momentum pass (at the same positions, densities and pressures; only the velocities have been kicked
/// since). With [`Rows::AirOnly`] only the air's rows.
pub fn continuity_rates(
    lists: &NeighbourLists,
    pt: &mut Particles,
    s: &Setup,
    air: &AirPhase,
    rows: Rows,
) {
    let ph = Phases::new(s, air);
    let pair_kernel = lists
        .kernel
        .expect("continuity pass before the momentum pass built the lists");
    let mut out = std::mem::take(&mut pt.rate);
    {
        let pt: &Particles = pt;
        out.par_chunks_mut(LIST_CHUNK)
            .zip(lists.chunks.par_iter())
            .enumerate()
            .for_each(|(c, (out, list))| {
                for (k, out) in out.iter_mut().enumerate() {
                    let i = c * LIST_CHUNK + k;
                    let ki = pt.kind[i];
                    if rows.skips(ki) {
                        if !ki.is_fluid() {
                            out[2] = 0.0;
                        }
                        continue;
                    }
                    let (yi, zi, vyi, vzi) = (pt.y[i], pt.z[i], pt.vy[i], pt.vz[i]);
                    let (rho_i, p_i, li) = (pt.rho[i], pt.p[i], pt.level[i]);
                    let (ci, rho0_i) = ph.of(ki);
                    let mut sum = 0.0;
                    for &t in list.tags(k) {
                        let (j, q) = pair_of(t, pt, yi, zi, vyi, vzi);
                        let fw = pair_kernel.grad_factor(li, pt.level[j], q.r) * q.vol;
                        let dp_hydro = -rho0_i * ph.g * q.dz;
                        sum += match q.kind {
                            // A flux to a dummy would carry mass through the wall.
                            Kind::Wall | Kind::Body => fw * q.vdotr,
                            kj if kj == ki => {
                                fw * q.vdotr
                                    + riemann::continuity_term(
                                        p_i, q.p, rho_i, q.rho, fw, q.r, ci, dp_hydro,
                                    )
                            }
                            // The water's density does not take the air's flux: for it the air is a
                            // free surface (see `crate::sph::air`, measured on a 30 deg wedge).
                            _ if ki == Kind::Fluid => 0.0,
                            _ => {
                                let (i, j) = ph.sides(p_i, rho_i, ci, &q);
                                air::interface_continuity_term(i, j, q.vdotr, q.r, fw, dp_hydro)
                            }
                        };
                    }
                    out[2] = rho_i * sum;
                }
            });
    }
    pt.rate = out;
}
