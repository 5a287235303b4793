//! When the water, rising relative to the hull, reaches a given height on a section in a regular wave
//! (bow-flare impact, Veen 2010 s. 6.2), and how fast.
//!
//! With the relative motion s(t) = Re(s_a e^{i w_e t}) (positive: hull above the local water surface,
//! [`crate::seakeeping::relative_motion`]) at a station of local draft T, the undisturbed water surface is
//! at height T - s above the keel. It reaches height h above the keel, rising, when s falls through
//! T - h, that is at w_e t + arg(s_a) = arccos((T - h) / |s_a|); the downward velocity of the section
//! relative to the water then is V = -Re(v_a e^{i w_e t}). Keel entry is h = 0. The undisturbed surface
//! is used: the pile-up of the water on the section (Wagner) makes the actual wetting earlier.
//!
//! # The flare event (keel immersed)
//!
//! Where the keel stays in the water (|s_a| < T) but the rising water reaches sensors above the
//! still-water line, the section still slams on its flare (the normal design case of large ships with an
//! immersed forefoot). The event ([`immersed_start`]) starts at the instant of least immersion, when s(t)
//! is at its maximum |s_a| and the keel is d0 = T - |s_a| below the local water surface, and is driven by
//! the downward relative velocity V(t) = -Ds/Dt from that instant until V reverses (the keel then is about
//! T + |s_a| deep). As in the 2D+t idealisation of Veen (2010) the 2D run starts with the section immersed
//! to d0 in **water at rest** with a flat surface: the wave orbital flow around the section and the flow
//! radiated by its earlier cycle of motion are neglected, and so is the free-surface elevation they carry.
//! What this implies: the rise of the water relative to the section is that of strip theory, but the local
//! flow at the flare at impact (its velocity and the water already piled up or drawn down there) is not;
//! the slam pressure, which scales with the square of the velocity of the contact point, depends on both,
//! so the estimate is only as good as the relative velocity at flare impact, and starting from rest
//! misses the momentum the water already has at the instant of least immersion.

use nalgebra::Complex;
use serde::Serialize;

use crate::seakeeping::relative_motion::{self, EntrySample, RelativeMotion};

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

/// The start of a flare event: the section at its least immersion d0 = T - |s_a| in a regular wave, and
/// the downward relative velocity from that instant until it reverses.
#[derive(Debug, Clone, Serialize)]
pub struct ImmersedStart {
    /// Keel depth below the undisturbed local water surface at the start, d0 = T - |s_a| (m).
    pub immersion_m: f64,
    /// Instant of least immersion within the encounter period (s; 0: wave crest at midship).
    pub start_time_s: f64,
    pub encounter_period_s: f64,
    /// V(t) from the start: `time_since_entry_s` counts from the start, `penetration_m` is the keel depth
    /// T - s(t).
    pub samples: Vec<EntrySample>,
}

/// The flare event at a station of local draft `draft` whose keel stays immersed (0 < |s_a| < T) in a
/// regular wave of amplitude `zeta_a`: the start at least immersion and `n` samples of V(t) until V, once
/// positive, reverses or the keel is `max_depth` deep. None when the keel emerges (a keel-entry event
/// instead), the relative motion vanishes or `n < 2`.
pub fn immersed_start(
    rm: &RelativeMotion,
    omega_e: f64,
    zeta_a: f64,
    draft: f64,
    max_depth: f64,
    n: usize,
) -> Option<ImmersedStart> {
    let amp = rm.motion.norm() * zeta_a;
    if !(amp > 0.0 && amp < draft && omega_e > 0.0 && n >= 2) {
        return None;
    }
    let period = 2.0 * std::f64::consts::PI / omega_e;
    // s(t) = amp cos(w t + arg s_a) is largest at w t + arg s_a = 0
    let t0 = (-rm.motion.arg() / omega_e).rem_euclid(period);
    let samples =
        relative_motion::entry_samples(rm, omega_e, zeta_a, draft, t0, max_depth, n, true);
    Some(ImmersedStart {
        immersion_m: draft - amp,
        start_time_s: t0,
        encounter_period_s: period,
        samples,
    })
}

/// Height above the keel (m) of the lower and upper edges of a sensor panel centred at girth `girth`
/// (m from the keel along the contour) and `width` wide, on the section `points` (starboard half, keel
/// first).
pub fn panel_edges(points: &[[f64; 2]], girth: f64, width: f64) -> Option<(f64, f64)> {
    let sec = crate::hull::Section {
        points: points.to_vec(),
    };
    if points.len() < 2 {
        return None;
    }
    let z0 = points[0][1];
    let a = sec.point_at_girth((girth - 0.5 * width).max(0.0))[1] - z0;
    let b = sec.point_at_girth(girth + 0.5 * width)[1] - z0;
    Some((a.min(b), a.max(b)))
}

/// The sensors a flare event strikes at a station of local draft `draft` with relative-motion amplitude
/// `amp` (m): those with part of the panel above the still-water line (upper edge above T) that the
/// undisturbed water surface reaches at its highest (lower edge below T + amp). Each with the height of
/// its lower edge above the keel (m).
pub fn struck_sensors(
    points: &[[f64; 2]],
    sensors: &[crate::sph::SensorSpec],
    draft: f64,
    amp: f64,
) -> Vec<(String, f64)> {
    sensors
        .iter()
        .filter_map(|s| {
            let (lo, hi) = panel_edges(points, s.s_m, s.width_m)?;
            (hi > draft && lo < draft + amp).then(|| (s.name.clone(), lo))
        })
        .collect()
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

    #[test]
    fn an_immersed_start_by_hand() {
        // s = 0.2 cos(t), V = -Ds/Dt = 0.2 sin(t) (w_e = 1): with T = 0.3 the keel stays in; the event
        // starts at t = 0 with the keel 0.1 deep and runs until V reverses at t = pi (keel 0.5 deep).
        let rm = RelativeMotion {
            x: 0.0,
            motion: Complex::new(0.2, 0.0),
            velocity: Complex::new(0.0, 0.2),
        };
        let e = immersed_start(&rm, 1.0, 1.0, 0.3, 10.0, 21).unwrap();
        assert!((e.immersion_m - 0.1).abs() < 1e-12);
        assert!(e.start_time_s.abs() < 1e-12);
        let first = e.samples[0];
        let last = e.samples[20];
        assert!(first.velocity.abs() < 1e-12 && (first.penetration - 0.1).abs() < 1e-12);
        let pi = std::f64::consts::PI;
        assert!(
            (last.t - pi).abs() < 2.0 * pi / 2000.0 + 1e-12,
            "{}",
            last.t
        );
        assert!((last.penetration - 0.5).abs() < 1e-4);
        assert!((e.samples[10].velocity - 0.2 * e.samples[10].t.sin()).abs() < 1e-12);
        // the keel emerges with T = 0.15: a keel entry, not this
        assert!(immersed_start(&rm, 1.0, 1.0, 0.15, 10.0, 21).is_none());
    }

    #[test]
    fn struck_sensors_are_the_dry_ones_the_water_reaches() {
        // a box side: y = 0.2 from z = 0 to 1; panels 0.1 wide centred 0.2 + z along the girth
        let pts = [[0.0, 0.0], [0.2, 0.0], [0.2, 1.0]];
        let at = |name: &str, z: f64| crate::sph::SensorSpec {
            name: name.into(),
            s_m: 0.2 + z,
            width_m: 0.1,
        };
        let s = [
            at("below", 0.3),
            at("straddling", 0.5),
            at("reached", 0.6),
            at("dry", 0.8),
        ];
        let hit = struck_sensors(&pts, &s, 0.5, 0.2);
        let names: Vec<&str> = hit.iter().map(|h| h.0.as_str()).collect();
        assert_eq!(names, ["straddling", "reached"]);
        assert!((hit[1].1 - 0.55).abs() < 1e-12);
    }
}
