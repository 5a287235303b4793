//! What a run will cost, told before it starts: particles, time steps, particle-steps and an estimated
//! wall time, with a bound above which a run is refused unless the user insists.

use serde::Serialize;

use crate::error::{Error, Result};
use crate::sph::case::Setup;
use crate::sph::study::StudyPlan;

/// Fluid particle-steps per second and per thread assumed for the estimate: the throughput measured on
/// the shared 2-core development machine in real hull-section runs with their companions (2.8-3.1 M/s on
/// two threads: the Ochi and car-carrier assessments; `slamtool bench` gave 3.0 M/s on two threads the
/// same day). It was 2 M/s per thread, which made the estimates about 30 % short.
pub const PARTICLE_STEPS_PER_THREAD_S: f64 = 1.4e6;

/// Cost of a fluid particle-step of a refined tank ([`crate::sph::refinement`]) relative to one of a
/// uniform tank, counted into the estimate: coarse particles scan 9 rows of the fine cell grid, and the
/// body's dummies and the per-step grid work weigh more among fewer water particles. Measured on the
/// 2-core machine: 1.28 on the Ochi 0.093 Lpp station at 1.5 m/s (41.5 s for 63,600 water particles
/// uniform, 19.0 s for 22,800 refined) before the search kept each pair within its own support (3-4 %
/// faster since); 1.05 over the whole Ochi `--fidelity sph` assessment after it (1.43e9 particle-steps
/// in 538 s on two threads). The value lies between the two, on the long side.
pub const REFINED_COST: f64 = 1.15;

/// Cost of a particle-step of a two-phase run ([`crate::sph::air`]) relative to one of water only:
/// `slamtool bench` on the 2-core machine gave 2.32 M particle-steps/s with air against 3.47 M without,
/// the same day (the two-phase pair pass and the air's wall terms).
pub const TWO_PHASE_COST: f64 = 1.5;

/// Estimated wall time above which a run is refused unless forced (s).
pub const MAX_WALL_S: f64 = 3600.0;

/// The estimated cost of a run with its convergence companions.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Estimate {
    /// Fluid particles of the reported run.
    pub fluid_particles: f64,
    /// Time steps of the reported run.
    pub steps: f64,
    /// Particle-steps of the reported run and its companions together.
    pub particle_steps: f64,
    /// The same in particle-steps of a uniform tank (times [`REFINED_COST`] for a refined one), which
    /// sets the wall time.
    #[serde(skip)]
    pub uniform_equivalent: f64,
    /// Estimated wall time (s) on `threads` threads.
    pub wall_s: f64,
    pub threads: usize,
}

impl Estimate {
    /// One line for the terminal.
    pub fn describe(&self) -> String {
        format!(
            "~{:.0} fluid particles, ~{:.0} steps, estimated wall time {} on {} thread(s)",
            self.fluid_particles,
            self.steps,
            human_time(self.wall_s),
            self.threads
        )
    }
}

/// Estimate the cost of `setup` run with the companions of `plan` on `threads` threads.
pub fn estimate(setup: &Setup, plan: StudyPlan, threads: usize) -> Estimate {
    let sides = if setup.mirror { 1.0 } else { 2.0 };
    let area = setup.tank_half_width * setup.tank_depth;
    // A refined tank has the base spacing in its band only, and 2 dp (a quarter of the particles per
    // area) beyond.
    let fine = setup.refinement.map_or(area, |b| {
        b.half_width.min(setup.tank_half_width) * b.depth.min(setup.tank_depth)
    });
    let water = (fine + 0.25 * (area - fine)) / (setup.dp * setup.dp) * sides;
    // Air: its layer at the base spacing, its own substeps within the water's step (the ratio of the
    // two acoustic limits, [`crate::sph::solver`]), and the approach through the air gap before t = 0.
    let air = setup.air.as_ref();
    let air_particles = air.map_or(0.0, |a| {
        a.half_width.min(setup.tank_half_width) * a.height / (setup.dp * setup.dp) * sides
    });
    let fluid = water + air_particles;
    // A refined run makes fewer particle-steps per second ([`REFINED_COST`]), a two-phase one too
    // ([`TWO_PHASE_COST`]).
    let weight = if setup.refinement.is_some() {
        REFINED_COST
    } else {
        1.0
    } * if air.is_some() { TWO_PHASE_COST } else { 1.0 };
    let v = setup
        .motion
        .as_ref()
        .and_then(|m| m.build().ok())
        .map_or(0.0, |m| m.max_speed(setup.t_end));
    let dt = setup.cfl * setup.h_over_dp * setup.dp / (setup.c0 + 1.5 * v);
    let substeps = air.map_or(1.0, |a| {
        ((a.phase().c + 1.5 * v) / (setup.c0 + 1.5 * v)).ceil()
    });
    let approach = match air {
        Some(a) if v > 0.0 => a.clearance / v,
        _ => 0.0,
    };
    let steps = ((setup.t_end + approach) / dt).ceil();
    // every particle once a step, the air once more in each further substep
    let per_step = fluid + (substeps - 1.0).max(0.0) * air_particles;
    // A companion at r times the spacing has 1/r^2 of the particles and 1/r of the steps.
    let companions: f64 = (1..plan.levels)
        .map(|k| plan.ratio.powi(-3 * k as i32))
        .sum();
    let particle_steps = per_step * steps * (1.0 + companions);
    let threads = threads.max(1);
    Estimate {
        fluid_particles: fluid,
        steps,
        particle_steps,
        uniform_equivalent: weight * particle_steps,
        wall_s: wall_time(weight * particle_steps, threads),
        threads,
    }
}

/// Estimated wall time (s) of `particle_steps` fluid particle-steps on `threads` threads, at
/// [`PARTICLE_STEPS_PER_THREAD_S`].
pub fn wall_time(particle_steps: f64, threads: usize) -> f64 {
    particle_steps / (PARTICLE_STEPS_PER_THREAD_S * threads.max(1) as f64)
}

/// Refuse a run whose estimate exceeds [`MAX_WALL_S`], unless `force`.
pub fn check(e: &Estimate, force: bool) -> Result<()> {
    if e.wall_s > MAX_WALL_S && !force {
        return Err(Error::Invalid(format!(
            "this run would take about {} ({}): more than the {} bound. Choose a coarser resolution, a \
             shorter t_end or a smaller tank, or give --force to run it anyway",
            human_time(e.wall_s),
            e.describe(),
            human_time(MAX_WALL_S)
        )));
    }
    Ok(())
}

/// "42 s", "3.5 min", "2.1 h".
pub fn human_time(s: f64) -> String {
    if s < 90.0 {
        format!("{s:.0} s")
    } else if s < 5400.0 {
        format!("{:.1} min", s / 60.0)
    } else {
        format!("{:.1} h", s / 3600.0)
    }
}
