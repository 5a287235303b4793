//! The assessment report: `slamtool assess` writes report.pdf and figures/ (SVG + CSV twins) at the end;
//! `slamtool report` regenerates them from the saved results, byte for byte; the PDF is A4 with the
//! bundled font embedded; a non-finite history is refused with the figure and series named.
//!
//! Fixture: a screening assessment of one Ochi station at two speeds with a very coarse SPH run
//! (10 particles across the half-breadth, one resolution): a few seconds.

use std::path::Path;
use std::process::{Command, Output};

fn slamtool(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap()
}

fn assess(out: &Path) {
    let o = slamtool(&[
        "-q",
        "assess",
        "hulls/ochi-vform.toml",
        "--sea",
        "sea_states/ochi-1958.toml",
        "--station",
        "0.093",
        "--speeds",
        "2.0,2.4",
        "--particles-per-half-beam",
        "10",
        "--convergence-levels",
        "1",
        "-o",
        out.to_str().unwrap(),
    ]);
    assert!(
        o.status.success(),
        "{}\n{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
}

fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .flatten()
        .map(|e| e.file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

#[test]
fn assessment_report_is_a4_with_embedded_font_wellformed_svgs_and_reproducible() {
    let d = tempfile::tempdir().unwrap();
    let res = d.path().join("res");
    assess(&res);
    let pdf_path = res.join("report.pdf");
    let pdf = std::fs::read(&pdf_path).unwrap();
    let doc = lopdf::Document::load_mem(&pdf).expect("the PDF parses");
    let pages = doc.get_pages();
    // Title + one page per chapter at least: summary, hull, motions, impact, design space, comparison,
    // appendix each start a new page.
    assert!(pages.len() >= 8, "{} pages", pages.len());
    for (_, id) in pages.iter() {
        let page = doc.get_object(*id).unwrap().as_dict().unwrap();
        let mb = page
            .get(b"MediaBox")
            .or_else(|_| {
                let parent = page.get(b"Parent").unwrap().as_reference().unwrap();
                doc.get_object(parent)
                    .unwrap()
                    .as_dict()
                    .unwrap()
                    .get(b"MediaBox")
            })
            .unwrap()
            .as_array()
            .unwrap();
        let num = |o: &lopdf::Object| {
            o.as_float()
                .map(f64::from)
                .or_else(|_| o.as_i64().map(|i| i as f64))
                .unwrap()
        };
        let (w, h) = (num(&mb[2]) - num(&mb[0]), num(&mb[3]) - num(&mb[1]));
        assert!(
            (w - 595.28).abs() < 1.0 && (h - 841.89).abs() < 1.0,
            "A4: {w} x {h}"
        );
    }
    // Every font is DejaVu Sans and embedded (a FontFile stream in its descriptor).
    let mut fonts = 0;
    for (_, obj) in doc.objects.iter() {
        let Ok(d) = obj.as_dict() else { continue };
        if d.get(b"Type").ok().and_then(|t| t.as_name().ok()) == Some(b"FontDescriptor") {
            fonts += 1;
            let name = String::from_utf8_lossy(d.get(b"FontName").unwrap().as_name().unwrap())
                .into_owned();
            assert!(name.contains("DejaVuSans"), "{name}");
            assert!(
                d.has(b"FontFile2") || d.has(b"FontFile3") || d.has(b"FontFile"),
                "{name} is not embedded"
            );
        }
    }
    assert!(fonts >= 1, "no font descriptor");
    // No date without --stamp.
    assert!(!String::from_utf8_lossy(&pdf).contains("/CreationDate"));

    // Figures: one SVG and one CSV twin each, well-formed, with axis labels and the sensors named.
    let figs = res.join("figures");
    let names = files_in(&figs);
    let svgs: Vec<&String> = names.iter().filter(|n| n.ends_with(".svg")).collect();
    assert!(svgs.len() >= 8, "{names:?}");
    for s in &svgs {
        let text = std::fs::read_to_string(figs.join(s)).unwrap();
        let xml = roxmltree::Document::parse(&text).unwrap_or_else(|e| panic!("{s}: {e}"));
        assert_eq!(xml.root_element().tag_name().name(), "svg");
        assert!(
            names.contains(&s.replace(".svg", ".csv")),
            "{s} has no CSV twin"
        );
    }
    let vs_speed = svgs
        .iter()
        .find(|n| n.contains("peak_pressure_vs_speed"))
        .expect("peak pressure against speed");
    let text = std::fs::read_to_string(figs.join(vs_speed)).unwrap();
    let xml = roxmltree::Document::parse(&text).unwrap();
    let all: String = xml
        .descendants()
        .filter_map(|n| n.text())
        .collect::<Vec<_>>()
        .join("|");
    for want in [
        "peak pressure (kPa)",
        "speed U (m/s)",
        "S093-1 analytic",
        "SPH, convergence not assessed",
    ] {
        assert!(all.contains(want), "'{want}' not in {vs_speed}: {all}");
    }
    let history = names
        .iter()
        .find(|n| n.contains("pressure_history") && n.ends_with(".csv"))
        .expect("a pressure history");
    let csv = std::fs::read_to_string(figs.join(history)).unwrap();
    assert!(
        csv.contains("S093-2 raw,"),
        "{}",
        &csv[..200.min(csv.len())]
    );
    assert!(
        names
            .iter()
            .any(|n| n.starts_with("peak_pressure_") && n.ends_with(".png"))
    );

    // Regenerated from the saved results: byte-identical PDF and figures.
    let again = d.path().join("again");
    let o = slamtool(&[
        "-q",
        "report",
        res.to_str().unwrap(),
        "-o",
        again.to_str().unwrap(),
    ]);
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    assert!(
        std::fs::read(again.join("report.pdf")).unwrap() == pdf,
        "PDF differs"
    );
    assert_eq!(files_in(&again.join("figures")), names);
    for n in &names {
        assert!(
            std::fs::read(figs.join(n)).unwrap()
                == std::fs::read(again.join("figures").join(n)).unwrap(),
            "{n} differs"
        );
    }
    let timing = std::fs::read_to_string(again.join("report_time.json")).unwrap();
    let t: serde_json::Value = serde_json::from_str(&timing).unwrap();
    assert!(t["report_time_s"].as_f64().unwrap() > 0.0);

    // A non-finite sample in a saved history: the figure is refused, naming figure and series.
    let run = std::fs::read_dir(res.join("cache"))
        .unwrap()
        .flatten()
        .next()
        .unwrap()
        .path();
    let hist = std::fs::read_to_string(run.join("history.csv")).unwrap();
    let mut lines: Vec<String> = hist.lines().map(str::to_string).collect();
    let header = lines.iter().position(|l| l.starts_with("time_s")).unwrap();
    let col = lines[header]
        .split(',')
        .position(|c| c == "S093-3_pa")
        .unwrap();
    let mut cells: Vec<String> = lines[header + 5].split(',').map(str::to_string).collect();
    cells[col] = "NaN".into();
    lines[header + 5] = cells.join(",");
    std::fs::write(run.join("history.csv"), lines.join("\n") + "\n").unwrap();
    let bad = d.path().join("bad");
    let o = slamtool(&["report", res.to_str().unwrap(), "-o", bad.to_str().unwrap()]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(o.status.success(), "{err}");
    assert!(
        err.contains("pressure_history")
            && err.contains("'S093-3 raw'")
            && err.contains("non-finite"),
        "{err}"
    );
    assert!(
        !files_in(&bad.join("figures"))
            .iter()
            .any(|n| n.contains("pressure_history"))
    );
}

#[test]
fn report_of_a_folder_without_results_is_bad_input() {
    let d = tempfile::tempdir().unwrap();
    let o = slamtool(&["report", d.path().to_str().unwrap()]);
    assert_eq!(o.status.code(), Some(1));
    assert!(String::from_utf8_lossy(&o.stderr).contains("no summary.json"));
}
