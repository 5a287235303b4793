//! Cutting a closed triangle mesh with a plane x = const into section contours.
//!
//! Each vertex gets the signed distance d = x − x_cut. A vertex exactly on the plane counts as lying on
//! the positive side (a symbolic perturbation), so every triangle is either uncut or cut along exactly two
//! of its edges, and every cut point is identified by the mesh edge it lies on. In a closed mesh each edge
//! belongs to two triangles, so every cut point is the end of exactly two segments and the segments chain
//! into closed loops without any tolerance on coordinates.

use std::collections::{HashMap, HashSet};

/// A closed triangle mesh with shared vertices (x, y, z in m).
#[derive(Debug, Clone)]
pub struct Mesh {
    pub vertices: Vec<[f64; 3]>,
    pub triangles: Vec<[usize; 3]>,
}

/// A mesh edge as an ordered vertex pair.
type Edge = (usize, usize);

fn edge(a: usize, b: usize) -> Edge {
    if a < b { (a, b) } else { (b, a) }
}

impl Mesh {
    /// The edges that do not belong to exactly two triangles (empty for a closed, manifold mesh), with
    /// the number of triangles that use them.
    pub fn open_edges(&self) -> Vec<(Edge, usize)> {
        let mut count: HashMap<Edge, usize> = HashMap::new();
        for t in &self.triangles {
            for k in 0..3 {
                *count.entry(edge(t[k], t[(k + 1) % 3])).or_default() += 1;
            }
        }
        let mut bad: Vec<(Edge, usize)> = count.into_iter().filter(|&(_, n)| n != 2).collect();
        bad.sort_unstable();
        bad
    }

    /// (min, max) of coordinate `c` over the vertices.
    pub fn range(&self, c: usize) -> (f64, f64) {
        self.vertices
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v[c]), hi.max(v[c]))
            })
    }

    /// The closed loops, as (y, z) polygons, where the plane x = `x_cut` cuts the mesh. The mesh must be
    /// closed (see [`Mesh::open_edges`]); a loop that does not close is reported as an error.
    pub fn slice_x(&self, x_cut: f64) -> Result<Vec<Vec<[f64; 2]>>, String> {
        let d: Vec<f64> = self.vertices.iter().map(|v| v[0] - x_cut).collect();
        let pos = |i: usize| d[i] >= 0.0;
        let point = |(a, b): Edge| {
            let t = d[a] / (d[a] - d[b]);
            let (pa, pb) = (self.vertices[a], self.vertices[b]);
            [pa[1] + t * (pb[1] - pa[1]), pa[2] + t * (pb[2] - pa[2])]
        };
        // Each cut edge -> the (up to two) cut edges it is joined to by a segment.
        let mut links: HashMap<Edge, Vec<Edge>> = HashMap::new();
        for t in &self.triangles {
            let cut: Vec<Edge> = (0..3)
                .map(|k| (t[k], t[(k + 1) % 3]))
                .filter(|&(a, b)| pos(a) != pos(b))
                .map(|(a, b)| edge(a, b))
                .collect();
            if let [e0, e1] = cut[..] {
                links.entry(e0).or_default().push(e1);
                links.entry(e1).or_default().push(e0);
            }
        }
        let mut keys: Vec<Edge> = links.keys().copied().collect();
        keys.sort_unstable();
        let mut seen: HashSet<Edge> = HashSet::new();
        let mut loops = Vec::new();
        for &start in &keys {
            if seen.contains(&start) {
                continue;
            }
            let mut pts = Vec::new();
            let (mut prev, mut cur) = (None, start);
            for _ in 0..=keys.len() {
                seen.insert(cur);
                pts.push(point(cur));
                let l = &links[&cur];
                if l.len() != 2 {
                    let p = pts[pts.len() - 1];
                    return Err(format!(
                        "the cut at x = {x_cut} m does not close (the mesh is open or not manifold near y = {:.4} m, z = {:.4} m)",
                        p[0], p[1]
                    ));
                }
                let next = if Some(l[0]) == prev { l[1] } else { l[0] };
                if next == start || seen.contains(&next) {
                    break;
                }
                prev = Some(cur);
                cur = next;
            }
            pts.dedup_by(|a, b| (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12);
            if pts.len() >= 3 {
                loops.push(pts);
            }
        }
        Ok(loops)
    }
}

/// The half-breadth contour (y ≥ 0 side) of a section from its cut loops: every arc of a loop that runs
/// through y > 0 between two centreline crossings, oriented keel-first, stacked from the lowest up, with
/// the deck (the run at the top going back inboard at less than 45°) dropped. `None` if no loop reaches y > 0.
pub fn half_contour(loops: &[Vec<[f64; 2]>], tol: f64) -> Option<Vec<[f64; 2]>> {
    let mut arcs: Vec<Vec<[f64; 2]>> = Vec::new();
    for lp in loops {
        // Walk the loop with points snapped to y = 0 within `tol`, inserting centreline crossings.
        let n = lp.len();
        let snap = |p: [f64; 2]| if p[0].abs() <= tol { [0.0, p[1]] } else { p };
        let mut ring: Vec<[f64; 2]> = Vec::with_capacity(n + 4);
        for k in 0..n {
            let (a, b) = (snap(lp[k]), snap(lp[(k + 1) % n]));
            ring.push(a);
            if a[0] * b[0] < 0.0 {
                let t = a[0] / (a[0] - b[0]);
                ring.push([0.0, a[1] + t * (b[1] - a[1])]);
            }
        }
        // Start the walk at a centreline point, then collect the runs of y > 0 with their end points.
        let Some(s) = ring.iter().position(|p| p[0] == 0.0) else {
            continue;
        };
        ring.rotate_left(s);
        ring.push(ring[0]);
        let mut cur: Vec<[f64; 2]> = Vec::new();
        for w in ring.windows(2) {
            let (a, b) = (w[0], w[1]);
            if b[0] > 0.0 {
                if cur.is_empty() {
                    cur.push(a);
                }
                cur.push(b);
            } else if !cur.is_empty() {
                cur.push(b);
                arcs.push(std::mem::take(&mut cur));
            }
        }
    }
    if arcs.is_empty() {
        return None;
    }
    for a in arcs.iter_mut() {
        if a[a.len() - 1][1] < a[0][1] {
            a.reverse();
        }
    }
    arcs.sort_by(|a, b| a[0][1].total_cmp(&b[0][1]));
    let mut out: Vec<[f64; 2]> = arcs.concat();
    out.dedup_by(|a, b| (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12);
    // Drop the deck: the run at the top that goes back inboard at less than 45° to the horizontal (flat
    // or cambered; a tumblehome side is steeper and stays).
    while out.len() > 2 {
        let (p, q) = (out[out.len() - 2], out[out.len() - 1]);
        let (dy, dz) = (q[0] - p[0], q[1] - p[1]);
        if dy < 0.0 && dz.abs() <= -dy {
            out.pop();
        } else {
            break;
        }
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A closed box [0, 1] × [−1, 1] × [0, 2], two triangles per face.
    fn box_mesh() -> Mesh {
        let mut vertices = Vec::new();
        for &x in &[0.0, 1.0] {
            for &y in &[-1.0, 1.0] {
                for &z in &[0.0, 2.0] {
                    vertices.push([x, y, z]);
                }
            }
        }
        let id = |x: usize, y: usize, z: usize| x * 4 + y * 2 + z;
        let quads = [
            [id(0, 0, 0), id(0, 1, 0), id(0, 1, 1), id(0, 0, 1)],
            [id(1, 0, 0), id(1, 0, 1), id(1, 1, 1), id(1, 1, 0)],
            [id(0, 0, 0), id(0, 0, 1), id(1, 0, 1), id(1, 0, 0)],
            [id(0, 1, 0), id(1, 1, 0), id(1, 1, 1), id(0, 1, 1)],
            [id(0, 0, 0), id(1, 0, 0), id(1, 1, 0), id(0, 1, 0)],
            [id(0, 0, 1), id(0, 1, 1), id(1, 1, 1), id(1, 0, 1)],
        ];
        let triangles = quads
            .iter()
            .flat_map(|q| [[q[0], q[1], q[2]], [q[0], q[2], q[3]]])
            .collect();
        Mesh {
            vertices,
            triangles,
        }
    }

    #[test]
    fn a_box_cuts_into_its_rectangle() {
        let m = box_mesh();
        assert!(m.open_edges().is_empty());
        let loops = m.slice_x(0.5).unwrap();
        assert_eq!(loops.len(), 1);
        let half = half_contour(&loops, 1e-9).unwrap();
        // keel on the centreline, out along the bottom, up the side; the deck run inboard is dropped
        assert_eq!(half.first().copied(), Some([0.0, 0.0]));
        assert_eq!(half.last().copied(), Some([1.0, 2.0]));
        assert!(half.iter().all(|p| p[0] >= 0.0));
        assert!(m.slice_x(3.0).unwrap().is_empty());
    }

    #[test]
    fn a_cambered_deck_is_dropped_and_tumblehome_kept() {
        // Half of a section with tumblehome above z = 1 and a cambered deck, as one closed loop.
        let half = [
            [0.0, 0.0],
            [1.0, 0.2],
            [1.2, 1.0],
            [1.1, 2.0],
            [0.5, 2.1],
            [0.0, 2.15],
        ];
        let mut lp: Vec<[f64; 2]> = half.to_vec();
        lp.extend(half[1..half.len() - 1].iter().rev().map(|p| [-p[0], p[1]]));
        let c = half_contour(&[lp], 1e-9).unwrap();
        assert_eq!(c, half[..4].to_vec());
    }

    #[test]
    fn an_open_mesh_is_found() {
        let mut m = box_mesh();
        m.triangles.pop();
        assert!(!m.open_edges().is_empty());
    }
}
