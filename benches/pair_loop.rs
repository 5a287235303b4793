//! The pair loops of the SPH solver (momentum pass with the neighbour search, continuity pass) on the
//! `slamtool bench` case, for profiling: `cargo bench --bench pair_loop`. A benchmark, not a test.

use slamtool::sph::{self, MotionSpec, Overrides, Simulation, body::Section};

fn main() {
    divan::main();
}

/// The `slamtool bench` case (30 deg wedge at 5 m/s, half tank 4 b x 3 b) with about `n` fluid particles.
fn simulation(n: u64) -> Simulation {
    let b = 0.25;
    let beta = 30f64.to_radians();
    let section = Section::wedge(beta, b, 1.5 * b * beta.tan()).expect("wedge");
    let setup = sph::case::resolve(
        "bench_wedge30_5ms",
        &section,
        &MotionSpec::Constant { speed_m_s: 5.0 },
        Vec::new(),
        &Overrides {
            particles_per_half_beam: Some((n as f64 / 12.0).sqrt()),
            tank_half_width: Some(4.0 * b),
            tank_depth: Some(3.0 * b),
            refinement: Some(false),
            ..Default::default()
        },
    )
    .expect("bench case");
    let mut sim = Simulation::new(setup).expect("simulation");
    // A few steps, so that the flow around the wedge has started.
    for _ in 0..5 {
        sim.step().expect("step");
    }
    sim
}

/// Both pair passes at a fixed state.
#[divan::bench(args = [20_000, 100_000], sample_count = 10)]
fn pair_passes(bencher: divan::Bencher, n: u64) {
    let mut sim = simulation(n);
    bencher.bench_local(|| sim.evaluate_pair_passes());
}

/// One whole time step (sort, boundary, both passes, integration, sensors).
#[divan::bench(args = [20_000], sample_count = 10)]
fn time_step(bencher: divan::Bencher, n: u64) {
    let mut sim = simulation(n);
    bencher.bench_local(|| sim.step().expect("step"));
}
