//! The keel-slope term of the 2D+t method: what it adds to an assessment's keel-entry velocities, said
//! in its warnings whether it is on or off.
//!
//! The 2D+t method follows an earth-fixed transverse plane through which the ship passes at speed U. A
//! station whose keel is not parallel to the calm waterline (a forefoot under a raked stem, a keel that
//! rises towards the bow, trim by the stern) therefore sinks in that plane at
//!
//! V_k = U dz_k/dx,
//!
//! z_k(x) the keel's height above the local calm waterline, x forward. The relative motion of strip
//! theory does not contain it: it is the rate at which the section's own shape descends through the
//! plane. Veen (2010, conclusions) applies his 2D+t method to keels that are longitudinally flat, names
//! the "longitudinal fluid velocity for non-flat keels" among the effects it misses, and proposes to
//! include "the relative velocity along the normal of the keel". The 2D+t theory of planing hulls keeps
//! the term: there it is the whole impact velocity U tan(tau) of a hull at trim tau (Faltinsen 2005,
//! Hydrodynamics of High-Speed Marine Vehicles, ch. 9).
//!
//! `assess` leaves it out by default, as Veen does, so that the bundled Ochi model is assessed as the
//! seed's method assesses it. Because leaving it out lowers the entry velocity of a rising forefoot (and
//! the pressures roughly with its square), a station where it would change an entry velocity by 5 % or
//! more gets a warning that names the amount; `--keel-slope-term` adds it to the keel entries of strip
//! theory in regular waves ([`crate::seakeeping::analysis::RegularStation::add_steady_velocity`]) and to
//! the slams of irregular seas ([`crate::seakeeping::slamming::SlamStatistics::with_steady_velocity`]).
//! Flare events (the keel stays immersed, the water reaches a panel above it) and measured
//! relative-motion records are not changed: the slope that matters there is the hull surface's at the
//! panel, not the keel's.

use super::plan::Event;
use crate::seakeeping::analysis::Station;

/// Share of an entry velocity from which leaving the term out is warned about.
pub const WARN_SHARE: f64 = 0.05;

/// How a warning that the term is left out ends ([`lines`]): the report's sign-off page finds the
/// stations by it. Each such warning starts "station <f> Lpp:".
pub const LEFT_OUT: &str = "--keel-slope-term adds it";

/// The largest share |U dz_k/dx| / V of the keel-slope term in the keel-entry velocity V of a station's
/// events (keel entries only; with the term on V contains it), with the event's speed and V.
fn largest_share(station: &Station, events: &[Event]) -> Option<(f64, f64, f64)> {
    events
        .iter()
        .filter(|e| (e.station - station.aft_of_fp).abs() < 1e-9 && e.flare.is_none())
        .filter_map(|e| {
            let v = e.entry_velocity_m_s.filter(|v| *v > 0.0)?;
            let vk = e.speed_m_s * station.keel_slope;
            Some(((vk / v).abs(), e.speed_m_s, v))
        })
        .max_by(|a, b| a.0.total_cmp(&b.0))
}

/// A share as a percentage, with one decimal below 10 % (a small term then does not read "0 %").
fn percent(share: f64) -> String {
    let pc = 100.0 * share;
    if pc < 10.0 {
        format!("{pc:.1} %")
    } else {
        format!("{pc:.0} %")
    }
}

/// The warning and note lines of the keel-slope term for an assessment's `stations` and `events`:
/// with the term off, one warning per station where it would be at least [`WARN_SHARE`] of a keel-entry
/// velocity; with it on, one line per station with a keel slope, stating what it added.
pub fn lines(stations: &[Station], events: &[Event], on: bool) -> Vec<String> {
    let mut out = Vec::new();
    for st in stations {
        let slope = st.keel_slope;
        let Some((share, u, v)) = largest_share(st, events) else {
            continue;
        };
        let vk = u * slope;
        let rises = if slope >= 0.0 {
            "rises towards the bow"
        } else {
            "falls towards the bow"
        };
        if on && slope != 0.0 {
            out.push(format!(
                "station {} Lpp: the keel-slope term is included: the keel {rises} at dz_k/dx = {slope:.4} \
                 above the calm waterline, so the section sinks through the 2D+t plane at U dz_k/dx = \
                 {vk:.3} m/s at {u:.3} m/s, {} of the keel-entry velocity {v:.3} m/s there (flare events \
                 and measured records exclude it)",
                st.aft_of_fp,
                percent(share)
            ));
        } else if !on && share >= WARN_SHARE {
            let effect = if vk > 0.0 { "are low" } else { "are high" };
            // pressures scale about with the square of the entry velocity
            let factor = (v / (v + vk)).powi(2);
            out.push(format!(
                "station {} Lpp: the keel {rises} at dz_k/dx = {slope:.4} above the calm waterline, so in the \
                 2D+t plane the section sinks at U dz_k/dx = {vk:.3} m/s at {u:.3} m/s, {} of the \
                 keel-entry velocity {v:.3} m/s. This assessment leaves that term out, as Veen (2010) does, \
                 so its entry velocities here {effect} by that much, and its pressures, which scale about \
                 with the square of the entry velocity, are about {factor:.2} times what they are with it; \
                 {LEFT_OUT}",
                st.aft_of_fp,
                percent(share)
            ));
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::report::sanity::SlamFlag;

    fn station(slope: f64) -> Station {
        Station {
            aft_of_fp: 0.05,
            x: 10.0,
            draft: 0.2,
            height: 3.0,
            keel_slope: slope,
        }
    }

    fn event(speed: f64, v: f64) -> Event {
        Event {
            station: 0.05,
            x: 10.0,
            speed_m_s: speed,
            wave: "w".into(),
            flag: SlamFlag::Slam,
            entry_velocity_m_s: Some(v),
            entry_time_s: None,
            encounter_period_s: 5.0,
            wave_omega_rad_s: 1.0,
            wave_amplitude_m: 1.0,
            draft_m: 0.2,
            design: None,
            flare: None,
            entry: None,
        }
    }

    #[test]
    fn off_warns_from_five_per_cent_of_the_entry_velocity_and_names_the_amount() {
        // U dz_k/dx = 10 x 0.04 = 0.4 m/s against 10 m/s (4 %) and 5 m/s (8 %): the largest share is
        // stated.
        let events = [event(10.0, 10.0), event(10.0, 5.0)];
        let w = lines(&[station(0.04)], &events, false);
        assert_eq!(w.len(), 1);
        assert!(w[0].contains("0.400 m/s") && w[0].contains("8.0 %") && w[0].contains("are low"));
        // (5 / 5.4)^2
        assert!(w[0].contains("about 0.86 times"), "{}", w[0]);
        // 4 % only: no warning.
        assert!(lines(&[station(0.04)], &events[..1], false).is_empty());
        // A keel falling towards the bow: the entry velocities without the term are high.
        let w = lines(&[station(-0.04)], &events, false);
        assert!(w[0].contains("falls towards the bow") && w[0].contains("are high"));
    }

    #[test]
    fn on_states_what_it_added_and_flat_keels_say_nothing() {
        let events = [event(10.0, 10.4)];
        let w = lines(&[station(0.04)], &events, true);
        assert_eq!(w.len(), 1);
        assert!(w[0].contains("is included") && w[0].contains("0.400 m/s"));
        assert!(lines(&[station(0.0)], &events, true).is_empty());
        assert!(lines(&[station(0.0)], &events, false).is_empty());
    }
}
