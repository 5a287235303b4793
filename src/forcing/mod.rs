//! Measured forcing: a station's 2D water entry driven by a measured or externally computed
//! relative-motion record (model test, full-scale monitoring, a nonlinear seakeeping code) instead of the
//! linear strip theory of [`crate::seakeeping`]. This is how Veen (2010, s. 6.2) ran the Hermundstad &
//! Moan (2005) flare panel: the relative elevation measured optically at 500 Hz, differentiated, imposed on
//! the 2D section.
//!
//! The steps, one module each:
//! * [`record_csv`] reads the record (CSV with units in the header, `#` provenance lines) and rejects bad
//!   input with file:line:column;
//! * [`keel_entry`] derives the relative velocity from an elevation record (central differences, no
//!   smoothing), finds the keel-entry instant and cuts the entry-velocity profile V(t) after it, in the
//!   form strip theory gives ([`crate::seakeeping::relative_motion::KeelEntry`]), so the prescribed motion
//!   of the 2D run is built the same way ([`crate::impact::entry_motion`]).
//!
//! Sign convention (as [`crate::seakeeping::relative_motion`]): the relative elevation s is the height of
//! the station's still-water-line point above the local water surface, positive with the hull above the
//! water; the keel is out of the water while s > T (T the local draft) and enters when s falls through T.
//! The relative velocity is Ds/Dt (positive upward); the entry velocity V = -Ds/Dt (positive downward).

pub mod keel_entry;
pub mod record_csv;

pub use keel_entry::{MeasuredEntry, measured_entry};
pub use record_csv::{Column, ForcingRecord, parse_record_text, read_record};
