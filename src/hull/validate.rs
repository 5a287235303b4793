//! Geometric checks on a section contour. Each check returns the index of the offending point and the
//! reason, so the caller can point at the right place in whichever file the offsets came from.

/// Why a section contour is rejected: the offending point, which of its coordinates is at fault (0 = y,
/// 1 = z; `None` for the point as a whole) and the reason.
#[derive(Debug, Clone, PartialEq)]
pub(crate) struct SectionFault {
    pub point: usize,
    pub coord: Option<usize>,
    pub message: String,
}

fn fault(point: usize, coord: Option<usize>, message: String) -> SectionFault {
    SectionFault {
        point,
        coord,
        message,
    }
}

/// Largest offset coordinate accepted, m: the longest Lpp accepted (no ship is wider or deeper than
/// long), so that offsets typed in millimetres are caught.
const COORD_MAX: f64 = super::load::LPP_MAX;

/// Tolerance for "on the centreline" and for coincident points, m.
const TOL: f64 = 1e-9;

/// Check a half-breadth contour: at least two points, finite, y ≥ 0, starts on the centreline, z
/// non-decreasing from keel to deck, no repeated points, no self-intersection.
///
/// Because z never falls along the contour, two segments can only meet at a common height: segment i
/// reaches up to z_{i+1}, a later segment j ≥ i + 2 starts at z_j ≥ z_{i+1}. So only segments on one
/// horizontal level need comparing, and there the test is a one-dimensional overlap of y intervals, which is
/// exact (no orientation round-off that would flag points lying along one straight line as crossing).
pub(crate) fn check_section(points: &[[f64; 2]]) -> Result<(), SectionFault> {
    if points.len() < 2 {
        return Err(fault(
            0,
            None,
            format!(
                "a section needs at least two (y, z) points from keel to deck, got {}",
                points.len()
            ),
        ));
    }
    for (i, p) in points.iter().enumerate() {
        for (c, name) in [(0, "y"), (1, "z")] {
            if !p[c].is_finite() {
                return Err(fault(
                    i,
                    Some(c),
                    format!("point {}: {name} = {} is not a finite number", i + 1, p[c]),
                ));
            }
        }
        for (c, name) in [(0, "y"), (1, "z")] {
            if p[c].abs() > COORD_MAX {
                return Err(fault(
                    i,
                    Some(c),
                    format!(
                        "point {}: {name} = {} m is larger than any ship (at most {COORD_MAX} m); offsets are in \
                         metres",
                        i + 1,
                        crate::input::num(p[c])
                    ),
                ));
            }
        }
        if p[0] < 0.0 {
            return Err(fault(
                i,
                Some(0),
                format!(
                    "point {} has a negative half-breadth y = {} (offsets are half-breadths, y ≥ 0)",
                    i + 1,
                    p[0]
                ),
            ));
        }
    }
    if points[0][0] > TOL {
        return Err(fault(
            0,
            Some(0),
            format!(
                "the first point must be the keel on the centreline (y = 0), got y = {}",
                points[0][0]
            ),
        ));
    }
    for i in 1..points.len() {
        let (a, b) = (points[i - 1], points[i]);
        if b[1] < a[1] {
            return Err(fault(
                i,
                Some(1),
                format!(
                    "section is not monotone: z falls from {} to {} at point {} (points go from keel up to deck)",
                    a[1],
                    b[1],
                    i + 1
                ),
            ));
        }
        if (b[0] - a[0]).abs() <= TOL && (b[1] - a[1]).abs() <= TOL {
            return Err(fault(
                i,
                None,
                format!("point {} repeats the point before it", i + 1),
            ));
        }
    }
    let n = points.len();
    let flat = |k: usize| (points[k + 1][1] - points[k][1]).abs() <= TOL;
    // y interval of segment k on the horizontal level it shares with a neighbour above/below it.
    let top = |k: usize| {
        if flat(k) {
            span(points[k][0], points[k + 1][0])
        } else {
            (points[k + 1][0], points[k + 1][0])
        }
    };
    let bottom = |k: usize| {
        if flat(k) {
            span(points[k][0], points[k + 1][0])
        } else {
            (points[k][0], points[k][0])
        }
    };
    for i in 0..n - 1 {
        // Adjacent segments fold back only along a horizontal run (anywhere else z would have to fall).
        if i + 2 < n && flat(i) && flat(i + 1) {
            let (d0, d1) = (
                points[i + 1][0] - points[i][0],
                points[i + 2][0] - points[i + 1][0],
            );
            if d0 * d1 < 0.0 {
                return Err(fault(
                    i + 2,
                    Some(0),
                    format!(
                        "section folds back on itself at point {} (the contour reverses along a line)",
                        i + 3
                    ),
                ));
            }
        }
        let level = points[i + 1][1];
        for (j, q) in points.iter().enumerate().take(n - 1).skip(i + 2) {
            if q[1] > level + TOL {
                break;
            }
            let (a, b) = (top(i), bottom(j));
            if a.0 <= b.1 + TOL && b.0 <= a.1 + TOL {
                return Err(fault(
                    j + 1,
                    Some(0),
                    format!(
                        "section is self-intersecting: segment {}-{} touches segment {}-{} at z = {}",
                        i + 1,
                        i + 2,
                        j + 1,
                        j + 2,
                        level
                    ),
                ));
            }
        }
    }
    Ok(())
}

fn span(a: f64, b: f64) -> (f64, f64) {
    (a.min(b), a.max(b))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn accepts_flat_bottom_flare_and_bulb() {
        let flat = [[0.0, 0.0], [0.3, 0.0], [0.4, 0.05], [0.4, 0.5]];
        assert!(check_section(&flat).is_ok());
        let bulb = [
            [0.0, 0.0],
            [0.1, 0.02],
            [0.12, 0.06],
            [0.05, 0.12],
            [0.2, 0.3],
            [0.4, 0.5],
        ];
        assert!(check_section(&bulb).is_ok());
        let stem = [[0.0, 0.1], [0.0, 0.5]];
        assert!(check_section(&stem).is_ok());
    }

    #[test]
    fn rejects_bad_sections() {
        assert_eq!(check_section(&[[0.0, 0.0]]).unwrap_err().point, 0);
        assert_eq!(
            check_section(&[[0.1, 0.0], [0.2, 1.0]]).unwrap_err().point,
            0
        );
        assert_eq!(
            check_section(&[[0.0, 0.0], [0.2, 1.0], [0.3, 0.9]])
                .unwrap_err()
                .point,
            2
        );
        assert_eq!(
            check_section(&[[0.0, 0.0], [-0.1, 1.0]]).unwrap_err().point,
            1
        );
        assert_eq!(
            check_section(&[[0.0, 0.0], [0.4, 0.0], [0.2, 0.0]])
                .unwrap_err()
                .point,
            2
        );
        // A loop at constant height would need z to fall; a crossing with non-decreasing z:
        let crossing = [[0.0, 0.0], [0.4, 0.1], [0.0, 0.1], [0.2, 0.1], [0.2, 0.3]];
        assert!(check_section(&crossing).is_err());
    }
}
