//! The measured-forcing path (issue 29): a relative-motion CSV is rejected with file:line:column for bad
//! units, non-monotone or repeated time, NaN and infinity, too few samples and a keel that never enters,
//! through the library and through `entry section --forcing`; a synthetic sinusoidal elevation record
//! gives the analytic velocity and keel-entry instant.

use std::f64::consts::PI;
use std::path::Path;
use std::process::Command;

use slamtool::forcing::{self, Column, parse_record_text};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn err(text: &str) -> String {
    match parse_record_text("rec.csv", text) {
        Ok(_) => "ok".into(),
        Err(e) => e.to_string(),
    }
}

const GOOD: &str = "# source: test\ntime [s], relative_elevation [m]\n0.0, 0.30\n0.1, 0.28\n0.2, 0.24\n0.3, 0.20\n0.4, 0.18\n";

#[test]
fn bad_records_are_rejected_with_file_line_and_column() {
    assert_eq!(err(GOOD), "ok");
    // units: missing, unknown
    let e = err(&GOOD.replace("relative_elevation [m]", "relative_elevation"));
    assert!(
        e.starts_with("rec.csv:2:11: column `relative_elevation` has no unit"),
        "{e}"
    );
    let e = err(&GOOD.replace("time [s]", "time [h]"));
    assert!(e.starts_with("rec.csv:2:1: unknown unit `[h]`"), "{e}");
    let e = err(&GOOD.replace("[m]", "[m/s]"));
    assert!(e.starts_with("rec.csv:2:11: unknown unit `[m/s]`"), "{e}");
    // time: non-monotone and repeated
    let e = err(&GOOD.replace("0.3, 0.20", "0.15, 0.20"));
    assert!(
        e.starts_with("rec.csv:6:1:") && e.contains("increase strictly"),
        "{e}"
    );
    let e = err(&GOOD.replace("0.3, 0.20", "0.2, 0.20"));
    assert!(e.starts_with("rec.csv:6:1:") && e.contains("line 5"), "{e}");
    // NaN and infinity, located at the cell
    let e = err(&GOOD.replace("0.2, 0.24", "0.2, NaN"));
    assert!(
        e.starts_with("rec.csv:5:6:") && e.contains("not a finite number"),
        "{e}"
    );
    let e = err(&GOOD.replace("0.1, 0.28", "inf, 0.28"));
    assert!(
        e.starts_with("rec.csv:4:1:") && e.contains("not a finite number"),
        "{e}"
    );
    let e = err(&GOOD.replace("0.1, 0.28", "0.1, 0,28"));
    assert!(
        e.starts_with("rec.csv:4:8:") && e.contains("2 numbers"),
        "{e}"
    );
    // too few samples
    let e = err("time [s], entry_velocity [m/s]\n0, 1\n0.1, 1\n");
    assert!(
        e.starts_with("rec.csv:3:1:") && e.contains("at least 5"),
        "{e}"
    );
    // no header
    let e = err("# only comments\n");
    assert!(e.starts_with("rec.csv:1:1: no header"), "{e}");
}

#[test]
fn a_keel_that_never_enters_is_rejected_at_its_line() {
    let r = parse_record_text("rec.csv", GOOD).unwrap();
    // the keel is out (s > T) but never comes back down through a draft of 0.1 m
    let e = forcing::measured_entry(&r, 0.1, 0.5)
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("rec.csv:7:1: the keel never enters"), "{e}");
    // the keel never leaves the water: largest elevation 0.30 m (line 3) against a draft of 0.4 m
    let e = forcing::measured_entry(&r, 0.4, 0.5)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("rec.csv:3:1: the keel never leaves the water"),
        "{e}"
    );
    // a velocity record must start at keel entry, going down
    let v = parse_record_text(
        "v.csv",
        "time [s], relative_velocity [m/s]\n0,0.5\n0.1,0.2\n0.2,-0.1\n0.3,-0.5\n0.4,-0.8\n",
    )
    .unwrap();
    let e = forcing::measured_entry(&v, 0.2, 0.5)
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("v.csv:2:1: a velocity record must start"),
        "{e}"
    );
}

#[test]
fn a_sinusoidal_elevation_gives_the_analytic_velocity_and_entry_instant() {
    // s(t) = T + c + R cos(w t): the keel is out while s > T; it enters where cos(w t) = -c/R falling,
    // w t_e = acos(-c/R); V = -ds/dt = R w sin(w t).
    let (draft, c, amp, w, dt) = (0.25, 0.05, 0.2, 5.76, 0.002);
    let mut text = String::from("# synthetic\ntime [s], relative_elevation [m]\n");
    let n = (1.0 / dt) as usize;
    for k in 0..=n {
        let t = k as f64 * dt;
        text += &format!("{t:.4}, {:.12}\n", draft + c + amp * (w * t).cos());
    }
    let r = parse_record_text("sine.csv", &text).unwrap();
    assert_eq!(r.column, Column::RelativeElevation);
    let e = forcing::measured_entry(&r, draft, 0.45).unwrap();
    let t_e = (-c / amp).acos() / w;
    assert!((e.t_entry - t_e).abs() < 1e-4, "{} vs {t_e}", e.t_entry);
    let v_e = amp * w * (w * t_e).sin();
    assert!(
        (e.entry_velocity - v_e).abs() < 2e-3 * amp * w,
        "{}",
        e.entry_velocity
    );
    // every later sample: the analytic velocity within the central-difference error (w dt)^2 / 6
    for s in &e.samples[1..] {
        let t = s.t + e.t_entry;
        let exact = amp * w * (w * t).sin();
        assert!(
            (s.velocity - exact).abs() < 1e-3 * amp * w,
            "t {t}: {} vs {exact}",
            s.velocity
        );
        let depth = -(c + amp * (w * t).cos());
        assert!(
            (s.penetration - depth).abs() < 1e-9,
            "t {t}: {} vs {depth}",
            s.penetration
        );
    }
    // the profile ends where the section stops going down (w t = pi), not before
    let last = e.samples.last().unwrap().t + e.t_entry;
    assert!((last - PI / w).abs() <= 1.01 * dt, "{last}");
    // the prescribed motion of the 2D run has the same samples, V >= 0
    match e.motion() {
        slamtool::sph::MotionSpec::Prescribed { table } => {
            assert_eq!(table.len(), e.samples.len());
            assert!(table.iter().all(|r| r[1] >= 0.0));
        }
        other => panic!("{other:?}"),
    }
    // provenance is carried
    assert_eq!(e.provenance, vec!["synthetic"]);
}

#[test]
fn the_shipped_records_are_read() {
    for f in [
        "data/forcing/hermundstad2005-flare-reconstructed.csv",
        "data/forcing/example-relative-elevation.csv",
    ] {
        let r = forcing::read_record(&Path::new(ROOT).join(f)).unwrap();
        assert!(!r.provenance.is_empty(), "{f}");
    }
}

#[test]
fn entry_section_reports_a_bad_record_with_its_line_and_needs_speed_or_forcing() {
    let dir = tempfile::tempdir().unwrap();
    let bad = dir.path().join("bad.csv");
    std::fs::write(&bad, GOOD.replace("0.2, 0.24", "0.2, nan")).unwrap();
    let hull = Path::new(ROOT).join("hulls/car-carrier-hm2005.toml");
    let run = |args: &[&str]| {
        Command::new(env!("CARGO_BIN_EXE_slamtool"))
            .args(["entry", "section"])
            .arg(&hull)
            .args(args)
            .current_dir(dir.path())
            .env("NO_COLOR", "1")
            .output()
            .unwrap()
    };
    let o = run(&["--station", "0.05", "--forcing", bad.to_str().unwrap()]);
    let e = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{e}");
    assert!(
        e.contains("bad.csv:5:6:") && e.contains("not a finite number"),
        "{e}"
    );
    assert!(!e.contains("panicked"), "{e}");
    // exactly one of --speed and --forcing
    let o = run(&["--station", "0.05"]);
    assert_eq!(o.status.code(), Some(2));
    let o = run(&["--station", "0.05", "--speed", "2", "--forcing", "x.csv"]);
    assert_eq!(o.status.code(), Some(2));
}
