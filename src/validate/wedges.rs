//! Wedges entering calm water at constant speed: the Zhao & Faltinsen (1993) similarity value at 20 deg,
//! Wagner's and von Karman's force bounds and Wagner's pressure bound at 10-40 deg, and a convergence
//! table in particle spacing.

use std::f64::consts::PI;
use std::sync::Arc;

use super::conditions::WATER_DENSITY;
use super::drops::window_mean;
use super::run::Memo;
use super::{Case, Figure, Mode, Outcome, Reference, Series, Table};
use crate::analytic::logvinovich_mlm::Mlm;
use crate::analytic::wagner_pressure::WagnerWedge;
use crate::analytic::{von_karman, wagner, zhao_faltinsen1993};
use crate::error::{Error, Result};
use crate::loads::peaks::summarise;
use crate::sph::{
    self, MotionSpec, Overrides, RunOptions, SensorMethod, SensorSpec, body::Section,
};

/// Wagner's chine-wetting time of a wedge of half-beam `b`: c(t) = (pi/2) V t cot(beta) = b.
pub fn chine_wetting_time(beta: f64, b: f64, v: f64) -> f64 {
    2.0 / PI * b * beta.tan() / v
}

/// A constant-speed wedge run: the case's `half_beam_m`, `speed_m_per_s`, `sensors` sensors of
/// `sensor_width_m` spread along the side between 15 % and 60 % of its length, `sensor_method`
/// (`interpolated` or `force-panel`), run to `t_frac` of the chine-wetting time.
pub struct WedgeRun {
    pub beta: f64,
    pub speed: f64,
    pub t_wet: f64,
    pub result: Arc<sph::RunResult>,
}

pub fn wedge_run(case: &Case, deadrise_deg: f64, n_half: f64, memo: &Memo) -> Result<WedgeRun> {
    let beta = deadrise_deg.to_radians();
    let b = case.number("half_beam_m")?;
    let speed = case.number("speed_m_per_s")?;
    let sensors = case.number("sensors")? as usize;
    let width = case.number("sensor_width_m")?;
    let t_frac = case.number("t_frac")?;
    let method = match case.text("sensor_method")?.as_str() {
        "interpolated" => SensorMethod::Interpolated,
        "force-panel" => SensorMethod::ForcePanel,
        other => {
            return Err(Error::Invalid(format!(
                "{}: sensor_method `{other}`: interpolated or force-panel",
                case.path.display()
            )));
        }
    };
    let t_wet = chine_wetting_time(beta, b, speed);
    let key =
        format!("wedge/{deadrise_deg}/{b}/{speed}/{sensors}/{width}/{t_frac}/{method:?}/{n_half}");
    let result = memo.run(key, || {
        let section = Section::wedge(beta, b, 1.5 * b * beta.tan())?;
        let side = b / beta.cos();
        let specs = (0..sensors)
            .map(|k| SensorSpec {
                name: format!("p{k}"),
                s_m: side * (0.15 + 0.45 * k as f64 / (sensors.max(2) - 1) as f64),
                width_m: width,
            })
            .collect();
        let setup = sph::case::resolve(
            &format!("wedge_{deadrise_deg}deg"),
            &section,
            &MotionSpec::Constant { speed_m_s: speed },
            specs,
            &Overrides {
                particles_per_half_beam: Some(n_half),
                t_end: Some(t_frac * t_wet),
                sensor_method: Some(method),
                ..Default::default()
            },
        )?;
        sph::run(setup, &RunOptions::default())
    })?;
    Ok(WedgeRun {
        beta,
        speed,
        t_wet,
        result,
    })
}

/// Filtered peak (value, time) of a history.
pub(super) fn filtered_peak(t: &[f64], x: &[f64], cutoff: f64) -> Result<(f64, f64)> {
    let s = summarise(t, x, Some(cutoff))?
        .filtered
        .ok_or_else(|| Error::Numerical("a history too short to filter".into()))?;
    Ok((s.value, s.time))
}

/// Like-for-like reference peak pressure coefficient of a sensor (centre `s`, `width` along the side)
/// on a wedge at constant speed `v` over [0, t_end]: Wagner's composite pressure distribution averaged
/// over the sensor width, sampled every t_end / 4000 and filtered like the SPH history; at 20 deg the
/// Zhao & Faltinsen (1993) similarity peak (Cp_max 17.77) times the ratio of that width-averaged,
/// filtered Wagner peak to Wagner's point peak (the similarity distribution itself is not in the
/// reference data, so its peak is lowered by the amount the Wagner peak of the same width is lowered).
pub fn like_for_like_cp(
    beta: f64,
    v: f64,
    s: f64,
    width: f64,
    t_end: f64,
    cutoff: f64,
) -> Result<f64> {
    let w = WagnerWedge::new(beta, WATER_DENSITY, v)?;
    let q = 0.5 * WATER_DENSITY * v * v;
    let n = 4000;
    let t: Vec<f64> = (0..=n).map(|k| t_end * k as f64 / n as f64).collect();
    let (p_sensor, _) = filtered_peak(&t, &w.sensor_history(s, width, &t), cutoff)?;
    if (beta.to_degrees() - zhao_faltinsen1993::DEADRISE_DEG).abs() < 1e-9 {
        let p_point = w
            .sensor_history(s, 1e-6 * width, &t)
            .into_iter()
            .fold(0.0, f64::max);
        Ok(zhao_faltinsen1993::CP_MAX * p_sensor / p_point)
    } else {
        Ok(p_sensor / q)
    }
}

/// Time at which the reference pressure peak passes arc length `s` from the keel of a wedge of deadrise
/// `beta` (rad) at constant speed `v`: the peak is at height (1 + z/Vt) V t above the keel, with z/Vt the
/// similarity solution's 0.5087 at 20 deg (Zhao & Faltinsen 1993) and Wagner's pi/2 - 1 otherwise.
pub fn reference_peak_time(beta: f64, v: f64, s: f64) -> f64 {
    let rise = zhao_faltinsen1993::peak(beta.to_degrees())
        .map(|(_, z_over_vt)| 1.0 + z_over_vt)
        .unwrap_or(0.5 * PI);
    s * beta.sin() / (rise * v)
}

/// Sensor peak errors of one run against the like-for-like reference: mean |Cp / Cp_ref - 1| and mean
/// |t / t_ref - 1| of the peak time (the reference peak passes the sensor centre at height
/// (1 + z/Vt) V t above the keel), with one table row and one (s, Cp) point per sensor.
struct SensorErrors {
    cp: f64,
    time: f64,
    rows: Vec<Vec<String>>,
    sph: Vec<[f64; 2]>,
    reference: Vec<[f64; 2]>,
}

fn sensor_errors(case: &Case, deg: f64, n: f64, memo: &Memo) -> Result<(SensorErrors, WedgeRun)> {
    let run = wedge_run(case, deg, n, memo)?;
    let cutoff = case.number("filter_hz")?;
    let h = &run.result.history;
    let sens = &run.result.summary.setup.sensors;
    let t_end = run.result.summary.setup.t_end;
    let q = 0.5 * WATER_DENSITY * run.speed * run.speed;
    let m = sens.len() as f64;
    let mut e = SensorErrors {
        cp: 0.0,
        time: 0.0,
        rows: Vec::new(),
        sph: Vec::new(),
        reference: Vec::new(),
    };
    for (col, s) in h.sensors.iter().zip(sens) {
        let (p, t) = filtered_peak(&h.t, col, cutoff)?;
        let cp = p / q;
        let cp_ref = like_for_like_cp(run.beta, run.speed, s.s_m, s.width_m, t_end, cutoff)?;
        let t_ref = reference_peak_time(run.beta, run.speed, s.s_m);
        e.cp += (cp / cp_ref - 1.0).abs() / m;
        e.time += (t / t_ref - 1.0).abs() / m;
        e.rows.push(vec![
            format!("{n}"),
            format!("{:.4}", s.s_m),
            format!("{cp:.3}"),
            format!("{cp_ref:.3}"),
            format!("{:.3}", t * 1e3),
            format!("{:.3}", t_ref * 1e3),
        ]);
        e.sph.push([s.s_m, cp]);
        e.reference.push([s.s_m, cp_ref]);
    }
    Ok((e, run))
}

const SENSOR_HEADER: [&str; 6] = [
    "particles_per_half_beam",
    "sensor_girth_m",
    "sph_cp",
    "reference_cp_like_for_like",
    "sph_peak_time_ms",
    "reference_peak_time_ms",
];

/// The 20 deg similarity value: mean |Cp / Cp_ref - 1| (%) of the sensor peaks against the Zhao &
/// Faltinsen (1993) Cp_max 17.77 (like for like).
pub fn similarity(case: &Case, mode: Mode, memo: &Memo) -> Result<Outcome> {
    let deg = case.number("deadrise_deg")?;
    let n = case.particles(mode)?;
    let (e, run) = sensor_errors(case, deg, n, memo)?;
    Ok(Outcome {
        facts: Vec::new(),
        computed: 100.0 * e.cp,
        reference: Reference::Value { value: 0.0 },
        table: Some(Table {
            header: SENSOR_HEADER.iter().map(|s| s.to_string()).collect(),
            rows: e.rows,
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
                    points: e.sph,
                },
                Series {
                    label: "similarity / Wagner, like for like".into(),
                    reference: true,
                    points: e.reference,
                },
            ],
        }],
        notes: vec![format!(
            "mean peak-time error {:.1} %; dp {:.4} m, c0 {:.0} m/s",
            100.0 * e.time,
            run.result.summary.dp_m,
            run.result.summary.c0_m_s
        )],
    })
}

/// Convergence in particle spacing: the sensor Cp error at the finest of `levels_quick` / `levels_full`
/// against the error at the next coarser level (it must fall).
pub fn convergence(case: &Case, mode: Mode, memo: &Memo) -> Result<Outcome> {
    let deg = case.number("deadrise_deg")?;
    let levels = case.numbers(match mode {
        Mode::Quick => "levels_quick",
        Mode::Full => "levels_full",
    })?;
    if levels.len() < 2 {
        return Err(Error::Invalid(format!(
            "{}: a convergence case needs at least two levels",
            case.path.display()
        )));
    }
    let mut rows = Vec::new();
    let mut cp = Vec::new();
    let mut time = Vec::new();
    for &n in &levels {
        let (e, run) = sensor_errors(case, deg, n, memo)?;
        rows.push(vec![
            format!("{n}"),
            format!("{:.5}", run.result.summary.dp_m),
            format!("{:.2}", 100.0 * e.cp),
            format!("{:.2}", 100.0 * e.time),
            format!("{:.1}", run.result.summary.wall_time_s),
        ]);
        cp.push([n, 100.0 * e.cp]);
        time.push([n, 100.0 * e.time]);
    }
    let k = cp.len() - 1;
    Ok(Outcome {
        facts: Vec::new(),
        computed: cp[k][1],
        reference: Reference::Value {
            value: cp[k - 1][1],
        },
        table: Some(Table {
            header: vec![
                "particles_per_half_beam".into(),
                "dp_m".into(),
                "mean_cp_error_percent".into(),
                "mean_peak_time_error_percent".into(),
                "wall_time_s".into(),
            ],
            rows,
        }),
        figures: vec![Figure {
            name: "convergence".into(),
            title: format!("{deg}° wedge: sensor peak errors against particle spacing"),
            x_label: "particles over the half-beam".into(),
            y_label: "mean error (%)".into(),
            series: vec![
                Series {
                    label: "peak Cp error".into(),
                    reference: false,
                    points: cp,
                },
                Series {
                    label: "peak-time error".into(),
                    reference: false,
                    points: time,
                },
            ],
        }],
        notes: vec![format!(
            "the reference column is the error at {} particles; the computed one at {}",
            levels[k - 1],
            levels[k]
        )],
    })
}

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

/// F / (rho V^3 t) of a wedge of deadrise `beta` at constant speed by the modified Logvinovich model
/// ([`Mlm`], Korobkin 2004): constant for the self-similar wedge flow, so it is taken at one instant
/// (1 ms at 1 m/s on a side long enough never to be wetted to its end).
pub fn mlm_force_coefficient(beta: f64) -> Result<f64> {
    let t: Vec<f64> = (0..=20).map(|k| k as f64 * 5e-5).collect();
    let half = [[0.0, 0.0], [1.0, beta.tan()]];
    let m = Mlm::new(&half, &t, &vec![1.0; t.len()], WATER_DENSITY)?;
    let s = m
        .history()
        .states
        .last()
        .copied()
        .ok_or_else(|| Error::Invalid("modified Logvinovich model: no entry state".into()))?;
    Ok(m.force(&s) / (WATER_DENSITY * s.t))
}

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
    let mut pts = Vec::new();
    let mut rows = Vec::new();
    for (col, s) in h.sensors.iter().zip(&run.result.summary.setup.sensors) {
        let (p, t) = filtered_peak(&h.t, col, cutoff)?;
        pts.push([s.s_m, p / q]);
        rows.push(vec![
            format!("{:.4}", s.s_m),
            format!("{:.3}", p / q),
            format!("{:.3}", t * 1e3),
            format!("{cp_w:.3}"),
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
                    points: pts,
                },
                Series {
                    label: "Wagner Cp_max".into(),
                    reference: true,
                    points: wag,
                },
            ],
        }],
        notes: vec![format!(
            "Wagner Cp_max = (π²/4) cot²β = {cp_w:.2}; dp {:.4} m, c0 {:.0} m/s",
            run.result.summary.dp_m, run.result.summary.c0_m_s
        )],
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
            let m = Mlm::new(
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
