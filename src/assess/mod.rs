//! `slamtool assess`: the 2D+t assessment of a hull in a sea state (Veen 2010, ch. 6), from strip-theory
//! relative motion to station pressures and section loads.
//!
//! The layers, in the order the data flows:
//!
//! * [`plan`]: strip theory at every speed and regular wave of the sea-state file, at the stations that
//!   carry sensors; each station whose keel emerges gives one water-entry event (its section, driven by
//!   the entry-velocity history after keel entry, with the station's sensors). Where the keel stays in the
//!   water the station is recorded as "no slam", with the flag `slamtool motions` prints (Ochi 1964), and
//!   where the water then reaches sensors above the still-water line it gives a flare event: the section
//!   immersed to its least immersion d0 = T - |s_a| in water at rest, driven from that instant
//!   ([`crate::impact::flare`]).
//!   Irregular seas give Ochi's slam statistics and one design event per slamming station and speed
//!   ([`design_event`]).
//! * [`analytic`]: modified Logvinovich section force and sensor pressures for an event, corrected to the
//!   similarity solution.
//! * [`execute`]: the SPH runs (with a convergence companion), in parallel, through the [`cache`].
//! * [`results`]: per event, per station (design pressure per sensor: the maximum over events) and the
//!   files (`summary.json`, `pressures.csv`).
//! * [`limits`]: the design-pressure gate.

pub mod analytic;
pub mod bow_force;
pub mod cache;
pub mod chines;
pub mod comparisons;
pub mod design_event;
pub mod design_rule;
pub mod diff;
pub mod execute;
pub mod keel_slope;
pub mod limits;
pub mod measured;
pub mod plan;
pub mod results;
pub mod trends;

pub use execute::run;
pub use plan::{Event, Fidelity, Plan, Settings};
pub use results::{Assessment, DesignValue, EventResult, SphRecord, StationResult};
