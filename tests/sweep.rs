//! `slamtool sweep` and `slamtool merge`: a sweep stopped part-way and resumed gives exactly the result of
//! an uninterrupted run (also after SIGKILL), two shards merged give the unsharded result, the scheduler
//! variables pick the shards the job scripts expect, bad ranges and invalid hull variants are located in
//! the sweep file, merge refuses shards of different sweeps or tool versions, and many warnings print as
//! kinds. Small analytic sweeps on the Ochi hull in Ochi's regular wave or the model-scale irregular sea
//! (a few seconds each).

use std::path::{Path, PathBuf};
use std::process::Command;

use slamtool::sweep::{self, Options, Shard};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

/// A sweep file in `dir` over the bundled Ochi hull and Ochi's regular wave, with `body` appended.
fn sweep_file(dir: &Path, name: &str, body: &str) -> PathBuf {
    let text = format!(
        "name = \"{name}\"\nhull = \"{ROOT}/hulls/ochi-vform.toml\"\nsea = \"{ROOT}/sea_states/ochi-1958.toml\"\n\
         loading = \"test-condition\"\nfidelity = \"analytic\"\n\n[bow_region]\nfull_aft_of_fp = 0.1\n\
         zero_aft_of_fp = 0.3\n\n{body}"
    );
    let p = dir.join(format!("{name}.toml"));
    std::fs::write(&p, text).unwrap();
    p
}

const SMALL: &str =
    "[grid]\nspeed_m_s = [1.6, 2.0, 2.4]\nflare_scale = { start = 0.8, stop = 1.2, count = 3 }\n";

fn opts(out: &Path) -> Options {
    Options {
        out: out.to_path_buf(),
        ..Default::default()
    }
}

fn read(p: &Path) -> String {
    std::fs::read_to_string(p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// The files a sweep writes that must agree between runs.
fn same_outputs(a: &Path, b: &Path) {
    for f in [
        "results.csv",
        "cases.csv",
        "best.csv",
        "plots/design_pressure_vs_speed_m_s.csv",
        "plots/design_pressure_vs_speed_m_s.svg",
    ] {
        let bytes = |d: &Path| std::fs::read(d.join(f)).unwrap_or_else(|e| panic!("{f}: {e}"));
        assert!(bytes(a) == bytes(b), "{f} differs");
    }
}

fn slamtool(args: &[&str], env: &[(&str, &str)]) -> std::process::Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_slamtool"));
    c.args(args);
    for k in [
        "SLURM_ARRAY_TASK_ID",
        "SLURM_ARRAY_TASK_COUNT",
        "SLURM_ARRAY_TASK_MIN",
        "JOB_COMPLETION_INDEX",
        "SLAMTOOL_SHARD_COUNT",
    ] {
        c.env_remove(k);
    }
    for (k, v) in env {
        c.env(k, v);
    }
    c.output().unwrap()
}

#[test]
fn a_stopped_sweep_resumes_to_the_uninterrupted_result() {
    let dir = tempfile::tempdir().unwrap();
    let f = sweep_file(dir.path(), "small", SMALL);
    let whole = sweep::run(&f, &opts(&dir.path().join("whole")), &Default::default()).unwrap();
    assert_eq!(whole.cases.len(), 9);
    assert_eq!(whole.failed_cases, 0);
    assert!(
        whole
            .cases
            .iter()
            .all(|c| c.max_design_pressure_pa.unwrap() > 0.0)
    );
    let part = dir.path().join("part");
    let stop = Options {
        stop_after: Some(4),
        ..opts(&part)
    };
    let err = sweep::run(&f, &stop, &Default::default()).unwrap_err();
    assert!(err.to_string().contains("stopped after"), "{err}");
    let cached = std::fs::read_dir(part.join("cache/cases")).unwrap().count();
    assert!((4..9).contains(&cached), "{cached} cases cached");
    // Resumed on one thread: the result does not depend on the thread count either.
    let one = Options {
        threads: Some(1),
        ..opts(&part)
    };
    let resumed = sweep::run(&f, &one, &Default::default()).unwrap();
    assert_eq!(resumed.cases, whole.cases);
    same_outputs(&dir.path().join("whole"), &part);
    // The flare changes the section force but not the speed dependence of the design pressure's inputs:
    // different flare scales give different results (the variants really differ).
    let f08 = &whole.cases[0];
    let f12 = &whole.cases[2];
    assert_ne!(f08.max_section_force_n_per_m, f12.max_section_force_n_per_m);
}

#[cfg(unix)]
#[test]
fn a_sigkilled_sweep_resumes_to_the_uninterrupted_result() {
    let dir = tempfile::tempdir().unwrap();
    let body = "[grid]\nspeed_m_s = { start = 1.2, stop = 2.8, step = 0.1 }\nwave_height_m = [0.15, 0.2, 0.25]\n";
    let f = sweep_file(dir.path(), "kill", body);
    let (fs, killed, whole) = (
        f.to_str().unwrap(),
        dir.path().join("killed"),
        dir.path().join("whole"),
    );
    let mut child = Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(["sweep", fs, "-q", "-o", killed.to_str().unwrap()])
        .spawn()
        .unwrap();
    // SIGKILL (no chance to clean up) once a few of the 51 cases are done.
    let cases = killed.join("cache/cases");
    let t0 = std::time::Instant::now();
    while t0.elapsed().as_secs() < 60 {
        if std::fs::read_dir(&cases).map_or(0, |d| d.count()) >= 3 {
            break;
        }
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    let _ = child.kill();
    let status = child.wait().unwrap();
    let before = std::fs::read_dir(&cases).map_or(0, |d| d.count());
    // (A sweep that finished before the signal arrived is simply complete.)
    if std::os::unix::process::ExitStatusExt::signal(&status) == Some(9) {
        assert!(
            before < 51 && !killed.join("sweep.json").exists(),
            "{before} cases"
        );
    }
    let o = slamtool(&["sweep", fs, "-q", "-o", killed.to_str().unwrap()], &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let o = slamtool(&["sweep", fs, "-q", "-o", whole.to_str().unwrap()], &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    same_outputs(&killed, &whole);
    assert_eq!(
        read(&killed.join("sweep.json")),
        read(&whole.join("sweep.json"))
    );
}

#[test]
fn two_shards_merged_equal_the_unsharded_sweep() {
    let dir = tempfile::tempdir().unwrap();
    let f = sweep_file(dir.path(), "shards", SMALL);
    let whole = sweep::run(&f, &opts(&dir.path().join("whole")), &Default::default()).unwrap();
    let mut dirs = Vec::new();
    for i in 0..2 {
        let d = dir.path().join(format!("s{i}"));
        let o = Options {
            shard: Some(Shard { index: i, count: 2 }),
            ..opts(&d)
        };
        let r = sweep::run(&f, &o, &Default::default()).unwrap();
        assert!(r.cases.iter().all(|c| c.index % 2 == i));
        dirs.push(d);
    }
    let merged = sweep::merge::merge(&dirs).unwrap();
    // sweep.json keeps 10 significant digits: compare with the unsharded sweep.json.
    assert_eq!(whole.cases.len(), merged.cases.len());
    let whole = sweep::merge::read(&dir.path().join("whole")).unwrap();
    assert_eq!(merged.cases, whole.cases);
    assert!(merged.warnings.is_empty(), "{:?}", merged.warnings);
    let out = dir.path().join("merged");
    sweep::output::write(&out, &merged).unwrap();
    same_outputs(&dir.path().join("whole"), &out);
    // One shard alone is incomplete, and says so.
    let half = sweep::merge::merge(&dirs[..1]).unwrap();
    assert!(
        half.warnings.iter().any(|w| w.contains("missing")),
        "{:?}",
        half.warnings
    );
}

#[test]
fn merge_refuses_shards_of_other_sweeps_and_tool_versions() {
    let dir = tempfile::tempdir().unwrap();
    let a = sweep_file(dir.path(), "a", SMALL);
    let b = sweep_file(dir.path(), "b", "[grid]\nspeed_m_s = [1.6, 2.0]\n");
    let (da, db) = (dir.path().join("a0"), dir.path().join("b1"));
    for (f, d, i) in [(&a, &da, 0), (&b, &db, 1)] {
        let o = Options {
            shard: Some(Shard { index: i, count: 2 }),
            ..opts(d)
        };
        sweep::run(f, &o, &Default::default()).unwrap();
    }
    let e = sweep::merge::merge(&[da.clone(), db])
        .unwrap_err()
        .to_string();
    assert!(e.contains("different sweeps"), "{e}");
    // The same sweep from another tool version.
    let da1 = dir.path().join("a1");
    let o = Options {
        shard: Some(Shard { index: 1, count: 2 }),
        ..opts(&da1)
    };
    sweep::run(&a, &o, &Default::default()).unwrap();
    let j = read(&da1.join("sweep.json")).replace("\"slamtool 0.", "\"slamtool 99.");
    std::fs::write(da1.join("sweep.json"), j).unwrap();
    let e = sweep::merge::merge(&[da, da1]).unwrap_err().to_string();
    assert!(e.contains("different tool versions"), "{e}");
}

#[test]
fn scheduler_variables_pick_the_shards_the_job_scripts_expect() {
    let dir = tempfile::tempdir().unwrap();
    let f = sweep_file(dir.path(), "env", "[grid]\nspeed_m_s = [1.6, 2.0, 2.4]\n");
    let (fs, out) = (f.to_str().unwrap(), dir.path().join("out"));
    let os = out.to_str().unwrap();
    // sweeps/slurm.sh: --array=0-1, two tasks.
    let o = slamtool(
        &["sweep", fs, "-q", "-o", os],
        &[
            ("SLURM_ARRAY_TASK_ID", "1"),
            ("SLURM_ARRAY_TASK_COUNT", "2"),
            ("SLURM_ARRAY_TASK_MIN", "0"),
        ],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s1 = sweep::merge::read(&out.join("shard-1-of-2")).unwrap();
    assert_eq!(s1.shard, Some(Shard { index: 1, count: 2 }));
    assert_eq!(
        s1.cases.iter().map(|c| c.index).collect::<Vec<_>>(),
        vec![1]
    );
    // sweeps/k8s-indexed-job.yaml: JOB_COMPLETION_INDEX with SLAMTOOL_SHARD_COUNT = completions.
    let o = slamtool(
        &["sweep", fs, "-q", "-o", os],
        &[("JOB_COMPLETION_INDEX", "0"), ("SLAMTOOL_SHARD_COUNT", "2")],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let s0 = sweep::merge::read(&out.join("shard-0-of-2")).unwrap();
    assert_eq!(
        s0.cases.iter().map(|c| c.index).collect::<Vec<_>>(),
        vec![0, 2]
    );
    // Without the count an Indexed Job is refused with the reason.
    let o = slamtool(
        &["sweep", fs, "-q", "-o", os],
        &[("JOB_COMPLETION_INDEX", "0")],
    );
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("SLAMTOOL_SHARD_COUNT"));
    // The merge step of both scripts: the folder every shard wrote into stands for its shard folders,
    // and is the default output.
    let o = slamtool(&["merge", os, "-q"], &[]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let all = sweep::merge::read(&out).unwrap();
    assert_eq!(
        all.cases.iter().map(|c| c.index).collect::<Vec<_>>(),
        vec![0, 1, 2]
    );
    assert_eq!(all.shard, None);
    // Shards of two different splits in one folder are refused with the reason.
    let odd = dir.path().join("odd");
    for s in ["shard-0-of-2", "shard-1-of-3"] {
        std::fs::create_dir_all(odd.join(s)).unwrap();
        std::fs::copy(
            out.join("shard-0-of-2/sweep.json"),
            odd.join(s).join("sweep.json"),
        )
        .unwrap();
    }
    let o = slamtool(&["merge", odd.to_str().unwrap(), "-q"], &[]);
    assert_eq!(o.status.code(), Some(1));
    assert!(
        String::from_utf8_lossy(&o.stderr).contains("different splits"),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // The shard folders named one by one.
    let o = slamtool(
        &[
            "merge",
            &format!("{os}/shard-0-of-2"),
            &format!("{os}/shard-1-of-2"),
            "-q",
            "-o",
            os,
        ],
        &[],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let all = sweep::merge::read(&out).unwrap();
    assert_eq!(all.cases.len(), 3);
    assert_eq!(all.shard, None);
}

/// The error of running the sweep file with `body`, as (line, column, message) within the file.
fn located_error(body: &str) -> (usize, usize, String) {
    let dir = tempfile::tempdir().unwrap();
    let f = sweep_file(dir.path(), "bad", body);
    let e = sweep::run(&f, &opts(&dir.path().join("o")), &Default::default()).unwrap_err();
    match e {
        slamtool::Error::Input(ie) => {
            assert_eq!(ie.file, f);
            (ie.line, ie.column, ie.message)
        }
        other => panic!("not a located error: {other}"),
    }
}

#[test]
fn bad_ranges_and_invalid_hull_variants_are_located_in_the_sweep_file() {
    // The header written by sweep_file has 10 lines; the body starts on line 11.
    let (l, c, m) = located_error("[grid]\nspeed_m_s = { start = 1.0, stop = 2.0, step = 0.3 }\n");
    assert_eq!((l, c), (12, 47), "{m}");
    assert!(m.contains("whole number of steps"), "{m}");
    let (l, _, m) = located_error("[grid]\nspeed_m_s = { start = 2.0, stop = 1.0, step = 0.5 }\n");
    assert_eq!(l, 12, "{m}");
    assert!(m.contains("range is empty"), "{m}");
    let (l, c, m) = located_error("[grid]\nflare_scale = [1.0, -0.5]\n");
    assert_eq!((l, c), (12, 21), "{m}");
    assert!(m.contains("positive"), "{m}");
    let (l, _, m) = located_error(
        "[latin_hypercube]\nsamples = 4\nseed = 1\ndraft_m = { min = 0.3, max = 0.2 }\n",
    );
    assert_eq!(l, 14, "{m}");
    assert!(m.contains("larger than min"), "{m}");
    // A draft above the deck (depth 0.5 m): the variant hull fails the hull checks.
    let (l, c, m) = located_error("[grid]\ndraft_m = [0.2, 0.55]\n");
    assert_eq!((l, c), (12, 17), "{m}");
    assert!(
        m.contains("case c0001") && m.contains("above the deck"),
        "{m}"
    );
    // Trim that lifts the forefoot out of the water far enough to leave a draft below zero.
    let (l, _, m) = located_error("[grid]\ntrim_m = [0.0, 0.5]\n");
    assert_eq!(l, 12, "{m}");
    assert!(m.contains("transformed hull is not valid"), "{m}");
    // A flare change needs a region; an unknown parameter is named.
    let (l, _, m) = located_error("[grid]\nspeed_m_s = [1.0]\nfin_scale = [1.0]\n");
    assert_eq!(l, 13, "{m}");
    assert!(m.contains("fin_scale"), "{m}");
    let (l, _, m) = located_error("[grid]\nwave = [\"no-such-wave\"]\n");
    assert_eq!(l, 12, "{m}");
    assert!(m.contains("H0.20-T2.0"), "{m}");
}

#[test]
fn hull_variants_keep_the_underwater_form_or_scale_it_as_defined() {
    let dir = tempfile::tempdir().unwrap();
    let body = "[grid]\nspeed_m_s = [2.0]\nflare_scale = [1.0, 1.5]\nbeam_scale = [1.0, 1.1]\n";
    let f = sweep_file(dir.path(), "variants", body);
    let out = dir.path().join("o");
    let p = sweep::prepare::prepare(&f, &out).unwrap();
    assert_eq!(p.cases.len(), 4);
    // Flare alone shares the strip model of the base hull; a beam change has its own.
    let model = |i: usize| p.variants[p.case_variant[i]].model;
    assert_eq!(model(0), model(2));
    assert_ne!(model(0), model(1));
    // Beam scale 1.1: the volume scales by 1.1 (drafts and length unchanged), to within the hull's
    // interpolation between stations (by normalised girth, which a beam change alters: 6e-6 here).
    let base = slamtool::hull::Hydrostatics::compute(&p.base, &p.base.loadings[0]);
    let wide = &p.variants[p.case_variant[1]];
    let h = slamtool::hull::Hydrostatics::compute(&wide.hull, &wide.hull.loadings[0]);
    assert!(
        (h.volume / base.volume - 1.1).abs() < 1e-4,
        "{}",
        h.volume / base.volume
    );
    // Flare 1.5 at a station forward of the region: below the waterline unchanged, above it the
    // half-breadth grows by 1.5 times the base growth from the waterline.
    let flared = &p.variants[p.case_variant[2]].hull;
    let x = flared.station_x(0.05);
    let (s0, s1) = (p.base.section_at(x).unwrap(), flared.section_at(x).unwrap());
    let zw = p.base.loadings[0].draft_at(x, p.base.lpp);
    assert!((s0.half_breadth_at(0.5 * zw) - s1.half_breadth_at(0.5 * zw)).abs() < 1e-9);
    let (b0, b1) = (s0.half_breadth_at(zw), s1.half_breadth_at(zw));
    let grow0 = s0.half_breadth_at(0.45) - b0;
    let grow1 = s1.half_breadth_at(0.45) - b1;
    assert!(
        grow0 > 0.0 && (grow1 / grow0 - 1.5).abs() < 1e-6,
        "{grow0} {grow1}"
    );
}

/// A sweep makes the same events as `assess`: where the keel stays in the water but the water reaches a
/// flare panel (the Hermundstad & Moan car carrier at 0.05 Lpp), a flare event gives the panel a design
/// pressure, equal to the assessment's.
#[test]
fn a_sweep_case_gets_the_flare_event_of_an_immersed_keel() {
    let dir = tempfile::tempdir().unwrap();
    let text = format!(
        "name = \"flare\"\nhull = \"{ROOT}/hulls/car-carrier-hm2005.toml\"\nsea = \
         \"{ROOT}/sea_states/car-carrier-hm2005.toml\"\nfidelity = \"analytic\"\n\n[bow_region]\n\
         full_aft_of_fp = 0.05\nzero_aft_of_fp = 0.2\n\n[grid]\nflare_scale = [1.0]\n"
    );
    let f = dir.path().join("flare.toml");
    std::fs::write(&f, text).unwrap();
    let r = sweep::run(&f, &opts(&dir.path().join("out")), &Default::default()).unwrap();
    assert_eq!(r.failed_cases, 0, "{:?}", r.warnings);
    let st = &r.cases[0].stations[0];
    assert_eq!(st.emerging_events, 0, "the keel stays in the water");
    let p1 = st
        .sensors
        .iter()
        .find(|s| s.name == "P1")
        .expect("a design pressure on the flare panel");
    assert!(p1.design_pressure_pa.is_some_and(|p| p > 0.0) && p1.source == "analytic");
    // The same as the assessment of the unchanged hull, to the interpolation of the sweep's strip-theory
    // table in frequency (measured: 4e-5).
    let hull = slamtool::hull::Hull::from_file(Path::new(&format!(
        "{ROOT}/hulls/car-carrier-hm2005.toml"
    )))
    .unwrap();
    let sea = slamtool::sea::SeaState::from_file(Path::new(&format!(
        "{ROOT}/sea_states/car-carrier-hm2005.toml"
    )))
    .unwrap();
    let s = slamtool::assess::Settings {
        fidelity: slamtool::assess::Fidelity::Analytic,
        ..Default::default()
    };
    let (a, _) = slamtool::assess::run(
        &hull,
        &sea,
        &s,
        &dir.path().join("assess"),
        &Default::default(),
    )
    .unwrap();
    let q = a.stations[0]
        .design_pressure_pa
        .iter()
        .find(|d| d.name == "P1")
        .unwrap();
    let (swept, assessed) = (p1.design_pressure_pa.unwrap(), q.value.unwrap());
    let rel = (swept - assessed).abs() / assessed;
    assert!(rel < 1e-3, "sweep {swept} vs assess {assessed}");
}

/// Beyond a dozen warnings the terminal gives each kind once (warnings that differ only in their
/// numbers), with the number of cases that gave it: on a small sweep in the model-scale irregular sea,
/// the kind "no design event at station ..." is printed once with its number of cases as `sweep.json`
/// counts them, and the lines printed are as many as the kinds announced.
#[test]
fn many_warnings_print_as_kinds_with_their_cases() {
    let dir = tempfile::tempdir().unwrap();
    let f = dir.path().join("kinds.toml");
    std::fs::write(
        &f,
        format!(
            "name = \"kinds\"\nhull = \"{ROOT}/hulls/ochi-vform.toml\"\nsea = \"{ROOT}/sweeps/ochi-sea.toml\"\n\
             loading = \"test-condition\"\nfidelity = \"analytic\"\n\n[grid]\n\
             speed_m_s = {{ start = 1.0, stop = 1.5, step = 0.1 }}\nwave_height_m = [0.1, 0.2]\n\
             wavelength_m = [4.5, 6.0]\n"
        ),
    )
    .unwrap();
    let out = dir.path().join("out");
    let o = slamtool(
        &["sweep", f.to_str().unwrap(), "-o", out.to_str().unwrap()],
        &[],
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let stdout = String::from_utf8_lossy(&o.stdout);
    let json: serde_json::Value = serde_json::from_str(&read(&out.join("sweep.json"))).unwrap();
    let distinct = json["warnings"].as_array().unwrap().len();
    assert!(
        distinct > sweep::results::WARNINGS_IN_FULL,
        "the sweep gives only {distinct} warnings: enlarge its grid"
    );
    let header = stdout
        .lines()
        .find(|l| l.starts_with(&format!("{distinct} distinct warnings of ")))
        .unwrap_or_else(|| panic!("no kinds header in\n{stdout}"));
    let kinds: usize = header.split(' ').nth(4).unwrap().parse().unwrap();
    let lines: Vec<&str> = stdout
        .lines()
        .filter(|l| l.starts_with("warning: ["))
        .collect();
    assert_eq!(lines.len(), kinds, "{stdout}");
    let no_event = lines
        .iter()
        .filter(|l| l.contains("] no design event at station"))
        .collect::<Vec<_>>();
    assert_eq!(no_event.len(), 1, "{stdout}");
    let cases_with = json["cases"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|c| {
            c["warnings"].as_array().unwrap().iter().any(|w| {
                w.as_str()
                    .unwrap()
                    .starts_with("no design event at station")
            })
        })
        .count();
    assert!(
        no_event[0].starts_with(&format!("warning: [{cases_with} cases] ")),
        "{} against {cases_with} cases",
        no_event[0]
    );
}
