//! Careless and hostile input through the binary (issue 27), one test per class:
//!
//! 1. output policy: names from files never become paths, paths read back from a results folder stay in
//!    it, no command writes over its own input or over files it did not write without `--force`;
//! 2. bounded readers: tampered shard files, truncated STL, oversized `-j`, a hull of thousands of stations;
//! 3. input checked before compute, with exit status 1 and the option named;
//! 4. plausibility: warnings (with the number) or refusals for hulls, sweeps and case files no ship has;
//! 6. messages: negative numbers after a space, control characters, a file in the way of `-o`, the
//!    report's hull found from another folder.
//!
//! Every test runs in a fresh temporary folder and needs no SPH run (each command stops before it).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

mod common;
use common::BOX_HULL as HULL;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

const SEA: &str =
    "name = \"s\"\nspeeds_m_s = [1.0, 2.0]\n\n[[regular]]\nheight_m = 0.2\nperiod_s = 2.0\n";

fn slamtool(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(args)
        .current_dir(dir)
        .env("NO_COLOR", "1")
        .output()
        .unwrap()
}

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

/// Run and require exit status `code`, no panic, and `words` in stderr.
#[track_caller]
fn fails(args: &[&str], dir: &Path, code: i32, words: &str) -> String {
    let o = slamtool(args, dir);
    let e = stderr(&o);
    assert_eq!(o.status.code(), Some(code), "{args:?}: {e}");
    assert!(e.contains(words), "{args:?}: expected '{words}' in: {e}");
    assert!(!e.contains("panicked"), "{e}");
    e
}

/// Run and require success.
#[track_caller]
fn succeeds(args: &[&str], dir: &Path) -> Output {
    let o = slamtool(args, dir);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    o
}

fn setup() -> (tempfile::TempDir, PathBuf) {
    let t = tempfile::tempdir().unwrap();
    let d = t.path().to_path_buf();
    std::fs::write(d.join("h.toml"), HULL).unwrap();
    std::fs::write(d.join("s.toml"), SEA).unwrap();
    (t, d)
}

/// Every file under `dir` (relative paths), for "nothing was written" checks.
fn files_under(dir: &Path) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap().flatten() {
            let p = e.path();
            if p.is_dir() {
                stack.push(p.clone());
            }
            out.push(p.strip_prefix(dir).unwrap().to_path_buf());
        }
    }
    out.sort();
    out
}

// ---------------------------------------------------------------------------------------------------
// 1. One output policy
// ---------------------------------------------------------------------------------------------------

/// A case file that resolves but whose run is refused by the one-hour cost bound, so that nothing runs.
fn costly_case(name_line: &str) -> String {
    format!(
        "{name_line}\n[section]\nwedge = {{ deadrise_deg = 30.0, half_beam_m = 0.25 }}\n\n[motion]\nkind = \
         \"constant\"\nspeed_m_s = 2.0\n\n[resolution]\nparticles_per_half_beam = 600\n"
    )
}

#[test]
fn a_case_name_never_becomes_a_path() {
    let (_t, d) = setup();
    let work = d.join("a/b");
    std::fs::create_dir_all(&work).unwrap();
    std::fs::write(
        work.join("c.toml"),
        costly_case("name = \"../../escaped_case\""),
    )
    .unwrap();
    let e = fails(&["entry", "case", "c.toml"], &work, 1, "more than the");
    assert!(e.contains("writing to out/_.._escaped_case"), "{e}");
    // Nothing outside ./out (the run was refused by its cost, and the name was never a path).
    assert!(!d.join("escaped_case").exists());
    assert!(!d.join("a/escaped_case").exists());
    // An absolute name is one folder name too.
    std::fs::write(work.join("abs.toml"), costly_case("name = \"/tmp/abs\"")).unwrap();
    let e = fails(&["entry", "case", "abs.toml"], &work, 1, "more than the");
    assert!(e.contains("out/_tmp_abs"), "{e}");
    // A name with nothing usable is refused before anything is resolved or written.
    for name in ["\"\"", "\"..\"", "\"/\""] {
        std::fs::write(work.join("e.toml"), costly_case(&format!("name = {name}"))).unwrap();
        fails(
            &["entry", "case", "e.toml"],
            &work,
            1,
            "gives no usable folder name",
        );
    }
    assert!(!work.join("out").exists());
}

#[test]
fn report_paths_from_results_stay_in_the_results_folder() {
    let (_t, d) = setup();
    let res = d.join("res");
    std::fs::create_dir_all(&res).unwrap();
    for folder in ["../../../../etc", "/etc", "cache/../../x"] {
        let summary = serde_json::json!({
            "events": [{"station": 0.1, "run_folder": folder}],
            "provenance": {"inputs": []},
        });
        std::fs::write(res.join("summary.json"), summary.to_string()).unwrap();
        fails(
            &["report", "res", "-o", "rep"],
            &d,
            1,
            "the run_folder of an event is refused",
        );
    }
}

#[test]
fn no_command_writes_over_its_input() {
    let (_t, d) = setup();
    // hull plot onto the hull file, under another spelling too.
    for out in ["h.toml", "./h.toml", "../h.toml"] {
        let dir = if out.starts_with("..") {
            std::fs::create_dir_all(d.join("sub")).unwrap();
            d.join("sub")
        } else {
            d.clone()
        };
        let hull = if out.starts_with("..") {
            "../h.toml"
        } else {
            "h.toml"
        };
        fails(
            &["hull", "plot", hull, "-o", out],
            &dir,
            1,
            "would overwrite it",
        );
        assert_eq!(std::fs::read_to_string(d.join("h.toml")).unwrap(), HULL);
    }
    // hull import onto its own grid.
    let grid = "x_m,0.0,0.5,1.0\n-5,0.0,1.0,1.0\n0,0.0,1.0,1.0\n5,0.0,1.0,1.0\n";
    std::fs::write(d.join("g.csv"), grid).unwrap();
    fails(
        &["hull", "import", "g.csv", "--draft-m", "0.5", "-o", "g.csv"],
        &d,
        1,
        "would overwrite it",
    );
    assert_eq!(std::fs::read_to_string(d.join("g.csv")).unwrap(), grid);
    // A new file is written as usual.
    succeeds(&["hull", "plot", "h.toml", "-o", "b.svg"], &d);
}

#[test]
fn report_leaves_foreign_figures_alone() {
    let (_t, d) = setup();
    let res = d.join("res");
    std::fs::create_dir_all(&res).unwrap();
    std::fs::write(
        res.join("summary.json"),
        r#"{"events": [], "provenance": {"inputs": []}}"#,
    )
    .unwrap();
    let figs = d.join("mine/figures");
    std::fs::create_dir_all(&figs).unwrap();
    std::fs::write(figs.join("my_plot.svg"), "<svg/>").unwrap();
    fails(
        &["report", "res", "-o", "mine"],
        &d,
        1,
        "holds 'my_plot.svg', which a report did not write",
    );
    assert!(figs.join("my_plot.svg").is_file());
    // A folder of the user's own files is refused the same way.
    std::fs::create_dir_all(d.join("notes")).unwrap();
    std::fs::write(d.join("notes/todo.txt"), "x").unwrap();
    fails(&["report", "res", "-o", "notes"], &d, 1, "holds 'todo.txt'");
}

/// A one-case analytic sweep of the Ochi hull, run into `dir/name` (a second or so).
fn one_case_sweep(d: &Path, name: &str) -> PathBuf {
    let text = format!(
        "name = \"{name}\"\nhull = \"{ROOT}/hulls/ochi-vform.toml\"\nsea = \"{ROOT}/sea_states/ochi-1958.toml\"\n\
         loading = \"test-condition\"\nfidelity = \"analytic\"\n\n[grid]\nspeed_m_s = [2.0]\n"
    );
    std::fs::write(d.join(format!("{name}.toml")), text).unwrap();
    let out = d.join(name);
    succeeds(
        &[
            "sweep",
            &format!("{name}.toml"),
            "-o",
            out.to_str().unwrap(),
        ],
        d,
    );
    out
}

#[test]
fn merge_refuses_a_shard_as_target_and_survives_tampered_shards() {
    let (_t, d) = setup();
    let a = one_case_sweep(&d, "a");
    let before = std::fs::read(a.join("sweep.json")).unwrap();
    fails(&["merge", "a", "-o", "a"], &d, 1, "would overwrite it");
    fails(
        &["merge", "a/sweep.json", "-o", "a"],
        &d,
        1,
        "would overwrite it",
    );
    assert_eq!(std::fs::read(a.join("sweep.json")).unwrap(), before);
    // Tampered copies: short and non-ASCII hashes and keys, an absurd case count.
    let json: serde_json::Value = serde_json::from_slice(&before).unwrap();
    let tamper = |name: &str, f: &dyn Fn(&mut serde_json::Value)| {
        let mut v = json.clone();
        f(&mut v);
        std::fs::create_dir_all(d.join(name)).unwrap();
        std::fs::write(d.join(name).join("sweep.json"), v.to_string()).unwrap();
    };
    tamper("short", &|v| v["sweep_hash"] = "ab".into());
    fails(
        &["merge", "a", "short", "-o", "m1"],
        &d,
        1,
        "come from different sweeps",
    );
    tamper("utf8", &|v| v["sweep_hash"] = "ééééééééé".into());
    fails(
        &["merge", "a", "utf8", "-o", "m2"],
        &d,
        1,
        "come from different sweeps",
    );
    tamper("key", &|v| v["cases"][0]["key"] = "é".into());
    fails(
        &["merge", "a", "key", "-o", "m3"],
        &d,
        1,
        "differs from the same case",
    );
    tamper("huge", &|v| {
        v["total_cases"] = 1_000_000_000_000_000u64.into()
    });
    fails(
        &["merge", "huge", "-o", "m4"],
        &d,
        1,
        "more than a sweep can have",
    );
}

#[test]
fn output_under_a_file_is_explained() {
    let (_t, d) = setup();
    std::fs::write(d.join("afile"), "x").unwrap();
    fails(
        &["hull", "plot", "h.toml", "-o", "afile/b.svg"],
        &d,
        5,
        "afile is a file, not a folder",
    );
    fails(
        &["motions", "h.toml", "--sea", "s.toml", "-o", "afile/sub"],
        &d,
        1,
        "afile is a file, not a folder",
    );
}

// ---------------------------------------------------------------------------------------------------
// 2. Bounded readers
// ---------------------------------------------------------------------------------------------------

#[test]
fn thread_counts_are_bounded() {
    let (_t, d) = setup();
    for j in ["100000", "0", "-3"] {
        fails(
            &["assess", "h.toml", "--sea", "s.toml", "-j", j],
            &d,
            2,
            "1..=256",
        );
    }
}

#[test]
fn a_truncated_binary_stl_says_so() {
    let (_t, d) = setup();
    let mut bytes = vec![0u8; 80];
    bytes.extend(12u32.to_le_bytes());
    bytes.extend(vec![0u8; 50 * 3 + 7]);
    std::fs::write(d.join("cut.stl"), &bytes).unwrap();
    fails(
        &[
            "hull",
            "import",
            "cut.stl",
            "--draft-m",
            "1",
            "-o",
            "x.toml",
        ],
        &d,
        1,
        "truncated binary STL: its header gives 12 triangles",
    );
    std::fs::write(d.join("tiny.stl"), b"abc").unwrap();
    fails(
        &[
            "hull",
            "import",
            "tiny.stl",
            "--draft-m",
            "1",
            "-o",
            "x.toml",
        ],
        &d,
        1,
        "too short for a binary STL",
    );
    assert!(!d.join("x.toml").exists());
}

/// A box-like hull of `n` stations with a flared topside (six points each).
fn many_stations(n: usize) -> String {
    let mut s = String::from(
        "name = \"long\"\nlpp_m = 100.0\ndepth_m = 12.0\n\n[[loading]]\nname = \"d\"\ndraft_fp_m = 5.0\n\
         draft_ap_m = 5.0\nkg_m = 6.0\nk_yy_over_lpp = 0.25\n",
    );
    for i in 0..n {
        let x = -50.0 + 100.0 * i as f64 / (n - 1) as f64;
        let b = 8.0 * (1.0 - (x / 55.0).powi(2));
        s += &format!(
            "\n[[station]]\nx_m = {x:.6}\npoints = [[0.0, 0.0], [{:.4}, 0.0], [{:.4}, 1.0], [{b:.4}, 6.0], \
             [{:.4}, 9.0], [{:.4}, 12.0]]\n",
            0.5 * b,
            0.9 * b,
            1.05 * b,
            1.1 * b
        );
    }
    s
}

#[test]
fn a_hull_of_thousands_of_stations_is_read() {
    // 3,000 stations: past the shared-girth limit, so sections come from the four stations around them.
    let (_t, d) = setup();
    std::fs::write(d.join("long.toml"), many_stations(3000)).unwrap();
    let o = succeeds(&["hull", "info", "long.toml", "--json"], &d);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let h = &v["loadings"][0]["hydrostatics"];
    // The area of the section (about 0.96 of b x T at the waterline) integrated over the parabolic
    // waterline: a finite, positive volume of the right size.
    let vol = h["volume_m3"].as_f64().unwrap();
    assert!(vol > 4000.0 && vol < 9000.0, "{vol}");
    assert_eq!(v["number_of_offset_stations"], 3000);
}

#[test]
fn a_fine_grid_resamples_to_many_stations() {
    // 30 stations on 20 waterlines to 200 stations: every resampled contour carries the girths of all
    // the grid's vertices, so the written hull is read back through the windowed interpolation.
    let (_t, d) = setup();
    let zs: Vec<f64> = (0..20).map(|k| 3.0 * f64::from(k) / 19.0).collect();
    let mut csv = format!(
        "x_m,{}\n",
        zs.iter()
            .map(|z| format!("{z:.4}"))
            .collect::<Vec<_>>()
            .join(",")
    );
    for i in 0..30 {
        let x = -25.0 + 50.0 * f64::from(i) / 29.0;
        let b = 4.0 * (1.0 - (x / 26.0f64).powi(2));
        let cells: Vec<String> = zs
            .iter()
            .map(|z| format!("{:.4}", b * (0.3 + 0.7 * (z / 3.0).sqrt())))
            .collect();
        csv += &format!("{x:.4},{}\n", cells.join(","));
    }
    std::fs::write(d.join("grid.csv"), csv).unwrap();
    succeeds(
        &[
            "hull",
            "import",
            "grid.csv",
            "--draft-m",
            "1.5",
            "--stations",
            "200",
            "-o",
            "g.toml",
        ],
        &d,
    );
    let o = succeeds(&["hull", "info", "g.toml", "--json"], &d);
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    assert_eq!(v["number_of_offset_stations"], 200);
    let cb = v["loadings"][0]["hydrostatics"]["cb"].as_f64().unwrap();
    assert!(cb > 0.4 && cb < 0.8, "{cb}");
}

// ---------------------------------------------------------------------------------------------------
// 3. Input checked before compute
// ---------------------------------------------------------------------------------------------------

#[test]
fn options_are_checked_before_the_computation() {
    let (_t, d) = setup();
    fails(
        &["assess", "h.toml", "--sea", "s.toml", "--speeds", "1000"],
        &d,
        1,
        "--speeds: 1000 m/s is outside the accepted range 0 to",
    );
    fails(
        &[
            "assess",
            "h.toml",
            "--sea",
            "s.toml",
            "--particles-per-half-beam",
            "1e6",
        ],
        &d,
        1,
        "--particles-per-half-beam must lie between 4 and 640",
    );
    let e = fails(
        &[
            "entry",
            "wedge",
            "--deadrise-deg",
            "30",
            "--speed",
            "2",
            "--filter-hz",
            "0",
            "-o",
            "w",
        ],
        &d,
        1,
        "--filter-hz must be a positive",
    );
    assert!(!e.contains("dp "), "refused only after resolving: {e}");
    assert!(!d.join("w").exists());
    for (opt, v, words) in [
        ("--swell-up", "0.5", "--swell-up must be between 1"),
        ("--slam-limit", "2", "--slam-limit must be a probability"),
        ("--strips", "100000", "--strips must be between 3 and 1000"),
    ] {
        fails(
            &["motions", "h.toml", "--sea", "s.toml", opt, v],
            &d,
            1,
            words,
        );
    }
    fails(
        &[
            "entry",
            "wedge",
            "--deadrise-deg",
            "30",
            "--speed",
            "1e-6",
            "-o",
            "slow",
        ],
        &d,
        1,
        "does not enter the water far enough",
    );
    assert!(!d.join("slow").exists());
}

// ---------------------------------------------------------------------------------------------------
// 4. Plausibility
// ---------------------------------------------------------------------------------------------------

#[test]
fn implausible_hulls_are_flagged_with_their_numbers() {
    let (_t, d) = setup();
    // Offsets 1 m beyond each perpendicular of an 8 m ship: the box holds more than Lpp x B x T.
    std::fs::write(
        d.join("long.toml"),
        HULL.replace("lpp_m = 10.0", "lpp_m = 8.0"),
    )
    .unwrap();
    let o = succeeds(&["hull", "info", "long.toml"], &d);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(text.contains("Cb = 1.250 is above 1"), "{text}");
    assert!(text.contains("1.000 m aft of the AP"), "{text}");
    // A 1e6 m half-breadth is refused where it is written.
    std::fs::write(
        d.join("wide.toml"),
        HULL.replace("[1.0, 0.0], [1.0, 2.0]]\n", "[1e6, 0.0], [1e6, 2.0]]\n"),
    )
    .unwrap();
    fails(
        &["hull", "info", "wide.toml"],
        &d,
        1,
        "y = 1000000 m is larger than any ship",
    );
}

#[test]
fn implausible_sweeps_and_cases_are_refused() {
    let (_t, d) = setup();
    for (key, v) in [("flare_scale", "1000.0"), ("length_scale", "1e-6")] {
        let text = format!(
            "name = \"x\"\nhull = \"{ROOT}/hulls/ochi-vform.toml\"\nsea = \"{ROOT}/sea_states/ochi-1958.toml\"\n\
             fidelity = \"analytic\"\n\n[bow_region]\nfull_aft_of_fp = 0.1\nzero_aft_of_fp = 0.3\n\n[grid]\n\
             {key} = [{v}]\n"
        );
        std::fs::write(d.join("sw.toml"), text).unwrap();
        fails(
            &["sweep", "sw.toml", "-o", "sw"],
            &d,
            1,
            "a scale factor between 0.1 and 10",
        );
    }
    let case = |section: &str, motion: &str| {
        format!("name = \"c\"\n[section]\n{section}\n\n[motion]\n{motion}\n")
    };
    let constant = "kind = \"constant\"\nspeed_m_s = 2.0";
    // Zig-zag and self-overlapping contours, as in hull files.
    for (points, words) in [
        (
            "points = [[0.0, 0.0], [0.2, 0.1], [0.1, 0.05], [0.3, 0.3]]",
            "z falls",
        ),
        (
            "points = [[0.0, 0.0], [0.2, 0.1], [0.1, 0.1], [0.3, 0.1], [0.3, 0.3]]",
            "self-intersecting",
        ),
    ] {
        std::fs::write(d.join("c.toml"), case(points, constant)).unwrap();
        fails(&["entry", "case", "c.toml", "-o", "c"], &d, 1, words);
    }
    // A velocity table that only goes up never enters the water.
    std::fs::write(
        d.join("up.toml"),
        case(
            "wedge = { deadrise_deg = 30.0, half_beam_m = 0.25 }",
            "kind = \"prescribed\"\ntable = [[0.0, -1.0], [0.1, -2.0]]",
        ),
    )
    .unwrap();
    fails(
        &["entry", "case", "up.toml", "-o", "up"],
        &d,
        1,
        "never moves the section down (the largest velocity is -1 m/s",
    );
    assert!(!d.join("c").exists() && !d.join("up").exists());
}

#[test]
fn a_station_given_twice_is_computed_once() {
    let (_t, d) = setup();
    let o = succeeds(
        &[
            "motions",
            "h.toml",
            "--sea",
            "s.toml",
            "--station",
            "0.3,0.3",
            "--json",
        ],
        &d,
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let w = v["warnings"].to_string();
    assert!(w.contains("given more than once"), "{w}");
    let flags = v["regular_slam_flags"].to_string();
    // One entry per speed (the sea file has two), not two.
    assert_eq!(flags.matches("\"station\":0.3").count(), 2, "{flags}");
}

// ---------------------------------------------------------------------------------------------------
// 6. Messages
// ---------------------------------------------------------------------------------------------------

#[test]
fn a_negative_number_after_a_space_is_a_value() {
    let (_t, d) = setup();
    fails(
        &[
            "assess",
            "h.toml",
            "--sea",
            "s.toml",
            "--risk-level",
            "-0.1",
        ],
        &d,
        1,
        "--risk-level must be a probability between 0 and 1 (exclusive), got -0.1",
    );
    fails(
        &["motions", "h.toml", "--sea", "s.toml", "--swell-up", "-2"],
        &d,
        1,
        "--swell-up must be between 1",
    );
}

#[test]
fn control_characters_never_reach_the_terminal() {
    let (_t, d) = setup();
    std::fs::write(
        d.join("c.toml"),
        HULL.replace("box barge", "evil\\u001b[31m\\u0007name"),
    )
    .unwrap();
    let o = succeeds(&["hull", "info", "c.toml"], &d);
    assert!(!o.stdout.contains(&0x1b) && !o.stdout.contains(&0x07));
    assert!(String::from_utf8_lossy(&o.stdout).contains("evil\\u{1b}[31m\\u{7}name"));
    let e = fails(
        &["hull", "info", "c.toml", "--loading", "\u{1b}[2J"],
        &d,
        1,
        "no loading condition named",
    );
    assert!(!e.contains('\u{1b}'), "{e}");
}

/// A bundled validation case file, its reference paths made absolute so that it runs from `cases/`.
fn bundled_validation_case(file: &str) -> String {
    std::fs::read_to_string(Path::new(ROOT).join("validation").join(file))
        .unwrap()
        .replace("\"../data/reference/", &format!("\"{ROOT}/data/reference/"))
}

/// `slamtool validate` on the single case `text` written to `cases/NAME.toml` under `d`, which must
/// exit with status 6 (a case in error).
fn validate_fails_on(d: &Path, name: &str, text: &str) -> std::process::Output {
    std::fs::create_dir_all(d.join("cases")).unwrap();
    std::fs::write(d.join(format!("cases/{name}.toml")), text).unwrap();
    let o = slamtool(&["validate", "--cases-dir", "cases", "-o", "v"], d);
    assert_eq!(o.status.code(), Some(6), "{}", stderr(&o));
    o
}

#[test]
fn validate_says_why_a_case_could_not_be_computed() {
    let (_t, d) = setup();
    let case = bundled_validation_case("ochi1958-particulars.toml").replace(
        "hull = \"../hulls/ochi-vform.toml\"",
        "hull = \"missing.toml\"",
    );
    let o = validate_fails_on(&d, "broken", &case);
    let text = String::from_utf8_lossy(&o.stdout);
    assert!(
        text.contains("ERROR broken: the computation failed:")
            && text.contains("missing.toml not found"),
        "{text}"
    );
}

/// The wedge convergence table's parameters are checked before any run, with the case file, line and
/// column of the bad one.
#[test]
fn validate_refuses_a_wedge_table_with_parameters_out_of_range() {
    let (_t, d) = setup();
    let case = bundled_validation_case("wedge-convergence-table.toml");
    for (from, to, says) in [
        (
            "t_frac = 0.92",
            "t_frac = 1.5",
            "`t_frac` is 1.5: it must be between 0 and 1",
        ),
        (
            "speed_m_per_s = 5.0",
            "speed_m_per_s = -5.0",
            "`speed_m_per_s` is -5: it must be above 0",
        ),
        (
            "span_first = 0.10",
            "span_first = 0.90",
            "`span_first` (0.9) must lie below `span_last`",
        ),
    ] {
        assert!(case.contains(from), "{from}");
        let o = validate_fails_on(&d, "bad", &case.replace(from, to));
        let text = format!("{}{}", String::from_utf8_lossy(&o.stdout), stderr(&o));
        assert!(text.contains(says) && !text.contains("panicked"), "{text}");
    }
}

#[test]
fn report_from_another_folder_finds_the_hull() {
    let (_t, d) = setup();
    let res = Path::new(ROOT).join("reports/ochi-vform");
    let o = succeeds(
        &["report", res.to_str().unwrap(), "-o", "rep", "--json"],
        &d,
    );
    let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
    let w = v["warnings"].to_string();
    assert!(
        !w.contains("hull section of this report is left out"),
        "{w}"
    );
    assert!(d.join("rep/report.pdf").is_file());
    assert!(files_under(&res).iter().all(|p| !p.starts_with("rep")));
}

#[test]
fn a_sweep_files_unknown_air_choice_is_located() {
    let (_t, d) = setup();
    let text = format!(
        "name = \"bad-air\"\nhull = \"{ROOT}/hulls/ochi-vform.toml\"\nsea = \"{ROOT}/sea_states/ochi-1958.toml\"\n\
         fidelity = \"screen\"\nair = \"maybe\"\n\n[grid]\nspeed_m_s = [2.0]\n"
    );
    std::fs::write(d.join("bad-air.toml"), text).unwrap();
    let e = fails(
        &["sweep", "bad-air.toml", "-o", "out-air"],
        &d,
        1,
        "air = \"maybe\": use \"off\", \"on\" or \"auto\"",
    );
    assert!(e.contains("bad-air.toml:5:7"), "{e}");
    assert!(!d.join("out-air").join("sweep.json").exists());
}
