//! The text tables of `slamtool assess`: events, design pressures, irregular seas and their design events,
//! the bow slamming force, and the comparisons with published results.

use slamtool::assess::Assessment;
use slamtool::report::assessment::data::speed_text;

fn kpa(v: Option<f64>) -> String {
    v.map_or("-".into(), |p| format!("{:.2}", p / 1e3))
}

/// The text tables: events, then the design pressure per station.
pub fn tables(a: &Assessment) -> String {
    let mut s = format!(
        "assessment of {} ({}), fidelity {}\n\nevents (station x speed x wave):\n",
        a.hull, a.loading, a.fidelity
    );
    s += "  station  speed_m_per_s  wave             flag                     v_entry_m_per_s  max_sensor_sph_kpa  max_sensor_analytic_kpa\n";
    for e in &a.events {
        let flag = serde_json::to_value(e.slam_flag)
            .ok()
            .and_then(|v| v.as_str().map(str::to_string))
            .unwrap_or_default();
        let sph = e
            .sph
            .as_ref()
            .map(|r| r.sensors.iter().map(|q| q.raw_peak_pa).fold(0.0, f64::max));
        let an = e
            .analytic
            .as_ref()
            .map(|r| r.sensors.iter().map(|q| q.peak_pa).fold(0.0, f64::max));
        s += &format!(
            "  {:<7}  {:<13.2}  {:<15}  {:<23}  {:<15}  {:<18}  {}{}\n",
            e.station,
            e.speed_m_per_s,
            e.wave,
            flag,
            e.entry_velocity_m_per_s
                .map_or("-".into(), |v| format!("{v:.3}")),
            kpa(sph),
            kpa(an),
            e.failed
                .as_ref()
                .map_or(String::new(), |f| format!("  FAILED: {f}"))
        );
    }
    s += "\ndesign pressure per station and sensor (largest over events):\n";
    for st in &a.stations {
        s += &format!(
            "  station {} (x {:.3} m): {} of {} events emerge, {} slam by Ochi's criterion",
            st.station,
            st.x_m,
            st.emerging_events,
            a.events
                .iter()
                .filter(|e| (e.station - st.station).abs() < 1e-9)
                .count(),
            st.slamming_events
        );
        if let Some(f) = &st.section_force_peak_n_per_m {
            s += &format!(
                "; section force {} N/m ({}, {} m/s)",
                f.value.map_or("none".into(), |v| format!("{v:.1}")),
                f.source,
                speed_text(Some(f.speed_m_per_s))
            );
        }
        s += "\n";
        for d in &st.design_pressure_pa {
            s += &format!(
                "    {:<10} {:>9} kPa  ({}, {} m/s, {})\n",
                d.name,
                d.value.map_or("none".into(), |v| format!("{:.2}", v / 1e3)),
                d.source,
                speed_text(Some(d.speed_m_per_s)),
                d.wave
            );
        }
        let dry: Vec<&str> = st
            .design_pressure_pa
            .iter()
            .filter(|d| d.source == slamtool::assess::results::DRY_SOURCE)
            .map(|d| d.name.as_str())
            .collect();
        if !dry.is_empty() {
            s += &format!(
                "    ({}: the SPH water did not reach the sensor with a slamming pressure; the analytic value, \
                 which assumes attached flow, stands in. See the event's warnings.)\n",
                dry.join(", ")
            );
        }
    }
    if !a.irregular.is_empty() {
        s += &format!(
            "\nirregular seas ({}):\n  speed_m_per_s  sea              station  slam_probability  slams_per_hour  extreme_entry_velocity_m_per_s\n",
            "Ochi's statistics; the design events are listed below"
        );
        for ir in &a.irregular {
            let stations = ir["stations"].as_array().cloned().unwrap_or_default();
            for (k, st) in stations.iter().enumerate() {
                let f = a.stations.get(k).map_or(f64::NAN, |s| s.station);
                s += &format!(
                    "  {:<13.3}  {:<15}  {:<7}  {:<16.4}  {:<14.1}  {}\n",
                    ir["speed_m_per_s"].as_f64().unwrap_or(f64::NAN),
                    ir["sea"].as_str().unwrap_or(""),
                    f,
                    st["slam_probability"].as_f64().unwrap_or(f64::NAN),
                    st["slams_per_hour"].as_f64().unwrap_or(f64::NAN),
                    ir["extreme_entry_velocity_m_per_s"][k]
                        .as_f64()
                        .map_or("-".into(), |v| format!("{v:.3}"))
                );
            }
        }
    }
    let design: Vec<_> = a
        .events
        .iter()
        .filter(|e| e.design_event.is_some())
        .collect();
    if !design.is_empty() {
        s += "\nirregular-sea design events (each with its definition):\n";
        for e in design {
            let d = e.design_event.as_ref().expect("filtered");
            let an = e
                .analytic
                .as_ref()
                .map(|r| r.sensors.iter().map(|q| q.peak_pa).fold(0.0, f64::max));
            s += &format!(
                "  station {} {:.3} m/s sea {}: entry {:.3} m/s (wave amplitude {:.4} m at T_p {:.3} s), max sensor \
                 {} kPa analytic{}\n    {}\n",
                e.station,
                e.speed_m_per_s,
                d.sea,
                d.design_entry_velocity_m_per_s,
                d.equivalent_wave_amplitude_m,
                d.peak_period_s,
                kpa(an),
                e.failed
                    .as_ref()
                    .map_or(String::new(), |f| format!("  FAILED: {f}")),
                d.definition
            );
        }
    }
    let event_warnings: usize = a.events.iter().map(|e| e.warnings.len()).sum();
    if event_warnings > 0 {
        s += &format!(
            "\n{event_warnings} warning(s) on the events: summary.json (events[].warnings) and the report's \
             warnings chapter\n"
        );
    }
    if !a.bow_force.is_empty() {
        s += "\ntotal bow slamming force (section force integrated along the bow; see bow_force.csv):\n";
        s += "  speed_m_per_s  wave             peak_sum_n  x_action_m  coincident_n  x_action_m\n";
        let n = |v: Option<f64>, p: usize| v.map_or("-".into(), |x| format!("{x:.p$}"));
        for b in &a.bow_force {
            s += &format!(
                "  {:<13.2}  {:<15}  {:<10}  {:<10}  {:<12}  {}\n",
                b.speed_m_per_s,
                b.wave,
                n(b.peak_sum_total_n, 1),
                n(b.peak_sum_x_action_m, 3),
                n(b.time_coincident.as_ref().map(|c| c.total_n), 1),
                n(b.time_coincident.as_ref().map(|c| c.x_action_m), 3),
            );
        }
    }
    if !a.validation.comparisons.is_empty() || !a.validation.trend_checks.is_empty() {
        s += &format!(
            "\ncomparison with published results ({}):\n",
            a.validation.reference_case.as_deref().unwrap_or("")
        );
        for c in &a.validation.comparisons {
            s += &format!(
                "  {}: computed {} {}, reference {} {} ({})\n",
                c.quantity,
                c.computed.map_or("-".into(), |v| format!("{v:.3}")),
                c.unit,
                c.reference,
                c.unit,
                c.note
            );
        }
        for t in &a.validation.trend_checks {
            s += &format!(
                "  {}: {} ({})\n",
                t.check,
                t.verdict.to_uppercase(),
                t.detail
            );
        }
        for n in &a.validation.notes {
            s += &format!("  note: {n}\n");
        }
    }
    s
}
