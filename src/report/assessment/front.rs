//! Title block, summary page and hull section of the assessment report.

use serde_json::Value;

use super::Report;
use super::data::{Saved, list, num, speed_text, text};
use crate::report::document::Block;

pub fn kpa(v: Option<f64>) -> String {
    v.map_or("-".into(), |p| format!("{:.2}", p / 1e3))
}

fn speeds(saved: &Saved) -> Vec<f64> {
    list(&saved.summary["settings"], "speeds_m_per_s")
        .iter()
        .filter_map(Value::as_f64)
        .collect()
}

fn waves(saved: &Saved) -> Vec<String> {
    let mut w: Vec<String> = Vec::new();
    for e in saved.events() {
        let n = text(e, "wave").to_string();
        if !w.contains(&n) {
            w.push(n);
        }
    }
    w.iter().map(|n| wave_words(saved, n)).collect()
}

/// A regular wave's name with its height and period spelled out from `motions.json`, where it is there
/// ("H0.20-T2.0 (height 0.20 m, period 2.00 s)"); the period is 2 pi / omega of the wave frequency.
fn wave_words(saved: &Saved, name: &str) -> String {
    let found = saved.motions.as_ref().and_then(|m| {
        list(m, "speeds")
            .iter()
            .flat_map(|s| list(s, "regular"))
            .find(|r| text(r, "wave") == name)
    });
    let parts =
        found.and_then(|r| Some((num(r, "height_m")?, num(r, "wave_frequency_rad_per_s")?)));
    match parts {
        Some((h, w)) if w > 0.0 => {
            let period = std::f64::consts::TAU / w;
            format!("{name} (height {h:.2} m, period {period:.2} s)")
        }
        _ => name.to_string(),
    }
}

pub fn title(r: &mut Report, saved: &Saved, stamp: Option<String>) {
    let s = &saved.summary;
    r.doc.title = format!("Slamming assessment: {}", text(s, "hull"));
    r.doc.footer = format!("{} · {}", text(s, "hull"), text(s, "tool"));
    r.doc.stamp = stamp;
    let sp: Vec<String> = speeds(saved).iter().map(|v| speed_text(Some(*v))).collect();
    r.doc.subtitle = vec![
        "2D+t method (Veen 2010): strip theory, relative motion, 2D water entry per station"
            .to_string(),
        format!(
            "Loading condition: {}   ·   fidelity: {}",
            text(s, "loading"),
            text(s, "fidelity")
        ),
    ];
    let mut kv = vec![
        ("Hull".to_string(), text(s, "hull").to_string()),
        ("Loading condition".into(), text(s, "loading").into()),
        ("Regular waves".into(), waves(saved).join(", ")),
        ("Irregular seas".into(), irregular_names(saved).join(", ")),
        ("Speeds (m/s)".into(), sp.join(", ")),
        (
            "Stations (fraction of Lpp aft of FP)".into(),
            saved
                .stations()
                .iter()
                .map(|st| format!("{}", num(st, "station").unwrap_or(f64::NAN)))
                .collect::<Vec<_>>()
                .join(", "),
        ),
        ("Fidelity".into(), text(s, "fidelity").into()),
        (
            "SPH resolution".into(),
            format!(
                "{} ({} convergence level(s))",
                saved.summary["settings"]["resolution"]
                    .as_str()
                    .unwrap_or("default"),
                saved.summary["settings"]["convergence_levels"]
                    .as_u64()
                    .unwrap_or(0)
            ),
        ),
        ("Tool".into(), text(s, "tool").into()),
        ("Commit".into(), text(&s["provenance"], "commit").into()),
    ];
    if kv[3].1.is_empty() {
        kv[3].1 = "none".into();
    }
    r.push(Block::KeyValue(kv));
    let mut rows: Vec<Vec<String>> = list(&s["provenance"], "inputs")
        .iter()
        .map(|i| vec![text(i, "path").to_string(), text(i, "sha256").to_string()])
        .collect();
    // the published numbers of the comparisons, compiled into the tool
    rows.extend(list(s, "reference_files").iter().map(|i| {
        vec![
            format!("{} (reference data, built in)", text(i, "path")),
            text(i, "sha256").to_string(),
        ]
    }));
    r.push(Block::Table {
        caption: "Input files and their SHA-256".into(),
        header: vec!["file".into(), "SHA-256".into()],
        rows,
    });
    r.para(
        "Pressures are gauge pressures in kPa; stations are fractions of Lpp aft of the forward \
         perpendicular; x is measured from midship, positive forward. Every figure is also in the folder \
         figures/ beside this PDF as SVG, with a CSV file of its plotted numbers.",
    );
}

fn irregular_names(saved: &Saved) -> Vec<String> {
    let mut w: Vec<String> = Vec::new();
    for ir in list(&saved.summary, "irregular") {
        let n = text(ir, "sea").to_string();
        if !w.contains(&n) {
            w.push(n);
        }
    }
    w
}

/// The verdict of an SPH sensor peak in an event ("" when no SPH run; "dry in SPH" when the run did not
/// wet the sensor, whose design value is then the analytic one and has no convergence verdict).
pub fn verdict(e: &Value, sensor: &str) -> String {
    list(&e["sph"], "sensors")
        .iter()
        .find(|q| text(q, "name") == sensor)
        .map(|q| {
            if q["wetted"].as_bool() == Some(false) {
                "dry in SPH".to_string()
            } else {
                text(q, "convergence").replace('_', " ")
            }
        })
        .unwrap_or_default()
}

/// Every warning of the assessment, deduplicated, grouped by kind.
/// A message with its numbers blanked out: warnings that differ only in numbers are listed once. A
/// number is a whole word that parses as one ("0.29", "+28.8 %", "t = 0.19 s;"); names with digits
/// ("S093-3") are kept.
fn shape(msg: &str) -> String {
    msg.split_whitespace()
        .map(|w| if number_in(w).is_some() { "#" } else { w })
        .collect::<Vec<_>>()
        .join(" ")
}

/// The byte span of the number a word is, inside the punctuation around it ("(+28.8" -> "+28.8", "s;" ->
/// none), with its value.
fn number_in(w: &str) -> Option<(usize, usize, f64)> {
    let punct = |c: char| ",;:()[]%".contains(c);
    let start = w.len() - w.trim_start_matches(punct).len();
    let end = w.trim_end_matches(punct).len().max(start);
    let value = w[start..end].parse::<f64>().ok()?;
    Some((start, end, value))
}

/// An event as (station, wave, speed).
type Ev = (String, String, String);

/// Events as "station 0.093 in H0.20-T2.0 at 1.2, 1.4 m/s; station 0.133 ...".
fn events_text(evs: &[Ev]) -> String {
    let mut groups: Vec<(&str, &str, Vec<&str>)> = Vec::new();
    for (st, w, u) in evs {
        match groups.iter_mut().find(|(a, b, _)| a == st && b == w) {
            Some((_, _, us)) => {
                if !us.contains(&u.as_str()) {
                    us.push(u);
                }
            }
            None => groups.push((st, w, vec![u])),
        }
    }
    groups
        .iter()
        .map(|(st, w, us)| format!("station {st} in {w} at {} m/s", us.join(", ")))
        .collect::<Vec<_>>()
        .join("; ")
}

/// The key under which a warning is grouped: its [`shape`] when it was raised for an event (the events
/// are listed with the group, so a range of numbers stays attributable), the message itself otherwise (a
/// warning of the whole assessment, e.g. one per flat station, would lose which station it names).
fn group_key(msg: &str, for_event: bool) -> String {
    if for_event {
        shape(msg)
    } else {
        msg.to_string()
    }
}

/// The messages of one group (same [`group_key`]) as one message: a number that is the same in all of
/// them is kept, and one that differs becomes the range "lowest to highest" over the group, each end
/// written as in its own message.
fn merged(msgs: &[String]) -> String {
    let split: Vec<Vec<&str>> = msgs
        .iter()
        .map(|m| m.split_whitespace().collect())
        .collect();
    let words = split[0].iter().enumerate().map(|(i, w)| {
        let Some((a, b, _)) = number_in(w) else {
            return w.to_string();
        };
        // (value, text) of this number in every message of the group
        let mut values: Vec<(f64, &str)> = split
            .iter()
            .filter_map(|m| {
                let w = m.get(i)?;
                let (a, b, v) = number_in(w)?;
                Some((v, &w[a..b]))
            })
            .collect();
        values.sort_by(|x, y| x.0.total_cmp(&y.0));
        match (values.first(), values.last()) {
            (Some(lo), Some(hi)) if lo.1 != hi.1 => {
                format!("{}{} to {}{}", &w[..a], lo.1, hi.1, &w[b..])
            }
            _ => w.to_string(),
        }
    });
    words.collect::<Vec<_>>().join(" ")
}

/// Every warning of the assessment, grouped by kind; a warning repeated over events (up to its numbers)
/// is given once, with the events it concerns and the range of each number that differs among them.
pub fn warnings(saved: &Saved) -> Vec<(String, Vec<String>)> {
    // (shape, messages, events they were raised for)
    let mut grouped: Vec<(String, Vec<String>, Vec<Ev>)> = Vec::new();
    let mut add = |msg: String, event: Option<Ev>| {
        let key = group_key(&msg, event.is_some());
        match grouped.iter_mut().find(|(k, _, _)| *k == key) {
            Some((_, msgs, evs)) => {
                msgs.push(msg);
                evs.extend(event);
            }
            None => grouped.push((key, vec![msg], event.into_iter().collect())),
        }
    };
    for w in list(&saved.summary, "warnings")
        .iter()
        .filter_map(Value::as_str)
    {
        add(w.to_string(), None);
    }
    for e in saved.events() {
        let label = (
            format!("{}", num(e, "station").unwrap_or(f64::NAN)),
            text(e, "wave").to_string(),
            speed_text(num(e, "speed_m_per_s")),
        );
        if let Some(f) = e["failed"].as_str() {
            add(format!("failed run: {f}"), Some(label.clone()));
        }
        for w in list(e, "warnings").iter().filter_map(Value::as_str) {
            add(w.to_string(), Some(label.clone()));
        }
        for q in list(&e["sph"], "sensors") {
            if text(q, "convergence") == "not_converged" && q["wetted"].as_bool() != Some(false) {
                add(
                    text(q, "convergence_statement").to_string(),
                    Some(label.clone()),
                );
            }
        }
    }
    for m in &saved.missing {
        add(m.clone(), None);
    }
    if let Err(why) = &saved.hull {
        add(
            format!("the hull section of this report is left out: {why}"),
            None,
        );
    }
    let mut all: Vec<String> = grouped
        .into_iter()
        .map(|(_, msgs, evs)| {
            let msg = merged(&msgs);
            match evs.len() {
                0 => msg,
                1 => format!("{}: {msg}", events_text(&evs)),
                n => format!(
                    "{msg} [{n} events: {}; a number that differs among them is given as its range]",
                    events_text(&evs)
                ),
            }
        })
        .collect();
    let mut seen = std::collections::BTreeSet::new();
    all.retain(|w| seen.insert(w.clone()));
    let mut out: Vec<(String, Vec<String>)> = Vec::new();
    for w in all {
        let k = heading_of(&w);
        match out.iter_mut().find(|(n, _)| n == WARNING_HEADINGS[k].0) {
            Some((_, v)) => v.push(w),
            None => out.push((WARNING_HEADINGS[k].0.to_string(), vec![w])),
        }
    }
    out.sort_by_key(|(n, _)| WARNING_HEADINGS.iter().position(|(k, _)| k == n));
    out
}

/// The headings of the report's warnings, in their order, each with the words (lower case) that file a
/// warning under it; the first heading with a match takes it, and "Other" takes the rest.
const WARNING_HEADINGS: [(&str, &[&str]); 8] = [
    ("Failed runs", &["failed", "stopped early"]),
    // a larger pressure after the impact: a load case of its own, not a slamming pressure
    ("Loads after the impact", &["comes after the impact"]),
    ("Entry velocities", &["keel-slope", "design event"]),
    ("Chines", &["has a chine"]),
    (
        "Air cushion / low deadrise",
        &["air", "cushion", "single-phase", "deadrise"],
    ),
    (
        "Resolution and convergence",
        &[
            "converged",
            "resolution",
            "narrower",
            "spacing",
            "under-resolved",
        ],
    ),
    ("Analytic estimates", &["analytic", "wagner"]),
    ("Other", &[""]),
];

/// The index in [`WARNING_HEADINGS`] of the heading warning `w` is filed under.
fn heading_of(w: &str) -> usize {
    let l = w.to_lowercase();
    let other = WARNING_HEADINGS.len() - 1;
    // a convergence statement names the panel's local deadrise too: it is filed by its GCI
    if l.contains("gci") {
        return WARNING_HEADINGS
            .iter()
            .position(|(n, _)| *n == "Resolution and convergence")
            .unwrap_or(other);
    }
    WARNING_HEADINGS
        .iter()
        .position(|(_, keys)| keys.iter().any(|key| l.contains(key)))
        .unwrap_or(other)
}

pub fn summary(r: &mut Report, saved: &Saved) {
    r.heading(1, "Summary");
    let s = &saved.summary;
    r.para(&format!(
        "The design pressure of every panel, with its uncertainty, hydrostatic part, source, verdict and \
         governing event, is on the sign-off page. Ochi's slam threshold velocity is {:.3} m/s.",
        num(s, "slam_threshold_velocity_m_per_s").unwrap_or(f64::NAN)
    ));
    let rows: Vec<Vec<String>> = saved
        .stations()
        .iter()
        .map(|st| {
            let fp = &st["section_force_peak_n_per_m"];
            vec![
                format!("{}", num(st, "station").unwrap_or(f64::NAN)),
                format!("{:.3}", num(st, "x_m").unwrap_or(f64::NAN)),
                format!(
                    "{} / {}",
                    st["slamming_events"].as_u64().unwrap_or(0),
                    st["emerging_events"].as_u64().unwrap_or(0)
                ),
                num(fp, "value").map_or("-".into(), |v| format!("{v:.1}")),
                text(fp, "source").to_string(),
                speed_text(num(fp, "speed_m_per_s")),
                text(fp, "wave").to_string(),
            ]
        })
        .collect();
    r.push(Block::Table {
        caption:
            "Governing event per station: design section force (N/m, the design rule applied to the \
                  section force peak), events that slam by Ochi's criterion / events whose keel emerges"
                .into(),
        header: [
            "station",
            "x m",
            "slam / emerge",
            "force N/m",
            "source",
            "speed m/s",
            "wave",
        ]
        .map(String::from)
        .to_vec(),
        rows,
    });
    r.heading(2, "Limit checks");
    let limits = list(s, "limits");
    if limits.is_empty() {
        r.para(
            "No design-pressure limit was given for this assessment (slamtool assess \
             --max-pressure-kpa P, or a [limits] table in the hull file), so no verdict is stated.",
        );
    } else {
        let rows = limits
            .iter()
            .map(|l| {
                let scope = match &l["scope"] {
                    serde_json::Value::String(a) if a == "all" => "every sensor".to_string(),
                    v => match (v["station"].as_f64(), v["sensor"].as_str()) {
                        (Some(f), _) => format!("station {f}"),
                        (_, Some(n)) => format!("sensor {n}"),
                        _ => v.to_string(),
                    },
                };
                vec![
                    scope,
                    kpa(num(l, "pressure_pa")),
                    l["origin"].as_str().unwrap_or("").to_string(),
                ]
            })
            .collect();
        r.push(Block::Table {
            caption: "Design-pressure limits checked".into(),
            header: ["applies to", "limit kPa", "given by"]
                .map(String::from)
                .to_vec(),
            rows,
        });
        let over: Vec<String> = list(s, "limit_violations")
            .iter()
            .filter_map(|v| v.as_str().map(String::from))
            .collect();
        if over.is_empty() {
            r.push(Block::Strong(
                "PASS: every checked sensor design pressure is within its limits.".into(),
            ));
        } else {
            r.push(Block::Strong(format!(
                "FAIL: {} limit violation(s).",
                over.len()
            )));
            r.push(Block::List(over));
        }
    }
    super::forcing::section(r, s);
    let failed = s["failed_runs"].as_u64().unwrap_or(0);
    r.para(&format!(
        "Runs that failed: {failed}. Events: {}.",
        saved.events().len()
    ));
    r.heading(2, "Warnings");
    let w = warnings(saved);
    if w.is_empty() {
        r.para("No warnings.");
    }
    for (kind, items) in w {
        r.heading(3, &format!("{kind} ({})", items.len()));
        r.push(Block::List(items));
    }
}

pub fn hull(r: &mut Report, saved: &Saved) {
    r.heading(1, "Hull");
    let hull = match &saved.hull {
        Ok(h) => h,
        Err(why) => {
            r.para(&format!("The hull is not shown: {why}."));
            return;
        }
    };
    match crate::hull::body_plan::body_plan_svg(hull) {
        Ok(svg) => r.push(Block::Svg {
            svg,
            caption:
                "Body plan: aft body left, fore body right, waterline of each loading, sensors \
                      marked and named"
                    .into(),
            width_mm: 165.0,
        }),
        Err(e) => r.para(&format!("The body plan could not be drawn: {e}")),
    }
    let loading = text(&saved.summary, "loading");
    if let Ok(l) = hull.loading(Some(loading)) {
        let h = crate::hull::Hydrostatics::compute(hull, l);
        let kv = vec![
            ("Lpp".to_string(), format!("{:.4} m", h.lpp_m)),
            ("Depth".into(), format!("{:.4} m", hull.depth)),
            ("Waterline beam B".into(), format!("{:.4} m", h.beam_wl_m)),
            ("Mean draft T".into(), format!("{:.4} m", h.mean_draft_m)),
            (
                "Trim by stern".into(),
                format!("{:.4} m", h.trim_by_stern_m),
            ),
            ("Volume".into(), format!("{:.6} m3", h.volume)),
            (
                "Displacement".into(),
                crate::report::mass_text(h.displacement_kg),
            ),
            ("LCB (from midship, +fwd)".into(), format!("{:.4} m", h.lcb)),
            ("KB".into(), format!("{:.4} m", h.kb)),
            (
                "GM_T / GM_L".into(),
                format!("{:.4} / {:.3} m", h.gm_t, h.gm_l),
            ),
            (
                "CB / CP / CM / CWP".into(),
                format!("{:.4} / {:.4} / {:.4} / {:.4}", h.cb, h.cp, h.cm, h.cwp),
            ),
            ("KG".into(), format!("{:.4} m", l.kg)),
            (
                "LCG (from midship, +fwd)".into(),
                match l.lcg {
                    Some(x) => format!("{x:.4} m"),
                    None => format!("{:.4} m (not given: LCG = LCB)", h.lcb),
                },
            ),
            (
                "k_yy (pitch radius of gyration)".into(),
                format!("{:.4} m ({:.3} Lpp)", l.k_yy, l.k_yy / h.lpp_m),
            ),
        ];
        r.heading(2, &format!("Main particulars ({loading})"));
        r.push(Block::KeyValue(kv));
    }
    // What the hull file says of itself: where its offsets and mass properties come from, and what is
    // assumed (the report's numbers rest on it).
    if let Some(d) = hull
        .description
        .as_deref()
        .map(str::trim)
        .filter(|d| !d.is_empty())
    {
        r.heading(2, "Provenance of the hull (its file's description)");
        for p in d.split("\n\n").map(str::trim).filter(|p| !p.is_empty()) {
            r.para(p);
        }
    }
    let rows: Vec<Vec<String>> = hull
        .sensors
        .iter()
        .map(|s| {
            vec![
                s.name.clone(),
                format!("{:.4}", hull.aft_of_fp(s.x)),
                format!("{:.4}", s.x),
                format!("{:.4}", s.girth),
                format!("{:.4}", s.position[0]),
                format!("{:.4}", s.position[1]),
                format!("{:.1}", s.diameter * 1e3),
            ]
        })
        .collect();
    r.push(Block::Table {
        caption: "Pressure sensors".into(),
        header: [
            "sensor",
            "station",
            "x m",
            "girth m",
            "y m",
            "z m",
            "diameter mm",
        ]
        .map(String::from)
        .to_vec(),
        rows,
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_sensor_the_sph_did_not_wet_shows_dry_instead_of_a_convergence_verdict() {
        let e = serde_json::json!({"sph": {"sensors": [
            {"name": "K1", "convergence": "not_converged", "wetted": true},
            {"name": "K3", "convergence": "not_converged", "wetted": false},
            {"name": "K4", "convergence": "converged"}
        ]}});
        assert_eq!(verdict(&e, "K1"), "not converged");
        assert_eq!(verdict(&e, "K3"), "dry in SPH");
        assert_eq!(verdict(&e, "K4"), "converged");
        assert_eq!(verdict(&e, "K9"), "");
    }

    #[test]
    fn warnings_differing_in_numbers_only_share_a_shape_but_sensor_names_do_not() {
        let a = shape("sensor S093-3 raw: +28.8 % change from dp 7.263 / 14.525 mm; GCI 86.3 %");
        let b = shape("sensor S093-3 raw: -21.9 % change from dp 7.263 / 14.525 mm; GCI 65.7 %");
        let c = shape("sensor S093-4 raw: -21.9 % change from dp 7.263 / 14.525 mm; GCI 65.7 %");
        assert_eq!(a, b);
        assert_ne!(b, c);
        assert_eq!(shape("at t = 0.19 s;"), "at t = # s;");
    }

    #[test]
    fn warnings_are_filed_under_their_headings() {
        let heading = |w: &str| WARNING_HEADINGS[heading_of(w)].0;
        assert_eq!(
            heading(
                "sensors S093-1 (4.02 kPa at 0.081 s): the largest SPH pressure comes after the impact, \
                 in the immersion phase"
            ),
            "Loads after the impact"
        );
        assert_eq!(
            heading("design events of sea SS6, 16 of them: their profiles' regular wave"),
            "Entry velocities"
        );
        assert_eq!(
            heading(
                "sensor S093-2 raw: -40.4 % change; GCI 121.1 %; a side of 46.3 deg local deadrise"
            ),
            "Resolution and convergence"
        );
        assert_eq!(heading("something else entirely"), "Other");
    }

    #[test]
    fn warnings_of_the_whole_assessment_are_not_grouped_by_shape() {
        let a = "station 0.174 Lpp has a flat keel (half-width 0.1313 m)";
        let b = "station 0.227 Lpp has a flat keel (half-width 0.2082 m)";
        assert_ne!(group_key(a, false), group_key(b, false));
        assert_eq!(group_key(a, true), group_key(b, true));
    }

    #[test]
    fn a_group_of_warnings_gives_each_differing_number_as_its_range() {
        let msgs = [
            "sensor S1 dry: y = 0.29 m before t = 0.2894 s; dp 7.3 mm".to_string(),
            "sensor S1 dry: y = 0.31 m before t = 0.1702 s; dp 7.3 mm".to_string(),
            "sensor S1 dry: y = 0.30 m before t = 0.25 s; dp 7.3 mm".to_string(),
        ];
        assert_eq!(
            merged(&msgs),
            "sensor S1 dry: y = 0.29 to 0.31 m before t = 0.1702 to 0.2894 s; dp 7.3 mm"
        );
        assert_eq!(merged(&msgs[..1]), msgs[0]);
        let signed = [
            "change (+28.8 %)".to_string(),
            "change (-21.9 %)".to_string(),
        ];
        assert_eq!(merged(&signed), "change (-21.9 to +28.8 %)");
    }
}
