//! Motions section: heave and pitch RAOs (amplitude and phase) per speed, natural periods, relative
//! motion and velocity at the slamming stations with Ochi's threshold velocity, and the slam statistics
//! of irregular seas, all from the strip-theory results the assessment saved (`motions.json`).

use serde_json::Value;

use super::Report;
use super::data::{Saved, capitalised, list, num, speed_text, text};
use crate::report::document::Block;
use crate::report::figure::{Figure, Mark, RefLine, Series};

fn rao_figure(m: &Value, id: &str, title: &str, y_label: &str, key: &str) -> Figure {
    let mut f = Figure::new(id, title, "wavelength over Lpp, lambda/L (-)", y_label);
    for (k, sp) in list(m, "speeds").iter().enumerate() {
        let mut pts: Vec<(f64, f64)> = list(sp, "raos")
            .iter()
            .map(|r| {
                (
                    num(r, "lambda_over_l").unwrap_or(f64::NAN),
                    num(r, key).unwrap_or(f64::NAN),
                )
            })
            .collect();
        if key.ends_with("_deg") {
            unwrap_degrees(&mut pts);
        }
        f.series.push(Series::new(
            format!(
                "U = {} m/s (Fn {:.3})",
                speed_text(num(sp, "speed_m_per_s")),
                num(sp, "froude_number").unwrap_or(f64::NAN)
            ),
            pts,
            k,
            Mark::Line,
        ));
    }
    f.size = (800, 380);
    f
}

/// Remove the 360-degree jumps of a phase curve (a phase is defined modulo 360 degrees; drawn wrapped, a
/// phase that passes 180 degrees would show a false vertical jump).
fn unwrap_degrees(pts: &mut [(f64, f64)]) {
    for k in 1..pts.len() {
        let prev = pts[k - 1].1;
        let mut y = pts[k].1;
        while y - prev > 180.0 {
            y -= 360.0;
        }
        while y - prev < -180.0 {
            y += 360.0;
        }
        pts[k].1 = y;
    }
}

/// Relative-motion (or velocity) amplitude against speed at each station, for one regular wave.
fn relative_figure(m: &Value, wave: &str, key: &str, what: &str, unit: &str) -> Figure {
    let f = Figure::new(
        &format!("relative_{}_{}", what.replace(' ', "_"), slug(wave)),
        &format!("Relative {what} amplitude at the stations, wave {wave}"),
        "speed U (m/s)",
        &format!("relative {what} amplitude ({unit})"),
    );
    station_figure(m, wave, f, |st| num(st, key))
}

/// The downward relative velocity at which each station's keel re-enters the water in a regular wave,
/// against speed: the velocity Ochi's criterion compares with the threshold (stations whose keel stays in
/// the water have no point at that speed).
fn reentry_figure(m: &Value, wave: &str) -> Figure {
    let f = Figure::new(
        &format!("keel_reentry_velocity_{}", slug(wave)),
        &format!("Keel re-entry velocity at the stations, wave {wave}"),
        "speed U (m/s)",
        "keel re-entry velocity (m/s)",
    );
    station_figure(m, wave, f, |st| {
        st.get("keel_entry")
            .and_then(|k| num(k, "entry_velocity_m_per_s"))
    })
}

/// One series per station of `value` against speed, in wave `wave`; a station without a value at a
/// speed has no point there.
fn station_figure(
    m: &Value,
    wave: &str,
    mut f: Figure,
    value: impl Fn(&Value) -> Option<f64>,
) -> Figure {
    let mut stations: Vec<f64> = Vec::new();
    for sp in list(m, "speeds") {
        for r in list(sp, "regular")
            .iter()
            .filter(|r| text(r, "wave") == wave)
        {
            for st in list(r, "stations") {
                let s = num(st, "station").unwrap_or(f64::NAN);
                if !stations.iter().any(|x| (x - s).abs() < 1e-9) {
                    stations.push(s);
                }
            }
        }
    }
    for (k, &s) in stations.iter().enumerate() {
        let mut pts = Vec::new();
        for sp in list(m, "speeds") {
            for r in list(sp, "regular")
                .iter()
                .filter(|r| text(r, "wave") == wave)
            {
                for st in list(r, "stations")
                    .iter()
                    .filter(|st| num(st, "station").is_some_and(|x| (x - s).abs() < 1e-9))
                {
                    if let (Some(u), Some(v)) = (num(sp, "speed_m_per_s"), value(st)) {
                        pts.push((u, v));
                    }
                }
            }
        }
        f.series
            .push(Series::new(format!("station {s}"), pts, k, Mark::LineDots));
    }
    f.y_from_zero = true;
    f.size = (800, 360);
    f
}

/// Text with its first letter in upper case and a full stop at the end.
fn sentence(s: &str) -> String {
    let mut out = capitalised(s.trim());
    if !out.is_empty() && !out.ends_with('.') {
        out.push('.');
    }
    out
}

pub fn slug(s: &str) -> String {
    let mut out = String::new();
    for c in s.chars() {
        if c.is_ascii_alphanumeric() || c == '.' {
            out.push(c.to_ascii_lowercase());
        } else if !out.ends_with('-') {
            out.push('-');
        }
    }
    out.trim_matches('-').to_string()
}

pub fn section(r: &mut Report, saved: &Saved) {
    r.heading(1, "Motions");
    let Some(m) = &saved.motions else {
        r.para(
            "This assessment did not save its strip-theory results (motions.json; written by slamtool \
             assess from this version on): run the assessment again to see the RAOs and relative motions \
             here.",
        );
        return;
    };
    r.para(&format!(
        "Strip theory (Salvesen, Tuck & Faltinsen 1970), head seas, sectional hydrodynamics by the {} method, {} strips. {}",
        text(m, "method"),
        m["strip_stations"].as_u64().unwrap_or(0),
        sentence(text(m, "limitation"))
    ));
    r.push(Block::KeyValue(vec![
        (
            "Heave natural period (uncoupled)".into(),
            format!(
                "{:.3} s",
                num(m, "heave_natural_period_s").unwrap_or(f64::NAN)
            ),
        ),
        (
            "Pitch natural period (uncoupled)".into(),
            format!(
                "{:.3} s",
                num(m, "pitch_natural_period_s").unwrap_or(f64::NAN)
            ),
        ),
        (
            "Coupled heave / pitch mode periods".into(),
            format!(
                "{:.3} / {:.3} s",
                num(m, "heave_mode_period_s").unwrap_or(f64::NAN),
                num(m, "pitch_mode_period_s").unwrap_or(f64::NAN)
            ),
        ),
        (
            "Ochi's threshold velocity 0.093 sqrt(g Lpp)".into(),
            format!(
                "{:.3} m/s",
                num(m, "slam_threshold_velocity_m_per_s").unwrap_or(f64::NAN)
            ),
        ),
    ]));
    r.heading(2, "Response amplitude operators");
    let specs = [
        (
            "rao_heave_amplitude",
            "Heave RAO",
            "heave / wave amplitude (-)",
            "heave_over_wave_amplitude",
        ),
        (
            "rao_heave_phase",
            "Heave phase (lead on the crest at midship, unwrapped)",
            "heave phase (deg)",
            "heave_phase_deg",
        ),
        (
            "rao_pitch_amplitude",
            "Pitch RAO",
            "pitch / wave slope k zeta (-)",
            "pitch_over_wave_slope",
        ),
        (
            "rao_pitch_phase",
            "Pitch phase (lead on the crest at midship, unwrapped)",
            "pitch phase (deg)",
            "pitch_phase_deg",
        ),
    ];
    for (id, title, yl, key) in specs {
        let f = rao_figure(m, id, title, yl, key);
        r.figure(f, &format!("{title} against wavelength, per speed"), 150.0);
    }
    r.heading(2, "Relative motion at the slamming stations");
    let threshold = num(m, "slam_threshold_velocity_m_per_s");
    let mut waves: Vec<String> = Vec::new();
    for sp in list(m, "speeds") {
        for w in list(sp, "regular") {
            let n = text(w, "wave").to_string();
            if !waves.contains(&n) {
                waves.push(n);
            }
        }
    }
    for w in &waves {
        let f = relative_figure(m, w, "relative_motion_amplitude_m", "motion", "m");
        r.figure(
            f,
            &format!("Relative vertical motion amplitude, wave {w}"),
            150.0,
        );
        let f = relative_figure(
            m,
            w,
            "relative_velocity_amplitude_m_per_s",
            "velocity",
            "m/s",
        );
        r.figure(
            f,
            &format!("Relative vertical velocity amplitude, wave {w}"),
            150.0,
        );
        let mut f = reentry_figure(m, w);
        if let Some(t) = threshold {
            f.ref_lines.push(RefLine {
                y: t,
                label: format!("Ochi's threshold velocity {t:.3} m/s"),
            });
        }
        r.figure(
            f,
            &format!(
                "Keel re-entry velocity, wave {w}: the downward relative velocity when the keel re-enters \
                 the water after emerging, which Ochi's criterion compares with the threshold velocity (red \
                 line); a point above the line is a slam. A station whose keel stays in the water at a speed \
                 has no point there. It is lower than the velocity amplitude of the figure before, because \
                 the keel re-enters before the relative velocity reaches its largest value"
            ),
            150.0,
        );
    }
    r.heading(2, "Slam statistics in irregular seas");
    let irr = list(&saved.summary, "irregular");
    if irr.is_empty() {
        r.para(
            "The sea-state file has no irregular seas, so there are no slam probabilities or slams per \
             hour to show.",
        );
        return;
    }
    let mut seas: Vec<String> = Vec::new();
    for ir in irr {
        let n = text(ir, "sea").to_string();
        if !seas.contains(&n) {
            seas.push(n);
        }
    }
    for sea in &seas {
        for (key, what, unit) in [
            ("slam_probability", "slam probability per encounter", "-"),
            ("slams_per_hour", "slams per hour", "1/h"),
        ] {
            let mut f = Figure::new(
                &format!("{}_{}", key, slug(sea)),
                &format!("{what}, {sea}"),
                "speed U (m/s)",
                &format!("{what} ({unit})"),
            );
            let nst = irr
                .iter()
                .map(|ir| list(ir, "stations").len())
                .max()
                .unwrap_or(0);
            for k in 0..nst {
                let mut pts = Vec::new();
                let mut name = format!("station {}", k + 1);
                for ir in irr.iter().filter(|ir| text(ir, "sea") == sea) {
                    if let Some(st) = list(ir, "stations").get(k) {
                        if let Some(x) = saved.stations().get(k).and_then(|s| num(s, "station")) {
                            name = format!("station {x}");
                        }
                        pts.push((
                            num(ir, "speed_m_per_s").unwrap_or(f64::NAN),
                            num(st, key).unwrap_or(f64::NAN),
                        ));
                    }
                }
                f.series.push(Series::new(name, pts, k, Mark::LineDots));
            }
            f.y_from_zero = true;
            f.size = (800, 340);
            r.figure(
                f,
                &format!(
                    "{what} by Ochi's criterion (keel emergence and re-entry faster than the threshold \
                     velocity), per station"
                ),
                150.0,
            );
        }
    }
}
