//! Two-dimensional hydrodynamics of one hull cross-section heaving on deep water: added mass a33(w),
//! damping b33(w) and the radiation potential on the contour (which the strip theory needs for the
//! diffraction force, Salvesen, Tuck & Faltinsen 1970).
//!
//! A section is given as its half contour in the waterline frame: points (y, z) from the keel on the
//! centreline (y = 0, z = -T) to the waterline (y = B/2, z = 0), z up. Both methods assume symmetry about
//! the centreline.
//!
//! * [`lewis`]: Lewis (1929) conformal mapping with the Ursell (1949) / Tasai (1959) multipole expansion
//!   (fast; exact for Lewis forms only).
//! * [`frank_close_fit`]: Frank (1967) pulsating-source close-fit panel method for arbitrary sections,
//!   with the irregular frequencies removed by an interior free-surface lid (the default).

pub mod frank_close_fit;
pub mod green;
pub mod lewis;

use nalgebra::Complex;
use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

/// Which 2D method computes the sectional coefficients.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SectionMethod {
    /// Lewis conformal mapping with Ursell-Tasai multipoles.
    Lewis,
    /// Frank close-fit pulsating sources (default: accurate for any section shape).
    #[default]
    #[serde(rename = "close-fit")]
    FrankCloseFit,
}

impl SectionMethod {
    /// The method's name in every output and on the command line: `close-fit` or `lewis`.
    pub fn name(self) -> &'static str {
        match self {
            SectionMethod::Lewis => "lewis",
            SectionMethod::FrankCloseFit => "close-fit",
        }
    }
}

/// A point on the contour where the radiation potential is known.
#[derive(Debug, Clone, Copy)]
pub struct BodySample {
    pub y: f64,
    pub z: f64,
    /// n_z ds on the half contour (normal into the fluid), so that int f n_z ds = 2 sum f nz_ds.
    pub nz_ds: f64,
    /// Heave radiation potential per unit heave velocity.
    pub phi: Complex<f64>,
}

/// Result of the heave radiation problem of one section at one frequency.
#[derive(Debug, Clone)]
pub struct Radiation {
    pub omega: f64,
    /// Added mass per unit length (kg/m).
    pub a33: f64,
    /// Damping per unit length (N s/m^2).
    pub b33: f64,
    pub samples: Vec<BodySample>,
}

impl Radiation {
    /// rho int psi3 n_z e^{kz} ds over the full contour: the diffraction integral of Salvesen, Tuck &
    /// Faltinsen (1970) with the exact e^{kz} decay of the incident wave over the section (Smith effect).
    pub fn diffraction_integral(&self, k: f64, rho: f64) -> Complex<f64> {
        self.samples
            .iter()
            .map(|s| s.phi * (2.0 * rho * (k * s.z).exp() * s.nz_ds))
            .sum()
    }

    /// The complex sectional coefficient Z = a33 - i b33 / w.
    pub fn z(&self) -> Complex<f64> {
        Complex::new(self.a33, -self.b33 / self.omega)
    }
}

/// Validated half contour of a section in the waterline frame.
#[derive(Debug, Clone, PartialEq)]
pub struct HalfSection {
    points: Vec<[f64; 2]>,
}

impl HalfSection {
    /// Check a half contour: at least two points, finite, starting on the centreline, ending on the waterline,
    /// all points at or below the waterline and at non-negative y, no zero-length segments.
    pub fn new(points: Vec<[f64; 2]>) -> Result<Self> {
        if points.len() < 2 {
            return Err(Error::Invalid(
                "a section needs at least two contour points".into(),
            ));
        }
        if points
            .iter()
            .any(|p| !p[0].is_finite() || !p[1].is_finite())
        {
            return Err(Error::Invalid(
                "section contour has a non-finite coordinate".into(),
            ));
        }
        let scale = points
            .iter()
            .map(|p| p[0].abs().max(p[1].abs()))
            .fold(0.0, f64::max);
        let tol = 1e-9 * scale.max(1e-12);
        if points[0][0].abs() > tol {
            return Err(Error::Invalid(format!(
                "section contour must start on the centreline (y = 0), starts at y = {}",
                points[0][0]
            )));
        }
        let last = points[points.len() - 1];
        if last[1].abs() > tol {
            return Err(Error::Invalid(format!(
                "section contour must end on the waterline (z = 0), ends at z = {}",
                last[1]
            )));
        }
        if points.iter().any(|p| p[0] < -tol || p[1] > tol) {
            return Err(Error::Invalid(
                "section contour must lie at y >= 0 and at or below the waterline".into(),
            ));
        }
        if points
            .windows(2)
            .any(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]) <= tol)
        {
            return Err(Error::Invalid(
                "section contour has a zero-length segment".into(),
            ));
        }
        let mut points = points;
        points[0][0] = 0.0;
        let n = points.len();
        points[n - 1][1] = 0.0;
        Ok(Self { points })
    }

    pub fn points(&self) -> &[[f64; 2]] {
        &self.points
    }

    /// Waterline beam B (full).
    pub fn beam(&self) -> f64 {
        2.0 * self.points[self.points.len() - 1][0]
    }

    /// Draft T (deepest point below the waterline).
    pub fn draft(&self) -> f64 {
        -self.points.iter().map(|p| p[1]).fold(0.0, f64::min)
    }

    /// Immersed area of the full section (both sides).
    pub fn area(&self) -> f64 {
        // area between the contour and the centreline/waterline: -int z dy along the contour, doubled
        2.0 * self
            .points
            .windows(2)
            .map(|w| -0.5 * (w[0][1] + w[1][1]) * (w[1][0] - w[0][0]))
            .sum::<f64>()
    }

    /// Height of the centroid of the immersed area above the waterline (negative).
    pub fn centroid_z(&self) -> f64 {
        // first moment about z = 0 of the area between contour and waterline: int z^2/2 dy (sign: below)
        let m: f64 = self
            .points
            .windows(2)
            .map(|w| {
                let dy = w[1][0] - w[0][0];
                -(w[0][1] * w[0][1] + w[0][1] * w[1][1] + w[1][1] * w[1][1]) / 6.0 * dy
            })
            .sum();
        2.0 * m / self.area()
    }

    /// Froude-Krylov integral int e^{kz} dy over the full waterline-to-waterline contour
    /// (= -int e^{kz} n_z ds): the sectional heave force is rho g zeta_a e^{ikx} times this.
    pub fn froude_krylov(&self, k: f64) -> f64 {
        2.0 * self
            .points
            .windows(2)
            .map(|w| {
                let dy = w[1][0] - w[0][0];
                let dz = w[1][1] - w[0][1];
                if (k * dz).abs() < 1e-9 {
                    dy * (k * 0.5 * (w[0][1] + w[1][1])).exp()
                } else {
                    dy * ((k * w[1][1]).exp() - (k * w[0][1]).exp()) / (k * dz)
                }
            })
            .sum::<f64>()
    }
}

/// Heave radiation of one section by the chosen method.
pub fn radiation(
    method: SectionMethod,
    section: &HalfSection,
    omega: f64,
    g: f64,
    rho: f64,
) -> Result<Radiation> {
    match method {
        SectionMethod::Lewis => lewis::radiation(section, omega, g, rho),
        SectionMethod::FrankCloseFit => frank_close_fit::radiation(
            section,
            omega,
            g,
            rho,
            &frank_close_fit::Settings::default(),
        ),
    }
}
