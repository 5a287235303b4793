//! Loads from water-entry histories: peaks, their times, impulses, and zero-phase low-pass filtering.

pub mod butterworth;
pub mod peaks;

pub use butterworth::{LowPass, resample_uniform};
pub use peaks::{Peak, peak, summarise};
