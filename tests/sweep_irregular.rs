//! An analytic sweep in an irregular sea makes the design events `assess` makes (the most probable
//! largest entry velocity of the exposure, with the profile of the regular wave at the spectral peak), so
//! its cases have design pressures, and they are those of `assess` to within the sweep's frequency-table
//! interpolation. Before 2026-11-30 an analytic sweep ran the sea file's regular waves only: in a sea
//! file with irregular seas alone its cases had slam statistics and no design pressure. The synthetic
//! patrol boat in its North Sea test sea (seconds).

use std::path::{Path, PathBuf};

use slamtool::assess::{self, Fidelity, Settings};
use slamtool::hull::Hull;
use slamtool::sea::SeaState;
use slamtool::sweep::{self, Options};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");
const HULL: &str = "tests/data/hard-chine-patrol.toml";
const SEA: &str = "tests/data/north-sea-hs2.5.toml";
const SPEED: f64 = 9.26;

fn path(p: &str) -> PathBuf {
    Path::new(ROOT).join(p)
}

#[test]
fn an_analytic_sweep_in_an_irregular_sea_has_the_design_pressures_of_assess() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("sweep.toml");
    std::fs::write(
        &file,
        format!(
            "name = \"irregular\"\nhull = \"{}\"\nsea = \"{}\"\nstations = [0.1]\nfidelity = \
             \"analytic\"\n\n[grid]\nspeed_m_s = [{SPEED}]\n",
            path(HULL).display(),
            path(SEA).display()
        ),
    )
    .unwrap();
    let opts = Options {
        out: dir.path().join("out"),
        ..Default::default()
    };
    let r = sweep::run(&file, &opts, &Default::default()).unwrap();
    assert_eq!(r.failed_cases, 0, "{:?}", r.warnings);
    let swept = &r.cases[0].stations[0];

    let hull = Hull::from_file(&path(HULL)).unwrap();
    let sea = SeaState::from_file(&path(SEA)).unwrap();
    let s = Settings {
        stations: vec![0.1],
        speeds: Some(vec![SPEED]),
        fidelity: Fidelity::Analytic,
        ..Settings::default()
    };
    let (a, _) = assess::run(
        &hull,
        &sea,
        &s,
        &dir.path().join("assess"),
        &Default::default(),
    )
    .unwrap();
    let assessed = &a.stations[0];

    assert!(!swept.sensors.is_empty());
    assert_eq!(swept.sensors.len(), assessed.design_pressure_pa.len());
    let mut compared = 0;
    for (q, d) in swept.sensors.iter().zip(&assessed.design_pressure_pa) {
        assert_eq!(q.name, d.name);
        let (p, pa) = (q.design_pressure_pa.unwrap(), d.value.unwrap());
        assert!(
            (p - pa).abs() <= 1e-3 * pa.abs().max(1.0),
            "{}: sweep {p} Pa, assess {pa} Pa",
            q.name
        );
        assert!(q.wave.ends_with("/design"), "{}", q.wave);
        compared += usize::from(pa > 0.0);
    }
    assert!(compared > 5, "{compared} panels with a pressure");
}
