//! The README's and the user guide's figures that come from a run are generated from the committed
//! outputs, and this test fails when they drift apart: every block between
//! `<!-- BEGIN GENERATED name -->` and `<!-- END GENERATED name -->` in README.md and docs/**/*.md must equal
//! what [`generate`] makes of `reports/*/summary.json` as committed. After regenerating `reports/`,
//! refresh the blocks with
//!
//! ```sh
//! UPDATE_DOCS=1 cargo test --release --test docs_tables
//! ```
//!
//! and commit the changed Markdown files. Also checked: the troubleshooting page lists every exit status
//! of `src/cli/exit.rs`.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde_json::Value;

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn json(rel: &str) -> Value {
    let p = Path::new(ROOT).join(rel);
    let text = std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()));
    serde_json::from_str(&text).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

fn s<'a>(v: &'a Value, k: &str) -> &'a str {
    v.get(k).and_then(Value::as_str).unwrap_or("")
}

fn short_commit(v: &Value) -> String {
    s(&v["provenance"], "commit").chars().take(7).collect()
}

/// `|`-separated Markdown row, with `|` inside a cell escaped.
fn row(cells: &[String]) -> String {
    format!(
        "| {} |",
        cells
            .iter()
            .map(|c| c.replace('|', "\\|"))
            .collect::<Vec<_>>()
            .join(" | ")
    )
}

/// The validation table of `reports/validation/summary.json`.
fn validation_table() -> String {
    let v = json("reports/validation/summary.json");
    let tally = v["tally"]
        .as_object()
        .expect("tally")
        .iter()
        .filter(|(_, n)| n.as_u64().unwrap_or(0) > 0)
        .map(|(k, n)| format!("{n} {k}"))
        .collect::<Vec<_>>()
        .join(", ");
    let mut out = format!(
        "`slamtool validate --{}` at commit `{}` ({} cases: {tally}; {:.0} s of wall time, from \
         `reports/validation/summary.json`):\n\n",
        s(&v, "mode"),
        short_commit(&v),
        v["summary"].as_array().map_or(0, Vec::len),
        v["wall_time_s"].as_f64().unwrap_or(f64::NAN)
    );
    out += "| case | quantity | computed | reference | error | tolerance | verdict |\n";
    out += "|---|---|---|---|---|---|---|\n";
    for r in v["summary"].as_array().expect("summary rows") {
        out += &row(&[
            "case",
            "quantity",
            "computed",
            "reference",
            "error",
            "tolerance",
            "verdict",
        ]
        .map(|k| s(r, k).to_string()));
        out += "\n";
    }
    out
}

fn kpa(v: &Value) -> String {
    v.as_f64()
        .map_or("–".into(), |x| format!("{:.2}", x / 1000.0))
}

/// The design table of the bundled example, `reports/ochi-vform/summary.json`.
fn ochi_design_table() -> String {
    let v = json("reports/ochi-vform/summary.json");
    let mut out = format!(
        "`slamtool assess hulls/ochi-vform.toml --sea sea_states/ochi-1958.toml` ({} fidelity, loading \
         `{}`) at commit `{}`, from `reports/ochi-vform/summary.json`:\n\n",
        s(&v, "fidelity"),
        s(&v, "loading"),
        short_commit(&v)
    );
    out += "| station | sensor | design pressure (kPa) | source | speed (m/s) | wave | SPH verdict |\n";
    out += "|---|---|---:|---|---:|---|---|\n";
    for st in v["stations"].as_array().expect("stations") {
        for d in st["design_pressure_pa"]
            .as_array()
            .expect("design_pressure_pa")
        {
            out += &row(&[
                format!("{}", st["station"].as_f64().unwrap_or(f64::NAN)),
                s(d, "name").into(),
                kpa(&d["value"]),
                s(d, "source").into(),
                d["speed_m_per_s"]
                    .as_f64()
                    .map_or("–".into(), |x| format!("{x}")),
                s(d, "wave").into(),
                s(d, "verdict").replace('_', " "),
            ]);
            out += "\n";
        }
    }
    out
}

/// The published comparisons of the bundled example.
fn ochi_comparisons() -> String {
    let v = json("reports/ochi-vform/summary.json");
    let mut out = String::from(
        "| quantity | computed | reference | unit | note |\n|---|---:|---:|---|---|\n",
    );
    for c in v["comparisons"].as_array().expect("comparisons") {
        let n = |k: &str| c[k].as_f64().map_or("–".into(), |x| format!("{x:.2}"));
        out += &row(&[
            s(c, "quantity").into(),
            n("computed"),
            n("reference"),
            s(c, "unit").into(),
            s(c, "note").into(),
        ]);
        out += "\n";
    }
    for t in v["trend_checks"].as_array().expect("trend_checks") {
        out += &format!("\n- *{}*: **{}**", s(t, "check"), s(t, "verdict"));
    }
    out + "\n"
}

fn json_type(v: &Value) -> &'static str {
    match v {
        Value::Null => "null",
        Value::Bool(_) => "boolean",
        Value::Number(_) => "number",
        Value::String(_) => "string",
        Value::Array(_) => "array",
        Value::Object(_) => "object",
    }
}

fn walk(v: &Value, path: String, out: &mut BTreeMap<String, Vec<&'static str>>) {
    let t = out.entry(path.clone()).or_default();
    if !t.contains(&json_type(v)) {
        t.push(json_type(v));
    }
    match v {
        Value::Object(m) => {
            for (k, x) in m {
                let p = if path.is_empty() {
                    k.clone()
                } else {
                    format!("{path}.{k}")
                };
                walk(x, p, out);
            }
        }
        Value::Array(a) => {
            for x in a {
                walk(x, format!("{path}[]"), out);
            }
        }
        _ => {}
    }
}

/// Every field path of the committed Ochi `summary.json` with the JSON types it takes there. `settings`
/// and `provenance.settings` are free-form records of the run's settings and are listed to one level.
fn summary_schema() -> String {
    let v = json("reports/ochi-vform/summary.json");
    let mut paths = BTreeMap::new();
    walk(&v, String::new(), &mut paths);
    let mut out = String::from("| field | JSON type |\n|---|---|\n");
    for (p, mut t) in paths {
        let free = ["settings.", "provenance.settings."]
            .iter()
            .any(|pre| p.starts_with(pre) && p[pre.len()..].contains(['.', '[']));
        if p.is_empty() || free {
            continue;
        }
        t.sort();
        out += &format!("| `{p}` | {} |\n", t.join(" or "));
    }
    out
}

fn generate(name: &str) -> Option<String> {
    Some(match name {
        "validation-table" => validation_table(),
        "ochi-design-table" => ochi_design_table(),
        "ochi-comparisons" => ochi_comparisons(),
        "summary-schema" => summary_schema(),
        _ => return None,
    })
}

fn markdown_files() -> Vec<PathBuf> {
    fn rec(d: &Path, out: &mut Vec<PathBuf>) {
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
    let mut v = vec![Path::new(ROOT).join("README.md")];
    rec(&Path::new(ROOT).join("docs"), &mut v);
    v
}

/// `text` with every generated block replaced by its generated content; the names of the blocks found.
fn refresh(text: &str, file: &Path) -> (String, Vec<String>) {
    let mut out = String::new();
    let mut names = Vec::new();
    let mut rest = text;
    while let Some(i) = rest.find("<!-- BEGIN GENERATED ") {
        let head_end = rest[i..].find("-->").expect("closing -->") + i + 3;
        let name = rest[i + 21..head_end - 3].trim().to_string();
        let end_marker = format!("<!-- END GENERATED {name} -->");
        let j = rest[head_end..]
            .find(&end_marker)
            .unwrap_or_else(|| panic!("{}: no {end_marker}", file.display()))
            + head_end;
        let body = generate(&name)
            .unwrap_or_else(|| panic!("{}: unknown generated block '{name}'", file.display()));
        out += &rest[..head_end];
        out += "\n";
        out += &body;
        rest = &rest[j..];
        names.push(name);
    }
    out += rest;
    (out, names)
}

#[test]
fn generated_tables_match_the_committed_reports() {
    let update = std::env::var_os("UPDATE_DOCS").is_some();
    let mut found = Vec::new();
    let mut stale = Vec::new();
    for f in markdown_files() {
        let text = std::fs::read_to_string(&f).unwrap();
        let (new, names) = refresh(&text, &f);
        found.extend(names);
        if new != text {
            if update {
                std::fs::write(&f, new).unwrap();
            } else {
                stale.push(f.strip_prefix(ROOT).unwrap().display().to_string());
            }
        }
    }
    for n in [
        "validation-table",
        "ochi-design-table",
        "ochi-comparisons",
        "summary-schema",
    ] {
        assert!(found.iter().any(|f| f == n), "no block '{n}' in the docs");
    }
    assert!(
        stale.is_empty(),
        "generated tables out of date with reports/ in {stale:?}: run \
         `UPDATE_DOCS=1 cargo test --release --test docs_tables` and commit the result"
    );
}

#[test]
fn troubleshooting_lists_every_exit_status() {
    let exit = std::fs::read_to_string(Path::new(ROOT).join("src/cli/exit.rs")).unwrap();
    let page =
        std::fs::read_to_string(Path::new(ROOT).join("docs/guide/troubleshooting.md")).unwrap();
    let codes: Vec<&str> = exit
        .lines()
        .filter(|l| l.contains(": u8 = "))
        .filter_map(|l| l.strip_prefix("pub const "))
        .filter_map(|l| l.split("= ").nth(1))
        .map(|l| l.trim_end_matches(';'))
        .collect();
    assert_eq!(codes.len(), 7, "{codes:?}");
    for c in codes {
        assert!(
            page.lines().any(|l| l.starts_with(&format!("| {c} |"))),
            "troubleshooting.md has no row for exit status {c}"
        );
    }
}
