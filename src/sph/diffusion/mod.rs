//! Density diffusion terms for the continuity equation. One file per published method.

pub mod antuono2010;
