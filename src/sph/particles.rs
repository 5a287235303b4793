//! Particle storage: structure of arrays, kept sorted by neighbour-grid cell.

use rayon::prelude::*;

/// What a particle represents.
#[repr(u8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Default)]
pub enum Kind {
    /// Water.
    #[default]
    Fluid = 0,
    /// Dummy particle of a fixed tank wall.
    Wall = 1,
    /// Dummy particle of the moving body.
    Body = 2,
    /// Air ([`crate::sph::air`]): a fluid particle of the second phase.
    Air = 3,
}

impl Kind {
    /// Whether the particle is integrated in time (water or air), not a dummy.
    #[inline(always)]
    pub fn is_fluid(self) -> bool {
        matches!(self, Kind::Fluid | Kind::Air)
    }
}

/// All particles of a run. Position and velocity components are (y, z) in the 2D water-entry frame.
#[derive(Debug, Clone, Default)]
pub struct Particles {
    pub y: Vec<f64>,
    pub z: Vec<f64>,
    pub vy: Vec<f64>,
    pub vz: Vec<f64>,
    /// Density (kg/m3): integrated for fluid, from the extrapolated pressure for dummies.
    pub rho: Vec<f64>,
    pub kind: Vec<Kind>,
    /// Mass (kg per metre): rho dp^2 with the initial (hydrostatic) density, so that every particle starts
    /// with the volume dp^2 of its lattice cell.
    pub mass: Vec<f64>,
    /// Volume m / rho (fluid) or dp^2 (dummies), refreshed with the pressures every step.
    pub vol: Vec<f64>,
    /// Pressure (Pa): equation of state for fluid, extrapolated (Adami et al. 2012) for dummies.
    pub p: Vec<f64>,
    /// Time derivatives of (vy, vz, rho) of fluid particles.
    pub rate: Vec<[f64; 3]>,
    /// Renormalised density gradient of fluid particles (Antuono et al. 2010).
    pub grad_rho: Vec<[f64; 2]>,
    /// Resolution level: 0 at the base spacing dp, 1 at 2 dp (the coarse far field of a refined
    /// tank, [`crate::sph::refinement`]), with smoothing length h 2^level.
    pub level: Vec<u8>,
    /// Whether any particle has a level above 0 (else `level` is all zeros and is not permuted).
    levels: bool,
    /// With the wall's wetness ([`crate::sph::wall_wetness`]): for a body dummy on the body's face, the
    /// part of its kernel support outside the body contour; 0 for every other particle. Empty (and not
    /// permuted) without it.
    pub face_outside: Vec<f64>,
    scratch: Vec<f64>,
    scratch_kind: Vec<Kind>,
    scratch_level: Vec<u8>,
}

/// The per-particle arrays the pair sums read, all cut to the same length: with one length known to the
/// compiler, a single bounds check covers the gathers of every array for a neighbour index.
#[derive(Clone, Copy)]
pub struct View<'a> {
    pub y: &'a [f64],
    pub z: &'a [f64],
    pub vy: &'a [f64],
    pub vz: &'a [f64],
    pub rho: &'a [f64],
    pub vol: &'a [f64],
    pub p: &'a [f64],
    pub kind: &'a [Kind],
}

impl Particles {
    pub fn len(&self) -> usize {
        self.y.len()
    }

    pub fn is_empty(&self) -> bool {
        self.y.is_empty()
    }

    /// The arrays read by the pair sums, cut to a common length.
    #[inline(always)]
    pub fn view(&self) -> View<'_> {
        let n = self.y.len();
        View {
            y: &self.y[..n],
            z: &self.z[..n],
            vy: &self.vy[..n],
            vz: &self.vz[..n],
            rho: &self.rho[..n],
            vol: &self.vol[..n],
            p: &self.p[..n],
            kind: &self.kind[..n],
        }
    }

    /// Add one particle.
    #[allow(clippy::too_many_arguments)]
    pub fn push(
        &mut self,
        kind: Kind,
        y: f64,
        z: f64,
        vy: f64,
        vz: f64,
        rho: f64,
        p: f64,
        vol: f64,
    ) {
        self.y.push(y);
        self.z.push(z);
        self.vy.push(vy);
        self.vz.push(vz);
        self.rho.push(rho);
        self.kind.push(kind);
        self.mass.push(rho * vol);
        self.vol.push(vol);
        self.p.push(p);
        self.rate.push([0.0; 3]);
        self.grad_rho.push([0.0; 2]);
        self.level.push(0);
    }

    /// Set the resolution level of the particle pushed last.
    pub fn set_last_level(&mut self, level: u8) {
        if let Some(l) = self.level.last_mut() {
            *l = level;
            self.levels |= level > 0;
        }
    }

    /// Whether any particle is coarser than the base spacing.
    pub fn multi_resolution(&self) -> bool {
        self.levels
    }

    /// Number of particles of a kind.
    pub fn count(&self, kind: Kind) -> usize {
        self.kind.iter().filter(|&&k| k == kind).count()
    }

    /// Reorder the state arrays so that new position k holds old particle `order[k]`. Rates and gradients
    /// are recomputed after every sort and are not carried over (volumes are, for the first pass after
    /// the sort).
    /// The pressures of the water and air particles from their densities (`pressure(kind, rho)`), the
    /// dummies' left as they are.
    pub fn update_fluid_pressures(&mut self, pressure: impl Fn(Kind, f64) -> f64 + Sync) {
        use rayon::prelude::*;
        (
            self.p.par_iter_mut(),
            self.rho.par_iter(),
            self.kind.par_iter(),
        )
            .into_par_iter()
            .with_min_len(4096)
            .for_each(|(p, rho, kind)| {
                if kind.is_fluid() {
                    *p = pressure(*kind, *rho);
                }
            });
    }

    pub fn permute(&mut self, order: &[u32]) {
        for a in [
            &mut self.y,
            &mut self.z,
            &mut self.vy,
            &mut self.vz,
            &mut self.rho,
            &mut self.p,
            &mut self.mass,
            &mut self.vol,
        ] {
            gather(a, &mut self.scratch, order);
        }
        gather(&mut self.kind, &mut self.scratch_kind, order);
        if self.levels {
            gather(&mut self.level, &mut self.scratch_level, order);
        }
        if !self.face_outside.is_empty() {
            gather(&mut self.face_outside, &mut self.scratch, order);
        }
    }

    /// Bytes allocated for the particle storage (state, rates, gradients and sort scratch; capacities
    /// counted, not only the lengths in use).
    pub fn bytes(&self) -> usize {
        fn b<T>(v: &Vec<T>) -> usize {
            v.capacity() * std::mem::size_of::<T>()
        }
        [
            &self.y,
            &self.z,
            &self.vy,
            &self.vz,
            &self.rho,
            &self.mass,
            &self.vol,
            &self.p,
            &self.scratch,
            &self.face_outside,
        ]
        .iter()
        .map(|v| b(v))
        .sum::<usize>()
            + b(&self.kind)
            + b(&self.scratch_kind)
            + b(&self.rate)
            + b(&self.grad_rho)
            + b(&self.level)
            + b(&self.scratch_level)
    }
}

/// Permute `a` so that position k holds old element `order[k]`, through `scratch` (swapped in).
fn gather<T: Copy + Default + Send + Sync>(a: &mut Vec<T>, scratch: &mut Vec<T>, order: &[u32]) {
    scratch.resize(a.len(), T::default());
    let src: &Vec<T> = a;
    scratch
        .par_iter_mut()
        .with_min_len(4096)
        .zip(order.par_iter())
        .for_each(|(d, &k)| *d = src[k as usize]);
    std::mem::swap(a, scratch);
}
