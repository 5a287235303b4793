//! Every class of bad input gives a located error (file:line:column: reason), a non-zero exit status from
//! the CLI, and never a panic.

use std::process::Command;

use slamtool::hull::Hull;
use slamtool::input::SourceText;
use slamtool::sea::SeaState;

const HULL: &str = r#"name = "box barge"
lpp_m = 10.0
depth_m = 2.0

[[loading]]
name = "design"
draft_fp_m = 1.0
draft_ap_m = 1.0
water_density_kg_m3 = 1025.0
kg_m = 1.0
k_yy_m = 2.5

[[station]]
x_m = -5.0
points = [[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]

[[station]]
x_m = 5.0
points = [[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]
"#;

/// Parse `text` as a hull and return the error text (panics if it parses).
fn hull_error(text: &str) -> String {
    match Hull::from_source(&SourceText::from_string("bad.toml", text)) {
        Ok(_) => panic!("expected an error for:\n{text}"),
        Err(e) => e.to_string(),
    }
}

fn assert_at(err: &str, line: usize, col: usize, words: &str) {
    let prefix = format!("bad.toml:{line}:{col}: ");
    assert!(err.starts_with(&prefix), "expected {prefix}..., got: {err}");
    assert!(err.contains(words), "expected '{words}' in: {err}");
}

#[test]
fn the_base_hull_is_valid() {
    let hull = Hull::from_source(&SourceText::from_string("ok.toml", HULL)).unwrap();
    let hs = slamtool::hull::Hydrostatics::compute(&hull, &hull.loadings[0]);
    assert!((hs.volume - 20.0).abs() < 1e-9, "box volume {}", hs.volume);
    assert!((hs.cb - 1.0).abs() < 1e-9);
    // BM_T of a box = B²/(12 T) = 4/12
    assert!((hs.bm_t - 4.0 / 12.0).abs() < 1e-9);
    // BM_L of a box = L²/(12 T)
    assert!((hs.bm_l - 100.0 / 12.0).abs() < 1e-9);
}

#[test]
fn unknown_key() {
    let e = hull_error(&HULL.replace("kg_m = 1.0", "kg_m = 1.0\nlcg_fraction = 0.5"));
    assert_at(&e, 11, 1, "unknown field `lcg_fraction`");
}

#[test]
fn wrong_type() {
    let e = hull_error(&HULL.replace("lpp_m = 10.0", "lpp_m = \"ten\""));
    assert_at(&e, 2, 9, "invalid type");
}

#[test]
fn missing_field() {
    let e = hull_error(&HULL.replace("kg_m = 1.0\n", ""));
    assert!(e.starts_with("bad.toml:5:"), "{e}");
    assert!(e.contains("missing field `kg_m`"), "{e}");
}

#[test]
fn syntax_error() {
    let e = hull_error(&HULL.replace("depth_m = 2.0", "depth_m = 2.0.0"));
    assert!(e.starts_with("bad.toml:3:"), "{e}");
}

#[test]
fn negative_length() {
    let e = hull_error(&HULL.replace("lpp_m = 10.0", "lpp_m = -10.0"));
    assert_at(&e, 2, 9, "lpp_m must be a positive number");
}

#[test]
fn draft_above_deck() {
    let e = hull_error(&HULL.replace("draft_fp_m = 1.0", "draft_fp_m = 2.5"));
    assert_at(&e, 7, 14, "above the deck");
}

#[test]
fn non_physical_density() {
    let e = hull_error(&HULL.replace("1025.0", "10.25"));
    assert_at(&e, 9, 23, "water_density_kg_m3 must lie in");
}

#[test]
fn non_monotone_section() {
    let e = hull_error(&HULL.replacen(
        "[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]",
        "[[0.0, 0.0], [1.0, 1.0], [1.0, 0.5]]",
        1,
    ));
    assert_at(&e, 15, 35, "not monotone");
}

#[test]
fn self_intersecting_section() {
    let e = hull_error(&HULL.replacen(
        "[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]",
        "[[0.0, 0.0], [1.0, 0.0], [0.5, 0.0], [1.0, 2.0]]",
        1,
    ));
    assert_at(&e, 15, 35, "folds back on itself at point 3");
    let e = hull_error(&HULL.replacen(
        "[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]",
        "[[0.0, 0.0], [1.0, 0.5], [0.0, 0.5], [0.5, 0.5], [0.5, 2.0]]",
        1,
    ));
    assert!(e.starts_with("bad.toml:15:"), "{e}");
}

#[test]
fn stations_out_of_order() {
    let text =
        format!("{HULL}\n[[station]]\nx_m = 0.0\npoints = [[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]\n");
    let e = hull_error(&text);
    assert_at(&e, 21, 1, "stations out of order");
}

#[test]
fn stations_listed_forward_to_aft_are_accepted() {
    let text = HULL
        .replace("x_m = -5.0", "x_m = 5.0#")
        .replacen("x_m = 5.0\n", "x_m = -5.0\n", 1);
    let text = text.replace("x_m = 5.0#", "x_m = 5.0");
    let hull = Hull::from_source(&SourceText::from_string("ok.toml", text)).unwrap();
    assert!(hull.stations[0].x < hull.stations[1].x);
}

#[test]
fn sensor_off_the_contour() {
    let text = format!(
        "{HULL}\n[[sensor]]\nname = \"P1\"\nx_m = 0.0\ny_m = 0.5\nz_m = 0.3\ndiameter_m = 0.02\n"
    );
    let e = hull_error(&text);
    assert_at(&e, 24, 7, "off the section contour");
}

#[test]
fn ambiguous_station_position() {
    let e = hull_error(&HULL.replacen("x_m = -5.0", "x_m = -5.0\naft_of_fp = 1.0", 1));
    assert_at(&e, 14, 7, "either x_m or aft_of_fp");
}

#[test]
fn sea_state_errors_are_located() {
    let base = "name = \"s\"\nspeeds_m_s = [1.0]\n\n[[regular]]\nheight_m = 0.2\nperiod_s = 2.0\n";
    let parse = |t: &str| SeaState::from_source(&SourceText::from_string("sea.toml", t));
    assert!(parse(base).is_ok());
    let e = parse(&base.replace("period_s = 2.0", "period_s = -2.0"))
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("sea.toml:6:12:"), "{e}");
    let e = parse(&base.replace("height_m = 0.2", "height_m = 2.0"))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("sea.toml:5:12:") && e.contains("breaking"),
        "{e}"
    );
    let e = parse(&base.replace("speeds_m_s", "speed"))
        .unwrap_err()
        .to_string();
    assert!(
        e.starts_with("sea.toml:2:1:") && e.contains("unknown field"),
        "{e}"
    );
    let irr = "name = \"s\"\nfroude_numbers = [0.2]\n\n[[irregular]]\nspectrum = \"pierson-moskowitz\"\nhs_m = 3.0\ntp_s = 9.0\n";
    let e = parse(irr).unwrap_err().to_string();
    assert!(
        e.starts_with("sea.toml:7:8:") && e.contains("one parameter"),
        "{e}"
    );
    let e = parse(&irr.replace("pierson-moskowitz", "bogus"))
        .unwrap_err()
        .to_string();
    assert!(e.starts_with("sea.toml:5:12:"), "{e}");
}

#[test]
fn cli_reports_errors_with_location_and_no_panic() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.toml");
    std::fs::write(&path, HULL.replace("lpp_m = 10.0", "lpp_m = 0.0")).unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(["hull", "info"])
        .arg(&path)
        .output()
        .unwrap();
    assert!(!out.status.success());
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(
        stderr.contains("bad.toml:2:9: lpp_m must be a positive number"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
    let missing = Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(["hull", "info", "does-not-exist.toml"])
        .output()
        .unwrap();
    assert!(!missing.status.success());
    assert!(String::from_utf8_lossy(&missing.stderr).contains("does-not-exist.toml"));
}

#[test]
fn csv_offsets_are_read_and_errors_point_into_the_csv() {
    let dir = tempfile::tempdir().unwrap();
    let csv = "station,y_m,z_m\n-5.0,0.0,0.0\n-5.0,1.0,0.0\n-5.0,1.0,2.0\n5.0,0.0,0.0\n5.0,1.0,0.0\n5.0,1.0,2.0\n";
    std::fs::write(dir.path().join("off.csv"), csv).unwrap();
    let toml_text = HULL.split("[[station]]").next().unwrap().to_string()
        + "[offsets_csv]\nfile = \"off.csv\"\nstation = \"x_m\"\n";
    let p = dir.path().join("h.toml");
    std::fs::write(&p, &toml_text).unwrap();
    let hull = Hull::from_file(&p).unwrap();
    assert_eq!(hull.stations.len(), 2);
    std::fs::write(
        dir.path().join("off.csv"),
        csv.replace("5.0,1.0,2.0\n", "5.0,1.0,-2.0\n"),
    )
    .unwrap();
    let e = Hull::from_file(&p).unwrap_err().to_string();
    assert!(
        e.contains("off.csv:4:6:") && e.contains("not monotone"),
        "{e}"
    );
}
