//! Wetted half-width c(t) and its rate dc/dt of a symmetric section entering calm water with a varying
//! speed V(t), from the Wagner condition on [`Profile`]: shared by the generalised Wagner estimate and the
//! modified Logvinovich model.
//!
//! * penetration h(t) = integral V dt (trapezoid over the samples, from h = 0 at the first sample);
//! * c(h) = inf { c : d(c) > h } with d the Wagner condition of [`Profile::wagner_depth`] (for a shape whose
//!   d(c) is not monotone, e.g. a hollow, c jumps where d has a local maximum; on a flat keel c starts at
//!   the keel half-width c_f);
//! * dc/dt = V / d'(c).
//!
//! **Acoustic stage.** Incompressible Wagner theory needs the contact points to move slower than sound in
//! water. Where V >= c_w d'(c) (dc/dt >= c_w, always at first contact of a flat keel, where d' = 0) the
//! state is marked as acoustic (`c_dot = None`): the flow is then governed by compressibility (the
//! water-hammer pressure rho c_w V of a flat impact, Korobkin & Pukhnachov 1988, Annu. Rev. Fluid Mech.
//! 20) and, in reality, by air cushioning. Callers report the acoustic value flagged, never an infinite one.
//!
//! **Initial immersion** ([`EntryHistory::new_immersed`], the flare event of a section whose keel stays
//! in the water). The section starts immersed to d0 (keel depth) in water at rest with a flat surface;
//! the body below the initial waterline is wetted from the start (half-width b0, the waterline
//! half-breadth at d0). Linearised as Wagner's problem is, that wetted part is a flat plate |y| < b0 on
//! the initial surface, and the Wagner condition (with the free-surface elevation counted from the
//! start) is applied to the body above the waterline, f~(y) = max(f(y) - d0, 0)
//! ([`Profile::above`]): with h the keel depth (h = d0 at the start),
//!
//!   h - d0 = (2/pi) integral_0^{pi/2} f~(c sin theta) d theta,   c >= b0.
//!
//! This follows from Wagner's condition in its integral form, integral_0^c (dh/dc~) c / sqrt(c^2 - c~^2)
//! dc~ = f~(c), with dh/dc~ = 0 for c~ < b0 (the plate is wetted at once, at rest); its Abel inversion
//! is the formula above (the derivation is the one of Faltinsen 2005, ch. 8, with the initial wetted
//! width; the idealisation, not a published formula, so stated here). For d0 = 0 it is the keel-entry
//! condition, exactly. At the start d/dc of the right side vanishes at c = b0, so dc/dt is unbounded: the
//! first sample is flagged like the acoustic stage (an artefact of the impulsive start of the linearised
//! flow, not an impact); the callers say so. The pressures of the MLM use the actual body f and h.
//!
//! **Input samples.** Times must increase; a sample whose time is not larger than the previous kept one
//! (a duplicate or a step back) is skipped. Non-finite speeds are refused. The history ends where the
//! wetted half-width reaches the end of f (chine, widest point) or where V turns negative (exit is not
//! an entry problem).

use crate::analytic::section_profile::{Profile, ProfileEnd};
use crate::error::{Error, Result};
use crate::numerics::{Pchip, bisect};

/// Speed of sound in water (m/s) used for the acoustic-stage test and the water-hammer pressure.
pub const WATER_SOUND_SPEED: f64 = 1500.0;

/// The entry state at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EntryState {
    pub t: f64,
    /// Penetration of the keel below the undisturbed surface, h (m).
    pub h: f64,
    /// Downward speed V = dh/dt (m/s).
    pub v: f64,
    /// dV/dt (m/s^2).
    pub v_dot: f64,
    /// Wetted half-width c (m).
    pub c: f64,
    /// dc/dt (m/s); `None` in the acoustic stage (dc/dt >= water sound speed or unbounded).
    pub c_dot: Option<f64>,
}

/// The entry states at the kept samples.
#[derive(Debug, Clone)]
pub struct EntryHistory {
    pub profile: Profile,
    /// The body the Wagner condition sees: f, or f~ above the initial waterline for an immersed start.
    pub wetting: Profile,
    /// Keel depth at the start, d0 (m; 0 for a keel entry).
    pub immersion: f64,
    pub states: Vec<EntryState>,
    /// Why the history ends before the last sample, if it does.
    pub stopped: Option<String>,
    c_grid: Vec<f64>,
    d_max: Vec<f64>,
}

impl EntryHistory {
    /// States of the section `half` (starboard half, keel first) moving down with speed `v` at times `t`.
    pub fn new(half: &[[f64; 2]], t: &[f64], v: &[f64]) -> Result<Self> {
        Self::new_immersed(half, 0.0, t, v)
    }

    /// States of the section `half` starting immersed to the keel depth `d0` in water at rest (see the
    /// module notes), moving down with speed `v` at times `t`; `d0 = 0` is [`EntryHistory::new`].
    pub fn new_immersed(half: &[[f64; 2]], d0: f64, t: &[f64], v: &[f64]) -> Result<Self> {
        let profile = Profile::from_half_points(half)?;
        let wetting = profile.above(d0)?;
        if t.len() != v.len() {
            return Err(Error::Invalid(format!(
                "entry history: {} times but {} speeds",
                t.len(),
                v.len()
            )));
        }
        let (mut ts, mut vs) = (Vec::new(), Vec::new());
        for (k, (&tk, &vk)) in t.iter().zip(v).enumerate() {
            if !tk.is_finite() || ts.last().is_some_and(|&last| tk <= last) {
                continue;
            }
            if !vk.is_finite() {
                return Err(Error::Invalid(format!(
                    "entry speed at sample {k} (t = {tk} s) is not finite"
                )));
            }
            ts.push(tk);
            vs.push(vk);
        }
        if ts.is_empty() {
            return Err(Error::Invalid(
                "entry history: no finite time samples".into(),
            ));
        }
        // Running maximum of d(c) on a grid through every vertex of f.
        let y_end = profile.y_end();
        let mut c_grid: Vec<f64> = (0..=2000).map(|k| y_end * k as f64 / 2000.0).collect();
        c_grid.extend(wetting.points().iter().map(|p| p[0]));
        c_grid.sort_by(f64::total_cmp);
        c_grid.dedup();
        let mut d_max = Vec::with_capacity(c_grid.len());
        let mut run = 0.0f64;
        for &c in &c_grid {
            run = run.max(wetting.wagner_depth(c).map_or(run, |d| d + d0));
            d_max.push(run);
        }
        let mut out = Self {
            profile,
            wetting,
            immersion: d0,
            states: Vec::new(),
            stopped: None,
            c_grid,
            d_max,
        };
        let dv = (ts.len() >= 2).then(|| Pchip::new(&ts, &vs));
        let mut h = d0;
        for k in 0..ts.len() {
            if k > 0 {
                h += 0.5 * (ts[k] - ts[k - 1]) * (vs[k] + vs[k - 1]);
            }
            if vs[k] < 0.0 {
                out.stopped = Some(format!(
                    "entry speed turned negative at t = {} s (exit is not modelled)",
                    ts[k]
                ));
                break;
            }
            let v_dot = dv.as_ref().map_or(0.0, |p| p.derivative(ts[k]));
            match out.state(ts[k], h, vs[k], v_dot) {
                Some(s) => out.states.push(s),
                None => {
                    let why = match out.profile.end() {
                        ProfileEnd::Widest => "the chine (widest point)",
                        ProfileEnd::Separation => {
                            "the widest point before the half-breadth decreases (flow separation)"
                        }
                    };
                    out.stopped = Some(format!(
                        "wetted half-width reached {why} at y = {:.6} m before t = {:.4} s; Wagner-type models \
                         do not apply beyond",
                        out.profile.y_end(),
                        ts[k]
                    ));
                    break;
                }
            }
        }
        Ok(out)
    }

    /// Largest penetration the Wagner condition covers (wetted half-width at the end of f).
    pub fn max_penetration(&self) -> f64 {
        *self.d_max.last().unwrap()
    }

    /// Wetted half-width at penetration h (`None` past the end of f). c(h) = inf { c : d(c) > h }.
    pub fn half_width(&self, h: f64) -> Option<f64> {
        if !h.is_finite() || h > self.max_penetration() {
            return None;
        }
        let k = self.d_max.partition_point(|&d| d <= h);
        if k == 0 {
            return Some(0.0);
        }
        if k == self.c_grid.len() {
            // h is the largest penetration covered (a plateau may reach the end, e.g. a flat bottom):
            // wetted to the end of f.
            return Some(self.profile.y_end());
        }
        // Whether the penetration at half-width c exceeds h (past the end of f counts as beyond; a NaN
        // depth does not).
        let beyond = |c: f64| {
            self.wetting
                .wagner_depth(c)
                .map_or(f64::INFINITY, |d| d + self.immersion)
                > h
        };
        // d(c_grid[k-1]) <= h < d(c_grid[k]): bisection on d.
        let (_, hi) = bisect(self.c_grid[k - 1], self.c_grid[k], 80, |mid| !beyond(mid));
        // Snap to the grid point below (a flat keel's edge, the keel itself) when within round-off.
        let lo0 = self.c_grid[k - 1];
        Some(if hi - lo0 <= 1e-12 * self.profile.y_end() {
            lo0
        } else {
            hi
        })
    }

    /// The state at penetration h with speed v and acceleration v_dot, or `None` past the end of f.
    pub fn state(&self, t: f64, h: f64, v: f64, v_dot: f64) -> Option<EntryState> {
        let c = self.half_width(h)?;
        let rate = self.wetting.wagner_depth_rate(c)?;
        let c_dot = if v <= 0.0 {
            Some(0.0)
        } else if v >= WATER_SOUND_SPEED * rate {
            None
        } else {
            Some(v / rate)
        };
        Some(EntryState {
            t,
            h,
            v,
            v_dot,
            c,
            c_dot,
        })
    }

    /// The state at time t between the kept samples (h, V, dV/dt linear between samples), or `None`
    /// outside them.
    pub fn state_at(&self, t: f64) -> Option<EntryState> {
        let s = &self.states;
        let k = s.partition_point(|x| x.t <= t);
        if k == 0 || (k == s.len() && t > s[k - 1].t) {
            return None;
        }
        let (a, b) = (s[k - 1], s[k.min(s.len() - 1)]);
        let w = if b.t > a.t {
            (t - a.t) / (b.t - a.t)
        } else {
            0.0
        };
        let mix = |x: f64, y: f64| x + w * (y - x);
        self.state(t, mix(a.h, b.h), mix(a.v, b.v), mix(a.v_dot, b.v_dot))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn duplicates_and_steps_back_in_time_are_skipped() {
        let half = [[0.0, 0.0], [0.3, 0.1]];
        let t = [0.0, 0.0, 1e-3, 1e-3, 0.5e-3, 2e-3, f64::NAN, 3e-3];
        let v = [5.0; 8];
        let e = EntryHistory::new(&half, &t, &v).unwrap();
        let ts: Vec<f64> = e.states.iter().map(|s| s.t).collect();
        assert_eq!(ts, vec![0.0, 1e-3, 2e-3, 3e-3]);
        assert!((e.states[3].h - 15e-3).abs() < 1e-12);
        assert!(EntryHistory::new(&half, &[0.0, 1.0], &[1.0, f64::NAN]).is_err());
    }

    #[test]
    fn flat_keel_starts_at_its_half_width_in_the_acoustic_stage() {
        let half = [[0.0, 0.0], [0.1, 0.0], [0.25, 0.15], [0.25, 0.3]];
        let e = EntryHistory::new(&half, &[0.0, 1e-4], &[5.0, 5.0]).unwrap();
        assert_eq!(e.states[0].c, 0.1);
        assert_eq!(e.states[0].c_dot, None);
        assert!(e.states[1].c > 0.1);
    }

    #[test]
    fn state_at_interpolates_between_samples() {
        let half = [[0.0, 0.0], [0.3, 0.1]];
        let e = EntryHistory::new(&half, &[0.0, 1e-3], &[5.0, 5.0]).unwrap();
        let s = e.state_at(0.5e-3).unwrap();
        assert!((s.h - 2.5e-3).abs() < 1e-12);
        assert!(e.state_at(2e-3).is_none());
    }
}
