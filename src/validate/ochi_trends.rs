//! Ochi's (1958) published trends on the 2D+t assessment of the reconstructed V-form at the test
//! condition: the maximum pressure near the keel, its location moving aft with speed, and the peaks
//! falling from keel to chine at 2.2 m/s on the foremost sections. Each case is judged by the same
//! function as the design report's trend check ([`crate::assess::trends`]), on the design values of the
//! assessment, so the two reports cannot disagree on the same assessment.

use super::run::Memo;
use super::ships::assessment;
use super::{Case, Figure, Outcome, Reference, Series, Table};
use crate::assess::trends::{ForeTrend, KeelTrend, SpeedTrend};
use crate::error::{Error, Result};

/// The station of the largest per-event design pressure, per speed ([`SpeedTrend`]): the quantity is
/// the shift aft from the lowest to the highest speed, or minus the largest forward move between two
/// consecutive speeds; it must be at least half the smallest station spacing (a location that does not
/// move is not the trend).
pub fn speed_trend(case: &Case, memo: &Memo) -> Result<Outcome> {
    let a = assessment(case, &case.file("sea")?, memo)?;
    let t = SpeedTrend::of(&a);
    let Some(measure) = t.measure() else {
        return Err(Error::Invalid(
            "fewer than two speeds with an emerging instrumented station: no trend to check".into(),
        ));
    };
    let rows = t
        .track
        .iter()
        .map(|(u, f, p, src)| {
            vec![
                format!("{u}"),
                format!("{f}"),
                format!("{:.3}", p / 1e3),
                src.to_string(),
            ]
        })
        .collect();
    let mut out = Outcome::new(
        measure,
        Reference::Range {
            lower: t.least_shift(),
            upper: 1.0,
        },
    );
    out.table = Some(Table {
        header: vec![
            "speed_m_per_s".into(),
            "station_of_largest_pressure".into(),
            "largest_sensor_peak_kpa".into(),
            "source".into(),
        ],
        rows,
    });
    out.figures.push(Figure {
        name: "location".into(),
        title: "Ochi V-form, test condition: where the largest pressure is, per speed".into(),
        x_label: "speed (m/s)".into(),
        y_label: "station (fraction of Lpp aft of the FP)".into(),
        series: vec![Series {
            label: format!("2D+t ({})", a.fidelity),
            reference: false,
            points: t.track.iter().map(|r| [r.0, r.1]).collect(),
        }],
    });
    out.notes.push(format!(
        "{} (fidelity {}; the design report's trend check gives the same verdict: {})",
        t.finding(),
        a.fidelity,
        t.found().label()
    ));
    out.fact("finding", t.finding());
    out.fact("track", t.detail());
    out.fact("analytic_finding", SpeedTrend::of_analytic(&a).finding());
    Ok(out)
}

/// The fraction of the stations with a design pressure whose largest is on the keel sensor
/// ([`KeelTrend`]); Ochi's finding is every station (1).
pub fn keel_trend(case: &Case, memo: &Memo) -> Result<Outcome> {
    let a = assessment(case, &case.file("sea")?, memo)?;
    let t = KeelTrend::of(&a);
    let Some(fraction) = t.fraction() else {
        return Err(Error::Invalid(
            "no instrumented station has a design pressure in this assessment: the trend cannot be \
             checked"
                .into(),
        ));
    };
    let mut rows = Vec::new();
    let mut series = Vec::new();
    for st in &a.stations {
        if !t.rows.iter().any(|r| r.0 == st.station) {
            continue;
        }
        let mut pts = Vec::new();
        for (i, d) in st.design_pressure_pa.iter().enumerate() {
            rows.push(vec![
                format!("{}", st.station),
                d.name.clone(),
                d.value.map_or("none".into(), |v| format!("{:.3}", v / 1e3)),
                d.source.to_string(),
                format!("{}", d.speed_m_per_s),
                d.wave.clone(),
            ]);
            if let Some(v) = d.value {
                pts.push([i as f64 + 1.0, v / 1e3]);
            }
        }
        series.push(Series {
            label: format!("station {}", st.station),
            reference: false,
            points: pts,
        });
    }
    let mut out = Outcome::new(
        fraction,
        Reference::Range {
            lower: 1.0,
            upper: 1.0,
        },
    );
    out.table = Some(Table {
        header: vec![
            "station".into(),
            "sensor".into(),
            "design_pressure_kpa".into(),
            "source".into(),
            "speed_m_per_s".into(),
            "wave".into(),
        ],
        rows,
    });
    out.figures.push(Figure {
        name: "design_pressures".into(),
        title: "Ochi V-form, test condition: design pressure per sensor".into(),
        x_label: "sensor, keel (1) to chine (4)".into(),
        y_label: "design pressure (kPa)".into(),
        series,
    });
    let keel = t.rows.iter().filter(|r| r.1 == r.4).count();
    out.notes.push(format!(
        "{keel} of {} stations have their largest design pressure on the keel sensor (fidelity {}; the \
         design report's trend check gives the same verdict: {}); Ochi's pressures themselves are not \
         available (ochi1958-pressures)",
        t.rows.len(),
        a.fidelity,
        t.found().label()
    ));
    if !t.without_keel_value.is_empty() {
        out.notes.push(format!(
            "not counted: {} (the keel sensor has no design value, so whether it carries the largest \
             pressure cannot be told)",
            t.without_keel_value
                .iter()
                .map(|(st, k, src)| format!("station {st} ({k}: {src})"))
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    out.fact("off_keel", t.off_keel());
    out.fact("stations", format!("{}", t.rows.len()));
    out.fact("keel_stations", format!("{keel}"));
    Ok(out)
}

/// The fraction of the two foremost stations whose per-sensor design peaks at 2.2 m/s fall from the
/// keel up ([`ForeTrend`]); Ochi's finding is both (1).
pub fn fore_trend(case: &Case, memo: &Memo) -> Result<Outcome> {
    let a = assessment(case, &case.file("sea")?, memo)?;
    let t = ForeTrend::of(&a);
    let Some(fraction) = t.fraction() else {
        return Err(Error::Invalid(format!(
            "no sensor peaks at the foremost stations at {} m/s: {}",
            crate::assess::trends::FORE_SPEED,
            t.detail()
        )));
    };
    let mut rows = Vec::new();
    let mut series = Vec::new();
    for (station, peaks) in &t.rows {
        for (i, (n, p, src)) in peaks.iter().enumerate() {
            rows.push(vec![
                format!("{station}"),
                format!("{}", i + 1),
                n.clone(),
                format!("{:.3}", p / 1e3),
                src.to_string(),
            ]);
        }
        series.push(Series {
            label: format!("station {station}"),
            reference: false,
            points: peaks
                .iter()
                .enumerate()
                .map(|(i, q)| [i as f64 + 1.0, q.1 / 1e3])
                .collect(),
        });
    }
    let mut out = Outcome::new(
        fraction,
        Reference::Range {
            lower: 1.0,
            upper: 1.0,
        },
    );
    out.table = Some(Table {
        header: vec![
            "station".into(),
            "sensor_index".into(),
            "sensor".into(),
            "peak_kpa".into(),
            "source".into(),
        ],
        rows,
    });
    out.figures.push(Figure {
        name: "fore_peaks".into(),
        title: format!(
            "Ochi V-form, test condition, {} m/s: sensor peaks at the foremost stations",
            crate::assess::trends::FORE_SPEED
        ),
        x_label: "sensor, keel (1) to chine (4)".into(),
        y_label: "peak pressure (kPa)".into(),
        series,
    });
    out.notes.push(format!(
        "{} (fidelity {}; the design report's trend check gives the same verdict: {})",
        t.detail(),
        a.fidelity,
        t.found().label()
    ));
    out.fact("rising", t.rising());
    Ok(out)
}
