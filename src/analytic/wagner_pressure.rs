//! Wagner's pressure distribution on a wedge entering calm water at constant speed: the composite of
//! the outer (flat-plate) solution and the inner jet-root solution, so that a pressure sensor of finite
//! width and a filtered time history can be compared like for like with SPH.
//!
//! Sources: Wagner (1932); Zhao & Faltinsen (1993), J. Fluid Mech. 246, 593-612, section 2 (outer and
//! jet-root solutions and their composite); Faltinsen (2005), Hydrodynamics of High-Speed Marine
//! Vehicles, chapter 8. With x the horizontal distance from the keel, c(t) the wetted half-width
//! (`wagner::wetted_half_width`) and c' = dc/dt = (pi/2) V cot(beta):
//!
//! * outer (|x| < c): p_o = rho V c c' / sqrt(c^2 - x^2);
//! * inner (jet root), parametric in tau > 0 with jet thickness delta = pi V^2 c / (8 c'^2):
//!   x - c = (delta/pi) (-ln tau - 4 sqrt(tau) - tau + 5),  p_i = (rho c'^2 / 2) 4 sqrt(tau) / (1 + sqrt(tau))^2;
//! * common part (outer near x = c, inner far from the root): p_c = rho V c' sqrt(c / (2 (c - x)));
//! * composite: p = p_o + p_i - p_c for |x| < c, p = p_i on the jet (|x| >= c).
//!
//! At x = c the composite is rho c'^2 / 2, the Wagner Cp_max = (pi^2/4) cot^2(beta) of
//! [`crate::analytic::wagner::peak_pressure_coefficient`]; its maximum lies just inside x = c and is about
//! 1.4 % higher (the outer-minus-common part is still positive there). Linear theory: valid for small deadrise; at
//! 20 deg Wagner's peak is about 5 % above the similarity solution (data/reference/water_entry_theory.md).

use crate::error::Result;
use std::f64::consts::PI;

/// A wedge of deadrise `beta` (rad) entering water of density `rho` at constant speed `v`. The deadrise
/// must lie strictly between 0 and 90 deg (flat plate: unbounded; vertical: no wetted width):
/// [`WagnerWedge::new`] checks it; a value built field by field outside that range gives infinite or
/// zero c'.
#[derive(Debug, Clone, Copy)]
pub struct WagnerWedge {
    pub beta: f64,
    pub rho: f64,
    pub v: f64,
}

impl WagnerWedge {
    /// A wedge with its deadrise checked ([`crate::analytic::wagner::cot_deadrise`]).
    pub fn new(beta: f64, rho: f64, v: f64) -> Result<Self> {
        crate::analytic::wagner::cot_deadrise(beta)?;
        Ok(Self { beta, rho, v })
    }

    /// dc/dt = (pi/2) V cot(beta).
    pub fn c_dot(&self) -> f64 {
        0.5 * PI * self.v / self.beta.tan()
    }

    /// Wetted half-width c(t) = (pi/2) V t cot(beta).
    pub fn c(&self, t: f64) -> f64 {
        self.c_dot() * t
    }

    /// Jet-root thickness delta = pi V^2 c / (8 c'^2) at time t.
    pub fn jet_thickness(&self, t: f64) -> f64 {
        let cd = self.c_dot();
        PI * self.v * self.v * self.c(t) / (8.0 * cd * cd)
    }

    /// Composite pressure (Pa) at horizontal distance `x` from the keel at time `t`.
    pub fn pressure(&self, t: f64, x: f64) -> f64 {
        let c = self.c(t);
        if c <= 0.0 {
            return 0.0;
        }
        let x = x.abs();
        let cd = self.c_dot();
        let delta = self.jet_thickness(t);
        let inner = 0.5 * self.rho * cd * cd * jet_root_shape(PI * (x - c) / delta);
        if x >= c {
            return inner;
        }
        let gap = c - x;
        // Outer minus common part, written so that the two square-root singularities cancel exactly:
        // rho V c' [c / sqrt(c + x) - sqrt(c / 2)] / sqrt(c - x), which tends to 0 as x -> c.
        let a = c / (c + x).sqrt();
        let b = (0.5 * c).sqrt();
        let outer_minus_common = self.rho * self.v * cd * (a - b) / gap.sqrt();
        outer_minus_common + inner
    }

    /// Mean pressure over x in [x0, x1] at time t (midpoint rule, `n` points).
    pub fn mean_pressure(&self, t: f64, x0: f64, x1: f64, n: usize) -> f64 {
        let n = n.max(1);
        let dx = (x1 - x0) / n as f64;
        (0..n)
            .map(|k| self.pressure(t, x0 + (k as f64 + 0.5) * dx))
            .sum::<f64>()
            / n as f64
    }

    /// History at the times `t` of the mean pressure over a sensor of width `width` along the wedge side
    /// centred at arc length `s` from the keel (x = s cos(beta) along the side).
    pub fn sensor_history(&self, s: f64, width: f64, t: &[f64]) -> Vec<f64> {
        let cb = self.beta.cos();
        let (x0, x1) = ((s - 0.5 * width) * cb, (s + 0.5 * width) * cb);
        t.iter()
            .map(|&tk| self.mean_pressure(tk, x0, x1, 100))
            .collect()
    }
}

/// p_i / (rho c'^2 / 2) = 4 s / (1 + s)^2 with s = sqrt(tau) solving
/// xi = -2 ln s - 4 s - s^2 + 5 (xi = pi (x - c) / delta). The right side falls monotonically from +inf
/// to -inf as ln s goes from -inf to +inf, so bisection on ln s finds the root.
fn jet_root_shape(xi: f64) -> f64 {
    let f = |u: f64| {
        let s = u.exp();
        -2.0 * u - 4.0 * s - s * s + 5.0
    };
    let (mut lo, mut hi) = (-200.0, 50.0);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > xi {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    let s = (0.5 * (lo + hi)).exp();
    4.0 * s / ((1.0 + s) * (1.0 + s))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analytic::wagner;

    fn wedge(deg: f64) -> WagnerWedge {
        WagnerWedge::new(deg.to_radians(), 1000.0, 5.0).unwrap()
    }

    #[test]
    fn flat_and_vertical_wedges_are_refused() {
        assert!(WagnerWedge::new(0.0, 1000.0, 5.0).is_err());
        assert!(WagnerWedge::new(0.5 * PI, 1000.0, 5.0).is_err());
    }

    #[test]
    fn peak_is_wagner_cp_at_the_wetted_half_width() {
        for deg in [20.0, 30.0] {
            let w = wedge(deg);
            let t = 0.01;
            let c = w.c(t);
            assert!((c - wagner::wetted_half_width(w.beta, 5.0, t).unwrap()).abs() < 1e-12);
            let q = 0.5 * 1000.0 * 25.0;
            let cp_peak = w.pressure(t, c) / q;
            let cp = wagner::peak_pressure_coefficient(w.beta).unwrap();
            assert!((cp_peak / cp - 1.0).abs() < 1e-9, "{cp_peak} vs {cp}");
            // The largest composite pressure lies just inside x = c (where the outer-minus-common part
            // is still positive), a little above the Wagner value.
            let p_max = (0..4000)
                .map(|k| w.pressure(t, 1.2 * c * k as f64 / 4000.0))
                .fold(0.0, f64::max);
            let excess = p_max / w.pressure(t, c) - 1.0;
            assert!((0.0..0.02).contains(&excess), "{deg} deg: {excess}");
        }
    }

    #[test]
    fn inner_solution_matches_the_outer_one_away_from_the_root() {
        // Far from the root on the wetted side (c - x >> delta, x not near the keel) the composite is
        // close to the outer solution. delta / c = tan^2(beta) / (2 pi): a small deadrise gives room.
        let w = wedge(5.0);
        let t = 0.01;
        let c = w.c(t);
        let delta = w.jet_thickness(t);
        let x = c - 200.0 * delta;
        assert!(x > 0.0);
        let outer = 1000.0 * 5.0 * w.c_dot() * c / (c * c - x * x).sqrt();
        let p = w.pressure(t, x);
        assert!((p / outer - 1.0).abs() < 0.02, "{p} vs outer {outer}");
        // On the jet the pressure falls towards zero.
        assert!(w.pressure(t, c + 50.0 * delta) < 0.01 * w.pressure(t, c));
    }

    #[test]
    fn averaging_over_a_width_lowers_the_peak() {
        let w = wedge(30.0);
        let t = 0.005;
        let c = w.c(t);
        let p_peak = w.pressure(t, c);
        let narrow = w.mean_pressure(t, c - 1e-5, c + 1e-5, 50);
        let wide = w.mean_pressure(t, c - 5e-3, c + 5e-3, 400);
        assert!((narrow / p_peak - 1.0).abs() < 1e-3);
        assert!(wide < narrow);
    }
}
