//! Water-entry cases: the resolved [`Setup`] of a run (its TOML form is read by [`crate::sph::case_file`]),
//! and the automatic choice of particle spacing, sound speed, tank size and end time from the section, the
//! speed and a resolution level. Every automatic choice can be overridden, and the resolved setup (with
//! a note on how each value was chosen) is written with the results.
//!
//! Automatic choices:
//! * particle spacing dp = b / N, b the largest half-breadth of the section, N = 40 / 80 / 160 for the
//!   coarse / medium / fine levels (or `particles_per_half_beam`);
//! * sound speed c0 = max(V sqrt(Cp / 0.02), 10 V, 10 sqrt(g D)): density variation below about 1 % at
//!   the expected peak pressure coefficient Cp = (pi^2/4) cot^2(beta) (Wagner 1932, beta the smallest
//!   local deadrise below the chine, not below 10 deg) and at the tank bottom (depth D), and a Mach number
//!   V / c0 of at most 0.1 ([`crate::sph::automatic::sound_speed`]);
//! * tank: a few half-breadths of clear water beside and under the body, plus an absorbing layer along
//!   the walls and the bottom ([`crate::sph::automatic::tank`]), refined: the spacing dp in a band around
//!   the body only and 2 dp beyond ([`crate::sph::automatic::refinement_band`],
//!   [`crate::sph::refinement`]). A tank given in a case, other numerics, `refined = false` under
//!   `[tank]` or `--tank uniform` give one spacing throughout;
//! * end time: when the impact is over, from Wagner's wetting and the entry velocity
//!   ([`crate::sph::automatic`]).
//!
//! Numerics (`[numerics]` in a case file): `riemann` (default true: the low-dissipation Riemann pair terms
//! of [`crate::sph::riemann`]; false: delta-SPH with artificial viscosity), `shifting` (default false:
//! particle shifting of [`crate::sph::shifting`]), `divergence_correction` (default false: the
//! kernel-gradient-corrected velocity divergence of [`crate::sph::kernel_correction`]), `wall_wetness`
//! (default false: the body dummies weighted by the wetness of the body's face,
//! [`crate::sph::wall_wetness`]), `force`
//! (`"normal_pair_forces"`, the default: the wall-normal part of the fluid-body pair forces;
//! `"pair_forces"`: all of them, the force along the wall included; or `"contour"`), and `c0_m_s`, `h_over_dp`, `eos`, `delta`, `alpha`, `cfl`, `mirror`. The defaults are the combination
//! that measured best against the Zhao et al. (1996) 2D solution, the Wagner and similarity peak pressures
//! and the drop tests (see `tests/sph_validation.rs`).

use serde::{Deserialize, Serialize};

use crate::error::{Error, Result};

use crate::sph::air::{self, AirChoice, AirLayer};
use crate::sph::automatic;
use crate::sph::body::{Motion, Section};
use crate::sph::eos::EosKind;
use crate::sph::refinement::{self, Band};
use crate::sph::sensors::SensorSpec;

/// How the body moves, as written in a case (speeds downward-positive).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "snake_case", deny_unknown_fields)]
pub enum MotionSpec {
    /// Constant entry speed.
    Constant {
        #[serde(rename = "speed_m_per_s", alias = "speed_m_s")]
        speed_m_s: f64,
    },
    /// Downward speed from a table of [t_s, v_m_s] rows.
    Prescribed { table: Vec<[f64; 2]> },
    /// Free fall in heave with the given mass per metre of section, from the given entry speed.
    FreeHeave {
        mass_per_m_kg: f64,
        #[serde(rename = "speed_m_per_s", alias = "speed_m_s")]
        speed_m_s: f64,
    },
}

impl MotionSpec {
    pub fn build(&self) -> Result<Motion> {
        match self {
            MotionSpec::Constant { speed_m_s } => Ok(Motion::Constant { speed: *speed_m_s }),
            MotionSpec::Prescribed { table } => {
                let t: Vec<f64> = table.iter().map(|r| r[0]).collect();
                let v: Vec<f64> = table.iter().map(|r| r[1]).collect();
                Motion::prescribed(&t, &v)
            }
            MotionSpec::FreeHeave {
                mass_per_m_kg,
                speed_m_s,
            } => Ok(Motion::FreeHeave {
                mass_per_m: *mass_per_m_kg,
                speed0: *speed_m_s,
            }),
        }
    }
}

/// How the section force is obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "snake_case")]
pub enum ForceMethod {
    /// Wall pressure (Adami et al. 2012 extrapolation) integrated around the contour.
    Contour,
    /// Sum of the fluid-body pair forces of the momentum equation ([`crate::sph::body_force`]), with the
    /// force along the wall that the Riemann dissipation makes (exactly the momentum the fluid receives).
    PairForces,
    /// The wall-normal part of the fluid-body pair forces, each fluid particle's along the contour
    /// normal at its foot: the pressure load, which the force-panel sensors integrate to
    /// ([`crate::sph::body_force`]).
    #[default]
    NormalPairForces,
}

/// How a sensor's pressure is obtained.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "kebab-case")]
pub enum SensorMethod {
    /// Mean over the sensor's width of the wall pressure extrapolated from the fluid (Adami et al. 2012),
    /// zero where the fluid support is below the dry threshold. With the corrected divergence (the
    /// default) it reads the jet-root peak about 25 % low.
    Interpolated,
    /// Normal force of the fluid-body pair forces on the body dummies whose contour projection lies
    /// within the sensor's span, divided by the span: a transducer that measures the force on its
    /// face, consistent with the pair-force section force. The default: the method of the default
    /// scheme, whose wedge peaks converge to the similarity solution.
    #[default]
    #[serde(alias = "force_panel")]
    ForcePanel,
}

/// Resolution level.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum Level {
    /// 40 particles across the largest half-breadth.
    Coarse,
    /// 80 particles across the largest half-breadth.
    Medium,
    /// 160 particles across the largest half-breadth.
    Fine,
}

impl Level {
    /// Particles across the largest half-breadth.
    pub fn particles_per_half_beam(self) -> f64 {
        match self {
            Level::Coarse => 40.0,
            Level::Medium => 80.0,
            Level::Fine => 160.0,
        }
    }
}

/// The particle layout of an automatic tank ([`crate::sph::refinement`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
#[serde(rename_all = "lowercase")]
pub enum TankLayout {
    /// The spacing dp in a band around the body (1.5 half-breadths beside it and under the keel's
    /// deepest position), 2 dp beyond: about a third of the particles.
    Refined,
    /// The spacing dp throughout.
    Uniform,
}

/// Everything a run needs, fully resolved. Written to the output folder as `setup.json`.
#[derive(Debug, Clone, Serialize)]
pub struct Setup {
    pub name: String,
    /// Starboard half of the section, keel first (body frame); `None` for a tank without a body.
    #[serde(rename = "section_points_y_z_m")]
    pub section_points: Option<Vec<[f64; 2]>>,
    pub motion: Option<MotionSpec>,
    #[serde(rename = "water_density_kg_per_m3")]
    pub rho0: f64,
    #[serde(rename = "gravity_m_per_s2")]
    pub g: f64,
    #[serde(rename = "dp_m")]
    pub dp: f64,
    pub h_over_dp: f64,
    #[serde(rename = "c0_m_per_s")]
    pub c0: f64,
    pub eos: EosKind,
    /// delta-SPH coefficient (Antuono et al. 2010).
    pub delta: f64,
    /// Artificial viscosity coefficient.
    pub alpha: f64,
    /// Courant number.
    pub cfl: f64,
    /// Particle shifting with free-surface treatment ([`crate::sph::shifting`]).
    #[serde(default)]
    pub shifting: bool,
    /// Low-dissipation Riemann pair terms instead of delta-SPH and artificial viscosity
    /// ([`crate::sph::riemann`]).
    #[serde(default)]
    pub riemann: bool,
    /// The velocity divergence of the continuity equation with the kernel-gradient correction
    /// ([`crate::sph::kernel_correction`]). Off by default (and in the summaries of runs made before
    /// it existed).
    #[serde(default)]
    pub divergence_correction: bool,
    /// Body dummies weighted by the wetness of the body's face ([`crate::sph::wall_wetness`]). Off by
    /// default (and in the summaries of runs made before it existed).
    #[serde(default)]
    pub wall_wetness: bool,
    /// How the section force is computed.
    #[serde(default)]
    pub force: ForceMethod,
    /// How the sensor pressures are computed.
    #[serde(default)]
    pub sensor_method: SensorMethod,
    #[serde(rename = "tank_half_width_m")]
    pub tank_half_width: f64,
    #[serde(rename = "tank_depth_m")]
    pub tank_depth: f64,
    #[serde(rename = "tank_wall_height_m")]
    pub tank_wall_height: f64,
    /// Thickness of the absorbing layer along the side walls and the bottom (m; 0 for none), inside
    /// the tank dimensions above ([`crate::sph::damping_zone`]).
    #[serde(default)]
    pub damping_zone: f64,
    /// Half domain with a symmetry plane at y = 0.
    pub mirror: bool,
    #[serde(rename = "t_end_s")]
    pub t_end: f64,
    /// Keel depth below the water surface at rest at t = 0 (m): 0 for a keel entry (the keel touches the
    /// surface), d0 > 0 for a section that starts immersed (a flare event of `assess`). The fluid is at rest
    /// with hydrostatic pressure and has no particle inside the body or within dp/2 of its contour.
    #[serde(
        rename = "initial_immersion_m",
        default,
        skip_serializing_if = "is_zero"
    )]
    pub initial_immersion: f64,
    /// The band of base resolution of a refined tank (the far field at 2 dp,
    /// [`crate::sph::refinement`]); `None` for one resolution throughout.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub refinement: Option<Band>,
    /// Air as a second phase ([`crate::sph::air`]); `None` for water only.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub air: Option<AirLayer>,
    pub sensors: Vec<SensorSpec>,
    /// Time between particle snapshots (VTK/PNG); `None` for none.
    #[serde(rename = "snapshot_interval_s")]
    pub snapshot_interval: Option<f64>,
    /// Cut-off of the zero-phase low-pass filter applied to the reported peaks (Hz); `None` for raw only.
    pub filter_cutoff_hz: Option<f64>,
    /// How each automatic choice was made.
    pub notes: Vec<String>,
}

fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

impl Setup {
    /// Lower bound of the sampling rate of the histories (Hz): one sample per step, and the step
    /// dt = min(C h / (c0 + |v|max), ...) of [`crate::sph::integrator::time_step`] is at most C h / c0.
    pub fn nominal_sample_hz(&self) -> f64 {
        self.c0 / (self.cfl * self.h_over_dp * self.dp)
    }

    /// Rough number of time steps (for reserving history storage).
    pub fn expected_steps(&self) -> usize {
        let dt = self.cfl * self.h_over_dp * self.dp / (self.c0 * 1.1);
        ((self.t_end / dt) * 1.3) as usize + 16
    }
}

/// Overrides of the automatic choices (all optional).
#[derive(Debug, Clone, Default)]
pub struct Overrides {
    pub level: Option<Level>,
    pub particles_per_half_beam: Option<f64>,
    pub dp: Option<f64>,
    pub c0: Option<f64>,
    pub h_over_dp: Option<f64>,
    pub eos: Option<EosKind>,
    pub delta: Option<f64>,
    pub alpha: Option<f64>,
    pub cfl: Option<f64>,
    pub shifting: Option<bool>,
    pub riemann: Option<bool>,
    pub divergence_correction: Option<bool>,
    pub wall_wetness: Option<bool>,
    pub force: Option<ForceMethod>,
    pub sensor_method: Option<SensorMethod>,
    pub tank_half_width: Option<f64>,
    pub tank_depth: Option<f64>,
    pub tank_wall_height: Option<f64>,
    pub damping_zone: Option<f64>,
    pub mirror: Option<bool>,
    pub t_end: Option<f64>,
    pub snapshot_interval: Option<f64>,
    pub filter_cutoff_hz: Option<f64>,
    /// Keel depth below the water at rest at t = 0 (m; None: 0, the keel at the surface).
    pub initial_immersion: Option<f64>,
    /// A refined tank: base resolution in a band around the body, 2 dp beyond (None: the default,
    /// refined with an automatic tank and the Riemann scheme, else uniform).
    pub refinement: Option<bool>,
    /// Air as a second phase (None: off).
    pub air: Option<AirChoice>,
    /// The air gap under the keel at the start of a keel entry with air (m; None: [`air::CLEARANCE_DP`]
    /// spacings).
    pub air_gap: Option<f64>,
}

/// Whether particle shifting is on unless a case says otherwise, in a single-phase run (a run with air
/// takes none: [`single_phase_default`]). On since the wall-resolved scheme became the default
/// (docs/numerics/wedge-convergence.md, item 33): shifting with free-surface treatment, the corrected
/// divergence and the wall's wetness together are the one combination measured under which the constant-
/// speed wedges' sensor peaks fall toward the exact similarity solution with refinement at 20, 30 and
/// 45 deg (mean error 3.3 / 7.9 / 9.5 % at 40 particles per half-beam and 4.2 / 4.5 / 4.6 % at 80,
/// against 7.8-18.7 % and 6.6-15.3 % with none of the three, whose error does not fall with refinement).
pub const DEFAULT_SHIFTING: bool = true;

/// Whether the body dummies are weighted by the wall's wetness unless a case says otherwise
/// ([`crate::sph::wall_wetness`]), in a single-phase run: on, as part of the scheme of
/// [`DEFAULT_SHIFTING`], with which it was measured (without the shifting and the corrected divergence it
/// reads the 30 and 45 deg wedges up to 20 and 49 % off the exact solution).
pub const DEFAULT_WALL_WETNESS: bool = true;

/// A default of the wall-resolved scheme ([`DEFAULT_SHIFTING`], [`DEFAULT_DIVERGENCE_CORRECTION`],
/// [`DEFAULT_WALL_WETNESS`]) for a run with or without air: the scheme is not built for two phases, so a
/// run with air takes the standard continuity equation and wall, and says so in its notes.
pub const fn single_phase_default(default: bool, two_phase: bool) -> bool {
    default && !two_phase
}

/// Courant number C of the acoustic time-step limit dt = C h / (c0 + |v|max) unless a case says otherwise
/// (see [`crate::sph::integrator`]). 0.4 (dt = 0.6 dp / c0 with h = 1.5 dp): against 0.2, the Zhao et al.
/// (1996) peak force moved by 0.3 %, the sensor peaks by under 1 % of Cp and the drop-test velocities by
/// under 0.005 m/s, for half the steps; 0.5, the largest a case may ask for, was still stable on the
/// Zhao case.
pub const DEFAULT_CFL: f64 = 0.4;

/// Largest Mach number V / c0 of the body speed that weakly compressible SPH is given: the density
/// variation of the flow, of order Ma^2 / 2, stays below half a per cent.
pub const MAX_MACH: f64 = 0.1;

/// Whether the Riemann pair terms are on unless a case says otherwise.
pub const DEFAULT_RIEMANN: bool = true;

/// Whether the velocity divergence is kernel-gradient corrected unless a case says otherwise
/// ([`crate::sph::kernel_correction`]), in a single-phase run: on, as part of the scheme of
/// [`DEFAULT_SHIFTING`]. Its sensors are read as force panels ([`SensorMethod::ForcePanel`], the default
/// sensor method): the interpolated wall pressure reads the jet-root peak about 25 % low with it.
pub const DEFAULT_DIVERGENCE_CORRECTION: bool = true;

/// Resolve a case: fill every automatic choice not overridden, and record how.
pub fn resolve(
    name: &str,
    section: &Section,
    motion: &MotionSpec,
    sensors: Vec<SensorSpec>,
    o: &Overrides,
) -> Result<Setup> {
    let built = motion.build()?;
    let mut notes = Vec::new();
    let d0 = o.initial_immersion.unwrap_or(0.0);
    if !(d0.is_finite() && d0 >= 0.0 && d0 < section.height()) {
        return Err(Error::Invalid(format!(
            "the initial immersion must be at least 0 m and below the section's height ({:.4} m), got {d0} m",
            section.height()
        )));
    }
    if d0 > 0.0 {
        notes.push(format!(
            "the section starts immersed: keel {d0:.4} m below the water surface at rest at t = 0 (fluid at rest, \
             hydrostatic pressure, no particle inside the body or within dp/2 of its contour); the contact \
             transient is then the start of the motion"
        ));
    }
    let b = section.half_breadth();
    let n_half = o
        .particles_per_half_beam
        .unwrap_or(o.level.unwrap_or(Level::Coarse).particles_per_half_beam());
    let dp = match o.dp {
        Some(d) => {
            notes.push(format!("dp = {d} m (given)"));
            d
        }
        None => {
            let d = b / n_half;
            notes.push(format!(
                "dp = b/N = {b:.4}/{n_half} = {d:.5} m (b largest half-breadth)"
            ));
            d
        }
    };
    let t_end = match o.t_end {
        Some(t) => {
            notes.push(format!("t_end = {t} s (given)"));
            t
        }
        None => {
            let c = automatic::end_time(section, &built, &sensors, dp, d0);
            notes.push(c.note);
            c.value
        }
    };
    let g = 9.81;
    let keel_depth_end = d0 + keel_depth(&built, t_end);
    let (auto_w, auto_d, auto_layer, tank_note) = automatic::tank(section, keel_depth_end);
    let tank_given = o.tank_half_width.is_some() || o.tank_depth.is_some();
    let mut tank_half_width = o.tank_half_width.unwrap_or(auto_w);
    let mut tank_depth = o.tank_depth.unwrap_or(auto_d);
    // The refined tank is the default wherever it applies: an automatic tank and the Riemann scheme.
    // A tank given by the user (an experiment's) stays uniform unless asked.
    let riemann = o.riemann.unwrap_or(DEFAULT_RIEMANN);
    let refine = match o.refinement {
        Some(r) => r,
        None if tank_given => {
            notes.push("uniform tank (the tank is given; `refined = true` refines it)".into());
            false
        }
        None if !riemann => {
            notes.push("uniform tank (a refined one needs the Riemann scheme)".into());
            false
        }
        None => true,
    };
    let refinement = if refine {
        let (band, note) = automatic::refinement_band(section, keel_depth_end, dp);
        tank_half_width = refinement::to_coarse_lattice(tank_half_width, dp);
        tank_depth = refinement::to_coarse_lattice(tank_depth, dp);
        notes.push(note);
        Some(band)
    } else {
        None
    };
    let tank_wall_height = o.tank_wall_height.unwrap_or(0.25 * tank_depth);
    // An absorbing layer comes with the automatic tank; a tank given by the user (an experiment's, say)
    // has reflecting walls unless a layer is asked for too.
    let damping_zone = o
        .damping_zone
        .unwrap_or(if tank_given { 0.0 } else { auto_layer });
    if tank_given {
        notes.push(format!(
            "tank half-width {tank_half_width:.3} m and depth {tank_depth:.3} m (given in part or whole; \
             absorbing layer {damping_zone:.3} m)"
        ));
    } else {
        notes.push(tank_note);
    }
    if o.damping_zone.is_some() {
        notes.push(format!("absorbing layer {damping_zone} m thick (given)"));
    }
    let c0 = match o.c0 {
        Some(c) => {
            notes.push(format!("c0 = {c} m/s (given)"));
            c
        }
        None => {
            let c = automatic::sound_speed(section, built.max_speed(t_end), g, tank_depth);
            notes.push(c.note);
            if c.value > automatic::MAX_C0 {
                return Err(Error::Invalid(format!(
                    "the automatic sound speed would be {:.0} m/s, above the real sound speed of water \
                     ({} m/s): an entry at {:.1} m/s is outside weakly compressible SPH (its acoustic phase is \
                     real physics there)",
                    c.value,
                    automatic::MAX_C0,
                    built.max_speed(t_end)
                )));
            }
            c.value
        }
    };
    let air = resolve_air(section, o, &refinement, keel_depth_end, d0, dp, &mut notes)?;
    let two_phase = air.is_some();
    let shifting = o
        .shifting
        .unwrap_or(single_phase_default(DEFAULT_SHIFTING, two_phase));
    let divergence_correction = o.divergence_correction.unwrap_or(single_phase_default(
        DEFAULT_DIVERGENCE_CORRECTION,
        two_phase,
    ));
    let wall_wetness = o
        .wall_wetness
        .unwrap_or(single_phase_default(DEFAULT_WALL_WETNESS, two_phase));
    if two_phase
        && o.shifting.is_none()
        && o.divergence_correction.is_none()
        && o.wall_wetness.is_none()
    {
        notes.push(
            "with air: no particle shifting, uncorrected velocity divergence and an unweighted wall (the \
             single-phase default scheme is not built for two phases)"
                .into(),
        );
    }
    if divergence_correction {
        notes.push(
            "velocity divergence with the kernel-gradient correction (divergence_correction = true): no \
             spurious compression of free-surface particles ahead of the jet root; read the sensors with \
             sensor_method = \"force-panel\" (the interpolated wall pressure then reads the root peak low)"
                .into(),
        );
    }
    if wall_wetness {
        notes.push(if shifting && divergence_correction {
            "body dummies weighted by the wetness of the body's face (wall_wetness = true)".to_string()
        } else {
            "body dummies weighted by the wetness of the body's face (wall_wetness = true) without the \
             shifting and the corrected divergence it was measured with: on the 30 and 45 deg wedges it then \
             reads up to 20 and 49 % off the exact solution (docs/numerics/wedge-convergence.md, item 29)"
                .to_string()
        });
    }
    let setup = Setup {
        name: name.to_string(),
        section_points: Some(section.half_points().to_vec()),
        motion: Some(motion.clone()),
        rho0: 1000.0,
        g,
        dp,
        h_over_dp: o.h_over_dp.unwrap_or(1.5),
        c0,
        eos: o.eos.unwrap_or(EosKind::Linear),
        delta: o.delta.unwrap_or(0.1),
        alpha: o.alpha.unwrap_or(0.02),
        cfl: o.cfl.unwrap_or(DEFAULT_CFL),
        shifting,
        riemann,
        divergence_correction,
        wall_wetness,
        force: o.force.unwrap_or_default(),
        sensor_method: o.sensor_method.unwrap_or_default(),
        tank_half_width,
        tank_depth,
        tank_wall_height,
        damping_zone,
        mirror: o.mirror.unwrap_or(true),
        t_end,
        initial_immersion: d0,
        refinement,
        air,
        sensors,
        snapshot_interval: o.snapshot_interval,
        filter_cutoff_hz: o.filter_cutoff_hz,
        notes,
    };
    check(&setup)?;
    Ok(setup)
}

/// The air layer of a run, by the `air` choice: none when off; when on (or auto and the deadrise is
/// low, [`air::auto_needs_air`], within the expected wetted half-width: the half-breadth at the keel's
/// deepest immersion, times pi/2 for the water's rise, Wagner 1932), a layer of standard air over the
/// calm surface as wide as the band of base resolution (the refined tank's, or 1.5 half-breadths without
/// one) and of height
///
///   h = min(d_end, H) + g + 3 dp,
///
/// d_end the keel's deepest immersion of the run (the water beside a section rises by less: (pi/2 - 1)
/// of the immersion at the spray root of a wedge, Wagner 1932), H the section's height above the water
/// at the start, and g the air gap under the keel (given, or the larger of [`air::CLEARANCE_DP`] spacings
/// and [`air::FLAT_GAP_FRACTION`] of the flat keel's half-width; none for an immersed start).
/// The air above that height is pushed aside by the hull's descent at pressures of order rho_a V^2, a
/// few pascals: on Ochi's flat 0.174 Lpp section at 1 m/s a layer as high as the section (0.57 m) and
/// one 0.81 m high gave the keel sensors' cushion peaks and the section force's peak of this layer
/// (0.27 m) within 0.3 %, at half its air particles (docs/guide/air.md).
fn resolve_air(
    section: &Section,
    o: &Overrides,
    refinement: &Option<Band>,
    keel_depth_end: f64,
    d0: f64,
    dp: f64,
    notes: &mut Vec<String>,
) -> Result<Option<AirLayer>> {
    let on = match o.air.unwrap_or_default() {
        AirChoice::Off if o.air_gap.is_some() => {
            return Err(Error::Invalid(
                "an air gap under the keel is given (air_gap_m) but air is off: set air = \"on\" or \"auto\", \
                 or leave the gap out"
                    .into(),
            ));
        }
        AirChoice::Off => return Ok(None),
        AirChoice::On => {
            notes.push(format!("{} (given)", air::ON_NOTE));
            true
        }
        AirChoice::Auto => {
            let wetted = (std::f64::consts::FRAC_PI_2 * section.half_breadth_at(keel_depth_end))
                .min(section.half_breadth());
            let (on, why) = air::auto_needs_air(section.half_points(), wetted.max(dp));
            notes.push(why);
            on
        }
    };
    if !on {
        return Ok(None);
    }
    let half_width = refinement
        .as_ref()
        .map_or(1.5 * section.half_breadth(), |b| b.half_width);
    let clearance = match o.air_gap {
        _ if d0 > 0.0 => 0.0,
        Some(g) => {
            notes.push(format!("air gap under the keel {:.2} mm (given)", g * 1e3));
            g
        }
        None => (air::CLEARANCE_DP * dp).max(air::FLAT_GAP_FRACTION * section.half_breadth_at(0.0)),
    };
    let above = (section.height() - d0).max(0.0);
    let height = above.min(keel_depth_end) + clearance + 3.0 * dp;
    let layer = AirLayer::standard(half_width, height, clearance);
    let phase = layer.phase();
    notes.push(format!(
        "air layer: {half_width:.3} m half-width, {height:.3} m over the calm surface (the keel's deepest immersion \
         of the run, at most the section's height above the water at the start, its clearance and 3 dp); standard air, {:.3} kg/m3, {:.0} Pa, gamma {}, sound \
         speed {:.0} m/s (the air takes its own substeps, limited by it, within the water's time step)",
        phase.rho0, phase.p_atm, phase.gamma, phase.c
    ));
    if clearance > 0.0 {
        notes.push(format!(
            "air gap: the keel starts {:.2} mm ({:.1} dp) above the calm surface and closes it at the entry speed \
             before t = 0, the instant it reaches the calm surface (the run's records start at negative times); \
             by default the larger of {} dp and {} of the flat keel's half-width",
            clearance * 1e3,
            clearance / dp,
            air::CLEARANCE_DP,
            air::FLAT_GAP_FRACTION
        ));
    }
    Ok(Some(layer))
}

/// Sanity checks on a resolved setup (catches overrides that cannot work).
pub fn check(s: &Setup) -> Result<()> {
    let bad =
        |what: &str, v: f64| Error::Invalid(format!("{what} must be a positive number, got {v}"));
    for (what, v) in [
        ("dp", s.dp),
        ("c0", s.c0),
        ("h_over_dp", s.h_over_dp),
        ("cfl", s.cfl),
        ("tank half-width", s.tank_half_width),
        ("tank depth", s.tank_depth),
        ("t_end", s.t_end),
    ] {
        if !(v.is_finite() && v > 0.0) {
            return Err(bad(what, v));
        }
    }
    if s.h_over_dp < 1.0 || s.h_over_dp > 3.0 {
        return Err(Error::Invalid(format!(
            "h/dp must lie in [1, 3], got {}",
            s.h_over_dp
        )));
    }
    if s.cfl > 0.5 {
        return Err(Error::Invalid(format!(
            "Courant number must be at most 0.5, got {}",
            s.cfl
        )));
    }
    let n = (s.tank_half_width / s.dp) * (s.tank_depth / s.dp) * if s.mirror { 1.0 } else { 2.0 };
    if n > 2.0e7 {
        return Err(Error::Invalid(format!(
            "{n:.3e} fluid particles: choose a larger dp or a smaller tank"
        )));
    }
    if n < 100.0 {
        return Err(Error::Invalid(format!(
            "only {n:.0} fluid particles: dp {} m is too large for the tank",
            s.dp
        )));
    }
    if let Some(MotionSpec::FreeHeave { mass_per_m_kg, .. }) = &s.motion
        && !(mass_per_m_kg.is_finite() && *mass_per_m_kg > 0.0)
    {
        return Err(bad("mass per metre", *mass_per_m_kg));
    }
    // Weak compressibility needs the sound speed well above the flow speed; at or above it the
    // "incompressible" water is hit supersonically and the results mean nothing.
    if let Some(m) = &s.motion {
        let built = m.build()?;
        let v = built.max_speed(s.t_end);
        if v > MAX_MACH * s.c0 {
            return Err(Error::Invalid(format!(
                "sound speed c0 = {} m/s is not well above the body speed {v} m/s (Mach number {:.3}, at most \
                 {MAX_MACH}): weakly compressible SPH needs c0 at least 10 times the flow speed (the automatic \
                 choice gives about 20 times the entry speed at 30 deg deadrise)",
                s.c0,
                v / s.c0
            )));
        }
        if let Some(p) = &s.section_points
            && !matches!(m, MotionSpec::FreeHeave { .. })
        {
            let height = p.iter().map(|q| q[1]).fold(f64::NEG_INFINITY, f64::max)
                - p.iter().map(|q| q[1]).fold(f64::INFINITY, f64::min);
            let depth = s.initial_immersion + keel_depth(&built, s.t_end);
            if depth > height {
                return Err(Error::Invalid(format!(
                    "t_end = {} s takes the keel {depth:.3} m deep, more than the section's height ({height:.3} m): \
                     the whole section would be under water, long after the impact is over (leave t_end out for \
                     the automatic end of the impact)",
                    s.t_end
                )));
            }
        }
    }
    if let Some(band) = &s.refinement {
        if !s.riemann {
            return Err(Error::Invalid(
                "a refined tank needs the Riemann scheme (riemann = true)".into(),
            ));
        }
        if !(band.half_width > 0.0
            && band.depth > 0.0
            && band.half_width < s.tank_half_width
            && band.depth < s.tank_depth)
        {
            return Err(Error::Invalid(format!(
                "the refined band ({:.3} m half-width, {:.3} m deep) must lie inside the tank ({:.3} m, {:.3} m)",
                band.half_width, band.depth, s.tank_half_width, s.tank_depth
            )));
        }
    }
    if let Some(a) = &s.air {
        if !s.riemann {
            return Err(Error::Invalid(
                "a run with air needs the Riemann scheme (riemann = true): its pair terms between the phases \
                 are the two-phase Riemann solver"
                    .into(),
            ));
        }
        if s.shifting || s.divergence_correction || s.wall_wetness {
            return Err(Error::Invalid(
                "a run with air takes neither particle shifting, the corrected divergence nor the wall's \
                 wetness (not built for two phases); leave shifting, divergence_correction and wall_wetness \
                 off"
                    .into(),
            ));
        }
        if !(a.clearance.is_finite() && a.clearance >= 0.0) {
            return Err(Error::Invalid(format!(
                "the air gap under the keel must be at least 0 m, got {} m",
                a.clearance
            )));
        }
        if a.clearance > 0.0 && s.initial_immersion > 0.0 {
            return Err(Error::Invalid(
                "a section that starts immersed has no air gap under its keel (clearance 0)".into(),
            ));
        }
        for (what, v) in [
            ("air density", a.rho0),
            ("atmospheric pressure", a.p_atm),
            ("air layer half-width", a.half_width),
            ("air layer height", a.height),
        ] {
            if !(v.is_finite() && v > 0.0) {
                return Err(bad(what, v));
            }
        }
        if !(a.gamma.is_finite() && a.gamma >= 1.0) {
            return Err(Error::Invalid(format!(
                "the air's ratio of specific heats must be at least 1, got {}",
                a.gamma
            )));
        }
        if let Some(band) = &s.refinement
            && a.half_width > band.half_width + 1e-12
        {
            return Err(Error::Invalid(format!(
                "the air layer ({:.3} m half-width) must lie inside the refined band ({:.3} m): air is at the base \
                 spacing only",
                a.half_width, band.half_width
            )));
        }
        if a.half_width > s.tank_half_width {
            return Err(Error::Invalid(format!(
                "the air layer ({:.3} m half-width) must lie inside the tank ({:.3} m)",
                a.half_width, s.tank_half_width
            )));
        }
    }
    if !(s.damping_zone >= 0.0 && s.damping_zone < s.tank_half_width.min(s.tank_depth)) {
        return Err(Error::Invalid(format!(
            "the absorbing layer must be at least 0 m and thinner than the tank's half-width and depth, got {} m",
            s.damping_zone
        )));
    }
    Ok(())
}

/// Depth of the keel below the calm surface at time `t` (the free-fall estimate for a free drop: the
/// initial speed held).
fn keel_depth(m: &Motion, t: f64) -> f64 {
    match m {
        Motion::FreeHeave { speed0, .. } => speed0 * t,
        _ => {
            let n = 2000;
            let dt = t / n as f64;
            (0..n)
                .map(|k| dt * m.speed_at((k as f64 + 0.5) * dt).unwrap_or(0.0))
                .sum::<f64>()
                .max(0.0)
        }
    }
}

pub use crate::sph::case_file::{from_file, from_source};
