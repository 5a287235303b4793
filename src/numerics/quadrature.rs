//! Quadrature helpers.

/// Composite trapezoidal rule over samples (x_k, f_k), x increasing.
pub fn trapezoid(x: &[f64], f: &[f64]) -> f64 {
    x.windows(2)
        .zip(f.windows(2))
        .map(|(xw, fw)| 0.5 * (xw[1] - xw[0]) * (fw[0] + fw[1]))
        .sum()
}

/// Gauss-Legendre nodes and weights on [-1, 1] (Golub-Welsch free closed forms for small n are error-prone,
/// so the nodes are found by Newton iteration on P_n; exact to round-off for n ≤ 64).
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut x = vec![0.0; n];
    let mut w = vec![0.0; n];
    for i in 0..n.div_ceil(2) {
        let mut z = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 0.0;
        for _ in 0..100 {
            let (mut p0, mut p1) = (1.0, z);
            for k in 2..=n {
                let p2 = ((2 * k - 1) as f64 * z * p1 - (k - 1) as f64 * p0) / k as f64;
                p0 = p1;
                p1 = p2;
            }
            let pn = if n == 0 { 1.0 } else { p1 };
            let pnm1 = if n == 1 { 1.0 } else { p0 };
            dp = n as f64 * (z * pn - pnm1) / (z * z - 1.0);
            let dz = pn / dp;
            z -= dz;
            if dz.abs() < 1e-15 {
                break;
            }
        }
        x[i] = -z;
        x[n - 1 - i] = z;
        w[i] = 2.0 / ((1.0 - z * z) * dp * dp);
        w[n - 1 - i] = w[i];
    }
    (x, w)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn gauss_legendre_integrates_polynomials_exactly() {
        let (x, w) = gauss_legendre(5);
        let s: f64 = x.iter().zip(&w).map(|(x, w)| w * x.powi(8)).sum();
        assert!((s - 2.0 / 9.0).abs() < 1e-13);
        assert!((w.iter().sum::<f64>() - 2.0).abs() < 1e-13);
    }

    #[test]
    fn trapezoid_is_exact_for_lines() {
        assert!((trapezoid(&[0.0, 1.0, 3.0], &[1.0, 2.0, 4.0]) - 7.5).abs() < 1e-14);
    }
}
