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
        let frame = frame_at(sim, self.z_keel, self.time_s);
        output::write_png(&dir.join(FILE), pt, &frame)?;
        Ok(true)
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
