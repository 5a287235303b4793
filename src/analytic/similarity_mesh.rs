//! Meshes of the similarity problem ([`crate::analytic::similarity`]): graded node positions along a
//! curve, the re-meshing of the free surface by arc length, and the first guess of its shape.

use crate::numerics::pchip::Pchip;

/// Positions 0 = s_0 < ... < s_n = `total` with spacing close to h(s) = `h0` + `g_lo` (`centre` - s)
/// below the centre and `h0` + `g_hi` (s - `centre`) above it: s_k = I^-1(k I(total) / n) with
/// I(s) = integral_0^s ds / h, n = ceil(I(total)).
pub fn graded(total: f64, centre: f64, h0: f64, g_lo: f64, g_hi: f64) -> Vec<f64> {
    let m = 8000;
    let h = |s: f64| {
        if s < centre {
            h0 + g_lo * (centre - s)
        } else {
            h0 + g_hi * (s - centre)
        }
    };
    let mut s_tab = Vec::with_capacity(m + 1);
    let mut i_tab = Vec::with_capacity(m + 1);
    let mut acc = 0.0;
    for k in 0..=m {
        let s = total * k as f64 / m as f64;
        if k > 0 {
            let sp = s_tab[k - 1];
            acc += (s - sp) / h(0.5 * (s + sp));
        }
        s_tab.push(s);
        i_tab.push(acc);
    }
    let n = (acc.ceil() as usize).max(2);
    let mut out = Vec::with_capacity(n + 1);
    let mut j = 0;
    for k in 0..=n {
        let target = acc * k as f64 / n as f64;
        while j + 1 < m && i_tab[j + 1] < target {
            j += 1;
        }
        let f = ((target - i_tab[j]) / (i_tab[j + 1] - i_tab[j])).clamp(0.0, 1.0);
        out.push(s_tab[j] + f * (s_tab[j + 1] - s_tab[j]));
    }
    out[0] = 0.0;
    out[n] = total;
    out
}

/// Cumulative arc length of a polyline.
pub fn arc_length(p: &[[f64; 2]]) -> Vec<f64> {
    let mut s = vec![0.0];
    for w in p.windows(2) {
        let l = (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]);
        s.push(s.last().copied().unwrap_or(0.0) + l);
    }
    s
}

/// Index of the node of smallest abscissa (the turning point of the free surface between the jet and
/// the outer surface: the spray root).
pub fn root_node(p: &[[f64; 2]]) -> usize {
    let mut best = (0, f64::MAX);
    for (k, q) in p.iter().enumerate() {
        if q[0] < best.1 {
            best = (k, q[0]);
        }
    }
    best.0
}

/// The polyline `p` re-sampled at the arc lengths `at` (monotone cubic in arc length per coordinate).
pub fn resample(p: &[[f64; 2]], at: &[f64]) -> Vec<[f64; 2]> {
    // Coincident nodes dropped first.
    let mut q: Vec<[f64; 2]> = Vec::with_capacity(p.len());
    for &v in p {
        if q.last()
            .is_none_or(|l: &[f64; 2]| (v[0] - l[0]).hypot(v[1] - l[1]) > 1e-12)
        {
            q.push(v);
        }
    }
    let p = &q;
    let s = arc_length(p);
    let x: Vec<f64> = p.iter().map(|q| q[0]).collect();
    let y: Vec<f64> = p.iter().map(|q| q[1]).collect();
    let (fx, fy) = (Pchip::new(&s, &x), Pchip::new(&s, &y));
    at.iter().map(|&t| [fx.eval(t), fy.eval(t)]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn graded_spacing_is_finest_at_the_centre() {
        let s = graded(10.0, 3.0, 0.01, 0.1, 0.1);
        assert_eq!(s[0], 0.0);
        assert_eq!(*s.last().unwrap(), 10.0);
        let (k, dmin) = s
            .windows(2)
            .enumerate()
            .map(|(k, w)| (k, w[1] - w[0]))
            .fold((0, f64::MAX), |b, v| if v.1 < b.1 { v } else { b });
        assert!((s[k] - 3.0).abs() < 0.05, "{}", s[k]);
        assert!(dmin > 0.005 && dmin < 0.02, "{dmin}");
    }
}
