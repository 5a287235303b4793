//! Small numerical building blocks shared by the pipeline steps.

pub mod bisection;
pub mod pchip;
pub mod quadrature;

pub use bisection::bisect;
pub use pchip::Pchip;
