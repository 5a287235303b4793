//! Section shapes for the reconstructed hulls.
//!
//! Below the waterline a family of half-sections (a reconstruction device, not a published form): a flat
//! of bottom of half-width y_f on the baseline, then, with η = z/T,
//!
//! y(z) = y_f + (b − y_f) [1 − (1 − η)^q],
//!
//! so the half-section area is a = y_f T + (b − y_f) T q/(q + 1). Without a flat (y_f = 0) the area
//! coefficient is σ = a/(b T) = q/(q + 1), q = σ/(1 − σ): σ = 1/2 (q = 1) is a straight V from the keel to
//! the waterline, σ → 1 a rectangle with a small bilge. With a flat of width fraction w = y_f/b the side
//! outside the flat has σ' = (σ − w)/(1 − w). The deadrise next to the flat (or at the keel) is
//! atan(T/(q (b − y_f))), and the side is vertical at the waterline for q > 1.
//!
//! Above the waterline a flare y(z) = b + Δ s^m with s = (z − T)/(D − T), tangent to the vertical side
//! at the waterline for m > 1; Δ is the increase of half-breadth up to the deck at height D.

/// Half-section below the waterline: flat of bottom plus power-law side.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PowerSection {
    /// Waterline half-breadth b, m.
    pub half_breadth: f64,
    /// Height of the waterline above the keel T, m.
    pub draft: f64,
    /// Half-width of the flat of bottom y_f, m (0: none).
    pub flat: f64,
    /// Area coefficient σ' of the side outside the flat, in [0.5, 1).
    pub side_sigma: f64,
}

impl PowerSection {
    /// A section without flat of bottom with area coefficient σ = a/(b T).
    pub fn new(half_breadth: f64, draft: f64, sigma: f64) -> Self {
        Self {
            half_breadth,
            draft,
            flat: 0.0,
            side_sigma: sigma,
        }
    }

    /// A section with area coefficient σ whose flat of bottom is the fraction w of the half-breadth
    /// (w < 2σ − 1 keeps the side's σ' = (σ − w)/(1 − w) above 1/2).
    pub fn with_flat(half_breadth: f64, draft: f64, sigma: f64, w: f64) -> Self {
        Self {
            half_breadth,
            draft,
            flat: w * half_breadth,
            side_sigma: (sigma - w) / (1.0 - w),
        }
    }

    /// q = σ'/(1 − σ').
    pub fn exponent(&self) -> f64 {
        self.side_sigma / (1.0 - self.side_sigma)
    }

    /// Overall area coefficient σ = a/(b T).
    pub fn sigma(&self) -> f64 {
        self.half_area() / (self.half_breadth * self.draft)
    }

    /// Half-breadth at height z above the keel (0 ≤ z ≤ T); the outer end of the flat at z = 0.
    pub fn y(&self, z: f64) -> f64 {
        let eta = (z / self.draft).clamp(0.0, 1.0);
        self.flat + (self.half_breadth - self.flat) * (1.0 - (1.0 - eta).powf(self.exponent()))
    }

    /// Half-section area y_f T + (b − y_f) T σ', m².
    pub fn half_area(&self) -> f64 {
        self.draft * (self.flat + (self.half_breadth - self.flat) * self.side_sigma)
    }

    /// Deadrise angle of the side where it leaves the keel or the flat, rad: atan(T/(q (b − y_f))).
    pub fn keel_deadrise(&self) -> f64 {
        (self.draft / (self.exponent() * (self.half_breadth - self.flat))).atan()
    }

    /// Heights that resolve the shape: `n` equal steps in z (the side), `n` equal steps in y (the bottom)
    /// and `n` equal steps in the slope angle of the contour (the bilge turn), keel and waterline included.
    /// The slope angle from the vertical is φ with tan φ = dy/dz = (q (b − y_f)/T)(1 − η)^(q−1), so
    /// η = 1 − (T tan φ/(q (b − y_f)))^(1/(q−1)) for q > 1.
    pub fn z_levels(&self, n: usize) -> Vec<f64> {
        let q = self.exponent();
        let side = self.half_breadth - self.flat;
        let mut z: Vec<f64> = (0..=n).map(|k| self.draft * k as f64 / n as f64).collect();
        z.extend((1..n).map(|j| {
            let r = 1.0 - j as f64 / n as f64;
            self.draft * (1.0 - r.powf(1.0 / q))
        }));
        if q > 1.0 + 1e-6 && side > 0.0 {
            let keel_slope = q * side / self.draft;
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

/// The contour through `y(z)` at the given heights: sorted, heights closer than 1 µm merged, a keel point
/// on the centreline added where the lowest point is off it (a flat bottom), and interior points on the
/// centreline between two other centreline points dropped (a stem is one vertical line).
pub fn contour(mut levels: Vec<f64>, y: impl Fn(f64) -> f64) -> Vec<[f64; 2]> {
    levels.sort_by(f64::total_cmp);
    levels.dedup_by(|a, b| (*a - *b).abs() < 1e-6);
    let mut pts: Vec<[f64; 2]> = levels.iter().map(|&z| [y(z).max(0.0), z]).collect();
    // The contour starts on the centreline: a flat bottom starts at the keel.
    if let Some(&[y0, z0]) = pts.first()
        && y0 > 0.0
    {
        pts.insert(0, [0.0, z0]);
    }
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
            let s = PowerSection::new(0.4, 0.36, sigma);
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
    fn flat_of_bottom_keeps_the_area() {
        let s = PowerSection::with_flat(0.4, 0.36, 0.75, 0.4);
        assert!((s.sigma() - 0.75).abs() < 1e-12);
        assert!((s.side_sigma - 0.35 / 0.6).abs() < 1e-12);
        let pts = contour(s.z_levels(16), |z| s.y(z));
        assert_eq!(pts[0], [0.0, 0.0]);
        assert!((pts[1][0] - 0.16).abs() < 1e-12 && pts[1][1] == 0.0);
        let area: f64 = pts
            .windows(2)
            .map(|w| 0.5 * (w[0][0] + w[1][0]) * (w[1][1] - w[0][1]))
            .sum();
        assert!((area - s.half_area()).abs() / s.half_area() < 2e-3);
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
