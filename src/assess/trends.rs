//! Ochi's (1958) published trends and Veen's (2010) numbers for the Ochi V-form (s. 6.3), beside an
//! assessment of the reconstructed hull. Ochi's peak pressures were published as figures only and are not
//! available; the trends are qualitative (data/reference/ochi1958_vform.toml, `[published_findings]`).
//! Each check is a function of the design values the assessment reports (per station, or per event
//! through [`EventResult::sensor_peak`]), whatever rule computes them, and is the one implementation both
//! the design report and `slamtool validate` (src/validate/ochi_trends.rs) use, so the two reports give
//! the same verdict on the same assessment.

use super::comparisons::{Comparison, OCHI, TrendCheck, Validation, reference_number, sensor_peak};
use super::results::{Assessment, EventResult, StationResult};
use crate::error::Result;

const SOURCE: &str = "Ochi (1958), findings as reported by Veen (2010) s. 6.3 \
(data/reference/ochi1958_vform.toml [published_findings])";
const VEEN: &str = "Veen (2010) s. 6.3, 2D SPH with SEAWAY relative motion \
(data/reference/ochi1958_vform.toml [veen2010_sph])";

pub(crate) fn same(a: f64, b: f64) -> bool {
    (a - b).abs() < 1e-6
}

/// The station's sensors from the keel up (by girth).
fn by_girth(st: &StationResult) -> Vec<&str> {
    let mut s: Vec<_> = st.sensors.iter().collect();
    s.sort_by(|a, b| a.girth_m.total_cmp(&b.girth_m));
    s.iter().map(|q| q.name.as_str()).collect()
}

/// What a trend check finds.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Found {
    Reproduced,
    NotReproduced,
    /// Too few stations or speeds with a pressure to tell.
    NotAssessed,
}

impl Found {
    fn of(ok: bool) -> Self {
        if ok {
            Found::Reproduced
        } else {
            Found::NotReproduced
        }
    }

    /// The verdict as both reports print it.
    pub fn label(self) -> &'static str {
        match self {
            Found::Reproduced => "reproduced",
            Found::NotReproduced => "not reproduced",
            Found::NotAssessed => "not assessed",
        }
    }
}

/// Ochi's "the maximum pressure is near the keel", station by station: the largest design pressure of
/// each station with a positive one ([`StationResult::design_pressure_pa`], whatever rule the assessment
/// uses for it) and the station's keel sensor (the sensor of least girth).
#[derive(Debug, Clone, Default)]
pub struct KeelTrend {
    /// (station, sensor with the largest design pressure, its value in Pa, its source, keel sensor).
    pub rows: Vec<(f64, String, f64, &'static str, String)>,
    /// Stations left out because their keel sensor has no design value (a flat keel's air-cushion
    /// impact, [`crate::assess::design_rule::NO_VALUE_FLAT_KEEL`]): whether the keel carries the largest
    /// pressure there cannot be told. (station, keel sensor, its design source.)
    pub without_keel_value: Vec<(f64, String, &'static str)>,
}

impl KeelTrend {
    pub fn of(a: &Assessment) -> Self {
        let mut rows = Vec::new();
        let mut without_keel_value = Vec::new();
        for st in &a.stations {
            let keel = by_girth(st).first().map(|k| k.to_string());
            let keel_none = keel.as_ref().and_then(|k| {
                st.design_pressure_pa
                    .iter()
                    .find(|d| &d.name == k && d.value.is_none())
            });
            if let Some(d) = keel_none {
                without_keel_value.push((st.station, d.name.clone(), d.source));
                continue;
            }
            let best = st
                .design_pressure_pa
                .iter()
                .filter_map(|p| p.value.map(|v| (p, v)))
                .max_by(|p, q| p.1.total_cmp(&q.1));
            if let Some((b, v)) = best
                && v > 0.0
            {
                let keel = keel.unwrap_or_else(|| st.design_pressure_pa[0].name.clone());
                rows.push((st.station, b.name.clone(), v, b.source, keel));
            }
        }
        KeelTrend {
            rows,
            without_keel_value,
        }
    }

    /// Stations whose largest design pressure is on the keel sensor, over the stations counted.
    pub fn fraction(&self) -> Option<f64> {
        let keel = self.rows.iter().filter(|r| r.1 == r.4).count();
        (!self.rows.is_empty()).then(|| keel as f64 / self.rows.len() as f64)
    }

    pub fn found(&self) -> Found {
        match self.fraction() {
            None => Found::NotAssessed,
            Some(f) => Found::of(f >= 1.0),
        }
    }

    /// The stations where the largest design pressure is not on the keel sensor, with the numbers.
    pub fn off_keel(&self) -> String {
        let v: Vec<String> = self
            .rows
            .iter()
            .filter(|r| r.1 != r.4)
            .map(|r| {
                format!(
                    "{} Lpp ({} {:.2} kPa, {}; keel sensor {})",
                    r.0,
                    r.1,
                    r.2 / 1e3,
                    r.3,
                    r.4
                )
            })
            .collect();
        if v.is_empty() {
            "no station".into()
        } else {
            v.join(", ")
        }
    }

    pub fn detail(&self) -> String {
        self.rows
            .iter()
            .map(|r| {
                format!(
                    "station {}: largest {} {:.2} kPa ({}), keel sensor {}",
                    r.0,
                    r.1,
                    r.2 / 1e3,
                    r.3,
                    r.4
                )
            })
            .chain(self.without_keel_value.iter().map(|(st, k, src)| {
                format!("station {st}: not counted, keel sensor {k} has no design value ({src})")
            }))
            .collect::<Vec<_>>()
            .join("; ")
    }
}

/// Ochi's "increasing forward speed moves the location of the maximum pressure aft": per speed, the
/// station of the largest per-event design sensor peak ([`EventResult::sensor_peak`]). The trend is
/// reproduced when the location never moves forward from one speed to the next and ends aft of where it
/// started by at least half the smallest spacing of the assessed stations: a location that does not move
/// is not the trend.
#[derive(Debug, Clone, Default)]
pub struct SpeedTrend {
    /// (speed m/s, station of the largest peak, the peak in Pa, its source).
    pub track: Vec<(f64, f64, f64, &'static str)>,
    /// The smallest spacing of the assessed stations (fraction of Lpp).
    pub spacing: f64,
}

/// A per-event sensor peak (Pa) and its source.
pub type PeakOf<'a> = &'a dyn Fn(&EventResult, &str) -> Option<(f64, &'static str)>;

impl SpeedTrend {
    /// The trend of the assessment's per-event design values ([`EventResult::sensor_peak`]).
    pub fn of(a: &Assessment) -> Self {
        Self::of_peaks(a, &|e, n| e.sensor_peak(n))
    }

    /// The trend of the analytic estimates alone, for the diagnosis of a difference.
    pub fn of_analytic(a: &Assessment) -> Self {
        Self::of_peaks(a, &|e, n| {
            let an = e.analytic.as_ref()?;
            an.sensors
                .iter()
                .find(|q| q.name == n)
                .map(|q| (q.peak_pa, "analytic"))
        })
    }

    /// The trend of the per-event peaks `peak` gives.
    pub fn of_peaks(a: &Assessment, peak: PeakOf) -> Self {
        let mut speeds: Vec<f64> = a.events.iter().map(|e| e.speed_m_per_s).collect();
        speeds.sort_by(f64::total_cmp);
        speeds.dedup_by(|p, q| same(*p, *q));
        let mut track = Vec::new();
        for &u in &speeds {
            let mut best: Option<(f64, f64, &'static str)> = None;
            for e in a.events.iter().filter(|e| same(e.speed_m_per_s, u)) {
                for st in a.stations.iter().filter(|s| same(s.station, e.station)) {
                    for q in &st.sensors {
                        if let Some((p, src)) = peak(e, &q.name)
                            && p > 0.0
                            && best.is_none_or(|b| p > b.1)
                        {
                            best = Some((e.station, p, src));
                        }
                    }
                }
            }
            if let Some((f, p, src)) = best {
                track.push((u, f, p, src));
            }
        }
        let mut st: Vec<f64> = a.stations.iter().map(|s| s.station).collect();
        st.sort_by(f64::total_cmp);
        let spacing = st
            .windows(2)
            .map(|w| w[1] - w[0])
            .filter(|d| *d > 1e-9)
            .fold(f64::INFINITY, f64::min);
        SpeedTrend { track, spacing }
    }

    /// The largest forward move between consecutive speeds (fraction of Lpp, positive), if any.
    pub fn forward_step(&self) -> Option<(f64, f64, f64, f64, f64)> {
        self.track
            .windows(2)
            .filter(|w| w[1].1 < w[0].1 - 1e-9)
            .map(|w| (w[0].1 - w[1].1, w[0].0, w[0].1, w[1].0, w[1].1))
            .max_by(|p, q| p.0.total_cmp(&q.0))
    }

    /// The measure both reports judge: the shift aft from the lowest to the highest speed, or, where the
    /// location moves forward between two consecutive speeds, minus the largest such move.
    pub fn measure(&self) -> Option<f64> {
        if self.track.len() < 2 {
            return None;
        }
        Some(match self.forward_step() {
            Some(f) => -f.0,
            None => self.track[self.track.len() - 1].1 - self.track[0].1,
        })
    }

    /// The least measure that counts as the trend: half the smallest station spacing.
    pub fn least_shift(&self) -> f64 {
        if self.spacing.is_finite() {
            0.5 * self.spacing
        } else {
            f64::INFINITY
        }
    }

    pub fn found(&self) -> Found {
        match self.measure() {
            None => Found::NotAssessed,
            Some(m) => Found::of(m >= self.least_shift()),
        }
    }

    /// What the track shows, in words with its numbers.
    pub fn finding(&self) -> String {
        let (Some(first), Some(last)) = (self.track.first(), self.track.last()) else {
            return "fewer than two speeds have a pressure".into();
        };
        if let Some((d, u0, f0, u1, f1)) = self.forward_step() {
            return format!(
                "the location moves forward by {d:.3} Lpp, from station {f0} at {u0} m/s to station {f1} \
                 at {u1} m/s"
            );
        }
        if same(first.1, last.1) {
            return format!(
                "the location stays at station {} from {} to {} m/s",
                first.1, first.0, last.0
            );
        }
        format!(
            "the location moves aft from station {} at {} m/s to station {} at {} m/s",
            first.1, first.0, last.1, last.0
        )
    }

    /// Why the track may not show Ochi's trend: how many of its maxima are analytic and how many SPH
    /// peaks, and what the analytic estimates alone show.
    pub fn reading(&self, a: &Assessment) -> String {
        let sph = self.track.iter().filter(|t| t.3.starts_with("sph")).count();
        format!(
            "The maxima of this track come from two models: the maxima of {sph} of its {} speeds from an SPH run, the others \
             from the analytic estimate (SPH runs only where the screening asks for one). Where the two \
             differ, the station of the largest value follows the source rather than the speed. With the \
             analytic estimates alone at every event, {}.",
            self.track.len(),
            Self::of_analytic(a).finding()
        )
    }

    pub fn detail(&self) -> String {
        self.track
            .iter()
            .map(|(u, f, p, src)| format!("{u} m/s: station {f} ({:.2} kPa, {src})", p / 1e3))
            .collect::<Vec<_>>()
            .join("; ")
    }
}

/// Ochi's "at 2.2 m/s the peak pressure falls from the keel sensor towards the chine at the foremost
/// sections", on the two foremost stations: each sensor's largest per-event design peak at 2.2 m/s,
/// keel first.
#[derive(Debug, Clone, Default)]
pub struct ForeTrend {
    /// (station, its sensor peaks from the keel up).
    pub rows: Vec<(f64, Vec<SensorPeak>)>,
}

/// A sensor's name, its peak (Pa) and the peak's source.
pub type SensorPeak = (String, f64, &'static str);

/// The speed of Ochi's finding on the foremost sections (m/s).
pub const FORE_SPEED: f64 = 2.2;

impl ForeTrend {
    pub fn of(a: &Assessment) -> Self {
        let mut fore: Vec<&StationResult> = a.stations.iter().collect();
        fore.sort_by(|p, q| p.station.total_cmp(&q.station));
        fore.truncate(2);
        let mut rows = Vec::new();
        for st in fore {
            let evs: Vec<&EventResult> = a
                .events
                .iter()
                .filter(|e| same(e.station, st.station) && same(e.speed_m_per_s, FORE_SPEED))
                .collect();
            let peaks: Vec<SensorPeak> = by_girth(st)
                .iter()
                .filter_map(|n| sensor_peak(&evs, n).map(|(p, src)| (n.to_string(), p, src)))
                .collect();
            if peaks.len() >= 2 {
                rows.push((st.station, peaks));
            }
        }
        ForeTrend { rows }
    }

    fn falls(peaks: &[SensorPeak]) -> bool {
        peaks.windows(2).all(|w| w[1].1 <= w[0].1)
    }

    /// The stations whose peaks fall from the keel up, over the stations counted.
    pub fn fraction(&self) -> Option<f64> {
        let ok = self.rows.iter().filter(|r| Self::falls(&r.1)).count();
        (!self.rows.is_empty()).then(|| ok as f64 / self.rows.len() as f64)
    }

    pub fn found(&self) -> Found {
        match self.fraction() {
            None => Found::NotAssessed,
            Some(f) => Found::of(f >= 1.0),
        }
    }

    fn row_text(r: &(f64, Vec<SensorPeak>)) -> String {
        format!(
            "station {}: {} kPa",
            r.0,
            r.1.iter()
                .map(|(n, p, src)| format!("{n} {:.2} ({src})", p / 1e3))
                .collect::<Vec<_>>()
                .join(", ")
        )
    }

    /// The stations whose peaks do not fall from the keel up, with the numbers.
    pub fn rising(&self) -> String {
        let v: Vec<String> = self
            .rows
            .iter()
            .filter(|r| !Self::falls(&r.1))
            .map(Self::row_text)
            .collect();
        if v.is_empty() {
            "no station".into()
        } else {
            v.join("; ")
        }
    }

    pub fn detail(&self) -> String {
        if self.rows.is_empty() {
            return format!("{FORE_SPEED} m/s not assessed, or no emerging event there");
        }
        self.rows
            .iter()
            .map(Self::row_text)
            .collect::<Vec<_>>()
            .join("; ")
    }
}

/// Why a keel sensor may not carry a station's largest pressure in the linear 2D+t chain (the reading of
/// the keel and fore trends when they are not reproduced).
const KEEL_ENTRY_READING: &str = "In the linear 2D+t chain the keel enters the water where the relative \
     motion falls through the local draft, while the relative velocity is still rising (it is largest where \
     the relative motion passes zero), so the water reaches the upper sensors faster than the keel. A keel \
     maximum at impact, as Ochi measured, needs the keel to re-enter near the largest relative velocity, \
     i.e. a relative motion well beyond the draft. Stations whose keel sensor has no design value are not \
     counted.";

/// The trend checks and comparisons of an Ochi V-form assessment.
pub fn ochi(a: &Assessment) -> Result<Validation> {
    let mut out = Validation::default();
    out.notes.push(
        "Ochi's (1958) measured peak pressures were published as figures only and are not available to \
         this tool: only his qualitative findings are checked, by the same functions as `slamtool \
         validate` (cases ochi1958-keel-trend, ochi1958-speed-trend, ochi1958-fore-trend)"
            .into(),
    );
    let keel = KeelTrend::of(a);
    let keel_found = keel.found();
    out.trend_checks.push(TrendCheck {
        check: "the maximum pressure is at the keel sensor of each station (design pressures)"
            .into(),
        verdict: keel_found.label(),
        detail: keel.detail(),
        source: SOURCE.into(),
        reading: (keel_found == Found::NotReproduced).then(|| KEEL_ENTRY_READING.to_string()),
    });
    let speed = SpeedTrend::of(a);
    let least = speed.least_shift();
    let least = if least.is_finite() {
        format!("at least {least:.3} Lpp (half the station spacing)")
    } else {
        "at least half the station spacing (one station assessed: no spacing)".to_string()
    };
    out.trend_checks.push(TrendCheck {
        check: format!(
            "the station of the maximum pressure moves aft (larger fraction of Lpp) as speed rises: never \
             forward between two speeds, and {least} aft overall"
        ),
        verdict: speed.found().label(),
        detail: format!("{}: {}", speed.finding(), speed.detail()),
        source: SOURCE.into(),
        reading: (speed.found() == Found::NotReproduced).then(|| speed.reading(a)),
    });
    let fore = ForeTrend::of(a);
    out.trend_checks.push(TrendCheck {
        check: format!(
            "at {FORE_SPEED} m/s the peak pressure falls from the keel sensor to the chine at the two \
             foremost stations"
        ),
        verdict: fore.found().label(),
        detail: fore.detail(),
        source: SOURCE.into(),
        reading: (fore.found() == Found::NotReproduced).then(|| {
            format!(
                "Not diagnosed separately; likely the keel trend's cause. {KEEL_ENTRY_READING}"
            )
        }),
    });
    // (d) Veen's P2 keel pressure and entry speeds at 2.0 m/s
    let num = |k: &str| reference_number(OCHI, "veen2010_sph", k);
    let (f2, u2) = (num("p2_station_aft_of_fp")?, num("p2_speed_m_s")?);
    let evs: Vec<&EventResult> = a
        .events
        .iter()
        .filter(|e| same(e.station, f2) && same(e.speed_m_per_s, u2))
        .collect();
    let keel = a
        .stations
        .iter()
        .find(|s| same(s.station, f2))
        .and_then(|s| by_girth(s).first().map(|n| n.to_string()));
    let p2 = keel.as_deref().and_then(|n| sensor_peak(&evs, n));
    out.comparisons.push(Comparison {
        quantity: format!("P2 ({f2} Lpp) pressure next to the keel at {u2} m/s"),
        computed: p2.map(|p| p.0 / 1e3),
        reference: num("p2_keel_pressure_kpa")?,
        unit: "kPa",
        source: VEEN.into(),
        note: match (&keel, p2) {
            (Some(n), Some((_, src))) => format!(
                "computed: peak of the keel sensor {n} ({src}); reference: Veen's field pressure next to the \
                 keel 0.1 s after impact, 'approximately 3.0 kPa' (not necessarily its peak)"
            ),
            _ => format!("station {f2} at {u2} m/s is not assessed or does not emerge"),
        },
    });
    let u = num("entry_speed_speed_m_s")?;
    for (st_key, v_key, label) in [
        ("p1_station_aft_of_fp", "p1_entry_speed_m_s", "P1"),
        ("p3_station_aft_of_fp", "p3_entry_speed_m_s", "P3"),
    ] {
        let f = num(st_key)?;
        let v = a
            .events
            .iter()
            .find(|e| same(e.station, f) && same(e.speed_m_per_s, u))
            .and_then(|e| e.entry_velocity_m_per_s);
        out.comparisons.push(Comparison {
            quantity: format!("{label} ({f} Lpp) keel-entry velocity at {u} m/s"),
            computed: v,
            reference: num(v_key)?,
            unit: "m/s",
            source: VEEN.into(),
            note: "computed: this tool's strip theory (reconstructed hull); reference: SEAWAY strip theory \
                   on Ochi's digitised hull (Veen)"
                .into(),
        });
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn speed(track: &[(f64, f64)]) -> SpeedTrend {
        SpeedTrend {
            track: track.iter().map(|&(u, f)| (u, f, 1e3, "sph")).collect(),
            spacing: 0.04,
        }
    }

    #[test]
    fn a_location_that_does_not_move_is_not_the_speed_trend() {
        let stays = speed(&[(1.2, 0.133), (2.0, 0.133), (2.8, 0.133)]);
        assert_eq!(stays.measure(), Some(0.0));
        assert_eq!(stays.found(), Found::NotReproduced);
        assert!(stays.finding().contains("stays"), "{}", stays.finding());
        let aft = speed(&[(1.2, 0.133), (2.0, 0.133), (2.8, 0.174)]);
        assert!((aft.measure().unwrap() - 0.041).abs() < 1e-9);
        assert_eq!(aft.found(), Found::Reproduced);
        // Aft overall but forward in between: the forward move decides.
        let back = speed(&[(1.2, 0.133), (1.6, 0.174), (2.4, 0.133), (2.8, 0.174)]);
        assert!((back.measure().unwrap() + 0.041).abs() < 1e-9);
        assert_eq!(back.found(), Found::NotReproduced);
        assert!(back.finding().contains("forward"), "{}", back.finding());
        assert_eq!(speed(&[(1.2, 0.133)]).found(), Found::NotAssessed);
    }

    #[test]
    fn the_keel_trend_needs_every_station_on_its_keel_sensor() {
        let row =
            |f: f64, best: &str, keel: &str| (f, best.to_string(), 3e3, "sph", keel.to_string());
        let all = KeelTrend {
            rows: vec![row(0.093, "S1", "S1"), row(0.133, "T1", "T1")],
            without_keel_value: Vec::new(),
        };
        assert_eq!(all.found(), Found::Reproduced);
        assert_eq!(all.off_keel(), "no station");
        let one_off = KeelTrend {
            rows: vec![row(0.093, "S2", "S1"), row(0.133, "T1", "T1")],
            without_keel_value: vec![(0.174, "U1".into(), "none")],
        };
        assert_eq!(one_off.fraction(), Some(0.5));
        assert_eq!(one_off.found(), Found::NotReproduced);
        assert!(one_off.off_keel().starts_with("0.093 Lpp (S2 3.00 kPa"));
        // a station whose keel sensor has no design value is not counted, and the detail says so
        assert!(one_off.detail().contains("station 0.174: not counted"));
        assert_eq!(KeelTrend::default().found(), Found::NotAssessed);
    }

    #[test]
    fn the_fore_trend_needs_peaks_falling_from_the_keel_up() {
        let peaks = |v: &[f64]| -> Vec<SensorPeak> {
            v.iter()
                .enumerate()
                .map(|(i, p)| (format!("S{}", i + 1), *p, "analytic"))
                .collect()
        };
        let falls = ForeTrend {
            rows: vec![
                (0.093, peaks(&[4.0, 3.0, 2.0])),
                (0.133, peaks(&[5.0, 5.0, 1.0])),
            ],
        };
        assert_eq!(falls.found(), Found::Reproduced);
        let rises = ForeTrend {
            rows: vec![
                (0.093, peaks(&[2.4, 3.2, 3.6])),
                (0.133, peaks(&[5.0, 1.0])),
            ],
        };
        assert_eq!(rises.fraction(), Some(0.5));
        assert!(
            rises.rising().starts_with("station 0.093"),
            "{}",
            rises.rising()
        );
    }
}
