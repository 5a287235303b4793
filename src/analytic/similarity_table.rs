//! The similarity solution's peak pressure tabulated once, and the wedge-equivalent correction of the
//! modified Logvinovich model's (MLM) peak pressure built on it.
//!
//! **The table.** Cp_max = 2 p_max / (rho V^2) of the nonlinear similarity solution of a wedge entering
//! at constant speed ([`crate::analytic::similarity`], Dobrovol'skaya 1969; Zhao & Faltinsen 1993), for
//! 5 to 55 deg in steps of 5, computed by this tool (`slamtool similarity --table`, default grid
//! [`crate::analytic::similarity::DEFAULT_GRID`]) and copied here because one solve costs seconds
//! (measured: 2-15 s a deadrise on the loaded 2-core machine), too slow for every section of a screening.
//! The test `the_table_is_the_solver_s` re-solves at 5, 10 and 20 deg and checks the copy. Between the
//! nodes the slowly varying Cp_max tan^2(beta) is interpolated (shape-preserving cubic,
//! [`crate::numerics::pchip`]) with the Wagner limit pi^2/4 added at 0 deg (Wagner's Cp_max = (pi^2/4)
//! cot^2(beta) is the small-deadrise limit of the similarity solution: Cp_max / Wagner is 0.991 at 5 deg).
//! No value is given above 55 deg (the iteration does not converge at 60 deg).
//!
//! **The MLM's own wedge peak.** With the full Bernoulli equation (`logvinovich_mlm`), the MLM pressure
//! of a wedge at constant speed near the contact point is a/sqrt(c - x) - b/(c - x) with
//! a = rho V c c' / sqrt(2 c), b = rho V^2 c / (4 (1 + tan^2 beta)); its maximum a^2/(4 b) plus the
//! uniform term -rho V^2/2 (and the x-dependent remainder, which vanishes at the peak to leading order)
//! gives, with c' = (pi/2) V cot(beta),
//!
//! ```text
//! Cp_MLM = pi^2 / (4 sin^2 beta) - sin^2 beta
//! ```
//!
//! (checked numerically against the model's own peak search in the tests). It is 18 % above the
//! similarity Cp_max at 20 deg, 40 % at 30 deg, 71 % at 40 deg and 73-76 % from 45 to 55 deg (where
//! the similarity maximum is at the keel), while its force is within 2 % up to 20 deg and 7 % at 30 deg
//! (22 % at 45 deg; [`crate::analytic::similarity_force`]): the MLM's pressure near the jet root is too
//! high at moderate deadrise.
//!
//! **The correction** (a choice, not a published model). The MLM pressure at time t is multiplied by
//!
//! ```text
//! K(beta_c) = Cp_sim(beta_c) / Cp_MLM(beta_c),   beta_c = atan f'(c(t)),
//! ```
//!
//! the local deadrise at the contact point. This is this tool's choice, not a published model (neither
//! Korobkin 2004 nor the comparison of MLM variants by Tassin et al. 2010 was reachable here to take a
//! published variant from). Its basis is *local-wedge equivalence*: the peak pressure lies in the
//! jet-root region, whose flow is set by the local quantities at the contact point (in Wagner theory the
//! inner jet-root solution depends only on c' and the local jet thickness, Zhao & Faltinsen 1993
//! section 2, [`crate::analytic::wagner_pressure`]), so the nonlinear correction of a smooth section at
//! the contact point is taken as the wedge's of the tangent deadrise there. It is applied to the ratio
//! rather than to the value, so that the MLM
//! keeps the section's shape, its wetting and the varying speed, and only its wedge bias at the local
//! deadrise is removed. Assumptions: constant speed (the similarity solution has no V'; the MLM's V'
//! terms are scaled alike), the flow at the peak is the local wedge's, no gravity. Consequences: for a
//! wedge at constant speed the corrected peak is the similarity Cp_max up to the interpolation error of
//! this table (stated, measured in the tests); the whole distribution is scaled, so a sensor wider than
//! the jet-root region reads the scaled MLM shape, not the similarity shape (the error this makes is
//! measured against the similarity sensor reference, `similarity_sensor`); the section force has its
//! own correction, for the equivalent wedge of the whole wetted width
//! ([`crate::analytic::similarity_force`]). Above 55 deg local deadrise the factor of 55 deg is used and the estimate says
//! so (the MLM over-prediction grows with the deadrise, so this under-corrects); at 0 deg (a flat keel,
//! whose contact is acoustic) the factor is 1.

use std::f64::consts::PI;
use std::sync::OnceLock;

use crate::numerics::pchip::Pchip;

/// Deadrise angles of the table (deg).
pub const DEADRISE_DEG: [f64; 11] = [
    5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0, 45.0, 50.0, 55.0,
];

/// Similarity Cp_max at [`DEADRISE_DEG`] (`slamtool similarity --table`, default grid, run at commit
/// 56903a4; from 45 deg up the maximum is at the keel).
pub const CP_MAX: [f64; 11] = [
    319.4418, 77.6346, 33.2280, 17.7083, 10.6578, 6.8924, 4.6591, 3.2490, 2.5146, 2.0864, 1.7182,
];

/// The stated error of the corrected MLM wedge peak against the similarity Cp_max, 5-55 deg (a
/// fraction): the interpolation error of this table plus the MLM's peak search. Measured against fresh
/// solves half-way between the nodes: -0.03 % at 12.5 deg, 0.00 % at 27.5 deg, +1.9 % at 42.5 deg (the
/// similarity maximum moves from the spray root to the keel at 42.2 deg, [`KEEL_MAXIMUM_FROM_DEG`], a kink in Cp_max
/// that the interpolation rounds off); at the nodes within 0.5 % (the peak search). Stated as 2.5 %.
pub const STATED_ERROR: f64 = 0.025;

/// Largest local deadrise with a tabulated value (deg).
pub const MAX_DEG: f64 = 55.0;

/// The deadrise (deg) from which the similarity solution's pressure maximum is at the keel, not at the
/// spray root (the solver on its default grid: the spray-root maximum 2.823 against 2.809 at the keel at
/// 42.05 deg; at 42.2 deg the keel's panel reads 2.793 against 2.7935 for the panel maximum, equal
/// within 0.01 %, and the refined maximum, 2.797, is the keel's; test `the_maximum_moves_to_the_keel`).
/// From about 41 to 45 deg the two differ by under 1 %: the pressure along the lower side is nearly
/// flat (Cp 2.29-2.52 over z/(V t) from -0.9 to 0.3 at 45 deg). A sensor on a side this steep sees no
/// impact pulse pass: at constant speed its pressure 1/2 rho V^2 Cp(z_s / (V t)) grows towards the
/// keel's value as the wetting deepens and falls only as the entry slows, so the largest value of its
/// impact window is a level, not the peak of an event ([`crate::loads::anatomy`]).
pub const KEEL_MAXIMUM_FROM_DEG: f64 = 42.2;

/// The MLM's constant-speed wedge peak pressure coefficient pi^2 / (4 sin^2 beta) - sin^2 beta.
pub fn mlm_wedge_cp_max(beta: f64) -> f64 {
    let s2 = beta.sin().powi(2);
    0.25 * PI * PI / s2 - s2
}

fn interpolant() -> &'static Pchip {
    static P: OnceLock<Pchip> = OnceLock::new();
    P.get_or_init(|| {
        let mut x = vec![0.0];
        let mut y = vec![0.25 * PI * PI];
        for (d, cp) in DEADRISE_DEG.iter().zip(CP_MAX) {
            x.push(*d);
            y.push(cp * d.to_radians().tan().powi(2));
        }
        Pchip::new(&x, &y)
    })
}

/// Similarity Cp_max at a deadrise in degrees, interpolated in the table (module notes); `None` outside
/// (0, 55] deg.
pub fn cp_max(deg: f64) -> Option<f64> {
    (deg > 0.0 && deg <= MAX_DEG).then(|| interpolant().eval(deg) / deg.to_radians().tan().powi(2))
}

/// The correction factor of the MLM pressure at a local deadrise `beta` (rad).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PeakCorrection {
    /// K = Cp_sim / Cp_MLM (1 at or below 0 deg).
    pub factor: f64,
    /// The local deadrise was above [`MAX_DEG`]: the factor of 55 deg is used.
    pub above_table: bool,
}

/// K(beta) of the module notes; beta in radians, below 0 (a hollow) or 0 taken as no correction.
pub fn peak_correction(beta: f64) -> PeakCorrection {
    let deg = beta.to_degrees();
    if deg.is_nan() || deg <= 0.0 {
        return PeakCorrection {
            factor: 1.0,
            above_table: false,
        };
    }
    let d = deg.min(MAX_DEG);
    let factor = cp_max(d).map_or(1.0, |cp| cp / mlm_wedge_cp_max(d.to_radians()));
    PeakCorrection {
        factor,
        above_table: deg > MAX_DEG,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn table_nodes_are_returned_and_the_factor_tends_to_one() {
        for (d, cp) in DEADRISE_DEG.iter().zip(CP_MAX) {
            assert!((cp_max(*d).unwrap() / cp - 1.0).abs() < 1e-12);
        }
        assert!(cp_max(0.0).is_none() && cp_max(56.0).is_none() && cp_max(f64::NAN).is_none());
        let k1 = peak_correction(1f64.to_radians()).factor;
        assert!(k1 < 1.0 && k1 > 0.99, "{k1}");
        let k = |d: f64| peak_correction(d.to_radians()).factor;
        // The MLM over-predicts more as the deadrise grows up to 45 deg; from there the similarity
        // maximum is at the keel and the ratio stays near 0.57.
        assert!(DEADRISE_DEG[..9].windows(2).all(|w| k(w[1]) < k(w[0])));
        assert!(DEADRISE_DEG.iter().all(|&d| k(d) < 1.0 && k(d) > 0.5));
        assert_eq!(peak_correction(0.0).factor, 1.0);
        let high = peak_correction(70f64.to_radians());
        assert!(high.above_table && high.factor == k(55.0));
    }

    /// The copy is the solver's: fresh solves at 5, 10 and 20 deg on the default grid give the tabulated
    /// Cp_max.
    #[test]
    fn the_table_is_the_solver_s() {
        for k in [0, 1, 3] {
            let s = crate::analytic::similarity::solve(DEADRISE_DEG[k]).unwrap();
            assert!(
                (s.cp_max / CP_MAX[k] - 1.0).abs() < 1e-5,
                "{} deg: solver {} table {}",
                DEADRISE_DEG[k],
                s.cp_max,
                CP_MAX[k]
            );
        }
    }

    /// Below [`KEEL_MAXIMUM_FROM_DEG`] the maximum is near the spray root (above the calm surface), from
    /// it on at the keel's panel (z/(V t) near -1).
    #[test]
    fn the_maximum_moves_to_the_keel() {
        use crate::analytic::similarity::solve;
        let below = solve(KEEL_MAXIMUM_FROM_DEG - 0.2).unwrap();
        let above = solve(KEEL_MAXIMUM_FROM_DEG + 0.1).unwrap();
        assert!(below.z_cp_max > 0.0, "{}", below.z_cp_max);
        assert!(above.z_cp_max < -0.8, "{}", above.z_cp_max);
        // the side is nearly flat there: the keel's value within 1 % of the maximum below the angle
        assert!(below.pressure[0][1] > 0.99 * below.cp_max);
    }

    /// Issue 28 item 2, measurement: at every 2.5 deg from 5 to 55 deg the fresh similarity Cp_max
    /// against the MLM (closed form and its own peak search), Wagner's (the generalised Wagner model's
    /// wedge peak) and the corrected MLM; then the seven 10 mm sensors of the validation wedges (5 m/s,
    /// half-beam 0.25 m, 15-60 % of the side, to 80 % of chine wetting) by the corrected and the plain
    /// MLM against the similarity sensor reference, both filtered at 2 kHz.
    /// `cargo test --release --lib similarity_table -- --ignored --nocapture`
    #[test]
    #[ignore = "measurement, minutes"]
    fn measure_corrected_mlm_against_similarity() {
        use crate::analytic::logvinovich_mlm::Mlm;
        use crate::analytic::similarity::{self as sim, DEFAULT_GRID};
        use crate::analytic::similarity_sensor::{SensorSpan, similarity_sensor_reference};
        use crate::loads::butterworth::LowPass;
        let degs: Vec<f64> = (0..=20).map(|k| 5.0 + 2.5 * k as f64).collect();
        let q = 0.5 * 1000.0 * 25.0;
        for r in sim::table(&degs, &DEFAULT_GRID) {
            let d = r.deadrise_deg;
            let Ok(s) = r.solution else {
                eprintln!("{d}: no solution");
                continue;
            };
            let b = d.to_radians();
            let t: Vec<f64> = (0..=20).map(|k| k as f64 * 1e-4).collect();
            let m = Mlm::new(
                &[[0.0, 0.0], [0.5, 0.5 * b.tan()]],
                &t,
                &vec![5.0; t.len()],
                1000.0,
            )
            .unwrap();
            let st = *m.history().states.last().unwrap();
            eprintln!(
                "{d:>5}: sim {:.4} table {:.4} ({:+.4}); MLM closed {:.4} search {:.4}; ratio MLM {:.3} GWM {:.3} \
                 corrected {:.4}; force MLM/sim {:.3}",
                s.cp_max,
                cp_max(d).unwrap_or(f64::NAN),
                cp_max(d).unwrap_or(f64::NAN) / s.cp_max - 1.0,
                mlm_wedge_cp_max(b),
                m.peak(&st).1 / q,
                m.peak(&st).1 / q / s.cp_max,
                sim::wagner_cp_max(d) / s.cp_max,
                m.corrected_peak(&st).1 / q / s.cp_max,
                m.force(&st) / (1000.0 * 125.0 * st.t) / s.force
            );
        }
        for d in [10.0f64, 20.0, 30.0, 40.0, 50.0] {
            let b = d.to_radians();
            let (half_beam, v, width, fc) = (0.25, 5.0, 0.01, 2000.0);
            let t_end = 0.8 * 2.0 / PI * half_beam * b.tan() / v;
            let n = 4000;
            let t: Vec<f64> = (0..=n).map(|k| t_end * k as f64 / n as f64).collect();
            let m = Mlm::new(&[[0.0, 0.0], [1.0, b.tan()]], &t, &vec![v; t.len()], 1000.0).unwrap();
            let side = half_beam / b.cos();
            let panels: Vec<(f64, f64)> = (0..7)
                .map(|k| {
                    let sc = side * (0.15 + 0.45 * k as f64 / 6.0);
                    (sc - 0.5 * width, sc + 0.5 * width)
                })
                .collect();
            let (corr, _) = m.corrected_sensor_histories(&panels);
            let plain = m.sensor_histories(&panels);
            let tm = m.times();
            let dt = tm[1] - tm[0];
            let lp = LowPass::new(fc, 1.0 / dt, 2).unwrap();
            let peak = |h: &[f64]| lp.filtfilt(h).into_iter().fold(0.0, f64::max);
            let mut line = format!("{d} deg sensors, corrected / plain MLM over similarity:");
            for (k, p) in panels.iter().enumerate() {
                let r = similarity_sensor_reference(
                    d,
                    v,
                    1000.0,
                    SensorSpan {
                        s_m: 0.5 * (p.0 + p.1),
                        width_m: width,
                    },
                    t_end,
                    Some(fc),
                )
                .unwrap();
                line += &format!(
                    " {:.3}/{:.3}",
                    peak(&corr[k]) / r.peak_pa,
                    peak(&plain[k]) / r.peak_pa
                );
            }
            eprintln!("{line}");
        }
    }
}
