//! The wedge convergence table of issue 28 (item 4): gravity-free constant-speed wedges at several
//! deadrise angles and levels of particle spacing, read by both sensor methods, every sensor's peak
//! against the nonlinear similarity solution (Dobrovol'skaya 1969; [`crate::analytic::similarity`])
//! averaged over the span the sensor integrates and filtered like the SPH history
//! ([`super::wedge_references::like_for_like`]).
//!
//! A constant-speed wedge without gravity has no length scale: what resolves a sensor's impact is the
//! number of particles across the wetted half-width c(t) (and across the jet root) when the pressure
//! peak crosses it, not the particles per half-beam. With the similarity solution's spray-root
//! half-width c = k_c V t and jet-root thickness delta = k_j V t (`root[0]` and `root_thickness`), a
//! sensor at arc length s from the keel is crossed when c = s cos(beta), with
//!
//! N_c = s cos(beta) / dp,   N_jet = (k_j / k_c) s cos(beta) / dp
//!
//! particles across, so sensors spread along the side are, within one run, a convergence study in
//! themselves. The table lists, per deadrise, sensor method, level and sensor: SPH / reference, the
//! peak-time error in dp / V, N_jet and N_c; the figures plot SPH / reference against N_c (one line per
//! deadrise and level), and the notes give the section force against the similarity force coefficient
//! F / (rho V^3 t) (mean ratio over t in [0.5, 0.9] t_end) and the observed order of the mean error.
//!
//! The computed value is the default-level check: the largest |SPH / reference - 1| over the
//! sensors below `side_fraction_checked` of the side, both methods, every deadrise, at `default_level`
//! particles per half-beam.

use super::drops::window_mean;
use super::run::Memo;
use super::wedge_references::{filtered_peak, like_for_like, reference_span};
use super::wedges::chine_wetting_time;
use super::{Case, Figure, Mode, Outcome, Reference, Series, Table};
use crate::analytic::similarity_sensor::solution;
use crate::error::{Error, Result};
use crate::sph::{
    self, MotionSpec, Overrides, RunOptions, SensorMethod, SensorSpec, body::Section,
};

/// Both sensor methods, the design one first ([`crate::assess::execute::DESIGN_SENSOR_METHOD`]).
const METHODS: [(SensorMethod, &str); 2] = [
    (SensorMethod::ForcePanel, "force-panel"),
    (SensorMethod::Interpolated, "interpolated"),
];

/// One sensor of one run.
struct Row {
    s_frac: f64,
    ratio: f64,
    dt_dp: f64,
    n_jet: f64,
    n_wet: f64,
    /// Whether the reference's largest value is at the end of the run (no impact peak: at high deadrise
    /// the similarity pressure is largest at the keel, so a point's pressure still rises after the
    /// crossing).
    end_of_run: bool,
}

/// The wedge geometry and run parameters of the case.
struct Params {
    b: f64,
    speed: f64,
    sensors: usize,
    width: f64,
    span: [f64; 2],
    t_frac: f64,
    cutoff: f64,
}

impl Params {
    fn read(case: &Case) -> Result<Self> {
        let sensors = case.number_between("sensors", 1.0, f64::INFINITY)?;
        if sensors.fract() != 0.0 {
            return Err(Error::Invalid(format!(
                "{}: `sensors` must be a whole number of at least 2",
                case.path.display()
            )));
        }
        let span = [
            case.number_between("span_first", 0.0, 1.0)?,
            case.number_between("span_last", 0.0, 1.0)?,
        ];
        if span[0] >= span[1] {
            return Err(Error::Invalid(format!(
                "{}: `span_first` ({}) must lie below `span_last` ({})",
                case.path.display(),
                span[0],
                span[1]
            )));
        }
        let inf = f64::INFINITY;
        Ok(Params {
            b: case.number_between("half_beam_m", 0.0, inf)?,
            speed: case.number_between("speed_m_per_s", 0.0, inf)?,
            sensors: sensors as usize,
            width: case.number_between("sensor_width_m", 0.0, inf)?,
            span,
            t_frac: case.number_between("t_frac", 0.0, 1.0)?,
            cutoff: case.number_between("filter_hz", 0.0, inf)?,
        })
    }
}

/// A gravity-free constant-speed wedge run (memoised), its sensor rows and its force ratio.
fn wedge(
    p: &Params,
    deg: f64,
    n: f64,
    method: SensorMethod,
    memo: &Memo,
) -> Result<(Vec<Row>, f64)> {
    let beta = deg.to_radians();
    let side = p.b / beta.cos();
    let t_wet = chine_wetting_time(beta, p.b, p.speed);
    let key = format!(
        "wedge-table/{deg}/{}/{}/{}/{}/{:?}/{}/{method:?}/{n}",
        p.b, p.speed, p.sensors, p.width, p.span, p.t_frac
    );
    let run = memo.run(key, || {
        let section = Section::wedge(beta, p.b, 1.5 * p.b * beta.tan())?;
        let specs = (0..p.sensors)
            .map(|k| SensorSpec {
                name: format!("p{k}"),
                s_m: side
                    * (p.span[0] + (p.span[1] - p.span[0]) * k as f64 / (p.sensors - 1) as f64),
                width_m: p.width,
            })
            .collect();
        let mut setup = sph::case::resolve(
            &format!("wedge_{deg}deg_{n}"),
            &section,
            &MotionSpec::Constant { speed_m_s: p.speed },
            specs,
            &Overrides {
                particles_per_half_beam: Some(n),
                t_end: Some(p.t_frac * t_wet),
                sensor_method: Some(method),
                ..Default::default()
            },
        )?;
        // The similarity solution's infinite Froude number.
        setup.g = 0.0;
        sph::run(setup, &RunOptions::default())
    })?;
    let sim = solution(deg)?;
    let s = &run.summary;
    let (dp, t_end) = (s.dp_m, s.setup.t_end);
    let h = &run.history;
    let q = 0.5 * super::conditions::WATER_DENSITY * p.speed * p.speed;
    let mut rows = Vec::new();
    for ((col, spec), named) in h.sensors.iter().zip(&s.setup.sensors).zip(&s.sensors) {
        let (peak, t) = filtered_peak(&h.t, col, p.cutoff)?;
        let (centre, width) = reference_span(spec, named);
        let (cp_ref, t_ref) = like_for_like(beta, p.speed, centre, width, t_end, p.cutoff)?;
        // At the crossing the spray root's half-width is the sensor centre's y = s cos(beta).
        let c = centre * beta.cos();
        rows.push(Row {
            s_frac: spec.s_m / side,
            ratio: peak / q / cp_ref,
            dt_dp: (t - t_ref) * p.speed / dp,
            n_jet: sim.root_thickness / sim.root[0] * c / dp,
            n_wet: c / dp,
            end_of_run: t_ref >= 0.99 * t_end,
        });
    }
    // F / (rho V^3 t C_F), averaged over t in [0.5, 0.9] t_end.
    let cf = super::conditions::WATER_DENSITY * p.speed.powi(3) * sim.force;
    let ratio: Vec<f64> = h.t.iter().zip(&h.fz).map(|(&t, &f)| f / (cf * t)).collect();
    let force = window_mean(&h.t, &ratio, 0.5 * t_end, 0.9 * t_end);
    Ok((rows, force))
}

fn mean_error(rows: &[Row]) -> f64 {
    rows.iter().map(|r| (r.ratio - 1.0).abs()).sum::<f64>() / rows.len().max(1) as f64
}

/// The convergence table (see the module docs).
pub fn table(case: &Case, mode: Mode, memo: &Memo) -> Result<Outcome> {
    let p = Params::read(case)?;
    let degs = case.numbers("deadrises_deg")?;
    let levels = case.levels(mode)?;
    let default_level = case.number("default_level")?;
    let checked_below = case.number("side_fraction_checked")?;
    if !levels.contains(&default_level) {
        return Err(Error::Invalid(format!(
            "{}: the levels must include the default level {default_level}",
            case.path.display()
        )));
    }
    let mut table_rows = Vec::new();
    let mut figures = Vec::new();
    let mut notes = Vec::new();
    let mut worst = (0.0f64, String::new());
    let mut within = Vec::new();
    for (method, name) in METHODS {
        let mut series = Vec::new();
        let mut n_range = (f64::MAX, 0.0f64);
        for &deg in &degs {
            let mut errors = Vec::new();
            for &n in &levels {
                let (rows, force) = wedge(&p, deg, n, method, memo)?;
                for r in &rows {
                    table_rows.push(vec![
                        format!("{deg}"),
                        name.to_string(),
                        format!("{n}"),
                        format!("{:.3}", r.s_frac),
                        format!("{:.3}", r.ratio),
                        format!("{:+.2}", r.dt_dp),
                        format!("{:.2}", r.n_jet),
                        format!("{:.1}", r.n_wet),
                        format!("{force:.3}"),
                        if r.end_of_run {
                            "end of run"
                        } else {
                            "crossing"
                        }
                        .to_string(),
                    ]);
                    n_range = (n_range.0.min(r.n_wet), n_range.1.max(r.n_wet));
                }
                let mut pts: Vec<[f64; 2]> = rows.iter().map(|r| [r.n_wet, r.ratio]).collect();
                pts.sort_by(|a, b| a[0].total_cmp(&b[0]));
                series.push(Series {
                    label: format!("{deg}°, {n} particles per half-beam"),
                    reference: false,
                    points: pts,
                });
                let e = mean_error(&rows);
                errors.push((n, e));
                notes.push(format!(
                    "{deg}° {name} at {n} particles: SPH / reference {:.3}-{:.3}, mean error {:.1} %, \
                     {} of {} sensors within 10 %; section force / similarity {force:.3}",
                    rows.iter().map(|r| r.ratio).fold(f64::MAX, f64::min),
                    rows.iter().map(|r| r.ratio).fold(f64::MIN, f64::max),
                    100.0 * e,
                    rows.iter().filter(|r| (r.ratio - 1.0).abs() <= 0.1).count(),
                    rows.len()
                ));
                if n == default_level {
                    let checked: Vec<&Row> =
                        rows.iter().filter(|r| r.s_frac < checked_below).collect();
                    within.push(format!(
                        "{deg}° {name} {}/{}",
                        checked
                            .iter()
                            .filter(|r| (r.ratio - 1.0).abs() <= 0.1)
                            .count(),
                        checked.len()
                    ));
                    for r in checked {
                        let err = (r.ratio - 1.0).abs();
                        if err > worst.0 {
                            worst = (
                                err,
                                format!(
                                    "the {deg}° {name} sensor at {:.2} of the side (SPH / reference {:.3})",
                                    r.s_frac, r.ratio
                                ),
                            );
                        }
                    }
                }
            }
            for w in errors.windows(2) {
                notes.push(format!(
                    "{deg}° {name}: mean error {:.1} % -> {:.1} % from {} to {} particles, observed order {:.2}",
                    100.0 * w[0].1,
                    100.0 * w[1].1,
                    w[0].0,
                    w[1].0,
                    (w[0].1 / w[1].1).ln() / (w[1].0 / w[0].0).ln()
                ));
            }
        }
        series.push(Series {
            label: "the similarity solution (reference)".into(),
            reference: true,
            points: vec![[n_range.0, 1.0], [n_range.1, 1.0]],
        });
        figures.push(Figure {
            name: format!("peak_ratio_{}", name.replace('-', "_")),
            title: format!(
                "{name} sensors: SPH peak / similarity reference against particles across the wetted half-width"
            ),
            x_label: "particles across the wetted half-width at the crossing, c / dp".into(),
            y_label: "SPH peak / reference".into(),
            series,
        });
    }
    let mut out = Outcome::new(100.0 * worst.0, Reference::Value { value: 0.0 });
    out.fact("worst_sensor", worst.1.clone());
    out.fact("within_ten_per_cent", within.join(", "));
    out.table = Some(Table {
        header: [
            "deadrise_deg",
            "sensor_method",
            "particles_per_half_beam",
            "sensor_over_side",
            "sph_over_similarity",
            "peak_time_error_dp_over_v",
            "particles_across_jet",
            "particles_across_wetted_half_width",
            "force_over_similarity",
            "reference_peak_at",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect(),
        rows: table_rows,
    });
    out.figures = figures;
    notes.insert(
        0,
        format!(
            "default level ({default_level} particles per half-beam), sensors below {checked_below} of the \
             side within 10 %: {}",
            within.join(", ")
        ),
    );
    out.notes = notes;
    Ok(out)
}
