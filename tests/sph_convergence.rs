//! The convergence statement attached to every SPH peak (`slamtool entry`, [`slamtool::sph::study`]).

use slamtool::loads::convergence::Verdict;
use slamtool::sph::{
    self, MotionSpec, Overrides, RunOptions, SensorSpec, StudyPlan, body::Section,
};

/// A small 30 deg wedge at 3 m/s with two sensors, at `n_half` particles per half-beam, to 60 % of the
/// Wagner chine-wetting time.
fn small_wedge(n_half: f64, filter: Option<f64>) -> sph::Setup {
    let beta = 30f64.to_radians();
    let b = 0.1;
    let section = Section::wedge(beta, b, 1.5 * b * beta.tan()).unwrap();
    let side = b / beta.cos();
    let sensors = [0.3, 0.6]
        .iter()
        .enumerate()
        .map(|(k, f)| SensorSpec {
            name: format!("p{}", k + 1),
            s_m: f * side,
            width_m: 0.01,
        })
        .collect();
    let t_wet = 2.0 / std::f64::consts::PI * b * beta.tan() / 3.0;
    sph::case::resolve(
        "small_wedge",
        &section,
        &MotionSpec::Constant { speed_m_s: 3.0 },
        sensors,
        &Overrides {
            particles_per_half_beam: Some(n_half),
            t_end: Some(0.6 * t_wet),
            filter_cutoff_hz: filter,
            ..Default::default()
        },
    )
    .unwrap()
}

#[test]
fn every_peak_gets_a_statement_from_a_coarser_companion() {
    let dir = tempfile::tempdir().unwrap();
    let opts = RunOptions {
        out_dir: Some(dir.path().to_path_buf()),
        ..Default::default()
    };
    let setup = small_wedge(16.0, Some(2000.0));
    let dp = setup.dp;
    let r = sph::run_with_convergence(setup, &opts, StudyPlan::default()).unwrap();
    let conv = r
        .summary
        .convergence
        .as_ref()
        .expect("a convergence report");
    assert_eq!(conv.companions.len(), 1);
    assert!((conv.companions[0].dp_m - 2.0 * dp).abs() < 1e-12);
    assert!(conv.companions[0].left_out.is_none());
    // Force and two sensors, raw and filtered, and the contour peak.
    assert_eq!(conv.peaks.len(), 7);
    for p in &conv.peaks {
        assert_eq!(p.values.len(), 2, "{}", p.statement);
        assert!(p.values.iter().all(|v| v.is_finite()));
        assert!(!p.statement.is_empty());
        // a GCI wherever the levels were compared: not for a quantity that is zero, a record without a
        // slamming peak at the reported resolution, or a companion whose peak is another event or that
        // has none
        if !matches!(
            p.verdict,
            Verdict::NotWetted
                | Verdict::NotAssessed
                | Verdict::Mismatched
                | Verdict::CompanionUnresolved
        ) {
            let g = p.gci.expect("a GCI");
            assert!(g.is_finite() && g >= 0.0, "{}", p.statement);
        }
    }
    // The reported force peak is the slamming peak of the requested resolution.
    let force = r
        .summary
        .force
        .anatomy
        .as_ref()
        .expect("a section run's anatomy");
    assert_eq!(
        conv.peaks[0].values[0],
        force.slamming_peak.expect("a force peak").value
    );
    // The filtered peaks compared are the filtered records' slamming peaks, in the same impact window as
    // the raw ones (not the whole filtered records' maxima), and their statements match events as the
    // raw ones do.
    let records = std::iter::once(&r.summary.force).chain(&r.summary.sensors);
    for (k, q) in records.enumerate() {
        let raw = q.anatomy.as_ref().expect("an anatomy");
        let f = q.filtered_anatomy.as_ref().expect("a filtered anatomy");
        assert_eq!(f.window, raw.window, "{}", q.name);
        let filtered = &conv.peaks[2 * k + 1];
        assert!(filtered.name.contains("filtered"), "{}", filtered.name);
        match (f.slamming_peak, f.window) {
            (Some(p), Some(w)) => {
                assert_eq!(filtered.values[0], p.value, "{}", filtered.statement);
                assert!(p.time >= w.start_s && p.time <= w.end_s, "{}", q.name);
            }
            _ => assert_eq!(filtered.values[0], 0.0, "{}", filtered.statement),
        }
    }
    // Machine-readable outputs: a CSV row per peak, and the statements inside summary.json.
    let csv = std::fs::read_to_string(dir.path().join("convergence.csv")).unwrap();
    assert_eq!(
        csv.lines().filter(|l| !l.starts_with('#')).count(),
        1 + conv.peaks.len()
    );
    let json = std::fs::read_to_string(dir.path().join("summary.json")).unwrap();
    assert!(json.contains("\"gci\""));
    assert!(
        dir.path()
            .join("convergence")
            .read_dir()
            .unwrap()
            .next()
            .is_some()
    );
}

#[test]
fn a_single_level_says_not_assessed_and_a_companion_that_cannot_run_is_left_out() {
    let single = StudyPlan {
        levels: 1,
        ..Default::default()
    };
    let r =
        sph::run_with_convergence(small_wedge(12.0, None), &RunOptions::default(), single).unwrap();
    let conv = r.summary.convergence.unwrap();
    // One resolution: no GCI and never a claim of convergence. (A peak can still be flagged on its
    // own: at 12 particles the first sensor's peak is the tail of the contact transient, "not
    // converged", and a sensor reached right at the end of this short run may be dry.)
    assert!(
        conv.peaks
            .iter()
            .all(|p| p.gci.is_none()
                && !matches!(p.verdict, Verdict::Converged | Verdict::Acceptable)),
        "{:?}",
        conv.peaks
    );
    assert!(conv.peaks.iter().any(|p| p.verdict == Verdict::NotAssessed));
    // At 20 particles per half-beam and a spacing ratio of 2, the third level (5 particles across) is too
    // coarse to inform the estimate: it is left out with the reason, and the statement rests on the two
    // levels that ran.
    let plan = StudyPlan {
        levels: 3,
        ratio: 2.0,
    };
    let r =
        sph::run_with_convergence(small_wedge(20.0, None), &RunOptions::default(), plan).unwrap();
    let conv = r.summary.convergence.unwrap();
    assert_eq!(conv.companions.len(), 2);
    let left: Vec<_> = conv
        .companions
        .iter()
        .filter(|c| c.left_out.is_some())
        .collect();
    assert_eq!(left.len(), 1, "{:?}", conv.companions);
    assert!(left[0].left_out.as_ref().unwrap().contains("too coarse"));
    assert!(conv.peaks.iter().all(|p| p.values.len() == 2));
}

#[test]
fn bad_plans_are_refused() {
    for plan in [
        StudyPlan {
            levels: 0,
            ratio: 2.0,
        },
        StudyPlan {
            levels: 4,
            ratio: 2.0,
        },
        StudyPlan {
            levels: 2,
            ratio: 1.0,
        },
        StudyPlan {
            levels: 2,
            ratio: f64::NAN,
        },
    ] {
        let e = sph::run_with_convergence(small_wedge(8.0, None), &RunOptions::default(), plan);
        assert!(e.is_err());
    }
}
