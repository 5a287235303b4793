//! Batches of neighbours for the pair loops of [`crate::sph::rates`].
//!
//! A pair loop runs in three stages over batches of [`BATCH`] neighbours of one particle: the
//! neighbours' state is gathered into small fixed-length arrays (with the mirror image's sign applied:
//! y -> -y, v_y -> -v_y), the pair terms are computed lane by lane over the whole batch (a loop without
//! gathers or early exits that the compiler vectorises: the square roots and divisions of several pairs
//! go through one vector instruction), and the terms are summed into the particle's accumulators one by
//! one in the neighbour order. Every term is computed with the same operations as one pair at a time
//! (IEEE arithmetic is the same in every lane, and Rust never fuses a multiply and an add), and the sums
//! keep the list order, so the results are bit-identical to a plain loop over the neighbours.
//!
//! For a mirror image the gathered y is -y_j, and r_i - r_j' = y_i - (-y_j) = y_i + y_j exactly (an IEEE
//! subtraction is the addition of the negated operand).

use crate::sph::neighbour_lists::{is_fluid, mark_fluid, neighbour};
use crate::sph::particles::{Kind, View};

/// Neighbours per batch.
pub const BATCH: usize = 8;

/// The state of a batch of neighbours j of one particle (lanes past the batch's length hold stale or zero
/// values whose terms are computed and left out of the sums).
#[derive(Clone, Copy, Default)]
pub struct Gathered {
    pub y: [f64; BATCH],
    pub z: [f64; BATCH],
    pub vy: [f64; BATCH],
    pub vz: [f64; BATCH],
    pub rho: [f64; BATCH],
    pub p: [f64; BATCH],
    pub vol: [f64; BATCH],
    pub fluid: [bool; BATCH],
    /// Whether j is coarse (level > 0; two-level runs only).
    pub coarse: [bool; BATCH],
}

impl Gathered {
    /// Gather the neighbours of list entries `tags` (at most [`BATCH`]); the fluid flags are read from
    /// the particle kinds and written into the entries when `MARK` (the momentum pass, which builds the
    /// lists), else read from the entries. `level` is read when `MULTI`.
    #[inline(always)]
    pub fn gather<const MARK: bool, const MULTI: bool>(
        &mut self,
        tags: &mut [u32],
        pt: &View,
        level: &[u8],
    ) {
        for (l, t) in tags.iter_mut().enumerate().take(BATCH) {
            let (j, mirrored) = neighbour(*t);
            self.y[l] = if mirrored { -pt.y[j] } else { pt.y[j] };
            self.z[l] = pt.z[j];
            self.vy[l] = if mirrored { -pt.vy[j] } else { pt.vy[j] };
            self.vz[l] = pt.vz[j];
            self.rho[l] = pt.rho[j];
            self.p[l] = pt.p[j];
            self.vol[l] = pt.vol[j];
            if MARK {
                let fluid = pt.kind[j] == Kind::Fluid;
                mark_fluid(t, fluid);
                self.fluid[l] = fluid;
            } else {
                self.fluid[l] = is_fluid(*t);
            }
            if MULTI {
                self.coarse[l] = level[j] != 0;
            }
        }
    }
}

/// Pair terms of a batch, lane by lane.
#[derive(Clone, Copy, Default)]
pub struct Terms {
    pub dy: [f64; BATCH],
    pub dz: [f64; BATCH],
    pub r2: [f64; BATCH],
    /// F_ij V_j.
    pub fw: [f64; BATCH],
    /// Pass-specific terms (the momentum pass's pressure force components and viscous factor).
    pub a: [f64; BATCH],
    pub b: [f64; BATCH],
    pub c: [f64; BATCH],
}

/// Whether the CPU runs AVX2 (then the pair loops are compiled for it: 4 lanes a vector instead of 2).
pub fn has_avx2() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        std::is_x86_feature_detected!("avx2")
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        false
    }
}
