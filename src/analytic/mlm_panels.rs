//! Mean MLM pressures of many sensor panels at once.
//!
//! The mean over a panel [s1, s2] (arc length s from the keel along the starboard contour) is
//!
//! ```text
//! p_mean = (1 / (s2 - s1)) integral_{s1}^{s2} max(p(y(s), t), 0) ds
//! ```
//!
//! with p the MLM pressure of [`Mlm::pressure`] (zero off f and on the dry part). Per time sample the arc
//! is cut once at the contour vertices, every panel end, the pressure peak, the zero of the MLM formula
//! between the peak and the contact point (max(p, 0) has a kink there) and the contact point itself, so
//! the cost of a sample does not grow with the number of panels times the quadrature of each. Only the
//! pieces inside at least one panel are integrated (the arc between panels is not needed), and a panel's
//! integral is the sum of its pieces from the keel outwards. Each piece on the wetted part is integrated
//! with Gauss panels graded towards the contact point (each no longer than [`GRADING`] times its
//! distance from it), where the pressure varies on the scale of that distance (p ~ 1/sqrt(c - x) and
//! -1/(c - x), see [`crate::analytic::logvinovich_mlm`]).

use rayon::prelude::*;

use super::Mlm;
use crate::analytic::entry_kinematics::EntryState;
use crate::numerics::bisect;

/// Largest Gauss panel on the wetted part, as a fraction of its distance from the contact point.
const GRADING: f64 = 0.25;
/// Largest Gauss panel on the wetted part, as a fraction of the wetted arc (so that the narrow positive
/// bumps a decelerating entry can give away from the contact point are seen by the sign test).
const MAX_PANEL: f64 = 1.0 / 400.0;
/// Closest distance from the contact point, as a fraction of the wetted arc, that graded panels
/// resolve (the formula is negative there, max(p, 0) = 0).
const MIN_DISTANCE: f64 = 1e-10;

impl Mlm {
    /// Arc length of the first point of the contour with half-breadth `y` on a segment of increasing
    /// half-breadth, or `None`.
    pub(super) fn arc_of_y(&self, y: f64) -> Option<f64> {
        self.contour.windows(2).find_map(|w| {
            let (a, b) = (w[0], w[1]);
            (b[0] > a[0] && a[0] <= y && y <= b[0])
                .then(|| a[2] + (y - a[0]) / (b[0] - a[0]) * (b[2] - a[2]))
        })
    }

    /// Half-breadth y of the point at arc length `s` on contour segment `k` when it lies on f, else `None`.
    fn y_on_f(&self, k: usize, s: f64) -> Option<f64> {
        let (a, b) = (self.contour[k], self.contour[k + 1]);
        let f = (s - a[2]) / (b[2] - a[2]);
        let (y, z) = (a[0] + f * (b[0] - a[0]), a[1] + f * (b[1] - a[1]));
        let prof = &self.hist.profile;
        prof.height(y)
            .is_some_and(|fy| (z - fy).abs() <= 1e-9 * prof.y_end().max(z.abs()))
            .then_some(y)
    }

    /// Pressure at arc length `s` on contour segment `k` (see [`Mlm::pressure_at_arc`]).
    fn pressure_on_segment(&self, st: &EntryState, k: usize, s: f64) -> f64 {
        self.y_on_f(k, s).map_or(0.0, |y| self.pressure(st, y))
    }

    /// Whether the MLM formula is positive at arc length `s` on contour segment `k` (where max(p, 0)
    /// has a kink, the sign changes).
    fn positive_on_segment(&self, st: &EntryState, k: usize, s: f64) -> bool {
        self.y_on_f(k, s)
            .and_then(|y| self.pressure_unclipped(st, y))
            .is_some_and(|p| p > 0.0)
    }

    /// The integral of max(p, 0) along the arc over each of the `spans` ([s1, s2] with s1 <= s2, arc
    /// lengths from the keel), at one state (module notes).
    pub fn span_integrals(&self, st: &EntryState, spans: &[(f64, f64)]) -> Vec<f64> {
        let c = st.c;
        if c <= 0.0 || spans.is_empty() {
            return vec![0.0; spans.len()];
        }
        let end = self.contour.last().map_or(0.0, |p| p[2]);
        let s_c = self.arc_of_y(c);
        // Peak and zero of the formula between the peak and the contact point (MLM stage only).
        let mut special: Vec<f64> = s_c.into_iter().collect();
        if st.c_dot.is_some() {
            let (xp, pp) = self.peak(st);
            special.extend(self.arc_of_y(xp));
            if pp > 0.0 {
                let (lo, hi) = bisect(xp, c, 60, |mid| {
                    self.pressure_unclipped(st, mid).unwrap_or(-1.0) > 0.0
                });
                special.extend(self.arc_of_y(0.5 * (lo + hi)));
            }
        }
        let clamped: Vec<(f64, f64)> = spans
            .iter()
            .map(|&(a, b)| (a.clamp(0.0, end), b.clamp(0.0, end)))
            .collect();
        let mut cuts: Vec<f64> = self.contour.iter().map(|p| p[2]).collect();
        cuts.extend(special);
        cuts.extend(clamped.iter().flat_map(|&(a, b)| [a, b]));
        cuts.sort_by(f64::total_cmp);
        cuts.dedup();
        // Each span is the union of the pieces starting at cuts i..j; a piece is integrated when it lies
        // in a span.
        let ranges: Vec<std::ops::Range<usize>> = clamped
            .iter()
            .map(|&(a, b)| cuts.partition_point(|&x| x < a)..cuts.partition_point(|&x| x < b))
            .collect();
        let mut inside = vec![false; cuts.len()];
        for r in &ranges {
            inside[r.clone()].iter_mut().for_each(|v| *v = true);
        }
        // Graded panels up to the contact point in the MLM stage, plain ones elsewhere.
        let graded_end = s_c.filter(|_| st.c_dot.is_some());
        let mut piece = vec![0.0; cuts.len()];
        let mut k = 0;
        for (n, w) in cuts.windows(2).enumerate() {
            let (a, b) = (w[0], w[1]);
            let mid = 0.5 * (a + b);
            while k + 2 < self.contour.len() && self.contour[k + 1][2] <= mid {
                k += 1;
            }
            let (pa, pb) = (self.contour[k], self.contour[k + 1]);
            // Skip pieces outside every span, of zero length, of a degenerate segment, or wholly dry
            // (y >= c).
            if inside[n] && b > a && pb[2] > pa[2] && pa[0].min(pb[0]) < c {
                let g = |s: f64| self.pressure_on_segment(st, k, s);
                let sign = |s: f64| st.c_dot.is_none() || self.positive_on_segment(st, k, s);
                piece[n] = match graded_end {
                    Some(sc) if b <= sc => self.graded(a, b, sc, &g, &sign),
                    _ => self.split_gauss(a, b, &g, &sign),
                };
            }
        }
        ranges.into_iter().map(|r| piece[r].iter().sum()).collect()
    }

    /// Integral over [a, b] (b <= sc) with Gauss panels no longer than [`GRADING`] times their distance
    /// from `sc` nor [`MAX_PANEL`] times `sc`, each split where `sign` changes; the last panel closes the
    /// interval once within [`MIN_DISTANCE`] times `sc` of `sc`.
    fn graded(
        &self,
        a: f64,
        b: f64,
        sc: f64,
        g: &impl Fn(f64) -> f64,
        sign: &impl Fn(f64) -> bool,
    ) -> f64 {
        let (h_max, d_min) = (MAX_PANEL * sc, MIN_DISTANCE * sc);
        let mut x = a;
        // The sign at a panel's start is that at the previous panel's end.
        let mut sx = sign(x);
        let mut sum = 0.0;
        while x < b {
            if sc - x <= d_min {
                return sum + self.split_gauss_signed((x, sx), (b, sign(b)), g, sign);
            }
            let h = (GRADING * (sc - x)).min(h_max);
            let next = if b - x <= 1.5 * h { b } else { x + h };
            let sn = sign(next);
            sum += self.split_gauss_signed((x, sx), (next, sn), g, sign);
            (x, sx) = (next, sn);
        }
        sum
    }

    /// Gauss rule on [a, b], split at the change of `sign` (by bisection) when the ends differ.
    fn split_gauss(
        &self,
        a: f64,
        b: f64,
        g: &impl Fn(f64) -> f64,
        sign: &impl Fn(f64) -> bool,
    ) -> f64 {
        self.split_gauss_signed((a, sign(a)), (b, sign(b)), g, sign)
    }

    /// [`Mlm::split_gauss`] with the signs at the ends already known: `(a, sign(a))`, `(b, sign(b))`.
    fn split_gauss_signed(
        &self,
        (a, sa): (f64, bool),
        (b, sb): (f64, bool),
        g: &impl Fn(f64) -> f64,
        sign: &impl Fn(f64) -> bool,
    ) -> f64 {
        if sa == sb {
            return self.gauss(a, b, g);
        }
        let (lo, hi) = bisect(a, b, 60, |mid| sign(mid) == sa);
        let m = 0.5 * (lo + hi);
        self.gauss(a, m, g) + self.gauss(m, b, g)
    }

    /// Mean pressures over the panels `panels` ([s1, s2] arc lengths from the keel, in either order) at
    /// one state; a panel of zero width reads the point value [`Mlm::pressure_at_arc`].
    pub fn sensor_means(&self, st: &EntryState, panels: &[(f64, f64)]) -> Vec<f64> {
        let spans: Vec<(f64, f64)> = panels.iter().map(|&(a, b)| (a.min(b), a.max(b))).collect();
        let integral = self.span_integrals(st, &spans);
        spans
            .iter()
            .zip(integral)
            .map(|(&(s1, s2), i)| {
                if s2 <= s1 {
                    self.pressure_at_arc(st, s1)
                } else {
                    i / (s2 - s1)
                }
            })
            .collect()
    }

    /// Histories of the mean pressure over each panel (`[panel][sample]`). Samples are independent and
    /// computed in parallel, collected in order (the result does not depend on the thread count).
    pub fn sensor_histories(&self, panels: &[(f64, f64)]) -> Vec<Vec<f64>> {
        let per_time: Vec<Vec<f64>> = self
            .hist
            .states
            .par_iter()
            .map(|s| self.sensor_means(s, panels))
            .collect();
        transpose(panels.len(), &per_time)
    }
}

/// `[sample][panel]` to `[panel][sample]`.
fn transpose(n: usize, per_time: &[Vec<f64>]) -> Vec<Vec<f64>> {
    (0..n)
        .map(|j| per_time.iter().map(|row| row[j]).collect())
        .collect()
}
