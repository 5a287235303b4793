//! The time step of a run with air: the water takes the step its own sound speed allows and the air
//! takes k substeps inside it with the step the air's sound speed allows (multiple time stepping, in the
//! manner of the reversible reference-system propagator of Tuckerman, Berne & Martyna 1992, J. Chem.
//! Phys. 97: 1990-2001).
//!
//! Why: the air's sound speed (343 m/s) is 2-6 times the water's artificial c0 of a slow entry, and with
//! one shared step the whole tank, water included, took the air's step, so a run with air cost 4.5-6.6
//! times its water-only run (docs/guide/air.md). The air is a thin layer, a sixth of the particles of
//! an Ochi section's run, so stepping it alone at its own rate is cheap.
//!
//! One water step Δ = k δ, with Δ = C h / (c0 + |u_w|max) (or the force limit) and δ ≤ C h / (c_a +
//! |u_a|max), k the smallest integer that makes δ fit:
//!
//! 1. half kick of the water with Δ and of the air with δ, from the rates of the last full pass;
//! 2. the continuity pass of both phases at r^n; the water's density takes its whole step, ρ_w^{n+1} =
//!    ρ_w^n + Δ D_w (for the water the air is a free surface, so its density rate does not depend on the
//!    air's state within the step);
//! 3. k substeps: the air drifts by δ (position and density); the water's positions drift by δ at their
//!    half-step velocity, exactly as one drift by Δ would move them, and the body by δ at its
//!    half-step velocity; between substeps the air alone is kicked (δ), with its pair terms against
//!    water, air, walls and body at the substep's positions (the air's rows of
//!    [`crate::sph::two_phase_pass`] with [`Rows::AirOnly`]), and its continuity is evaluated;
//! 4. the full pass at r^{n+1} (every particle, the body force and the sensors), and the second half
//!    kicks: Δ for the water and δ for the air.
//!
//! So within a water step the air sees the water and the body move at their half-step velocities, and
//! the water sees the air's pressure at the step's ends, as in the single-rate scheme. The histories are
//! sampled once a water step. Every sum is the gather of one particle over its list, as in every other
//! pass, so the run stays bit-identical on any thread count.

use std::time::Instant;

use super::Simulation;
use crate::sph::counters::Stage;
use crate::sph::integrator;
use crate::sph::particles::Kind;
use crate::sph::two_phase_pass::{self, Rows};

/// At most this many air substeps a water step: beyond it the air's time step has collapsed and the
/// run stops with the diagnostic of a collapsed step.
const MAX_SUBSTEPS: f64 = 1000.0;

impl Simulation {
    /// One water step of a run with air, with the air's substeps (see the module doc).
    pub(super) fn step_with_air_substeps(&mut self) -> Result<(), String> {
        let air = self.air.expect("air substeps in a run without air");
        let h = self.kernel.h();
        let (v_w, a_w) = integrator::max_speed_accel_of(&self.pt, Kind::Fluid);
        let (v_a, a_a) = integrator::max_speed_accel_of(&self.pt, Kind::Air);
        if ![v_w, a_w, v_a, a_a].iter().all(|x| x.is_finite()) {
            return Err(self.nan_diagnostic());
        }
        let v_body = self.body.v_down.abs();
        let cfl = self.setup.cfl;
        let dt_water = integrator::time_step(cfl, h, self.setup.c0, v_w.max(v_body), a_w);
        let dt_air = integrator::time_step(cfl, h, air.c, v_a.max(v_body), a_a);
        let k = (dt_water / dt_air).ceil().clamp(1.0, MAX_SUBSTEPS);
        let dt = dt_water.min(k * dt_air);
        let sub = dt / k;
        if sub < 1e-3 * self.dt_first {
            return Err(self.collapse_diagnostic(sub, v_w.max(v_a), a_w.max(a_a)));
        }
        let k = k as usize;
        self.dt = dt;
        let (t_start, t_mid, t_new) = (self.time, self.time + 0.5 * dt, self.time + dt);
        let t0 = Instant::now();
        integrator::kick_phase(&mut self.pt, dt, Kind::Fluid);
        integrator::kick_phase(&mut self.pt, sub, Kind::Air);
        let v_half = self.body_half_step_speed(t_mid, dt);
        if self.motion.is_some() {
            integrator::move_body(&mut self.pt, 0.0, 0.0, [0.0, -v_half]);
        }
        self.counters.add(Stage::Integrate, t0.elapsed());
        self.evaluate_continuity();
        integrator::density_step(&mut self.pt, dt, Kind::Fluid);
        let mirror = self.setup.mirror;
        for s in 1..=k {
            let t0 = Instant::now();
            integrator::drift_air_substep(&mut self.pt, sub, mirror);
            self.time = t_start + s as f64 * sub;
            if self.motion.is_some() {
                self.body.z_keel -= sub * v_half;
                integrator::move_body(&mut self.pt, 0.0, -sub * v_half, [0.0, -v_half]);
                self.collide_with_body(v_half)?;
            }
            self.counters.add(Stage::Integrate, t0.elapsed());
            if s < k {
                self.sort();
                self.air_substep(sub);
            }
        }
        let t0 = Instant::now();
        self.damping
            .apply(&mut self.pt, dt, &self.eos, self.setup.g);
        self.lists_fresh = false;
        if let Some(a) = self.motion.as_ref().and_then(|m| m.accel_at(t_new)) {
            self.body.a_down = a;
        }
        self.time = t_new;
        self.counters.add(Stage::Integrate, t0.elapsed());
        self.sort();
        self.evaluate_momentum();
        self.sample_body();
        let t0 = Instant::now();
        integrator::kick_phase(&mut self.pt, dt, Kind::Fluid);
        integrator::kick_phase(&mut self.pt, sub, Kind::Air);
        self.update_body_speed(v_half, dt, t_new);
        self.counters.add(Stage::Integrate, t0.elapsed());
        self.steps += 1;
        self.counters.steps += 1;
        self.counters.particle_steps += (self.pt.len() + (k - 1) * self.n_air()) as u64;
        self.record();
        Ok(())
    }

    /// Between two air substeps: the pressures from the densities, the air's accelerations at the
    /// substep's positions, its kick by `sub` (the second half of this substep's and the first half of
    /// the next one's) and its density rates for the next drift.
    fn air_substep(&mut self, sub: f64) {
        let air = self.air.expect("air substeps in a run without air");
        let t0 = Instant::now();
        let eos = self.eos;
        self.pt.update_fluid_pressures(|kind, rho| match kind {
            Kind::Air => air.pressure(rho),
            _ => eos.pressure(rho),
        });
        self.counters.add(Stage::Boundary, t0.elapsed());
        let (grid, kernel, s) = (&self.grid, &self.kernel, &self.setup);
        let (pt, lists) = (&mut self.pt, &mut self.lists);
        let n = self.counters.time(Stage::Momentum, || {
            two_phase_pass::momentum_rates(grid, lists, pt, kernel, s, &air, Rows::AirOnly)
        });
        self.counters.interactions += n;
        let t0 = Instant::now();
        integrator::kick_phase(&mut self.pt, 2.0 * sub, Kind::Air);
        self.counters.add(Stage::Integrate, t0.elapsed());
        let (lists, pt) = (&self.lists, &mut self.pt);
        self.counters.time(Stage::Continuity, || {
            two_phase_pass::continuity_rates(lists, pt, s, &air, Rows::AirOnly)
        });
    }
}
