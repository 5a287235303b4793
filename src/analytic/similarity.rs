//! Nonlinear similarity solution of constant-speed symmetric wedge entry (DOC TODO).

use super::similarity_mesh::root_node;
use super::similarity_solver::{self as solver, Grid, Shape};
use crate::error::{Error, Result};

/// The default discretisation.
pub const DEFAULT_GRID: Grid = Grid {
    h_root: 0.25,
    growth: 0.12,
    far: 12.0,
    jet: 8.0,
    arc_panels: 16,
};

/// The similarity solution for one deadrise.
#[derive(Debug, Clone)]
pub struct Similarity {
    /// Deadrise (deg).
    pub deadrise_deg: f64,
    /// (z/(V t), Cp) at the body panels' midpoints from the keel to the jet cut; z from the undisturbed
    /// free surface (apex at -1).
    pub pressure: Vec<[f64; 2]>,
    pub cp_max: f64,
    pub z_cp_max: f64,
    /// Spray root (largest curvature of the free surface): (x/(V t), z/(V t)).
    pub root: [f64; 2],
    /// Its projection on the body, as z/(V t).
    pub root_body_z: f64,
    /// Distance from the root to the body (the jet-root thickness) / (V t).
    pub root_thickness: f64,
    /// F / (rho V^3 t), both sides.
    pub force: f64,
    /// Free surface (x/(V t), z/(V t)) from the jet cut to the far field.
    pub free_surface: Vec<[f64; 2]>,
    /// Largest kinematic residual at the end.
    pub residual: f64,
    pub panels: usize,
}

/// Solves for a deadrise in degrees with the default grid.
pub fn solve(deadrise_deg: f64) -> Result<Similarity> {
    solve_with(deadrise_deg, &DEFAULT_GRID)
}

/// Solves for a deadrise in degrees on a given grid.
pub fn solve_with(deadrise_deg: f64, grid: &Grid) -> Result<Similarity> {
    check_deadrise(deadrise_deg)?;
    let beta = deadrise_deg.to_radians();
    let mut sh = solver::first_guess(beta, grid);
    let tol = 1e-9;
    let mut res = f64::MAX;
    for _ in 0..6 {
        let root_before = sh.body_s(sh.fs[root_node(&sh.fs)]);
        res = solver::newton(&mut sh, grid.arc_panels, 12, tol)?;
        sh = solver::remesh(&sh, grid);
        let root_after = sh.body_s(sh.fs[root_node(&sh.fs)]);
        if (root_after - root_before).abs() < 1e-4 * root_after {
            break;
        }
    }
    res = res.min(solver::newton(&mut sh, grid.arc_panels, 12, tol)?);
    post(&sh, grid, deadrise_deg, res)
}

/// Error unless 5 <= deadrise <= 60 deg... (range TBD)
pub fn check_deadrise(deg: f64) -> Result<()> {
    if deg.is_finite() && (2.0..=75.0).contains(&deg) {
        Ok(())
    } else {
        Err(Error::Invalid(format!(
            "the similarity solution is computed for a deadrise from 2 to 75 deg, got {deg} deg"
        )))
    }
}

fn post(sh: &Shape, grid: &Grid, deg: f64, residual: f64) -> Result<Similarity> {
    let e = solver::evaluate(sh, grid.arc_panels)?;
    let nb = sh.body.len() - 1;
    let tb = [sh.beta.cos(), sh.beta.sin()];
    let s_mid: Vec<f64> = sh.body.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
    let phi = &e.sol.phi[..nb];
    let mut pressure = Vec::with_capacity(nb);
    let mut force = 0.0;
    for i in 0..nb {
        // dPhi/ds from the neighbouring midpoints (three-point formula on a non-uniform grid).
        let (a, b, c) = if i == 0 {
            (0, 1, 2)
        } else if i == nb - 1 {
            (nb - 3, nb - 2, nb - 1)
        } else {
            (i - 1, i, i + 1)
        };
        let (sa, sb, sc) = (s_mid[a], s_mid[b], s_mid[c]);
        let x = s_mid[i];
        let dphi = phi[a] * (2.0 * x - sb - sc) / ((sa - sb) * (sa - sc))
            + phi[b] * (2.0 * x - sa - sc) / ((sb - sa) * (sb - sc))
            + phi[c] * (2.0 * x - sa - sb) / ((sc - sa) * (sc - sb));
        let r = sh.body_point(x);
        let u = dphi - (r[0] * tb[0] + r[1] * tb[1]);
        let cp = r[0] * r[0] + r[1] * r[1] - 2.0 * phi[i] - u * u;
        pressure.push([r[1], cp]);
        force += cp * (sh.body[i + 1] - sh.body[i]) * tb[0];
    }
    let (k, _) = pressure
        .iter()
        .enumerate()
        .fold((0, f64::MIN), |b, (k, p)| if p[1] > b.1 { (k, p[1]) } else { b });
    let (z_cp_max, cp_max) = if k > 0 && k + 1 < nb {
        parabola_peak(pressure[k - 1], pressure[k], pressure[k + 1])
    } else {
        (pressure[k][0], pressure[k][1])
    };
    let kr = root_node(&sh.fs);
    let root = sh.fs[kr];
    let sr = sh.body_s(root);
    let bp = sh.body_point(sr);
    Ok(Similarity {
        deadrise_deg: deg,
        pressure,
        cp_max,
        z_cp_max,
        root,
        root_body_z: bp[1],
        root_thickness: (root[0] - bp[0]).hypot(root[1] - bp[1]),
        force,
        free_surface: sh.fs.clone(),
        residual,
        panels: e.panels.len(),
    })
}

/// Vertex of the parabola through three points (x, y).
fn parabola_peak(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> (f64, f64) {
    let d1 = (b[1] - a[1]) / (b[0] - a[0]);
    let d2 = (c[1] - b[1]) / (c[0] - b[0]);
    let curv = (d2 - d1) / (c[0] - a[0]);
    if curv >= 0.0 {
        return (b[0], b[1]);
    }
    // y = b + d (x - xb) + curv (x - xb)(x - x?) ; use Newton form through a, b, c.
    // y(x) = a1 + d1 (x - xa) + curv (x - xa)(x - xb)
    let xv = 0.5 * (a[0] + b[0]) - d1 / (2.0 * curv);
    let yv = a[1] + d1 * (xv - a[0]) + curv * (xv - a[0]) * (xv - b[0]);
    (xv, yv)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[ignore]
    fn explore() {
        for deg in [20.0] {
            let t = std::time::Instant::now();
            let s = solve(deg).unwrap();
            eprintln!(
                "{deg}: cp {:.4} at {:.4}, root {:?} body z {:.4} thick {:.4} F {:.4} res {:.2e} panels {} ({:?})",
                s.cp_max,
                s.z_cp_max,
                s.root,
                s.root_body_z,
                s.root_thickness,
                s.force,
                s.residual,
                s.panels,
                t.elapsed()
            );
        }
    }
}
