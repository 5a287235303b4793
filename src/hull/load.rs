//! Turning a parsed `hull.toml` into a validated [`Hull`], with every error located in its file.

use std::collections::HashSet;

use toml::Spanned;

use super::schema::{HullFile, LoadingRaw, SensorRaw, StationRaw};
use super::validate::check_section;
use super::{
    Hull, LoadingCondition, Section, SectionInterpolator, Sensor, Station, offsets_csv, station_x,
};
use crate::error::{Error, InputError, Result};
use crate::input::{SourceText, finite, in_range, num, positive};

/// Water density accepted as physical, kg/m³ (fresh water at 40 °C to brine-rich sea water).
const RHO_RANGE: (f64, f64) = (990.0, 1050.0);

/// Most stations a hull may have (a scanned or finely resampled hull has thousands; the reader's cost is
/// linear in them).
pub const MAX_STATIONS: usize = 200_000;

/// Most points a station contour may have.
pub const MAX_POINTS_PER_STATION: usize = 10_000;

/// Longest Lpp accepted, m: longer than any ship built (the longest, Seawise Giant, had 440 m), so that a
/// length typed in millimetres is caught.
pub(crate) const LPP_MAX: f64 = 1000.0;

/// A given displacement may differ from the buoyancy at the loading's drafts by at most this fraction; a
/// larger difference is a mistake (a unit slip, wrong drafts), since the ship would not float at those drafts.
const MASS_BUOYANCY_TOLERANCE: f64 = 0.25;

/// A name from the file, trimmed, with control characters escaped (`\u{1b}`) so that no command prints
/// them raw to a terminal.
fn clean_name(s: &str) -> String {
    crate::output_policy::escape_control(s.trim())
}

pub(crate) fn hull_from_source(src: &SourceText) -> Result<Hull> {
    let raw: HullFile = super::chunked::parse(src)?;
    if raw.name.get_ref().trim().is_empty() {
        return Err(src.error(&raw.name, "name must not be empty").into());
    }
    let lpp = positive(src, &raw.lpp_m, "lpp_m")?;
    if lpp > LPP_MAX {
        return Err(src
            .error(
                &raw.lpp_m,
                format!(
                    "lpp_m = {} m is longer than any ship (limit {LPP_MAX} m); lengths are in metres",
                    num(lpp)
                ),
            )
            .into());
    }

    let stations = match (&raw.station, &raw.offsets_csv) {
        (Some(st), None) => stations_from_toml(src, lpp, st)?,
        (None, Some(csv)) => offsets_csv::read_stations(src, lpp, csv)?,
        (Some(st), Some(_)) => {
            return Err(src
                .error(
                    st,
                    "give the offsets either as [[station]] tables or as [offsets_csv], not both",
                )
                .into());
        }
        (None, None) => {
            return Err(src
                .error_at(
                    0..0,
                    "no offsets: add [[station]] tables or an [offsets_csv] table",
                )
                .into());
        }
    };

    let (xa, xf) = (stations[0].x, stations[stations.len() - 1].x);
    if !(xa <= 1e-9 && xf >= -1e-9) || xf - xa < 0.5 * lpp {
        return Err(src
            .error(
                &raw.lpp_m,
                format!(
                    "the offsets run from x = {xa:.4} m to {xf:.4} m, which {} for lpp_m = {} m: the stations must cover midship (x = 0) and at least half the length (x is from midship, positive forward; aft_of_fp is a fraction of Lpp)",
                    if xa <= 1e-9 && xf >= -1e-9 {
                        "is less than half of Lpp"
                    } else {
                        "does not include midship"
                    },
                    num(lpp)
                ),
            )
            .into());
    }
    if stations.iter().all(|s| s.section.max_half_breadth() <= 0.0) {
        let at = match (&raw.station, &raw.offsets_csv) {
            (Some(st), _) => st.span(),
            (_, Some(csv)) => csv.span(),
            _ => 0..0,
        };
        return Err(src
            .error_at(
                at,
                "the hull has no breadth: every station lies on the centreline (y = 0)",
            )
            .into());
    }
    let top = stations
        .iter()
        .map(|s| s.section.deck_z())
        .fold(f64::NEG_INFINITY, f64::max);
    let depth = match &raw.depth_m {
        Some(d) => positive(src, d, "depth_m")?,
        None => top,
    };

    let loadings = loadings(src, lpp, depth, &raw.loading)?;
    let mut hull = Hull {
        name: clean_name(raw.name.get_ref()),
        description: raw.description.clone(),
        lpp,
        depth,
        interpolator: SectionInterpolator::new(&stations),
        stations,
        loadings,
        sensors: Vec::new(),
        hydrostatics: Vec::new(),
        source: src.path.clone(),
        offsets_file: raw.offsets_csv.as_ref().map(|c| {
            let base = src.path.parent().unwrap_or(std::path::Path::new("."));
            base.join(c.get_ref().file.get_ref())
        }),
    };
    for l in &raw.loading.get_ref()[..] {
        check_offsets_reach_waterline(src, &hull, l)?;
        let hs = check_immersed(src, &hull, l)?;
        hull.hydrostatics.push(hs);
    }
    let mut names = HashSet::new();
    for s in &raw.sensor {
        let sensor = sensor(src, &hull, s)?;
        if !names.insert(sensor.name.clone()) {
            return Err(src
                .error(
                    &s.get_ref().name,
                    format!("sensor name '{}' is used twice", sensor.name),
                )
                .into());
        }
        hull.sensors.push(sensor);
    }
    Ok(hull)
}

/// Exactly one of `x_m` / `aft_of_fp`, turned into x from midship.
pub(crate) fn position(
    src: &SourceText,
    lpp: f64,
    table: &Spanned<impl Sized>,
    x_m: &Option<Spanned<f64>>,
    aft_of_fp: &Option<Spanned<f64>>,
) -> Result<f64, InputError> {
    match (x_m, aft_of_fp) {
        (Some(x), None) => in_range(src, x, -1.5 * lpp, 1.5 * lpp, "x_m"),
        (None, Some(f)) => Ok(station_x(lpp, in_range(src, f, -0.5, 1.5, "aft_of_fp")?)),
        (Some(x), Some(_)) => Err(src.error(x, "give either x_m or aft_of_fp, not both")),
        (None, None) => Err(src.error(table, "missing position: give x_m or aft_of_fp")),
    }
}

fn stations_from_toml(
    src: &SourceText,
    lpp: f64,
    raw: &Spanned<Vec<Spanned<StationRaw>>>,
) -> Result<Vec<Station>> {
    if raw.get_ref().len() < 2 {
        return Err(src.error(raw, "a hull needs at least two stations").into());
    }
    let mut out = Vec::with_capacity(raw.get_ref().len());
    for st in raw.get_ref() {
        let s = st.get_ref();
        let x = position(src, lpp, st, &s.x_m, &s.aft_of_fp)?;
        let points: Vec<[f64; 2]> = s.points.get_ref().iter().map(|p| p.get_ref().0).collect();
        check_section(&points).map_err(|f| {
            if s.points.get_ref().is_empty() {
                src.error(&s.points, f.message)
            } else {
                src.error(
                    &s.points.get_ref()[f.point.min(points.len() - 1)],
                    f.message,
                )
            }
        })?;
        out.push((x, points, st.span()));
    }
    order_stations(out, |span, msg| src.error_at(span, msg).into())
}

/// Stations must run monotonically (aft to forward, or forward to aft as the slamming literature lists
/// them); the result is sorted aft to forward.
pub(crate) fn order_stations<L: Clone>(
    mut stations: Vec<(f64, Vec<[f64; 2]>, L)>,
    err: impl Fn(L, String) -> Error,
) -> Result<Vec<Station>> {
    if stations.len() > MAX_STATIONS {
        let at = stations[MAX_STATIONS].2.clone();
        return Err(err(
            at,
            format!(
                "{} stations, more than the {MAX_STATIONS} a hull may have",
                stations.len()
            ),
        ));
    }
    if let Some(s) = stations.iter().find(|s| s.1.len() > MAX_POINTS_PER_STATION) {
        return Err(err(
            s.2.clone(),
            format!(
                "the station at x = {:.4} m has {} points, more than the {MAX_POINTS_PER_STATION} a station may have",
                s.0,
                s.1.len()
            ),
        ));
    }
    let ascending = stations.len() < 2 || stations[1].0 > stations[0].0;
    for k in 1..stations.len() {
        let (prev, cur) = (stations[k - 1].0, stations[k].0);
        if cur == prev {
            return Err(err(
                stations[k].2.clone(),
                format!(
                    "two stations at the same position x = {cur:.6} m: each station must have its own x"
                ),
            ));
        }
        let ok = if ascending { cur > prev } else { cur < prev };
        if !ok {
            let dir = if ascending {
                "aft to forward"
            } else {
                "forward to aft"
            };
            return Err(err(
                stations[k].2.clone(),
                format!(
                    "stations out of order: x = {cur:.4} m after x = {prev:.4} m, but the first stations run {dir} (each station must be strictly further in that direction)"
                ),
            ));
        }
    }
    if !ascending {
        stations.reverse();
    }
    Ok(stations
        .into_iter()
        .map(|(x, points, _)| Station {
            x,
            section: Section::new(points),
        })
        .collect())
}

fn loadings(
    src: &SourceText,
    lpp: f64,
    depth: f64,
    raw: &Spanned<Vec<Spanned<LoadingRaw>>>,
) -> Result<Vec<LoadingCondition>> {
    if raw.get_ref().is_empty() {
        return Err(src
            .error(raw, "at least one [[loading]] condition is needed")
            .into());
    }
    let mut names = HashSet::new();
    let mut out = Vec::new();
    for l in raw.get_ref() {
        let r = l.get_ref();
        let name = clean_name(r.name.get_ref());
        if name.is_empty() {
            return Err(src.error(&r.name, "loading name must not be empty").into());
        }
        if !names.insert(name.clone()) {
            return Err(src
                .error(&r.name, format!("loading name '{name}' is used twice"))
                .into());
        }
        // One end may be just out of the water (draft 0) under heavy trim; the mean draft must be positive.
        let draft_fp = non_negative(src, &r.draft_fp_m, "draft_fp_m")?;
        let draft_ap = non_negative(src, &r.draft_ap_m, "draft_ap_m")?;
        if draft_fp + draft_ap <= 0.0 {
            return Err(src
                .error(
                    &r.draft_fp_m,
                    "the drafts at FP and AP are both zero: the ship is not afloat",
                )
                .into());
        }
        for (d, v) in [(&r.draft_fp_m, draft_fp), (&r.draft_ap_m, draft_ap)] {
            if v > depth {
                return Err(src
                    .error(
                        d,
                        format!("draft {v} m is above the deck (depth {depth} m)"),
                    )
                    .into());
            }
        }
        let rho = match &r.water_density_kg_m3 {
            Some(v) => in_range(src, v, RHO_RANGE.0, RHO_RANGE.1, "water_density_kg_m3")?,
            None => 1025.0,
        };
        let displacement_kg = match &r.displacement_kg {
            Some(v) => Some(positive(src, v, "displacement_kg")?),
            None => None,
        };
        // Checked against the buoyancy once the hull is assembled (check_immersed).
        let lcg = match &r.lcg_m {
            Some(v) => Some(in_range(src, v, -0.5 * lpp, 0.5 * lpp, "lcg_m")?),
            None => None,
        };
        let kg = positive(src, &r.kg_m, "kg_m")?;
        if kg > 2.0 * depth {
            return Err(src
                .error(
                    &r.kg_m,
                    format!("kg_m = {kg} m is more than twice the depth ({depth} m)"),
                )
                .into());
        }
        let k_yy = match (&r.k_yy_m, &r.k_yy_over_lpp) {
            (Some(k), None) => at_most(src, k, 0.5 * lpp, "k_yy_m", "half of Lpp")?,
            (None, Some(f)) => at_most(src, f, 0.5, "k_yy_over_lpp", "half of Lpp")? * lpp,
            (Some(k), Some(_)) => {
                return Err(src
                    .error(k, "give either k_yy_m or k_yy_over_lpp, not both")
                    .into());
            }
            (None, None) => {
                return Err(src
                    .error(
                        l,
                        "missing pitch radius of gyration: give k_yy_m or k_yy_over_lpp",
                    )
                    .into());
            }
        };
        out.push(LoadingCondition {
            name,
            draft_fp,
            draft_ap,
            rho,
            displacement_kg,
            lcg,
            kg,
            k_yy,
        });
    }
    Ok(out)
}

/// A finite number ≥ 0.
fn non_negative(src: &SourceText, v: &Spanned<f64>, what: &str) -> Result<f64, InputError> {
    let x = finite(src, v, what)?;
    if x < 0.0 {
        return Err(src.error(
            v,
            format!(
                "{what} must not be negative (z is up from the baseline), got {}",
                num(x)
            ),
        ));
    }
    Ok(x)
}

/// A positive number no larger than `max` (`why` names the limit).
fn at_most(
    src: &SourceText,
    v: &Spanned<f64>,
    max: f64,
    what: &str,
    why: &str,
) -> Result<f64, InputError> {
    let x = positive(src, v, what)?;
    if x > max {
        return Err(src.error(
            v,
            format!("{what} = {} is more than {why} ({})", num(x), num(max)),
        ));
    }
    Ok(x)
}

/// The offsets must reach the local waterline at every station: a contour that stops below the water with
/// some breadth leaves the immersed hull undefined. (A contour that closes on the centreline below the
/// water, such as a section through a bulb forward of the stem, is complete.)
fn check_offsets_reach_waterline(
    src: &SourceText,
    hull: &Hull,
    raw: &Spanned<LoadingRaw>,
) -> Result<()> {
    let r = raw.get_ref();
    let name = clean_name(r.name.get_ref());
    let name = name.as_str();
    let l = hull.loading(Some(name))?;
    for st in &hull.stations {
        let zw = l.draft_at(st.x, hull.lpp);
        let last = st.section.points[st.section.points.len() - 1];
        if last[1] < zw - 1e-9 && last[0] > 1e-9 {
            let at = if st.x >= 0.0 {
                &r.draft_fp_m
            } else {
                &r.draft_ap_m
            };
            return Err(src
                .error(
                    at,
                    format!(
                        "loading '{name}': the waterline (z = {zw:.4} m) is above the top of the offsets of the station at x = {:.4} m, which end at z = {:.4} m with half-breadth {:.4} m; give that station's contour up to the deck",
                        st.x, last[1], last[0]
                    ),
                )
                .into());
        }
    }
    Ok(())
}

/// The loading's hydrostatics, checked: the hull is immersed, pierces the water, and floats near the
/// given displacement.
fn check_immersed(
    src: &SourceText,
    hull: &Hull,
    raw: &Spanned<LoadingRaw>,
) -> Result<super::Hydrostatics> {
    let r = raw.get_ref();
    let name = clean_name(r.name.get_ref());
    let name = name.as_str();
    let l = hull.loading(Some(name))?;
    let hs = super::Hydrostatics::compute(hull, l);
    if hs.volume <= 0.0 {
        return Err(src
            .error(
                &r.draft_fp_m,
                format!("loading '{name}': the hull is not immersed at these drafts (the keel is above the waterline everywhere)"),
            )
            .into());
    }
    if hs.awp <= 0.0 {
        return Err(src
            .error(
                &r.draft_fp_m,
                format!("loading '{name}': the waterline does not cut the hull (waterplane area 0): the hull must pierce the water surface"),
            )
            .into());
    }
    if let (Some(m), Some(v)) = (l.displacement_kg, &r.displacement_kg) {
        let mismatch = (m - hs.displacement_kg) / hs.displacement_kg;
        if mismatch.abs() > MASS_BUOYANCY_TOLERANCE {
            return Err(src
                .error(
                    v,
                    format!(
                        "loading '{name}': displacement_kg = {} kg differs by {:+.1} % from the buoyancy at these drafts ({:.1} kg; more than {:.0} % means the ship does not float at these drafts): check the drafts, water density and units (kg, not tonnes)",
                        num(m),
                        100.0 * mismatch,
                        hs.displacement_kg,
                        100.0 * MASS_BUOYANCY_TOLERANCE
                    ),
                )
                .into());
        }
    }
    Ok(hs)
}

fn sensor(src: &SourceText, hull: &Hull, s: &Spanned<SensorRaw>) -> Result<Sensor> {
    let r = s.get_ref();
    let name = clean_name(r.name.get_ref());
    if name.is_empty() {
        return Err(src.error(&r.name, "sensor name must not be empty").into());
    }
    let x = position(src, hull.lpp, s, &r.x_m, &r.aft_of_fp)?;
    let (xa, xf) = hull.x_range();
    if x < xa - 1e-9 || x > xf + 1e-9 {
        let at = r
            .x_m
            .as_ref()
            .or(r.aft_of_fp.as_ref())
            .expect("position given");
        return Err(src
            .error(
                at,
                format!(
                    "sensor '{name}' at x = {x:.4} m is outside the offsets ({xa:.4} to {xf:.4} m)"
                ),
            )
            .into());
    }
    let diameter = positive(src, &r.diameter_m, "diameter_m")?;
    let section = hull.section_at(x)?;
    let girth_total = section.girth();
    if diameter > girth_total {
        return Err(src
            .error(
                &r.diameter_m,
                format!(
                    "sensor '{name}': diameter_m = {} m is larger than the whole section contour at x = {x:.4} m (girth {girth_total:.4} m)",
                    num(diameter)
                ),
            )
            .into());
    }
    let (girth, position) = match (&r.girth_m, &r.y_m, &r.z_m) {
        (Some(g), None, None) => {
            let gv = finite(src, g, "girth_m")?;
            if !(0.0..=girth_total).contains(&gv) {
                return Err(src
                    .error(
                        g,
                        format!(
                            "sensor '{name}': girth_m = {} m is not on the section contour at x = {x:.4} m, which runs from girth 0 (keel) to {girth_total:.4} m (deck)",
                            num(gv)
                        ),
                    )
                    .into());
            }
            (gv, section.point_at_girth(gv))
        }
        (None, Some(y), Some(z)) => {
            let q = [finite(src, y, "y_m")?, finite(src, z, "z_m")?];
            let (g, dist) = section.project(q);
            let allowed = (0.5 * diameter).max(1e-3);
            if dist > allowed {
                return Err(src
                    .error(
                        y,
                        format!(
                            "sensor '{name}' at (y, z) = ({}, {}) m is {:.1} mm off the section contour (allowed: {:.1} mm, half its diameter)",
                            q[0],
                            q[1],
                            dist * 1e3,
                            allowed * 1e3
                        ),
                    )
                    .into());
            }
            (g, section.point_at_girth(g))
        }
        (None, Some(y), None) => {
            return Err(src.error(y, "y_m needs z_m as well").into());
        }
        (None, None, Some(z)) => {
            return Err(src.error(z, "z_m needs y_m as well").into());
        }
        (Some(g), _, _) => {
            return Err(src
                .error(
                    g,
                    "give the sensor position either as girth_m or as y_m and z_m, not both",
                )
                .into());
        }
        (None, None, None) => {
            return Err(src
                .error(
                    s,
                    "missing sensor position on the section: give girth_m or y_m and z_m",
                )
                .into());
        }
    };
    Ok(Sensor {
        name,
        x,
        girth,
        position,
        diameter,
    })
}
