//! `hull plot`: the body plan SVG of a bundled hull has every section, the waterlines and the sensors,
//! sets its text in the bundled font, and the command writes it.

use std::path::Path;
use std::process::Command;

use slamtool::hull::Hull;
use slamtool::hull::body_plan::body_plan_svg;

#[test]
fn ochi_body_plan_has_sections_waterlines_and_sensors() {
    let hull = Hull::from_file(Path::new("hulls/ochi-vform.toml")).unwrap();
    let svg = body_plan_svg(&hull).unwrap();
    assert!(svg.starts_with("<svg"), "{}", &svg[..80]);
    assert!(svg.trim_end().ends_with("</svg>"));
    assert!(svg.contains("font-family=\"DejaVu Sans\""));
    // One polyline per section and side (midship on both), plus the axes' own lines.
    let polylines = svg.matches("<polyline").count();
    assert!(polylines >= hull.stations.len(), "{polylines} polylines");
    // each sensor named once, in the callout column (a text element of its own)
    for s in &hull.sensors {
        assert_eq!(
            svg.matches(&format!("\n {}\n", s.name)).count(),
            1,
            "sensor {}",
            s.name
        );
    }
    for l in &hull.loadings {
        assert!(svg.contains(&format!("waterline {}: T", l.name)));
    }
}

#[test]
fn cli_writes_the_svg() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("body.svg");
    let status = Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(["hull", "plot", "hulls/wigley-iii.toml", "-o"])
        .arg(&out)
        .status()
        .unwrap();
    assert!(status.success());
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.contains("Wigley III"));
}
