//! Strip theory for a sweep, shared by the cases of one hull variant. Building the sectional solutions of
//! a hull (Frank close-fit at each strip and encounter frequency) is the costly part of an analytic case;
//! the cases of one variant differ only in speed and waves, so one [`StripTable`] per variant serves them
//! all. The table covers the encounter frequencies of *every* case of that variant in the sweep file (not
//! only those of one shard or of the cases still to run), so a case's result does not depend on sharding
//! or on resuming; its range is part of the case's cache key. From the table, each case takes the same
//! steps as `assess::plan` (through `seakeeping::analysis`): the heave-pitch response in each regular
//! wave, relative motion and keel entry at the stations, one water-entry event per emerging station, and
//! Ochi's slam statistics in each irregular sea. Natural periods and RAO tables, which an assessment
//! prints, are not needed and not computed.

use crate::assess::design_event;
use crate::assess::plan::{self, Event};
use crate::error::Result;
use crate::hull::{Hull, LoadingCondition};
use crate::impact;
use crate::report::sanity::SlamFlag;
use crate::sea::{IrregularSea, RegularWave};
use crate::seakeeping::ShipModel;
use crate::seakeeping::analysis::{RegularStation, Station};
use crate::seakeeping::relative_motion;
use crate::seakeeping::slamming::{self, SampledSpectrum, SlamStatistics};
use crate::seakeeping::strip_table::StripTable;
use crate::seakeeping::strip_theory::{self, StripSettings};

/// Grid spacing of the table in ln ω, as `slamtool motions` and `assess` use it.
pub const TABLE_SPACING: f64 = 0.1;
/// Samples per spectrum and per entry profile, as `assess` uses them.
const SPECTRUM_SAMPLES: usize = 30;
const PROFILE_SAMPLES: usize = 41;

/// The sampled spectrum of an irregular sea, as `seakeeping::analysis` samples it (0.4 to 3.5 ω_p).
pub fn sampled(sea: &IrregularSea) -> Result<SampledSpectrum> {
    let wp = sea.spectrum.peak_frequency();
    SampledSpectrum::from_fn(
        |w| sea.spectrum.density(w),
        0.4 * wp,
        3.5 * wp,
        SPECTRUM_SAMPLES,
    )
}

/// The encounter frequencies a case needs at `speed`.
pub fn needed(speed: f64, regular: &[RegularWave], irregular: &[IrregularSea]) -> Result<Vec<f64>> {
    let mut out = Vec::new();
    for w in regular {
        out.push(strip_theory::encounter_frequency(
            w.omega,
            speed,
            crate::sea::G,
        ));
    }
    for s in irregular {
        for &w in &sampled(s)?.omega {
            out.push(strip_theory::encounter_frequency(w, speed, crate::sea::G));
        }
    }
    Ok(out)
}

/// The strip theory of a ship model: shared by every hull variant with the same underwater form and mass
/// properties (a flare change above the waterline leaves it as it is).
pub struct StripModel {
    pub model: ShipModel,
    pub table: StripTable,
    /// Ochi's threshold velocity 0.093 sqrt(g Lpp).
    pub threshold: f64,
}

impl StripModel {
    /// The table of `model` over the frequency band `band` (lowest, highest).
    pub fn new(model: ShipModel, band: (f64, f64)) -> Result<Self> {
        let table = StripTable::covering(
            &model,
            &[band.0, band.1],
            TABLE_SPACING,
            &StripSettings::default(),
        )?;
        Ok(Self {
            threshold: slamming::threshold_velocity(model.g, model.lpp),
            model,
            table,
        })
    }
}

/// A content key of a ship model (its strips, mass properties and settings): variants with equal keys
/// share their [`StripModel`].
pub fn model_key(model: &ShipModel) -> String {
    crate::provenance::sha256_hex(format!("{model:?}").as_bytes())
}

/// A hull variant ready for its cases: its strip theory and its seakeeping stations.
pub struct VariantModel<'a> {
    pub strip: &'a StripModel,
    pub stations: Vec<Station>,
    /// The sensors of each station: the hull's, or the default panels where it has none (as `assess`).
    pub sensors: Vec<Vec<crate::sph::sensors::SensorSpec>>,
    /// Add the keel-slope term U dz_k/dx to the keel entries and slams (`assess::keel_slope`).
    pub keel_slope_term: bool,
}

impl<'a> VariantModel<'a> {
    /// The seakeeping stations of `hull` in `loading` at `at` (fractions of Lpp aft of the FP), with or
    /// without the keel-slope term.
    pub fn new(
        strip: &'a StripModel,
        hull: &Hull,
        loading: &LoadingCondition,
        at: &[f64],
        keel_slope_term: bool,
    ) -> Result<Self> {
        let stations = at
            .iter()
            .map(|&f| impact::seakeeping_station(hull, loading, f))
            .collect::<Result<Vec<_>>>()?;
        let sensors = stations
            .iter()
            .map(|st| {
                let given = impact::station_sensors(hull, st.x);
                if given.is_empty() {
                    impact::default_sensors::default_sensors(hull, loading, st.x)
                } else {
                    Ok(given)
                }
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(Self {
            strip,
            stations,
            sensors,
            keel_slope_term,
        })
    }

    /// The events of one speed in the regular waves, in the order wave, station (as `assess::plan`).
    pub fn events(&self, hull: &Hull, speed: f64, waves: &[RegularWave]) -> Result<Vec<Event>> {
        let mut events = Vec::new();
        for w in waves {
            let r = strip_theory::respond(&self.strip.model, w.omega, speed, &self.strip.table)?;
            let za = w.amplitude();
            for (s, sensors) in self.stations.iter().zip(&self.sensors) {
                let rm = relative_motion::at_station(&r, s.x, 1.0)?;
                let mut st = RegularStation::new(s, rm, r.omega_e, za, PROFILE_SAMPLES);
                if self.keel_slope_term {
                    st.add_steady_velocity(speed * s.keel_slope);
                }
                events.push(plan::station_event(
                    &st,
                    &plan::Wave {
                        name: &w.name,
                        omega0: w.omega,
                        omega_e: r.omega_e,
                        amplitude_m: za,
                    },
                    speed,
                    SlamFlag::of(&st, self.strip.threshold),
                    (hull.section_at(st.x)?.points.clone(), s.height),
                    sensors.clone(),
                ));
            }
        }
        Ok(events)
    }

    /// The design events of one speed in an irregular sea whose stations' slam statistics are `stats`,
    /// made as `assess` makes them ([`design_event::sea_events`], the most probable largest entry
    /// velocity of the exposure), with the response at the spectral peak from this model's table; lines
    /// on stations without one go to `notes`, oversized profile waves to `oversized`.
    pub(crate) fn design_events(
        &self,
        hull: &Hull,
        speed: f64,
        sea: &IrregularSea,
        stats: &[SlamStatistics],
        notes: &mut Vec<String>,
        oversized: &mut Vec<design_event::Oversized>,
    ) -> Result<Vec<Event>> {
        let r = strip_theory::respond(
            &self.strip.model,
            sea.spectrum.peak_frequency(),
            speed,
            &self.strip.table,
        )?;
        let sensors_at = |f: f64| {
            self.stations
                .iter()
                .zip(&self.sensors)
                .find(|(s, _)| (s.aft_of_fp - f).abs() < 1e-9)
                .map(|(_, q)| q.clone())
                .unwrap_or_default()
        };
        let at = design_event::SeaSpeed {
            speed_m_s: speed,
            sea,
            // as `seakeeping::analysis` takes it
            exposure_h: sea.duration_h.unwrap_or(1.0),
            stats,
            response: &r,
        };
        design_event::sea_events(
            hull,
            &self.stations,
            &sensors_at,
            &at,
            design_event::Basis::MostProbableLargest,
            notes,
            oversized,
        )
    }

    /// Ochi's slam statistics at the stations for one speed in an irregular sea.
    pub fn statistics(&self, speed: f64, sea: &IrregularSea) -> Result<Vec<SlamStatistics>> {
        let spec = sampled(sea)?;
        let xs: Vec<f64> = self.stations.iter().map(|s| s.x).collect();
        let pts: Vec<(f64, f64)> = self.stations.iter().map(|s| (s.x, s.draft)).collect();
        let responses = slamming::response_spectra(
            &self.strip.model,
            &spec,
            speed,
            &xs,
            1.0,
            &self.strip.table,
        )?;
        let mut stats = slamming::statistics_from_spectra(&self.strip.model, &responses, &pts);
        // as `seakeeping::analysis::run` does
        if self.keel_slope_term {
            for (st, s) in stats.iter_mut().zip(&self.stations) {
                *st = st.with_steady_velocity(speed * s.keel_slope);
            }
        }
        Ok(stats)
    }
}
