//! Analytic water-entry estimates: a second opinion on every SPH peak and a fast screening mode.
//!
//! All for a 2D symmetric section entering calm water, incompressible, no air, no gravity.

pub mod entry_kinematics;
pub mod generalised_wagner;
pub mod logvinovich_mlm;
pub mod peak;
pub mod section_profile;
pub mod similarity;
mod similarity_bem;
pub mod similarity_force;
mod similarity_mesh;
pub mod similarity_sensor;
mod similarity_solver;
pub mod similarity_table;
pub mod von_karman;
pub mod wagner;
pub mod wagner_pressure;
pub mod zhao_faltinsen1993;
