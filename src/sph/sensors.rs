//! Pressure sensors on the body contour and the recorded time histories.
//!
//! A sensor is a stretch of the starboard contour, centred at arc length s from the keel, of physical
//! width w (a real transducer's diameter). Two ways to get its pressure ([`crate::sph::case::SensorMethod`]):
//!
//! * interpolated: the mean wall pressure over that width, from points at spacing at most dp/4, each
//!   evaluated with the Adami et al. (2012) extrapolation (zero where the fluid support is below the dry
//!   threshold);
//! * force panel: p = -F . n / w, with F the sum of the fluid-body pair forces
//!   ([`crate::sph::body_force::panel_forces`]) on the body dummies near the span [s - w/2, s + w/2], each
//!   weighted by the fraction of the contour it stands for (dp about its nearest contour point) that lies
//!   on the span, and n the outward normal of the contour at s: the force a transducer measures on its
//!   face, consistent with the default (wall-normal) pair-force section force: the panels tiling the
//!   contour add up to it, up to the particles at a corner, where the section force takes each pair
//!   along the normal of its own side.

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};
use crate::sph::body::{self, Section};
use crate::sph::solver::BodyState;

/// One sensor as given in a case.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SensorSpec {
    /// Name used as the CSV column and JSON key.
    pub name: String,
    /// Arc length from the keel along the starboard contour to the sensor centre (m).
    pub s_m: f64,
    /// Physical width of the sensor along the contour (m).
    pub width_m: f64,
}

impl SensorSpec {
    /// Whether the sensor lies on a starboard contour `len` long (m), with a positive width.
    pub fn fits(&self, len: f64) -> bool {
        self.width_m > 0.0
            && self.s_m - 0.5 * self.width_m >= 0.0
            && self.s_m + 0.5 * self.width_m <= len
    }
}

/// Sensors with their sample points (body frame).
#[derive(Debug, Clone, Default)]
pub struct SensorSet {
    names: Vec<String>,
    /// (sensor index, y, z) of every sample point.
    points: Vec<(usize, f64, f64)>,
    counts: Vec<usize>,
    values: Vec<f64>,
    /// Span [s0, s1) along the contour, width and outward normal (body frame) of every sensor.
    panels: Vec<Panel>,
    /// Starboard half contour (body frame, keel first) and the arc length at each of its points.
    half: Vec<[f64; 2]>,
    arc: Vec<f64>,
    /// Particle spacing: the length of contour each body dummy stands for.
    dp: f64,
    /// Span [s0, s1] along the contour over which each sensor's pressure is integrated.
    spans: Vec<[f64; 2]>,
}

/// The face of a sensor for the force-panel method.
#[derive(Debug, Clone, Copy)]
pub struct Panel {
    pub s0: f64,
    pub s1: f64,
    pub ny: f64,
    pub nz: f64,
}

impl SensorSet {
    pub fn new(specs: &[SensorSpec], section: Option<&Section>, dp: f64) -> Result<Self> {
        let mut set = SensorSet::default();
        if specs.is_empty() {
            return Ok(set);
        }
        let Some(sec) = section else {
            return Err(Error::Invalid("sensors need a body section".into()));
        };
        let len = body::half_contour_length(sec);
        for (k, s) in specs.iter().enumerate() {
            if !s.fits(len) {
                return Err(Error::Invalid(format!(
                    "sensor '{}' (centre {} m, width {} m along the contour) must lie on the starboard \
                     contour, which is {:.4} m long from the keel",
                    s.name, s.s_m, s.width_m, len
                )));
            }
            let [a0, a1] = integration_span(s, dp, len);
            let w = a1 - a0;
            let n = ((w / (0.25 * dp)).ceil() as usize).max(3);
            for i in 0..n {
                let a = a0 + (i as f64 + 0.5) / n as f64 * w;
                let p = body::point_at_arc(sec, a).expect("inside the contour");
                set.points.push((k, p[0], p[1]));
            }
            set.names.push(s.name.clone());
            set.counts.push(n);
            set.spans.push([a0, a1]);
            set.panels.push(panel(sec, s.s_m, [a0, a1]));
        }
        set.dp = dp;
        set.half = sec.half_points().to_vec();
        set.arc = std::iter::once(0.0)
            .chain(set.half.windows(2).scan(0.0, |acc, w| {
                *acc += (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]);
                Some(*acc)
            }))
            .collect();
        set.values = vec![0.0; specs.len()];
        Ok(set)
    }

    pub fn names(&self) -> &[String] {
        &self.names
    }

    pub fn values(&self) -> &[f64] {
        &self.values
    }

    pub fn panels(&self) -> &[Panel] {
        &self.panels
    }

    /// Span [s0, s1] of the contour over which each sensor's pressure is integrated (its width, or
    /// [`MIN_WIDTH_DP`] particle spacings when it is narrower).
    pub fn spans(&self) -> &[[f64; 2]] {
        &self.spans
    }

    /// Arc length from the keel of the starboard contour point nearest to the body-frame point (y, z).
    pub fn arc_of(&self, y: f64, z: f64) -> f64 {
        body::nearest_on_polyline(&self.half, y, z).map_or(0.0, |(k, f, _)| {
            self.arc[k] + f * (self.arc[k + 1] - self.arc[k])
        })
    }

    /// Fraction of a body dummy at arc length `s` (standing for the contour [s - dp/2, s + dp/2]) that
    /// lies on `panel`: overlap of the two spans divided by dp.
    pub fn panel_weight(&self, panel: &Panel, s: f64) -> f64 {
        let lo = panel.s0.max(s - 0.5 * self.dp);
        let hi = panel.s1.min(s + 0.5 * self.dp);
        ((hi - lo) / self.dp).max(0.0)
    }

    /// Set the sensor values from the body forces (y, z) on the panels (N/m), in panel order.
    pub fn set_from_panel_forces(&mut self, forces: &[[f64; 2]]) {
        for ((v, f), p) in self.values.iter_mut().zip(forces).zip(&self.panels) {
            *v = -(f[0] * p.ny + f[1] * p.nz) / (p.s1 - p.s0);
        }
    }

    /// Sample all sensors with the body keel at `z_keel`, given a wall-pressure function of (y, z).
    pub fn sample(&mut self, z_keel: f64, pressure: &impl Fn(f64, f64) -> f64) {
        self.values.iter_mut().for_each(|v| *v = 0.0);
        for &(k, y, z) in &self.points {
            self.values[k] += pressure(y, z + z_keel);
        }
        for (v, &n) in self.values.iter_mut().zip(&self.counts) {
            *v /= n as f64;
        }
    }
}

/// Narrowest span, in particle spacings, over which a sensor's pressure is integrated. A force-panel
/// sensor attributes each fluid particle's force on the wall to the particle's own place along the
/// contour, while that force comes from the wall within the kernel support radius 2h (3 dp) of the
/// particle: a panel not much wider than that reads the passage of single particles at the jet root,
/// and its peak is biased high. Measured on gravity-free constant-speed wedges at 40 particles per
/// half-beam (the default level; refined tank, Riemann scheme, shifting and corrected divergence),
/// twelve sensors from 10 % to 75 % of the side, against the similarity solution averaged over the
/// same span: a 2 dp span read 0.84-1.56 (20 deg) and 1.05-1.29 (30 deg) of the reference, mean
/// error 13.5 % and 15.9 %; 3 dp, 6.7 % and 6.3 %; 4 dp, 5.4 % and 4.5 % (30 deg: 0.97-1.10). At 80
/// particles a 10 mm sensor is 3.2 dp wide, and widening it to 4 dp moved the 30 deg mean error from
/// 3.5 % to 3.8 % (`tests/sph_wedge_convergence.rs`, `CONV_WIDTH_DP`;
/// docs/numerics/wedge-convergence.md, item 8). (The first value, 2 dp, was chosen against 5 mm
/// sensors on a 6.25 mm spacing, which read 31-56 % high.)
pub const MIN_WIDTH_DP: f64 = 4.0;

/// The span of the contour over which a sensor is integrated: its own width about its centre, widened
/// symmetrically to [`MIN_WIDTH_DP`] dp when narrower, and then moved to lie between the keel and the
/// deck edge (a contour `len` long) when the widening took it past either.
pub fn integration_span(s: &SensorSpec, dp: f64, len: f64) -> [f64; 2] {
    let w = s.width_m.max(MIN_WIDTH_DP * dp).min(len);
    let a0 = (s.s_m - 0.5 * w).clamp(0.0, len - w);
    [a0, a0 + w]
}

/// The panel of a sensor centred at arc length `s` with the span `span`: the span and the outward normal
/// at s.
fn panel(sec: &Section, s: f64, span: [f64; 2]) -> Panel {
    let (mut acc, mut n) = (0.0, [0.0, -1.0]);
    for seg in sec.half_points().windows(2) {
        if let Some((normal, l)) = body::outward_normal(seg[0], seg[1]) {
            n = normal;
            if s <= acc + l {
                break;
            }
            acc += l;
        }
    }
    Panel {
        s0: span[0],
        s1: span[1],
        ny: n[0],
        nz: n[1],
    }
}

/// Time histories sampled every step.
#[derive(Debug, Clone, Default, Serialize)]
pub struct History {
    pub t: Vec<f64>,
    pub z_keel: Vec<f64>,
    pub v_down: Vec<f64>,
    pub a_down: Vec<f64>,
    pub fz: Vec<f64>,
    pub fy: Vec<f64>,
    pub fy_starboard: Vec<f64>,
    /// Largest wall pressure on the contour samples (Pa) and its arc length from the keel (m; negative on
    /// the port half).
    pub p_contour_max: Vec<f64>,
    pub s_at_p_max: Vec<f64>,
    pub sensor_names: Vec<String>,
    pub sensors: Vec<Vec<f64>>,
}

impl History {
    /// Empty histories with room for `steps` samples (no reallocation in the time loop).
    pub fn new(set: &SensorSet, steps: usize) -> Self {
        let col = || Vec::with_capacity(steps);
        Self {
            t: col(),
            z_keel: col(),
            v_down: col(),
            a_down: col(),
            fz: col(),
            fy: col(),
            fy_starboard: col(),
            p_contour_max: col(),
            s_at_p_max: col(),
            sensor_names: set.names().to_vec(),
            sensors: set.names().iter().map(|_| col()).collect(),
        }
    }

    pub fn push(&mut self, t: f64, b: &BodyState, sensors: &[f64]) {
        self.t.push(t);
        self.z_keel.push(b.z_keel);
        self.v_down.push(b.v_down);
        self.a_down.push(b.a_down);
        self.fz.push(b.fz);
        self.fy.push(b.fy);
        self.fy_starboard.push(b.fy_starboard);
        self.p_contour_max.push(b.p_contour_max);
        self.s_at_p_max.push(b.s_at_p_max);
        for (c, &v) in self.sensors.iter_mut().zip(sensors) {
            c.push(v);
        }
    }

    pub fn len(&self) -> usize {
        self.t.len()
    }

    pub fn is_empty(&self) -> bool {
        self.t.is_empty()
    }
}
