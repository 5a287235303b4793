//! The strip-theory chain's entry velocities on the two ship cases, computed under each definition in
//! turn (issue 29): Ochi's V-form keel-entry speeds at P1 and P3 at 2.0 m/s beside Veen's (2010) SEAWAY
//! values, with the Hermundstad & Moan (2005) flare-impact velocity at 0.05 Lpp beside them, and the
//! Hermundstad chain under the readings of its published wave.

use super::run::{toml_number, toml_table};
use super::{Case, Outcome, Reference, Table};
use crate::error::{Error, Result};
use crate::hull::Hull;
use crate::sea::SeaState;
use crate::seakeeping::entry_definitions::{self, Published, Target};
use crate::seakeeping::wave_readings::{self, Reading, ReadingRow};

/// Station (fraction of Lpp aft of the FP) and the height of the lower edge above the keel (m) of the
/// sensor `name` of `hull`, found on the section as `assess` does (girth minus half the width).
pub fn panel_lower_edge(hull: &Hull, name: &str) -> Result<(f64, f64)> {
    let s = hull
        .sensors
        .iter()
        .find(|s| s.name == name)
        .ok_or_else(|| {
            Error::Invalid(format!(
                "{}: no sensor named '{name}'",
                hull.source.display()
            ))
        })?;
    let sec = hull.section_at(s.x)?;
    let lower = sec.point_at_girth((s.girth - 0.5 * s.diameter).max(0.0));
    Ok((hull.aft_of_fp(s.x), lower[1] - sec.keel_z()))
}

/// The first regular wave of a sea state.
fn first_wave(sea: &SeaState) -> Result<&crate::sea::RegularWave> {
    sea.regular
        .first()
        .ok_or_else(|| Error::Invalid(format!("{}: no regular wave", sea.source.display())))
}

/// Ochi's keel-entry velocities at P1 and P3 at Veen's speed under each definition, and Hermundstad's
/// flare-impact velocity at its panel: the table in the case's numbers and as Markdown in its notes. The
/// computed value is P3 under all of Veen's stated definitions, against his 0.58 m/s.
pub fn ochi_entry_velocities(case: &Case) -> Result<Outcome> {
    let ochi = toml_table(case.reference("ochi1958_vform.toml")?)?;
    let num = |k: &str| toml_number(&ochi, &["veen2010_sph", k]);
    let hull = Hull::from_file(&case.file("hull")?)?;
    let sea = SeaState::from_file(&case.file("sea")?)?;
    let loading = hull.loading(Some(&case.text("loading")?))?;
    let hm_hull = Hull::from_file(&case.file("hm_hull")?)?;
    let hm_sea = SeaState::from_file(&case.file("hm_sea")?)?;
    let hm_loading = hm_hull.loading(Some(&case.text("hm_loading")?))?;
    let hm = toml_table(case.reference("hermundstad2005_panel.toml")?)?;
    let (hm_station, hm_h) = panel_lower_edge(&hm_hull, &case.text("hm_sensor")?)?;
    let u = num("entry_speed_speed_m_s")?;
    let wave = first_wave(&sea)?;
    let hm_wave = first_wave(&hm_sea)?;
    let mut targets = Vec::new();
    for (key, label) in [
        ("p1_station_aft_of_fp", "P1"),
        ("p3_station_aft_of_fp", "P3"),
    ] {
        let f = num(key)?;
        targets.push(Target::keel_entry(
            format!("Ochi {label} {f} Lpp keel entry"),
            &hull,
            loading,
            wave,
            u,
            f,
        ));
    }
    targets.push(Target {
        label: format!(
            "H&M {hm_station:.3} Lpp flare impact ({} m/s, {})",
            toml_number(&hm, &["model", "model_speed_m_s"])?,
            hm_wave.name
        ),
        hull: &hm_hull,
        loading: hm_loading,
        wave: hm_wave,
        speed: toml_number(&hm, &["model", "model_speed_m_s"])?,
        aft_of_fp: hm_station,
        height_above_keel: hm_h,
        fixed_wave: true,
    });
    let variants = entry_definitions::standard_variants(loading);
    let rows = entry_definitions::table(&targets, &variants)?;
    let published = Published {
        label: format!(
            "published: Veen (2010) SEAWAY at {u} m/s (Ochi columns); measured at flare impact (H&M)"
        ),
        values: vec![
            Some(num("p1_entry_speed_m_s")?),
            Some(num("p3_entry_speed_m_s")?),
            Some(toml_number(
                &hm,
                &["reported_comparisons", "flare_impact_speed_m_s"],
            )?),
        ],
    };
    let md = entry_definitions::markdown(&targets, &rows, Some(&published));
    let all_veen = rows
        .iter()
        .find(|r| r.definition.starts_with("all of Veen's stated definitions"))
        .ok_or_else(|| Error::Invalid("definitions table: no row of Veen's definitions".into()))?;
    let computed = all_veen.velocities_m_per_s[1].unwrap_or(f64::NAN);
    let mut header = vec!["definition".to_string()];
    header.extend(targets.iter().map(|t| format!("{} (m/s)", t.label)));
    let mut table_rows: Vec<Vec<String>> = rows
        .iter()
        .map(|r| {
            let mut row = vec![r.definition.clone()];
            row.extend(
                r.velocities_m_per_s
                    .iter()
                    .map(|v| v.map_or("not reached".into(), |v| format!("{v:.4}"))),
            );
            row
        })
        .collect();
    let mut last = vec![published.label.clone()];
    last.extend(
        published
            .values
            .iter()
            .map(|v| v.map_or("-".into(), |v| format!("{v}"))),
    );
    table_rows.push(last);
    let mut out = Outcome::new(
        computed,
        Reference::Value {
            value: num("p3_entry_speed_m_s")?,
        },
    );
    out.table = Some(Table {
        header,
        rows: table_rows,
    });
    out.notes.push(format!(
        "entry velocities under each definition (the first row is the reference of the changes; 'gap \
         closed' is the change as a share of the gap from the first row to the published value; the \
         H&M column is the velocity when the undisturbed surface reaches the panel's lower edge, \
         {hm_h:.4} m above the keel, against the 1.4 m/s measured at flare impact, always in its sea \
         file's wave (its changes count from that); bundled k_yy = \
         {:.3} Lpp for Ochi, {:.3} Lpp for H&M):\n\n{md}",
        loading.k_yy / hull.lpp,
        hm_loading.k_yy / hm_hull.lpp
    ));
    out.fact(
        "p1_all_veen",
        all_veen.velocities_m_per_s[0].map_or("not reached".into(), |v| format!("{v:.3} m/s")),
    );
    out.fact("p3_all_veen", format!("{computed:.3} m/s"));
    Ok(out)
}

/// The Hermundstad chain at the panel's station under the readings of the published wave (0.1 m as a
/// height and as an amplitude at 1.9 s; the full-scale 2.5 m, 9.0 s at the model scale), beside the
/// measured 1.4 m/s: a Markdown table and a paragraph that states, from the numbers, which reading the
/// kinematics support and why the chain cannot reach the measured forcing.
pub fn hermundstad_readings(case: &Case) -> Result<(String, Vec<ReadingRow>)> {
    let r = toml_table(case.reference("hermundstad2005_panel.toml")?)?;
    let fs = toml_table(case.reference("hermundstad2005_full_scale.toml")?)?;
    let hull = Hull::from_file(&case.file("hull")?)?;
    let loading = hull.loading(Some(&case.text("loading")?))?;
    let (station, h) = panel_lower_edge(&hull, &case.text("sensor")?)?;
    let h_model = toml_number(&r, &["model", "wave_height_m"])?;
    let t_model = toml_number(&r, &["model", "wave_period_s"])?;
    let scale = toml_number(&r, &["model", "scale"])?;
    let h_full = toml_number(&fs, &["full_scale", "wave_height_m"])?;
    let t_full = toml_number(&fs, &["full_scale", "wave_period_s"])?;
    let (h_fs, t_fs) = (h_full / scale, t_full / scale.sqrt());
    let v_ref = toml_number(&r, &["reported_comparisons", "flare_impact_speed_m_s"])?;
    let delay = toml_number(
        &r,
        &["reported_comparisons", "flare_impact_delay_after_keel_s"],
    )?;
    let speed = toml_number(&r, &["model", "model_speed_m_s"])?;
    let readings = [
        Reading {
            label: format!("{h_model} m read as a height, {t_model} s"),
            amplitude_m: 0.5 * h_model,
            period_s: t_model,
        },
        Reading {
            label: format!("{h_model} m read as an amplitude, {t_model} s"),
            amplitude_m: h_model,
            period_s: t_model,
        },
        Reading {
            label: format!(
                "full scale {h_full} m, {t_full} s at 1:{scale}: height {h_fs:.4} m, {t_fs:.3} s"
            ),
            amplitude_m: 0.5 * h_fs,
            period_s: t_fs,
        },
    ];
    let rows = wave_readings::readings(&hull, loading, station, h, speed, &readings, v_ref)?;
    let mut md = wave_readings::markdown(&rows, v_ref, delay);
    let best = rows
        .iter()
        .min_by(|a, b| {
            let d = |r: &ReadingRow| {
                (r.needed_amplitude_m / r.relative_motion_amplitude_m)
                    .ln()
                    .abs()
            };
            d(a).total_cmp(&d(b))
        })
        .ok_or_else(|| Error::Invalid("no wave readings".into()))?;
    let first = &rows[0];
    md += &format!(
        "\nStrip theory gives a relative-motion RAO |s_a|/ζ_a = {:.2} at {station:.3} Lpp ({speed} m/s, head \
         seas, the reconstructed hull). The measured {v_ref} m/s at ω_e = {:.2} rad/s needs |s_a| ≥ {:.3} m \
         (a sinusoid's largest rate is |s_a| ω_e), i.e. |s_a|/ζ_a ≥ {:.2} if {h_model} m is a height and {:.2} \
         if it is an amplitude. The reading closest to what the kinematics give is '{}' (needed/computed \
         {:.2}). With the height reading the chain's relative velocity is at most {:.3} m/s ({:.0} % of \
         {v_ref} m/s; the pressure, as the square, {:.0} %), and the keel at this station {}: the measured \
         forcing (keel entry first, the flare {delay} s later at {v_ref} m/s) needs a relative motion {:.1} \
         times the linear one, which linear strip theory on this hull cannot give in a {h_model} m high wave. \
         The heading of the record is not stated (head to bow quartering); head seas are assumed.\n",
        first.relative_motion_rao,
        first.encounter_frequency_rad_per_s,
        first.needed_amplitude_m,
        first.needed_rao,
        rows[1].needed_rao,
        best.reading,
        best.needed_amplitude_m / best.relative_motion_amplitude_m,
        first.velocity_bound_m_per_s,
        100.0 * first.velocity_bound_m_per_s / v_ref,
        100.0 * (first.velocity_bound_m_per_s / v_ref).powi(2),
        if first.keel_entry_velocity_m_per_s.is_some() {
            "emerges"
        } else {
            "stays in the water (|s_a| below the local draft)"
        },
        first.needed_amplitude_m / first.relative_motion_amplitude_m,
    );
    Ok((md, rows))
}
