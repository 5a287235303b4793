//! Linear (Airy) wave kinematics: dispersion and encounter frequency.

/// Standard gravity, m/s².
pub const G: f64 = 9.80665;

/// Wave number k from the linear dispersion relation ω² = g k tanh(k h) (Newton iteration; deep water
/// k = ω²/g when `depth` is None). Source: e.g. Dean & Dalrymple, "Water Wave Mechanics", eq. 3.19.
pub fn wave_number(omega: f64, depth: Option<f64>) -> f64 {
    let k_deep = omega * omega / G;
    let Some(h) = depth else { return k_deep };
    // Start from the Eckart (1952) approximation, then Newton on f(k) = g k tanh(kh) − ω².
    let mut k = k_deep / (k_deep * h).tanh().sqrt().max(1e-12);
    for _ in 0..50 {
        let th = (k * h).tanh();
        let f = G * k * th - omega * omega;
        let df = G * th + G * k * h * (1.0 - th * th);
        let dk = f / df;
        k -= dk;
        if dk.abs() < 1e-14 * k {
            break;
        }
    }
    k
}

/// Wave frequency from wavelength: ω = sqrt(g k tanh(k h)), k = 2π/λ.
pub fn frequency_from_wavelength(lambda: f64, depth: Option<f64>) -> f64 {
    let k = 2.0 * std::f64::consts::PI / lambda;
    let th = depth.map_or(1.0, |h| (k * h).tanh());
    (G * k * th).sqrt()
}

/// Encounter frequency in head seas for ship speed U: ω_e = ω + k U (deep water: ω + ω² U/g).
pub fn encounter_frequency(omega: f64, speed: f64, depth: Option<f64>) -> f64 {
    omega + wave_number(omega, depth) * speed
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn dispersion_deep_and_shallow() {
        let w = 2.0;
        assert!((wave_number(w, None) - w * w / G).abs() < 1e-12);
        // shallow-water limit ω ≈ k sqrt(g h)
        let h = 0.01;
        let k = wave_number(0.1, Some(h));
        assert!((0.1 / k - (G * h).sqrt()).abs() / (G * h).sqrt() < 1e-3);
        let lam = 2.0 * std::f64::consts::PI / wave_number(w, Some(3.0));
        assert!((frequency_from_wavelength(lam, Some(3.0)) - w).abs() < 1e-10);
    }

    #[test]
    fn encounter_frequency_head_seas() {
        let w = 1.0;
        assert!((encounter_frequency(w, 5.0, None) - (w + w * w * 5.0 / G)).abs() < 1e-12);
    }
}
