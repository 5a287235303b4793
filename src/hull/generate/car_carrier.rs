//! A reconstruction of a flared, bulbous-bow car carrier for the bow-flare slamming case of Hermundstad &
//! Moan (2005), "Numerical and experimental analysis of bow flare slamming on a Ro-Ro vessel in regular
//! oblique waves", J. Marine Science and Technology 10: 105-122, as used by Veen (2010), Section 6.2.
//!
//! The hull lines were not published (only a digitised section in a figure that is not available). Published
//! and used here: a 120 m car carrier, model scale 1:21.6, the flared section at 0.05 Lpp aft of the FP with
//! a model-scale beam of 0.82 m (taken as the beam at the deck), the 37° equivalent deadrise Veen used for
//! the flare, and the 0.067 m panel. Everything else (beam, draft, fullness, bulb, stern) is an assumption
//! typical of car carriers of this length, stated in the file.
//!
//! Sections: below the waterline the family of [`PowerSection`] (area coefficient σ(f)), plus an
//! elliptical bulb at the forward stations, y = max(hull, bulb); above the waterline a flare
//! y = b + Δ s^m ([`Flare`]) up to the deck.

use super::section_family::{Flare, PowerSection, contour};
use super::{HullSpec, LoadingSpec, Position, RadiusOfGyration, SensorSpec, StationSpec};
use crate::error::{Error, Result};
use crate::hull::Section;

/// Full-scale length between perpendiculars, m (published).
pub const LPP_FULL: f64 = 120.0;
/// Model scale (published).
pub const SCALE: f64 = 21.6;
/// Full-scale beam, m: assumed (B/L = 0.18, typical of car carriers and Ro-Ro ships of this length).
pub const BEAM_FULL: f64 = 21.6;
/// Full-scale design draft, m: assumed (T/B = 0.25).
pub const DRAFT_FULL: f64 = 5.4;
/// Published section: fraction of Lpp aft of the FP, and its model-scale beam (taken at the deck), m.
pub const SECTION_AFT_OF_FP: f64 = 0.05;
pub const SECTION_BEAM: f64 = 0.82;
/// Equivalent deadrise of the flare quoted by Veen (2010), deg: used as the angle of the chord of the flare
/// from the waterline to the deck at the published section.
pub const FLARE_DEADRISE_DEG: f64 = 37.0;
/// Panel width, m (published).
pub const PANEL_WIDTH: f64 = 0.067;
/// Basin water assumed fresh, kg/m³.
pub const RHO: f64 = 1000.0;
/// Pitch radius of gyration over Lpp: conventional value.
pub const K_YY_OVER_LPP: f64 = 0.25;
/// Centre of gravity above baseline, full scale, m: assumed.
pub const KG_FULL: f64 = 7.6;

/// Waterline entrance and run: fraction of Lpp from the FP (resp. AP) over which the waterline and
/// sections fine out; parallel middle body between.
pub const ENTRANCE: f64 = 0.5;
pub const RUN: f64 = 0.5;
/// Section area coefficient at midship and at the ends of the hull.
pub const SIGMA_MID: f64 = 0.97;
pub const SIGMA_END: f64 = 0.55;
/// Deck half-breadth at the FP over B/2 (raked, bluff upper bow); the deck line fills out to full beam
/// over `DECK_ENTRANCE`.
pub const DECK_AT_FP: f64 = 0.5;
pub const DECK_ENTRANCE: f64 = 0.35;
/// Deck half-breadth over B/2 at the AP (overhanging stern).
pub const DECK_AT_AP: f64 = 0.7;
/// Flare exponent m: vertical at the waterline, flattening towards the deck.
pub const FLARE_EXPONENT: f64 = 1.5;
/// Bulb: half-breadth at the FP over B/2, centre height and half-height over T, length over Lpp.
pub const BULB_HALF_BREADTH: f64 = 0.15;
pub const BULB_CENTRE: f64 = 0.4;
pub const BULB_HALF_HEIGHT: f64 = 0.35;
pub const BULB_LENGTH: f64 = 0.05;

/// Model-scale particulars.
pub fn lpp() -> f64 {
    LPP_FULL / SCALE
}
pub fn beam() -> f64 {
    BEAM_FULL / SCALE
}
pub fn draft() -> f64 {
    DRAFT_FULL / SCALE
}

/// Waterline half-breadth over B/2 at f (fraction of Lpp aft of the FP).
pub fn beta(f: f64) -> f64 {
    if f < ENTRANCE {
        1.0 - ((ENTRANCE - f) / ENTRANCE).powi(2)
    } else if f > 1.0 - RUN {
        1.0 - ((f - (1.0 - RUN)) / RUN).powf(2.5)
    } else {
        1.0
    }
}

/// Section area coefficient σ below the design waterline at f.
pub fn sigma(f: f64) -> f64 {
    let r = if f < ENTRANCE {
        ((ENTRANCE - f) / ENTRANCE).powi(2)
    } else if f > 1.0 - RUN {
        ((f - (1.0 - RUN)) / RUN).powi(2)
    } else {
        0.0
    };
    SIGMA_MID - (SIGMA_MID - SIGMA_END) * r
}

/// Exponent k of the deck line forward, b_deck/(B/2) = 1 − (1 − DECK_AT_FP)((F − f)/F)^k, chosen so that
/// the deck beam at the published section is the published 0.82 m.
pub fn deck_exponent() -> f64 {
    let target = SECTION_BEAM / beam();
    let r = (DECK_ENTRANCE - SECTION_AFT_OF_FP) / DECK_ENTRANCE;
    ((1.0 - target) / (1.0 - DECK_AT_FP)).ln() / r.ln()
}

/// Deck half-breadth over B/2 at f.
pub fn deck(f: f64) -> f64 {
    if f < DECK_ENTRANCE {
        1.0 - (1.0 - DECK_AT_FP) * ((DECK_ENTRANCE - f) / DECK_ENTRANCE).powf(deck_exponent())
    } else if f > 1.0 - RUN {
        1.0 - (1.0 - DECK_AT_AP) * ((f - (1.0 - RUN)) / RUN).powf(2.5)
    } else {
        1.0
    }
}

/// Depth (deck above baseline), m: such that the chord of the flare at the published section is inclined
/// at the quoted equivalent deadrise: D = T + tan(37°)(b_deck − b_wl).
pub fn depth() -> f64 {
    let f = SECTION_AFT_OF_FP;
    let half = 0.5 * beam();
    draft() + FLARE_DEADRISE_DEG.to_radians().tan() * half * (deck(f) - beta(f))
}

/// Bulb half-breadth at height z and station f, m (elliptical cross-section, fining out aft to zero at
/// `BULB_LENGTH`).
fn bulb(f: f64, z: f64) -> f64 {
    if f >= BULB_LENGTH {
        return 0.0;
    }
    let r = 0.5 * beam() * BULB_HALF_BREADTH * (1.0 - (f / BULB_LENGTH).powi(2)).sqrt();
    let zc = BULB_CENTRE * draft();
    let h = BULB_HALF_HEIGHT * draft();
    let e = (z - zc) / h;
    if e.abs() >= 1.0 {
        0.0
    } else {
        r * (1.0 - e * e).sqrt()
    }
}

/// The flare above the waterline at f.
pub fn flare(f: f64) -> Flare {
    let half = 0.5 * beam();
    Flare {
        half_breadth_wl: half * beta(f),
        half_breadth_deck: half * deck(f),
        z_wl: draft(),
        z_deck: depth(),
        exponent: FLARE_EXPONENT,
    }
}

/// Half-section contour at f.
pub fn section_points(f: f64) -> Result<Vec<[f64; 2]>> {
    let t = draft();
    let b = 0.5 * beam() * beta(f);
    let lower = PowerSection::new(b, t, sigma(f));
    let fl = flare(f);
    if fl.half_breadth_deck < fl.half_breadth_wl {
        return Err(Error::Numerical(format!(
            "car carrier: deck narrower than the waterline at {f:.4} Lpp aft of FP"
        )));
    }
    let mut levels = if b > 0.0 {
        lower.z_levels(12)
    } else {
        vec![0.0, t]
    };
    if f < BULB_LENGTH {
        let (zc, h) = (BULB_CENTRE * t, BULB_HALF_HEIGHT * t);
        levels.extend((0..=24).map(|k| zc - h * (std::f64::consts::PI * k as f64 / 24.0).cos()));
    }
    levels.extend(fl.z_levels(10));
    Ok(contour(levels, |z| {
        if z <= t {
            let hull = if b > 0.0 { lower.y(z) } else { 0.0 };
            hull.max(bulb(f, z))
        } else {
            fl.y(z)
        }
    }))
}

/// Height of the panel centre on the published section: where the local flare angle equals the quoted
/// equivalent deadrise, s = (1/m)^(1/(m−1)) for a flare whose chord is at that angle.
pub fn panel_height() -> f64 {
    let m = FLARE_EXPONENT;
    let s = (1.0 / m).powf(1.0 / (m - 1.0));
    draft() + s * (depth() - draft())
}

/// Stations: every 0.025 Lpp, and every 0.0125 Lpp forward of 0.1 Lpp aft of the FP.
fn station_fractions() -> Vec<f64> {
    let mut f: Vec<f64> = (0..=40).map(|k| k as f64 / 40.0).collect();
    f.extend([0.0125, 0.0375, 0.0625, 0.0875]);
    f.sort_by(|a, b| b.total_cmp(a));
    f
}

/// The reconstructed car-carrier hull file.
pub fn car_carrier_hm2005() -> Result<HullSpec> {
    let mut stations = Vec::new();
    for f in station_fractions() {
        stations.push(StationSpec {
            position: Position::AftOfFp(f),
            points: section_points(f)?,
        });
    }
    let ref_points = section_points(SECTION_AFT_OF_FP)?;
    let panel_girth = Section::new(Section::new(ref_points).wetted(panel_height())).girth();
    let fl = flare(SECTION_AFT_OF_FP);
    let description = format!(
        "RECONSTRUCTION of a flared, bulbous-bow car carrier for the bow-flare slamming case of Hermundstad & \
Moan (2005), J. Marine Science and Technology 10: 105-122, as used by Veen (2010), Section 6.2. The hull lines \
were not published: this is not their hull, only one with the published features.\n\
\n\
Published and used: 120 m ship, model scale 1:21.6 (Lpp {lpp:.4} m); the flared section at 0.05 Lpp aft of \
FP with a model-scale beam of 0.82 m, taken as the beam at the deck; the flare's equivalent deadrise of 37 deg \
quoted by Veen, used as the angle of the chord of the flare from the waterline to the deck at that section; \
the 0.067 m wide slamming panel (P1) on the flare at that section.\n\
\n\
Assumed (typical of car carriers / Ro-Ro ships of 120 m, not published): beam {BEAM_FULL} m (B/L 0.18), \
design draft {DRAFT_FULL} m (T/B 0.25), Cb about {cb:.3} (from the shape below), fresh basin water (rho \
{RHO}). Depth {depth:.4} m model ({depth_full:.1} m full scale) follows from the 0.82 m deck beam and the 37 deg \
flare chord at the published section. Waterline half-breadth b/(B/2) = 1 - ((E - f)/E)^2 over the \
entrance f < E = {ENTRANCE} (f = fraction of Lpp aft of FP), 1 - ((f - 1 + R)/R)^2.5 over the run f > 1 - R, \
R = {RUN}, 1 between (parallel middle body where E + R < 1); sigma falls quadratically in the same \
variables; \
sections below the waterline y = b [1 - (1 - z/T)^q], q = sigma/(1 - sigma), sigma from {SIGMA_END} at the \
ends to {SIGMA_MID} amidships; keel on the baseline; no transom (the stern is simplified; only the bow is \
meant to resemble a car carrier). Bulb: elliptical cross-section, half-breadth {bulb_b:.4} m at the FP, \
centre {BULB_CENTRE} T, half-height {BULB_HALF_HEIGHT} T, fining out to nothing at {BULB_LENGTH} Lpp aft of \
FP (the bulb nose is at the FP: stations forward of the FP are not used). Flare: y = b + (b_deck - b) s^1.5, \
s = (z - T)/(depth - T), vertical at the waterline; deck line forward b_deck/(B/2) = 1 - {deck_fp} ((F - f)/F)^k, \
F = {DECK_ENTRANCE}, with k = {k:.3} so that the deck beam at 0.05 Lpp is 0.82 m. At that section: waterline beam {bwl2:.4} m, \
flare chord {chord:.1} deg; panel P1 centred {zp:.4} m above baseline, where the local flare angle is \
{local:.1} deg (its position on the flare is not published).\n\
\n\
Loading 'design': design draft even keel; k_yy = 0.25 Lpp (conventional), LCG = LCB (lcg_m omitted), KG \
{KG_FULL} m full scale = {kg:.4} m model (assumed).",
        lpp = lpp(),
        cb = block_coefficient_of_curves(),
        depth = depth(),
        depth_full = depth() * SCALE,
        bulb_b = 0.5 * beam() * BULB_HALF_BREADTH,
        k = deck_exponent(),
        deck_fp = 1.0 - DECK_AT_FP,
        bwl2 = 2.0 * fl.half_breadth_wl,
        chord = fl.chord_deadrise().to_degrees(),
        zp = panel_height(),
        local = fl.local_deadrise(panel_height()).to_degrees(),
        kg = KG_FULL / SCALE,
    );
    Ok(HullSpec {
        name: "Car carrier for Hermundstad & Moan (2005), model 1:21.6 (reconstruction)".into(),
        description,
        lpp: lpp(),
        depth: depth(),
        loadings: vec![LoadingSpec {
            name: "design".into(),
            draft_fp: draft(),
            draft_ap: draft(),
            rho: RHO,
            displacement_kg: None,
            kg: KG_FULL / SCALE,
            k_yy: RadiusOfGyration::OverLpp(K_YY_OVER_LPP),
        }],
        stations,
        sensors: vec![SensorSpec {
            name: "P1".into(),
            position: Position::AftOfFp(SECTION_AFT_OF_FP),
            girth: panel_girth,
            diameter: PANEL_WIDTH,
        }],
    })
}

/// C_B of the analytic curves without the bulb, ∫₀¹ σ β df, by the trapezoidal rule on 2001 points.
pub fn block_coefficient_of_curves() -> f64 {
    let n = 2000;
    let f: Vec<f64> = (0..=n).map(|k| k as f64 / n as f64).collect();
    let g: Vec<f64> = f.iter().map(|&f| sigma(f) * beta(f)).collect();
    crate::numerics::quadrature::trapezoid(&f, &g)
}
