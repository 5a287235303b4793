//! The classical bounds on a constant-speed wedge: Wagner's and von Karman's forces bound the section
//! force, Wagner's point peak bounds the sensor peaks (with the similarity solution and Wagner's
//! composite distribution, like for like, shown beside it).

use super::conditions::WATER_DENSITY;
use super::drops::window_mean;
use super::run::Memo;
use super::wedge_references::{
    filtered_peak, like_for_like, reference_span, wagner_like_for_like_cp,
};
use super::wedges::{mean_ratio, ratio_range, wedge_run};
use super::{Case, Figure, Mode, Outcome, Reference, Series, Table};
use crate::analytic::{von_karman, wagner};
use crate::error::Result;

/// Wagner's and von Karman's forces bound the section force: F_SPH / F_Wagner averaged over 30-60 % of
/// the chine-wetting time must lie in [F_vK / F_W, 1] = [4/pi^2, 1]. The modified Logvinovich model's
/// force ([`mlm_force_coefficient`]) is shown beside it, with the ratio F_SPH / F_MLM in the notes: a
/// closer cross-check than the bounds (the MLM keeps the nonlinear Bernoulli terms that Wagner's
/// pressure drops), not a pass/fail criterion, since the MLM's own error against a fully nonlinear
/// solution is not in the reference data.
pub fn force_bounds(case: &Case, mode: Mode, memo: &Memo) -> Result<Outcome> {
    let deg = case.number("deadrise_deg")?;
    let n = case.particles(mode)?;
    let run = wedge_run(case, deg, n, memo)?;
    let h = &run.result.history;
    let (t0, t1) = (0.3 * run.t_wet, 0.6 * run.t_wet);
    let f_sph = window_mean(&h.t, &h.fz, t0, t1);
    let tm = 0.45 * run.t_wet;
    let f_w = wagner::force(run.beta, WATER_DENSITY, run.speed, tm)?;
    let f_vk = von_karman::force(run.beta, WATER_DENSITY, run.speed, tm)?;
    let theory = |f: &dyn Fn(f64) -> Result<f64>| -> Result<Vec<[f64; 2]>> {
        (1..=20)
            .map(|k| {
                let t = h.t.last().copied().unwrap_or(0.0) * k as f64 / 20.0;
                Ok([t * 1e3, f(t)?])
            })
            .collect()
    };
    let wag = theory(&|t| wagner::force(run.beta, WATER_DENSITY, run.speed, t))?;
    let vk = theory(&|t| von_karman::force(run.beta, WATER_DENSITY, run.speed, t))?;
    let k_mlm = mlm_force_coefficient(run.beta)?;
    let f_mlm = k_mlm * WATER_DENSITY * run.speed.powi(3) * tm;
    let mlm = theory(&|t| Ok(k_mlm * WATER_DENSITY * run.speed.powi(3) * t))?;
    let dp = run.result.summary.dp_m;
    Ok(Outcome {
        facts: vec![
            (
                "window_dp".into(),
                format!("{:.1}-{:.1}", run.speed * t0 / dp, run.speed * t1 / dp),
            ),
            (
                "window_mm".into(),
                format!("{:.0}-{:.0} mm", run.speed * t0 * 1e3, run.speed * t1 * 1e3),
            ),
            ("particles".into(), format!("{n}")),
        ],
        computed: f_sph / f_w,
        reference: Reference::Range {
            lower: f_vk / f_w,
            upper: 1.0,
        },
        table: Some(Table {
            header: vec![
                "window_s".into(),
                "sph_mean_force_n_per_m".into(),
                "von_karman_n_per_m".into(),
                "wagner_n_per_m".into(),
                "mlm_n_per_m".into(),
            ],
            rows: vec![vec![
                format!("{t0:.5}-{t1:.5}"),
                format!("{f_sph:.1}"),
                format!("{f_vk:.1}"),
                format!("{f_w:.1}"),
                format!("{f_mlm:.1}"),
            ]],
        }),
        figures: vec![Figure {
            name: "force".into(),
            title: format!("{deg}° wedge at {} m/s: section force", run.speed),
            x_label: "t (ms)".into(),
            y_label: "force (N/m)".into(),
            series: vec![
                Series {
                    label: format!("SPH, {n} particles"),
                    reference: false,
                    points: h.t.iter().zip(&h.fz).map(|(t, f)| [t * 1e3, *f]).collect(),
                },
                Series {
                    label: "Wagner (upper bound)".into(),
                    reference: true,
                    points: wag,
                },
                Series {
                    label: "von Karman (lower bound)".into(),
                    reference: true,
                    points: vk,
                },
                Series {
                    label: "modified Logvinovich model (cross-check)".into(),
                    reference: true,
                    points: mlm,
                },
            ],
        }],
        notes: vec![
            format!(
                "forces at mid-window t = {tm:.5} s; dp {:.4} m, c0 {:.0} m/s",
                run.result.summary.dp_m, run.result.summary.c0_m_s
            ),
            format!(
                "cross-check, not a criterion: SPH / modified Logvinovich model (Korobkin 2004) = {:.3} \
                 (MLM / Wagner = {:.3})",
                f_sph / f_mlm,
                f_mlm / f_w
            ),
        ],
    })
}

/// F / (rho V^3 t) of a wedge of deadrise `beta` (rad) at constant speed by the modified Logvinovich
/// model, the analytic module's ([`crate::analytic::similarity_force::mlm_wedge_force_coefficient`]).
pub use crate::analytic::similarity_force::mlm_wedge_force_coefficient as mlm_force_coefficient;

/// Wagner's peak pressure bounds the sensor peaks: the largest filtered sensor Cp over Wagner's point
/// Cp_max = (pi^2/4) cot^2(beta).
pub fn pressure_bound(case: &Case, mode: Mode, memo: &Memo) -> Result<Outcome> {
    let deg = case.number("deadrise_deg")?;
    let n = case.particles(mode)?;
    let cutoff = case.number("filter_hz")?;
    let run = wedge_run(case, deg, n, memo)?;
    let h = &run.result.history;
    let q = 0.5 * WATER_DENSITY * run.speed * run.speed;
    let cp_w = wagner::peak_pressure_coefficient(run.beta)?;
    let t_end = run.result.summary.setup.t_end;
    let mut pts = Vec::new();
    let mut sim = Vec::new();
    let mut composite = Vec::new();
    let mut rows = Vec::new();
    let summary = &run.result.summary;
    for ((col, s), named) in h
        .sensors
        .iter()
        .zip(&summary.setup.sensors)
        .zip(&summary.sensors)
    {
        let (p, t) = filtered_peak(&h.t, col, cutoff)?;
        let (centre, width) = reference_span(s, named);
        let (cp_ref, _) = like_for_like(run.beta, run.speed, centre, width, t_end, cutoff)?;
        let cp_c = wagner_like_for_like_cp(run.beta, run.speed, centre, width, t_end, cutoff)?;
        pts.push([s.s_m, p / q]);
        sim.push([s.s_m, cp_ref]);
        composite.push([s.s_m, cp_c]);
        rows.push(vec![
            format!("{:.4}", s.s_m),
            format!("{:.3}", p / q),
            format!("{:.3}", t * 1e3),
            format!("{cp_w:.3}"),
            format!("{cp_ref:.3}"),
            format!("{:.3}", p / q / cp_ref),
            format!("{cp_c:.3}"),
        ]);
    }
    let max = pts.iter().map(|p| p[1]).fold(f64::MIN, f64::max);
    let wag: Vec<[f64; 2]> = pts.iter().map(|p| [p[0], cp_w]).collect();
    let ratio = |p: &[f64; 2]| format!("{:.2}", p[1] / cp_w);
    let lowest = pts.iter().map(|p| p[1]).fold(f64::MAX, f64::min);
    let all_but_last = &pts[..pts.len().saturating_sub(1)];
    let (lo, hi) = all_but_last
        .iter()
        .fold((f64::MAX, f64::MIN), |b, p| (b.0.min(p[1]), b.1.max(p[1])));
    let mut facts = vec![
        ("cp_max".to_string(), format!("{cp_w:.2}")),
        ("sensors".to_string(), format!("{}", pts.len())),
        (
            "above".to_string(),
            format!("{}", pts.iter().filter(|p| p[1] > cp_w).count()),
        ),
        ("lowest".to_string(), format!("{:.2}", lowest / cp_w)),
        (
            "others_range".to_string(),
            format!("{:.2}-{:.2}", lo / cp_w, hi / cp_w),
        ),
    ];
    if let (Some(first), Some(last)) = (pts.first(), pts.last()) {
        facts.push(("first".into(), ratio(first)));
        facts.push(("last".into(), ratio(last)));
        facts.push(("last_girth".into(), format!("{:.3} m", last[0])));
        facts.push(("last_cp".into(), format!("{:.2}", last[1])));
    }
    Ok(Outcome {
        facts,
        computed: max / cp_w,
        reference: Reference::Value { value: 1.0 },
        table: Some(Table {
            header: vec![
                "sensor_girth_m".into(),
                "sph_cp".into(),
                "sph_peak_time_ms".into(),
                "wagner_cp_max".into(),
                "similarity_cp_like_for_like".into(),
                "sph_over_similarity".into(),
                "wagner_composite_cp_like_for_like".into(),
            ],
            rows,
        }),
        figures: vec![Figure {
            name: "sensor_cp".into(),
            title: format!("{deg}° wedge at {} m/s: sensor peak Cp", run.speed),
            x_label: "sensor girth from the keel (m)".into(),
            y_label: "peak Cp = 2p/(ρV²)".into(),
            series: vec![
                Series {
                    label: format!("SPH, {n} particles"),
                    reference: false,
                    points: pts.clone(),
                },
                Series {
                    label: "Wagner Cp_max (the bound of this case)".into(),
                    reference: true,
                    points: wag,
                },
                Series {
                    label: "similarity solution, like for like".into(),
                    reference: true,
                    points: sim.clone(),
                },
                Series {
                    label: "Wagner composite distribution, like for like (second line)".into(),
                    reference: true,
                    points: composite.clone(),
                },
            ],
        }],
        notes: vec![
            format!(
                "Wagner Cp_max = (π²/4) cot²β = {cp_w:.2}; dp {:.4} m, c0 {:.0} m/s",
                run.result.summary.dp_m, run.result.summary.c0_m_s
            ),
            format!(
                "not a criterion of this case: SPH sensor peak / similarity solution like for like (span \
                 mean, filtered) {:.2}-{:.2} (mean {:.3}); / Wagner composite like for like mean {:.3}",
                ratio_range(&pts, &sim).0,
                ratio_range(&pts, &sim).1,
                mean_ratio(&pts, &sim),
                mean_ratio(&pts, &composite)
            ),
        ],
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::f64::consts::PI;

    /// The MLM force coefficient lies between von Karman's pi cot^2(beta) and Wagner's
    /// (pi^3/4) cot^2(beta), and matches the model at another speed and time (self-similarity:
    /// F = k rho V^3 t).
    #[test]
    fn mlm_force_coefficient_is_bounded_and_self_similar() {
        for deg in [20.0f64, 30.0, 40.0] {
            let beta = deg.to_radians();
            let k = mlm_force_coefficient(beta).unwrap();
            let cot2 = 1.0 / beta.tan().powi(2);
            assert!(PI * cot2 < k && k < PI.powi(3) / 4.0 * cot2, "{deg}: {k}");
            let t: Vec<f64> = (0..=40).map(|j| j as f64 * 1e-4).collect();
            let m = crate::analytic::logvinovich_mlm::Mlm::new(
                &[[0.0, 0.0], [0.5, 0.5 * beta.tan()]],
                &t,
                &vec![3.0; t.len()],
                WATER_DENSITY,
            )
            .unwrap();
            let s = *m.history().states.last().unwrap();
            let other = m.force(&s) / (WATER_DENSITY * 27.0 * s.t);
            assert!((other / k - 1.0).abs() < 2e-3, "{deg}: {other} vs {k}");
        }
    }
}
