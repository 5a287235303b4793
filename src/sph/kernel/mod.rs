//! Smoothing kernels. One file per published kernel.

pub mod wendland_c2;

pub use wendland_c2::WendlandC2;
