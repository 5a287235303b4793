//! Kick-drift-kick (velocity-Verlet) time stepping with the density treated like a position, so that the
//! acoustic exchange between density and velocity is a symplectic leapfrog (a scheme that "kicks" density
//! and velocity together from rates at one instant is unstable for the fast acoustic modes):
//!
//! v^{n+1/2} = v^n + dt/2 a(r^n, rho^n)
//! rho^{n+1} = rho^n + dt D(r^n, v^{n+1/2}, rho^n),   r^{n+1} = r^n + dt v^{n+1/2}
//! v^{n+1} = v^{n+1/2} + dt/2 a(r^{n+1}, rho^{n+1})
//!
//! (the artificial viscosity in a uses v^{n+1/2}). Two neighbour passes per step: the continuity pass at
//! r^n and the momentum pass at r^{n+1}. Only the momentum pass searches; it keeps its neighbour lists,
//! which the continuity pass of the next step (at the same positions) reuses.
//!
//! Time step (Monaghan 1992; Antuono et al. 2012): dt = min(C h / (c0 + |v|_max), 0.25 sqrt(h / |a|_max))
//! with the Courant number C 0.4 by default ([`crate::sph::case::DEFAULT_CFL`]; at most 0.5). The viscous
//! limit h / (alpha c0) of the artificial viscosity is far above the acoustic one for alpha < 1 and is not
//! checked.

use rayon::prelude::*;

use crate::sph::particles::{Kind, Particles};

/// Half kick of the fluid velocities (water and air) with the current accelerations.
pub fn kick(pt: &mut Particles, dt: f64) {
    kick_where(pt, dt, Kind::is_fluid);
}

/// [`kick`] of the fluid particles of one phase only (`Kind::Fluid` for the water, `Kind::Air`), for the
/// air's own time step ([`crate::sph::solver`]'s substeps).
pub fn kick_phase(pt: &mut Particles, dt: f64, phase: Kind) {
    kick_where(pt, dt, |k| k == phase);
}

/// Half kick by `dt` of the particles whose kind `moves`.
#[inline(always)]
fn kick_where(pt: &mut Particles, dt: f64, moves: impl Fn(Kind) -> bool + Sync) {
    let hdt = 0.5 * dt;
    (
        pt.vy.par_iter_mut(),
        pt.vz.par_iter_mut(),
        pt.kind.par_iter(),
        pt.rate.par_iter(),
    )
        .into_par_iter()
        .with_min_len(4096)
        .for_each(|(vy, vz, kind, r)| {
            if moves(*kind) {
                *vy += hdt * r[0];
                *vz += hdt * r[1];
            }
        });
}

/// Full step of fluid density (with the continuity rate) and position (with the half-step velocity).
/// With a symmetry plane, a particle that drifts through y = 0 is reflected.
pub fn drift(pt: &mut Particles, dt: f64, mirror: bool) {
    (
        pt.y.par_iter_mut(),
        pt.z.par_iter_mut(),
        pt.vy.par_iter_mut(),
        pt.vz.par_iter(),
        pt.rho.par_iter_mut(),
        pt.kind.par_iter(),
        pt.rate.par_iter(),
    )
        .into_par_iter()
        .with_min_len(4096)
        .for_each(|(y, z, vy, vz, rho, kind, r)| {
            if !kind.is_fluid() {
                return;
            }
            *rho += dt * r[2];
            *y += dt * *vy;
            *z += dt * *vz;
            if mirror && *y < 0.0 {
                *y = -*y;
                *vy = -*vy;
            }
        });
}

/// Move the body dummy particles rigidly by (dy, dz) and give them the body velocity.
pub fn move_body(pt: &mut Particles, dy: f64, dz: f64, vel: [f64; 2]) {
    (
        pt.y.par_iter_mut(),
        pt.z.par_iter_mut(),
        pt.vy.par_iter_mut(),
        pt.vz.par_iter_mut(),
        pt.kind.par_iter(),
    )
        .into_par_iter()
        .with_min_len(4096)
        .for_each(|(y, z, vy, vz, kind)| {
            if *kind == Kind::Body {
                *y += dy;
                *z += dz;
                *vy = vel[0];
                *vz = vel[1];
            }
        });
}

/// Largest fluid (water or air) speed and acceleration magnitude. NaN if any fluid particle has a
/// non-finite state (max is exact, so the result does not depend on the thread count).
pub fn max_speed_accel(pt: &Particles) -> (f64, f64) {
    max_speed_accel_where(pt, Kind::is_fluid)
}

/// [`max_speed_accel`] over the particles of one phase.
pub fn max_speed_accel_of(pt: &Particles, phase: Kind) -> (f64, f64) {
    max_speed_accel_where(pt, |k| k == phase)
}

/// Largest speed and acceleration magnitude of the particles whose kind is `counted`.
#[inline(always)]
fn max_speed_accel_where(pt: &Particles, counted: impl Fn(Kind) -> bool + Sync) -> (f64, f64) {
    let (v2, a2) = (
        pt.vy.par_iter(),
        pt.vz.par_iter(),
        pt.rate.par_iter(),
        pt.kind.par_iter(),
    )
        .into_par_iter()
        .with_min_len(4096)
        .map(|(vy, vz, r, k)| {
            if !counted(*k) {
                return (0.0, 0.0);
            }
            (vy * vy + vz * vz, r[0] * r[0] + r[1] * r[1])
        })
        .reduce(|| (0.0, 0.0), |a, b| (nan_max(a.0, b.0), nan_max(a.1, b.1)));
    (v2.sqrt(), a2.sqrt())
}

/// max that propagates NaN (so a single bad particle is seen).
#[inline]
fn nan_max(a: f64, b: f64) -> f64 {
    if a.is_nan() || b.is_nan() {
        f64::NAN
    } else {
        a.max(b)
    }
}

/// The time step from the acoustic (Courant) and force limits.
pub fn time_step(cfl: f64, h: f64, c0: f64, v_max: f64, a_max: f64) -> f64 {
    let dt_c = cfl * h / (c0 + v_max);
    let dt_f = if a_max > 0.0 {
        0.25 * (h / a_max).sqrt()
    } else {
        f64::INFINITY
    };
    dt_c.min(dt_f)
}

/// The drift of an air substep: the air's positions and densities by `dt` ([`drift`]), and the water's
/// positions alone (its density takes its whole step at once, [`density_step`], while its positions
/// move in the air's substeps).
pub fn drift_air_substep(pt: &mut Particles, dt: f64, mirror: bool) {
    (
        pt.y.par_iter_mut(),
        pt.z.par_iter_mut(),
        pt.vy.par_iter_mut(),
        pt.vz.par_iter(),
        pt.rho.par_iter_mut(),
        pt.kind.par_iter(),
        pt.rate.par_iter(),
    )
        .into_par_iter()
        .with_min_len(4096)
        .for_each(|(y, z, vy, vz, rho, kind, r)| {
            match kind {
                Kind::Air => *rho += dt * r[2],
                Kind::Fluid => {}
                _ => return,
            }
            *y += dt * *vy;
            *z += dt * *vz;
            if mirror && *y < 0.0 {
                *y = -*y;
                *vy = -*vy;
            }
        });
}

/// The density step of one phase alone (`rho += dt rate[2]`), the positions left where they are.
pub fn density_step(pt: &mut Particles, dt: f64, phase: Kind) {
    (
        pt.rho.par_iter_mut(),
        pt.kind.par_iter(),
        pt.rate.par_iter(),
    )
        .into_par_iter()
        .with_min_len(4096)
        .for_each(|(rho, kind, r)| {
            if *kind == phase {
                *rho += dt * r[2];
            }
        });
}
