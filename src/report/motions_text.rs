//! Text tables of a motions analysis ([`crate::seakeeping::analysis::Report`]), as `slamtool motions`
//! prints them: a summary, then per speed the RAO table, one table per regular wave and one per irregular
//! sea, then the operability limits.

use std::fmt::Write;

use super::sanity::SlamFlag;
use crate::seakeeping::analysis::{IrregularResult, RegularResult, Report, SpeedResult};

/// The whole report as text; `warnings` are the report's own and the caller's sanity warnings.
pub fn tables(hull: &str, loading: &str, r: &Report, warnings: &[String]) -> String {
    let mut out = summary(hull, loading, r, warnings);
    for s in &r.speeds {
        out += &speed_heading(s);
        out += &raos(s);
        for w in &s.regular {
            out += &regular_wave(w, r.slam_threshold_velocity_m_s);
        }
        for ir in &s.irregular {
            out += &irregular_sea(ir, r.lpp_m);
        }
    }
    out += &operability(r);
    out
}

// Writing to a String cannot fail, so the fmt::Result of writeln! is discarded throughout.

/// Particulars, natural periods, slam threshold, the stated limitation and the warnings.
pub fn summary(hull: &str, loading: &str, r: &Report, warnings: &[String]) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "{hull}, loading '{loading}': Lpp {:.3} m, mass {}, section method {}, {} strips",
        r.lpp_m,
        super::mass_text(r.mass_kg),
        r.method.name(),
        r.strip_stations
    );
    let _ = writeln!(
        o,
        "natural periods at loading '{loading}' (uncoupled, zero speed): heave {:.3} s, pitch {:.3} s",
        r.heave_natural_period_s, r.pitch_natural_period_s
    );
    let _ = writeln!(
        o,
        "natural periods at loading '{loading}' (coupled heave-pitch modes, zero speed): heave {:.3} s, pitch {:.3} s",
        r.heave_mode_period_s, r.pitch_mode_period_s
    );
    let _ = writeln!(
        o,
        "Ochi slam threshold velocity 0.093 sqrt(g Lpp) = {:.3} m/s",
        r.slam_threshold_velocity_m_s
    );
    let _ = writeln!(o, "note: {}", r.limitation);
    let _ = writeln!(
        o,
        "station = fraction of Lpp aft of the FP; x from midship, positive forward"
    );
    for w in warnings {
        let _ = writeln!(o, "warning: {w}");
    }
    o
}

fn speed_heading(s: &SpeedResult) -> String {
    format!(
        "\n== speed {:.3} m/s (Froude number {:.3})\n",
        s.speed_m_s, s.froude_number
    )
}

/// Heave and pitch RAOs at one speed over the wavelength ratios.
pub fn raos(s: &SpeedResult) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "{:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12}",
        "wavelength",
        "wave freq",
        "encounter",
        "heave /",
        "heave phase",
        "pitch Lpp /",
        "pitch /",
        "pitch phase"
    );
    let _ = writeln!(
        o,
        "{:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12} {:>12}",
        "/ Lpp", "rad/s", "freq rad/s", "wave ampl.", "deg", "2pi ampl.", "wave slope", "deg"
    );
    for q in &s.raos {
        let _ = writeln!(
            o,
            "{:12.3} {:12.3} {:12.3} {:12.3} {:12.1} {:12.3} {:12.3} {:12.1}",
            q.lambda_over_l,
            q.omega0,
            q.omega_e,
            q.heave,
            q.heave_phase_deg,
            q.pitch_nd,
            q.pitch_over_k,
            q.pitch_phase_deg
        );
    }
    o
}

/// Motions, relative motion, keel entry and Ochi's slam flag per station in one regular wave.
pub fn regular_wave(w: &RegularResult, threshold_m_per_s: f64) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "-- regular wave '{}', height {:.3} m: heave amplitude {:.4} m, pitch amplitude {:.3} deg",
        w.wave, w.height_m, w.heave_m, w.pitch_deg
    );
    let _ = writeln!(
        o,
        "{:>8} {:>8} {:>8} {:>10} {:>10} {:>9} {:>10}  slam flag",
        "station", "x", "draft", "rel.motion", "rel.veloc.", "entry at", "entry vel."
    );
    let _ = writeln!(
        o,
        "{:>8} {:>8} {:>8} {:>10} {:>10} {:>9} {:>10}",
        "", "m", "m", "ampl. m", "ampl. m/s", "s", "m/s"
    );
    for t in &w.stations {
        let (te, ve) = t
            .keel_entry
            .as_ref()
            .map_or(("-".to_string(), "-".to_string()), |k| {
                (
                    format!("{:.3}", k.t_entry),
                    format!("{:.3}", k.entry_velocity),
                )
            });
        let _ = writeln!(
            o,
            "{:8.3} {:8.3} {:8.3} {:10.4} {:10.4} {:>9} {:>10}  {}",
            t.aft_of_fp,
            t.x,
            t.draft,
            t.relative_motion_m,
            t.relative_velocity_m_s,
            te,
            ve,
            SlamFlag::of(t, threshold_m_per_s).text()
        );
    }
    let _ = writeln!(o, "   (- : the keel does not emerge, so there is no entry)");
    o
}

/// Relative motion statistics and Ochi slam occurrence per station in one irregular sea (`lpp` in m, for
/// the station column).
pub fn irregular_sea(ir: &IrregularResult, lpp: f64) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "-- irregular sea '{}', significant height {:.3} m, peak period {:.2} s",
        ir.sea, ir.hs_m, ir.tp_s
    );
    let _ = writeln!(
        o,
        "{:>8} {:>8} {:>10} {:>10} {:>10} {:>9} {:>14}",
        "station", "x", "rel.motion", "rel.veloc.", "slam prob.", "slams", "extreme entry"
    );
    let _ = writeln!(
        o,
        "{:>8} {:>8} {:>10} {:>10} {:>10} {:>9} {:>14}",
        "", "m", "st.dev. m", "st.dev. m/s", "per enc.", "per hour", "velocity m/s"
    );
    for (t, e) in ir.stations.iter().zip(&ir.extreme_velocity_m_s) {
        let e = e.map_or("-".to_string(), |v| format!("{v:.3}"));
        let _ = writeln!(
            o,
            "{:8.3} {:8.3} {:10.4} {:10.4} {:10.3e} {:9.2} {:>14}",
            (0.5 * lpp - t.x) / lpp,
            t.x,
            t.m0.sqrt(),
            t.m2.sqrt(),
            t.probability,
            t.slams_per_hour,
            e
        );
    }
    let _ = writeln!(
        o,
        "   (- : fewer than one slam expected over the exposure time)"
    );
    o
}

/// The operability limit speed in each irregular sea.
pub fn operability(r: &Report) -> String {
    let mut o = String::new();
    if r.operability.is_empty() {
        o += "\noperability: no irregular sea in the sea-state file\n";
    }
    for op in &r.operability {
        let lim = op.operability.limit_speed.map_or(
            "none: even the lowest speed tested exceeds the limit".to_string(),
            |u| {
                if op
                    .operability
                    .speeds
                    .last()
                    .is_some_and(|&top| (u - top).abs() <= 1e-9 * top.max(1.0))
                {
                    format!("no limit within the tested speeds (up to {u:.3} m/s)")
                } else {
                    format!("{u:.3} m/s")
                }
            },
        );
        let _ = writeln!(
            o,
            "\noperability in '{}' (slam probability <= {}): {lim}",
            op.sea, op.operability.limit
        );
    }
    o
}
