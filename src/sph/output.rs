//! Run outputs: the history CSV, particle snapshots for ParaView (binary VTK XML .vtu files, see
//! [`super::vtu`], and a .pvd series) and PNG frames coloured by pressure ([`super::frame`]). All files
//! are written atomically.

use std::fmt::Write as _;
use std::path::Path;

use crate::error::{Error, Result};
use crate::files::write_text_atomic;
use crate::provenance::Provenance;
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

pub use super::frame::{Frame, write_png};
pub use super::vtu::write_vtu;

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
