//! A panel on a vertical side reads 0 from the analytic models, and the design value says why instead of
//! printing a bare zero: the wetted half-width of the Wagner/Logvinovich models does not grow along a
//! vertical side, so they wet it without an impact pressure. On the synthetic workboat
//! (`tests/data/workboat-vertical-side.toml`) the section at 0.05 Lpp is a V to a chine 1.1 m above its
//! keel, vertical from there to the waterline and flared above; the panels wholly on the vertical part
//! read 0 with that source, and those on the V below it read a pressure with the plain `analytic` source.

use std::path::Path;

use slamtool::assess::design_rule::{ANALYTIC_NO_PRESSURE, ANALYTIC_WITHOUT_SPH};
use slamtool::assess::{self, Fidelity, Settings};
use slamtool::hull::Hull;
use slamtool::sea::SeaState;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// The girth range (from the keel, m) of the vertical segments of a half-section contour.
fn vertical_girth(points: &[[f64; 2]]) -> (f64, f64) {
    let mut s = 0.0;
    let (mut from, mut to) = (f64::INFINITY, f64::NEG_INFINITY);
    for w in points.windows(2) {
        let len = (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]);
        if (w[1][0] - w[0][0]).abs() < 1e-9 && w[1][1] > w[0][1] {
            from = from.min(s);
            to = to.max(s + len);
        }
        s += len;
    }
    (from, to)
}

#[test]
fn panels_on_a_vertical_side_read_zero_with_the_reason() {
    let hull = Hull::from_file(Path::new(&format!(
        "{ROOT}/tests/data/workboat-vertical-side.toml"
    )))
    .unwrap();
    let sea = SeaState::from_file(Path::new(&format!(
        "{ROOT}/sea_states/north-atlantic-jonswap.toml"
    )))
    .unwrap();
    let dir = tempfile::tempdir().unwrap();
    let s = Settings {
        stations: vec![0.05],
        fidelity: Fidelity::Analytic,
        ..Settings::default()
    };
    let (a, _) = assess::run(&hull, &sea, &s, dir.path(), &Default::default()).unwrap();
    let st = &a.stations[0];
    let section = hull.section_at(hull.station_x(0.05)).unwrap();
    let (from, to) = vertical_girth(&section.points);
    assert!(
        to - from > 1.0,
        "the vertical side is {from}..{to} m of girth"
    );
    let (mut on_side, mut below) = (0, 0);
    for (info, d) in st.sensors.iter().zip(&st.design_pressure_pa) {
        assert_eq!(info.name, d.name);
        let (lo, hi) = (
            info.girth_m - 0.5 * info.width_m,
            info.girth_m + 0.5 * info.width_m,
        );
        if lo >= from && hi <= to {
            on_side += 1;
            assert_eq!(d.value, Some(0.0), "{}", d.name);
            assert_eq!(d.source, ANALYTIC_NO_PRESSURE, "{}", d.name);
        } else if hi <= from {
            below += 1;
            assert!(d.value.unwrap() > 0.0, "{}", d.name);
            assert_eq!(d.source, ANALYTIC_WITHOUT_SPH, "{}", d.name);
        }
    }
    assert!(
        on_side >= 4 && below >= 4,
        "{on_side} panels on the side, {below} below"
    );
}
