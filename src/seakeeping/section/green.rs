//! The two-dimensional pulsating-source Green function for deep water (Wehausen & Laitone 1960, eq. 13.31;
//! the form used by Frank 1967), time factor e^{i w t}, z up, fluid in z < 0.
//!
//! For a source of unit strength at (eta, zeta) and a field point (y, z), with r1 the distance to the source,
//! r2 the distance to its image (eta, -zeta), nu = w^2/g and W = (z + zeta) + i (y - eta):
//!
//! G = ln r1 - ln r2 + 2 PV int_0^inf e^{k(z+zeta)} cos k(y-eta) / (nu - k) dk + 2 pi i e^{nu(z+zeta)} cos nu(y-eta)
//!
//! The imaginary part makes the far field an outgoing wave e^{i(w t - nu|y|)}. With
//! F(W) = PV int_0^inf e^{kW}/(k - nu) dk = e^{nu W} [E1(nu W) + i pi sgn(Im W)] the real part is
//! ln r1 - ln r2 - 2 Re F(W). For panel integration the logarithms are split off:
//!
//! G = ln r1 + ln r2 + R(W) + i Gi,   R = -2 Re F(W) - 2 ln|W|,   Gi = 2 pi e^{nu(z+zeta)} cos nu(y-eta),
//!
//! where R is continuous (it tends to 2 gamma + 2 ln nu as W -> 0) and dF/dW = nu F - 1/W gives
//! dR/dy = 2 nu Im F, dR/dz = -2 nu Re F (derivatives with respect to the field point).

use nalgebra::Complex;

type C64 = Complex<f64>;

const EULER_GAMMA: f64 = 0.577_215_664_901_532_9;

/// 1/n for n = 0..400 (entry 0 unused): the terms of the E1 power series.
const RECIPROCALS: [f64; 400] = {
    let mut r = [0.0; 400];
    let mut n = 1;
    while n < 400 {
        r[n] = 1.0 / n as f64;
        n += 1;
    }
    r
};

/// Exponential integral E1(z) for complex z off the negative real axis (principal branch; on the axis the
/// branch follows the sign of the zero imaginary part). Power series near the origin and in the left half
/// plane, where its terms do not cancel; continued fraction (Abramowitz & Stegun 5.1.22) elsewhere.
pub fn e1(z: C64) -> C64 {
    // Squared norms and ln|z| = ln(|z|^2) / 2 keep hypot out of the function (it dominates `motions`).
    let r2 = z.norm_sqr();
    if r2 < 64.0 || z.re < -z.im.abs() {
        // E1(z) = -gamma - ln z - sum_{n>=1} (-z)^n / (n n!)   (A&S 5.1.11)
        let mut sum = C64::new(0.0, 0.0);
        let mut term = C64::new(1.0, 0.0);
        let minus_z = -z;
        for &inv_n in &RECIPROCALS[1..] {
            // Multiplications by 1/n instead of divisions by n: this loop dominates `motions`.
            term = minus_z * term * inv_n;
            let add = term * inv_n;
            sum += add;
            // Squared norms: the same test without a hypot per term (this loop dominates `motions`).
            if add.norm_sqr() < 1e-34 * sum.norm_sqr().max(1e-300) {
                break;
            }
        }
        let ln_z = C64::new(0.5 * r2.ln(), z.im.atan2(z.re));
        -EULER_GAMMA - ln_z - sum
    } else {
        // Modified Lentz evaluation of e^{-z} / (z + 1 - 1/(z + 3 - 4/(z + 5 - ...)))
        let tiny = 1e-300;
        let mut b = z + 1.0;
        let mut c = C64::new(1.0 / tiny, 0.0);
        let mut d = C64::new(1.0, 0.0) / b;
        let mut h = d;
        for i in 1..2000 {
            let an = -((i * i) as f64);
            b += 2.0;
            d = C64::new(1.0, 0.0) / (d * an + b);
            c = b + C64::new(an, 0.0) / c;
            let del = c * d;
            h *= del;
            if (del - 1.0).norm_sqr() < 1e-32 {
                break;
            }
        }
        h * (-z).exp()
    }
}

/// F(W) = PV int_0^inf e^{kW}/(k - nu) dk for Re W <= 0, W != 0.
pub fn wave_integral(nu: f64, w: C64) -> C64 {
    let z = w * nu;
    let sgn = if z.im.is_sign_negative() { -1.0 } else { 1.0 };
    z.exp() * (e1(z) + C64::new(0.0, std::f64::consts::PI * sgn))
}

/// Regular part of the Green function and its gradient at field point `p` = (y, z) for a source at
/// `q` = (eta, zeta): returns (R + i Gi, [d/dy, d/dz] of R + i Gi). See the module docs.
pub fn regular_part(nu: f64, p: [f64; 2], q: [f64; 2]) -> (C64, [C64; 2]) {
    let dy = p[0] - q[0];
    let sz = p[1] + q[1];
    let w = C64::new(sz, dy);
    let gi = 2.0 * std::f64::consts::PI * (nu * sz).exp();
    let (gi_val, gi_dy, gi_dz) = (
        gi * (nu * dy).cos(),
        -gi * nu * (nu * dy).sin(),
        nu * gi * (nu * dy).cos(),
    );
    let r2 = w.norm_sqr();
    if r2 < 1e-24 {
        let val = 2.0 * EULER_GAMMA + 2.0 * nu.ln();
        return (
            C64::new(val, gi_val),
            [C64::new(0.0, gi_dy), C64::new(0.0, gi_dz)],
        );
    }
    let f = wave_integral(nu, w);
    // -2 ln r = -ln r^2.
    let rr = -2.0 * f.re - r2.ln();
    (
        C64::new(rr, gi_val),
        [
            C64::new(2.0 * nu * f.im, gi_dy),
            C64::new(-2.0 * nu * f.re, gi_dz),
        ],
    )
}

/// x ln x with the limit 0 at x = 0.
fn xlnx(x: f64) -> f64 {
    if x.abs() < 1e-300 {
        0.0
    } else {
        x * x.abs().ln()
    }
}

/// Integral of ln|p - s| over the straight panel s in [a, b] and its gradient with respect to p
/// (Hess & Smith 1964 closed forms). `fluid_side` gives the limit of the normal component when p lies on
/// the panel: +1 means the side the panel's left-hand normal points to, -1 the other side.
pub fn log_panel(p: [f64; 2], a: [f64; 2], b: [f64; 2], fluid_side: f64) -> (f64, [f64; 2]) {
    let len = ((b[0] - a[0]).powi(2) + (b[1] - a[1]).powi(2)).sqrt();
    let t = [(b[0] - a[0]) / len, (b[1] - a[1]) / len];
    let n = [-t[1], t[0]];
    let rel = [p[0] - a[0], p[1] - a[1]];
    let u = rel[0] * t[0] + rel[1] * t[1];
    let v = rel[0] * n[0] + rel[1] * n[1];
    let ra2 = u * u + v * v;
    let rb2 = (u - len).powi(2) + v * v;
    // subtended angle, signed like v: atan2(cross, dot) of the vectors from p to a and to b
    let dot = -u * (len - u) + v * v;
    let theta = if v.abs() < 1e-12 * len {
        if u > 0.0 && u < len {
            std::f64::consts::PI * fluid_side
        } else {
            0.0
        }
    } else {
        (v * len).atan2(dot)
    };
    let value = if ra2 < 1e-300 || rb2 < 1e-300 {
        xlnx(len) - len
    } else {
        0.5 * ((len - u) * rb2.ln() + u * ra2.ln()) - len + v * theta
    };
    let lnratio = if ra2 < 1e-300 || rb2 < 1e-300 {
        0.0
    } else {
        0.5 * (ra2 / rb2).ln()
    };
    let grad = [lnratio * t[0] + theta * n[0], lnratio * t[1] + theta * n[1]];
    (value, grad)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::numerics::quadrature::gauss_legendre;

    /// Direct numerical PV integral for comparison.
    fn pv_direct(nu: f64, w: C64) -> C64 {
        let (x, wt) = gauss_legendre(64);
        let mut s = C64::new(0.0, 0.0);
        // [0, 2 nu] with the pole subtracted (the PV of 1/(k - nu) over a symmetric interval is zero)
        let en = (w * nu).exp();
        for (xi, wi) in x.iter().zip(&wt) {
            let k = nu + nu * xi;
            let d = k - nu;
            let f = if d.abs() < 1e-14 {
                w * en
            } else {
                ((w * k).exp() - en) / d
            };
            s += f * (wi * nu);
        }
        // [2 nu, inf): k = 2 nu + t, split in blocks
        let mut a = 2.0 * nu;
        for _ in 0..60 {
            let h = 1.0 / (-w.re).max(0.05);
            for (xi, wi) in x.iter().zip(&wt) {
                let k = a + 0.5 * h * (xi + 1.0);
                s += (w * k).exp() / (k - nu) * (0.5 * h * wi);
            }
            a += h;
        }
        s
    }

    #[test]
    fn wave_integral_matches_direct_quadrature() {
        for &(nu, zr, y) in &[
            (1.0, -0.3, 0.7),
            (2.5, -1.2, -0.4),
            (0.7, -2.0, 0.0),
            (4.0, -0.5, 3.0),
        ] {
            let w = C64::new(zr, y);
            let a = wave_integral(nu, w);
            let b = pv_direct(nu, w);
            assert!(
                (a - b).norm() < 1e-6 * (1.0 + b.norm()),
                "nu {nu} W {w}: {a} vs {b}"
            );
        }
    }

    #[test]
    fn e1_series_and_fraction_agree() {
        for &z in &[
            C64::new(7.9, 2.0),
            C64::new(-3.0, 7.9),
            C64::new(0.5, -7.95),
        ] {
            let s = {
                let mut sum = C64::new(0.0, 0.0);
                let mut term = C64::new(1.0, 0.0);
                for n in 1..200 {
                    term *= -z / n as f64;
                    sum += term / n as f64;
                }
                -EULER_GAMMA - z.ln() - sum
            };
            assert!((e1(z) - s).norm() < 1e-9 * s.norm().max(1e-3));
        }
        // continued fraction branch at |z| > 8 against the asymptotic check E1(z) ~ e^-z/z (1 - 1/z + 2/z^2)
        let z = C64::new(30.0, 5.0);
        let asym = (-z).exp() / z * (1.0 - 1.0 / z + 2.0 / (z * z) - 6.0 / (z * z * z));
        assert!((e1(z) - asym).norm() < 1e-4 * asym.norm());
    }

    #[test]
    fn log_panel_gradient_is_the_derivative_of_the_value() {
        let a = [0.1, -0.5];
        let b = [0.4, -0.2];
        for &p in &[[0.3, -0.1], [-0.2, -0.6], [0.5, -0.45]] {
            let (_, g) = log_panel(p, a, b, 1.0);
            let h = 1e-6;
            let fy = (log_panel([p[0] + h, p[1]], a, b, 1.0).0
                - log_panel([p[0] - h, p[1]], a, b, 1.0).0)
                / (2.0 * h);
            let fz = (log_panel([p[0], p[1] + h], a, b, 1.0).0
                - log_panel([p[0], p[1] - h], a, b, 1.0).0)
                / (2.0 * h);
            assert!(
                (g[0] - fy).abs() < 1e-6 && (g[1] - fz).abs() < 1e-6,
                "{p:?}: {g:?} vs {fy} {fz}"
            );
        }
    }
}
