//! Every TOML example in the README and the user guide (docs/**/*.md) is complete and valid: hull files,
//! sea states and case files are extracted and read exactly as the tool reads them (sweep files: their
//! schema and cases). A hull example that names an offsets CSV file gets the same page's next CSV block as
//! that file. Every `slamtool` command line of their `sh` blocks names existing subcommands and options.

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

/// README.md and every Markdown file under docs/, in a fixed order.
fn pages() -> Vec<std::path::PathBuf> {
    fn rec(d: &std::path::Path, out: &mut Vec<std::path::PathBuf>) {
        let mut es: Vec<_> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().path())
            .collect();
        es.sort();
        for p in es {
            if p.is_dir() {
                rec(&p, out);
            } else if p.extension().is_some_and(|e| e == "md") {
                out.push(p);
            }
        }
    }
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut v = vec![root.join("README.md")];
    rec(&root.join("docs"), &mut v);
    v
}

#[test]
fn every_toml_example_in_the_readme_and_the_guide_is_read_without_error() {
    let (mut hulls, mut seas, mut cases, mut sweeps) = (0, 0, 0, 0);
    for page in pages() {
        let text = std::fs::read_to_string(&page).unwrap();
        let counts = check_toml_examples(&page, &text);
        hulls += counts.0;
        seas += counts.1;
        cases += counts.2;
        sweeps += counts.3;
    }
    assert!(
        hulls >= 2 && seas >= 1 && cases >= 1 && sweeps >= 1,
        "{hulls} hulls, {seas} seas, {cases} cases, {sweeps} sweeps"
    );
}

/// Reads every TOML block of one page; returns the numbers of (hulls, seas, cases, sweeps) read.
fn check_toml_examples(page: &std::path::Path, text: &str) -> (usize, usize, usize, usize) {
    let page = page.display();
    let blocks = code_blocks(text);
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
                .unwrap_or_else(|e| panic!("{page}: validation case example {i}: {e}\n{body}"));
        } else if body.contains("[grid]") || body.contains("[latin_hypercube]") {
            // A sweep file: its schema, values and cases (the files it names are the repository's).
            let f = slamtool::sweep::file::SweepFile::read(&path)
                .unwrap_or_else(|e| panic!("{page}: sweep example {i}: {e}\n{body}"));
            let n = slamtool::sweep::cases::expand(&f)
                .unwrap_or_else(|e| panic!("{page}: sweep example {i}: {e}\n{body}"))
                .len();
            assert!(n > 0, "{page}: sweep example {i} has no cases");
            sweeps += 1;
        } else if body.contains("[section]") {
            case_file::from_source(&SourceText::from_string(&path, body.as_str()))
                .unwrap_or_else(|e| panic!("{page}: case example {i}: {e}\n{body}"));
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
                .unwrap_or_else(|e| panic!("{page}: hull example {i}: {e}\n{body}"));
            for l in &hull.loadings {
                let h = slamtool::hull::Hydrostatics::compute(&hull, l);
                assert!(h.gm_t > 0.0, "{page}: hull example {i} has a negative GM_T");
            }
            hulls += 1;
        } else if body.contains("[[regular]]") || body.contains("[[irregular]]") {
            SeaState::from_source(&SourceText::from_string(&path, body.as_str()))
                .unwrap_or_else(|e| panic!("{page}: sea-state example {i}: {e}\n{body}"));
            seas += 1;
        } else {
            panic!(
                "{page}: TOML example {i} is neither a hull, a sea state nor a case file:\n{body}"
            );
        }
    }
    (hulls, seas, cases, sweeps)
}

/// The `slamtool` command lines of the `sh` blocks of a page (also `cargo run --release -- ...`), as
/// their arguments after `slamtool`, comments and continuation lines removed.
fn command_lines(text: &str) -> Vec<Vec<String>> {
    let mut out = Vec::new();
    for (lang, body) in code_blocks(text) {
        if lang != "sh" && lang != "bash" {
            continue;
        }
        for line in body.lines() {
            let line = line.split(" #").next().unwrap_or("").trim();
            let rest = if let Some(r) = line.split_once("cargo run --release -- ") {
                r.1
            } else if let Some(r) = line.split_once("slamtool ") {
                r.1
            } else {
                continue;
            };
            out.push(rest.split_whitespace().map(str::to_string).collect());
        }
    }
    out
}

#[test]
fn every_command_line_in_the_readme_and_the_guide_names_real_subcommands_and_options() {
    let mut helps: std::collections::HashMap<Vec<String>, String> = Default::default();
    let mut checked = 0;
    for page in pages() {
        let text = std::fs::read_to_string(&page).unwrap();
        for args in command_lines(&text) {
            // The subcommand path: the leading words that are neither options nor paths nor values.
            let sub: Vec<String> = args
                .iter()
                .take_while(|a| {
                    !a.starts_with('-')
                        && !a.contains(['/', '.', '=', '$', '"', '['])
                        && a.chars().all(|c| c.is_ascii_lowercase() || c == '-')
                })
                .take(2)
                .cloned()
                .collect();
            let help = helps.entry(sub.clone()).or_insert_with(|| {
                let o = std::process::Command::new(env!("CARGO_BIN_EXE_slamtool"))
                    .args(&sub)
                    .arg("--help")
                    .output()
                    .unwrap();
                String::from_utf8_lossy(&o.stdout).into_owned()
            });
            // `hull info` takes a file after its subcommand: keep only real subcommands.
            assert!(
                help.contains("Usage:"),
                "{}: `slamtool {}`: no such command",
                page.display(),
                args.join(" ")
            );
            for a in args.iter().filter(|a| a.starts_with("--")) {
                let opt = a.split('=').next().unwrap().trim_end_matches([',', ')']);
                let listed = help.match_indices(opt).any(|(i, _)| {
                    !help[i + opt.len()..]
                        .starts_with(|c: char| c.is_ascii_alphanumeric() || c == '-')
                });
                assert!(
                    listed,
                    "{}: `slamtool {}`: option {opt} is not in `slamtool {} --help`",
                    page.display(),
                    args.join(" "),
                    sub.join(" ")
                );
            }
            checked += 1;
        }
    }
    assert!(checked >= 10, "only {checked} command lines found");
}
