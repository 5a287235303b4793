//! Design events for irregular seas (issue #10): one water entry per slamming station, speed and sea,
//! whose entry velocity comes from Ochi's slam statistics and whose profile shape comes from the response
//! at the spectral peak.
//!
//! * **Entry velocity.** Given a slam (the keel emerges and re-enters faster than the threshold v_th),
//!   the entry velocity V is Rayleigh distributed above v_th, P(V > v | slam) = exp(-(v^2 - v_th^2) /
//!   (2 m2)), with m2 the relative-velocity variance (Ochi 1964). With N = slams per hour x exposure
//!   hours (the sea file's `duration_h`, 1 h if not given):
//!   - the most probable largest in N slams (default): V_N = sqrt(v_th^2 + 2 m2 ln N), N >= 1;
//!   - at risk level alpha (`--risk-level`): the velocity the largest of the N slams exceeds with
//!     probability alpha, 1 - (1 - exp(-(V^2 - v_th^2)/(2 m2)))^N = alpha, so
//!     V_alpha = sqrt(v_th^2 - 2 m2 ln(1 - (1 - alpha)^(1/N))).
//! * **Profile shape.** The relative motion of a regular head wave at the spectral peak frequency w_p,
//!   with the amplitude zeta_a for which the keel-entry velocity equals V (found by bisection; the entry
//!   velocity grows with zeta_a): the regular-wave entry profile v(t) of that wave, from keel entry until
//!   the velocity reverses ([`crate::seakeeping::relative_motion::keel_entry`]).

use nalgebra::Complex;
use serde::Serialize;

use crate::seakeeping::relative_motion::{KeelEntry, RelativeMotion, keel_entry};
use crate::seakeeping::slamming::SlamStatistics;

/// How the design entry velocity is chosen.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Basis {
    /// The most probable largest entry velocity in the N slams of the exposure.
    MostProbableLargest,
    /// The entry velocity the largest of the N slams exceeds with this probability.
    RiskLevel(f64),
}

/// The definition of a design event, as written wherever its result appears.
#[derive(Debug, Clone, Serialize)]
pub struct DesignEvent {
    pub sea: String,
    /// The definition in words, with N (and alpha).
    pub definition: String,
    pub exposure_h: f64,
    pub slams_per_hour: f64,
    /// N: the expected number of slams in the exposure.
    pub expected_slams: f64,
    pub risk_level: Option<f64>,
    pub threshold_velocity_m_per_s: f64,
    /// The entry velocity, the keel-slope term included when it is on.
    pub design_entry_velocity_m_per_s: f64,
    /// The keel-slope term U dz_k/dx in the entry velocity (m/s; 0 when it is off).
    pub keel_slope_velocity_m_per_s: f64,
    /// The profile: a regular head wave at the spectral peak period, with this amplitude.
    pub peak_period_s: f64,
    pub equivalent_wave_amplitude_m: f64,
}

/// The design entry velocity of a station (None with fewer than one slam expected).
pub fn design_velocity(st: &SlamStatistics, exposure_h: f64, basis: Basis) -> Option<(f64, f64)> {
    let n = st.slams_per_hour * exposure_h;
    if n.is_nan() || n < 1.0 || st.m2 <= 0.0 {
        return None;
    }
    let v = match basis {
        Basis::MostProbableLargest => st.most_probable_extreme_velocity(n),
        Basis::RiskLevel(a) => st.velocity_exceeded_with(1.0 - (1.0 - a).powf(1.0 / n)),
    };
    Some((v, n))
}

/// The words of a definition.
pub fn definition(basis: Basis, n: f64, exposure_h: f64, peak_period_s: f64) -> String {
    let what = match basis {
        Basis::MostProbableLargest => format!(
            "the most probable largest keel-entry velocity in N = {n:.1} slams (Ochi's slams per hour x \
             {exposure_h} h exposure)"
        ),
        Basis::RiskLevel(a) => format!(
            "the keel-entry velocity exceeded with probability alpha = {a} by the largest of N = {n:.1} slams \
             (Ochi's slams per hour x {exposure_h} h exposure)"
        ),
    };
    format!(
        "design event: entry velocity = {what}; profile shape = the regular head wave at the spectral peak \
         period {peak_period_s:.3} s scaled to that entry velocity"
    )
}

/// A warning when the regular wave at the spectral peak period that gives the design entry velocity
/// (amplitude `zeta`) is larger than the most probable largest wave amplitude of the exposure,
/// (Hs / 4) sqrt(2 ln N_w) with N_w = exposure / T_p waves (Rayleigh amplitudes of standard deviation
/// Hs / 4; Longuet-Higgins 1952): the relative motion at T_p is then small for this hull and the slams
/// come from other periods of the spectrum, so the profile shape (its deceleration after keel entry) is a
/// stand-in, slower than the sea's slams. The entry velocity itself comes from the slam statistics and
/// is not affected.
pub fn amplitude_warning(zeta: f64, hs: f64, exposure_h: f64, tp: f64) -> Option<String> {
    let (largest, waves) = largest_amplitude(hs, exposure_h, tp);
    exceeds_largest(zeta, hs, exposure_h, tp).then(|| {
        format!(
            "its profile's regular wave at the spectral peak period {tp:.2} s needs an amplitude of {zeta:.2} m \
             to give the design entry velocity, {:.1} times the most probable largest wave amplitude of the \
             exposure ({largest:.2} m: Hs {hs:.2} m, {waves:.0} waves of T_p): the relative motion at T_p is \
             small for this hull, so the profile's deceleration after keel entry is a stand-in (slower than \
             the sea's slams); the entry velocity comes from the slam statistics and is not affected",
            zeta / largest
        )
    })
}

/// The most probable largest wave amplitude of an exposure of `exposure_h` hours to a sea of significant
/// height `hs` and peak period `tp`, (Hs / 4) sqrt(2 ln N_w), and the number of waves N_w = exposure / T_p
/// (Rayleigh amplitudes; Longuet-Higgins 1952).
fn largest_amplitude(hs: f64, exposure_h: f64, tp: f64) -> (f64, f64) {
    let waves = (exposure_h * 3600.0 / tp).max(1.0);
    (0.25 * hs * (2.0 * waves.ln()).sqrt(), waves)
}

/// Whether a profile wave of amplitude `zeta` is larger than the most probable largest wave amplitude of
/// the exposure ([`amplitude_warning`] states it).
fn exceeds_largest(zeta: f64, hs: f64, exposure_h: f64, tp: f64) -> bool {
    let (largest, _) = largest_amplitude(hs, exposure_h, tp);
    zeta.is_finite() && largest > 0.0 && zeta > largest
}

/// The design events of one irregular sea whose profile wave is larger than the sea's largest
/// ([`amplitude_warning`]): the sea's name, Hs, exposure, T_p and each event's (station, speed, amplitude).
#[derive(Debug, Default, Clone)]
pub(crate) struct Oversized {
    sea: String,
    hs: f64,
    exposure_h: f64,
    tp: f64,
    events: Vec<(f64, f64, f64)>,
}

impl Oversized {
    /// One warning line for all of the sea's events: the single event's own wording, or the ranges and
    /// the list of (station, speed, amplitude) where there are several (they share the cause).
    fn warning(&self) -> Option<String> {
        let (hs, h, tp) = (self.hs, self.exposure_h, self.tp);
        match self.events.as_slice() {
            [] => None,
            [(st, u, zeta)] => amplitude_warning(*zeta, hs, h, tp).map(|w| {
                format!(
                    "design event at station {st} Lpp, {u:.3} m/s, sea {}: {w}",
                    self.sea
                )
            }),
            many => {
                let (largest, waves) = largest_amplitude(hs, h, tp);
                let (z0, z1) = many
                    .iter()
                    .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), e| {
                        (a.min(e.2), b.max(e.2))
                    });
                let list: Vec<String> = many
                    .iter()
                    .map(|(st, u, z)| format!("{st} Lpp at {u:.3} m/s: {z:.2} m"))
                    .collect();
                Some(format!(
                    "design events of sea {}, {} of them: their profiles' regular wave at the spectral peak \
                     period {tp:.2} s needs amplitudes of {z0:.2} to {z1:.2} m to give the design entry \
                     velocities, {:.1} to {:.1} times the most probable largest wave amplitude of the exposure \
                     ({largest:.2} m: Hs {hs:.2} m, {waves:.0} waves of T_p): the relative motion at T_p is \
                     small for this hull, so the profiles' deceleration after keel entry is a stand-in (slower \
                     than the sea's slams); the entry velocities come from the slam statistics and are not \
                     affected ({})",
                    self.sea,
                    many.len(),
                    z0 / largest,
                    z1 / largest,
                    list.join("; ")
                ))
            }
        }
    }
}

/// The keel-entry profile of the regular wave (relative motion `rm` per unit amplitude, encounter frequency
/// `omega_e`) whose amplitude gives the entry velocity `v` at a station of draft `draft`; the amplitude
/// and the profile (`n` samples, ending at `max_depth` at most). None when no amplitude up to 100 times
/// the emergence amplitude reaches `v`.
pub fn scaled_entry(
    rm: &RelativeMotion,
    omega_e: f64,
    draft: f64,
    max_depth: f64,
    v: f64,
    n: usize,
) -> Option<(f64, KeelEntry)> {
    let s = rm.motion.norm();
    if s <= 0.0 || !v.is_finite() || v <= 0.0 {
        return None;
    }
    // Entry velocity at amplitude z: at the instant s(t) = draft on the way down.
    let entry_v = |z: f64| {
        let a = s * z;
        if a <= draft.abs() {
            return f64::NEG_INFINITY;
        }
        let t = ((draft / a).acos() - rm.motion.arg()) / omega_e;
        -(rm.velocity * Complex::new(0.0, omega_e * t).exp()).re * z
    };
    // the smallest amplitude that reaches the keel: |draft| / |s| (a dry station has draft < 0)
    let lo0 = draft.abs() / s * (1.0 + 1e-12);
    let (mut lo, mut hi) = (lo0, 2.0 * lo0.max(1e-6));
    while entry_v(hi) < v {
        hi *= 2.0;
        if hi > 100.0 * lo0.max(1e-6) {
            return None;
        }
    }
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if entry_v(mid) < v {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    keel_entry(rm, omega_e, hi, draft, max_depth, n).map(|k| (hi, k))
}

/// The design events of every irregular sea, speed and station of a plan (appended after the regular
/// waves' events, in the order speed, sea, station), and warning lines: one per station without a design
/// event (why), and one per sea whose profile waves are larger than its largest
/// ([`amplitude_warning`]).
pub(crate) fn plan_events(
    p: &PlanInputs,
    basis: Basis,
) -> crate::error::Result<(Vec<super::plan::Event>, Vec<String>)> {
    use crate::seakeeping::strip_theory::{StripSettings, respond};
    let mut events = Vec::new();
    let mut notes = Vec::new();
    let mut oversized: Vec<Oversized> = Vec::new();
    for sp in &p.motions.speeds {
        for (ir, sea) in sp.irregular.iter().zip(&p.sea.irregular) {
            let r = respond(
                p.model,
                sea.spectrum.peak_frequency(),
                sp.speed_m_s,
                &StripSettings::default(),
            )?;
            let at = SeaSpeed {
                speed_m_s: sp.speed_m_s,
                sea,
                exposure_h: ir.duration_h,
                stats: &ir.stations,
                response: &r,
            };
            let sensors_at = |f: f64| p.sensors_at(f);
            events.extend(sea_events(
                p.hull,
                p.stations,
                &sensors_at,
                &at,
                basis,
                &mut notes,
                &mut oversized,
            )?);
        }
    }
    notes.extend(oversized_warnings(&oversized));
    Ok((events, notes))
}

/// One speed in one irregular sea, as [`sea_events`] needs it: the sea, its exposure (h), the stations'
/// slam statistics at that speed, and the strip-theory response at the sea's spectral peak frequency.
pub(crate) struct SeaSpeed<'a> {
    pub speed_m_s: f64,
    pub sea: &'a crate::sea::IrregularSea,
    pub exposure_h: f64,
    pub stats: &'a [SlamStatistics],
    pub response: &'a crate::seakeeping::strip_theory::Response,
}

/// The design events of the stations (`stations`, their sensors from `sensors_at`) at one speed in one
/// irregular sea, in station order: `assess` ([`plan_events`]) and the analytic cases of a sweep make
/// them the same way. A station without a design event gets a line in `notes` (why); one whose profile
/// wave is larger than the sea's largest is added to the sea's entry of `oversized`, whose warnings the
/// caller states once it has all its speeds ([`oversized_warnings`]).
pub(crate) fn sea_events(
    hull: &crate::hull::Hull,
    stations: &[crate::seakeeping::analysis::Station],
    sensors_at: &dyn Fn(f64) -> Vec<crate::sph::SensorSpec>,
    at: &SeaSpeed,
    basis: Basis,
    notes: &mut Vec<String>,
    oversized: &mut Vec<Oversized>,
) -> crate::error::Result<Vec<super::plan::Event>> {
    use super::plan::{EntryCase, Event};
    use crate::report::sanity::SlamFlag;
    use crate::seakeeping::relative_motion::at_station;
    let (sea, r) = (at.sea, at.response);
    let omega_p = sea.spectrum.peak_frequency();
    let tp = 2.0 * std::f64::consts::PI / omega_p;
    let k_sea = match oversized.iter().position(|o| o.sea == sea.name) {
        Some(k) => k,
        None => {
            oversized.push(Oversized {
                sea: sea.name.clone(),
                hs: sea.spectrum.hs(),
                exposure_h: at.exposure_h,
                tp,
                events: Vec::new(),
            });
            oversized.len() - 1
        }
    };
    let mut events = Vec::new();
    for (st, stats) in stations.iter().zip(at.stats) {
        let label = format!("{}/design", sea.name);
        let Some((v, n)) = design_velocity(stats, at.exposure_h, basis) else {
            notes.push(format!(
                "no design event at station {} Lpp, {:.3} m/s, sea {}: {:.2} slams expected in {} h \
                 (fewer than one)",
                st.aft_of_fp,
                at.speed_m_s,
                sea.name,
                stats.slams_per_hour * at.exposure_h,
                at.exposure_h
            ));
            continue;
        };
        let rm = at_station(r, st.x, 1.0)?;
        // The regular wave gives the oscillating part; the keel-slope term (0 when off) is added to the
        // profile after it.
        let v_s = stats.steady_velocity;
        let scaled = scaled_entry(&rm, r.omega_e, st.draft, st.height, v - v_s, 41);
        let Some((zeta, k)) = scaled.map(|(z, mut k)| {
            k.add_steady_velocity(v_s);
            (z, k)
        }) else {
            notes.push(format!(
                "no design event at station {} Lpp, {:.3} m/s, sea {}: no regular wave at the spectral \
                 peak period gives the design entry velocity {v:.3} m/s",
                st.aft_of_fp, at.speed_m_s, sea.name
            ));
            continue;
        };
        if exceeds_largest(zeta, sea.spectrum.hs(), at.exposure_h, tp) {
            oversized[k_sea]
                .events
                .push((st.aft_of_fp, at.speed_m_s, zeta));
        }
        let design = DesignEvent {
            sea: sea.name.clone(),
            definition: definition(basis, n, at.exposure_h, tp),
            exposure_h: at.exposure_h,
            slams_per_hour: stats.slams_per_hour,
            expected_slams: n,
            risk_level: match basis {
                Basis::RiskLevel(a) => Some(a),
                Basis::MostProbableLargest => None,
            },
            threshold_velocity_m_per_s: stats.threshold_velocity,
            design_entry_velocity_m_per_s: v,
            keel_slope_velocity_m_per_s: v_s,
            peak_period_s: tp,
            equivalent_wave_amplitude_m: zeta,
        };
        events.push(Event {
            station: st.aft_of_fp,
            x: st.x,
            speed_m_s: at.speed_m_s,
            wave: label,
            flag: SlamFlag::Slam,
            entry_velocity_m_s: Some(k.entry_velocity),
            entry_time_s: None,
            encounter_period_s: 2.0 * std::f64::consts::PI / r.omega_e,
            wave_omega_rad_s: omega_p,
            wave_amplitude_m: zeta,
            draft_m: st.draft,
            entry: Some(EntryCase {
                half_points: hull.section_at(st.x)?.points.clone(),
                motion: crate::impact::entry_motion(&k),
                sensors: sensors_at(st.aft_of_fp),
                immersion_m: 0.0,
            }),
            design: Some(design),
            flare: None,
        });
    }
    Ok(events)
}

/// Add the oversized profile waves of `from` to those of the same seas in `into` (a sea not in `into`
/// yet is appended): the parts [`sea_events`] collected for several speeds, joined.
pub(crate) fn merge_oversized(into: &mut Vec<Oversized>, from: &[Oversized]) {
    for o in from {
        match into.iter_mut().find(|x| x.sea == o.sea) {
            Some(x) => x.events.extend_from_slice(&o.events),
            None => into.push(o.clone()),
        }
    }
}

/// The warnings of the oversized profile waves [`sea_events`] collected, one a sea.
pub(crate) fn oversized_warnings(oversized: &[Oversized]) -> Vec<String> {
    oversized.iter().filter_map(Oversized::warning).collect()
}

/// What [`plan_events`] needs of a plan in the making.
pub(crate) struct PlanInputs<'a> {
    pub hull: &'a crate::hull::Hull,
    pub sea: &'a crate::sea::SeaState,
    pub model: &'a crate::seakeeping::ShipModel,
    pub motions: &'a crate::seakeeping::analysis::Report,
    pub stations: &'a [crate::seakeeping::analysis::Station],
    pub sensors: &'a [super::plan::StationSensors],
}

impl PlanInputs<'_> {
    fn sensors_at(&self, f: f64) -> Vec<crate::sph::SensorSpec> {
        self.sensors
            .iter()
            .find(|q| (q.station - f).abs() < 1e-9)
            .map(|q| q.sensors.clone())
            .unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn stats(m2: f64, rate: f64) -> SlamStatistics {
        SlamStatistics {
            x: 0.0,
            speed: 1.0,
            draft: 0.1,
            m0: 0.01,
            m2,
            threshold_velocity: 0.5,
            probability: 0.1,
            slams_per_hour: rate,
            steady_velocity: 0.0,
        }
    }

    #[test]
    fn most_probable_largest_and_risk_level_by_hand() {
        let st = stats(0.04, 10.0);
        // N = 10 slams in 1 h: V = sqrt(0.25 + 2 * 0.04 * ln 10)
        let (v, n) = design_velocity(&st, 1.0, Basis::MostProbableLargest).unwrap();
        assert!((n - 10.0).abs() < 1e-12);
        assert!((v - (0.25f64 + 0.08 * 10f64.ln()).sqrt()).abs() < 1e-12);
        // alpha = 1 - (1 - 1/e)^N gives exp(-(V^2 - v_th^2)/(2 m2)) = 1/e, V^2 = v_th^2 + 2 m2
        let a = 1.0 - (1.0 - (-1.0f64).exp()).powf(10.0);
        let (v, _) = design_velocity(&st, 1.0, Basis::RiskLevel(a)).unwrap();
        assert!((v - (0.25f64 + 0.08).sqrt()).abs() < 1e-9, "{v}");
        assert!(design_velocity(&stats(0.04, 0.5), 1.0, Basis::MostProbableLargest).is_none());
    }

    #[test]
    fn scaled_profile_enters_at_the_design_velocity() {
        // pure heave s = z cos(t), v = -z sin(t): entry V = sqrt(A^2 - T^2) for w = 1
        let rm = RelativeMotion {
            x: 0.0,
            motion: Complex::new(1.0, 0.0),
            velocity: Complex::new(0.0, 1.0),
        };
        let (z, k) = scaled_entry(&rm, 1.0, 0.3, 10.0, 0.4, 11).unwrap();
        assert!((z - 0.5).abs() < 1e-9, "{z}");
        assert!((k.entry_velocity - 0.4).abs() < 1e-9);
    }

    /// A profile wave larger than the sea's most probable largest wave is flagged; one within it is not.
    #[test]
    fn a_profile_wave_larger_than_the_sea_is_flagged() {
        // Hs 5.5 m, 3 h at Tp 11 s: 982 waves, largest amplitude 1.375 x sqrt(2 ln 982) = 5.10 m.
        let w = amplitude_warning(52.0, 5.5, 3.0, 11.0).unwrap();
        assert!(
            w.contains("52.00 m") && w.contains("10.2 times") && w.contains("5.10 m"),
            "{w}"
        );
        assert!(amplitude_warning(4.0, 5.5, 3.0, 11.0).is_none());
        assert!(amplitude_warning(f64::NAN, 5.5, 3.0, 11.0).is_none());
    }

    /// The oversized profile waves of one sea are stated in one line with their ranges and every event;
    /// a single one keeps the event's own wording.
    #[test]
    fn oversized_profile_waves_of_a_sea_are_stated_once() {
        let mut o = Oversized {
            sea: "SS6".into(),
            hs: 5.5,
            exposure_h: 3.0,
            tp: 11.0,
            events: vec![(0.05, 4.116, 34.04)],
        };
        let one = o.warning().unwrap();
        assert!(
            one.starts_with("design event at station 0.05 Lpp, 4.116 m/s, sea SS6: its profile's"),
            "{one}"
        );
        o.events.push((0.2, 10.289, 29.14));
        let two = o.warning().unwrap();
        assert!(
            two.starts_with("design events of sea SS6, 2 of them"),
            "{two}"
        );
        assert!(two.contains("29.14 to 34.04 m"), "{two}");
        // 29.14 / 5.10 and 34.04 / 5.10
        assert!(two.contains("5.7 to 6.7 times"), "{two}");
        assert!(two.contains("0.2 Lpp at 10.289 m/s: 29.14 m"), "{two}");
        o.events.clear();
        assert!(o.warning().is_none());
    }
}
