//! When the water, rising relative to the hull, reaches a given height on a section in a regular wave
//! (bow-flare impact, Veen 2010 s. 6.2), and how fast.
//!
//! With the relative motion s(t) = Re(s_a e^{i w_e t}) (positive: hull above the local water surface,
//! [`crate::seakeeping::relative_motion`]) at a station of local draft T, the undisturbed water surface is
//! at height T - s above the keel. It reaches height h above the keel, rising, when s falls through
//! T - h, that is at w_e t + arg(s_a) = arccos((T - h) / |s_a|); the downward velocity of the section
//! relative to the water then is V = -Re(v_a e^{i w_e t}). Keel entry is h = 0. The undisturbed surface
//! is used: the pile-up of the water on the section (Wagner) makes the actual wetting earlier.

use nalgebra::Complex;
use serde::Serialize;

use crate::seakeeping::relative_motion::RelativeMotion;

/// The instant the water reaches a height on the section and the relative velocity then.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Crossing {
    /// Instant within the encounter period (s; 0: wave crest at midship).
    pub time_s: f64,
    /// Downward velocity of the section relative to the water (m/s).
    pub velocity_m_per_s: f64,
}

/// The crossing of height `h` above the keel (m) at a station of local draft `draft` in a regular wave of
/// amplitude `zeta_a` and encounter frequency `omega_e`; None when the water never reaches it or never
/// falls below it (|T - h| >= |s_a|).
pub fn water_reaches(
    rm: &RelativeMotion,
    omega_e: f64,
    zeta_a: f64,
    draft: f64,
    h: f64,
) -> Option<Crossing> {
    let amp = rm.motion.norm() * zeta_a;
    let level = draft - h;
    if amp.is_nan() || amp <= level.abs() || omega_e.is_nan() || omega_e <= 0.0 {
        return None;
    }
    let period = 2.0 * std::f64::consts::PI / omega_e;
    let phase = (level / amp).acos() - rm.motion.arg();
    let t = (phase / omega_e).rem_euclid(period);
    let v = -(rm.velocity * Complex::new(0.0, omega_e * t).exp()).re * zeta_a;
    Some(Crossing {
        time_s: t,
        velocity_m_per_s: v,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pure_heave_crossing_by_hand() {
        // s = 0.2 cos(t) (w_e = 1, zeta_a = 1), v = Ds/Dt = -0.2 sin(t); T = 0.1, h = 0.2: s falls
        // through -0.1 at t = arccos(-0.5) = 2 pi / 3, V = 0.2 sin(2 pi / 3)
        let rm = RelativeMotion {
            x: 0.0,
            motion: Complex::new(0.2, 0.0),
            velocity: Complex::new(0.0, 0.2),
        };
        let c = water_reaches(&rm, 1.0, 1.0, 0.1, 0.2).unwrap();
        assert!((c.time_s - 2.0 * std::f64::consts::PI / 3.0).abs() < 1e-12);
        assert!(
            (c.velocity_m_per_s - 0.2 * (2.0 * std::f64::consts::PI / 3.0).sin()).abs() < 1e-12
        );
        assert!(water_reaches(&rm, 1.0, 1.0, 0.1, 0.4).is_none());
    }
}
