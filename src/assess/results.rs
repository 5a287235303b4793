//! The results of an assessment: per event (station x speed x wave), per station (the design pressure
//! of each sensor, the maximum over events, and the peak section force), and the files they are written
//! to: `summary.json` and the tidy `pressures.csv` (one row per station x speed x wave x sensor), both
//! with provenance. This is the API the report generator reads.

use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use super::analytic::Estimate;
use super::design_rule::{AnalyticPeak, Decision, SphQuantity, decide};
use crate::error::{Error, Result};
use crate::files::write_text_atomic;
use crate::loads::anatomy::{ImpactStatus, Phase};
use crate::provenance::{Provenance, TOOL, tidy_numbers};
use crate::report::sanity::SlamFlag;

/// One sensor of an SPH run.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct SphSensor {
    pub name: String,
    /// The largest raw value the panel carries in the run, and its time (`peak_time_s`): for a sensor a
    /// keel stage resolved, the stage's, or the main run's later load where that is larger (the stage
    /// covers only the early entry; [`crate::sph::keel_stage::LaterLoad`]).
    pub raw_peak_pa: f64,
    pub filtered_peak_pa: Option<f64>,
    pub peak_time_s: f64,
    pub impulse_pa_s: f64,
    /// Convergence verdict of the slamming peak (filtered where `slamming_filtered`: converged,
    /// acceptable, not_converged, mismatched, ...) and its statement.
    pub convergence: Option<String>,
    pub convergence_statement: Option<String>,
    /// Whether the SPH water reached the sensor with a slamming pressure: its raw peak is at least
    /// [`DRY_FRACTION`] x 1/2 rho V^2 (V the largest entry speed of the run). A dry sensor's design value
    /// is the analytic one ([`EventResult::sensor_peak`]).
    #[serde(default = "yes")]
    pub wetted: bool,
    /// Whether the raw peak is the last sample of the record: the pressure was still rising when the run
    /// ended.
    #[serde(default)]
    pub still_rising: bool,
    /// The record's anatomy ([`crate::loads::anatomy`]): whether SPH resolves the impact, its window,
    /// the slamming peak (the largest value in the window; `raw_peak_pa` is the largest after the contact
    /// transient, whatever its phase), its hydrostatic part, rise time and impulse.
    #[serde(default)]
    pub impact: Option<ImpactStatus>,
    #[serde(default)]
    pub impact_window_s: Option<[f64; 2]>,
    #[serde(default)]
    pub slamming_peak_pa: Option<f64>,
    #[serde(default)]
    pub slamming_peak_time_s: Option<f64>,
    #[serde(default)]
    pub slamming_impulse_pa_s: Option<f64>,
    /// Whether the slamming peak, its window status, time, rise, hydrostatic part, GCI, spread and
    /// verdict are those of the low-passed record (the run's physical cut-off, `filter_cutoff_hz`), the
    /// design quantity wherever the run has a cut-off ([`super::design_rule`]); false: the raw record's.
    #[serde(default)]
    pub slamming_filtered: bool,
    /// The raw record's slamming peak (the largest unfiltered value in the impact window) and its
    /// convergence verdict, reported beside the filtered design quantity.
    #[serde(default)]
    pub raw_slamming_peak_pa: Option<f64>,
    #[serde(default)]
    pub raw_convergence: Option<String>,
    /// The slamming peak is the window's last sample and the record still rises after it: no distinct
    /// impact peak, the value where the window closes ([`crate::loads::anatomy::Anatomy::at_window_end`]).
    #[serde(default)]
    pub rising_at_window_end: bool,
    #[serde(default)]
    pub rise_time_s: Option<f64>,
    #[serde(default)]
    pub hydrostatic_pa: Option<f64>,
    /// The phase of the largest value after the transient (`raw_peak_pa`) and its hydrostatic part.
    #[serde(default)]
    pub largest_phase: Option<Phase>,
    #[serde(default)]
    pub largest_hydrostatic_pa: Option<f64>,
    /// GCI of the slamming peak (fraction), from the matched levels.
    #[serde(default)]
    pub gci: Option<f64>,
    /// Where the levels' peaks are different events: |P_2 - P| / |P| ([`super::design_rule`]).
    #[serde(default)]
    pub spread: Option<f64>,
    /// Particles across the analytic wetted half-width when the contact crosses the sensor (at the
    /// spacing of the run whose record the sensor has: the keel stage's when one resolved it).
    #[serde(default)]
    pub particles_across_wetted: Option<f64>,
    /// The spacing (m) of the keel stage that resolved the sensor ([`crate::sph::keel_stage`]); `None`
    /// when the record is the main run's.
    #[serde(default)]
    pub stage_dp_m: Option<f64>,
    /// The local deadrise of the sensor's integration span (deg); from
    /// [`crate::loads::anatomy::KEEL_MAXIMUM_FROM_DEG`] on, the record has no impact pulse and its
    /// convergence levels are compared by value ([`crate::loads::anatomy::matched`]).
    #[serde(default)]
    pub local_deadrise_deg: Option<f64>,
}

impl SphSensor {
    /// The largest SPH value when it lies in the immersion phase (after the impact window) and exceeds
    /// `design` (any, where there is no design value): a load the panel carries that is not its
    /// slamming pressure.
    pub fn later_load(&self, design: Option<f64>) -> Option<f64> {
        (self.largest_phase == Some(Phase::Immersion)
            && design.is_none_or(|d| self.raw_peak_pa > d))
        .then_some(self.raw_peak_pa)
    }

    /// What the design rule needs of this sensor.
    pub fn quantity(&self) -> SphQuantity<'_> {
        SphQuantity {
            status: self.impact,
            slamming: if self.impact.is_some() {
                self.slamming_peak_pa
            } else {
                Some(self.raw_peak_pa)
            },
            gci: self.gci,
            verdict: self.convergence.as_deref(),
            wetted: self.wetted,
            spread: self.spread,
            rising_at_window_end: self.rising_at_window_end,
        }
    }
}

fn yes() -> bool {
    true
}

/// A sensor whose SPH peak stays below this fraction of the dynamic pressure 1/2 rho V^2 of the entry
/// saw no slam in the run: a slamming pressure coefficient is of order one or more (Wagner: Cp =
/// (pi^2/4) cot^2 beta, 1 at 57 deg of deadrise), and a sensor that one layer of particles covers at
/// rest reads rho g dp, well above a splash. Such a sensor was not wetted by the impact within the run,
/// most often because the flow separated from the contour below it.
pub const DRY_FRACTION: f64 = 0.05;

/// The design-value `source` of a sensor the SPH run did not wet, whose value is the analytic one.
pub const DRY_SOURCE: &str = "analytic (dry in SPH)";

/// The warnings an SPH run's sensors raise in an assessment, only what a reader must act on: a sensor
/// the SPH water did not reach (with the analytic value that stands in for it), and the sensors whose
/// impact SPH does not compute at this spacing (grouped by the reason), whose design values are the
/// analytic ones.
pub fn sensor_warnings(r: &SphRecord, analytic: Option<&Estimate>) -> Vec<String> {
    let mut out = Vec::new();
    let mlm = |name: &str| {
        analytic
            .and_then(|a| a.sensors.iter().find(|s| s.name == name))
            .and_then(|s| s.peak())
    };
    for q in &r.sensors {
        if !q.wetted {
            let a = mlm(&q.name).map_or_else(
                || "no analytic estimate either".to_string(),
                |p| {
                    format!(
                        "its design value is the analytic (MLM) peak, {:.2} kPa, which assumes the flow \
                         stays attached and is therefore the conservative value",
                        p * 1e-3
                    )
                },
            );
            // What was compared with the threshold: the slamming peak in the sensor's impact window when
            // the record has one (the run's largest value may come later, with the water that reached
            // the sensor after the window), else the run's largest value.
            let reached = match (
                q.raw_slamming_peak_pa.or(q.slamming_peak_pa),
                q.impact_window_s,
            ) {
                (Some(p), Some([t0, t1])) => {
                    let later = if q.raw_peak_pa > p {
                        format!(
                            "; the run's largest value, {:.3} kPa at {:.3} s, came after it",
                            q.raw_peak_pa * 1e-3,
                            q.peak_time_s
                        )
                    } else {
                        String::new()
                    };
                    format!(
                        "within its impact window ({t0:.3}-{t1:.3} s: largest {:.3} kPa, below \
                         {DRY_FRACTION} x 1/2 rho V^2{later})",
                        p * 1e-3
                    )
                }
                _ => format!(
                    "within the run (raw peak {:.3} kPa, below {DRY_FRACTION} x 1/2 rho V^2)",
                    q.raw_peak_pa * 1e-3
                ),
            };
            out.push(format!(
                "sensor {}: the SPH water did not reach it with a slamming pressure {reached}: the flow \
                 separated from the contour below it or reached it only after that; {a}",
                q.name
            ));
        }
    }
    let group = |status: ImpactStatus| -> Vec<&str> {
        r.sensors
            .iter()
            .filter(|q| q.wetted && q.impact == Some(status))
            .map(|q| q.name.as_str())
            .collect()
    };
    let transient = group(ImpactStatus::InTransient);
    if !transient.is_empty() {
        out.push(format!(
            "sensors {}: the analytic contact crosses them within the SPH contact transient (the keel less \
             than {} particle spacings deep, dp {:.2} mm), so SPH does not resolve their impact at this \
             spacing; their design values are the analytic (MLM) estimates where that model gives one (not \
             on a panel already wetted at contact). A finer spacing near the keel \
             would resolve them",
            transient.join(", "),
            crate::sph::CONTACT_TRANSIENT_DP,
            r.dp_m * 1e3
        ));
    }
    let cushioned = group(ImpactStatus::Cushioned);
    if !cushioned.is_empty() {
        out.push(format!(
            "sensors {}: on the flat keel, computed with air (a two-phase run): their slamming peaks are those \
             of the two-phase model's cushioned impact, taken from the start of the run (the keel's approach \
             through the air gap) to the end of the widened analytic crossing; they grow with the water's \
             artificial sound speed (docs/guide/air.md), so they are not design values, and no analytic \
             model computes a cushioned impact to cross-check them",
            cushioned.join(", ")
        ));
    }
    let acoustic = group(ImpactStatus::Acoustic);
    if !acoustic.is_empty() {
        out.push(format!(
            "sensors {}: the contact crosses them at an acoustic speed (flat or nearly flat keel): the impact \
             is a water-hammer pressure that single-phase SPH with an artificial sound speed does not \
             compute, and air cushions it in reality; the analytic models give no peak there either (their \
             pressure only falls from the flat keel's singular start), so these panels have no design \
             value from this tool: the water-hammer pressure rho c_w V is the upper bound of an impact \
             without air, and the cushioned impact needs a two-phase model",
            acoustic.join(", ")
        ));
    }
    let later: Vec<String> = r
        .sensors
        .iter()
        .filter_map(|q| {
            let design = decide(Some(q.quantity()), mlm(&q.name).into())?.value;
            let load = q.later_load(design)?;
            Some(format!(
                "{} ({:.2} kPa at {:.3} s, of which {:.2} kPa hydrostatic; design {})",
                q.name,
                load * 1e-3,
                q.peak_time_s,
                q.largest_hydrostatic_pa.unwrap_or(0.0) * 1e-3,
                design.map_or("none".into(), |d| format!("{:.2} kPa", d * 1e-3))
            ))
        })
        .collect();
    if !later.is_empty() {
        out.push(format!(
            "sensors {}: the largest SPH pressure comes after the impact, in the immersion phase (the \
             added-mass and hydrostatic load of the deepening section, or a later impact higher up felt \
             across the wetted contour), above the design slamming value: it is not a slamming pressure of \
             the panel, but a load the panel carries; check it as a load case of its own",
            later.join(", ")
        ));
    }
    let late = group(ImpactStatus::AfterRecord);
    if !late.is_empty() {
        out.push(format!(
            "sensors {}: their impact window lies at or after the end of the SPH run; their design values \
             are the analytic estimates (a longer run would compute them)",
            late.join(", ")
        ));
    }
    out
}

/// What an assessment keeps of an SPH run (also the record in its cache entry).
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct SphRecord {
    /// Cache key (the run folder is `cache/<key>/`).
    pub key: String,
    pub dp_m: f64,
    /// Cut-off of the zero-phase low-pass filter of the `filtered_peak_pa` values (Hz), or none.
    #[serde(default)]
    pub filter_cutoff_hz: Option<f64>,
    /// How the cut-off was chosen ([`crate::loads::cutoff`]).
    #[serde(default)]
    pub filter_rule: Option<String>,
    pub force_peak_n_per_m: f64,
    pub force_peak_time_s: f64,
    pub force_convergence: Option<String>,
    /// The section force's slamming peak (its largest value up to Wagner's full wetting, widened; see
    /// [`crate::sph::phases`]), its time, hydrostatic part (buoyancy) and GCI.
    #[serde(default)]
    pub force_slamming_peak_n_per_m: Option<f64>,
    #[serde(default)]
    pub force_slamming_time_s: Option<f64>,
    #[serde(default)]
    pub force_hydrostatic_n_per_m: Option<f64>,
    #[serde(default)]
    pub force_gci: Option<f64>,
    /// Where the levels' force peaks are different events: |F_2 - F| / |F| ([`super::design_rule`]).
    #[serde(default)]
    pub force_spread: Option<f64>,
    #[serde(default)]
    pub force_convergence_statement: Option<String>,
    /// Whether the force's slamming peak and convergence are those of the low-passed record (as
    /// [`SphSensor::slamming_filtered`]), and the raw record's slamming peak beside it.
    #[serde(default)]
    pub force_slamming_filtered: bool,
    #[serde(default)]
    pub force_raw_slamming_peak_n_per_m: Option<f64>,
    pub sensors: Vec<SphSensor>,
    pub stopped_early: Option<String>,
    pub warnings: Vec<String>,
    /// Whether the run had air as a second phase, and why (`--air`; [`crate::sph::air`]): the choice's
    /// note (with `auto`, the deadrise it found) and the air layer; None when air was off.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub air: Option<String>,
}

/// One station at one speed in one regular wave.
#[derive(Debug, Clone, Serialize)]
pub struct EventResult {
    /// Fraction of Lpp aft of the FP.
    pub station: f64,
    pub x_m: f64,
    pub speed_m_per_s: f64,
    pub wave: String,
    /// Ochi's criterion as `slamtool motions` reports it: slam, emerges-below-threshold, no-emergence.
    pub slam_flag: SlamFlag,
    /// Velocity at keel entry (m/s), when the keel emerges.
    pub entry_velocity_m_per_s: Option<f64>,
    /// The kind of water entry: "keel entry", or "flare, keel immersed to `<d0>` m" for a flare event (the
    /// keel stays immersed; see `flare_event`); None when nothing runs.
    pub entry_kind: Option<String>,
    /// For a flare event: its start (least immersion d0), the sensors struck, the relative velocity at
    /// flare impact and the idealisation it rests on.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub flare_event: Option<super::plan::FlareEvent>,
    /// For an irregular sea's design event (wave `"<sea>/design"`): how it is defined, with N or alpha.
    pub design_event: Option<super::design_event::DesignEvent>,
    /// The analytic section force and sensor pressures (corrected MLM; when the keel emerges).
    pub analytic: Option<Estimate>,
    /// The SPH run, when one was made and finished.
    pub sph: Option<SphRecord>,
    /// Run folder relative to the output folder.
    pub run_folder: Option<String>,
    /// Why a computation of this event failed.
    pub failed: Option<String>,
    pub warnings: Vec<String>,
}

impl EventResult {
    /// The result of the planned event `e` with its analytic estimate and warnings, before any SPH run
    /// (`sph`, `run_folder` and `failed` empty): what an analytic sweep case keeps, and what `assess`
    /// completes with its run.
    pub fn of_event(
        e: &super::plan::Event,
        analytic: Option<Estimate>,
        warnings: Vec<String>,
    ) -> Self {
        Self {
            station: e.station,
            x_m: e.x,
            speed_m_per_s: e.speed_m_s,
            wave: e.wave.clone(),
            slam_flag: e.flag,
            entry_velocity_m_per_s: e.entry_velocity_m_s,
            entry_kind: e
                .entry
                .as_ref()
                .map(|_| super::plan::kind_of(e.flare.as_ref())),
            flare_event: e.flare.clone(),
            design_event: e.design.clone(),
            analytic,
            sph: None,
            run_folder: None,
            failed: None,
            warnings,
        }
    }

    /// The section force design decision ([`super::design_rule`]).
    pub fn force_design(&self) -> Option<Decision> {
        let q = self.sph.as_ref().map(|s| SphQuantity {
            status: s
                .force_slamming_peak_n_per_m
                .map(|_| ImpactStatus::Resolved),
            slamming: s.force_slamming_peak_n_per_m.or(Some(s.force_peak_n_per_m)),
            gci: s.force_gci,
            verdict: s.force_convergence.as_deref(),
            wetted: true,
            spread: s.force_spread,
            rising_at_window_end: false,
        });
        decide(
            q,
            self.analytic
                .as_ref()
                .and_then(|a| a.force_peak_n_per_m)
                .into(),
        )
    }

    /// The section force peak used for design (N/m) and its source ([`super::design_rule`]).
    pub fn force_peak(&self) -> Option<(f64, &'static str)> {
        self.force_design()
            .and_then(|d| d.value.map(|v| (v, d.source)))
    }

    /// A sensor's design decision ([`super::design_rule`]): none when neither SPH nor the analytic
    /// estimate has the sensor.
    pub fn sensor_design(&self, name: &str) -> Option<Decision> {
        let estimate = self
            .analytic
            .as_ref()
            .and_then(|a| a.sensors.iter().find(|q| q.name == name));
        let q = match &self.sph {
            Some(s) => Some(s.sensors.iter().find(|q| q.name == name)?.quantity()),
            None => None,
        };
        decide(q, AnalyticPeak::of_sensor(estimate))
    }

    /// A sensor's design value (Pa) for this event and its source ([`super::design_rule`]).
    pub fn sensor_peak(&self, name: &str) -> Option<(f64, &'static str)> {
        self.sensor_design(name)
            .and_then(|d| d.value.map(|v| (v, d.source)))
    }
}

/// The design value of one quantity at a station: the maximum over events, and where it comes from.
#[derive(Debug, Clone, Serialize)]
pub struct DesignValue {
    pub name: String,
    /// `None` where no model here computes the load ([`super::design_rule::NO_VALUE_FLAT_KEEL`]).
    pub value: Option<f64>,
    /// "sph", "analytic", or "analytic (dry in SPH)" for a sensor the SPH run did not wet
    /// ([`SphSensor::wetted`]).
    pub source: &'static str,
    pub speed_m_per_s: f64,
    pub wave: String,
    /// The SPH slamming peak of the governing event (total), its discretisation uncertainty U = GCI P
    /// and convergence verdict; the analytic estimate of the same sensor and event; the hydrostatic part
    /// at the time of the SPH peak; the water-hammer upper bound of a flat keel.
    pub sph: Option<f64>,
    pub uncertainty: Option<f64>,
    pub verdict: Option<String>,
    pub analytic: Option<f64>,
    pub hydrostatic: Option<f64>,
    pub acoustic_bound: Option<f64>,
    /// Whether SPH resolves the impact ([`crate::loads::anatomy::ImpactStatus`]).
    pub impact: Option<ImpactStatus>,
    /// Time of the SPH slamming peak (s), its impulse over the impact window and rise time.
    pub peak_time_s: Option<f64>,
    /// The SPH record still rises where the impact window closes: no distinct impact peak, the SPH value
    /// is the one at the window's end ([`SphSensor::rising_at_window_end`]).
    pub rising_at_window_end: bool,
    pub impulse: Option<f64>,
    pub rise_time_s: Option<f64>,
    /// Particles across the analytic wetted half-width when the contact crosses the sensor.
    pub particles_across_wetted: Option<f64>,
    /// The spacing (m) of the keel stage the SPH value comes from, when a stage resolved the sensor.
    pub stage_dp_m: Option<f64>,
    /// The local deadrise of the sensor's SPH integration span (deg), [`SphSensor::local_deadrise_deg`].
    pub local_deadrise_deg: Option<f64>,
    /// The largest SPH value of the governing event where it comes after the impact (immersion phase) and
    /// exceeds the design value ([`SphSensor::later_load`]).
    pub later_load: Option<f64>,
    /// The hydrostatic part of `later_load` at its time.
    pub later_load_hydrostatic: Option<f64>,
}

impl DesignValue {
    /// The design value of `name` in event `e` from its decision `d`, with the details beside it.
    fn of(name: &str, e: &EventResult, d: Decision) -> Self {
        let q = e
            .sph
            .as_ref()
            .and_then(|s| s.sensors.iter().find(|q| q.name == name));
        let an = e
            .analytic
            .as_ref()
            .and_then(|a| a.sensors.iter().find(|q| q.name == name));
        let force = name == "section force";
        let sph = e.sph.as_ref();
        DesignValue {
            name: name.to_string(),
            value: d.value,
            source: d.source,
            speed_m_per_s: e.speed_m_per_s,
            wave: e.wave.clone(),
            sph: if force {
                sph.and_then(|s| s.force_slamming_peak_n_per_m)
            } else {
                q.and_then(|q| q.slamming_peak_pa)
            },
            uncertainty: d.uncertainty,
            verdict: if force {
                sph.and_then(|s| s.force_convergence.clone())
            } else {
                q.and_then(|q| q.convergence.clone())
            },
            analytic: if force {
                e.analytic.as_ref().and_then(|a| a.force_peak_n_per_m)
            } else {
                an.and_then(|a| a.peak())
            },
            hydrostatic: if force {
                sph.and_then(|s| s.force_hydrostatic_n_per_m)
            } else {
                q.and_then(|q| q.hydrostatic_pa)
            },
            acoustic_bound: an.and_then(|a| a.acoustic_bound_pa),
            impact: if force {
                sph.and_then(|s| {
                    s.force_slamming_peak_n_per_m
                        .map(|_| ImpactStatus::Resolved)
                })
            } else {
                q.and_then(|q| q.impact)
            },
            peak_time_s: if force {
                sph.and_then(|s| s.force_slamming_time_s)
            } else {
                q.and_then(|q| q.slamming_peak_time_s)
            },
            rising_at_window_end: !force && q.is_some_and(|q| q.rising_at_window_end),
            impulse: q.and_then(|q| q.slamming_impulse_pa_s),
            rise_time_s: q.and_then(|q| q.rise_time_s),
            particles_across_wetted: q.and_then(|q| q.particles_across_wetted),
            stage_dp_m: q.and_then(|q| q.stage_dp_m),
            local_deadrise_deg: q.and_then(|q| q.local_deadrise_deg),
            later_load: q.and_then(|q| q.later_load(d.value)),
            later_load_hydrostatic: q
                .filter(|q| q.later_load(d.value).is_some())
                .and_then(|q| q.largest_hydrostatic_pa),
        }
    }
}

/// Where a sensor is on its station's contour.
#[derive(Debug, Clone, Serialize)]
pub struct SensorInfo {
    pub name: String,
    /// Girth from the keel along the contour to the sensor centre (m).
    pub girth_m: f64,
    /// Width along the contour (m).
    pub width_m: f64,
}

/// Per station: design pressure per sensor and peak section force, each the maximum over the events with
/// an SPH run at that station, or over all events where none has one (analytic values).
#[derive(Debug, Clone, Serialize)]
pub struct StationResult {
    pub station: f64,
    pub x_m: f64,
    /// The station's sensors; `default_sensors` is true when the hull file has none there and these are
    /// the default panels (every 5 % of the keel-to-waterline girth, up to the deck edge).
    pub default_sensors: bool,
    pub sensors: Vec<SensorInfo>,
    /// Sensor design pressures (`value` in Pa).
    pub design_pressure_pa: Vec<DesignValue>,
    /// Section force peak (`value` in N/m).
    pub section_force_peak_n_per_m: Option<DesignValue>,
    /// Events at this station that slam by Ochi's criterion, and that emerge at all.
    pub slamming_events: usize,
    pub emerging_events: usize,
}

/// A whole assessment, written as `summary.json`.
#[derive(Debug, Clone, Serialize)]
pub struct Assessment {
    pub tool: String,
    pub provenance: Provenance,
    pub hull: String,
    pub loading: String,
    pub fidelity: String,
    pub settings: serde_json::Value,
    pub slam_threshold_velocity_m_per_s: f64,
    pub events: Vec<EventResult>,
    pub stations: Vec<StationResult>,
    /// Slam statistics of the irregular seas per speed (no design events are run for them).
    pub irregular: Vec<serde_json::Value>,
    /// Total bow slamming force and point of action per speed and regular wave ([`super::bow_force`]).
    pub bow_force_definition: &'static str,
    pub bow_force: Vec<super::bow_force::BowForce>,
    /// Published numbers and trends beside the results, for hulls that have them
    /// (`data/reference/validation.toml`): top-level `reference_case`, `comparisons`, `trend_checks`,
    /// `validation_notes`.
    #[serde(flatten)]
    pub validation: super::comparisons::Validation,
    pub failed_runs: usize,
    /// The design pressure limits checked and the violations, one line each.
    pub limits: Vec<super::limits::Limit>,
    pub limit_violations: Vec<String>,
    pub warnings: Vec<String>,
    /// Stations driven by a measured relative-motion record instead of strip theory: the file, its
    /// provenance lines and the keel entry found in it ([`super::measured`]).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub measured_forcing: Vec<super::measured::MeasuredForcing>,
}

/// The per-station design values of a list of events at the stations `at` (fraction of Lpp aft of the
/// FP, x in m from midship).
pub fn stations(events: &[EventResult], at: &[(f64, f64)]) -> Vec<StationResult> {
    at.iter()
        .map(|&(f, x)| {
            let all: Vec<&EventResult> = events
                .iter()
                .filter(|e| (e.station - f).abs() < 1e-9)
                .collect();
            // Where SPH ran at a station, its design values come from the SPH runs only: the analytic
            // values of the other events are screening estimates (on a flat keel the water-hammer bound),
            // not design pressures.
            let with_sph: Vec<&EventResult> =
                all.iter().copied().filter(|e| e.sph.is_some()).collect();
            let here = if with_sph.is_empty() { &all } else { &with_sph };
            let mut names: Vec<String> = Vec::new();
            for e in &all {
                for n in e
                    .analytic
                    .iter()
                    .flat_map(|a| a.sensors.iter().map(|s| &s.name))
                {
                    if !names.contains(n) {
                        names.push(n.clone());
                    }
                }
            }
            let best = |get: &dyn Fn(&EventResult) -> Option<Decision>, name: &str| {
                let mut out: Option<DesignValue> = None;
                for e in here {
                    if let Some(d) = get(e)
                        && out.as_ref().is_none_or(|b| {
                            d.value.is_some_and(|v| b.value.is_none_or(|bv| v > bv))
                        })
                    {
                        out = Some(DesignValue::of(name, e, d));
                    }
                }
                out
            };
            StationResult {
                station: f,
                x_m: x,
                default_sensors: false,
                sensors: Vec::new(),
                design_pressure_pa: names
                    .iter()
                    .filter_map(|n| best(&|e: &EventResult| e.sensor_design(n), n))
                    .collect(),
                section_force_peak_n_per_m: best(
                    &|e: &EventResult| e.force_design(),
                    "section force",
                ),
                slamming_events: all.iter().filter(|e| e.slam_flag == SlamFlag::Slam).count(),
                emerging_events: all
                    .iter()
                    .filter(|e| e.entry_velocity_m_per_s.is_some())
                    .count(),
            }
        })
        .collect()
}

fn num(v: Option<f64>) -> String {
    v.map_or(String::new(), crate::report::csv_number)
}

/// The tidy table: one row per station x speed x wave x sensor (one row with no sensor for a station
/// without sensors).
pub fn pressures_csv(a: &Assessment, sensors_of: &dyn Fn(f64) -> Vec<String>) -> Result<String> {
    let header: Vec<String> = [
        "station",
        "x_m",
        "speed_m_per_s",
        "wave",
        "slam_flag",
        "entry_velocity_m_per_s",
        "entry_kind",
        "flare_impact_velocity_m_per_s",
        "sensor",
        "sph_raw_peak_pa",
        "sph_filtered_peak_pa",
        "sph_filter_cutoff_hz",
        "sph_peak_time_s",
        "sph_impulse_pa_s",
        "sph_convergence",
        "sph_impact",
        "sph_slamming_peak_pa",
        "sph_slamming_peak_time_s",
        "sph_slamming_basis",
        "sph_raw_slamming_peak_pa",
        "sph_raw_convergence",
        "sph_hydrostatic_at_peak_pa",
        "sph_gci",
        "particles_across_wetted_half_width",
        "analytic_peak_pa",
        "analytic_peak_time_s",
        "analytic_impulse_pa_s",
        "sph_section_force_peak_n_per_m",
        "analytic_section_force_peak_n_per_m",
        "event_design_value_pa",
        "event_design_source",
        "failed",
        "design_event_definition",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let mut rows = Vec::new();
    for e in &a.events {
        let flag = serde_json::to_value(e.slam_flag)
            .ok()
            .and_then(|v| v.as_str().map(str::to_string))
            .unwrap_or_default();
        let mut names = sensors_of(e.station);
        if names.is_empty() {
            names.push(String::new());
        }
        for n in names {
            let s = e
                .sph
                .as_ref()
                .and_then(|r| r.sensors.iter().find(|q| q.name == n));
            let an = e
                .analytic
                .as_ref()
                .and_then(|r| r.sensors.iter().find(|q| q.name == n));
            let design = e.sensor_design(&n);
            rows.push(vec![
                crate::report::csv_number(e.station),
                crate::report::csv_number(e.x_m),
                crate::report::csv_number(e.speed_m_per_s),
                e.wave.clone(),
                flag.clone(),
                num(e.entry_velocity_m_per_s),
                e.entry_kind.clone().unwrap_or_default(),
                num(e
                    .flare_event
                    .as_ref()
                    .and_then(|f| f.impact_velocity_m_per_s)),
                n.clone(),
                num(s.map(|q| q.raw_peak_pa)),
                num(s.and_then(|q| q.filtered_peak_pa)),
                num(e.sph.as_ref().and_then(|r| r.filter_cutoff_hz)),
                num(s.map(|q| q.peak_time_s)),
                num(s.map(|q| q.impulse_pa_s)),
                s.and_then(|q| q.convergence.clone()).unwrap_or_default(),
                s.and_then(|q| q.impact)
                    .and_then(|i| serde_json::to_value(i).ok())
                    .and_then(|v| v.as_str().map(str::to_string))
                    .unwrap_or_default(),
                num(s.and_then(|q| q.slamming_peak_pa)),
                num(s.and_then(|q| q.slamming_peak_time_s)),
                s.filter(|q| q.slamming_peak_pa.is_some())
                    .map_or("", |q| {
                        if q.slamming_filtered {
                            "filtered"
                        } else {
                            "raw"
                        }
                    })
                    .to_string(),
                num(s.and_then(|q| q.raw_slamming_peak_pa)),
                s.and_then(|q| q.raw_convergence.clone())
                    .unwrap_or_default(),
                num(s.and_then(|q| q.hydrostatic_pa)),
                num(s.and_then(|q| q.gci)),
                num(s.and_then(|q| q.particles_across_wetted)),
                num(an.and_then(|q| q.peak())),
                num(an.filter(|q| q.peak().is_some()).map(|q| q.peak_time_s)),
                num(an.map(|q| q.impulse_pa_s)),
                num(e.sph.as_ref().map(|r| r.force_peak_n_per_m)),
                num(e.analytic.as_ref().and_then(|r| r.force_peak_n_per_m)),
                num(design.and_then(|d| d.value)),
                design.map_or(String::new(), |d| d.source.to_string()),
                e.failed.clone().unwrap_or_default(),
                e.design_event
                    .as_ref()
                    .map_or(String::new(), |d| d.definition.clone()),
            ]);
        }
    }
    crate::sph::output::csv_text(Some(&a.provenance), &header, &rows)
}

/// One row per speed x wave: the total bow slamming force and its point of action (see
/// [`super::bow_force::DEFINITION`], repeated as a note).
pub fn bow_force_csv(a: &Assessment) -> Result<String> {
    let header: Vec<String> = [
        "speed_m_per_s",
        "wave",
        "stations",
        "peak_sum_total_n",
        "peak_sum_x_action_m",
        "time_coincident_total_n",
        "time_coincident_x_action_m",
        "time_coincident_time_s",
        "verdict",
        "note",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let rows = a
        .bow_force
        .iter()
        .map(|b| {
            vec![
                crate::report::csv_number(b.speed_m_per_s),
                b.wave.clone(),
                b.stations.len().to_string(),
                num(b.peak_sum_total_n),
                num(b.peak_sum_x_action_m),
                num(b.time_coincident.as_ref().map(|c| c.total_n)),
                num(b.time_coincident.as_ref().map(|c| c.x_action_m)),
                num(b.time_coincident.as_ref().map(|c| c.time_s)),
                b.verdict.clone(),
                b.note.clone().unwrap_or_default(),
            ]
        })
        .collect::<Vec<_>>();
    let mut text = crate::sph::output::csv_text(Some(&a.provenance), &header, &rows)?;
    let note = format!("# note: {}\n", super::bow_force::DEFINITION);
    let at: usize = text
        .lines()
        .take_while(|l| l.starts_with('#'))
        .map(|l| l.len() + 1)
        .sum();
    text.insert_str(at, &note);
    Ok(text)
}

/// Write `summary.json` and `pressures.csv` into `dir` (atomically); returns the paths.
pub fn write(
    dir: &Path,
    a: &Assessment,
    sensors_of: &dyn Fn(f64) -> Vec<String>,
) -> Result<Vec<PathBuf>> {
    let v = serde_json::to_value(a).map_err(|e| Error::Invalid(format!("summary: {e}")))?;
    let json = serde_json::to_string_pretty(&tidy_numbers(v))
        .map_err(|e| Error::Invalid(format!("summary: {e}")))?;
    let summary = dir.join("summary.json");
    write_text_atomic(&summary, &(json + "\n"))?;
    let csv = dir.join("pressures.csv");
    write_text_atomic(&csv, &pressures_csv(a, sensors_of)?)?;
    let bow = dir.join("bow_force.csv");
    write_text_atomic(&bow, &bow_force_csv(a)?)?;
    Ok(vec![summary, csv, bow])
}

/// Write the strip-theory results of the plan as `motions.json` (for the report's motions section);
/// deterministic like summary.json.
pub fn write_motions(dir: &Path, m: &crate::seakeeping::analysis::Report) -> Result<PathBuf> {
    let v = serde_json::to_value(m).map_err(|e| Error::Invalid(format!("motions: {e}")))?;
    let json = serde_json::to_string_pretty(&tidy_numbers(v))
        .map_err(|e| Error::Invalid(format!("motions: {e}")))?;
    let path = dir.join("motions.json");
    write_text_atomic(&path, &(json + "\n"))?;
    Ok(path)
}

/// The tool name and version, as every summary gives it.
pub fn tool() -> String {
    TOOL.to_string()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assess::analytic::SensorEstimate;

    fn sph_sensor(name: &str, peak: f64, wetted: bool, still_rising: bool) -> SphSensor {
        SphSensor {
            name: name.into(),
            raw_peak_pa: peak,
            filtered_peak_pa: None,
            peak_time_s: 0.05,
            impulse_pa_s: 1.0,
            convergence: None,
            convergence_statement: None,
            wetted,
            still_rising,
            impact: Some(ImpactStatus::Resolved),
            impact_window_s: Some([0.01, 0.06]),
            slamming_peak_pa: Some(peak),
            slamming_peak_time_s: Some(0.05),
            slamming_impulse_pa_s: Some(1.0),
            slamming_filtered: false,
            raw_slamming_peak_pa: Some(peak),
            raw_convergence: None,
            rising_at_window_end: false,
            rise_time_s: Some(0.01),
            hydrostatic_pa: Some(10.0),
            largest_phase: Some(Phase::Impact),
            largest_hydrostatic_pa: None,
            gci: None,
            spread: None,
            particles_across_wetted: Some(12.0),
            stage_dp_m: None,
            local_deadrise_deg: Some(30.0),
        }
    }

    fn event() -> EventResult {
        let analytic = Estimate {
            force_peak_n_per_m: Some(300.0),
            force_peak_time_s: Some(0.03),
            wagner_force_peak_n_per_m: None,
            sensors: ["K1", "K2", "K3"]
                .iter()
                .map(|n| SensorEstimate {
                    name: (*n).into(),
                    peak_pa: 3750.0,
                    peak_time_s: 0.02,
                    impulse_pa_s: 2.0,
                    acoustic_bound_pa: None,
                    uncorrected_peak_pa: None,
                    no_peak_after_start: false,
                })
                .collect(),
            notes: Vec::new(),
            force_history: Vec::new(),
        };
        let sph = SphRecord {
            key: "k".into(),
            dp_m: 0.0015,
            filter_cutoff_hz: None,
            filter_rule: None,
            force_peak_n_per_m: 250.0,
            force_peak_time_s: 0.05,
            force_convergence: None,
            force_slamming_peak_n_per_m: Some(250.0),
            force_slamming_time_s: Some(0.05),
            force_hydrostatic_n_per_m: Some(5.0),
            force_gci: None,
            force_spread: None,
            force_convergence_statement: None,
            force_slamming_filtered: false,
            force_raw_slamming_peak_n_per_m: Some(250.0),
            sensors: vec![
                sph_sensor("K1", 2780.0, true, false),
                sph_sensor("K2", 1120.0, true, true),
                sph_sensor("K3", 47.0, false, false),
            ],
            stopped_early: None,
            air: None,
            warnings: Vec::new(),
        };
        EventResult {
            station: 0.1,
            x_m: 1.2,
            speed_m_per_s: 1.6,
            wave: "w".into(),
            slam_flag: SlamFlag::Slam,
            entry_velocity_m_per_s: Some(1.76),
            entry_kind: None,
            flare_event: None,
            design_event: None,
            analytic: Some(analytic),
            sph: Some(sph),
            run_folder: None,
            failed: None,
            warnings: Vec::new(),
        }
    }

    #[test]
    fn a_sensor_the_sph_did_not_wet_takes_the_analytic_design_value_and_says_so() {
        let mut e = event();
        if let Some(s) = &mut e.sph {
            s.sensors[0].convergence = Some("converged".into());
            s.sensors[0].gci = Some(0.01);
        }
        let (v, src) = e.sensor_peak("K1").unwrap();
        assert!((v - 2780.0 * 1.01).abs() < 1e-9);
        assert_eq!(src, "sph (converged)");
        assert_eq!(e.sensor_peak("K3"), Some((3750.0, "analytic (dry in SPH)")));
        let st = stations(std::slice::from_ref(&e), &[(0.1, 1.2)]);
        let k3 = st[0]
            .design_pressure_pa
            .iter()
            .find(|d| d.name == "K3")
            .unwrap();
        assert_eq!(k3.source, "analytic (dry in SPH)");
        let mut r = e.sph.clone().unwrap();
        r.sensors[1].impact = Some(ImpactStatus::InTransient);
        let w = sensor_warnings(&r, e.analytic.as_ref());
        assert_eq!(w.len(), 2, "{w:?}");
        assert!(w[0].starts_with("sensor K3") && w[0].contains("3.75 kPa"));
        assert!(w[1].starts_with("sensors K2") && w[1].contains("contact transient"));
    }
}
