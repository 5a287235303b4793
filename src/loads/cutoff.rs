//! The default low-pass cut-off of the sensor records of a hull-section water entry, chosen from the
//! physics of the impact rather than from the numerics.
//!
//! A pressure panel of width w reads the mean pressure over its surface. As the wetted contact (the jet
//! root, where the slamming pressure peaks) moves up the section, the panel's mean pressure rises from
//! nothing to its peak in the time the contact takes to cross it,
//!
//! tau = t(c = y_hi) - t(c = y_lo),
//!
//! where c(t) is the wetted half-width of the generalised Wagner theory (Wagner 1932; the wetting
//! condition for the actual section, [`crate::analytic::generalised_wagner`]) along the event's entry
//! velocity v(t), and y_lo, y_hi are the half-breadths at the panel's lower and upper edges. Where the
//! contact point would move faster than sound (a flat keel at contact) the pressure builds up acoustically
//! instead, so tau is never taken shorter than the acoustic crossing (y_hi - y_lo) / c0. Content faster
//! than the quickest physical rise, tau_min over the panels the contact crosses, is not slamming: it is
//! the acoustic and particle noise of weakly compressible SPH. The cut-off is
//!
//! f_c = 2 / tau_min,
//!
//! for which the zero-phase second-order Butterworth pass of [`crate::loads::summarise`] keeps at least
//! 90 % of the peak of a pulse rising over tau (the test below checks this on a ramp-and-decay pulse).
//! A cut-off above a quarter of the sampling rate of the coarsest record would leave fewer than four
//! samples per rise: the records are then left unfiltered and the note says why.

use crate::analytic::generalised_wagner;
use crate::sph::SensorSpec;
use crate::sph::body::{Section, point_at_arc};

/// Ratio of the cut-off frequency to the inverse of the quickest rise time, f_c tau_min.
pub const CUTOFF_TIMES_RISE: f64 = 2.0;

/// Largest cut-off as a fraction of the sampling rate of the coarsest record.
pub const MAX_CUTOFF_OVER_SAMPLE_RATE: f64 = 0.25;

/// A chosen cut-off, with the statement of how it was chosen.
#[derive(Debug, Clone, PartialEq)]
pub struct Cutoff {
    /// Cut-off frequency (Hz), or `None` when the records are left unfiltered.
    pub hz: Option<f64>,
    /// How it was chosen (for the run's setup notes and the report).
    pub note: String,
}

/// The time at which the increasing half-width `c` first reaches `y`, linearly interpolated.
fn time_reaching(t: &[f64], c: &[f64], y: f64) -> Option<f64> {
    let k = c.iter().position(|&x| x >= y)?;
    if k == 0 {
        return Some(t[0]);
    }
    let (c0, c1) = (c[k - 1], c[k]);
    let f = if c1 > c0 { (y - c0) / (c1 - c0) } else { 1.0 };
    Some(t[k - 1] + f * (t[k] - t[k - 1]))
}

/// The cut-off for the sensor records of `section`, started with its keel `d0` (m) deep in water at rest
/// (0: keel entry) and driven by the downward velocity samples (`t`, `v`) from the start, with sound
/// speed `c0` (m/s), where the coarsest record is sampled at `coarsest_sample_hz`. Sensors already wetted
/// at the start are not crossed by the contact and set no rise time. Without a Wagner estimate of the
/// section the records are left unfiltered, and the note says why.
pub fn slamming_cutoff(
    section: &Section,
    d0: f64,
    t: &[f64],
    v: &[f64],
    sensors: &[SensorSpec],
    c0: f64,
    coarsest_sample_hz: f64,
) -> Cutoff {
    let est = match generalised_wagner::estimate_immersed(section.half_points(), d0, t, v, 1000.0) {
        Ok(e) if !e.half_width.is_empty() => e,
        Ok(_) => {
            return Cutoff {
                hz: None,
                note: "no low-pass filter: the Wagner estimate of this run is empty (raw records only)"
                    .into(),
            };
        }
        Err(e) => {
            return Cutoff {
                hz: None,
                note: format!(
                    "no low-pass filter: no Wagner estimate of this section to set a cut-off ({e}); \
                     raw records only"
                ),
            };
        }
    };
    let wetted_at_start = if d0 > 0.0 { est.half_width[0] } else { 0.0 };
    let mut quickest: Option<(f64, &str)> = None;
    for q in sensors {
        let edge = |s: f64| point_at_arc(section, s).map(|p| p[0].abs());
        let (Some(y_lo), Some(y_hi)) =
            (edge(q.s_m - 0.5 * q.width_m), edge(q.s_m + 0.5 * q.width_m))
        else {
            continue;
        };
        let (y_lo, y_hi) = (y_lo.min(y_hi), y_lo.max(y_hi));
        if y_lo < wetted_at_start {
            continue;
        }
        let (Some(t_lo), Some(t_hi)) = (
            time_reaching(&est.t, &est.half_width, y_lo),
            time_reaching(&est.t, &est.half_width, y_hi),
        ) else {
            continue;
        };
        let tau = (t_hi - t_lo).max((y_hi - y_lo) / c0);
        if tau > 0.0 && quickest.is_none_or(|(best, _)| tau < best) {
            quickest = Some((tau, &q.name));
        }
    }
    let Some((tau, name)) = quickest else {
        return Cutoff {
            hz: None,
            note:
                "no low-pass filter: Wagner's wetted contact crosses no sensor of this run, so no \
                   slamming rise time sets a cut-off (raw records only)"
                    .into(),
        };
    };
    let fc = CUTOFF_TIMES_RISE / tau;
    let limit = MAX_CUTOFF_OVER_SAMPLE_RATE * coarsest_sample_hz;
    if fc <= limit {
        Cutoff {
            hz: Some(fc),
            note: format!(
                "low-pass cut-off f_c = 2 / tau = {fc:.0} Hz (zero-phase Butterworth): tau = {:.2} ms, the \
                 quickest rise of a sensor's mean pressure, the time Wagner's wetted contact takes to \
                 cross sensor {name}",
                tau * 1e3
            ),
        }
    } else {
        Cutoff {
            hz: None,
            note: format!(
                "no low-pass filter: the quickest slamming rise (sensor {name}, tau = {:.3} ms, f_c = 2 / tau \
                 = {fc:.0} Hz) is faster than a quarter of the coarsest record's sampling rate \
                 ({coarsest_sample_hz:.0} Hz), so filtering would cut the physics (raw records only)",
                tau * 1e3
            ),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::loads::summarise;

    fn sensor(name: &str, s: f64, w: f64) -> SensorSpec {
        SensorSpec {
            name: name.into(),
            s_m: s,
            width_m: w,
        }
    }

    #[test]
    fn the_rule_keeps_ninety_per_cent_of_a_pulse_rising_over_tau() {
        // a ramp to 1 over tau, then a decay over 3 tau, sampled at 40 samples per tau
        let tau = 2e-3;
        let dt = tau / 40.0;
        let t: Vec<f64> = (0..800).map(|k| k as f64 * dt).collect();
        let t0 = 5.0 * tau;
        let x: Vec<f64> = t
            .iter()
            .map(|&s| {
                let r = s - t0;
                if r < 0.0 {
                    0.0
                } else if r < tau {
                    r / tau
                } else {
                    (1.0 - (r - tau) / (3.0 * tau)).max(0.0)
                }
            })
            .collect();
        let s = summarise(&t, &x, Some(CUTOFF_TIMES_RISE / tau)).unwrap();
        let kept = s.filtered.unwrap().value;
        assert!(kept >= 0.9, "filtered peak {kept}");
        assert!(kept < 1.0);
    }

    #[test]
    fn a_wedge_cutoff_follows_wagner_contact_speed() {
        // 20 deg wedge at 2 m/s: Wagner's c = (pi/2) V t / tan(beta), so a panel with half-breadth edges
        // y_lo, y_hi is crossed in tau = (y_hi - y_lo) tan(beta) / ((pi/2) V)
        let beta = 20f64.to_radians();
        let sec = Section::wedge(beta, 0.3, 0.3).unwrap();
        let t: Vec<f64> = (0..=2000).map(|k| k as f64 * 1e-4).collect();
        let v = vec![2.0; t.len()];
        let (s, w) = (0.15, 0.02);
        let c = slamming_cutoff(&sec, 0.0, &t, &v, &[sensor("S1", s, w)], 50.0, 1e6);
        let dy = w * beta.cos();
        let tau = dy * beta.tan() / (std::f64::consts::FRAC_PI_2 * 2.0);
        let fc = c.hz.unwrap();
        assert!(
            (fc * tau / 2.0 - 1.0).abs() < 0.03,
            "f_c {fc} Hz, tau {tau}"
        );
        assert!(c.note.contains("S1"));
    }

    #[test]
    fn too_quick_a_rise_leaves_the_records_unfiltered() {
        let beta = 20f64.to_radians();
        let sec = Section::wedge(beta, 0.3, 0.3).unwrap();
        let t: Vec<f64> = (0..=2000).map(|k| k as f64 * 1e-4).collect();
        let v = vec![2.0; t.len()];
        let c = slamming_cutoff(&sec, 0.0, &t, &v, &[sensor("S1", 0.15, 0.02)], 50.0, 2000.0);
        assert_eq!(c.hz, None);
        assert!(c.note.contains("no low-pass filter"));
    }
}
