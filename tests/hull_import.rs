//! `hull import`: a Wigley hull meshed here (binary and ASCII STL) and tabulated as a lines-plan grid
//! (CSV) is imported and its hydrostatics compared with the closed forms of the Wigley form; bad inputs
//! give located errors.
//!
//! Closed forms (Wigley III, 2y/B = (1 − ζ²)(1 − ξ²)(1 + 0.2ξ²)): ∇ = (2/3)(1 − 0.8/3 − 0.04) L B T,
//! A_wp = (1 − 0.8/3 − 0.04) L B, LCB = LCF = 0 by symmetry, KB = (5/8) T (centroid of 1 − ζ² on
//! ζ ∈ [−1, 0] at ζ = −3/8).
//!
//! Tolerance. The mesh is linear between its vertices: on NZ = 24 intervals in ζ the chord of the
//! parabola 1 − ζ² lies below it by h²/6 on average (h = 1/24), 0.04 % of its mean 2/3; on NX = 60
//! intervals in ξ (h = 1/30) the chord of (1 − ξ²)(1 + 0.2ξ²) loses about h²·|g''|/12 ≈ 1.2e-4 of the
//! mean 0.693, 0.02 %. Cutting at 21 stations and interpolating between them (PCHIP, as for any hull
//! file) adds the interpolation error of the sectional-area curve, of the order of the 0.1 % the bundled
//! 41-station Wigley file shows. The sum, about 0.2 %, is the tolerance used for ∇, A_wp and KB (measured:
//! ∇ −0.05 %, A_wp −0.005 %, KB +0.01 % for the STL; −0.04 %, 0.00 %, +0.01 % for the grid); LCB and LCF
//! must be within 0.1 % of L of zero (measured 3e-5 L).

use std::io::Write;
use std::path::Path;
use std::process::Command;

use slamtool::hull::generate::wigley::{BEAM, DEPTH, DRAFT, LENGTH, half_breadth};
use slamtool::hull::import::{ImportOptions, import};
use slamtool::hull::{Hull, Hydrostatics};
use slamtool::input::SourceText;

const NX: usize = 60;
const NZ: usize = 24;

/// The closed Wigley III surface: both sides from the keel to the waterline, continued vertically to a
/// deck at DEPTH, closed by the deck. Keel and ends have zero breadth, so the two sides share their
/// vertices there and no transom is needed. Returns (vertices, triangles).
fn wigley_mesh() -> (Vec<[f64; 3]>, Vec<[usize; 3]>) {
    let mut vertices: Vec<[f64; 3]> = Vec::new();
    let mut index = std::collections::HashMap::new();
    let mut vid = |i: usize, j: usize, side: i8| -> usize {
        let x = -0.5 * LENGTH + LENGTH * i as f64 / NX as f64;
        let z = if j <= NZ {
            DRAFT * j as f64 / NZ as f64
        } else {
            DEPTH
        };
        let y = half_breadth(x, z.min(DRAFT), 0.0).max(0.0);
        let y = if i == 0 || i == NX || j == 0 { 0.0 } else { y };
        let key = if y == 0.0 { (i, j, 0) } else { (i, j, side) };
        *index.entry(key).or_insert_with(|| {
            vertices.push([x, side as f64 * y, z]);
            vertices.len() - 1
        })
    };
    let mut tris = Vec::new();
    // Triangles with a repeated corner, or lying wholly on the centreline (at the stem and stern post
    // both sides would add the same one), are left out.
    let quad = |q: [usize; 4], tris: &mut Vec<[usize; 3]>, v: &[[f64; 3]]| {
        for t in [[q[0], q[1], q[2]], [q[0], q[2], q[3]]] {
            let distinct = t[0] != t[1] && t[1] != t[2] && t[0] != t[2];
            if distinct && t.iter().any(|&k| v[k][1] != 0.0) {
                tris.push(t);
            }
        }
    };
    let mut quads = Vec::new();
    for side in [-1i8, 1] {
        for i in 0..NX {
            for j in 0..=NZ {
                let q = [
                    vid(i, j, side),
                    vid(i + 1, j, side),
                    vid(i + 1, j + 1, side),
                    vid(i, j + 1, side),
                ];
                quads.push(q);
            }
        }
    }
    let top = NZ + 1;
    for i in 0..NX {
        let q = [
            vid(i, top, -1),
            vid(i + 1, top, -1),
            vid(i + 1, top, 1),
            vid(i, top, 1),
        ];
        quads.push(q);
    }
    for q in quads {
        quad(q, &mut tris, &vertices);
    }
    (vertices, tris)
}

fn write_binary_stl(path: &Path, v: &[[f64; 3]], t: &[[usize; 3]]) {
    let f32v = |p: [f64; 3]| stl_io::Vertex::new([p[0] as f32, p[1] as f32, p[2] as f32]);
    let tris: Vec<stl_io::Triangle> = t
        .iter()
        .map(|t| stl_io::Triangle {
            normal: stl_io::Normal::new([0.0, 0.0, 0.0]),
            vertices: [f32v(v[t[0]]), f32v(v[t[1]]), f32v(v[t[2]])],
        })
        .collect();
    let mut f = std::fs::File::create(path).unwrap();
    stl_io::write_stl(&mut f, tris.iter()).unwrap();
}

fn write_ascii_stl(path: &Path, v: &[[f64; 3]], t: &[[usize; 3]]) {
    let mut s = String::from("solid wigley\n");
    for t in t {
        s.push_str("facet normal 0 0 0\nouter loop\n");
        for &k in t {
            let p = v[k];
            s.push_str(&format!("vertex {:e} {:e} {:e}\n", p[0], p[1], p[2]));
        }
        s.push_str("endloop\nendfacet\n");
    }
    s.push_str("endsolid wigley\n");
    std::fs::write(path, s).unwrap();
}

fn options(stations: Option<usize>) -> ImportOptions {
    ImportOptions {
        name: Some("Wigley III (imported)".into()),
        lpp: None,
        ap_x: None,
        draft: DRAFT,
        kg: Some(0.17),
        k_yy_over_lpp: None,
        rho: Some(1000.0),
        stations,
    }
}

/// Import, write, read back with the usual checks, and compare with the closed forms.
fn check_against_closed_forms(file: &Path, stations: Option<usize>) {
    let imported = import(file, &options(stations)).unwrap();
    let src = SourceText::from_string(file.with_extension("toml"), imported.to_toml());
    let hull = Hull::from_source(&src).unwrap();
    let h = Hydrostatics::compute(&hull, &hull.loadings[0]);
    let long = 1.0 - 0.8 / 3.0 - 0.04;
    let (vol, awp, kb) = (
        2.0 / 3.0 * long * LENGTH * BEAM * DRAFT,
        long * LENGTH * BEAM,
        0.625 * DRAFT,
    );
    let rel = |a: f64, b: f64| (a - b).abs() / b;
    eprintln!(
        "{}: volume {:.6} ({:+.3} %), Awp {:.5} ({:+.3} %), KB {:.5} ({:+.3} %), LCB {:+.5}, LCF {:+.5}, Lpp {}",
        file.display(),
        h.volume,
        100.0 * (h.volume / vol - 1.0),
        h.awp,
        100.0 * (h.awp / awp - 1.0),
        h.kb,
        100.0 * (h.kb / kb - 1.0),
        h.lcb,
        h.lcf,
        hull.lpp
    );
    assert!((hull.lpp - LENGTH).abs() < 1e-6);
    assert!(rel(h.volume, vol) < 2e-3, "volume {} vs {vol}", h.volume);
    assert!(rel(h.awp, awp) < 2e-3, "Awp {} vs {awp}", h.awp);
    assert!(rel(h.kb, kb) < 2e-3, "KB {} vs {kb}", h.kb);
    assert!(h.lcb.abs() < 1e-3 * LENGTH, "LCB {}", h.lcb);
    assert!(h.lcf.abs() < 1e-3 * LENGTH, "LCF {}", h.lcf);
    assert!((hull.depth - DEPTH).abs() < 1e-6);
}

#[test]
fn wigley_stl_binary_and_ascii_match_the_closed_forms() {
    let dir = tempfile::tempdir().unwrap();
    let (v, t) = wigley_mesh();
    let bin = dir.path().join("wigley.stl");
    write_binary_stl(&bin, &v, &t);
    check_against_closed_forms(&bin, Some(21));
    // A binary file whose header starts with "solid", as some CAD programs write them.
    let mut bytes = std::fs::read(&bin).unwrap();
    bytes[..12].copy_from_slice(b"solid wigley");
    let solid = dir.path().join("wigley-solid-header.stl");
    std::fs::write(&solid, bytes).unwrap();
    check_against_closed_forms(&solid, Some(21));
    let ascii = dir.path().join("wigley-ascii.stl");
    write_ascii_stl(&ascii, &v, &t);
    check_against_closed_forms(&ascii, Some(21));
}

#[test]
fn wigley_grid_csv_matches_the_closed_forms() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("wigley-grid.csv");
    let mut f = std::fs::File::create(&path).unwrap();
    // Stations from the AP at x = 0 to the FP at x = L (not from midship: the importer centres them).
    let zs: Vec<f64> = (0..=NZ).map(|j| DRAFT * j as f64 / NZ as f64).collect();
    let mut header = String::from("x_m");
    for z in zs.iter().chain([&DEPTH]) {
        header.push_str(&format!(",{z}"));
    }
    writeln!(f, "# Wigley III lines plan\n{header}").unwrap();
    for i in 0..=40 {
        let x = LENGTH * i as f64 / 40.0;
        let mut row = format!("{x}");
        for z in zs.iter().chain([&DRAFT]) {
            let y = half_breadth(x - 0.5 * LENGTH, *z, 0.0).max(0.0);
            row.push_str(&format!(",{y:.7}"));
        }
        writeln!(f, "{row}").unwrap();
    }
    drop(f);
    check_against_closed_forms(&path, None);
    // Resampled to 21 stations by the shape-preserving interpolation.
    check_against_closed_forms(&path, Some(21));
}

#[test]
fn an_open_surface_and_a_bad_grid_are_reported() {
    let dir = tempfile::tempdir().unwrap();
    let (v, mut t) = wigley_mesh();
    t.truncate(t.len() - 10); // no deck amidships
    let open = dir.path().join("open.stl");
    write_binary_stl(&open, &v, &t);
    let e = import(&open, &options(None)).unwrap_err().to_string();
    assert!(e.contains("not closed"), "{e}");
    assert!(e.contains("close the hull with a deck"), "{e}");

    // A face drawn twice: closed, but not one simple surface, and the remedy is not a deck.
    let (v, mut t) = wigley_mesh();
    t.push(t[0]);
    let twice = dir.path().join("twice.stl");
    write_binary_stl(&twice, &v, &t);
    let e = import(&twice, &options(None)).unwrap_err().to_string();
    assert!(e.contains("shared by more than two triangles"), "{e}");
    assert!(e.contains("(3 triangles)"), "{e}");
    assert!(!e.contains("not closed") && !e.contains("deck"), "{e}");

    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, "x_m,0,0.1,0.2\n0,0.1,0.2,0.3\n1,0.1,x,0.3\n").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(["hull", "import"])
        .arg(&bad)
        .args(["--draft-m", "0.1", "-o"])
        .arg(dir.path().join("h.toml"))
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("bad.csv:3:7:"), "{err}");

    // Fractions of Lpp need Lpp.
    let frac = dir.path().join("frac.csv");
    std::fs::write(&frac, "aft_of_fp,0,0.1\n0,0,0.1\n1,0,0.1\n").unwrap();
    let e = import(&frac, &options(None)).unwrap_err().to_string();
    assert!(e.contains("--lpp-m"), "{e}");

    // A draft above the deck: the usual check, located in the written hull file.
    let (v, t) = wigley_mesh();
    let stl = dir.path().join("w.stl");
    write_binary_stl(&stl, &v, &t);
    let toml = dir.path().join("deep.toml");
    let out = Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(["hull", "import"])
        .arg(&stl)
        .args(["--draft-m", "0.4", "-o"])
        .arg(&toml)
        .output()
        .unwrap();
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    let located = format!("{}:", toml.display());
    assert!(err.contains(&located) && err.contains("deck"), "{err}");
}

#[test]
fn cli_import_writes_a_hull_that_reads_back() {
    let dir = tempfile::tempdir().unwrap();
    let (v, t) = wigley_mesh();
    let stl = dir.path().join("w.stl");
    write_binary_stl(&stl, &v, &t);
    let out = dir.path().join("w.toml");
    let status = Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(["hull", "import"])
        .arg(&stl)
        .args(["--stations", "11", "--draft-m", "0.1875", "-o"])
        .arg(&out)
        .status()
        .unwrap();
    assert!(status.success());
    let hull = Hull::from_file(&out).unwrap();
    assert_eq!(hull.stations.len(), 11);
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.contains("KG = 0.1875 m, the draft (assumed, not given)"));
}
