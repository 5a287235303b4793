//! Text tables of a motions analysis ([`crate::seakeeping::analysis::Report`]), as `slamtool motions`
//! prints them: a summary, then per speed the RAO table, one table per regular wave and one per irregular
//! sea, then the operability limits.

use std::fmt::Write;

use crate::seakeeping::analysis::{IrregularResult, RegularResult, Report, SpeedResult};

/// The whole report as text.
pub fn tables(hull: &str, loading: &str, r: &Report) -> String {
    let mut out = summary(hull, loading, r);
    for s in &r.speeds {
        out += &speed_heading(s);
        out += &raos(s);
        for w in &s.regular {
            out += &regular_wave(w);
        }
        for ir in &s.irregular {
            out += &irregular_sea(ir);
        }
    }
    out += &operability(r);
    out
}

// Writing to a String cannot fail, so the fmt::Result of writeln! is discarded throughout.

/// Particulars, natural periods, slam threshold, the stated limitation and any warnings.
pub fn summary(hull: &str, loading: &str, r: &Report) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "{hull}, loading '{loading}': Lpp {:.3} m, mass {:.1} kg, {:?}, {} strips",
        r.lpp_m, r.mass_kg, r.method, r.strip_stations
    );
    let _ = writeln!(
        o,
        "natural periods (uncoupled, zero speed): heave {:.3} s, pitch {:.3} s",
        r.heave_natural_period_s, r.pitch_natural_period_s
    );
    let _ = writeln!(
        o,
        "natural periods (coupled heave-pitch modes, zero speed): heave {:.3} s, pitch {:.3} s",
        r.heave_mode_period_s, r.pitch_mode_period_s
    );
    let _ = writeln!(
        o,
        "Ochi slam threshold velocity 0.093 sqrt(g Lpp) = {:.3} m/s",
        r.slam_threshold_velocity_m_s
    );
    let _ = writeln!(o, "note: {}", r.limitation);
    for w in &r.warnings {
        let _ = writeln!(o, "WARNING: {w}");
    }
    o
}

fn speed_heading(s: &SpeedResult) -> String {
    format!(
        "\n== U = {:.3} m/s (Fn {:.3})\n",
        s.speed_m_s, s.froude_number
    )
}

/// Heave and pitch RAOs at one speed over the wavelength ratios.
pub fn raos(s: &SpeedResult) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "{:>8} {:>8} {:>8} {:>8} {:>9} {:>9} {:>9} {:>9}",
        "lam/L", "w0", "we", "z/za", "ph_z deg", "thL/2pza", "th/kza", "ph_t deg"
    );
    for q in &s.raos {
        let _ = writeln!(
            o,
            "{:8.3} {:8.3} {:8.3} {:8.3} {:9.1} {:9.3} {:9.3} {:9.1}",
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

/// Motions, relative motion and keel entry per station in one regular wave.
pub fn regular_wave(w: &RegularResult) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "-- regular wave '{}' H {:.3} m: heave {:.4} m, pitch {:.3} deg",
        w.wave, w.height_m, w.heave_m, w.pitch_deg
    );
    let _ = writeln!(
        o,
        "{:>8} {:>8} {:>8} {:>9} {:>9} {:>9} {:>10}",
        "aft_FP", "x", "draft", "s_amp", "v_amp", "t_entry", "V_entry"
    );
    for t in &w.stations {
        let (te, ve) =
            t.keel_entry
                .as_ref()
                .map_or(("-".to_string(), "no entry".to_string()), |k| {
                    (
                        format!("{:.3}", k.t_entry),
                        format!("{:.3}", k.entry_velocity),
                    )
                });
        let _ = writeln!(
            o,
            "{:8.3} {:8.3} {:8.3} {:9.4} {:9.4} {:>9} {:>10}",
            t.aft_of_fp, t.x, t.draft, t.relative_motion_m, t.relative_velocity_m_s, te, ve
        );
    }
    o
}

/// Relative motion statistics and Ochi slam occurrence per station in one irregular sea.
pub fn irregular_sea(ir: &IrregularResult) -> String {
    let mut o = String::new();
    let _ = writeln!(
        o,
        "-- irregular sea '{}' Hs {:.3} m Tp {:.2} s",
        ir.sea, ir.hs_m, ir.tp_s
    );
    let _ = writeln!(
        o,
        "{:>8} {:>9} {:>9} {:>10} {:>9} {:>12}",
        "x", "sd_s", "sd_v", "P(slam)", "per hour", "V_extreme"
    );
    for (t, e) in ir.stations.iter().zip(&ir.extreme_velocity_m_s) {
        let e = e.map_or("-".to_string(), |v| format!("{v:.3}"));
        let _ = writeln!(
            o,
            "{:8.3} {:9.4} {:9.4} {:10.3e} {:9.2} {:>12}",
            t.x,
            t.m0.sqrt(),
            t.m2.sqrt(),
            t.probability,
            t.slams_per_hour,
            e
        );
    }
    o
}

/// The operability limit speed in each irregular sea.
pub fn operability(r: &Report) -> String {
    let mut o = String::new();
    for op in &r.operability {
        let lim = op
            .operability
            .limit_speed
            .map_or("below the lowest speed".to_string(), |u| {
                format!("{u:.3} m/s")
            });
        let _ = writeln!(
            o,
            "\noperability in '{}' (slam probability <= {}): {lim}",
            op.sea, op.operability.limit
        );
    }
    o
}
