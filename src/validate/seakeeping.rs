//! Seakeeping against published data: Journee (1992) Wigley III coefficients, wave loads and RAOs, and
//! the Ochi (1958) V-form natural periods. The ship comes from the bundled hull files, as a user's would.

use std::f64::consts::PI;

use super::run::{toml_number, toml_numbers, toml_table};
use super::{Case, Figure, Outcome, Reference, Series, Table};
use crate::error::Result;
use crate::hull::Hull;
use crate::seakeeping::ShipModel;
use crate::seakeeping::strip_theory::{self, StripSettings};

const G: f64 = 9.81;

/// The ship model of the case's `hull` file at `loading` with `strips` strips.
fn model(case: &Case) -> Result<ShipModel> {
    let hull = Hull::from_file(&case.file("hull")?)?;
    let loading = hull.loading(Some(&case.text("loading")?))?;
    ShipModel::from_hull(&hull, loading, case.number("strips")? as usize)
}

fn journee(case: &Case) -> Result<toml::Table> {
    toml_table(case.reference("journee1992_wigley3.toml")?)
}

/// Wave frequency of a head wave of length lambda = r L in deep water.
fn omega0(r: f64, l: f64) -> f64 {
    (G * 2.0 * PI / (r * l)).sqrt()
}

/// One compared quantity: (label, x, computed, published); the largest |computed/published - 1| wins.
struct Rows {
    header: Vec<String>,
    rows: Vec<Vec<String>>,
    worst: f64,
}

impl Rows {
    fn new(x: &str) -> Self {
        Rows {
            header: vec![
                "quantity".into(),
                x.into(),
                "computed".into(),
                "published".into(),
                "difference_percent".into(),
            ],
            rows: Vec::new(),
            worst: 0.0,
        }
    }
    fn add(&mut self, what: &str, x: f64, got: f64, want: f64) {
        let e = got / want - 1.0;
        self.worst = self.worst.max(e.abs());
        self.rows.push(vec![
            what.into(),
            format!("{x}"),
            format!("{got:.4}"),
            format!("{want}"),
            format!("{:+.1}", 100.0 * e),
        ]);
    }
    fn outcome(self, figures: Vec<Figure>, notes: Vec<String>) -> Outcome {
        Outcome {
            facts: Vec::new(),
            computed: 100.0 * self.worst,
            reference: Reference::Value { value: 0.0 },
            table: Some(Table {
                header: self.header,
                rows: self.rows,
            }),
            figures,
            notes,
        }
    }
}

fn line(label: &str, pts: Vec<[f64; 2]>) -> Series {
    Series {
        label: label.into(),
        reference: false,
        points: pts,
    }
}

fn marks(label: &str, x: &[f64], y: &[f64]) -> Series {
    Series {
        label: label.into(),
        reference: true,
        points: x.iter().zip(y).map(|(x, y)| [*x, *y]).collect(),
    }
}

/// A grid from a to b with n intervals.
fn grid(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..=n).map(|k| a + (b - a) * k as f64 / n as f64).collect()
}

/// Journee Table 2-III, Fn 0.3: A33'' = A33/(rho V), B33'' = B33/(rho V) sqrt(L/g) against w' = w sqrt(L/g).
pub fn wigley_coefficients(case: &Case) -> Result<Outcome> {
    let m = model(case)?;
    let r = journee(case)?;
    let fn_ = case.number("froude_number")?;
    let u = fn_ * (G * m.lpp).sqrt();
    let scale = (m.lpp / G).sqrt();
    let rv = m.rho * m.volume();
    let s = StripSettings::default();
    let coef = |wn: f64| -> Result<(f64, f64)> {
        let st = strip_theory::strips(&m, wn / scale, &s)?;
        let c = strip_theory::coefficients(&m, &st, u);
        Ok((c.added_mass[0][0] / rv, c.damping[0][0] / rv * scale))
    };
    let w = toml_numbers(&r, &["forced_heave_fn030", "omega_nd"])?;
    let a = toml_numbers(&r, &["forced_heave_fn030", "a33_nd"])?;
    let b = toml_numbers(&r, &["forced_heave_fn030", "b33_nd"])?;
    let mut rows = Rows::new("omega_nd");
    for ((wn, a), b) in w.iter().zip(&a).zip(&b) {
        let (ca, cb) = coef(*wn)?;
        rows.add("A33''", *wn, ca, *a);
        rows.add("B33''", *wn, cb, *b);
    }
    let mut ca = Vec::new();
    let mut cb = Vec::new();
    for wn in grid(2.0, 4.7, 27) {
        let (x, y) = coef(wn)?;
        ca.push([wn, x]);
        cb.push([wn, y]);
    }
    let fig = Figure {
        name: "heave_coefficients".into(),
        title: format!("Wigley III, Fn {fn_}: heave added mass and damping"),
        x_label: "ω' = ω√(L/g)".into(),
        y_label: "A33'', B33''".into(),
        series: vec![
            line("A33'' strip theory", ca),
            line("B33'' strip theory", cb),
            marks("A33'' Journée (1992)", &w, &a),
            marks("B33'' Journée (1992)", &w, &b),
        ],
    };
    Ok(rows.outcome(vec![fig], Vec::new()))
}

/// Journee Table 6-III, Fn 0.3: X3'' = |F3|/(C33 zeta_a), X5'' = |F5|/(k C55 zeta_a).
pub fn wigley_wave_loads(case: &Case) -> Result<Outcome> {
    let m = model(case)?;
    let r = journee(case)?;
    let fn_ = case.number("froude_number")?;
    let u = fn_ * (G * m.lpp).sqrt();
    let c = strip_theory::restoring(&m);
    let loads = |lr: f64| -> Result<(f64, f64)> {
        let w0 = omega0(lr, m.lpp);
        let k = w0 * w0 / G;
        let resp = strip_theory::respond(&m, w0, u, &StripSettings::default())?;
        Ok((
            resp.excitation.f3.norm() / c[0][0],
            resp.excitation.f5.norm() / (k * c[1][1]),
        ))
    };
    let lrs = toml_numbers(&r, &["wave_loads_fn030", "lambda_over_l"])?;
    let x3 = toml_numbers(&r, &["wave_loads_fn030", "x3_nd"])?;
    let x5 = toml_numbers(&r, &["wave_loads_fn030", "x5_nd"])?;
    let mut rows = Rows::new("lambda_over_l");
    for ((lr, a), b) in lrs.iter().zip(&x3).zip(&x5) {
        let (g3, g5) = loads(*lr)?;
        rows.add("X3''", *lr, g3, *a);
        rows.add("X5''", *lr, g5, *b);
    }
    let (mut c3, mut c5) = (Vec::new(), Vec::new());
    for lr in grid(0.75, 2.25, 30) {
        let (a, b) = loads(lr)?;
        c3.push([lr, a]);
        c5.push([lr, b]);
    }
    let fig = Figure {
        name: "wave_loads".into(),
        title: format!("Wigley III, Fn {fn_}: wave loads on the restrained model"),
        x_label: "λ/L".into(),
        y_label: "X3'', X5''".into(),
        series: vec![
            line("X3'' strip theory", c3),
            line("X5'' strip theory", c5),
            marks("X3'' Journée (1992)", &lrs, &x3),
            marks("X5'' Journée (1992)", &lrs, &x5),
        ],
    };
    Ok(rows.outcome(vec![fig], Vec::new()))
}

/// Journee Table 8-III: heave RAO z_a / zeta_a in head waves at Fn 0.3.
pub fn wigley_heave_rao(case: &Case) -> Result<Outcome> {
    let m = model(case)?;
    let r = journee(case)?;
    let fn_ = case.number("froude_number")?;
    let u = fn_ * (G * m.lpp).sqrt();
    let rao = |lr: f64| -> Result<f64> {
        Ok(
            strip_theory::respond(&m, omega0(lr, m.lpp), u, &StripSettings::default())?
                .heave
                .norm(),
        )
    };
    let lrs = toml_numbers(&r, &["heave_rao_fn030", "lambda_over_l"])?;
    let h = toml_numbers(&r, &["heave_rao_fn030", "heave"])?;
    let mut rows = Rows::new("lambda_over_l");
    for (lr, h) in lrs.iter().zip(&h) {
        rows.add("heave RAO", *lr, rao(*lr)?, *h);
    }
    let curve = grid(0.75, 2.25, 30)
        .into_iter()
        .map(|lr| Ok([lr, rao(lr)?]))
        .collect::<Result<Vec<_>>>()?;
    let fig = Figure {
        name: "heave_rao".into(),
        title: format!("Wigley III, Fn {fn_}: heave RAO"),
        x_label: "λ/L".into(),
        y_label: "z_a / ζ_a".into(),
        series: vec![
            line("strip theory", curve),
            marks("Journée (1992)", &lrs, &h),
        ],
    };
    Ok(rows.outcome(vec![fig], Vec::new()))
}

/// Journee Tables 10-III, zero speed: heave z_a/zeta_a or pitch theta_a L/(2 pi zeta_a) (`response`)
/// at lambda/L >= `min_lambda_over_l`; both are drawn.
pub fn wigley_zero_speed(case: &Case) -> Result<Outcome> {
    let m = model(case)?;
    let r = journee(case)?;
    let min_lr = case.number("min_lambda_over_l")?;
    let pitch = match case.text("response")?.as_str() {
        "heave" => false,
        "pitch" => true,
        other => {
            return Err(crate::Error::Invalid(format!(
                "{}: response `{other}`: heave or pitch",
                case.path.display()
            )));
        }
    };
    let resp = |lr: f64| -> Result<(f64, f64)> {
        let x = strip_theory::respond(&m, omega0(lr, m.lpp), 0.0, &StripSettings::default())?;
        Ok((x.heave.norm(), x.pitch.norm() * m.lpp / (2.0 * PI)))
    };
    let lrs = toml_numbers(&r, &["zero_speed", "lambda_over_l"])?;
    let h = toml_numbers(&r, &["zero_speed", "heave"])?;
    let p = toml_numbers(&r, &["zero_speed", "pitch"])?;
    let mut rows = Rows::new("lambda_over_l");
    let (mut hx, mut hy, mut px, mut py) = (Vec::new(), Vec::new(), Vec::new(), Vec::new());
    for ((lr, h), p) in lrs.iter().zip(&h).zip(&p) {
        if *lr < min_lr {
            continue;
        }
        let (gh, gp) = resp(*lr)?;
        if pitch {
            rows.add("pitch RAO θL/(2πζ)", *lr, gp, *p);
        } else {
            rows.add("heave RAO", *lr, gh, *h);
        }
        hx.push(*lr);
        hy.push(*h);
        px.push(*lr);
        py.push(*p);
    }
    let (mut ch, mut cp) = (Vec::new(), Vec::new());
    for lr in grid(min_lr, 2.25, 25) {
        let (a, b) = resp(lr)?;
        ch.push([lr, a]);
        cp.push([lr, b]);
    }
    let fig = Figure {
        name: "zero_speed_raos".into(),
        title: "Wigley III, zero speed: heave and pitch RAOs".into(),
        x_label: "λ/L".into(),
        y_label: "z_a/ζ_a, θ_a L/(2π ζ_a)".into(),
        series: vec![
            line("heave, strip theory", ch),
            line("pitch, strip theory", cp),
            marks("heave, Journée (1992)", &hx, &hy),
            marks("pitch, Journée (1992)", &px, &py),
        ],
    };
    Ok(rows.outcome(vec![fig], Vec::new()))
}

/// Ochi V-form natural period (`mode` heave or pitch) at the `loading` (max draft): the coupled
/// heave-pitch normal-mode period (what a free model shows) against the measured one; the uncoupled
/// period is given beside it.
pub fn ochi_period(case: &Case) -> Result<Outcome> {
    let m = model(case)?;
    let r = toml_table(case.reference("ochi1958_vform.toml")?)?;
    let which = case.text("mode")?;
    let s = StripSettings::default();
    let (mh, mp) = strip_theory::natural_mode_periods(&m, &s)?;
    let (uh, up) = strip_theory::natural_periods(&m, &s)?;
    let (key, coupled, uncoupled) = match which.as_str() {
        "heave" => ("heave_natural_period_s", mh, uh),
        "pitch" => ("pitch_natural_period_s", mp, up),
        other => {
            return Err(crate::Error::Invalid(format!(
                "{}: mode `{other}`: heave or pitch",
                case.path.display()
            )));
        }
    };
    let measured = toml_number(&r, &["model", key])?;
    Ok(Outcome {
        facts: Vec::new(),
        computed: coupled,
        reference: Reference::Value { value: measured },
        table: Some(Table {
            header: vec![
                "definition".into(),
                "period_s".into(),
                "measured_s".into(),
                "difference_percent".into(),
            ],
            rows: vec![
                vec![
                    "coupled heave-pitch mode".into(),
                    format!("{coupled:.3}"),
                    format!("{measured}"),
                    format!("{:+.1}", 100.0 * (coupled / measured - 1.0)),
                ],
                vec![
                    "uncoupled (pitch about midship)".into(),
                    format!("{uncoupled:.3}"),
                    format!("{measured}"),
                    format!("{:+.1}", 100.0 * (uncoupled / measured - 1.0)),
                ],
            ],
        }),
        figures: Vec::new(),
        notes: vec![format!(
            "uncoupled {which} period {uncoupled:.3} s ({:+.1} %); see data/reference/ochi_vform_natural_periods.md",
            100.0 * (uncoupled / measured - 1.0)
        )],
    })
}
