//! Generators for the example and reference hulls in `hulls/`.
//!
//! Each generator builds a [`HullSpec`] (the content of a `hull.toml`) from a published analytic form or
//! from published particulars, and [`HullSpec::to_toml`] writes it in the format the hull reader takes.
//! The committed files are regenerated with `slamtool hull generate <hull> -o hulls/<file>`; a test
//! checks that the committed files equal what the generators produce, so they cannot drift apart.
//!
//! * [`wigley`]: the Wigley III model of Journée (1992), from its analytic form.
//! * [`ochi_vform`]: a reconstruction of Ochi's (1958) 6 m V-form model from its published form
//!   coefficients (its offsets are not published), fitted by [`form_fit`].
//! * [`car_carrier`]: a reconstruction of a flared, bulbous-bow car carrier for the Hermundstad & Moan
//!   (2005) bow-flare case.

pub mod bspline;
pub mod car_carrier;
pub mod form_fit;
pub mod ochi_vform;
pub mod section_family;
pub mod toml_writer;
pub mod wigley;

use crate::error::Result;
use crate::hull::{Hull, Hydrostatics};
use crate::input::SourceText;

/// The content of a hull file, as a generator builds it.
#[derive(Debug, Clone, PartialEq)]
pub struct HullSpec {
    pub name: String,
    pub description: String,
    /// Length between perpendiculars, m.
    pub lpp: f64,
    /// Deck height above baseline, m.
    pub depth: f64,
    /// Loading conditions; the first is the default.
    pub loadings: Vec<LoadingSpec>,
    /// Stations ordered aft to forward (strictly increasing x).
    pub stations: Vec<StationSpec>,
    pub sensors: Vec<SensorSpec>,
}

/// One loading condition as written to the file.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadingSpec {
    pub name: String,
    pub draft_fp: f64,
    pub draft_ap: f64,
    pub rho: f64,
    /// Written only where a published value exists; otherwise the reader takes the buoyancy.
    pub displacement_kg: Option<f64>,
    pub kg: f64,
    pub k_yy: RadiusOfGyration,
}

/// Pitch radius of gyration, as a length or as a fraction of Lpp.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RadiusOfGyration {
    Metres(f64),
    OverLpp(f64),
}

/// Where a station (or sensor) sits along the hull.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Position {
    /// m from midship, positive forward.
    X(f64),
    /// Fraction of Lpp aft of the forward perpendicular.
    AftOfFp(f64),
}

impl Position {
    /// x from midship for a hull of length `lpp` (x = Lpp/2 − f·Lpp for a fraction f aft of the FP).
    pub fn x(self, lpp: f64) -> f64 {
        match self {
            Position::X(x) => x,
            Position::AftOfFp(f) => crate::hull::station_x(lpp, f),
        }
    }
}

/// One station: the half-breadth contour (y, z) from the keel up to the deck.
#[derive(Debug, Clone, PartialEq)]
pub struct StationSpec {
    pub position: Position,
    pub points: Vec<[f64; 2]>,
}

/// A pressure sensor or panel, located by its girth from the keel.
#[derive(Debug, Clone, PartialEq)]
pub struct SensorSpec {
    pub name: String,
    pub position: Position,
    pub girth: f64,
    pub diameter: f64,
}

/// The hulls this module can generate.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum GeneratedHull {
    /// Journée (1992) Wigley III.
    WigleyIii,
    /// Reconstruction of Ochi's (1958) V-form model.
    OchiVform,
    /// Reconstruction of the Hermundstad & Moan (2005) car carrier.
    CarCarrier,
}

impl GeneratedHull {
    /// All generated hulls.
    pub const ALL: [GeneratedHull; 3] = [
        GeneratedHull::WigleyIii,
        GeneratedHull::OchiVform,
        GeneratedHull::CarCarrier,
    ];

    /// The name used on the command line.
    pub fn cli_name(self) -> &'static str {
        match self {
            GeneratedHull::WigleyIii => "wigley-iii",
            GeneratedHull::OchiVform => "ochi-vform",
            GeneratedHull::CarCarrier => "car-carrier",
        }
    }

    /// The committed file under `hulls/`.
    pub fn file_name(self) -> &'static str {
        match self {
            GeneratedHull::WigleyIii => "wigley-iii.toml",
            GeneratedHull::OchiVform => "ochi-vform.toml",
            GeneratedHull::CarCarrier => "car-carrier-hm2005.toml",
        }
    }

    /// Build the hull. Its description ends with the hydrostatics of the offsets as written (computed by
    /// [`Hydrostatics`] from the file text) and the command that regenerates it.
    pub fn spec(self) -> Result<HullSpec> {
        let mut spec = match self {
            GeneratedHull::WigleyIii => wigley::wigley_iii(),
            GeneratedHull::OchiVform => ochi_vform::ochi_vform()?,
            GeneratedHull::CarCarrier => car_carrier::car_carrier_hm2005()?,
        };
        let summary = hydrostatics_summary(&spec)?;
        spec.description = format!(
            "{}\n\n{summary}\n\nRegenerate with: slamtool hull generate {} -o hulls/{}",
            spec.description.trim_end(),
            self.cli_name(),
            self.file_name()
        );
        Ok(spec)
    }

    /// The hull file text.
    pub fn toml(self) -> Result<String> {
        Ok(self.spec()?.to_toml())
    }
}

/// The hydrostatics of a generated hull at each of its loadings, read back from its own file text, in
/// words for the description.
pub fn hydrostatics_summary(spec: &HullSpec) -> Result<String> {
    let src = SourceText::from_string("<generated hull>", spec.to_toml());
    let hull = Hull::from_source(&src)?;
    let mut out = format!(
        "Hydrostatics of these offsets (slamtool, {} stations):",
        hull.stations.len()
    );
    for l in &hull.loadings {
        let h = Hydrostatics::compute(&hull, l);
        out.push_str(&format!(
            " '{}': draft FP {:.4} m, AP {:.4} m, volume {:.6} m3, buoyancy {:.2} kg, LCB {:+.4} m, KB {:.4} m, \
waterplane {:.4} m2, LCF {:+.4} m, beam {:.4} m, Cb {:.4}, Cp {:.4}, Cm {:.4}, Cwp {:.4}, GM_T {:.4} m, GM_L {:.3} m.",
            l.name,
            l.draft_fp,
            l.draft_ap,
            h.volume,
            h.displacement_kg,
            h.lcb,
            h.kb,
            h.awp,
            h.lcf,
            h.beam_wl_m,
            h.cb,
            h.cp,
            h.cm,
            h.cwp,
            h.gm_t,
            h.gm_l
        ));
    }
    Ok(out)
}
