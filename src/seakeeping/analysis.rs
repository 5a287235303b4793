//! One seakeeping analysis of a ship in a sea-state file: natural periods, RAOs per speed, relative motion
//! and keel entry in the regular waves, Ochi slam statistics in the irregular seas and the operability
//! limit. This is what `slamtool motions` prints; the CLI only formats it.

use serde::Serialize;

use super::ShipModel;
use super::rao::{self, RaoRow};
use super::relative_motion::{self, KeelEntry};
use super::section::{HalfSection, SectionMethod};
use super::slamming::{self, Operability, ResponseSpectrum, SampledSpectrum, SlamStatistics};
use super::strip_table::{StripTable, TableOrSolve};
use super::strip_theory::{self, SectionSolutions, StripSettings};
use crate::error::{Error, Result};
use crate::sea::{IrregularSea, RegularWave};

/// A station where relative motion and slamming are evaluated.
#[derive(Debug, Clone, Serialize)]
pub struct Station {
    #[serde(rename = "station")]
    pub aft_of_fp: f64,
    #[serde(rename = "x_m")]
    pub x: f64,
    /// Keel depth below the local calm waterline (m); negative for a keel above it (a dry station, such as
    /// the forefoot under a raked stem or a rising keel), which only the waves' relative motion wets.
    #[serde(rename = "draft_m")]
    pub draft: f64,
    /// Keel-to-deck height of the section (m): the entry profile stops at this depth.
    #[serde(rename = "height_m")]
    pub height: f64,
    /// Slope dz_k/dx of the keel above the local calm waterline (x forward; positive for a keel rising
    /// towards the bow or trim by the stern), for the keel-slope term U dz_k/dx of the entry velocity
    /// ([`super::entry_definitions`]); 0 unless set.
    #[serde(rename = "keel_slope")]
    pub keel_slope: f64,
}

impl Station {
    /// A station from its wetted half section (waterline frame) and the keel-to-deck height.
    pub fn new(lpp: f64, aft_of_fp: f64, wetted: &HalfSection, height: f64) -> Self {
        Self {
            aft_of_fp,
            x: 0.5 * lpp - aft_of_fp * lpp,
            draft: wetted.draft(),
            height,
            keel_slope: 0.0,
        }
    }

    /// A station whose keel is above the local calm waterline by `clearance` (m, > 0): its draft is
    /// -clearance, and the water reaches its keel only when the relative motion s falls below it.
    pub fn dry(lpp: f64, aft_of_fp: f64, clearance: f64, height: f64) -> Self {
        Self {
            aft_of_fp,
            x: 0.5 * lpp - aft_of_fp * lpp,
            draft: -clearance,
            height,
            keel_slope: 0.0,
        }
    }
}

/// What to compute.
#[derive(Debug, Clone)]
pub struct Request {
    pub speeds: Vec<f64>,
    pub lambda_over_l: Vec<f64>,
    pub regular: Vec<RegularWave>,
    pub irregular: Vec<IrregularSea>,
    pub stations: Vec<Station>,
    pub swell_up: f64,
    /// Add the keel-slope term U dz_k/dx (each station's `keel_slope`) to the downward velocity of the
    /// keel-entry profiles ([`RegularStation::add_steady_velocity`]) and of the irregular seas' slams
    /// ([`slamming::SlamStatistics::with_steady_velocity`]); off by default.
    pub keel_slope_term: bool,
    pub slam_probability_limit: f64,
    pub method: SectionMethod,
    /// Samples per spectrum for the irregular-sea statistics.
    pub spectrum_samples: usize,
    /// Samples per keel-entry velocity profile.
    pub profile_samples: usize,
    /// Spacing in ln w of the frequency table the sectional solutions are interpolated from
    /// ([`super::strip_table`]); `None` solves every encounter frequency directly. At 0.1 the RAOs differ
    /// from direct solves by about 1e-4 relative (tests/seakeeping_strip_table.rs). The natural-period
    /// iterations use the table too where their iterates fall inside it (about 1e-5 on the periods).
    pub frequency_table_spacing: Option<f64>,
    /// Water depth if the sea file gives one (the theory here is for deep water: a warning is issued where
    /// the depth is below half a wavelength of the waves analysed).
    pub water_depth: Option<f64>,
}

impl Request {
    /// The request for a sea-state file at `speeds` (m/s) and `stations`, with the defaults of
    /// `slamtool motions`: Frank close-fit sections, no swell-up, the default slam-probability limit, 30
    /// samples per spectrum, 41 per entry profile, the frequency table at 0.1 in ln w, and no RAO table
    /// (set `lambda_over_l` for one).
    pub fn for_sea(sea: &crate::sea::SeaState, speeds: Vec<f64>, stations: Vec<Station>) -> Self {
        Self {
            speeds,
            lambda_over_l: Vec::new(),
            regular: sea.regular.clone(),
            irregular: sea.irregular.clone(),
            stations,
            swell_up: 1.0,
            keel_slope_term: false,
            slam_probability_limit: slamming::DEFAULT_SLAM_PROBABILITY_LIMIT,
            method: SectionMethod::FrankCloseFit,
            spectrum_samples: 30,
            profile_samples: 41,
            frequency_table_spacing: Some(0.1),
            water_depth: sea.water_depth_m,
        }
    }
}

#[derive(Debug, Clone, Serialize)]
pub struct RegularResult {
    pub wave: String,
    pub height_m: f64,
    #[serde(rename = "wave_frequency_rad_per_s")]
    pub omega0: f64,
    #[serde(rename = "encounter_frequency_rad_per_s")]
    pub omega_e: f64,
    #[serde(rename = "heave_amplitude_m")]
    pub heave_m: f64,
    #[serde(rename = "pitch_amplitude_deg")]
    pub pitch_deg: f64,
    pub stations: Vec<RegularStation>,
}

#[derive(Debug, Clone, Serialize)]
pub struct RegularStation {
    #[serde(rename = "station")]
    pub aft_of_fp: f64,
    #[serde(rename = "x_m")]
    pub x: f64,
    #[serde(rename = "draft_m")]
    pub draft: f64,
    /// Relative motion amplitude (m) in this wave.
    #[serde(rename = "relative_motion_amplitude_m")]
    pub relative_motion_m: f64,
    /// Relative velocity amplitude (m/s) in this wave.
    #[serde(rename = "relative_velocity_amplitude_m_per_s")]
    pub relative_velocity_m_s: f64,
    pub keel_entry: Option<KeelEntry>,
    /// Relative motion and velocity per unit wave amplitude (for the events of `assess`; not written).
    #[serde(skip)]
    pub relative_motion: relative_motion::RelativeMotion,
}

impl RegularStation {
    /// The station `s` in a regular wave of amplitude `zeta_a` and encounter frequency `omega_e`, from its
    /// relative motion per unit amplitude `rm`; the keel-entry profile (if the keel emerges) has
    /// `profile_samples` samples.
    pub fn new(
        s: &Station,
        rm: relative_motion::RelativeMotion,
        omega_e: f64,
        zeta_a: f64,
        profile_samples: usize,
    ) -> Self {
        RegularStation {
            aft_of_fp: s.aft_of_fp,
            x: s.x,
            draft: s.draft,
            relative_motion_m: rm.motion.norm() * zeta_a,
            relative_velocity_m_s: rm.velocity.norm() * zeta_a,
            keel_entry: relative_motion::keel_entry(
                &rm,
                omega_e,
                zeta_a,
                s.draft,
                s.height,
                profile_samples,
            ),
            relative_motion: rm,
        }
    }

    /// Add a steady downward velocity `v` (m/s; the keel-slope term U dz_k/dx) to the keel-entry velocity
    /// and its profile ([`relative_motion::KeelEntry::add_steady_velocity`]). A station whose total entry
    /// velocity is not downward (a keel that falls towards the bow, faster than the water rises onto it)
    /// has no keel entry.
    pub fn add_steady_velocity(&mut self, v: f64) {
        if let Some(k) = self.keel_entry.as_mut() {
            k.add_steady_velocity(v);
            if k.entry_velocity <= 0.0 {
                self.keel_entry = None;
            }
        }
    }
}

#[derive(Debug, Clone, Serialize)]
pub struct IrregularResult {
    pub sea: String,
    pub hs_m: f64,
    pub tp_s: f64,
    /// Exposure for the extreme values (h): the file's duration, or 1 h.
    pub duration_h: f64,
    pub stations: Vec<SlamStatistics>,
    /// Most probable largest entry velocity in the expected number of slams over the duration (m/s).
    #[serde(rename = "extreme_entry_velocity_m_per_s")]
    pub extreme_velocity_m_s: Vec<Option<f64>>,
    /// Relative motion and velocity spectra at the stations (plot data).
    pub response_spectra: Vec<ResponseSpectrum>,
}

#[derive(Debug, Clone, Serialize)]
pub struct SpeedResult {
    #[serde(rename = "speed_m_per_s")]
    pub speed_m_s: f64,
    pub froude_number: f64,
    pub raos: Vec<RaoRow>,
    pub regular: Vec<RegularResult>,
    pub irregular: Vec<IrregularResult>,
}

#[derive(Debug, Clone, Serialize)]
pub struct OperabilityResult {
    pub sea: String,
    pub operability: Operability,
}

#[derive(Debug, Clone, Serialize)]
pub struct Report {
    pub method: SectionMethod,
    pub strip_stations: usize,
    pub lpp_m: f64,
    pub mass_kg: f64,
    /// Uncoupled natural periods at zero speed (pitch about midship).
    pub heave_natural_period_s: f64,
    pub pitch_natural_period_s: f64,
    /// Natural periods of the coupled heave-pitch modes at zero speed (what a free model shows).
    pub heave_mode_period_s: f64,
    pub pitch_mode_period_s: f64,
    #[serde(rename = "slam_threshold_velocity_m_per_s")]
    pub slam_threshold_velocity_m_s: f64,
    pub limitation: &'static str,
    /// Conditions outside the range of validity of the method.
    pub warnings: Vec<String>,
    pub speeds: Vec<SpeedResult>,
    pub operability: Vec<OperabilityResult>,
}

/// The known limitation every report states.
pub const PITCH_DAMPING_NOTE: &str = "strip theory over-predicts pitch damping at forward speed \
(Journee 1992, Wigley hulls): pitch near resonance at speed is under-predicted";

/// Run the analysis.
pub fn run(model: &ShipModel, req: &Request) -> Result<Report> {
    model.validate()?;
    if req.speeds.is_empty() {
        return Err(Error::Invalid("no speeds to analyse".into()));
    }
    let settings = StripSettings {
        method: req.method,
        ..StripSettings::default()
    };
    let mut warnings = Vec::new();
    let fn_max = req.speeds.iter().fold(0.0f64, |a, &u| a.max(u)) / (model.g * model.lpp).sqrt();
    if fn_max > 0.4 {
        warnings.push(format!(
            "Froude number up to {fn_max:.2}: strip theory is a low-to-moderate-speed theory (Fn <= 0.4); \
             check that speeds and hull are at the same scale"
        ));
    }
    if let Some(d) = req.water_depth {
        let longest = req
            .lambda_over_l
            .iter()
            .map(|r| r * model.lpp)
            .chain(req.regular.iter().map(|w| w.wavelength_m))
            .fold(0.0f64, f64::max);
        if d < 0.5 * longest {
            warnings.push(format!(
                "water depth {d} m is below half the longest wavelength analysed ({longest:.2} m): \
                 the deep-water theory used here over-predicts the wave length and under-predicts the motions"
            ));
        }
    }
    // The sampled spectra (their frequencies decide the table range).
    let spectra: Vec<SampledSpectrum> = req
        .irregular
        .iter()
        .map(|sea| {
            let wp = sea.spectrum.peak_frequency();
            SampledSpectrum::from_fn(
                |w| sea.spectrum.density(w),
                0.4 * wp,
                3.5 * wp,
                req.spectrum_samples,
            )
        })
        .collect::<Result<_>>()?;
    let rao_omegas: Vec<f64> = req
        .lambda_over_l
        .iter()
        .map(|&r| rao::omega_of_lambda_over_l(r, model.lpp, model.g))
        .collect();
    let table = match req.frequency_table_spacing {
        None => None,
        Some(d) => {
            let mut needed = Vec::new();
            for &u in &req.speeds {
                let wave_omegas = rao_omegas
                    .iter()
                    .chain(req.regular.iter().map(|w| &w.omega))
                    .chain(spectra.iter().flat_map(|sp| sp.omega.iter()));
                needed
                    .extend(wave_omegas.map(|&w| strip_theory::encounter_frequency(w, u, model.g)));
            }
            Some(StripTable::covering(model, &needed, d, &settings)?)
        }
    };
    let sections: &dyn SectionSolutions = match &table {
        Some(t) => t,
        None => &settings,
    };
    let periods_from: &dyn SectionSolutions = match &table {
        Some(table) => &TableOrSolve {
            table,
            settings: &settings,
        },
        None => &settings,
    };
    let (th, tp) = strip_theory::natural_periods(model, periods_from)?;
    let (th_mode, tp_mode) = strip_theory::natural_mode_periods(model, periods_from)?;
    let mut speeds = Vec::new();
    for &u in &req.speeds {
        let raos = rao::responses(model, u, &rao_omegas, sections)?
            .iter()
            .map(|r| RaoRow::from_response(r, model.lpp))
            .collect();
        let mut regular = Vec::new();
        for w in &req.regular {
            let r = strip_theory::respond(model, w.omega, u, sections)?;
            let za = w.amplitude();
            let mut st = Vec::new();
            for s in &req.stations {
                let rm = relative_motion::at_station(&r, s.x, req.swell_up)?;
                let mut station = RegularStation::new(s, rm, r.omega_e, za, req.profile_samples);
                if req.keel_slope_term {
                    station.add_steady_velocity(u * s.keel_slope);
                }
                st.push(station);
            }
            regular.push(RegularResult {
                wave: w.name.clone(),
                height_m: w.height_m,
                omega0: w.omega,
                omega_e: r.omega_e,
                heave_m: r.heave.norm() * za,
                pitch_deg: (r.pitch.norm() * za).to_degrees(),
                stations: st,
            });
        }
        let mut irregular = Vec::new();
        for (sea, spec) in req.irregular.iter().zip(&spectra) {
            let pts: Vec<(f64, f64)> = req.stations.iter().map(|s| (s.x, s.draft)).collect();
            let xs: Vec<f64> = pts.iter().map(|p| p.0).collect();
            let responses =
                slamming::response_spectra(model, spec, u, &xs, req.swell_up, sections)?;
            let mut stats = slamming::statistics_from_spectra(model, &responses, &pts);
            if req.keel_slope_term {
                for (st, s) in stats.iter_mut().zip(&req.stations) {
                    *st = st.with_steady_velocity(u * s.keel_slope);
                }
            }
            let duration_h = sea.duration_h.unwrap_or(1.0);
            let extreme = stats
                .iter()
                .map(|s| {
                    let n = s.slams_per_hour * duration_h;
                    (n >= 1.0).then(|| s.most_probable_extreme_velocity(n))
                })
                .collect();
            irregular.push(IrregularResult {
                sea: sea.name.clone(),
                hs_m: sea.spectrum.hs(),
                tp_s: sea.spectrum.peak_period(),
                duration_h,
                stations: stats,
                extreme_velocity_m_s: extreme,
                response_spectra: responses,
            });
        }
        speeds.push(SpeedResult {
            speed_m_s: u,
            froude_number: u / (model.g * model.lpp).sqrt(),
            raos,
            regular,
            irregular,
        });
    }
    let mut operability = Vec::new();
    if req.speeds.windows(2).all(|w| w[1] > w[0]) {
        for (i, sea) in req.irregular.iter().enumerate() {
            let p: Vec<f64> = speeds
                .iter()
                .map(|s| {
                    s.irregular[i]
                        .stations
                        .iter()
                        .map(|t| t.probability)
                        .fold(0.0, f64::max)
                })
                .collect();
            operability.push(OperabilityResult {
                sea: sea.name.clone(),
                operability: slamming::operability_limit(
                    &req.speeds,
                    &p,
                    req.slam_probability_limit,
                )?,
            });
        }
    }
    Ok(Report {
        method: req.method,
        strip_stations: model.stations.len(),
        lpp_m: model.lpp,
        mass_kg: model.mass,
        heave_natural_period_s: th,
        pitch_natural_period_s: tp,
        heave_mode_period_s: th_mode,
        pitch_mode_period_s: tp_mode,
        slam_threshold_velocity_m_s: slamming::threshold_velocity(model.g, model.lpp),
        limitation: PITCH_DAMPING_NOTE,
        warnings,
        speeds,
        operability,
    })
}
