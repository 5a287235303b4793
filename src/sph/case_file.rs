//! The TOML case file of a water-entry run (`slamtool entry case`): sections `[section]`, `[motion]`,
//! `[resolution]`, `[numerics]`, `[tank]`, `[run]` and `[[sensor]]`. Every value is checked where it is
//! read, and every problem is reported with its file, line and column; the automatic choices are then
//! made by [`crate::sph::case::resolve`].

use std::path::Path;

use serde::Deserialize;
use toml::Spanned;

use crate::error::{Error, Result};
use crate::input::{SourceText, positive};
use crate::sph::air::AirChoice;
use crate::sph::body::Section;
use crate::sph::case::{ForceMethod, Level, MotionSpec, Overrides, SensorMethod, Setup, resolve};
use crate::sph::eos::EosKind;
use crate::sph::sensors::SensorSpec;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct CaseFile {
    name: Option<String>,
    section: SectionFile,
    motion: MotionFile,
    #[serde(default)]
    resolution: ResolutionFile,
    #[serde(default)]
    numerics: NumericsFile,
    #[serde(default)]
    tank: TankFile,
    #[serde(default)]
    run: RunFile,
    #[serde(default)]
    sensor: Vec<SensorFile>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SectionFile {
    wedge: Option<Spanned<WedgeFile>>,
    /// Starboard half (y, z) from the keel up.
    points: Option<Spanned<Vec<[f64; 2]>>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct WedgeFile {
    deadrise_deg: Spanned<f64>,
    half_beam_m: Spanned<f64>,
    height_m: Option<Spanned<f64>>,
}

#[derive(Debug, Clone, Copy, Deserialize)]
#[serde(rename_all = "snake_case")]
enum MotionKind {
    Constant,
    Prescribed,
    FreeHeave,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct MotionFile {
    kind: Spanned<MotionKind>,
    speed_m_s: Option<Spanned<f64>>,
    table: Option<Spanned<Vec<[f64; 2]>>>,
    mass_per_m_kg: Option<Spanned<f64>>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct ResolutionFile {
    level: Option<Level>,
    particles_per_half_beam: Option<Spanned<f64>>,
    dp_m: Option<Spanned<f64>>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct NumericsFile {
    c0_m_s: Option<Spanned<f64>>,
    h_over_dp: Option<Spanned<f64>>,
    eos: Option<EosKind>,
    delta: Option<Spanned<f64>>,
    alpha: Option<Spanned<f64>>,
    cfl: Option<Spanned<f64>>,
    shifting: Option<bool>,
    riemann: Option<bool>,
    divergence_correction: Option<bool>,
    /// Body dummies weighted by the wetness of the body's face (`crate::sph::wall_wetness`).
    wall_wetness: Option<bool>,
    force: Option<ForceMethod>,
    sensor_method: Option<SensorMethod>,
    mirror: Option<bool>,
    /// Air as a second phase: "on", "off" (the default) or "auto".
    air: Option<AirChoice>,
    /// The air gap under the keel at the start of a run with air (m; default 4 particle spacings).
    air_gap_m: Option<Spanned<f64>>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct TankFile {
    half_width_m: Option<Spanned<f64>>,
    depth_m: Option<Spanned<f64>>,
    wall_height_m: Option<Spanned<f64>>,
    /// Thickness of the absorbing layer along the walls and bottom (0 for none).
    damping_zone_m: Option<Spanned<f64>>,
    /// Base resolution in a band around the body, 2 dp beyond (default: true with the automatic tank
    /// and the Riemann scheme, false with a given tank).
    refined: Option<bool>,
}

#[derive(Debug, Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct RunFile {
    t_end_s: Option<Spanned<f64>>,
    snapshot_interval_s: Option<Spanned<f64>>,
    filter_cutoff_hz: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
struct SensorFile {
    name: String,
    s_m: Spanned<f64>,
    width_m: Spanned<f64>,
}

/// Most points accepted in a section contour.
pub const MAX_SECTION_POINTS: usize = 10_000;
/// Most rows accepted in a velocity table.
pub const MAX_TABLE_ROWS: usize = 100_000;
/// Most sensors accepted in a case.
pub const MAX_SENSORS: usize = 1_000;

/// A section contour from a case file under the rules of a hull file's stations
/// ([`crate::hull::validate::check_section`]): finite, y ≥ 0, z never falling from keel to deck (no
/// zig-zag), no repeated point, no self-overlap; at most [`MAX_SECTION_POINTS`] points. As in
/// [`Section::from_half_points`], a keel point on the centreline is added when the first point is off it.
fn check_points(src: &SourceText, p: &Spanned<Vec<[f64; 2]>>) -> Result<()> {
    let given = p.get_ref();
    if given.len() > MAX_SECTION_POINTS {
        return Err(src
            .error(
                p,
                format!(
                    "the section has {} points, more than the {MAX_SECTION_POINTS} accepted",
                    given.len()
                ),
            )
            .into());
    }
    let mut pts = given.clone();
    let added = pts.first().is_some_and(|q| q[0] > 0.0);
    if added {
        pts.insert(0, [0.0, pts[0][1]]);
    }
    crate::hull::validate::check_section(&pts).map_err(|f| {
        let note = if added {
            " (counting the keel point added on the centreline as point 1)"
        } else {
            ""
        };
        src.error(p, format!("section points: {}{note}", f.message))
    })?;
    Ok(())
}

/// Read and resolve a case file. Every problem is reported with its file, line and column.
pub fn from_file(path: &Path) -> Result<Setup> {
    let src = SourceText::read(path)?;
    from_source(&src)
}

/// Resolve a case from its text.
pub fn from_source(src: &SourceText) -> Result<Setup> {
    let f: CaseFile = src.parse_toml()?;
    let opt = |v: &Option<Spanned<f64>>, what: &str| -> Result<Option<f64>> {
        Ok(match v {
            Some(x) => Some(positive(src, x, what)?),
            None => None,
        })
    };
    let section = match (&f.section.wedge, &f.section.points) {
        (Some(w), None) => {
            let wf = w.get_ref();
            let beta = crate::input::in_range(src, &wf.deadrise_deg, 1.0, 89.0, "deadrise_deg")?;
            let hb = positive(src, &wf.half_beam_m, "half_beam_m")?;
            let zk = hb * beta.to_radians().tan();
            let height = match &wf.height_m {
                Some(hm) => {
                    let hv = positive(src, hm, "height_m")?;
                    if hv < zk {
                        return Err(src
                            .error(
                                hm,
                                format!("height_m must be at least the chine height {zk:.4} m"),
                            )
                            .into());
                    }
                    hv
                }
                None => zk,
            };
            Section::wedge(beta.to_radians(), hb, height)
                .map_err(|e| src.error(w, e.to_string()))?
        }
        (None, Some(p)) => {
            check_points(src, p)?;
            Section::from_half_points(p.get_ref().clone())
                .map_err(|e| src.error(p, e.to_string()))?
        }
        _ => {
            return Err(Error::Input(src.error_at(
                0..0,
                "[section] needs exactly one of `wedge = {...}` or `points = [[y, z], ...]`",
            )));
        }
    };
    let m = &f.motion;
    let need = |v: &Option<Spanned<f64>>, key: &str| -> Result<f64> {
        match v {
            Some(x) => Ok(positive(src, x, key)?),
            None => Err(src
                .error(&m.kind, format!("this motion kind needs `{key}`"))
                .into()),
        }
    };
    let motion = match m.kind.get_ref() {
        MotionKind::Constant => MotionSpec::Constant {
            speed_m_s: need(&m.speed_m_s, "speed_m_s")?,
        },
        MotionKind::Prescribed => {
            let Some(table) = &m.table else {
                return Err(src
                    .error(
                        &m.kind,
                        "this motion kind needs `table = [[t_s, v_m_s], ...]`",
                    )
                    .into());
            };
            let rows = table.get_ref();
            if rows.len() < 2 {
                return Err(src
                    .error(table, "the velocity table needs at least two rows")
                    .into());
            }
            if rows.len() > MAX_TABLE_ROWS {
                return Err(src
                    .error(
                        table,
                        format!(
                            "the velocity table has {} rows, more than the {MAX_TABLE_ROWS} accepted",
                            rows.len()
                        ),
                    )
                    .into());
            }
            for (k, r) in rows.iter().enumerate() {
                if !r[0].is_finite() || !r[1].is_finite() {
                    return Err(src
                        .error(table, format!("row {} of the table is not finite", k + 1))
                        .into());
                }
                if k > 0 && r[0] <= rows[k - 1][0] {
                    return Err(src
                        .error(
                            table,
                            format!("table times must increase: row {} has t = {}", k + 1, r[0]),
                        )
                        .into());
                }
            }
            // Velocities are positive downward: a table that never goes down never enters the water.
            if rows.iter().all(|r| r[1] <= 0.0) {
                let v = rows.iter().map(|r| r[1]).fold(f64::NEG_INFINITY, f64::max);
                return Err(src
                    .error(
                        table,
                        format!(
                            "the velocity table never moves the section down (the largest velocity is {} m/s; \
                             velocities are positive downward, into the water): flip the sign of the velocities",
                            crate::input::num(v)
                        ),
                    )
                    .into());
            }
            MotionSpec::Prescribed {
                table: rows.clone(),
            }
        }
        MotionKind::FreeHeave => MotionSpec::FreeHeave {
            mass_per_m_kg: need(&m.mass_per_m_kg, "mass_per_m_kg")?,
            speed_m_s: need(&m.speed_m_s, "speed_m_s")?,
        },
    };
    if f.sensor.len() > MAX_SENSORS {
        return Err(src
            .error_at(
                0..0,
                format!(
                    "{} sensors, more than the {MAX_SENSORS} accepted",
                    f.sensor.len()
                ),
            )
            .into());
    }
    let mut sensors = Vec::new();
    for s in &f.sensor {
        sensors.push(SensorSpec {
            name: s.name.clone(),
            s_m: crate::input::finite(src, &s.s_m, "s_m")?,
            width_m: positive(src, &s.width_m, "width_m")?,
        });
    }
    let o = Overrides {
        air: f.numerics.air,
        air_gap: match &f.numerics.air_gap_m {
            Some(v) if !matches!(f.numerics.air, Some(AirChoice::On | AirChoice::Auto)) => {
                return Err(src
                    .error(
                        v,
                        "air_gap_m is given but air is off: set air = \"on\" or \"auto\", or leave the gap out",
                    )
                    .into());
            }
            Some(v) => Some(crate::input::in_range(src, v, 0.0, 10.0, "air_gap_m")?),
            None => None,
        },
        initial_immersion: None,
        refinement: f.tank.refined,
        level: f.resolution.level,
        particles_per_half_beam: opt(
            &f.resolution.particles_per_half_beam,
            "particles_per_half_beam",
        )?,
        dp: opt(&f.resolution.dp_m, "dp_m")?,
        c0: opt(&f.numerics.c0_m_s, "c0_m_s")?,
        h_over_dp: match &f.numerics.h_over_dp {
            Some(v) => Some(crate::input::in_range(src, v, 1.0, 3.0, "h_over_dp")?),
            None => None,
        },
        eos: f.numerics.eos,
        delta: match &f.numerics.delta {
            Some(v) => Some(crate::input::in_range(src, v, 0.0, 1.0, "delta")?),
            None => None,
        },
        alpha: match &f.numerics.alpha {
            Some(v) => Some(crate::input::in_range(src, v, 0.0, 1.0, "alpha")?),
            None => None,
        },
        cfl: match &f.numerics.cfl {
            Some(v) => Some(crate::input::in_range(src, v, 0.01, 0.5, "cfl")?),
            None => None,
        },
        shifting: f.numerics.shifting,
        riemann: f.numerics.riemann,
        divergence_correction: f.numerics.divergence_correction,
        wall_wetness: f.numerics.wall_wetness,
        force: f.numerics.force,
        sensor_method: f.numerics.sensor_method,
        tank_half_width: opt(&f.tank.half_width_m, "half_width_m")?,
        tank_depth: opt(&f.tank.depth_m, "depth_m")?,
        tank_wall_height: opt(&f.tank.wall_height_m, "wall_height_m")?,
        damping_zone: match &f.tank.damping_zone_m {
            Some(v) => Some(crate::input::in_range(src, v, 0.0, 1e3, "damping_zone_m")?),
            None => None,
        },
        mirror: f.numerics.mirror,
        t_end: opt(&f.run.t_end_s, "t_end_s")?,
        snapshot_interval: opt(&f.run.snapshot_interval_s, "snapshot_interval_s")?,
        filter_cutoff_hz: opt(&f.run.filter_cutoff_hz, "filter_cutoff_hz")?,
    };
    let name = f.name.clone().unwrap_or_else(|| {
        src.path
            .file_stem()
            .map_or("case".into(), |s| s.to_string_lossy().into_owned())
    });
    let setup = resolve(&name, &section, &motion, sensors, &o)?;
    // Sensor positions are checked against the contour here so the error can point at the file.
    let len = crate::sph::body::half_contour_length(&section);
    for (s, spec) in f.sensor.iter().zip(&setup.sensors) {
        if !spec.fits(len) {
            return Err(src
                .error(
                    &s.s_m,
                    format!(
                        "sensor '{}' (centre {} m, width {} m) must lie on the starboard contour, {len:.4} m long",
                        spec.name, spec.s_m, spec.width_m
                    ),
                )
                .into());
        }
    }
    Ok(setup)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::case::{DEFAULT_RIEMANN, DEFAULT_SHIFTING, DEFAULT_WALL_WETNESS};

    fn parse(text: &str) -> Result<Setup> {
        from_source(&SourceText::from_string("case.toml", text))
    }

    #[test]
    fn resolves_a_wedge_case_and_records_the_choices() {
        let s = parse(
            "[section]\nwedge = { deadrise_deg = 30.0, half_beam_m = 0.25 }\n\
             [motion]\nkind = \"constant\"\nspeed_m_s = 2.0\n",
        )
        .unwrap();
        // c0 from Wagner's Cp at 30 deg: 2 sqrt(7.40 / 0.02) = 38.5 m/s, above 10 sqrt(g 0.75) = 27.1 m/s.
        assert!(
            (s.c0 - 2.0 * (7.402f64 / 0.02).sqrt()).abs() < 0.05,
            "{}",
            s.c0
        );
        assert!((s.dp - 0.25 / 40.0).abs() < 1e-12);
        // Wagner's wetting reaches the chine at a keel depth (2/pi) z_chine; the run lasts 1.2 times
        // that (below the cap of 0.9 x the height).
        let t_wet = 2.0 / std::f64::consts::PI * 0.25 * 30f64.to_radians().tan() / 2.0;
        assert!((s.t_end / (1.2 * t_wet) - 1.0).abs() < 1e-3, "{}", s.t_end);
        assert!(s.notes.iter().any(|n| n.starts_with("c0 =")));
    }

    #[test]
    fn numerics_options_parse_and_bad_values_name_the_place() {
        let base = "[section]\nwedge = { deadrise_deg = 30.0, half_beam_m = 0.25 }\n\
                    [motion]\nkind = \"constant\"\nspeed_m_s = 2.0\n";
        let s = parse(base).unwrap();
        assert!(s.riemann == DEFAULT_RIEMANN && s.shifting == DEFAULT_SHIFTING);
        assert_eq!(s.wall_wetness, DEFAULT_WALL_WETNESS);
        assert_eq!(s.force, ForceMethod::NormalPairForces);
        assert!(s.shifting && s.divergence_correction && s.wall_wetness);
        let s = parse(&format!(
            "{base}[numerics]\nriemann = false\nshifting = false\nforce = \"contour\"\nwall_wetness = false\n"
        ))
        .unwrap();
        assert!(!s.riemann && !s.shifting && s.force == ForceMethod::Contour && !s.wall_wetness);
        let s = parse(&format!("{base}[numerics]\nforce = \"pair_forces\"\n")).unwrap();
        assert_eq!(s.force, ForceMethod::PairForces);
        let e = parse(&format!("{base}[numerics]\nforce = \"pressure\"\n")).unwrap_err();
        assert!(e.to_string().starts_with("case.toml:7:9:"), "{e}");
        assert_eq!(s.sensor_method, SensorMethod::ForcePanel);
        let s = parse(&format!(
            "{base}[numerics]\nsensor_method = \"interpolated\"\n"
        ))
        .unwrap();
        assert_eq!(s.sensor_method, SensorMethod::Interpolated);
        let e = parse(&format!("{base}[numerics]\nsensor_method = \"panel\"\n")).unwrap_err();
        assert!(e.to_string().starts_with("case.toml:7:17:"), "{e}");
    }

    #[test]
    fn errors_name_line_and_column() {
        let e = parse(
            "[section]\nwedge = { deadrise_deg = 30.0, half_beam_m = 0.25 }\n\
             [motion]\nkind = \"free_heave\"\nspeed_m_s = 2.0\n",
        )
        .unwrap_err();
        let m = e.to_string();
        assert!(
            m.starts_with("case.toml:4:8:") && m.contains("mass_per_m_kg"),
            "{m}"
        );
        let e = parse(
            "[section]\nwedge = { deadrise_deg = 95.0, half_beam_m = 0.25 }\n\
             [motion]\nkind = \"constant\"\nspeed_m_s = 2.0\n",
        )
        .unwrap_err();
        assert!(e.to_string().starts_with("case.toml:2:26:"), "{e}");
    }
}
