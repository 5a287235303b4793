//! Ochi's (1958) published trend "increasing forward speed moves the location of the maximum pressure
//! aft", checked on the 2D+t assessment of the reconstructed V-form at the test condition.

use super::run::Memo;
use super::ships::assessment;
use super::{Case, Figure, Outcome, Reference, Series, Table};
use crate::error::{Error, Result};

/// Per speed, the station (fraction of Lpp aft of the FP) whose event has the largest analytic sensor
/// peak; the quantity is the station at the highest such speed minus the one at the lowest (positive:
/// moved aft), and the table lists every speed.
pub fn speed_trend(case: &Case, memo: &Memo) -> Result<Outcome> {
    let a = assessment(case, &case.file("sea")?, memo)?;
    let mut speeds: Vec<f64> = a.events.iter().map(|e| e.speed_m_per_s).collect();
    speeds.sort_by(f64::total_cmp);
    speeds.dedup();
    let mut rows = Vec::new();
    let mut pts = Vec::new();
    for u in speeds {
        let best = a
            .events
            .iter()
            .filter(|e| e.speed_m_per_s == u)
            .filter_map(|e| {
                let an = e.analytic.as_ref()?;
                let p = an
                    .sensors
                    .iter()
                    .map(|s| s.peak_pa)
                    .fold(f64::MIN, f64::max);
                (p > 0.0).then_some((e.station, p))
            })
            .fold(None, |b: Option<(f64, f64)>, x| match b {
                Some(b) if b.1 >= x.1 => Some(b),
                _ => Some(x),
            });
        if let Some((station, p)) = best {
            rows.push(vec![
                format!("{u}"),
                format!("{station}"),
                format!("{:.3}", p / 1e3),
            ]);
            pts.push([u, station]);
        }
    }
    if pts.len() < 2 {
        return Err(Error::Invalid(
            "fewer than two speeds with an emerging instrumented station: no trend to check".into(),
        ));
    }
    let shift = pts[pts.len() - 1][1] - pts[0][1];
    let mut notes = Vec::new();
    if shift == 0.0 {
        notes.push(
            "the location does not move with speed: Ochi's trend is not contradicted, but not \
             reproduced either"
                .to_string(),
        );
    }
    Ok(Outcome {
        computed: shift,
        reference: Reference::Range {
            lower: 0.0,
            upper: 1.0,
        },
        table: Some(Table {
            header: vec![
                "speed_m_per_s".into(),
                "station_of_largest_pressure".into(),
                "largest_sensor_peak_kpa".into(),
            ],
            rows,
        }),
        figures: vec![Figure {
            name: "location".into(),
            title: "Ochi V-form, test condition: where the largest pressure is, per speed".into(),
            x_label: "speed (m/s)".into(),
            y_label: "station (fraction of Lpp aft of the FP)".into(),
            series: vec![Series {
                label: format!("2D+t ({})", a.fidelity),
                reference: false,
                points: pts,
            }],
        }],
        notes: {
            notes.push(format!(
                "the location moves {shift:+.3} Lpp from the lowest to the highest speed with an \
                 emerging station (positive: aft)"
            ));
            notes
        },
    })
}
