//! Lewis (1929) conformal mapping with the Ursell (1949) - Tasai (1959) multipole method, heave mode.
//!
//! Mapping of the exterior of the unit circle (lower half, zeta = rho e^{i psi}, psi in (-pi, 0)) onto the
//! fluid outside the section, xi = y + i z:
//!
//! xi = M (zeta + a1/zeta + a3/zeta^3),   B/2 = M (1 + a1 + a3),   T = M (1 - a1 + a3),
//!
//! with a1, a3 from the half-beam-to-draft ratio H = B/(2T) and the area coefficient s = A/(B T)
//! (Lewis 1929; Journee & Adegeest 2003, "Theoretical manual of strip theory program SEAWAY", ch. 3):
//! C1 = 3 + 4s/pi + (1 - 4s/pi) ((H-1)/(H+1))^2, a3 = (3 - C1 + sqrt(9 - 2 C1))/C1, a1 = (H-1)/(H+1) (1 + a3).
//!
//! The heave potential is a wave source at the origin (the Green function of [`super::green`] with the source
//! at (0, 0)) plus symmetric multipoles that each satisfy the free-surface condition phi_z = nu phi
//! (derived for this mapping: on the real zeta axis phi_z = (d phi/d Im zeta)/h with h = dxi/dzeta):
//!
//! w_2m(zeta) = zeta^{-2m} + i nu M [zeta^{-(2m-1)}/(2m-1) - a1 zeta^{-(2m+1)}/(2m+1) - 3 a3 zeta^{-(2m+3)}/(2m+3)],
//! phi_2m = Re w_2m.
//!
//! The complex strengths are found by least squares on d phi/dn = n_z at points of the contour (Tasai's
//! approach); then a33 = -rho Re int phi n_z ds, b33 = w rho Im int phi n_z ds as in the close-fit method.

use nalgebra::{Complex, DMatrix, DVector};

use super::green::regular_part;
use super::{BodySample, HalfSection, Radiation};
use crate::error::{Error, Result};

type C64 = Complex<f64>;

/// Lewis form parameters of a section.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LewisForm {
    pub scale: f64,
    pub a1: f64,
    pub a3: f64,
}

impl LewisForm {
    /// Lewis coefficients from beam, draft and sectional area; an error where no conformal Lewis form exists.
    pub fn fit(beam: f64, draft: f64, area: f64) -> Result<Self> {
        if !(beam > 0.0 && draft > 0.0 && area > 0.0) {
            return Err(Error::Invalid(format!(
                "Lewis form needs positive beam, draft and area (B {beam}, T {draft}, A {area})"
            )));
        }
        let h = beam / (2.0 * draft);
        let s = area / (beam * draft);
        let q = (h - 1.0) / (h + 1.0);
        let c1 =
            3.0 + 4.0 * s / std::f64::consts::PI + (1.0 - 4.0 * s / std::f64::consts::PI) * q * q;
        let disc = 9.0 - 2.0 * c1;
        if disc < 0.0 {
            return Err(Error::Invalid(format!(
                "no Lewis form for B/2T = {h:.3}, area coefficient {s:.3} (section too full)"
            )));
        }
        let a3 = (3.0 - c1 + disc.sqrt()) / c1;
        let a1 = q * (1.0 + a3);
        let scale = 0.5 * beam / (1.0 + a1 + a3);
        let form = Self { scale, a1, a3 };
        // conformal and not re-entrant: |h| > 0 and y(psi) >= 0 on the quarter circle
        for k in 0..=64 {
            let psi = -0.5 * std::f64::consts::PI * k as f64 / 64.0;
            let z = C64::new(0.0, psi).exp();
            if form.dxi(z).norm() < 1e-6 * scale || form.xi(z).re < -1e-9 * beam {
                return Err(Error::Invalid(format!(
                    "Lewis mapping is not conformal for B/2T = {h:.3}, area coefficient {s:.3} \
                     (a1 = {a1:.3}, a3 = {a3:.3})"
                )));
            }
        }
        Ok(form)
    }

    /// Physical point xi = y + i z of zeta.
    pub fn xi(&self, z: C64) -> C64 {
        (z + z.inv() * self.a1 + z.powi(-3) * self.a3) * self.scale
    }

    /// dxi/dzeta.
    pub fn dxi(&self, z: C64) -> C64 {
        (C64::new(1.0, 0.0) - z.powi(-2) * self.a1 - z.powi(-4) * (3.0 * self.a3)) * self.scale
    }

    /// Complex multipole potential w_2m and its derivative.
    fn multipole(&self, m: i32, nu: f64, z: C64) -> (C64, C64) {
        let im = C64::new(0.0, nu * self.scale);
        let (k1, k2, k3) = (2 * m - 1, 2 * m + 1, 2 * m + 3);
        let w = z.powi(-2 * m)
            + im * (z.powi(-k1) / k1 as f64
                - z.powi(-k2) * (self.a1 / k2 as f64)
                - z.powi(-k3) * (3.0 * self.a3 / k3 as f64));
        let dw = z.powi(-2 * m - 1) * (-2.0 * m as f64)
            + im * (-z.powi(-2 * m)
                + z.powi(-2 * m - 2) * self.a1
                + z.powi(-2 * m - 4) * (3.0 * self.a3));
        (w, dw)
    }
}

/// Number of multipoles and contour points.
const MULTIPOLES: i32 = 10;
const POINTS: usize = 40;

/// Heave radiation of a section approximated by its Lewis form.
pub fn radiation(section: &HalfSection, omega: f64, g: f64, rho: f64) -> Result<Radiation> {
    if !(omega > 0.0 && omega.is_finite()) {
        return Err(Error::Invalid(format!(
            "frequency must be positive, got {omega}"
        )));
    }
    let form = LewisForm::fit(section.beam(), section.draft(), section.area())?;
    radiation_of_form(&form, omega, g, rho)
}

/// Heave radiation of a given Lewis form.
pub fn radiation_of_form(form: &LewisForm, omega: f64, g: f64, rho: f64) -> Result<Radiation> {
    let nu = omega * omega / g;
    let nm = MULTIPOLES as usize;
    let pi = std::f64::consts::PI;
    // least squares rows: d phi/dn - n_z at psi in (-pi/2, 0), scaled by |h| (i.e. d/d rho in the circle plane)
    let mut a = DMatrix::<C64>::zeros(POINTS, nm + 1);
    let mut b = DVector::<C64>::zeros(POINTS);
    for k in 0..POINTS {
        let psi = -0.5 * pi * (k as f64 + 0.5) / POINTS as f64;
        let e = C64::new(0.0, psi).exp();
        let h = form.dxi(e);
        let nvec = e * h; // |h| n, n into the fluid
        let p = form.xi(e);
        let (_, grad) = source_potential(nu, [p.re, p.im]);
        a[(k, 0)] = grad[0] * nvec.re + grad[1] * nvec.im;
        for m in 1..=MULTIPOLES {
            let (_, dw) = form.multipole(m, nu, e);
            a[(k, m as usize)] = C64::new((dw * e).re, 0.0);
        }
        b[k] = C64::new(nvec.im, 0.0);
    }
    let svd = a.svd(true, true);
    let q = svd
        .solve(&b, 1e-13)
        .map_err(|e| Error::Numerical(format!("Lewis least squares failed: {e}")))?;
    // potential on the contour and the force integral int phi n_z ds = -int phi dy (half contour, doubled)
    let (gx, gw) = crate::numerics::quadrature::gauss_legendre(32);
    let mut samples = Vec::with_capacity(gx.len());
    let mut integral = C64::new(0.0, 0.0);
    for (x, w) in gx.iter().zip(&gw) {
        let psi = -0.25 * pi * (x + 1.0);
        let dpsi = 0.25 * pi * w;
        let e = C64::new(0.0, psi).exp();
        let p = form.xi(e);
        let (g0, _) = source_potential(nu, [p.re, p.im]);
        let mut phi = q[0] * g0;
        for m in 1..=MULTIPOLES {
            let (wm, _) = form.multipole(m, nu, e);
            phi += q[m as usize] * wm.re;
        }
        // dy/dpsi = Re(dxi/dzeta * i zeta); psi runs from 0 down to -pi/2 here, so ds along keel->waterline
        // has dy = -(dy/dpsi) dpsi
        let dy_dpsi = (form.dxi(e) * C64::new(0.0, 1.0) * e).re;
        let nz_ds = -dy_dpsi * dpsi; // n_z ds = -dy along keel -> waterline
        samples.push(BodySample {
            y: p.re,
            z: p.im,
            nz_ds,
            phi,
        });
        integral += phi * (2.0 * nz_ds);
    }
    let a33 = -rho * integral.re;
    let b33 = omega * rho * integral.im;
    if !a33.is_finite() || !b33.is_finite() {
        return Err(Error::Numerical(format!(
            "Lewis method gave non-finite coefficients at w = {omega}"
        )));
    }
    Ok(Radiation {
        omega,
        a33,
        b33,
        samples,
    })
}

/// Wave source at the origin: G = 2 ln r + R + i Gi and its gradient (d/dy, d/dz).
fn source_potential(nu: f64, p: [f64; 2]) -> (C64, [C64; 2]) {
    let r2 = p[0] * p[0] + p[1] * p[1];
    let (reg, g) = regular_part(nu, p, [0.0, 0.0]);
    (
        reg + C64::new(r2.ln(), 0.0),
        [
            g[0] + C64::new(2.0 * p[0] / r2, 0.0),
            g[1] + C64::new(2.0 * p[1] / r2, 0.0),
        ],
    )
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn multipoles_satisfy_the_free_surface_condition() {
        let form = LewisForm {
            scale: 0.7,
            a1: 0.15,
            a3: -0.05,
        };
        let nu = 1.3;
        for m in 1..4 {
            for &s in &[1.2, 2.0, -1.5] {
                let zeta = C64::new(s, 0.0);
                // phi_z = (d phi / d Im zeta) / h on the real axis
                let eps = 1e-6;
                let up = form.multipole(m, nu, zeta + C64::new(0.0, eps)).0.re;
                let dn = form.multipole(m, nu, zeta - C64::new(0.0, eps)).0.re;
                let phi_z = (up - dn) / (2.0 * eps) / form.dxi(zeta).re;
                let phi = form.multipole(m, nu, zeta).0.re;
                assert!(
                    (phi_z - nu * phi).abs() < 1e-6 * (1.0 + phi.abs()),
                    "m {m} s {s}: {phi_z} vs {}",
                    nu * phi
                );
            }
        }
    }

    #[test]
    fn lewis_fit_reproduces_beam_draft_and_area() {
        let (b, t, area) = (2.0, 0.8, 0.85 * 2.0 * 0.8);
        let f = LewisForm::fit(b, t, area).unwrap();
        let wl = f.xi(C64::new(1.0, 0.0));
        let keel = f.xi(C64::new(0.0, -1.0));
        assert!((wl.re - 1.0).abs() < 1e-12 && wl.im.abs() < 1e-12);
        assert!((keel.im + t).abs() < 1e-12 && keel.re.abs() < 1e-12);
        // area by the shoelace formula on the mapped contour
        let n = 2000;
        let mut a = 0.0;
        let mut prev = keel;
        for k in 1..=n {
            let psi =
                -0.5 * std::f64::consts::PI + 0.5 * std::f64::consts::PI * k as f64 / n as f64;
            let p = f.xi(C64::new(0.0, psi).exp());
            a += -0.5 * (prev.im + p.im) * (p.re - prev.re);
            prev = p;
        }
        assert!(
            (2.0 * a - area).abs() < 1e-5 * area,
            "{} vs {area}",
            2.0 * a
        );
    }
}
