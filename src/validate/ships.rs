//! Ship cases through the whole 2D+t chain: the reconstructed Ochi (1958) V-form at the published test
//! condition (particulars, trends, pressures as pending data with a drop-in file), and the Hermundstad
//! & Moan (2005) car-carrier flare panel through `assess`, beside the measured 2.4 kPa, Veen's 3.2 kPa
//! and Wagner's 4.2 kPa.

use std::path::Path;
use std::sync::Arc;

use super::run::{Memo, csv_rows, toml_number, toml_table};
use super::{Case, Figure, Outcome, Reference, Series, Table};
use crate::assess::{self, Assessment, Fidelity, Settings};
use crate::error::{Error, Result};
use crate::hull::Hull;
use crate::hull::Hydrostatics;
use crate::sea::SeaState;

/// The fidelity of the ship cases' assessments: analytic in `--quick`, `screen` (SPH at the default
/// resolution for the governing event of each station, with its convergence companion) in `--full`.
pub(super) fn ship_fidelity(memo: &Memo) -> Fidelity {
    if memo.full {
        Fidelity::Screen
    } else {
        Fidelity::Analytic
    }
}

/// The 2D+t assessment of the case's `hull` under `sea` at `loading` ([`ship_fidelity`]), written under
/// the work folder; computed once per suite for each hull, sea, loading and fidelity.
pub(super) fn assessment(case: &Case, sea: &Path, memo: &Memo) -> Result<Arc<Assessment>> {
    let hull_file = case.file("hull")?;
    let loading = case.text("loading")?;
    let fidelity = ship_fidelity(memo);
    let stem = |p: &Path| {
        p.file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
    };
    let name = format!(
        "assess-{}-{}-{loading}-{fidelity:?}",
        stem(&hull_file),
        stem(sea)
    );
    memo.assessment(name.clone(), || {
        let hull = Hull::from_file(&hull_file)?;
        let sea = SeaState::from_file(sea)?;
        let settings = Settings {
            loading: Some(loading),
            fidelity,
            ..Settings::default()
        };
        let out = memo.work_dir(&name);
        let (a, _) = assess::run(&hull, &sea, &settings, &out, &Default::default())?;
        Ok(a)
    })
}

/// Published particulars of the Ochi model (`model` table of ochi1958_vform.toml) against the
/// hydrostatics of the reconstruction at `loading`: the largest relative difference (%).
pub fn ochi_particulars(case: &Case) -> Result<Outcome> {
    let r = toml_table(case.reference("ochi1958_vform.toml")?)?;
    let hull = Hull::from_file(&case.file("hull")?)?;
    let h = Hydrostatics::compute(&hull, hull.loading(Some(&case.text("loading")?))?);
    let pairs = [
        ("displacement_kg", h.displacement_kg),
        ("beam_m", h.beam_wl_m),
        ("block_coefficient", h.cb),
        ("prismatic_coefficient", h.cp),
        ("midship_coefficient", h.cm),
        ("waterplane_coefficient", h.cwp),
        ("lpp_m", h.lpp_m),
    ];
    let mut rows = Vec::new();
    let mut worst = 0.0f64;
    let mut pts = Vec::new();
    for (k, (key, got)) in pairs.iter().enumerate() {
        let want = toml_number(&r, &["model", key])?;
        let e = got / want - 1.0;
        worst = worst.max(e.abs());
        rows.push(vec![
            key.to_string(),
            format!("{got:.4}"),
            format!("{want}"),
            format!("{:+.2}", 100.0 * e),
        ]);
        pts.push([k as f64 + 1.0, 100.0 * e]);
    }
    Ok(Outcome {
        facts: Vec::new(),
        computed: 100.0 * worst,
        reference: Reference::Value { value: 0.0 },
        table: Some(Table {
            header: vec![
                "particular".into(),
                "reconstruction".into(),
                "published".into(),
                "difference_percent".into(),
            ],
            rows,
        }),
        figures: vec![Figure {
            name: "particulars".into(),
            title: "Ochi V-form reconstruction: particulars against Ochi (1958)".into(),
            x_label: "particular (1 Δ, 2 B, 3 Cb, 4 Cp, 5 Cm, 6 Cwp, 7 Lpp)".into(),
            y_label: "difference (%)".into(),
            series: vec![Series {
                label: "reconstruction - published".into(),
                reference: true,
                points: pts,
            }],
        }],
        notes: vec![
            "the hull is a reconstruction matched to these particulars (the offsets are not published)"
                .into(),
        ],
    })
}

/// Ochi's measured peak pressures: pending until the drop-in file (`pressures`, a CSV with the header
/// `station,speed_m_per_s,sensor_index,peak_pressure_kpa`, sensor 1 at the keel) holds rows; then the
/// largest relative difference (%) of the analytic design-event peaks at the same station, speed and
/// sensor.
pub fn ochi_pressures(case: &Case, memo: &Memo) -> Result<Outcome> {
    let file = case.file("pressures")?;
    let rows = csv_rows(&file)?;
    if rows.is_empty() {
        return Ok(Outcome {
            facts: Vec::new(),
            computed: f64::NAN,
            reference: Reference::Pending {
                reason: format!(
                    "Ochi's (1958) peak pressures were published as figures only; fill {} (one row per \
                     station, speed and sensor: station,speed_m_per_s,sensor_index,peak_pressure_kpa, \
                     sensor 1 at the keel) to compare",
                    file.display()
                ),
            },
            table: None,
            figures: Vec::new(),
            notes: Vec::new(),
        });
    }
    let a = assessment(case, &case.file("sea")?, memo)?;
    let mut out = Vec::new();
    let mut worst = 0.0f64;
    let mut pts = Vec::new();
    for r in &rows {
        if r.len() != 4 {
            return Err(Error::Invalid(format!(
                "{}: every row needs station,speed_m_per_s,sensor_index,peak_pressure_kpa",
                file.display()
            )));
        }
        let ev = a
            .events
            .iter()
            .find(|e| (e.station - r[0]).abs() < 1e-6 && (e.speed_m_per_s - r[1]).abs() < 1e-6);
        let got = ev
            .and_then(|e| e.analytic.as_ref())
            .and_then(|an| an.sensors.get((r[2] as usize).wrapping_sub(1)))
            .map(|s| s.peak_pa / 1e3);
        let Some(got) = got else {
            return Err(Error::Invalid(format!(
                "{}: no analytic event at station {}, speed {} m/s, sensor {}",
                file.display(),
                r[0],
                r[1],
                r[2]
            )));
        };
        worst = worst.max((got / r[3] - 1.0).abs());
        out.push(vec![
            format!("{}", r[0]),
            format!("{}", r[1]),
            format!("{}", r[2]),
            format!("{got:.3}"),
            format!("{}", r[3]),
        ]);
        pts.push([r[3], got]);
    }
    Ok(Outcome {
        facts: Vec::new(),
        computed: 100.0 * worst,
        reference: Reference::Value { value: 0.0 },
        table: Some(Table {
            header: vec![
                "station".into(),
                "speed_m_per_s".into(),
                "sensor_index".into(),
                "computed_kpa".into(),
                "measured_kpa".into(),
            ],
            rows: out,
        }),
        figures: vec![Figure {
            name: "pressures".into(),
            title: "Ochi (1958): computed against measured peak pressures".into(),
            x_label: "measured (kPa)".into(),
            y_label: "computed (kPa)".into(),
            series: vec![Series {
                label: "analytic 2D+t".into(),
                reference: true,
                points: pts,
            }],
        }],
        notes: Vec::new(),
    })
}

/// Wagner's estimate for the flare as Veen made it: a wedge of `deadrise_deg` (37) struck at
/// `speed_m_per_s` (1.4), p = (pi^2/4) cot^2(beta) rho V^2 / 2 in kPa, against Veen's 4.2 kPa.
pub fn hermundstad_wagner(case: &Case) -> Result<Outcome> {
    let r = toml_table(case.reference("hermundstad2005_panel.toml")?)?;
    let beta = toml_number(
        &r,
        &["reported_comparisons", "flare_equivalent_deadrise_deg"],
    )?;
    let v = toml_number(&r, &["reported_comparisons", "flare_impact_speed_m_s"])?;
    let rho = case.number("water_density_kg_per_m3")?;
    let p =
        crate::analytic::wagner::peak_pressure_coefficient(beta.to_radians())? * 0.5 * rho * v * v;
    let veen = toml_number(&r, &["reported_comparisons", "wagner_peak_pressure_kpa"])?;
    let measured = toml_number(&r, &["measured", "panel_peak_pressure_kpa"])?;
    Ok(Outcome {
        facts: Vec::new(),
        computed: p / 1e3,
        reference: Reference::Value { value: veen },
        table: None,
        figures: Vec::new(),
        notes: vec![format!(
            "flare as a {beta}° wedge at {v} m/s, ρ = {rho} kg/m³; the measured panel peak is {measured} kPa"
        )],
    })
}

/// The flare panel through `assess` (analytic 2D+t with strip-theory relative motion on the
/// reconstructed car-carrier hull): the design pressure of the panel sensor (`sensor`) against the
/// measured 2.4 kPa, with Veen's SPH 3.2 kPa and Wagner's 4.2 kPa beside it. Pending while the
/// model-test sea state (`sea`) is not in the project.
pub fn hermundstad_assess(case: &Case, memo: &Memo) -> Result<Outcome> {
    let r = toml_table(case.reference("hermundstad2005_panel.toml")?)?;
    let measured = toml_number(&r, &["measured", "panel_peak_pressure_kpa"])?;
    let veen = toml_number(&r, &["reported_comparisons", "sph_peak_pressure_kpa"])?;
    let wag = toml_number(&r, &["reported_comparisons", "wagner_peak_pressure_kpa"])?;
    let sea = case
        .path
        .parent()
        .unwrap_or(Path::new("."))
        .join(case.text("sea")?);
    if !sea.is_file() {
        return Ok(Outcome {
            facts: Vec::new(),
            computed: f64::NAN,
            reference: Reference::Pending {
                reason: format!(
                    "the model-test sea state {} is not in the project yet",
                    sea.display()
                ),
            },
            table: None,
            figures: Vec::new(),
            notes: Vec::new(),
        });
    }
    let a = assessment(case, &sea, memo)?;
    let mut facts = flare_facts(&a);
    let (readings_md, readings) = super::entry_velocities::hermundstad_readings(case)?;
    let readings_note = format!(
        "the strip-theory chain at the panel's station under the readings of the published wave \
         (computed; the keel entry and flare impact are where the relative motion falls through the local \
         draft and through the draft minus the panel's lower edge):\n\n{readings_md}"
    );
    if let Some(r) = readings.get(1) {
        facts.push((
            "amplitude_reading_bound".to_string(),
            format!("{:.2} m/s", r.velocity_bound_m_per_s),
        ));
    }
    let name = case.text("sensor")?;
    let Some((design, design_pa)) = a
        .stations
        .iter()
        .flat_map(|s| s.design_pressure_pa.iter())
        .find(|d| d.name == name)
        .and_then(|d| d.value.map(|v| (d, v)))
    else {
        let flags: Vec<String> = a
            .events
            .iter()
            .map(|e| {
                let flag = serde_json::to_value(e.slam_flag)
                    .ok()
                    .and_then(|v| v.as_str().map(str::to_string))
                    .unwrap_or_default();
                format!(
                    "station {} at {} m/s, {}: {flag}",
                    e.station, e.speed_m_per_s, e.wave
                )
            })
            .collect();
        return Ok(Outcome {
            facts,
            computed: f64::NAN,
            reference: Reference::Value { value: measured },
            table: None,
            figures: Vec::new(),
            notes: vec![
                format!(
                    "assess gives no design pressure for sensor {name}: {}; Veen's SPH {veen} kPa and \
                     Wagner's {wag} kPa are the published comparisons",
                    flags.join("; ")
                ),
                readings_note,
            ],
        });
    };
    let p = design_pa / 1e3;
    Ok(Outcome {
        facts,
        computed: p,
        reference: Reference::Value { value: measured },
        table: Some(Table {
            header: vec!["source".into(), "panel_peak_kpa".into()],
            rows: vec![
                vec![
                    format!("slamtool assess ({})", design.source),
                    format!("{p:.3}"),
                ],
                vec![
                    "measured (Hermundstad & Moan 2005)".into(),
                    format!("{measured}"),
                ],
                vec![
                    "Veen (2010) 2D SPH, measured velocity".into(),
                    format!("{veen}"),
                ],
                vec![
                    "Veen (2010) Wagner, 37° wedge at 1.4 m/s".into(),
                    format!("{wag}"),
                ],
            ],
        }),
        figures: Vec::new(),
        notes: {
            let ev = a.events.iter().find(|e| {
                e.speed_m_per_s == design.speed_m_per_s
                    && e.wave == design.wave
                    && e.sensor_peak(&name).is_some()
            });
            let mut notes = vec![format!(
                "design event: {} m/s, wave {}, {}; the section is a reconstruction",
                design.speed_m_per_s,
                design.wave,
                ev.and_then(|e| e.entry_kind.clone())
                    .unwrap_or_else(|| "kind unknown".into())
            )];
            notes.extend(
                a.validation
                    .comparisons
                    .iter()
                    .filter(|c| c.unit == "m/s")
                    .map(|c| {
                        format!(
                            "{}: {} m/s against {} m/s",
                            c.quantity,
                            c.computed.map_or("-".into(), |v| format!("{v:.3}")),
                            c.reference
                        )
                    }),
            );
            notes.push(readings_note);
            notes
        },
    })
}

/// The relative velocities of the Hermundstad comparison ([`crate::assess::comparisons`]) as facts for the
/// known-failure text: the bound of linear strip theory |s_a| w_e (`velocity_bound`), the velocity when
/// the undisturbed surface reaches the panel (`velocity_at_panel`), and the measured one
/// (`measured_velocity`).
fn flare_facts(a: &Assessment) -> Vec<(String, String)> {
    let mut out = Vec::new();
    let show = |v: Option<f64>| v.map_or("not reached".to_string(), |v| format!("{v:.2} m/s"));
    for c in a.validation.comparisons.iter().filter(|c| c.unit == "m/s") {
        if c.quantity.starts_with("largest relative velocity") {
            out.push(("velocity_bound".to_string(), show(c.computed)));
            out.push((
                "measured_velocity".to_string(),
                format!("{} m/s", c.reference),
            ));
        } else if c.quantity.starts_with("relative velocity at flare impact") {
            out.push(("velocity_at_panel".to_string(), show(c.computed)));
        }
    }
    out
}
