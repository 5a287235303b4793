//! Shape-preserving piecewise cubic Hermite interpolation (PCHIP).
//!
//! Fritsch, F. N. & Carlson, R. E. (1980), "Monotone piecewise cubic interpolation", SIAM J. Numer. Anal.
//! 17(2): 238-246, with the derivative choice of Fritsch & Butland (1984): at an interior knot the slope is the
//! weighted harmonic mean
//!
//! d_k = (w1 + w2) / (w1/δ_{k-1} + w2/δ_k),  w1 = 2h_k + h_{k-1},  w2 = h_k + 2h_{k-1},
//!
//! and zero where the secant slopes δ change sign or one is zero. End slopes use the one-sided three-point
//! formula, limited so that the interpolant keeps the sign of the data and does not overshoot. The
//! interpolant is monotone wherever the data are, and has no new extrema: a hull's offsets never bulge
//! beyond what the lines plan says.

/// A PCHIP interpolant through (x_k, y_k), x strictly increasing.
#[derive(Debug, Clone)]
pub struct Pchip {
    x: Vec<f64>,
    y: Vec<f64>,
    d: Vec<f64>,
}

/// A point located among the knots of an interpolant: interval k, local coordinate s in [0, 1] (outside
/// for extrapolation) and the interval's length h.
#[derive(Debug, Clone, Copy)]
pub struct Located {
    k: usize,
    s: f64,
    h: f64,
}

impl Pchip {
    /// Build the interpolant. Panics only on programmer error (fewer than one knot, x not strictly
    /// increasing); user data are validated before they get here.
    pub fn new(x: &[f64], y: &[f64]) -> Self {
        assert_eq!(x.len(), y.len(), "pchip: x and y lengths differ");
        assert!(!x.is_empty(), "pchip: no knots");
        assert!(
            x.windows(2).all(|w| w[1] > w[0]),
            "pchip: x must be strictly increasing"
        );
        let d = (0..x.len()).map(|k| knot_slope(x, y, k)).collect();
        Self {
            x: x.to_vec(),
            y: y.to_vec(),
            d,
        }
    }

    /// Knot abscissae.
    pub fn knots(&self) -> &[f64] {
        &self.x
    }

    fn interval(&self, t: f64) -> usize {
        let n = self.x.len();
        // A NaN argument goes to the first interval and gives a NaN value instead of a panic.
        if n < 2 || t.is_nan() || t <= self.x[0] {
            return 0;
        }
        if t >= self.x[n - 1] {
            return n - 2;
        }
        self.x.partition_point(|&xk| xk <= t) - 1
    }

    /// Value at `t`. Outside the knots the end cubic is extended (callers decide whether that is allowed).
    pub fn eval(&self, t: f64) -> f64 {
        self.eval_at(self.locate(t))
    }

    /// Where `t` falls among the knots, for [`Pchip::eval_at`] on this interpolant or any other with the
    /// same knots (one search serves them all).
    pub fn locate(&self, t: f64) -> Located {
        if self.x.len() == 1 {
            return Located {
                k: 0,
                s: 0.0,
                h: 0.0,
            };
        }
        let k = self.interval(t);
        let h = self.x[k + 1] - self.x[k];
        Located {
            k,
            s: (t - self.x[k]) / h,
            h,
        }
    }

    /// Value at a point found by [`Pchip::locate`] on an interpolant with the same knots: the Hermite
    /// cubic p(s) = h00 y_k + h10 h d_k + h01 y_k+1 + h11 h d_k+1 (Fritsch & Carlson 1980).
    pub fn eval_at(&self, at: Located) -> f64 {
        if self.x.len() == 1 {
            return self.y[0];
        }
        let Located { k, s, h } = at;
        let (h00, h10, h01, h11) = hermite_basis(s);
        h00 * self.y[k] + h10 * h * self.d[k] + h01 * self.y[k + 1] + h11 * h * self.d[k + 1]
    }

    /// First derivative at `t`.
    pub fn derivative(&self, t: f64) -> f64 {
        let n = self.x.len();
        if n == 1 {
            return 0.0;
        }
        let k = self.interval(t);
        let h = self.x[k + 1] - self.x[k];
        let s = (t - self.x[k]) / h;
        let dh00 = 6.0 * s * s - 6.0 * s;
        let dh10 = 3.0 * s * s - 4.0 * s + 1.0;
        let dh01 = -dh00;
        let dh11 = 3.0 * s * s - 2.0 * s;
        (dh00 * self.y[k] + dh01 * self.y[k + 1]) / h + dh10 * self.d[k] + dh11 * self.d[k + 1]
    }

    /// Exact integral of the interpolant over its whole knot range:
    /// ∫ p dx = Σ h_k (y_k + y_{k+1})/2 + h_k² (d_k − d_{k+1})/12.
    pub fn integral(&self) -> f64 {
        (0..self.x.len().saturating_sub(1))
            .map(|k| {
                let h = self.x[k + 1] - self.x[k];
                h * (self.y[k] + self.y[k + 1]) / 2.0 + h * h * (self.d[k] - self.d[k + 1]) / 12.0
            })
            .sum()
    }
}

/// The slope of the PCHIP through (x, y) at knot `k`, from the knot's neighbours only (two on each side
/// at most): the slopes [`Pchip::new`] uses, so that a caller that needs the interpolant on one interval
/// only can evaluate it from a window of four knots around the interval without building the whole.
pub fn knot_slope(x: &[f64], y: &[f64], k: usize) -> f64 {
    let n = x.len();
    if n < 2 {
        return 0.0;
    }
    // Only the (up to) three intervals next to knot k matter.
    let lo = k.saturating_sub(2).min(n - 2);
    let hi = (k + 2).min(n - 1);
    let mut h = [0.0; 4];
    let mut del = [0.0; 4];
    for i in lo..hi {
        h[i - lo] = x[i + 1] - x[i];
        del[i - lo] = (y[i + 1] - y[i]) / h[i - lo];
    }
    slope_from(
        &h[..hi - lo],
        &del[..hi - lo],
        k - lo,
        n == 2,
        k == 0,
        k == n - 1,
    )
}

/// The PCHIP slope at knot `k` of a run of intervals with lengths `h` and secant slopes `del` (knot k
/// is the left end of interval k of the run); `two` when the whole interpolant has two knots, `first` and
/// `last` when k is its first or last knot. The formula of [`knot_slope`], for callers that share `h`.
pub fn slope_from(h: &[f64], del: &[f64], k: usize, two: bool, first: bool, last: bool) -> f64 {
    if two {
        return del[0];
    }
    if first {
        return end_slope(h[k], h[k + 1], del[k], del[k + 1]);
    }
    if last {
        return end_slope(h[k - 1], h[k - 2], del[k - 1], del[k - 2]);
    }
    let (d0, d1) = (del[k - 1], del[k]);
    if d0 * d1 > 0.0 {
        let w1 = 2.0 * h[k] + h[k - 1];
        let w2 = h[k] + 2.0 * h[k - 1];
        (w1 + w2) / (w1 / d0 + w2 / d1)
    } else {
        0.0
    }
}

/// The cubic Hermite basis (h00, h10, h01, h11) at the local coordinate s ∈ [0, 1] of an interval.
pub fn hermite_basis(s: f64) -> (f64, f64, f64, f64) {
    let s2 = s * s;
    let s3 = s2 * s;
    (
        2.0 * s3 - 3.0 * s2 + 1.0,
        s3 - 2.0 * s2 + s,
        -2.0 * s3 + 3.0 * s2,
        s3 - s2,
    )
}

/// Non-centred three-point end slope, limited to keep shape (Moler, "Numerical Computing with MATLAB", §3.4).
fn end_slope(h0: f64, h1: f64, del0: f64, del1: f64) -> f64 {
    let d = ((2.0 * h0 + h1) * del0 - h0 * del1) / (h0 + h1);
    if d * del0 <= 0.0 {
        0.0
    } else if del0 * del1 < 0.0 && d.abs() > 3.0 * del0.abs() {
        3.0 * del0
    } else {
        d
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reproduces_knots_and_lines() {
        let x = [0.0, 1.0, 2.5, 4.0];
        let y = [1.0, 3.0, 6.0, 9.0];
        let p = Pchip::new(&x, &y);
        for (xi, yi) in x.iter().zip(y.iter()) {
            assert!((p.eval(*xi) - yi).abs() < 1e-12);
        }
        let lin = Pchip::new(&[0.0, 1.0, 3.0], &[0.0, 2.0, 6.0]);
        assert!((lin.eval(2.0) - 4.0).abs() < 1e-12);
        assert!((lin.integral() - 9.0).abs() < 1e-12);
    }

    #[test]
    fn nan_argument_gives_nan_not_a_panic() {
        let p = Pchip::new(&[0.0, 1.0, 2.0], &[0.0, 1.0, 4.0]);
        assert!(p.eval(f64::NAN).is_nan());
        assert!(p.derivative(f64::NAN).is_nan());
    }

    #[test]
    fn monotone_data_give_a_monotone_interpolant() {
        // Uneven spacing and slopes from flat to steep: the interpolant never turns back.
        let x = [0.0, 0.1, 0.15, 1.0, 1.05, 3.0, 3.01];
        let y = [0.0, 0.0, 0.5, 0.52, 2.0, 2.0, 7.0];
        let p = Pchip::new(&x, &y);
        let mut prev = f64::NEG_INFINITY;
        for i in 0..=3010 {
            let v = p.eval(i as f64 * 0.001);
            assert!(v >= prev - 1e-12, "decreases at {}", i as f64 * 0.001);
            assert!(p.derivative(i as f64 * 0.001) >= -1e-9);
            prev = v;
        }
        // Flat data stay flat.
        for i in 0..=50 {
            assert!((p.eval(3.0 - 1.95 * i as f64 / 50.0) - 2.0).abs() < 1e-12);
        }
        // The exact integral agrees with a fine quadrature of eval.
        let m = 301_000;
        let h = 3.01 / m as f64;
        let num: f64 = (0..m).map(|i| p.eval((i as f64 + 0.5) * h) * h).sum();
        assert!(
            (num - p.integral()).abs() < 1e-8,
            "{num} vs {}",
            p.integral()
        );
    }

    #[test]
    fn no_overshoot_on_step_data() {
        let x = [0.0, 1.0, 2.0, 3.0, 4.0];
        let y = [0.0, 0.0, 1.0, 1.0, 1.0];
        let p = Pchip::new(&x, &y);
        for i in 0..=400 {
            let v = p.eval(i as f64 * 0.01);
            assert!((-1e-12..=1.0 + 1e-12).contains(&v), "overshoot {v}");
        }
    }

    #[test]
    fn integral_of_smooth_function_converges() {
        let n = 41;
        let x: Vec<f64> = (0..n).map(|i| i as f64 / (n - 1) as f64).collect();
        let y: Vec<f64> = x
            .iter()
            .map(|t| (1.0 - t * t) * (1.0 + 0.2 * t * t))
            .collect();
        let exact = 1.0 + 0.2 / 3.0 - 1.0 / 3.0 - 0.2 / 5.0;
        assert!((Pchip::new(&x, &y).integral() - exact).abs() < 1e-5);
    }
}
