//! Sanity checks on inputs and results that are not errors but that a naval architect must see: they are
//! printed with the text tables, stored in the JSON `warnings` and written into the report files.

use crate::hull::Hydrostatics;
use crate::sea::IrregularSea;
use crate::seakeeping::analysis::{RegularStation, Report};
use crate::seakeeping::slamming::SampledSpectrum;

/// Largest relative error of the sampled spectrum's variance before `--spectrum-samples` is called too
/// small.
pub const SPECTRUM_SAMPLING_TOLERANCE: f64 = 0.02;

/// Warnings for a negative transverse or longitudinal metacentric height.
pub fn negative_gm(h: &Hydrostatics) -> Vec<String> {
    let mut w = Vec::new();
    for (what, gm) in [("GM_T", h.gm_t), ("GM_L", h.gm_l)] {
        if gm < 0.0 {
            w.push(format!(
                "loading '{}': negative {what} ({gm:.4} m): the ship as loaded is unstable; check kg_m",
                h.loading
            ));
        }
    }
    w
}

/// Largest waterline beam over Lpp that is not called implausible: no ship is wider than it is long.
pub const MAX_BEAM_OVER_LPP: f64 = 1.0;

/// Warnings for a hull form no ship has, each with the number that triggered it: a block coefficient
/// above 1 (more displacement than the box Lpp x B x T holds: offsets that run far aft of the AP or
/// forward of the FP, or a length or draft that does not belong to them), and a waterline beam above
/// [`MAX_BEAM_OVER_LPP`] times Lpp (offsets in the wrong unit).
pub fn implausible_form(h: &Hydrostatics, x_range: (f64, f64)) -> Vec<String> {
    let mut w = Vec::new();
    let l = h.lpp_m;
    if h.cb > 1.0 + 1e-6 {
        let (aft, fwd) = (-x_range.0 - 0.5 * l, x_range.1 - 0.5 * l);
        w.push(format!(
            "loading '{}': block coefficient Cb = {:.3} is above 1: the immersed hull is larger than the box Lpp x \
             B x T it should fit in; the offsets reach {:.3} m aft of the AP and {:.3} m forward of the FP \
             (Lpp = {l} m): check lpp_m and the stations' x",
            h.loading,
            h.cb,
            aft.max(0.0),
            fwd.max(0.0)
        ));
    }
    if h.beam_wl_m > MAX_BEAM_OVER_LPP * l {
        w.push(format!(
            "loading '{}': the waterline beam {:.4} m is {:.1} times Lpp ({l} m): no ship is wider than it is \
             long; check the units of the offsets (metres)",
            h.loading,
            h.beam_wl_m,
            h.beam_wl_m / l
        ));
    }
    w
}

/// Relative error of the variance (m0) of `sea`'s spectrum sampled with `n` points over the window the
/// motions analysis uses (0.4 to 3.5 times the peak frequency), against a fine sampling of that window.
pub fn spectrum_sampling_error(sea: &IrregularSea, n: usize) -> f64 {
    let wp = sea.spectrum.peak_frequency();
    let m0 = |n: usize| {
        SampledSpectrum::from_fn(|w| sea.spectrum.density(w), 0.4 * wp, 3.5 * wp, n)
            .map_or(f64::NAN, |s| s.m0())
    };
    let fine = m0(4001);
    ((m0(n.max(3)) - fine) / fine).abs()
}

/// A warning when `n` samples do not resolve a spectrum, with the number that would.
pub fn spectrum_samples(sea: &IrregularSea, n: usize) -> Option<String> {
    let err = spectrum_sampling_error(sea, n);
    if err.is_finite() && err <= SPECTRUM_SAMPLING_TOLERANCE {
        return None;
    }
    let enough = (1..=10)
        .map(|k| n.max(3) << k)
        .find(|&m| spectrum_sampling_error(sea, m) <= 0.5 * SPECTRUM_SAMPLING_TOLERANCE);
    Some(format!(
        "--spectrum-samples {n} is too few for the spectrum of '{}': its variance is off by {:.1} % \
         (tolerance {:.0} %){}",
        sea.name,
        100.0 * err,
        100.0 * SPECTRUM_SAMPLING_TOLERANCE,
        enough.map_or(String::new(), |m| format!("; use at least {m}"))
    ))
}

/// Warnings where an operability "limit" is only the highest speed tested: the slam probability stays
/// below the limit at every speed, so the true limit is not known.
pub fn operability_limits(r: &Report) -> Vec<String> {
    let mut w = Vec::new();
    for o in &r.operability {
        let op = &o.operability;
        let top = op.speeds.last().copied();
        if let (Some(l), Some(top)) = (op.limit_speed, top)
            && (l - top).abs() <= 1e-9 * top.abs().max(1.0)
        {
            w.push(format!(
                "irregular sea '{}': no operability limit within the tested speeds (up to {top:.3} m/s); \
                 the limit speed shown is the highest speed tested",
                o.sea
            ));
        }
    }
    w
}

/// What happens at a station in a regular wave, by Ochi's criterion.
#[derive(Debug, Clone, Copy, PartialEq, Eq, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum SlamFlag {
    /// The keel emerges and re-enters faster than the threshold velocity.
    Slam,
    /// The keel emerges but re-enters slower than the threshold velocity.
    EmergesBelowThreshold,
    /// The keel stays in the water.
    NoEmergence,
}

impl SlamFlag {
    /// The flag of one station, against the threshold velocity (m/s).
    pub fn of(station: &RegularStation, threshold_m_per_s: f64) -> Self {
        match &station.keel_entry {
            None => SlamFlag::NoEmergence,
            Some(k) if k.entry_velocity >= threshold_m_per_s => SlamFlag::Slam,
            Some(_) => SlamFlag::EmergesBelowThreshold,
        }
    }

    /// The flag as written in tables and CSV files.
    pub fn text(self) -> &'static str {
        match self {
            SlamFlag::Slam => "slam",
            SlamFlag::EmergesBelowThreshold => "emerges below threshold",
            SlamFlag::NoEmergence => "no emergence",
        }
    }
}

/// One slam flag per speed, regular wave and station, as JSON records.
pub fn regular_slam_flags(r: &Report) -> Vec<serde_json::Value> {
    let mut out = Vec::new();
    for s in &r.speeds {
        for w in &s.regular {
            for t in &w.stations {
                out.push(serde_json::json!({
                    "speed_m_per_s": s.speed_m_s,
                    "wave": w.wave,
                    "station": t.aft_of_fp,
                    "x_m": t.x,
                    "flag": SlamFlag::of(t, r.slam_threshold_velocity_m_s),
                }));
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sea::Spectrum;

    #[test]
    fn coarse_sampling_of_a_peaked_spectrum_is_flagged() {
        let sea = IrregularSea {
            name: "peaked".into(),
            spectrum: Spectrum::jonswap(5.5, 11.0, 7.0),
            duration_h: None,
        };
        assert!(spectrum_samples(&sea, 5).is_some());
        assert!(spectrum_samples(&sea, 200).is_none());
        let w = spectrum_samples(&sea, 5).unwrap();
        assert!(w.contains("use at least"), "{w}");
    }
}
