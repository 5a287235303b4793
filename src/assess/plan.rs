//! The plan of an assessment: strip theory at every speed and regular wave, and one water-entry event per
//! station whose keel emerges (the 2D+t join of Veen 2010, ch. 6: the keel-entry velocity history of the
//! relative motion drives the station's 2D section), or, where the keel stays immersed but the rising
//! water reaches sensors above the still-water line, one flare event: the section immersed to its least
//! immersion d0 = T - |s_a| in water at rest, driven by the relative velocity from that instant until it
//! reverses ([`crate::impact::flare`], where the idealisation and what it neglects are stated).

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::hull::Hull;
use crate::impact;
use crate::report::sanity::SlamFlag;
use crate::sea::SeaState;
use crate::seakeeping::ShipModel;
use crate::seakeeping::analysis::{self, Report, Request};
use crate::sph::air::AirChoice;
use crate::sph::{MotionSpec, Overrides, SensorSpec, StudyPlan};

/// How each event's water entry is computed.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Fidelity {
    /// Modified Logvinovich (MLM) section force and sensor pressures, corrected to the similarity
    /// solution: seconds.
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
    /// What to do with the cache entries this assessment did not use (runs of other stations, speeds,
    /// numerics or tool versions): count them in a note, remove them, or leave them unlooked at.
    pub unused_cache: super::cache::Unused,
    /// Parallel SPH runs (None: rayon's default, one per core).
    pub threads: Option<usize>,
    /// Refuse, before any SPH run starts, an assessment whose estimated wall time for the runs not yet in
    /// the cache exceeds this (s); None: no bound.
    pub max_wall_s: Option<f64>,
    /// Design pressure limits (`--max-pressure-kpa`, the hull file's `[limits]`); violations are listed in
    /// the results.
    pub limits: Vec<super::limits::Limit>,
    /// How the design events of irregular seas are chosen.
    pub design_basis: super::design_event::Basis,
    /// Warnings from reading the settings (e.g. a station outside the perpendiculars), kept in the results.
    pub warnings: Vec<String>,
    /// Measured relative-motion records of stations, which replace strip theory there
    /// ([`super::measured`]).
    pub forcing: Vec<super::measured::StationRecord>,
    /// Add the keel-slope term U dz_k/dx of the 2D+t plane to the keel-entry velocities of strip theory
    /// ([`super::keel_slope`]); off by default, as in Veen (2010).
    pub keel_slope_term: bool,
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
            unused_cache: super::cache::Unused::Report,
            threads: None,
            max_wall_s: None,
            limits: Vec::new(),
            design_basis: super::design_event::Basis::MostProbableLargest,
            warnings: Vec::new(),
            forcing: Vec::new(),
            keel_slope_term: false,
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
    /// Instant of keel entry within the encounter period (s; 0: wave crest at midship), and the period.
    pub entry_time_s: Option<f64>,
    pub encounter_period_s: f64,
    /// The regular wave: frequency (rad/s) and amplitude (m); the station's local draft (m).
    pub wave_omega_rad_s: f64,
    pub wave_amplitude_m: f64,
    pub draft_m: f64,
    /// For an irregular sea's design event: its definition (None for a regular wave).
    pub design: Option<super::design_event::DesignEvent>,
    /// For a flare event (keel immersed): its start and flare impact (None for a keel entry).
    pub flare: Option<FlareEvent>,
    /// What runs: the section, the prescribed entry motion and the sensors (None: the keel does not
    /// emerge and no sensor is struck, nothing runs).
    pub entry: Option<EntryCase>,
}

/// A flare event: the keel stays immersed, the water rising relative to the hull strikes sensors above
/// the still-water line ([`crate::impact::flare::immersed_start`]).
#[derive(Debug, Clone, Serialize)]
pub struct FlareEvent {
    /// Keel depth below the undisturbed local water surface at the start, d0 = T - |s_a| (m).
    pub immersion_m: f64,
    /// Instant of least immersion within the encounter period (s; 0: wave crest at midship).
    pub start_time_s: f64,
    /// Relative motion amplitude |s_a| (m) and relative velocity amplitude (m/s) of strip theory.
    pub relative_motion_amplitude_m: f64,
    pub relative_velocity_amplitude_m_per_s: f64,
    /// Sensors with part of the panel above the still-water line that the water reaches.
    pub struck_sensors: Vec<String>,
    /// The first of them whose lower edge the water reaches after the start (None when every struck
    /// panel is partly wet already at least immersion).
    pub first_sensor: Option<String>,
    /// Height of that sensor's lower edge above the keel (m).
    pub impact_height_m: Option<f64>,
    /// Downward relative velocity when the undisturbed water surface reaches it (m/s), and when that is
    /// after the start of the event (s).
    pub impact_velocity_m_per_s: Option<f64>,
    pub impact_delay_after_start_s: Option<f64>,
    /// The idealisation, as written wherever the event appears.
    pub note: String,
}

/// What every flare event says of its idealisation.
pub const FLARE_NOTE: &str = "flare event with the keel immersed: the 2D run starts at the instant of \
least immersion with the section immersed to d0 in water at rest (2D+t still-water idealisation, as Veen \
2010); the wave orbital flow and the flow radiated by the earlier cycle of motion are neglected, so the \
water has no velocity and no surface elevation of its own at the start, and the impact depends only on the \
strip-theory relative velocity";

/// The kind of water entry, as written in summary.json, the CSV tables and the report.
pub fn kind_of(flare: Option<&FlareEvent>) -> String {
    match flare {
        Some(f) => format!("flare, keel immersed to {:.3} m", f.immersion_m),
        None => "keel entry".into(),
    }
}

/// The 2D water entry of an event.
#[derive(Debug, Clone)]
pub struct EntryCase {
    /// Starboard half of the section, keel first, from the keel to the deck edge (m).
    pub half_points: Vec<[f64; 2]>,
    pub motion: MotionSpec,
    pub sensors: Vec<SensorSpec>,
    /// Keel depth below the water surface at rest at the start (m): 0 for a keel entry, d0 for a flare
    /// event.
    pub immersion_m: f64,
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

/// The sensors of one station.
#[derive(Debug, Clone)]
pub struct StationSensors {
    pub station: f64,
    pub x: f64,
    pub sensors: Vec<SensorSpec>,
    /// True when the hull file has none at this station and these are the default panels
    /// ([`impact::default_sensors`]).
    pub default: bool,
}

impl Plan {
    /// The sensors of the station at `f` (fraction of Lpp aft of the FP).
    pub fn sensors_at(&self, f: f64) -> &[SensorSpec] {
        self.sensors
            .iter()
            .find(|s| (s.station - f).abs() < 1e-9)
            .map_or(&[], |s| s.sensors.as_slice())
    }
}

/// The events of an assessment and the motions they come from.
#[derive(Debug, Clone)]
pub struct Plan {
    pub loading: String,
    /// Water density of the loading (kg/m3), used by the analytic estimates and the SPH runs.
    pub rho: f64,
    /// Stations assessed (fractions of Lpp aft of the FP).
    pub stations: Vec<f64>,
    pub speeds: Vec<f64>,
    /// The strip-theory report (relative motion, keel entry, irregular-sea statistics).
    pub motions: Report,
    /// The ship model the motions come from (for responses the report does not keep).
    pub model: ShipModel,
    /// The sensors of each station (same order as `stations`), from the hull file or the defaults.
    pub sensors: Vec<StationSensors>,
    /// In the order speed, wave, station.
    pub events: Vec<Event>,
    pub warnings: Vec<String>,
    /// The measured records that drive stations instead of strip theory.
    pub forcing: Vec<super::measured::MeasuredForcing>,
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
    let mut at = if s.stations.is_empty() {
        impact::sensor_stations(hull)
    } else {
        s.stations.clone()
    };
    // A station with a measured record is assessed whether or not it is listed.
    for r in &s.forcing {
        if !at.iter().any(|&f| (f - r.station).abs() < 1e-9) {
            at.push(r.station);
        }
    }
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
    let mut sensors = Vec::new();
    for &f in &at {
        let x = hull.station_x(f);
        let given = impact::station_sensors(hull, x);
        sensors.push(if given.is_empty() {
            StationSensors {
                station: f,
                x,
                sensors: impact::default_sensors::default_sensors(hull, loading, x)
                    .map_err(|e| Error::Invalid(format!("--station {f}: {e}")))?,
                default: true,
            }
        } else {
            StationSensors {
                station: f,
                x,
                sensors: given,
                default: false,
            }
        });
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
    let mut req = Request::for_sea(sea, speeds.clone(), stations.clone());
    req.keel_slope_term = s.keel_slope_term;
    // RAOs at lambda/L = 0.5, 0.6, .., 3.0 for the report (strip theory only, no water entry).
    req.lambda_over_l = (5..=30).map(|k| f64::from(k) / 10.0).collect();
    let motions = analysis::run(&model, &req)?;
    let mut events = Vec::new();
    for sp in &motions.speeds {
        for w in &sp.regular {
            for st in &w.stations {
                let flag = SlamFlag::of(st, motions.slam_threshold_velocity_m_s);
                let here = sensors
                    .iter()
                    .find(|q| (q.station - st.aft_of_fp).abs() < 1e-9)
                    .map(|q| q.sensors.clone())
                    .unwrap_or_default();
                let points = hull.section_at(st.x)?.points.clone();
                let height = stations
                    .iter()
                    .find(|q| (q.aft_of_fp - st.aft_of_fp).abs() < 1e-9)
                    .map_or(f64::INFINITY, |q| q.height);
                events.push(station_event(
                    st,
                    &Wave {
                        name: &w.wave,
                        omega0: w.omega0,
                        omega_e: w.omega_e,
                        amplitude_m: 0.5 * w.height_m,
                    },
                    sp.speed_m_s,
                    flag,
                    (points, height),
                    here,
                ));
            }
        }
    }
    let (design, design_warnings) = super::design_event::plan_events(
        &super::design_event::PlanInputs {
            hull,
            sea,
            model: &model,
            motions: &motions,
            stations: &stations,
            sensors: &sensors,
        },
        s.design_basis,
    )?;
    events.extend(design);
    let mut warnings = s.warnings.clone();
    warnings.extend(motions.warnings.iter().cloned());
    warnings.extend(design_warnings);
    // the `--air` choice under which the SPH runs have air (none without SPH runs)
    let air = match s.overrides.air {
        _ if s.fidelity == Fidelity::Analytic => None,
        Some(AirChoice::On) => Some("on"),
        Some(AirChoice::Auto) => Some("auto"),
        _ => None,
    };
    // `sensors` holds one entry per station of `at`, in its order
    for (&f, q) in at.iter().zip(&sensors) {
        let points = &hull.section_at(hull.station_x(f))?.points;
        warnings.extend(match air {
            Some(choice) => impact::air_cushion_statement(f, points, choice),
            None => impact::air_cushion_warning(f, points),
        });
        warnings.extend(chine_warning(points, q));
    }
    for st in stations.iter().filter(|st| st.draft <= 0.0) {
        warnings.push(format!(
            "station {} Lpp is a dry station: its keel is {:.3} m above the calm waterline at loading \
             '{}', so an event there is the water reaching the keel (keel entry when the relative motion \
             exceeds that height; Ochi's statistics take that height for the draft), not a keel that emerges and \
             re-enters",
            st.aft_of_fp,
            -st.draft,
            loading.name
        ));
    }
    warnings.extend(super::keel_slope::lines(
        &stations,
        &events,
        s.keel_slope_term,
    ));
    for q in sensors.iter().filter(|q| q.default) {
        let first = q.sensors.first().map_or("", |s| s.name.as_str());
        let rule = if first.starts_with('D') {
            "one every 5 % of the girth from the keel to the deck edge (each 5 % of it wide): the keel is \
             above the design waterline, or its girth below it is less than a quarter of the whole"
        } else {
            "one every 5 % of the girth from the keel to the design waterline (each 5 % of it wide), \
             continued up the side and flare to the deck edge"
        };
        warnings.push(format!(
            "station {} Lpp carries no sensors in the hull file: {} default panels {first}..{} are used, \
             {rule}",
            q.station,
            q.sensors.len(),
            q.sensors.last().map_or("", |s| s.name.as_str()),
        ));
    }
    let threshold = motions.slam_threshold_velocity_m_s;
    let mut p = Plan {
        loading: loading.name.clone(),
        stations: at,
        speeds,
        motions,
        model,
        sensors,
        events,
        warnings,
        rho: loading.rho,
        forcing: Vec::new(),
    };
    p.forcing = super::measured::apply(&mut p, hull, loading, &s.forcing, threshold)?;
    Ok(p)
}

/// A regular wave as an event needs it: its name, frequency (rad/s), encounter frequency (rad/s) and
/// amplitude (m).
pub struct Wave<'a> {
    pub name: &'a str,
    pub omega0: f64,
    pub omega_e: f64,
    pub amplitude_m: f64,
}

/// The event of one station at one speed in one regular wave: a keel entry where the keel emerges, a
/// flare event where it stays immersed but the water reaches sensors above the still-water line
/// (`flare_event`), otherwise none. `section` is the station's offsets (half points, keel first) and
/// its keel-to-deck height. Shared by the assessment and the sweeps.
pub fn station_event(
    st: &crate::seakeeping::analysis::RegularStation,
    w: &Wave,
    speed_m_s: f64,
    flag: SlamFlag,
    section: (Vec<[f64; 2]>, f64),
    sensors: Vec<SensorSpec>,
) -> Event {
    let (points, height) = section;
    let mut flare = None;
    let entry = match &st.keel_entry {
        Some(k) => Some(EntryCase {
            half_points: points,
            motion: impact::entry_motion(k),
            sensors,
            immersion_m: 0.0,
        }),
        None => flare_event(st, w.omega_e, w.amplitude_m, height, &points, &sensors).map(
            |(f, motion)| {
                let immersion_m = f.immersion_m;
                flare = Some(f);
                EntryCase {
                    half_points: points,
                    motion,
                    sensors,
                    immersion_m,
                }
            },
        ),
    };
    Event {
        station: st.aft_of_fp,
        x: st.x,
        speed_m_s,
        wave: w.name.to_string(),
        flag,
        entry_velocity_m_s: st.keel_entry.as_ref().map(|k| k.entry_velocity),
        entry_time_s: st
            .keel_entry
            .as_ref()
            .map(|k| k.t_entry)
            .or(flare.as_ref().map(|f| f.start_time_s)),
        encounter_period_s: 2.0 * std::f64::consts::PI / w.omega_e,
        wave_omega_rad_s: w.omega0,
        wave_amplitude_m: w.amplitude_m,
        draft_m: st.draft,
        design: None,
        flare,
        entry,
    }
}

/// The flare event of a station whose keel stays immersed, and its prescribed motion: None when the keel
/// emerges, or when no sensor above the still-water line is reached by the water.
fn flare_event(
    st: &crate::seakeeping::analysis::RegularStation,
    omega_e: f64,
    zeta_a: f64,
    max_depth: f64,
    points: &[[f64; 2]],
    sensors: &[SensorSpec],
) -> Option<(FlareEvent, MotionSpec)> {
    use crate::impact::flare;
    let rm = &st.relative_motion;
    let amp = rm.motion.norm() * zeta_a;
    let struck = flare::struck_sensors(points, sensors, st.draft, amp);
    if struck.is_empty() {
        return None;
    }
    let start = flare::immersed_start(rm, omega_e, zeta_a, st.draft, max_depth, 41)?;
    // The first panel whose lower edge is still dry at least immersion (above d0).
    let first = struck
        .iter()
        .filter(|(_, lo)| *lo > start.immersion_m)
        .min_by(|a, b| a.1.total_cmp(&b.1));
    let hit = first.and_then(|(_, lo)| flare::water_reaches(rm, omega_e, zeta_a, st.draft, *lo));
    let motion = MotionSpec::Prescribed {
        table: start
            .samples
            .iter()
            .map(|s| [s.t, s.velocity.max(0.0)])
            .collect(),
    };
    Some((
        FlareEvent {
            immersion_m: start.immersion_m,
            start_time_s: start.start_time_s,
            relative_motion_amplitude_m: amp,
            relative_velocity_amplitude_m_per_s: rm.velocity.norm() * zeta_a,
            struck_sensors: struck.iter().map(|(n, _)| n.clone()).collect(),
            first_sensor: first.map(|(n, _)| n.clone()),
            impact_height_m: first.map(|(_, lo)| *lo),
            impact_velocity_m_per_s: hit.map(|c| c.velocity_m_per_s),
            impact_delay_after_start_s: hit
                .map(|c| (c.time_s - start.start_time_s).rem_euclid(start.encounter_period_s)),
            note: FLARE_NOTE.into(),
        },
        motion,
    ))
}

/// The warning of a station whose panels reach above a chine (the first one up the contour,
/// [`super::chines`]): their analytic estimates assume attached flow past it. None without such panels.
fn chine_warning(points: &[[f64; 2]], q: &StationSensors) -> Option<String> {
    let c = super::chines::chines(points).into_iter().next()?;
    let above: Vec<&str> = q
        .sensors
        .iter()
        .filter(|s| s.s_m + 0.5 * s.width_m > c.girth_m + 1e-9)
        .map(|s| s.name.as_str())
        .collect();
    if above.is_empty() {
        return None;
    }
    let names = if above.len() > 6 {
        format!(
            "{} panels, {}..{}",
            above.len(),
            above[0],
            above[above.len() - 1]
        )
    } else {
        above.join(", ")
    };
    Some(format!(
        "station {} Lpp has a chine at girth {:.3} m (y {:.3} m, {:.3} m above the keel), where the contour \
         turns {:.0} deg steeper ({:.0} to {:.0} deg of deadrise): the flow can separate there, while the \
         analytic models assume it stays attached and can read several times the SPH pressure above a chine. The \
         analytic values of the panels that reach above it ({names}), and of the section force once the chine is \
         wetted, are attached-flow bounds; where one is a design value (SPH not converged or not \
         resolved), refine the SPH run rather than sign it",
        q.station,
        c.girth_m,
        c.y_m,
        c.z_m,
        c.turn_deg(),
        c.deadrise_below_deg,
        c.deadrise_above_deg
    ))
}
