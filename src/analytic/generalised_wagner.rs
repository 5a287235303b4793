//! Wagner theory for an arbitrary symmetric section entering with a varying speed V(t) (the flat-plate
//! approximation of Wagner 1932, with the wetting condition solved for the actual shape; see Faltinsen
//! 2005, "Hydrodynamics of High-Speed Marine Vehicles", ch. 8).
//!
//! With the body surface z = f(y) above the keel and the penetration depth d(t):
//!
//! * Wagner condition: integral_0^{pi/2} f(c sin theta) d theta = (pi/2) d
//!   gives the wetted half-width c(d);
//! * force per unit length F = d/dt (rho pi c^2 V / 2) = rho pi (c c' V + c^2 V'/2), c' = dc/dt = V dc/dd;
//! * peak (jet-root) pressure p_max = rho c'^2 / 2 (for a wedge at constant V this is (pi^2/4) cot^2(beta)
//!   rho V^2/2).
//!
//! It holds for moderate deadrise and before flow separation at a knuckle; beyond the chine it is not
//! valid (reported as `None`).

use crate::numerics::Pchip;

/// Wagner estimate along a time history.
#[derive(Debug, Clone)]
pub struct WagnerEstimate {
    pub t: Vec<f64>,
    pub penetration: Vec<f64>,
    pub half_width: Vec<f64>,
    pub force: Vec<f64>,
    pub peak_pressure: Vec<f64>,
}

/// Height of the body surface above the keel at half-breadth y (first crossing from the keel), or `None`
/// above the widest point. `half` is the starboard half of the section, keel first at (0, 0).
fn surface_height(half: &[[f64; 2]], y: f64) -> Option<f64> {
    for w in half.windows(2) {
        let (a, b) = (w[0], w[1]);
        if (a[0] <= y && y <= b[0]) && b[0] > a[0] {
            return Some(a[1] + (y - a[0]) / (b[0] - a[0]) * (b[1] - a[1]));
        }
    }
    None
}

/// Penetration depth at which the wetted half-width is c (the Wagner condition), or `None` past the chine.
pub fn penetration_for_half_width(half: &[[f64; 2]], c: f64) -> Option<f64> {
    let n = 64;
    let (x, w) = crate::numerics::quadrature::gauss_legendre(n);
    let half_pi = std::f64::consts::FRAC_PI_2;
    let mut s = 0.0;
    for k in 0..n {
        let theta = 0.5 * half_pi * (x[k] + 1.0);
        s += 0.5 * half_pi * w[k] * surface_height(half, c * theta.sin())?;
    }
    Some(s / half_pi)
}

/// Wagner estimate for a section (starboard half `half`, keel first at (0, 0)) moving down with speed
/// v(t) (sampled at times `t`, with the same `v`), density rho. Stops where the wetted half-width reaches
/// the widest point of the section.
pub fn estimate(half: &[[f64; 2]], t: &[f64], v: &[f64], rho: f64) -> WagnerEstimate {
    let b = half.iter().map(|p| p[0]).fold(0.0, f64::max);
    // Table d(c) on a fine c grid, inverted to c(d).
    let m = 400;
    let mut cs = Vec::new();
    let mut ds = Vec::new();
    for k in 1..=m {
        let c = b * k as f64 / m as f64;
        if let Some(d) = penetration_for_half_width(half, c) {
            if ds.last().is_none_or(|&last| d > last) {
                cs.push(c);
                ds.push(d);
            }
        }
    }
    let mut out = WagnerEstimate {
        t: Vec::new(),
        penetration: Vec::new(),
        half_width: Vec::new(),
        force: Vec::new(),
        peak_pressure: Vec::new(),
    };
    if ds.len() < 4 || t.len() < 2 {
        return out;
    }
    // Prepend the keel (c = 0 at d = 0).
    cs.insert(0, 0.0);
    ds.insert(0, 0.0);
    let c_of_d = Pchip::new(&ds, &cs);
    let vp = Pchip::new(t, v);
    let d_max = *ds.last().unwrap();
    let mut d = 0.0;
    for k in 0..t.len() {
        if k > 0 {
            let dt = t[k] - t[k - 1];
            d += 0.5 * dt * (v[k] + v[k - 1]);
        }
        if d > d_max {
            break;
        }
        let c = c_of_d.eval(d);
        let dcdt = c_of_d.derivative(d) * v[k];
        let dvdt = vp.derivative(t[k]);
        out.t.push(t[k]);
        out.penetration.push(d);
        out.half_width.push(c);
        out.force
            .push(rho * std::f64::consts::PI * (c * dcdt * v[k] + 0.5 * c * c * dvdt));
        out.peak_pressure.push(0.5 * rho * dcdt * dcdt);
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analytic::wagner;

    #[test]
    fn reproduces_the_wedge_formulas() {
        let beta = 30f64.to_radians();
        let zk = 0.25 * beta.tan();
        let s = [[0.0, 0.0], [0.25, zk], [0.25, 0.29]];
        let t: Vec<f64> = (0..=100).map(|k| k as f64 * 1e-4).collect();
        let v = vec![5.0; t.len()];
        let e = estimate(&s, &t, &v, 1000.0);
        assert!(e.t.len() > 50);
        let k = 50;
        let f = wagner::force(beta, 1000.0, 5.0, e.t[k]);
        assert!((e.force[k] / f - 1.0).abs() < 0.01, "{} vs {f}", e.force[k]);
        let cp = 2.0 * e.peak_pressure[k] / (1000.0 * 25.0);
        assert!(
            (cp / wagner::peak_pressure_coefficient(beta) - 1.0).abs() < 0.01,
            "{cp}"
        );
        let c = wagner::wetted_half_width(beta, 5.0, e.t[k]);
        assert!((e.half_width[k] / c - 1.0).abs() < 0.01);
    }
}
