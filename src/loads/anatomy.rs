//! The anatomy of a water-entry record: which part of a sensor's (or the section force's) history is the
//! slamming impact, and which is not.
//!
//! A wall-pressure record of a weakly compressible SPH water entry has four phases, set apart by
//! physical rules that do not look at the SPH values themselves:
//!
//! 1. **Contact transient**, t < t_tr, the keel less than [`crate::sph::CONTACT_TRANSIENT_DP`] particle
//!    spacings deep: the acoustic answer of the weakly compressible fluid to first contact, of order
//!    rho c0 V with the artificial sound speed c0, the same at every resolution. Not a slamming load.
//! 2. **Impact**: the wetted contact (the jet root, where the slamming pressure peaks) crosses the sensor.
//!    Its expected window comes from the analytic contact half-width c(t) of the same event (generalised
//!    Wagner, [`crate::analytic::generalised_wagner`], along the run's own velocity history): with t_lo and
//!    t_hi the times at which c reaches the half-breadths of the sensor's lower and upper edges,
//!
//!    window = [ t_lo (1 - F),  t_hi (1 + F) + L dp / V(t_hi) ],
//!
//!    times from the start of the run (keel entry). F = [`WINDOW_FRACTION`] allows for the contact of the
//!    nonlinear flow differing from Wagner's (the similarity solution's jet root lies 4 % below Wagner's at
//!    20 deg of deadrise and further at higher deadrise; Zhao & Faltinsen 1993) and for the pulse decaying
//!    after the crossing; in a self-similar entry every time scales with t, hence the fraction. The SPH
//!    peaks' lag behind the similarity solution's scales the same way: on constant-speed wedges of 20 and
//!    30 deg at 20, 40 and 80 particles per half-beam the latest sensor peak is 0.47 t_hi late, inside F,
//!    while in spacings it grows with refinement (docs/numerics/wedge-convergence.md, item 20). L =
//!    [`LAG_SPACINGS`] allows on top for the SPH contact's penetration offset of about half a spacing
//!    (the same document, item 7), twice over. An allowance proportional to dp / V alone (6 dp / V until
//!    the nineteenth session) grows without bound as the entry slows: at Ochi's slow entries it reached
//!    55 ms beyond a 25 ms crossing and took the side jet's later swings for slamming peaks.
//! 3. **Immersion**, after the window: the hydrostatic and added-mass loads of the deepening section.
//! 4. **Record end**, the last [`RECORD_END_FRACTION`] of the record: a value there may be cut off by the
//!    end of the run (a load still rising), so it is never a design value.
//!
//! **A steep side has no impact pulse.** Where the sensor's local deadrise (the slope of the chord of its
//! span on the contour) is at least [`KEEL_MAXIMUM_FROM_DEG`], the nonlinear similarity flow of the local
//! wedge has its pressure maximum at the keel, not at the spray root: at constant speed the sensor's
//! pressure grows towards the keel's value as the wetting deepens, and falls only as the entry slows.
//! The largest value in its window is then a level, not the peak of an event, and two resolutions'
//! values are compared by value, not by the times at which they occur ([`matched`]).
//!
//! A sensor's **slamming peak** is the largest value in its impact window, outside the contact transient
//! and the record end, leaving out isolated single-sample spikes (a sample more than [`SPIKE_RATIO`] times
//! both of its neighbours, which no physical pressure pulse resolved by several samples can produce).
//! Where Wagner's contact crosses the sensor inside the contact transient, or with an acoustic contact
//! speed (a flat keel), single-phase SPH with an artificial sound speed does not compute the impact at
//! all: the anatomy says so and gives no slamming peak. In a run with air the flat keel's impact is the
//! air cushion's ([`ImpactStatus::Cushioned`]): its window runs from the start of the run, the keel's
//! approach through the air gap, to the widened end of Wagner's crossing, with no contact transient. The hydrostatic part at the time of the peak,
//! rho g (d(t) - z_s) with d the keel depth below the calm surface and z_s the height of the sensor
//! centre above the keel (zero when the sensor is above the calm surface), is reported beside it, since
//! class rules treat the two apart.

use serde::{Deserialize, Serialize};

use crate::loads::peaks::Peak;
use crate::numerics::quadrature::trapezoid;

/// Fraction F by which the expected impact window is widened about Wagner's crossing times.
pub const WINDOW_FRACTION: f64 = 0.5;

/// The SPH contact's lag L allowed for at the end of the window beyond the widening F, in particle
/// spacings over the speed (module notes).
pub const LAG_SPACINGS: f64 = 1.0;

/// The last fraction of a record that is never a design value.
pub const RECORD_END_FRACTION: f64 = 0.05;

/// A sample more than this many times both neighbours is an isolated spike.
pub const SPIKE_RATIO: f64 = 2.0;

/// Two peaks at successive resolutions are the same physical event when their times differ by at most
/// this fraction of the impact duration ([`ImpactWindow::duration`]).
pub const MATCH_FRACTION: f64 = 0.25;

/// The local deadrise (deg) from which a sensor's record has no impact pulse: the similarity solution's
/// pressure maximum is at the keel ([`crate::analytic::similarity_table::KEEL_MAXIMUM_FROM_DEG`]).
pub use crate::analytic::similarity_table::KEEL_MAXIMUM_FROM_DEG;

/// The phase of a time in a record.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum Phase {
    /// The acoustic contact transient, t < t_tr.
    ContactTransient,
    /// Before the contact reaches the sensor (the sensor is dry or barely wetted).
    BeforeImpact,
    /// The impact window.
    Impact,
    /// After the impact window: hydrostatic and added-mass loads of the immersion.
    Immersion,
    /// The last [`RECORD_END_FRACTION`] of the record.
    RecordEnd,
}

impl Phase {
    /// Words for reports.
    pub fn describe(self) -> &'static str {
        match self {
            Phase::ContactTransient => "contact transient",
            Phase::BeforeImpact => "before the impact",
            Phase::Impact => "impact",
            Phase::Immersion => "immersion",
            Phase::RecordEnd => "end of record",
        }
    }
}

/// Whether, and how, a record holds a slamming impact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ImpactStatus {
    /// A slamming peak inside the impact window.
    Resolved,
    /// Wagner's contact crosses the sensor inside the contact transient: the impact is not resolved at
    /// this particle spacing.
    InTransient,
    /// Wagner's contact crosses the sensor at an acoustic speed (a flat or nearly flat keel): the impact
    /// is a water-hammer pressure that single-phase SPH with an artificial sound speed does not compute.
    Acoustic,
    /// A sensor Wagner's contact would cross at an acoustic speed (a flat keel), in a run with air
    /// ([`crate::sph::air`]): the impact is the air cushion's, which the two-phase run computes. Its window
    /// opens at the start of the run (the keel's approach through the air gap, where the cushion builds)
    /// and the contact transient does not apply to it: the keel meets air first, not the water.
    Cushioned,
    /// Wagner's contact does not reach the sensor within the run (it stops at a chine or the widest point,
    /// or the run ends first).
    NotCrossed,
    /// The sensor is below the waterline at the start of the run (an immersed start): no impact.
    WettedAtStart,
    /// The impact window lies in the record's end, or after it: the run ended before the impact.
    AfterRecord,
}

impl ImpactStatus {
    /// Words for reports.
    pub fn describe(self) -> &'static str {
        match self {
            ImpactStatus::Resolved => "impact resolved",
            ImpactStatus::InTransient => {
                "impact not resolved: the contact crosses the sensor within the contact transient"
            }
            ImpactStatus::Acoustic => {
                "acoustic impact (flat keel): not computed by single-phase SPH with an artificial c0"
            }
            ImpactStatus::Cushioned => "air-cushioned impact (flat keel, two-phase run with air)",
            ImpactStatus::NotCrossed => "the analytic contact does not reach the sensor in the run",
            ImpactStatus::WettedAtStart => "wetted at the start of the run: no impact",
            ImpactStatus::AfterRecord => "the run ends before the impact window",
        }
    }
}

/// The expected impact window of one sensor, from the analytic contact half-width.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ImpactWindow {
    /// When the analytic contact reaches the sensor's lower and upper edge (s).
    pub crossing_start_s: f64,
    pub crossing_end_s: f64,
    /// The window (s).
    pub start_s: f64,
    pub end_s: f64,
}

impl ImpactWindow {
    /// The window around the crossing [`t_lo`, `t_hi`] (module notes), with spacing `dp` and the downward
    /// speed `v` at `t_hi`.
    pub fn around(t_lo: f64, t_hi: f64, dp: f64, v: f64) -> Self {
        let lag = if v > 0.0 { LAG_SPACINGS * dp / v } else { 0.0 };
        Self {
            crossing_start_s: t_lo,
            crossing_end_s: t_hi,
            start_s: t_lo * (1.0 - WINDOW_FRACTION),
            end_s: t_hi * (1.0 + WINDOW_FRACTION) + lag,
        }
    }

    /// The window of a cushioned sensor ([`ImpactStatus::Cushioned`]): from `t_start`, the start of the
    /// run (the keel above the calm surface by the air gap), to Wagner's crossing of the sensor's upper
    /// edge `t_hi` widened as [`ImpactWindow::around`] widens it.
    pub fn cushioned(t_start: f64, t_hi: f64, dp: f64, v: f64) -> Self {
        let lag = if v > 0.0 { LAG_SPACINGS * dp / v } else { 0.0 };
        Self {
            crossing_start_s: t_start,
            crossing_end_s: t_hi,
            start_s: t_start,
            end_s: t_hi.max(0.0) * (1.0 + WINDOW_FRACTION) + lag,
        }
    }

    /// The impact duration the peak-time match is measured against (s): the time from the start of the
    /// entry (or of the approach through the air gap, for a cushioned sensor) to the end of the crossing,
    /// the time scale of a self-similar impact (every time of a constant-speed wedge entry scales with
    /// it).
    pub fn duration(&self) -> f64 {
        self.crossing_end_s - self.crossing_start_s.min(0.0)
    }
}

/// What the record is measured against: its expected impact (or why there is none) and its phases.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Expectation {
    /// The impact window, for a record whose impact the run can resolve.
    pub window: Option<ImpactWindow>,
    /// Why there is no window (anything but [`ImpactStatus::Resolved`] when `window` is `None`).
    pub status: ImpactStatus,
    /// End of the contact transient (s).
    pub transient_end_s: f64,
    /// The analytic contact half-width when the contact has crossed the record's sensor (m), where it
    /// crosses it at all.
    pub crossing_half_width_m: Option<f64>,
    /// The local deadrise of the record's sensor (deg): the slope of the chord of its integration span
    /// on the contour; `None` for the section force.
    pub local_deadrise_deg: Option<f64>,
}

/// The anatomy of one record.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Anatomy {
    pub status: ImpactStatus,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub window: Option<ImpactWindow>,
    /// Start of the record's end phase (s).
    pub record_end_from_s: f64,
    /// The slamming peak: the largest value in the impact window (total, hydrostatic included), with its
    /// time; the impulse is over the window.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub slamming_peak: Option<Peak>,
    /// The hydrostatic part at the time of the slamming peak (Pa for a sensor, N/m for a force).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub hydrostatic_at_peak: Option<f64>,
    /// The slamming peak is the last sample of the window and the record still rises after it: the
    /// window's end cuts a load that grows into the immersion.
    pub at_window_end: bool,
    /// The largest value after the contact transient, with the phase it lies in and its hydrostatic
    /// part.
    pub largest: Peak,
    pub largest_phase: Phase,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub hydrostatic_at_largest: Option<f64>,
    /// Samples left out as isolated spikes.
    pub spikes: usize,
    /// The analytic contact half-width when the contact has crossed the sensor (m): over the particle
    /// spacing, the particles across the wetted half-width at the crossing.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub crossing_half_width_m: Option<f64>,
    /// Rise time of the slamming peak (s): from the last time before the peak, within the window, that the
    /// record was below a tenth of the peak.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub rise_time_s: Option<f64>,
    /// The local deadrise of the sensor (deg), as in [`Expectation::local_deadrise_deg`].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub local_deadrise_deg: Option<f64>,
}

impl Anatomy {
    /// The sensor's side is steep enough that no impact pulse crosses it (local deadrise at least
    /// [`KEEL_MAXIMUM_FROM_DEG`]): its slamming value is the largest of a slowly varying pressure in the
    /// window, a level rather than the peak of an event.
    pub fn without_pulse(&self) -> bool {
        self.local_deadrise_deg
            .is_some_and(|b| b >= KEEL_MAXIMUM_FROM_DEG)
    }

    /// The slamming value net of the hydrostatic part.
    pub fn slamming_net(&self) -> Option<f64> {
        self.slamming_peak
            .map(|p| p.value - self.hydrostatic_at_peak.unwrap_or(0.0))
    }

    /// One sentence for reports.
    pub fn statement(&self, unit_scale: f64, unit: &str) -> String {
        let v = |x: f64| format!("{:.3} {unit}", x * unit_scale);
        match (&self.slamming_peak, &self.window) {
            (Some(p), Some(w)) => format!(
                "slamming peak {} at {:.1} ms (impact window {:.1}-{:.1} ms){}{}",
                v(p.value),
                p.time * 1e3,
                w.start_s * 1e3,
                w.end_s * 1e3,
                self.hydrostatic_at_peak
                    .map_or(String::new(), |h| format!(", hydrostatic part {}", v(h))),
                if self.at_window_end {
                    "; still rising at the window's end (no distinct impact peak)"
                } else {
                    ""
                }
            ),
            _ => format!(
                "{}; largest value {} at {:.1} ms ({})",
                self.status.describe(),
                v(self.largest.value),
                self.largest.time * 1e3,
                self.largest_phase.describe()
            ),
        }
    }
}

/// The phase of time `t` under `e`, with the record's end phase starting at `end_from`.
pub fn phase_at(t: f64, e: &Expectation, end_from: f64) -> Phase {
    if t < e.transient_end_s {
        Phase::ContactTransient
    } else if t >= end_from {
        Phase::RecordEnd
    } else {
        match &e.window {
            Some(w) if t < w.start_s => Phase::BeforeImpact,
            Some(w) if t <= w.end_s => Phase::Impact,
            Some(_) => Phase::Immersion,
            None => match e.status {
                ImpactStatus::NotCrossed | ImpactStatus::AfterRecord => Phase::BeforeImpact,
                _ => Phase::Immersion,
            },
        }
    }
}

/// Whether sample `k` of `x` is an isolated spike (module notes).
fn is_spike(x: &[f64], k: usize) -> bool {
    if k == 0 || k + 1 >= x.len() || x[k] <= 0.0 {
        return false;
    }
    x[k] > SPIKE_RATIO * x[k - 1].max(x[k + 1]).max(0.0)
}

/// The anatomy of the record (`t`, `x`) under the expectation `e`; `hydrostatic(t)` is the hydrostatic
/// part of the quantity at time t.
pub fn anatomy(t: &[f64], x: &[f64], e: &Expectation, hydrostatic: &dyn Fn(f64) -> f64) -> Anatomy {
    let n = t.len().min(x.len());
    let (t, x) = (&t[..n], &x[..n]);
    let (t0, t1) = (
        t.first().copied().unwrap_or(0.0),
        t.last().copied().unwrap_or(0.0),
    );
    let end_from = t1 - RECORD_END_FRACTION * (t1 - t0);
    let k_tr = t.partition_point(|&s| s < e.transient_end_s);
    let spikes: Vec<bool> = (0..n).map(|k| is_spike(x, k)).collect();
    let arg_max = |r: std::ops::Range<usize>| -> Option<usize> {
        r.filter(|&k| !spikes[k])
            .max_by(|&a, &b| x[a].total_cmp(&x[b]).then(b.cmp(&a)))
    };
    let largest_k = arg_max(k_tr..n);
    let largest = largest_k.map_or(
        Peak {
            value: 0.0,
            time: 0.0,
            impulse: 0.0,
        },
        |k| Peak {
            value: x[k],
            time: t[k],
            impulse: trapezoid(t, x),
        },
    );
    let largest_phase = phase_at(largest.time, e, end_from);
    let mut out = Anatomy {
        status: e.status,
        window: e.window,
        record_end_from_s: end_from,
        slamming_peak: None,
        hydrostatic_at_peak: None,
        at_window_end: false,
        hydrostatic_at_largest: largest_k.map(|_| hydrostatic(largest.time)),
        largest,
        largest_phase,
        spikes: spikes.iter().filter(|&&s| s).count(),
        crossing_half_width_m: e.crossing_half_width_m,
        rise_time_s: None,
        local_deadrise_deg: e.local_deadrise_deg,
    };
    let Some(w) = e.window else {
        return out;
    };
    let a = t.partition_point(|&s| s < w.start_s.max(e.transient_end_s));
    let b = t.partition_point(|&s| s <= w.end_s.min(end_from) && s < end_from);
    if a >= b {
        out.status = if w.start_s >= end_from {
            ImpactStatus::AfterRecord
        } else {
            ImpactStatus::InTransient
        };
        return out;
    }
    let Some(k) = arg_max(a..b) else {
        return out;
    };
    if e.status != ImpactStatus::Cushioned {
        out.status = ImpactStatus::Resolved;
    }
    out.slamming_peak = Some(Peak {
        value: x[k],
        time: t[k],
        impulse: trapezoid(&t[a..b], &x[a..b]),
    });
    out.hydrostatic_at_peak = Some(hydrostatic(t[k]));
    let foot = (a..k).rev().find(|&j| x[j] < 0.1 * x[k]).unwrap_or(a);
    out.rise_time_s = Some(t[k] - t[foot]);
    out.at_window_end = k + 1 == b && b < n && x[b] > x[k];
    if k == a && a == k_tr && a > 0 && x[a - 1] > x[a] {
        // the window opens at the end of the transient and the record is still falling from it: the
        // transient's tail, not an impact
        out.status = ImpactStatus::InTransient;
        out.slamming_peak = None;
        out.hydrostatic_at_peak = None;
    }
    out
}

/// The time at which the non-decreasing `c` (sampled at `t`) first reaches `y`, linearly interpolated;
/// `None` if it never does.
pub fn time_reaching(t: &[f64], c: &[f64], y: f64) -> Option<f64> {
    let k = c.iter().position(|&x| x >= y)?;
    if k == 0 {
        return Some(t[0]);
    }
    let (c0, c1) = (c[k - 1], c[k]);
    let f = if c1 > c0 { (y - c0) / (c1 - c0) } else { 1.0 };
    Some(t[k - 1] + f * (t[k] - t[k - 1]))
}

/// Two slamming peaks at successive resolutions are the same physical event when both are resolved and
/// their times differ by at most [`MATCH_FRACTION`] of the finer run's impact duration; `Err` says why
/// not. On a sensor without an impact pulse ([`Anatomy::without_pulse`]) the two values are the largest
/// of the same slowly varying pressure in the window, whose time is not an event's: both resolved is
/// enough, and the levels are compared by value.
pub fn matched(fine: &Anatomy, coarse: &Anatomy) -> std::result::Result<(), String> {
    let (Some(pf), Some(w)) = (&fine.slamming_peak, &fine.window) else {
        return Err(format!(
            "the reported run has no slamming peak ({})",
            fine.status.describe()
        ));
    };
    let Some(pc) = &coarse.slamming_peak else {
        return Err(format!(
            "the companion has no peak in the impact window ({})",
            coarse.status.describe()
        ));
    };
    let tol = MATCH_FRACTION * w.duration();
    if !fine.without_pulse() && (pf.time - pc.time).abs() > tol {
        return Err(format!(
            "the peaks are different events: {:.1} ms against {:.1} ms, more than {:.0} % of the {:.1} ms \
             impact duration apart",
            pf.time * 1e3,
            pc.time * 1e3,
            MATCH_FRACTION * 100.0,
            w.duration() * 1e3
        ));
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn grid(n: usize, dt: f64) -> Vec<f64> {
        (0..n).map(|k| k as f64 * dt).collect()
    }

    fn expect(window: Option<ImpactWindow>, tr: f64) -> Expectation {
        Expectation {
            window,
            status: if window.is_some() {
                ImpactStatus::Resolved
            } else {
                ImpactStatus::NotCrossed
            },
            transient_end_s: tr,
            crossing_half_width_m: None,
            local_deadrise_deg: None,
        }
    }

    /// A pulse peaking at `tp` with height `h`, rising over `rise` and decaying over `3 rise`.
    fn pulse(t: f64, tp: f64, h: f64, rise: f64) -> f64 {
        if t < tp - rise {
            0.0
        } else if t < tp {
            h * (t - (tp - rise)) / rise
        } else {
            (h * (1.0 - (t - tp) / (3.0 * rise))).max(0.0)
        }
    }

    #[test]
    fn an_end_spike_is_never_the_slamming_peak() {
        // impact of 1.8 kPa at 40 ms; the record rises to 2.8 kPa in its last samples (S174-4)
        let t = grid(1801, 1e-4);
        let x: Vec<f64> = t
            .iter()
            .map(|&s| pulse(s, 0.04, 1800.0, 0.005) + if s > 0.175 { 2800.0 } else { 0.0 })
            .collect();
        let w = ImpactWindow::around(0.03, 0.04, 0.002, 1.0);
        let a = anatomy(&t, &x, &expect(Some(w), 0.002), &|_| 0.0);
        let p = a.slamming_peak.unwrap();
        assert!((p.value - 1800.0).abs() < 1.0, "{p:?}");
        assert!((p.time - 0.04).abs() < 2e-4);
        assert_eq!(a.largest_phase, Phase::RecordEnd);
        assert!(a.largest.value > 2700.0);
    }

    #[test]
    fn a_later_swing_of_a_slow_entry_is_not_the_slamming_peak() {
        // S174-3 of the committed Ochi assessment: crossing 12.7-25.1 ms at 1.1 m/s with dp 10.4 mm, an
        // impact of 1.6 kPa at 25.7 ms and a swing of the side jet to 2.2 kPa at 92 ms
        let t = grid(1700, 1e-4);
        let x: Vec<f64> = t
            .iter()
            .map(|&s| pulse(s, 0.0257, 1600.0, 0.006) + pulse(s, 0.092, 2200.0, 0.01))
            .collect();
        let w = ImpactWindow::around(0.0127, 0.0251, 0.010375, 1.1);
        assert!(w.end_s < 0.0251 * (1.0 + WINDOW_FRACTION) + 0.01, "{w:?}");
        let a = anatomy(&t, &x, &expect(Some(w), 0.019), &|_| 0.0);
        let p = a.slamming_peak.unwrap();
        assert!((p.time - 0.0257).abs() < 2e-4, "{p:?}");
        assert!((p.value - 1600.0).abs() < 1.0);
        assert_eq!(a.largest_phase, Phase::Immersion);
    }

    #[test]
    fn a_transient_tail_is_not_an_impact() {
        // the record falls from the contact transient and the window opens at its end
        let t = grid(1000, 1e-4);
        let x: Vec<f64> = t.iter().map(|&s| 60_000.0 * (-s / 0.002).exp()).collect();
        let w = ImpactWindow::around(0.0005, 0.001, 0.001, 1.0);
        let a = anatomy(&t, &x, &expect(Some(w), 0.004), &|_| 0.0);
        assert_eq!(a.slamming_peak, None);
        assert_eq!(a.status, ImpactStatus::InTransient);
    }

    #[test]
    fn a_late_hydrostatic_rise_is_immersion_not_impact() {
        // an impact of 2 kPa at 20 ms, then a hydrostatic rise to 3.4 kPa at 120 ms (S093-1)
        let t = grid(1801, 1e-4);
        let x: Vec<f64> = t
            .iter()
            .map(|&s| pulse(s, 0.02, 2000.0, 0.004) + 3400.0 * (s / 0.12).min(1.0).powi(2))
            .collect();
        let w = ImpactWindow::around(0.014, 0.019, 0.001, 1.2);
        let hydro = |s: f64| 3400.0 * (s / 0.12).min(1.0).powi(2);
        let a = anatomy(&t, &x, &expect(Some(w), 0.002), &hydro);
        let p = a.slamming_peak.unwrap();
        assert!(p.time < 0.04, "{p:?}");
        assert!(p.value < 2300.0, "{p:?}");
        assert!((a.hydrostatic_at_peak.unwrap() - hydro(p.time)).abs() < 1e-9);
        assert_eq!(a.largest_phase, Phase::Immersion);
        assert!(a.slamming_net().unwrap() < p.value);
    }

    #[test]
    fn an_isolated_spike_is_left_out() {
        let t = grid(1000, 1e-4);
        let mut x: Vec<f64> = t.iter().map(|&s| pulse(s, 0.03, 1000.0, 0.005)).collect();
        x[350] = 9000.0;
        let w = ImpactWindow::around(0.025, 0.03, 0.001, 1.0);
        let a = anatomy(&t, &x, &expect(Some(w), 0.002), &|_| 0.0);
        assert_eq!(a.spikes, 1);
        assert!((a.slamming_peak.unwrap().value - 1000.0).abs() < 1.0);
    }

    #[test]
    fn a_window_after_the_record_says_so() {
        let t = grid(100, 1e-3);
        let x = vec![1.0; 100];
        let w = ImpactWindow::around(0.2, 0.3, 0.001, 1.0);
        let a = anatomy(&t, &x, &expect(Some(w), 0.002), &|_| 0.0);
        assert_eq!(a.status, ImpactStatus::AfterRecord);
        assert_eq!(a.slamming_peak, None);
    }

    /// The mismatched pairs of the committed Ochi report (fine peak, companion peak, in ms) are told
    /// apart from a matched one.
    #[test]
    fn peaks_of_different_events_do_not_match() {
        let mk = |tp: f64, w: ImpactWindow| Anatomy {
            status: ImpactStatus::Resolved,
            window: Some(w),
            record_end_from_s: 1.0,
            slamming_peak: Some(Peak {
                value: 1.0,
                time: tp,
                impulse: 0.0,
            }),
            hydrostatic_at_peak: None,
            at_window_end: false,
            largest: Peak {
                value: 1.0,
                time: tp,
                impulse: 0.0,
            },
            largest_phase: Phase::Impact,
            hydrostatic_at_largest: None,
            spikes: 0,
            crossing_half_width_m: None,
            rise_time_s: None,
            local_deadrise_deg: None,
        };
        // S174-1, S174-2, S227-4 and the 0.227 Lpp section force: windows of about the crossing times
        for (fine, coarse, lo, hi) in [
            (26.5e-3, 106.9e-3, 0.015, 0.025),
            (134.9e-3, 177.9e-3, 0.06, 0.09),
            (135.9e-3, 82.5e-3, 0.06, 0.09),
            (46.5e-3, 114.3e-3, 0.002, 0.06),
        ] {
            let w = ImpactWindow::around(lo, hi, 0.001, 1.0);
            assert!(
                matched(&mk(fine, w), &mk(coarse, w)).is_err(),
                "{fine} {coarse}"
            );
        }
        let w = ImpactWindow::around(0.02, 0.03, 0.001, 1.0);
        assert!(matched(&mk(0.031, w), &mk(0.033, w)).is_ok());
        let mut none = mk(0.03, w);
        none.slamming_peak = None;
        let why = matched(&mk(0.031, w), &none).unwrap_err();
        assert!(why.contains("companion has no peak"), "{why}");
    }

    #[test]
    fn levels_of_a_steep_side_are_compared_by_value_not_time() {
        // a side of S174-3's 50 deg: the fine run's largest value at 25.7 ms, the companion's at 37 ms,
        // both in the window of 7.5-47.0 ms, more than a quarter of the 25 ms crossing apart
        let w = ImpactWindow::around(0.015, 0.025, 0.0104, 1.1);
        let mk = |t: f64, deg: Option<f64>| {
            let e = Expectation {
                window: Some(w),
                status: ImpactStatus::Resolved,
                transient_end_s: 0.0,
                crossing_half_width_m: None,
                local_deadrise_deg: deg,
            };
            let tt: Vec<f64> = (0..=1000).map(|k| k as f64 * 1e-4).collect();
            let x: Vec<f64> = tt
                .iter()
                .map(|&s| (-((s - t) / 0.004).powi(2)).exp())
                .collect();
            anatomy(&tt, &x, &e, &|_| 0.0)
        };
        let steep = KEEL_MAXIMUM_FROM_DEG + 7.8;
        assert!(mk(0.0257, Some(steep)).without_pulse());
        assert!(matched(&mk(0.0257, Some(steep)), &mk(0.037, Some(steep))).is_ok());
        // the same times on a side below the angle are different events
        let low = KEEL_MAXIMUM_FROM_DEG - 4.2;
        assert!(!mk(0.0257, Some(low)).without_pulse());
        assert!(matched(&mk(0.0257, Some(low)), &mk(0.037, Some(low))).is_err());
        // steep or not, a companion without a value in the window does not match
        let mut none = mk(0.037, Some(steep));
        none.slamming_peak = None;
        assert!(matched(&mk(0.0257, Some(steep)), &none).is_err());
    }
}
