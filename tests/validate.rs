//! `slamtool validate`: case files are checked with file:line:column errors, a tiny (analytic) case
//! runs, the verdict logic gives the documented exit status (6 for a failure, 0 for a known failure),
//! and the summary table has one row per case.

use std::path::{Path, PathBuf};
use std::process::Command;

use slamtool::input::SourceText;
use slamtool::validate::{self, Case, Mode, Verdict};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

/// A case computing Wagner's flare pressure (analytic, milliseconds) with the given tolerance and an
/// optional known-failure line.
fn wagner_case(tolerance: f64, known_failure: Option<&str>) -> String {
    let reference = root().join("data/reference/hermundstad2005_panel.toml");
    format!(
        r#"title = "tiny analytic case"
kind = "hermundstad2005-wagner"
quantity = "Wagner peak pressure"
unit = "kPa"
reference_files = ["{}"]
provenance = "test"
{}
[tolerance]
kind = "relative"
value = {tolerance}
reason = "test"
stated = "before-results"

[parameters]
water_density_kg_per_m3 = 1000.0
"#,
        reference.display(),
        known_failure.map_or(String::new(), |k| format!("known_failure = \"{k}\"\n"))
    )
}

fn parse(text: &str) -> String {
    match Case::from_source(SourceText::from_string("case.toml", text)) {
        Ok(_) => "ok".into(),
        Err(e) => e.to_string(),
    }
}

#[test]
fn bundled_case_files_parse() {
    let files = validate::case::case_files(&root().join("validation")).unwrap();
    assert!(files.len() >= 20, "{} case files", files.len());
    for f in files {
        Case::from_file(&f).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn bad_case_files_are_located() {
    let good = wagner_case(0.05, None);
    assert_eq!(parse(&good), "ok");
    let bad_kind = good.replace("hermundstad2005-wagner", "no-such-kind");
    assert!(
        parse(&bad_kind).starts_with("case.toml:2:8: unknown kind `no-such-kind`"),
        "{}",
        parse(&bad_kind)
    );
    let bad_tol = good.replace("kind = \"relative\"", "kind = \"roughly\"");
    assert!(
        parse(&bad_tol).starts_with("case.toml:9:8: unknown tolerance kind"),
        "{}",
        parse(&bad_tol)
    );
    let no_reason = good.replace("reason = \"test\"", "reason = \" \"");
    assert!(
        parse(&no_reason).starts_with("case.toml:11:10:"),
        "{}",
        parse(&no_reason)
    );
    let negative = good.replace("value = 0.05", "value = -0.05");
    assert!(
        parse(&negative).starts_with("case.toml:10:9:"),
        "{}",
        parse(&negative)
    );
    let missing = good.replace("hermundstad2005_panel.toml", "nothing_here.toml");
    assert!(
        parse(&missing).contains("case.toml:5:20: reference file"),
        "{}",
        parse(&missing)
    );
    let unknown_key = good.replace("unit = \"kPa\"", "unit = \"kPa\"\ncolour = 3");
    assert!(
        parse(&unknown_key).starts_with("case.toml:5:1:"),
        "{}",
        parse(&unknown_key)
    );
}

#[test]
fn a_parameter_of_the_wrong_type_is_located_when_the_case_runs() {
    let text = wagner_case(0.05, None).replace(
        "water_density_kg_per_m3 = 1000.0",
        "water_density_kg_per_m3 = \"fresh\"",
    );
    let case = Case::from_source(SourceText::from_string("case.toml", text)).unwrap();
    let r = validate::run_case(&case, Mode::Quick, &Default::default());
    assert_eq!(r.verdict, Verdict::Error);
    assert!(
        r.notes.iter().any(|n| n.contains("case.toml:15:27:")),
        "{:?}",
        r.notes
    );
}

#[test]
fn verdicts_of_a_tiny_case() {
    let run = |tol: f64, known: Option<&str>| {
        let case = Case::from_source(SourceText::from_string(
            "case.toml",
            wagner_case(tol, known),
        ))
        .unwrap();
        validate::run_case(&case, Mode::Quick, &Default::default())
    };
    // Wagner at 37 deg and 1.4 m/s is 4.26 kPa against Veen's 4.2 kPa: +1.4 %.
    let pass = run(0.05, None);
    assert_eq!(pass.verdict, Verdict::Pass);
    assert!((pass.computed.unwrap() - 4.26).abs() < 0.01);
    assert_eq!(run(0.001, None).verdict, Verdict::Fail);
    assert_eq!(run(0.001, Some("expected")).verdict, Verdict::KnownFailure);
    assert_eq!(run(0.05, Some("expected")).verdict, Verdict::UnexpectedPass);
}

/// Write the cases into a folder and run the binary on them; returns (exit status, stdout, out dir).
fn run_cli(cases: &[(&str, String)], dir: &Path) -> (i32, String, PathBuf) {
    let cdir = dir.join("cases");
    std::fs::create_dir_all(&cdir).unwrap();
    for (name, text) in cases {
        std::fs::write(cdir.join(format!("{name}.toml")), text).unwrap();
    }
    let out = dir.join("out");
    let o = Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(["validate", "--quick", "-q", "--cases-dir"])
        .arg(&cdir)
        .arg("-o")
        .arg(&out)
        .output()
        .unwrap();
    (
        o.status.code().unwrap(),
        String::from_utf8_lossy(&o.stdout).into_owned(),
        out,
    )
}

#[test]
fn exit_status_follows_the_verdicts_and_the_summary_has_one_row_per_case() {
    let dir = tempfile::tempdir().unwrap();
    let (code, stdout, out) = run_cli(
        &[
            ("a-pass", wagner_case(0.05, None)),
            ("b-known", wagner_case(0.001, Some("expected in this test"))),
        ],
        dir.path(),
    );
    assert_eq!(code, 0, "{stdout}");
    let csv = std::fs::read_to_string(out.join("summary.csv")).unwrap();
    let rows: Vec<&str> = csv.lines().filter(|l| !l.starts_with('#')).collect();
    assert_eq!(rows.len(), 3, "{csv}");
    assert!(rows[0].starts_with("case,quantity,computed,reference,error,tolerance,verdict"));
    assert!(rows[1].starts_with("a-pass,") && rows[1].contains(",pass,"));
    assert!(rows[2].starts_with("b-known,") && rows[2].contains("known failure"));
    let md = std::fs::read_to_string(out.join("summary.md")).unwrap();
    assert_eq!(
        md.lines()
            .filter(|l| l.starts_with("| a-pass") || l.starts_with("| b-known"))
            .count(),
        2
    );
    assert!(out.join("a-pass/case.json").is_file());

    let dir = tempfile::tempdir().unwrap();
    let (code, stdout, _) = run_cli(
        &[
            ("a-pass", wagner_case(0.05, None)),
            ("c-fail", wagner_case(0.001, None)),
        ],
        dir.path(),
    );
    assert_eq!(code, 6, "{stdout}");
    assert!(stdout.contains("FAIL"), "{stdout}");
}

/// Each case's CSV files name that case's own inputs (its case file and what it reads), not every
/// file of the suite, with lexically normal paths.
#[test]
fn a_case_csv_names_its_own_inputs() {
    let r = root();
    let particulars = std::fs::read_to_string(r.join("validation/ochi1958-particulars.toml"))
        .unwrap()
        .replace(
            "\"../data/reference/ochi1958_vform.toml\"",
            &format!(
                "\"{}/../data/reference/ochi1958_vform.toml\"",
                r.join("validation").display()
            ),
        )
        .replace(
            "\"../hulls/ochi-vform.toml\"",
            &format!("\"{}\"", r.join("hulls/ochi-vform.toml").display()),
        );
    let dir = tempfile::tempdir().unwrap();
    let (code, stdout, out) = run_cli(
        &[
            ("a-pass", wagner_case(0.05, None)),
            ("c-particulars", particulars),
        ],
        dir.path(),
    );
    assert_eq!(code, 0, "{stdout}");
    let csvs: Vec<PathBuf> = std::fs::read_dir(out.join("c-particulars"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "csv"))
        .collect();
    assert!(csvs.len() >= 2, "{csvs:?}");
    for p in &csvs {
        let text = std::fs::read_to_string(p).unwrap();
        let inputs: Vec<&str> = text.lines().filter(|l| l.starts_with("# input ")).collect();
        let shows = |name: &str| inputs.iter().any(|l| l.contains(name));
        assert!(shows("c-particulars.toml"), "{}: {inputs:?}", p.display());
        assert!(
            shows("ochi-vform.toml") && shows("ochi1958_vform.toml"),
            "{inputs:?}"
        );
        assert!(
            !shows("a-pass.toml") && !shows("hermundstad2005_panel"),
            "{inputs:?}"
        );
        assert!(!inputs.iter().any(|l| l.contains("/../")), "{inputs:?}");
        assert!(
            text.contains(r#""case":"c-particulars""#),
            "{}",
            p.display()
        );
    }
}

/// The document outline the PDF is built from: the front table has one row per case, and every case
/// has its own section with its verdict.
#[test]
fn document_outline_has_one_summary_row_and_one_section_per_case() {
    let cases: Vec<Case> = [
        wagner_case(0.05, None),
        wagner_case(0.001, Some("expected")),
    ]
    .into_iter()
    .enumerate()
    .map(|(i, t)| Case::from_source(SourceText::from_string(format!("case{i}.toml"), t)).unwrap())
    .collect();
    let dir = tempfile::tempdir().unwrap();
    let suite = validate::run_suite(&cases, Mode::Quick, dir.path().to_path_buf(), &mut |_| {});
    let o = validate::document::outline(&suite, "test").unwrap();
    // The front page states the tally of every verdict, zeros included.
    let all = "2 cases: 1 pass, 0 pass of a known failure, 1 known failure, 0 pending data, 0 fail, 0 error";
    assert!(o.subtitle.iter().any(|l| l == all), "{:?}", o.subtitle);
    let slamtool::report::document::Block::Table { rows, header, .. } = &o.blocks[0] else {
        panic!("the first block is not the summary table");
    };
    // case and quantity share the first column ("case: quantity"), then computed, reference, error,
    // tolerance, verdict
    assert_eq!(header.len(), 6);
    assert_eq!(rows.len(), 2);
    assert!(rows[0][0].starts_with("case0: "), "{}", rows[0][0]);
    assert_eq!(rows[0][5], "pass");
    assert_eq!(rows[1][5], "known failure");
    let headings = o
        .blocks
        .iter()
        .filter(|b| {
            matches!(
                b,
                slamtool::report::document::Block::Heading { level: 1, .. }
            )
        })
        .count();
    assert_eq!(headings, 2);
}

#[test]
fn a_known_failure_is_written_from_the_run_s_numbers_and_literal_numbers_are_refused() {
    let literal = wagner_case(0.001, Some("Veen rounds to 0.1 kPa"));
    let err = parse(&literal);
    assert!(
        err.starts_with("case.toml:7:17:") && err.contains("the number 0.1"),
        "{err}"
    );
    // Words with digits (2D, S093) are not numbers.
    assert_eq!(
        parse(&wagner_case(0.001, Some("a 2D estimate at S093"))),
        "ok"
    );
    let run = |known: &str, tol: f64| {
        let case = Case::from_source(SourceText::from_string(
            "case.toml",
            wagner_case(tol, Some(known)),
        ))
        .unwrap();
        validate::run_case(&case, Mode::Quick, &Default::default())
    };
    let r = run("Veen's value is {reference} and ours {computed}", 0.001);
    assert_eq!(r.verdict, Verdict::KnownFailure);
    let text = r.known_failure.unwrap();
    assert!(
        text.starts_with(
            "computed 4.258 kPa against 4.2 kPa (tolerance ±0.1 %, error +1.4 %): outside the \
             tolerance."
        ) && text.ends_with("Veen's value is 4.2 kPa and ours 4.258 kPa"),
        "{text}"
    );
    // Within the tolerance: the text says the mark should be revisited.
    let r = run("ours {computed}", 0.05);
    assert_eq!(r.verdict, Verdict::UnexpectedPass);
    let text = r.known_failure.unwrap();
    assert!(
        text.contains("within the tolerance in this run") && !text.contains("ours"),
        "{text}"
    );
    // A placeholder the computation does not give is an error of the case, not a silent gap.
    let r = run("the {missing} number", 0.001);
    assert_eq!(r.verdict, Verdict::Error);
    assert!(
        r.notes.iter().any(|n| n.contains("{missing}")),
        "{:?}",
        r.notes
    );
}

#[test]
fn a_tolerance_revised_after_results_says_so_and_one_sided_bounds_are_marked() {
    let revised = wagner_case(0.05, None).replace(
        "stated = \"before-results\"",
        "stated = \"after-results\"\nrevision = \"widened after the first run\"",
    );
    let case = Case::from_source(SourceText::from_string("case.toml", revised.clone())).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let suite = validate::run_suite(&[case], Mode::Quick, dir.path().to_path_buf(), &mut |_| {});
    let md = validate::report::markdown(&suite);
    assert!(
        md.contains("*Tolerance, revised after results were seen (widened after the first run):*"),
        "{md}"
    );
    assert!(!md.contains("set before the result was seen"), "{md}");
    let no_revision = revised.replace("revision = \"widened after the first run\"\n", "");
    assert!(
        parse(&no_revision).contains("needs `revision`"),
        "{}",
        parse(&no_revision)
    );
    assert!(
        parse(&wagner_case(0.05, None).replace("stated = \"before-results\"\n", ""))
            .contains("stated")
    );
    // A one-sided bound passes far below it, and every table says it is one-sided.
    let one_sided = wagner_case(0.05, None).replace(
        "kind = \"relative\"\nvalue = 0.05",
        "kind = \"upper-bound\"\nvalue = 100.0",
    );
    let case = Case::from_source(SourceText::from_string("case.toml", one_sided)).unwrap();
    let r = validate::run_case(&case, Mode::Quick, &Default::default());
    assert_eq!(r.verdict, Verdict::Pass);
    let row = validate::report::summary_row(&r);
    assert_eq!(row.tolerance, "≤ 100 kPa (one-sided bound)");
}

#[test]
fn every_file_a_case_reads_is_hashed_and_its_water_density_stated() {
    let files = validate::case::case_files(&root().join("validation")).unwrap();
    let keel = files
        .iter()
        .find(|f| f.ends_with("ochi1958-particulars.toml"))
        .unwrap();
    let case = Case::from_file(keel).unwrap();
    let r = validate::run_case(&case, Mode::Quick, &Default::default());
    let paths: Vec<&str> = r.inputs.iter().map(|f| f.path.as_str()).collect();
    assert!(
        paths.iter().any(|p| p.ends_with("hulls/ochi-vform.toml"))
            && paths.iter().any(|p| p.ends_with("ochi1958_vform.toml")),
        "{paths:?}"
    );
    let hull = std::fs::read(root().join("hulls/ochi-vform.toml")).unwrap();
    let h = r
        .inputs
        .iter()
        .find(|f| f.path.ends_with("hulls/ochi-vform.toml"))
        .unwrap();
    assert_eq!(h.sha256, slamtool::provenance::sha256_hex(&hull));
    let conditions: Vec<String> = r
        .conditions
        .iter()
        .map(|c| format!("{}: {}", c.0, c.1))
        .collect();
    assert!(
        conditions
            .iter()
            .any(|c| c.starts_with("water density: 1000 kg/m³"))
            && conditions
                .iter()
                .any(|c| c.starts_with("scale: ") && c.contains("Lpp 6 m")),
        "{conditions:?}"
    );
}
