//! Convergence in particle spacing of the sensor peak pressures of constant-speed wedges, compared like
//! for like with theory: the reference is the theoretical pressure averaged over the same sensor width
//! and passed through the same zero-phase low-pass filter as the SPH history.

mod common;

use common::sph::{WedgeRun, wedge_run};
use slamtool::analytic::wagner_pressure::WagnerWedge;
use slamtool::analytic::{wagner, zhao_faltinsen1993};
use slamtool::loads::peaks::summarise;
use slamtool::sph::SensorMethod;

/// Zero-phase low-pass applied to every sensor history before taking its peak (Hz).
const CUTOFF_HZ: f64 = 2000.0;

/// Filtered peak (value, time) of a history.
fn filtered_peak(t: &[f64], x: &[f64]) -> (f64, f64) {
    let s = summarise(t, x, Some(CUTOFF_HZ)).unwrap().filtered.unwrap();
    (s.value, s.time)
}

/// Like-for-like reference peak pressure coefficient of a sensor (centre `s`, width `width` along the
/// side) on a wedge at constant speed `v`, over [0, t_end]:
/// * 30 deg: Wagner's composite pressure distribution ([`WagnerWedge`]) averaged over the sensor width,
///   sampled every t_end / 4000 and filtered like the SPH history;
/// * 20 deg: the Zhao & Faltinsen (1993) similarity peak, Cp_max 17.77 (data/reference/
///   water_entry_theory.md), times the ratio of the width-averaged, filtered Wagner peak to Wagner's point
///   peak (the similarity distribution itself is not in the reference data, so its peak is lowered by
///   the amount the Wagner peak of the same width is lowered).
fn like_for_like_cp(beta: f64, v: f64, s: f64, width: f64, t_end: f64) -> f64 {
    let w = WagnerWedge {
        beta,
        rho: 1000.0,
        v,
    };
    let q = 0.5 * 1000.0 * v * v;
    let n = 4000;
    let t: Vec<f64> = (0..=n).map(|k| t_end * k as f64 / n as f64).collect();
    let (p_sensor, _) = filtered_peak(&t, &w.sensor_history(s, width, &t));
    if (beta.to_degrees() - zhao_faltinsen1993::DEADRISE_DEG).abs() < 1e-9 {
        let p_point = w
            .sensor_history(s, 1e-6 * width, &t)
            .into_iter()
            .fold(0.0, f64::max);
        zhao_faltinsen1993::CP_MAX * p_sensor / p_point
    } else {
        p_sensor / q
    }
}

/// Peak errors of one run: mean over its sensors of |Cp / Cp_ref - 1| against the point reference (Wagner
/// (pi^2/4) cot^2(beta) at 30 deg, 17.77 at 20 deg) and against the like-for-like reference, and the mean
/// |t / t_ref - 1| of the time of the peak against the time the reference peak passes the sensor centre
/// (Wagner: at height (pi/2) V t above the keel; similarity: 1.5087 V t).
struct PeakErrors {
    point: f64,
    like: f64,
    time: f64,
}

fn peak_errors(deadrise_deg: f64, n_half: f64, method: SensorMethod) -> PeakErrors {
    let t_frac = 0.8;
    let run: WedgeRun = wedge_run(deadrise_deg, 5.0, n_half, 3, t_frac, method);
    let beta = run.beta;
    let t_end = run.result.summary.setup.t_end;
    let similarity = deadrise_deg == zhao_faltinsen1993::DEADRISE_DEG;
    let (cp_point, rise) = if similarity {
        (
            zhao_faltinsen1993::CP_MAX,
            1.0 + zhao_faltinsen1993::Z_OVER_VT,
        )
    } else {
        (
            wagner::peak_pressure_coefficient(beta),
            0.5 * std::f64::consts::PI,
        )
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
    for (col, s) in h.sensors.iter().zip(sens) {
        let (p, t) = filtered_peak(&h.t, col);
        let cp = p / q;
        let cp_like = like_for_like_cp(beta, run.speed, s.s_m, s.width_m, t_end);
        let t_ref = s.s_m * beta.sin() / (rise * run.speed);
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

/// Measured with the default (interpolated) sensors, mean like-for-like Cp error / mean peak-time error
/// over the three sensors (point-reference Cp error in brackets):
///
/// | particles over the half-beam | 30 deg vs Wagner | 20 deg vs similarity |
/// |---|---|---|
/// | 15 | 11.7 % / 59 % (12.4 %) | 15.1 % / 39 % (9.6 %) |
/// | 25 (not run here) | 13.3 % / 31 % (14.4 %) | 4.9 % / 23 % (11.3 %) |
/// | 40 | 9.4 % / 17 % (8.7 %) | 5.5 % / 10 % (9.6 %) |
///
/// Asserted: from 15 to 40 particles the like-for-like Cp error and the peak-time error fall at both
/// angles, and the 40-particle Cp error is below 15 %. (Between 15 and 25 particles the 30 deg Cp error
/// does not fall: the interpolated sensor's maximum comes 1.5-2 dp of jet-root travel after the root
/// has passed, when the kernel support of the sample points is filled with the high-pressure fluid
/// behind the root, and sits on the lattice-impact noise of the particle pressures; see the report in
/// [`sensor_peak_convergence_force_panel`] for the alternative.)
#[test]
fn sensor_peak_convergence() {
    for deg in [30.0, zhao_faltinsen1993::DEADRISE_DEG] {
        let coarse = peak_errors(deg, 15.0, SensorMethod::Interpolated);
        let fine = peak_errors(deg, 40.0, SensorMethod::Interpolated);
        assert!(
            fine.like < coarse.like,
            "{deg} deg: like-for-like Cp error {} -> {}",
            coarse.like,
            fine.like
        );
        assert!(
            fine.time < coarse.time,
            "{deg} deg: peak-time error {} -> {}",
            coarse.time,
            fine.time
        );
        assert!(fine.like < 0.15, "{deg} deg: Cp error {}", fine.like);
    }
}

/// The force-panel sensors ([`SensorMethod::ForcePanel`]) at 15, 25 and 40 particles. Measured (mean
/// like-for-like Cp error / mean peak-time error):
///
/// | particles over the half-beam | 30 deg vs Wagner | 20 deg vs similarity |
/// |---|---|---|
/// | 15 | 23.4 % / 44 % | 27.7 % / 28 % |
/// | 25 | 25.3 % / 2.3 % | 15.1 % / 7.7 % |
/// | 40 | 10.6 % / 1.1 % | 8.0 % / 8.8 % |
///
/// The time of the peak is right from 25 particles on (the force is where the fluid pushes, with no
/// kernel extrapolation lag); the value is noisier than the interpolated one at coarse resolution (a
/// 10 mm panel holds one or two wall-adjacent fluid particles at 15-25 particles over the half-beam),
/// so the interpolated pressure stays the default. Asserted: the Cp error and the peak-time error fall
/// from 15 to 40 particles at both angles.
#[test]
#[ignore = "three resolutions at two angles, about a minute"]
fn sensor_peak_convergence_force_panel() {
    for deg in [30.0, zhao_faltinsen1993::DEADRISE_DEG] {
        let e: Vec<PeakErrors> = [15.0, 25.0, 40.0]
            .iter()
            .map(|&n| peak_errors(deg, n, SensorMethod::ForcePanel))
            .collect();
        assert!(e[2].like < e[0].like, "{deg} deg: Cp error");
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
