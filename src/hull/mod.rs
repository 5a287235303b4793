//! Hull definition: offsets, loading conditions and pressure sensors read from `hull.toml` (or a CSV
//! offsets table), validated with located errors; shape-preserving section interpolation; hydrostatics
//! and form coefficients.
//!
//! Axes: x forward from midship (FP at +Lpp/2, AP at −Lpp/2), y to port (half-breadth), z up from the
//! baseline. A station given as a fraction f of Lpp aft of the FP sits at x = Lpp/2 − f·Lpp.

pub mod body_plan;
mod chunked;
pub mod generate;
mod hydrostatics;
pub mod import;
mod interpolate;
mod load;
mod offsets_csv;
mod schema;
mod section;
pub(crate) mod validate;

use std::path::{Path, PathBuf};

pub use hydrostatics::{Hydrostatics, MassProperties, SectionalArea};
pub use section::{Section, SectionProperties};

use crate::error::{Error, Result};
use crate::input::SourceText;
pub(crate) use interpolate::SectionInterpolator;

/// One offset station.
#[derive(Debug, Clone, PartialEq)]
pub struct Station {
    /// Longitudinal position, m from midship, positive forward.
    pub x: f64,
    pub section: Section,
}

/// A loading condition: floating position and mass properties.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadingCondition {
    pub name: String,
    /// Draft above baseline at the forward perpendicular, m.
    pub draft_fp: f64,
    /// Draft above baseline at the aft perpendicular, m.
    pub draft_ap: f64,
    /// Water density, kg/m³.
    pub rho: f64,
    /// Displacement mass if the file gives one, kg (otherwise it equals the buoyancy at these drafts).
    pub displacement_kg: Option<f64>,
    /// Longitudinal centre of gravity, m from midship, if given (otherwise LCG = LCB).
    pub lcg: Option<f64>,
    /// Centre of gravity above baseline, m.
    pub kg: f64,
    /// Pitch radius of gyration about the centre of gravity, m.
    pub k_yy: f64,
}

impl LoadingCondition {
    /// Local draft (waterline height above baseline) at x for a hull of length `lpp`, linear between the
    /// perpendiculars: T(x) = T_AP + (T_FP − T_AP)(x + Lpp/2)/Lpp.
    pub fn draft_at(&self, x: f64, lpp: f64) -> f64 {
        self.draft_ap + (self.draft_fp - self.draft_ap) * (x + 0.5 * lpp) / lpp
    }

    /// Mean draft (at midship), m.
    pub fn mean_draft(&self) -> f64 {
        0.5 * (self.draft_fp + self.draft_ap)
    }

    /// Trim by the stern (T_AP − T_FP), m.
    pub fn trim_by_stern(&self) -> f64 {
        self.draft_ap - self.draft_fp
    }
}

/// A pressure sensor (or pressure panel) on the hull surface.
#[derive(Debug, Clone, PartialEq)]
pub struct Sensor {
    pub name: String,
    /// Station, m from midship.
    pub x: f64,
    /// Girth from the keel along the section contour, m.
    pub girth: f64,
    /// (y, z) on the section contour, m.
    pub position: [f64; 2],
    /// Physical diameter or panel width, m.
    pub diameter: f64,
}

/// A validated hull.
#[derive(Debug, Clone)]
pub struct Hull {
    pub name: String,
    pub description: Option<String>,
    /// Length between perpendiculars, m.
    pub lpp: f64,
    /// Deck height above baseline, m.
    pub depth: f64,
    /// Stations, sorted aft to forward.
    pub stations: Vec<Station>,
    /// Loading conditions; the first is the default.
    pub loadings: Vec<LoadingCondition>,
    pub sensors: Vec<Sensor>,
    /// The file the hull was read from.
    pub source: PathBuf,
    /// The offsets CSV file the stations came from, when the hull file names one (`[offsets_csv]`).
    pub offsets_file: Option<PathBuf>,
    interpolator: SectionInterpolator,
    /// The hydrostatics of each loading, computed when the hull was read (its checks need them).
    hydrostatics: Vec<Hydrostatics>,
}

impl Hull {
    /// Read and validate a hull file.
    pub fn from_file(path: &Path) -> Result<Self> {
        let src = SourceText::read(path)?;
        Self::from_source(&src)
    }

    /// Every file the hull was read from: the hull file and, if any, its offsets CSV (for provenance).
    pub fn input_files(&self) -> Vec<&Path> {
        std::iter::once(self.source.as_path())
            .chain(self.offsets_file.as_deref())
            .collect()
    }

    /// Validate a hull from text (the path is used for error messages and relative CSV files).
    pub fn from_source(src: &SourceText) -> Result<Self> {
        load::hull_from_source(src)
    }

    /// x of a station given as a fraction of Lpp aft of the FP.
    pub fn station_x(&self, aft_of_fp: f64) -> f64 {
        station_x(self.lpp, aft_of_fp)
    }

    /// Fraction of Lpp aft of the FP of a longitudinal position x.
    pub fn aft_of_fp(&self, x: f64) -> f64 {
        (0.5 * self.lpp - x) / self.lpp
    }

    /// Extent of the offsets, (x_aft, x_fwd).
    pub fn x_range(&self) -> (f64, f64) {
        (self.stations[0].x, self.stations[self.stations.len() - 1].x)
    }

    /// The section at any x within the offsets, by shape-preserving interpolation between stations
    /// (the given section itself at a station).
    pub fn section_at(&self, x: f64) -> Result<Section> {
        let (a, f) = self.x_range();
        if !(x >= a - 1e-9 && x <= f + 1e-9) {
            return Err(Error::Invalid(format!(
                "x = {x:.4} m is outside the hull's offsets ({a:.4} m to {f:.4} m from midship)"
            )));
        }
        Ok(self.interpolator.section_at(&self.stations, x))
    }

    /// The sections at `xs`, all between stations `k` and `k + 1` (as [`Hull::section_at`] at each, with
    /// the interpolation work of the interval shared).
    pub(crate) fn sections_in_interval(&self, k: usize, xs: &[f64]) -> Vec<Section> {
        self.interpolator
            .sections_in_interval(&self.stations, k, xs)
    }

    /// The hydrostatics of `loading`: for one of the hull's own loadings those computed when the file was
    /// read (a hull of many stations need not be integrated twice), for any other loading computed now.
    /// (A hull read from a file is not meant to have its stations changed afterwards; after such a change
    /// use [`Hydrostatics::compute`].)
    pub fn hydrostatics(&self, loading: &LoadingCondition) -> Hydrostatics {
        match self.loadings.iter().position(|l| l == loading) {
            Some(i) if i < self.hydrostatics.len() => self.hydrostatics[i].clone(),
            _ => Hydrostatics::compute(self, loading),
        }
    }

    /// A loading condition by name, or the first (default) one.
    pub fn loading(&self, name: Option<&str>) -> Result<&LoadingCondition> {
        match name {
            None => Ok(&self.loadings[0]),
            Some(n) => self.loadings.iter().find(|l| l.name == n).ok_or_else(|| {
                let names: Vec<&str> = self.loadings.iter().map(|l| l.name.as_str()).collect();
                Error::Invalid(format!(
                    "{}: no loading condition named '{n}' (the file has: {})",
                    self.source.display(),
                    names.join(", ")
                ))
            }),
        }
    }
}

/// x = Lpp/2 − f·Lpp for a station a fraction f of Lpp aft of the FP.
pub fn station_x(lpp: f64, aft_of_fp: f64) -> f64 {
    0.5 * lpp - aft_of_fp * lpp
}
