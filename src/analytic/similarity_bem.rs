//! Panel method of the similarity problem of [`crate::analytic::similarity`]: constant-strength straight
//! panels, collocation at the panel midpoints, exact integrals of the free-space Green's function
//! G(x, y) = -(1/2 pi) ln|x - y| and of its normal derivative over each panel, and the mirror image in
//! the symmetry plane xi = 0 (so that plane carries no panels).
//!
//! For a collocation point x_i on the boundary (smooth there) Green's third identity reads
//!
//! ```text
//! Phi_i / 2 + sum_j H_ij Phi_j - sum_j G_ij q_j = 0,
//! H_ij = integral_j dG/dn_y ds_y,   G_ij = integral_j G ds_y   (panel j and its image),
//! ```
//!
//! with q = dPhi/dn the outward normal derivative. The boundary is walked clockwise (fluid on the right),
//! so the outward normal of a panel from a to b is the left normal (-e_y, e_x).

use nalgebra::{DMatrix, DVector};

use crate::error::{Error, Result};

/// The boundary condition of a panel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Bc {
    /// Phi given (the unknown is q).
    Dirichlet(f64),
    /// q given (the unknown is Phi).
    Neumann(f64),
    /// q = -Phi / r (the far-field dipole; the unknown is Phi), r given.
    Robin(f64),
}

/// A straight panel from `a` to `b`.
#[derive(Debug, Clone, Copy)]
pub struct Panel {
    pub a: [f64; 2],
    pub b: [f64; 2],
    pub bc: Bc,
}

impl Panel {
    pub fn mid(&self) -> [f64; 2] {
        [0.5 * (self.a[0] + self.b[0]), 0.5 * (self.a[1] + self.b[1])]
    }
    pub fn len(&self) -> f64 {
        (self.b[0] - self.a[0]).hypot(self.b[1] - self.a[1])
    }
    /// Unit tangent (a to b).
    pub fn tangent(&self) -> [f64; 2] {
        let l = self.len();
        [(self.b[0] - self.a[0]) / l, (self.b[1] - self.a[1]) / l]
    }
    /// Outward unit normal (left of the direction of travel).
    pub fn normal(&self) -> [f64; 2] {
        let e = self.tangent();
        [-e[1], e[0]]
    }
}

/// (integral of G, integral of dG/dn_y) over panel `p` for the point `x`; `self_panel` gives the
/// principal value (x at the midpoint of `p`).
fn influence(x: [f64; 2], p: &Panel, self_panel: bool) -> (f64, f64) {
    let l = p.len();
    let e = p.tangent();
    let n = p.normal();
    let d = [x[0] - p.a[0], x[1] - p.a[1]];
    let u = d[0] * e[0] + d[1] * e[1];
    let v = if self_panel {
        0.0
    } else {
        d[0] * n[0] + d[1] * n[1]
    };
    let (w1, w2) = (-u, l - u);
    // Signed angle subtended: atan(w2/v) - atan(w1/v).
    let delta = if self_panel {
        0.0
    } else {
        (v * (w2 - w1)).atan2(v * v + w1 * w2)
    };
    let wlnr = |w: f64| {
        let r2 = w * w + v * v;
        if r2 > 0.0 { 0.5 * w * r2.ln() } else { 0.0 }
    };
    let int_ln = wlnr(w2) - wlnr(w1) - (w2 - w1) + v * delta;
    let inv2pi = 0.5 / std::f64::consts::PI;
    // d ln r / dn_y = (y - x).n / r^2 = -v / r^2; its integral is -delta.
    (-inv2pi * int_ln, inv2pi * delta)
}

/// The solution on every panel: Phi and q at the midpoints.
#[derive(Debug, Clone)]
pub struct Solution {
    pub phi: Vec<f64>,
    pub q: Vec<f64>,
}

/// Solves the boundary-integral equation on the panels (with the mirror image in xi = 0).
pub fn solve(panels: &[Panel]) -> Result<Solution> {
    let m = panels.len();
    let mut a = DMatrix::<f64>::zeros(m, m);
    let mut rhs = DVector::<f64>::zeros(m);
    for (i, pi) in panels.iter().enumerate() {
        let x = pi.mid();
        let xm = [-x[0], x[1]];
        for (j, pj) in panels.iter().enumerate() {
            let (g1, h1) = influence(x, pj, i == j);
            let (g2, h2) = influence(xm, pj, false);
            let g = g1 + g2;
            let h = h1 + h2 + if i == j { 0.5 } else { 0.0 };
            match pj.bc {
                Bc::Dirichlet(phi) => {
                    a[(i, j)] = -g;
                    rhs[i] -= h * phi;
                }
                Bc::Neumann(q) => {
                    a[(i, j)] = h;
                    rhs[i] += g * q;
                }
                Bc::Robin(r) => a[(i, j)] = h + g / r,
            }
        }
    }
    let x = a
        .lu()
        .solve(&rhs)
        .ok_or_else(|| Error::Numerical("similarity panel system is singular".into()))?;
    let mut phi = vec![0.0; m];
    let mut q = vec![0.0; m];
    for (j, p) in panels.iter().enumerate() {
        match p.bc {
            Bc::Dirichlet(v) => {
                phi[j] = v;
                q[j] = x[j];
            }
            Bc::Neumann(v) => {
                phi[j] = x[j];
                q[j] = v;
            }
            Bc::Robin(r) => {
                phi[j] = x[j];
                q[j] = -x[j] / r;
            }
        }
    }
    Ok(Solution { phi, q })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Closed clockwise polygon in xi > 0 touching xi = 0 (the image closes it).
    fn box_panels(n: usize, bc: impl Fn([f64; 2], [f64; 2]) -> Bc) -> Vec<Panel> {
        // Rectangle 0 <= xi <= 1, -1 <= eta <= 0 walked clockwise (fluid on the right) without the
        // xi = 0 side: (0,0) -> (1,0) -> (1,-1) -> (0,-1).
        let corners = [[0.0, 0.0], [1.0, 0.0], [1.0, -1.0], [0.0, -1.0]];
        let mut out = Vec::new();
        for s in 0..3 {
            let (a, b) = (corners[s], corners[s + 1]);
            for k in 0..n {
                let f0 = k as f64 / n as f64;
                let f1 = (k + 1) as f64 / n as f64;
                let pa = [a[0] + f0 * (b[0] - a[0]), a[1] + f0 * (b[1] - a[1])];
                let pb = [a[0] + f1 * (b[0] - a[0]), a[1] + f1 * (b[1] - a[1])];
                out.push(Panel {
                    a: pa,
                    b: pb,
                    bc: bc(pa, pb),
                });
            }
        }
        out
    }

    #[test]
    fn even_harmonic_function_is_reproduced() {
        // Phi = xi^2 - eta^2 (even in xi): Dirichlet on top, Neumann elsewhere.
        let f = |p: [f64; 2]| p[0] * p[0] - p[1] * p[1];
        let grad = |p: [f64; 2]| [2.0 * p[0], -2.0 * p[1]];
        let panels = box_panels(40, |a, b| {
            let m = [0.5 * (a[0] + b[0]), 0.5 * (a[1] + b[1])];
            if a[1] == 0.0 && b[1] == 0.0 {
                Bc::Dirichlet(f(m))
            } else {
                let p = Panel {
                    a,
                    b,
                    bc: Bc::Neumann(0.0),
                };
                let n = p.normal();
                let g = grad(m);
                Bc::Neumann(g[0] * n[0] + g[1] * n[1])
            }
        });
        let s = solve(&panels).unwrap();
        let mut err: f64 = 0.0;
        for (p, phi) in panels.iter().zip(&s.phi) {
            err = err.max((phi - f(p.mid())).abs());
        }
        assert!(err < 5e-3, "max error {err}");
        // The top is walked in +xi: outward normal (0, 1), q = -2 eta = 0 there.
        let top_q = s.q[..40].iter().fold(0.0f64, |m, v| m.max(v.abs()));
        assert!(top_q < 0.05, "{top_q}");
    }
}
