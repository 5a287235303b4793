//! The plan of an assessment: strip theory at every speed and regular wave, and one water-entry event per
//! station whose keel emerges (the 2D+t join of Veen 2010, ch. 6: the keel-entry velocity history of the
//! relative motion drives the station's 2D section).

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::hull::Hull;
use crate::impact;
use crate::report::sanity::SlamFlag;
use crate::sea::SeaState;
use crate::seakeeping::ShipModel;
use crate::seakeeping::analysis::{self, Report, Request};
use crate::sph::{MotionSpec, Overrides, SensorSpec, StudyPlan};

/// How each event's water entry is computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Fidelity {
    /// Generalised Wagner force and modified Logvinovich (MLM) sensor pressures: seconds.
    Analytic,
    /// SPH for every event, each with the analytic estimate and a convergence statement beside it.
    Sph,
    /// Analytic everywhere, then SPH for the governing event of each station (highest analytic sensor
    /// pressure).
    Screen,
}

impl Fidelity {
    pub fn name(self) -> &'static str {
        match self {
            Fidelity::Analytic => "analytic",
            Fidelity::Sph => "sph",
            Fidelity::Screen => "screen",
        }
    }
}

/// What to assess and how.
#[derive(Debug, Clone)]
pub struct Settings {
    /// Loading condition (None: the hull's first).
    pub loading: Option<String>,
    /// Stations as fractions of Lpp aft of the FP (empty: the hull's sensor stations).
    pub stations: Vec<f64>,
    /// Speeds in m/s (None: the sea-state file's).
    pub speeds: Option<Vec<f64>>,
    pub fidelity: Fidelity,
    /// Numerics of the SPH runs (resolution level or particles across the half-breadth).
    pub overrides: Overrides,
    /// Convergence study of every SPH run.
    pub study: StudyPlan,
    /// Strips along the hull for strip theory.
    pub strips: usize,
    /// Read finished runs from the cache (they are always written to it).
    pub use_cache: bool,
    /// Parallel SPH runs (None: rayon's default, one per core).
    pub threads: Option<usize>,
    /// The design gate's limit on sensor design pressures (kPa), recorded in summary.json so that the
    /// report states the verdict.
    pub max_pressure_kpa: Option<f64>,
}

impl Default for Settings {
    fn default() -> Self {
        Self {
            loading: None,
            stations: Vec::new(),
            speeds: None,
            fidelity: Fidelity::Screen,
            overrides: Overrides::default(),
            study: StudyPlan::default(),
            strips: 31,
            use_cache: true,
            threads: None,
            max_pressure_kpa: None,
        }
    }
}

/// One station at one speed in one regular wave.
#[derive(Debug, Clone)]
pub struct Event {
    /// Fraction of Lpp aft of the FP.
    pub station: f64,
    /// m from midship.
    pub x: f64,
    pub speed_m_s: f64,
    pub wave: String,
    pub flag: SlamFlag,
    /// Velocity at keel entry (m/s), when the keel emerges.
    pub entry_velocity_m_s: Option<f64>,
    /// What runs: the section, the prescribed entry motion and the sensors (None: the keel does not
    /// emerge, nothing runs).
    pub entry: Option<EntryCase>,
}

/// The 2D water entry of an event.
#[derive(Debug, Clone)]
pub struct EntryCase {
    /// Starboard half of the section, keel first, from the keel to the deck edge (m).
    pub half_points: Vec<[f64; 2]>,
    pub motion: MotionSpec,
    pub sensors: Vec<SensorSpec>,
}

impl Event {
    /// A short unique label: station, speed and wave.
    pub fn label(&self) -> String {
        format!(
            "{:.3} Lpp, {:.2} m/s, {}",
            self.station, self.speed_m_s, self.wave
        )
    }
}

/// The events of an assessment and the motions they come from.
#[derive(Debug, Clone)]
pub struct Plan {
    pub loading: String,
    /// Stations assessed (fractions of Lpp aft of the FP).
    pub stations: Vec<f64>,
    pub speeds: Vec<f64>,
    /// The strip-theory report (relative motion, keel entry, irregular-sea statistics).
    pub motions: Report,
    /// In the order speed, wave, station.
    pub events: Vec<Event>,
    pub warnings: Vec<String>,
}

/// Plan an assessment: strip theory and the events.
pub fn plan(hull: &Hull, sea: &SeaState, s: &Settings) -> Result<Plan> {
    let loading = hull.loading(s.loading.as_deref())?;
    if sea.regular.is_empty() && sea.irregular.is_empty() {
        return Err(Error::Invalid(format!(
            "{}: the sea state has no waves (give [[regular]] waves or [[irregular]] seas)",
            sea.source.display()
        )));
    }
    let at = if s.stations.is_empty() {
        impact::sensor_stations(hull)
    } else {
        s.stations.clone()
    };
    let mut stations = Vec::new();
    for &f in &at {
        if !(f.is_finite() && (0.0..=1.0).contains(&f)) {
            return Err(Error::Invalid(format!(
                "--station {f}: a station is a fraction of Lpp aft of the FP between 0 and 1"
            )));
        }
        hull.section_at(hull.station_x(f))
            .map_err(|e| Error::Invalid(format!("--station {f}: {e}")))?;
        stations.push(
            impact::seakeeping_station(hull, loading, f)
                .map_err(|e| Error::Invalid(format!("--station {f}: {e}")))?,
        );
    }
    let model = ShipModel::from_hull(hull, loading, s.strips)?;
    let speeds = match &s.speeds {
        Some(v) => v.clone(),
        None => sea.speeds.resolve(hull.lpp),
    };
    for &u in &speeds {
        if !(u.is_finite() && u >= 0.0) {
            return Err(Error::Invalid(format!(
                "speeds must be finite and not negative, got {u} m/s"
            )));
        }
    }
    let mut req = Request::for_sea(sea, speeds.clone(), stations);
    // RAOs at lambda/L = 0.5, 0.6, .., 3.0 for the report (strip theory only, no water entry).
    req.lambda_over_l = (5..=30).map(|k| f64::from(k) / 10.0).collect();
    let motions = analysis::run(&model, &req)?;
    let mut events = Vec::new();
    for sp in &motions.speeds {
        for w in &sp.regular {
            for st in &w.stations {
                let flag = SlamFlag::of(st, motions.slam_threshold_velocity_m_s);
                let entry = match &st.keel_entry {
                    Some(k) => Some(EntryCase {
                        half_points: hull.section_at(st.x)?.points.clone(),
                        motion: impact::entry_motion(k),
                        sensors: impact::station_sensors(hull, st.x),
                    }),
                    None => None,
                };
                events.push(Event {
                    station: st.aft_of_fp,
                    x: st.x,
                    speed_m_s: sp.speed_m_s,
                    wave: w.wave.clone(),
                    flag,
                    entry_velocity_m_s: st.keel_entry.as_ref().map(|k| k.entry_velocity),
                    entry,
                });
            }
        }
    }
    let mut warnings = motions.warnings.clone();
    if !sea.irregular.is_empty() {
        warnings.push(IRREGULAR_NOTE.to_string());
    }
    for &f in &at {
        if impact::station_sensors(hull, hull.station_x(f)).is_empty() {
            warnings.push(format!(
                "station {f} Lpp carries no sensors in the hull file: only its section force is reported"
            ));
        }
    }
    Ok(Plan {
        loading: loading.name.clone(),
        stations: at,
        speeds,
        motions,
        events,
        warnings,
    })
}

/// What an assessment says about irregular seas.
pub const IRREGULAR_NOTE: &str = "irregular seas are reported as slam statistics only (probability per \
encounter, slams per hour, most probable largest entry velocity over the exposure): design events for \
irregular seas are not run yet";
