//! The sign-off page: the first page after the title, one per assessment. For every panel the design
//! slamming pressure with its uncertainty, the hydrostatic part, where the value comes from (SPH,
//! analytic, or a bound), the governing event, the convergence verdict, impulse and rise time, and the
//! validity flags; the section forces with their verdicts; the total bow force. Everything on it is read
//! from `summary.json` (the design values of `src/assess/design_rule.rs`); nothing is recomputed.

use serde_json::Value;

use super::Report;
use super::data::{Saved, at, fmt, list, num, speed_text, text};
use crate::loads::anatomy::KEEL_MAXIMUM_FROM_DEG;
use crate::report::document::Block;

/// The verdict as words ("-" where none applies). A two-phase cushion peak's verdict is one of spacing
/// only: the peak grows with the water's artificial sound speed, which no spacing study removes.
fn verdict_words(d: &Value) -> String {
    match d["verdict"].as_str() {
        Some(v) if text(d, "source").contains("artificial sound speed") => {
            format!("{} in spacing only (grows with c0)", v.replace('_', " "))
        }
        Some(v) => v.replace('_', " "),
        None => "-".into(),
    }
}

/// The validity flags of one design value: what a signer must know about it.
fn flags(d: &Value) -> Vec<String> {
    let mut f: Vec<String> = Vec::new();
    if let Some(l) = num(d, "later_load") {
        // a panel whose impact a keel stage resolved: its later load is the main run's reading
        let source = if num(d, "stage_dp_m").is_some() {
            "; read in the main SPH run, whose spacing does not resolve this panel's impact (the keel \
             stage does) but covers the slower immersion after it, and not convergence-checked"
        } else {
            ""
        };
        f.push(format!(
            "a larger load after the impact, in the immersion phase ({:.2} kPa, of which {:.2} kPa \
             hydrostatic{source}): not a slamming pressure, check it as a load case of its own",
            l / 1e3,
            num(d, "later_load_hydrostatic").unwrap_or(0.0) / 1e3
        ));
    }
    if let (Some(v), Some(a)) = (num(d, "value"), num(d, "analytic"))
        && text(d, "source").starts_with("sph")
        && a > v
    {
        f.push(format!(
            "the design value is below the analytic estimate of the same event ({:.2} kPa): the rule \
             takes the SPH value where it is converged or acceptable; the larger is the conservative choice",
            a / 1e3
        ));
    }
    let mut g = flags_of_source(d);
    f.append(&mut g);
    f
}

/// The flag of a panel with an SPH value whose local deadrise is at least [`KEEL_MAXIMUM_FROM_DEG`]
/// (`src/analytic/similarity_table.rs`: from there the similarity solution's pressure maximum is at the
/// keel, so a panel this steep sees no impact pulse pass, only a pressure that grows towards the keel's
/// as the wetting deepens; `src/loads/anatomy.rs` compares its levels by value).
fn steep_panel_flag(d: &Value, deadrise_deg: Option<f64>) -> Option<String> {
    let beta = deadrise_deg.filter(|&b| b >= KEEL_MAXIMUM_FROM_DEG)?;
    d["sph"].is_number().then(|| {
        format!(
            "local deadrise {beta:.1} deg (at least {KEEL_MAXIMUM_FROM_DEG:.1}): the nonlinear wedge \
             flow has its pressure maximum at the keel, not at the spray root, so no impact pulse \
             crosses this panel; its SPH value is the largest of a slowly varying pressure in the \
             window, and its convergence levels are compared by value, not by the time of their largest \
             values"
        )
    })
}

/// The water-hammer bound of a flat-keel panel's entry `d`, as a parenthesis ("" where there is none).
fn water_hammer_bound(d: &Value) -> String {
    num(d, "acoustic_bound").map_or(String::new(), |b| {
        format!(
            " (upper bound without air, the water hammer rho c_w V: {:.0} kPa)",
            b / 1e3
        )
    })
}

fn flags_of_source(d: &Value) -> Vec<String> {
    let mut f: Vec<String> = Vec::new();
    if text(d, "source") == crate::assess::results::DRY_SOURCE {
        f.push("the SPH water did not reach it with a slamming pressure: analytic value".into());
        return f;
    }
    match d["impact"].as_str() {
        Some("acoustic") if d["value"].is_null() => f.push(format!(
            "flat keel: air-cushion impact, which neither single-phase SPH nor the analytic models \
             compute: no design value{}",
            water_hammer_bound(d)
        )),
        Some("acoustic") => f.push("flat keel: acoustic impact, air cushion not modelled".into()),
        Some("cushioned") if d["value"].is_null() => f.push(format!(
            "flat keel with air: the two-phase cushion peak ({} kPa) grows with the water's artificial \
             sound speed, so it is no design value{}",
            fmt(num(d, "sph"), 1e-3, 2),
            water_hammer_bound(d)
        )),
        Some("in_transient") => f.push("impact not resolved by SPH at this spacing".into()),
        Some("not_crossed") | Some("after_record") => f.push("no SPH impact in the run".into()),
        _ => {}
    }
    if !f.is_empty() {
        return f;
    }
    let rising = d["rising_at_window_end"].as_bool() == Some(true);
    if rising {
        f.push(
            "no distinct impact peak: the SPH record still rises where the impact window closes, so its \
             value is the window's last sample, not converged whatever its verdict"
                .into(),
        );
    }
    match d["verdict"].as_str() {
        // a rising value's flag already says it is not converged
        Some("not_converged") if !rising => f.push("SPH not converged".into()),
        Some("mismatched") => f.push("SPH levels show different events".into()),
        Some("companion_unresolved") => f.push(
            "SPH convergence not assessed: the coarser level does not resolve the impact".into(),
        ),
        Some("not_assessed") => f.push("SPH convergence not assessed".into()),
        _ => {}
    }
    if text(d, "source").starts_with("analytic") && d["sph"].is_number() {
        f.push("analytic value governs".into());
    }
    f
}

/// The section forces of the stations with a flat keel (a panel whose impact is acoustic, or
/// cushioned in a run with air): what their design value leaves out. The force's slamming window opens
/// after the contact transient (`src/sph/phases.rs`), so neither the water hammer of a run without air
/// nor the cushion of a run with air, which follows the artificial sound speed, is in it. `None` where
/// no station has a flat keel.
fn flat_keel_force_flag(saved: &Saved) -> Option<String> {
    let flat: Vec<String> = saved
        .stations()
        .iter()
        .filter(|st| {
            list(st, "design_pressure_pa")
                .iter()
                .any(|d| matches!(d["impact"].as_str(), Some("acoustic") | Some("cushioned")))
        })
        .map(|st| format!("{}", num(st, "station").unwrap_or(f64::NAN)))
        .collect();
    (!flat.is_empty()).then(|| {
        format!(
            "Section force at the stations with a flat keel ({}): its slamming peak is taken after the \
             contact transient (the keel {} spacings deep), so the flat bottom's first impact is not in \
             it: without air a water hammer that SPH with an artificial sound speed does not compute, with \
             air a cushion load that grows with that sound speed (docs/guide/air.md). No model here gives \
             that part of the force; the design section force is the load of the flow after it.",
            flat.join(", "),
            crate::sph::CONTACT_TRANSIENT_DP
        )
    })
}

/// The forcing behind the design values against a published one: where the assessment compares its
/// keel-entry velocities with a published computation of the same hull (the `comparisons` of
/// `summary.json`, unit m/s), the flag gives each ratio and what it means for a pressure, which grows
/// about with the square of the entry velocity (Wagner 1932; the analytic models here and the SPH
/// runs are driven by that velocity). `None` where there is no such comparison.
fn forcing_flag(s: &Value) -> Option<String> {
    let velocities: Vec<&Value> = list(s, "comparisons")
        .iter()
        .filter(|c| text(c, "unit") == "m/s")
        .collect();
    let rows: Vec<String> = velocities
        .iter()
        .filter_map(|c| {
            let (v, r) = (num(c, "computed")?, num(c, "reference")?);
            (r > 0.0).then(|| {
                format!(
                    "{}: {v:.2} against {r:.2} m/s ({:+.0} %; a pressure about {:+.0} %)",
                    text(c, "quantity"),
                    100.0 * (v / r - 1.0),
                    100.0 * ((v / r).powi(2) - 1.0)
                )
            })
        })
        .collect();
    if rows.is_empty() {
        return None;
    }
    let (note, source) = (text(velocities[0], "note"), text(velocities[0], "source"));
    Some(format!(
        "Forcing: the keel-entry velocities behind these design values against a published computation \
         of the same hull: {} ({note}; {source}). A slamming pressure grows about with the square of the \
         entry velocity, so a difference of the forcing of this size carries into every design value \
         above, SPH and analytic alike: the relative motion (hull reconstruction and strip theory) is a \
         source of uncertainty that U, the SPH discretisation's, does not include.",
        rows.join("; ")
    ))
}

/// The governing event of design entry `d` of station `f`: the one whose speed and wave the entry names.
fn governing_event<'a>(saved: &'a Saved, f: f64, d: &Value) -> Option<&'a Value> {
    saved.events().iter().find(|e| {
        at(e, f)
            && num(e, "speed_m_per_s") == num(d, "speed_m_per_s")
            && text(e, "wave") == text(d, "wave")
    })
}

/// The raw slamming peak (kPa, two decimals) of the governing event's SPH record of panel `d`, where the
/// design quantity is the filtered record's; "-" otherwise.
fn governing_raw(saved: &Saved, f: f64, d: &Value) -> String {
    let name = text(d, "name");
    governing_event(saved, f, d)
        .and_then(|e| {
            list(&e["sph"], "sensors")
                .iter()
                .find(|x| text(x, "name") == name && x["slamming_filtered"].as_bool() == Some(true))
                .and_then(|x| num(x, "raw_slamming_peak_pa"))
        })
        .filter(|_| num(d, "sph").is_some())
        .map_or_else(|| "-".into(), |p| format!("{:.2}", p / 1e3))
}

/// The impact window of the SPH run and the analytic peak time of design entry `d` of station `f`,
/// from the governing event ([`governing_event`]).
fn governing_timing(saved: &Saved, f: f64, d: &Value) -> (String, Option<f64>) {
    let name = text(d, "name");
    let Some(e) = governing_event(saved, f, d) else {
        return ("-".into(), None);
    };
    let named = |v: &Value| -> Option<Value> {
        list(v, "sensors")
            .iter()
            .find(|x| text(x, "name") == name)
            .cloned()
    };
    let window = named(&e["sph"])
        .and_then(|x| {
            let w = x["impact_window_s"].as_array()?;
            Some(format!(
                "{:.1} to {:.1}",
                w.first()?.as_f64()? * 1e3,
                w.get(1)?.as_f64()? * 1e3
            ))
        })
        .unwrap_or_else(|| "-".into());
    // No analytic peak (a flat keel's panels): no time either.
    let analytic = named(&e["analytic"])
        .filter(|x| num(x, "peak_pa").is_some_and(|p| p > 0.0))
        .and_then(|x| num(&x, "peak_time_s"));
    (window, analytic)
}

/// What the entry velocities contain of the keel-slope term U dz_k/dx (`assess::keel_slope`): a paragraph
/// when it is on, and when it is off but a station's warning says it would be 5 % or more of an entry
/// velocity there.
fn keel_slope_paragraph(r: &mut Report, s: &serde_json::Value) {
    let on = s["settings"]["keel_slope_term"].as_bool() == Some(true);
    let left_out: Vec<&str> = list(s, "warnings")
        .iter()
        .filter_map(|w| w.as_str())
        .filter(|w| w.contains(crate::assess::keel_slope::LEFT_OUT))
        .filter_map(|w| w.split(':').next())
        .map(|w| w.trim_start_matches("station ").trim_end_matches(" Lpp"))
        .collect();
    if on {
        r.para(
            "Entry velocities: this assessment adds the keel-slope term U dz_k/dx to every keel entry of \
             strip theory, the sinking of a section whose keel is not parallel to the calm waterline through \
             the earth-fixed plane of the 2D+t method (--keel-slope-term; Veen 2010 leaves it out). The \
             stations' lines under Warnings give the amount. Flare events and measured records do not \
             include it.",
        );
    } else if !left_out.is_empty() {
        r.para(&format!(
            "Entry velocities: the keel-slope term U dz_k/dx is left out, as in Veen (2010), but at {} {} \
             Lpp it would change a keel-entry velocity by 5 % or more. The design values there are off about \
             as the square of the entry velocity (each station's warning under Warnings gives the factor), \
             low where the keel rises towards the bow: assess with --keel-slope-term before signing them.",
            if left_out.len() == 1 {
                "station"
            } else {
                "stations"
            },
            left_out.join(", ")
        ));
    }
}

pub fn page(r: &mut Report, saved: &Saved) {
    r.heading(1, "Sign-off: design slamming loads");
    let s = &saved.summary;
    r.para(&format!(
        "Design rule: {}. The SPH value is the slamming peak of the sensor's impact window (the analytic \
         wetted contact crossing the sensor, widened by half its time and by one particle spacing), never a value of the \
         contact transient or of the end of a run, read from the record low-passed at the event's physical \
         cut-off where the run has one (zero-phase 2nd-order Butterworth at 2 / tau, tau the quickest \
         analytic crossing of a panel: it keeps at least 90 % of a pulse rising that fast; faster content is \
         the acoustic and particle noise of weakly compressible SPH, which does not converge with the \
         spacing), its convergence verdict that of the filtered peaks; the raw slamming peak and its \
         verdict are in pressures.csv beside it. Where the record still rises as the window closes \
         there is no distinct impact peak: the value is the window's last sample, flagged, and the design \
         value is the larger of it (with U) and the analytic one. U is its discretisation uncertainty: \
         the GCI of the matched peaks at the convergence levels (SPH = smoothed-particle hydrodynamics; GCI = Roache's grid \
         convergence index, from two levels with the order 1 assumed unless three give it), or, where the \
         levels' peaks are different events, the difference between them. Verdicts: converged (GCI at \
         most 5 %), acceptable (at most 20 %), not converged (above 20 %: refine before relying on the \
         SPH value), mismatched (the coarser level's peak is another event), companion unresolved (the \
         coarser level has no peak in the impact window: its contact crosses the sensor inside its \
         contact transient), not assessed (one level, \
         or no SPH impact). A verdict measures how much the peak moves between the run's spacings, not \
         its error against an exact solution: on the validation's constant-speed wedges the default \
         level's force-panel peaks (the default scheme, sensors below 80 % of the side) read 0.98-1.16 of \
         the exact similarity pressure at 20, 30 and 45 deg (validation case wedge-convergence-table, a \
         known failure; docs/numerics/wedge-convergence.md, item 33). On a panel of {:.1} deg local deadrise or more the similarity solution's \
         pressure maximum is at the keel and no impact pulse crosses the panel: its levels are compared \
         by value, whatever their times. A panel with no design value (\"-\") is one no model here computes. \
         Analytic: the modified Logvinovich model (MLM) for pressures and forces, each corrected to the \
         nonlinear similarity solution of the equivalent wedge (the flat-plate Wagner force is 38 % above \
         that solution at 20 deg and 126 % at 45 deg); after a flat keel's start, which has no equivalent \
         wedge, the force is the flat-plate Wagner force, kept as a conservative estimate. \
         SPH pressures are totals, hydrostatic part included; the analytic (MLM) pressures are \
         hydrodynamic only. The hydrostatic column is the part at the time of the SPH peak, given apart as \
         class rules treat them apart (it is not in an analytic design value). Density {} kg/m3.",
        text(&s["settings"], "design_value"),
        KEEL_MAXIMUM_FROM_DEG,
        fmt(num(&s["settings"], "water_density_kg_m3"), 1.0, 1)
    ));
    let air = text(&s["settings"], "air");
    if air == "auto" || air == "on" {
        r.para(&format!(
            "Air: this assessment ran with --air {air}, so the stations it ran with air (see the SPH notes) \
             have every panel and section force from two-phase runs, those above a flat keel included. \
             Those values can differ from a single-phase assessment of the same hull and sea (the two-phase \
             runs converge differently, and the cushion peaks on a flat keel grow with the water's \
             artificial sound speed, so they are not design values). Where this hull is also assessed \
             without air, sign the larger of the two values of each panel away from the flat keel; the \
             two-phase model's validation is incomplete (docs/guide/air.md)."
        ));
    }
    keel_slope_paragraph(r, s);
    if list(s, "irregular").is_empty() {
        r.para(
            "No irregular sea in this assessment: the design values below are those of the regular waves \
             and speeds assessed, not of the design events of an irregular sea (the most probable largest \
             entry velocity over an exposure time: [[irregular]] in the sea-state file, \
             docs/guide/assess.md). Check that these waves are the design basis you intend to sign.",
        );
    }
    let mut rows = Vec::new();
    let mut detail = Vec::new();
    let mut flagged: Vec<String> = Vec::new();
    for st in saved.stations() {
        let f = num(st, "station").unwrap_or(f64::NAN);
        for d in list(st, "design_pressure_pa") {
            let u = num(d, "uncertainty");
            rows.push(vec![
                format!("{f}"),
                text(d, "name").to_string(),
                fmt(num(d, "value"), 1e-3, 2),
                match (num(d, "sph"), u) {
                    (Some(p), Some(u)) => format!("{:.2} ± {:.2}", p / 1e3, u / 1e3),
                    (Some(p), None) => format!("{:.2}", p / 1e3),
                    _ => "-".into(),
                },
                governing_raw(saved, f, d),
                fmt(num(d, "analytic"), 1e-3, 2),
                fmt(num(d, "hydrostatic"), 1e-3, 2),
                text(d, "source").to_string(),
                verdict_words(d),
                speed_text(num(d, "speed_m_per_s")),
            ]);
            let (window, analytic_time) = governing_timing(saved, f, d);
            // the SPH run's own (its integration span), else the panel's from the hull file
            let deadrise = num(d, "local_deadrise_deg").or_else(|| {
                let width = list(st, "sensors")
                    .iter()
                    .find(|x| text(x, "name") == text(d, "name"))
                    .and_then(|x| num(x, "width_m"))
                    .unwrap_or(0.0);
                saved.local_deadrise_deg(text(d, "name"), width)
            });
            detail.push(vec![
                text(d, "name").to_string(),
                fmt(deadrise, 1.0, 1),
                text(d, "impact").replace('_', " "),
                fmt(num(d, "peak_time_s"), 1e3, 1),
                window,
                fmt(analytic_time, 1e3, 1),
                fmt(num(d, "rise_time_s"), 1e3, 2),
                fmt(num(d, "impulse"), 1.0, 2),
                fmt(num(d, "particles_across_wetted"), 1.0, 1),
                fmt(num(d, "stage_dp_m"), 1e3, 2),
                fmt(num(d, "acoustic_bound").filter(|&b| b > 0.0), 1e-3, 0),
            ]);
            let mut fl = flags(d);
            fl.extend(steep_panel_flag(d, deadrise));
            if !fl.is_empty() {
                flagged.push(format!("{}: {}", text(d, "name"), fl.join("; ")));
            }
        }
    }
    r.push(Block::Table {
        caption:
            "Design slamming pressure per panel (kPa) with the governing event; SPH ± U is the \
                  slamming peak of the low-passed record where the run has a cut-off, SPH raw the \
                  unfiltered record's, beside it"
                .into(),
        header: [
            "station",
            "panel",
            "design",
            "SPH ± U",
            "SPH raw",
            "analytic",
            "hydrostatic",
            "source",
            "verdict",
            "speed m/s",
        ]
        .map(String::from)
        .to_vec(),
        rows,
    });
    r.push(Block::Table {
        caption: format!(
            "The governing impact of each panel: the local deadrise (the contour's mean slope over the \
             span the SPH run integrates, the panel widened to four particle spacings where narrower, or \
             over the panel without SPH; from {KEEL_MAXIMUM_FROM_DEG:.1} deg the similarity solution's \
             pressure maximum is at the keel), SPH impact status, slamming peak time, the impact \
                  window it was taken from (Wagner's contact crossing the panel, widened by half its time \
                  and by one particle spacing of penetration for the SPH contact's lag), the analytic \
                  (MLM) peak time, rise time (of the SPH record: from its last sample below a tenth of the \
                  slamming peak, within the window, to the peak), impulse over the impact window (the sph_impulse_pa_s column \
                  of pressures.csv is over the whole record), particles across the analytic wetted half-width when \
                  the contact crosses the panel (at the spacing of the keel stage that resolved it, where one did: \
                  a fine run of the section's lower part, see the SPH notes), and the water-hammer bound rho c_w V of a flat keel \
                  (an upper bound without air; averaged over the panel, so a panel reaching beyond the flat \
                  reads less than rho c_w V); \"-\": not applicable to the panel's impact"
        ),
        header: [
            "panel",
            "local deadrise deg",
            "SPH impact",
            "peak ms",
            "window ms",
            "MLM peak ms",
            "rise ms",
            "impulse Pa s",
            "particles across",
            "keel stage dp mm",
            "water hammer kPa",
        ]
        .map(String::from)
        .to_vec(),
        rows: detail,
    });
    let forces: Vec<Vec<String>> = saved
        .stations()
        .iter()
        .filter_map(|st| {
            let d = &st["section_force_peak_n_per_m"];
            d.is_object().then(|| {
                vec![
                    format!("{}", num(st, "station").unwrap_or(f64::NAN)),
                    fmt(num(d, "value"), 1.0, 0),
                    match (num(d, "sph"), num(d, "uncertainty")) {
                        (Some(p), Some(u)) => format!("{p:.0} ± {u:.0}"),
                        (Some(p), None) => format!("{p:.0}"),
                        _ => "-".into(),
                    },
                    fmt(num(d, "analytic"), 1.0, 0),
                    fmt(num(d, "hydrostatic"), 1.0, 0),
                    text(d, "source").to_string(),
                    verdict_words(d),
                    speed_text(num(d, "speed_m_per_s")),
                ]
            })
        })
        .collect();
    r.push(Block::Table {
        caption: "Section force per metre (N/m): design value, SPH slamming peak ± U, analytic (corrected MLM; \
                  flat-plate Wagner after a flat keel's start), buoyancy at the SPH peak (the hydrostatic part), source and verdict. \
                  U covers the spacing only: at the automatic sound speed the SPH section force of a wedge reads \
                  3.5-6 % below the exact similarity force, and within 1 % of it at twice that sound speed \
                  (the default scheme; docs/numerics/wedge-convergence.md, item 31), and a flat \
                  keel's acoustic impact is not in these forces (see the flags)"
            .into(),
        header: [
            "station",
            "design",
            "SPH ± U",
            "analytic",
            "buoyancy",
            "source",
            "verdict",
            "speed m/s",
        ]
        .map(String::from)
        .to_vec(),
        rows: forces,
    });
    let bow = list(s, "bow_force");
    let top = bow
        .iter()
        .filter(|b| num(b, "peak_sum_total_n").is_some())
        .max_by(|a, b| {
            num(a, "peak_sum_total_n")
                .unwrap_or(0.0)
                .total_cmp(&num(b, "peak_sum_total_n").unwrap_or(0.0))
        });
    match top {
        Some(b) => r.para(&format!(
            "Total bow slamming force, largest over the events: {:.1} N at {} m/s in {}, point of action \
             {:.3} m from midship: the integral along the hull (trapezoid rule) of each station's design \
             section force in that one event (the design rule as in the table above: the SPH peak plus its \
             uncertainty where SPH ran, the analytic force where it did not or governs; where a station's \
             largest design force comes from another event, the table above differs), over the span from the \
             aftmost to the foremost assessed station only, with nothing extrapolated forward or aft of them; \
             an upper bound of the computed section forces over that span, since the stations' peaks do not \
             occur together (a flat keel's acoustic impact is not among them, see the flags). At one instant \
             (each station's analytic force history placed at its keel-entry time and scaled to its design \
             section force): {} N. Verdict: {}.",
            num(b, "peak_sum_total_n").unwrap_or(f64::NAN),
            speed_text(num(b, "speed_m_per_s")),
            text(b, "wave"),
            num(b, "peak_sum_x_action_m").unwrap_or(f64::NAN),
            fmt(num(&b["time_coincident"], "total_n"), 1.0, 1),
            text(b, "verdict")
        )),
        None => r.para("Total bow slamming force: no station slams, or fewer than two stations."),
    }
    r.heading(2, "Validity flags");
    let mut items = flagged;
    if let Some(f) = flat_keel_force_flag(saved) {
        items.push(f);
    }
    if let Some(f) = forcing_flag(s) {
        items.push(f);
    }
    items.push(
        "2D+t: each station is a 2D water entry; the three-dimensional relief of the flow along the hull \
         is not modelled, which generally over-predicts the loads, and least accurately near the stem, \
         where the flow along the hull matters most."
            .into(),
    );
    let air = text(&saved.summary["settings"], "air");
    items.push(if air == "off" || air.is_empty() {
        "Single-phase SPH: no air. At flat and low-deadrise panels the impact is cushioned by air in \
         reality. Panels on a flat keel have no design value here (neither SPH nor the analytic models \
         compute that impact); the water-hammer pressure is stated as the bound without air."
            .into()
    } else {
        format!(
            "Air (--air {air}): the runs listed under \"Air cushion / low deadrise\" below have air as a \
             second phase, the others are single-phase. The cushion peaks of the panels on a flat keel are \
             shown but have no design value: they grow with the water's artificial sound speed \
             (docs/guide/air.md). The peak times of those panels count from keel entry and are negative \
             where the cushion peaks before it, during the keel's approach through the air gap."
        )
    });
    r.push(Block::List(items));
}

#[cfg(test)]
mod tests {
    use super::{flags, forcing_flag, steep_panel_flag};
    use serde_json::json;

    #[test]
    fn steep_panels_and_rising_records_are_flagged() {
        let d = json!({"name": "S093-2", "sph": 2636.0, "verdict": "not_converged",
                       "rising_at_window_end": true});
        let f = steep_panel_flag(&d, Some(46.2)).unwrap();
        assert!(f.contains("local deadrise 46.2 deg"), "{f}");
        assert!(steep_panel_flag(&d, Some(42.0)).is_none());
        assert!(steep_panel_flag(&d, None).is_none());
        // no SPH value: nothing about its record to flag
        assert!(steep_panel_flag(&json!({"name": "S227-3"}), Some(49.0)).is_none());
        // a rising record's flag, and the verdict's not repeated
        let f = flags(&d).join("; ");
        assert!(f.contains("no distinct impact peak"), "{f}");
        assert!(!f.contains("SPH not converged"), "{f}");
    }

    #[test]
    fn an_acceptable_sph_value_below_the_analytic_one_is_flagged() {
        // S174-4 of the Ochi assessment: 1.45 kPa (SPH 1.27 + U, acceptable) against 2.14 kPa analytic
        let d = json!({"name": "S174-4", "value": 1452.96, "sph": 1266.0, "analytic": 2141.45,
                       "source": "sph (acceptable)", "verdict": "acceptable"});
        let f = flags(&d).join("; ");
        assert!(
            f.contains("below the analytic estimate of the same event (2.14 kPa)"),
            "{f}"
        );
        // the analytic value governing: nothing to flag
        let d = json!({"name": "S174-3", "value": 2630.0, "sph": 1570.0, "analytic": 2630.0,
                       "source": "analytic (SPH not converged)", "verdict": "mismatched"});
        assert!(!flags(&d).join("; ").contains("below the analytic"));
    }

    #[test]
    fn the_forcing_flag_gives_each_velocity_ratio_and_its_square() {
        let s = json!({"comparisons": [
            {"quantity": "P1 keel-entry velocity", "unit": "m/s", "computed": 1.289, "reference": 1.06,
             "note": "n", "source": "src"},
            {"quantity": "P2 pressure", "unit": "kPa", "computed": 2.7, "reference": 3.0},
            {"quantity": "P3 keel-entry velocity", "unit": "m/s", "computed": 0.928, "reference": 0.58}
        ]});
        let f = forcing_flag(&s).unwrap();
        // 1.289 / 1.06 = 1.216 and its square 1.479; 0.928 / 0.58 = 1.6 and 2.56
        assert!(
            f.contains("1.29 against 1.06 m/s (+22 %; a pressure about +48 %)"),
            "{f}"
        );
        assert!(
            f.contains("0.93 against 0.58 m/s (+60 %; a pressure about +156 %)"),
            "{f}"
        );
        assert!(!f.contains("P2 pressure"), "only velocities: {f}");
        // without a velocity comparison there is no flag
        let s = json!({"comparisons": [{"quantity": "p", "unit": "kPa", "computed": 1.0, "reference": 2.0}]});
        assert!(forcing_flag(&s).is_none());
        assert!(forcing_flag(&json!({})).is_none());
    }
}
