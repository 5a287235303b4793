//! Validation of the air phase ([`crate::sph::air`]): each case runs the same entry with and without air
//! and compares the two.
//!
//! * **Single-phase limit** (`air-single-phase-limit`): at 30 deg of deadrise the air is irrelevant to the
//!   impact (no cushion forms above about 15-20 deg; Chuang 1966), so the two-phase run must give the
//!   single-phase sensor peaks, force peak and impulse. The computed value is the largest relative
//!   difference, in %.
//! * **Cushion ratio** (`air-cushion-ratio`): a low-deadrise or flat entry where Veen (2010) found his
//!   single-phase SPH about twice the measurement and named the missing air cushion as the cause (Breder's
//!   10 deg panel, Ochi's flat 0.174 Lpp section). If the two-phase run computes the real cushion, the
//!   ratio of the single-phase peak to the two-phase one is what Veen's single-phase SPH was to the
//!   measurement. That reads Veen's SPH as this tool's single-phase run, an assumption the case's notes
//!   state: the peaks of a flat impact without air depend on the sound speed, and his was not this tool's.

use super::run::Memo;
use super::wedge_references::filtered_peak;
use super::wedges::chine_wetting_time;
use super::{Case, Mode, Outcome, Reference, Series, Table};
use crate::error::{Error, Result};
use crate::numerics::quadrature::trapezoid;
use crate::sph::air::AirChoice;
use crate::sph::body::Section;
use crate::sph::{self, MotionSpec, Overrides, RunOptions, RunResult, SensorMethod, SensorSpec};

/// The largest value of `x` (a raw peak over the whole record: the approach through the air gap
/// included).
fn raw_peak(x: &[f64]) -> f64 {
    x.iter().copied().fold(f64::NEG_INFINITY, f64::max)
}

/// A run of `section` at constant `speed` to `t_end` (s after the keel reaches the calm surface), with
/// `n` particles over the half-beam, force-panel `sensors`, air on or off, the water's sound speed `c0`
/// (None: the automatic one). Both runs take the standard continuity equation and wall, without shifting
/// or the wall's wetness: a run with air cannot take the single-phase default scheme, and a comparison
/// with and without air measures the air only when the numerics are otherwise the same.
#[allow(clippy::too_many_arguments)]
fn entry(
    memo: &Memo,
    key: &str,
    label: &str,
    section: &Section,
    speed: f64,
    t_end: f64,
    n: f64,
    sensors: &[SensorSpec],
    air: bool,
    c0: Option<f64>,
) -> Result<std::sync::Arc<RunResult>> {
    memo.run(
        format!("air/{key}/{n}/{speed}/{t_end}/{air}/{c0:?}"),
        || {
            let mut setup = sph::case::resolve(
                label,
                section,
                &MotionSpec::Constant { speed_m_s: speed },
                sensors.to_vec(),
                &Overrides {
                    particles_per_half_beam: Some(n),
                    t_end: Some(t_end),
                    air: Some(if air { AirChoice::On } else { AirChoice::Off }),
                    c0,
                    sensor_method: Some(SensorMethod::ForcePanel),
                    shifting: Some(false),
                    divergence_correction: Some(false),
                    wall_wetness: Some(false),
                    ..Default::default()
                },
            )?;
            setup.sensor_method = SensorMethod::ForcePanel;
            sph::run(setup, &RunOptions::default())
        },
    )
}

/// The history of `r`'s quantity `k` (None: the section force; Some(i): sensor i) as plot points (ms).
fn series(label: String, r: &RunResult, k: Option<usize>, scale: f64) -> Series {
    let h = &r.history;
    let x = k.map_or(&h.fz, |i| &h.sensors[i]);
    Series {
        label,
        reference: false,
        points: h
            .t
            .iter()
            .zip(x)
            .map(|(t, v)| [t * 1e3, v * scale])
            .collect(),
    }
}

/// The single-phase limit: a wedge (`deadrise_deg`, `half_beam_m`) at `speed_m_per_s` to `t_frac` of
/// Wagner's chine wetting, force-panel sensors `sensors_s_m` (`sensor_width_m` wide), with and without
/// air. Computed: the largest |with air / water only - 1| (%) over the section force's peak and impulse
/// and the sensor peaks.
pub fn single_phase_limit(case: &Case, mode: Mode, memo: &Memo) -> Result<Outcome> {
    let n = case.particles(mode)?;
    let beta = case.number_between("deadrise_deg", 1.0, 89.0)?.to_radians();
    let b = case.number("half_beam_m")?;
    let speed = case.number("speed_m_per_s")?;
    let t_frac = case.number("t_frac")?;
    let width = case.number("sensor_width_m")?;
    let sensors: Vec<SensorSpec> = case
        .numbers("sensors_s_m")?
        .iter()
        .enumerate()
        .map(|(i, &s)| SensorSpec {
            name: format!("p{}", i + 1),
            s_m: s,
            width_m: width,
        })
        .collect();
    let section = Section::wedge(beta, b, 1.5 * b * beta.tan())?;
    let t_end = t_frac * chine_wetting_time(beta, b, speed);
    let deg = beta.to_degrees();
    let run = |air| {
        entry(
            memo,
            &format!("wedge{deg}/{b}"),
            &format!("wedge {deg:.0} deg"),
            &section,
            speed,
            t_end,
            n,
            &sensors,
            air,
            None,
        )
    };
    let (w, a) = (run(false)?, run(true)?);
    let side = b / beta.cos();
    let mut rows = Vec::new();
    let mut worst: f64 = 0.0;
    let mut each = Vec::new();
    let mut shown: f64 = 0.0;
    let mut add = |what: String, x: f64, y: f64| {
        let d = (y / x - 1.0) * 100.0;
        if what.contains("not compared") {
            shown = shown.max(d.abs());
        } else {
            worst = worst.max(d.abs());
            each.push(format!("{what}: {d:+.1} %"));
        }
        rows.push(vec![
            what,
            format!("{x:.1}"),
            format!("{y:.1}"),
            format!("{d:+.1}"),
        ]);
    };
    let impulse = |r: &RunResult| trapezoid(&r.history.t, &r.history.fz);
    add(
        "peak force (N/m)".into(),
        raw_peak(&w.history.fz),
        raw_peak(&a.history.fz),
    );
    add("impulse (N s/m)".into(), impulse(&w), impulse(&a));
    for (i, s) in sensors.iter().enumerate() {
        add(
            format!(
                "sensor {} at {:.0} % of the side, peak (kPa)",
                s.name,
                100.0 * s.s_m / side
            ),
            raw_peak(&w.history.sensors[i]) * 1e-3,
            raw_peak(&a.history.sensors[i]) * 1e-3,
        );
    }
    let sensor_impulse = |r: &RunResult, i: usize| trapezoid(&r.history.t, &r.history.sensors[i]);
    for (i, s) in sensors.iter().enumerate() {
        add(
            format!("sensor {} impulse (Pa s; shown, not compared)", s.name),
            sensor_impulse(&w, i),
            sensor_impulse(&a, i),
        );
    }
    let mut o = Outcome::new(worst, Reference::Value { value: 0.0 });
    o.fact("difference", format!("{worst:.1} %"));
    o.fact("each", each.join("; "));
    o.fact("sensor_impulses", format!("{shown:.1} %"));
    o.fact(
        "steps_ratio",
        format!(
            "{:.2}",
            a.summary.steps as f64 / w.summary.steps.max(1) as f64
        ),
    );
    o.table = Some(Table {
        header: vec![
            "quantity".into(),
            "water only".into(),
            "with air".into(),
            "air / water only - 1, %".into(),
        ],
        rows,
    });
    o.figures.push(super::Figure {
        name: "force".into(),
        title: format!("{deg:.0} deg wedge at {speed} m/s: section force with and without air"),
        x_label: "t (ms)".into(),
        y_label: "force (N/m)".into(),
        series: vec![
            series(format!("water only, {n} particles"), &w, None, 1.0),
            series(format!("with air, {n} particles"), &a, None, 1.0),
        ],
    });
    o.notes.push(format!(
        "The runs at {n} particles over the half-beam with force-panel sensors; the run with air starts \
         with the keel {:.1} mm above the calm surface (its air gap), and its records from that moment. \
         Its water steps as the water-only run's does and its air takes its own substeps within each \
         water step (the air's sound speed is {:.0} m/s against the water's c0 {:.1} m/s).",
        a.summary
            .setup
            .air
            .map_or(0.0, |l| l.clearance * 1e3),
        a.summary.setup.air.map_or(0.0, |l| l.phase().c),
        w.summary.c0_m_s
    ));
    Ok(o)
}

/// The cushion ratio: the entry of a wedge (`deadrise_deg`, `panel_keel_to_chine_m`) or of a hull's
/// section (`hull`, `station`) at `speed_m_per_s` (or the reference value `speed_from`, "file:table.key")
/// to `t_end_s`, with and without air; the compared peak
/// is the section force's (`quantity_of = "force"`, low-passed at `filter_hz`) or the keel sensor's
/// (`"keel sensor"`, the station's first sensor of the hull file, raw). Computed: peak without air / peak
/// with air, against `single_phase_over_measured`, the ratio Veen quotes.
pub fn cushion_ratio(case: &Case, mode: Mode, memo: &Memo) -> Result<Outcome> {
    let n = case.particles(mode)?;
    let speed = match case.text("speed_from") {
        // "<reference file>:<table>.<key>": a speed quoted in a reference file
        Ok(at) => {
            let (file, key) = at.split_once(':').ok_or_else(|| {
                Error::Invalid(format!(
                    "speed_from = \"{at}\": use \"<reference file>:<table>.<key>\""
                ))
            })?;
            let t = super::run::toml_table(case.reference(file)?)?;
            super::run::toml_number(&t, &key.split('.').collect::<Vec<_>>())?
        }
        Err(_) => case.number("speed_m_per_s")?,
    };
    let t_end = case.number("t_end_s")?;
    let quoted = case.number("single_phase_over_measured")?;
    let of = case.text("quantity_of")?;
    let (key, section, sensors) = match case.text("hull") {
        Ok(_) => {
            let hull = crate::hull::Hull::from_file(&case.file("hull")?)?;
            let f = case.number_between("station", 0.0, 1.0)?;
            let x = hull.station_x(f);
            let sensors = crate::impact::station_sensors(&hull, x);
            (
                format!("hull{f}"),
                crate::impact::entry_section(&hull, x)?,
                sensors,
            )
        }
        Err(_) => {
            let beta = case.number_between("deadrise_deg", 1.0, 89.0)?.to_radians();
            let b = case.number("panel_keel_to_chine_m")? * beta.cos();
            let section = Section::wedge(beta, b, 1.5 * b * beta.tan())?;
            (
                format!("wedge{}/{b}", beta.to_degrees()),
                section,
                Vec::new(),
            )
        }
    };
    let run = |air| {
        entry(
            memo, &key, &key, &section, speed, t_end, n, &sensors, air, None,
        )
    };
    let (w, a) = (run(false)?, run(true)?);
    let (peak_w, peak_a, what, k, unit, scale) = match of.as_str() {
        "force" => {
            let cutoff = case.number("filter_hz")?;
            let fw = filtered_peak(&w.history.t, &w.history.fz, cutoff)?.0;
            let fa = filtered_peak(&a.history.t, &a.history.fz, cutoff)?.0;
            (
                fw,
                fa,
                format!("peak section force, {cutoff} Hz low-pass"),
                None,
                "N/m",
                1.0,
            )
        }
        "keel sensor" => {
            let s = sensors.first().ok_or_else(|| {
                Error::Invalid("the station has no sensors in the hull file".into())
            })?;
            (
                raw_peak(&w.history.sensors[0]),
                raw_peak(&a.history.sensors[0]),
                format!(
                    "raw peak of the keel sensor {} (s = {:.3} m)",
                    s.name, s.s_m
                ),
                Some(0),
                "kPa",
                1e-3,
            )
        }
        other => {
            return Err(Error::Invalid(format!(
                "quantity_of = \"{other}\": use \"force\" or \"keel sensor\""
            )));
        }
    };
    if peak_a.is_nan() || peak_a <= 0.0 {
        return Err(Error::Numerical(format!(
            "the run with air has no positive {what}: {peak_a}"
        )));
    }
    let ratio = peak_w / peak_a;
    let mut o = Outcome::new(ratio, Reference::Value { value: quoted });
    o.fact("ratio", format!("{ratio:.2}"));
    o.fact("water_only", format!("{:.2} {unit}", peak_w * scale));
    o.fact("with_air", format!("{:.2} {unit}", peak_a * scale));
    o.fact("c0", format!("{:.1} m/s", w.summary.c0_m_s));
    o.fact(
        "rho_c0_v",
        format!(
            "{:.2} kPa",
            w.summary.setup.rho0 * w.summary.c0_m_s * speed * 1e-3
        ),
    );
    o.table = Some(Table {
        header: vec![
            "quantity".into(),
            "water only".into(),
            "with air".into(),
            "ratio".into(),
            "Veen: single-phase / measured".into(),
        ],
        rows: vec![vec![
            format!("{what} ({unit})"),
            format!("{:.2}", peak_w * scale),
            format!("{:.2}", peak_a * scale),
            format!("{ratio:.2}"),
            format!("about {quoted}"),
        ]],
    });
    o.figures.push(super::Figure {
        name: "peak".into(),
        title: format!("{what} at {speed:.2} m/s, with and without air"),
        x_label: "t (ms)".into(),
        y_label: format!(
            "{} ({unit})",
            if k.is_some() { "pressure" } else { "force" }
        ),
        series: vec![
            series(format!("water only, {n} particles"), &w, k, scale),
            series(format!("with air, {n} particles"), &a, k, scale),
        ],
    });
    o.notes.push(format!(
        "Both runs at {n} particles over the half-beam, constant {speed} m/s, to {:.0} ms after the keel \
         reaches the calm surface; the run with air starts {:.1} mm above it. The ratio stands for Veen's \
         single-phase SPH over the measurement only if the two-phase run computes the real cushion and \
         this tool's single-phase run is Veen's; the peak of a flat impact without air depends on the \
         artificial sound speed ({:.1} m/s here), and Veen's was not this tool's.",
        t_end * 1e3,
        a.summary.setup.air.map_or(0.0, |l| l.clearance * 1e3),
        w.summary.c0_m_s
    ));
    Ok(o)
}

/// The cushion's dependence on the water's sound speed: a flat bottom (`flat_half_width_m`, a 45 deg
/// bilge of a quarter of it, vertical sides) with air at `speed_m_per_s` to `t_end_s`, a force panel at
/// `sensor_s_m` (`sensor_width_m` wide), run at the automatic c0 and at `c0_factor` times it. Computed:
/// the change of the panel's raw peak, in %. A physical cushion far below the water hammer does not
/// depend on the water's compressibility; the case records how far the two-phase run's does.
pub fn sound_speed_sensitivity(case: &Case, mode: Mode, memo: &Memo) -> Result<Outcome> {
    let n = case.particles(mode)?;
    let b = case.number("flat_half_width_m")?;
    let speed = case.number("speed_m_per_s")?;
    let t_end = case.number("t_end_s")?;
    let factor = case.number_between("c0_factor", 1.0, 100.0)?;
    let sensors = vec![SensorSpec {
        name: "p1".into(),
        s_m: case.number("sensor_s_m")?,
        width_m: case.number("sensor_width_m")?,
    }];
    let section = Section::from_half_points(vec![
        [0.0, 0.0],
        [b, 0.0],
        [1.25 * b, 0.25 * b],
        [1.25 * b, 0.75 * b],
    ])?;
    let key = format!("flat{b}");
    let run = |c0| {
        entry(
            memo,
            &key,
            "flat bottom",
            &section,
            speed,
            t_end,
            n,
            &sensors,
            true,
            c0,
        )
    };
    let auto = run(None)?;
    let c0 = auto.summary.c0_m_s;
    let high = run(Some(factor * c0))?;
    let peak = |r: &RunResult| raw_peak(&r.history.sensors[0]);
    let (p_lo, p_hi) = (peak(&auto), peak(&high));
    if !(p_lo > 0.0 && p_hi.is_finite()) {
        return Err(Error::Numerical(format!(
            "the flat bottom's panel has no positive peak: {p_lo} and {p_hi} Pa"
        )));
    }
    let change = (p_hi / p_lo - 1.0) * 100.0;
    let mut o = Outcome::new(change.abs(), Reference::Value { value: 0.0 });
    o.fact("change", format!("{change:+.1} %"));
    o.fact("c0", format!("{c0:.1} m/s"));
    o.fact("c0_high", format!("{:.1} m/s", factor * c0));
    o.fact("peak", format!("{:.1} kPa", p_lo * 1e-3));
    o.fact("peak_high", format!("{:.1} kPa", p_hi * 1e-3));
    let rho = auto.summary.setup.rho0;
    let row = |r: &RunResult, c: f64| {
        vec![
            format!("{c:.1}"),
            format!("{:.1}", peak(r) * 1e-3),
            format!("{:.2}", raw_peak(&r.history.fz) * 1e-3),
            format!("{:.1}", rho * c * speed * 1e-3),
            format!("{:.2}", peak(r) / (rho * c * speed)),
        ]
    };
    o.table = Some(Table {
        header: vec![
            "c0 (m/s)".into(),
            "panel p1 raw peak (kPa)".into(),
            "force peak (kN/m)".into(),
            "water hammer rho c0 V (kPa)".into(),
            "peak / rho c0 V".into(),
        ],
        rows: vec![row(&auto, c0), row(&high, factor * c0)],
    });
    o.figures.push(super::Figure {
        name: "panel".into(),
        title: format!("flat bottom with air at {speed} m/s: keel panel at two sound speeds"),
        x_label: "t (ms)".into(),
        y_label: "pressure (kPa)".into(),
        series: vec![
            series(format!("c0 = {c0:.0} m/s"), &auto, Some(0), 1e-3),
            series(format!("c0 = {:.0} m/s", factor * c0), &high, Some(0), 1e-3),
        ],
    });
    o.notes.push(format!(
        "Both runs have air, the keel {:.1} mm above the calm surface at the start, {n} particles over the \
         largest half-breadth; the records start at that moment.",
        auto.summary.setup.air.map_or(0.0, |l| l.clearance * 1e3)
    ));
    Ok(o)
}
