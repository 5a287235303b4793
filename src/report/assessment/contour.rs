//! The largest wall pressure anywhere on the wetted contour of each SPH run and keel stage, beside the
//! panels' design values: a panel is a chosen girth, and the largest pressure of the section may lie
//! between panels. From each run's and keel stage's own `summary.json` ([`super::data::Run`]:
//! `peak_contour_pressure_*`, and the convergence statement of `contour peak pressure` where the run had a
//! companion at twice the spacing).

use serde_json::Value;

use super::Report;
use super::data::{Saved, fmt, list, num, speed_text, text};
use crate::report::document::Block;

/// One row: where the value came from, then the pressure (kPa), girth (m), time (ms) and the
/// convergence statement, each "-" where the summary does not give it.
fn row(station: String, speed: String, record: &str, s: &Value) -> Vec<String> {
    let statement = list(&s["convergence"], "peaks")
        .iter()
        .find(|p| text(p, "name") == "contour peak pressure")
        .map_or("-".to_string(), |p| {
            let gci = num(p, "gci").map_or(String::new(), |x| format!("GCI {:.0} %, ", x * 100.0));
            format!("{gci}{}", text(p, "verdict").replace('_', " "))
        });
    vec![
        station,
        speed,
        record.to_string(),
        fmt(num(s, "peak_contour_pressure_pa"), 1e-3, 2),
        fmt(num(s, "peak_contour_pressure_girth_m"), 1.0, 3),
        fmt(num(s, "peak_contour_pressure_time_s"), 1e3, 1),
        statement,
    ]
}

/// The table of the largest contour pressure per run and keel stage (appendix).
pub fn table(r: &mut Report, saved: &Saved) {
    let mut rows = Vec::new();
    for (e, run) in saved.events().iter().zip(&saved.runs) {
        let Some(run) = run else { continue };
        let station = format!("{}", num(e, "station").unwrap_or(f64::NAN));
        let speed = speed_text(num(e, "speed_m_per_s"));
        rows.push(row(station.clone(), speed.clone(), "run", &run.summary));
        for (k, stage) in run.stage_summaries.iter().enumerate() {
            let sensors: Vec<&str> = list(&run.summary["stages"][k], "sensors")
                .iter()
                .filter_map(Value::as_str)
                .collect();
            let what = format!("keel stage {} ({})", k + 1, sensors.join(", "));
            match stage {
                Some(s) => rows.push(row(station.clone(), speed.clone(), &what, s)),
                None => rows.push(vec![
                    station.clone(),
                    speed.clone(),
                    what,
                    "-".into(),
                    "-".into(),
                    "-".into(),
                    format!(
                        "stage_{k}/summary.json of {} not readable",
                        run.folder.display()
                    ),
                ]),
            }
        }
    }
    if rows.is_empty() {
        return;
    }
    r.push(Block::Table {
        caption: "The largest wall pressure anywhere on the wetted contour after the contact transient, per \
                  SPH run and keel stage (kPa, at girth m from the keel, at ms), with its convergence \
                  statement where the run had a companion at twice the spacing. Not a design value: a point \
                  value of the interpolated wall pressure, which at the default numerics reads the jet root \
                  high (docs/guide/numerics.md); it shows whether the largest pressure of a section lies \
                  between the panels, whose design values are means over their spans"
            .into(),
        header: [
            "station",
            "speed m/s",
            "record",
            "contour peak kPa",
            "girth m",
            "time ms",
            "convergence",
        ]
        .map(String::from)
        .to_vec(),
        rows,
    });
}
