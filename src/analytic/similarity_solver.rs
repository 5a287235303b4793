//! Newton iteration for the free surface of the similarity problem (see
//! [`crate::analytic::similarity`] for the equations). Private to the analytic module.

use nalgebra::{DMatrix, DVector};
use rayon::prelude::*;

use super::similarity_bem::{self as bem, Bc, Panel};
use super::similarity_mesh::{arc_length, graded, resample, root_node};
use crate::error::{Error, Result};

/// Discretisation of the similarity problem.
#[derive(Debug, Clone, Copy)]
pub struct Grid {
    /// Panel size at the spray root and along the jet, in units of the jet-root thickness.
    pub h_root: f64,
    /// Growth of the panel size with the distance from the root (panel / distance).
    pub growth: f64,
    /// Far-field radius, in units of the root's distance from the apex.
    pub far: f64,
    /// Length of jet kept beyond the spray root, in units of the jet-root thickness.
    pub jet: f64,
    /// Panels on the far-field arc.
    pub arc_panels: usize,
}

/// State of the iteration: the deadrise, the body length kept (to the jet cut) and the free-surface
/// nodes from the jet cut (node 0, on the normal to the body at the cut) to the far field (last node,
/// fixed at (R, 0)).
#[derive(Debug, Clone)]
pub struct Shape {
    pub beta: f64,
    pub s_cut: f64,
    pub fs: Vec<[f64; 2]>,
    pub body: Vec<f64>,
}

/// What one panel solution gives.
pub struct Eval {
    pub panels: Vec<Panel>,
    pub sol: bem::Solution,
    /// Kinematic residual q - r.n on every free-surface panel.
    pub res: Vec<f64>,
}

fn dot(a: [f64; 2], b: [f64; 2]) -> f64 {
    a[0] * b[0] + a[1] * b[1]
}

impl Shape {
    fn tb(&self) -> [f64; 2] {
        [self.beta.cos(), self.beta.sin()]
    }
    /// Body normal pointing into the fluid.
    fn nf(&self) -> [f64; 2] {
        [self.beta.sin(), -self.beta.cos()]
    }
    pub fn body_point(&self, s: f64) -> [f64; 2] {
        let t = self.tb();
        [s * t[0], -1.0 + s * t[1]]
    }
    /// Arc length along the body of the projection of `p`.
    pub fn body_s(&self, p: [f64; 2]) -> f64 {
        dot([p[0], p[1] + 1.0], self.tb())
    }
    pub fn far(&self) -> f64 {
        self.fs.last().map_or(1.0, |p| p[0])
    }
}

/// Phi along the free surface from the far end (Phi = 0) to the jet cut, from the dynamic condition
/// with the kinematic one: dPhi/ds = r.t + sqrt(|r|^2 - 2 Phi), s running towards the jet. Returns Phi
/// at the nodes and at the panel midpoints (panel k from node k to node k+1).
pub fn surface_potential(fs: &[[f64; 2]]) -> Result<(Vec<f64>, Vec<f64>)> {
    let n = fs.len();
    let mut node = vec![0.0; n];
    let mut mid = vec![0.0; n - 1];
    for k in (0..n - 1).rev() {
        let (a, b) = (fs[k + 1], fs[k]);
        let l = (b[0] - a[0]).hypot(b[1] - a[1]);
        let t = [(b[0] - a[0]) / l, (b[1] - a[1]) / l];
        let nn = [-t[1], t[0]];
        let f = |s: f64, phi: f64| -> f64 {
            let r = [a[0] + s * t[0], a[1] + s * t[1]];
            let rt = dot(r, t);
            let rn = dot(r, nn);
            let w = (rt * rt + rn * rn - 2.0 * phi).max(0.0).sqrt();
            if rt < 0.0 {
                (rn * rn - 2.0 * phi) / (w - rt)
            } else {
                rt + w
            }
        };
        let rk4 = |s0: f64, h: f64, y: f64| {
            let k1 = f(s0, y);
            let k2 = f(s0 + 0.5 * h, y + 0.5 * h * k1);
            let k3 = f(s0 + 0.5 * h, y + 0.5 * h * k2);
            let k4 = f(s0 + h, y + h * k3);
            y + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
        };
        let half = rk4(0.0, 0.5 * l, node[k + 1]);
        mid[k] = half;
        node[k] = rk4(0.5 * l, 0.5 * l, half);
        if !node[k].is_finite() {
            return Err(Error::Numerical(
                "similarity: free-surface potential diverged".into(),
            ));
        }
    }
    Ok((node, mid))
}

/// Panels: body (apex to cut), jet cut, free surface (jet to far), far-field arc.
pub fn panels(sh: &Shape, arc_panels: usize) -> Result<(Vec<Panel>, usize)> {
    let (phi_node, phi_mid) = surface_potential(&sh.fs)?;
    let mut p = Vec::new();
    let qb = -sh.beta.cos();
    for w in sh.body.windows(2) {
        p.push(Panel {
            a: sh.body_point(w[0]),
            b: sh.body_point(w[1]),
            bc: Bc::Neumann(qb),
        });
    }
    // Jet cut: the flow leaves along the body with the jet's speed at the free surface there,
    // dPhi/dn = r.t_b + sqrt(|r|^2 - 2 Phi).
    let (ca, cb) = (sh.body_point(sh.s_cut), sh.fs[0]);
    let cm = [0.5 * (ca[0] + cb[0]), 0.5 * (ca[1] + cb[1])];
    let tb = sh.tb();
    let qc = dot(cm, tb) + (dot(cm, cm) - 2.0 * phi_node[0]).max(0.0).sqrt();
    p.push(Panel {
        a: ca,
        b: cb,
        bc: Bc::Neumann(qc),
    });
    let first_fs = p.len();
    for (k, w) in sh.fs.windows(2).enumerate() {
        p.push(Panel {
            a: w[0],
            b: w[1],
            bc: Bc::Dirichlet(phi_mid[k]),
        });
    }
    let r = sh.far();
    for k in 0..arc_panels {
        let th = |k: usize| -0.5 * std::f64::consts::PI * k as f64 / arc_panels as f64;
        let (t0, t1) = (th(k), th(k + 1));
        p.push(Panel {
            a: [r * t0.cos(), r * t0.sin()],
            b: [r * t1.cos(), r * t1.sin()],
            bc: Bc::Robin(r),
        });
    }
    Ok((p, first_fs))
}

pub fn evaluate(sh: &Shape, arc_panels: usize) -> Result<Eval> {
    let (panels, first) = panels(sh, arc_panels)?;
    let sol = bem::solve(&panels)?;
    let nfs = sh.fs.len() - 1;
    let res = (0..nfs)
        .map(|k| {
            let p = &panels[first + k];
            sol.q[first + k] - dot(p.mid(), p.normal())
        })
        .collect();
    Ok(Eval { panels, sol, res })
}

/// Direction in which free-surface node k moves: node 0 along the cut, the others along the mean
/// normal of their two panels.
fn move_dir(sh: &Shape, k: usize) -> [f64; 2] {
    if k == 0 {
        return sh.nf();
    }
    let fs = &sh.fs;
    let t = [fs[k + 1][0] - fs[k - 1][0], fs[k + 1][1] - fs[k - 1][1]];
    let l = t[0].hypot(t[1]);
    [-t[1] / l, t[0] / l]
}

fn moved(sh: &Shape, d: &[f64]) -> Shape {
    let mut out = sh.clone();
    for (k, dk) in d.iter().enumerate() {
        let m = move_dir(sh, k);
        out.fs[k][0] += dk * m[0];
        out.fs[k][1] += dk * m[1];
    }
    out
}

fn norm2(v: &[f64]) -> f64 {
    v.iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn norm(v: &[f64]) -> f64 {
    v.iter().fold(0.0f64, |m, x| m.max(x.abs()))
}

/// Newton iterations (finite-difference Jacobian) on the free-surface nodes of a fixed mesh. Returns the
/// final residual (max norm).
pub fn newton(sh: &mut Shape, arc_panels: usize, iters: usize, tol: f64) -> Result<f64> {
    let n = sh.fs.len() - 1;
    let mut r0 = evaluate(sh, arc_panels)?.res;
    for _ in 0..iters {
        if norm(&r0) < tol {
            break;
        }
        // Finite-difference Jacobian, one column per node (in parallel; each column is independent, so
        // the result does not depend on the number of threads).
        let cols: Vec<Result<Vec<f64>>> = (0..n)
            .into_par_iter()
            .map(|k| {
                let l = (sh.fs[k + 1][0] - sh.fs[k][0]).hypot(sh.fs[k + 1][1] - sh.fs[k][1]);
                let eps = 1e-4 * l;
                let mut d = vec![0.0; n];
                d[k] = eps;
                let rk = evaluate(&moved(sh, &d), arc_panels)?.res;
                Ok(rk.iter().zip(&r0).map(|(a, b)| (a - b) / eps).collect())
            })
            .collect();
        let mut jac = DMatrix::<f64>::zeros(n, n);
        for (k, c) in cols.into_iter().enumerate() {
            for (i, v) in c?.into_iter().enumerate() {
                jac[(i, k)] = v;
            }
        }
        let rhs = DVector::from_iterator(n, r0.iter().map(|v| -v));
        let step = jac
            .lu()
            .solve(&rhs)
            .ok_or_else(|| Error::Numerical("similarity: singular Newton matrix".into()))?;
        // Full step, halved until the residual (2-norm) falls and the surface stays off the body.
        let mut alpha = 1.0;
        let mut accepted = false;
        for _ in 0..12 {
            let d: Vec<f64> = step.iter().map(|v| alpha * v).collect();
            let trial = moved(sh, &d);
            let off_body = trial
                .fs
                .iter()
                .all(|p| dot([p[0], p[1] + 1.0], sh.nf()) > 0.0);
            if off_body
                && let Ok(e) = evaluate(&trial, arc_panels)
                && norm2(&e.res) < norm2(&r0)
            {
                *sh = trial;
                r0 = e.res;
                accepted = true;
                break;
            }
            alpha *= 0.5;
        }
        if !accepted {
            break;
        }
    }
    Ok(norm(&r0))
}

/// Rebuilds the mesh around the current spray root: body nodes, jet cut and free-surface nodes graded
/// from the root, with the grid's sizes.
pub fn remesh(sh: &Shape, grid: &Grid) -> Shape {
    let kr = root_node(&sh.fs);
    let s_root = sh.body_s(sh.fs[kr]);
    let nf = sh.nf();
    let thick = |p: [f64; 2]| dot([p[0], p[1] + 1.0], nf);
    let delta = thick(sh.fs[kr]);
    let h0 = grid.h_root * delta;
    let s_cut_new = s_root + grid.jet * delta;
    // Free surface: extend or trim the jet along the body to the new cut first.
    let mut pts = sh.fs.clone();
    if s_cut_new > sh.s_cut {
        // Prolong at the cut's thickness.
        let d0 = thick(pts[0]);
        let m = 20;
        let mut jet: Vec<[f64; 2]> = Vec::new();
        for i in 0..m {
            let s = s_cut_new - (s_cut_new - sh.s_cut) * i as f64 / m as f64;
            let b = sh.body_point(s);
            jet.push([b[0] + d0 * nf[0], b[1] + d0 * nf[1]]);
        }
        jet.extend_from_slice(&pts);
        pts = jet;
    } else {
        let keep: Vec<[f64; 2]> = pts
            .iter()
            .copied()
            .skip_while(|p| sh.body_s(*p) > s_cut_new * (1.0 - 1e-9))
            .collect();
        pts = keep;
        // New first node on the cut normal, at the thickness of the first node kept.
        let dk = thick(pts[0]);
        let b = sh.body_point(s_cut_new);
        pts.insert(0, [b[0] + dk * nf[0], b[1] + dk * nf[1]]);
    }
    let s = arc_length(&pts);
    let kr = root_node(&pts);
    let at = graded(*s.last().unwrap_or(&1.0), s[kr], h0, 0.0, grid.growth);
    let mut fs = resample(&pts, &at);
    let last = fs.len() - 1;
    fs[last] = [sh.far(), 0.0];
    let body = graded(s_cut_new, s_root, h0, grid.growth, 0.0);
    Shape {
        beta: sh.beta,
        s_cut: s_cut_new,
        fs,
        body,
    }
}

/// First guess: Wagner's free surface of the wedge, eta = (xi / k) asin(k / xi) - 1 for xi > k,
/// k = pi / (2 tan beta) (from the flat-plate vertical velocity V (|x| / sqrt(x^2 - c^2) - 1) with
/// c = k V t integrated in time; vertical at the contact point, where it meets the body at height
/// pi/2 - 1), moved off the body by `d0` (in V t), with a jet of that
/// thickness along the body thinning towards the cut.
pub fn first_guess(beta: f64, grid: &Grid, d0: f64) -> Shape {
    let k = 0.5 * std::f64::consts::PI / beta.tan();
    let shift = d0 / beta.sin();
    let far = grid.far * k.hypot(1.0);
    let tb = [beta.cos(), beta.sin()];
    let nf = [beta.sin(), -beta.cos()];
    let bp = |s: f64| [s * tb[0], -1.0 + s * tb[1]];
    let pr = [k + shift, 0.5 * std::f64::consts::PI - 1.0];
    let s_r = pr[0] * tb[0] + (pr[1] + 1.0) * tb[1];
    let s_cut = s_r + grid.jet * d0;
    let mut pts = Vec::new();
    let m = 60;
    for i in 0..m {
        let s = s_cut - (s_cut - s_r) * i as f64 / m as f64;
        let d = d0 * (1.0 - 0.7 * (s - s_r) / (s_cut - s_r));
        let b = bp(s);
        pts.push([b[0] + d * nf[0], b[1] + d * nf[1]]);
    }
    let mo = 400;
    for i in 0..=mo {
        let u = i as f64 / mo as f64;
        let x = k * (far / k).powf(u * u);
        let eta = if i == mo {
            0.0
        } else {
            (x / k) * (k / x).min(1.0).asin() - 1.0
        };
        pts.push([x + shift, eta]);
    }
    if let Some(p) = pts.last_mut() {
        p[0] = far;
    }
    let sh = Shape {
        beta,
        s_cut,
        fs: pts,
        body: vec![0.0, s_cut],
    };
    remesh(&sh, grid)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flat_surface_carries_no_potential() {
        // The undisturbed surface eta = 0: r . n = 0 and Phi = 0 solve the ODE exactly.
        let fs: Vec<[f64; 2]> = (0..=40).map(|k| [1.0 + 0.5 * k as f64, 0.0]).collect();
        let (node, mid) = surface_potential(&fs).unwrap();
        assert!(node.iter().chain(&mid).all(|v| v.abs() < 1e-12));
    }

    #[test]
    fn surface_potential_follows_the_dynamic_condition() {
        // On any curve the ODE keeps |grad Phi - r|^2 = |r|^2 - 2 Phi with a tangential relative
        // velocity: check dPhi/ds against that relation by finite differences on a fine curve.
        // Node 0 at xi = 2 (towards the jet), the far end at xi = 10.
        let fs: Vec<[f64; 2]> = (0..=4000)
            .map(|k| {
                let x = 2.0 + 0.002 * k as f64;
                [x, 0.3 / (x * x)]
            })
            .collect();
        let (node, _) = surface_potential(&fs).unwrap();
        let k = 2000;
        // s runs from node k + 1 to node k - 1.
        let (a, b) = (fs[k + 1], fs[k - 1]);
        let l = (b[0] - a[0]).hypot(b[1] - a[1]);
        let t = [(b[0] - a[0]) / l, (b[1] - a[1]) / l];
        let dphi = (node[k - 1] - node[k + 1]) / l;
        let r = fs[k];
        let u = dphi - dot(r, t);
        let want = (dot(r, r) - 2.0 * node[k]).sqrt();
        assert!((u - want).abs() < 1e-6 * want, "{u} {want}");
        assert!(node[0].abs() > 1e-6, "a curved surface carries potential");
    }
}
