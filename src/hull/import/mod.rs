//! Hulls from where they live: a lines-plan offsets grid (CSV, see [`grid_csv`]) or a closed triangulated
//! hull surface (STL, ASCII or binary, sliced at stations by [`slice`](mod@slice)), turned into the content of a
//! `hull.toml` ([`HullSpec`]) that the usual reader then checks.
//!
//! What a hull file needs beyond the geometry comes from [`ImportOptions`]: the draft is required; Lpp
//! and the perpendiculars default to the ends of the offsets; KG, k_yy and the water density default to
//! stated assumptions that the description of the written file lists.

pub mod grid_csv;
pub mod slice;

use std::path::Path;

use super::generate::toml_writer::fmt_num;
use super::generate::{HullSpec, LoadingSpec, Position, RadiusOfGyration, StationSpec};
use super::schema::StationColumn;
use super::{Hull, station_x};
use crate::error::{Error, Result};
use crate::input::SourceText;
use slice::Mesh;

/// A station as read from a source file: its position as written, its contour and its line (0 if none).
#[derive(Debug, Clone)]
pub(crate) struct SourceStation {
    pub value: f64,
    pub points: Vec<[f64; 2]>,
    pub line: usize,
}

/// Default number of stations an STL surface is cut into.
pub const DEFAULT_STL_STATIONS: usize = 21;

/// Default pitch radius of gyration, as a fraction of Lpp (the usual 0.25 Lpp).
pub const DEFAULT_K_YY_OVER_LPP: f64 = 0.25;

/// Default water density, kg/m³ (sea water).
pub const DEFAULT_RHO: f64 = 1025.0;

/// What a hull file needs beyond the offsets.
#[derive(Debug, Clone, PartialEq)]
pub struct ImportOptions {
    /// Hull name (default: the source file's name without extension).
    pub name: Option<String>,
    /// Length between perpendiculars, m (default: from the aftmost to the foremost station of a grid, or
    /// the length of an STL surface).
    pub lpp: Option<f64>,
    /// Position of the aft perpendicular in the source's x (default: the aft end of the offsets). Only
    /// for sources given in x.
    pub ap_x: Option<f64>,
    /// Draft above the baseline (the lowest point of the hull), m, level keel. Required.
    pub draft: f64,
    /// Centre of gravity above the baseline, m (default: the draft, an assumption stated in the file).
    pub kg: Option<f64>,
    /// Pitch radius of gyration over Lpp (default [`DEFAULT_K_YY_OVER_LPP`]).
    pub k_yy_over_lpp: Option<f64>,
    /// Water density, kg/m³ (default [`DEFAULT_RHO`]).
    pub rho: Option<f64>,
    /// Number of stations: an STL surface is cut at this many equally spaced stations (default
    /// [`DEFAULT_STL_STATIONS`]); a grid is resampled to it by the hull's section interpolation (default:
    /// the table's own stations).
    pub stations: Option<usize>,
}

/// The kind of source file, from its extension.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SourceKind {
    /// Lines-plan offsets grid, `.csv`.
    GridCsv,
    /// Triangulated surface, `.stl` (ASCII or binary).
    Stl,
}

impl SourceKind {
    /// From the file extension (case-insensitive).
    pub fn of(path: &Path) -> Result<Self> {
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_ascii_lowercase());
        match ext.as_deref() {
            Some("csv") => Ok(Self::GridCsv),
            Some("stl") => Ok(Self::Stl),
            _ => Err(Error::Invalid(format!(
                "{}: cannot tell the format: give an offsets grid as .csv or a hull surface as .stl",
                path.display()
            ))),
        }
    }
}

/// An imported hull: the file content and notes on what was derived or assumed.
#[derive(Debug, Clone)]
pub struct Imported {
    pub spec: HullSpec,
    pub notes: Vec<String>,
}

impl Imported {
    /// The hull file text, headed by a comment that names the importer.
    pub fn to_toml(&self) -> String {
        let text = self.spec.to_toml();
        let body = text
            .split_once('\n')
            .map_or(text.as_str(), |(_, rest)| rest);
        format!(
            "# Imported by `slamtool hull import`; the description says from what and what was assumed.\n{body}"
        )
    }
}

/// Import a hull from an offsets grid (`.csv`) or a closed surface (`.stl`).
pub fn import(path: &Path, opts: &ImportOptions) -> Result<Imported> {
    check_options(opts)?;
    match SourceKind::of(path)? {
        SourceKind::GridCsv => import_grid(path, opts),
        SourceKind::Stl => import_stl(path, opts),
    }
}

fn check_options(o: &ImportOptions) -> Result<()> {
    let bad = |what: &str, v: f64| {
        Err(Error::Invalid(format!(
            "{what} = {v} must be a finite positive number"
        )))
    };
    for (what, v) in [
        ("--draft-m", Some(o.draft)),
        ("--lpp-m", o.lpp),
        ("--kg-m", o.kg),
        ("--k-yy-over-lpp", o.k_yy_over_lpp),
        ("--water-density-kg-m3", o.rho),
    ] {
        if let Some(v) = v
            && !(v.is_finite() && v > 0.0)
        {
            return bad(what, v);
        }
    }
    if let Some(a) = o.ap_x
        && !a.is_finite()
    {
        return Err(Error::Invalid(format!("--ap-x-m = {a} must be finite")));
    }
    if let Some(n) = o.stations
        && !(3..=500).contains(&n)
    {
        return Err(Error::Invalid(format!(
            "--stations {n}: give between 3 and 500 stations"
        )));
    }
    Ok(())
}

/// Lpp and the x shift (source x → x from midship) for stations given in source x over [lo, hi].
fn frame(opts: &ImportOptions, lo: f64, hi: f64, notes: &mut Vec<String>) -> (f64, f64) {
    let lpp = match opts.lpp {
        Some(l) => l,
        None => {
            notes.push(format!(
                "Lpp = {} m, the length of the offsets (not given)",
                fmt_num(hi - lo)
            ));
            hi - lo
        }
    };
    let ap = match opts.ap_x {
        Some(a) => a,
        None => {
            notes.push(format!(
                "aft perpendicular at the aft end of the offsets, x = {lo} m in the source"
            ));
            lo
        }
    };
    (lpp, -(ap + 0.5 * lpp))
}

fn import_grid(path: &Path, opts: &ImportOptions) -> Result<Imported> {
    let src = SourceText::read(path)?;
    let table = grid_csv::parse(&src)?;
    let mut notes = Vec::new();
    let values: Vec<f64> = table.stations.iter().map(|s| s.value).collect();
    let (lo, hi) = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), &v| {
            (a.min(v), b.max(v))
        });
    let (lpp, to_x): (f64, Box<dyn Fn(f64) -> f64>) = match table.column {
        StationColumn::XM => {
            let (lpp, shift) = frame(opts, lo, hi, &mut notes);
            (lpp, Box::new(move |v| v + shift))
        }
        StationColumn::AftOfFp => {
            let lpp = opts.lpp.ok_or_else(|| {
                Error::Invalid(format!(
                    "{}: the stations are fractions of Lpp (aft_of_fp): give --lpp-m",
                    path.display()
                ))
            })?;
            (lpp, Box::new(move |v| station_x(lpp, v)))
        }
    };
    let mut stations: Vec<(f64, Vec<[f64; 2]>, usize)> = table
        .stations
        .iter()
        .map(|s| (to_x(s.value), s.points.clone(), s.line))
        .collect();
    // Stations must run one way; the hull reader sorts aft to forward.
    let stations = super::load::order_stations(std::mem::take(&mut stations), |line, msg| {
        src.error_line(line, 1, msg).into()
    })?;
    let specs = stations
        .into_iter()
        .map(|s| (s.x, s.section.points))
        .collect();
    let kind = "a lines-plan offsets grid (CSV)";
    let mut imported = assemble(path, opts, lpp, specs, kind, notes)?;
    if let Some(n) = opts.stations {
        resample(&mut imported, n)?;
    }
    Ok(imported)
}

/// Most triangles accepted in an STL surface (a detailed hull has some hundred thousand).
pub const MAX_STL_TRIANGLES: usize = 10_000_000;

/// A binary STL (one that does not start with "solid") must be as long as its triangle count says and
/// hold at most [`MAX_STL_TRIANGLES`]; checked before reading, so that a truncated file is reported as
/// such (not as "failed to fill whole buffer") and a damaged count never allocates.
fn check_binary_stl_size(path: &Path, bytes: &[u8]) -> Result<()> {
    if bytes.starts_with(b"solid") {
        return Ok(());
    }
    if bytes.len() < 84 {
        return Err(Error::Invalid(format!(
            "{}: {} bytes is too short for a binary STL file (an 80-byte header and a 4-byte triangle count \
             come first) and it is not ASCII STL (which starts with 'solid'): the file is empty or cut short",
            path.display(),
            bytes.len()
        )));
    }
    let n = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
    if n > MAX_STL_TRIANGLES {
        return Err(Error::Invalid(format!(
            "{}: the binary STL header gives {n} triangles, more than the {MAX_STL_TRIANGLES} accepted",
            path.display()
        )));
    }
    let need = 84 + 50 * n;
    if bytes.len() < need {
        return Err(Error::Invalid(format!(
            "{}: truncated binary STL: its header gives {n} triangles, which take {need} bytes, but the file has \
             only {} ({} whole triangles); the file was cut short (copy or export it again)",
            path.display(),
            bytes.len(),
            (bytes.len() - 84) / 50
        )));
    }
    Ok(())
}

/// Read an STL file (ASCII or binary) into a mesh with shared vertices.
pub fn read_stl(path: &Path) -> Result<Mesh> {
    let mut bytes = std::fs::read(path).map_err(|e| Error::io(path, e))?;
    // Some CAD programs start the 80-byte header of a binary STL with "solid", which makes it look like
    // ASCII. A file whose size is exactly that of a binary STL with the triangle count in bytes 80-83 is
    // binary: blank its header (free text, ignored) so that the reader takes it as such.
    if bytes.len() >= 84 && bytes.starts_with(b"solid") {
        let n = u32::from_le_bytes([bytes[80], bytes[81], bytes[82], bytes[83]]) as usize;
        if bytes.len() == 84 + 50 * n {
            bytes[..80].fill(0);
        }
    }
    check_binary_stl_size(path, &bytes)?;
    let m = stl_io::read_stl(&mut std::io::Cursor::new(bytes)).map_err(|e| {
        Error::Invalid(format!(
            "{}: not a readable STL file (ASCII or binary): {e}",
            path.display()
        ))
    })?;
    let vertices: Vec<[f64; 3]> = m
        .vertices
        .iter()
        .map(|v| [v[0] as f64, v[1] as f64, v[2] as f64])
        .collect();
    if let Some(v) = vertices.iter().find(|v| v.iter().any(|c| !c.is_finite())) {
        return Err(Error::Invalid(format!(
            "{}: a vertex has a coordinate that is not a finite number: {v:?}",
            path.display()
        )));
    }
    let triangles: Vec<[usize; 3]> = m
        .faces
        .iter()
        .map(|f| f.vertices)
        // Faces whose corners coincide (after the reader merges equal vertices) add nothing.
        .filter(|t| t[0] != t[1] && t[1] != t[2] && t[0] != t[2])
        .collect();
    if triangles.is_empty() {
        return Err(Error::Invalid(format!(
            "{}: the STL file has no triangles",
            path.display()
        )));
    }
    Ok(Mesh {
        vertices,
        triangles,
    })
}

/// What keeps `mesh` from being one closed surface that can be cut into sections, or `None`: edges of
/// one triangle (a hole: a missing deck, transom or faces), or edges shared by more than two (faces
/// duplicated or overlapping, or the two sides drawn on the same faces along a stem, keel or skeg of
/// zero thickness). Each with the count and the first such edge.
fn surface_fault(mesh: &Mesh) -> Option<String> {
    let bad = mesh.open_edges();
    let at = |((a, b), _): &((usize, usize), usize)| {
        let (pa, pb) = (mesh.vertices[*a], mesh.vertices[*b]);
        format!(
            "from ({:.4}, {:.4}, {:.4}) to ({:.4}, {:.4}, {:.4}) m",
            pa[0], pa[1], pa[2], pb[0], pb[1], pb[2]
        )
    };
    let edges = |n: usize, one: &str, many: &str| {
        if n == 1 {
            format!("1 edge {one}")
        } else {
            format!("{n} edges {many}")
        }
    };
    let open: Vec<_> = bad.iter().filter(|e| e.1 < 2).collect();
    let shared: Vec<_> = bad.iter().filter(|e| e.1 > 2).collect();
    let mut faults = Vec::new();
    if let Some(first) = open.first() {
        faults.push(format!(
            "the surface is not closed: {} to one triangle only, the first {}; close the hull with a deck \
             (and transom) before importing",
            edges(open.len(), "belongs", "belong"),
            at(first)
        ));
    }
    if let Some(first) = shared.first() {
        faults.push(format!(
            "the surface is not a simple closed surface: {} by more than two triangles, the first ({} \
             triangles) {}; faces are duplicated or overlap, or the two sides of the hull \
             lie on the same faces along an edge of zero thickness (a stem, keel or skeg drawn as a \
             plane): remove the duplicated faces, or give that edge a thickness, before importing",
            edges(shared.len(), "is shared", "are shared"),
            first.1,
            at(first)
        ));
    }
    (!faults.is_empty()).then(|| faults.join("; and "))
}

fn import_stl(path: &Path, opts: &ImportOptions) -> Result<Imported> {
    let mut mesh = read_stl(path)?;
    if let Some(why) = surface_fault(&mesh) {
        return Err(Error::Invalid(format!("{}: {why}", path.display())));
    }
    let mut notes = Vec::new();
    let (x0, x1) = mesh.range(0);
    let (y0, y1) = mesh.range(1);
    let (z0, _) = mesh.range(2);
    if !(x1 > x0 && y1 > 0.0 && y0 < 0.0) {
        return Err(Error::Invalid(format!(
            "{}: the surface must span both sides of the centreline plane y = 0 (y runs from {y0} to {y1} m) and have a length",
            path.display()
        )));
    }
    if z0 != 0.0 {
        notes.push(format!(
            "baseline at the lowest point of the surface, z = {z0} m in the source"
        ));
        for v in mesh.vertices.iter_mut() {
            v[2] -= z0;
        }
    }
    let (lpp, shift) = frame(opts, x0, x1, &mut notes);
    let n = opts.stations.unwrap_or(DEFAULT_STL_STATIONS);
    let len = x1 - x0;
    // The end stations are moved inboard by a millionth of the length, where the plane still cuts the
    // surface rather than touching it at a point or along the stem.
    let nudge = 1e-6 * len;
    // Within this of the centreline counts as on it: a few float32 roundings of the file's coordinates.
    let tol = 1e-7 * len;
    let mut stations = Vec::with_capacity(n);
    for i in 0..n {
        let xs = x0 + len * i as f64 / (n - 1) as f64;
        let cut = xs.clamp(x0 + nudge, x1 - nudge);
        let loops = mesh
            .slice_x(cut)
            .map_err(|m| Error::Invalid(format!("{}: {m}", path.display())))?;
        if loops.is_empty() {
            return Err(Error::Invalid(format!(
                "{}: the plane x = {xs} m (station {}) does not cut the surface",
                path.display(),
                i + 1
            )));
        }
        let half = slice::half_contour(&loops, tol).ok_or_else(|| {
            Error::Invalid(format!(
                "{}: the section at x = {xs} m (station {}) does not cross the centreline y = 0; the mesh must be a whole (both sides) hull about y = 0",
                path.display(),
                i + 1
            ))
        })?;
        stations.push((xs + shift, half));
    }
    let kind = "a closed triangulated surface (STL), cut at equally spaced stations";
    notes.push(format!(
        "{n} stations from x = {x0} m to {x1} m in the source, the end ones cut {nudge:.3e} m inboard"
    ));
    assemble(path, opts, lpp, stations, kind, notes)
}

/// Build the hull file content from stations in x from midship (aft to forward).
fn assemble(
    path: &Path,
    opts: &ImportOptions,
    lpp: f64,
    stations: Vec<(f64, Vec<[f64; 2]>)>,
    kind: &str,
    mut notes: Vec<String>,
) -> Result<Imported> {
    let depth = stations
        .iter()
        .flat_map(|s| s.1.iter().map(|p| p[1]))
        .fold(f64::NEG_INFINITY, f64::max);
    let kg = opts.kg.unwrap_or_else(|| {
        notes.push(format!(
            "KG = {} m, the draft (assumed, not given)",
            opts.draft
        ));
        opts.draft
    });
    let k_yy = opts.k_yy_over_lpp.unwrap_or_else(|| {
        notes.push(format!(
            "k_yy = {DEFAULT_K_YY_OVER_LPP} Lpp (assumed, not given)"
        ));
        DEFAULT_K_YY_OVER_LPP
    });
    let rho = opts.rho.unwrap_or_else(|| {
        notes.push(format!(
            "water density {DEFAULT_RHO} kg/m3 (assumed, not given)"
        ));
        DEFAULT_RHO
    });
    let file = path.file_name().map_or_else(
        || path.display().to_string(),
        |f| f.to_string_lossy().into(),
    );
    let name = match &opts.name {
        Some(n) => n.clone(),
        None => path
            .file_stem()
            .map_or_else(|| "imported hull".into(), |s| s.to_string_lossy().into()),
    };
    let min_gap = MIN_POINT_GAP_LPP * lpp;
    let stations: Vec<(f64, Vec<[f64; 2]>)> = stations
        .into_iter()
        .map(|(x, points)| (x, tidy(points, min_gap)))
        .collect();
    notes.push(format!(
        "points rounded to the micrometre, and points closer than {min_gap:.2e} m ({MIN_POINT_GAP_LPP} Lpp) to \
         the point before them merged into it"
    ));
    let description = format!(
        "Imported by `slamtool hull import` from {file}, {kind}. {}.",
        notes.join("; ")
    );
    let spec = HullSpec {
        name,
        description,
        lpp,
        depth,
        loadings: vec![LoadingSpec {
            name: "design".into(),
            draft_fp: opts.draft,
            draft_ap: opts.draft,
            rho,
            displacement_kg: None,
            kg,
            k_yy: RadiusOfGyration::OverLpp(k_yy),
        }],
        stations: stations
            .into_iter()
            .map(|(x, points)| StationSpec {
                position: Position::X(x),
                points,
            })
            .collect(),
        sensors: vec![],
    };
    Ok(Imported { spec, notes })
}

/// Closest spacing of two points of an imported section, as a fraction of the length between
/// perpendiculars: a cut through a triangulated surface next to a vertex gives points a fraction of a
/// millimetre apart on a ship (0.2 mm on a 120 m hull), which no offset table means.
pub const MIN_POINT_GAP_LPP: f64 = 1e-5;

/// Points rounded to the micrometre the hull file keeps, with points that then repeat dropped (the
/// near-zero breadths a cut close to a stem gives would otherwise become repeated points), and points
/// closer than `min_gap` to the point kept before them merged into it. The keel point and the top
/// point are kept: a top point too close to the one before replaces it.
fn tidy(points: Vec<[f64; 2]>, min_gap: f64) -> Vec<[f64; 2]> {
    let round = |v: f64| (v * 1e6).round() / 1e6 + 0.0;
    let mut out: Vec<[f64; 2]> = Vec::with_capacity(points.len());
    let close = |a: [f64; 2], b: [f64; 2]| (a[0] - b[0]).hypot(a[1] - b[1]) < min_gap;
    let last = points.len().saturating_sub(1);
    for (k, p) in points.iter().enumerate() {
        let p = [round(p[0]), round(p[1])];
        match out.last() {
            Some(&q) if q == p => {}
            Some(&q) if close(q, p) && k == last && out.len() > 1 => {
                out.pop();
                out.push(p);
            }
            Some(&q) if close(q, p) && k < last => {}
            _ => out.push(p),
        }
    }
    out
}

/// Replace the stations by `n` equally spaced ones over the same range, interpolated by the hull reader's
/// shape-preserving section interpolation.
fn resample(imported: &mut Imported, n: usize) -> Result<()> {
    let src = SourceText::from_string("<imported offsets>", imported.spec.to_toml());
    let hull = Hull::from_source(&src)?;
    let (a, f) = hull.x_range();
    let mut stations = Vec::with_capacity(n);
    for i in 0..n {
        let x = a + (f - a) * i as f64 / (n - 1) as f64;
        stations.push(StationSpec {
            position: Position::X(x),
            points: tidy(
                hull.section_at(x)?.points,
                MIN_POINT_GAP_LPP * imported.spec.lpp,
            ),
        });
    }
    imported.spec.stations = stations;
    imported.spec.description = format!(
        "{} Resampled to {n} equally spaced stations by shape-preserving interpolation.",
        imported.spec.description
    );
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::tidy;

    /// A point of a cut a fraction of a millimetre from the one before it (a triangle vertex next to the
    /// cut plane) is merged into it; the keel and the top point stay, and a top point too close to the
    /// one before replaces it.
    #[test]
    fn points_closer_than_the_gap_are_merged_and_the_ends_kept() {
        let gap = 1.2e-3;
        let cut = vec![
            [0.0, 0.0],
            [0.000196, 0.000005],
            [0.5, 0.2],
            [0.5000004, 0.2000003],
            [1.0, 1.0],
            [1.0002, 1.0004],
        ];
        assert_eq!(
            tidy(cut, gap),
            vec![[0.0, 0.0], [0.5, 0.2], [1.0002, 1.0004]]
        );
        let two = vec![[0.0, 0.0], [0.0001, 0.0001]];
        assert_eq!(tidy(two.clone(), gap), two);
    }
}
