//! The strip-theory chain at one station under alternative readings of a published wave (height or
//! amplitude, model or full scale), beside a measured relative velocity: what the linear kinematics give,
//! and what relative-motion amplitude the measured velocity would need (issue 29, Hermundstad & Moan 2005).
//!
//! For a regular relative motion s(t) = |s_a| cos(w_e t + phi) the relative velocity is at most
//! |s_a| w_e, so a measured velocity v_m at the encounter frequency needs |s_a| >= v_m / w_e: a relative-
//! motion RAO |s_a| / zeta_a of at least v_m / (w_e zeta_a). Comparing that with the RAO strip theory
//! gives for the station says which reading of the wave the kinematics can support.

use serde::Serialize;

use super::entry_definitions::{self, Target, Variant};
use crate::error::{Error, Result};
use crate::hull::{Hull, LoadingCondition};
use crate::sea::{G, RegularWave};

/// One reading of the wave.
#[derive(Debug, Clone)]
pub struct Reading {
    pub label: String,
    /// Wave amplitude zeta_a under this reading (m).
    pub amplitude_m: f64,
    pub period_s: f64,
}

/// The chain under one reading.
#[derive(Debug, Clone, Serialize)]
pub struct ReadingRow {
    pub reading: String,
    pub wave_amplitude_m: f64,
    pub period_s: f64,
    pub encounter_frequency_rad_per_s: f64,
    pub draft_m: f64,
    pub relative_motion_amplitude_m: f64,
    /// |s_a| / zeta_a.
    pub relative_motion_rao: f64,
    /// Amplitude of Ds/Dt (m/s).
    pub relative_velocity_amplitude_m_per_s: f64,
    /// |s_a| w_e (m/s): the largest rate of change of s in the ship frame.
    pub velocity_bound_m_per_s: f64,
    pub keel_entry_velocity_m_per_s: Option<f64>,
    pub flare_impact_velocity_m_per_s: Option<f64>,
    /// Flare impact after keel entry (s), where both happen.
    pub flare_delay_after_keel_s: Option<f64>,
    /// v_m / w_e (m): the relative-motion amplitude the measured velocity needs.
    pub needed_amplitude_m: f64,
    /// v_m / (w_e zeta_a).
    pub needed_rao: f64,
}

/// The wave of `amplitude_m` and `period_s` (deep water).
pub fn wave(label: &str, amplitude_m: f64, period_s: f64) -> Result<RegularWave> {
    if !(amplitude_m > 0.0 && period_s > 0.0 && amplitude_m.is_finite() && period_s.is_finite()) {
        return Err(Error::Invalid(format!(
            "wave reading '{label}': amplitude and period must be positive, got {amplitude_m} m, {period_s} s"
        )));
    }
    let omega = 2.0 * std::f64::consts::PI / period_s;
    Ok(RegularWave {
        name: label.to_string(),
        height_m: 2.0 * amplitude_m,
        omega,
        period_s,
        wavelength_m: 2.0 * std::f64::consts::PI * G / (omega * omega),
    })
}

/// The chain at station `aft_of_fp` of `hull` in `loading` at `speed` under each reading, with the
/// panel's lower edge `panel_height_m` above the keel and the measured velocity `measured_m_per_s`.
pub fn readings(
    hull: &Hull,
    loading: &LoadingCondition,
    aft_of_fp: f64,
    panel_height_m: f64,
    speed: f64,
    readings: &[Reading],
    measured_m_per_s: f64,
) -> Result<Vec<ReadingRow>> {
    readings
        .iter()
        .map(|rd| {
            let w = wave(&rd.label, rd.amplitude_m, rd.period_s)?;
            let target = |h: f64| Target {
                label: rd.label.clone(),
                hull,
                loading,
                wave: &w,
                speed,
                aft_of_fp,
                height_above_keel: h,
                fixed_wave: true,
            };
            let keel = entry_definitions::evaluate(&target(0.0), &Variant::default())?;
            let flare = entry_definitions::evaluate(&target(panel_height_m), &Variant::default())?;
            let we = keel.encounter_frequency_rad_per_s;
            let delay = match (keel.crossing_time_s, flare.crossing_time_s) {
                (Some(k), Some(f)) => Some((f - k).rem_euclid(2.0 * std::f64::consts::PI / we)),
                _ => None,
            };
            Ok(ReadingRow {
                reading: rd.label.clone(),
                wave_amplitude_m: rd.amplitude_m,
                period_s: rd.period_s,
                encounter_frequency_rad_per_s: we,
                draft_m: keel.draft_m,
                relative_motion_amplitude_m: keel.relative_motion_amplitude_m,
                relative_motion_rao: keel.relative_motion_amplitude_m / rd.amplitude_m,
                relative_velocity_amplitude_m_per_s: keel.relative_velocity_amplitude_m_per_s,
                velocity_bound_m_per_s: keel.relative_motion_amplitude_m * we,
                keel_entry_velocity_m_per_s: keel.crossing_velocity_m_per_s,
                flare_impact_velocity_m_per_s: flare.crossing_velocity_m_per_s,
                flare_delay_after_keel_s: delay,
                needed_amplitude_m: measured_m_per_s / we,
                needed_rao: measured_m_per_s / (we * rd.amplitude_m),
            })
        })
        .collect()
}

/// The rows as a Markdown table, with the measured velocity and delay of flare impact after keel entry
/// in the last row.
pub fn markdown(rows: &[ReadingRow], measured_m_per_s: f64, measured_delay_s: f64) -> String {
    let opt =
        |v: Option<f64>, p: usize| v.map_or("not reached".to_string(), |v| format!("{v:.p$}"));
    let mut out = "| reading | ζ_a (m) | T (s) | ω_e (rad/s) | local draft (m) | \\|s_a\\| (m) | \\|s_a\\|/ζ_a | \
                   \\|Ds/Dt\\| (m/s) | \\|s_a\\| ω_e (m/s) | keel entry (m/s) | flare impact (m/s) | flare after keel (s) | \
                   \\|s_a\\| needed (m) | \\|s_a\\|/ζ_a needed | needed / computed |\n\
                   |---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n"
        .to_string();
    for r in rows {
        out += &format!(
            "| {} | {:.4} | {:.3} | {:.3} | {:.3} | {:.4} | {:.2} | {:.3} | {:.3} | {} | {} | {} | {:.4} | {:.2} | {:.2} |\n",
            r.reading,
            r.wave_amplitude_m,
            r.period_s,
            r.encounter_frequency_rad_per_s,
            r.draft_m,
            r.relative_motion_amplitude_m,
            r.relative_motion_rao,
            r.relative_velocity_amplitude_m_per_s,
            r.velocity_bound_m_per_s,
            opt(r.keel_entry_velocity_m_per_s, 3),
            opt(r.flare_impact_velocity_m_per_s, 3),
            opt(r.flare_delay_after_keel_s, 3),
            r.needed_amplitude_m,
            r.needed_rao,
            r.needed_amplitude_m / r.relative_motion_amplitude_m,
        );
    }
    out += &format!(
        "| measured (Hermundstad & Moan 2005, via Veen 2010) | | | | | | | | | | {measured_m_per_s} | {measured_delay_s} | | | |\n"
    );
    out
}
