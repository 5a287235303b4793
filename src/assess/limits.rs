//! The design gate of an assessment: every sensor design pressure above a limit is one violation, one
//! line each, `LIMIT EXCEEDED: station F sensor NAME p kPa > limit kPa (...)`.

use super::results::Assessment;

/// The violations of a pressure limit (Pa) by the design pressures of `a`.
pub fn violations(a: &Assessment, max_pressure_pa: f64) -> Vec<String> {
    let mut out = Vec::new();
    for st in &a.stations {
        for d in &st.design_pressure_pa {
            if d.value > max_pressure_pa {
                out.push(format!(
                    "LIMIT EXCEEDED: station {} sensor {} {:.2} kPa > {:.2} kPa ({}, {} m/s, {})",
                    st.station,
                    d.name,
                    d.value / 1e3,
                    max_pressure_pa / 1e3,
                    d.source,
                    d.speed_m_per_s,
                    d.wave
                ));
            }
        }
    }
    out
}
