//! Seakeeping: strip theory for heave and pitch in head seas, relative motion and velocity along the hull,
//! and slamming statistics (Veen 2010, ch. 3 and 6; design notes in `physics.md` sections 1-2).
//!
//! Axes as in the crate docs: x forward from midship, z up, pitch positive bow down (Salvesen, Tuck &
//! Faltinsen 1970). Complex amplitudes use the time factor e^{i w_e t} with w_e the encounter frequency.

pub mod section;
