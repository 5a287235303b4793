//! One truth in both reports (issue 26): the design report's Ochi trend checks (`assess` on the Ochi
//! V-form, `trend_checks` of its summary) and the validation cases on the same assessment give the same
//! verdict on every trend, because both call `assess::trends`. Checked at the analytic fidelity (the
//! one `validate --quick` assesses with), in seconds.

use std::path::{Path, PathBuf};

use slamtool::assess::{self, Fidelity, Settings};
use slamtool::hull::Hull;
use slamtool::progress::ProgressHandle;
use slamtool::sea::SeaState;
use slamtool::validate::{self, Case, Mode, Verdict};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

#[test]
fn design_report_and_validate_give_the_same_verdict_on_every_ochi_trend() {
    let hull = Hull::from_file(&root().join("hulls/ochi-vform.toml")).unwrap();
    let sea = SeaState::from_file(&root().join("sea_states/ochi-1958.toml")).unwrap();
    let settings = Settings {
        loading: Some("test-condition".into()),
        fidelity: Fidelity::Analytic,
        ..Settings::default()
    };
    let d = tempfile::tempdir().unwrap();
    let (a, _) = assess::run(
        &hull,
        &sea,
        &settings,
        &d.path().join("assess"),
        &ProgressHandle::default(),
    )
    .unwrap();
    let design = &a.validation.trend_checks;
    assert_eq!(design.len(), 3, "{design:?}");
    let memo = validate::run::Memo::new(d.path().join("validate"), Mode::Quick);
    for (name, check) in [
        ("ochi1958-keel-trend", "keel sensor"),
        ("ochi1958-speed-trend", "moves aft"),
        ("ochi1958-fore-trend", "foremost"),
    ] {
        let case =
            Case::from_file(&root().join("validation").join(format!("{name}.toml"))).unwrap();
        let r = validate::run_case(&case, Mode::Quick, &memo);
        let d = design
            .iter()
            .find(|t| t.check.contains(check))
            .unwrap_or_else(|| panic!("no design check on '{check}': {design:?}"));
        let validated = match r.verdict {
            Verdict::Pass | Verdict::UnexpectedPass => "reproduced",
            Verdict::Fail | Verdict::KnownFailure => "not reproduced",
            other => panic!("{name}: {other:?} {:?}", r.notes),
        };
        assert_eq!(
            validated, d.verdict,
            "{name}: validate {:?} against the design report's '{}' ({})",
            r.verdict, d.verdict, d.detail
        );
        // A known failure's text is made from this run's numbers, never a stale sentence.
        if let Some(k) = &r.known_failure {
            assert!(!k.contains('{'), "{name}: {k}");
        }
    }
}

#[test]
fn the_speed_trend_case_does_not_pass_a_location_that_stays() {
    // The case's acceptance is the trend function's: at least half the station spacing aft, never
    // forward. A reference range starting at zero (the old tolerance) would pass a location that stays.
    let case = Case::from_file(Path::new(
        &root().join("validation/ochi1958-speed-trend.toml"),
    ))
    .unwrap();
    let d = tempfile::tempdir().unwrap();
    let memo = validate::run::Memo::new(d.path().to_path_buf(), Mode::Quick);
    let r = validate::run_case(&case, Mode::Quick, &memo);
    let Some(validate::Reference::Range { lower, .. }) = r.reference else {
        panic!("{:?}", r.reference);
    };
    assert!(lower > 0.0, "{lower}");
}
