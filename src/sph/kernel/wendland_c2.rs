//! The Wendland (1995) C2 kernel in two dimensions.
//!
//! With q = r/h and support 2h:
//!
//! W(r, h) = a (1 - q/2)^4 (2q + 1),  a = 7 / (4 pi h^2),  0 <= q <= 2
//!
//! (Wendland 1995, Adv. Comput. Math. 4, 389-396; 2D normalisation as in Dehnen & Aly 2012, MNRAS 425).
//! Its radial derivative is dW/dr = -5 a q (1 - q/2)^3 / h, so the gradient with respect to particle i is
//! grad_i W_ij = F(r) (r_i - r_j) with F(r) = -5 a (1 - q/2)^3 / h^2, which needs no division by r.

use std::f64::consts::PI;

/// Wendland C2 kernel for smoothing length `h` (support radius 2h).
#[derive(Debug, Clone, Copy)]
pub struct WendlandC2 {
    h: f64,
    inv_h: f64,
    norm: f64,
    grad_norm: f64,
    support2: f64,
}

impl WendlandC2 {
    pub fn new(h: f64) -> Self {
        let norm = 7.0 / (4.0 * PI * h * h);
        Self {
            h,
            inv_h: 1.0 / h,
            norm,
            grad_norm: -5.0 * norm / (h * h),
            support2: 4.0 * h * h,
        }
    }

    /// Smoothing length h.
    pub fn h(&self) -> f64 {
        self.h
    }

    /// Support radius 2h.
    pub fn support(&self) -> f64 {
        2.0 * self.h
    }

    /// Square of the support radius.
    #[inline(always)]
    pub fn support2(&self) -> f64 {
        self.support2
    }

    /// W(r).
    #[inline(always)]
    pub fn w(&self, r: f64) -> f64 {
        let q = r * self.inv_h;
        if q >= 2.0 {
            return 0.0;
        }
        let t = 1.0 - 0.5 * q;
        let t2 = t * t;
        self.norm * t2 * t2 * (2.0 * q + 1.0)
    }

    /// F(r) with grad_i W_ij = F(r) (r_i - r_j); F <= 0.
    #[inline(always)]
    pub fn grad_factor(&self, r: f64) -> f64 {
        let q = r * self.inv_h;
        if q >= 2.0 {
            return 0.0;
        }
        let t = 1.0 - 0.5 * q;
        self.grad_norm * t * t * t
    }

    /// [`WendlandC2::grad_factor`] without a branch, for the batched pair loops that the compiler
    /// vectorises (a select instead of the early return). The same value, except that outside the
    /// support it gives -0 instead of +0 (the same in every sum).
    #[inline(always)]
    pub fn grad_factor_lane(&self, r: f64) -> f64 {
        let q = r * self.inv_h;
        let t = if q < 2.0 { 1.0 - 0.5 * q } else { 0.0 };
        self.grad_norm * t * t * t
    }

    /// W(r) and F(r) together.
    #[inline(always)]
    pub fn w_and_grad(&self, r: f64) -> (f64, f64) {
        let q = r * self.inv_h;
        if q >= 2.0 {
            return (0.0, 0.0);
        }
        let t = 1.0 - 0.5 * q;
        let t3 = t * t * t;
        (self.norm * t3 * t * (2.0 * q + 1.0), self.grad_norm * t3)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_to_one_in_2d() {
        let k = WendlandC2::new(0.013);
        // Integral of W over the disc of radius 2h: int_0^{2h} W(r) 2 pi r dr, midpoint rule.
        let n = 20_000;
        let dr = k.support() / n as f64;
        let s: f64 = (0..n)
            .map(|i| {
                let r = (i as f64 + 0.5) * dr;
                k.w(r) * 2.0 * PI * r * dr
            })
            .sum();
        assert!((s - 1.0).abs() < 1e-6, "integral {s}");
    }

    #[test]
    fn the_lane_gradient_factor_is_the_branching_one() {
        let k = WendlandC2::new(0.013);
        for n in 0..=300 {
            let r = n as f64 * 1e-4;
            assert_eq!(k.grad_factor_lane(r), k.grad_factor(r), "r = {r}");
        }
    }

    #[test]
    fn gradient_matches_finite_difference() {
        let k = WendlandC2::new(1.0);
        for &r in &[0.1, 0.5, 1.0, 1.5, 1.9] {
            let e = 1e-6;
            let dwdr = (k.w(r + e) - k.w(r - e)) / (2.0 * e);
            // grad W = F r_vec, so dW/dr = F r.
            assert!((dwdr - k.grad_factor(r) * r).abs() < 1e-7, "r={r}");
        }
        assert_eq!(k.w(2.0), 0.0);
        assert_eq!(k.grad_factor(2.5), 0.0);
    }
}
