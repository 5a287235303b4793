//! Particle snapshots as VTK XML unstructured grids (`.vtu`) in binary: every array is written raw into
//! one appended-data block (`<AppendedData encoding="raw">`), each preceded by its length in bytes as a
//! little-endian UInt64 (`header_type="UInt64"`). Coordinates and fields are Float32, which keeps all
//! the digits the pictures need at a quarter of the size of ASCII Float64; the run histories keep full
//! precision in `history.csv`.
//!
//! Layout: points (y, z, 0), one vertex cell per particle (connectivity and offsets Int32, types UInt8),
//! and point data pressure (Pa), density (kg/m³), velocity (m/s, 3 components) and kind (0 fluid, 2 body;
//! tank walls are left out).

use std::fmt::Write as _;
use std::path::Path;

use crate::error::Result;
use crate::files::write_atomic;
use crate::sph::particles::{Kind, Particles};

/// VTK cell type of a single vertex.
const VTK_VERTEX: u8 = 1;

/// One data array for the appended block.
struct Array {
    /// `<DataArray>` attributes other than `format` and `offset`.
    attrs: String,
    bytes: Vec<u8>,
}

fn f32_array(name: &str, components: usize, values: impl Iterator<Item = f64>) -> Array {
    let mut bytes = Vec::new();
    for v in values {
        bytes.extend_from_slice(&(v as f32).to_le_bytes());
    }
    let name = if name.is_empty() {
        String::new()
    } else {
        format!(" Name=\"{name}\"")
    };
    Array {
        attrs: format!("type=\"Float32\"{name} NumberOfComponents=\"{components}\""),
        bytes,
    }
}

fn i32_array(name: &str, values: impl Iterator<Item = i32>) -> Array {
    let bytes = values.flat_map(|v| v.to_le_bytes()).collect();
    Array {
        attrs: format!("type=\"Int32\" Name=\"{name}\""),
        bytes,
    }
}

fn u8_array(name: &str, values: impl Iterator<Item = u8>) -> Array {
    Array {
        attrs: format!("type=\"UInt8\" Name=\"{name}\""),
        bytes: values.collect(),
    }
}

/// The `.vtu` file of the fluid and body particles (cell indices are Int32: at most 2^31 − 1 particles,
/// far beyond any 2D run).
pub fn vtu_bytes(pt: &Particles) -> Vec<u8> {
    let idx: Vec<usize> = (0..pt.len())
        .filter(|&i| pt.kind[i] != Kind::Wall)
        .collect();
    let n = idx.len();
    let points = f32_array("", 3, idx.iter().flat_map(|&i| [pt.y[i], pt.z[i], 0.0]));
    let cells = [
        i32_array("connectivity", 0..n as i32),
        i32_array("offsets", 1..=n as i32),
        u8_array("types", std::iter::repeat_n(VTK_VERTEX, n)),
    ];
    let data = [
        f32_array("pressure", 1, idx.iter().map(|&i| pt.p[i])),
        f32_array("density", 1, idx.iter().map(|&i| pt.rho[i])),
        f32_array(
            "velocity",
            3,
            idx.iter().flat_map(|&i| [pt.vy[i], pt.vz[i], 0.0]),
        ),
        u8_array("kind", idx.iter().map(|&i| pt.kind[i] as u8)),
    ];
    let mut xml = String::from(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\">\n",
    );
    let _ = writeln!(
        xml,
        "<UnstructuredGrid>\n<Piece NumberOfPoints=\"{n}\" NumberOfCells=\"{n}\">"
    );
    let mut offset = 0usize;
    let mut tag = |xml: &mut String, a: &Array| {
        let _ = writeln!(
            xml,
            "<DataArray {} format=\"appended\" offset=\"{offset}\"/>",
            a.attrs
        );
        offset += 8 + a.bytes.len();
    };
    xml.push_str("<Points>\n");
    tag(&mut xml, &points);
    xml.push_str("</Points>\n<Cells>\n");
    for a in &cells {
        tag(&mut xml, a);
    }
    xml.push_str("</Cells>\n<PointData Scalars=\"pressure\" Vectors=\"velocity\">\n");
    for a in &data {
        tag(&mut xml, a);
    }
    xml.push_str("</PointData>\n</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_");
    let mut out = xml.into_bytes();
    for a in std::iter::once(&points).chain(&cells).chain(&data) {
        out.extend_from_slice(&(a.bytes.len() as u64).to_le_bytes());
        out.extend_from_slice(&a.bytes);
    }
    out.extend_from_slice(b"\n</AppendedData>\n</VTKFile>\n");
    out
}

/// Write one snapshot (atomically).
pub fn write_vtu(path: &Path, pt: &Particles) -> Result<()> {
    write_atomic(path, &vtu_bytes(pt))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Parse the XML header, then walk the appended block by the declared offsets and check every
    /// array's byte count against the number of points and components it declares.
    #[test]
    fn header_and_array_sizes_agree() {
        let mut pt = Particles::default();
        pt.push(Kind::Fluid, 0.1, -0.2, 0.0, -1.0, 1000.0, 123.0, 1e-6);
        pt.push(Kind::Wall, 0.5, -0.5, 0.0, 0.0, 1000.0, 0.0, 1e-6);
        pt.push(Kind::Body, 0.0, 0.0, 0.0, -2.0, 1000.0, 456.0, 1e-6);
        pt.push(Kind::Fluid, 0.2, -0.3, 0.5, 0.0, 1001.0, 789.0, 1e-6);
        let bytes = vtu_bytes(&pt);
        let start = bytes.windows(2).position(|w| w == b"\n_").unwrap() + 2;
        let header = std::str::from_utf8(&bytes[..start]).unwrap();
        assert!(header.contains("header_type=\"UInt64\""));
        assert!(header.contains("<AppendedData encoding=\"raw\">"));
        let n = 3; // walls are left out
        assert!(header.contains(&format!("NumberOfPoints=\"{n}\"")));
        let attr = |line: &str, key: &str| -> Option<String> {
            let k = line.find(&format!(" {key}=\""))? + key.len() + 3;
            Some(line[k..k + line[k..].find('"')?].to_string())
        };
        let mut arrays = 0;
        for line in header.lines().filter(|l| l.starts_with("<DataArray")) {
            arrays += 1;
            let off: usize = attr(line, "offset").unwrap().parse().unwrap();
            let comps: usize = attr(line, "NumberOfComponents").map_or(1, |c| c.parse().unwrap());
            let size = match attr(line, "type").unwrap().as_str() {
                "Float32" => 4,
                "Int32" => 4,
                "UInt8" => 1,
                t => panic!("unexpected type {t}"),
            };
            let at = start + off;
            let len = u64::from_le_bytes(bytes[at..at + 8].try_into().unwrap()) as usize;
            assert_eq!(len, n * comps * size, "{line}");
            if attr(line, "Name").as_deref() == Some("pressure") {
                let p: Vec<f32> = bytes[at + 8..at + 8 + len]
                    .chunks(4)
                    .map(|c| f32::from_le_bytes(c.try_into().unwrap()))
                    .collect();
                assert_eq!(p, vec![123.0, 456.0, 789.0]);
            }
        }
        assert_eq!(arrays, 8);
        assert!(bytes.ends_with(b"</AppendedData>\n</VTKFile>\n"));
    }
}
