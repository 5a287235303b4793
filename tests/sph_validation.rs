//! SPH validation at coarse resolution (default suite) and finer resolution (`--ignored`).
//!
//! Reference data are in `data/reference/` with their provenance; the numbers used here are copied from
//! those files with the file named beside them. Tolerances state what the coarse resolution achieves; the
//! doc comment of each test says what the finer run gives.

mod common;

use common::sph::{ZHAO_VELOCITY, quiet, wedge_run, window_mean, zhao_wedge};
use slamtool::analytic::{von_karman, wagner};
use slamtool::loads::peaks::summarise;
use slamtool::sph::{
    self, MotionSpec, Overrides, RunOptions, SensorMethod, SensorSpec, Setup, Simulation,
    body::Section, case::ForceMethod, eos::EosKind, particles::Kind,
};

// ------------------------------------------------------------------------------------------------
// Reference data (copied with provenance).

/// data/reference/zhao1996_wedge30_drop.csv: vertical force on the 0.20 m measuring section (N): t_ms,
/// f_measured_n, f_bem_n (fully nonlinear 2D BEM of the paper). Eye-digitised, +-250 N.
const ZHAO_FORCE: [[f64; 3]; 12] = [
    [0.0, 0.0, 0.0],
    [2.5, 1400.0, 1400.0],
    [5.0, 2800.0, 2850.0],
    [7.5, 3900.0, 4200.0],
    [10.0, 4500.0, 5500.0],
    [12.5, 4900.0, 6200.0],
    [14.5, 5150.0, 6550.0],
    [15.5, 5100.0, 6650.0],
    [17.5, 3700.0, 5000.0],
    [20.0, 2600.0, 3500.0],
    [22.5, 2300.0, 3100.0],
    [25.0, 1900.0, 2800.0],
];

/// Length of the Zhao et al. measuring section (m), data/reference/zhao1996_wedge30_drop.csv.
const ZHAO_SECTION_M: f64 = 0.20;

// ------------------------------------------------------------------------------------------------
// Hydrostatic tank.

fn still_tank(dp: f64) -> Setup {
    Setup {
        name: "hydrostatic".into(),
        section_points: None,
        motion: None,
        rho0: 1000.0,
        g: 9.81,
        dp,
        h_over_dp: 1.5,
        c0: 20.0, // > 10 sqrt(g D) = 14 m/s: density varies by 0.5 % at the bottom
        eos: EosKind::Linear,
        delta: 0.1,
        alpha: 0.02,
        cfl: 0.2,
        shifting: sph::case::DEFAULT_SHIFTING,
        riemann: sph::case::DEFAULT_RIEMANN,
        divergence_correction: sph::case::DEFAULT_DIVERGENCE_CORRECTION,
        wall_wetness: sph::case::DEFAULT_WALL_WETNESS,
        force: Default::default(),
        sensor_method: Default::default(),
        tank_half_width: 0.15,
        tank_depth: 0.2,
        tank_wall_height: 0.05,
        damping_zone: 0.0,
        mirror: true,
        t_end: 3.0,
        initial_immersion: 0.0,
        refinement: None,
        air: None,
        sensors: Vec::new(),
        snapshot_interval: None,
        filter_cutoff_hz: None,
        notes: Vec::new(),
    }
}

/// Time-averaged p / (rho g d) at four wall points over [t0, t0 + 1 s] (about one period of the first
/// sloshing mode, which the still tank keeps at a small amplitude).
fn wall_pressure_averages(sim: &mut Simulation, t0: f64) -> Vec<f64> {
    let (rho, g, d, w) = (
        1000.0,
        9.81,
        sim.setup.tank_depth,
        sim.setup.tank_half_width,
    );
    let probes = [
        (0.0, -d, d),
        (0.5 * w, -d, d),
        (w, -0.5 * d, 0.5 * d),
        (w, -0.75 * d, 0.75 * d),
    ];
    let mut sum = vec![0.0; probes.len()];
    let n = 50;
    for k in 1..=n {
        sim.run_until(t0 + k as f64 / n as f64, 0, &mut |_| {})
            .unwrap();
        for (s, &(y, z, depth)) in sum.iter_mut().zip(&probes) {
            *s += sim.fixed_wall_pressure(y, z) / (rho * g * depth) / n as f64;
        }
    }
    sum
}

/// The still tank at `dp`: p / (rho g d) at the probes within `tol` of 1 over 2-3 s; in the plain scheme
/// (`plain`: no shifting, the uncorrected divergence) also no drift between the two windows.
fn check_hydrostatic(dp: f64, tol: f64, plain: bool) {
    let setup = if plain {
        Setup {
            shifting: false,
            divergence_correction: false,
            ..still_tank(dp)
        }
    } else {
        still_tank(dp)
    };
    let mut sim = Simulation::new(setup).unwrap();
    sim.run_until(1.0, 0, &mut |_| {}).unwrap();
    let a = wall_pressure_averages(&mut sim, 1.0);
    let b = wall_pressure_averages(&mut sim, 2.0);
    eprintln!("dp {dp}: p/(rho g d) averaged over 1-2 s {a:?}, over 2-3 s {b:?}");
    for (k, (x, y)) in a.iter().zip(&b).enumerate() {
        assert!((y - 1.0).abs() < tol, "probe {k}: p / (rho g d) = {y}");
        if plain {
            assert!((y - x).abs() < 0.005, "probe {k} drifts: {x} -> {y}");
        }
    }
}

/// A tank without a body, with the wall-wetness rule on (`sph::wall_wetness`), has no face to weigh:
/// it steps, and every dummy of the tank keeps its lattice volume.
#[test]
fn a_tank_without_a_body_steps_with_the_wall_wetness_rule_on() {
    let mut sim = Simulation::new(Setup {
        wall_wetness: true,
        ..still_tank(0.01)
    })
    .unwrap();
    for _ in 0..5 {
        sim.step().unwrap();
    }
    let dummies: Vec<usize> = (0..sim.pt.len())
        .filter(|&i| !sim.pt.kind[i].is_fluid())
        .collect();
    assert!(!dummies.is_empty());
    assert!(dummies.iter().all(|&i| sim.pt.kind[i] != Kind::Body));
    assert!(dummies.iter().all(|&i| sim.pt.vol[i] == sim.dummy_vol));
}

/// Still tank (c0 = 20 m/s): wall pressure (Adami et al. 2012 extrapolation, the same the body sensors
/// use) at the bottom and on the side wall against rho g d, time-averaged over 1 s windows after 1 s of
/// settling (a small undamped sloshing oscillation remains), at bottom centre, bottom quarter, side wall
/// at half and three quarters depth. Measured over 2-3 s:
/// * 20 particle rows (this test): 1.0091, 1.0064, 1.0055, 1.0081;
/// * 40 particle rows (`hydrostatic_fine`): 1.0100, 1.0054, 1.0045, 1.0062.
///
/// Both assert the 1 % and no drift (change below 0.5 % between the two windows). What is left
/// of the bias scales with the compressibility rho g D / (rho0 c0^2) (0.5 % here): +0.4 % at c0 = 40 m/s.
/// Those figures are the plain scheme's (no shifting, the uncorrected divergence), the default until
/// 2026-12-01, and `hydrostatic_coarse` asserts them on it. The default scheme since then (shifting and
/// the corrected divergence; no body, so no wall wetness) does not hold the 1 % at 20 rows: over 2-3 s
/// its probes read 1.0041, 1.0056, 1.0132 and 1.0014 (the side wall at half depth 1.3 % high), and the
/// bottom centre moved from 0.9962 over 1-2 s (a drift of 0.8 %), measured when it became the default;
/// `hydrostatic_coarse_default_scheme` asserts the 1 % on it and fails today.
#[test]
fn hydrostatic_coarse() {
    check_hydrostatic(0.01, 0.01, true);
}

#[test]
#[ignore = "the default scheme's still tank reads the side wall 1.3 % high at 20 rows: fails today"]
fn hydrostatic_coarse_default_scheme() {
    check_hydrostatic(0.01, 0.01, false);
}

#[test]
#[ignore = "fine resolution, about a minute and a half"]
fn hydrostatic_fine() {
    check_hydrostatic(0.005, 0.01, true);
}

// ------------------------------------------------------------------------------------------------
// Determinism across thread counts.

/// The same short wedge run on a 1-thread and a 2-thread rayon pool gives bit-identical histories and
/// particle states, with the default numerics, with the alternatives (particle shifting, delta-SPH,
/// contour-integrated force), with the Riemann scheme, shifting, the corrected divergence and the
/// full pair force in the refined tank, and with shifting, the corrected divergence and the wall's
/// wetness with force-panel sensors.
#[test]
fn identical_on_one_and_two_threads() {
    for variant in 0..4 {
        identical_on_one_and_two_threads_with(variant);
    }
}

fn identical_on_one_and_two_threads_with(variant: u8) {
    let alt = variant == 1;
    let run = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap();
        pool.install(|| {
            let setup = sph::case::resolve(
                "det",
                &zhao_wedge(),
                &MotionSpec::Constant { speed_m_s: 5.0 },
                vec![SensorSpec {
                    name: "p".into(),
                    s_m: 0.02,
                    width_m: 0.01,
                }],
                &Overrides {
                    particles_per_half_beam: Some(20.0),
                    shifting: Some(variant > 0),
                    riemann: Some(!alt),
                    divergence_correction: Some(variant >= 2),
                    wall_wetness: Some(variant == 3),
                    force: Some(match variant {
                        0 => ForceMethod::NormalPairForces,
                        1 => ForceMethod::Contour,
                        _ => ForceMethod::PairForces,
                    }),
                    sensor_method: Some(if alt || variant == 3 {
                        SensorMethod::ForcePanel
                    } else {
                        SensorMethod::Interpolated
                    }),
                    ..Default::default()
                },
            )
            .unwrap();
            assert_eq!(setup.refinement.is_some(), !alt, "variant {variant}");
            let mut sim = Simulation::new(setup).unwrap();
            for _ in 0..60 {
                sim.step().unwrap();
            }
            (sim.history.clone(), sim.pt.clone())
        })
    };
    let (h1, p1) = run(1);
    let (h2, p2) = run(2);
    assert!(
        h1.fz.iter().any(|&f| f != 0.0),
        "the body must have met the water"
    );
    for (a, b) in [
        (&h1.fz, &h2.fz),
        (&h1.t, &h2.t),
        (&h1.sensors[0], &h2.sensors[0]),
    ] {
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(b) {
            assert_eq!(x.to_bits(), y.to_bits());
        }
    }
    for (a, b) in [
        (&p1.y, &p2.y),
        (&p1.z, &p2.z),
        (&p1.vz, &p2.vz),
        (&p1.rho, &p2.rho),
        (&p1.p, &p2.p),
    ] {
        assert!(a.iter().zip(b).all(|(x, y)| x.to_bits() == y.to_bits()));
    }
}

// ------------------------------------------------------------------------------------------------
// Constant-speed wedges.

/// 30 deg wedge at 5 m/s: the section force lies between the von Karman and Wagner forces (the
/// classical lower and upper bounds), averaged over 30-60 % of the chine-wetting time. Coarse (25
/// particles over the half-beam, this test): SPH/Wagner = 0.70 measured (0.90 with the delta-SPH scheme
/// and the contour-integrated force, whose coarse-resolution force is too high, see the Zhao tests).
#[test]
fn wedge30_constant_speed_force_bounds() {
    let run = wedge_run(30.0, 5.0, 25.0, 0, 0.65, SensorMethod::default());
    let h = &run.result.history;
    let t_wet = 2.0 / std::f64::consts::PI * 0.25 * run.beta.tan() / run.speed;
    let (t0, t1) = (0.3 * t_wet, 0.6 * t_wet);
    let f_sph = window_mean(&h.t, &h.fz, t0, t1);
    let tm = 0.45 * t_wet;
    let f_w = wagner::force(run.beta, 1000.0, run.speed, tm).unwrap();
    let f_vk = von_karman::force(run.beta, 1000.0, run.speed, tm).unwrap();
    eprintln!(
        "30 deg force over {t0:.4}-{t1:.4} s: SPH {f_sph:.0} N/m, von Karman {f_vk:.0}, Wagner {f_w:.0} (SPH/Wagner {:.3})",
        f_sph / f_w
    );
    assert!(
        f_sph > f_vk && f_sph < f_w,
        "SPH force {f_sph} outside [{f_vk}, {f_w}]"
    );
}

// ------------------------------------------------------------------------------------------------
// Zhao et al. (1996) 30 deg wedge drop.

fn zhao_prescribed(n_half: f64) -> sph::RunResult {
    let table = ZHAO_VELOCITY.iter().map(|r| [r[0] * 1e-3, r[1]]).collect();
    let setup = sph::case::resolve(
        "zhao1996_prescribed",
        &zhao_wedge(),
        &MotionSpec::Prescribed { table },
        Vec::new(),
        &Overrides {
            particles_per_half_beam: Some(n_half),
            t_end: Some(0.025),
            ..Default::default()
        },
    )
    .unwrap();
    sph::run(setup, &quiet()).unwrap()
}

/// Peak of the section force on the 0.2 m measuring section after a 300 Hz zero-phase low-pass (inside
/// the 100-500 Hz range the experiments used; it removes the row-by-row impact noise of the particle
/// lattice at V/dp = 0.6-1 kHz), and its time (ms).
fn zhao_peak(r: &sph::RunResult) -> (f64, f64) {
    let h = &r.history;
    let f: Vec<f64> = h.fz.iter().map(|f| f * ZHAO_SECTION_M).collect();
    let s = summarise(&h.t, &f, Some(300.0)).unwrap().filtered.unwrap();
    (s.value, s.time * 1e3)
}

/// Zhao et al. (1996) 30 deg wedge with the measured velocity imposed: force on the 0.2 m section against
/// the paper's fully nonlinear 2D BEM (peak 6650 N near 15.5 ms), which solves the same 2D problem. The
/// measured peak (5150 N at 14.5 ms, about 23 % lower: 3D end effects of the rig) is printed for
/// context only. Measured with the defaults (Riemann scheme, pair-force section force, tank sized so that
/// no wall echo returns before t_end) and the 300 Hz filter (peak, time, error against the BEM peak):
/// * 15 particles over the half-beam: 7036 N at 13.1 ms (+5.8 %);
/// * 25 particles (this test): 6876 N at 13.6 ms (+3.4 %); tolerance 10 % (the target) and 3 ms;
/// * 40 particles (`zhao1996_prescribed_fine`): 7210 N at 15.1 ms (+8.4 %); tolerance 10 % and 2 ms.
///
/// Before (delta-SPH with artificial viscosity, contour-integrated force, tank 4 b x 3 b): +61 %, +46 %,
/// +28 % at 15, 25, 40 particles and +1.9 % at 80. Three causes were found: (1) acoustic ringing at the
/// lattice row-impact frequency V/dp (force swinging by +-100 % at 25 particles), removed by the Riemann
/// dissipation; (2) the wall echo of the impact pulse from the tank bottom (c0 = 118 m/s, depth 0.75 m:
/// back after 12.7 ms, on top of the force peak), removed by the tank rule; (3) the contour integral gives
/// the full extrapolated pressure to contour points that see only a few fluid particles (wetted length
/// about one dp too long at each spray root), replaced by the sum of the fluid-body pair forces.
///
/// The early force is still high at coarse resolution (+61 % at 2.5 ms, +33 % at 5 ms with 25 particles:
/// the body meets the water through the kernel support, 2h, before the contours touch); see
/// [`zhao1996_convergence`].
#[test]
fn zhao1996_prescribed_velocity_force() {
    check_zhao(25.0, 0.10, 3.0);
}

#[test]
#[ignore = "40 particles over the half-beam, about two minutes"]
fn zhao1996_prescribed_fine() {
    check_zhao(40.0, 0.10, 2.0);
}

fn check_zhao(n_half: f64, tol: f64, t_tol_ms: f64) {
    let r = zhao_prescribed(n_half);
    let (f, t) = zhao_peak(&r);
    eprintln!(
        "Zhao 1996 prescribed, {n_half} particles: SPH peak {f:.0} N at {t:.2} ms (300 Hz low-pass); BEM 6650 N at 15.5 ms; measured 5150 N at 14.5 ms"
    );
    for row in ZHAO_FORCE {
        let fs = zhao_section_force(&r, row[0]);
        eprintln!(
            "  t {:5.1} ms: SPH {fs:7.0} N  BEM {:6.0} N  measured {:6.0} N",
            row[0], row[2], row[1]
        );
    }
    assert!((f / 6650.0 - 1.0).abs() < tol, "peak {f} N vs BEM 6650 N");
    assert!((t - 15.5).abs() < t_tol_ms, "peak time {t} ms vs 15.5 ms");
}

/// The SPH force on the Zhao et al. measuring section (N): the 1 ms window mean of the force per metre
/// about `t_ms`, times the section length.
fn zhao_section_force(r: &sph::RunResult, t_ms: f64) -> f64 {
    let (t0, t1) = ((t_ms - 0.5) * 1e-3, (t_ms + 0.5) * 1e-3);
    window_mean(&r.history.t, &r.history.fz, t0, t1) * ZHAO_SECTION_M
}

/// Mean |SPH / BEM - 1| of the force (1 ms window means) at the BEM rows up to `t_max_ms`.
fn zhao_mean_error(r: &sph::RunResult, t_max_ms: f64) -> f64 {
    let rows: Vec<_> = ZHAO_FORCE
        .iter()
        .filter(|row| row[0] > 0.0 && row[0] <= t_max_ms)
        .collect();
    rows.iter()
        .map(|row| (zhao_section_force(r, row[0]) / row[2] - 1.0).abs())
        .sum::<f64>()
        / rows.len() as f64
}

/// Convergence in particle spacing on the Zhao prescribed-velocity case: the mean error of the force
/// against the BEM over the rising phase (2.5-12.5 ms) and over all rows (2.5-25 ms) falls as dp falls.
/// Measured (rising phase / all rows): 15 particles 35.1 % / 24.6 %, 25 particles 26.9 % / 18.6 %,
/// 40 particles 20.7 % / 11.6 %. (The filtered peak, +5.8 %, +3.4 %, +8.4 %, is within 10 % at all three
/// levels but not monotone.)
#[test]
#[ignore = "three resolutions, about three minutes"]
fn zhao1996_convergence() {
    let mut errs = Vec::new();
    for n in [15.0, 25.0, 40.0] {
        let r = zhao_prescribed(n);
        let (f, t) = zhao_peak(&r);
        let (e_rise, e_all) = (zhao_mean_error(&r, 12.5), zhao_mean_error(&r, 25.0));
        eprintln!(
            "n = {n}: peak {f:.0} N at {t:.2} ms ({:+.1} % vs BEM); mean error {:.1} % (2.5-12.5 ms), {:.1} % (all rows)",
            (f / 6650.0 - 1.0) * 100.0,
            e_rise * 100.0,
            e_all * 100.0
        );
        errs.push((e_rise, e_all));
    }
    for k in 1..errs.len() {
        assert!(
            errs[k].0 < errs[k - 1].0 && errs[k].1 < errs[k - 1].1,
            "error does not fall: {errs:?}"
        );
    }
}

// ------------------------------------------------------------------------------------------------
// Divergence handling.

/// A run that blows up stops with a diagnostic, and the histories up to that point are on disk. With
/// the wall collision and the Mach-number check in place no physical input makes the solver diverge
/// any more (a Courant number of 3 or a sound speed of 2 m/s at 5 m/s both run to a meaningless but
/// finite end), so the blow-up is forced: gravity becomes NaN after the set-up, as a corrupted state
/// would, and the first step that meets it must stop the run.
#[test]
fn diverging_run_stops_and_keeps_histories() {
    let beta = 30f64.to_radians();
    let mut setup = sph::case::resolve(
        "diverge",
        &Section::wedge(beta, 0.25, 0.2).unwrap(),
        &MotionSpec::Constant { speed_m_s: 5.0 },
        Vec::new(),
        &Overrides {
            dp: Some(0.02),
            ..Default::default()
        },
    )
    .unwrap();
    setup.g = f64::NAN;
    let dir = tempfile::tempdir().unwrap();
    let opts = RunOptions {
        out_dir: Some(dir.path().to_path_buf()),
        ..Default::default()
    };
    let err = match sph::run(setup, &opts) {
        Ok(_) => panic!("the run with NaN gravity did not stop"),
        Err(e) => e.to_string(),
    };
    assert!(err.contains("stopped at t ="), "{err}");
    let csv = std::fs::read_to_string(dir.path().join("history.csv")).unwrap();
    // The header, the initial state, and the step that met the NaN.
    assert!(csv.lines().count() >= 2, "{csv}");
    let summary = std::fs::read_to_string(dir.path().join("summary.json")).unwrap();
    assert!(
        summary.contains("\"stopped_early\": \"non-finite state"),
        "{summary}"
    );
}
