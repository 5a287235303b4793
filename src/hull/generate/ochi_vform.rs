//! A reconstruction of Ochi's (1958) 6 m V-form model ("Model experiments on ship strength and slamming in
//! regular waves", Trans. SNAME 66: 345-383), with the particulars reported in Veen (2010), Table 6.1.
//! The offsets were not published: the hull is a fair form fitted by [`super::form_fit`] to the published
//! length, beam, maximum draft, displacement and form coefficients, with V-shaped sections forward. Nothing
//! else (in particular no natural period) is fitted.

use super::form_fit::{FittedForm, FormTargets, fit_form};
use super::section_family::{Flare, PowerSection, contour};
use super::{HullSpec, LoadingSpec, Position, RadiusOfGyration, SensorSpec, StationSpec};
use crate::error::{Error, Result};
use crate::hull::Section;

/// Length between perpendiculars, m (published).
pub const LPP: f64 = 6.0;
/// Beam, m (published).
pub const BEAM: f64 = 0.83;
/// Maximum draft, m (published).
pub const DRAFT_MAX: f64 = 0.36;
/// Displacement at the maximum draft, kg (published).
pub const DISPLACEMENT_KG: f64 = 1334.0;
/// Water density, kg/m³: the basin is assumed to hold fresh water (not stated in the source).
pub const RHO: f64 = 1000.0;
/// Published midship coefficient.
pub const CM: f64 = 0.99;
/// Published waterplane coefficient.
pub const CWP: f64 = 0.83;
/// Deck height above baseline, m: not published, assumed.
pub const DEPTH: f64 = 0.5;
/// Centre of gravity above baseline, m: not published, assumed (half the assumed depth).
pub const KG: f64 = 0.25;
/// Pitch radius of gyration over Lpp: not published, the conventional value.
pub const K_YY_OVER_LPP: f64 = 0.25;
/// Test condition (published): mean draft 0.20 m, trim 0.08 m by the stern.
pub const TEST_MEAN_DRAFT: f64 = 0.20;
pub const TEST_TRIM_BY_STERN: f64 = 0.08;
/// Instrumented sections, fraction of Lpp aft of the FP (published).
pub const SENSOR_STATIONS: [f64; 4] = [0.093, 0.133, 0.174, 0.227];
/// Sensor diameter, m (published).
pub const SENSOR_DIAMETER: f64 = 0.02;
/// Sensor girths as fractions of the wetted girth at the test condition (positions not published).
pub const SENSOR_GIRTH_FRACTIONS: [f64; 4] = [0.1, 0.35, 0.6, 0.85];
/// Uniform stations from AP to FP (the instrumented sections are added to these).
pub const STATIONS: usize = 41;
/// Largest section area coefficient forward of 0.1 Lpp aft of the FP: V-sections (reconstruction choice).
pub const SIGMA_MAX_FORWARD: f64 = 0.6;
/// The side above the waterline continues, straight, the mean slope of the section over this top fraction
/// of the draft.
pub const FLARE_SLOPE_SPAN: f64 = 0.1;

/// Block coefficient implied by the published displacement in fresh water, C_B = Δ/(ρ L B T) = 0.7441.
/// The published C_B 0.74 and C_P 0.75 (two digits) are not fitted directly: this C_B rounds to 0.74 and,
/// with C_M 0.99, gives C_P = C_B/C_M = 0.7516, which rounds to 0.75.
pub fn cb_target() -> f64 {
    DISPLACEMENT_KG / (RHO * LPP * BEAM * DRAFT_MAX)
}

/// σ_max(u): 0.6 forward of 0.1 Lpp aft of the FP, rising linearly to C_M at 0.3 Lpp, C_M elsewhere (no
/// section fuller than midship).
fn sigma_max(u: f64) -> f64 {
    let f = 1.0 - u;
    if f <= 0.1 {
        SIGMA_MAX_FORWARD
    } else if f < 0.3 {
        SIGMA_MAX_FORWARD + (CM - SIGMA_MAX_FORWARD) * (f - 0.1) / 0.2
    } else {
        CM
    }
}

/// Flat of bottom: none forward of `FLAT_START` Lpp aft of the FP (V-sections), then the half-width
/// fraction w = λ (2σ − 1) of the waterline half-breadth, λ rising linearly from 0 to `FLAT_FRACTION` over
/// `FLAT_RAMP` Lpp. Veen (2010) describes the instrumented section at 0.174 Lpp as flat-bottomed; the model
/// is a V-form; where the flat-of-bottom line ends forward is not published (0.14 is a choice).
pub const FLAT_START: f64 = 0.14;
pub const FLAT_RAMP: f64 = 0.03;
pub const FLAT_FRACTION: f64 = 0.8;

/// Flat-of-bottom half-width over the waterline half-breadth at f (fraction of Lpp aft of FP) for a
/// section of area coefficient σ.
pub fn flat_fraction(f: f64, sigma: f64) -> f64 {
    let lambda = FLAT_FRACTION * ((f - FLAT_START) / FLAT_RAMP).clamp(0.0, 1.0);
    lambda * (2.0 * sigma - 1.0).max(0.0)
}

/// The fitted form curves.
pub fn fitted_form() -> Result<FittedForm> {
    fit_form(&FormTargets {
        cb: cb_target(),
        cm: CM,
        cwp: CWP,
        sigma_min: 0.5,
        sigma_max,
        intervals: 20,
        extra_samples: SENSOR_STATIONS.iter().map(|f| 1.0 - f).collect(),
    })
}

/// The half-section below the design waterline at u (AP = 0, FP = 1) from the fitted curves; `None` at
/// a stem or stern post (zero breadth).
fn underwater_section(form: &FittedForm, u: f64) -> Result<Option<PowerSection>> {
    let beta = form.beta(u);
    let alpha = form.alpha(u);
    let b = 0.5 * BEAM * beta;
    if b < 1e-6 {
        return Ok(None);
    }
    let sigma = alpha / beta;
    let smax = sigma_max(u);
    if !(sigma >= 0.5 - 1e-6 && sigma <= smax + 1e-6) {
        return Err(Error::Numerical(format!(
            "Ochi V-form: section area coefficient {sigma:.6} at {:.4} Lpp aft of FP is outside [0.5, {smax}]",
            1.0 - u
        )));
    }
    // Only solver round-off is removed here (checked just above).
    let sigma = sigma.clamp(0.5, smax);
    Ok(Some(PowerSection::with_flat(
        b,
        DRAFT_MAX,
        sigma,
        flat_fraction(1.0 - u, sigma),
    )))
}

/// Half-section contour at u (AP = 0, FP = 1) from the fitted curves.
fn section_points(form: &FittedForm, u: f64) -> Result<Vec<[f64; 2]>> {
    let Some(lower) = underwater_section(form, u)? else {
        return Ok(vec![[0.0, 0.0], [0.0, DEPTH]]);
    };
    let b = lower.half_breadth;
    // dy/dz of the side continued above the waterline: the chord slope over the top of the section.
    let span = FLARE_SLOPE_SPAN * DRAFT_MAX;
    let wl_slope = (b - lower.y(DRAFT_MAX - span)) / span;
    let flare = Flare {
        half_breadth_wl: b,
        half_breadth_deck: (b + (DEPTH - DRAFT_MAX) * wl_slope).min(0.5 * BEAM),
        z_wl: DRAFT_MAX,
        z_deck: DEPTH,
        exponent: 1.0,
    };
    let mut levels = lower.z_levels(12);
    levels.extend(flare.z_levels(6));
    Ok(contour(levels, |z| {
        if z <= DRAFT_MAX {
            lower.y(z)
        } else {
            flare.y(z)
        }
    }))
}

/// The reconstructed Ochi V-form hull file.
pub fn ochi_vform() -> Result<HullSpec> {
    let form = fitted_form()?;
    let mut fractions: Vec<f64> = (0..STATIONS)
        .map(|k| 1.0 - k as f64 / (STATIONS - 1) as f64)
        .collect();
    fractions.extend(SENSOR_STATIONS);
    fractions.sort_by(|a, b| b.total_cmp(a));
    fractions.dedup_by(|a, b| (*a - *b).abs() < 1e-9);
    let mut stations = Vec::with_capacity(fractions.len());
    for &f in &fractions {
        stations.push(StationSpec {
            position: Position::AftOfFp(f),
            points: section_points(&form, 1.0 - f)?,
        });
    }

    let draft_fp = TEST_MEAN_DRAFT - 0.5 * TEST_TRIM_BY_STERN;
    let draft_ap = TEST_MEAN_DRAFT + 0.5 * TEST_TRIM_BY_STERN;
    let mut sensors = Vec::new();
    for &f in &SENSOR_STATIONS {
        let points = section_points(&form, 1.0 - f)?;
        let t_local = draft_ap + (draft_fp - draft_ap) * (1.0 - f);
        let wet_girth = Section::new(Section::new(points).wetted(t_local)).girth();
        for (k, frac) in SENSOR_GIRTH_FRACTIONS.iter().enumerate() {
            sensors.push(SensorSpec {
                name: format!("S{:03.0}-{}", f * 1000.0, k + 1),
                position: Position::AftOfFp(f),
                girth: frac * wet_girth,
                diameter: SENSOR_DIAMETER,
            });
        }
    }

    let mut instrumented = Vec::new();
    for &f in &SENSOR_STATIONS {
        if let Some(sec) = underwater_section(&form, 1.0 - f)? {
            instrumented.push(if sec.flat > 0.0 {
                format!(
                    "{f}: flat of bottom {:.3} m half-width, side rising at {:.1} deg from it",
                    sec.flat,
                    sec.keel_deadrise().to_degrees()
                )
            } else {
                format!(
                    "{f}: V, deadrise {:.1} deg at the keel",
                    sec.keel_deadrise().to_degrees()
                )
            });
        }
    }
    let cb = form.cb();
    let cm = form.cm();
    let description = format!(
        "RECONSTRUCTION of Ochi's (1958) 6 m V-form merchant ship model (Trans. SNAME 66: 345-383), from the \
particulars reported in Veen (2010), Table 6.1. The offsets were not published: this hull is not Ochi's \
hull, only a fair hull with the same published particulars.\n\
\n\
Published: Lpp {LPP} m, beam {BEAM} m, max draft {DRAFT_MAX} m, displacement {DISPLACEMENT_KG} kg, Cb 0.74, \
Cp 0.75, Cm 0.99, Cwp 0.83. The basin water is assumed fresh (rho {RHO} kg/m3, not stated in the source); \
then 1334 kg at the maximum draft gives Cb = {cb_t:.4}, and with Cm 0.99 Cp = {cp_t:.4}: this set rounds to \
every published value and is the one fitted.\n\
\n\
Method: the sectional-area curve and the design-waterline half-breadth curve are cubic B-splines (20 \
intervals) in x, chosen by a quadratic programme (Clarabel) that minimises their squared second derivatives \
subject to the form coefficients as equality constraints (Cb, Cwp, Cm at midship, full beam at midship, \
zero area and breadth at AP and FP) and section bounds 0.5 b T <= A/2 <= sigma_max b T at 401+ points, \
sigma_max = 0.6 forward of 0.1 Lpp aft of FP (V-sections), rising linearly to Cm at 0.3 Lpp. Sections below \
the waterline are a flat of bottom of half-width y_f and a side y = y_f + (b - y_f) [1 - (1 - z/T)^q] with \
q = s/(1 - s), s = (sigma - w)/(1 - w), w = y_f/b (without a flat: sigma 0.5 = straight V, near 1 = \
rectangle with small bilge). No flat forward of {FLAT_START} Lpp aft of FP (V-sections); aft of it \
w = L (2 sigma - 1), L rising linearly from 0 to {FLAT_FRACTION} over {FLAT_RAMP} Lpp: Veen (2010) calls the \
instrumented section at 0.174 Lpp flat-bottomed (where the flat-of-bottom line ends is not published). \
Keel on the baseline from AP to FP, no forefoot or cutaway. Above the \
waterline the side continues as a straight line with the mean slope of the section over the top 10 % of the \
draft (a V section continues its V, a full section stays nearly wall-sided), the deck half-breadth not \
exceeding half the beam, up to an assumed deck at {DEPTH} m (depth not published).\n\
\n\
Fitted curves: Cb {cb:.4}, Cm {cm:.4}, Cp {cp:.4}, Cwp {cwp:.4}, LCB {lcb:+.2} % Lpp from midship (+ \
forward; LCB not published). The offsets below reproduce these to within their discretisation ({nst} \
stations, polylines); the tests in tests/hull_generate.rs check them against the published values (2.5 %).\n\
\n\
Loadings: 'test-condition' is the published forward-speed condition, read as mean draft 0.20 m at \
midship with 0.08 m trim by the stern over Lpp: draft 0.16 m at FP, 0.24 m at AP; its displacement is not \
published and follows from the drafts. 'max-draft' is 0.36 m even keel with the published 1334 kg. Mass \
properties not published take conventional values: k_yy = 0.25 Lpp, LCG = LCB (lcg_m omitted), KG {KG} m \
(assumed, half the assumed depth). Nothing was tuned to the published natural periods.\n\
\n\
Sensors: the four instrumented sections (0.093, 0.133, 0.174, 0.227 Lpp aft of FP) and the 0.02 m sensor \
diameter are published; the positions on each section are not, so four sensors per section are placed at \
0.10, 0.35, 0.60 and 0.85 of the wetted girth at the test condition, from near the keel towards the \
waterline (S093-1 nearest the keel). Ochi had 19 sensors in all; the other 3 are not modelled. The \
instrumented sections here: {instrumented}.",
        instrumented = instrumented.join("; "),
        cb_t = cb_target(),
        cp_t = cb_target() / CM,
        cp = cb / cm,
        cwp = form.cwp(),
        lcb = 100.0 * form.lcb_over_l(),
        nst = stations.len(),
    );
    Ok(HullSpec {
        name: "Ochi (1958) V-form model (reconstruction)".into(),
        description,
        lpp: LPP,
        depth: DEPTH,
        loadings: vec![
            LoadingSpec {
                name: "test-condition".into(),
                draft_fp,
                draft_ap,
                rho: RHO,
                displacement_kg: None,
                kg: KG,
                k_yy: RadiusOfGyration::OverLpp(K_YY_OVER_LPP),
            },
            LoadingSpec {
                name: "max-draft".into(),
                draft_fp: DRAFT_MAX,
                draft_ap: DRAFT_MAX,
                rho: RHO,
                displacement_kg: Some(DISPLACEMENT_KG),
                kg: KG,
                k_yy: RadiusOfGyration::OverLpp(K_YY_OVER_LPP),
            },
        ],
        stations,
        sensors,
    })
}
