//! From relative motion to water entry (the 2D+t join, Veen 2010 ch. 6): the seakeeping station of a
//! hull section (its local draft in the loading), the 2D section that enters the water, and the
//! entry-velocity history after keel entry as the prescribed motion of a 2D run; and, where the keel stays
//! in the water, the flare event that starts at least immersion ([`flare`]).
//!
//! Frames: the hull's sections are given above the baseline; the 2D water-entry frame has the keel at
//! the origin at the instant of keel entry and the undisturbed local water surface at z = 0 (see
//! [`crate::sph::body`]). The relative motion s(t) and velocity come from strip theory
//! ([`crate::seakeeping::relative_motion`]); the downward entry velocity is V = -Ds/Dt.

pub mod default_sensors;
pub mod flare;

use crate::error::{Error, Result};
use crate::hull::{Hull, LoadingCondition};
use crate::seakeeping::analysis::Station;
use crate::seakeeping::relative_motion::KeelEntry;
use crate::seakeeping::section::HalfSection;
use crate::sph::body::Section;
use crate::sph::{MotionSpec, SensorSpec};

/// The seakeeping station at `aft_of_fp` (fraction of Lpp aft of the FP) in `loading`: its local draft
/// from the wetted half section and its keel-to-deck height. A station whose keel is above the calm
/// waterline (a forefoot under a raked stem, a rising keel) is a dry station with a negative draft: the
/// water reaches its keel when the relative motion exceeds the keel's height above the waterline
/// ([`Station::dry`]); a section wholly above the waterline, deck included, is an error.
pub fn seakeeping_station(
    hull: &Hull,
    loading: &LoadingCondition,
    aft_of_fp: f64,
) -> Result<Station> {
    if !aft_of_fp.is_finite() {
        return Err(Error::Invalid(format!(
            "a station is a fraction of Lpp aft of the FP, got {aft_of_fp}"
        )));
    }
    let x = hull.station_x(aft_of_fp);
    let sec = hull.section_at(x)?;
    let z_w = loading.draft_at(x, hull.lpp);
    let mut pts: Vec<[f64; 2]> = Vec::new();
    for q in sec.wetted(z_w).iter().map(|p| [p[0], p[1] - z_w]) {
        if pts
            .last()
            .is_none_or(|l: &[f64; 2]| (l[0] - q[0]).hypot(l[1] - q[1]) > 1e-9)
        {
            pts.push(q);
        }
    }
    let height = sec.deck_z() - sec.keel_z();
    let mut st = if pts.len() < 2 {
        // The keel is above the calm waterline: a dry station, which the relative motion wets.
        let clearance = sec.keel_z() - z_w;
        if clearance >= height {
            return Err(Error::Invalid(format!(
                "station {aft_of_fp} Lpp aft of the FP: the whole section (keel {:.3} m, deck {:.3} m above \
                 the baseline) is above the calm waterline at {z_w:.3} m at loading '{}'",
                sec.keel_z(),
                sec.deck_z(),
                loading.name
            )));
        }
        Station::dry(hull.lpp, aft_of_fp, clearance.max(0.0), height)
    } else {
        Station::new(hull.lpp, aft_of_fp, &HalfSection::new(pts)?, height)
    };
    st.keel_slope = crate::seakeeping::entry_definitions::keel_slope(hull, loading, x)?;
    Ok(st)
}

/// The stations that carry sensors in the hull file, as fractions of Lpp aft of the FP (sorted, without
/// repeats), or 0.05, 0.1, 0.15 and 0.2 Lpp when the hull has no sensors.
pub fn sensor_stations(hull: &Hull) -> Vec<f64> {
    // Rounded to 1e-9 Lpp: x -> fraction of Lpp is not exact in floating point (0.093 -> 0.09299999999999997).
    let mut at: Vec<f64> = hull
        .sensors
        .iter()
        .map(|s| (hull.aft_of_fp(s.x) * 1e9).round() / 1e9)
        .collect();
    at.sort_by(f64::total_cmp);
    at.dedup_by(|p, q| (*p - *q).abs() < 1e-6);
    if at.is_empty() {
        at = vec![0.05, 0.1, 0.15, 0.2];
    }
    at
}

/// The 2D section that enters the water at x (m from midship): the hull section from the keel to the
/// deck edge, keel at the origin.
pub fn entry_section(hull: &Hull, x: f64) -> Result<Section> {
    let hs = hull.section_at(x)?;
    Section::from_half_points(hs.points.clone())
}

/// The hull's pressure sensors on the station at x, as sensors of a 2D run: girth from the keel along
/// the contour and physical diameter.
pub fn station_sensors(hull: &Hull, x: f64) -> Vec<SensorSpec> {
    hull.sensors
        .iter()
        .filter(|s| (s.x - x).abs() < 1e-6)
        .map(|s| SensorSpec {
            name: s.name.clone(),
            s_m: s.girth,
            width_m: s.diameter,
        })
        .collect()
}

/// The prescribed motion of a 2D run: the downward entry velocity from keel entry until it reverses
/// (or the keel is as deep as the profile goes), as a table [t_s, v_m_per_s].
pub fn entry_motion(entry: &KeelEntry) -> MotionSpec {
    entry_motion_of(&entry.samples)
}

/// The prescribed motion of a 2D run from entry-velocity samples (of strip theory or of a measured record,
/// [`crate::forcing`]): [t since keel entry, max(V, 0)].
pub fn entry_motion_of(samples: &[crate::seakeeping::relative_motion::EntrySample]) -> MotionSpec {
    MotionSpec::Prescribed {
        table: samples.iter().map(|s| [s.t, s.velocity.max(0.0)]).collect(),
    }
}

/// Half-width of the flat part of a section's keel (m): the run of contour points from the keel at the
/// keel's height (0 for a keel with deadrise).
pub fn flat_keel_half_width(points: &[[f64; 2]]) -> f64 {
    let Some(z0) = points.first().map(|p| p[1]) else {
        return 0.0;
    };
    let tol = 1e-9
        * points
            .iter()
            .map(|p| p[0].abs() + p[1].abs())
            .fold(1.0, f64::max);
    points
        .iter()
        .take_while(|p| (p[1] - z0).abs() <= tol)
        .map(|p| p[0])
        .fold(0.0, f64::max)
}

/// The warning for a station with a flat keel at least 5 % of its largest half-breadth wide (None
/// otherwise): air trapped under a flat bottom cushions the impact, which the single-phase models do not
/// represent (Veen 2010 s. 6.3: SPH about twice Ochi's measured peaks at the flat 0.174 Lpp section).
pub fn air_cushion_warning(aft_of_fp: f64, points: &[[f64; 2]]) -> Option<String> {
    significant_flat_keel(points).map(|flat| {
        let mut w = format!(
            "station {aft_of_fp} Lpp has a flat keel (half-width {flat:.4} m): its bottom impact is \
             acoustic, which single-phase SPH with an artificial sound speed does not compute, and the \
             analytic models give no peak on the flat (their pressure only falls from the flat keel's \
             singular start), so the panels on the flat have no design value from this tool; the \
             water-hammer pressure rho c_w V is the upper bound of an impact without air, and air trapped \
             under the flat bottom cushions the real impact, which needs a two-phase model (Veen 2010 s. \
             6.3: single-phase SPH read about twice Ochi's measured peaks at his flat section)"
        );
        if let Some(beta) = deadrise_beyond_flat_deg(points, flat)
            && beta < LOW_DEADRISE_DEG
        {
            w += &format!(
                "; beyond the flat the contour starts at {beta:.1} deg of deadrise, below \
                 {LOW_DEADRISE_DEG:.0} deg, where air cushions the impact too, so the water-only peaks of \
                 the panels there (Wagner-type pressures grow as the cotangent of the deadrise squared) \
                 over-state it"
            );
        }
        w
    })
}

/// The statement that replaces [`air_cushion_warning`] when the station's SPH runs have air (`--air on`,
/// or `auto`, which turns air on for every flat keel): None without a flat keel.
pub fn air_cushion_statement(aft_of_fp: f64, points: &[[f64; 2]], choice: &str) -> Option<String> {
    significant_flat_keel(points).map(|flat| {
        format!(
            "station {aft_of_fp} Lpp has a flat keel (half-width {flat:.4} m): its SPH runs have air as a \
             second phase (--air {choice}), and the peaks of the panels on the flat are those of the \
             air-cushioned impact the two-phase run computes, but they are not design values: on a flat \
             keel the two-phase peak grows with the water's artificial sound speed (doubling c0 raised it by \
             half to four fifths in the measurements of docs/guide/air.md), so it measures the numerical \
             water's compressibility more than the cushion; the panels on the flat keep no design value, \
             the water-hammer pressure rho c_w V stays the upper bound, and the analytic models give no \
             peak there"
        )
    })
}

/// The half-width (m) of a flat keel that the warning and the statement name: a flat at least 5 % of the
/// contour's widest half-breadth (narrower flats are a keel plate's rounding, not a flat bottom).
fn significant_flat_keel(points: &[[f64; 2]]) -> Option<f64> {
    let flat = flat_keel_half_width(points);
    let widest = points.iter().map(|p| p[0]).fold(0.0, f64::max);
    (flat > 0.0 && flat >= 0.05 * widest).then_some(flat)
}

/// Deadrise below which the water meets the hull through a cushion of air (deg): about 15-20 deg
/// (the brief of the air-cushion issue; Veen 2010 s. 5 for Breder's 10 deg wedge); the lower end is used.
pub const LOW_DEADRISE_DEG: f64 = 15.0;

/// The deadrise (deg) of the first contour segment beyond a flat keel of half-width `flat`, `None` when
/// the contour has none.
fn deadrise_beyond_flat_deg(points: &[[f64; 2]], flat: f64) -> Option<f64> {
    let k = points.iter().position(|p| p[0] >= flat)?;
    let (a, b) = (points[k], *points.get(k + 1)?);
    let (dy, dz) = (b[0] - a[0], b[1] - a[1]);
    (dy > 0.0 || dz > 0.0).then(|| dz.atan2(dy).to_degrees())
}

#[cfg(test)]
mod air_cushion_tests {
    use super::{LOW_DEADRISE_DEG, air_cushion_warning, deadrise_beyond_flat_deg};

    #[test]
    fn a_low_deadrise_beyond_the_flat_is_named() {
        // flat keel, then a bilge starting at 10 deg
        let bilge = [
            [0.0, 0.0],
            [0.1, 0.0],
            [0.15, 0.05 * 10f64.to_radians().tan()],
            [0.2, 0.3],
        ];
        let b = deadrise_beyond_flat_deg(&bilge, 0.1).unwrap();
        assert!((b - 10.0).abs() < 1e-9, "{b}");
        assert!(
            air_cushion_warning(0.1, &bilge)
                .unwrap()
                .contains("below 15 deg")
        );
        // flat keel, then a 30 deg V: the flat alone is warned about
        let v = [
            [0.0, 0.0],
            [0.1, 0.0],
            [0.2, 0.1 * 30f64.to_radians().tan()],
            [0.3, 0.3],
        ];
        let b = deadrise_beyond_flat_deg(&v, 0.1).unwrap();
        assert!((b - 30.0).abs() < 1e-9 && b > LOW_DEADRISE_DEG);
        let w = air_cushion_warning(0.1, &v).unwrap();
        assert!(!w.contains("beyond the flat"), "{w}");
    }
}
