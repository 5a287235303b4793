//! Seakeeping: strip theory for heave and pitch in head seas, relative motion and velocity along the hull,
//! and slamming statistics (Veen 2010, ch. 3 and 6; design notes in `physics.md` sections 1-2).
//!
//! Axes as in the crate docs: x forward from midship, z up, pitch positive bow down (Salvesen, Tuck &
//! Faltinsen 1970). Complex amplitudes use the time factor e^{i w_e t} with w_e the encounter frequency and
//! phases relative to the wave crest at midship.
//!
//! The core works on its own input type [`ShipModel`] (stations with wetted half sections in the waterline
//! frame); [`ShipModel::from_hull`] builds one from a `hull::Hull` and a loading condition.

pub mod analysis;
pub mod entry_definitions;
mod from_hull;
pub mod rao;
pub mod relative_motion;
pub mod section;
pub mod slamming;
pub mod strip_table;
pub mod strip_theory;
pub mod wave_readings;

use crate::error::{Error, Result};
use section::HalfSection;

/// One strip: station position and its wetted half section (None where the station is dry).
#[derive(Debug, Clone)]
pub struct StripSection {
    /// Station position x (m, forward of midship).
    pub x: f64,
    /// Wetted half contour in the waterline frame, keel to waterline.
    pub section: Option<HalfSection>,
}

/// Everything the strip theory needs about a ship in one loading condition.
#[derive(Debug, Clone)]
pub struct ShipModel {
    /// Length between perpendiculars (m).
    pub lpp: f64,
    /// Water density (kg/m^3).
    pub rho: f64,
    /// Gravity (m/s^2).
    pub g: f64,
    /// Mass (kg).
    pub mass: f64,
    /// Longitudinal centre of gravity x_G (m, forward of midship).
    pub xg: f64,
    /// Vertical centre of gravity in the waterline frame (m, above the waterline; usually negative).
    pub zg: f64,
    /// Pitch radius of gyration about G (m).
    pub k_yy: f64,
    /// Stations, sorted aft to forward.
    pub stations: Vec<StripSection>,
}

impl ShipModel {
    /// Check the model: positive particulars, at least three stations in increasing x, some wetted.
    pub fn validate(&self) -> Result<()> {
        for (v, what) in [
            (self.lpp, "Lpp"),
            (self.rho, "water density"),
            (self.g, "gravity"),
            (self.mass, "mass"),
            (self.k_yy, "pitch radius of gyration"),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(Error::Invalid(format!(
                    "{what} must be a positive number, got {v}"
                )));
            }
        }
        if !self.xg.is_finite() || !self.zg.is_finite() {
            return Err(Error::Invalid("centre of gravity must be finite".into()));
        }
        if self.stations.len() < 3 {
            return Err(Error::Invalid(
                "strip theory needs at least three stations".into(),
            ));
        }
        if self
            .stations
            .windows(2)
            .any(|w| w[1].x.partial_cmp(&w[0].x) != Some(std::cmp::Ordering::Greater))
        {
            return Err(Error::Invalid(
                "stations must be sorted by increasing x without repeats".into(),
            ));
        }
        if self.stations.iter().all(|s| s.section.is_none()) {
            return Err(Error::Invalid("no station is wetted".into()));
        }
        Ok(())
    }

    fn integrate(&self, f: impl Fn(&HalfSection) -> f64) -> f64 {
        let v: Vec<f64> = self
            .stations
            .iter()
            .map(|s| s.section.as_ref().map_or(0.0, &f))
            .collect();
        self.stations
            .windows(2)
            .zip(v.windows(2))
            .map(|(s, v)| 0.5 * (s[1].x - s[0].x) * (v[0] + v[1]))
            .sum()
    }

    /// Displaced volume by strips (m^3).
    pub fn volume(&self) -> f64 {
        self.integrate(|s| s.area())
    }

    /// Vertical centre of buoyancy in the waterline frame (m, negative below the waterline).
    pub fn z_buoyancy(&self) -> f64 {
        self.integrate(|s| s.area() * s.centroid_z()) / self.volume()
    }

    /// Longitudinal centre of buoyancy (m).
    pub fn x_buoyancy(&self) -> f64 {
        let v: Vec<f64> = self
            .stations
            .iter()
            .map(|s| s.x * s.section.as_ref().map_or(0.0, |h| h.area()))
            .collect();
        let m: f64 = self
            .stations
            .windows(2)
            .zip(v.windows(2))
            .map(|(s, v)| 0.5 * (s[1].x - s[0].x) * (v[0] + v[1]))
            .sum();
        m / self.volume()
    }

    /// Waterplane area by strips (m^2).
    pub fn waterplane_area(&self) -> f64 {
        self.integrate(|s| s.beam())
    }

    /// The wetted half section at station index `i`.
    pub fn draft_at_station(&self, i: usize) -> f64 {
        self.stations[i].section.as_ref().map_or(0.0, |s| s.draft())
    }
}
