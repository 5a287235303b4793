//! Shared fixtures for the SPH tests: reference data copied with provenance, and small helpers.

use slamtool::sph::{RunOptions, body::Section};

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
