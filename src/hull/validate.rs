//! Geometric checks on a section contour. Each check returns the index of the offending point and the
//! reason, so the caller can point at the right place in whichever file the offsets came from.

/// Why a section contour is rejected: (index of the offending point, reason).
pub(crate) type SectionFault = (usize, String);

/// Tolerance for "on the centreline" and for coincident points, m.
const TOL: f64 = 1e-9;

/// Check a half-breadth contour: at least two points, finite, y ≥ 0, starts on the centreline, z
/// non-decreasing from keel to deck, no repeated points, no self-intersection.
pub(crate) fn check_section(points: &[[f64; 2]]) -> Result<(), SectionFault> {
    if points.len() < 2 {
        return Err((
            0,
            format!(
                "a section needs at least two (y, z) points from keel to deck, got {}",
                points.len()
            ),
        ));
    }
    for (i, p) in points.iter().enumerate() {
        if !p[0].is_finite() || !p[1].is_finite() {
            return Err((i, format!("point {} is not a finite number pair", i + 1)));
        }
        if p[0] < 0.0 {
            return Err((
                i,
                format!(
                    "point {} has a negative half-breadth y = {} (offsets are half-breadths, y ≥ 0)",
                    i + 1,
                    p[0]
                ),
            ));
        }
    }
    if points[0][0] > TOL {
        return Err((
            0,
            format!(
                "the first point must be the keel on the centreline (y = 0), got y = {}",
                points[0][0]
            ),
        ));
    }
    for i in 1..points.len() {
        let (a, b) = (points[i - 1], points[i]);
        if b[1] < a[1] {
            return Err((
                i,
                format!(
                    "section is not monotone: z falls from {} to {} at point {} (points go from keel up to deck)",
                    a[1],
                    b[1],
                    i + 1
                ),
            ));
        }
        if (b[0] - a[0]).abs() <= TOL && (b[1] - a[1]).abs() <= TOL {
            return Err((i, format!("point {} repeats the point before it", i + 1)));
        }
    }
    // Self-intersection: any two non-adjacent segments that touch, or adjacent ones that fold back.
    let n = points.len();
    for i in 0..n - 1 {
        for j in i + 1..n - 1 {
            let (p1, p2, q1, q2) = (points[i], points[i + 1], points[j], points[j + 1]);
            if j == i + 1 {
                if folds_back(p1, p2, q2) {
                    return Err((
                        j + 1,
                        format!(
                            "section folds back on itself at point {} (the contour reverses along a line)",
                            j + 2
                        ),
                    ));
                }
            } else if segments_touch(p1, p2, q1, q2) {
                return Err((
                    j + 1,
                    format!(
                        "section is self-intersecting: segment {}-{} touches segment {}-{}",
                        i + 1,
                        i + 2,
                        j + 1,
                        j + 2
                    ),
                ));
            }
        }
    }
    Ok(())
}

fn orient(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> f64 {
    (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
}

fn on_segment(a: [f64; 2], b: [f64; 2], p: [f64; 2]) -> bool {
    p[0] >= a[0].min(b[0]) - TOL
        && p[0] <= a[0].max(b[0]) + TOL
        && p[1] >= a[1].min(b[1]) - TOL
        && p[1] <= a[1].max(b[1]) + TOL
}

/// Adjacent segments a→b, b→c fold back if they are collinear and c lies back towards a.
fn folds_back(a: [f64; 2], b: [f64; 2], c: [f64; 2]) -> bool {
    let scale = ((b[0] - a[0]).hypot(b[1] - a[1])) * ((c[0] - b[0]).hypot(c[1] - b[1]));
    let collinear = orient(a, b, c).abs() <= 1e-12 * scale.max(1e-30);
    let backwards = (b[0] - a[0]) * (c[0] - b[0]) + (b[1] - a[1]) * (c[1] - b[1]) < 0.0;
    collinear && backwards
}

/// Do closed segments p1p2 and q1q2 share any point?
fn segments_touch(p1: [f64; 2], p2: [f64; 2], q1: [f64; 2], q2: [f64; 2]) -> bool {
    let d1 = orient(q1, q2, p1);
    let d2 = orient(q1, q2, p2);
    let d3 = orient(p1, p2, q1);
    let d4 = orient(p1, p2, q2);
    if ((d1 > 0.0 && d2 < 0.0) || (d1 < 0.0 && d2 > 0.0))
        && ((d3 > 0.0 && d4 < 0.0) || (d3 < 0.0 && d4 > 0.0))
    {
        return true;
    }
    (d1 == 0.0 && on_segment(q1, q2, p1))
        || (d2 == 0.0 && on_segment(q1, q2, p2))
        || (d3 == 0.0 && on_segment(p1, p2, q1))
        || (d4 == 0.0 && on_segment(p1, p2, q2))
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
        assert_eq!(check_section(&[[0.0, 0.0]]).unwrap_err().0, 0);
        assert_eq!(check_section(&[[0.1, 0.0], [0.2, 1.0]]).unwrap_err().0, 0);
        assert_eq!(
            check_section(&[[0.0, 0.0], [0.2, 1.0], [0.3, 0.9]])
                .unwrap_err()
                .0,
            2
        );
        assert_eq!(check_section(&[[0.0, 0.0], [-0.1, 1.0]]).unwrap_err().0, 1);
        assert_eq!(
            check_section(&[[0.0, 0.0], [0.4, 0.0], [0.2, 0.0]])
                .unwrap_err()
                .0,
            2
        );
        // A loop at constant height would need z to fall; a crossing with non-decreasing z:
        let crossing = [[0.0, 0.0], [0.4, 0.1], [0.0, 0.1], [0.2, 0.1], [0.2, 0.3]];
        assert!(check_section(&crossing).is_err());
    }
}
