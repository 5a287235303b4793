//! Relative vertical motion and velocity between the hull and the local water surface at a station,
//! keel-entry instants and the entry-velocity profile v(t) in regular waves (Veen 2010, ch. 6).
//!
//! Per unit wave amplitude, at station x (x forward), with zeta(x) = e^{ikx} the incident wave:
//!
//! s(x) = eta3 - x eta5 - zeta(x)          (positive: hull higher than the water surface)
//! v(x) = Ds/Dt = i w_e s - U ds/dx = i w_e s + U eta5 + i k U zeta(x)
//!
//! D/Dt = d/dt - U d/dx is the rate of change seen in an earth-fixed transverse plane (the 2D+t slice) that
//! the ship passes at speed U; the U eta5 term is the forward-speed contribution of pitch (Journee &
//! Adegeest 2003; physics.md s. 1). An optional dynamic swell-up factor c >= 1 scales both (the bow wave
//! raises the local surface; c = 1 means none).
//!
//! The keel at a station of local draft T is out of the water when s > T; keel entry happens when s falls
//! through T, and from then on the section enters the water with velocity V(t) = -v(t) (downwards positive).
//! A dry station (keel above the calm waterline, T < 0) is the same with T negative: its keel is out of the
//! water while s > T, and keel entry needs |s| > -T.

use nalgebra::Complex;

use super::strip_theory::Response;
use crate::error::{Error, Result};

type C64 = Complex<f64>;

/// Relative motion and velocity at one station, per unit wave amplitude.
#[derive(Debug, Clone, Copy)]
pub struct RelativeMotion {
    pub x: f64,
    /// Relative vertical motion s (m per m of wave amplitude).
    pub motion: C64,
    /// Relative vertical velocity Ds/Dt (m/s per m of wave amplitude).
    pub velocity: C64,
}

/// Relative motion at station x, with dynamic swell-up factor `swell_up` (1 for none): the project's
/// definition ([`Definition::default`] with the factor), Ds/Dt with its forward-speed terms.
pub fn at_station(r: &Response, x: f64, swell_up: f64) -> Result<RelativeMotion> {
    at_station_as(
        r,
        x,
        &Definition {
            swell_up,
            ..Definition::default()
        },
    )
}

/// Which rate of change of the relative motion is called the relative velocity.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum VelocityDefinition {
    /// Ds/Dt = i w_e s + U eta5 + i k U zeta: the rate seen in an earth-fixed transverse plane (2D+t), the
    /// project's default (Journee & Adegeest 2003).
    #[default]
    EarthFixedPlane,
    /// i w_e s + i k U zeta: as the default without the forward-speed term of pitch U eta5.
    WithoutPitchSpeedTerm,
    /// ds/dt = i w_e s at a fixed station of the ship, with no forward-speed term at all: Veen (2010)
    /// eq. 6.2, "the time derivative of the relative elevation" at a point along the hull.
    ShipFixedStation,
}

/// How the relative motion at a station is formed from the heave and pitch responses.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Definition {
    /// Dynamic swell-up factor c >= 1 on the relative motion and velocity (1: none).
    pub swell_up: f64,
    pub velocity: VelocityDefinition,
    /// Take the heave of the centre of gravity, eta3 - x_G eta5, with the pitch lever x measured from
    /// amidships: s = (eta3 - x_G eta5) - x eta5 - zeta. This is Veen's eq. 6.1 (the keel amidships on the
    /// origin) fed with a heave amplitude reported at G; it differs from the consistent s by -x_G eta5.
    /// `None`: heave and pitch about the same origin (consistent).
    pub heave_of_g_at: Option<f64>,
}

impl Default for Definition {
    fn default() -> Self {
        Self {
            swell_up: 1.0,
            velocity: VelocityDefinition::default(),
            heave_of_g_at: None,
        }
    }
}

/// Relative motion at station x by `def` (see [`Definition`]); the default is the module's s and Ds/Dt.
pub fn at_station_as(r: &Response, x: f64, def: &Definition) -> Result<RelativeMotion> {
    let swell_up = def.swell_up;
    if !(swell_up.is_finite() && swell_up >= 1.0) {
        return Err(Error::Invalid(format!(
            "swell-up factor must be >= 1, got {swell_up}"
        )));
    }
    let k = r.wave_number;
    let zeta = C64::new(0.0, k * x).exp();
    let heave = match def.heave_of_g_at {
        Some(xg) => r.heave - r.pitch * xg,
        None => r.heave,
    };
    let s = heave - r.pitch * x - zeta;
    let ship_frame = C64::new(0.0, r.omega_e) * s;
    let v = match def.velocity {
        VelocityDefinition::EarthFixedPlane => {
            ship_frame + r.pitch * r.speed + C64::new(0.0, k * r.speed) * zeta
        }
        VelocityDefinition::WithoutPitchSpeedTerm => ship_frame + C64::new(0.0, k * r.speed) * zeta,
        VelocityDefinition::ShipFixedStation => ship_frame,
    };
    Ok(RelativeMotion {
        x,
        motion: s * swell_up,
        velocity: v * swell_up,
    })
}

/// One sample of an entry-velocity profile.
#[derive(Debug, Clone, Copy, serde::Serialize)]
pub struct EntrySample {
    /// Time since keel entry (s).
    #[serde(rename = "time_since_entry_s")]
    pub t: f64,
    /// Downward entry velocity V = -Ds/Dt (m/s).
    #[serde(rename = "velocity_m_per_s")]
    pub velocity: f64,
    /// Keel depth below the local water surface, T - s(t) (m).
    #[serde(rename = "penetration_m")]
    pub penetration: f64,
}

/// Keel entry in a regular wave and the velocity profile after it.
#[derive(Debug, Clone, serde::Serialize)]
pub struct KeelEntry {
    #[serde(rename = "x_m")]
    pub x: f64,
    /// Instant of keel entry within the encounter period, t in [0, T_e) (s; t = 0: crest at midship).
    #[serde(rename = "entry_time_s")]
    pub t_entry: f64,
    #[serde(rename = "encounter_period_s")]
    pub encounter_period: f64,
    /// Velocity at the instant of entry (m/s, downward positive).
    #[serde(rename = "entry_velocity_m_per_s")]
    pub entry_velocity: f64,
    pub samples: Vec<EntrySample>,
}

impl KeelEntry {
    /// Add a steady downward velocity `v` (m/s) to the entry velocity and the whole profile: the keel-slope
    /// term U dz_k/dx of the 2D+t plane ([`super::entry_definitions`]), in which the section also sinks by
    /// v t. The instant of entry and the profile's times stay those of the oscillating part (the water
    /// reaches the keel when the relative motion falls through the draft, as without the term).
    pub fn add_steady_velocity(&mut self, v: f64) {
        self.entry_velocity += v;
        for p in &mut self.samples {
            p.velocity += v;
            p.penetration += v * p.t;
        }
    }
}

/// `n` samples of the downward relative velocity V(t) and the keel depth T - s(t) of a station of local
/// draft `draft` in a regular wave of amplitude `zeta_a`, from `t_start` (times counted from it) until V
/// reverses or the keel is `max_depth` deep, within half an encounter period at the most. With
/// `wait_for_rise` (a start at rest, V = 0), V must first become positive before its reversal ends the
/// profile; otherwise the first V <= 0 after the start ends it.
#[allow(clippy::too_many_arguments)]
pub fn entry_samples(
    rm: &RelativeMotion,
    omega_e: f64,
    zeta_a: f64,
    draft: f64,
    t_start: f64,
    max_depth: f64,
    n: usize,
    wait_for_rise: bool,
) -> Vec<EntrySample> {
    let period = 2.0 * std::f64::consts::PI / omega_e;
    let s_at = |t: f64| (rm.motion * Complex::new(0.0, omega_e * t).exp()).re * zeta_a;
    let v_at = |t: f64| -(rm.velocity * Complex::new(0.0, omega_e * t).exp()).re * zeta_a;
    let steps = 2000;
    let dt = period / steps as f64;
    let mut t_end = t_start + 0.5 * period;
    let mut rising = !wait_for_rise;
    for i in 1..=steps {
        let t = t_start + i as f64 * dt;
        let v = v_at(t);
        rising |= v > 0.0;
        if (rising && v <= 0.0) || draft - s_at(t) >= max_depth {
            t_end = t;
            break;
        }
    }
    (0..n)
        .map(|i| {
            let t = t_start + (t_end - t_start) * i as f64 / (n.max(2) - 1) as f64;
            EntrySample {
                t: t - t_start,
                velocity: v_at(t),
                penetration: draft - s_at(t),
            }
        })
        .collect()
}

/// Keel entry at a station of local draft `draft` in a regular wave of amplitude `zeta_a`. None when the
/// keel does not emerge (|s| zeta_a <= draft) or, for a dry station (draft < 0, the keel above the calm
/// waterline), when the water does not reach the keel (|s| zeta_a <= -draft): either way |s| zeta_a <=
/// |draft|. The profile runs from entry until the entry velocity
/// reverses or the keel is `max_depth` below the surface (e.g. the section fully wetted), with `n` samples.
pub fn keel_entry(
    rm: &RelativeMotion,
    omega_e: f64,
    zeta_a: f64,
    draft: f64,
    max_depth: f64,
    n: usize,
) -> Option<KeelEntry> {
    let amp = rm.motion.norm() * zeta_a;
    if amp <= draft.abs() || n < 2 {
        return None;
    }
    let period = 2.0 * std::f64::consts::PI / omega_e;
    // s(t) = amp cos(w t + phi) falls through draft where w t + phi = arccos(draft / amp)
    let phase = (draft / amp).acos() - rm.motion.arg();
    let t_entry = (phase / omega_e).rem_euclid(period);
    let v_at = |t: f64| -(rm.velocity * Complex::new(0.0, omega_e * t).exp()).re * zeta_a;
    let samples = entry_samples(rm, omega_e, zeta_a, draft, t_entry, max_depth, n, false);
    Some(KeelEntry {
        x: rm.x,
        t_entry,
        encounter_period: period,
        entry_velocity: v_at(t_entry),
        samples,
    })
}
