//! Hydrostatics and form coefficients at a loading condition.
//!
//! With A(x) the immersed sectional area under the local waterline T(x), z_c(x) its centroid height and
//! b(x) the waterline half-breadth (standard definitions, e.g. Rawson & Tupper, "Basic Ship Theory", ch. 2-4;
//! Biran & López-Pulido, "Ship Hydrostatics and Stability", ch. 2):
//!
//! * volume ∇ = ∫ A dx, LCB = ∫ x A dx / ∇, KB = ∫ z_c A dx / ∇
//! * waterplane A_wp = ∫ 2b dx, LCF = ∫ 2b x dx / A_wp
//! * I_T = ∫ (2/3) b³ dx, I_L = ∫ 2b (x − LCF)² dx, BM_T = I_T/∇, BM_L = I_L/∇
//! * GM_T = KB + BM_T − KG, GM_L = KB + BM_L − KG
//! * C_B = ∇/(L B T), C_M = A_M/(B T), C_P = ∇/(A_M L), C_WP = A_wp/(L B), with L = Lpp, B the largest
//!   waterline breadth (over the stations and the interpolated sections between them), T the mean draft and
//!   A_M the midship (x = 0) sectional area.
//!
//! The integrals over x use Gauss-Legendre quadrature (6 points per station interval, down to 2 on hulls of
//! more than 2,000 station intervals) on the sections
//! interpolated between stations (shape-preserving PCHIP, see `interpolate`), each cut by its own local
//! waterline, so trim is exact for any station spacing.

use rayon::prelude::*;
use serde::Serialize;

use super::{Hull, LoadingCondition, SectionProperties};

/// Gauss-Legendre points per station interval.
const GAUSS_POINTS: usize = 6;

/// Quadrature nodes over the whole hull above which the points per interval are reduced (to at least 2,
/// exact for the cubic interpolants between stations): a hull of thousands of stations needs no more.
const MAX_NODES: usize = 12_000;

/// Gauss-Legendre points per interval for a hull of `intervals` station intervals: [`GAUSS_POINTS`] for
/// any hull up to 2,000 intervals, fewer for more, so that the cost stays linear in the stations.
fn gauss_points(intervals: usize) -> usize {
    (MAX_NODES / intervals.max(1)).clamp(2, GAUSS_POINTS)
}
use crate::numerics::quadrature::gauss_legendre;

/// Sectional area at one station.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SectionalArea {
    /// Station, m from midship.
    pub x_m: f64,
    /// Immersed area, m².
    pub area_m2: f64,
    /// Local draft, m.
    pub draft_m: f64,
    /// Waterline half-breadth, m.
    pub half_breadth_m: f64,
}

/// Hydrostatic particulars at a loading condition. Lengths in m, x from midship positive forward.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Hydrostatics {
    pub loading: String,
    pub lpp_m: f64,
    pub beam_wl_m: f64,
    pub mean_draft_m: f64,
    pub trim_by_stern_m: f64,
    #[serde(rename = "water_density_kg_per_m3")]
    pub rho_kg_m3: f64,
    /// Immersed volume ∇, m³.
    #[serde(rename = "volume_m3")]
    pub volume: f64,
    /// Buoyancy ρ∇, kg.
    pub displacement_kg: f64,
    #[serde(rename = "lcb_m")]
    pub lcb: f64,
    #[serde(rename = "kb_m")]
    pub kb: f64,
    #[serde(rename = "waterplane_area_m2")]
    pub awp: f64,
    #[serde(rename = "lcf_m")]
    pub lcf: f64,
    #[serde(rename = "bm_t_m")]
    pub bm_t: f64,
    #[serde(rename = "bm_l_m")]
    pub bm_l: f64,
    #[serde(rename = "gm_t_m")]
    pub gm_t: f64,
    #[serde(rename = "gm_l_m")]
    pub gm_l: f64,
    /// Midship sectional area, m².
    #[serde(rename = "midship_area_m2")]
    pub am: f64,
    pub cb: f64,
    pub cp: f64,
    pub cm: f64,
    pub cwp: f64,
    pub sectional_area: Vec<SectionalArea>,
}

/// Mass properties resolved for a loading condition: what the file gives, or the hydrostatic default.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MassProperties {
    pub mass_kg: f64,
    /// True if the mass was not given and equals the buoyancy at the drafts.
    pub mass_from_buoyancy: bool,
    pub lcg_m: f64,
    /// True if LCG was not given and is taken equal to LCB.
    pub lcg_from_lcb: bool,
    pub kg_m: f64,
    pub k_yy_m: f64,
    /// (mass − buoyancy)/buoyancy: a loading whose given mass differs from its buoyancy is not in equilibrium.
    pub mass_buoyancy_mismatch: f64,
}

impl Hydrostatics {
    /// Hydrostatics of `hull` floating at the drafts of `loading`.
    pub fn compute(hull: &Hull, loading: &LoadingCondition) -> Self {
        let lpp = hull.lpp;
        let n = hull.stations.len();
        let xs: Vec<f64> = hull.stations.iter().map(|s| s.x).collect();
        let sac: Vec<SectionalArea> = hull
            .stations
            .iter()
            .map(|st| {
                let t = loading.draft_at(st.x, lpp);
                let p = st.section.properties(t);
                SectionalArea {
                    x_m: st.x,
                    area_m2: p.area,
                    draft_m: t,
                    half_breadth_m: p.half_breadth,
                }
            })
            .collect();
        // Section properties at every quadrature node, each under its own local waterline.
        let (nodes, weights) = gauss_legendre(gauss_points(n - 1));
        // The intervals in parallel, collected in order (the sums below do not depend on the threads).
        let samples: Vec<(f64, f64, SectionProperties)> = (0..n - 1)
            .into_par_iter()
            .flat_map_iter(|k| {
                let (mid, half) = (0.5 * (xs[k] + xs[k + 1]), 0.5 * (xs[k + 1] - xs[k]));
                let at: Vec<f64> = nodes.iter().map(|t| mid + half * t).collect();
                let sections = hull.sections_in_interval(k, &at);
                at.into_iter()
                    .zip(sections)
                    .zip(&weights)
                    .map(move |((x, s), wt)| (x, wt * half, s.properties(loading.draft_at(x, lpp))))
                    .collect::<Vec<_>>()
            })
            .collect();
        let int = |f: &dyn Fn(f64, &SectionProperties) -> f64| -> f64 {
            samples.iter().map(|(x, w, p)| w * f(*x, p)).sum()
        };
        let volume = int(&|_, p| p.area);
        let safe = |num: f64, den: f64| if den > 0.0 { num / den } else { 0.0 };
        let lcb = safe(int(&|x, p| x * p.area), volume);
        let kb = safe(int(&|_, p| p.area * p.centroid_z), volume);
        let awp = int(&|_, p| 2.0 * p.half_breadth);
        let lcf = safe(int(&|x, p| 2.0 * x * p.half_breadth), awp);
        let i_l = int(&|x, p| 2.0 * p.half_breadth * (x - lcf).powi(2));
        let i_t = int(&|_, p| 2.0 / 3.0 * p.half_breadth.powi(3));
        let bm_t = safe(i_t, volume);
        let bm_l = safe(i_l, volume);
        let t_mean = loading.mean_draft();
        // Largest waterline breadth over the stations and the interpolated sections between them (with
        // trim or flare the widest waterline need not lie at a station).
        let beam = 2.0
            * sac
                .iter()
                .map(|s| s.half_breadth_m)
                .chain(samples.iter().map(|(_, _, p)| p.half_breadth))
                .fold(0.0, f64::max);
        let am = match hull.section_at(0.0) {
            Ok(s) => s.properties(loading.draft_at(0.0, lpp)).area,
            Err(_) => 0.0,
        };
        Self {
            loading: loading.name.clone(),
            lpp_m: lpp,
            beam_wl_m: beam,
            mean_draft_m: t_mean,
            trim_by_stern_m: loading.trim_by_stern(),
            rho_kg_m3: loading.rho,
            volume,
            displacement_kg: loading.rho * volume,
            lcb,
            kb,
            awp,
            lcf,
            bm_t,
            bm_l,
            gm_t: kb + bm_t - loading.kg,
            gm_l: kb + bm_l - loading.kg,
            am,
            cb: safe(volume, lpp * beam * t_mean),
            cp: safe(volume, am * lpp),
            cm: safe(am, beam * t_mean),
            cwp: safe(awp, lpp * beam),
            sectional_area: sac,
        }
    }

    /// Mass properties of `loading`, defaulting mass to buoyancy and LCG to LCB where the file is silent.
    pub fn mass_properties(&self, loading: &LoadingCondition) -> MassProperties {
        let mass = loading.displacement_kg.unwrap_or(self.displacement_kg);
        MassProperties {
            mass_kg: mass,
            mass_from_buoyancy: loading.displacement_kg.is_none(),
            lcg_m: loading.lcg.unwrap_or(self.lcb),
            lcg_from_lcb: loading.lcg.is_none(),
            kg_m: loading.kg,
            k_yy_m: loading.k_yy,
            mass_buoyancy_mismatch: (mass - self.displacement_kg) / self.displacement_kg,
        }
    }
}
