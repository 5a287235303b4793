//! Run outputs: the history CSV, particle snapshots for ParaView (VTK XML .vtu files and a .pvd series)
//! and PNG frames coloured by pressure. All files are written atomically.

use std::fmt::Write as _;
use std::path::Path;

use crate::error::{Error, Result};
use crate::files::{write_atomic, write_text_atomic};
use crate::provenance::Provenance;
use crate::sph::particles::{Kind, Particles};
use crate::sph::sensors::History;

/// The history as CSV, one row per time step, headed by the provenance (when given) as `#` lines. Written
/// through `csv::Writer`, so sensor names (which come from users) are quoted where needed.
pub fn history_csv(h: &History, prov: Option<&Provenance>) -> Result<String> {
    let mut header: Vec<String> = [
        "time_s",
        "keel_z_m",
        "downward_velocity_m_per_s",
        "downward_acceleration_m_per_s2",
        "vertical_force_n_per_m",
        "horizontal_force_n_per_m",
        "horizontal_force_starboard_n_per_m",
        "max_contour_pressure_pa",
        "girth_at_max_pressure_m",
    ]
    .iter()
    .map(|c| c.to_string())
    .collect();
    header.extend(h.sensor_names.iter().map(|n| format!("{n}_pa")));
    let mut rows = Vec::with_capacity(h.len());
    for k in 0..h.len() {
        let mut r: Vec<String> = [
            h.t[k],
            h.z_keel[k],
            h.v_down[k],
            h.a_down[k],
            h.fz[k],
            h.fy[k],
            h.fy_starboard[k],
            h.p_contour_max[k],
        ]
        .iter()
        .map(|v| format!("{v:.9e}"))
        .collect();
        r.push(format!("{:.6e}", h.s_at_p_max[k]));
        r.extend(h.sensors.iter().map(|c| format!("{:.9e}", c[k])));
        rows.push(r);
    }
    csv_text(prov, &header, &rows)
}

/// CSV text through `csv::Writer`: the provenance as `#` lines, then the header and the rows.
pub fn csv_text(
    prov: Option<&Provenance>,
    header: &[String],
    rows: &[Vec<String>],
) -> Result<String> {
    let err = |e: &dyn std::fmt::Display| Error::Invalid(format!("CSV: {e}"));
    let mut w = csv::Writer::from_writer(Vec::new());
    w.write_record(header).map_err(|e| err(&e))?;
    for r in rows {
        w.write_record(r).map_err(|e| err(&e))?;
    }
    let body = w.into_inner().map_err(|e| err(&e))?;
    let head = prov.map_or(String::new(), Provenance::csv_header);
    Ok(head + &String::from_utf8_lossy(&body))
}

/// Write one snapshot as a VTK XML unstructured grid of vertices (fluid and body particles; tank walls
/// left out), with pressure, density, velocity and kind as point data.
pub fn write_vtu(path: &Path, pt: &Particles) -> Result<()> {
    let idx: Vec<usize> = (0..pt.len())
        .filter(|&i| pt.kind[i] != Kind::Wall)
        .collect();
    let n = idx.len();
    let mut s = String::with_capacity(n * 120 + 1024);
    s.push_str("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n");
    let _ = writeln!(
        s,
        "<UnstructuredGrid><Piece NumberOfPoints=\"{n}\" NumberOfCells=\"{n}\">"
    );
    s.push_str("<Points><DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for &i in &idx {
        let _ = writeln!(s, "{:.7e} {:.7e} 0", pt.y[i], pt.z[i]);
    }
    s.push_str("</DataArray></Points>\n<Cells><DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
    for k in 0..n {
        let _ = write!(s, "{k} ");
    }
    s.push_str("\n</DataArray><DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
    for k in 0..n {
        let _ = write!(s, "{} ", k + 1);
    }
    s.push_str("\n</DataArray><DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
    for _ in 0..n {
        s.push_str("1 ");
    }
    s.push_str("\n</DataArray></Cells>\n<PointData Scalars=\"pressure\">\n");
    s.push_str("<DataArray type=\"Float64\" Name=\"pressure\" format=\"ascii\">\n");
    for &i in &idx {
        let _ = writeln!(s, "{:.6e}", pt.p[i]);
    }
    s.push_str("</DataArray>\n<DataArray type=\"Float64\" Name=\"density\" format=\"ascii\">\n");
    for &i in &idx {
        let _ = writeln!(s, "{:.8e}", pt.rho[i]);
    }
    s.push_str("</DataArray>\n<DataArray type=\"Float64\" Name=\"velocity\" NumberOfComponents=\"3\" format=\"ascii\">\n");
    for &i in &idx {
        let _ = writeln!(s, "{:.6e} {:.6e} 0", pt.vy[i], pt.vz[i]);
    }
    s.push_str("</DataArray>\n<DataArray type=\"UInt8\" Name=\"kind\" format=\"ascii\">\n");
    for &i in &idx {
        let _ = write!(s, "{} ", pt.kind[i] as u8);
    }
    s.push_str("\n</DataArray></PointData>\n</Piece></UnstructuredGrid>\n</VTKFile>\n");
    write_text_atomic(path, &s)
}

/// The ParaView collection file for a series of (time, file name) snapshots.
pub fn write_pvd(path: &Path, frames: &[(f64, String)]) -> Result<()> {
    let mut s = String::from(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n",
    );
    for (t, f) in frames {
        let _ = writeln!(s, "<DataSet timestep=\"{t:.9e}\" part=\"0\" file=\"{f}\"/>");
    }
    s.push_str("</Collection>\n</VTKFile>\n");
    write_text_atomic(path, &s)
}

/// Render the particles in the window [y0, y1] x [z0, z1] to a PNG `width` pixels wide: fluid coloured by
/// pressure from 0 (blue) to `p_scale` (red), body particles grey, tank walls dark grey.
#[allow(clippy::too_many_arguments)]
pub fn write_png(
    path: &Path,
    pt: &Particles,
    window: [f64; 4],
    width: usize,
    p_scale: f64,
    mirror: bool,
) -> Result<()> {
    let [y0, y1, z0, z1] = window;
    let height = ((width as f64) * (z1 - z0) / (y1 - y0)).round().max(1.0) as usize;
    let mut img = vec![255u8; width * height * 3];
    let sy = width as f64 / (y1 - y0);
    let dot = 1usize.max((width / 400).min(3));
    let mut plot = |y: f64, z: f64, c: [u8; 3]| {
        let px = ((y - y0) * sy).floor();
        let pz = ((z1 - z) * sy).floor();
        if px < 0.0 || pz < 0.0 {
            return;
        }
        let (px, pz) = (px as usize, pz as usize);
        for a in 0..dot {
            for b in 0..dot {
                let (x, yy) = (px + a, pz + b);
                if x < width && yy < height {
                    let o = (yy * width + x) * 3;
                    img[o..o + 3].copy_from_slice(&c);
                }
            }
        }
    };
    for i in 0..pt.len() {
        let c = match pt.kind[i] {
            Kind::Fluid => colour(pt.p[i] / p_scale),
            Kind::Body => [128, 128, 128],
            Kind::Wall => [64, 64, 64],
        };
        plot(pt.y[i], pt.z[i], c);
        if mirror {
            plot(-pt.y[i], pt.z[i], c);
        }
    }
    write_atomic(path, &encode_png(width, height, &img))
}

/// A blue-cyan-green-yellow-red colour scale over [0, 1] (values outside are clamped for display only).
fn colour(x: f64) -> [u8; 3] {
    let x = if x.is_finite() {
        x.clamp(0.0, 1.0)
    } else {
        1.0
    };
    let stops = [
        [0.0, 0.0, 1.0],
        [0.0, 1.0, 1.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 0.0],
        [1.0, 0.0, 0.0],
    ];
    let f = x * 4.0;
    let k = (f.floor() as usize).min(3);
    let t = f - k as f64;
    let mut c = [0u8; 3];
    for m in 0..3 {
        c[m] = ((stops[k][m] * (1.0 - t) + stops[k + 1][m] * t) * 255.0).round() as u8;
    }
    c
}

/// Encode 8-bit RGB pixels as a PNG (zlib stream of stored deflate blocks; no compression library needed).
pub fn encode_png(width: usize, height: usize, rgb: &[u8]) -> Vec<u8> {
    let mut raw = Vec::with_capacity(height * (width * 3 + 1));
    for row in rgb.chunks(width * 3) {
        raw.push(0u8); // filter type: none
        raw.extend_from_slice(row);
    }
    let mut z = vec![0x78, 0x01];
    let mut chunks = raw.chunks(65_535).peekable();
    if raw.is_empty() {
        z.extend_from_slice(&[1, 0, 0, 0xff, 0xff]);
    }
    while let Some(c) = chunks.next() {
        z.push(if chunks.peek().is_none() { 1 } else { 0 });
        let len = c.len() as u16;
        z.extend_from_slice(&len.to_le_bytes());
        z.extend_from_slice(&(!len).to_le_bytes());
        z.extend_from_slice(c);
    }
    z.extend_from_slice(&adler32(&raw).to_be_bytes());
    let mut out = vec![0x89, b'P', b'N', b'G', 0x0d, 0x0a, 0x1a, 0x0a];
    let mut ihdr = Vec::new();
    ihdr.extend_from_slice(&(width as u32).to_be_bytes());
    ihdr.extend_from_slice(&(height as u32).to_be_bytes());
    ihdr.extend_from_slice(&[8, 2, 0, 0, 0]);
    chunk(&mut out, b"IHDR", &ihdr);
    chunk(&mut out, b"IDAT", &z);
    chunk(&mut out, b"IEND", &[]);
    out
}

fn chunk(out: &mut Vec<u8>, kind: &[u8; 4], data: &[u8]) {
    out.extend_from_slice(&(data.len() as u32).to_be_bytes());
    let start = out.len();
    out.extend_from_slice(kind);
    out.extend_from_slice(data);
    let crc = crc32(&out[start..]);
    out.extend_from_slice(&crc.to_be_bytes());
}

fn crc32(data: &[u8]) -> u32 {
    let mut crc = 0xffff_ffffu32;
    for &b in data {
        crc ^= b as u32;
        for _ in 0..8 {
            crc = if crc & 1 != 0 {
                (crc >> 1) ^ 0xedb8_8320
            } else {
                crc >> 1
            };
        }
    }
    !crc
}

fn adler32(data: &[u8]) -> u32 {
    let (mut a, mut b) = (1u32, 0u32);
    for &x in data {
        a = (a + x as u32) % 65_521;
        b = (b + a) % 65_521;
    }
    (b << 16) | a
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn png_checksums() {
        // CRC-32 and Adler-32 check values of "123456789".
        assert_eq!(crc32(b"123456789"), 0xcbf4_3926);
        assert_eq!(adler32(b"123456789"), 0x091e_01de);
        let png = encode_png(2, 1, &[255, 0, 0, 0, 0, 255]);
        assert_eq!(&png[1..4], b"PNG");
    }
}
