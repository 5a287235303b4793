//! `slamtool bench`: SPH throughput on a standard case (30 deg wedge entering at 5 m/s, about 100,000 fluid
//! particles in a half tank of 4 b x 3 b, uniform or refined), a fixed number of time steps; optionally
//! on 1, 2, ... threads in one run (`--threads-scan`) for the thread scaling; with `--air`, the same case
//! with air as a second phase (`slamtool::sph::air`), whose figures count the air particles as fluid.

use clap::{Args, ValueEnum};
use slamtool::provenance::{GIT_COMMIT, TOOL};
use slamtool::sph::{self, MotionSpec, Overrides, Simulation, body::Section, case::Setup};

use super::global::{self, JsonArg};

/// Examples at the end of `slamtool bench --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool bench --plain --steps 50 --particles 20000
  slamtool bench --tank refined --threads-scan --air
  RAYON_NUM_THREADS=1 slamtool bench --json";

/// The tank of the benchmark.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum BenchTank {
    /// One particle spacing everywhere.
    Uniform,
    /// Base spacing in a band around the wedge, twice it beyond.
    Refined,
}

#[derive(Debug, Args)]
pub struct BenchArgs {
    /// Number of time steps to time.
    #[arg(long, default_value_t = 200)]
    steps: u64,
    /// Approximate number of fluid particles (of the uniform tank; a refined one holds fewer).
    #[arg(long, default_value_t = 100_000)]
    particles: u64,
    /// Uniform or refined tank.
    #[arg(long, value_enum, default_value_t = BenchTank::Uniform)]
    tank: BenchTank,
    /// Time the run on 1, 2, ... up to the available threads (each in its own thread pool) and report
    /// the speed-up over 1 thread.
    #[arg(long)]
    threads_scan: bool,
    /// The same case with air as a second phase (a layer over the water around the wedge): the
    /// two-phase passes, whose particle-steps count the air particles as fluid.
    #[arg(long)]
    air: bool,
    /// The plain scheme: no particle shifting, the uncorrected velocity divergence and an unweighted
    /// body wall, the default before the wall-resolved scheme (whose three passes a run with air does
    /// not take either); for figures comparable with earlier ones.
    #[arg(long)]
    plain: bool,
    #[command(flatten)]
    json: JsonArg,
}

/// The figures of one timed run.
struct Timing {
    threads: usize,
    n_fluid: usize,
    n_all: usize,
    secs: f64,
    /// Fluid particle-steps made: every water and air particle once a step, and the air once more in
    /// each further substep of a run with air.
    fluid_steps: f64,
    /// Simulated time covered (s).
    simulated_s: f64,
    interactions: u64,
    bytes_per_particle: usize,
    stages: serde_json::Value,
    untimed_s: f64,
    dp: f64,
    c0: f64,
    fz: f64,
}

fn setup(a: &BenchArgs) -> slamtool::Result<Setup> {
    let b = 0.25;
    let beta = 30f64.to_radians();
    let section = Section::wedge(beta, b, 1.5 * b * beta.tan())?;
    // Half tank of 4 b x 3 b: 12 (b/dp)^2 fluid particles at the base spacing.
    let n_half = (a.particles as f64 / 12.0).sqrt();
    sph::case::resolve(
        "bench_wedge30_5ms",
        &section,
        &MotionSpec::Constant { speed_m_s: 5.0 },
        Vec::new(),
        &Overrides {
            particles_per_half_beam: Some(n_half),
            // Fixed tank (the automatic one grows with c0 t_end), so the particle count is as stated.
            tank_half_width: Some(4.0 * b),
            tank_depth: Some(3.0 * b),
            refinement: Some(a.tank == BenchTank::Refined),
            air: Some(if a.air {
                sph::air::AirChoice::On
            } else {
                sph::air::AirChoice::Off
            }),
            shifting: a.plain.then_some(false),
            divergence_correction: a.plain.then_some(false),
            wall_wetness: a.plain.then_some(false),
            ..Default::default()
        },
    )
}

/// The numerical scheme a resolved benchmark case runs, in words (read from its setup, which applies the
/// defaults, `--plain` and the rule for runs with air).
fn scheme(s: &Setup) -> String {
    let on = |b: bool| if b { "on" } else { "off" };
    format!(
        "shifting {}, corrected divergence {}, wall wetness {}",
        on(s.shifting),
        on(s.divergence_correction),
        on(s.wall_wetness)
    )
}

/// Build the case and time `steps` steps on the current thread pool.
fn time_run(setup: Setup, steps: u64) -> slamtool::Result<Timing> {
    let mut sim = Simulation::new(setup)?;
    let n_fluid = sim.n_fluid() + sim.n_air();
    let n_all = sim.pt.len();
    let c0 = sim.counters.clone();
    let time0 = sim.time;
    let t0 = std::time::Instant::now();
    // On a thread of rayon's pool, as `sph::run` steps a run.
    rayon::scope(|_| -> slamtool::Result<()> {
        for _ in 0..steps {
            sim.step().map_err(|e| sim.failure(&e))?;
        }
        Ok(())
    })?;
    let secs = t0.elapsed().as_secs_f64();
    let c = &sim.counters;
    let stages = serde_json::json!({
        "sort": c.sort_s - c0.sort_s, "boundary": c.boundary_s - c0.boundary_s,
        "continuity": c.continuity_s - c0.continuity_s, "momentum": c.momentum_s - c0.momentum_s,
        "integrate": c.integrate_s - c0.integrate_s, "sensors": c.sensors_s - c0.sensors_s,
        "output": c.output_s - c0.output_s,
    });
    // the counters count every particle once a step (dummies included) and the air's substeps
    let dummies = (n_all - n_fluid) as f64 * (c.steps - c0.steps) as f64;
    Ok(Timing {
        threads: rayon::current_num_threads(),
        n_fluid,
        n_all,
        secs,
        fluid_steps: (c.particle_steps - c0.particle_steps) as f64 - dummies,
        simulated_s: sim.time - time0,
        interactions: c.interactions - c0.interactions,
        bytes_per_particle: sim.bytes_per_particle(),
        stages,
        untimed_s: secs - (c.total_s() - c0.total_s()),
        dp: sim.setup.dp,
        c0: sim.setup.c0,
        fz: sim.body.fz,
    })
}

pub fn run(a: BenchArgs) -> slamtool::Result<()> {
    if a.particles < 1000 || a.steps == 0 {
        return Err(slamtool::Error::Invalid(
            "--particles must be at least 1000 and --steps at least 1".into(),
        ));
    }
    let tank = match a.tank {
        BenchTank::Uniform => "uniform",
        BenchTank::Refined => "refined",
    };
    let available = rayon::current_num_threads();
    let counts: Vec<usize> = if a.threads_scan {
        (1..=available).collect()
    } else {
        vec![available]
    };
    let mut runs = Vec::new();
    let mut scheme_text = String::new();
    for &n in &counts {
        global::note(&format!(
            "timing {} steps of a 30 deg wedge at 5 m/s ({tank} tank) on {n} thread(s)",
            a.steps
        ));
        let s = setup(&a)?;
        scheme_text = scheme(&s);
        let t = if a.threads_scan {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(n)
                .build()
                .map_err(|e| slamtool::Error::Invalid(format!("thread pool of {n}: {e}")))?;
            pool.install(|| time_run(s, a.steps))?
        } else {
            time_run(s, a.steps)?
        };
        runs.push(t);
    }
    let per_run = |t: &Timing| {
        serde_json::json!({
            "threads": t.threads,
            "seconds": t.secs,
            "fluid_particle_steps_per_s": t.fluid_steps / t.secs,
            "all_particle_steps_per_s": (t.fluid_steps + (t.n_all - t.n_fluid) as f64 * a.steps as f64) / t.secs,
            "simulated_ms_per_wall_s": 1e3 * t.simulated_s / t.secs,
            "neighbour_interactions_per_s": t.interactions as f64 / t.secs,
            "stage_seconds": t.stages,
            "untimed_seconds": t.untimed_s,
            "speed_up_over_1_thread": runs.first().filter(|r| r.threads == 1).map(|r| r.secs / t.secs),
        })
    };
    let last = runs.last().expect("at least one run");
    let mut out = per_run(last);
    let extra = serde_json::json!({
        "tool": TOOL,
        "provenance": {"tool": TOOL, "commit": GIT_COMMIT, "inputs": [], "settings": {"steps": a.steps, "particles": a.particles, "tank": tank, "threads_scan": a.threads_scan, "plain": a.plain}},
        "warnings": [],
        "outputs": null,
        "case": "30 deg wedge, 5 m/s, half tank 4b x 3b, b = 0.25 m",
        "air": a.air,
        "scheme": scheme_text,
        "tank": tank,
        "steps": a.steps,
        "fluid_particles": last.n_fluid,
        "all_particles": last.n_all,
        "dp_m": last.dp,
        "c0_m_per_s": last.c0,
        "interactions_per_fluid_particle": last.interactions as f64 / (a.steps as f64 * last.n_fluid as f64),
        "bytes_per_particle": last.bytes_per_particle,
        "final_force_n_per_m": last.fz,
        "thread_scan": runs.iter().map(per_run).collect::<Vec<_>>(),
    });
    if let (Some(o), Some(e)) = (out.as_object_mut(), extra.as_object()) {
        o.extend(e.clone());
    }
    if a.json.json {
        global::print_json(out);
        return Ok(());
    }
    println!(
        "case                      30 deg wedge at 5 m/s, {tank} tank{}, {} steps",
        if a.air { ", with air" } else { "" },
        a.steps
    );
    println!("scheme                    {scheme_text}");
    println!(
        "particles                 {} fluid{}, {} with wall and body dummies",
        last.n_fluid,
        if a.air { " (water and air)" } else { "" },
        last.n_all
    );
    println!("bytes per particle        {}", last.bytes_per_particle);
    for t in &runs {
        let o = per_run(t);
        println!("threads                   {}", t.threads);
        println!("  time                      {:.2} s", t.secs);
        for (label, key) in [
            ("fluid particle-steps/s", "fluid_particle_steps_per_s"),
            ("all particle-steps/s", "all_particle_steps_per_s"),
            ("neighbour interactions/s", "neighbour_interactions_per_s"),
            ("simulated ms per wall s", "simulated_ms_per_wall_s"),
        ] {
            println!("  {label:<26}{:.3e}", o[key].as_f64().unwrap_or(f64::NAN));
        }
        if let Some(s) = o["speed_up_over_1_thread"].as_f64() {
            println!("  speed-up over 1 thread    {s:.2}");
        }
        println!(
            "  stage seconds             {} (untimed {:.3})",
            t.stages, t.untimed_s
        );
    }
    Ok(())
}
