//! Sea states: regular head waves and irregular seas (wave spectra), ship speeds and water depth, read from
//! `sea_state.toml` with located validation; linear wave kinematics and encounter frequency.

mod schema;
pub mod spectrum;
pub mod waves;

use std::path::{Path, PathBuf};

use serde::Serialize;
use toml::Spanned;

pub use spectrum::{Spectrum, SpectrumSummary};
pub use waves::{G, encounter_frequency, frequency_from_wavelength, wave_number};

use crate::error::{InputError, Result};
use crate::input::{SourceText, in_range, num, positive};
use schema::{IrregularRaw, RegularRaw, SeaFile, SpectrumKind};

/// Knot in m/s.
pub const KNOT: f64 = 1852.0 / 3600.0;

/// Steepest regular wave accepted: H/λ = 1/7 (Michell 1893 deep-water breaking limit).
pub const BREAKING_STEEPNESS: f64 = 1.0 / 7.0;

/// Wave heights (and H_s) accepted, m: from 1 mm (below that surface tension governs) to 40 m (higher than
/// any wave measured; the Draupner wave was 25.6 m).
const HEIGHT_RANGE: (f64, f64) = (1e-3, 40.0);
/// Wave periods accepted (T, T_p, T_z), s: gravity waves from 0.1 s (a 16 mm wave) to 60 s (long swell).
const PERIOD_RANGE: (f64, f64) = (0.1, 60.0);
/// Wavelengths accepted, m: those of the deep-water waves with the periods above.
const WAVELENGTH_RANGE: (f64, f64) = (0.015, 6000.0);
/// Deepest water, m (the deepest ocean trench is about 11 km).
const DEPTH_MAX: f64 = 11_000.0;

/// Breaking steepness limit in water of depth h: H/λ = (1/7) tanh(k h) (Miche 1944; 1/7 in deep water,
/// H ≈ 0.9 h in shallow water).
pub fn breaking_steepness(k: f64, depth: Option<f64>) -> f64 {
    BREAKING_STEEPNESS * depth.map_or(1.0, |h| (k * h).tanh())
}

/// A regular (Airy) head wave.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct RegularWave {
    pub name: String,
    /// Wave height (crest to trough), m.
    pub height_m: f64,
    /// Wave frequency ω, rad/s.
    #[serde(rename = "wave_frequency_rad_per_s")]
    pub omega: f64,
    /// Period, s.
    pub period_s: f64,
    /// Wavelength, m.
    pub wavelength_m: f64,
}

impl RegularWave {
    /// Amplitude ζ_a = H/2.
    pub fn amplitude(&self) -> f64 {
        0.5 * self.height_m
    }

    /// Wave steepness H/λ.
    pub fn steepness(&self) -> f64 {
        self.height_m / self.wavelength_m
    }
}

/// An irregular sea: a spectrum and, optionally, the exposure time used for slam statistics.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct IrregularSea {
    pub name: String,
    pub spectrum: Spectrum,
    pub duration_h: Option<f64>,
}

/// Ship speeds as the file gives them; Froude numbers need the hull length to become speeds.
#[derive(Debug, Clone, PartialEq, Serialize)]
#[serde(tag = "unit", content = "values", rename_all = "snake_case")]
pub enum Speeds {
    MetresPerSecond(Vec<f64>),
    FroudeNumbers(Vec<f64>),
}

impl Speeds {
    /// Speeds in m/s for a ship of length `lpp` (U = Fn sqrt(g L)).
    pub fn resolve(&self, lpp: f64) -> Vec<f64> {
        match self {
            Speeds::MetresPerSecond(v) => v.clone(),
            Speeds::FroudeNumbers(f) => f.iter().map(|fn_| fn_ * (G * lpp).sqrt()).collect(),
        }
    }
}

/// A validated sea-state file.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct SeaState {
    pub name: String,
    pub description: Option<String>,
    /// Water depth, m; None for deep water.
    pub water_depth_m: Option<f64>,
    pub speeds: Speeds,
    pub regular: Vec<RegularWave>,
    pub irregular: Vec<IrregularSea>,
    #[serde(skip)]
    pub source: PathBuf,
}

impl SeaState {
    /// Read and validate a sea-state file.
    pub fn from_file(path: &Path) -> Result<Self> {
        Self::from_source(&SourceText::read(path)?)
    }

    /// Validate a sea state from text.
    pub fn from_source(src: &SourceText) -> Result<Self> {
        let raw: SeaFile = src.parse_toml()?;
        if raw.name.get_ref().trim().is_empty() {
            return Err(src.error(&raw.name, "name must not be empty").into());
        }
        let depth = match &raw.water_depth_m {
            Some(d) => {
                let h = positive(src, d, "water_depth_m")?;
                if h > DEPTH_MAX {
                    return Err(src
                        .error(
                            d,
                            format!(
                                "water_depth_m = {} m is deeper than any ocean ({DEPTH_MAX} m); leave it out for deep water",
                                num(h)
                            ),
                        )
                        .into());
                }
                Some(h)
            }
            None => None,
        };
        if let Some(h) = &raw.heading
            && h.get_ref() != "head"
        {
            return Err(src
                .error(h, format!("heading '{}' is not supported: slamtool computes head seas only (heading = \"head\")", h.get_ref()))
                .into());
        }
        let speeds = speeds(src, &raw)?;
        let mut regular = Vec::new();
        for (i, r) in raw.regular.iter().enumerate() {
            regular.push(regular_wave(src, r, depth, i)?);
        }
        let mut irregular = Vec::new();
        for (i, r) in raw.irregular.iter().enumerate() {
            irregular.push(irregular_sea(src, r, depth, i)?);
        }
        let mut names = std::collections::HashSet::new();
        let given = raw
            .regular
            .iter()
            .map(|r| &r.get_ref().name)
            .chain(raw.irregular.iter().map(|r| &r.get_ref().name))
            .flatten();
        for n in given {
            let t = n.get_ref().trim();
            if t.is_empty() {
                return Err(src.error(n, "a wave name must not be empty").into());
            }
            if !names.insert(t) {
                return Err(src
                    .error(n, format!("wave name '{t}' is used twice"))
                    .into());
            }
        }
        if regular.is_empty() && irregular.is_empty() {
            return Err(src
                .error_at(
                    0..0,
                    "no waves: add [[regular]] waves or [[irregular]] seas",
                )
                .into());
        }
        Ok(Self {
            name: crate::output_policy::escape_control(raw.name.get_ref().trim()),
            description: raw.description,
            water_depth_m: depth,
            speeds,
            regular,
            irregular,
            source: src.path.clone(),
        })
    }
}

fn speeds(src: &SourceText, raw: &SeaFile) -> Result<Speeds, InputError> {
    let given: Vec<(&str, &Spanned<Vec<Spanned<f64>>>)> = [
        ("speeds_m_s", &raw.speeds_m_s),
        ("speeds_kn", &raw.speeds_kn),
        ("froude_numbers", &raw.froude_numbers),
    ]
    .into_iter()
    .filter_map(|(n, v)| v.as_ref().map(|v| (n, v)))
    .collect();
    let (name, list) = match given.as_slice() {
        [one] => *one,
        [] => {
            return Err(src.error_at(
                0..0,
                "no ship speeds: give speeds_m_s, speeds_kn or froude_numbers",
            ));
        }
        [_, second, ..] => {
            return Err(src.error(
                second.1,
                "give only one of speeds_m_s, speeds_kn, froude_numbers",
            ));
        }
    };
    if list.get_ref().is_empty() {
        return Err(src.error(list, format!("{name} is empty")));
    }
    let upper = if name == "froude_numbers" { 1.0 } else { 100.0 };
    let mut vals = Vec::new();
    for v in list.get_ref() {
        vals.push(in_range(src, v, 0.0, upper, name)?);
    }
    Ok(match name {
        "speeds_kn" => Speeds::MetresPerSecond(vals.iter().map(|v| v * KNOT).collect()),
        "froude_numbers" => Speeds::FroudeNumbers(vals),
        _ => Speeds::MetresPerSecond(vals),
    })
}

fn regular_wave(
    src: &SourceText,
    r: &Spanned<RegularRaw>,
    depth: Option<f64>,
    i: usize,
) -> Result<RegularWave, InputError> {
    let w = r.get_ref();
    let height = bounded(src, &w.height_m, HEIGHT_RANGE, "height_m", "m")?;
    let (omega, lambda) = match (&w.period_s, &w.wavelength_m) {
        (Some(t), None) => {
            let t = bounded(src, t, PERIOD_RANGE, "period_s", "s")?;
            let omega = 2.0 * std::f64::consts::PI / t;
            (
                omega,
                2.0 * std::f64::consts::PI / wave_number(omega, depth),
            )
        }
        (None, Some(l)) => {
            let l = bounded(src, l, WAVELENGTH_RANGE, "wavelength_m", "m")?;
            (frequency_from_wavelength(l, depth), l)
        }
        (Some(t), Some(_)) => {
            return Err(src.error(t, "give either period_s or wavelength_m, not both"));
        }
        (None, None) => {
            return Err(src.error(r, "missing wave period: give period_s or wavelength_m"));
        }
    };
    let limit = breaking_steepness(2.0 * std::f64::consts::PI / lambda, depth);
    if height / lambda > limit {
        return Err(src.error(
            &w.height_m,
            format!(
                "wave height {} m over wavelength {lambda:.4} m (H/λ = {:.4}) is steeper than the breaking limit H/λ = {:.4} ({})",
                num(height),
                height / lambda,
                limit,
                if depth.is_some() {
                    "(1/7) tanh(kh), Miche 1944"
                } else {
                    "1/7 in deep water"
                }
            ),
        ));
    }
    Ok(RegularWave {
        name: w
            .name
            .as_ref()
            .map(|n| n.get_ref().trim().to_string())
            .unwrap_or_else(|| format!("regular-{}", i + 1)),
        height_m: height,
        omega,
        period_s: 2.0 * std::f64::consts::PI / omega,
        wavelength_m: lambda,
    })
}

fn irregular_sea(
    src: &SourceText,
    r: &Spanned<IrregularRaw>,
    depth: Option<f64>,
    i: usize,
) -> Result<IrregularSea, InputError> {
    let w = r.get_ref();
    let hs = bounded(src, &w.hs_m, HEIGHT_RANGE, "hs_m", "m")?;
    let kind = *w.spectrum.get_ref();
    if kind != SpectrumKind::Jonswap
        && let Some(g) = &w.gamma
    {
        return Err(src.error(
            g,
            "gamma (peak enhancement) applies to the JONSWAP spectrum only",
        ));
    }
    let spectrum = match kind {
        SpectrumKind::PiersonMoskowitz => {
            if let Some(t) = w.tp_s.as_ref().or(w.tz_s.as_ref()) {
                return Err(src.error(
                    t,
                    "the Pierson-Moskowitz spectrum has one parameter (its period follows from hs_m); use spectrum = \"ittc\" to give a period",
                ));
            }
            Spectrum::pierson_moskowitz(hs)
        }
        SpectrumKind::Ittc | SpectrumKind::Jonswap => {
            let gamma = match &w.gamma {
                Some(g) => in_range(src, g, 1.0, 10.0, "gamma")?,
                None => 3.3,
            };
            let make = |tp: f64| match kind {
                SpectrumKind::Jonswap => Spectrum::jonswap(hs, tp, gamma),
                _ => Spectrum::bretschneider(hs, tp),
            };
            match (&w.tp_s, &w.tz_s) {
                (Some(tp), None) => make(bounded(src, tp, PERIOD_RANGE, "tp_s", "s")?),
                (None, Some(tz)) => {
                    let tz = bounded(src, tz, PERIOD_RANGE, "tz_s", "s")?;
                    make(tz).with_tz(tz)
                }
                (Some(tp), Some(_)) => {
                    return Err(src.error(tp, "give either tp_s or tz_s, not both"));
                }
                (None, None) => {
                    return Err(src.error(r, "missing spectrum period: give tp_s or tz_s"));
                }
            }
        }
    };
    // Steepness check on the significant wave: H_s/λ_p within the breaking limit at this depth.
    let k_p = wave_number(spectrum.peak_frequency(), depth);
    let lambda_p = 2.0 * std::f64::consts::PI / k_p;
    let limit = breaking_steepness(k_p, depth);
    if hs / lambda_p > limit {
        return Err(src.error(
            &w.hs_m,
            format!(
                "hs_m = {} m is steeper than the breaking limit for this period (H_s/λ_p = {:.4} > {:.4}, λ_p = {lambda_p:.4} m)",
                num(hs),
                hs / lambda_p,
                limit
            ),
        ));
    }
    let duration_h = match &w.duration_h {
        // A century of exposure at most.
        Some(d) => Some(bounded(src, d, (1e-6, 876_600.0), "duration_h", "h")?),
        None => None,
    };
    Ok(IrregularSea {
        name: w
            .name
            .as_ref()
            .map(|n| n.get_ref().trim().to_string())
            .unwrap_or_else(|| format!("irregular-{}", i + 1)),
        spectrum,
        duration_h,
    })
}

/// A number within a plausible physical range (positive and finite first, so the message says so).
fn bounded(
    src: &SourceText,
    v: &Spanned<f64>,
    (lo, hi): (f64, f64),
    what: &str,
    unit: &str,
) -> Result<f64, InputError> {
    let x = positive(src, v, what)?;
    if x < lo || x > hi {
        return Err(src.error(
            v,
            format!(
                "{what} = {} {unit} is outside the physical range {} to {} {unit}",
                num(x),
                num(lo),
                num(hi)
            ),
        ));
    }
    Ok(x)
}
