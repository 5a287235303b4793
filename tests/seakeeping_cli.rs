//! `slamtool motions` end to end on the Wigley III hull file.

use std::process::Command;

fn sea_file(dir: &std::path::Path) -> std::path::PathBuf {
    let p = dir.join("sea.toml");
    std::fs::write(
        &p,
        r#"name = "Wigley model-scale test sea"
heading = "head"
speeds_m_s = [1.0]

[[regular]]
name = "H0.1-L3.75"
height_m = 0.1
wavelength_m = 3.75

[[irregular]]
name = "model-scale JONSWAP"
spectrum = "jonswap"
hs_m = 0.12
tp_s = 1.6
gamma = 3.3
duration_h = 1.0
"#,
    )
    .unwrap();
    p
}

#[test]
fn motions_command_end_to_end_on_wigley3() {
    let dir = tempfile::tempdir().unwrap();
    let sea = sea_file(dir.path());
    let out = dir.path().join("out");
    let hull = concat!(env!("CARGO_MANIFEST_DIR"), "/hulls/wigley-iii.toml");
    let res = Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(["motions", hull, "--sea"])
        .arg(&sea)
        .args([
            "--fn",
            "0.2,0.3",
            "--lambda-over-l",
            "1.25",
            "--strips",
            "21",
            "--spectrum-samples",
            "8",
            "--station",
            "0.05,0.1",
            "--json",
            "-o",
        ])
        .arg(&out)
        .output()
        .unwrap();
    assert!(
        res.status.success(),
        "{}",
        String::from_utf8_lossy(&res.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&res.stdout).unwrap();
    let m = &v["motions"];
    assert!(m["heave_natural_period_s"].as_f64().unwrap() > 0.0);
    let speeds = m["speeds"].as_array().unwrap();
    assert_eq!(speeds.len(), 2);
    // through the hull file: heave RAO at Fn 0.3, lambda/L 1.25 within 15 % of Journee's 1.28
    let heave = speeds[1]["raos"][0]["heave_over_wave_amplitude"]
        .as_f64()
        .unwrap();
    assert!((heave / 1.28 - 1.0).abs() < 0.15, "heave RAO {heave}");
    assert_eq!(m["operability"].as_array().unwrap().len(), 1);
    let p = speeds[1]["irregular"][0]["stations"][0]["slam_probability"]
        .as_f64()
        .unwrap();
    assert!((0.0..=1.0).contains(&p));
    for f in [
        "raos.csv",
        "relative_motion.csv",
        "entry_profiles.csv",
        "slam_statistics.csv",
        "operability.csv",
    ] {
        let text = std::fs::read_to_string(out.join(f)).unwrap();
        assert!(text.starts_with("# slamtool"), "{f} lacks provenance");
        assert!(
            text.lines().filter(|l| !l.starts_with('#')).count() >= 2,
            "{f} has no rows"
        );
    }
}

#[test]
fn motions_command_rejects_bad_arguments() {
    let dir = tempfile::tempdir().unwrap();
    let sea = sea_file(dir.path());
    let hull = concat!(env!("CARGO_MANIFEST_DIR"), "/hulls/wigley-iii.toml");
    for bad in [
        ["--fn", "-0.2"],
        ["--lambda-over-l", "0"],
        ["--station", "1.5"],
        ["--at", "1.5"],
        ["--loading", "nope"],
    ] {
        let res = Command::new(env!("CARGO_BIN_EXE_slamtool"))
            .args(["motions", hull, "--sea"])
            .arg(&sea)
            .args(bad)
            .output()
            .unwrap();
        assert!(!res.status.success(), "{bad:?} accepted");
        let err = String::from_utf8_lossy(&res.stderr);
        assert!(
            err.starts_with("error:") && !err.contains("panicked"),
            "{bad:?}: {err}"
        );
    }
}
