//! Wagner theory for an arbitrary symmetric section entering with a varying speed V(t) (the flat-plate
//! approximation of Wagner 1932, with the wetting condition solved for the actual shape; see Faltinsen
//! 2005, "Hydrodynamics of High-Speed Marine Vehicles", ch. 8).
//!
//! With the body surface z = f(y) above the keel ([`Profile`]) and the penetration depth d(t):
//!
//! * Wagner condition: integral_0^{pi/2} f(c sin theta) d theta = (pi/2) d
//!   gives the wetted half-width c(d) ([`crate::analytic::entry_kinematics`]);
//! * force per unit length F = d/dt (rho pi c^2 V / 2) = rho pi (c c' V + c^2 V'/2), c' = dc/dt = V dc/dd;
//! * peak (jet-root) pressure p_max = rho c'^2 / 2 (for a wedge at constant V this is (pi^2/4) cot^2(beta)
//!   rho V^2/2).
//!
//! It holds for moderate deadrise and before flow separation at a knuckle or at the widest point of a
//! bulb; the estimate stops there (`stopped` says why).
//!
//! **Initial immersion** ([`estimate_immersed`]; the flare event of a station whose keel stays in the
//! water). The section starts immersed to the keel depth d0 in water at rest: c starts at the waterline
//! half-breadth b0 and follows the Wagner condition applied to the body above the initial waterline
//! ([`crate::analytic::entry_kinematics`], module notes); the force is the same d/dt (rho pi c^2 V / 2)
//! of the flat plate of half-width c (the added mass of the wetted width; buoyancy and the hydrostatic
//! pressure of the immersed part are not included, as in the keel-entry estimate). The first sample (c =
//! b0, dc/dt unbounded) is the impulsive start of the idealisation, flagged like the acoustic stage and
//! left out of the peaks. For large penetration compared with d0 the estimate tends to the keel-entry one
//! (checked for a wedge in the tests); d0 = 0 is the keel-entry estimate exactly.
//!
//! **Flat keel, acoustic stage.** A flat keel of half-width c_f is wetted at once on contact: Wagner's
//! c jumps to c_f, c' and hence force and pressure are unbounded (flat-plate impact). While c' would be
//! at least the sound speed of water c_w (always at first contact of a flat keel, and just after it),
//! or wherever Wagner's values exceed them, the estimate reports the acoustic (water-hammer) values
//! p = rho c_w V and F = 2 c rho c_w V instead, and flags the sample in `acoustic_limited`. These are the
//! compressible limit of a flat impact of a rigid body on pure water (Korobkin & Pukhnachov 1988), not a
//! Wagner result and not a strict bound on a local peak; air cushioning lowers real values much further
//! (see the single-phase warning of the SPH reports).
//!
//! **Peaks after a singular start.** On a flat keel and after an immersed start, c' falls from
//! infinity, and with it force and pressure: the largest of the first Wagner samples is set by where
//! the sampling happens to begin, not by the flow (in the Ochi assessment, 2.2-2.7 kN/m at 1.3 ms at the
//! flat stations, against 5.7 kN/m for another sampling of the same event). The peaks
//! ([`WagnerEstimate::force_peak`], [`WagnerEstimate::pressure_peak`]) are therefore taken from the
//! first sample where the value rises again (the load of the contour beyond the flat, or of a flare);
//! where it never rises the estimate has no peak, and says so in `notes` (the rule of
//! [`crate::analytic::peak`], shared with the assessment's sensor pressures).

use crate::analytic::entry_kinematics::{EntryHistory, WATER_SOUND_SPEED};
use crate::analytic::peak::peak_candidates;
use crate::analytic::section_profile::Profile;
use crate::error::Result;
use std::f64::consts::PI;

/// Wagner estimate along a time history.
#[derive(Debug, Clone, Default)]
pub struct WagnerEstimate {
    /// Kept sample times (duplicates and steps back in the input skipped).
    pub t: Vec<f64>,
    pub penetration: Vec<f64>,
    pub half_width: Vec<f64>,
    pub force: Vec<f64>,
    pub peak_pressure: Vec<f64>,
    /// Whether force or peak pressure at the sample is the acoustic value rho c_w V (not Wagner's).
    pub acoustic_limited: Vec<bool>,
    /// Half-width of the flat part of the keel (0 with deadrise at the keel).
    pub flat_keel_half_width: f64,
    /// Whether the wetted width starts at a finite value with dc/dt unbounded (a flat keel, or a
    /// section starting immersed): force and pressure then fall from infinity over the first samples,
    /// and the peaks are taken after that decay.
    pub singular_start: bool,
    /// Why the estimate ends before the last sample, if it does.
    pub stopped: Option<String>,
    /// Notes for reports (flat keel, acoustic values).
    pub notes: Vec<String>,
}

impl WagnerEstimate {
    /// Indices of the samples that carry Wagner's own values (not the acoustic limit).
    fn wagner_samples(&self) -> impl Iterator<Item = usize> + '_ {
        (0..self.t.len()).filter(|&k| !self.acoustic_limited.get(k).copied().unwrap_or(false))
    }

    /// The samples that may carry a peak of `x`: Wagner's own values (not the acoustic limit) and, after a
    /// singular start ([`WagnerEstimate::singular_start`]), only those from the end of its decay on, by
    /// the rule of [`crate::analytic::peak`]. Empty when `x` only decays (no later rise: no Wagner peak).
    fn peak_samples(&self, x: &[f64]) -> Vec<usize> {
        let kept: Vec<usize> = self.wagner_samples().collect();
        peak_candidates(x, &kept, self.singular_start)
            .map(<[usize]>::to_vec)
            .unwrap_or_default()
    }

    /// Wagner's peak force (N/m) and its time, leaving out the samples at the acoustic limit (a flat
    /// keel at contact: the water-hammer bound, reported in `notes`) and the decay of a singular start
    /// ([`WagnerEstimate::singular_start`]); the last of equal peaks. `None` when no sample is left (the
    /// force of a flat keel or an immersed start that only decays has no Wagner peak).
    pub fn force_peak(&self) -> Option<(f64, f64)> {
        self.peak_samples(&self.force)
            .into_iter()
            .max_by(|&a, &b| self.force[a].total_cmp(&self.force[b]))
            .map(|k| (self.force[k], self.t[k]))
    }

    /// Wagner's largest jet-root pressure (Pa), on the samples of [`WagnerEstimate::force_peak`]'s rule.
    pub fn pressure_peak(&self) -> Option<f64> {
        self.peak_samples(&self.peak_pressure)
            .into_iter()
            .map(|k| self.peak_pressure[k])
            .reduce(f64::max)
    }
}

/// Penetration depth at which the wetted half-width is c (the Wagner condition), or `None` past the chine
/// or widest point, or for a section the model cannot take (see [`Profile::from_half_points`]).
pub fn penetration_for_half_width(half: &[[f64; 2]], c: f64) -> Option<f64> {
    Profile::from_half_points(half).ok()?.wagner_depth(c)
}

/// Wagner estimate for a section (starboard half `half`, keel first at y = 0) moving down with speed
/// v(t) (sampled at times `t`, with the same `v`), density rho. Stops where the wetted half-width
/// reaches the chine or widest point of the section, or where v turns negative. Errors for a section
/// the model cannot take (contour below its keel, no breadth), mismatched lengths or non-finite speeds.
pub fn estimate(half: &[[f64; 2]], t: &[f64], v: &[f64], rho: f64) -> Result<WagnerEstimate> {
    estimate_immersed(half, 0.0, t, v, rho)
}

/// [`estimate`] for a section that starts immersed to the keel depth `d0` in water at rest (module
/// notes); `d0 = 0` is [`estimate`].
pub fn estimate_immersed(
    half: &[[f64; 2]],
    d0: f64,
    t: &[f64],
    v: &[f64],
    rho: f64,
) -> Result<WagnerEstimate> {
    Ok(estimate_from_history(
        &EntryHistory::new_immersed(half, d0, t, v)?,
        d0,
        rho,
    ))
}

/// [`estimate_immersed`] along an entry history already computed ([`EntryHistory::new_immersed`] with
/// the same keel depth `d0`), so that an estimate that also needs the MLM of the same history computes
/// it once.
pub fn estimate_from_history(hist: &EntryHistory, d0: f64, rho: f64) -> WagnerEstimate {
    let mut out = WagnerEstimate {
        flat_keel_half_width: hist.profile.flat_keel_half_width(),
        singular_start: d0 > 0.0 || hist.profile.flat_keel_half_width() > 0.0,
        stopped: hist.stopped.clone(),
        ..Default::default()
    };
    for s in &hist.states {
        let p_ac = rho * WATER_SOUND_SPEED * s.v;
        let f_ac = 2.0 * s.c * p_ac;
        let (force, p, limited) = match s.c_dot {
            Some(cd) => {
                let f = rho * PI * (s.c * cd * s.v + 0.5 * s.c * s.c * s.v_dot);
                let p = 0.5 * rho * cd * cd;
                (f.min(f_ac), p.min(p_ac), f > f_ac || p > p_ac)
            }
            None => (f_ac, p_ac, true),
        };
        out.t.push(s.t);
        out.penetration.push(s.h);
        out.half_width.push(s.c);
        out.force.push(force);
        out.peak_pressure.push(p);
        out.acoustic_limited.push(limited);
    }
    if d0 > 0.0 {
        out.notes.push(format!(
            "the section starts immersed to {d0:.4} m in water at rest, wetted to the waterline half-breadth \
             {:.4} m; the first sample (impulsive start of the linearised flow, unbounded dc/dt) is flagged \
             and left out of the peaks",
            hist.wetting.flat_keel_half_width()
        ));
    } else if out.flat_keel_half_width > 0.0 {
        out.notes.push(format!(
            "flat keel of half-width {:.4} m: Wagner's wetted width jumps to it at contact and its force and \
             pressure are unbounded there (flat-plate impact); the acoustic values rho c_w V (c_w = {} m/s) \
             are reported instead where flagged; air cushioning lowers real values",
            out.flat_keel_half_width, WATER_SOUND_SPEED
        ));
    }
    if out.singular_start {
        let peak = match out.force_peak() {
            Some((f, t)) => format!(
                "the force peak is the largest after that decay ({f:.1} N/m at {:.2} ms)",
                1e3 * t
            ),
            None => "the force only decays, so Wagner gives no force peak for this event".into(),
        };
        out.notes.push(format!(
            "Wagner's force and pressure fall from infinity after the {} start, and their first values \
             depend on the sampling: the peaks leave out that decay; {peak}",
            if d0 > 0.0 { "immersed" } else { "flat-keel" }
        ));
    }
    let n_ac = out.acoustic_limited.iter().filter(|&&a| a).count();
    if n_ac > 0 && d0 == 0.0 {
        out.notes.push(format!(
            "{n_ac} of {} samples carry the acoustic limit rho c_w V instead of Wagner's force or peak \
             pressure (incompressible theory out of range there)",
            out.t.len()
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::analytic::wagner;

    #[test]
    fn a_flat_keel_start_is_no_force_peak() {
        // flat keel of half-width 0.1 m, then a 30 deg side: the force decays from the flat-plate start
        let beta = 30f64.to_radians();
        let s = [[0.0, 0.0], [0.1, 0.0], [0.4, 0.3 * beta.tan()], [0.4, 0.5]];
        let v = |n: usize| vec![2.0; n];
        let peak_for = |n: usize| {
            let t: Vec<f64> = (0..=n).map(|k| k as f64 * 0.02 / n as f64).collect();
            let e = estimate(&s, &t, &v(t.len()), 1000.0).unwrap();
            assert!(e.singular_start);
            e.force_peak()
        };
        // two samplings of the same entry give the same peak, after the decay (the largest of the
        // first samples would differ by the sampling)
        // (the first kept samples read 10.4 and 12.6 kN/m with these two samplings; the force has its
        // minimum at about 4 ms and rises again as the 30 deg side is wetted)
        let (f1, t1) = peak_for(200).unwrap();
        let (f2, t2) = peak_for(400).unwrap();
        assert!((f1 / f2 - 1.0).abs() < 1e-3, "{f1} vs {f2}");
        assert!(t1 > 4e-3 && t2 > 4e-3, "{t1} {t2}");
        // a pure flat plate only decays: no Wagner peak
        let plate = [[0.0, 0.0], [0.3, 0.0], [0.3, 0.2]];
        let t: Vec<f64> = (0..=100).map(|k| k as f64 * 1e-4).collect();
        let e = estimate(&plate, &t, &v(t.len()), 1000.0).unwrap();
        assert!(e.force_peak().is_none());
        assert!(e.notes.iter().any(|n| n.contains("no force peak")));
    }

    #[test]
    fn reproduces_the_wedge_formulas() {
        let beta = 30f64.to_radians();
        let zk = 0.25 * beta.tan();
        let s = [[0.0, 0.0], [0.25, zk], [0.25, 0.29]];
        let t: Vec<f64> = (0..=100).map(|k| k as f64 * 1e-4).collect();
        let v = vec![5.0; t.len()];
        let e = estimate(&s, &t, &v, 1000.0).unwrap();
        assert!(e.t.len() > 50);
        let k = 50;
        let f = wagner::force(beta, 1000.0, 5.0, e.t[k]).unwrap();
        assert!((e.force[k] / f - 1.0).abs() < 0.01, "{} vs {f}", e.force[k]);
        let cp = 2.0 * e.peak_pressure[k] / (1000.0 * 25.0);
        assert!(
            (cp / wagner::peak_pressure_coefficient(beta).unwrap() - 1.0).abs() < 0.01,
            "{cp}"
        );
        let c = wagner::wetted_half_width(beta, 5.0, e.t[k]).unwrap();
        assert!((e.half_width[k] / c - 1.0).abs() < 0.01);
    }

    fn all_finite(e: &WagnerEstimate) -> bool {
        [&e.penetration, &e.half_width, &e.force, &e.peak_pressure]
            .iter()
            .all(|x| x.iter().all(|v| v.is_finite()))
    }

    fn times(n: usize, dt: f64) -> Vec<f64> {
        (0..n).map(|k| k as f64 * dt).collect()
    }

    #[test]
    fn flat_bottom_with_deadrise_starts_acoustic_then_follows_wagner() {
        let s = [[0.0, 0.0], [0.1, 0.0], [0.25, 0.15], [0.25, 0.3]];
        let t = times(400, 1e-4);
        let e = estimate(&s, &t, &vec![5.0; t.len()], 1000.0).unwrap();
        assert!(all_finite(&e));
        assert_eq!(e.flat_keel_half_width, 0.1);
        assert!(e.acoustic_limited[0]);
        assert_eq!(e.peak_pressure[0], 1000.0 * WATER_SOUND_SPEED * 5.0);
        assert_eq!(e.half_width[0], 0.1);
        // Later on the 45 deg flank Wagner's values return.
        assert!(!e.acoustic_limited.last().unwrap());
        assert!(e.half_width.windows(2).all(|w| w[1] >= w[0]));
        assert!(e.stopped.is_some(), "the chine is reached");
        assert!(!e.notes.is_empty());
    }

    #[test]
    fn flat_rectangle_gives_only_the_acoustic_contact_value() {
        let s = [[0.0, 0.0], [0.2, 0.0], [0.2, 0.2]];
        let t = times(50, 1e-4);
        let e = estimate(&s, &t, &vec![3.0; t.len()], 1000.0).unwrap();
        assert_eq!(e.t.len(), 1);
        assert!(all_finite(&e));
        assert!(e.acoustic_limited[0]);
        assert_eq!(e.force[0], 2.0 * 0.2 * 1000.0 * WATER_SOUND_SPEED * 3.0);
    }

    #[test]
    fn vertical_segments_at_the_keel_and_in_the_middle() {
        // A keel bar (vertical at the keel), then 20 deg, a vertical step, 30 deg to the chine.
        let s = [
            [0.0, 0.0],
            [0.0, 0.02],
            [0.1, 0.02 + 0.1 * 20f64.to_radians().tan()],
            [0.1, 0.08],
            [0.25, 0.08 + 0.15 * 30f64.to_radians().tan()],
        ];
        let t = times(300, 1e-4);
        let e = estimate(&s, &t, &vec![4.0; t.len()], 1000.0).unwrap();
        assert!(all_finite(&e));
        assert!(e.t.len() > 50);
        // Before the bar's depth is reached there is no wetted width and no load.
        assert_eq!(e.half_width[1], 0.0);
        assert_eq!(e.force[1], 0.0);
        assert_eq!(e.peak_pressure[1], 0.0);
        assert!(e.half_width.iter().any(|&c| c > 0.12));
    }

    #[test]
    fn bulb_stops_at_its_widest_point() {
        let s = [
            [0.0, 0.0],
            [0.08, 0.02],
            [0.12, 0.08],
            [0.1, 0.15],
            [0.06, 0.2],
            [0.3, 0.45],
        ];
        let t = times(400, 1e-4);
        let e = estimate(&s, &t, &vec![5.0; t.len()], 1000.0).unwrap();
        assert!(all_finite(&e));
        assert!(e.half_width.iter().all(|&c| c <= 0.12));
        assert!(e.stopped.as_deref().unwrap().contains("separation"));
    }

    #[test]
    fn immersed_wedge_tends_to_the_keel_entry_wedge() {
        // 30 deg wedge at 2 m/s, started with the keel 5 mm under the surface at rest: once the
        // penetration since the start is large against d0 the force and the wetted width approach the
        // keel-entry values at the same keel depth (Wagner similarity), and d0 = 0 is the keel entry.
        let beta = 30f64.to_radians();
        let s = [[0.0, 0.0], [3.0, 3.0 * beta.tan()]];
        let t = times(2001, 1e-4);
        let v = vec![2.0; t.len()];
        let d0 = 0.005;
        let dry = estimate(&s, &t, &v, 1000.0).unwrap();
        let wet = estimate_immersed(&s, d0, &t, &v, 1000.0).unwrap();
        let same = estimate_immersed(&s, 0.0, &t, &v, 1000.0).unwrap();
        assert_eq!(same.force, dry.force);
        assert_eq!(same.half_width, dry.half_width);
        assert!(wet.acoustic_limited[0] && !wet.acoustic_limited[1]);
        assert!((wet.half_width[0] - d0 / beta.tan()).abs() < 1e-9);
        // at the end the keel is d0 + 0.4 m deep: compare with the keel entry at the same keel depth
        let k = wet.t.len() - 1;
        let h = wet.penetration[k];
        assert!((h - (d0 + 0.4)).abs() < 1e-9);
        let c = wagner::wetted_half_width(beta, 2.0, h / 2.0).unwrap();
        let f = wagner::force(beta, 1000.0, 2.0, h / 2.0).unwrap();
        assert!(
            (wet.half_width[k] / c - 1.0).abs() < 0.01,
            "{} vs {c}",
            wet.half_width[k]
        );
        assert!(
            (wet.force[k] / f - 1.0).abs() < 0.02,
            "{} vs {f}",
            wet.force[k]
        );
        // early on (penetration comparable with d0) they differ: the immersed start is not a keel entry
        let j = 25;
        let cj = wagner::wetted_half_width(beta, 2.0, wet.penetration[j] / 2.0).unwrap();
        assert!((wet.half_width[j] / cj - 1.0).abs() > 0.05);
    }

    #[test]
    fn repeated_times_and_deceleration() {
        let beta = 25f64.to_radians();
        let s = [[0.0, 0.0], [0.3, 0.3 * beta.tan()]];
        let mut t = times(200, 1e-4);
        t.insert(10, t[10]);
        t.insert(50, t[49]);
        let v: Vec<f64> = t.iter().map(|&tk| 5.0 - 200.0 * tk).collect();
        let e = estimate(&s, &t, &v, 1000.0).unwrap();
        assert!(all_finite(&e));
        assert_eq!(e.t.len(), 200);
        assert!(e.t.windows(2).all(|w| w[1] > w[0]));
        assert!(estimate(&s, &[0.0, 1.0], &[1.0], 1000.0).is_err());
        assert!(estimate(&[[0.0, 0.1], [0.2, 0.0]], &t, &v, 1000.0).is_err());
    }
}
