//! The weakly compressible SPH solver: builds the particles of a [`Setup`], advances them in time and
//! records the body motion, the section force and the sensor pressures every step.
//!
//! Equations (2D, per fluid particle i, sums over neighbours j including wall/body dummies and, with a
//! symmetry plane, mirror images; V_j = m / rho_j, grad_i W_ij from the Wendland C2 kernel):
//!
//! * continuity with delta-SPH diffusion (Antuono et al. 2010):
//!   D rho_i / Dt = rho_i sum_j (v_i - v_j) . grad_i W_ij V_j + delta h c0 sum_j psi_ij . grad_i W_ij V_j
//! * momentum (Antuono et al. 2010, eq. 2.2 with the artificial viscosity of Monaghan 1992 between fluid
//!   particles; free slip at the walls):
//!   D v_i / Dt = -sum_j (p_i + p_j)/rho_i grad_i W_ij V_j
//!   + alpha h c0 rho0/rho_i sum_j pi_ij grad_i W_ij V_j + g;
//! * artificial viscosity kernel: pi_ij = (v_i - v_j) . (r_i - r_j) / (|r_ij|^2 + 0.01 h^2);
//! * equation of state: [`crate::sph::eos`]; wall pressure: [`crate::sph::boundary::adami2012`].
//!
//! The above is the `riemann = false` scheme. By default (`riemann = true`) the pressure sum p_i + p_j
//! becomes 2 P* and the delta-SPH term the Riemann density dissipation of [`crate::sph::riemann`], without
//! artificial viscosity. Optional particle shifting after each drift: [`crate::sph::shifting`]. Section
//! force: the wall-normal part of the fluid-body pair forces ([`crate::sph::body_force`], default), all of
//! the pair forces, or the contour integral of the
//! extrapolated wall pressure; the contour pressure always uses the extrapolated pressure, the sensors
//! either that (default) or the pair forces on their panel ([`crate::sph::sensors`]).
//!
//! Every sum is a gather over the neighbours of one particle in the fixed cell-sorted order, so the
//! results are bit-identical on any number of threads.

use rayon::prelude::*;

use crate::error::{Error, Result};
use crate::sph::air::AirPhase;
use crate::sph::body::{self, ContourPoint, Motion, Section};
use crate::sph::body_force;
use crate::sph::boundary::{adami2012, kruisbrink2018};
use crate::sph::case::{ForceMethod, SensorMethod, Setup};
use crate::sph::counters::{Counters, Stage};
use crate::sph::damping_zone::DampingZone;
use crate::sph::dummy_band;
use crate::sph::eos::Eos;
use crate::sph::integrator;
use crate::sph::kernel::WendlandC2;
use crate::sph::neighbours::{Grid, NeighbourLists};
use crate::sph::particles::{Kind, Particles};
use crate::sph::rates::{continuity_rates, momentum_rates};
use crate::sph::refinement::{self, PairKernels};
use crate::sph::sensors::{History, SensorSet};
use crate::sph::shifting::Shifting;
use crate::sph::tank::Tank;
use crate::sph::two_phase_pass::{self, Rows};
use crate::sph::wall_wetness;

mod air_substeps;

/// Fraction of full support (Shepard sum of a fully wetted flat wall is about 1/2) below which a wall
/// point counts as dry and gets zero pressure.
pub const DRY_SHEPARD: f64 = 0.1;

/// The state of the rigid body (heave only).
#[derive(Debug, Clone, Copy, Default)]
pub struct BodyState {
    /// z of the keel in the water-entry frame (m); at t = 0, 0 (keel entry) or -d0 (a section immersed
    /// at the start, [`Setup::initial_immersion`]); negative once immersed.
    pub z_keel: f64,
    /// Downward speed (m/s).
    pub v_down: f64,
    /// Downward acceleration (m/s^2).
    pub a_down: f64,
    /// Upward water force on the whole section (N/m).
    pub fz: f64,
    /// Horizontal (+y) water force on the whole section (N/m); zero by construction with a symmetry plane.
    pub fy: f64,
    /// Horizontal (+y) water force on the starboard half (N/m).
    pub fy_starboard: f64,
    /// Largest wall pressure over the contour samples (Pa) and its arc length from the keel (m).
    pub p_contour_max: f64,
    pub s_at_p_max: f64,
}

/// A running simulation.
pub struct Simulation {
    pub setup: Setup,
    pub kernel: WendlandC2,
    pub eos: Eos,
    /// The air of a two-phase run ([`crate::sph::air`]).
    pub air: Option<AirPhase>,
    /// The number of air particles (fixed once the tank is filled: no particle changes its kind).
    n_air: usize,
    /// Volume of a dummy particle, dp^2 (m^2).
    pub dummy_vol: f64,
    pub pt: Particles,
    grid: Grid,
    /// Neighbour lists of the last momentum pass, reused by the next continuity pass.
    lists: NeighbourLists,
    /// Whether the last momentum pass ran at the current positions and storage order and no continuity
    /// pass has used it yet (its lists and dissipation sums are those of the current state).
    lists_fresh: bool,
    section: Option<Section>,
    motion: Option<Motion>,
    contour: Vec<ContourPoint>,
    contour_p: Vec<f64>,
    /// The closed section contour (body frame), for the check that no fluid went through the body.
    closed_contour: Vec<[f64; 2]>,
    sensors: SensorSet,
    /// Partial sums of the body forces (reused every step).
    force_scratch: body_force::ForceScratch,
    /// Contour normals for the wall-normal section force.
    wall_normals: body_force::WallNormals,
    shifting: Shifting,
    /// The absorbing layer along the tank walls and bottom.
    damping: DampingZone,
    pub body: BodyState,
    pub time: f64,
    pub dt: f64,
    dt_first: f64,
    pub steps: u64,
    pub counters: Counters,
    pub history: History,
}

impl Simulation {
    /// Build the particles and the neighbour grid of a resolved case and evaluate the initial rates.
    pub fn new(setup: Setup) -> Result<Self> {
        let dp = setup.dp;
        let h = setup.h_over_dp * dp;
        let kernel = WendlandC2::new(h);
        let eos = Eos {
            kind: setup.eos,
            rho0: setup.rho0,
            c0: setup.c0,
        };
        let layers = (kernel.support() / dp).ceil() as usize;
        let mirror = setup.mirror;
        let section = match &setup.section_points {
            Some(p) => Some(Section::from_half_points(p.clone())?),
            None => None,
        };
        let motion = match &setup.motion {
            Some(m) => Some(m.build()?),
            None => None,
        };
        let tank = Tank {
            half_width: setup.tank_half_width,
            depth: setup.tank_depth,
            wall_height: setup.tank_wall_height,
        };
        let mut pt = Particles::default();
        let d0 = setup.initial_immersion;
        // With air, a keel entry starts with the keel `clearance` above the calm surface, at the time
        // t = -clearance / V0 (t = 0 stays the instant it reaches the calm surface). The keel starts at
        // z = z0.
        let clearance = setup.air.map_or(0.0, |a| a.clearance);
        let z0 = clearance - d0;
        // No water or air inside the body or within dp/2 of its contour (the spacing a fluid particle
        // keeps from a wall), in the body frame (keel at z = z0).
        let outside_body = |y: f64, z: f64| match &section {
            Some(sec) => {
                !sec.contains(y, z - z0)
                    && body::distance_to_polyline(sec.full_contour(), y, z - z0) >= 0.5 * dp
            }
            None => true,
        };
        // The water of a section immersed at the start keeps out of it.
        let keep = |y: f64, z: f64| d0 <= 0.0 || outside_body(y, z);
        match &setup.refinement {
            Some(band) => refinement::fill(
                &mut pt, &tank, band, dp, layers, mirror, &eos, setup.g, &keep,
            ),
            None if d0 > 0.0 => tank.fill_where(&mut pt, dp, layers, mirror, &eos, setup.g, &keep),
            None => tank.fill(&mut pt, dp, layers, mirror, &eos, setup.g),
        }
        let mut body = BodyState {
            z_keel: z0,
            ..BodyState::default()
        };
        let mut t0 = 0.0;
        let mut contour = Vec::new();
        if let (Some(sec), Some(mot)) = (&section, &motion) {
            let v0 = mot.initial_speed();
            body.v_down = v0;
            body.a_down = mot.accel_at(0.0).unwrap_or(setup.g);
            if clearance > 0.0 {
                if v0.is_nan() || v0 <= 0.0 {
                    return Err(Error::Invalid(format!(
                        "a run with an air gap under the keel needs a downward speed at the start, got {v0} m/s"
                    )));
                }
                t0 = -clearance / v0;
            }
            let y_min = if mirror { 0.25 * dp } else { f64::NEG_INFINITY };
            let band = dummy_band::dummy_points(sec, dp, layers, y_min);
            if setup.wall_wetness {
                pt.face_outside = vec![0.0; pt.len()];
                pt.face_outside
                    .extend(wall_wetness::face_outside(sec, &band, dp, &kernel));
            }
            for p in band {
                pt.push(
                    Kind::Body,
                    p[0],
                    p[1] + z0,
                    0.0,
                    -v0,
                    setup.rho0,
                    0.0,
                    dp * dp,
                );
            }
            contour = body::contour_points(sec, 0.5 * dp, !mirror);
        }
        let air = setup.air.map(|a| a.phase());
        if let Some(layer) = &setup.air {
            fill_air(&mut pt, layer, dp, mirror, setup.g, &outside_body);
        }
        if !pt.face_outside.is_empty() {
            pt.face_outside.resize(pt.len(), 0.0);
        }
        let sensors = SensorSet::new(&setup.sensors, section.as_ref(), dp)?;
        // Wall layers are 2 dp thick each in a refined tank.
        let l = layers as f64 * dp * if setup.refinement.is_some() { 2.0 } else { 1.0 };
        let y0 = if mirror { 0.0 } else { -tank.half_width - l };
        let top = tank
            .wall_height
            .max(section.as_ref().map_or(0.0, |s| s.height()))
            + 2.0 * l;
        let grid = Grid::new(
            y0,
            tank.half_width + l,
            -tank.depth - l,
            top,
            kernel.h(),
            mirror,
        );
        let history = History::new(&sensors, setup.expected_steps());
        let n = contour.len();
        let closed_contour = section.as_ref().map_or(Vec::new(), |s| s.closed_contour());
        let wall_normals = section
            .as_ref()
            .map_or_else(Default::default, body_force::WallNormals::new);
        let mut sim = Self {
            dummy_vol: dp * dp,
            kernel,
            eos,
            air,
            n_air: pt.count(Kind::Air),
            pt,
            grid,
            lists: NeighbourLists::default(),
            lists_fresh: false,
            section,
            motion,
            contour,
            contour_p: vec![0.0; n],
            closed_contour,
            sensors,
            force_scratch: body_force::ForceScratch::default(),
            wall_normals,
            shifting: Shifting::default(),
            damping: DampingZone::new(tank.half_width, tank.depth, setup.damping_zone, setup.c0),
            body,
            time: t0,
            dt: 0.0,
            dt_first: 0.0,
            steps: 0,
            counters: Counters::default(),
            history,
            setup,
        };
        sim.sort();
        sim.evaluate_momentum();
        sim.sample_body();
        sim.record();
        let (v, a) = integrator::max_speed_accel(&sim.pt);
        sim.dt_first = integrator::time_step(
            sim.setup.cfl,
            h,
            sim.sound_speed(),
            v.max(sim.body.v_down.abs()),
            a,
        );
        Ok(sim)
    }

    /// Number of water particles.
    pub fn n_fluid(&self) -> usize {
        self.pt.count(Kind::Fluid)
    }

    /// Number of air particles.
    pub fn n_air(&self) -> usize {
        self.n_air
    }

    /// The largest sound speed of the run's phases: the water's c0, or the air's where it is larger
    /// (the acoustic time-step limit).
    pub fn sound_speed(&self) -> f64 {
        self.air.map_or(self.setup.c0, |a| a.c.max(self.setup.c0))
    }

    /// The section, when there is a body.
    pub fn section(&self) -> Option<&Section> {
        self.section.as_ref()
    }

    fn sort(&mut self) {
        let t0 = std::time::Instant::now();
        let order = self.grid.sort(&self.pt.y, &self.pt.z);
        self.pt.permute(order);
        if self.pt.multi_resolution() {
            self.grid.mark_coarse(&self.pt.level);
        }
        self.lists_fresh = false;
        self.counters.add(Stage::Sort, t0.elapsed());
    }

    /// Body acceleration vector (y, z) in the water-entry frame.
    fn body_accel(&self) -> [f64; 2] {
        [0.0, -self.body.a_down]
    }

    /// Continuity pass at the current positions: density rates (with the density gradients, the
    /// neighbour lists and the Riemann dissipation sums of the last momentum pass, which ran at these
    /// same positions and densities). Once per momentum pass: the pass consumes the dissipation sums the
    /// momentum pass left in the density rates, so a second one without a momentum pass between them is
    /// refused like one after a drift.
    fn evaluate_continuity(&mut self) {
        assert!(
            self.lists_fresh,
            "continuity pass without a momentum pass at the current positions"
        );
        let (lists, kernel) = (&self.lists, &self.kernel);
        let pt = &mut self.pt;
        let s = &self.setup;
        match &self.air {
            Some(air) => self.counters.time(Stage::Continuity, || {
                two_phase_pass::continuity_rates(lists, pt, s, air, Rows::AllFluid)
            }),
            None => self
                .counters
                .time(Stage::Continuity, || continuity_rates(lists, pt, kernel, s)),
        }
        self.lists_fresh = false;
    }

    /// Momentum pass at the current positions: wall and body pressures, then accelerations and the
    /// renormalised density gradients.
    fn evaluate_momentum(&mut self) {
        let (grid, kernel, eos, vol, g) = (
            &self.grid,
            &self.kernel,
            &self.eos,
            self.dummy_vol,
            self.setup.g,
        );
        let acc = [0.0, -self.body.a_down];
        let pt = &mut self.pt;
        let air = self.air.as_ref();
        self.counters.time(Stage::Boundary, || {
            adami2012::update_pressures(grid, pt, kernel, eos, air, vol, g, acc);
            if self.setup.wall_wetness {
                wall_wetness::weight_body_dummies(grid, pt, kernel);
            }
        });
        let s = &self.setup;
        let lists = &mut self.lists;
        let n = self.counters.time(Stage::Momentum, || match air {
            Some(a) => {
                two_phase_pass::momentum_rates(grid, lists, pt, kernel, s, a, Rows::AllFluid)
            }
            None => momentum_rates(grid, lists, pt, kernel, s),
        });
        self.counters.interactions += n;
        self.lists_fresh = true;
    }

    /// The momentum and the continuity pass at the current state, without a time step: the pair loops
    /// alone, for the benchmarks (`benches/pair_loop.rs`). The rates they leave are the ones the state
    /// gives, so a following [`Simulation::step`] is unaffected.
    pub fn evaluate_pair_passes(&mut self) {
        self.evaluate_momentum();
        self.evaluate_continuity();
    }

    /// Wall pressure on the contour and sensors; integrate the section force.
    fn sample_body(&mut self) {
        let t0 = std::time::Instant::now();
        let acc = self.body_accel();
        let zk = self.body.z_keel;
        let (grid, pt, kernel, eos, g) =
            (&self.grid, &self.pt, &self.kernel, &self.eos, self.setup.g);
        let air = self.air.as_ref();
        let pairs = pt.multi_resolution().then(|| PairKernels::new(kernel.h()));
        let sample = |y: f64, z: f64| {
            let (p, shepard) = match &pairs {
                Some(k) => {
                    adami2012::wall_pressure_at_level(grid, pt, k, 0, eos, air, g, y, z, acc)
                }
                None => adami2012::wall_pressure(grid, pt, kernel, eos, air, g, y, z, acc),
            };
            if shepard < DRY_SHEPARD { 0.0 } else { p }
        };
        self.contour_p
            .par_iter_mut()
            .with_min_len(16)
            .zip(self.contour.par_iter())
            .for_each(|(p, c)| *p = sample(c.y, c.z + zk));
        let (mut fy, mut fz, mut fy_s) = (0.0, 0.0, 0.0);
        let (mut p_max, mut s_max) = (0.0, 0.0);
        for (c, &p) in self.contour.iter().zip(&self.contour_p) {
            if p > p_max {
                p_max = p;
                s_max = c.s;
            }
            // Force on the body: -p n ds with n the outward normal.
            fy -= p * c.ny * c.ds;
            fz -= p * c.nz * c.ds;
            if c.y >= 0.0 {
                fy_s -= p * c.ny * c.ds;
            }
        }
        if self.setup.mirror {
            fz *= 2.0;
            fy = 0.0;
        }
        if matches!(
            self.setup.force,
            ForceMethod::PairForces | ForceMethod::NormalPairForces
        ) {
            let s = &self.setup;
            // Heights a fluid neighbour of a body dummy can have: the section, its dummy layers (one
            // kernel support thick) and one kernel support, plus one grid row (h), the spread of the
            // heights within a row of the cell-sorted storage.
            let reach = 2.0 * self.kernel.support() + self.kernel.h();
            let height = self.section.as_ref().map_or(0.0, |x| x.height());
            let z_range = [zk - reach, zk + height + reach];
            [fy, fz] = body_force::interaction_force(
                &self.lists,
                &self.pt,
                s.riemann,
                s.c0,
                self.air.as_ref(),
                s.mirror,
                z_range,
                (s.force == ForceMethod::NormalPairForces).then_some((&self.wall_normals, zk)),
                &mut self.force_scratch,
            );
        }
        self.body.fy = fy;
        self.body.fz = fz;
        self.body.fy_starboard = fy_s;
        self.body.p_contour_max = p_max;
        self.body.s_at_p_max = s_max;
        match self.setup.sensor_method {
            SensorMethod::Interpolated => self.sensors.sample(zk, &sample),
            SensorMethod::ForcePanel => {
                let s = &self.setup;
                let f = body_force::panel_forces(
                    &self.lists,
                    &self.pt,
                    s.riemann,
                    s.c0,
                    self.air.as_ref(),
                    zk,
                    &self.sensors,
                    &mut self.force_scratch,
                );
                self.sensors.set_from_panel_forces(f);
            }
        }
        self.counters.add(Stage::Sensors, t0.elapsed());
    }

    fn record(&mut self) {
        self.history
            .push(self.time, &self.body, self.sensors.values());
    }

    /// Advance one time step. An `Err` describes why the run cannot go on (the state is left as it was at
    /// the failure, for inspection).
    pub fn step(&mut self) -> std::result::Result<(), String> {
        if self.air.is_some() {
            return self.step_with_air_substeps();
        }
        let h = self.kernel.h();
        let (v_max, a_max) = integrator::max_speed_accel(&self.pt);
        if !v_max.is_finite() || !a_max.is_finite() {
            return Err(self.nan_diagnostic());
        }
        let dt = integrator::time_step(
            self.setup.cfl,
            h,
            self.sound_speed(),
            v_max.max(self.body.v_down.abs()),
            a_max,
        );
        if dt < 1e-3 * self.dt_first {
            return Err(self.collapse_diagnostic(dt, v_max, a_max));
        }
        self.dt = dt;
        let t_mid = self.time + 0.5 * dt;
        let t_new = self.time + dt;
        let t0 = std::time::Instant::now();
        integrator::kick(&mut self.pt, dt);
        let v_half = self.body_half_step_speed(t_mid, dt);
        if self.motion.is_some() {
            integrator::move_body(&mut self.pt, 0.0, 0.0, [0.0, -v_half]);
        }
        self.counters.add(Stage::Integrate, t0.elapsed());
        self.evaluate_continuity();
        let t0 = std::time::Instant::now();
        if self.setup.shifting {
            let u_max = v_max.max(self.body.v_down.abs());
            let s = &self.setup;
            self.shifting.compute(
                &self.lists,
                &self.pt,
                &self.kernel,
                s.dp,
                s.cfl * u_max / s.c0,
            );
        }
        integrator::drift(&mut self.pt, dt, self.setup.mirror);
        if self.setup.shifting {
            self.shifting.apply(&mut self.pt, self.setup.mirror);
        }
        self.damping
            .apply(&mut self.pt, dt, &self.eos, self.setup.g);
        self.lists_fresh = false;
        if self.motion.is_some() {
            self.body.z_keel -= dt * v_half;
            integrator::move_body(&mut self.pt, 0.0, -dt * v_half, [0.0, -v_half]);
            if let Some(a) = self.motion.as_ref().and_then(|m| m.accel_at(t_new)) {
                self.body.a_down = a;
            }
            self.collide_with_body(v_half)?;
        }
        self.time = t_new;
        self.counters.add(Stage::Integrate, t0.elapsed());
        self.sort();
        self.evaluate_momentum();
        self.sample_body();
        let t0 = std::time::Instant::now();
        integrator::kick(&mut self.pt, dt);
        self.update_body_speed(v_half, dt, t_new);
        self.counters.add(Stage::Integrate, t0.elapsed());
        self.steps += 1;
        self.counters.steps += 1;
        self.counters.particle_steps += self.pt.len() as u64;
        self.record();
        Ok(())
    }

    /// Why the run stopped when its time step `dt` fell below a thousandth of the first one.
    fn collapse_diagnostic(&self, dt: f64, v_max: f64, a_max: f64) -> String {
        let (at, kind) = self.fastest_fluid_particle();
        format!(
            "time step collapsed to {dt:.3e} s (first step {:.3e} s): largest fluid speed {v_max:.3} m/s, {} \
             particle at (y, z) = ({:.4}, {:.4}) m (keel at z = {:.4} m), largest acceleration {a_max:.3e} m/s^2",
            self.dt_first,
            kind_name(kind),
            at[0],
            at[1],
            self.body.z_keel
        )
    }

    /// The body's downward speed over the step of length `dt` whose middle is `t_mid`: the prescribed
    /// one, or the free body's speed half a step on.
    fn body_half_step_speed(&self, t_mid: f64, dt: f64) -> f64 {
        match &self.motion {
            Some(m) => m
                .speed_at(t_mid)
                .unwrap_or(self.body.v_down + 0.5 * dt * self.body.a_down),
            None => 0.0,
        }
    }

    /// The body's speed at the end of the step (`t_new`), after the force at the new positions: a
    /// free body's from its half-step speed `v_half` and the new acceleration.
    fn update_body_speed(&mut self, v_half: f64, dt: f64, t_new: f64) {
        if let Some(m) = &self.motion {
            match m {
                Motion::FreeHeave { mass_per_m, .. } => {
                    self.body.a_down = self.setup.g - self.body.fz / mass_per_m;
                    self.body.v_down = v_half + 0.5 * dt * self.body.a_down;
                }
                _ => self.body.v_down = m.speed_at(t_new).unwrap_or(v_half),
            }
        }
    }

    /// Run until `t_stop` (or the first failure). `progress` is called every `every` steps.
    pub fn run_until(
        &mut self,
        t_stop: f64,
        every: u64,
        progress: &mut dyn FnMut(&Simulation),
    ) -> std::result::Result<(), String> {
        self.run_until_watching(t_stop, every, progress, &mut |_| {})
    }

    /// [`Simulation::run_until`], with `watch` called after every step (e.g. to keep the state at a peak).
    pub fn run_until_watching(
        &mut self,
        t_stop: f64,
        every: u64,
        progress: &mut dyn FnMut(&Simulation),
        watch: &mut dyn FnMut(&Simulation),
    ) -> std::result::Result<(), String> {
        while self.time < t_stop - 1e-12 {
            self.step()?;
            watch(self);
            if every > 0 && self.steps.is_multiple_of(every) {
                progress(self);
            }
        }
        Ok(())
    }

    /// Position and kind of the fastest fluid particle (the first of equals, in storage order).
    fn fastest_fluid_particle(&self) -> ([f64; 2], Kind) {
        let mut best = (f64::NEG_INFINITY, [0.0; 2], Kind::Fluid);
        for i in 0..self.pt.len() {
            if self.pt.kind[i].is_fluid() {
                let v2 = self.pt.vy[i] * self.pt.vy[i] + self.pt.vz[i] * self.pt.vz[i];
                if v2 > best.0 {
                    best = (v2, [self.pt.y[i], self.pt.z[i]], self.pt.kind[i]);
                }
            }
        }
        (best.1, best.2)
    }

    fn nan_diagnostic(&self) -> String {
        for i in 0..self.pt.len() {
            let bad = [
                self.pt.y[i],
                self.pt.z[i],
                self.pt.vy[i],
                self.pt.vz[i],
                self.pt.rho[i],
            ]
            .iter()
            .any(|v| !v.is_finite());
            if bad || self.pt.rate[i].iter().any(|v| !v.is_finite()) {
                return format!(
                    "non-finite state at t = {:.6} s (step {}): {} particle at (y, z) = ({:.4}, {:.4}) m, \
                     velocity ({:.3}, {:.3}) m/s, density {:.3} kg/m3",
                    self.time,
                    self.steps,
                    kind_name(self.pt.kind[i]),
                    self.pt.y[i],
                    self.pt.z[i],
                    self.pt.vy[i],
                    self.pt.vz[i],
                    self.pt.rho[i]
                );
            }
        }
        format!(
            "non-finite state at t = {:.6} s (step {})",
            self.time, self.steps
        )
    }

    /// Wall collision with the body after the drift ([`kruisbrink2018`]): fluid particles inside the
    /// contour are put back outside. One found deeper than two particle spacings inside is a blow-up, and
    /// the run stops with where it happened.
    fn collide_with_body(&mut self, v_down: f64) -> std::result::Result<(), String> {
        let Some(sec) = &self.section else {
            return Ok(());
        };
        let dp = self.setup.dp;
        let c = kruisbrink2018::resolve(
            &mut self.pt,
            sec,
            &self.closed_contour,
            self.body.z_keel,
            v_down,
            dp,
            self.setup.mirror,
        );
        self.counters.contact_corrections += c.corrected;
        if c.deepest > 2.0 * dp {
            return Err(format!(
                "a fluid particle went {:.2} mm through the body surface in one step at t = {:.6} s, at \
                 (y, z) = ({:.4}, {:.4}) m above the keel (particle spacing {:.2} mm): the flow has blown \
                 up there",
                c.deepest * 1e3,
                self.time,
                c.deepest_at[0],
                c.deepest_at[1],
                dp * 1e3
            ));
        }
        Ok(())
    }

    /// Bytes of storage per particle, everything that grows with the particle count counted at its
    /// allocated capacity: the particle arrays with their sort scratch, the cell grid (cell index, sort
    /// order, cell starts), the neighbour lists (a list start per particle and 4 bytes per neighbour
    /// entry) and the shifting arrays when shifting is on.
    pub fn bytes_per_particle(&self) -> usize {
        let n = self.pt.len().max(1);
        let total =
            self.pt.bytes() + self.grid.bytes() + self.lists.bytes() + self.shifting.bytes();
        total.div_ceil(n)
    }

    /// Wall pressure at a point of a fixed wall (hydrostatic checks).
    pub fn fixed_wall_pressure(&self, y: f64, z: f64) -> f64 {
        adami2012::wall_pressure(
            &self.grid,
            &self.pt,
            &self.kernel,
            &self.eos,
            None,
            self.setup.g,
            y,
            z,
            [0.0; 2],
        )
        .0
    }

    /// The pressure sensors of this run.
    pub fn sensors(&self) -> &SensorSet {
        &self.sensors
    }

    /// An error for a failed run, naming the time and the reason.
    pub fn failure(&self, why: &str) -> Error {
        Error::Numerical(format!("SPH run stopped at t = {:.6} s: {why}", self.time))
    }
}

/// What a particle of `kind` is, in a diagnostic.
fn kind_name(kind: Kind) -> &'static str {
    match kind {
        Kind::Fluid => "water",
        Kind::Wall => "tank-wall",
        Kind::Body => "body",
        Kind::Air => "air",
    }
}

/// Fill the air layer of a two-phase run ([`crate::sph::air`]): air at rest on the water's lattice
/// (spacing `dp`, cells centred at (i + 1/2) dp) above the calm surface, |y| < the layer's half-width and
/// z < its height, where `keep(y, z)` (outside the body and dp/2 clear of its contour). The pressure is
/// the air's hydrostatic one, zero (atmospheric) at the top of the layer: p = rho_a g (H - z), a few
/// pascals.
fn fill_air(
    pt: &mut Particles,
    layer: &crate::sph::air::AirLayer,
    dp: f64,
    mirror: bool,
    g: f64,
    keep: &dyn Fn(f64, f64) -> bool,
) {
    let air = layer.phase();
    let ny = (layer.half_width / dp).floor() as i64;
    let nz = (layer.height / dp).floor() as i64;
    let y_start = if mirror { 0 } else { -ny };
    for kz in 0..nz {
        let z = (kz as f64 + 0.5) * dp;
        let p = air.rho0 * g * (layer.height - z);
        let rho = air.density(p);
        for iy in y_start..ny {
            let y = (iy as f64 + 0.5) * dp;
            if keep(y, z) {
                pt.push(Kind::Air, y, z, 0.0, 0.0, rho, p, dp * dp);
            }
        }
    }
}
