//! Zhao & Faltinsen (1993) similarity solution of wedge entry at constant speed: the tabulated peak
//! pressure for beta = 20 deg.
//!
//! Source (as copied in `data/reference/water_entry_theory.md`): Iafrati (2013), Table 1, Zhao-Faltinsen
//! columns: Cp_max = 17.77 at z/(V t) = 0.5087, z measured from the undisturbed free surface (apex at
//! z/(V t) = -1). Only the 20 deg value is available in the reference data.

/// Deadrise of the tabulated value (deg).
pub const DEADRISE_DEG: f64 = 20.0;
/// Peak pressure coefficient 2 p_max / (rho V^2).
pub const CP_MAX: f64 = 17.77;
/// Height of the peak above the undisturbed free surface, divided by V t.
pub const Z_OVER_VT: f64 = 0.5087;

/// The similarity value for a deadrise in degrees, if tabulated.
pub fn peak(deadrise_deg: f64) -> Option<(f64, f64)> {
    ((deadrise_deg - DEADRISE_DEG).abs() < 1e-9).then_some((CP_MAX, Z_OVER_VT))
}
