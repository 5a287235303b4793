//! Small numerical building blocks shared by the pipeline steps.

pub mod pchip;
pub mod quadrature;

pub use pchip::Pchip;
