//! The sweep file (`sweep.toml`) as the user writes it, and its checks. Every value keeps its position in
//! the file, so a bad value, an invalid range or a case whose transformed hull is invalid is reported as
//! `file:line:column`.

use crate::sph::air::AirChoice;
use std::ops::Range;
use std::path::{Path, PathBuf};

use serde::Deserialize;
use toml::Spanned;

use crate::assess::Fidelity;
use crate::error::{InputError, Result};
use crate::input::{SourceText, num};
use crate::sph::Level;

/// The numeric parameters a sweep can vary, in the fixed order of the case table (and of the Latin
/// hypercube's dimensions).
pub const NUMERIC: [&str; 11] = [
    "speed_m_s",
    "wave_height_m",
    "wavelength_m",
    "hs_m",
    "tp_s",
    "draft_m",
    "trim_m",
    "flare_scale",
    "deadrise_scale",
    "length_scale",
    "beam_scale",
];

/// A list of values, or a range.
#[derive(Debug, Clone)]
pub enum AxisRaw {
    List(Vec<Spanned<f64>>),
    Range(RangeRaw),
}

/// `{ start, stop, step }` or `{ start, stop, count }` (both ends included).
#[derive(Debug, Clone, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RangeRaw {
    pub start: Spanned<f64>,
    pub stop: Spanned<f64>,
    pub step: Option<Spanned<f64>>,
    pub count: Option<Spanned<i64>>,
}

impl<'de> Deserialize<'de> for AxisRaw {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> std::result::Result<Self, D::Error> {
        struct V;
        impl<'de> serde::de::Visitor<'de> for V {
            type Value = AxisRaw;
            fn expecting(&self, f: &mut std::fmt::Formatter) -> std::fmt::Result {
                f.write_str(
                    "a list of values [a, b, ...] or a range { start = a, stop = b, step = s } / \
                     { start = a, stop = b, count = n }",
                )
            }
            fn visit_seq<A: serde::de::SeqAccess<'de>>(
                self,
                mut seq: A,
            ) -> std::result::Result<AxisRaw, A::Error> {
                let mut v = Vec::new();
                while let Some(x) = seq.next_element::<Spanned<f64>>()? {
                    v.push(x);
                }
                Ok(AxisRaw::List(v))
            }
            fn visit_map<A: serde::de::MapAccess<'de>>(
                self,
                map: A,
            ) -> std::result::Result<AxisRaw, A::Error> {
                RangeRaw::deserialize(serde::de::value::MapAccessDeserializer::new(map))
                    .map(AxisRaw::Range)
            }
        }
        d.deserialize_any(V)
    }
}

/// `[grid]`: every combination of these values is a case.
#[derive(Debug, Deserialize, Default)]
#[serde(deny_unknown_fields)]
pub struct GridRaw {
    pub speed_m_s: Option<Spanned<AxisRaw>>,
    pub wave_height_m: Option<Spanned<AxisRaw>>,
    pub wavelength_m: Option<Spanned<AxisRaw>>,
    pub hs_m: Option<Spanned<AxisRaw>>,
    pub tp_s: Option<Spanned<AxisRaw>>,
    pub draft_m: Option<Spanned<AxisRaw>>,
    pub trim_m: Option<Spanned<AxisRaw>>,
    pub flare_scale: Option<Spanned<AxisRaw>>,
    pub deadrise_scale: Option<Spanned<AxisRaw>>,
    pub length_scale: Option<Spanned<AxisRaw>>,
    pub beam_scale: Option<Spanned<AxisRaw>>,
    /// Names of regular waves of the sea file (one case per wave).
    pub wave: Option<Spanned<Vec<Spanned<String>>>>,
}

impl GridRaw {
    /// The numeric axes given, in [`NUMERIC`] order.
    pub fn axes(&self) -> Vec<(&'static str, &Spanned<AxisRaw>)> {
        let all = [
            &self.speed_m_s,
            &self.wave_height_m,
            &self.wavelength_m,
            &self.hs_m,
            &self.tp_s,
            &self.draft_m,
            &self.trim_m,
            &self.flare_scale,
            &self.deadrise_scale,
            &self.length_scale,
            &self.beam_scale,
        ];
        NUMERIC
            .iter()
            .zip(all)
            .filter_map(|(n, a)| a.as_ref().map(|a| (*n, a)))
            .collect()
    }
}

/// `{ min, max }` of a Latin-hypercube parameter.
#[derive(Debug, Deserialize, Clone)]
#[serde(deny_unknown_fields)]
pub struct BoundsRaw {
    pub min: Spanned<f64>,
    pub max: Spanned<f64>,
}

/// `[latin_hypercube]`.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct LhsRaw {
    pub samples: Spanned<i64>,
    pub seed: Spanned<i64>,
    pub speed_m_s: Option<Spanned<BoundsRaw>>,
    pub wave_height_m: Option<Spanned<BoundsRaw>>,
    pub wavelength_m: Option<Spanned<BoundsRaw>>,
    pub hs_m: Option<Spanned<BoundsRaw>>,
    pub tp_s: Option<Spanned<BoundsRaw>>,
    pub draft_m: Option<Spanned<BoundsRaw>>,
    pub trim_m: Option<Spanned<BoundsRaw>>,
    pub flare_scale: Option<Spanned<BoundsRaw>>,
    pub deadrise_scale: Option<Spanned<BoundsRaw>>,
    pub length_scale: Option<Spanned<BoundsRaw>>,
    pub beam_scale: Option<Spanned<BoundsRaw>>,
}

impl LhsRaw {
    /// The parameters given, in [`NUMERIC`] order.
    pub fn bounds(&self) -> Vec<(&'static str, &Spanned<BoundsRaw>)> {
        let all = [
            &self.speed_m_s,
            &self.wave_height_m,
            &self.wavelength_m,
            &self.hs_m,
            &self.tp_s,
            &self.draft_m,
            &self.trim_m,
            &self.flare_scale,
            &self.deadrise_scale,
            &self.length_scale,
            &self.beam_scale,
        ];
        NUMERIC
            .iter()
            .zip(all)
            .filter_map(|(n, a)| a.as_ref().map(|a| (*n, a)))
            .collect()
    }
}

/// `[bow_region]`: where `flare_scale` and `deadrise_scale` act.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct RegionRaw {
    /// Full change forward of this station (fraction of Lpp aft of the FP).
    pub full_aft_of_fp: Spanned<f64>,
    /// No change aft of this station; a smooth taper between the two.
    pub zero_aft_of_fp: Spanned<f64>,
}

/// `[best]`: the table of the best variants.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BestRaw {
    pub minimise: Option<Spanned<String>>,
    pub max_slam_probability: Option<Spanned<f64>>,
    pub max_design_pressure_kpa: Option<Spanned<f64>>,
    pub count: Option<Spanned<i64>>,
}

/// The whole file.
#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SweepRaw {
    pub name: Spanned<String>,
    pub description: Option<String>,
    pub hull: Spanned<String>,
    pub sea: Spanned<String>,
    pub loading: Option<Spanned<String>>,
    pub stations: Option<Spanned<Vec<Spanned<f64>>>>,
    pub fidelity: Option<Spanned<String>>,
    pub resolution: Option<Spanned<String>>,
    pub air: Option<Spanned<String>>,
    pub keel_slope_term: Option<Spanned<bool>>,
    pub convergence_levels: Option<Spanned<i64>>,
    pub strips: Option<Spanned<i64>>,
    pub bow_region: Option<Spanned<RegionRaw>>,
    pub grid: Option<Spanned<GridRaw>>,
    pub latin_hypercube: Option<Spanned<LhsRaw>>,
    pub best: Option<Spanned<BestRaw>>,
}

/// What the best-variants table ranks by (lowest first).
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Objective {
    /// The largest sensor design pressure over the stations.
    DesignPressure,
    /// The largest section-force peak over the stations.
    SectionForce,
    /// The largest slam probability per encounter over the stations.
    SlamProbability,
}

/// The best-variants rule.
#[derive(Debug, Clone, PartialEq, serde::Serialize, Deserialize)]
pub struct Best {
    pub minimise: Objective,
    pub max_slam_probability: Option<f64>,
    pub max_design_pressure_pa: Option<f64>,
    pub count: usize,
}

/// The forward region of the flare and deadrise changes.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct BowRegion {
    pub full_aft_of_fp: f64,
    pub zero_aft_of_fp: f64,
}

impl BowRegion {
    /// Weight of the change at a station (fraction of Lpp aft of the FP): 1 forward of `full`, 0 aft of
    /// `zero`, and between them the smooth step w = 3s² − 2s³ of s = (zero − f)/(zero − full), whose slope
    /// is zero at both ends (the change fades in without a knuckle in the waterlines).
    pub fn weight(&self, aft_of_fp: f64) -> f64 {
        if aft_of_fp <= self.full_aft_of_fp {
            1.0
        } else if aft_of_fp >= self.zero_aft_of_fp {
            0.0
        } else {
            let s = (self.zero_aft_of_fp - aft_of_fp) / (self.zero_aft_of_fp - self.full_aft_of_fp);
            s * s * (3.0 - 2.0 * s)
        }
    }
}

/// The parsed file with its source (for located errors).
pub struct SweepFile {
    pub src: SourceText,
    pub raw: SweepRaw,
}

/// Settings of the whole sweep, checked.
#[derive(Debug, Clone)]
pub struct Common {
    pub hull_path: PathBuf,
    pub sea_path: PathBuf,
    pub loading: Option<String>,
    pub stations: Vec<f64>,
    pub fidelity: Fidelity,
    pub resolution: Level,
    /// Air as a second phase in the SPH runs (`air = "off" | "on" | "auto"`; default off).
    pub air: AirChoice,
    /// Add the keel-slope term U dz_k/dx to the keel-entry velocities (`keel_slope_term = true`, as
    /// `assess --keel-slope-term`; default false).
    pub keel_slope_term: bool,
    pub convergence_levels: usize,
    pub strips: usize,
    pub region: Option<BowRegion>,
    pub best: Best,
}

impl SweepFile {
    pub fn read(path: &Path) -> Result<Self> {
        let src = SourceText::read(path)?;
        let raw: SweepRaw = src.parse_toml()?;
        Ok(Self { src, raw })
    }

    /// The value of the keyword `key` (`default` when absent) among `options`; any other word is an
    /// error at its place that lists them.
    fn keyword<T: Copy>(
        &self,
        v: &Option<Spanned<String>>,
        key: &str,
        default: T,
        options: &[(&str, T)],
    ) -> std::result::Result<T, InputError> {
        let Some(v) = v else {
            return Ok(default);
        };
        let word = v.get_ref().as_str();
        if let Some((_, t)) = options.iter().find(|(name, _)| *name == word) {
            return Ok(*t);
        }
        let names: Vec<String> = options.iter().map(|(n, _)| format!("\"{n}\"")).collect();
        let list = match names.split_last() {
            Some((last, rest)) if !rest.is_empty() => format!("{} or {last}", rest.join(", ")),
            _ => names.concat(),
        };
        Err(self.error(v, format!("{key} = \"{word}\": use {list}")))
    }

    pub fn error<T>(&self, v: &Spanned<T>, msg: impl Into<String>) -> InputError {
        self.src.error(v, msg)
    }

    pub fn error_at(&self, span: Range<usize>, msg: impl Into<String>) -> InputError {
        self.src.error_at(span, msg)
    }

    /// A path in the file, relative to the file's folder.
    fn relative(&self, v: &Spanned<String>) -> PathBuf {
        let base = self.src.path.parent().unwrap_or(Path::new(""));
        base.join(v.get_ref())
    }

    /// Check the settings that hold for every case.
    pub fn common(&self) -> Result<Common, InputError> {
        let r = &self.raw;
        if r.name.get_ref().trim().is_empty() {
            return Err(self.error(&r.name, "name must not be empty"));
        }
        let hull_path = self.relative(&r.hull);
        if !hull_path.is_file() {
            return Err(self.error(
                &r.hull,
                format!(
                    "hull file {} not found (paths are relative to the sweep file)",
                    hull_path.display()
                ),
            ));
        }
        let sea_path = self.relative(&r.sea);
        if !sea_path.is_file() {
            return Err(self.error(
                &r.sea,
                format!(
                    "sea-state file {} not found (paths are relative to the sweep file)",
                    sea_path.display()
                ),
            ));
        }
        let mut stations = Vec::new();
        if let Some(st) = &r.stations {
            for f in st.get_ref() {
                let v = *f.get_ref();
                if !(v.is_finite() && (0.0..=1.0).contains(&v)) {
                    return Err(self.error(
                        f,
                        format!(
                            "a station is a fraction of Lpp aft of the FP between 0 and 1, got {}",
                            num(v)
                        ),
                    ));
                }
                stations.push(v);
            }
        }
        let fidelity = self.keyword(
            &r.fidelity,
            "fidelity",
            Fidelity::Analytic,
            &[
                ("analytic", Fidelity::Analytic),
                ("screen", Fidelity::Screen),
                ("sph", Fidelity::Sph),
            ],
        )?;
        let resolution = self.keyword(
            &r.resolution,
            "resolution",
            Level::Coarse,
            &[
                ("coarse", Level::Coarse),
                ("medium", Level::Medium),
                ("fine", Level::Fine),
            ],
        )?;
        let air = self.keyword(
            &r.air,
            "air",
            AirChoice::Off,
            &[
                ("off", AirChoice::Off),
                ("on", AirChoice::On),
                ("auto", AirChoice::Auto),
            ],
        )?;
        let convergence_levels = match &r.convergence_levels {
            None => 2,
            Some(n) if (1..=3).contains(n.get_ref()) => *n.get_ref() as usize,
            Some(n) => {
                return Err(self.error(
                    n,
                    format!("convergence_levels must be 1, 2 or 3, got {}", n.get_ref()),
                ));
            }
        };
        let strips = match &r.strips {
            None => 31,
            Some(n) if (3..=401).contains(n.get_ref()) => *n.get_ref() as usize,
            Some(n) => {
                return Err(self.error(
                    n,
                    format!("strips must be between 3 and 401, got {}", n.get_ref()),
                ));
            }
        };
        let region = match &r.bow_region {
            None => None,
            Some(b) => {
                let g = b.get_ref();
                let full = self.fraction(&g.full_aft_of_fp, "full_aft_of_fp")?;
                let zero = self.fraction(&g.zero_aft_of_fp, "zero_aft_of_fp")?;
                if zero <= full {
                    return Err(self.error(
                        &g.zero_aft_of_fp,
                        format!(
                            "zero_aft_of_fp = {} must lie aft of full_aft_of_fp = {} (the change tapers \
                             from full at the bow to zero further aft)",
                            num(zero),
                            num(full)
                        ),
                    ));
                }
                Some(BowRegion {
                    full_aft_of_fp: full,
                    zero_aft_of_fp: zero,
                })
            }
        };
        Ok(Common {
            hull_path,
            sea_path,
            loading: r.loading.as_ref().map(|l| l.get_ref().clone()),
            stations,
            fidelity,
            resolution,
            air,
            keel_slope_term: r.keel_slope_term.as_ref().is_some_and(|b| *b.get_ref()),
            convergence_levels,
            strips,
            region,
            best: self.best()?,
        })
    }

    fn fraction(&self, v: &Spanned<f64>, what: &str) -> Result<f64, InputError> {
        let x = *v.get_ref();
        if !(x.is_finite() && (0.0..=1.0).contains(&x)) {
            return Err(self.error(
                v,
                format!(
                    "{what} is a fraction of Lpp aft of the FP between 0 and 1, got {}",
                    num(x)
                ),
            ));
        }
        Ok(x)
    }

    fn best(&self) -> Result<Best, InputError> {
        let Some(b) = &self.raw.best else {
            return Ok(Best {
                minimise: Objective::DesignPressure,
                max_slam_probability: None,
                max_design_pressure_pa: None,
                count: 10,
            });
        };
        let b = b.get_ref();
        let minimise = match &b.minimise {
            None => Objective::DesignPressure,
            Some(m) => match m.get_ref().as_str() {
                "design_pressure" => Objective::DesignPressure,
                "section_force" => Objective::SectionForce,
                "slam_probability" => Objective::SlamProbability,
                other => {
                    return Err(self.error(
                        m,
                        format!(
                            "minimise = \"{other}\": use \"design_pressure\", \"section_force\" or \
                             \"slam_probability\""
                        ),
                    ));
                }
            },
        };
        let max_slam_probability = match &b.max_slam_probability {
            None => None,
            Some(p) if p.get_ref().is_finite() && (0.0..=1.0).contains(p.get_ref()) => {
                Some(*p.get_ref())
            }
            Some(p) => {
                return Err(self.error(
                    p,
                    format!(
                        "max_slam_probability is a probability per encounter between 0 and 1 \
                         (0.03 for 3 %), got {}",
                        num(*p.get_ref())
                    ),
                ));
            }
        };
        let max_design_pressure_pa = match &b.max_design_pressure_kpa {
            None => None,
            Some(p) if p.get_ref().is_finite() && *p.get_ref() > 0.0 => Some(p.get_ref() * 1e3),
            Some(p) => {
                return Err(self.error(
                    p,
                    format!(
                        "max_design_pressure_kpa must be a positive number, got {}",
                        num(*p.get_ref())
                    ),
                ));
            }
        };
        let count = match &b.count {
            None => 10,
            Some(n) if *n.get_ref() >= 1 => *n.get_ref() as usize,
            Some(n) => {
                return Err(self.error(n, format!("count must be at least 1, got {}", n.get_ref())));
            }
        };
        Ok(Best {
            minimise,
            max_slam_probability,
            max_design_pressure_pa,
            count,
        })
    }
}
