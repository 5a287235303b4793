//! The total bow slamming force and its point of action, per speed and wave: the section slamming forces
//! per metre f(x) of the assessed stations integrated along the bow (the "+t" half of the 2D+t method;
//! Veen 2010, ch. 6 combines the simulated cross-sections into the hull's slamming but gives no formula for
//! a total force, so the definition here is this tool's):
//!
//! F = ∫ f(x) dx,    x_F = ∫ x f(x) dx / F,
//!
//! with f linear between the assessed stations (trapezoid rule; the moment integral is exact for the
//! linear f), over the span from the aftmost to the foremost assessed station only: nothing is
//! extrapolated beyond them. A station whose keel stays in the water has f = 0 (no slam).
//!
//! Two totals are given:
//! * `peak_sum`: f is each station's peak section force, whenever it occurs. The peaks of different
//!   stations do not occur together, so this is an upper bound of the total force.
//! * `time_coincident`: the largest over time of ∫ f(x, t) dx, with each station's analytic force
//!   history ([`crate::assess::analytic::section_force`]: the corrected MLM force, or the flat-plate
//!   Wagner force after a flat keel's or an immersed start) placed at its keel-entry instant within the
//!   encounter period and scaled to the station's design section force (f(x, t) = F_A(t) f_design /
//!   max F_A), so that the shape in time is the analytic model's and the level the design value's. It is the total a hull girder feels at one instant, and never exceeds
//!   `peak_sum`, whose integrand is the largest of each f(x, t).

use serde::Serialize;

use super::results::EventResult;

/// How the bow force is defined, as written into summary.json and the CSV notes.
pub const DEFINITION: &str = "total bow slamming force F = integral of the section force per metre f(x) over \
x, f linear between the assessed stations (trapezoid rule), from the aftmost to the foremost assessed \
station only (no extrapolation), f = 0 where the keel stays in the water; point of action x_F = integral \
of x f dx / F (m from midship, positive forward). peak_sum: f = each station's design section force in that \
event (the design rule: the SPH peak plus its uncertainty where SPH ran, or the analytic force where it did not or \
governs), an upper bound of the computed section forces because the peaks are not simultaneous; \
time_coincident: the largest over time of the integral of the analytic force histories placed at \
each station's keel-entry instant, each scaled to its station's design section force (so that it never \
exceeds peak_sum)";

/// F and x_F of f over x (x in any order; pairs sorted by x). None with fewer than two stations or no
/// force.
pub fn integrate(x: &[f64], f: &[f64]) -> Option<(f64, f64)> {
    let mut p: Vec<(f64, f64)> = x.iter().copied().zip(f.iter().copied()).collect();
    if p.len() < 2 {
        return None;
    }
    p.sort_by(|a, b| a.0.total_cmp(&b.0));
    let (mut total, mut moment) = (0.0, 0.0);
    for w in p.windows(2) {
        let ((x0, f0), (x1, f1)) = (w[0], w[1]);
        let h = x1 - x0;
        total += 0.5 * h * (f0 + f1);
        moment += h / 6.0 * (x0 * (2.0 * f0 + f1) + x1 * (f0 + 2.0 * f1));
    }
    (total > 0.0).then(|| (total, moment / total))
}

/// One station's contribution.
#[derive(Debug, Clone, Serialize)]
pub struct StationForce {
    pub station: f64,
    pub x_m: f64,
    /// Peak section force per metre (N/m; 0 where the keel stays in the water).
    pub section_force_peak_n_per_m: f64,
    /// The design rule's source of the section force ([`super::design_rule`]) or "no-emergence".
    pub source: &'static str,
    /// Convergence verdict of the SPH section force, where SPH ran.
    pub verdict: Option<String>,
}

/// The coincident total at its instant.
#[derive(Debug, Clone, Serialize)]
pub struct Coincident {
    pub total_n: f64,
    pub x_action_m: f64,
    /// Instant within the encounter period (s; 0: wave crest at midship).
    pub time_s: f64,
}

/// The bow force of one speed and wave.
#[derive(Debug, Clone, Serialize)]
pub struct BowForce {
    pub speed_m_per_s: f64,
    pub wave: String,
    pub stations: Vec<StationForce>,
    /// Upper bound from the peaks (N) and its point of action (m from midship).
    pub peak_sum_total_n: Option<f64>,
    pub peak_sum_x_action_m: Option<f64>,
    /// From the analytic histories at one instant.
    pub time_coincident: Option<Coincident>,
    /// The verdict of the total: converged where every station's SPH section force is shown converged
    /// (converged or acceptable), otherwise which stations are not and what stands in for them.
    pub verdict: String,
    pub note: Option<String>,
}

/// The verdict of a total over `stations` ([`BowForce::verdict`]): converged where every slamming
/// station's section force is an SPH force shown converged (converged or acceptable); otherwise which
/// stations take the analytic force because no SPH ran at them in this event, and
/// which have an SPH force not shown converged, with its verdict.
fn total_verdict(stations: &[StationForce]) -> String {
    let slamming: Vec<&StationForce> = stations
        .iter()
        .filter(|s| s.section_force_peak_n_per_m > 0.0)
        .collect();
    if slamming.is_empty() {
        return "no slamming station".into();
    }
    let (analytic, sph): (Vec<&StationForce>, Vec<&StationForce>) = slamming
        .iter()
        .partition(|s| s.source == super::design_rule::ANALYTIC_WITHOUT_SPH);
    let unconverged: Vec<String> = sph
        .iter()
        .filter(|s| !super::design_rule::shown_converged(s.verdict.as_deref()))
        .map(|s| {
            format!(
                "{} ({}, verdict {})",
                s.station,
                s.source,
                s.verdict
                    .as_deref()
                    .unwrap_or("not assessed")
                    .replace('_', " ")
            )
        })
        .collect();
    if analytic.is_empty() && unconverged.is_empty() {
        return "converged: every station's SPH section force is converged or acceptable".into();
    }
    let stations_word = |n: usize| if n == 1 { "station" } else { "stations" };
    let mut parts = Vec::new();
    if !analytic.is_empty() {
        let list: Vec<String> = analytic.iter().map(|s| s.station.to_string()).collect();
        parts.push(format!(
            "at {} {} no SPH ran in this event: the force there is the analytic estimate (the \
             corrected MLM force, or the flat-plate Wagner force after a flat keel's or an immersed start), \
             which has no convergence to show",
            stations_word(list.len()),
            list.join(", ")
        ));
    }
    if !unconverged.is_empty() {
        parts.push(format!(
            "at {} {} the SPH section force is not shown converged: the design rule's value is used",
            stations_word(unconverged.len()),
            unconverged.join(", ")
        ));
    }
    format!("not shown converged as a whole: {}", parts.join("; "))
}

/// Linear interpolation in a history [t, f], 0 outside it.
fn at(h: &[[f64; 2]], t: f64) -> f64 {
    if h.is_empty() || t < h[0][0] || t > h[h.len() - 1][0] {
        return 0.0;
    }
    let k = h.partition_point(|p| p[0] <= t).clamp(1, h.len() - 1);
    let (a, b) = (h[k - 1], h[k]);
    if b[0] > a[0] {
        a[1] + (b[1] - a[1]) * (t - a[0]) / (b[0] - a[0])
    } else {
        b[1]
    }
}

/// Samples of the encounter period in the coincident search.
const SAMPLES: usize = 4000;

/// The bow force of the events of one speed and wave (`events` at distinct stations), `entry[i]` the keel
/// entry instant of event i within the encounter period `period` (s).
pub fn of_events(events: &[&EventResult], entry: &[Option<f64>], period: f64) -> Option<BowForce> {
    let first = events.first()?;
    let stations: Vec<StationForce> = events
        .iter()
        .map(|e| {
            let none = if e.entry_velocity_m_per_s.is_some() {
                "none (no force peak: a flat keel's analytic force only decays)"
            } else {
                "no-emergence"
            };
            let (v, src) = e.force_peak().unwrap_or((0.0, none));
            StationForce {
                station: e.station,
                x_m: e.x_m,
                section_force_peak_n_per_m: v,
                source: src,
                verdict: e.sph.as_ref().and_then(|s| s.force_convergence.clone()),
            }
        })
        .collect();
    let xs: Vec<f64> = stations.iter().map(|s| s.x_m).collect();
    let fs: Vec<f64> = stations
        .iter()
        .map(|s| s.section_force_peak_n_per_m)
        .collect();
    let peak = integrate(&xs, &fs);
    // each analytic history scaled to its station's design force
    let scale: Vec<f64> = events
        .iter()
        .zip(&fs)
        .map(|(e, &f)| {
            let top = e.analytic.as_ref().map_or(0.0, |a| {
                a.force_history.iter().map(|p| p[1]).fold(0.0, f64::max)
            });
            if top > 0.0 { f / top } else { 0.0 }
        })
        .collect();
    let mut best: Option<Coincident> = None;
    if xs.len() >= 2 && period > 0.0 {
        for k in 0..SAMPLES {
            let t = period * k as f64 / SAMPLES as f64;
            let f: Vec<f64> = events
                .iter()
                .zip(entry)
                .zip(&scale)
                .map(|((e, te), k)| match (e.analytic.as_ref(), te) {
                    (Some(a), Some(te)) => k * at(&a.force_history, (t - te).rem_euclid(period)),
                    _ => 0.0,
                })
                .collect();
            if let Some((total, x)) = integrate(&xs, &f)
                && best.as_ref().is_none_or(|b| total > b.total_n)
            {
                best = Some(Coincident {
                    total_n: total,
                    x_action_m: x,
                    time_s: t,
                });
            }
        }
    }
    let note = if xs.len() < 2 {
        Some("one station assessed: a force along the bow needs at least two stations".to_string())
    } else if peak.is_none() {
        Some("no station slams: the total bow slamming force is zero".to_string())
    } else {
        None
    };
    Some(BowForce {
        speed_m_per_s: first.speed_m_per_s,
        wave: first.wave.clone(),
        peak_sum_total_n: peak.map(|p| p.0),
        peak_sum_x_action_m: peak.map(|p| p.1),
        time_coincident: best,
        verdict: total_verdict(&stations),
        note,
        stations,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn trapezoid_total_and_point_of_action_by_hand() {
        // f = 0, 2, 2 N/m at x = 0, 1, 2 m: F = 1 + 2 = 3 N;
        // moment = (1/6)(0 + 1*4) + (1/6)(1*6 + 2*6) = 4/6 + 18/6 = 22/6 N m; x_F = 22/18 m
        let (f, x) = integrate(&[2.0, 0.0, 1.0], &[2.0, 0.0, 2.0]).unwrap();
        assert!((f - 3.0).abs() < 1e-12, "{f}");
        assert!((x - 22.0 / 18.0).abs() < 1e-12, "{x}");
        assert!(integrate(&[1.0], &[5.0]).is_none());
        assert!(integrate(&[0.0, 1.0], &[0.0, 0.0]).is_none());
    }

    #[test]
    fn the_verdict_tells_analytic_stations_from_unconverged_ones() {
        let st = |station: f64, source: &'static str, verdict: Option<&str>| StationForce {
            station,
            x_m: station,
            section_force_peak_n_per_m: 1000.0,
            source,
            verdict: verdict.map(String::from),
        };
        let v = total_verdict(&[
            st(0.093, "analytic", None),
            st(0.133, "sph (converged)", Some("converged")),
            st(0.227, "sph (not converged)", Some("not_converged")),
        ]);
        assert!(v.contains("at station 0.093 no SPH ran"), "{v}");
        assert!(
            v.contains("0.227 (sph (not converged), verdict not converged)"),
            "{v}"
        );
        assert!(!v.contains("0.133"), "{v}");
        let v = total_verdict(&[
            st(0.093, "sph (converged)", Some("converged")),
            st(0.133, "sph (acceptable)", Some("acceptable")),
        ]);
        assert!(v.starts_with("converged"), "{v}");
    }

    #[test]
    fn history_interpolation_is_zero_outside() {
        let h = [[0.0, 0.0], [1.0, 10.0]];
        assert_eq!(at(&h, -0.1), 0.0);
        assert!((at(&h, 0.25) - 2.5).abs() < 1e-12);
        assert_eq!(at(&h, 1.5), 0.0);
    }
}
