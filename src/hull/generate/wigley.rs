//! The Wigley III model of Journée (1992), "Experiments and calculations on four Wigley hullforms",
//! Delft University of Technology, Ship Hydromechanics Laboratory, report 0909.
//!
//! Hull form, with ξ = 2x/L ∈ [−1, 1] and ζ = z'/T ∈ [−1, 0] (z' up from the waterline):
//!
//! 2y/B = (1 − ζ²)(1 − ξ²)(1 + 0.2 ξ²) + α ζ² (1 − ζ⁸)(1 − ξ²)⁴, with α = 0 for model III.
//!
//! The form is defined below the waterline only; above it the sides are continued vertically (y = y(T))
//! to the deck. Exact values for this form: C_B = (2/3)(1 − 0.8/3 − 0.04) = 0.4622,
//! A_WP = L B (1 − 0.8/3 − 0.04) = 0.6240 m², ∇ = C_B L B T = 0.0780 m³ (the published values).

use super::{HullSpec, LoadingSpec, Position, RadiusOfGyration, StationSpec};

/// Length, m (Journée 1992, model III).
pub const LENGTH: f64 = 3.0;
/// Beam, m.
pub const BEAM: f64 = 0.3;
/// Draft, m.
pub const DRAFT: f64 = 0.1875;
/// Deck height above baseline, m: not part of the analytic form, chosen here.
pub const DEPTH: f64 = 0.25;
/// Centre of gravity above base, m (published).
pub const KG: f64 = 0.17;
/// Pitch radius of gyration, m (published).
pub const K_YY: f64 = 0.75;
/// Fresh water, kg/m³.
pub const RHO: f64 = 1000.0;
/// Number of stations, uniformly spaced from AP to FP.
pub const STATIONS: usize = 41;
/// Intervals in z between the keel and the waterline, uniform.
pub const SECTION_INTERVALS: usize = 20;

/// Half-breadth of the Wigley form with parameter `alpha` at (x, z), z from the baseline, 0 ≤ z ≤ T.
pub fn half_breadth(x: f64, z: f64, alpha: f64) -> f64 {
    let xi = 2.0 * x / LENGTH;
    let zeta = z / DRAFT - 1.0;
    let lon = 1.0 - xi * xi;
    0.5 * BEAM
        * ((1.0 - zeta * zeta) * lon * (1.0 + 0.2 * xi * xi)
            + alpha * zeta * zeta * (1.0 - zeta.powi(8)) * lon.powi(4))
}

/// The Wigley III hull file.
pub fn wigley_iii() -> HullSpec {
    let stations = (0..STATIONS)
        .map(|i| {
            let x = -0.5 * LENGTH + LENGTH * i as f64 / (STATIONS - 1) as f64;
            let y_wl = half_breadth(x, DRAFT, 0.0);
            let points = if y_wl <= 0.0 {
                // Stem and stern post: a vertical line on the centreline.
                vec![[0.0, 0.0], [0.0, DEPTH]]
            } else {
                let mut p: Vec<[f64; 2]> = (0..=SECTION_INTERVALS)
                    .map(|k| {
                        let z = DRAFT * k as f64 / SECTION_INTERVALS as f64;
                        [half_breadth(x, z, 0.0).max(0.0), z]
                    })
                    .collect();
                p.push([y_wl, DEPTH]);
                p
            };
            StationSpec {
                position: Position::X(x),
                points,
            }
        })
        .collect();
    let description = format!(
        "Wigley III model of Journee (1992), Delft Ship Hydromechanics Laboratory report 0909, from its \
analytic form 2y/B = (1 - zeta^2)(1 - xi^2)(1 + 0.2 xi^2) (alpha = 0), xi = 2x/L, zeta = z'/T with z' up from \
the waterline. L {LENGTH} m, B {BEAM} m, T {DRAFT} m. Published: volume 0.0780 m3, waterplane area 0.6240 m2, \
Cb 0.4622, KG 0.170 m, k_yy 0.75 m, fresh water. Offsets: {STATIONS} uniformly spaced stations, \
{SECTION_INTERVALS} uniform intervals in z from keel to waterline. The form is defined below the waterline \
only: above it the sides are continued vertically to a deck at {DEPTH} m (chosen, not published)."
    );
    HullSpec {
        name: "Wigley III (Journee 1992)".into(),
        description,
        lpp: LENGTH,
        depth: DEPTH,
        loadings: vec![LoadingSpec {
            name: "design".into(),
            draft_fp: DRAFT,
            draft_ap: DRAFT,
            rho: RHO,
            displacement_kg: None,
            kg: KG,
            k_yy: RadiusOfGyration::Metres(K_YY),
        }],
        stations,
        sensors: vec![],
    }
}
