//! Measured forcing in an assessment (`assess --forcing STATION=FILE.csv`): a station with a measured or
//! externally computed relative-motion record is driven by it ([`crate::forcing`]) instead of strip
//! theory. Its strip-theory events (every regular wave and design event at that station) are replaced by
//! one event, "measured: FILE", whose water entry starts at the keel-entry instant found in the record and
//! follows the record's entry velocity; the other stations keep strip theory. A record belongs to one ship
//! speed, so an assessment with a record runs one speed.

use std::path::PathBuf;

use serde::{Deserialize, Serialize};

use super::plan::{EntryCase, Event, Plan};
use crate::error::{Error, Result};
use crate::forcing::{self, MeasuredEntry};
use crate::hull::{Hull, LoadingCondition};
use crate::report::sanity::SlamFlag;

/// A record given for a station.
#[derive(Debug, Clone)]
pub struct StationRecord {
    /// Fraction of Lpp aft of the FP.
    pub station: f64,
    pub file: PathBuf,
}

impl StationRecord {
    /// Parse `STATION=FILE` (as `--forcing` gives it).
    pub fn parse(text: &str) -> Result<Self> {
        let bad = |why: &str| {
            Error::Invalid(format!(
                "--forcing {text}: {why}; write STATION=FILE.csv, STATION the fraction of Lpp aft of the FP \
                 (e.g. --forcing 0.05=data/forcing/record.csv)"
            ))
        };
        let (f, file) = text.split_once('=').ok_or_else(|| bad("no `=`"))?;
        let station: f64 = f
            .trim()
            .parse()
            .map_err(|_| bad(&format!("`{}` is not a number", f.trim())))?;
        if !(station.is_finite() && (0.0..=1.0).contains(&station)) {
            return Err(bad("the station must lie between 0 and 1"));
        }
        if file.trim().is_empty() {
            return Err(bad("no file"));
        }
        Ok(StationRecord {
            station,
            file: PathBuf::from(file.trim()),
        })
    }
}

/// What an assessment says of a record: where it drives, from which file, its provenance and keel entry
/// (written to summary.json as `measured_forcing` and in the report).
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct MeasuredForcing {
    /// Fraction of Lpp aft of the FP.
    pub station: f64,
    pub file: String,
    /// The file's `#` lines.
    pub provenance: Vec<String>,
    /// The record's motion column (its sign convention).
    pub column: String,
    pub velocity_from: String,
    pub draft_m: f64,
    /// Keel entry on the record's clock (s) and the downward velocity there (m/s).
    pub entry_time_s: f64,
    pub entry_velocity_m_per_s: f64,
    /// Duration of the entry profile (s) and its number of samples.
    pub profile_duration_s: f64,
    pub profile_samples: usize,
    pub profile_end: String,
    /// The strip-theory events of the station that the record replaces (their labels).
    pub replaces: Vec<String>,
}

/// The event label of a record.
pub fn wave_name(file: &str) -> String {
    let name = std::path::Path::new(file)
        .file_name()
        .map_or(file.to_string(), |n| n.to_string_lossy().into_owned());
    format!("measured: {name}")
}

/// Replace the events of every station with a record by the record's event. `threshold` is the slam
/// threshold velocity (m/s) of the flag.
pub fn apply(
    plan: &mut Plan,
    hull: &Hull,
    loading: &LoadingCondition,
    records: &[StationRecord],
    threshold: f64,
) -> Result<Vec<MeasuredForcing>> {
    if records.is_empty() {
        return Ok(Vec::new());
    }
    if plan.speeds.len() != 1 {
        return Err(Error::Invalid(format!(
            "--forcing: a measured record belongs to one ship speed, but the assessment runs {} speeds \
             ({:?} m/s); give the record's speed alone with --speeds",
            plan.speeds.len(),
            plan.speeds
        )));
    }
    let speed = plan.speeds[0];
    let mut out = Vec::new();
    for (k, r) in records.iter().enumerate() {
        if records[..k]
            .iter()
            .any(|q| (q.station - r.station).abs() < 1e-9)
        {
            return Err(Error::Invalid(format!(
                "--forcing: two records for station {}; give one per station",
                r.station
            )));
        }
        let st = crate::impact::seakeeping_station(hull, loading, r.station)?;
        let record = forcing::read_record(&r.file)?;
        let entry = forcing::measured_entry(&record, st.draft, st.height)?;
        let x = hull.station_x(r.station);
        let here = |e: &Event| (e.station - r.station).abs() < 1e-9;
        let replaces: Vec<String> = plan
            .events
            .iter()
            .filter(|e| here(e))
            .map(Event::label)
            .collect();
        plan.events.retain(|e| !here(e));
        let sensors = plan.sensors_at(r.station).to_vec();
        let points = hull.section_at(x)?.points.clone();
        let summary = summary_of(r, &entry, replaces);
        plan.warnings.push(format!(
            "station {} Lpp is driven by the measured record {} (keel entry at {:.4} s of the record, \
             {:.3} m/s) instead of strip theory; {} strip-theory event(s) of the station are replaced",
            r.station,
            summary.file,
            entry.t_entry,
            entry.entry_velocity,
            summary.replaces.len()
        ));
        plan.events.push(Event {
            station: r.station,
            x,
            speed_m_s: speed,
            wave: wave_name(&summary.file),
            flag: if entry.entry_velocity >= threshold {
                SlamFlag::Slam
            } else {
                SlamFlag::EmergesBelowThreshold
            },
            entry_velocity_m_s: Some(entry.entry_velocity),
            entry_time_s: Some(entry.t_entry),
            // A record has no encounter period: its own span stands in for the period that places the
            // event in time (the bow force groups events by speed and wave; this one is alone).
            encounter_period_s: record.time_s[record.time_s.len() - 1] - record.time_s[0],
            wave_omega_rad_s: 0.0,
            wave_amplitude_m: 0.0,
            draft_m: st.draft,
            design: None,
            flare: None,
            entry: Some(EntryCase {
                half_points: points,
                motion: entry.motion(),
                sensors,
                immersion_m: 0.0,
            }),
        });
        out.push(summary);
    }
    Ok(out)
}

fn summary_of(r: &StationRecord, e: &MeasuredEntry, replaces: Vec<String>) -> MeasuredForcing {
    MeasuredForcing {
        station: r.station,
        file: r.file.display().to_string(),
        provenance: e.provenance.clone(),
        column: e.column.name().to_string(),
        velocity_from: e.velocity_from.clone(),
        draft_m: e.draft,
        entry_time_s: e.t_entry,
        entry_velocity_m_per_s: e.entry_velocity,
        profile_duration_s: e.samples.last().map_or(0.0, |s| s.t),
        profile_samples: e.samples.len(),
        profile_end: e.profile_end.clone(),
        replaces,
    }
}
