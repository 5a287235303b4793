//! Fitting a sectional-area curve and a design-waterline curve to published form coefficients.
//!
//! With u = x/L + 1/2 ∈ [0, 1] (AP to FP), the non-dimensional half-section area α(u) = a/((B/2) T) and
//! waterline half-breadth β(u) = b/(B/2) at the design draft T are cubic B-splines (see [`super::bspline`]).
//! By definition
//!
//! C_B = ∇/(L B T) = ∫₀¹ α du,  C_M = A_M/(B T) = α(½),  C_WP = A_WP/(L B) = ∫₀¹ β du,  C_P = C_B/C_M,
//!
//! and the section area coefficient is σ(u) = a/(b T) = α/β. The coefficients are found by the convex
//! quadratic programme (solved with Clarabel, Goulart & Chen 2024)
//!
//! minimise ∫₀¹ (α″² + β″²) du (the fairest curves)
//! subject to ∫α = C_B, ∫β = C_WP, α(½) = C_M, β(½) = 1, α = β = 0 at both ends,
//!            0 ≤ β ≤ 1, α ≤ C_M, σ_min β ≤ α ≤ σ_max(u) β at sample points,
//!
//! where the σ bounds keep every section realisable by the section family of
//! [`super::section_family::PowerSection`] (σ ∈ [½, 1)).

use clarabel::algebra::CscMatrix;
use clarabel::solver::{
    DefaultSettings, DefaultSolver, IPSolver, NonnegativeConeT, SolverStatus, ZeroConeT,
};

use super::bspline::CubicBSpline;
use crate::error::{Error, Result};
use crate::numerics::quadrature::gauss_legendre;

/// What the fitted form must satisfy.
#[derive(Debug, Clone)]
pub struct FormTargets {
    pub cb: f64,
    pub cm: f64,
    pub cwp: f64,
    /// Smallest section area coefficient anywhere (½ for the V-sections of the family).
    pub sigma_min: f64,
    /// Largest section area coefficient as a function of u (AP = 0, FP = 1).
    pub sigma_max: fn(f64) -> f64,
    /// Knot intervals of each spline.
    pub intervals: usize,
    /// u where the inequalities are enforced (in addition to a uniform grid of 400 intervals).
    pub extra_samples: Vec<f64>,
}

/// The fitted curves.
#[derive(Debug, Clone)]
pub struct FittedForm {
    pub basis: CubicBSpline,
    /// Coefficients of α(u) (half-section area over (B/2) T).
    pub alpha: Vec<f64>,
    /// Coefficients of β(u) (waterline half-breadth over B/2).
    pub beta: Vec<f64>,
}

impl FittedForm {
    pub fn alpha(&self, u: f64) -> f64 {
        self.basis.eval(&self.alpha, u, 0)
    }

    pub fn beta(&self, u: f64) -> f64 {
        self.basis.eval(&self.beta, u, 0)
    }

    /// ∫₀¹ α du = C_B of the curves.
    pub fn cb(&self) -> f64 {
        dot(&self.basis.integrals(), &self.alpha)
    }

    /// ∫₀¹ β du = C_WP of the curves.
    pub fn cwp(&self) -> f64 {
        dot(&self.basis.integrals(), &self.beta)
    }

    /// α(½) = C_M of the curves.
    pub fn cm(&self) -> f64 {
        self.alpha(0.5)
    }

    /// Longitudinal centre of buoyancy of the curves as a fraction of L from midship (positive forward):
    /// ∫ (u − ½) α du / ∫ α du, by Gauss–Legendre quadrature on each polynomial piece.
    pub fn lcb_over_l(&self) -> f64 {
        let (gx, gw) = gauss_legendre(4);
        let bp = self.basis.breakpoints();
        let mut m = 0.0;
        for w in bp.windows(2) {
            let (a, b) = (w[0], w[1]);
            for (x, wt) in gx.iter().zip(&gw) {
                let u = 0.5 * (a + b) + 0.5 * (b - a) * x;
                m += 0.5 * (b - a) * wt * (u - 0.5) * self.alpha(u);
            }
        }
        m / self.cb()
    }
}

fn dot(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| x * y).sum()
}

/// Solve the fairing programme above.
pub fn fit_form(t: &FormTargets) -> Result<FittedForm> {
    let basis = CubicBSpline::uniform(t.intervals);
    let n = basis.len();
    let nv = 2 * n;

    // Objective ½ zᵀ P z with P = 2 diag(G, G), G_ij = ∫ N_i″ N_j″ du (exact: Gauss 4 points per piece),
    // plus a tiny ridge term so that P is positive definite.
    let (gx, gw) = gauss_legendre(4);
    let bp = basis.breakpoints();
    let mut g = vec![vec![0.0; n]; n];
    for w in bp.windows(2) {
        let (a, b) = (w[0], w[1]);
        for (x, wt) in gx.iter().zip(&gw) {
            let u = 0.5 * (a + b) + 0.5 * (b - a) * x;
            let d2 = basis.basis(u, 2);
            for (i, gi) in g.iter_mut().enumerate() {
                for (j, gij) in gi.iter_mut().enumerate().skip(i) {
                    *gij += 0.5 * (b - a) * wt * d2[i] * d2[j];
                }
            }
        }
    }
    let (mut pi, mut pj, mut pv) = (vec![], vec![], vec![]);
    for block in 0..2 {
        for (i, gi) in g.iter().enumerate() {
            for (j, gij) in gi.iter().enumerate().skip(i) {
                let mut v = 2.0 * gij;
                if i == j {
                    v += 1e-8;
                }
                if v != 0.0 {
                    pi.push(block * n + i);
                    pj.push(block * n + j);
                    pv.push(v);
                }
            }
        }
    }
    let p = CscMatrix::new_from_triplets(nv, nv, pi, pj, pv);
    let q = vec![0.0; nv];

    // Constraint rows: first the equalities (zero cone), then the inequalities A z ≤ b.
    let mut rows: Vec<Vec<f64>> = Vec::new();
    let mut rhs: Vec<f64> = Vec::new();
    let row_alpha = |coef: &[f64]| {
        let mut r = vec![0.0; nv];
        r[..n].copy_from_slice(coef);
        r
    };
    let row_beta = |coef: &[f64]| {
        let mut r = vec![0.0; nv];
        r[n..].copy_from_slice(coef);
        r
    };
    let ints = basis.integrals();
    let mid = basis.basis(0.5, 0);
    let end0 = basis.basis(0.0, 0);
    let end1 = basis.basis(1.0, 0);
    for (r, v) in [
        (row_alpha(&ints), t.cb),
        (row_beta(&ints), t.cwp),
        (row_alpha(&mid), t.cm),
        (row_beta(&mid), 1.0),
        (row_alpha(&end0), 0.0),
        (row_alpha(&end1), 0.0),
        (row_beta(&end0), 0.0),
        (row_beta(&end1), 0.0),
    ] {
        rows.push(r);
        rhs.push(v);
    }
    let n_eq = rows.len();

    let mut samples: Vec<f64> = (0..=400).map(|k| k as f64 / 400.0).collect();
    samples.extend(t.extra_samples.iter().copied());
    for &u in &samples {
        let nb = basis.basis(u, 0);
        let neg: Vec<f64> = nb.iter().map(|v| -v).collect();
        let smax = (t.sigma_max)(u);
        // α ≤ C_M, β ≤ 1, −β ≤ 0
        rows.push(row_alpha(&nb));
        rhs.push(t.cm);
        rows.push(row_beta(&nb));
        rhs.push(1.0);
        rows.push(row_beta(&neg));
        rhs.push(0.0);
        // σ_min β − α ≤ 0 and α − σ_max β ≤ 0
        let mut r = vec![0.0; nv];
        let mut s = vec![0.0; nv];
        for i in 0..n {
            r[i] = -nb[i];
            r[n + i] = t.sigma_min * nb[i];
            s[i] = nb[i];
            s[n + i] = -smax * nb[i];
        }
        rows.push(r);
        rhs.push(0.0);
        rows.push(s);
        rhs.push(0.0);
    }
    let m = rows.len();
    let (mut ai, mut aj, mut av) = (vec![], vec![], vec![]);
    for (i, r) in rows.iter().enumerate() {
        for (j, &v) in r.iter().enumerate() {
            if v != 0.0 {
                ai.push(i);
                aj.push(j);
                av.push(v);
            }
        }
    }
    let a = CscMatrix::new_from_triplets(m, nv, ai, aj, av);
    let cones = [ZeroConeT(n_eq), NonnegativeConeT(m - n_eq)];
    let settings = DefaultSettings {
        verbose: false,
        tol_gap_abs: 1e-10,
        tol_gap_rel: 1e-10,
        tol_feas: 1e-10,
        ..DefaultSettings::default()
    };
    let mut solver = DefaultSolver::new(&p, &q, &a, &rhs, &cones, settings)
        .map_err(|e| Error::Numerical(format!("form fit: solver setup failed: {e}")))?;
    solver.solve();
    match solver.solution.status {
        SolverStatus::Solved | SolverStatus::AlmostSolved => {}
        s => {
            return Err(Error::Numerical(format!(
                "form fit: no fair hull satisfies the form coefficients and section bounds (solver status: {})",
                words(&format!("{s:?}"))
            )));
        }
    }
    let z = &solver.solution.x;
    Ok(FittedForm {
        basis,
        alpha: z[..n].to_vec(),
        beta: z[n..].to_vec(),
    })
}

/// A CamelCase identifier as lower-case words ("PrimalInfeasible" -> "primal infeasible"), for messages
/// that name a status of an external solver.
fn words(ident: &str) -> String {
    let mut out = String::new();
    for (i, c) in ident.chars().enumerate() {
        if c.is_uppercase() && i > 0 {
            out.push(' ');
        }
        out.extend(c.to_lowercase());
    }
    out
}
