//! Ochi's (1958) published trends and Veen's (2010) numbers for the Ochi V-form (s. 6.3), beside an
//! assessment of the reconstructed hull. Ochi's peak pressures were published as figures only and are not
//! available; the trends are qualitative (data/reference/ochi1958_vform.toml, `[published_findings]`).
//! Each check uses the per-event sensor peaks the assessment reports: SPH where an SPH run was made,
//! otherwise the analytic (MLM) estimate; the detail says which.

use super::comparisons::{Comparison, OCHI, TrendCheck, Validation, reference_number, sensor_peak};
use super::results::{Assessment, EventResult, StationResult};
use crate::error::Result;

const SOURCE: &str = "Ochi (1958), findings as reported by Veen (2010) s. 6.3 \
(data/reference/ochi1958_vform.toml [published_findings])";
const VEEN: &str = "Veen (2010) s. 6.3, 2D SPH with SEAWAY relative motion \
(data/reference/ochi1958_vform.toml [veen2010_sph])";

fn same(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-6
}

/// The station's sensors from the keel up (by girth).
fn by_girth(st: &StationResult) -> Vec<&str> {
    let mut s: Vec<_> = st.sensors.iter().collect();
    s.sort_by(|a, b| a.girth_m.total_cmp(&b.girth_m));
    s.iter().map(|q| q.name.as_str()).collect()
}

fn verdict(ok: bool) -> &'static str {
    if ok { "reproduced" } else { "not reproduced" }
}

/// The trend checks and comparisons of an Ochi V-form assessment.
pub fn ochi(a: &Assessment) -> Result<Validation> {
    let mut out = Validation::default();
    out.notes.push(
        "Ochi's (1958) measured peak pressures were published as figures only and are not available to \
         this tool: only his qualitative findings are checked"
            .into(),
    );
    // (a) the maximum pressure is near the keel
    let mut rows = Vec::new();
    let mut ok = true;
    for st in &a.stations {
        let order = by_girth(st);
        let best = st
            .design_pressure_pa
            .iter()
            .max_by(|p, q| p.value.total_cmp(&q.value));
        if let (Some(b), Some(keel)) = (best, order.first())
            && b.value > 0.0
        {
            ok &= b.name == *keel;
            rows.push(format!(
                "station {}: largest {} {:.2} kPa ({}), keel sensor {}",
                st.station,
                b.name,
                b.value / 1e3,
                b.source,
                keel
            ));
        }
    }
    out.trend_checks.push(TrendCheck {
        check: "the maximum pressure is at the keel sensor of each station (design pressures)"
            .into(),
        verdict: if rows.is_empty() {
            "not assessed"
        } else {
            verdict(ok)
        },
        detail: rows.join("; "),
        source: SOURCE.into(),
    });
    // (b) the location of the maximum moves aft with speed
    let mut speeds: Vec<f64> = a.events.iter().map(|e| e.speed_m_per_s).collect();
    speeds.dedup_by(|p, q| same(*p, *q));
    speeds.sort_by(f64::total_cmp);
    speeds.dedup_by(|p, q| same(*p, *q));
    let mut track: Vec<(f64, f64, f64, &str)> = Vec::new();
    for &u in &speeds {
        let mut best: Option<(f64, f64, &str)> = None;
        for e in a.events.iter().filter(|e| same(e.speed_m_per_s, u)) {
            for st in a.stations.iter().filter(|s| same(s.station, e.station)) {
                for q in &st.sensors {
                    if let Some((p, src)) = e.sensor_peak(&q.name)
                        && best.is_none_or(|b| p > b.1)
                    {
                        best = Some((e.station, p, src));
                    }
                }
            }
        }
        if let Some((f, p, src)) = best {
            track.push((u, f, p, src));
        }
    }
    let moves_aft = track.len() >= 2
        && track.windows(2).all(|w| w[1].1 >= w[0].1 - 1e-9)
        && track[track.len() - 1].1 > track[0].1;
    out.trend_checks.push(TrendCheck {
        check:
            "the station of the maximum pressure moves aft (larger fraction of Lpp) as speed rises"
                .into(),
        verdict: if track.len() < 2 {
            "not assessed"
        } else {
            verdict(moves_aft)
        },
        detail: track
            .iter()
            .map(|(u, f, p, src)| format!("{u} m/s: station {f} ({:.2} kPa, {src})", p / 1e3))
            .collect::<Vec<_>>()
            .join("; "),
        source: SOURCE.into(),
    });
    // (c) at 2.2 m/s the peak falls from keel to chine at the foremost stations
    let mut fore: Vec<&StationResult> = a.stations.iter().collect();
    fore.sort_by(|p, q| p.station.total_cmp(&q.station));
    fore.truncate(2);
    let mut rows = Vec::new();
    let mut ok = true;
    for st in &fore {
        let evs: Vec<&EventResult> = a
            .events
            .iter()
            .filter(|e| same(e.station, st.station) && same(e.speed_m_per_s, 2.2))
            .collect();
        let peaks: Vec<(String, f64)> = by_girth(st)
            .iter()
            .filter_map(|n| {
                sensor_peak(&evs, n).map(|(p, src)| (format!("{n} {:.2} ({src})", p / 1e3), p))
            })
            .collect();
        if peaks.len() >= 2 {
            ok &= peaks.windows(2).all(|w| w[1].1 <= w[0].1);
            rows.push(format!(
                "station {}: {} kPa",
                st.station,
                peaks
                    .iter()
                    .map(|p| p.0.as_str())
                    .collect::<Vec<_>>()
                    .join(", ")
            ));
        }
    }
    out.trend_checks.push(TrendCheck {
        check: "at 2.2 m/s the peak pressure falls from the keel sensor to the chine at the two foremost \
                stations"
            .into(),
        verdict: if rows.is_empty() { "not assessed" } else { verdict(ok) },
        detail: if rows.is_empty() {
            "2.2 m/s not assessed, or no emerging event there".into()
        } else {
            rows.join("; ")
        },
        source: SOURCE.into(),
    });
    // (d) Veen's P2 keel pressure and entry speeds at 2.0 m/s
    let num = |k: &str| reference_number(OCHI, "veen2010_sph", k);
    let (f2, u2) = (num("p2_station_aft_of_fp")?, num("p2_speed_m_s")?);
    let evs: Vec<&EventResult> = a
        .events
        .iter()
        .filter(|e| same(e.station, f2) && same(e.speed_m_per_s, u2))
        .collect();
    let keel = a
        .stations
        .iter()
        .find(|s| same(s.station, f2))
        .and_then(|s| by_girth(s).first().map(|n| n.to_string()));
    let p2 = keel.as_deref().and_then(|n| sensor_peak(&evs, n));
    out.comparisons.push(Comparison {
        quantity: format!("P2 ({f2} Lpp) pressure next to the keel at {u2} m/s"),
        computed: p2.map(|p| p.0 / 1e3),
        reference: num("p2_keel_pressure_kpa")?,
        unit: "kPa",
        source: VEEN.into(),
        note: match (&keel, p2) {
            (Some(n), Some((_, src))) => format!(
                "computed: peak of the keel sensor {n} ({src}); reference: Veen's field pressure next to the \
                 keel 0.1 s after impact, 'approximately 3.0 kPa' (not necessarily its peak)"
            ),
            _ => format!("station {f2} at {u2} m/s is not assessed or does not emerge"),
        },
    });
    let u = num("entry_speed_speed_m_s")?;
    for (st_key, v_key, label) in [
        ("p1_station_aft_of_fp", "p1_entry_speed_m_s", "P1"),
        ("p3_station_aft_of_fp", "p3_entry_speed_m_s", "P3"),
    ] {
        let f = num(st_key)?;
        let v = a
            .events
            .iter()
            .find(|e| same(e.station, f) && same(e.speed_m_per_s, u))
            .and_then(|e| e.entry_velocity_m_per_s);
        out.comparisons.push(Comparison {
            quantity: format!("{label} ({f} Lpp) keel-entry velocity at {u} m/s"),
            computed: v,
            reference: num(v_key)?,
            unit: "m/s",
            source: VEEN.into(),
            note: "computed: this tool's strip theory (reconstructed hull); reference: SEAWAY strip theory \
                   on Ochi's digitised hull (Veen)"
                .into(),
        });
    }
    Ok(out)
}
