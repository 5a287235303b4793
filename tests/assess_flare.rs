//! Flare events of `slamtool assess`: the Hermundstad & Moan (2005) car carrier, whose keel stays in the
//! water at 0.05 Lpp in the model-test wave while the water reaches the flare panel P1.

use std::path::{Path, PathBuf};

use slamtool::assess::{self, Fidelity, Settings};
use slamtool::hull::Hull;
use slamtool::sea::SeaState;
use slamtool::sph::{Overrides, StudyPlan};

fn data(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(rel)
}

fn inputs() -> (Hull, SeaState) {
    (
        Hull::from_file(&data("hulls/car-carrier-hm2005.toml")).unwrap(),
        SeaState::from_file(&data("sea_states/car-carrier-hm2005.toml")).unwrap(),
    )
}

fn settings(fidelity: Fidelity) -> Settings {
    Settings {
        fidelity,
        overrides: Overrides {
            particles_per_half_beam: Some(10.0),
            ..Default::default()
        },
        study: StudyPlan {
            levels: 1,
            ..StudyPlan::default()
        },
        threads: Some(2),
        ..Settings::default()
    }
}

#[test]
fn the_immersed_keel_gives_a_flare_event_with_an_analytic_panel_pressure() {
    let (hull, sea) = inputs();
    let s = settings(Fidelity::Analytic);
    let plan = assess::plan::plan(&hull, &sea, &s).unwrap();
    let st = &plan.motions.speeds[0].regular[0].stations[0];
    assert!(st.keel_entry.is_none(), "the keel must stay in the water");
    let dir = tempfile::tempdir().unwrap();
    let (a, _) = assess::run(&hull, &sea, &s, dir.path(), &Default::default()).unwrap();
    assert_eq!(a.events.len(), 1);
    let e = &a.events[0];
    let f = e.flare_event.as_ref().expect("a flare event");
    // d0 = T - |s_a| from the same strip theory
    assert!((f.immersion_m - (st.draft - st.relative_motion_m)).abs() < 1e-12);
    assert_eq!(
        e.entry_kind.as_deref(),
        Some(format!("flare, keel immersed to {:.3} m", f.immersion_m).as_str())
    );
    assert_eq!(f.first_sensor.as_deref(), Some("P1"));
    assert!(e.entry_velocity_m_per_s.is_none());
    let v = f.impact_velocity_m_per_s.unwrap();
    assert!(v > 0.0 && v < st.relative_velocity_m_s);
    let p1 = e.sensor_peak("P1").unwrap();
    assert_eq!(p1.1, "analytic");
    assert!(p1.0.is_finite() && p1.0 > 0.0, "{}", p1.0);
    // the acoustic start sample is no water-hammer bound for an immersed start
    let est = e.analytic.as_ref().unwrap();
    assert!(est.sensors.iter().all(|q| q.acoustic_bound_pa.is_none()));
    // the kind is in the tidy table and the summary
    let csv = std::fs::read_to_string(dir.path().join("pressures.csv")).unwrap();
    assert!(csv.contains("entry_kind") && csv.contains("flare, keel immersed to"));
    let json = std::fs::read_to_string(dir.path().join("summary.json")).unwrap();
    assert!(json.contains("\"flare_event\"") && json.contains("water at rest"));
    // the comparison prints the bound of linear strip theory, |s_a| w_e, beside the measured 1.4 m/s
    let w = plan.motions.speeds[0].regular[0].omega_e;
    let bound = a
        .validation
        .comparisons
        .iter()
        .find(|c| c.quantity.contains("|s_a| w_e"))
        .expect("the strip-theory bound");
    assert!((bound.computed.unwrap() - st.relative_motion_m * w).abs() < 1e-12);
    assert_eq!(bound.reference, 1.4);
    assert!(a.validation.comparisons.iter().any(|c| {
        c.quantity.contains("after the start of the flare event") && c.computed.is_some()
    }));
}

#[test]
fn a_flare_event_runs_in_sph_from_the_immersed_start() {
    let (hull, sea) = inputs();
    let dir = tempfile::tempdir().unwrap();
    let (a, _) = assess::run(
        &hull,
        &sea,
        &settings(Fidelity::Screen),
        dir.path(),
        &Default::default(),
    )
    .unwrap();
    let e = &a.events[0];
    assert!(e.failed.is_none(), "{:?}", e.failed);
    let r = e.sph.as_ref().expect("an SPH run");
    assert!(r.force_peak_n_per_m.is_finite() && r.force_peak_n_per_m > 0.0);
    assert!(r.stopped_early.is_none(), "{:?}", r.stopped_early);
    assert!(e.warnings.iter().any(|w| w.contains("buoyancy")));
}
