//! Which samples of a force or pressure record may carry its peak after a singular start.
//!
//! The rule: after a singular start (a flat keel wetted at once on contact, or a section starting
//! immersed; the wetted width starts at a finite value with dc/dt unbounded) the force and pressure fall
//! from infinity, so the largest of the first samples is set by where the sampling happens to begin,
//! not by the flow. The peak is therefore taken only from the first sample where the value rises again
//! (the load of the contour beyond the flat, of a flare, or of the contact reaching a sensor panel), and
//! a record that only decays has no peak. The Wagner section force and jet-root pressure
//! ([`crate::analytic::generalised_wagner::WagnerEstimate::force_peak`]) and the assessment's MLM
//! sensor pressures (`assess::analytic`) both follow it through [`peak_candidates`].

/// The samples of `x` that may carry its peak, out of `kept` (indices into `x` in time order, e.g. the
/// samples not at the acoustic limit), by the rule of the module notes.
///
/// With `falls_from_start` (the record starts at the singular value and falls from infinity) the
/// candidates are the kept samples from the first one where `x` rises again on (a kept sample whose
/// successor among `kept` is larger), and `None` when `x` only decays over `kept` (no peak). Without it
/// they are all of `kept`. `Some` of an empty slice means no sample was kept at all.
pub fn peak_candidates<'a>(
    x: &[f64],
    kept: &'a [usize],
    falls_from_start: bool,
) -> Option<&'a [usize]> {
    if !falls_from_start {
        return Some(kept);
    }
    kept.windows(2)
        .position(|w| x[w[1]] > x[w[0]])
        .map(|i| &kept[i..])
}

#[cfg(test)]
mod tests {
    use super::peak_candidates;

    #[test]
    fn after_a_singular_start_the_peak_is_taken_from_the_first_rise() {
        let kept = [1, 2, 3, 4, 5];
        // only decaying after the start: no peak
        let decay = [9e9, 500.0, 300.0, 200.0, 150.0, 120.0];
        assert_eq!(peak_candidates(&decay, &kept, true), None);
        // decaying, then rising again: the candidates start at the last sample before the rise
        let later = [9e9, 500.0, 300.0, 200.0, 350.0, 280.0];
        assert_eq!(peak_candidates(&later, &kept, true), Some(&kept[2..]));
        // no singular start: every kept sample
        assert_eq!(peak_candidates(&decay, &kept, false), Some(&kept[..]));
        // a single kept sample cannot rise: no peak after a singular start
        assert_eq!(peak_candidates(&decay, &kept[..1], true), None);
        // nothing kept: no candidate, but not the "only decays" case unless the start is singular
        assert_eq!(peak_candidates(&decay, &[], false), Some(&[][..]));
        assert_eq!(peak_candidates(&decay, &[], true), None);
    }
}
