//! Equations of state of weakly compressible water.
//!
//! * Linear: p = c0^2 (rho - rho0).
//! * Tait (Monaghan 1994, J. Comput. Phys. 110): p = rho0 c0^2 / gamma ((rho/rho0)^gamma - 1), gamma = 7.
//!
//! Both have the sound speed c0 at rho0. c0 is chosen so that the density varies by about 1 % at the
//! expected peak pressure (see `case.rs`).

use serde::{Deserialize, Serialize};

/// Which equation of state.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum EosKind {
    Linear,
    Tait,
}

/// An equation of state with its constants.
#[derive(Debug, Clone, Copy)]
pub struct Eos {
    pub kind: EosKind,
    pub rho0: f64,
    pub c0: f64,
}

const GAMMA: f64 = 7.0;

impl Eos {
    /// Pressure from density.
    #[inline(always)]
    pub fn pressure(&self, rho: f64) -> f64 {
        match self.kind {
            EosKind::Linear => self.c0 * self.c0 * (rho - self.rho0),
            EosKind::Tait => {
                self.rho0 * self.c0 * self.c0 / GAMMA * ((rho / self.rho0).powi(7) - 1.0)
            }
        }
    }

    /// Density from pressure (inverse of [`Eos::pressure`]).
    #[inline(always)]
    pub fn density(&self, p: f64) -> f64 {
        match self.kind {
            EosKind::Linear => self.rho0 + p / (self.c0 * self.c0),
            EosKind::Tait => {
                let b = 1.0 + GAMMA * p / (self.rho0 * self.c0 * self.c0);
                self.rho0 * b.max(1e-6).powf(1.0 / GAMMA)
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn density_inverts_pressure() {
        for kind in [EosKind::Linear, EosKind::Tait] {
            let e = Eos {
                kind,
                rho0: 1000.0,
                c0: 80.0,
            };
            for p in [-2000.0, 0.0, 5000.0, 120_000.0] {
                let r = e.density(p);
                assert!(
                    (e.pressure(r) - p).abs() < 1e-6 * (1.0 + p.abs()),
                    "{kind:?} {p}"
                );
            }
        }
    }
}
