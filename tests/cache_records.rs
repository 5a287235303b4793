//! The run cache's records are verified on reuse (issue 27): a well-formed number changed by hand in a
//! cache entry's `event.json` makes the assessment compute that run again, say so (a progress note and
//! a warning on the event), and give the result of the run, not the edited number.

use std::path::Path;
use std::sync::{Arc, Mutex};

use slamtool::assess::{self, Fidelity, Settings};
use slamtool::hull::Hull;
use slamtool::progress::{Progress, ProgressHandle};
use slamtool::sea::SeaState;
use slamtool::sph::{Overrides, StudyPlan};

/// A progress sink that keeps the notes.
#[derive(Default, Clone)]
struct Notes(Arc<Mutex<Vec<String>>>);

impl Progress for Notes {
    fn start(&self, _: &str, _: f64, _: &str) {}
    fn update(&self, _: f64, _: &str) {}
    fn finish(&self) {}
    fn note(&self, text: &str) {
        self.0.lock().unwrap().push(text.to_string());
    }
}

fn data(rel: &str) -> std::path::PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(rel)
}

#[test]
fn a_tampered_record_is_recomputed_and_the_assessment_says_so() {
    let hull = Hull::from_file(&data("hulls/ochi-vform.toml")).unwrap();
    let sea = SeaState::from_file(&data("sea_states/ochi-1958.toml")).unwrap();
    let settings = Settings {
        stations: vec![0.093],
        speeds: Some(vec![2.4]),
        fidelity: Fidelity::Sph,
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
    };
    let d = tempfile::tempdir().unwrap();
    let quiet = ProgressHandle::default();
    let (a, _) = assess::run(&hull, &sea, &settings, d.path(), &quiet).unwrap();
    let rec = a.events[0].sph.as_ref().expect("an SPH run").clone();
    let file = d.path().join("cache").join(&rec.key).join("event.json");
    let text = std::fs::read_to_string(&file).unwrap();
    // The section force's peak, written as serde_json writes it, multiplied by 100.
    let value = format!("\"force_peak_n_per_m\": {}", rec.force_peak_n_per_m);
    assert!(text.contains(&value), "{value} in {text}");
    let forged = format!("\"force_peak_n_per_m\": {}", rec.force_peak_n_per_m * 100.0);
    std::fs::write(&file, text.replace(&value, &forged)).unwrap();

    let notes = Notes::default();
    let (b, _) = assess::run(
        &hull,
        &sea,
        &settings,
        d.path(),
        &ProgressHandle::new(notes.clone()),
    )
    .unwrap();
    let again = b.events[0].sph.as_ref().expect("an SPH run");
    assert_eq!(
        again.force_peak_n_per_m, rec.force_peak_n_per_m,
        "recomputed, not the forged value"
    );
    let said = notes.0.lock().unwrap().join("\n");
    assert!(
        said.contains("does not match its checksum") && said.contains("computed again"),
        "progress notes: {said}"
    );
    assert!(
        b.events[0]
            .warnings
            .iter()
            .any(|w| w.contains("does not match its checksum")),
        "{:?}",
        b.events[0].warnings
    );
    // The entry is whole again: a third assessment reuses it without a word about the cache record.
    let notes = Notes::default();
    assess::run(
        &hull,
        &sea,
        &settings,
        d.path(),
        &ProgressHandle::new(notes.clone()),
    )
    .unwrap();
    assert!(
        !notes
            .0
            .lock()
            .unwrap()
            .iter()
            .any(|n| n.contains("checksum")),
        "{:?}",
        notes.0.lock().unwrap()
    );
    assert!(!std::fs::read_to_string(&file).unwrap().contains(&forged));
}
