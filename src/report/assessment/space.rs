//! Results across the design space (peak pressure against speed and along the girth, the analytic
//! estimate beside every SPH peak, the convergence verdict as the marker), the comparison with
//! published data (the optional `comparisons` list of summary.json) and the appendix (every plotted
//! number of these figures, the settings of every run).

use serde_json::Value;

use super::Report;
use super::data::{Saved, at, capitalised, list, num, speed_text, text};
use super::front::kpa;
use crate::report::document::Block;
use crate::report::figure::{Figure, Mark, Series};

/// Marker of an SPH peak by its convergence verdict, and the legend text.
pub fn verdict_mark(v: &str) -> (Mark, &'static str) {
    match v {
        "converged" => (Mark::Dot, "SPH, converged (GCI <= 5 %)"),
        "acceptable" => (Mark::Ring, "SPH, acceptable (GCI <= 20 %)"),
        "not_converged" => (Mark::Cross, "SPH, not converged"),
        "mismatched" => (Mark::Triangle, "SPH, levels show different events"),
        "companion_unresolved" => (
            Mark::Square,
            "SPH, coarser level does not resolve the impact",
        ),
        _ => (Mark::Square, "SPH, convergence not assessed"),
    }
}

fn sensor_value(e: &Value, part: &str, name: &str, key: &str) -> Option<f64> {
    list(&e[part], "sensors")
        .iter()
        .find(|q| text(q, "name") == name)
        // an analytic panel wetted at once by a singular start has no peak (`peak_pa` 0)
        .filter(|q| !(key == "peak_pa" && q["no_peak_after_start"].as_bool() == Some(true)))
        .and_then(|q| num(q, key))
}

/// Points of one kind of marker: legend text, marker, points.
type Marked = (String, Mark, Vec<(f64, f64)>);

/// SPH series of one sensor, split by verdict: (legend, mark, points).
fn sph_points(evs: &[&Value], name: &str, x: &dyn Fn(&Value) -> f64) -> Vec<Marked> {
    let mut out: Vec<Marked> = Vec::new();
    for e in evs {
        let Some(q) = list(&e["sph"], "sensors")
            .iter()
            .find(|q| text(q, "name") == name)
        else {
            continue;
        };
        // the slamming peak; a sensor whose impact SPH does not resolve has none and no marker
        let Some(v) = num(q, "slamming_peak_pa") else {
            continue;
        };
        let (m, label) = verdict_mark(text(q, "convergence"));
        let p = (x(e), v * 1e-3);
        match out.iter_mut().find(|(l, _, _)| l == label) {
            Some((_, _, v)) => v.push(p),
            None => out.push((label.to_string(), m, vec![p])),
        }
    }
    out
}

pub fn design_space(r: &mut Report, saved: &Saved) {
    r.heading(1, "Results across the design space");
    r.para(
        "Peak pressure per sensor against speed (the largest over the regular waves at each speed) and \
         along the girth. Lines with dots: the analytic estimate (modified Logvinovich, generalised Wagner \
         wetting) of every emerging event; markers: SPH slamming peaks (the largest value in each sensor's \
         impact window; none where SPH does not resolve the impact), their shape the convergence verdict of \
         the peak (legend). Colours are those of the sensors throughout the report.",
    );
    for st in saved.stations() {
        let f = num(st, "station").unwrap_or(f64::NAN);
        let sensors = saved.sensors_at(f);
        let evs: Vec<&Value> = saved.events().iter().filter(|e| at(e, f)).collect();
        let mut fig = Figure::new(
            &format!("peak_pressure_vs_speed_{f}"),
            &format!("Peak pressure against speed, station {f}"),
            "speed U (m/s)",
            "peak pressure (kPa)",
        );
        for (k, n) in sensors.iter().enumerate() {
            let mut speeds: Vec<f64> = evs.iter().filter_map(|e| num(e, "speed_m_per_s")).collect();
            speeds.sort_by(f64::total_cmp);
            speeds.dedup();
            let pts: Vec<(f64, f64)> = speeds
                .iter()
                .filter_map(|&u| {
                    evs.iter()
                        .filter(|e| num(e, "speed_m_per_s") == Some(u))
                        .filter_map(|e| sensor_value(e, "analytic", n, "peak_pa"))
                        .reduce(f64::max)
                        .map(|p| (u, p * 1e-3))
                })
                .collect();
            if !pts.is_empty() {
                fig.series
                    .push(Series::new(format!("{n} analytic"), pts, k, Mark::LineDots));
            }
            for (label, m, pts) in
                sph_points(&evs, n, &|e| num(e, "speed_m_per_s").unwrap_or(f64::NAN))
            {
                fig.series
                    .push(Series::new(format!("{n} {label}"), pts, k, m));
            }
        }
        fig.y_from_zero = true;
        fig.size = (800, 420);
        if fig.series.is_empty() {
            r.para(&format!(
                "Station {f}: no event emerges, so there is no peak pressure to plot."
            ));
            continue;
        }
        r.figure(
            fig,
            &format!("Peak pressure against speed at station {f}"),
            160.0,
        );
        // Along the girth: the governing event of the station.
        if let Some(i) = super::impact::governing(saved, f) {
            let e = &saved.events()[i];
            let mut fig = Figure::new(
                &format!("peak_pressure_along_girth_{f}"),
                &format!(
                    "Peak pressure along the girth, station {f}, {} m/s, {}",
                    speed_text(num(e, "speed_m_per_s")),
                    text(e, "wave")
                ),
                "girth from the keel (m)",
                "peak pressure (kPa)",
            );
            let an: Vec<(f64, f64)> = sensors
                .iter()
                .filter_map(|n| {
                    Some((
                        saved.girth(n)?,
                        sensor_value(e, "analytic", n, "peak_pa")? * 1e-3,
                    ))
                })
                .collect();
            if !an.is_empty() {
                fig.series
                    .push(Series::new("analytic", an, 7, Mark::LineDots));
            }
            let one = [e];
            for (k, n) in sensors.iter().enumerate() {
                let Some(g) = saved.girth(n) else { continue };
                for (label, m, pts) in sph_points(&one, n, &|_| g) {
                    fig.series
                        .push(Series::new(format!("{n} {label}"), pts, k, m));
                }
            }
            fig.y_from_zero = true;
            fig.size = (800, 380);
            if !fig.series.is_empty() {
                r.figure(
                    fig,
                    &format!("Peak pressure along the girth at station {f} (governing event)"),
                    150.0,
                );
            } else if saved.hull.is_err() {
                r.para("The girth positions of the sensors come from the hull file, which is not available.");
            }
        }
    }
}

pub fn comparison(r: &mut Report, saved: &Saved) {
    r.heading(1, "Comparison with published data");
    let cmp = list(&saved.summary, "comparisons");
    let trends = list(&saved.summary, "trend_checks");
    if cmp.is_empty() && trends.is_empty() {
        r.para(
            "This assessment's summary holds no comparisons with published data (summary.json \
             'comparisons'): the case does not match a published experiment the tool knows, or the \
             assessment was made by a version that did not compare. Nothing is compared here.",
        );
        return;
    }
    let case = text(&saved.summary, "reference_case");
    if !case.is_empty() {
        r.para(&format!(
            "Reference case: {case} (data/reference/validation.toml, matched by hull and sea-state name)."
        ));
    }
    let show = |c: &Value, k: &str| match &c[k] {
        Value::Null => "-".to_string(),
        Value::Number(n) => n.as_f64().map_or("-".into(), |v| format!("{v:.4}")),
        Value::String(s) => s.clone(),
        other => other.to_string(),
    };
    if !cmp.is_empty() {
        let rows: Vec<Vec<String>> = cmp
            .iter()
            .map(|c| {
                let diff = match (c["computed"].as_f64(), c["reference"].as_f64()) {
                    (Some(x), Some(y)) if y != 0.0 => format!("{:+.0} %", 100.0 * (x / y - 1.0)),
                    _ => "-".into(),
                };
                vec![
                    show(c, "quantity"),
                    show(c, "computed"),
                    show(c, "reference"),
                    diff,
                    show(c, "unit"),
                    show(c, "source"),
                    show(c, "note"),
                ]
            })
            .collect();
        r.para(
            "The values below are set beside published computations or readings, each with its source; they \
             carry no tolerance and no verdict, because the published values are not measurements of the \
             same quantity (see each note). The verdicts against published data are those of the \
             validation suite (slamtool validate, reports/validation), whose cases include the same \
             hull's entry velocities and trends.",
        );
        r.push(Block::Table {
            caption: "Computed values beside published ones, the difference computed / published - 1, and \
                      the source of each ('-': not computed, the note says why)"
                .into(),
            header: [
                "quantity",
                "computed",
                "reference",
                "difference",
                "unit",
                "source",
                "note",
            ]
            .map(String::from)
            .to_vec(),
            rows,
        });
    }
    if !trends.is_empty() {
        let rows: Vec<Vec<String>> = trends
            .iter()
            .map(|c| {
                vec![
                    show(c, "check"),
                    show(c, "verdict"),
                    show(c, "detail"),
                    show(c, "source"),
                ]
            })
            .collect();
        r.push(Block::Table {
            caption: "Published trends and whether this assessment reproduces them".into(),
            header: ["trend", "verdict", "numbers", "source"]
                .map(String::from)
                .to_vec(),
            rows,
        });
        let readings: Vec<String> = trends
            .iter()
            .filter_map(|c| {
                c["reading"]
                    .as_str()
                    .map(|why| format!("{}: {why}", capitalised(&show(c, "check"))))
            })
            .collect();
        if !readings.is_empty() {
            r.para(
                "Why the trends marked 'not reproduced' are not, as far as this assessment can tell (the \
                 same reading as the known-failure texts of the matching `slamtool validate` cases). A \
                 trend that is not reproduced does not by itself make a design value wrong: it says the \
                 computed distribution of pressure over the stations, sensors or speeds is not the one \
                 Ochi measured, so the design values of the affected sensors rest on the chain's relative \
                 motion and on the model named in their source, not on agreement with the experiment.",
            );
            r.push(Block::List(readings));
        }
    }
    let notes: Vec<String> = list(&saved.summary, "validation_notes")
        .iter()
        .filter_map(|v| v.as_str().map(String::from))
        .collect();
    if !notes.is_empty() {
        r.push(Block::List(notes));
    }
}

/// The kind of an event's water entry, short: "keel" or "flare, d0 <m>" (the keel immersed to d0 at the
/// start, see `flare_event` in summary.json); "-" when nothing runs.
fn entry_kind(e: &serde_json::Value) -> String {
    match e["entry_kind"].as_str() {
        Some(k) if k.starts_with("flare") => match num(&e["flare_event"], "immersion_m") {
            Some(d0) => format!("flare, d0 {d0:.3} m"),
            None => "flare".into(),
        },
        Some(_) => "keel".into(),
        None => "-".into(),
    }
}

pub fn appendix(r: &mut Report, saved: &Saved) {
    r.heading(1, "Appendix");
    r.heading(2, "Peak pressures of every event");
    let mut rows = Vec::new();
    for e in saved.events() {
        let f = num(e, "station").unwrap_or(f64::NAN);
        for n in saved.sensors_at(f) {
            rows.push(vec![
                format!("{f}"),
                speed_text(num(e, "speed_m_per_s")),
                text(e, "wave").to_string(),
                entry_kind(e),
                n.clone(),
                num(e, "entry_velocity_m_per_s").map_or("-".into(), |v| format!("{v:.3}")),
                kpa(sensor_value(e, "analytic", &n, "peak_pa")),
                kpa(sensor_value(e, "sph", &n, "slamming_peak_pa")),
                kpa(sensor_value(e, "sph", &n, "raw_peak_pa")),
                super::front::verdict(e, &n),
            ]);
        }
    }
    r.push(Block::Table {
        caption: "Every event and sensor: analytic peak, SPH slamming peak (in the impact window, as \
                  plotted) and the largest SPH value after the contact transient, whatever its phase (kPa)"
            .into(),
        header: [
            "station",
            "speed m/s",
            "wave",
            "entry",
            "sensor",
            "v entry m/s",
            "analytic",
            "SPH slam.",
            "SPH largest",
            "convergence",
        ]
        .map(String::from)
        .to_vec(),
        rows,
    });
    if let Some(m) = &saved.motions {
        r.heading(2, "Relative motion at the stations");
        let mut rows = Vec::new();
        for sp in list(m, "speeds") {
            for w in list(sp, "regular") {
                for st in list(w, "stations") {
                    let g = |k: &str| num(st, k).map_or("-".into(), |v| format!("{v:.4}"));
                    rows.push(vec![
                        format!("{}", num(st, "station").unwrap_or(f64::NAN)),
                        speed_text(num(sp, "speed_m_per_s")),
                        text(w, "wave").to_string(),
                        g("relative_motion_amplitude_m"),
                        g("relative_velocity_amplitude_m_per_s"),
                        g("draft_m"),
                        num(&st["keel_entry"], "entry_velocity_m_per_s")
                            .map_or("-".into(), |v| format!("{v:.4}")),
                    ]);
                }
            }
        }
        r.push(Block::Table {
            caption:
                "Relative motion and velocity amplitudes, local draft and keel-entry velocity (m, \
                      m/s) as plotted; the RAOs are in the CSV twins of their figures"
                    .into(),
            header: [
                "station",
                "speed m/s",
                "wave",
                "motion m",
                "velocity m/s",
                "draft m",
                "entry m/s",
            ]
            .map(String::from)
            .to_vec(),
            rows,
        });
    }
    r.heading(2, "Settings of every SPH run");
    let mut rows = Vec::new();
    for (e, run) in saved.events().iter().zip(&saved.runs) {
        let Some(run) = run else { continue };
        let s = &run.summary;
        let st = &s["setup"];
        let g = |v: Option<f64>, d: usize| v.map_or("-".into(), |x| format!("{x:.d$}"));
        rows.push(vec![
            format!("{}", num(e, "station").unwrap_or(f64::NAN)),
            speed_text(num(e, "speed_m_per_s")),
            text(e, "wave").to_string(),
            g(num(s, "dp_m").map(|x| x * 1e3), 3),
            g(num(s, "c0_m_per_s"), 2),
            format!(
                "{}x{}",
                g(num(st, "tank_half_width_m"), 3),
                g(num(st, "tank_depth_m"), 3)
            ),
            if st["refinement"].is_object() {
                format!(
                    "{}x{}",
                    g(num(&st["refinement"], "half_width_m"), 3),
                    g(num(&st["refinement"], "depth_m"), 3)
                )
            } else {
                "all".into()
            },
            g(num(s, "t_end_s").map(|x| x * 1e3), 1),
            s["fluid_particles"]
                .as_u64()
                .map_or("-".into(), |v| v.to_string()),
            s["steps"].as_u64().map_or("-".into(), |v| v.to_string()),
            g(num(st, "filter_cutoff_hz"), 0),
        ]);
    }
    if rows.is_empty() {
        r.para("No SPH run was made in this assessment.");
    } else {
        let mut schemes: Vec<String> = saved
            .runs
            .iter()
            .flatten()
            .map(|run| numerics_text(&run.summary["setup"]))
            .collect();
        schemes.sort();
        schemes.dedup();
        r.para(&format!("Numerics: {}.", schemes.join("; ")));
        r.para(&air_text(saved));
        r.para(
            "Sound speed: the automatic c0 keeps the density change to 1 % at Wagner's peak pressure, which \
             puts Wagner's wetted contact at Mach 0.14, (pi/2) V cot(beta) / c0, wherever that bound sets c0 \
             (each run's summary.json states its own Mach number). On constant-speed wedges of 20-45 deg at \
             Mach 0.14 the SPH section force reads 3.5-6 % below the exact similarity force with the default \
             scheme and within 1 % of it at twice the sound speed, a compressibility error of first order in \
             1/c0 (docs/numerics/wedge-convergence.md, items 10 and 31). The section forces \
             of this report carry that bias; their convergence verdicts, made in the particle spacing at a \
             fixed c0, do not measure it.",
        );
        r.push(Block::Table {
            caption:
                "SPH runs: particle spacing dp (mm), sound speed c0 (m/s), tank half-width x depth \
                      (m), the band of spacing dp in a refined tank (half-width x depth, m; 2 dp beyond) \
                      or all of a uniform one, end time (ms), water particles, time steps, filter cut-off \
                      (Hz)"
                    .into(),
            header: [
                "station",
                "speed m/s",
                "wave",
                "dp mm",
                "c0 m/s",
                "tank m",
                "dp band m",
                "t_end ms",
                "particles",
                "steps",
                "cut-off Hz",
            ]
            .map(String::from)
            .to_vec(),
            rows,
        });
    }
    super::contour::table(r, saved);
    r.para(
        "Histories (pressure, force, velocity) are plotted from the run folders named in summary.json \
         (cache/<key>/history.csv); every plotted number of every figure is in its CSV twin in figures/.",
    );
}

/// Which SPH runs had air as a second phase, and why (each run's air note, from its setup), or that
/// none had.
fn air_text(saved: &Saved) -> String {
    let mut with = Vec::new();
    let mut auto_without = Vec::new();
    for (e, run) in saved.events().iter().zip(&saved.runs) {
        let Some(run) = run else { continue };
        let st = &run.summary["setup"];
        let what = format!(
            "station {} at {} m/s ({})",
            num(e, "station").unwrap_or(f64::NAN),
            speed_text(num(e, "speed_m_per_s")),
            text(e, "wave")
        );
        let notes: Vec<&str> = st["notes"]
            .as_array()
            .into_iter()
            .flatten()
            .filter_map(serde_json::Value::as_str)
            .collect();
        let why = crate::sph::air::decision_note(&notes).map(str::to_string);
        if st["air"].is_object() {
            with.push(format!(
                "{what}: {}",
                why.unwrap_or_else(|| "air on".into())
            ));
        } else if let Some(w) = why {
            auto_without.push(format!("{what}: {w}"));
        }
    }
    if with.is_empty() && auto_without.is_empty() {
        return "Air: every SPH run is single-phase (water only; --air off). Air cushions the impact of flat \
                and low-deadrise bottoms, which these runs do not compute."
            .into();
    }
    let mut t = String::from("Air: ");
    if with.is_empty() {
        t.push_str("no SPH run had air. ");
    } else {
        t.push_str(&format!(
            "runs with air as a second phase (standard air, adiabatic, with the two-phase Riemann pair terms; \
             docs/guide/air.md): {}. ",
            with.join("; ")
        ));
    }
    if !auto_without.is_empty() {
        t.push_str(&format!("Runs without air: {}.", auto_without.join("; ")));
    }
    t.trim_end().to_string()
}

/// The SPH scheme of a run's setup (summary.json `setup`), in words: the pair terms, the velocity
/// divergence, shifting, and how the section force and the sensors are computed.
fn numerics_text(st: &serde_json::Value) -> String {
    let on = |k: &str| st[k].as_bool().unwrap_or(false);
    let mut parts = vec![
        if on("riemann") {
            "weakly compressible SPH with low-dissipation Riemann pair terms (Zhang, Hu & Adams 2017)"
        } else {
            "weakly compressible delta-SPH with artificial viscosity (Antuono et al. 2010)"
        }
        .to_string(),
        if on("divergence_correction") {
            "kernel-gradient-corrected velocity divergence (Bonet & Lok 1999)"
        } else {
            "uncorrected velocity divergence"
        }
        .to_string(),
        "Adami et al. (2012) wall pressure".to_string(),
    ];
    if on("shifting") {
        parts.push("particle shifting".into());
    }
    if on("wall_wetness") {
        parts.push("body dummies weighted by the wetness of the body's face".into());
    }
    match st["force"].as_str() {
        Some("pair_forces") => {
            parts.push("section force as the sum of the fluid-body pair forces".into())
        }
        Some("normal_pair_forces") => parts.push(
            "section force as the wall-normal part of the fluid-body pair forces (the pressure load)"
                .into(),
        ),
        Some("contour") => parts.push("section force from the contour pressure".into()),
        _ => {}
    }
    match st["sensor_method"].as_str() {
        Some("interpolated") => parts
            .push("sensor pressure as the wall pressure averaged over the sensor's width".into()),
        Some("force-panel") => parts
            .push("sensor pressure as the normal force on the sensor's face over its width".into()),
        _ => {}
    }
    parts.join(", ")
}

#[cfg(test)]
mod tests {
    use super::numerics_text;

    #[test]
    fn the_numerics_are_stated_from_the_setup() {
        let st = serde_json::json!({"riemann": true, "divergence_correction": true, "shifting": false,
            "force": "pair_forces", "sensor_method": "interpolated"});
        let t = numerics_text(&st);
        assert!(
            t.contains("Riemann") && t.contains("Bonet & Lok") && !t.contains("shifting"),
            "{t}"
        );
        // A run made before the correction existed has no field: it is stated as uncorrected.
        let old = serde_json::json!({"riemann": true, "force": "contour", "sensor_method": "force-panel"});
        let t = numerics_text(&old);
        assert!(
            t.contains("uncorrected") && t.contains("contour") && t.contains("face"),
            "{t}"
        );
    }
}
