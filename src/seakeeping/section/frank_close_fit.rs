//! Frank (1967) close-fit pulsating-source method, heave mode.
//!
//! The wetted half contour is cut into straight panels of constant source strength sigma_j; the sources are
//! mirrored about the centreline (symmetric heave). The potential is phi(p) = sum_j sigma_j int_{P_j} G ds
//! with the Green function of [`super::green`]; the body condition d phi/dn = n_z (unit heave velocity, n into
//! the fluid) at the panel mid-points gives
//!
//! pi sigma_i + sum_j sigma_j d/dn_i int_{P_j} G ds = n_z,i.
//!
//! Irregular frequencies (where the interior problem - Dirichlet on the hull, free-surface condition on the
//! interior waterplane - has eigenvalues and the plain source method fails) are removed by an interior lid
//! (after Ohmatsu 1975): extra source panels on the interior waterplane z = 0, |y| < B/2, where the interior
//! flow is made to satisfy a rigid-lid condition d phi/dz = 0 instead of the free-surface condition. The
//! interior problem (Dirichlet on the hull, Neumann on the lid) then has no eigenvalues, and the exterior
//! solution, which is unique, is unchanged. (A Dirichlet condition phi = 0 on the lid was tried first: it
//! makes the interior data jump at the waterline corners and converges badly.)
//!
//! Forces: the heave force per unit length is i w rho int phi n_z ds = -(i w a33 + b33), hence
//! a33 = -rho Re(int phi n_z ds), b33 = w rho Im(int phi n_z ds).
//!
//! The log parts of G are integrated in closed form (Hess & Smith 1964); the regular wave part by 4-point
//! Gauss-Legendre quadrature on each panel.

use nalgebra::{Complex, DMatrix, DVector};

use super::green::{log_panel, regular_part};
use super::{BodySample, HalfSection, Radiation};
use crate::error::{Error, Result};

type C64 = Complex<f64>;

/// Discretisation settings.
#[derive(Debug, Clone, Copy)]
pub struct Settings {
    /// Panels on the half contour (at least one per input segment).
    pub body_panels: usize,
    /// Panels on the interior lid (half); 0 switches the irregular-frequency removal off.
    pub lid_panels: usize,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            body_panels: 32,
            lid_panels: 8,
        }
    }
}

#[derive(Debug, Clone, Copy)]
struct Panel {
    a: [f64; 2],
    b: [f64; 2],
}

impl Panel {
    fn mid(&self) -> [f64; 2] {
        [0.5 * (self.a[0] + self.b[0]), 0.5 * (self.a[1] + self.b[1])]
    }
    fn len(&self) -> f64 {
        (self.b[0] - self.a[0]).hypot(self.b[1] - self.a[1])
    }
    /// Normal into the fluid for a body panel running from keel to waterline (right-hand side).
    fn fluid_normal(&self) -> [f64; 2] {
        let l = self.len();
        [(self.b[1] - self.a[1]) / l, -(self.b[0] - self.a[0]) / l]
    }
    fn mirror(&self) -> Panel {
        Panel {
            a: [-self.b[0], self.b[1]],
            b: [-self.a[0], self.a[1]],
        }
    }
    fn image(&self) -> Panel {
        Panel {
            a: [self.a[0], -self.a[1]],
            b: [self.b[0], -self.b[1]],
        }
    }
}

/// Cut the contour into about `n` panels. Corners (direction change above 15 deg) and the end points are
/// kept as panel ends; between them the panels are equally long along the contour, so dense input
/// polylines are resampled and sparse ones subdivided. A corner-to-corner piece that is one straight
/// segment gets cosine spacing (panels shrink towards its corners, where the flow is singular).
fn panelise(points: &[[f64; 2]], n: usize) -> Vec<Panel> {
    let seg_len = |a: [f64; 2], b: [f64; 2]| (b[0] - a[0]).hypot(b[1] - a[1]);
    let mut cum = vec![0.0];
    for w in points.windows(2) {
        cum.push(cum[cum.len() - 1] + seg_len(w[0], w[1]));
    }
    let total = cum[cum.len() - 1];
    let mut corners = vec![0];
    for i in 1..points.len() - 1 {
        let (a, b, c) = (points[i - 1], points[i], points[i + 1]);
        let d1 = [b[0] - a[0], b[1] - a[1]];
        let d2 = [c[0] - b[0], c[1] - b[1]];
        let cross = d1[0] * d2[1] - d1[1] * d2[0];
        let dot = d1[0] * d2[0] + d1[1] * d2[1];
        if cross.atan2(dot).abs() > 15f64.to_radians() {
            corners.push(i);
        }
    }
    corners.push(points.len() - 1);
    // point at arc length s within vertices [lo, hi]
    let at = |s: f64, lo: usize, hi: usize| {
        let mut k = lo;
        while k + 1 < hi && cum[k + 1] < s {
            k += 1;
        }
        let f = ((s - cum[k]) / (cum[k + 1] - cum[k])).clamp(0.0, 1.0);
        let (a, b) = (points[k], points[k + 1]);
        [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])]
    };
    let mut panels = Vec::new();
    for w in corners.windows(2) {
        let (lo, hi) = (w[0], w[1]);
        let len = cum[hi] - cum[lo];
        let m = ((n as f64 * len / total).round() as usize).max(1);
        let cosine = hi == lo + 1 && m >= 4;
        let s_of = |i: usize| {
            let t = i as f64 / m as f64;
            let t = if cosine {
                0.5 * (1.0 - (std::f64::consts::PI * t).cos())
            } else {
                t
            };
            cum[lo] + t * len
        };
        for k in 0..m {
            let a = if k == 0 {
                points[lo]
            } else {
                at(s_of(k), lo, hi)
            };
            let b = if k + 1 == m {
                points[hi]
            } else {
                at(s_of(k + 1), lo, hi)
            };
            panels.push(Panel { a, b });
        }
    }
    panels
}

/// Potential and gradient at `p` induced by unit source density on `panel` (and not its mirror).
/// `own`: `p` is the panel's own mid-point, approached from the right-hand side of the panel (the fluid side
/// of a body panel, the interior side below a lid panel, whose image coincides with it).
fn influence(
    nu: f64,
    p: [f64; 2],
    panel: &Panel,
    own: bool,
    gauss: &(Vec<f64>, Vec<f64>),
) -> (C64, [C64; 2]) {
    let side = if own { -1.0 } else { 1.0 };
    let (v1, g1) = log_panel(p, panel.a, panel.b, side);
    let img = panel.image();
    let (v2, g2) = log_panel(p, img.a, img.b, side);
    let mut val = C64::new(v1 + v2, 0.0);
    let mut grad = [C64::new(g1[0] + g2[0], 0.0), C64::new(g1[1] + g2[1], 0.0)];
    let l = panel.len();
    for (x, w) in gauss.0.iter().zip(&gauss.1) {
        let s = 0.5 * (x + 1.0);
        let q = [
            panel.a[0] + s * (panel.b[0] - panel.a[0]),
            panel.a[1] + s * (panel.b[1] - panel.a[1]),
        ];
        let (r, gr) = regular_part(nu, p, q);
        let wt = 0.5 * l * w;
        val += r * wt;
        grad[0] += gr[0] * wt;
        grad[1] += gr[1] * wt;
    }
    (val, grad)
}

struct Solution {
    body: Vec<Panel>,
    all: Vec<Panel>,
    sigma: DVector<C64>,
    /// potential on the body mid-points per unit source density on each panel
    pot: DMatrix<C64>,
}

fn solve(section: &HalfSection, omega: f64, g: f64, settings: &Settings) -> Result<Solution> {
    if !(omega > 0.0 && omega.is_finite()) {
        return Err(Error::Invalid(format!(
            "frequency must be positive, got {omega}"
        )));
    }
    let nu = omega * omega / g;
    let body = panelise(section.points(), settings.body_panels);
    let lid = lid_panels(0.5 * section.beam(), settings.lid_panels);
    let nb = body.len();
    let all: Vec<Panel> = body.iter().chain(lid.iter()).copied().collect();
    let n = all.len();
    let gauss = crate::numerics::quadrature::gauss_legendre(4);
    let mut mat = DMatrix::<C64>::zeros(n, n);
    let mut pot = DMatrix::<C64>::zeros(nb, n);
    let mut rhs = DVector::<C64>::zeros(n);
    for i in 0..n {
        let p = all[i].mid();
        for (j, pj) in all.iter().enumerate() {
            let (v_a, g_a) = influence(nu, p, pj, i == j, &gauss);
            let (v_b, g_b) = influence(nu, p, &pj.mirror(), false, &gauss);
            if i < nb {
                let nf = body[i].fluid_normal();
                mat[(i, j)] = (g_a[0] + g_b[0]) * nf[0] + (g_a[1] + g_b[1]) * nf[1];
                pot[(i, j)] = v_a + v_b;
            } else {
                // lid: d phi/dz = 0 on the interior side
                mat[(i, j)] = g_a[1] + g_b[1];
            }
        }
        if i < nb {
            rhs[i] = C64::new(body[i].fluid_normal()[1], 0.0);
        }
    }
    let sigma = mat
        .lu()
        .solve(&rhs)
        .ok_or_else(|| Error::Numerical(format!("close-fit system singular at w = {omega}")))?;
    Ok(Solution {
        body,
        all,
        sigma,
        pot,
    })
}

/// Heave radiation of a section by the close-fit method.
pub fn radiation(
    section: &HalfSection,
    omega: f64,
    g: f64,
    rho: f64,
    settings: &Settings,
) -> Result<Radiation> {
    let sol = solve(section, omega, g, settings)?;
    let phi = &sol.pot * &sol.sigma;
    let mut samples = Vec::with_capacity(sol.body.len());
    let mut integral = C64::new(0.0, 0.0);
    for (i, pnl) in sol.body.iter().enumerate() {
        let nz_ds = -(pnl.b[0] - pnl.a[0]);
        let m = pnl.mid();
        samples.push(BodySample {
            y: m[0],
            z: m[1],
            nz_ds,
            phi: phi[i],
        });
        integral += phi[i] * (2.0 * nz_ds);
    }
    let a33 = -rho * integral.re;
    let b33 = omega * rho * integral.im;
    if !a33.is_finite() || !b33.is_finite() {
        return Err(Error::Numerical(format!(
            "close-fit gave non-finite coefficients at w = {omega}"
        )));
    }
    Ok(Radiation {
        omega,
        a33,
        b33,
        samples,
    })
}

/// Amplitude of the radiated far-field wave per unit heave amplitude, |zeta_far| / |eta3|, from the source
/// strengths (used to check the damping against the energy flux b33 = rho g^2 A^2 / w^3).
pub fn far_field_wave_ratio(
    section: &HalfSection,
    omega: f64,
    g: f64,
    settings: &Settings,
) -> Result<f64> {
    // Re-solve and sum the outgoing-wave amplitude of every source: phi_far = 2 pi i e^{nu z} e^{-i nu y}
    // sum_j sigma_j int e^{nu zeta} e^{i nu eta} ds (y -> +infinity).
    let nu = omega * omega / g;
    let sol = solve(section, omega, g, settings)?;
    let gauss = crate::numerics::quadrature::gauss_legendre(8);
    let mut amp = C64::new(0.0, 0.0);
    for (pnl, s) in sol.all.iter().zip(sol.sigma.iter()) {
        for p in [*pnl, pnl.mirror()] {
            let l = p.len();
            for (x, w) in gauss.0.iter().zip(&gauss.1) {
                let t = 0.5 * (x + 1.0);
                let q = [
                    p.a[0] + t * (p.b[0] - p.a[0]),
                    p.a[1] + t * (p.b[1] - p.a[1]),
                ];
                amp += s * C64::new(0.0, nu * q[0]).exp() * ((nu * q[1]).exp() * 0.5 * l * w);
            }
        }
    }
    let phi_far = amp * (2.0 * std::f64::consts::PI);
    // heave velocity 1 -> heave amplitude 1/w; wave elevation |zeta| = w/g |phi|
    Ok(omega / g * phi_far.norm() * omega)
}

fn lid_panels(half_beam: f64, m: usize) -> Vec<Panel> {
    if half_beam <= 0.0 {
        return Vec::new();
    }
    (0..m)
        .map(|k| {
            let f = |i: usize| (0.5 * std::f64::consts::PI * i as f64 / m as f64).sin() * half_beam;
            Panel {
                a: [f(k), 0.0],
                b: [f(k + 1), 0.0],
            }
        })
        .collect()
}
