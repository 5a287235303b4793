//! Batches of neighbours for the pair loops of [`crate::sph::rates`].
//!
//! A pair loop runs in three stages over batches of neighbours of one particle ([`BATCH`] in the
//! momentum pass, [`KINEMATIC_BATCH`] in the continuity pass): the neighbours' state is gathered into
//! small fixed-length arrays (with the mirror image's sign applied: y -> -y, v_y -> -v_y), the pair
//! terms are computed lane by lane over the whole batch (a loop without gathers or early exits that the
//! compiler vectorises: the square roots and divisions of several pairs go through one vector
//! instruction), and the terms are summed into the particle's accumulators one by one in the neighbour
//! order. Every term is computed with the same operations as one pair at a time (IEEE arithmetic is the
//! same in every lane, and Rust never fuses a multiply and an add), and the sums keep the list order,
//! so the results are bit-identical to a plain loop over the neighbours.
//!
//! For a mirror image the gathered y is -y_j, and r_i - r_j' = y_i - (-y_j) = y_i + y_j exactly (an IEEE
//! subtraction is the addition of the negated operand).

use crate::sph::neighbour_lists::{is_fluid, mark_fluid, neighbour};
use crate::sph::particles::{Kind, View};

/// Neighbours per batch of the momentum pass.
pub const BATCH: usize = 8;

/// Neighbours per batch of the continuity pass: a whole neighbour list at the usual spacing (h = 1.3-1.5
/// dp: 21-28 neighbours). Its gather is short, and with a whole list gathered before the lane loop reads
/// it the lane loop's vector loads no longer wait on the gather's scalar stores (the batch of 8 ran
/// about 1.5 times slower).
pub const KINEMATIC_BATCH: usize = 32;

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
        // Slices of one length, so that one bounds check covers every array.
        let n = pt.y.len();
        let (y, z, vy, vz) = (&pt.y[..n], &pt.z[..n], &pt.vy[..n], &pt.vz[..n]);
        let (rho, p, vol, kind) = (&pt.rho[..n], &pt.p[..n], &pt.vol[..n], &pt.kind[..n]);
        for (l, t) in tags.iter_mut().enumerate().take(BATCH) {
            let (j, mirrored) = neighbour(*t);
            assert!(j < n);
            let sign = sign_bit(mirrored);
            self.y[l] = f64::from_bits(y[j].to_bits() ^ sign);
            self.z[l] = z[j];
            self.vy[l] = f64::from_bits(vy[j].to_bits() ^ sign);
            self.vz[l] = vz[j];
            self.rho[l] = rho[j];
            self.p[l] = p[j];
            self.vol[l] = vol[j];
            if MARK {
                let fluid = kind[j] == Kind::Fluid;
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

/// The positions, velocities and volumes of a batch of neighbours j of one particle: what the continuity
/// pass reads (mirror images as in [`Gathered`]).
#[derive(Clone, Copy, Default)]
pub struct Kinematics {
    pub y: [f64; KINEMATIC_BATCH],
    pub z: [f64; KINEMATIC_BATCH],
    pub vy: [f64; KINEMATIC_BATCH],
    pub vz: [f64; KINEMATIC_BATCH],
    pub vol: [f64; KINEMATIC_BATCH],
    /// Whether j is coarse (level > 0; two-level runs only).
    pub coarse: [bool; KINEMATIC_BATCH],
}

impl Kinematics {
    /// Gather the neighbours of list entries `tags` (at most [`KINEMATIC_BATCH`]); `level` is read when
    /// `MULTI`.
    #[inline(always)]
    pub fn gather<const MULTI: bool>(&mut self, tags: &[u32], pt: &View, level: &[u8]) {
        let n = pt.y.len();
        let (y, z, vy, vz, vol) = (
            &pt.y[..n],
            &pt.z[..n],
            &pt.vy[..n],
            &pt.vz[..n],
            &pt.vol[..n],
        );
        for (l, &t) in tags.iter().enumerate().take(KINEMATIC_BATCH) {
            let (j, mirrored) = neighbour(t);
            assert!(j < n);
            let sign = sign_bit(mirrored);
            self.y[l] = f64::from_bits(y[j].to_bits() ^ sign);
            self.z[l] = z[j];
            self.vy[l] = f64::from_bits(vy[j].to_bits() ^ sign);
            self.vz[l] = vz[j];
            self.vol[l] = vol[j];
            if MULTI {
                self.coarse[l] = level[j] != 0;
            }
        }
    }
}

/// The sign bit of an f64 when `mirrored` (XOR with it negates exactly), else 0.
#[inline(always)]
fn sign_bit(mirrored: bool) -> u64 {
    (mirrored as u64) << 63
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

/// Pair terms of a batch of the continuity pass, lane by lane: the divergence term, or the seven
/// products of the corrected divergence ([`crate::sph::kernel_correction::DivergenceSums::add_products`]).
#[derive(Clone, Copy, Default)]
pub struct KinematicTerms {
    pub moment: [[f64; KINEMATIC_BATCH]; 3],
    pub gradient: [[f64; KINEMATIC_BATCH]; 4],
}

/// A pass's AVX2 twin: `avx2_twin!(name = inner<const A: bool, ...>(arg: Type, ...) -> Ret)` defines
/// `name`, which calls the `#[inline(always)]` function `inner` with the same arguments, compiled with
/// AVX2 enabled (so `inner`'s lane loops use 4-lane vectors). Call it only where [`has_avx2`] is true.
macro_rules! avx2_twin {
    ($name:ident = $inner:ident $(<$(const $c:ident: bool),+>)? ($($arg:ident: $ty:ty),* $(,)?) $(-> $ret:ty)?) => {
        #[doc = concat!("[`", stringify!($inner), "`] compiled with AVX2.")]
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx2")]
        fn $name $(<$(const $c: bool),+>)? ($($arg: $ty),*) $(-> $ret)? {
            $inner $(::<$($c),+>)? ($($arg),*)
        }
    };
}
pub(crate) use avx2_twin;

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
