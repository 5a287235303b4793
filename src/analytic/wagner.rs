//! Wagner (1932) theory for a wedge of deadrise beta entering at constant speed V
//! (formulas as collected in `data/reference/water_entry_theory.md`):
//!
//! * wetted half-width c(t) = (pi/2) V t / tan(beta)
//! * peak pressure coefficient Cp_max = 2 p_max / (rho V^2) = (pi^2/4) cot^2(beta); the composite form
//!   1 + (pi^2/4) cot^2(beta) is given by [`composite_peak_pressure_coefficient`]
//! * vertical force per unit length F = (pi^3/4) rho V^3 t cot^2(beta)
//! * free drop of a wedge of mass m per metre (momentum form, von Karman 1929 with Wagner's wetted width;
//!   e.g. Faltinsen 2005, Hydrodynamics of High-Speed Marine Vehicles, section 8.2): the added mass of the
//!   flat-plate approximation m_a = (pi/2) rho c^2 with c = (pi/2) z cot(beta) at penetration z, and
//!   d/dt [(m + m_a(z)) V] = m g, dz/dt = V.

//!
//! Every function takes the deadrise in radians and returns an error outside 0 < beta < 90 deg (see
//! [`cot_deadrise`]) instead of an infinite or meaningless value.

use crate::error::{Error, Result};
use std::f64::consts::PI;

/// cot(beta) of a wedge deadrise, or an error unless 0 < beta < 90 deg: at 0 deg (a flat plate) Wagner's
/// and von Karman's values are unbounded (see `generalised_wagner` for the acoustic limit of a flat
/// keel), at 90 deg (a vertical plate) there is no wetted width.
pub fn cot_deadrise(beta: f64) -> Result<f64> {
    if beta > 0.0 && beta < 0.5 * PI {
        Ok(1.0 / beta.tan())
    } else {
        Err(Error::Invalid(format!(
            "wedge formulas need a deadrise strictly between 0 and 90 deg, got {} deg",
            beta.to_degrees()
        )))
    }
}

/// Cp_max = (pi^2/4) cot^2(beta).
pub fn peak_pressure_coefficient(beta: f64) -> Result<f64> {
    let cot = cot_deadrise(beta)?;
    Ok(0.25 * PI * PI * cot * cot)
}

/// Cp_max = 1 + (pi^2/4) cot^2(beta) (composite form quoted by some texts).
pub fn composite_peak_pressure_coefficient(beta: f64) -> Result<f64> {
    Ok(1.0 + peak_pressure_coefficient(beta)?)
}

/// Wetted half-width c(t) = (pi/2) V t / tan(beta).
pub fn wetted_half_width(beta: f64, v: f64, t: f64) -> Result<f64> {
    Ok(0.5 * PI * v * t * cot_deadrise(beta)?)
}

/// Vertical force per unit length F = (pi^3/4) rho V^3 t cot^2(beta).
pub fn force(beta: f64, rho: f64, v: f64, t: f64) -> Result<f64> {
    let cot = cot_deadrise(beta)?;
    Ok(0.25 * PI.powi(3) * rho * v.powi(3) * t * cot * cot)
}

/// Downward speed of a freely falling wedge (mass `mass_per_m` per metre, entry speed `v0`) at the times
/// `t` (ascending, from 0), from the momentum form above, integrated with steps of at most `dt_max`
/// (midpoint rule). This is [`free_drop_speed_scaled`] with the factor 1.
pub fn free_drop_speed(
    beta: f64,
    rho: f64,
    mass_per_m: f64,
    v0: f64,
    g: f64,
    t: &[f64],
    dt_max: f64,
) -> Result<Vec<f64>> {
    free_drop_speed_scaled(beta, rho, mass_per_m, v0, g, t, dt_max, 1.0)
}

/// [`free_drop_speed`] with the added mass scaled by `factor`: d/dt [(M + k m_a(zeta)) V] = M g with
/// m_a = (pi/2) rho c^2 and Wagner's c = (pi/2) zeta / tan(beta) (zeta the keel's penetration). k = 1 is
/// Wagner's momentum model; k = (2/pi)^2 = 0.405 is von Karman's (c = zeta / tan(beta)). Any momentum
/// model whose added mass grows like zeta^2 (every similarity solution of a wedge) is one of this family.
#[allow(clippy::too_many_arguments)]
pub fn free_drop_speed_scaled(
    beta: f64,
    rho: f64,
    mass_per_m: f64,
    v0: f64,
    g: f64,
    t: &[f64],
    dt_max: f64,
    factor: f64,
) -> Result<Vec<f64>> {
    let k = 0.5 * PI * cot_deadrise(beta)?;
    let added = |z: f64| factor * 0.5 * PI * rho * (k * z) * (k * z);
    let speed = |momentum: f64, z: f64| momentum / (mass_per_m + added(z));
    let (mut time, mut z, mut momentum) = (0.0, 0.0, mass_per_m * v0);
    let mut out = Vec::with_capacity(t.len());
    for &tk in t {
        while time < tk - 1e-15 {
            let dt = dt_max.min(tk - time);
            let zm = z + 0.5 * dt * speed(momentum, z);
            let pm = momentum + 0.5 * dt * mass_per_m * g;
            z += dt * speed(pm, zm);
            momentum += dt * mass_per_m * g;
            time += dt;
        }
        out.push(speed(momentum, z));
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tabulated_values() {
        // data/reference/water_entry_theory.md: 34.37 at 15 deg, 18.63 at 20 deg, 7.402 at 30 deg.
        for (deg, cp) in [(15.0f64, 34.37), (20.0, 18.63), (30.0, 7.402)] {
            let v = peak_pressure_coefficient(deg.to_radians()).unwrap();
            assert!((v - cp).abs() < 0.01, "{deg}: {v}");
        }
        // Seed check: 37 deg flare struck at 1.4 m/s gives about 4.26 kPa.
        let p =
            0.5 * 1000.0 * 1.4f64.powi(2) * peak_pressure_coefficient(37f64.to_radians()).unwrap();
        assert!((p - 4260.0).abs() < 20.0, "{p}");
    }

    #[test]
    fn free_drop_conserves_momentum_without_gravity() {
        // With g = 0: (m + m_a(z)) V = m V0 at every instant, z = integral of V.
        let (beta, m, v0) = (30f64.to_radians(), 241.0, 6.15);
        let t: Vec<f64> = (0..=10).map(|k| k as f64 * 2.5e-3).collect();
        let v = free_drop_speed(beta, 1000.0, m, v0, 0.0, &t, 1e-6).unwrap();
        let mut z = 0.0;
        for k in 1..t.len() {
            z += 0.5 * (v[k] + v[k - 1]) * (t[k] - t[k - 1]);
            let c = 0.5 * PI * z / beta.tan();
            let ma = 0.5 * PI * 1000.0 * c * c;
            assert!(
                ((m + ma) * v[k] / (m * v0) - 1.0).abs() < 2e-3,
                "{k}: {}",
                v[k]
            );
        }
        assert!(v.windows(2).all(|w| w[1] < w[0]));
    }

    #[test]
    fn flat_and_vertical_deadrise_are_errors_not_infinities() {
        for beta in [0.0, -0.1, 0.5 * PI, 2.0, f64::NAN] {
            assert!(peak_pressure_coefficient(beta).is_err());
            assert!(wetted_half_width(beta, 5.0, 0.01).is_err());
            assert!(force(beta, 1000.0, 5.0, 0.01).is_err());
            assert!(free_drop_speed(beta, 1000.0, 100.0, 5.0, 9.81, &[0.0, 0.01], 1e-4).is_err());
        }
    }
}
