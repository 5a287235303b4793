//! Stage timers: wall-clock time spent in each stage of the time step, for the benchmark and the run log.

use std::time::{Duration, Instant};

use serde::Serialize;

/// The stages of one time step.
#[derive(Debug, Clone, Copy)]
pub enum Stage {
    Sort,
    Boundary,
    Continuity,
    Momentum,
    Integrate,
    Sensors,
    Output,
}

/// Accumulated time per stage (s) and interaction counts.
#[derive(Debug, Clone, Default, Serialize)]
pub struct Counters {
    pub sort_s: f64,
    pub boundary_s: f64,
    pub continuity_s: f64,
    pub momentum_s: f64,
    pub integrate_s: f64,
    pub sensors_s: f64,
    pub output_s: f64,
    pub steps: u64,
    pub particle_steps: u64,
    /// Fluid-particle pair interactions evaluated in the momentum pass (within the kernel support).
    pub interactions: u64,
    /// Fluid particles moved back out of the body by the wall collision
    /// ([`crate::sph::boundary::kruisbrink2018`]), summed over the run.
    pub contact_corrections: u64,
}

impl Counters {
    pub fn add(&mut self, stage: Stage, d: Duration) {
        let s = d.as_secs_f64();
        match stage {
            Stage::Sort => self.sort_s += s,
            Stage::Boundary => self.boundary_s += s,
            Stage::Continuity => self.continuity_s += s,
            Stage::Momentum => self.momentum_s += s,
            Stage::Integrate => self.integrate_s += s,
            Stage::Sensors => self.sensors_s += s,
            Stage::Output => self.output_s += s,
        }
    }

    /// Time a closure into a stage.
    pub fn time<T>(&mut self, stage: Stage, f: impl FnOnce() -> T) -> T {
        let t0 = Instant::now();
        let r = f();
        self.add(stage, t0.elapsed());
        r
    }

    /// Total of the timed stages (s).
    pub fn total_s(&self) -> f64 {
        self.sort_s
            + self.boundary_s
            + self.continuity_s
            + self.momentum_s
            + self.integrate_s
            + self.sensors_s
            + self.output_s
    }
}
