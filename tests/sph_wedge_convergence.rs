//! Issue 28, item 4: convergence of the SPH wedge sensor peaks and section force to the nonlinear
//! similarity solution ([`slamtool::analytic::similarity`]) at 20, 30 and 45 deg, constant speed, three
//! levels of particle spacing, both sensor methods.
//!
//! The study uses self-similarity: a constant-speed wedge without gravity has no length scale, so what
//! fixes the resolution of a sensor's impact is the number of particles across the wetted half-width
//! c(t) (and across the jet root) at the time the pressure peak crosses it, not the particles per
//! half-beam. Sensors spread along the side from 10 % to 75 % of its length are therefore, in one run,
//! a convergence study in themselves: each is crossed at a larger c / dp than the one before. Every
//! run is made without gravity (`g = 0`: infinite Froude number, the similarity solution's assumption);
//! the sound speed, tank and refinement are the automatic ones of `entry wedge`.
//!
//! The reference of every sensor is the similarity solution averaged over the span the SPH sensor
//! integrates (its width, or `sph::sensors::MIN_WIDTH_DP` spacings when narrower) and filtered like
//! the SPH history (`slamtool::validate::wedges::like_for_like`), with its peak time.
//! Particles across the jet: the similarity jet-root thickness (`root_thickness` V t) / dp at the time
//! of the reference peak; across the wetted half-width: the spray root's half-width (`root[0]` V t) / dp.
//! The section force is compared with the similarity force coefficient F / (rho V^3 t) over the window
//! t in [0.5, 0.9] t_end (mean of the ratio).
//!
//! Tolerances, stated before the runs (issue 28): at the default level (40 particles per half-beam,
//! refined tank) every sensor below 80 % of the side within 10 % of its reference; force within 3 %.

mod common;

use common::sph::{WEDGE_HALF_BEAM, wedge_setup, window_mean};

use slamtool::analytic::similarity_sensor::solution;
use slamtool::loads::peaks::summarise;
use slamtool::sph::{self, Overrides, RunOptions, SensorMethod};
use slamtool::validate::wedges::{like_for_like, reference_span};

/// Zero-phase low-pass applied to every sensor history and to the reference (Hz).
const CUTOFF_HZ: f64 = 2000.0;
/// Entry speed (m/s); the study is scale-free, this and the half-beam ([`WEDGE_HALF_BEAM`]) only set the
/// units.
const SPEED: f64 = 5.0;
/// Sensors along the side, 10 mm wide ([`wedge_setup`]), centres from `S_FIRST` to `S_LAST` of the
/// side's length.
const SENSORS: usize = 12;
const S_FIRST: f64 = 0.10;
const S_LAST: f64 = 0.75;
/// End of the run as a fraction of Wagner's chine-wetting time.
const T_FRAC: f64 = 0.92;

/// One sensor's row of the table.
#[derive(Debug, Clone)]
struct Row {
    /// Sensor centre / side length.
    s_frac: f64,
    cp: f64,
    cp_ref: f64,
    /// (t_peak - t_ref) V / dp.
    dt_dp: f64,
    /// Particles across the jet root and across the wetted half-width at the reference peak time.
    n_jet: f64,
    n_wet: f64,
}

/// One run's result.
struct Study {
    deg: f64,
    n_half: f64,
    method: SensorMethod,
    rows: Vec<Row>,
    /// Mean over [0.5, 0.9] t_end of F_sph / (rho V^3 t C_F).
    force_ratio: f64,
    wall_s: f64,
}

fn method_name(m: SensorMethod) -> &'static str {
    match m {
        SensorMethod::Interpolated => "interpolated",
        SensorMethod::ForcePanel => "force-panel",
    }
}

/// A gravity-free constant-speed wedge at `n_half` particles per half-beam, read by `method`, with
/// `divergence_correction` on or off.
fn study(deg: f64, n_half: f64, method: SensorMethod, divergence_correction: bool) -> Study {
    let beta = deg.to_radians();
    let side = WEDGE_HALF_BEAM / beta.cos();
    let mut setup = wedge_setup(
        deg,
        SPEED,
        SENSORS,
        [S_FIRST, S_LAST],
        T_FRAC,
        Overrides {
            particles_per_half_beam: Some(n_half),
            sensor_method: Some(method),
            divergence_correction: Some(divergence_correction),
            // Diagnostics: `CONV_RIEMANN=0` for delta-SPH with artificial viscosity (uniform tank),
            // `CONV_CFL` for another Courant number.
            riemann: std::env::var("CONV_RIEMANN").ok().map(|v| v != "0"),
            cfl: std::env::var("CONV_CFL").ok().map(|v| v.parse().unwrap()),
            // `CONV_H` for another smoothing length / spacing ratio.
            h_over_dp: std::env::var("CONV_H").ok().map(|v| v.parse().unwrap()),
            // `CONV_SHIFTING=1`: particle shifting with free-surface treatment (uniform tank).
            shifting: std::env::var("CONV_SHIFTING").ok().map(|v| v == "1"),
            // `CONV_WET=1`: body dummies weighted by the wetness of the body's face (item 29).
            wall_wetness: std::env::var("CONV_WET").ok().map(|v| v == "1"),
            // `CONV_MIRROR=0`: both sides of the wedge in the tank instead of a symmetry plane.
            mirror: std::env::var("CONV_MIRROR").ok().map(|v| v != "0"),
            // `CONV_UNIFORM=1`: one spacing throughout the tank instead of the refined band.
            refinement: std::env::var("CONV_UNIFORM")
                .ok()
                .filter(|v| v == "1")
                .map(|_| false),
            ..Default::default()
        },
    );
    // No gravity: the similarity solution's infinite Froude number.
    setup.g = 0.0;
    // Diagnostics: `CONV_C0_FACTOR` scales the automatic sound speed (Mach-number effects).
    if let Ok(f) = std::env::var("CONV_C0_FACTOR") {
        setup.c0 *= f.parse::<f64>().unwrap();
    }
    // Diagnostics: `CONV_TANK_SCALE` scales the automatic tank's half-width and depth;
    // `CONV_WIDTH_DP` gives every sensor a width of that many particle spacings.
    if let Ok(f) = std::env::var("CONV_TANK_SCALE") {
        let f: f64 = f.parse().unwrap();
        setup.tank_half_width *= f;
        setup.tank_depth *= f;
    }
    if let Ok(w) = std::env::var("CONV_WIDTH_DP") {
        let w: f64 = w.parse().unwrap();
        for s in &mut setup.sensors {
            s.width_m = w * setup.dp;
        }
    }
    let run = sph::run(setup, &RunOptions::default()).unwrap();
    let sim = solution(deg).unwrap();
    let setup = &run.summary.setup;
    let (dp, t_end) = (run.summary.dp_m, setup.t_end);
    let h = &run.history;
    let q = 0.5 * 1000.0 * SPEED * SPEED;
    let rows = h
        .sensors
        .iter()
        .zip(&setup.sensors)
        .zip(&run.summary.sensors)
        .map(|((col, s), named)| {
            let f = summarise(&h.t, col, Some(CUTOFF_HZ))
                .unwrap()
                .filtered
                .unwrap();
            // The reference over the span the SPH sensor integrates (its width, or the narrowest
            // span when it is narrower: `sph::sensors::integration_span`).
            let [a, b] = named.integration_span_m.unwrap();
            let (cp_ref, t_ref) =
                like_for_like(beta, SPEED, 0.5 * (a + b), b - a, t_end, CUTOFF_HZ).unwrap();
            let vt = SPEED * t_ref;
            Row {
                s_frac: s.s_m / side,
                cp: f.value / q,
                cp_ref,
                dt_dp: (f.time - t_ref) * SPEED / dp,
                n_jet: sim.root_thickness * vt / dp,
                n_wet: sim.root[0] * vt / dp,
            }
        })
        .collect();
    let cf = 1000.0 * SPEED.powi(3) * sim.force;
    // `CONV_DUMP=<file>`: the run's time, section force and sensor records as CSV (diagnosis).
    if let Ok(path) = std::env::var("CONV_DUMP") {
        let mut txt = String::new();
        for k in 0..h.t.len() {
            txt += &format!("{},{}", h.t[k], h.fz[k]);
            for c in &h.sensors {
                txt += &format!(",{}", c[k]);
            }
            txt += "\n";
        }
        std::fs::write(path, txt).unwrap();
        println!(
            "dp {dp} t_end {t_end} speed {SPEED} cf {cf} c0 {}",
            setup.c0
        );
    }
    // `CONV_PROFILE=1`: the sensor records collapsed on the similarity variable (diagnosis).
    if std::env::var("CONV_PROFILE").is_ok_and(|v| v == "1") {
        let centres: Vec<f64> = setup
            .sensors
            .iter()
            .zip(&run.summary.sensors)
            .map(|(s, named)| reference_span(s, named).0)
            .collect();
        print_profile(deg, q, &h.t, &h.sensors, &centres, t_end, &sim.pressure);
    }
    let ratio: Vec<f64> = h.t.iter().zip(&h.fz).map(|(t, f)| f / (cf * t)).collect();
    // `CONV_FORCE_TRACE=1`: F / F_similarity over tenths of the run (window means).
    if std::env::var("CONV_FORCE_TRACE").is_ok_and(|v| v == "1") {
        let trace: Vec<String> = (1..10)
            .map(|k| {
                let (a, b) = (
                    (k as f64 - 0.5) / 10.0 * t_end,
                    (k as f64 + 0.5) / 10.0 * t_end,
                );
                format!(
                    "{:.1}: {:.3}",
                    k as f64 / 10.0,
                    window_mean(&h.t, &ratio, a, b)
                )
            })
            .collect();
        println!("F / F_similarity at t / t_end = {}", trace.join(", "));
    }
    let st = Study {
        deg,
        n_half,
        method,
        rows,
        force_ratio: window_mean(&h.t, &ratio, 0.5 * t_end, 0.9 * t_end),
        wall_s: run.summary.wall_time_s,
    };
    print_study(&st);
    st
}

/// The sensor records collapsed on the similarity variable: a sensor at arc length s from the keel
/// sits at z / (V t) = s sin(beta) / (V t) - 1 (apex at -1), so in a self-similar flow every record is
/// a piece of one profile Cp(z / (V t)). Printed for two windows of the run, in bins of 0.1: the mean
/// SPH Cp of the samples in the bin and the mean of the similarity Cp at the same samples' positions
/// (interpolated between its panel midpoints), and their ratio. The bins behind the spray root tell
/// whether the wetted wall carries the similarity pressure; those at the root are smeared by the
/// sensors' span and the filter-free records.
fn print_profile(
    deg: f64,
    q: f64,
    t: &[f64],
    records: &[Vec<f64>],
    centres: &[f64],
    t_end: f64,
    reference: &[[f64; 2]],
) {
    let sin_b = deg.to_radians().sin();
    let cp_ref = |x: f64| {
        let k = reference.partition_point(|p| p[0] < x);
        if k == 0 || k == reference.len() {
            return if k == 0 { reference[0][1] } else { 0.0 };
        }
        let ([x0, y0], [x1, y1]) = (reference[k - 1], reference[k]);
        y0 + (y1 - y0) * (x - x0) / (x1 - x0)
    };
    for (a, b) in [(0.3, 0.6), (0.6, 0.95)] {
        let mut bins = vec![(0.0, 0.0, 0usize); 17];
        for (k, &tk) in t.iter().enumerate() {
            if tk < a * t_end || tk > b * t_end {
                continue;
            }
            for (rec, &s) in records.iter().zip(centres) {
                let x = s * sin_b / (SPEED * tk) - 1.0;
                let m = ((x + 1.0) / 0.1).floor();
                if (0.0..17.0).contains(&m) {
                    let bin = &mut bins[m as usize];
                    bin.0 += rec[k] / q;
                    bin.1 += cp_ref(x);
                    bin.2 += 1;
                }
            }
        }
        println!("profile, t in [{a}, {b}] t_end: z/(V t), Cp SPH, Cp similarity, ratio");
        for (m, (sph, sim, n)) in bins.iter().enumerate() {
            if *n > 0 {
                let n = *n as f64;
                let x = -0.95 + 0.1 * m as f64;
                println!("  {x:+.2} {:6.2} {:6.2} {:.3}", sph / n, sim / n, sph / sim);
            }
        }
    }
}

fn print_study(st: &Study) {
    eprintln!(
        "## {} deg, {} particles per half-beam, {}: F / F_similarity {:.3} (t in [0.5, 0.9] t_end), wall {:.0} s",
        st.deg,
        st.n_half,
        method_name(st.method),
        st.force_ratio,
        st.wall_s
    );
    eprintln!(
        "| s/side | Cp SPH | Cp ref | SPH/ref | peak-time error (dp/V) | particles across jet | across c |"
    );
    eprintln!("|---|---|---|---|---|---|---|");
    for r in &st.rows {
        eprintln!(
            "| {:.2} | {:.2} | {:.2} | {:.3} | {:+.2} | {:.2} | {:.1} |",
            r.s_frac,
            r.cp,
            r.cp_ref,
            r.cp / r.cp_ref,
            r.dt_dp,
            r.n_jet,
            r.n_wet
        );
    }
    eprintln!(
        "mean |SPH/ref - 1| {:.1} %, largest {:.1} %",
        100.0 * mean_error(&st.rows),
        100.0 * max_error(&st.rows)
    );
}

fn mean_error(rows: &[Row]) -> f64 {
    rows.iter()
        .map(|r| (r.cp / r.cp_ref - 1.0).abs())
        .sum::<f64>()
        / rows.len() as f64
}

fn max_error(rows: &[Row]) -> f64 {
    rows.iter()
        .map(|r| (r.cp / r.cp_ref - 1.0).abs())
        .fold(0.0, f64::max)
}

fn env_list(name: &str, default: &str) -> Vec<String> {
    std::env::var(name)
        .unwrap_or(default.into())
        .split(',')
        .map(|s| s.trim().to_string())
        .collect()
}

/// The convergence table: `CONV_DEGS` (default 20,30,45) x `CONV_LEVELS` (particles per half-beam,
/// default 20,40,80) x `CONV_METHODS` (interpolated,panel), `CONV_CORRECTED=1` for the
/// kernel-gradient-corrected divergence. Prints one table per run and the observed order of the mean
/// error between successive levels. Asserts nothing (a measurement).
/// `cargo test --release --test sph_wedge_convergence -- --ignored --nocapture convergence_table`
#[test]
#[ignore = "measurement, minutes to tens of minutes"]
fn convergence_table() {
    let degs: Vec<f64> = env_list("CONV_DEGS", "20,30,45")
        .iter()
        .map(|s| s.parse().unwrap())
        .collect();
    let levels: Vec<f64> = env_list("CONV_LEVELS", "20,40,80")
        .iter()
        .map(|s| s.parse().unwrap())
        .collect();
    let methods: Vec<SensorMethod> = env_list("CONV_METHODS", "interpolated,panel")
        .iter()
        .map(|s| match s.as_str() {
            "panel" => SensorMethod::ForcePanel,
            _ => SensorMethod::Interpolated,
        })
        .collect();
    let corrected = std::env::var("CONV_CORRECTED").is_ok_and(|v| v == "1");
    for &deg in &degs {
        for &m in &methods {
            let errs: Vec<(f64, f64)> = levels
                .iter()
                .map(|&n| (n, mean_error(&study(deg, n, m, corrected).rows)))
                .collect();
            for w in errs.windows(2) {
                eprintln!(
                    "{deg} deg {}: mean error {:.1} % -> {:.1} % from {} to {} particles: observed order {:.2}",
                    method_name(m),
                    100.0 * w[0].1,
                    100.0 * w[1].1,
                    w[0].0,
                    w[1].0,
                    (w[0].1 / w[1].1).ln() / (w[1].0 / w[0].0).ln()
                );
            }
        }
    }
}

/// Issue 28's default-level check: at the default level of `entry wedge` and `assess` (40 particles per
/// half-beam, refined tank, default numerics), every sensor below 80 % of the side within 10 % of its
/// like-for-like similarity reference, at 20, 30 and 45 deg, both sensor methods; and the section
/// force within 3 % of the similarity force coefficient. Tolerances are the issue's, stated before the
/// runs. It does not hold today, so it is ignored rather than loosened. Measured 2026-11-27 with
/// sensors integrated over at least 4 dp and the references over the same span (sensor SPH / reference
/// over the 12 sensors, sensors within 10 %, section force / similarity):
///
/// | deadrise | interpolated | force-panel | force |
/// |---|---|---|---|
/// | 20 deg | 1.13-1.25, 0/12 | 0.85-0.97, 9/12 | 1.044 |
/// | 30 deg | 1.04-1.27, 3/12 | 0.92-1.07, 12/12 | 1.000 |
/// | 45 deg (end-of-run pressure below 40 % of the side) | 0.75-1.71, 5/12 | 0.87-1.38, 6/12 | 1.129 |
///
/// The validation report has its sensor part as case `wedge-convergence-table` (a known failure),
/// with the section force in its notes.
/// (docs/numerics/wedge-convergence.md has the other levels and the diagnosis.)
/// `cargo test --release --test sph_wedge_convergence -- --ignored --nocapture default_level`
#[test]
#[ignore = "does not hold at the default level (docs/numerics/wedge-convergence.md); about two minutes"]
fn default_level_within_ten_per_cent() {
    let mut failures = Vec::new();
    for deg in [20.0, 30.0, 45.0] {
        for m in [SensorMethod::Interpolated, SensorMethod::ForcePanel] {
            let st = study(deg, 40.0, m, sph::case::DEFAULT_DIVERGENCE_CORRECTION);
            for r in st.rows.iter().filter(|r| r.s_frac < 0.8) {
                if (r.cp / r.cp_ref - 1.0).abs() > 0.10 {
                    failures.push(format!(
                        "{deg} deg {} s/side {:.2}: {:.3}",
                        method_name(m),
                        r.s_frac,
                        r.cp / r.cp_ref
                    ));
                }
            }
            if (st.force_ratio - 1.0).abs() > 0.03 {
                failures.push(format!("{deg} deg force {:.3}", st.force_ratio));
            }
        }
    }
    assert!(failures.is_empty(), "{failures:#?}");
}
