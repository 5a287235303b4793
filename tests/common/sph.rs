//! Shared fixtures for the SPH tests: reference data copied with provenance, and small helpers.

use slamtool::sph::{
    self, MotionSpec, Overrides, RunOptions, SensorMethod, SensorSpec, body::Section,
};

/// data/reference/zhao1996_wedge30_velocity.csv: Zhao, Faltinsen & Aarsnes (1996) 30 deg wedge drop,
/// measured downward velocity (m/s), eye-digitised, +-0.05 m/s. Columns t_ms, v_down_m_s.
pub const ZHAO_VELOCITY: [[f64; 2]; 11] = [
    [0.0, 6.15],
    [2.5, 6.14],
    [5.0, 6.08],
    [7.5, 5.97],
    [10.0, 5.80],
    [12.5, 5.58],
    [15.0, 5.35],
    [17.5, 5.15],
    [20.0, 5.02],
    [22.5, 4.94],
    [25.0, 4.90],
];

pub fn zhao_wedge() -> Section {
    // data/reference/zhao1996_wedge30_drop.csv: breadth 0.5 m, knuckles at 0.25 m, height 0.29 m.
    Section::wedge(30f64.to_radians(), 0.25, 0.29).unwrap()
}

pub fn quiet() -> RunOptions {
    RunOptions::default()
}

/// Mean of `x` over the samples with t in [t0, t1].
pub fn window_mean(t: &[f64], x: &[f64], t0: f64, t1: f64) -> f64 {
    let v: Vec<f64> = t
        .iter()
        .zip(x)
        .filter(|(t, _)| **t >= t0 && **t <= t1)
        .map(|(_, x)| *x)
        .collect();
    v.iter().sum::<f64>() / v.len() as f64
}

/// Half-beam of the test wedges (m).
pub const WEDGE_HALF_BEAM: f64 = 0.25;

/// A constant-speed wedge run (see [`wedge_run`]).
pub struct WedgeRun {
    pub beta: f64,
    pub speed: f64,
    pub result: sph::RunResult,
}

/// A wedge (knuckle at 0.25 m, vertical sides) at constant speed, with `sensors` sensors of 10 mm spread
/// along the side between 15 % and 60 % of its length (all passed by the pressure peak well before the
/// chine is wetted), sensor pressures by `method`; runs to `t_frac` of the Wagner chine-wetting time.
pub fn wedge_run(
    deadrise_deg: f64,
    speed: f64,
    n_half: f64,
    sensors: usize,
    t_frac: f64,
    method: SensorMethod,
) -> WedgeRun {
    wedge_run_with(
        deadrise_deg,
        speed,
        sensors,
        t_frac,
        Overrides {
            particles_per_half_beam: Some(n_half),
            sensor_method: Some(method),
            ..Default::default()
        },
    )
}

/// [`wedge_run`] in the plain scheme (no shifting, an unweighted wall) with the kernel-gradient-corrected
/// divergence on or off: the scheme in which the correction was measured on its own.
pub fn wedge_run_numerics(
    deadrise_deg: f64,
    speed: f64,
    n_half: f64,
    sensors: usize,
    t_frac: f64,
    method: SensorMethod,
    divergence_correction: bool,
) -> WedgeRun {
    wedge_run_with(
        deadrise_deg,
        speed,
        sensors,
        t_frac,
        Overrides {
            particles_per_half_beam: Some(n_half),
            sensor_method: Some(method),
            divergence_correction: Some(divergence_correction),
            shifting: Some(false),
            wall_wetness: Some(false),
            ..Default::default()
        },
    )
}

fn wedge_run_with(
    deadrise_deg: f64,
    speed: f64,
    sensors: usize,
    t_frac: f64,
    overrides: Overrides,
) -> WedgeRun {
    let setup = wedge_setup(
        deadrise_deg,
        speed,
        sensors,
        [0.15, 0.60],
        t_frac,
        overrides,
    );
    WedgeRun {
        beta: deadrise_deg.to_radians(),
        speed,
        result: sph::run(setup, &quiet()).unwrap(),
    }
}

/// The set-up of a wedge of half-beam [`WEDGE_HALF_BEAM`] (knuckle there, vertical sides above) entering
/// at constant `speed`, with `sensors` sensors of 10 mm spread evenly along the side between the
/// fractions `span[0]` and `span[1]` of its length, run to `t_frac` of the Wagner chine-wetting time
/// t = 2 b tan(beta) / (pi V); every other choice is taken from `overrides`.
pub fn wedge_setup(
    deadrise_deg: f64,
    speed: f64,
    sensors: usize,
    span: [f64; 2],
    t_frac: f64,
    overrides: Overrides,
) -> sph::case::Setup {
    let beta = deadrise_deg.to_radians();
    let b = WEDGE_HALF_BEAM;
    let section = Section::wedge(beta, b, 1.5 * b * beta.tan()).unwrap();
    let side = b / beta.cos();
    let specs = (0..sensors)
        .map(|k| SensorSpec {
            name: format!("p{k}"),
            s_m: side * (span[0] + (span[1] - span[0]) * k as f64 / (sensors.max(2) - 1) as f64),
            width_m: 0.01,
        })
        .collect();
    let t_wet = 2.0 / std::f64::consts::PI * b * beta.tan() / speed;
    sph::case::resolve(
        "wedge",
        &section,
        &MotionSpec::Constant { speed_m_s: speed },
        specs,
        &Overrides {
            t_end: Some(t_frac * t_wet),
            ..overrides
        },
    )
    .unwrap()
}

/// Largest |other - reference| of two section-force histories over their common steps, as a fraction of
/// the reference's peak, and the ratio of the peaks other / reference.
pub fn force_difference(reference: &sph::RunResult, other: &sph::RunResult) -> (f64, f64) {
    let (fr, fo) = (&reference.history.fz, &other.history.fz);
    let n = fr.len().min(fo.len());
    let peak_r = fr.iter().copied().fold(0.0, f64::max);
    let peak_o = fo.iter().copied().fold(0.0, f64::max);
    let diff = (0..n).map(|k| (fr[k] - fo[k]).abs()).fold(0.0, f64::max);
    (diff / peak_r, peak_o / peak_r)
}

/// The one warning of a run summary that lists its widened sensors ([`sph::WIDENED_SENSORS`]); fails
/// the test when there is not exactly one.
pub fn widened_sensor_warning(s: &sph::RunSummary) -> String {
    let w: Vec<&String> = s
        .warnings
        .iter()
        .filter(|w| w.starts_with(sph::WIDENED_SENSORS))
        .collect();
    assert_eq!(w.len(), 1, "{:?}", s.warnings);
    w[0].clone()
}
