//! The analytic section force corrected to the similarity solution's force: the wedge-equivalent
//! correction of the modified Logvinovich model's (MLM) force.
//!
//! **Why.** The flat-plate Wagner force F = rho pi c c' V (Wagner 1932; the generalised Wagner estimate,
//! [`crate::analytic::generalised_wagner`]) of a wedge at constant speed is F / (rho V^3 t) =
//! (pi^3 / 4) cot^2(beta). Against the nonlinear similarity solution ([`crate::analytic::similarity`],
//! Dobrovol'skaya 1969; Zhao & Faltinsen 1993) it is 8 % high at 5 deg, 38 % at 20 deg, 66 % at 30 deg,
//! 126 % at 45 deg and 184 % at 55 deg (test `wagner_and_mlm_forces_against_the_similarity_force`):
//! the flat plate's added mass ignores that the body's sides are not horizontal. The MLM (Korobkin 2004)
//! keeps the body shape in the body condition and integrates the full Bernoulli pressure, and its force
//! is much closer: -2 % at 5 and 10 deg, +1 % at 20 deg, +7 % at 30 deg, +22 % at 45 deg and +32 % at 55 deg.
//!
//! **The correction** (this tool's choice, not a published model, as for the pressure in
//! [`crate::analytic::similarity_table`]). The MLM force at time t is multiplied by
//!
//! ```text
//! K_F(beta_e) = C_F,sim(beta_e) / C_F,MLM(beta_e),   beta_e = atan(pi h / (2 c)),
//! ```
//!
//! C_F = F / (rho V^3 t) of the wedge by each model, h the keel's penetration and c the wetted
//! half-width of the Wagner condition. beta_e is the deadrise of the *equivalent wedge*: the wedge that,
//! entering to the same depth, has the same Wagner wetted half-width (c = (pi/2) h cot beta for a wedge,
//! so for a wedge beta_e is its deadrise at every instant). The force is an integral over the whole
//! wetted width, so its equivalent wedge is a mean of the section's deadrise over it, not the local
//! deadrise at the contact point that the pressure's correction uses: on a flared section the local
//! deadrise at the contact is that of the flare while most of the force still acts on the flatter part
//! below. Assumptions, as for the pressure: constant speed (the MLM's V' terms are scaled alike), no
//! gravity, the MLM's bias on the section is the equivalent wedge's. For a wedge at constant speed the
//! corrected force is the similarity force up to the interpolation of the table (stated:
//! [`FORCE_STATED_ERROR`]); on other sections and at varying speed the error is not measured against an
//! exact solution (none is available here).
//!
//! **The table.** C_F,sim at 5-55 deg ([`FORCE`], the solver's values, checked by
//! `the_force_table_is_the_solver_s`) and C_F,MLM of the model itself at the same angles (computed once,
//! [`mlm_wedge_force_coefficient`]). K_F is interpolated between the nodes with a shape-preserving
//! cubic ([`crate::numerics::pchip`]). Below 5 deg (no similarity solution is computed there) the factor
//! of 5 deg is used (it is 1.02; both models tend to Wagner's force as the deadrise goes to zero), and
//! above 55 deg that of 55 deg, flagged (the MLM's over-prediction grows with the deadrise, so this
//! under-corrects: the force stays on the high side).
//!
//! Discretisation of the similarity force: halving the solver's panel size at the root and its growth
//! rate moves C_F,sim by -0.12 % at 5 deg, -0.17 % at 10, -0.25 % at 20 and -0.26 % at 30 deg; halving
//! the root panel alone moves it by -0.08 % at 40 deg and +0.002 % at 50 deg, and a far field 1.5 times
//! as large by 0.001 % at 40 deg (at 45 and 55 deg those finer grids did not converge).

use std::sync::OnceLock;

use super::logvinovich_mlm::Mlm;
use super::similarity_table::{DEADRISE_DEG, MAX_DEG, PeakCorrection};
use crate::error::{Error, Result};
use crate::numerics::pchip::Pchip;

/// Similarity F / (rho V^3 t) (both sides) at [`DEADRISE_DEG`] (`slamtool similarity --table --json`,
/// default grid, run at commit 22e1685).
pub const FORCE: [f64; 11] = [
    938.05155889,
    213.27217370,
    85.02609038,
    42.32864564,
    23.60185552,
    14.03403609,
    8.66053790,
    5.44505973,
    3.43651119,
    2.16279351,
    1.33836739,
];

/// The stated error of the corrected MLM wedge force against the similarity force, 5-55 deg (a
/// fraction): the interpolation of the factor between the nodes, measured against fresh solves
/// half-way between them in `corrected_force_is_the_similarity_force_between_the_nodes`: -0.005 %
/// at 12.5 deg, +0.007 % at 27.5 deg, -0.11 % at 42.5 deg. Stated as 0.5 %.
pub const FORCE_STATED_ERROR: f64 = 0.005;

/// The MLM's F / (rho V^3 t) of a wedge of deadrise `beta` (rad) entering at constant speed: constant
/// in time for the self-similar wedge flow, so taken at one instant (1 ms at 1 m/s on a side long
/// enough never to be wetted to its end).
pub fn mlm_wedge_force_coefficient(beta: f64) -> Result<f64> {
    let t: Vec<f64> = (0..=20).map(|k| k as f64 * 5e-5).collect();
    let half = [[0.0, 0.0], [1.0, beta.tan()]];
    let m = Mlm::new(&half, &t, &vec![1.0; t.len()], 1000.0)?;
    let s = m
        .history()
        .states
        .last()
        .copied()
        .ok_or_else(|| Error::Invalid("modified Logvinovich model: no entry state".into()))?;
    Ok(m.force(&s) / (1000.0 * s.t))
}

/// K_F at the nodes, interpolated (module notes).
fn interpolant() -> &'static Pchip {
    static P: OnceLock<Pchip> = OnceLock::new();
    P.get_or_init(|| {
        let k: Vec<f64> = DEADRISE_DEG
            .iter()
            .zip(FORCE)
            .map(|(d, f)| {
                // The wedge is a valid MLM input at every node; a failure here is a bug.
                let m = mlm_wedge_force_coefficient(d.to_radians())
                    .expect("the MLM force of a wedge between 5 and 55 deg");
                f / m
            })
            .collect();
        Pchip::new(&DEADRISE_DEG, &k)
    })
}

/// K_F(beta) of the module notes; `beta` the equivalent wedge's deadrise in radians (not a number:
/// factor 1, no correction).
pub fn force_correction(beta: f64) -> PeakCorrection {
    let deg = beta.to_degrees();
    if deg.is_nan() {
        return PeakCorrection {
            factor: 1.0,
            above_table: false,
        };
    }
    let d = deg.clamp(DEADRISE_DEG[0], MAX_DEG);
    PeakCorrection {
        factor: interpolant().eval(d),
        above_table: deg > MAX_DEG,
    }
}

impl Mlm {
    /// The equivalent wedge's deadrise atan(pi h / (2 c)) (rad) of a state (module notes), or `None`
    /// before wetting or in the acoustic stage.
    pub fn equivalent_wedge_deadrise(
        &self,
        s: &super::entry_kinematics::EntryState,
    ) -> Option<f64> {
        (s.c > 0.0 && s.c_dot.is_some()).then(|| (0.5 * std::f64::consts::PI * s.h / s.c).atan())
    }

    /// The force correction of every kept sample (factor 1 before wetting and in the acoustic stage).
    pub fn force_corrections(&self) -> Vec<PeakCorrection> {
        self.history()
            .states
            .iter()
            .map(|s| {
                self.equivalent_wedge_deadrise(s).map_or(
                    PeakCorrection {
                        factor: 1.0,
                        above_table: false,
                    },
                    force_correction,
                )
            })
            .collect()
    }

    /// [`Mlm::force_history`] with every sample multiplied by its force correction, and the
    /// corrections (one per kept sample).
    pub fn corrected_force_history(&self) -> (Vec<f64>, Vec<PeakCorrection>) {
        let k = self.force_corrections();
        let f = self
            .force_history()
            .into_iter()
            .zip(&k)
            .map(|(f, c)| f * c.factor)
            .collect();
        (f, k)
    }
}

#[cfg(test)]
#[path = "similarity_force_tests.rs"]
mod tests;
