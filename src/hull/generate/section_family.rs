//! Section shapes for the reconstructed hulls.
//!
//! Below the waterline a one-parameter family of half-sections (a reconstruction device, not a published
//! form): with η = z/T,
//!
//! y(z) = b [1 − (1 − η)^q],  half-section area a = ∫₀ᵀ y dz = b T q/(q + 1),
//!
//! so the area coefficient σ = a/(b T) = q/(q + 1), q = σ/(1 − σ). σ = 1/2 (q = 1) is a straight V from the
//! keel to the waterline; σ → 1 a rectangle with a small bilge. The deadrise at the keel is
//! atan(T/(q b)) and the side is vertical at the waterline for q > 1.
//!
//! Above the waterline a flare y(z) = b + Δ s^m with s = (z − T)/(D − T), tangent to the vertical side
//! at the waterline for m > 1; Δ is the increase of half-breadth up to the deck at height D.

/// Power-law half-section below the waterline.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerSection {
    /// Waterline half-breadth b, m.
    pub half_breadth: f64,
    /// Height of the waterline above the keel T, m.
    pub draft: f64,
    /// Area coefficient σ = a/(b T), in [0.5, 1).
    pub sigma: f64,
}

impl PowerSection {
    /// q = σ/(1 − σ).
    pub fn exponent(&self) -> f64 {
        self.sigma / (1.0 - self.sigma)
    }

    /// Half-breadth at height z above the keel (0 ≤ z ≤ T).
    pub fn y(&self, z: f64) -> f64 {
        let eta = (z / self.draft).clamp(0.0, 1.0);
        self.half_breadth * (1.0 - (1.0 - eta).powf(self.exponent()))
    }

    /// Half-section area b T σ, m².
    pub fn half_area(&self) -> f64 {
        self.half_breadth * self.draft * self.sigma
    }

    /// Deadrise angle at the keel, rad: atan(T/(q b)).
    pub fn keel_deadrise(&self) -> f64 {
        (self.draft / (self.exponent() * self.half_breadth)).atan()
    }

    /// Heights that resolve the shape: `n` equal steps in z (the side), `n` equal steps in y (the bottom)
    /// and `n` equal steps in the slope angle of the contour (the bilge turn), keel and waterline included.
    /// The slope angle from the vertical is φ with tan φ = dy/dz = (q b/T)(1 − η)^(q−1), so
    /// η = 1 − (T tan φ/(q b))^(1/(q−1)) for q > 1.
    pub fn z_levels(&self, n: usize) -> Vec<f64> {
        let q = self.exponent();
        let mut z: Vec<f64> = (0..=n).map(|k| self.draft * k as f64 / n as f64).collect();
        z.extend((1..n).map(|j| {
            let r = 1.0 - j as f64 / n as f64;
            self.draft * (1.0 - r.powf(1.0 / q))
        }));
        if q > 1.0 + 1e-6 && self.half_breadth > 0.0 {
            let keel_slope = q * self.half_breadth / self.draft;
            let phi_keel = keel_slope.atan();
            z.extend((1..n).map(|k| {
                let phi = phi_keel * k as f64 / n as f64;
                self.draft * (1.0 - (phi.tan() / keel_slope).powf(1.0 / (q - 1.0)))
            }));
        }
        z
    }
}

/// Flare above the waterline: y = b + Δ s^m, s = (z − T)/(D − T).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Flare {
    /// Waterline half-breadth b, m.
    pub half_breadth_wl: f64,
    /// Deck half-breadth b + Δ, m.
    pub half_breadth_deck: f64,
    /// Waterline height T, m.
    pub z_wl: f64,
    /// Deck height D, m.
    pub z_deck: f64,
    /// Shape exponent m (1: straight; > 1: vertical at the waterline, flattening towards the deck).
    pub exponent: f64,
}

impl Flare {
    fn s(&self, z: f64) -> f64 {
        ((z - self.z_wl) / (self.z_deck - self.z_wl)).clamp(0.0, 1.0)
    }

    /// Half-breadth at height z (T ≤ z ≤ D).
    pub fn y(&self, z: f64) -> f64 {
        self.half_breadth_wl
            + (self.half_breadth_deck - self.half_breadth_wl) * self.s(z).powf(self.exponent)
    }

    /// Local angle of the flare from the horizontal at height z, rad: atan(dz/dy).
    pub fn local_deadrise(&self, z: f64) -> f64 {
        let delta = self.half_breadth_deck - self.half_breadth_wl;
        let dy_dz =
            delta * self.exponent * self.s(z).powf(self.exponent - 1.0) / (self.z_deck - self.z_wl);
        (1.0 / dy_dz).atan()
    }

    /// Angle from the horizontal of the chord from the waterline to the deck, rad.
    pub fn chord_deadrise(&self) -> f64 {
        (self.z_deck - self.z_wl).atan2(self.half_breadth_deck - self.half_breadth_wl)
    }

    /// Heights from the waterline to the deck in `n` equal steps.
    pub fn z_levels(&self, n: usize) -> Vec<f64> {
        (0..=n)
            .map(|k| self.z_wl + (self.z_deck - self.z_wl) * k as f64 / n as f64)
            .collect()
    }
}

/// The contour through `y(z)` at the given heights: sorted, heights closer than 1 µm merged, and interior
/// points on the centreline between two other centreline points dropped (a stem is one vertical line).
pub fn contour(mut levels: Vec<f64>, y: impl Fn(f64) -> f64) -> Vec<[f64; 2]> {
    levels.sort_by(f64::total_cmp);
    levels.dedup_by(|a, b| (*a - *b).abs() < 1e-6);
    let pts: Vec<[f64; 2]> = levels.iter().map(|&z| [y(z).max(0.0), z]).collect();
    let mut out: Vec<[f64; 2]> = Vec::with_capacity(pts.len());
    for (i, p) in pts.iter().enumerate() {
        let interior_on_centreline = i > 0
            && i + 1 < pts.len()
            && p[0] == 0.0
            && pts[i - 1][0] == 0.0
            && pts[i + 1][0] == 0.0;
        if !interior_on_centreline {
            out.push(*p);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polyline_area_matches_the_area_coefficient() {
        for &sigma in &[0.5, 0.6, 0.8, 0.95, 0.99] {
            let s = PowerSection {
                half_breadth: 0.4,
                draft: 0.36,
                sigma,
            };
            let pts = contour(s.z_levels(16), |z| s.y(z));
            let area: f64 = pts
                .windows(2)
                .map(|w| 0.5 * (w[0][0] + w[1][0]) * (w[1][1] - w[0][1]))
                .sum();
            let rel = (area - s.half_area()).abs() / s.half_area();
            assert!(rel < 2e-3, "sigma {sigma}: polyline area off by {rel}");
            assert_eq!(pts[0], [0.0, 0.0]);
            assert!((pts[pts.len() - 1][0] - 0.4).abs() < 1e-12);
        }
    }

    #[test]
    fn flare_angles() {
        let f = Flare {
            half_breadth_wl: 0.1,
            half_breadth_deck: 0.4,
            z_wl: 0.25,
            z_deck: 0.55,
            exponent: 1.0,
        };
        assert!((f.chord_deadrise().to_degrees() - 45.0).abs() < 1e-9);
        assert!((f.local_deadrise(0.4).to_degrees() - 45.0).abs() < 1e-9);
    }
}
