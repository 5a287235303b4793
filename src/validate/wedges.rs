//! Wedges entering calm water at constant speed: the sensor peaks against the similarity solution
//! averaged over each sensor's span and filtered like the SPH history (with Wagner's composite
//! distribution as a second line, [`super::wedge_references`]), Wagner's and von Karman's force bounds
//! and Wagner's pressure bound at 10-40 deg, and a convergence table in particle spacing.

use std::f64::consts::PI;
use std::sync::Arc;

use super::conditions::WATER_DENSITY;
use super::run::Memo;
pub use super::wedge_bounds::mlm_force_coefficient;
pub(super) use super::wedge_references::filtered_peak;
pub use super::wedge_references::{
    like_for_like, like_for_like_cp, reference_peak_time, reference_span, wagner_like_for_like_cp,
};
use super::{Case, Figure, Mode, Outcome, Reference, Series, Table};
use crate::error::{Error, Result};
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

/// Sensor peak errors of one run against the like-for-like reference (the similarity solution over the
/// sensor's span, filtered): mean |Cp / Cp_ref - 1| and mean |t / t_ref - 1| of the peak time (t_ref the
/// time of the filtered reference's peak), with one table row and one (s, Cp) point per sensor, and
/// Wagner's composite distribution over the same span as a second line.
struct SensorErrors {
    cp: f64,
    time: f64,
    rows: Vec<Vec<String>>,
    sph: Vec<[f64; 2]>,
    reference: Vec<[f64; 2]>,
    wagner: Vec<[f64; 2]>,
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
        wagner: Vec::new(),
    };
    for ((col, s), named) in h.sensors.iter().zip(sens).zip(&run.result.summary.sensors) {
        let (p, t) = filtered_peak(&h.t, col, cutoff)?;
        let cp = p / q;
        let (centre, width) = reference_span(s, named);
        let (cp_ref, t_ref) = like_for_like(run.beta, run.speed, centre, width, t_end, cutoff)?;
        let cp_w = wagner_like_for_like_cp(run.beta, run.speed, centre, width, t_end, cutoff)?;
        e.cp += (cp / cp_ref - 1.0).abs() / m;
        e.time += (t / t_ref - 1.0).abs() / m;
        e.rows.push(vec![
            format!("{n}"),
            format!("{:.4}", s.s_m),
            format!("{cp:.3}"),
            format!("{cp_ref:.3}"),
            format!("{:.3}", cp / cp_ref),
            format!("{cp_w:.3}"),
            format!("{:.3}", cp / cp_w),
            format!("{:.3}", t * 1e3),
            format!("{:.3}", t_ref * 1e3),
        ]);
        e.sph.push([s.s_m, cp]);
        e.reference.push([s.s_m, cp_ref]);
        e.wagner.push([s.s_m, cp_w]);
    }
    Ok((e, run))
}

const SENSOR_HEADER: [&str; 9] = [
    "particles_per_half_beam",
    "sensor_girth_m",
    "sph_cp",
    "similarity_cp_like_for_like",
    "sph_over_similarity",
    "wagner_composite_cp_like_for_like",
    "sph_over_wagner_composite",
    "sph_peak_time_ms",
    "similarity_peak_time_ms",
];

/// The sensor peaks against the similarity solution: mean |Cp / Cp_ref - 1| (%) against the similarity
/// distribution averaged over each sensor's span and filtered like the SPH history (Wagner's composite
/// distribution, like for like, as a second line).
pub fn similarity(case: &Case, mode: Mode, memo: &Memo) -> Result<Outcome> {
    let deg = case.number("deadrise_deg")?;
    let n = case.particles(mode)?;
    let (e, run) = sensor_errors(case, deg, n, memo)?;
    let (r_sim, r_wagner) = (
        mean_ratio(&e.sph, &e.reference),
        mean_ratio(&e.sph, &e.wagner),
    );
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
                    label: "similarity solution, like for like (reference)".into(),
                    reference: true,
                    points: e.reference,
                },
                Series {
                    label: "Wagner composite distribution, like for like (second line)".into(),
                    reference: true,
                    points: e.wagner,
                },
            ],
        }],
        notes: vec![
            format!(
                "reference: the similarity solution averaged over each sensor's span and filtered like the \
                 SPH history; mean SPH / reference {:.3}; second line, Wagner's composite distribution \
                 like for like: mean SPH / Wagner composite {:.3}",
                r_sim, r_wagner
            ),
            format!(
                "mean peak-time error {:.1} %; dp {:.4} m, c0 {:.0} m/s",
                100.0 * e.time,
                run.result.summary.dp_m,
                run.result.summary.c0_m_s
            ),
        ],
    })
}

/// Mean of a[k].1 / b[k].1.
pub(super) fn mean_ratio(a: &[[f64; 2]], b: &[[f64; 2]]) -> f64 {
    let n = a.len().min(b.len()).max(1) as f64;
    a.iter().zip(b).map(|(x, y)| x[1] / y[1]).sum::<f64>() / n
}

/// Smallest and largest a[k].1 / b[k].1.
pub(super) fn ratio_range(a: &[[f64; 2]], b: &[[f64; 2]]) -> (f64, f64) {
    a.iter()
        .zip(b)
        .map(|(x, y)| x[1] / y[1])
        .fold((f64::MAX, f64::MIN), |r, v| (r.0.min(v), r.1.max(v)))
}

/// Convergence in particle spacing: the sensor Cp error at the finest of `levels_quick` / `levels_full`
/// against the error at the next coarser level (it must fall).
pub fn convergence(case: &Case, mode: Mode, memo: &Memo) -> Result<Outcome> {
    let deg = case.number("deadrise_deg")?;
    let levels = case.levels(mode)?;
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
