//! The settings of a sweep file that change its cases' results (`air`, `keel_slope_term`) are part of
//! every case's key, so a sweep resumed after editing them computes its cases again; and a sweep with
//! `keel_slope_term = true` gives its analytic cases the keel-slope term U dz_k/dx exactly as
//! `assess --keel-slope-term` does. Small analytic sweeps on the synthetic patrol boat (seconds).

use std::path::{Path, PathBuf};

use slamtool::assess::{self, Fidelity, Settings};
use slamtool::hull::Hull;
use slamtool::sea::SeaState;
use slamtool::sweep::{self, Options};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// One regular head wave of 2.5 m and 7 s at 9.26 m/s (18 kn), written beside the sweep files.
const REGULAR_SEA: &str = "name = \"patrol test wave\"\nheading = \"head\"\nspeeds_m_s = [9.26]\n\n\
                           [[regular]]\nname = \"H2.5-T7\"\nheight_m = 2.5\nperiod_s = 7.0\n";

fn files(dir: &Path, settings: &str) -> (PathBuf, PathBuf) {
    let sea = dir.join("sea.toml");
    std::fs::write(&sea, REGULAR_SEA).unwrap();
    let text = format!(
        "name = \"keel slope\"\nhull = \"{ROOT}/tests/data/hard-chine-patrol.toml\"\nsea = \"{}\"\n\
         stations = [0.1]\nfidelity = \"analytic\"\n{settings}\n[grid]\nspeed_m_s = [9.26]\n",
        sea.display()
    );
    let f = dir.join("sweep.toml");
    std::fs::write(&f, text).unwrap();
    (f, sea)
}

fn key(settings: &str) -> String {
    let dir = tempfile::tempdir().unwrap();
    let (f, _) = files(dir.path(), settings);
    let p = sweep::prepare::prepare(&f, &dir.path().join("out")).unwrap();
    p.case_keys[0].clone()
}

#[test]
fn air_and_the_keel_slope_term_are_in_the_case_key() {
    let base = key("");
    assert_eq!(base, key("air = \"off\"\nkeel_slope_term = false"));
    assert_ne!(base, key("air = \"auto\""));
    assert_ne!(base, key("keel_slope_term = true"));
}

fn sweep_result(settings: &str) -> sweep::SweepResult {
    let dir = tempfile::tempdir().unwrap();
    let (f, _) = files(dir.path(), settings);
    let opts = Options {
        out: dir.path().join("out"),
        ..Default::default()
    };
    let r = sweep::run(&f, &opts, &Default::default()).unwrap();
    assert_eq!(r.failed_cases, 0, "{:?}", r.warnings);
    r
}

fn sweep_pressures(settings: &str) -> Vec<(String, f64)> {
    sweep_result(settings).cases[0].stations[0]
        .sensors
        .iter()
        .map(|s| (s.name.clone(), s.design_pressure_pa.unwrap_or(0.0)))
        .collect()
}

fn assessment(on: bool) -> assess::Assessment {
    let dir = tempfile::tempdir().unwrap();
    let (_, sea) = files(dir.path(), "");
    let hull = Hull::from_file(Path::new(&format!(
        "{ROOT}/tests/data/hard-chine-patrol.toml"
    )))
    .unwrap();
    let s = Settings {
        stations: vec![0.1],
        fidelity: Fidelity::Analytic,
        keel_slope_term: on,
        ..Settings::default()
    };
    let (a, _) = assess::run(
        &hull,
        &SeaState::from_file(&sea).unwrap(),
        &s,
        &dir.path().join("assess"),
        &Default::default(),
    )
    .unwrap();
    a
}

fn assess_pressures(on: bool) -> Vec<(String, f64)> {
    assessment(on).stations[0]
        .design_pressure_pa
        .iter()
        .map(|d| (d.name.clone(), d.value.unwrap_or(0.0)))
        .collect()
}

#[test]
fn the_keel_slope_term_of_a_sweep_is_the_one_of_assess() {
    let (off, on) = (
        sweep_pressures(""),
        sweep_pressures("keel_slope_term = true"),
    );
    let (a_off, a_on) = (assess_pressures(false), assess_pressures(true));
    // The rising keel (dz_k/dx 0.27 at 0.1 Lpp) adds about 2.5 m/s at 9.26 m/s: the bottom panels'
    // pressures rise by far more than the table interpolation's difference between sweep and assess.
    let d05 = |v: &[(String, f64)]| v.iter().find(|s| s.0 == "D05").unwrap().1;
    assert!(d05(&on) > 1.3 * d05(&off), "{} {}", d05(&on), d05(&off));
    for (sweep, assess) in [(&off, &a_off), (&on, &a_on)] {
        assert_eq!(sweep.len(), assess.len());
        for ((n, p), (m, q)) in sweep.iter().zip(assess.iter()) {
            assert_eq!(n, m);
            // the sweep's strip theory is interpolated from a frequency table (about 1e-4)
            assert!(
                (p - q).abs() <= 1e-3 * q.abs().max(1.0),
                "{n}: {p} against {q}"
            );
        }
    }
}

/// An analytic sweep that leaves the term out warns about it as `assess` does, naming the case; with the
/// term on there is no such warning.
#[test]
fn an_analytic_sweep_warns_when_it_leaves_the_keel_slope_term_out() {
    let left_out = |w: &String| w.contains(assess::keel_slope::LEFT_OUT);
    let from_assess: Vec<String> = assessment(false)
        .warnings
        .into_iter()
        .filter(left_out)
        .collect();
    assert_eq!(from_assess.len(), 1, "{from_assess:?}");
    let r = sweep_result("");
    let id = &r.cases[0].id;
    let from_sweep: Vec<&String> = r.warnings.iter().filter(|w| left_out(w)).collect();
    assert_eq!(from_sweep, [&format!("{} (case {id})", from_assess[0])]);
    assert!(r.cases[0].warnings.iter().any(left_out));
    let on = sweep_result("keel_slope_term = true");
    assert!(!on.warnings.iter().any(left_out), "{:?}", on.warnings);
}
