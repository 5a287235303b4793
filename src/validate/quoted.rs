//! Wedge experiments known only through the numbers Veen (2010) quotes in his text
//! (`data/reference/veen2010_quoted_results.toml`): Breder (2005) constant-speed panels and Whelan (2004)
//! free drops.

use super::conditions::WATER_DENSITY;
use super::run::{Memo, lookup, toml_number, toml_table};
use super::wedges::{chine_wetting_time, filtered_peak};
use super::{Case, Figure, Mode, Outcome, Reference, Series, Table};
use crate::analytic::wagner;
use crate::error::{Error, Result};
use crate::sph::{self, MotionSpec, Overrides, RunOptions, body::Section};

/// Breder (2005) panels at 20 and 30 deg and 2 m/s as quoted by Veen (2010): the panel length along the
/// wedge axis is not quoted, so a 2D force per metre cannot be put beside the quoted kN; the ratio of
/// the peak loads at 20 and 30 deg, which does not depend on that length, is compared with the ratio
/// of Veen's 2D SPH peaks (the measured 30 deg load is not quoted).
pub fn breder_load_ratio(case: &Case, mode: Mode, memo: &Memo) -> Result<Outcome> {
    let quoted = toml_table(case.reference("veen2010_quoted_results.toml")?)?;
    let n = case.particles(mode)?;
    let panel = case.number("panel_keel_to_chine_m")?;
    let speed = case.number("speed_m_per_s")?;
    let cutoff = case.number("filter_hz")?;
    let t_frac = case.number("t_frac")?;
    let cases = lookup(&quoted, &["breder2005_constant_velocity", "cases"])?
        .as_array()
        .ok_or_else(|| Error::Invalid("breder2005_constant_velocity.cases is not a list".into()))?;
    let find = |deg: f64, key: &str| -> Option<f64> {
        cases.iter().find_map(|c| {
            let t = c.as_table()?;
            let d = t.get("deadrise_deg")?.as_float()?;
            let v = t.get("speed_m_s")?.as_float()?;
            if (d - deg).abs() < 1e-9 && (v - speed).abs() < 1e-9 {
                t.get(key)?.as_float()
            } else {
                None
            }
        })
    };
    let mut peaks = Vec::new();
    let mut rows = Vec::new();
    let mut series = Vec::new();
    for deg in [20.0, 30.0] {
        let beta = f64::to_radians(deg);
        let b = panel * beta.cos();
        let t_wet = chine_wetting_time(beta, b, speed);
        let r = memo.run(format!("breder/{deg}/{b}/{speed}/{t_frac}/{n}"), || {
            let section = Section::wedge(beta, b, 1.5 * b * beta.tan())?;
            let setup = sph::case::resolve(
                &format!("breder2005_{deg}deg"),
                &section,
                &MotionSpec::Constant { speed_m_s: speed },
                Vec::new(),
                &Overrides {
                    particles_per_half_beam: Some(n),
                    t_end: Some(t_frac * t_wet),
                    ..Default::default()
                },
            )?;
            sph::run(setup, &RunOptions::default())
        })?;
        let (f, t) = filtered_peak(&r.history.t, &r.history.fz, cutoff)?;
        peaks.push(f);
        let fmt = |x: Option<f64>| x.map_or("not quoted".to_string(), |x| format!("{x}"));
        rows.push(vec![
            format!("{deg}"),
            format!("{:.3}", 2.0 * b),
            format!("{f:.0}"),
            format!("{:.2}", t * 1e3),
            format!("{:.2}", t_wet * 1e3),
            fmt(find(deg, "peak_load_sph_kn")),
            fmt(find(deg, "peak_load_measured_kn")),
        ]);
        series.push(Series {
            label: format!("SPH {deg}°, {n} particles"),
            reference: false,
            points: r
                .history
                .t
                .iter()
                .zip(&r.history.fz)
                .map(|(t, f)| [t * 1e3, *f])
                .collect(),
        });
    }
    let veen = match (
        find(20.0, "peak_load_sph_kn"),
        find(30.0, "peak_load_sph_kn"),
    ) {
        (Some(a), Some(b)) => a / b,
        _ => {
            return Err(Error::Invalid(
                "Veen's 20 and 30 deg SPH peak loads at this speed are not in the reference file"
                    .into(),
            ));
        }
    };
    Ok(Outcome {
        facts: Vec::new(),
        computed: peaks[0] / peaks[1],
        reference: Reference::Value { value: veen },
        table: Some(Table {
            header: vec![
                "deadrise_deg".into(),
                "beam_m".into(),
                "sph_peak_force_n_per_m".into(),
                "sph_peak_time_ms".into(),
                "wagner_chine_wetting_ms".into(),
                "veen_sph_peak_kn".into(),
                "measured_peak_kn".into(),
            ],
            rows,
        }),
        figures: vec![Figure {
            name: "force".into(),
            title: format!("Breder (2005) panels at {speed} m/s: section force"),
            x_label: "t (ms)".into(),
            y_label: "force (N/m)".into(),
            series,
        }],
        notes: vec![
            "Breder's panel length along the wedge axis is not in the quoted text, so the kN values \
             cannot be compared with a 2D force per metre; the 20/30 deg ratio does not depend on it."
                .into(),
            "At 10 deg single-phase SPH is expected to over-predict (Veen: about 2x the measurement, \
             30 kN against the measured trace) because the air cushion is absent; that case is not \
             run here."
                .into(),
        ],
    })
}

/// Whelan (2004) free-drop peak pressures as quoted by Veen (2010): the measured maximum is available,
/// but the sensor positions along the side and the basis of the 74 kg rig mass (per model length, which
/// is not quoted) are not, so an SPH drop cannot be set up without guessing them: the case is pending.
/// The analytic Wagner point peak at the largest quoted impact speed is shown as the upper bound.
pub fn whelan_peak_pressure(case: &Case) -> Result<Outcome> {
    let quoted = toml_table(case.reference("veen2010_quoted_results.toml")?)?;
    let deg = case.number("deadrise_deg")?;
    let key = |what: &str| format!("max_peak_pressure_{}deg_{what}_kpa", deg as i64);
    let measured = toml_number(&quoted, &["whelan2004_free_drop", &key("measured")])?;
    let veen = toml_number(&quoted, &["whelan2004_free_drop", &key("sph")])?;
    let cases = lookup(&quoted, &["whelan2004_free_drop", "cases"])?
        .as_array()
        .ok_or_else(|| Error::Invalid("whelan2004_free_drop.cases is not a list".into()))?;
    let v_max = cases
        .iter()
        .filter_map(|c| {
            let t = c.as_table()?;
            ((t.get("deadrise_deg")?.as_float()? - deg).abs() < 1e-9)
                .then(|| t.get("impact_speed_m_s")?.as_float())
                .flatten()
        })
        .fold(f64::MIN, f64::max);
    if v_max <= 0.0 {
        return Err(Error::Invalid(format!(
            "no Whelan (2004) impact speeds at {deg} deg in the reference file"
        )));
    }
    let p_w =
        0.5 * WATER_DENSITY * v_max * v_max * wagner::peak_pressure_coefficient(deg.to_radians())?;
    Ok(Outcome {
        facts: Vec::new(),
        computed: p_w / 1e3,
        reference: Reference::Pending {
            reason: format!(
                "measured maximum peak {measured} kPa (Veen's SPH {veen} kPa) is quoted, but not the \
                 sensor positions or the basis of the 74 kg rig mass; add them to \
                 data/reference/veen2010_quoted_results.toml to run the SPH drop"
            ),
        },
        table: None,
        figures: Vec::new(),
        notes: vec![format!(
            "computed: Wagner's point peak (π²/4) cot²β ρV²/2 at the largest quoted impact speed \
             {v_max} m/s, an upper bound (no deceleration, no sensor averaging); measured {measured} \
             kPa, Veen's SPH {veen} kPa"
        )],
    })
}
