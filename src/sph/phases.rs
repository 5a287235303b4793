//! The phases of a run's records ([`crate::loads::anatomy`]): for every sensor the expected impact window
//! from the generalised Wagner contact half-width c(t) along the run's own velocity history (with the
//! run's initial immersion), and for the section force the window up to full wetting; then each record's
//! anatomy with its hydrostatic part.
//!
//! Rules beyond the module notes of [`crate::loads::anatomy`]:
//!
//! * in a run with air at a flat keel, the sensors reaching onto the flat (their lower edge wetted in
//!   Wagner's acoustic stage) are **cushioned**: their window opens at the start of the run, the
//!   keel's approach through the air gap, and the flat keel has no contact transient
//!   ([`RunPhases::with_air`]);
//! * a sensor is crossed by the contact at an **acoustic** speed when Wagner's contact speed there is
//!   at the water-hammer limit (a flat keel: c jumps to the flat half-width at contact), or when Wagner's
//!   jet-root pressure rho c'^2 / 2 at the crossing exceeds rho c0 V, the largest pressure a weakly
//!   compressible fluid with the run's artificial sound speed c0 can carry: SPH does not compute that
//!   impact, whatever the spacing;
//! * the section force's window runs from the end of the contact transient to Wagner's full wetting
//!   (the time c reaches the chine or widest point; the end of the record when it does not stop), widened
//!   as a sensor's; its hydrostatic part is the buoyancy rho g A(d) of the section immersed to the keel
//!   depth d;
//! * in a run with air at a flat keel the section force's window still opens at the end of the contact
//!   transient a single-phase run would have ([`RunPhases::force_start_s`]), not at the start: the flat
//!   bottom's cushion load grows with the water's artificial sound speed as its panels' cushion peaks do
//!   (Ochi's 0.174 Lpp section at 1 m/s with air, 10.4 mm: force peak 4.02 kN/m at c0 = 63 m/s, 5.27 kN/m
//!   at 126 m/s; a flat bottom at 2 m/s, 6.25 mm: 33.0, 61.6 and 93.1 kN/m at c0 = 126, 252 and 504 m/s;
//!   docs/guide/air.md), so, like those peaks and like the water hammer of a run without air, it is not
//!   a slamming value of the section force.

use crate::analytic::generalised_wagner::{self, WagnerEstimate};
use crate::loads::anatomy::{
    Anatomy, Expectation, ImpactStatus, ImpactWindow, WINDOW_FRACTION, anatomy, time_reaching,
};
use crate::sph::body::{Section, point_at_arc};
use crate::sph::sensors::History;

/// Gravity (m/s2) of the hydrostatic parts, as the solver's.
const G: f64 = 9.81;

/// The value of `y` (sampled at `t`) at time `x`, linearly interpolated and held at the ends.
fn at(t: &[f64], y: &[f64], x: f64) -> f64 {
    let k = t.partition_point(|&s| s <= x);
    if k == 0 {
        return y.first().copied().unwrap_or(0.0);
    }
    if k >= t.len() {
        return y.last().copied().unwrap_or(0.0);
    }
    let f = (x - t[k - 1]) / (t[k] - t[k - 1]);
    y[k - 1] + f * (y[k] - y[k - 1])
}

/// What a run's phases are measured against.
pub struct RunPhases<'a> {
    pub section: &'a Section,
    pub history: &'a History,
    pub wagner: Option<WagnerEstimate>,
    pub dp: f64,
    pub c0: f64,
    pub rho: f64,
    pub d0: f64,
    pub transient_end_s: f64,
    /// Where the section force's window opens: the end of the contact transient of the water alone,
    /// also in a run with air at a flat keel (module notes).
    pub force_start_s: f64,
    /// The run has air ([`crate::sph::air`]): a flat keel's impact is cushioned, not acoustic.
    pub air: bool,
}

impl<'a> RunPhases<'a> {
    /// The Wagner estimate of the run (none when the model cannot take the section).
    pub fn new(
        section: &'a Section,
        history: &'a History,
        dp: f64,
        c0: f64,
        rho: f64,
        d0: f64,
        transient_end_s: f64,
    ) -> Self {
        // From the keel's arrival at the calm surface (t = 0) on: a run with an air gap records the
        // approach at negative times.
        let k0 = history.t.partition_point(|&t| t < 0.0);
        let wagner = generalised_wagner::estimate_immersed(
            section.half_points(),
            d0,
            &history.t[k0..],
            &history.v_down[k0..],
            rho,
        )
        .ok()
        .filter(|e| !e.t.is_empty());
        Self {
            section,
            history,
            wagner,
            dp,
            c0,
            rho,
            d0,
            transient_end_s,
            force_start_s: transient_end_s,
            air: false,
        }
    }

    /// The phases of a run with air (`air` true): the sensors of a flat keel are cushioned
    /// ([`ImpactStatus::Cushioned`]), and a flat keel, which meets the water through the air cushion, has
    /// no contact transient: it ends at the start of the run, so the section force's window and every
    /// sensor's open there.
    pub fn with_air(mut self, air: bool) -> Self {
        self.air = air;
        if air && self.flat_keel() {
            // the flat keel meets the water through the air cushion: no acoustic contact transient
            self.transient_end_s = self.run_start();
        }
        self
    }

    /// The run's first time (s), or 0 when it starts after the keel's contact.
    fn run_start(&self) -> f64 {
        self.history.t.first().copied().unwrap_or(0.0).min(0.0)
    }

    /// The keel is flat: Wagner's contact starts at the water-hammer limit.
    fn flat_keel(&self) -> bool {
        self.d0 == 0.0
            && self
                .wagner
                .as_ref()
                .is_some_and(|w| w.acoustic_limited.first().copied().unwrap_or(false))
    }

    fn keel_depth(&self, t: f64) -> f64 {
        -at(&self.history.t, &self.history.z_keel, t)
    }

    fn speed(&self, t: f64) -> f64 {
        at(&self.history.t, &self.history.v_down, t)
    }

    /// The expectation of the sensor integrated over the contour span [s0, s1] (m from the keel).
    pub fn sensor_expectation(&self, span: [f64; 2]) -> Expectation {
        let ends = (
            point_at_arc(self.section, span[0]),
            point_at_arc(self.section, span[1]),
        );
        let local_deadrise_deg = match ends {
            (Some(a), Some(b)) => {
                let (dy, dz) = ((b[0] - a[0]).abs(), (b[1] - a[1]).abs());
                (dy + dz > 0.0).then(|| dz.atan2(dy).to_degrees())
            }
            _ => None,
        };
        let none = |status, half_width| Expectation {
            window: None,
            status,
            transient_end_s: self.transient_end_s,
            crossing_half_width_m: half_width,
            local_deadrise_deg,
        };
        let Some(w) = &self.wagner else {
            return none(ImpactStatus::NotCrossed, None);
        };
        let (Some(a), Some(b)) = ends else {
            return none(ImpactStatus::NotCrossed, None);
        };
        let (y_lo, y_hi) = (a[0].abs().min(b[0].abs()), a[0].abs().max(b[0].abs()));
        let c_start = w.half_width[0];
        if self.d0 > 0.0 && y_hi <= c_start {
            return none(ImpactStatus::WettedAtStart, None);
        }
        let (Some(t_lo), Some(t_hi)) = (
            time_reaching(&w.t, &w.half_width, y_lo),
            time_reaching(&w.t, &w.half_width, y_hi),
        ) else {
            return none(ImpactStatus::NotCrossed, None);
        };
        // Wagner's sample at the end of the crossing: acoustic, or beyond what c0 can carry
        let k = w.half_width.iter().position(|&c| c >= y_hi).unwrap_or(0);
        let v = self.speed(t_hi);
        let acoustic = (self.d0 == 0.0 && w.acoustic_limited.get(k).copied().unwrap_or(false))
            || w.peak_pressure.get(k).copied().unwrap_or(0.0) > self.rho * self.c0 * v.max(0.0);
        // with air, a sensor that reaches onto the flat keel (its lower edge wetted in the acoustic
        // stage) takes the cushion's load too
        let k_lo = w.half_width.iter().position(|&c| c >= y_lo).unwrap_or(0);
        let on_flat = self.d0 == 0.0 && w.acoustic_limited.get(k_lo).copied().unwrap_or(false);
        if (acoustic || on_flat) && self.air && self.flat_keel() {
            // `with_air` ended the transient at the run's start
            return Expectation {
                window: Some(ImpactWindow::cushioned(self.run_start(), t_hi, self.dp, v)),
                status: ImpactStatus::Cushioned,
                transient_end_s: self.transient_end_s,
                crossing_half_width_m: Some(y_hi),
                local_deadrise_deg,
            };
        }
        if acoustic {
            return none(ImpactStatus::Acoustic, Some(y_hi));
        }
        if t_hi <= self.transient_end_s {
            return none(ImpactStatus::InTransient, Some(y_hi));
        }
        let window = ImpactWindow::around(t_lo, t_hi, self.dp, v);
        Expectation {
            window: Some(window),
            status: ImpactStatus::Resolved,
            transient_end_s: self.transient_end_s,
            crossing_half_width_m: Some(y_hi),
            local_deadrise_deg,
        }
    }

    /// The anatomy of the sensor record `x` integrated over `span`.
    pub fn sensor(&self, span: [f64; 2], x: &[f64]) -> Anatomy {
        self.sensor_record(span, &self.history.t, x)
    }

    /// The anatomy of a record (`t`, `x`) of the sensor integrated over `span`: the run's own record, or
    /// its low-passed resampling ([`crate::loads::filtered_record`]), measured against the same impact
    /// window.
    pub fn sensor_record(&self, span: [f64; 2], t: &[f64], x: &[f64]) -> Anatomy {
        let e = self.sensor_expectation(span);
        let z_s = point_at_arc(self.section, 0.5 * (span[0] + span[1])).map_or(0.0, |p| p[1]);
        let hydro = |t: f64| self.rho * G * (self.keel_depth(t) - z_s).max(0.0);
        anatomy(t, x, &e, &hydro)
    }

    /// The anatomy of the section force record.
    pub fn force(&self) -> Anatomy {
        let h = self.history;
        self.force_record(&h.t, &h.fz)
    }

    /// The anatomy of a section force record (`t`, `fz`): the run's own, or its low-passed resampling,
    /// measured against the same window.
    pub fn force_record(&self, t: &[f64], fz: &[f64]) -> Anatomy {
        let h = self.history;
        let t_last = h.t.last().copied().unwrap_or(0.0);
        let t_full = match &self.wagner {
            Some(w) if w.stopped.is_some() => w.t.last().copied().unwrap_or(t_last),
            _ => t_last,
        };
        let v = self.speed(t_full);
        let lag = if v > 0.0 {
            crate::loads::anatomy::LAG_SPACINGS * self.dp / v
        } else {
            0.0
        };
        let e = Expectation {
            window: Some(ImpactWindow {
                crossing_start_s: h.t.first().copied().unwrap_or(0.0),
                crossing_end_s: t_full,
                start_s: self.force_start_s,
                end_s: t_full * (1.0 + WINDOW_FRACTION) + lag,
            }),
            status: ImpactStatus::Resolved,
            transient_end_s: self.transient_end_s,
            crossing_half_width_m: None,
            local_deadrise_deg: None,
        };
        let hull_section = crate::hull::Section::new(self.section.half_points().to_vec());
        let hydro = |t: f64| self.rho * G * hull_section.properties(self.keel_depth(t)).area;
        anatomy(t, fz, &e, &hydro)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn history(v: f64, dt: f64, n: usize) -> History {
        let t: Vec<f64> = (0..n).map(|k| k as f64 * dt).collect();
        History {
            z_keel: t.iter().map(|&s| -v * s).collect(),
            v_down: vec![v; n],
            a_down: vec![0.0; n],
            fz: vec![0.0; n],
            fy: vec![0.0; n],
            fy_starboard: vec![0.0; n],
            p_contour_max: vec![0.0; n],
            s_at_p_max: vec![0.0; n],
            sensor_names: Vec::new(),
            sensors: Vec::new(),
            t,
        }
    }

    #[test]
    fn a_wedge_sensor_window_brackets_wagner_crossing() {
        // 30 deg wedge at 2 m/s: Wagner's c = (pi/2) V t / tan(beta)
        let beta = 30f64.to_radians();
        let sec = Section::wedge(beta, 0.3, 0.3).unwrap();
        let h = history(2.0, 1e-4, 2001);
        let ph = RunPhases::new(&sec, &h, 0.002, 40.0, 1000.0, 0.0, 0.002);
        let s = 0.2;
        let e = ph.sensor_expectation([s - 0.01, s + 0.01]);
        let w = e.window.unwrap();
        let t_hi = (s + 0.01) * beta.cos() * beta.tan() / (std::f64::consts::FRAC_PI_2 * 2.0);
        assert!((w.crossing_end_s / t_hi - 1.0).abs() < 0.02, "{w:?} {t_hi}");
        assert!(w.start_s < w.crossing_start_s && w.end_s > w.crossing_end_s);
    }

    #[test]
    fn keel_sensors_in_the_transient_and_flat_keels_are_named() {
        let beta = 30f64.to_radians();
        let sec = Section::wedge(beta, 0.3, 0.3).unwrap();
        let h = history(2.0, 1e-4, 2001);
        let ph = RunPhases::new(&sec, &h, 0.002, 40.0, 1000.0, 0.0, 0.002);
        assert_eq!(
            ph.sensor_expectation([0.0, 0.004]).status,
            ImpactStatus::InTransient
        );
        // a flat keel of half-width 0.05 m
        let flat =
            Section::from_half_points(vec![[0.0, 0.0], [0.05, 0.0], [0.3, 0.15], [0.3, 0.3]])
                .unwrap();
        let ph = RunPhases::new(&flat, &h, 0.002, 40.0, 1000.0, 0.0, 0.002);
        assert_eq!(
            ph.sensor_expectation([0.01, 0.03]).status,
            ImpactStatus::Acoustic
        );
    }

    #[test]
    fn a_flat_keel_with_air_is_cushioned_from_the_start_of_the_approach() {
        let flat =
            Section::from_half_points(vec![[0.0, 0.0], [0.05, 0.0], [0.3, 0.15], [0.3, 0.3]])
                .unwrap();
        // the keel starts 10 mm above the calm surface at 2 m/s: t from -5 ms
        let mut h = history(2.0, 1e-4, 2001);
        for t in h.t.iter_mut() {
            *t -= 0.005;
        }
        h.z_keel = h.t.iter().map(|&t| -2.0 * t).collect();
        let ph = RunPhases::new(&flat, &h, 0.002, 40.0, 1000.0, 0.0, 0.002).with_air(true);
        assert_eq!(ph.transient_end_s, -0.005, "no contact transient");
        let e = ph.sensor_expectation([0.01, 0.03]);
        assert_eq!(e.status, ImpactStatus::Cushioned);
        let w = e.window.unwrap();
        assert_eq!(w.start_s, -0.005);
        assert!(w.end_s > 0.0 && w.duration() >= 0.005, "{w:?}");
        // the cushion peaks before the keel reaches the calm surface: that is its slamming peak
        let x: Vec<f64> =
            h.t.iter()
                .map(|&t| 1e4 * (-((t + 0.001) / 5e-4).powi(2)).exp())
                .collect();
        let a = ph.sensor([0.01, 0.03], &x);
        assert_eq!(a.status, ImpactStatus::Cushioned);
        assert!(
            (a.slamming_peak.unwrap().time + 0.001).abs() < 1e-9,
            "{a:?}"
        );
        // a sensor reaching onto the flat from beyond it takes the cushion too
        let e = ph.sensor_expectation([0.04, 0.08]);
        assert_eq!(e.status, ImpactStatus::Cushioned);
        // a sensor beyond the flat keeps Wagner's window
        let e = ph.sensor_expectation([0.15, 0.17]);
        assert_eq!(e.status, ImpactStatus::Resolved);
        assert!(e.window.unwrap().start_s > 0.0);
        // the force's window opens where the water alone's contact transient ends: the cushion's force,
        // like its panel peaks, follows the artificial sound speed
        assert_eq!(ph.force_start_s, 0.002);
        assert_eq!(ph.force().window.unwrap().start_s, 0.002);
        // a force peak in the cushion is not the section's slamming peak; a later one is
        let fz: Vec<f64> =
            h.t.iter()
                .map(|&t| {
                    1e4 * (-((t + 0.001) / 5e-4).powi(2)).exp()
                        + 2e3 * (-((t - 0.004) / 1e-3).powi(2)).exp()
                })
                .collect();
        let h2 = History { fz, ..h.clone() };
        let ph2 = RunPhases::new(&flat, &h2, 0.002, 40.0, 1000.0, 0.0, 0.002).with_air(true);
        let peak = ph2.force().slamming_peak.unwrap();
        assert!((peak.time - 0.004).abs() < 1e-9, "{peak:?}");
        // a V keel with air keeps its contact transient
        let beta = 10f64.to_radians();
        let sec = Section::wedge(beta, 0.3, 0.3).unwrap();
        let ph = RunPhases::new(&sec, &h, 0.002, 40.0, 1000.0, 0.0, 0.002).with_air(true);
        assert_eq!(ph.transient_end_s, 0.002);
    }
}
