//! Neighbour lists: the pairs found by the momentum pass's search ([`crate::sph::neighbours`]), kept as
//! one 32-bit word per pair (neighbour index with a mirror-image and a fluid flag) for the passes that
//! follow at the same positions (continuity, shifting, body force).
//!
//! Distances and kernel factors are not stored: each pass recomputes |r_ij| = sqrt(dy^2 + dz^2) and
//! F(|r_ij|) from the positions with exactly the operations of the momentum pass, so the values are
//! bit-identical to stored ones, and a pair costs 4 bytes instead of 20. (Streaming the stored 20 bytes
//! a pair from memory cost more than the square root and the five multiplications that replace them.)

use crate::sph::kernel::WendlandC2;
use crate::sph::neighbours::Grid;
use crate::sph::particles::{Kind, Particles};
use crate::sph::refinement::PairKernels;

/// Particles per chunk of the neighbour lists (fixed, so the layout does not depend on the thread count).
pub const LIST_CHUNK: usize = 512;

/// Bit of a list entry set when the neighbour is a mirror image (y -> -y).
const MIRRORED: u32 = 1 << 31;
/// Bit of a list entry set when the neighbour is a fluid particle.
const FLUID: u32 = 1 << 30;
/// Mask of the particle index in a list entry.
const INDEX: u32 = FLUID - 1;

/// The neighbour index of a list entry and whether it is a mirror image.
#[inline(always)]
pub fn neighbour(tag: u32) -> (usize, bool) {
    ((tag & INDEX) as usize, tag & MIRRORED != 0)
}

/// Whether a list entry's neighbour is a fluid particle (set by [`mark_fluid`]).
#[inline(always)]
pub fn is_fluid(tag: u32) -> bool {
    tag & FLUID != 0
}

/// Flag a list entry's neighbour as fluid.
#[inline(always)]
pub fn mark_fluid(tag: &mut u32, fluid: bool) {
    if fluid {
        *tag |= FLUID;
    }
}

/// One neighbour of a list with its pair geometry at the current positions: index j, whether it is a
/// mirror image and whether it is fluid, the distance |r_ij| and the kernel gradient factor F(|r_ij|)
/// (grad_i W_ij = F r_ij).
#[derive(Debug, Clone, Copy)]
pub struct ListEntry {
    pub j: usize,
    pub mirrored: bool,
    pub fluid: bool,
    pub r: f64,
    pub f: f64,
}

impl ListEntry {
    /// r_i - r_j for particle i at (yi, zi), with r_j the mirror image when the entry is one.
    #[inline(always)]
    pub fn offset(&self, yi: f64, zi: f64, y: &[f64], z: &[f64]) -> (f64, f64) {
        let dy = if self.mirrored {
            yi + y[self.j]
        } else {
            yi - y[self.j]
        };
        (dy, zi - z[self.j])
    }
}

/// Neighbours of the particles of one chunk, in search order.
#[derive(Debug, Clone, Default)]
pub struct ChunkLists {
    /// Entries of particle k of the chunk are `start[k]..start[k + 1]`.
    start: Vec<u32>,
    /// Neighbour index with the `MIRRORED` and `FLUID` bits.
    tag: Vec<u32>,
}

impl ChunkLists {
    /// Start a new build of the lists.
    pub fn clear(&mut self) {
        self.start.clear();
        self.tag.clear();
        self.start.push(0);
    }

    /// Append the neighbours of point (yi, zi) within `support2` (squared support radius), mirror images
    /// included, in the order of [`crate::sph::neighbours::for_each_neighbour`], leaving out particle
    /// `skip` (not its image), with their index and mirror flag; the caller flags the fluid ones
    /// ([`ChunkLists::last_entries`], [`mark_fluid`]).
    ///
    /// The list grows once by the number of candidates, which are then filtered without branches
    /// straight into it (each is written and kept by advancing the count).
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub fn push_candidates(
        &mut self,
        grid: &Grid,
        y: &[f64],
        z: &[f64],
        yi: f64,
        zi: f64,
        skip: usize,
        support2: f64,
    ) {
        let (rows, mirrored) = (grid.ranges(yi, zi), grid.mirror_ranges(yi, zi));
        let total: usize = rows.iter().chain(mirrored.iter()).map(|r| r.len()).sum();
        let mut n = self.tag.len();
        self.tag.resize(n + total, 0);
        let out = &mut self.tag[..];
        for r in rows {
            let (ys, zs) = (&y[r.clone()], &z[r.clone()]);
            for (k, (&yj, &zj)) in ys.iter().zip(zs).enumerate() {
                let j = r.start + k;
                let dy = yi - yj;
                let dz = zi - zj;
                out[n] = j as u32;
                n += ((dy * dy + dz * dz < support2) & (j != skip)) as usize;
            }
        }
        for r in mirrored {
            let (ys, zs) = (&y[r.clone()], &z[r.clone()]);
            for (k, (&yj, &zj)) in ys.iter().zip(zs).enumerate() {
                let j = r.start + k;
                let dy = yi + yj;
                let dz = zi - zj;
                out[n] = j as u32 | MIRRORED;
                n += (dy * dy + dz * dz < support2) as usize;
            }
        }
        self.tag.truncate(n);
    }

    /// [`ChunkLists::push_candidates`] over the cells within `k` of the point's own (a
    /// multi-resolution search, [`Grid::reach`]), keeping a candidate j within the support of its
    /// pair: `support2[0]` when j is at the base resolution (`level[j]` = 0), `support2[1]` when it is
    /// coarse.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    pub fn push_candidates_within(
        &mut self,
        grid: &Grid,
        y: &[f64],
        z: &[f64],
        level: &[u8],
        yi: f64,
        zi: f64,
        skip: usize,
        support2: [f64; 2],
        k: usize,
    ) {
        let rows = grid.ranges_within(yi, zi, k);
        let mirrored = grid.mirror_ranges_within(yi, zi, k);
        let total: usize = rows.iter().chain(mirrored.iter()).map(|r| r.len()).sum();
        let mut n = self.tag.len();
        self.tag.resize(n + total, 0);
        let out = &mut self.tag[..];
        for r in rows {
            let (ys, zs, ls) = (&y[r.clone()], &z[r.clone()], &level[r.clone()]);
            for (m, ((&yj, &zj), &lj)) in ys.iter().zip(zs).zip(ls).enumerate() {
                let j = r.start + m;
                let dy = yi - yj;
                let dz = zi - zj;
                out[n] = j as u32;
                let s2 = support2[(lj != 0) as usize];
                n += ((dy * dy + dz * dz < s2) & (j != skip)) as usize;
            }
        }
        for r in mirrored {
            let (ys, zs, ls) = (&y[r.clone()], &z[r.clone()], &level[r.clone()]);
            for (m, ((&yj, &zj), &lj)) in ys.iter().zip(zs).zip(ls).enumerate() {
                let j = r.start + m;
                let dy = yi + yj;
                let dz = zi - zj;
                out[n] = j as u32 | MIRRORED;
                let s2 = support2[(lj != 0) as usize];
                n += (dy * dy + dz * dz < s2) as usize;
            }
        }
        self.tag.truncate(n);
    }

    /// The entries of the particle being built (pushed since the last [`ChunkLists::end_particle`]), to
    /// be flagged with [`mark_fluid`].
    #[inline(always)]
    pub fn last_entries(&mut self) -> &mut [u32] {
        let first = self.start[self.start.len() - 1] as usize;
        &mut self.tag[first..]
    }

    /// Close the list of the current particle.
    #[inline(always)]
    pub fn end_particle(&mut self) {
        self.start.push(self.tag.len() as u32);
    }

    /// The list entries of particle k of the chunk, in the order they were found (decode them with
    /// [`neighbour`] and [`is_fluid`]).
    #[inline(always)]
    pub fn tags(&self, k: usize) -> &[u32] {
        &self.tag[self.start[k] as usize..self.start[k + 1] as usize]
    }

    /// Number of neighbour entries held.
    pub fn len(&self) -> usize {
        self.tag.len()
    }

    /// Whether the chunk holds no neighbour entries.
    pub fn is_empty(&self) -> bool {
        self.tag.is_empty()
    }

    /// Bytes allocated (capacity, not only the entries in use).
    pub fn bytes(&self) -> usize {
        4 * (self.start.capacity() + self.tag.capacity()) + std::mem::size_of::<Self>()
    }
}

/// The kernel of the pairs: one smoothing length, or the pair kernels of a two-level run.
#[derive(Debug, Clone, Copy)]
pub struct PairKernel {
    uniform: WendlandC2,
    refined: Option<PairKernels>,
}

impl PairKernel {
    /// The kernel of a run with base kernel `kernel`, two-level when `multi_resolution`.
    pub fn new(kernel: &WendlandC2, multi_resolution: bool) -> Self {
        Self {
            uniform: *kernel,
            refined: multi_resolution.then(|| PairKernels::new(kernel.h())),
        }
    }

    /// The kernel of the pair of levels `li`, `lj` (the run's one kernel when it is uniform).
    #[inline(always)]
    pub fn pair(&self, li: u8, lj: u8) -> &WendlandC2 {
        match &self.refined {
            Some(p) => p.pair(li, lj),
            None => &self.uniform,
        }
    }

    /// The kernels of a level-`li` particle's pairs with a base-resolution (level 0) and with a coarse
    /// (level 1) neighbour.
    #[inline(always)]
    pub fn of_level(&self, li: u8) -> [WendlandC2; 2] {
        [*self.pair(li, 0), *self.pair(li, 1)]
    }

    /// F(r) of the pair of levels `li`, `lj`.
    #[inline(always)]
    pub fn grad_factor(&self, li: u8, lj: u8, r: f64) -> f64 {
        match &self.refined {
            Some(p) => p.pair(li, lj).grad_factor(r),
            None => self.uniform.grad_factor(r),
        }
    }
}

/// Neighbour lists of all particles (chunks of [`LIST_CHUNK`] particles in storage order), built once per
/// step at the sorted positions by the momentum pass, and valid until the particles move or are re-sorted.
/// Reusing them in the next continuity pass (taken at the same positions) halves the searches. The
/// buffers keep their capacity, so after the first steps the time loop does not allocate.
#[derive(Debug, Clone, Default)]
pub struct NeighbourLists {
    pub chunks: Vec<ChunkLists>,
    /// The kernel the lists were built for (set by the momentum pass).
    pub kernel: Option<PairKernel>,
}

impl NeighbourLists {
    /// Bytes allocated by the lists (list starts and neighbour entries, capacities counted).
    pub fn bytes(&self) -> usize {
        self.chunks.iter().map(ChunkLists::bytes).sum()
    }

    /// Make room for `n` particles.
    pub fn resize(&mut self, n: usize) {
        self.chunks
            .resize_with(n.div_ceil(LIST_CHUNK), ChunkLists::default);
    }

    /// The lists with the positions and levels of `pt` (the ones they were built at), to read the
    /// neighbours of a particle with their distances and kernel factors.
    pub fn at<'a>(&'a self, pt: &'a Particles) -> ListsAt<'a> {
        ListsAt {
            lists: self,
            kernel: self
                .kernel
                .expect("neighbour lists used before the momentum pass built them"),
            y: &pt.y,
            z: &pt.z,
            level: &pt.level,
            kind: &pt.kind,
        }
    }
}

/// Neighbour lists read at the positions they were built at ([`NeighbourLists::at`]).
#[derive(Clone, Copy)]
pub struct ListsAt<'a> {
    pub lists: &'a NeighbourLists,
    pub kernel: PairKernel,
    y: &'a [f64],
    z: &'a [f64],
    level: &'a [u8],
    kind: &'a [Kind],
}

impl<'a> ListsAt<'a> {
    /// The neighbours of particle i (entry k of chunk c: i = c LIST_CHUNK + k) in the order they were
    /// found, with |r_ij| and F(|r_ij|) computed as in the momentum pass.
    #[inline(always)]
    pub fn of(&self, c: usize, k: usize, i: usize) -> impl Iterator<Item = ListEntry> + 'a {
        let (yi, zi, li) = (self.y[i], self.z[i], self.level[i]);
        let (y, z, level, kernel) = (self.y, self.z, self.level, self.kernel);
        debug_assert!(self.kind[i].is_fluid() || self.lists.chunks[c].tags(k).is_empty());
        self.lists.chunks[c].tags(k).iter().map(move |&t| {
            let (j, mirrored) = neighbour(t);
            let dz = zi - z[j];
            let dy = if mirrored { yi + y[j] } else { yi - y[j] };
            let r = (dy * dy + dz * dz).sqrt();
            ListEntry {
                j,
                mirrored,
                fluid: is_fluid(t),
                r,
                f: kernel.grad_factor(li, level[j], r),
            }
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::neighbours::for_each_neighbour;

    #[test]
    fn lists_hold_the_pairs_of_the_search_in_its_order() {
        let (mut y, mut z) = (Vec::new(), Vec::new());
        for k in 0..400 {
            let a = k as f64 * 0.618_033_988_75;
            y.push((a * 7.3).fract());
            z.push((a * 3.1).fract() - 0.5);
        }
        let support = 0.09;
        let mut g = Grid::new(0.0, 1.0, -0.5, 0.5, 0.5 * support, true);
        let order = g.sort(&y, &z).to_vec();
        let mut pt = Particles::default();
        for &k in &order {
            let (yk, zk) = (y[k as usize], z[k as usize]);
            pt.push(Kind::Fluid, yk, zk, 0.0, 0.0, 1000.0, 0.0, 1e-4);
        }
        let kernel = WendlandC2::new(0.5 * support);
        let mut lists = NeighbourLists {
            kernel: Some(PairKernel::new(&kernel, false)),
            ..Default::default()
        };
        lists.resize(pt.len());
        let mut want_all = Vec::new();
        for i in 0..pt.len() {
            let (c, k) = (i / LIST_CHUNK, i % LIST_CHUNK);
            let list = &mut lists.chunks[c];
            if k == 0 {
                list.clear();
            }
            let mut want = Vec::new();
            for_each_neighbour(
                &g,
                &pt.y,
                &pt.z,
                pt.y[i],
                pt.z[i],
                i,
                support * support,
                |j, _, _, r2, m| want.push((j, m, j.is_multiple_of(3), r2.sqrt())),
            );
            list.push_candidates(&g, &pt.y, &pt.z, pt.y[i], pt.z[i], i, support * support);
            for t in list.last_entries() {
                let j = neighbour(*t).0;
                mark_fluid(t, j.is_multiple_of(3));
            }
            list.end_particle();
            want_all.push(want);
        }
        let at = lists.at(&pt);
        let mut pairs = 0;
        for (i, want) in want_all.iter().enumerate() {
            let (c, k) = (i / LIST_CHUNK, i % LIST_CHUNK);
            let got: Vec<_> = at
                .of(c, k, i)
                .map(|e| (e.j, e.mirrored, e.fluid, e.r))
                .collect();
            assert_eq!(&got, want, "particle {i}");
            for e in at.of(c, k, i) {
                assert_eq!(e.f, kernel.grad_factor(e.r));
            }
            pairs += got.len();
        }
        assert!(pairs > pt.len(), "too few pairs to test: {pairs}");
    }
}
