//! Wall and body boundary conditions. One file per published method.

pub mod adami2012;
pub mod kruisbrink2018;
