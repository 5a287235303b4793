//! The particle state at the instant of the highest sensor pressure, for the report's picture of the
//! impact. During a run the largest sensor pressure after the contact transient (the keel
//! [`super::CONTACT_TRANSIENT_DP`] spacings deep, as the peaks are reported) is watched; when it rises
//! above its previous maximum the particles are copied in memory. At the end of the run that one state
//! is drawn as `peak_pressure.png` (fluid coloured by pressure, body outline, colour bar; see
//! [`super::frame`]). A copy happens only when the maximum rises, so runs without an output folder
//! (the benchmark) never copy.

use std::path::Path;

use super::output::{self, Frame};
use super::particles::Particles;
use super::solver::Simulation;
use crate::error::Result;

/// File name of the picture in a run's output folder.
pub const FILE: &str = "peak_pressure.png";

/// The particle state at the highest sensor pressure so far.
#[derive(Debug, Default)]
pub struct PeakSnapshot {
    /// Largest sensor pressure seen after the contact transient (Pa), its time and sensor.
    pub pressure_pa: f64,
    pub time_s: f64,
    pub sensor: String,
    z_keel: f64,
    particles: Option<Particles>,
}

impl PeakSnapshot {
    /// Look at the state after a step; copy it when a sensor pressure exceeds every earlier one.
    pub fn observe(&mut self, sim: &Simulation) {
        let d0 = sim.setup.initial_immersion;
        if -sim.body.z_keel - d0 < super::CONTACT_TRANSIENT_DP * sim.setup.dp {
            return;
        }
        let values = sim.sensors().values();
        let Some((k, &p)) = values
            .iter()
            .enumerate()
            .filter(|(_, p)| p.is_finite())
            .max_by(|a, b| a.1.total_cmp(b.1))
        else {
            return;
        };
        if self.particles.is_some() && p <= self.pressure_pa {
            return;
        }
        self.pressure_pa = p;
        self.time_s = sim.time;
        self.sensor = sim.sensors().names().get(k).cloned().unwrap_or_default();
        self.z_keel = sim.body.z_keel;
        match &mut self.particles {
            Some(copy) => copy.clone_from(&sim.pt),
            None => self.particles = Some(sim.pt.clone()),
        }
    }

    /// Write the picture into `dir` (nothing when no sensor was wetted after the transient).
    pub fn write(&self, sim: &Simulation, dir: &Path) -> Result<bool> {
        let Some(pt) = &self.particles else {
            return Ok(false);
        };
        let mut frame = frame_at(sim, self.z_keel, self.time_s);
        frame.p_scale = colour_scale_top(self.pressure_pa, frame.p_scale);
        output::write_png(&dir.join(FILE), pt, &frame)?;
        Ok(true)
    }
}

/// The top of the snapshot's colour scale: a round value (1, 2 or 5 times a power of ten) between the
/// snapshot's sensor peak `p_peak` and 2.5 times it, so that the impact's pressure field spans the scale;
/// `fallback` (the run's expected peak pressure) when the peak is not positive. Before, every snapshot used
/// the expected peak the sound speed was chosen for, which on a hull section can be many times the
/// computed peak and left the picture in the scale's lowest colours.
fn colour_scale_top(p_peak: f64, fallback: f64) -> f64 {
    if p_peak.is_finite() && p_peak > 0.0 {
        super::frame::nice_length(2.5 * p_peak)
    } else {
        fallback
    }
}

/// The picture window and colour scale of a run, with the body where it was (keel at `z_keel`) at `t`.
pub fn frame_at(sim: &Simulation, z_keel: f64, t: f64) -> Frame {
    let s = &sim.setup;
    let b = sim
        .section()
        .map_or(s.tank_half_width, |x| x.half_breadth());
    let hgt = sim.section().map_or(0.2 * s.tank_depth, |x| x.height());
    let y1 = (2.0 * b).min(s.tank_half_width);
    let window = [-y1, y1, -(1.5 * b).min(s.tank_depth), hgt.max(0.5 * b)];
    // Colour scale: 0.01 rho0 c0^2, the expected peak pressure the sound speed was chosen for.
    let p_scale = 0.01 * s.rho0 * s.c0 * s.c0;
    // The body outline where the body is (the section's keel is at z = 0 in its own frame).
    let outline = sim.section().map_or_else(Vec::new, |x| {
        x.closed_contour()
            .iter()
            .map(|p| [p[0], p[1] + z_keel])
            .collect()
    });
    Frame {
        window,
        width: 1000,
        p_scale,
        mirror: s.mirror,
        time_s: t,
        outline,
    }
}

#[cfg(test)]
mod tests {
    use super::colour_scale_top;

    #[test]
    fn the_colour_scale_spans_the_snapshot_peak() {
        for p in [3.06e3, 4.99e3, 1.0e4, 17.7e3, 2.0e5] {
            let top = colour_scale_top(p, 1e6);
            assert!(top > p && top <= 2.5 * p, "{p} -> {top}");
        }
        assert_eq!(colour_scale_top(0.0, 4e4), 4e4);
        assert_eq!(colour_scale_top(f64::NAN, 4e4), 4e4);
    }
}
