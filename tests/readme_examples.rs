//! Every TOML example in the README is complete and valid: hull files, sea states and case files are
//! extracted and read exactly as the tool reads them (sweep files: their schema and cases). A hull example that names an offsets CSV file gets
//! the README's next CSV block as that file.

use slamtool::hull::Hull;
use slamtool::input::SourceText;
use slamtool::sea::SeaState;
use slamtool::sph::case_file;

/// The fenced code blocks of `text` as (language, body), in order.
fn code_blocks(text: &str) -> Vec<(String, String)> {
    let mut blocks = Vec::new();
    let mut current: Option<(String, String)> = None;
    for line in text.lines() {
        match (&mut current, line.trim_start().strip_prefix("```")) {
            (None, Some(lang)) => current = Some((lang.trim().to_string(), String::new())),
            (Some(_), Some(_)) => blocks.push(current.take().expect("open block")),
            (Some((_, body)), None) => {
                body.push_str(line);
                body.push('\n');
            }
            (None, None) => {}
        }
    }
    blocks
}

#[test]
fn every_toml_example_in_the_readme_is_read_without_error() {
    let readme =
        std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/README.md")).unwrap();
    let blocks = code_blocks(&readme);
    let dir = tempfile::tempdir().unwrap();
    let (mut hulls, mut seas, mut cases, mut sweeps) = (0, 0, 0, 0);
    for (i, (lang, body)) in blocks.iter().enumerate() {
        if lang != "toml" {
            continue;
        }
        let path = dir.path().join(format!("example{i}.toml"));
        std::fs::write(&path, body).unwrap();
        if body.contains("[tolerance]") {
            // a validation case: reference paths are relative to validation/
            let at =
                std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("validation/example.toml");
            slamtool::validate::Case::from_source(SourceText::from_string(at, body.as_str()))
                .unwrap_or_else(|e| panic!("README validation case example {i}: {e}\n{body}"));
        } else if body.contains("[grid]") || body.contains("[latin_hypercube]") {
            // A sweep file: its schema, values and cases (the files it names are the repository's).
            let f = slamtool::sweep::file::SweepFile::read(&path)
                .unwrap_or_else(|e| panic!("README sweep example {i}: {e}\n{body}"));
            let n = slamtool::sweep::cases::expand(&f)
                .unwrap_or_else(|e| panic!("README sweep example {i}: {e}\n{body}"))
                .len();
            assert!(n > 0, "README sweep example {i} has no cases");
            sweeps += 1;
        } else if body.contains("[section]") {
            case_file::from_source(&SourceText::from_string(&path, body.as_str()))
                .unwrap_or_else(|e| panic!("README case example {i}: {e}\n{body}"));
            cases += 1;
        } else if body.contains("lpp_m") {
            if body.contains("[offsets_csv]") {
                let file = body
                    .lines()
                    .find_map(|l| l.trim().strip_prefix("file = \""))
                    .and_then(|l| l.split('"').next())
                    .expect("the offsets file name");
                let csv = blocks[i + 1..]
                    .iter()
                    .find(|(l, _)| l == "csv")
                    .expect("a CSV block after the offsets_csv example");
                std::fs::write(dir.path().join(file), &csv.1).unwrap();
            }
            let hull = Hull::from_file(&path)
                .unwrap_or_else(|e| panic!("README hull example {i}: {e}\n{body}"));
            for l in &hull.loadings {
                let h = slamtool::hull::Hydrostatics::compute(&hull, l);
                assert!(h.gm_t > 0.0, "README hull example {i} has a negative GM_T");
            }
            hulls += 1;
        } else if body.contains("[[regular]]") || body.contains("[[irregular]]") {
            SeaState::from_source(&SourceText::from_string(&path, body.as_str()))
                .unwrap_or_else(|e| panic!("README sea-state example {i}: {e}\n{body}"));
            seas += 1;
        } else {
            panic!(
                "README TOML example {i} is neither a hull, a sea state nor a case file:\n{body}"
            );
        }
    }
    assert!(
        hulls >= 2 && seas >= 1 && cases >= 1 && sweeps >= 1,
        "{hulls} hulls, {seas} seas, {cases} cases, {sweeps} sweeps"
    );
}
