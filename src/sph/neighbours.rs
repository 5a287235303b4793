//! Cell-linked neighbour search on a uniform grid of cell size 2h (the kernel support).
//!
//! Every time step the particles are counting-sorted by cell (row-major: cell = iz * ny + iy) and the
//! structure-of-arrays storage is permuted into that order, so the three cells of a grid row that a particle
//! must look at are one contiguous range of memory. The sort is stable, so the order (and with it every
//! sum in the solver) is the same on any number of threads.
//!
//! With a symmetry plane (`mirror`), the grid starts at y = 0 and a particle in the first column also
//! interacts with the mirror images (y -> -y) of the particles in the first column.

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
}

impl Grid {
    /// Grid covering y in [y0, y1], z in [z0, z1] with square cells of side `cell` (at least the kernel
    /// support). Particles outside are put in the nearest boundary cell, which keeps the search correct
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
        }
    }

    /// Number of cells.
    pub fn n_cells(&self) -> usize {
        self.ny * self.nz
    }

    #[inline(always)]
    fn column_row(&self, y: f64, z: f64) -> (usize, usize) {
        let iy = ((y - self.y0) * self.inv_cell).floor();
        let iz = ((z - self.z0) * self.inv_cell).floor();
        let iy = iy.clamp(0.0, (self.ny - 1) as f64) as usize;
        let iz = iz.clamp(0.0, (self.nz - 1) as f64) as usize;
        (iy, iz)
    }

    /// Counting sort of the particles by cell. Returns the permutation: new position k holds old particle
    /// `order[k]`. Allocates only on the first call (or when the particle count grows).
    pub fn sort(&mut self, y: &[f64], z: &[f64]) -> &[u32] {
        let n = y.len();
        self.cell_of.resize(n, 0);
        self.order.resize(n, 0);
        let (ny, nz, y0, z0, inv) = (self.ny, self.nz, self.y0, self.z0, self.inv_cell);
        self.cell_of
            .par_iter_mut()
            .with_min_len(4096)
            .enumerate()
            .for_each(|(i, c)| {
                let iy = ((y[i] - y0) * inv).floor().clamp(0.0, (ny - 1) as f64) as usize;
                let iz = ((z[i] - z0) * inv).floor().clamp(0.0, (nz - 1) as f64) as usize;
                *c = (iz * ny + iy) as u32;
            });
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

    /// The three contiguous index ranges (rows iz-1, iz, iz+1, each over columns iy-1..=iy+1) that hold
    /// every possible neighbour of a point, valid after [`Grid::sort`] and the permutation.
    #[inline(always)]
    pub fn ranges(&self, y: f64, z: f64) -> [Range<usize>; 3] {
        let (iy, iz) = self.column_row(y, z);
        let c0 = iy.saturating_sub(1);
        let c1 = (iy + 1).min(self.ny - 1);
        let mut out = [0..0, 0..0, 0..0];
        for (k, dz) in [-1isize, 0, 1].into_iter().enumerate() {
            let r = iz as isize + dz;
            if r < 0 || r >= self.nz as isize {
                continue;
            }
            let row = r as usize * self.ny;
            out[k] = self.cell_start[row + c0] as usize..self.cell_start[row + c1 + 1] as usize;
        }
        out
    }

    /// Ranges whose mirror images (y -> -y) can be neighbours of a point: the first column, rows iz-1..=iz+1,
    /// when the point itself lies in the first column of a grid with a symmetry plane; else empty.
    #[inline(always)]
    pub fn mirror_ranges(&self, y: f64, z: f64) -> [Range<usize>; 3] {
        let mut out = [0..0, 0..0, 0..0];
        if !self.mirror {
            return out;
        }
        let (iy, iz) = self.column_row(y, z);
        if iy != 0 {
            return out;
        }
        for (k, dz) in [-1isize, 0, 1].into_iter().enumerate() {
            let r = iz as isize + dz;
            if r < 0 || r >= self.nz as isize {
                continue;
            }
            let row = r as usize * self.ny;
            out[k] = self.cell_start[row] as usize..self.cell_start[row + 1] as usize;
        }
        out
    }

    /// Whether the grid has a symmetry plane at y = 0.
    pub fn mirror(&self) -> bool {
        self.mirror
    }
}

/// Visit every particle j within `support2` (squared support radius) of point (yi, zi), including mirror
/// images. The closure gets (j, dy, dz, r2, mirrored) with (dy, dz) = r_i - r_j (r_j the image position when
/// mirrored). Particle `skip` itself (not its image) is left out.
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
    for r in grid.ranges(yi, zi) {
        for j in r {
            let dy = yi - y[j];
            let dz = zi - z[j];
            let r2 = dy * dy + dz * dz;
            if r2 < support2 && j != skip {
                f(j, dy, dz, r2, false);
            }
        }
    }
    for r in grid.mirror_ranges(yi, zi) {
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

#[cfg(test)]
mod tests {
    use super::*;

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
        let mut g = Grid::new(0.0, 1.0, -0.5, 0.5, support, true);
        let order = g.sort(&y, &z).to_vec();
        let ys: Vec<f64> = order.iter().map(|&k| y[k as usize]).collect();
        let zs: Vec<f64> = order.iter().map(|&k| z[k as usize]).collect();
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
