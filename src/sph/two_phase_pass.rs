//! The momentum and continuity passes of a run with air ([`crate::sph::air`]): the pair terms of the
//! single-phase Riemann scheme between particles of one phase (water-water with the water's c0, air-air
//! with the air's sound speed), the two-phase Riemann terms between water and air, and against the wall
//! and body dummies the water's extrapolated wall pressure for a water particle and the particle's own
//! pressure for an air particle (all stated in [`crate::sph::air`]).
//!
//! The passes are separate from the single-phase ones ([`crate::sph::rates`]), which carry no test of the
//! phase. Their pair loops run over batches of neighbours (`AirBatch`): the offsets, distances, normal
//! velocity differences and kernel factors lane by lane (vectorised, and compiled for AVX2 where the CPU
//! has it), then the phase-dependent Riemann terms one by one; each quantity takes the operations of one
//! pair at a time, so the histories are bit-identical to the plain loop this replaced (checked on Ochi
//! 0.174 Lpp with air; 6-13 % faster there). As in the single-phase passes every sum is a gather over
//! the neighbours of one particle in the fixed cell-sorted order, so the results are bit-identical on
//! any thread count; the momentum pass builds the neighbour lists (flagging water and air alike as fluid)
//! that the continuity pass, the body force and the force-panel sensors read.

use rayon::prelude::*;

use crate::sph::air::{self, AirPhase, State};
use crate::sph::case::Setup;
use crate::sph::kernel::WendlandC2;
use crate::sph::neighbour_lists::{
    ChunkLists, LIST_CHUNK, NeighbourLists, PairKernel, mark_fluid, neighbour,
};
use crate::sph::neighbours::Grid;
use crate::sph::pair_batch::{avx2_twin, has_avx2};
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
}

/// Neighbours per batch of the two-phase passes.
const AIR_BATCH: usize = 8;

/// A batch of neighbours j of particle i: gathered one by one (mirror images with y and v_y negated),
/// then the offsets' lengths, the normal velocity differences and the kernel factors lane by lane, a
/// loop without gathers or branches that the compiler vectorises; the pair terms that depend on the
/// phases follow one by one. Every quantity takes the operations of a pair at a time, so the sums are
/// bit-identical to a plain loop (as in [`crate::sph::pair_batch`]).
#[derive(Clone, Copy, Default)]
struct AirBatch {
    dy: [f64; AIR_BATCH],
    dz: [f64; AIR_BATCH],
    dvy: [f64; AIR_BATCH],
    dvz: [f64; AIR_BATCH],
    r: [f64; AIR_BATCH],
    vdotr: [f64; AIR_BATCH],
    fw: [f64; AIR_BATCH],
    p: [f64; AIR_BATCH],
    rho: [f64; AIR_BATCH],
    vol: [f64; AIR_BATCH],
    coarse: [bool; AIR_BATCH],
    kind: [Kind; AIR_BATCH],
}

impl AirBatch {
    /// Gather the neighbours of list entries `tags` (at most [`AIR_BATCH`]) of particle `i`.
    #[inline(always)]
    fn gather(&mut self, tags: &[u32], pt: &Particles, i: usize) {
        let n = pt.y.len();
        let (y, z, vy, vz) = (&pt.y[..n], &pt.z[..n], &pt.vy[..n], &pt.vz[..n]);
        let (rho, p, vol, kind, level) = (
            &pt.rho[..n],
            &pt.p[..n],
            &pt.vol[..n],
            &pt.kind[..n],
            &pt.level[..n],
        );
        let (yi, zi, vyi, vzi) = (y[i], z[i], vy[i], vz[i]);
        for (l, &t) in tags.iter().enumerate().take(AIR_BATCH) {
            let (j, mirrored) = neighbour(t);
            assert!(j < n);
            let (dy, vyj) = if mirrored {
                (yi + y[j], -vy[j])
            } else {
                (yi - y[j], vy[j])
            };
            self.dy[l] = dy;
            self.dz[l] = zi - z[j];
            self.dvy[l] = vyi - vyj;
            self.dvz[l] = vzi - vz[j];
            self.p[l] = p[j];
            self.rho[l] = rho[j];
            self.vol[l] = vol[j];
            self.kind[l] = kind[j];
            self.coarse[l] = level[j] != 0;
        }
    }

    /// |r_ij|, (v_i - v_j) . r_ij and F_ij V_j of every lane, with the kernels `k0` of the pairs with a
    /// neighbour at the base resolution and `k1` with a coarse one.
    #[inline(always)]
    fn geometry(&mut self, [k0, k1]: &[WendlandC2; 2]) {
        for l in 0..AIR_BATCH {
            let (dy, dz) = (self.dy[l], self.dz[l]);
            let r = (dy * dy + dz * dz).sqrt();
            self.r[l] = r;
            self.vdotr[l] = self.dvy[l] * dy + self.dvz[l] * dz;
            let f = if self.coarse[l] {
                k1.grad_factor_lane(r)
            } else {
                k0.grad_factor_lane(r)
            };
            self.fw[l] = f * self.vol[l];
        }
    }

    /// Lane `l` as a [`Pair`].
    #[inline(always)]
    fn pair(&self, l: usize) -> Pair {
        Pair {
            dy: self.dy[l],
            dz: self.dz[l],
            r: self.r[l],
            vdotr: self.vdotr[l],
            kind: self.kind[l],
            p: self.p[l],
            rho: self.rho[l],
        }
    }
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
    let avx2 = has_avx2();
    let mut out = std::mem::take(&mut pt.rate);
    let n = {
        let pt: &Particles = pt;
        let ctx = MomentumChunk {
            grid,
            pt,
            kernel,
            pairs: &pairs,
            pair_kernel: &pair_kernel,
            ph: &ph,
            rows,
            multi,
        };
        out.par_chunks_mut(LIST_CHUNK)
            .zip(lists.chunks.par_iter_mut())
            .enumerate()
            .map(|(c, (out, list))| {
                #[cfg(target_arch = "x86_64")]
                if avx2 {
                    // SAFETY: the CPU has AVX2 (checked at run time above).
                    return unsafe { momentum_chunk_avx2(&ctx, c, out, list) };
                }
                momentum_chunk(&ctx, c, out, list)
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

/// What a chunk of the two-phase momentum pass reads.
struct MomentumChunk<'a> {
    grid: &'a Grid,
    pt: &'a Particles,
    kernel: &'a WendlandC2,
    pairs: &'a PairKernels,
    pair_kernel: &'a PairKernel,
    ph: &'a Phases,
    rows: Rows,
    multi: bool,
}

avx2_twin!(momentum_chunk_avx2 = momentum_chunk(
    ctx: &MomentumChunk,
    c: usize,
    out: &mut [[f64; 3]],
    list: &mut ChunkLists,
) -> u64);

/// The two-phase momentum pass over chunk `c` of the particles: search, list, pair sums.
#[inline(always)]
fn momentum_chunk(
    ctx: &MomentumChunk,
    c: usize,
    out: &mut [[f64; 3]],
    list: &mut ChunkLists,
) -> u64 {
    let MomentumChunk {
        grid,
        pt,
        kernel,
        pairs,
        pair_kernel,
        ph,
        rows,
        multi,
    } = *ctx;
    list.clear();
    let mut count = 0u64;
    let mut b = AirBatch::default();
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
        search(list, grid, pt, i, kernel, pairs, multi);
        let (rho_i, p_i) = (pt.rho[i], pt.p[i]);
        let li = pt.level[i];
        let kernels = pair_kernel.of_level(li);
        let (mut ay, mut az) = (0.0, 0.0);
        let entries = list.last_entries();
        count += entries.len() as u64;
        for tags in entries.chunks_mut(AIR_BATCH) {
            b.gather(tags, pt, i);
            // The lists flag water and air alike as fluid (for the body force and the sensors).
            for (t, kind) in tags.iter_mut().zip(b.kind) {
                mark_fluid(t, kind.is_fluid());
            }
            b.geometry(&kernels);
            for l in 0..tags.len() {
                let q = b.pair(l);
                let pf = pressure_sum(ph, ki, p_i, rho_i, &q) * b.fw[l];
                ay -= pf * q.dy;
                az -= pf * q.dz;
            }
        }
        list.end_particle();
        *out = [ay / rho_i, az / rho_i - ph.g, 0.0];
    }
    count
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
    let avx2 = has_avx2();
    let mut out = std::mem::take(&mut pt.rate);
    {
        let pt: &Particles = pt;
        let ctx = ContinuityChunk {
            pt,
            pair_kernel: &pair_kernel,
            ph: &ph,
            rows,
        };
        out.par_chunks_mut(LIST_CHUNK)
            .zip(lists.chunks.par_iter())
            .enumerate()
            .for_each(|(c, (out, list))| {
                #[cfg(target_arch = "x86_64")]
                if avx2 {
                    // SAFETY: the CPU has AVX2 (checked at run time above).
                    return unsafe { continuity_chunk_avx2(&ctx, c, out, list) };
                }
                continuity_chunk(&ctx, c, out, list)
            });
    }
    pt.rate = out;
}

/// What a chunk of the two-phase continuity pass reads.
struct ContinuityChunk<'a> {
    pt: &'a Particles,
    pair_kernel: &'a PairKernel,
    ph: &'a Phases,
    rows: Rows,
}

avx2_twin!(continuity_chunk_avx2 = continuity_chunk(
    ctx: &ContinuityChunk,
    c: usize,
    out: &mut [[f64; 3]],
    list: &ChunkLists,
));

/// The two-phase continuity pass over chunk `c` of the particles.
#[inline(always)]
fn continuity_chunk(ctx: &ContinuityChunk, c: usize, out: &mut [[f64; 3]], list: &ChunkLists) {
    let ContinuityChunk {
        pt,
        pair_kernel,
        ph,
        rows,
    } = *ctx;
    let mut b = AirBatch::default();
    for (k, out) in out.iter_mut().enumerate() {
        let i = c * LIST_CHUNK + k;
        let ki = pt.kind[i];
        if rows.skips(ki) {
            if !ki.is_fluid() {
                out[2] = 0.0;
            }
            continue;
        }
        let (rho_i, p_i) = (pt.rho[i], pt.p[i]);
        let (ci, rho0_i) = ph.of(ki);
        let li = pt.level[i];
        let kernels = pair_kernel.of_level(li);
        let mut sum = 0.0;
        for tags in list.tags(k).chunks(AIR_BATCH) {
            b.gather(tags, pt, i);
            b.geometry(&kernels);
            for l in 0..tags.len() {
                let q = b.pair(l);
                let fw = b.fw[l];
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
                    // The water's density does not take the air's flux: for it the air is a free
                    // surface (see `crate::sph::air`, measured on a 30 deg wedge).
                    _ if ki == Kind::Fluid => 0.0,
                    _ => {
                        let (i, j) = ph.sides(p_i, rho_i, ci, &q);
                        air::interface_continuity_term(i, j, q.vdotr, q.r, fw, dp_hydro)
                    }
                };
            }
        }
        out[2] = rho_i * sum;
    }
}
