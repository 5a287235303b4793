//! Air as a second phase: the adiabatic equation of state and the pair terms between the phases
//! (issue 30).
//!
//! **Why.** Below about 15-20 deg of deadrise the water meets the hull through a thin layer of air that
//! has to escape sideways; its compression spreads the impact and lowers the peak pressure (Veen 2010,
//! ch. 5-6: single-phase SPH about twice the measured keel pressure on Breder's 10 deg wedge and Ochi's
//! flat 0.174 Lpp section). The air is modelled as a second weakly compressible fluid with its real density
//! and its real compressibility.
//!
//! **Equation of state.** Adiabatic air about atmospheric pressure p_a, gauge pressure (the water's
//! pressures are gauge too):
//!
//! p = p_a [ (rho / rho_a)^gamma - 1 ],   gamma = 1.4,
//!
//! with rho_a the density at p_a (1.204 kg/m3 at 20 deg C and 101 325 Pa) and the sound speed
//! c_a = sqrt(gamma p_a / rho_a) = 343 m/s. The air is not given an artificial sound speed: its
//! compressibility is the physics of the cushion (Verhagen 1967), so the air takes its own time steps,
//! limited by c_a, within the water's step ([`crate::sph::solver`], multiple time stepping).
//!
//! **Pair terms between the phases.** The scheme is the low-dissipation Riemann SPH of the water
//! ([`crate::sph::riemann`]; Zhang, Hu & Adams 2017). For a pair of particles of different phases the
//! one-dimensional Riemann problem along e_ij has a left state (rho_L, U_L, p_L) with impedance
//! Z_L = rho_L c_L and a right one with Z_R = rho_R c_R. Its linearised (acoustic) solution follows from
//! the two characteristic relations p* - p_L = Z_L (U_L - U*) and p* - p_R = Z_R (U* - U_R) (Toro 2009,
//! *Riemann Solvers and Numerical Methods for Fluid Dynamics*, 3rd ed., sec. 9.3, the primitive-variable
//! solver; the two-phase form is the one of Rezavand, Zhang & Hu 2020, J. Comput. Phys. 402, 109092):
//!
//! U* = (Z_L U_L + Z_R U_R + p_L - p_R) / (Z_L + Z_R),
//! P* = (Z_R p_L + Z_L p_R + Z_L Z_R (U_L - U_R)) / (Z_L + Z_R).
//!
//! With Z_L = Z_R it is the single-phase solver of [`crate::sph::riemann`]. Between water (Z about
//! 10^5 kg/m2 s) and air (413 kg/m2 s) it gives what the physics asks of an interface: the water sees
//! the air's pressure (P* -> p_air) and the air moves with the water at the interface (U* -> U_water). The
//! dissipation term Z_L Z_R / (Z_L + Z_R) (U_L - U_R) gets the limiter of the single-phase scheme,
//! beta / c with beta = min(eta max(U_L - U_R, 0), c) and c the smaller sound speed of the pair (so
//! that it acts on approaching pairs only and reduces to the single-phase limiter for one phase).
//!
//! The momentum equation keeps its form, D u_i / Dt = -sum_j 2 P* / rho_i grad_i W_ij V_j, and P* is
//! symmetric in i and j, so momentum is exchanged pairwise between the phases. The continuity equation
//! D rho_i / Dt = 2 rho_i sum_j (u_i - u*) . grad_i W_ij V_j would become, with grad_i W_ij = F r_ij and
//! 2 (U_L - U*) = 2 Z_R (U_L - U_R) / (Z_L + Z_R) - 2 (p_L - p_R) / (Z_L + Z_R),
//!
//! D rho_i / Dt = rho_i sum_j F V_j [ 2 Z_j / (Z_i + Z_j) (u_i - u_j) . r_ij
//!                                    + 2 |r_ij| (p_i - p_j - Dp_h) / (Z_i + Z_j) ]
//!
//! (Dp_h the hydrostatic part of the pressure difference, left out as in the single-phase term). Two
//! departures from it, both measured:
//!
//! * **The air's density: the velocity divergence with weight 1.** The Riemann weight 2 Z_water /
//!   (Z_water + Z_air), about 2, counts the water's velocity twice, as for a wall whose velocity is
//!   mirrored; but the water particles in the kernel carry their own velocity, and the consistent SPH
//!   divergence of a velocity field that is continuous across the interface has weight 1 (as for the wall
//!   dummies, which carry the wall's velocity). With weight 2 an air particle carried into water under
//!   tension expanded without bound: Ochi's flat station 0.174 Lpp at 1 m/s diverged at t = 111 ms with
//!   16 mm spacing and at 142 ms with 10.4 mm, an air particle at a fifth of the air's density and 230 m/s.
//!   With weight 1 the 16 mm run completes. The pressure-relaxation part is kept.
//! * **The water's density takes no flux from the air.** For a water particle the divergence weight would
//!   be 2 Z_air / (Z_water + Z_air), about 1 % at c0 = 80 m/s, and the second part relaxes the water's
//!   pressure towards the air's at the interface, at twice the rate of the single-phase dissipation
//!   between water particles. That changed the water's flow where air is irrelevant: on a 30 deg wedge at
//!   5 m/s (6.25 mm spacing, interpolated sensors) the sensor peaks fell 1-19 % below the water-only run's
//!   with it, and stayed within 1 % (three sensors) and 11 % (one) without it, the section force within
//!   0.5 %. So for the water's continuity the air is a free surface, as in the single-phase scheme, and the
//!   air acts on the water through the momentum equation, where P* is the air's pressure.
//!
//! Against wall and body dummies an air particle takes its own pressure as the wall's (p_w = p_i, the
//! wall condition of Zhang et al. 2017 without gravity, which for air is 1.2 Pa a metre) and the mirrored
//! wall velocity; the dummies' extrapolated pressure ([`crate::sph::boundary::adami2012`]) is the water's
//! alone, so a water particle next to a dummy is not pulled by the air's lower pressure.

use serde::{Deserialize, Serialize};

use crate::sph::riemann::ETA;

/// Density of air at 20 deg C and 101 325 Pa (kg/m3; ISO 2533 standard atmosphere gives 1.225 at
/// 15 deg C, the ideal gas law 1.204 at 20 deg C).
pub const AIR_DENSITY: f64 = 1.204;

/// Atmospheric pressure (Pa).
pub const ATMOSPHERIC_PRESSURE: f64 = 101_325.0;

/// Ratio of specific heats of air.
pub const AIR_GAMMA: f64 = 1.4;

/// Whether a run has air: `on`, `off`, or `auto` (on where the section's deadrise is low within the
/// event's expected wetted width, [`auto_needs_air`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum AirChoice {
    On,
    #[default]
    Off,
    Auto,
}

/// The air gap under the keel at the start of a keel entry with air, in particle spacings: at least
/// three rows of air between the keel and the water, so that the section has air to push out before it
/// meets the water (the air cushion forms in that approach; Verhagen 1967).
pub const CLEARANCE_DP: f64 = 4.0;

/// The air gap under a flat keel, as a fraction of the flat's half-width (the default gap is the larger
/// of this and [`CLEARANCE_DP`] spacings). Measured on a flat bottom of 0.2 m half-width at 2 m/s
/// (docs/guide/air.md): the impact's force peak was 41.7, 31.2 and 33.3 kN/m with gaps of 0.125, 0.25
/// and 0.5 half-widths at 6.25 mm spacing, and 34.6, 31.2 and 31.1 kN/m at 12.5, 6.25 and 3.125 mm with
/// 0.25: from a quarter of the half-width the gap no longer sets the cushion.
pub const FLAT_GAP_FRACTION: f64 = 0.25;

/// The deadrise below which `--air auto` runs with air (deg): the lower end of the 15-20 deg below
/// which an air cushion forms (Veen 2010, ch. 5; Chuang 1966 measured it for wedges up to 15 deg).
pub const AUTO_DEADRISE_DEG: f64 = 15.0;

/// Whether `--air auto` runs a section with air, and why: the smallest deadrise of the starboard half
/// contour `half` (keel first) below `wetted_half_width` from the centre plane, against
/// [`AUTO_DEADRISE_DEG`].
pub fn auto_needs_air(half: &[[f64; 2]], wetted_half_width: f64) -> (bool, String) {
    let mut least = f64::INFINITY;
    for w in half.windows(2) {
        let (a, b) = (w[0], w[1]);
        if a[0] >= wetted_half_width {
            break;
        }
        let (dy, dz) = (b[0] - a[0], b[1] - a[1]);
        if dy > 0.0 {
            least = least.min(dz.atan2(dy).to_degrees().max(0.0));
        }
    }
    if !least.is_finite() {
        return (
            false,
            format!(
                "{AUTO_NOTE} no contour within the expected wetted half-width {wetted_half_width:.3} m rises outward; water only"
            ),
        );
    }
    let on = least < AUTO_DEADRISE_DEG;
    let why = format!(
        "{AUTO_NOTE} smallest deadrise {least:.1} deg within the expected wetted half-width {wetted_half_width:.3} m, \
         {} the {AUTO_DEADRISE_DEG} deg below which an air cushion forms: {}",
        if on { "below" } else { "not below" },
        if on { "with air" } else { "water only" }
    );
    (on, why)
}

/// The note of a run's setup ([`crate::sph::case::Setup::notes`]) that says whether the run has air and
/// why: `air: on (given)` or the `air auto: ...` of [`auto_needs_air`]; `None` when air was off.
pub fn decision_note<S: AsRef<str>>(notes: &[S]) -> Option<&str> {
    notes
        .iter()
        .map(AsRef::as_ref)
        .find(|n| n.starts_with(AUTO_NOTE) || n.starts_with(ON_NOTE))
}

/// The notes of a run's setup about its air: the decision ([`decision_note`]), the layer and the gap.
pub fn notes<S: AsRef<str>>(notes: &[S]) -> impl Iterator<Item = &str> {
    notes
        .iter()
        .map(AsRef::as_ref)
        .filter(|n| n.starts_with("air"))
}

/// How the decision notes start.
pub const AUTO_NOTE: &str = "air auto:";
pub const ON_NOTE: &str = "air: on";

/// The air of a two-phase run: its equation of state and where its particles start.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct AirLayer {
    /// Density at atmospheric pressure (kg/m3).
    #[serde(rename = "density_kg_per_m3")]
    pub rho0: f64,
    /// Atmospheric (reference) pressure (Pa, absolute); the run's pressures are gauge.
    #[serde(rename = "atmospheric_pressure_pa")]
    pub p_atm: f64,
    pub gamma: f64,
    /// Half-width of the layer about the centre plane (m).
    #[serde(rename = "half_width_m")]
    pub half_width: f64,
    /// Height of the layer above the calm water surface (m).
    #[serde(rename = "height_m")]
    pub height: f64,
    /// Height of the keel above the calm surface at the start of the run (m; keel entries only): the air
    /// gap the section closes before it reaches the water. The run starts at t = -clearance / V0, so
    /// that t = 0 stays the instant the keel reaches the calm surface.
    #[serde(rename = "clearance_m", default)]
    pub clearance: f64,
}

impl AirLayer {
    /// Standard air in a layer of the given extent.
    pub fn standard(half_width: f64, height: f64, clearance: f64) -> Self {
        Self {
            rho0: AIR_DENSITY,
            p_atm: ATMOSPHERIC_PRESSURE,
            gamma: AIR_GAMMA,
            half_width,
            height,
            clearance,
        }
    }

    /// The air's equation of state.
    pub fn phase(&self) -> AirPhase {
        AirPhase {
            rho0: self.rho0,
            p_atm: self.p_atm,
            gamma: self.gamma,
            c: (self.gamma * self.p_atm / self.rho0).sqrt(),
        }
    }
}

/// Adiabatic air: p = p_a ((rho / rho_a)^gamma - 1) (gauge), sound speed c = sqrt(gamma p_a / rho_a).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AirPhase {
    pub rho0: f64,
    pub p_atm: f64,
    pub gamma: f64,
    /// Sound speed at atmospheric pressure (m/s).
    pub c: f64,
}

impl AirPhase {
    /// Gauge pressure from density.
    #[inline(always)]
    pub fn pressure(&self, rho: f64) -> f64 {
        self.p_atm * ((rho / self.rho0).powf(self.gamma) - 1.0)
    }

    /// Density from gauge pressure (the inverse of [`AirPhase::pressure`]; a gauge pressure at or below
    /// -p_a, a vacuum, gives a density of zero).
    #[inline(always)]
    pub fn density(&self, p: f64) -> f64 {
        let b = (1.0 + p / self.p_atm).max(0.0);
        self.rho0 * b.powf(1.0 / self.gamma)
    }
}

/// 2 P* of an air particle i (pressure `p_i`, density `rho_i`, sound speed `c`) with a wall or body
/// dummy, for the momentum sum and the body force: the air's own pressure as the wall's and the mirrored
/// wall velocity (see the module doc). `vdotr` = (u_i - u_w) . r_iw, r = |r_iw|.
#[inline(always)]
pub fn wall_pressure_sum(p_i: f64, rho_i: f64, vdotr: f64, r: f64, c: f64) -> f64 {
    crate::sph::riemann::pressure_sum(p_i, p_i, rho_i, rho_i, vdotr, r, c, false)
}

/// One side of a pair: pressure, density and sound speed of a particle.
#[derive(Debug, Clone, Copy)]
pub struct State {
    pub p: f64,
    pub rho: f64,
    pub c: f64,
}

/// 2 P* of a pair of different phases, for the momentum sum (see the module doc). `vdotr` =
/// (u_i - u_j) . r_ij and r = |r_ij| > 0.
#[inline(always)]
pub fn interface_pressure_sum(i: State, j: State, vdotr: f64, r: f64) -> f64 {
    if r <= 0.0 {
        return i.p + j.p;
    }
    let (zi, zj) = (i.rho * i.c, j.rho * j.c);
    let du = -vdotr / r; // U_L - U_R
    let c = i.c.min(j.c);
    let approach = if du > 0.0 { ETA * du } else { 0.0 };
    let beta = if approach < c { approach } else { c };
    let zsum = zi + zj;
    2.0 * (zj * i.p + zi * j.p + zi * zj * (beta / c) * du) / zsum
}

/// The continuity term of an air particle i with a water neighbour j, to be multiplied by rho_i: F V_j
/// times [(u_i - u_j) . r_ij + 2 r (p_i - p_j - Dp_h) / (Z_i + Z_j)] (see the module doc: the velocity
/// divergence with weight 1, the pressure relaxation of the two-phase Riemann solver). `fv` = F V_j.
#[inline(always)]
pub fn interface_continuity_term(
    i: State,
    j: State,
    vdotr: f64,
    r: f64,
    fv: f64,
    dp_hydro: f64,
) -> f64 {
    let zsum = i.rho * i.c + j.rho * j.c;
    fv * (vdotr + 2.0 * r * (i.p - j.p - dp_hydro) / zsum)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sph::riemann;

    fn air() -> AirPhase {
        AirLayer::standard(1.0, 1.0, 0.0).phase()
    }

    #[test]
    fn standard_air_has_its_sound_speed_and_inverts() {
        let a = air();
        assert!((a.c - 343.1).abs() < 0.5, "{}", a.c);
        for p in [-50_000.0, -100.0, 0.0, 3000.0, 2.0e5] {
            let r = a.density(p);
            assert!((a.pressure(r) - p).abs() < 1e-6 * (1.0 + p.abs()), "{p}");
        }
        // Small changes: dp = c^2 drho.
        let dr = 1e-6;
        let slope = a.pressure(a.rho0 + dr) / dr;
        assert!((slope / (a.c * a.c) - 1.0).abs() < 1e-4);
        assert_eq!(a.density(-2.0 * a.p_atm), 0.0);
    }

    #[test]
    fn one_phase_gives_the_single_phase_solver() {
        // Equal densities and sound speeds: the same P* as the single-phase scheme (which uses the mean
        // density; with equal densities the two agree to rounding).
        let (c, rho) = (60.0, 1000.0);
        for (pi, pj, vdotr) in [
            (1000.0, 300.0, -0.02),
            (0.0, 50.0, 0.01),
            (2.0e4, 1.0e4, -0.4),
        ] {
            let i = State { p: pi, rho, c };
            let j = State { p: pj, rho, c };
            let r = 0.01;
            let two = interface_pressure_sum(i, j, vdotr, r);
            let one = riemann::pressure_sum(pi, pj, rho, rho, vdotr, r, c, true);
            assert!((two - one).abs() < 1e-9 * one.abs().max(1.0), "{two} {one}");
            let fv = 3.0;
            let cont = interface_continuity_term(i, j, vdotr, r, fv, 0.0);
            let want = fv * vdotr + riemann::continuity_term(pi, pj, rho, rho, fv, r, c, 0.0);
            assert!(
                (cont - want).abs() < 1e-9 * want.abs().max(1.0),
                "{cont} {want}"
            );
        }
    }

    #[test]
    fn water_sees_the_air_pressure_and_the_air_the_water_velocity() {
        let a = air();
        let water = State {
            p: 5000.0,
            rho: 1000.0,
            c: 60.0,
        };
        let gas = State {
            p: 200.0,
            rho: a.rho0,
            c: a.c,
        };
        // At rest relative to each other: P* is within 1 % of the air pressure's share.
        let p_star = 0.5 * interface_pressure_sum(water, gas, 0.0, 0.01);
        assert!((p_star - 200.0).abs() < 0.01 * 4800.0, "{p_star}");
        // Symmetric in the pair.
        let back = 0.5 * interface_pressure_sum(gas, water, 0.0, 0.01);
        assert!((back - p_star).abs() < 1e-9 * p_star.abs());
        // The air's density rate: the water's velocity with weight 1 (at equal pressures).
        let (vdotr, r, fv) = (-0.01, 0.01, 1.0);
        let g = interface_continuity_term(State { p: 5000.0, ..gas }, water, vdotr, r, fv, 0.0);
        assert!((g / vdotr - 1.0).abs() < 1e-12, "{}", g / vdotr);
        // A pressure difference relaxes at the pair's impedance: nearly the water's.
        let d = interface_continuity_term(State { p: 5100.0, ..gas }, water, 0.0, r, fv, 0.0);
        let (zw, za) = (water.rho * water.c, gas.rho * gas.c);
        assert!((d - 2.0 * r * 100.0 / (zw + za)).abs() < 1e-15, "{d}");
    }

    #[test]
    fn auto_reads_the_deadrise_within_the_wetted_width() {
        // A flat keel to 0.1 m, then a 45 deg bilge.
        let flat = [[0.0, 0.0], [0.1, 0.0], [0.2, 0.1]];
        assert!(auto_needs_air(&flat, 0.05).0);
        // A 30 deg V: never below 15 deg.
        let v = [[0.0, 0.0], [0.2, 0.2 * 30f64.to_radians().tan()]];
        let (on, why) = auto_needs_air(&v, 0.15);
        assert!(!on && why.contains("30.0 deg"), "{why}");
        // A 10 deg keel wedge to 0.05 m, then steep: on within 0.05 m, on beyond it too (the keel is
        // wetted first).
        let keel = [
            [0.0, 0.0],
            [0.05, 0.05 * 10f64.to_radians().tan()],
            [0.1, 0.1],
        ];
        assert!(auto_needs_air(&keel, 0.02).0);
        // A contour that only rises vertically within the width: water only, said so.
        let wall = [[0.0, 0.0], [0.0, 0.1]];
        let (on, why) = auto_needs_air(&wall, 0.05);
        assert!(!on && why.contains("water only"), "{why}");
    }
}
