//! Cell-linked neighbour search on a uniform grid of cell size h (half the kernel support).
//!
//! Every time step the particles are counting-sorted by cell (row-major: cell = iz * ny + iy) and the
//! structure-of-arrays storage is permuted into that order, so the five cells of a grid row that a particle
//! must look at are one contiguous range of memory. Cells of size h (5 x 5 cells searched) hold about 30 %
//! fewer candidates outside the support than cells of size 2h (3 x 3 cells). The sort is stable, so the order (and with it every
//! sum in the solver) is the same on any number of threads.
//!
//! With a symmetry plane (`mirror`), the grid starts at y = 0 and a particle in the first two columns also
//! interacts with the mirror images (y -> -y) of the particles in the first columns.

use std::ops::Range;

use rayon::prelude::*;

/// Uniform cell grid over the computational domain.
#[derive(Debug, Clone)]
pub struct Grid {
    y0: f64,
    z0: f64,
    inv_cell: f64,
    ny: usize,
    nz: usize,
    mirror: bool,
    cell_start: Vec<u32>,
    cell_of: Vec<u32>,
    order: Vec<u32>,
    /// Per cell, whether a coarse (level > 0) particle lies within [`COARSE_REACH`] - 1 cells of it;
    /// empty for a single-resolution run ([`Grid::mark_coarse`]).
    near_coarse: Vec<bool>,
    /// The cells that held a coarse particle at the last [`Grid::mark_coarse`], whose dilation
    /// `near_coarse` is.
    has_coarse: Vec<bool>,
    /// Scratch of [`Grid::mark_coarse`] (the cells holding a coarse particle now; the row-wise dilation).
    rows_coarse: Vec<bool>,
}

/// Cells a coarse particle (smoothing length 2h on cells of size h) searches on either side of its own:
/// its support 4h with another coarse particle.
pub const COARSE_REACH: usize = 4;
/// Cells a base-resolution particle searches on either side of its own when a coarse particle may be
/// near: the support 2 (h + 2h) / 2 = 3h of a mixed pair.
pub const MIXED_REACH: usize = 3;

impl Grid {
    /// Grid covering y in [y0, y1], z in [z0, z1] with square cells of side `cell` (at least half the
    /// kernel support). Particles outside are put in the nearest boundary cell, which keeps the search correct
    /// (only slower) for the few that fly out of the box.
    pub fn new(y0: f64, y1: f64, z0: f64, z1: f64, cell: f64, mirror: bool) -> Self {
        let ny = (((y1 - y0) / cell).ceil() as usize).max(1);
        let nz = (((z1 - z0) / cell).ceil() as usize).max(1);
        Self {
            y0,
            z0,
            inv_cell: 1.0 / cell,
            ny,
            nz,
            mirror,
            cell_start: vec![0; ny * nz + 1],
            cell_of: Vec::new(),
            order: Vec::new(),
            near_coarse: Vec::new(),
            has_coarse: Vec::new(),
            rows_coarse: Vec::new(),
        }
    }

    /// After [`Grid::sort`] and the permutation: mark every cell within [`MIXED_REACH`] cells of a cell
    /// that holds a coarse particle (`level` in storage order), so that a base-resolution particle there
    /// searches far enough for its mixed pairs (and one elsewhere only as far as its own support).
    ///
    /// The marks depend only on which cells hold a coarse particle: when those are the cells of the last
    /// call (the coarse far field moves little between two sorts), the marks are kept as they are.
    pub fn mark_coarse(&mut self, level: &[u8]) {
        let (ny, nz) = (self.ny, self.nz);
        let mut has = std::mem::take(&mut self.rows_coarse);
        has.resize(ny * nz, false);
        for (c, h) in has.iter_mut().enumerate() {
            let r = self.cell_start[c] as usize..self.cell_start[c + 1] as usize;
            *h = level[r].iter().any(|&l| l > 0);
        }
        if has == self.has_coarse && self.near_coarse.len() == ny * nz {
            self.rows_coarse = has;
            return;
        }
        let mut rows = std::mem::take(&mut self.has_coarse);
        rows.resize(ny * nz, false);
        let k = MIXED_REACH;
        // Separable dilation: along the rows, then along the columns, each with a running count of the
        // marked cells in the window of 2k + 1 (one pass over the cells instead of 2k + 1).
        for iz in 0..nz {
            let row = iz * ny;
            dilate(ny, k, |x| has[row + x], |x, v| rows[row + x] = v);
        }
        self.near_coarse.resize(ny * nz, false);
        let near = &mut self.near_coarse;
        for iy in 0..ny {
            dilate(nz, k, |x| rows[x * ny + iy], |x, v| near[x * ny + iy] = v);
        }
        self.has_coarse = has;
        self.rows_coarse = rows;
        // The mirror image of a coarse particle in column x is x + 1 columns behind the plane, so a
        // particle in column iy sees it within k cells only when iy + x + 1 <= k: then x is also within
        // k columns of iy, and the dilation above has marked the cell already.
    }

    /// Cells to search on either side for a particle of `level` at (y, z): 2 for the base resolution
    /// away from coarse particles, [`MIXED_REACH`] near them, [`COARSE_REACH`] for a coarse particle.
    #[inline(always)]
    pub fn reach(&self, level: u8, y: f64, z: f64) -> usize {
        if level > 0 {
            return COARSE_REACH;
        }
        let (iy, iz) = self.column_row(y, z);
        if self
            .near_coarse
            .get(iz * self.ny + iy)
            .copied()
            .unwrap_or(false)
        {
            MIXED_REACH
        } else {
            2
        }
    }

    /// The contiguous index ranges (rows iz-k..=iz+k, each over columns iy-k..=iy+k) that hold every
    /// possible neighbour of a point within k cells, k at most [`COARSE_REACH`]; unused entries are empty.
    #[inline(always)]
    pub fn ranges_within(&self, y: f64, z: f64, k: usize) -> [Range<usize>; 2 * COARSE_REACH + 1] {
        let (iy, iz) = self.column_row(y, z);
        let c0 = iy.saturating_sub(k);
        let c1 = (iy + k).min(self.ny - 1);
        let mut out: [Range<usize>; 2 * COARSE_REACH + 1] = Default::default();
        let r0 = iz.saturating_sub(k);
        let r1 = (iz + k).min(self.nz - 1);
        for (m, r) in (r0..=r1).enumerate() {
            let row = r * self.ny;
            out[m] = self.cell_start[row + c0] as usize..self.cell_start[row + c1 + 1] as usize;
        }
        out
    }

    /// Mirror-image ranges within k cells (see [`Grid::mirror_ranges`]): columns 0..=k-1-iy for a point
    /// in column iy < k.
    #[inline(always)]
    pub fn mirror_ranges_within(
        &self,
        y: f64,
        z: f64,
        k: usize,
    ) -> [Range<usize>; 2 * COARSE_REACH + 1] {
        let mut out: [Range<usize>; 2 * COARSE_REACH + 1] = Default::default();
        if !self.mirror {
            return out;
        }
        let (iy, iz) = self.column_row(y, z);
        if iy >= k {
            return out;
        }
        let c1 = (k - 1 - iy).min(self.ny - 1);
        let r0 = iz.saturating_sub(k);
        let r1 = (iz + k).min(self.nz - 1);
        for (m, r) in (r0..=r1).enumerate() {
            let row = r * self.ny;
            out[m] = self.cell_start[row] as usize..self.cell_start[row + c1 + 1] as usize;
        }
        out
    }

    /// Bytes allocated by the grid (cell starts, cell of each particle, sort order, coarse-cell marks).
    pub fn bytes(&self) -> usize {
        4 * (self.cell_start.capacity() + self.cell_of.capacity() + self.order.capacity())
            + self.near_coarse.capacity()
            + self.has_coarse.capacity()
            + self.rows_coarse.capacity()
    }

    /// Number of cells.
    pub fn n_cells(&self) -> usize {
        self.ny * self.nz
    }

    /// Cell column and row of a point, clamped to the grid. Truncation toward zero equals floor for the
    /// points inside, and points below the grid are clamped to the first cell either way.
    #[inline(always)]
    fn column_row(&self, y: f64, z: f64) -> (usize, usize) {
        let iy = (((y - self.y0) * self.inv_cell) as isize).clamp(0, self.ny as isize - 1) as usize;
        let iz = (((z - self.z0) * self.inv_cell) as isize).clamp(0, self.nz as isize - 1) as usize;
        (iy, iz)
    }

    /// Counting sort of the particles by cell. Returns the permutation: new position k holds old particle
    /// `order[k]`. Allocates only on the first call (or when the particle count grows).
    pub fn sort(&mut self, y: &[f64], z: &[f64]) -> &[u32] {
        let n = y.len();
        self.cell_of.resize(n, 0);
        self.order.resize(n, 0);
        let ny = self.ny;
        let mut cell_of = std::mem::take(&mut self.cell_of);
        let this = &*self;
        cell_of
            .par_iter_mut()
            .with_min_len(4096)
            .enumerate()
            .for_each(|(i, c)| {
                let (iy, iz) = this.column_row(y[i], z[i]);
                *c = (iz * ny + iy) as u32;
            });
        self.cell_of = cell_of;
        let start = &mut self.cell_start;
        start.iter_mut().for_each(|s| *s = 0);
        for &c in &self.cell_of {
            start[c as usize + 1] += 1;
        }
        for k in 1..start.len() {
            start[k] += start[k - 1];
        }
        // Scatter with a running cursor per cell (stable); the cursor is cell_start shifted by one, rebuilt
        // in place afterwards.
        for (i, &c) in self.cell_of.iter().enumerate() {
            let slot = &mut start[c as usize];
            self.order[*slot as usize] = i as u32;
            *slot += 1;
        }
        // start[c] now equals the end of cell c, i.e. the start of cell c + 1: shift back.
        for k in (1..start.len()).rev() {
            start[k] = start[k - 1];
        }
        start[0] = 0;
        &self.order
    }

    /// The five contiguous index ranges (rows iz-2..=iz+2, each over columns iy-2..=iy+2) that hold every
    /// possible neighbour of a point, valid after [`Grid::sort`] and the permutation.
    #[inline(always)]
    pub fn ranges(&self, y: f64, z: f64) -> [Range<usize>; 5] {
        let (iy, iz) = self.column_row(y, z);
        let c0 = iy.saturating_sub(2);
        let c1 = (iy + 2).min(self.ny - 1);
        let mut out = [0..0, 0..0, 0..0, 0..0, 0..0];
        let r0 = iz.saturating_sub(2);
        let r1 = (iz + 2).min(self.nz - 1);
        for (k, r) in (r0..=r1).enumerate() {
            let row = r * self.ny;
            out[k] = self.cell_start[row + c0] as usize..self.cell_start[row + c1 + 1] as usize;
        }
        out
    }

    /// Ranges whose mirror images (y -> -y) can be neighbours of a point in column iy < 2 of a grid with a
    /// symmetry plane: columns 0..=1-iy, rows iz-2..=iz+2; else empty.
    #[inline(always)]
    pub fn mirror_ranges(&self, y: f64, z: f64) -> [Range<usize>; 5] {
        let mut out = [0..0, 0..0, 0..0, 0..0, 0..0];
        if !self.mirror {
            return out;
        }
        let (iy, iz) = self.column_row(y, z);
        if iy >= 2 {
            return out;
        }
        let c1 = (1 - iy).min(self.ny - 1);
        let r0 = iz.saturating_sub(2);
        let r1 = (iz + 2).min(self.nz - 1);
        for (k, r) in (r0..=r1).enumerate() {
            let row = r * self.ny;
            out[k] = self.cell_start[row] as usize..self.cell_start[row + c1 + 1] as usize;
        }
        out
    }

    /// Whether the grid has a symmetry plane at y = 0.
    pub fn mirror(&self) -> bool {
        self.mirror
    }
}

/// Neighbours gathered per batch before the closure runs on them.
const BATCH: usize = 32;

/// One-dimensional dilation over n cells: `set(x, v)` with v whether any of `get(x - k ..= x + k)` (clipped
/// to the cells) holds, by a running count of the marked cells in the window.
#[inline]
fn dilate(n: usize, k: usize, get: impl Fn(usize) -> bool, mut set: impl FnMut(usize, bool)) {
    let mut count = (0..=k.min(n.saturating_sub(1))).filter(|&x| get(x)).count();
    for x in 0..n {
        set(x, count > 0);
        if x + k + 1 < n && get(x + k + 1) {
            count += 1;
        }
        if x >= k && get(x - k) {
            count -= 1;
        }
    }
}

/// Visit every particle j within `support2` (squared support radius) of point (yi, zi), including mirror
/// images. The closure gets (j, dy, dz, r2, mirrored) with (dy, dz) = r_i - r_j (r_j the image position when
/// mirrored). Particle `skip` itself (not its image) is left out.
///
/// The candidates of the neighbouring cells are first filtered without branches into a small buffer (a
/// candidate is written unconditionally and kept by advancing the count), then the closure runs over the
/// buffer: this avoids a mispredicted branch for every candidate outside the support. The visiting order
/// is the storage order, so sums do not depend on the thread count.
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn for_each_neighbour<F: FnMut(usize, f64, f64, f64, bool)>(
    grid: &Grid,
    y: &[f64],
    z: &[f64],
    yi: f64,
    zi: f64,
    skip: usize,
    support2: f64,
    mut f: F,
) {
    let mut idx = [0u32; BATCH];
    let mut n = 0usize;
    // Candidates are filtered into `idx` without branches; distances are recomputed for the few kept.
    let mut flush = |idx: &[u32], mirrored: bool| {
        for &j in idx {
            let j = j as usize;
            let dy = if mirrored { yi + y[j] } else { yi - y[j] };
            let dz = zi - z[j];
            f(j, dy, dz, dy * dy + dz * dz, mirrored);
        }
    };
    for r in grid.ranges(yi, zi) {
        let (ys, zs) = (&y[r.clone()], &z[r.clone()]);
        for (k, (&yj, &zj)) in ys.iter().zip(zs).enumerate() {
            let j = r.start + k;
            let dy = yi - yj;
            let dz = zi - zj;
            idx[n] = j as u32;
            n += ((dy * dy + dz * dz < support2) & (j != skip)) as usize;
            if n == BATCH {
                flush(&idx, false);
                n = 0;
            }
        }
    }
    flush(&idx[..n], false);
    n = 0;
    for r in grid.mirror_ranges(yi, zi) {
        for j in r {
            let dy = yi + y[j];
            let dz = zi - z[j];
            idx[n] = j as u32;
            n += (dy * dy + dz * dz < support2) as usize;
            if n == BATCH {
                flush(&idx, true);
                n = 0;
            }
        }
    }
    flush(&idx[..n], true);
}

/// [`for_each_neighbour`] over the cells within `k` of the point's own (a multi-resolution search,
/// [`Grid::reach`]).
#[allow(clippy::too_many_arguments)]
#[inline(always)]
pub fn for_each_neighbour_within<F: FnMut(usize, f64, f64, f64, bool)>(
    grid: &Grid,
    y: &[f64],
    z: &[f64],
    yi: f64,
    zi: f64,
    skip: usize,
    support2: f64,
    k: usize,
    mut f: F,
) {
    for r in grid.ranges_within(yi, zi, k) {
        for j in r {
            let dy = yi - y[j];
            let dz = zi - z[j];
            let r2 = dy * dy + dz * dz;
            if r2 < support2 && j != skip {
                f(j, dy, dz, r2, false);
            }
        }
    }
    for r in grid.mirror_ranges_within(yi, zi, k) {
        for j in r {
            let dy = yi + y[j];
            let dz = zi - z[j];
            let r2 = dy * dy + dz * dz;
            if r2 < support2 {
                f(j, dy, dz, r2, true);
            }
        }
    }
}

pub use crate::sph::neighbour_lists::{ChunkLists, LIST_CHUNK, NeighbourLists};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_running_dilation_marks_what_the_window_test_marks() {
        // Every pattern of 9 cells, windows of half-width 0 to 10 (wider than the row included).
        for bits in 0u32..512 {
            let n = 9;
            let has = |x: usize| bits >> x & 1 == 1;
            for k in 0..=10 {
                let mut got = vec![false; n];
                dilate(n, k, has, |x, v| got[x] = v);
                for (x, g) in got.iter().enumerate() {
                    let want = (x.saturating_sub(k)..=(x + k).min(n - 1)).any(has);
                    assert_eq!(*g, want, "pattern {bits:09b}, k {k}, cell {x}");
                }
            }
        }
    }

    /// Points in the unit box (mirror plane at y = 0) sorted by cell on a grid of cells support/2.
    fn sorted_on_grid(y: &[f64], z: &[f64], support: f64) -> (Grid, Vec<f64>, Vec<f64>) {
        let mut g = Grid::new(0.0, 1.0, -0.5, 0.5, 0.5 * support, true);
        let order = g.sort(y, z).to_vec();
        let ys = order.iter().map(|&k| y[k as usize]).collect();
        let zs = order.iter().map(|&k| z[k as usize]).collect();
        (g, ys, zs)
    }

    #[test]
    fn the_coarse_marks_follow_a_coarse_particle_to_its_new_cell() {
        // Cells of 0.1 on [0, 1] x [0, 1]: one coarse particle and one at the base resolution.
        let mut g = Grid::new(0.0, 1.0, 0.0, 1.0, 0.1, false);
        let marks = |g: &mut Grid, y: [f64; 2], z: [f64; 2]| {
            let order = g.sort(&y, &z).to_vec();
            let level: Vec<u8> = order.iter().map(|&k| [1u8, 0][k as usize]).collect();
            g.mark_coarse(&level);
            (0..10)
                .map(|c| g.reach(0, 0.05 + 0.1 * c as f64, 0.05))
                .collect::<Vec<_>>()
        };
        let first = marks(&mut g, [0.05, 0.95], [0.05, 0.95]);
        assert_eq!(first, [3, 3, 3, 3, 2, 2, 2, 2, 2, 2]);
        // the coarse particle moves within its cell: the marks stay
        assert_eq!(marks(&mut g, [0.06, 0.5], [0.04, 0.5]), first);
        // it moves five cells along the row: the marks move with it
        let moved = marks(&mut g, [0.55, 0.5], [0.05, 0.5]);
        assert_eq!(moved, [2, 2, 3, 3, 3, 3, 3, 3, 3, 2]);
    }

    #[test]
    fn finds_the_same_pairs_as_brute_force() {
        let mut y = Vec::new();
        let mut z = Vec::new();
        let mut s = 12345u64;
        for _ in 0..500 {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            y.push((s >> 11) as f64 / (1u64 << 53) as f64);
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            z.push((s >> 11) as f64 / (1u64 << 53) as f64 - 0.5);
        }
        let support = 0.07;
        let (g, ys, zs) = sorted_on_grid(&y, &z, support);
        for i in 0..ys.len() {
            let mut found = Vec::new();
            for_each_neighbour(
                &g,
                &ys,
                &zs,
                ys[i],
                zs[i],
                i,
                support * support,
                |j, _, _, _, m| found.push((j, m)),
            );
            let mut brute = Vec::new();
            for j in 0..ys.len() {
                let r2 = (ys[i] - ys[j]).powi(2) + (zs[i] - zs[j]).powi(2);
                if j != i && r2 < support * support {
                    brute.push((j, false));
                }
                let r2m = (ys[i] + ys[j]).powi(2) + (zs[i] - zs[j]).powi(2);
                if r2m < support * support {
                    brute.push((j, true));
                }
            }
            found.sort();
            brute.sort();
            assert_eq!(found, brute, "particle {i}");
        }
    }
}
