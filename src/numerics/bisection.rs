//! Bisection of an interval on a two-sided test.

/// Bisect [lo, hi] at most `iterations` times: at each midpoint m = (lo + hi) / 2 the interval keeps
/// [m, hi] where `keeps_upper(m)` holds and [lo, m] otherwise. Returns the final (lo, hi).
///
/// The loop stops early once an iteration leaves (lo, hi) unchanged: the midpoint has then reached one
/// of the ends in floating point, and since every later iteration would start from the same interval,
/// none could change it. The result is therefore bit-identical to running all `iterations`.
pub fn bisect(
    mut lo: f64,
    mut hi: f64,
    iterations: usize,
    keeps_upper: impl Fn(f64) -> bool,
) -> (f64, f64) {
    for _ in 0..iterations {
        let mid = 0.5 * (lo + hi);
        let next = if keeps_upper(mid) {
            (mid, hi)
        } else {
            (lo, mid)
        };
        if next == (lo, hi) {
            break;
        }
        (lo, hi) = next;
    }
    (lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The early stop gives the interval of the full count of iterations, bit for bit, on roots at a
    /// grid point, between grid points and at an end.
    #[test]
    fn early_stop_is_the_full_bisection() {
        let full = |lo: f64, hi: f64, n: usize, f: &dyn Fn(f64) -> bool| {
            let (mut lo, mut hi) = (lo, hi);
            for _ in 0..n {
                let mid = 0.5 * (lo + hi);
                if f(mid) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            (lo, hi)
        };
        for root in [0.1, 1.0 / 3.0, 0.5, 0.0, 1.0, 2.0f64.sqrt() - 1.0] {
            let below = |x: f64| x * x < root * root;
            for n in [5, 40, 60, 80, 200] {
                assert_eq!(
                    bisect(0.0, 1.0, n, below),
                    full(0.0, 1.0, n, &below),
                    "{root} {n}"
                );
            }
        }
        let (lo, hi) = bisect(0.0, 1.0, 200, |x| x < 0.3);
        assert!(lo < 0.3 && 0.3 <= hi && hi - lo <= f64::EPSILON);
    }
}
