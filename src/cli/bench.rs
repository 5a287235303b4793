//! `slamtool bench`: SPH throughput on a standard case (30 deg wedge entering at 5 m/s, about 100,000 fluid
//! particles in a half tank), a fixed number of time steps.

use clap::Args;
use slamtool::provenance::{GIT_COMMIT, TOOL};
use slamtool::sph::{self, MotionSpec, Overrides, Simulation, body::Section};

use super::global::{self, JsonArg};

/// Examples at the end of `slamtool bench --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool bench
  slamtool bench --steps 50 --particles 20000
  RAYON_NUM_THREADS=1 slamtool bench --json";

#[derive(Debug, Args)]
pub struct BenchArgs {
    /// Number of time steps to time.
    #[arg(long, default_value_t = 200)]
    steps: u64,
    /// Approximate number of fluid particles.
    #[arg(long, default_value_t = 100_000)]
    particles: u64,
    #[command(flatten)]
    json: JsonArg,
}

pub fn run(a: BenchArgs) -> slamtool::Result<()> {
    if a.particles < 1000 || a.steps == 0 {
        return Err(slamtool::Error::Invalid(
            "--particles must be at least 1000 and --steps at least 1".into(),
        ));
    }
    let b = 0.25;
    let beta = 30f64.to_radians();
    let section = Section::wedge(beta, b, 1.5 * b * beta.tan())?;
    // Half tank of 4 b x 3 b: 12 (b/dp)^2 fluid particles.
    let n_half = (a.particles as f64 / 12.0).sqrt();
    let setup = sph::case::resolve(
        "bench_wedge30_5ms",
        &section,
        &MotionSpec::Constant { speed_m_s: 5.0 },
        Vec::new(),
        &Overrides {
            particles_per_half_beam: Some(n_half),
            // Fixed tank (the automatic one grows with c0 t_end), so the particle count is as stated.
            tank_half_width: Some(4.0 * b),
            tank_depth: Some(3.0 * b),
            ..Default::default()
        },
    )?;
    global::note(&format!(
        "timing {} steps of a 30 deg wedge at 5 m/s on {} thread(s)",
        a.steps,
        rayon::current_num_threads()
    ));
    let mut sim = Simulation::new(setup)?;
    let n_fluid = sim.n_fluid();
    let n_all = sim.pt.len();
    let c_setup = sim.counters.clone();
    let t0 = std::time::Instant::now();
    for _ in 0..a.steps {
        sim.step().map_err(|e| sim.failure(&e))?;
    }
    let secs = t0.elapsed().as_secs_f64();
    let mut c = sim.counters.clone();
    c.interactions -= c_setup.interactions;
    let threads = rayon::current_num_threads();
    let out = serde_json::json!({
        "tool": TOOL,
        "provenance": {"tool": TOOL, "commit": GIT_COMMIT, "inputs": [], "settings": {"steps": a.steps, "particles": a.particles}},
        "warnings": [],
        "outputs": null,
        "case": "30 deg wedge, 5 m/s, half tank 4b x 3b, b = 0.25 m",
        "threads": threads,
        "steps": a.steps,
        "fluid_particles": n_fluid,
        "all_particles": n_all,
        "dp_m": sim.setup.dp,
        "c0_m_per_s": sim.setup.c0,
        "seconds": secs,
        "fluid_particle_steps_per_s": n_fluid as f64 * a.steps as f64 / secs,
        "all_particle_steps_per_s": n_all as f64 * a.steps as f64 / secs,
        "neighbour_interactions_per_s": c.interactions as f64 / secs,
        "interactions_per_fluid_particle": c.interactions as f64 / (a.steps as f64 * n_fluid as f64),
        "bytes_per_particle": sim.bytes_per_particle(),
        "stage_seconds": {
            "sort": c.sort_s - c_setup.sort_s, "boundary": c.boundary_s - c_setup.boundary_s,
            "continuity": c.continuity_s - c_setup.continuity_s, "momentum": c.momentum_s - c_setup.momentum_s,
            "integrate": c.integrate_s - c_setup.integrate_s, "sensors": c.sensors_s - c_setup.sensors_s,
        },
        "final_force_n_per_m": sim.body.fz,
    });
    if a.json.json {
        global::print_json(out);
    } else {
        println!(
            "case                      30 deg wedge at 5 m/s, {a_steps} steps",
            a_steps = a.steps
        );
        println!("threads                   {threads}");
        println!("particles                 {n_fluid} fluid, {n_all} with wall and body dummies");
        println!("time                      {secs:.2} s");
        println!(
            "fluid particle-steps/s    {:.3e}",
            out["fluid_particle_steps_per_s"].as_f64().unwrap()
        );
        println!(
            "all particle-steps/s      {:.3e}",
            out["all_particle_steps_per_s"].as_f64().unwrap()
        );
        println!(
            "neighbour interactions/s  {:.3e}",
            out["neighbour_interactions_per_s"].as_f64().unwrap()
        );
        println!("bytes per particle        {}", sim.bytes_per_particle());
        println!("stage seconds             {}", out["stage_seconds"]);
    }
    Ok(())
}
