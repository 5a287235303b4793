//! Published numbers and trends beside an assessment's results, for the hulls that have them. Which hull
//! has which comparisons is declared in `data/reference/validation.toml` (matched by the hull's name); the
//! numbers are read from the reference files it names (compiled in), never adjusted. Each comparison
//! states what is computed, what the reference is, and where the two differ in definition.
//!
//! * Hermundstad & Moan (2005) car carrier, as reported by Veen (2010) s. 6.2 (this module).
//! * Ochi (1958) V-form, trends and Veen's (2010) s. 6.3 numbers ([`super::trends`]).

use serde::{Deserialize, Serialize};

use super::plan::Plan;
use super::results::{Assessment, EventResult};
use crate::error::{Error, Result};
use crate::hull::Hull;
use crate::impact::flare;
use crate::provenance::{InputFile, sha256_hex};
use crate::seakeeping::relative_motion::{self, RelativeMotion};
use crate::seakeeping::strip_theory::{self, StripSettings};

/// One computed number beside a published one.
#[derive(Debug, Clone, Serialize)]
pub struct Comparison {
    pub quantity: String,
    /// None where the assessment cannot compute it (the note says why).
    pub computed: Option<f64>,
    pub reference: f64,
    pub unit: &'static str,
    pub source: String,
    pub note: String,
}

/// One published qualitative finding and whether the assessment reproduces it.
#[derive(Debug, Clone, Serialize)]
pub struct TrendCheck {
    pub check: String,
    /// "reproduced", "not reproduced" or "not assessed".
    pub verdict: &'static str,
    /// The numbers the verdict rests on.
    pub detail: String,
    pub source: String,
    /// Where the finding is not reproduced: what in this assessment explains it, as far as the tool can
    /// tell (the same reading as the known-failure text of the matching `slamtool validate` case).
    pub reading: Option<String>,
}

/// The comparisons and trend checks of an assessment (empty for a hull without reference data).
#[derive(Debug, Clone, Default, Serialize)]
pub struct Validation {
    /// The reference case matched (`data/reference/validation.toml`), if any.
    pub reference_case: Option<String>,
    pub comparisons: Vec<Comparison>,
    pub trend_checks: Vec<TrendCheck>,
    #[serde(rename = "validation_notes")]
    pub notes: Vec<String>,
    /// The reference files the comparisons read (compiled into the tool) with the SHA-256 of their text
    /// as built in: the index `data/reference/validation.toml` and the matched case's file. Empty when no
    /// comparison is made.
    pub reference_files: Vec<InputFile>,
}

#[derive(Deserialize)]
struct Index {
    case: Vec<Case>,
}

#[derive(Deserialize)]
struct Case {
    hull_name: String,
    sea_name: String,
    kind: String,
    reference: String,
}

const INDEX: &str = include_str!("../../data/reference/validation.toml");
const HERMUNDSTAD: &str = include_str!("../../data/reference/hermundstad2005_panel.toml");
pub(crate) const OCHI: &str = include_str!("../../data/reference/ochi1958_vform.toml");

/// The reference files compiled in, by their path in the repository.
const BUILT_IN: [(&str, &str); 3] = [
    ("data/reference/validation.toml", INDEX),
    ("data/reference/hermundstad2005_panel.toml", HERMUNDSTAD),
    ("data/reference/ochi1958_vform.toml", OCHI),
];

/// The index and the reference file of `case`, each with the SHA-256 of its built-in text.
fn reference_files(case: &Case) -> Result<Vec<InputFile>> {
    ["data/reference/validation.toml", case.reference.as_str()]
        .into_iter()
        .map(|path| {
            let text = BUILT_IN
                .iter()
                .find(|(p, _)| *p == path)
                .map(|(_, t)| *t)
                .ok_or_else(|| {
                    Error::Invalid(format!(
                        "data/reference/validation.toml: the reference file '{path}' is not built into \
                         the tool"
                    ))
                })?;
            Ok(InputFile {
                path: path.to_string(),
                sha256: sha256_hex(text.as_bytes()),
            })
        })
        .collect()
}

/// A number at `path` (table.key) of a compiled-in reference file.
pub(crate) fn reference_number(text: &str, table: &str, key: &str) -> Result<f64> {
    let v: toml::Value =
        toml::from_str(text).map_err(|e| Error::Invalid(format!("reference data: {e}")))?;
    v.get(table)
        .and_then(|t| t.get(key))
        .and_then(|x| x.as_float().or_else(|| x.as_integer().map(|i| i as f64)))
        .ok_or_else(|| Error::Invalid(format!("reference data: no number {table}.{key}")))
}

/// The comparisons for `hull`'s assessment `a` (planned as `plan`).
pub fn validate(hull: &Hull, sea_name: &str, plan: &Plan, a: &Assessment) -> Result<Validation> {
    let index: Index = toml::from_str(INDEX)
        .map_err(|e| Error::Invalid(format!("data/reference/validation.toml: {e}")))?;
    let Some(case) = index.case.iter().find(|c| c.hull_name == hull.name) else {
        return Ok(Validation::default());
    };
    if case.sea_name != sea_name {
        return Ok(Validation {
            reference_case: Some(format!("{} ({})", case.kind, case.reference)),
            notes: vec![format!(
                "the published results for this hull belong to the sea state '{}'; this assessment is in \
                 '{sea_name}', so they are not compared",
                case.sea_name
            )],
            ..Validation::default()
        });
    }
    let mut v = match case.kind.as_str() {
        "hermundstad2005" => hermundstad(hull, plan, a)?,
        "ochi1958" => super::trends::ochi(a)?,
        other => {
            return Err(Error::Invalid(format!(
                "data/reference/validation.toml: unknown kind '{other}'"
            )));
        }
    };
    v.reference_case = Some(format!("{} ({})", case.kind, case.reference));
    v.reference_files = reference_files(case)?;
    Ok(v)
}

/// The largest sensor peak of `name` over `events` (SPH where run, else analytic), with its source.
pub(crate) fn sensor_peak(events: &[&EventResult], name: &str) -> Option<(f64, &'static str)> {
    events
        .iter()
        .filter_map(|e| e.sensor_peak(name))
        .max_by(|a, b| a.0.total_cmp(&b.0))
}

/// The relative motion of a planned event's station in its wave: the plan's own (the one its events
/// come from), or strip theory again for an event the plan's regular waves do not hold.
fn relative_motion_of(plan: &Plan, k: usize) -> Result<(RelativeMotion, f64)> {
    let e = &plan.events[k];
    let planned = plan
        .motions
        .speeds
        .iter()
        .filter(|sp| sp.speed_m_s == e.speed_m_s)
        .flat_map(|sp| sp.regular.iter().filter(|w| w.wave == e.wave))
        .find_map(|w| {
            w.stations
                .iter()
                .find(|st| (st.aft_of_fp - e.station).abs() < 1e-9)
                .map(|st| (st.relative_motion, w.omega_e))
        });
    if let Some(found) = planned {
        return Ok(found);
    }
    let r = strip_theory::respond(
        &plan.model,
        e.wave_omega_rad_s,
        e.speed_m_s,
        &StripSettings::default(),
    )?;
    Ok((relative_motion::at_station(&r, e.x, 1.0)?, r.omega_e))
}

const HM_SOURCE: &str = "Hermundstad & Moan (2005), as reported by Veen (2010) s. 6.2 \
(data/reference/hermundstad2005_panel.toml)";

/// Hermundstad & Moan (2005): the flare panel at 0.05 Lpp and the relative velocity at flare impact.
fn hermundstad(hull: &Hull, plan: &Plan, a: &Assessment) -> Result<Validation> {
    let num = |t: &str, k: &str| reference_number(HERMUNDSTAD, t, k);
    let f = num("model", "section_aft_of_fp_fraction")?;
    let width = num("model", "panel_width_m")?;
    let x = hull.station_x(f);
    let mut out = Validation::default();
    // The panel: the hull's sensor on that station whose width is the published panel width.
    let panel = hull
        .sensors
        .iter()
        .filter(|s| (s.x - x).abs() < 1e-6)
        .min_by(|p, q| {
            (p.diameter - width)
                .abs()
                .total_cmp(&(q.diameter - width).abs())
        });
    let Some(panel) = panel else {
        out.notes.push(format!(
            "the hull file has no sensor on the station at {f} Lpp: no flare-panel comparison"
        ));
        return Ok(out);
    };
    let here: Vec<usize> = (0..plan.events.len())
        .filter(|&k| (plan.events[k].station - f).abs() < 1e-6)
        .collect();
    if here.is_empty() {
        out.notes.push(format!(
            "the station at {f} Lpp is not assessed (give --station {f}): no flare-panel comparison"
        ));
        return Ok(out);
    }
    let events: Vec<&EventResult> = here.iter().map(|&k| &a.events[k]).collect();
    let peak = sensor_peak(&events, &panel.name);
    let flare_event = here.iter().find_map(|&k| plan.events[k].flare.as_ref());
    let why_none = "no water-entry event at this station: neither does its keel emerge nor does the water \
                    reach a sensor above the still-water line in this wave, so the panel pressure is not \
                    computed";
    let which = match flare_event {
        Some(fe) => format!(
            "the flare event (keel immersed to {:.4} m at least immersion, water at rest at the start: wave \
             orbital flow and the flow of the earlier cycle neglected)",
            fe.immersion_m
        ),
        None => "the events".into(),
    };
    let pressure_note = |what: &str| match peak {
        Some((_, src)) => format!(
            "computed: peak of sensor {} ({src}) over {which} at {f} Lpp; reference: {what}",
            panel.name
        ),
        None => format!("{why_none}; reference: {what}"),
    };
    let kpa = |p: Option<(f64, &str)>| p.map(|(v, _)| v / 1e3);
    for (key, table, what) in [
        (
            "panel_peak_pressure_kpa",
            "measured",
            "measured on the 0.067 m bow-flare panel in the basin",
        ),
        (
            "sph_peak_pressure_kpa",
            "reported_comparisons",
            "Veen's 2D SPH with the measured relative velocity imposed (100 Hz low-pass)",
        ),
        (
            "wagner_peak_pressure_kpa",
            "reported_comparisons",
            "Wagner's wedge peak for the flare as a 37 deg wedge struck at 1.4 m/s (Veen)",
        ),
    ] {
        out.comparisons.push(Comparison {
            quantity: format!("peak pressure on flare panel {} at {f} Lpp", panel.name),
            computed: kpa(peak),
            reference: num(table, key)?,
            unit: "kPa",
            source: HM_SOURCE.into(),
            note: pressure_note(what),
        });
    }
    // A station driven by a measured record has no strip-theory relative motion to compare.
    if let Some(m) = plan.forcing.iter().find(|m| (m.station - f).abs() < 1e-6) {
        out.notes.push(format!(
            "the station at {f} Lpp is driven by the measured record {} (keel entry at {:.3} m/s), not by \
             strip theory: the panel pressure above is that record's; the strip-theory relative-velocity \
             comparisons are not made",
            m.file, m.entry_velocity_m_per_s
        ));
        return Ok(out);
    }
    // Flare impact: the undisturbed water surface reaches the panel's lower edge.
    let sec = hull.section_at(x)?;
    let lower = sec.point_at_girth((panel.girth - 0.5 * panel.diameter).max(0.0));
    let upper = sec.point_at_girth(panel.girth + 0.5 * panel.diameter);
    let h = lower[1] - sec.keel_z();
    let beta = (upper[1] - lower[1]).atan2(upper[0] - lower[0]);
    let k0 = here[0];
    let e = &plan.events[k0];
    let (rm, omega_e) = relative_motion_of(plan, k0)?;
    let hit = flare::water_reaches(&rm, omega_e, e.wave_amplitude_m, e.draft_m, h);
    let keel = flare::water_reaches(&rm, omega_e, e.wave_amplitude_m, e.draft_m, 0.0);
    let at = format!(
        "{} m/s, wave {}: the undisturbed water surface (no pile-up) reaching the panel's lower edge, \
         {h:.4} m above the keel, from strip theory",
        e.speed_m_s, e.wave
    );
    let v_note = match hit {
        Some(_) => format!("computed at {at}"),
        None => format!(
            "the water does not reach the panel's lower edge in this wave at {at} (relative motion \
             amplitude {:.4} m, draft {:.4} m)",
            rm.motion.norm() * e.wave_amplitude_m,
            e.draft_m
        ),
    };
    out.comparisons.push(Comparison {
        quantity: format!("relative velocity at flare impact, {f} Lpp"),
        computed: hit.map(|c| c.velocity_m_per_s),
        reference: num("reported_comparisons", "flare_impact_speed_m_s")?,
        unit: "m/s",
        source: HM_SOURCE.into(),
        note: v_note + "; reference: from the measured relative velocity (Veen)",
    });
    // The bound of linear strip theory: s(t) = |s_a| cos(w_e t + phi) rises at most at |s_a| w_e.
    let amp = rm.motion.norm() * e.wave_amplitude_m;
    let v_ref = num("reported_comparisons", "flare_impact_speed_m_s")?;
    let bound = amp * omega_e;
    out.comparisons.push(Comparison {
        quantity: format!(
            "largest relative velocity linear strip theory can give at {f} Lpp, |s_a| w_e"
        ),
        computed: Some(bound),
        reference: v_ref,
        unit: "m/s",
        source: HM_SOURCE.into(),
        note: format!(
            "|s_a| = {amp:.4} m (local draft {:.4} m), w_e = {omega_e:.3} rad/s; the amplitude of the \
             relative velocity Ds/Dt with its forward-speed terms is {:.3} m/s; reference: the measured \
             relative velocity reached at least {v_ref} m/s at flare impact. Linear strip theory's relative \
             velocity here is at most {:.0} % of that ({}), so a slamming pressure, which scales with the \
             square of the speed, is at most {:.0} % of one at the measured speed{}: most of the shortfall of \
             the panel pressure is in the relative motion of linear strip theory on the reconstructed hull \
             (no bow-wave swell-up, no nonlinear motion), before any water-entry model",
            e.draft_m,
            rm.velocity.norm() * e.wave_amplitude_m,
            100.0 * bound / v_ref,
            hit.map_or("the water does not reach the panel".into(), |c| format!(
                "{:.3} m/s, {:.0} %, when the undisturbed surface reaches the panel's lower edge",
                c.velocity_m_per_s,
                100.0 * c.velocity_m_per_s / v_ref
            )),
            100.0 * (bound / v_ref).powi(2),
            hit.map_or(String::new(), |c| format!(
                " ({:.0} % at the panel's lower edge)",
                100.0 * (c.velocity_m_per_s / v_ref).powi(2)
            )),
        ),
    });
    let (delay, delay_note, delay_quantity) = match (hit, keel) {
        (Some(h), Some(k)) => (
            Some((h.time_s - k.time_s).rem_euclid(2.0 * std::f64::consts::PI / omega_e)),
            "computed: flare impact (as above) minus keel entry, from strip theory".to_string(),
            format!("delay of flare impact after keel entry, {f} Lpp"),
        ),
        _ => (
            flare_event.and_then(|fe| fe.impact_delay_after_start_s),
            "the keel does not emerge at this station in the computed motions, so there is no keel entry \
             to count from; computed instead: the delay from the start of the flare event (least immersion) \
             to the water reaching the panel's lower edge, a different definition. Reference: the 0.21 s is \
             the delay in Veen's 2D run, which imposed the measured relative velocity from keel contact in \
             still water (Veen 2010 s. 6.2.2), not a delay measured in the basin"
                .to_string(),
            format!(
                "delay of flare impact after the start of the flare event (least immersion, not keel \
                 entry), {f} Lpp"
            ),
        ),
    };
    out.comparisons.push(Comparison {
        quantity: delay_quantity,
        computed: delay,
        reference: num("reported_comparisons", "flare_impact_delay_after_keel_s")?,
        unit: "s",
        source: HM_SOURCE.into(),
        note: delay_note,
    });
    // Wagner's wedge peak, rho V^2 / 2 (pi^2/4) cot^2(beta), at the panel's own chord angle.
    let rho = plan_rho(hull, plan);
    let cp = crate::analytic::wagner::peak_pressure_coefficient(beta)?;
    let wagner_at = |v: f64| 0.5 * rho * v * v * cp / 1e3;
    out.comparisons.push(Comparison {
        quantity: format!(
            "Wagner wedge peak pressure at the panel's chord angle {:.1} deg and the reference 1.4 m/s",
            beta.to_degrees()
        ),
        computed: Some(wagner_at(v_ref)),
        reference: num("reported_comparisons", "wagner_peak_pressure_kpa")?,
        unit: "kPa",
        source: HM_SOURCE.into(),
        note: "a check of the formula and of the reconstructed flare angle: the same equation as Veen's \
               (his eq. 2.1 with a 37 deg wedge), not a check of the assessment"
            .into(),
    });
    out.comparisons.push(Comparison {
        quantity: format!(
            "Wagner wedge peak pressure at the panel's chord angle {:.1} deg and the computed flare impact velocity",
            beta.to_degrees()
        ),
        computed: hit.map(|c| wagner_at(c.velocity_m_per_s.max(0.0))),
        reference: num("reported_comparisons", "wagner_peak_pressure_kpa")?,
        unit: "kPa",
        source: HM_SOURCE.into(),
        note: "the difference follows the relative velocity (above)".into(),
    });
    out.notes.push(
        "the car-carrier hull is a reconstruction (its lines were not published) and strip theory is \
         linear without the bow wave's swell-up: differences in the relative velocity come from both"
            .into(),
    );
    Ok(out)
}

/// Water density of the assessed loading (kg/m3).
fn plan_rho(hull: &Hull, plan: &Plan) -> f64 {
    hull.loading(Some(&plan.loading)).map_or(1000.0, |l| l.rho)
}

/// The kind of reference case (`data/reference/validation.toml`) a hull and sea state match, if any:
/// "hermundstad2005", "ochi1958", ...
pub fn reference_kind(hull_name: &str, sea_name: &str) -> Result<Option<String>> {
    let index: Index = toml::from_str(INDEX)
        .map_err(|e| Error::Invalid(format!("data/reference/validation.toml: {e}")))?;
    Ok(index
        .case
        .into_iter()
        .find(|c| c.hull_name == hull_name && c.sea_name == sea_name)
        .map(|c| c.kind))
}

/// Veen's (2010) SEAWAY keel-entry speeds for Ochi's V-form (`veen2010_sph` of ochi1958_vform.toml) as
/// (station as a fraction of Lpp aft of the FP, speed m/s, entry speed m/s).
pub fn veen_ochi_entry_speeds() -> Result<Vec<(f64, f64, f64)>> {
    let num = |k: &str| reference_number(OCHI, "veen2010_sph", k);
    let u = num("entry_speed_speed_m_s")?;
    Ok(vec![
        (num("p1_station_aft_of_fp")?, u, num("p1_entry_speed_m_s")?),
        (num("p3_station_aft_of_fp")?, u, num("p3_entry_speed_m_s")?),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The hashes stated for the built-in reference files are those of the files in the repository, and
    /// every case of the index names a file that is built in.
    #[test]
    fn the_built_in_reference_files_are_the_repository_s() {
        let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
        for (path, text) in BUILT_IN {
            let on_disk = std::fs::read(root.join(path)).unwrap();
            assert_eq!(sha256_hex(text.as_bytes()), sha256_hex(&on_disk), "{path}");
        }
        let index: Index = toml::from_str(INDEX).unwrap();
        for case in &index.case {
            let files = reference_files(case).unwrap();
            assert_eq!(files.len(), 2);
            assert_eq!(files[1].path, case.reference);
        }
    }
}
