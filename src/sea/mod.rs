//! Sea states (in progress).
