//! Shared fixtures for the integration tests.
#![allow(dead_code)]

pub mod sph;

use slamtool::seakeeping::section::HalfSection;
use slamtool::seakeeping::{ShipModel, StripSection};

/// Gravity used by the seakeeping tests, m/s².
pub const G: f64 = 9.81;

/// A 10 m x 2 m box barge at 1 m draft: the smallest valid hull file.
pub const BOX_HULL: &str = r#"name = "box barge"
lpp_m = 10.0
depth_m = 2.0

[[loading]]
name = "design"
draft_fp_m = 1.0
draft_ap_m = 1.0
water_density_kg_m3 = 1025.0
kg_m = 1.0
k_yy_m = 2.5

[[station]]
x_m = -5.0
points = [[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]

[[station]]
x_m = 5.0
points = [[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]
"#;

/// Wigley III from its analytic form (alpha = 0): 2y/B = (1 - zeta^2)(1 - xi^2)(1 + 0.2 xi^2).
/// `nz` intervals in depth per section.
pub fn wigley3(n_stations: usize, nz: usize) -> ShipModel {
    let (l, b, t) = (3.0, 0.3, 0.1875);
    let stations = (0..n_stations)
        .map(|i| {
            let xi = -1.0 + 2.0 * i as f64 / (n_stations - 1) as f64;
            let hb = 0.5 * b * (1.0 - xi * xi) * (1.0 + 0.2 * xi * xi);
            let section = if hb > 1e-9 {
                let pts = (0..=nz)
                    .map(|k| {
                        let zeta = -1.0 + k as f64 / nz as f64;
                        [hb * (1.0 - zeta * zeta), zeta * t]
                    })
                    .collect();
                Some(HalfSection::new(pts).unwrap())
            } else {
                None
            };
            StripSection {
                x: 0.5 * l * xi,
                section,
            }
        })
        .collect();
    let mut m = ShipModel {
        lpp: l,
        rho: 1000.0,
        g: G,
        mass: 1.0,
        xg: 0.0,
        zg: 0.17 - t,
        k_yy: 0.75,
        stations,
    };
    m.mass = m.rho * m.volume();
    m.validate().unwrap();
    m
}
