//! # slamtool
//!
//! A 2D+t ship-slamming design tool after Veen (2010): strip theory gives the heave and pitch of a ship in
//! head seas, the relative vertical motion and velocity at each bow station turn into 2D water-entry
//! problems, and a weakly compressible SPH solver (with analytic Wagner-type cross-checks) gives the
//! slamming pressures and section loads.
//!
//! ## Axes and units (used everywhere in the crate)
//!
//! * SI units throughout (m, s, kg, N, Pa, rad). Degrees appear only at the input/output edge, and then the
//!   field name says so (`deadrise_deg`).
//! * Ship axes: x forward, y to port, z up. The origin is at midship (half-way between the perpendiculars)
//!   on the baseline. The forward perpendicular is at x = +Lpp/2, the aft perpendicular at x = -Lpp/2.
//! * Stations may be given as x (m) or as a fraction of Lpp aft of the forward perpendicular, the way the
//!   slamming literature gives them (`aft_of_fp = 0.1` is x = 0.4 Lpp).
//! * Heave positive up, pitch positive bow down (Salvesen, Tuck & Faltinsen 1970).
//! * 2D water-entry frame: y horizontal, z up, undisturbed free surface at z = 0.
//!
//! ## Pipeline
//!
//! `hull` + `sea` → `seakeeping` → `impact` → water entry (`sph`, `analytic`) → `loads` → `report`.
//! Each step is one module that owns its types; data flows one way.

pub mod analytic;
pub mod assess;
pub mod error;
pub mod files;
pub mod forcing;
pub mod hull;
pub mod impact;
pub mod input;
pub mod loads;
pub mod numerics;
pub mod output_policy;
pub mod plot;
pub mod progress;
pub mod provenance;
pub mod report;
pub mod sea;
pub mod seakeeping;
pub mod sph;
pub mod sweep;
pub mod validate;

pub use error::{Error, InputError, Result};
