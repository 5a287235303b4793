//! von Karman (1929) momentum theory for a wedge at constant speed V (no pile-up of the water):
//!
//! * wetted half-width c(t) = V t / tan(beta)
//! * vertical force per unit length F = pi rho V^3 t cot^2(beta)
//!
//! It has no pile-up, so it is a lower bound on the force next to Wagner's (pi^3/4) rho V^3 t cot^2(beta).

//!
//! Both return an error outside 0 < beta < 90 deg ([`crate::analytic::wagner::cot_deadrise`]).

use crate::analytic::wagner::cot_deadrise;
use crate::error::Result;
use std::f64::consts::PI;

/// Wetted half-width c(t) = V t / tan(beta).
pub fn wetted_half_width(beta: f64, v: f64, t: f64) -> Result<f64> {
    Ok(v * t * cot_deadrise(beta)?)
}

/// Vertical force per unit length F = pi rho V^3 t cot^2(beta).
pub fn force(beta: f64, rho: f64, v: f64, t: f64) -> Result<f64> {
    let cot = cot_deadrise(beta)?;
    Ok(PI * rho * v.powi(3) * t * cot * cot)
}
