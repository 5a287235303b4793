//! Loads from water-entry histories: peaks, their times, impulses, zero-phase low-pass filtering, and how
//! converged a peak is in particle spacing.

pub mod anatomy;
pub mod butterworth;
pub mod convergence;
pub mod cutoff;
pub mod peaks;

pub use butterworth::{LowPass, resample_uniform};
pub use peaks::{Peak, filtered_record, peak, summarise};
