//! Malformed inputs as a user produces them: each gives `file:line:column: reason` pointing at the culprit,
//! a non-zero exit status from the CLI, no panic and no NaN. Valid variants (integer literals, CRLF line
//! ends, a byte-order mark, blank lines in a CSV) are accepted.

use std::path::Path;
use std::process::{Command, Output};

use slamtool::hull::{Hull, Hydrostatics};
use slamtool::input::SourceText;
use slamtool::sea::SeaState;

mod common;
use common::BOX_HULL as HULL;

const SEA: &str = "name = \"s\"\nspeeds_m_s = [1.0, 2.0]\n\n[[regular]]\nheight_m = 0.2\nperiod_s = 2.0\n\n[[irregular]]\nspectrum = \"jonswap\"\nhs_m = 3.0\ntp_s = 9.0\n";

fn hull(text: &str) -> Result<Hull, String> {
    Hull::from_source(&SourceText::from_string("h.toml", text)).map_err(|e| e.to_string())
}

fn sea(text: &str) -> Result<SeaState, String> {
    SeaState::from_source(&SourceText::from_string("s.toml", text)).map_err(|e| e.to_string())
}

/// The error starts with `file:line:column: ` and contains `words`.
#[track_caller]
fn located(result: Result<impl std::fmt::Debug, String>, at: &str, words: &str) {
    let e = result.expect_err("expected an error");
    assert!(
        e.starts_with(&format!("{at}: ")),
        "expected {at}: ..., got: {e}"
    );
    assert!(e.contains(words), "expected '{words}' in: {e}");
}

fn slamtool(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap()
}

/// Run the CLI and require a clean bad-input failure (status 1) whose message starts with `prefix`.
#[track_caller]
fn cli_fails(args: &[&str], dir: &Path, prefix: &str) {
    cli_fails_with(args, dir, prefix, 1)
}

/// Run the CLI and require a clean failure with exit status `code` whose message starts with `prefix`.
#[track_caller]
fn cli_fails_with(args: &[&str], dir: &Path, prefix: &str, code: i32) {
    let out = slamtool(args, dir);
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success(), "{args:?} succeeded");
    assert_eq!(out.status.code(), Some(code), "{args:?}: {err}");
    assert!(
        err.starts_with(&format!("error: {prefix}")),
        "{args:?}: {err}"
    );
    assert!(!err.contains("panicked"), "{err}");
}

#[test]
fn empty_and_comment_only_files() {
    located(hull(""), "h.toml:1:1", "missing field `name`");
    located(
        hull("# lines plan\n# nothing yet\n"),
        "h.toml:1:1",
        "missing field `name`",
    );
    located(sea(""), "s.toml:1:1", "missing field `name`");
    located(
        hull(&HULL.replace("box barge", " ")),
        "h.toml:1:8",
        "name must not be empty",
    );
}

#[test]
fn integer_literals_are_numbers() {
    let ints = HULL
        .replace("10.0", "10")
        .replace("2.0", "2")
        .replace("1.0", "1")
        .replace("0.0", "0")
        .replace("-5.0", "-5")
        .replace("5.0", "5")
        .replace("1025.0", "1025")
        .replace("2.5", "3");
    assert!(!ints.contains(".0"), "{ints}");
    let h = hull(&ints).unwrap();
    assert_eq!(h.lpp, 10.0);
    assert_eq!(h.stations[1].section.points[2], [1.0, 2.0]);
    let s = sea(&SEA
        .replace("2.0\n", "2\n")
        .replace("[1.0, 2.0]", "[1, 2]")
        .replace("3.0", "3"));
    assert_eq!(s.unwrap().regular[0].period_s, 2.0);
}

#[test]
fn non_finite_and_absurd_numbers() {
    located(
        hull(&HULL.replace("lpp_m = 10.0", "lpp_m = nan")),
        "h.toml:2:9",
        "positive number",
    );
    located(
        hull(&HULL.replace("lpp_m = 10.0", "lpp_m = inf")),
        "h.toml:2:9",
        "got inf",
    );
    located(
        hull(&HULL.replace("lpp_m = 10.0", "lpp_m = 1e300")),
        "h.toml:2:9",
        "longer than any ship",
    );
    located(
        hull(&HULL.replace("lpp_m = 10.0", "lpp_m = -10")),
        "h.toml:2:9",
        "positive",
    );
    located(
        hull(&HULL.replace("kg_m = 1.0", "kg_m = 0")),
        "h.toml:10:8",
        "positive",
    );
    located(
        hull(&HULL.replace("k_yy_m = 2.5", "k_yy_m = 6.0")),
        "h.toml:11:10",
        "more than half of Lpp",
    );
    located(
        hull(&HULL.replacen("[1.0, 0.0]", "[-inf, 0.0]", 1)),
        "h.toml:15:23",
        "not a finite number",
    );
    // Lpp that does not fit the stations (a length in the wrong unit, or offsets in a different origin).
    located(
        hull(&HULL.replace("lpp_m = 10.0", "lpp_m = 30")),
        "h.toml:2:9",
        "less than half of Lpp",
    );
    located(
        hull(&HULL.replace("x_m = -5.0", "x_m = 1.0")),
        "h.toml:2:9",
        "does not include midship",
    );
}

#[test]
fn points_must_be_pairs() {
    located(
        hull(&HULL.replacen("[1.0, 0.0]", "[1.0]", 1)),
        "h.toml:15:23",
        "got 1 number",
    );
    located(
        hull(&HULL.replacen("[1.0, 0.0]", "[1.0, 0.0, 3.0]", 1)),
        "h.toml:15:23",
        "got 3 numbers",
    );
    located(
        hull(&HULL.replacen("[1.0, 0.0]", "[\"a\", 0.0]", 1)),
        "h.toml:15:24",
        "invalid type",
    );
    located(
        hull(&HULL.replace("lpp_m = 10.0", "lpp_m = {a = 1}")),
        "h.toml:2:9",
        "invalid type: map",
    );
    located(
        hull(&HULL.replace("lpp_m = 10.0", "lpp_m = [1.0]")),
        "h.toml:2:9",
        "invalid type: sequence",
    );
}

#[test]
fn single_brackets_for_a_list_of_tables() {
    located(
        hull(&HULL.replace("[[loading]]", "[loading]")),
        "h.toml:5:1",
        "double brackets",
    );
}

#[test]
fn unknown_keys_at_every_level() {
    located(
        hull(&HULL.replace("depth_m = 2.0", "depth_m = 2.0\nbeam_m = 2")),
        "h.toml:4:1",
        "unknown field `beam_m`",
    );
    located(
        hull(&HULL.replace("kg_m = 1.0", "kg_m = 1.0\nlcb_m = 0")),
        "h.toml:11:1",
        "unknown field `lcb_m`",
    );
    located(
        hull(&HULL.replacen("x_m = -5.0", "x_m = -5.0\nz_m = 0", 1)),
        "h.toml:15:1",
        "unknown field `z_m`",
    );
    let sensor = format!(
        "{HULL}\n[[sensor]]\nname = \"P1\"\nx_m = 0.0\ngirth_m = 0.5\ndiameter_m = 0.02\nkind = \"x\"\n"
    );
    located(hull(&sensor), "h.toml:26:1", "unknown field `kind`");
    let csv = HULL.split("[[station]]").next().unwrap().to_string()
        + "[offsets_csv]\nfile = \"o.csv\"\nstation = \"x_m\"\nsep = \";\"\n";
    located(hull(&csv), "h.toml:16:1", "unknown field `sep`");
    located(
        sea(&SEA.replace("tp_s = 9.0", "tp_s = 9.0\nfoo = 1")),
        "s.toml:12:1",
        "unknown field `foo`",
    );
    located(
        sea(&SEA.replace("period_s = 2.0", "period_s = 2.0\nphase = 0")),
        "s.toml:7:1",
        "unknown field `phase`",
    );
}

#[test]
fn station_geometry_errors() {
    let single = HULL.split("\n[[station]]\nx_m = 5.0").next().unwrap();
    located(hull(single), "h.toml:13:1", "at least two stations");
    located(
        hull(&HULL.replace("x_m = 5.0", "x_m = -5.0")),
        "h.toml:17:1",
        "same position",
    );
    located(
        hull(&HULL.replacen("[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]", "[[0.0, 0.0]]", 1)),
        "h.toml:15:11",
        "at least two",
    );
    located(
        hull(&HULL.replace(
            "[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]",
            "[[0.0, 0.0], [0.0, 2.0]]",
        )),
        "h.toml:13:1",
        "no breadth",
    );
    // Keel above the waterline everywhere.
    located(
        hull(&HULL.replace(
            "[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]",
            "[[0.0, 1.5], [1.0, 1.5], [1.0, 2.0]]",
        )),
        "h.toml:7:14",
        "not immersed",
    );
    // Offsets stopping below the waterline with breadth: the hull is undefined there.
    located(
        hull(&HULL.replacen(
            "[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]",
            "[[0.0, 0.0], [1.0, 0.0], [1.0, 0.5]]",
            1,
        )),
        "h.toml:8:14",
        "above the top of the offsets",
    );
    located(
        hull(&HULL.replace("draft_ap_m = 1.0", "draft_ap_m = 2.5")),
        "h.toml:8:14",
        "above the deck",
    );
    // A body entirely under water (closed contours below the waterline) is not a floating ship.
    located(
        hull(&HULL.replace(
            "[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]",
            "[[0.0, 0.0], [1.0, 0.25], [0.0, 0.5]]",
        )),
        "h.toml:7:14",
        "does not cut the hull",
    );
    // One end just out of the water under trim is fine; a negative draft or no draft at all is not.
    let trimmed = hull(&HULL.replace("draft_fp_m = 1.0", "draft_fp_m = 0")).unwrap();
    let hs = Hydrostatics::compute(&trimmed, &trimmed.loadings[0]);
    assert!((hs.volume - 10.0).abs() < 1e-9, "{}", hs.volume);
    located(
        hull(&HULL.replace("draft_fp_m = 1.0", "draft_fp_m = -0.1")),
        "h.toml:7:14",
        "must not be negative",
    );
    located(
        hull(
            &HULL
                .replace("draft_fp_m = 1.0", "draft_fp_m = 0")
                .replace("draft_ap_m = 1.0", "draft_ap_m = 0.0"),
        ),
        "h.toml:7:14",
        "not afloat",
    );
}

#[test]
fn collinear_points_are_not_a_self_intersection() {
    // Many points along one straight flank (a fine lines plan): orientation round-off must not flag them.
    let pts: Vec<String> = (0..=2000)
        .map(|i| format!("[{}, {}]", i as f64 * 1e-4 * 0.7, i as f64 * 1e-3))
        .collect();
    let text = HULL.replace(
        "[[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]",
        &format!("[{}]", pts.join(", ")),
    );
    let h = hull(&text).unwrap();
    let hs = Hydrostatics::compute(&h, &h.loadings[0]);
    assert!((hs.volume - 0.07 * 10.0).abs() < 1e-9, "{}", hs.volume);
}

#[test]
fn sensors() {
    let with = |body: &str| hull(&format!("{HULL}\n[[sensor]]\n{body}\n"));
    located(
        with("name = \"P1\"\nx_m = 7.0\ngirth_m = 0.5\ndiameter_m = 0.02"),
        "h.toml:23:7",
        "outside the offsets",
    );
    located(
        with("name = \"P1\"\nx_m = 0.0\ngirth_m = 3.5\ndiameter_m = 0.02"),
        "h.toml:24:11",
        "not on the section contour",
    );
    located(
        with("name = \"P1\"\nx_m = 0.0\ngirth_m = -0.1\ndiameter_m = 0.02"),
        "h.toml:24:11",
        "not on the section contour",
    );
    located(
        with("name = \"P1\"\nx_m = 0.0\ny_m = 3.0\nz_m = 1.0\ndiameter_m = 0.02"),
        "h.toml:24:7",
        "off the section contour",
    );
    located(
        with("name = \"P1\"\nx_m = 0.0\ngirth_m = 0.5\ndiameter_m = 100"),
        "h.toml:25:14",
        "larger than the whole section",
    );
    located(
        with("name = \"P1\"\nx_m = nan\ngirth_m = 0.5\ndiameter_m = 0.02"),
        "h.toml:23:7",
        "finite",
    );
    located(
        with(
            "name = \"P1\"\nx_m = 0.0\ngirth_m = 0.5\ndiameter_m = 0.02\n[[sensor]]\nname = \"P1\"\nx_m = 1.0\ngirth_m = 0.5\ndiameter_m = 0.02",
        ),
        "h.toml:27:8",
        "used twice",
    );
    let ok = with("name = \"P1\"\nx_m = 0.0\ny_m = 1.0\nz_m = 1.0\ndiameter_m = 0.02").unwrap();
    assert!((ok.sensors[0].girth - 2.0).abs() < 1e-12);
}

#[test]
fn loadings() {
    let second = format!(
        "{HULL}\n[[loading]]\nname = \"design\"\ndraft_fp_m = 1.0\ndraft_ap_m = 1.0\nkg_m = 1.0\nk_yy_m = 2.5\n"
    );
    located(hull(&second), "h.toml:22:8", "used twice");
    // A displacement in tonnes typed into the kg field.
    located(
        hull(&HULL.replace("kg_m = 1.0", "kg_m = 1.0\ndisplacement_kg = 20.5")),
        "h.toml:11:19",
        "units (kg, not tonnes)",
    );
    let h = hull(&HULL.replace("kg_m = 1.0", "kg_m = 1.0\ndisplacement_kg = 20000")).unwrap();
    assert_eq!(h.loadings[0].displacement_kg, Some(20000.0));
}

#[test]
fn not_utf8_is_located() {
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("h.toml");
    std::fs::write(&p, b"name = \"box\"\nlpp_m = 1\n# caf\xe9\n").unwrap();
    let e = Hull::from_file(&p).unwrap_err().to_string();
    assert!(
        e.ends_with("h.toml:3:6: the file is not UTF-8 text (byte 0xe9); save it as UTF-8"),
        "{e}"
    );
}

#[test]
fn byte_order_mark_and_crlf_are_accepted() {
    let crlf = HULL.replace('\n', "\r\n");
    assert!(hull(&crlf).is_ok());
    assert!(hull(&format!("\u{feff}{HULL}")).is_ok());
    located(
        hull(&format!("\u{feff}{}", HULL.replace("\"box barge\"", "5"))),
        "h.toml:1:8",
        "invalid type",
    );
    located(
        hull(&crlf.replace("lpp_m = 10.0", "lpp_m = -1")),
        "h.toml:2:9",
        "positive",
    );
}

#[test]
fn csv_offsets() {
    let dir = tempfile::tempdir().unwrap();
    let toml = HULL.split("[[station]]").next().unwrap().to_string()
        + "[offsets_csv]\nfile = \"o.csv\"\nstation = \"x_m\"\n";
    let p = dir.path().join("h.toml");
    std::fs::write(&p, &toml).unwrap();
    let good = "station,y_m,z_m\n-5.0,0.0,0.0\n-5.0,1.0,0.0\n-5.0,1.0,2.0\n5.0,0.0,0.0\n5.0,1.0,0.0\n5.0,1.0,2.0\n";
    let run = |csv: &[u8]| {
        std::fs::write(dir.path().join("o.csv"), csv).unwrap();
        Hull::from_file(&p).map_err(|e| e.to_string())
    };
    let at = |csv: &str, line_col: &str, words: &str| {
        let e = run(csv.as_bytes()).expect_err(csv);
        assert!(
            e.contains(&format!("o.csv:{line_col}: ")),
            "{line_col}: {e}"
        );
        assert!(e.contains(words), "{words}: {e}");
    };
    assert!(run(good.as_bytes()).is_ok());
    assert!(run(good.replace('\n', "\r\n").as_bytes()).is_ok());
    // Windows line ends: errors still on the right line.
    at(
        &good
            .replace("5.0,1.0,0.0\n5.0,1.0,2.0", "5.0,1.0,0.0\n5.0,x,2.0")
            .replace('\n', "\r\n"),
        "7:5",
        "'x' is not a finite number (y_m)",
    );
    assert!(run(format!("\u{feff}{good}").as_bytes()).is_ok());
    assert!(
        run(good
            .replace("-5.0,1.0,2.0\n", "-5.0,1.0,2.0\n\n\n")
            .as_bytes())
        .is_ok()
    );
    assert!(run(format!("# exported lines plan\n{good}").as_bytes()).is_ok());
    at(
        &good.replace("-5.0,1.0,0.0\n", "-5.0,1.0\n"),
        "3:9",
        "got 2: a value is missing",
    );
    at(
        &good.replace("-5.0,1.0,0.0\n", "-5.0,1.0,0.0,7\n"),
        "3:14",
        "got 4: remove the extra values",
    );
    at(
        &good.replace("station,y_m,z_m", "station,y,z"),
        "1:1",
        "header must be",
    );
    at(
        &good.replace("5.0,1.0,0.0\n5.0,1.0,2.0", "5.0,1.0,0.0\n5.0,1.0,x"),
        "7:9",
        "'x' is not a finite number (z_m)",
    );
    at(
        &good.replace("-5.0,1.0,0.0", "-5.0,NaN,0.0"),
        "3:6",
        "not a finite number (y_m)",
    );
    at(
        &good.replace("-5.0,1.0,0.0", "-5.0,1.0,-1.0"),
        "3:10",
        "not monotone",
    );
    at(&format!("{good}-5.0,1.0,3.0\n"), "8:1", "appears again");
    at(
        "station,y_m,z_m\n-5.0,0.0,0.0\n-5.0,1.0,0.0\n",
        "1:1",
        "at least two stations",
    );
    at("", "1:1", "header must be");
    let e = run(b"station,y_m,z_m\n-5.0,0.0,0.0\n-5.0,\xff1.0,0.0\n").unwrap_err();
    assert!(e.contains("o.csv:3:6: the file is not UTF-8"), "{e}");
    std::fs::remove_file(dir.path().join("o.csv")).unwrap();
    let e = Hull::from_file(&p).unwrap_err().to_string();
    assert!(e.contains("h.toml:14:8: cannot read offsets file"), "{e}");
    std::fs::create_dir(dir.path().join("o.csv")).unwrap();
    let e = Hull::from_file(&p).unwrap_err().to_string();
    assert!(e.contains("h.toml:14:8: cannot read offsets file"), "{e}");
    // Wrong kind of station column.
    std::fs::write(
        &p,
        toml.replace("station = \"x_m\"", "station = \"metres\""),
    )
    .unwrap();
    let e = Hull::from_file(&p).unwrap_err().to_string();
    assert!(
        e.contains("h.toml:15:11: station = \"metres\" is not a station column kind"),
        "{e}"
    );
}

#[test]
fn sea_state_values() {
    located(
        sea(&SEA.replace("period_s = 2.0", "period_s = 1e300")),
        "s.toml:6:12",
        "outside the physical range",
    );
    located(
        sea(&SEA.replace("tp_s = 9.0", "tp_s = inf")),
        "s.toml:11:8",
        "got inf",
    );
    located(
        sea(&SEA.replace("tp_s = 9.0", "tp_s = nan")),
        "s.toml:11:8",
        "positive number",
    );
    located(
        sea(&SEA.replace("hs_m = 3.0", "hs_m = 1e-9")),
        "s.toml:10:8",
        "outside the physical range",
    );
    located(
        sea(&SEA.replace("jonswap", "JONSWAP")),
        "s.toml:9:12",
        "not a known spectrum",
    );
    located(
        sea(&SEA.replace("\"jonswap\"", "3")),
        "s.toml:9:12",
        "expected a string",
    );
    located(
        sea(&SEA
            .replace("height_m = 0.2", "name = \"a\"\nheight_m = 0.2")
            .replace("hs_m = 3.0", "name = \"a\"\nhs_m = 3.0")),
        "s.toml:11:8",
        "used twice",
    );
    // Shallow water: a 0.2 m, 2 s wave breaks in 0.1 m of water (Miche) though it would not in deep water.
    located(
        sea(&SEA.replace("name = \"s\"", "name = \"s\"\nwater_depth_m = 0.1")),
        "s.toml:6:12",
        "Miche",
    );
    located(
        sea(&SEA.replace("name = \"s\"", "name = \"s\"\nwater_depth_m = 1e6")),
        "s.toml:2:17",
        "deeper than any ocean",
    );
    located(
        sea(&SEA.replace("speeds_m_s = [1.0, 2.0]", "speeds_m_s = [1.0, nan]")),
        "s.toml:2:20",
        "speeds_m_s",
    );
}

#[test]
fn cli_failures_are_clean() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::write(d.join("h.toml"), HULL).unwrap();
    std::fs::write(d.join("s.toml"), SEA).unwrap();
    std::fs::write(
        d.join("bad.toml"),
        HULL.replace("lpp_m = 10.0", "lpp_m = nan"),
    )
    .unwrap();
    std::fs::create_dir(d.join("dir.toml")).unwrap();
    cli_fails(
        &["hull", "info", "bad.toml"],
        d,
        "bad.toml:2:9: lpp_m must be",
    );
    // A file that cannot be read is an I/O error (status 5).
    cli_fails_with(&["hull", "info", "missing.toml"], d, "missing.toml: ", 5);
    cli_fails_with(&["hull", "info", "dir.toml"], d, "dir.toml: ", 5);
    cli_fails(
        &["hull", "info", "h.toml", "--loading", "ballast"],
        d,
        "h.toml: no loading condition named 'ballast'",
    );
    cli_fails(
        &["hull", "section", "h.toml", "--x-m", "7"],
        d,
        "--x-m 7: x = 7.0000 m is outside",
    );
    cli_fails(
        &["hull", "section", "h.toml", "--x-m", "nan"],
        d,
        "--x-m NaN: the station must be a finite number",
    );
    cli_fails(
        &[
            "hull",
            "section",
            "h.toml",
            "--station",
            "0.5",
            "--loading",
            "x",
        ],
        d,
        "h.toml: no loading",
    );
    cli_fails(
        &["sea", "info", "s.toml", "--lpp-m", "-3"],
        d,
        "--lpp-m must be",
    );
    // Negative stations (aft of midship) are ordinary values, not options.
    let out = slamtool(&["hull", "section", "h.toml", "--x-m", "-2.5"], d);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(
        text.contains("x = -2.5000 m") && !text.contains("-0.000000"),
        "{text}"
    );
    let out = slamtool(&["hull", "info", "h.toml", "--json"], d);
    assert!(out.status.success());
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let v = json["loadings"][0]["hydrostatics"]["volume_m3"]
        .as_f64()
        .unwrap();
    assert!((v - 20.0).abs() < 1e-9);
    for args in [
        &["hull", "info", "h.toml"][..],
        &["sea", "info", "s.toml"],
        &["sea", "info", "s.toml", "--json"],
    ] {
        let out = slamtool(args, d);
        assert!(out.status.success());
        let text = String::from_utf8_lossy(&out.stdout);
        assert!(!text.contains("NaN") && !text.contains("inf"), "{text}");
    }
}

/// Every single-character deletion of a valid file, and every number replaced by an awkward value, gives
/// either a valid hull or a located error, never a panic or a NaN in the hydrostatics.
#[test]
fn mutated_files_never_panic() {
    let sensor =
        format!("{HULL}\n[[sensor]]\nname = \"P1\"\nx_m = 0.0\ngirth_m = 1.5\ndiameter_m = 0.02\n");
    let check_hull = |text: &str| {
        let r = std::panic::catch_unwind(|| hull(text));
        match r {
            Err(_) => panic!("panic on:\n{text}"),
            Ok(Err(e)) => assert!(e.starts_with("h.toml:"), "unlocated: {e}\n{text}"),
            Ok(Ok(h)) => {
                for l in &h.loadings {
                    let hs = Hydrostatics::compute(&h, l);
                    let json = serde_json::to_string(&hs).unwrap();
                    assert!(!json.contains("null"), "NaN/inf in {json}\n{text}");
                }
            }
        }
    };
    let check_sea = |text: &str| {
        let r = std::panic::catch_unwind(|| sea(text));
        match r {
            Err(_) => panic!("panic on:\n{text}"),
            Ok(Err(e)) => assert!(e.starts_with("s.toml:"), "unlocated: {e}\n{text}"),
            Ok(Ok(s)) => {
                for i in &s.irregular {
                    let m = i.spectrum.summary();
                    assert!(
                        m.m0.is_finite() && m.m2.is_finite() && m.tz_s.is_finite(),
                        "{text}"
                    );
                }
                for w in &s.regular {
                    assert!(w.wavelength_m.is_finite() && w.omega.is_finite(), "{text}");
                }
            }
        }
    };
    for (base, check) in [
        (sensor.as_str(), &check_hull as &dyn Fn(&str)),
        (SEA, &check_sea as &dyn Fn(&str)),
    ] {
        for (i, _) in base.char_indices() {
            let mut t = base.to_string();
            t.remove(i);
            check(&t);
        }
        // Each number in turn replaced by awkward values.
        let mut starts = Vec::new();
        let b = base.as_bytes();
        for i in 0..b.len() {
            let begins = (b[i].is_ascii_digit() || b[i] == b'-')
                && (i == 0
                    || !(b[i - 1].is_ascii_alphanumeric() || b[i - 1] == b'.' || b[i - 1] == b'_'));
            if begins {
                starts.push(i);
            }
        }
        for &i in &starts {
            let end = i + base[i..]
                .find(|c: char| !(c.is_ascii_digit() || c == '.' || c == '-' || c == 'e'))
                .unwrap_or(base.len() - i);
            for v in [
                "nan", "-inf", "0", "-0.0", "-1", "1e308", "1e-308", "3", "0.5", "7.0",
            ] {
                check(&format!("{}{v}{}", &base[..i], &base[end..]));
            }
        }
    }
}
