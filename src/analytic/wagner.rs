//! Wagner (1932) theory for a wedge of deadrise beta entering at constant speed V
//! (formulas as collected in `data/reference/water_entry_theory.md`):
//!
//! * wetted half-width c(t) = (pi/2) V t / tan(beta)
//! * peak pressure coefficient Cp_max = 2 p_max / (rho V^2) = (pi^2/4) cot^2(beta); the composite form
//!   1 + (pi^2/4) cot^2(beta) is given by [`composite_peak_pressure_coefficient`]
//! * vertical force per unit length F = (pi^3/4) rho V^3 t cot^2(beta)

use std::f64::consts::PI;

/// Cp_max = (pi^2/4) cot^2(beta).
pub fn peak_pressure_coefficient(beta: f64) -> f64 {
    let cot = 1.0 / beta.tan();
    0.25 * PI * PI * cot * cot
}

/// Cp_max = 1 + (pi^2/4) cot^2(beta) (composite form quoted by some texts).
pub fn composite_peak_pressure_coefficient(beta: f64) -> f64 {
    1.0 + peak_pressure_coefficient(beta)
}

/// Wetted half-width c(t) = (pi/2) V t / tan(beta).
pub fn wetted_half_width(beta: f64, v: f64, t: f64) -> f64 {
    0.5 * PI * v * t / beta.tan()
}

/// Vertical force per unit length F = (pi^3/4) rho V^3 t cot^2(beta).
pub fn force(beta: f64, rho: f64, v: f64, t: f64) -> f64 {
    let cot = 1.0 / beta.tan();
    0.25 * PI.powi(3) * rho * v.powi(3) * t * cot * cot
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tabulated_values() {
        // data/reference/water_entry_theory.md: 34.37 at 15 deg, 18.63 at 20 deg, 7.402 at 30 deg.
        for (deg, cp) in [(15.0f64, 34.37), (20.0, 18.63), (30.0, 7.402)] {
            let v = peak_pressure_coefficient(deg.to_radians());
            assert!((v - cp).abs() < 0.01, "{deg}: {v}");
        }
        // Seed check: 37 deg flare struck at 1.4 m/s gives about 4.26 kPa.
        let p = 0.5 * 1000.0 * 1.4f64.powi(2) * peak_pressure_coefficient(37f64.to_radians());
        assert!((p - 4260.0).abs() < 20.0, "{p}");
    }
}
