//! How a station is given, the same way in every command: `--station F` (fraction of Lpp aft of the FP,
//! as the slamming literature gives it) or `--x-m X` (m from midship, positive forward). The spellings of
//! earlier releases (`--aft-of-fp`, `--at`, `--x`) are accepted as hidden aliases for one release.

use clap::Args;
use slamtool::hull::Hull;
use slamtool::{Error, Result};

/// One station.
#[derive(Debug, Clone, Args)]
#[group(required = true, multiple = false)]
pub struct StationArg {
    /// Station as a fraction of Lpp aft of the forward perpendicular (0 is the FP, 0.1 is x = 0.4 Lpp).
    #[arg(
        long,
        value_name = "F",
        alias = "aft-of-fp",
        allow_negative_numbers = true
    )]
    pub station: Option<f64>,
    /// Station as x in m from midship, positive forward (aft of midship is negative, e.g. --x-m -1.2).
    #[arg(long, value_name = "X", alias = "x", allow_negative_numbers = true)]
    pub x_m: Option<f64>,
}

/// A resolved station: x, how the user gave it, and any sanity warning.
#[derive(Debug, Clone)]
pub struct Resolved {
    /// x in m from midship.
    pub x: f64,
    /// The option as given, for messages ("--station 0.1").
    pub given: String,
    /// Set when the station lies outside the perpendiculars (still within the offsets).
    pub warning: Option<String>,
}

impl StationArg {
    /// x of the station on `hull`; an error if it is not a finite number or outside the offsets.
    pub fn resolve(&self, hull: &Hull) -> Result<Resolved> {
        let (x, given) = match (self.station, self.x_m) {
            (Some(f), None) => (hull.station_x(f), format!("--station {f}")),
            (None, Some(x)) => (x, format!("--x-m {x}")),
            _ => {
                return Err(Error::Invalid(
                    "give the station as --station F (fraction of Lpp aft of the FP) or --x-m X (m from midship)"
                        .into(),
                ));
            }
        };
        check(hull, x, given)
    }
}

/// Check a station at `x` (given as `given`) against the hull.
pub fn check(hull: &Hull, x: f64, given: String) -> Result<Resolved> {
    if !x.is_finite() {
        return Err(Error::Invalid(format!(
            "{given}: the station must be a finite number"
        )));
    }
    hull.section_at(x)
        .map_err(|e| Error::Invalid(format!("{given}: {e}")))?;
    let warning = outside_perpendiculars(hull, x, &given);
    Ok(Resolved { x, given, warning })
}

/// A warning when x lies ahead of the FP or aft of the AP.
pub fn outside_perpendiculars(hull: &Hull, x: f64, given: &str) -> Option<String> {
    let f = hull.aft_of_fp(x);
    if f < -1e-9 {
        Some(format!(
            "{given}: the station lies {:.3} m ahead of the FP (x = {x:.3} m), outside the hull between the perpendiculars",
            -f * hull.lpp
        ))
    } else if f > 1.0 + 1e-9 {
        Some(format!(
            "{given}: the station lies {:.3} m aft of the AP (x = {x:.3} m), outside the hull between the perpendiculars",
            (f - 1.0) * hull.lpp
        ))
    } else {
        None
    }
}

/// Stations given as lists, `--station F,..` and/or `--x-m X,..`, each checked against the hull (a station
/// outside the offsets is an error naming the option). Returns them in the order given, `--station` first,
/// as fractions of Lpp aft of the FP, each once (a repeat is dropped with a warning), with the warnings of
/// stations outside the perpendiculars.
pub fn resolve_list(hull: &Hull, stations: &[f64], x_m: &[f64]) -> Result<(Vec<f64>, Vec<String>)> {
    let mut at = Vec::new();
    let mut warnings = Vec::new();
    let given = stations
        .iter()
        .map(|&f| (hull.station_x(f), format!("--station {f}")))
        .chain(x_m.iter().map(|&x| (x, format!("--x-m {x}"))));
    for (x, g) in given {
        let r = check(hull, x, g)?;
        warnings.extend(r.warning);
        // Rounded to 1e-9 Lpp, as the sensor stations are (x -> fraction is not exact in floating point).
        let f = (hull.aft_of_fp(r.x) * 1e9).round() / 1e9;
        if at.contains(&f) {
            warnings.push(duplicate(&r.given, f));
        } else {
            at.push(f);
        }
    }
    Ok((at, warnings))
}

/// The note for a station given twice: it is computed once.
pub fn duplicate(given: &str, f: f64) -> String {
    format!(
        "{given}: station {f} (fraction of Lpp aft of the FP) is given more than once; it is computed once"
    )
}
