//! The keel-slope term U dz_k/dx of the 2D+t plane in `slamtool assess` (`--keel-slope-term`,
//! `assess::keel_slope`): what it adds to the design events of an irregular sea and to their velocity
//! profiles, and the warnings with it off and on. At the analytic fidelity (seconds).

use std::path::{Path, PathBuf};

use slamtool::assess::{self, Fidelity, Settings};
use slamtool::hull::Hull;
use slamtool::sea::SeaState;
use slamtool::seakeeping::entry_definitions::keel_slope;
use slamtool::sph::MotionSpec;

fn data(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(rel)
}

fn plan(hull: &Hull, sea: &str, station: f64, speed: f64, on: bool) -> assess::plan::Plan {
    let sea = SeaState::from_file(&data(sea)).unwrap();
    let s = Settings {
        stations: vec![station],
        speeds: Some(vec![speed]),
        fidelity: Fidelity::Analytic,
        keel_slope_term: on,
        ..Settings::default()
    };
    assess::plan::plan(hull, &sea, &s).unwrap()
}

fn table(e: &assess::plan::Event) -> Vec<[f64; 2]> {
    match &e.entry.as_ref().unwrap().motion {
        MotionSpec::Prescribed { table } => table.clone(),
        m => panic!("{m:?}"),
    }
}

#[test]
fn the_rising_forefoot_of_the_patrol_boat_sinks_through_the_plane_at_u_times_its_keel_slope() {
    let hull = Hull::from_file(&data("tests/data/hard-chine-patrol.toml")).unwrap();
    let sea = "tests/data/north-sea-hs2.5.toml";
    let (f, u) = (0.1, 9.26);
    let x = hull.station_x(f);
    let slope = keel_slope(&hull, &hull.loadings[0], x).unwrap();
    assert!(slope > 0.1, "the test needs a rising keel: {slope}");
    let vk = u * slope;
    let off = plan(&hull, sea, f, u, false);
    let on = plan(&hull, sea, f, u, true);
    let design = |p: &assess::plan::Plan| {
        p.events
            .iter()
            .find(|e| e.design.is_some() && e.entry.is_some())
            .cloned()
            .unwrap()
    };
    let (a, b) = (design(&off), design(&on));
    let (da, db) = (a.design.as_ref().unwrap(), b.design.as_ref().unwrap());
    assert_eq!(da.keel_slope_velocity_m_per_s, 0.0);
    assert!((db.keel_slope_velocity_m_per_s - vk).abs() < 1e-12);
    // v_th = 0.093 sqrt(g L) is below U dz_k/dx here, so every keel entry slams, and the most probable
    // largest entry of the exposure is the oscillating part's largest over all entries plus U dz_k/dx: the
    // oscillating part is the one without the term.
    assert!(da.threshold_velocity_m_per_s < vk);
    let (va, vb) = (a.entry_velocity_m_s.unwrap(), b.entry_velocity_m_s.unwrap());
    assert!((vb - va - vk).abs() < 1e-9, "{va} {vb} {vk}");
    assert!((db.design_entry_velocity_m_per_s - vb).abs() < 1e-12);
    assert!(db.expected_slams > da.expected_slams);
    // The same regular wave drives both profiles: the velocities differ by U dz_k/dx at every sample.
    assert_eq!(
        da.equivalent_wave_amplitude_m,
        db.equivalent_wave_amplitude_m
    );
    let (ta, tb) = (table(&a), table(&b));
    assert_eq!(ta.len(), tb.len());
    for (p, q) in ta.iter().zip(&tb) {
        assert_eq!(p[0], q[0]);
        if p[1] > 0.0 {
            assert!((q[1] - p[1] - vk).abs() < 1e-9, "{p:?} {q:?}");
        }
    }
    // Off: a warning states the amount and the option; on: a line states what was added.
    let named = |p: &assess::plan::Plan, what: &str| {
        p.warnings.iter().any(|w| {
            w.starts_with("station 0.1 Lpp")
                && w.contains(what)
                && w.contains(&format!("{vk:.3} m/s"))
        })
    };
    assert!(
        named(&off, "--keel-slope-term adds it"),
        "{:?}",
        off.warnings
    );
    assert!(
        named(&on, "the keel-slope term is included"),
        "{:?}",
        on.warnings
    );
    assert!(!named(&on, "--keel-slope-term adds it"));
}

#[test]
fn the_ochi_model_at_its_test_speed_gets_no_keel_slope_warning() {
    // Its keel is flat; only the trim by the stern slopes it: U dz_k/dx is about 2 % of the entry
    // velocity, below the 5 % of the warning.
    let hull = Hull::from_file(&data("hulls/ochi-vform.toml")).unwrap();
    let p = plan(&hull, "sea_states/ochi-1958.toml", 0.093, 2.0, false);
    assert!(p.events.iter().any(|e| e.entry_velocity_m_s.is_some()));
    assert!(
        !p.warnings.iter().any(|w| w.contains("keel-slope")),
        "{:?}",
        p.warnings
    );
}
