//! Latin hypercube sampling (McKay, Beckman & Conover 1979) with a small seeded generator, so that a sweep
//! file with a `seed` gives the same samples on every machine and with every thread count.
//!
//! **Generator.** SplitMix64 (Steele, Lea & Flood 2014): state s ← s + 0x9E3779B97F4A7C15, then the output
//! z = s, z ← (z ⊕ (z ≫ 30))·0xBF58476D1CE4E5B9, z ← (z ⊕ (z ≫ 27))·0x94D049BB133111EB, z ⊕ (z ≫ 31).
//! A uniform number in [0, 1) is the top 53 bits of z times 2⁻⁵³.
//!
//! **Design.** For n samples and d parameters (in the sweep's fixed parameter order), each parameter k gets
//! a random permutation π_k of 0..n (Fisher–Yates, drawing j uniformly in 0..=i for i = n−1 down to 1, as
//! ⌊u (i + 1)⌋), then n jitters u_{k,0..n}; sample i of parameter k is the unit value
//! (π_k(i) + u_{k,i}) / n, so each of the n equal strata of every parameter holds exactly one sample. The
//! unit value maps linearly onto [min, max].

/// SplitMix64 pseudo-random generator.
#[derive(Debug, Clone)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    pub fn new(seed: u64) -> Self {
        Self { state: seed }
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform number in [0, 1).
    pub fn unit(&mut self) -> f64 {
        (self.next_u64() >> 11) as f64 * (1.0 / (1u64 << 53) as f64)
    }
}

/// An n-sample Latin hypercube over `dims` unit intervals: `result[i][k]` is sample i of parameter k, in
/// [0, 1).
pub fn unit_hypercube(n: usize, dims: usize, seed: u64) -> Vec<Vec<f64>> {
    let mut rng = SplitMix64::new(seed);
    let mut out = vec![vec![0.0; dims]; n];
    for k in 0..dims {
        let mut perm: Vec<usize> = (0..n).collect();
        for i in (1..n).rev() {
            let j = ((rng.unit() * (i + 1) as f64) as usize).min(i);
            perm.swap(i, j);
        }
        for (i, row) in out.iter_mut().enumerate() {
            row[k] = (perm[i] as f64 + rng.unit()) / n as f64;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix_matches_the_reference_sequence() {
        // First outputs of SplitMix64 seeded with 0 (the reference C implementation of Vigna).
        let mut r = SplitMix64::new(0);
        assert_eq!(r.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(r.next_u64(), 0x6E78_9E6A_A1B9_65F4);
    }

    #[test]
    fn every_stratum_holds_one_sample_and_the_seed_decides() {
        let n = 37;
        let s = unit_hypercube(n, 3, 42);
        for k in 0..3 {
            let mut strata: Vec<usize> = s.iter().map(|r| (r[k] * n as f64) as usize).collect();
            strata.sort_unstable();
            assert_eq!(strata, (0..n).collect::<Vec<_>>());
        }
        assert_eq!(s, unit_hypercube(n, 3, 42));
        assert_ne!(s, unit_hypercube(n, 3, 43));
    }
}
