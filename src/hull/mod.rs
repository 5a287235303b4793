//! Hull definition (in progress).
