//! Run outputs: the history CSV, particle snapshots for ParaView (binary VTK XML .vtu files, see
//! [`super::vtu`], and a .pvd series) and PNG frames coloured by pressure ([`super::frame`]). All files
//! are written atomically.

use std::fmt::Write as _;
use std::path::Path;

use crate::error::Result;
use crate::files::write_text_atomic;
use crate::sph::sensors::History;

/// The history as CSV, one row per time step.
pub fn history_csv(h: &History) -> String {
    let mut s = String::from(
        "t_s,z_keel_m,v_down_m_s,a_down_m_s2,fz_n_per_m,fy_n_per_m,fy_starboard_n_per_m,p_contour_max_pa,s_at_p_max_m",
    );
    for n in &h.sensor_names {
        let _ = write!(s, ",{n}_pa");
    }
    s.push('\n');
    for k in 0..h.len() {
        let _ = write!(
            s,
            "{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.9e},{:.6e}",
            h.t[k],
            h.z_keel[k],
            h.v_down[k],
            h.a_down[k],
            h.fz[k],
            h.fy[k],
            h.fy_starboard[k],
            h.p_contour_max[k],
            h.s_at_p_max[k]
        );
        for c in &h.sensors {
            let _ = write!(s, ",{:.9e}", c[k]);
        }
        s.push('\n');
    }
    s
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
