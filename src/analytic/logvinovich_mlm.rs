//! Modified Logvinovich model (MLM) of water entry for an arbitrary symmetric section with a varying
//! speed V(t) (Korobkin 2004, "Analytical models of water impact", Eur. J. Appl. Math. 15, 821-838;
//! used with gravity added by Hulin, Del Buono, Tassin, Bernardini & Iafrati 2022, J. Fluid Mech. 944).
//!
//! **Source note.** Neither paper's text was reachable from this project's stored references (only the
//! abstracts), so the equation numbers could not be checked. The formulas below are derived here from the
//! model's defining assumptions as Korobkin states them, and the derivation is given so it can be checked
//! against the paper:
//!
//! 1. The wetted half-width c(t) comes from the Wagner condition for the actual shape
//!    ([`crate::analytic::entry_kinematics`]); the body is z = f(x) - h(t), h the penetration, V = dh/dt.
//! 2. The velocity potential on the wetted body surface is the first-order Taylor expansion of Wagner's
//!    flat-plate potential phi_0 = -V sqrt(c^2 - x^2) (on z = 0, |x| < c) about z = 0, with
//!    d phi_0 / dz = -V there:
//!
//!    Phi(x, t) = phi(x, f(x) - h(t), t) = -V [ sqrt(c^2 - x^2) + f(x) - h ].
//!
//! 3. The pressure follows from the full (nonlinear) Bernoulli equation p = -rho (phi_t + |grad phi|^2/2)
//!    on the body surface. With the body condition phi_z - f' phi_x = -V and the tangential derivative
//!    phi_x + f' phi_z = Phi_x, |grad phi|^2 = (Phi_x^2 + V^2)/(1 + f'^2) and phi_t = Phi_t + V phi_z,
//!    which gives p = rho [ -Phi_t - (Phi_x + V f')^2 / (2 (1 + f'^2)) + V^2/2 ], and with Phi above
//!    (c' = dc/dt, V' = dV/dt):
//!
//! ```text
//! p(x, t) = rho { V c c' / sqrt(c^2 - x^2) + V' [ sqrt(c^2 - x^2) + f(x) - h ]
//!                 - (V^2/2) [ 1 + x^2 / ((c^2 - x^2)(1 + f'(x)^2)) ] },      |x| < c.
//! ```
//!
//! Near the contact point the first term (+1/sqrt(c - x)) and the last (-1/(c - x)) give a peak of
//! about rho c'^2 (1 + f'(c)^2) / 2 just inside x = c (a consequence of the formula, checked in the tests;
//! it is Wagner's rho c'^2/2 with the contact point's speed along the surface, c' sqrt(1 + f'^2)), then
//! the pressure falls to -infinity at x = c. That negative region is an artefact of the outer solution:
//! as is usual with the MLM, the pressure is set to zero where the formula is negative, both for the
//! force, F = integral_{-c}^{c} max(p, 0) dx, and for sensor means. Dry points (|x| >= c) read zero.
//!
//! In the acoustic stage of [`crate::analytic::entry_kinematics`] (flat keel at contact, dc/dt of the
//! order of the water sound speed) the model does not apply: the wetted part is given the water-hammer
//! pressure rho c_w V, flagged in [`Mlm::acoustic`].
//!
//! **Initial immersion** ([`Mlm::new_immersed`]): the section starts immersed to the keel depth d0 in
//! water at rest; c(t) comes from the Wagner condition of the body above the initial waterline
//! ([`crate::analytic::entry_kinematics`]) and h is the keel depth (d0 at the start), so the formula above
//! is unchanged, with f the actual body also on the part wetted from the start. The first sample (c at the
//! waterline half-breadth, dc/dt unbounded) is the impulsive start of the idealisation and is flagged as
//! in the acoustic stage. Hydrostatic pressure is not included (nor is it for a keel entry).
//!
//! Points of the contour that are not on f (a vertical step's face, the contour above a bulb's widest
//! point) get no MLM pressure (zero).

use crate::analytic::entry_kinematics::{EntryHistory, EntryState, WATER_SOUND_SPEED};
use crate::error::Result;
use crate::numerics::bisect;
use crate::numerics::quadrature::gauss_legendre;
use std::f64::consts::FRAC_PI_2;

/// The MLM along one entry history.
#[derive(Debug, Clone)]
pub struct Mlm {
    hist: EntryHistory,
    rho: f64,
    /// Contour (starboard half, keel first, z from the keel) with cumulative arc length.
    contour: Vec<[f64; 3]>,
    gl: (Vec<f64>, Vec<f64>),
}

impl Mlm {
    /// The MLM for the section `half` (starboard half, keel first at y = 0) moving down with speed `v` at
    /// times `t` (see [`EntryHistory::new`] for how samples are kept), water density `rho`.
    pub fn new(half: &[[f64; 2]], t: &[f64], v: &[f64], rho: f64) -> Result<Self> {
        Self::new_immersed(half, 0.0, t, v, rho)
    }

    /// The MLM for the section `half` starting immersed to the keel depth `d0` in water at rest (module
    /// notes); `d0 = 0` is [`Mlm::new`].
    pub fn new_immersed(
        half: &[[f64; 2]],
        d0: f64,
        t: &[f64],
        v: &[f64],
        rho: f64,
    ) -> Result<Self> {
        Ok(Self::with_history(
            half,
            EntryHistory::new_immersed(half, d0, t, v)?,
            rho,
        ))
    }

    /// The MLM along an entry history already computed for the section `half`
    /// ([`EntryHistory::new_immersed`] of the same `half`), so that an estimate that also needs the
    /// Wagner values of the same history computes it once.
    pub fn with_history(half: &[[f64; 2]], hist: EntryHistory, rho: f64) -> Self {
        let z0 = half[0][1];
        let mut contour: Vec<[f64; 3]> = vec![[half[0][0], 0.0, 0.0]];
        for p in &half[1..] {
            let last = *contour.last().unwrap();
            let l = (p[0] - last[0]).hypot(p[1] - z0 - last[1]);
            contour.push([p[0], p[1] - z0, last[2] + l]);
        }
        Self {
            hist,
            rho,
            contour,
            gl: gauss_legendre(6),
        }
    }

    /// The entry history (times, penetration, c, dc/dt, why it stopped).
    pub fn history(&self) -> &EntryHistory {
        &self.hist
    }

    /// Kept sample times.
    pub fn times(&self) -> Vec<f64> {
        self.hist.states.iter().map(|s| s.t).collect()
    }

    /// Whether each sample is in the acoustic stage (pressures there are rho c_w V, not the MLM's).
    pub fn acoustic(&self) -> Vec<bool> {
        self.hist.states.iter().map(|s| s.c_dot.is_none()).collect()
    }

    /// The MLM formula at |x| < c (may be negative), or `None` on the dry part or in the acoustic stage.
    pub fn pressure_unclipped(&self, s: &EntryState, x: f64) -> Option<f64> {
        let x = x.abs();
        let cd = s.c_dot?;
        let r = s.c * s.c - x * x;
        if x >= s.c || r <= 0.0 {
            return None;
        }
        let u = r.sqrt();
        let (f, fp) = self.hist.profile.height_and_slope(x);
        let f = f?;
        let vv = s.v * s.v;
        Some(
            self.rho
                * (s.v * s.c * cd / u + s.v_dot * (u + f - s.h)
                    - 0.5 * vv * (1.0 + x * x / (r * (1.0 + fp * fp)))),
        )
    }

    /// Pressure at horizontal coordinate x: the MLM value clipped at zero on the wetted part, zero on the
    /// dry part, rho c_w V on the wetted part in the acoustic stage.
    pub fn pressure(&self, s: &EntryState, x: f64) -> f64 {
        if s.c_dot.is_none() {
            return if x.abs() <= s.c {
                self.rho * WATER_SOUND_SPEED * s.v
            } else {
                0.0
            };
        }
        self.pressure_unclipped(s, x).map_or(0.0, |p| p.max(0.0))
    }

    /// Pressure distribution (x, p) at time `t` at `n` points on 0 <= x < c, clustered towards the
    /// contact point (x = c sin theta, theta uniform); `None` outside the history.
    pub fn distribution_at(&self, t: f64, n: usize) -> Option<Vec<[f64; 2]>> {
        let s = self.hist.state_at(t)?;
        let n = n.max(2);
        Some(
            (0..n)
                .map(|k| {
                    let x = s.c * (FRAC_PI_2 * k as f64 / n as f64).sin();
                    [x, self.pressure(&s, x)]
                })
                .collect(),
        )
    }

    /// Largest pressure on the wetted part and its x: searched on a grid in sqrt(c^2 - x^2) (log-spaced
    /// towards the contact point), refined by golden section.
    pub fn peak(&self, s: &EntryState) -> (f64, f64) {
        if s.c <= 0.0 {
            return (0.0, 0.0);
        }
        if s.c_dot.is_none() {
            return (0.0, self.pressure(s, 0.0));
        }
        let x_of = |w: f64| s.c * (1.0 - w * w).max(0.0).sqrt();
        let p_of = |w: f64| self.pressure(s, x_of(w));
        let grid = peak_grid();
        let n = PEAK_GRID;
        let on_grid: Vec<f64> = grid[..=n].iter().map(|&w| p_of(w)).collect();
        let k_best = (0..=n)
            .max_by(|&a, &b| on_grid[a].total_cmp(&on_grid[b]))
            .unwrap_or(n);
        let (mut a, mut b) = (grid[k_best.saturating_sub(1)], grid[(k_best + 1).min(n)]);
        let g = 0.5 * (5f64.sqrt() - 1.0);
        for _ in 0..80 {
            let (m1, m2) = (b - g * (b - a), a + g * (b - a));
            let next = if p_of(m1) > p_of(m2) {
                (a, m2)
            } else {
                (m1, b)
            };
            // An iteration that leaves the bracket as it was leaves it so for good.
            if next == (a, b) {
                break;
            }
            (a, b) = next;
        }
        let w = 0.5 * (a + b);
        let (x, p) = (x_of(w), p_of(w));
        if p >= on_grid[k_best] {
            (x, p)
        } else {
            (x_of(grid[k_best]), on_grid[k_best])
        }
    }

    /// Vertical force per unit length F = 2 c integral_0^{pi/2} max(p, 0) cos theta d theta (x = c sin
    /// theta); 2 c rho c_w V in the acoustic stage.
    pub fn force(&self, s: &EntryState) -> f64 {
        if s.c <= 0.0 {
            return 0.0;
        }
        if s.c_dot.is_none() {
            return 2.0 * s.c * self.rho * WATER_SOUND_SPEED * s.v;
        }
        let g = |th: f64| self.pressure(s, s.c * th.sin()) * th.cos();
        let sign = |th: f64| self.pressure_unclipped(s, s.c * th.sin()).unwrap_or(-1.0) > 0.0;
        // Panel ends: log-spaced in cos(theta) towards the contact point, and the vertices of f.
        let mut ends: Vec<f64> = force_grid().to_vec();
        ends.extend(
            self.hist
                .profile
                .points()
                .iter()
                .filter(|p| p[0] > 0.0 && p[0] < s.c)
                .map(|p| (p[0] / s.c).asin()),
        );
        ends.push(FRAC_PI_2);
        ends.sort_by(f64::total_cmp);
        ends.dedup();
        let signs: Vec<bool> = ends.iter().map(|&e| sign(e)).collect();
        let mut sum = 0.0;
        for (w, sw) in ends.windows(2).zip(signs.windows(2)) {
            let (a, b) = (w[0], w[1]);
            let mut cuts = vec![a];
            let sa = sw[0];
            if sa != sw[1] {
                let (lo, hi) = bisect(a, b, 60, |mid| sign(mid) == sa);
                cuts.push(0.5 * (lo + hi));
            }
            cuts.push(b);
            for q in cuts.windows(2) {
                sum += self.gauss(q[0], q[1], &g);
            }
        }
        2.0 * s.c * sum
    }

    fn gauss(&self, a: f64, b: f64, f: &impl Fn(f64) -> f64) -> f64 {
        let (x, w) = &self.gl;
        let (m, r) = (0.5 * (a + b), 0.5 * (b - a));
        x.iter()
            .zip(w)
            .map(|(xi, wi)| wi * f(m + r * xi))
            .sum::<f64>()
            * r
    }

    /// The contour point (y, z above the keel) at arc length `s` from the keel, or `None` past its end.
    fn point_at_arc(&self, s: f64) -> Option<[f64; 2]> {
        self.contour.windows(2).find_map(|w| {
            let (a, b) = (w[0], w[1]);
            (s >= a[2] && s <= b[2] && b[2] > a[2]).then(|| {
                let f = (s - a[2]) / (b[2] - a[2]);
                [a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1])]
            })
        })
    }

    /// Pressure at arc length `s` along the starboard contour: [`Mlm::pressure`] where the contour point
    /// lies on f, zero elsewhere (vertical faces, above a bulb's widest point, past the contour's end).
    pub fn pressure_at_arc(&self, st: &EntryState, s: f64) -> f64 {
        let Some([y, z]) = self.point_at_arc(s) else {
            return 0.0;
        };
        let prof = &self.hist.profile;
        let on_f = prof
            .height(y)
            .is_some_and(|f| (z - f).abs() <= 1e-9 * prof.y_end().max(z.abs()));
        if on_f { self.pressure(st, y) } else { 0.0 }
    }

    /// Mean pressure over the sensor panel [s1, s2] (arc length from the keel along the starboard
    /// contour), integrated with Gauss panels split at the contour vertices and at the arc positions of
    /// the contact point and the peak.
    pub fn sensor_mean(&self, st: &EntryState, s1: f64, s2: f64) -> f64 {
        let (s1, s2) = (s1.min(s2), s1.max(s2));
        if s2 <= s1 {
            return self.pressure_at_arc(st, s1);
        }
        let prof = &self.hist.profile;
        let mut ends = vec![s1, s2];
        ends.extend(self.contour.iter().map(|p| p[2]));
        if st.c > 0.0 && st.c <= prof.y_end() {
            ends.push(prof.arc_length_to(st.c));
            ends.push(prof.arc_length_to(self.peak(st).0));
        }
        ends.retain(|&e| e >= s1 && e <= s2);
        ends.sort_by(f64::total_cmp);
        ends.dedup();
        let g = |s: f64| self.pressure_at_arc(st, s);
        let panels = 64;
        let mut sum = 0.0;
        for w in ends.windows(2) {
            let h = (w[1] - w[0]) / panels as f64;
            for k in 0..panels {
                let a = w[0] + k as f64 * h;
                sum += self.gauss(a, a + h, &g);
            }
        }
        sum / (s2 - s1)
    }

    /// Peak pressure history (one value per kept sample).
    pub fn peak_pressure_history(&self) -> Vec<f64> {
        self.hist.states.iter().map(|s| self.peak(s).1).collect()
    }

    /// Force history (N/m, one value per kept sample).
    pub fn force_history(&self) -> Vec<f64> {
        self.hist.states.iter().map(|s| self.force(s)).collect()
    }

    /// History of the mean pressure over the sensor panel [s1, s2] (arc length from the keel), by the
    /// direct quadrature of [`Mlm::sensor_mean`] (for many panels, [`Mlm::sensor_histories`] is faster).
    pub fn sensor_history(&self, s1: f64, s2: f64) -> Vec<f64> {
        self.hist
            .states
            .iter()
            .map(|s| self.sensor_mean(s, s1, s2))
            .collect()
    }
}

/// Intervals of the peak search's grid in w = sqrt(1 - x^2/c^2) ([`Mlm::peak`]).
const PEAK_GRID: usize = 600;

/// The grid of the peak search, w_k = 10^(-9 (1 - k / [`PEAK_GRID`])), computed once.
fn peak_grid() -> &'static [f64; PEAK_GRID + 1] {
    static GRID: std::sync::OnceLock<[f64; PEAK_GRID + 1]> = std::sync::OnceLock::new();
    GRID.get_or_init(|| {
        std::array::from_fn(|k| 10f64.powf(-9.0 * (1.0 - k as f64 / PEAK_GRID as f64)))
    })
}

/// Log-spaced panel ends of the force quadrature ([`Mlm::force`]), theta_k = acos(10^(-9 k / 80)),
/// computed once.
fn force_grid() -> &'static [f64; 81] {
    static GRID: std::sync::OnceLock<[f64; 81]> = std::sync::OnceLock::new();
    GRID.get_or_init(|| std::array::from_fn(|k| (10f64.powf(-9.0 * k as f64 / 80.0)).acos()))
}

#[path = "mlm_panels.rs"]
mod panels;

#[path = "mlm_correction.rs"]
mod correction;

#[cfg(test)]
#[path = "logvinovich_mlm_tests.rs"]
mod tests;
