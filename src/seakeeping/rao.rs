//! Response amplitude operators over wave frequency, in the forms towing-tank tables use, and time
//! histories in regular waves.

use nalgebra::Complex;

use super::ShipModel;
use super::strip_theory::{self, Response, SectionSolutions};
use crate::error::Result;

/// One row of an RAO table (per unit wave amplitude).
#[derive(Debug, Clone, Copy, serde::Serialize)]
pub struct RaoRow {
    #[serde(rename = "wave_frequency_rad_per_s")]
    pub omega0: f64,
    #[serde(rename = "encounter_frequency_rad_per_s")]
    pub omega_e: f64,
    #[serde(rename = "wavelength_m")]
    pub wavelength: f64,
    pub lambda_over_l: f64,
    /// |eta3| / zeta_a.
    #[serde(rename = "heave_over_wave_amplitude")]
    pub heave: f64,
    /// Heave phase lead relative to the wave crest at midship (deg).
    pub heave_phase_deg: f64,
    /// |eta5| / (k zeta_a).
    #[serde(rename = "pitch_over_wave_slope")]
    pub pitch_over_k: f64,
    /// |eta5| L / (2 pi zeta_a), the nondimensional pitch of Journee (1992).
    #[serde(rename = "pitch_lpp_over_2pi_wave_amplitude")]
    pub pitch_nd: f64,
    pub pitch_phase_deg: f64,
}

impl RaoRow {
    pub fn from_response(r: &Response, lpp: f64) -> Self {
        let lambda = 2.0 * std::f64::consts::PI / r.wave_number;
        Self {
            omega0: r.omega0,
            omega_e: r.omega_e,
            wavelength: lambda,
            lambda_over_l: lambda / lpp,
            heave: r.heave.norm(),
            heave_phase_deg: r.heave.arg().to_degrees(),
            pitch_over_k: r.pitch.norm() / r.wave_number,
            pitch_nd: r.pitch.norm() * lpp / (2.0 * std::f64::consts::PI),
            pitch_phase_deg: r.pitch.arg().to_degrees(),
        }
    }
}

/// Wave frequency of a wavelength ratio in deep water.
pub fn omega_of_lambda_over_l(lambda_over_l: f64, lpp: f64, g: f64) -> f64 {
    (g * 2.0 * std::f64::consts::PI / (lambda_over_l * lpp)).sqrt()
}

/// Responses at a list of wave frequencies (each frequency solved on its own; deterministic).
pub fn responses<S: SectionSolutions + ?Sized>(
    model: &ShipModel,
    speed: f64,
    omegas0: &[f64],
    sections: &S,
) -> Result<Vec<Response>> {
    omegas0
        .iter()
        .map(|&w| strip_theory::respond(model, w, speed, sections))
        .collect()
}

/// Heave (m) and pitch (rad) at time t in a regular wave of amplitude `zeta_a`.
pub fn time_history(r: &Response, zeta_a: f64, t: f64) -> (f64, f64) {
    let e = Complex::new(0.0, r.omega_e * t).exp();
    ((r.heave * e).re * zeta_a, (r.pitch * e).re * zeta_a)
}
