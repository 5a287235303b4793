//! Low-dissipation Riemann-solver pair terms (Zhang, Hu & Adams 2017, J. Comput. Phys. 335, 605-620,
//! eqs. 11-17), an alternative to the delta-SPH density diffusion and the artificial viscosity.
//!
//! Between particle i (left state) and neighbour j (right state), along e_ij = (r_j - r_i) / |r_ij|:
//! U_L = u_i . e_ij, U_R = u_j . e_ij, rho_bar = (rho_i + rho_j) / 2, and
//!
//! P* = (p_i + p_j) / 2 + beta rho_bar (U_L - U_R) / 2,   beta = min(eta max(U_L - U_R, 0), c0),  eta = 3,
//! U* = (U_L + U_R) / 2 + (p_i - p_j) / (2 rho_bar c0).
//!
//! Momentum: D u_i / Dt = -sum_j 2 P* / rho_i grad_i W_ij V_j + g (so 2 P* replaces p_i + p_j of the
//! standard form; the limiter beta makes the dissipation act on approaching pairs only).
//! Continuity: D rho_i / Dt = 2 rho_i sum_j (u_i - u*_ij) . grad_i W_ij V_j, which with grad_i W_ij = F r_ij
//! is the standard divergence term plus rho_i sum_j (p_i - p_j) / (rho_bar c0) F |r_ij| V_j (here with the
//! hydrostatic part of p_i - p_j left out, see [`continuity_term`]).
//!
//! Wall and body dummies (Adami et al. 2012 pressure) take part in the momentum term with the wall
//! velocity mirrored (U_R = 2 u_w . e - U_L, so U_L - U_R = 2 (u_i - u_w) . e): a particle running into a
//! wall is damped like one running into its mirror image. The continuity dissipation is exchanged between
//! fluid particles only (a flux to a dummy would carry mass through the wall, as for the delta-SPH term).

/// Limiter factor eta of the low-dissipation scheme (Zhang et al. 2017).
pub const ETA: f64 = 3.0;

/// 2 P* for the momentum sum (replaces p_i + p_j). `vdotr` = (u_i - u_j) . r_ij, r = |r_ij|; `fluid` is
/// false for a wall or body dummy j (whose velocity is the wall velocity).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn pressure_sum(
    p_i: f64,
    p_j: f64,
    rho_i: f64,
    rho_j: f64,
    vdotr: f64,
    r: f64,
    c0: f64,
    fluid: bool,
) -> f64 {
    if r <= 0.0 {
        return p_i + p_j;
    }
    // U_L - U_R = (u_i - u_j) . e_ij = -(u_i - u_j) . r_ij / r (doubled against a mirrored wall state).
    let du = if fluid { -vdotr / r } else { -2.0 * vdotr / r };
    // Comparisons rather than f64::max/min (same results, NaN included: a NaN du gives beta = 0 either
    // way), which keeps the NaN bookkeeping of max/min out of the pair loop.
    let approach = if du > 0.0 { ETA * du } else { 0.0 };
    let beta = if approach < c0 { approach } else { c0 };
    p_i + p_j + beta * 0.5 * (rho_i + rho_j) * du
}

/// The continuity dissipation of one fluid pair: (p_i - p_j - Dp_h) / (rho_bar c0) F |r_ij| V_j (to be
/// multiplied by rho_i), `fv` = F V_j. `dp_hydro` = -rho0 g (z_i - z_j) is the hydrostatic part of the
/// pressure difference, which is left out so that water at rest stays at rest (with the full difference
/// the term diffuses the hydrostatic density gradient away: a still tank lost about 27 % of its bottom
/// pressure in 3 s; a correction of this implementation, in the spirit of the hydrostatic correction of
/// the delta-SPH term).
#[inline(always)]
#[allow(clippy::too_many_arguments)]
pub fn continuity_term(
    p_i: f64,
    p_j: f64,
    rho_i: f64,
    rho_j: f64,
    fv: f64,
    r: f64,
    c0: f64,
    dp_hydro: f64,
) -> f64 {
    (p_i - p_j - dp_hydro) / (0.5 * (rho_i + rho_j) * c0) * fv * r
}
