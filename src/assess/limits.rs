//! The design gate of an assessment: sensor design pressures checked against `--max-pressure-kpa` and the
//! hull file's `[limits]` table. Every violation is one line,
//! `LIMIT EXCEEDED: station F sensor NAME p kPa > limit kPa (source, speed, wave; which limit)`, and the
//! command exits with status 4.
//!
//! The `[limits]` table (all keys optional; pressures in kPa):
//!
//! ```toml
//! [limits]
//! pressure_kpa = 60.0          # every sensor of every assessed station
//!
//! [[limits.station]]           # every sensor (the hull's or the default panels) of one station
//! aft_of_fp = 0.093            # or x_m
//! pressure_kpa = 40.0
//!
//! [[limits.sensor]]            # one sensor of the hull file, by name
//! name = "S093-1"
//! pressure_kpa = 30.0
//! ```
//!
//! A sensor is checked against every limit that applies to it (the tightest decides the verdict; each
//! violated limit is one line).

use serde::Deserialize;
use toml::Spanned;

use super::results::Assessment;
use crate::error::Result;
use crate::hull::Hull;
use crate::input::{SourceText, positive};

/// What one limit applies to.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Scope {
    /// Every sensor (`--max-pressure-kpa` or `[limits] pressure_kpa`).
    All,
    /// Every sensor of the station at this fraction of Lpp aft of the FP.
    Station(f64),
    /// One sensor by name.
    Sensor(String),
}

/// One pressure limit and where it was given.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct Limit {
    pub scope: Scope,
    pub pressure_pa: f64,
    /// "--max-pressure-kpa" or "file:line:column".
    pub origin: String,
}

#[derive(Debug, Deserialize)]
struct FileRaw {
    limits: Option<LimitsRaw>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct LimitsRaw {
    pressure_kpa: Option<Spanned<f64>>,
    #[serde(default)]
    station: Vec<Spanned<StationLimitRaw>>,
    #[serde(default)]
    sensor: Vec<Spanned<SensorLimitRaw>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct StationLimitRaw {
    aft_of_fp: Option<Spanned<f64>>,
    x_m: Option<Spanned<f64>>,
    pressure_kpa: Spanned<f64>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SensorLimitRaw {
    name: Spanned<String>,
    pressure_kpa: Spanned<f64>,
}

fn origin<T>(src: &SourceText, v: &Spanned<T>) -> String {
    let (l, c) = src.line_column(v.span().start);
    format!("{}:{l}:{c}", src.path.display())
}

/// The `[limits]` table of a hull file's text (empty when there is none). A station outside the offsets
/// or a sensor name the hull does not have is an error at its line and column.
pub fn from_source(src: &SourceText, hull: &Hull) -> Result<Vec<Limit>> {
    let raw: FileRaw = src.parse_toml()?;
    let Some(l) = raw.limits else {
        return Ok(Vec::new());
    };
    let mut out = Vec::new();
    if let Some(p) = &l.pressure_kpa {
        out.push(Limit {
            scope: Scope::All,
            pressure_pa: positive(src, p, "limits.pressure_kpa")? * 1e3,
            origin: origin(src, p),
        });
    }
    for st in &l.station {
        let r = st.get_ref();
        let x = match (&r.aft_of_fp, &r.x_m) {
            (Some(f), None) => hull.station_x(crate::input::finite(src, f, "aft_of_fp")?),
            (None, Some(x)) => crate::input::finite(src, x, "x_m")?,
            _ => {
                return Err(src
                    .error(
                        st,
                        "give the limited station as aft_of_fp or x_m (one of them)",
                    )
                    .into());
            }
        };
        if let Err(e) = hull.section_at(x) {
            let at = r.aft_of_fp.as_ref().map_or_else(
                || src.error(r.x_m.as_ref().expect("x_m given"), e.to_string()),
                |f| src.error(f, e.to_string()),
            );
            return Err(at.into());
        }
        out.push(Limit {
            scope: Scope::Station((hull.aft_of_fp(x) * 1e9).round() / 1e9),
            pressure_pa: positive(src, &r.pressure_kpa, "pressure_kpa")? * 1e3,
            origin: origin(src, st),
        });
    }
    for s in &l.sensor {
        let r = s.get_ref();
        let name = r.name.get_ref();
        if !hull.sensors.iter().any(|q| &q.name == name) {
            let names: Vec<&str> = hull.sensors.iter().map(|q| q.name.as_str()).collect();
            return Err(src
                .error(
                    &r.name,
                    format!(
                        "limits.sensor: the hull file has no sensor named '{name}' (it has: {}); limit the \
                         default panels of a station with [[limits.station]]",
                        if names.is_empty() {
                            "none".to_string()
                        } else {
                            names.join(", ")
                        }
                    ),
                )
                .into());
        }
        out.push(Limit {
            scope: Scope::Sensor(name.clone()),
            pressure_pa: positive(src, &r.pressure_kpa, "pressure_kpa")? * 1e3,
            origin: origin(src, s),
        });
    }
    Ok(out)
}

/// The `[limits]` table of a hull's file.
pub fn of_hull(hull: &Hull) -> Result<Vec<Limit>> {
    let src = SourceText::read(&hull.source)?;
    from_source(&src, hull)
}

/// The violations of `limits` by the design pressures of `a`, one line each.
pub fn check(a: &Assessment, limits: &[Limit]) -> Vec<String> {
    let mut out = Vec::new();
    for st in &a.stations {
        for d in &st.design_pressure_pa {
            for l in limits {
                let applies = match &l.scope {
                    Scope::All => true,
                    Scope::Station(f) => (f - st.station).abs() < 1e-6,
                    Scope::Sensor(n) => n == &d.name,
                };
                let Some(v) = d.value else { continue };
                if applies && v > l.pressure_pa {
                    out.push(format!(
                        "LIMIT EXCEEDED: station {} sensor {} {:.2} kPa > {:.2} kPa ({}, {} m/s, {}; limit from {})",
                        st.station,
                        d.name,
                        v / 1e3,
                        l.pressure_pa / 1e3,
                        d.source,
                        d.speed_m_per_s,
                        d.wave,
                        l.origin
                    ));
                }
            }
        }
    }
    out
}

/// The station limits that apply to no assessed station (they are not checked; a warning says so).
pub fn unchecked(a: &Assessment, limits: &[Limit]) -> Vec<String> {
    limits
        .iter()
        .filter_map(|l| match &l.scope {
            Scope::Station(f) if !a.stations.iter().any(|s| (s.station - f).abs() < 1e-6) => Some(
                format!(
                    "the limit at station {f} Lpp ({}) is not checked: that station is not assessed \
                     (give --station {f})",
                    l.origin
                ),
            ),
            _ => None,
        })
        .collect()
}

/// The violations of one pressure limit (Pa) on every sensor (`--max-pressure-kpa`).
pub fn violations(a: &Assessment, max_pressure_pa: f64) -> Vec<String> {
    check(
        a,
        &[Limit {
            scope: Scope::All,
            pressure_pa: max_pressure_pa,
            origin: "--max-pressure-kpa".into(),
        }],
    )
}
