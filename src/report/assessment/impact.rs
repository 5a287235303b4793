//! Impact per station: the governing event's entry-velocity profile, each sensor's pressure history
//! (raw, and low-pass filtered where the run had a cut-off), the section force history, and the
//! particles coloured by pressure at the instant of the highest sensor pressure.

use serde_json::Value;

use super::Report;
use super::data::{Run, Saved, at, list, num, speed_text, text};
use super::motions::slug;
use crate::report::document::Block;
use crate::report::figure::{Figure, Mark, Series};

/// The governing event at a station: the SPH event with the highest sensor peak, else the event with
/// the highest analytic sensor peak. Returns its index.
pub fn governing(saved: &Saved, station: f64) -> Option<usize> {
    let peak = |e: &Value, part: &str, key: &str| {
        list(&e[part], "sensors")
            .iter()
            .filter_map(|q| num(q, key))
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let evs: Vec<usize> = (0..saved.events().len())
        .filter(|&i| at(&saved.events()[i], station))
        .collect();
    let with_run: Vec<usize> = evs
        .iter()
        .copied()
        .filter(|&i| saved.runs[i].is_some())
        .collect();
    if !with_run.is_empty() {
        return with_run.into_iter().max_by(|&a, &b| {
            let (ea, eb) = (&saved.events()[a], &saved.events()[b]);
            peak(ea, "sph", "raw_peak_pa").total_cmp(&peak(eb, "sph", "raw_peak_pa"))
        });
    }
    evs.into_iter()
        .filter(|&i| !saved.events()[i]["analytic"].is_null())
        .max_by(|&a, &b| {
            let (ea, eb) = (&saved.events()[a], &saved.events()[b]);
            peak(ea, "analytic", "peak_pa").total_cmp(&peak(eb, "analytic", "peak_pa"))
        })
}

/// Keel-entry profile from the strip-theory results (for events without an SPH run).
fn profile_from_motions(saved: &Saved, e: &Value) -> Option<Vec<(f64, f64)>> {
    let m = saved.motions.as_ref()?;
    let sp = list(m, "speeds")
        .iter()
        .find(|s| num(s, "speed_m_per_s") == num(e, "speed_m_per_s"))?;
    let w = list(sp, "regular")
        .iter()
        .find(|w| text(w, "wave") == text(e, "wave"))?;
    let st = list(w, "stations")
        .iter()
        .find(|s| num(s, "station").is_some_and(|x| at(e, x)))?;
    let pts = list(&st["keel_entry"], "samples")
        .iter()
        .map(|q| {
            (
                num(q, "time_since_entry_s").unwrap_or(f64::NAN) * 1e3,
                num(q, "velocity_m_per_s").unwrap_or(f64::NAN),
            )
        })
        .collect::<Vec<_>>();
    (!pts.is_empty()).then_some(pts)
}

/// Palette index of the contact-transient marker (grey).
const TRANSIENT_COLOUR: usize = 7;

/// Draw the end of the contact transient at `t_tr` (s) as a grey vertical line across the data of `fig`,
/// and say what it means (for the caption; empty when there is none).
fn mark_transient(fig: &mut Figure, t_tr: Option<f64>) -> String {
    let (lo, hi) = fig
        .series
        .iter()
        .flat_map(|s| s.points.iter().map(|p| p.1))
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), y| {
            (a.min(y), b.max(y))
        });
    match t_tr {
        Some(t) if t > 0.0 && lo.is_finite() && hi > lo => {
            fig.series.push(Series::new(
                format!("end of contact transient ({:.1} ms)", t * 1e3),
                vec![(t * 1e3, lo), (t * 1e3, hi)],
                TRANSIENT_COLOUR,
                Mark::ThinLine,
            ));
            format!(
                " The grey vertical line ends the contact transient ({:.1} ms after keel entry): peaks \
                 before it (the acoustic contact spike, of order rho c0 V) are not reported as slamming \
                 peaks.",
                t * 1e3
            )
        }
        _ => String::new(),
    }
}

/// Cut the y axis of `fig` (times in ms) when the contact transient before `t_tr` (s) rises more than
/// twice as high as anything after it, so that the slamming peaks are not pressed onto the baseline;
/// returns the caption's sentence (empty when nothing is cut). Call before the transient line is added.
fn clip_transient(fig: &mut Figure, t_tr: Option<f64>, unit: &str) -> String {
    let Some(t_ms) = t_tr.map(|t| t * 1e3) else {
        return String::new();
    };
    // the slamming-peak dots count as after the transient wherever they lie (a keel stage's peak may
    // come before the main run's transient ends)
    let max_where = |after: bool| {
        fig.series
            .iter()
            .flat_map(|s| s.points.iter().map(move |p| (p, s.mark == Mark::Dot)))
            .filter(|(p, dot)| (*dot || p.0 > t_ms) == after)
            .map(|(p, _)| p.1)
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let (before, after) = (max_where(false), max_where(true));
    if !(after > 0.0 && before > 2.0 * after) {
        return String::new();
    }
    let top = 1.25 * after;
    fig.y_max = Some(top);
    format!(
        " The contact-transient spike (up to {before:.1} {unit}) runs off the top of the plot, which is cut \
         at {top:.1} {unit} so that the slamming peaks can be read; the CSV beside the figure has every \
         value."
    )
}

fn series_of(run: &Run, col: &str, scale: f64) -> Vec<(f64, f64)> {
    match (run.column("time_s"), run.column(col)) {
        (Some(t), Some(x)) => t
            .iter()
            .zip(x)
            .map(|(&t, &x)| (t * 1e3, x * scale))
            .collect(),
        _ => Vec::new(),
    }
}

/// The record of sensor `name` (column `col`), from the keel stage that resolved it where one did.
fn sensor_series(run: &Run, name: &str, col: &str, scale: f64) -> Vec<(f64, f64)> {
    run.record_of(name, col).map_or_else(Vec::new, |(t, x)| {
        t.iter()
            .zip(x)
            .map(|(&t, &x)| (t * 1e3, x * scale))
            .collect()
    })
}

fn filtered(run: &Run, name: &str, col: &str, cutoff_hz: f64) -> Option<Vec<(f64, f64)>> {
    let (t, x) = run.record_of(name, col)?;
    if t.len() < 3 {
        return None;
    }
    let dt = (t[t.len() - 1] - t[0]) / (t.len() - 1) as f64;
    let lp = crate::loads::LowPass::new(cutoff_hz, 1.0 / dt, 2).ok()?;
    let (tu, xu) = crate::loads::resample_uniform(t, x, dt);
    let y = lp.filtfilt(&xu);
    Some(
        tu.iter()
            .zip(y)
            .map(|(&t, y)| (t * 1e3, y * 1e-3))
            .collect(),
    )
}

pub fn section(r: &mut Report, saved: &Saved) {
    r.heading(1, "Impact per station");
    r.para(
        "For each station, the governing event: the one with an SPH run and the highest sensor peak, or, \
         where no SPH run was made, the one with the highest analytic sensor peak. Time is counted from \
         keel entry.",
    );
    for st in saved.stations() {
        let f = num(st, "station").unwrap_or(f64::NAN);
        let sensors = saved.sensors_at(f);
        r.heading(
            2,
            &format!(
                "Station {f} (x = {:.3} m)",
                num(st, "x_m").unwrap_or(f64::NAN)
            ),
        );
        let Some(i) = governing(saved, f) else {
            r.para("No event at this station has a keel entry: nothing to show.");
            continue;
        };
        let e = &saved.events()[i];
        let tag = format!("{}_{}", f, slug(text(e, "wave")));
        let t_axis = if e["flare_event"].is_object() {
            "time since the start at least immersion (ms)"
        } else {
            "time since keel entry (ms)"
        };
        match num(&e["flare_event"], "immersion_m") {
            Some(d0) => r.para(&format!(
                "Governing event: {} m/s in wave {}, a flare event ({}): the keel stays immersed, the section \
                 starts at its least immersion d0 = {d0:.3} m in water at rest (the wave orbital flow and the \
                 flow of the earlier cycle are neglected) and time is counted from that start, not from a keel \
                 entry. The undisturbed water reaches the first panel above the still-water line at {} m/s, \
                 {} s after the start.",
                speed_text(num(e, "speed_m_per_s")),
                text(e, "wave"),
                text(e, "entry_kind"),
                num(&e["flare_event"], "impact_velocity_m_per_s")
                    .map_or("-".into(), |v| format!("{v:.3}")),
                num(&e["flare_event"], "impact_delay_after_start_s")
                    .map_or("-".into(), |v| format!("{v:.3}")),
            )),
            None => r.para(&format!(
                "Governing event: {} m/s in wave {}, entry velocity {:.3} m/s ({}).",
                speed_text(num(e, "speed_m_per_s")),
                text(e, "wave"),
                num(e, "entry_velocity_m_per_s").unwrap_or(f64::NAN),
                text(e, "slam_flag").replace('-', " ")
            )),
        }
        let Some(run) = &saved.runs[i] else {
            if let Some(pts) = profile_from_motions(saved, e) {
                let mut fig = Figure::new(
                    &format!("entry_velocity_{tag}"),
                    &format!("Entry-velocity profile, station {f}"),
                    t_axis,
                    "downward velocity (m/s)",
                );
                fig.series
                    .push(Series::new("strip theory v(t)", pts, 0, Mark::Line));
                fig.y_from_zero = true;
                fig.size = (800, 300);
                r.figure(
                    fig,
                    "Entry-velocity profile from the relative motion",
                    150.0,
                );
            }
            r.para(
                "No SPH run was made for this event (analytic fidelity, or not the governing event of a \
                 screening): there are no pressure or force histories, only the analytic peaks of the \
                 design-space section.",
            );
            continue;
        };
        let setup = &run.summary["setup"];
        let mut fig = Figure::new(
            &format!("entry_velocity_{tag}"),
            &format!("Entry-velocity profile, station {f}"),
            t_axis,
            "downward velocity (m/s)",
        );
        fig.series.push(Series::new(
            "v(t) driving the SPH run",
            series_of(run, "downward_velocity_m_per_s", 1.0),
            0,
            Mark::Line,
        ));
        fig.y_from_zero = true;
        fig.size = (800, 280);
        r.figure(
            fig,
            "Entry-velocity profile (downward, from the relative motion)",
            150.0,
        );
        let cutoff = num(setup, "filter_cutoff_hz");
        let mut fig = Figure::new(
            &format!("pressure_history_{tag}"),
            &format!("Sensor pressures, station {f}"),
            t_axis,
            "pressure (kPa)",
        );
        for (k, n) in sensors.iter().enumerate() {
            let col = format!("{n}_pa");
            fig.series.push(Series::new(
                format!("{n} raw"),
                sensor_series(run, n, &col, 1e-3),
                k,
                Mark::ThinLine,
            ));
            // a sensor resolved by a keel stage is filtered at the stage's own cut-off
            let stage_cutoff = list(&run.summary, "sensors")
                .iter()
                .find(|q| text(q, "name") == n.as_str())
                .and_then(|q| q["stage"]["stage"].as_u64())
                .map(|k| run.summary["stages"][k as usize]["filter_cutoff_hz"].as_f64());
            if let Some(fc) = stage_cutoff.unwrap_or(cutoff)
                && let Some(pts) = filtered(run, n, &col, fc)
            {
                fig.series
                    .push(Series::new(format!("{n} filtered"), pts, k, Mark::Line));
            }
        }
        // each sensor's slamming peak (the largest value in its impact window), where SPH has one: the
        // filtered record's where the run has a cut-off (the design quantity), else the raw record's
        let mut marked = 0;
        let mut on_filtered = false;
        for (k, n) in sensors.iter().enumerate() {
            let peak = list(&run.summary, "sensors")
                .iter()
                .find(|q| text(q, "name") == n.as_str())
                .map(|q| {
                    let f = &q["filtered_anatomy"]["slamming_peak"];
                    on_filtered |= !f.is_null();
                    if f.is_null() {
                        &q["anatomy"]["slamming_peak"]
                    } else {
                        f
                    }
                })
                .and_then(|p| Some((num(p, "time_s")? * 1e3, num(p, "value")? * 1e-3)));
            if let Some(pt) = peak {
                fig.series.push(Series::new(
                    format!("{n} slamming peak"),
                    vec![pt],
                    k,
                    Mark::Dot,
                ));
                marked += 1;
            }
        }
        let dots = if marked > 0 {
            let (read, design) = if on_filtered {
                (
                    "the largest value of its filtered record",
                    ", the design quantity",
                )
            } else {
                ("the largest raw value", "")
            };
            format!(
                " Dots: each sensor's slamming peak, {read} in its impact window (the analytic contact \
                 crossing it){design}; a sensor without a dot has no SPH impact (see the sign-off page)."
            )
        } else {
            String::new()
        };
        let staged: Vec<String> = list(&run.summary, "stages")
            .iter()
            .filter(|st| st["left_out"].is_null())
            .map(|st| {
                format!(
                    "{} from a keel stage (the section cut at half-breadth {:.1} mm, dp {:.3} mm, run to {:.2} ms)",
                    list(st, "sensors")
                        .iter()
                        .filter_map(|x| x.as_str())
                        .collect::<Vec<_>>()
                        .join(", "),
                    num(st, "cut_half_breadth_m").unwrap_or(f64::NAN) * 1e3,
                    num(st, "dp_m").unwrap_or(f64::NAN) * 1e3,
                    num(st, "t_end_s").unwrap_or(f64::NAN) * 1e3
                )
            })
            .collect();
        let dots = if staged.is_empty() {
            dots
        } else {
            format!(
                "{dots} Records of sensors the main run crossed too early to resolve: {}.",
                staged.join("; ")
            )
        };
        let t_tr = run.summary["contact_transient_end_s"].as_f64();
        let cut = clip_transient(&mut fig, t_tr, "kPa");
        let mut transient = mark_transient(&mut fig, t_tr);
        transient.push_str(&cut);
        if !staged.is_empty() && !transient.is_empty() {
            transient.push_str(
                " That line is the main run's: a record from a keel stage has the stage's own contact \
                 transient, shorter by the ratio of the spacings, so its slamming peak may lie before the \
                 line.",
            );
        }
        fig.size = (800, 400);
        let rule = setup
            .get("notes")
            .and_then(|n| n.as_array())
            .and_then(|n| {
                n.iter()
                    .filter_map(|x| x.as_str())
                    .find(|x| x.contains("low-pass"))
            })
            .map(|x| format!(" The rule: {x}."))
            .unwrap_or_default();
        let filt = match cutoff {
            Some(fc) => format!(
                "thin lines raw, thick lines low-pass filtered (2nd-order Butterworth forward and back, \
                 cut-off {fc:.0} Hz).{rule}"
            ),
            None => format!(
                "raw histories; the run had no low-pass cut-off, so no filtered history is shown.{rule}"
            ),
        };
        r.figure(
            fig,
            &format!("Sensor pressure histories: {filt}{transient}{dots}"),
            160.0,
        );
        let mut fig = Figure::new(
            &format!("section_force_{tag}"),
            &format!("Vertical section force, station {f}"),
            t_axis,
            "section force (kN/m)",
        );
        fig.series.push(Series::new(
            "SPH section force",
            series_of(run, "vertical_force_n_per_m", 1e-3),
            0,
            Mark::Line,
        ));
        let cut = clip_transient(&mut fig, t_tr, "kN/m");
        let transient = mark_transient(&mut fig, t_tr) + &cut;
        fig.size = (800, 300);
        r.figure(
            fig,
            &format!("Vertical force per metre on the section.{transient}"),
            150.0,
        );
        match &run.peak_png {
            Some(png) => {
                let name = format!("peak_pressure_{tag}.png");
                r.pngs.push((name.clone(), png.clone()));
                r.push(Block::Png {
                    png: png.clone(),
                    caption: format!(
                        "Particles coloured by pressure at the instant of the highest sensor pressure \
                         after the contact transient, whatever its phase: often the immersion after the \
                         slam (hydrostatic and inertial pressure), not a slamming peak; the time printed \
                         on the picture tells which (the sign-off section gives each panel's slamming \
                         peak time). The colour scale runs from zero to a round value above that sensor \
                         pressure (higher pressures take its top colour) [figures/{name}]"
                    ),
                    width_mm: 140.0,
                });
            }
            None => r.para(
                "No particle snapshot at peak pressure was saved with this run (runs cached before this \
                 version do not have one; run with --no-cache to make it).",
            ),
        }
    }
}
