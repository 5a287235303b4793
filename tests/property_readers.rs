//! Property tests of every reader of user files (issue 27, item 7): for generated and mutated inputs the
//! readers never panic, and every rejection is an error with a message (located as `file:line:column`
//! where the format has lines). Accepted inputs give finite results.
//!
//! What is generated (proptest, stable Rust, a fixed number of cases per property so that the whole file
//! runs in a few seconds in CI; no failure files are written):
//!
//! * hull files from a template with every number drawn from ordinary and awkward values (`nan`, `inf`,
//!   `-0.0`, `1e308`, negative, huge), random station lists and contours (zig-zags, repeats, folds);
//! * valid hull and sea-state files with random single-character edits (delete, insert, replace);
//! * sea-state files from a template with drawn numbers;
//! * `entry case` files: wedge or point sections, constant or tabulated motions, drawn numbers;
//! * offsets CSV files referenced by a hull file, with drawn cells (numbers, blanks, text, extra fields);
//! * STL files: random bytes, binary STL with a random triangle count and coordinates (truncated or not),
//!   and ASCII STL with random tokens;
//! * lines-plan grids for `hull import`, with drawn cells.

use proptest::prelude::*;
use proptest::test_runner::Config;

use slamtool::hull::import::{ImportOptions, import, read_stl};
use slamtool::hull::{Hull, Hydrostatics};
use slamtool::input::SourceText;
use slamtool::sea::SeaState;

mod common;
use common::BOX_HULL;

/// Cases per property: enough to reach the awkward corners the strategies aim at, few enough for CI.
const CASES: u32 = 256;

fn config() -> Config {
    Config {
        cases: CASES,
        failure_persistence: None,
        ..Config::default()
    }
}

/// A number as TOML text: ordinary values and the awkward ones a careless or hostile file holds.
fn number() -> impl Strategy<Value = String> {
    prop_oneof![
        4 => (-20.0f64..20.0).prop_map(|v| format!("{v:.3}")),
        1 => (0u32..5).prop_map(|v| v.to_string()),
        1 => prop::sample::select(vec![
            "nan", "-nan", "inf", "-inf", "-0.0", "0.0", "1e308", "-1e308", "1e-308", "1e6", "1e12",
        ])
        .prop_map(str::to_string),
    ]
}

/// A contour `[[y, z], ...]` of drawn numbers.
fn contour() -> impl Strategy<Value = String> {
    prop::collection::vec((number(), number()), 0..7).prop_map(|pts| {
        let inner: Vec<String> = pts.iter().map(|(y, z)| format!("[{y}, {z}]")).collect();
        format!("[{}]", inner.join(", "))
    })
}

/// Accepted or refused with a message at a place in `file`: never a panic, never a silent NaN.
fn check_hull(text: &str) -> Result<(), TestCaseError> {
    match Hull::from_source(&SourceText::from_string("h.toml", text)) {
        Ok(h) => {
            for l in &h.loadings {
                let hs = Hydrostatics::compute(&h, l);
                prop_assert!(
                    hs.volume.is_finite() && hs.volume > 0.0 && hs.cb.is_finite(),
                    "{hs:?}\n{text}"
                );
            }
            let (a, f) = h.x_range();
            for i in 0..=8 {
                let x = a + (f - a) * f64::from(i) / 8.0;
                let s = h.section_at(x).unwrap();
                prop_assert!(s.points.iter().flatten().all(|v| v.is_finite()));
            }
        }
        Err(e) => {
            let m = e.to_string();
            prop_assert!(m.starts_with("h.toml:") && m.len() > 12, "{m}\n{text}");
        }
    }
    Ok(())
}

/// One edit of `base`: delete, insert or replace the character at a drawn position.
fn edited(base: &'static str) -> impl Strategy<Value = String> {
    let chars: Vec<char> = base.chars().collect();
    let n = chars.len();
    (
        0..n,
        0u8..3,
        prop::sample::select(vec![
            '[', ']', '"', '=', '\n', '#', '-', '.', 'e', '0', ',', '\u{0}',
        ]),
    )
        .prop_map(move |(i, op, c)| {
            let mut v = chars.clone();
            match op {
                0 => {
                    v.remove(i);
                }
                1 => v.insert(i, c),
                _ => v[i] = c,
            }
            v.into_iter().collect()
        })
}

const SEA: &str = "name = \"s\"\nspeeds_m_s = [1.0, 2.0]\n\n[[regular]]\nheight_m = 0.2\nperiod_s = 2.0\n\n\
[[irregular]]\nspectrum = \"jonswap\"\nhs_m = 3.0\ntp_s = 9.0\n";

fn check_sea(text: &str) -> Result<(), TestCaseError> {
    match SeaState::from_source(&SourceText::from_string("s.toml", text)) {
        Ok(s) => {
            for w in &s.regular {
                prop_assert!(w.omega.is_finite() && w.wavelength_m.is_finite(), "{text}");
            }
            for i in &s.irregular {
                prop_assert!(i.spectrum.summary().m0.is_finite(), "{text}");
            }
        }
        Err(e) => {
            let m = e.to_string();
            prop_assert!(m.starts_with("s.toml:") && m.len() > 12, "{m}\n{text}");
        }
    }
    Ok(())
}

fn check_case(text: &str) -> Result<(), TestCaseError> {
    match slamtool::sph::case_file::from_source(&SourceText::from_string("c.toml", text)) {
        Ok(s) => prop_assert!(
            s.dp.is_finite() && s.dp > 0.0 && s.t_end.is_finite() && s.c0.is_finite(),
            "{text}"
        ),
        Err(e) => prop_assert!(!e.to_string().trim().is_empty(), "{text}"),
    }
    Ok(())
}

/// `hull import` options: a draft of 0.5 m, everything else defaulted.
fn import_options(stations: Option<usize>) -> ImportOptions {
    ImportOptions {
        name: None,
        lpp: None,
        ap_x: None,
        draft: 0.5,
        kg: None,
        k_yy_over_lpp: None,
        rho: None,
        stations,
    }
}

/// Any error of a file reader has a message.
fn has_message<T>(r: slamtool::Result<T>) -> Result<(), TestCaseError> {
    if let Err(e) = r {
        prop_assert!(e.to_string().len() > 5, "{e}");
    }
    Ok(())
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn hull_files_from_drawn_numbers(
        lpp in number(),
        draft in number(),
        kg in number(),
        stations in prop::collection::vec((number(), contour()), 0..5),
        sensor in prop::option::of((number(), number())),
    ) {
        let mut t = format!(
            "name = \"p\"\nlpp_m = {lpp}\n\n[[loading]]\nname = \"d\"\ndraft_fp_m = {draft}\ndraft_ap_m = {draft}\n\
             kg_m = {kg}\nk_yy_over_lpp = 0.25\n"
        );
        for (x, pts) in &stations {
            t += &format!("\n[[station]]\nx_m = {x}\npoints = {pts}\n");
        }
        if let Some((x, g)) = sensor {
            t += &format!("\n[[sensor]]\nname = \"s\"\nx_m = {x}\ngirth_m = {g}\ndiameter_m = 0.01\n");
        }
        check_hull(&t)?;
    }

    #[test]
    fn valid_hull_with_one_edit(t in edited(BOX_HULL)) {
        check_hull(&t)?;
    }

    #[test]
    fn valid_sea_with_one_edit(t in edited(SEA)) {
        check_sea(&t)?;
    }

    #[test]
    fn sea_files_from_drawn_numbers(
        speeds in prop::collection::vec(number(), 0..4),
        h in number(),
        p in number(),
        hs in number(),
        tp in number(),
        depth in prop::option::of(number()),
    ) {
        let depth = depth.map_or(String::new(), |d| format!("water_depth_m = {d}\n"));
        let t = format!(
            "name = \"s\"\n{depth}speeds_m_s = [{}]\n\n[[regular]]\nheight_m = {h}\nperiod_s = {p}\n\n\
             [[irregular]]\nspectrum = \"jonswap\"\nhs_m = {hs}\ntp_s = {tp}\n",
            speeds.join(", ")
        );
        check_sea(&t)?;
    }

    #[test]
    fn case_files_from_drawn_numbers(
        wedge in any::<bool>(),
        deadrise in number(),
        half_beam in number(),
        pts in contour(),
        table in prop::option::of(prop::collection::vec((number(), number()), 0..5)),
        speed in number(),
        ppb in prop::option::of(number()),
    ) {
        let section = if wedge {
            format!("wedge = {{ deadrise_deg = {deadrise}, half_beam_m = {half_beam} }}")
        } else {
            format!("points = {pts}")
        };
        let motion = match &table {
            Some(rows) => {
                let r: Vec<String> = rows.iter().map(|(t, v)| format!("[{t}, {v}]")).collect();
                format!("kind = \"prescribed\"\ntable = [{}]", r.join(", "))
            }
            None => format!("kind = \"constant\"\nspeed_m_s = {speed}"),
        };
        let res = ppb.map_or(String::new(), |n| format!("\n[resolution]\nparticles_per_half_beam = {n}\n"));
        check_case(&format!("name = \"c\"\n[section]\n{section}\n\n[motion]\n{motion}\n{res}"))?;
    }

    #[test]
    fn offsets_csv_with_drawn_cells(
        rows in prop::collection::vec(prop::collection::vec(
            prop_oneof![number(), Just(String::new()), Just("-".to_string()), Just("x".to_string())],
            1..5,
        ), 0..5),
        header in prop::collection::vec(number(), 1..4),
    ) {
        let dir = tempfile::tempdir().unwrap();
        let mut csv = format!("x_m,{}\n", header.join(","));
        for r in &rows {
            csv += &r.join(",");
            csv += "\n";
        }
        std::fs::write(dir.path().join("o.csv"), &csv).unwrap();
        let hull = "name = \"c\"\nlpp_m = 10.0\ndepth_m = 2.0\noffsets_csv = { file = \"o.csv\" }\n\n[[loading]]\n\
                    name = \"d\"\ndraft_fp_m = 1.0\ndraft_ap_m = 1.0\nkg_m = 1.0\nk_yy_m = 2.5\n";
        let path = dir.path().join("h.toml");
        std::fs::write(&path, hull).unwrap();
        match Hull::from_file(&path) {
            Ok(h) => {
                let hs = Hydrostatics::compute(&h, &h.loadings[0]);
                prop_assert!(hs.volume.is_finite(), "{csv}");
            }
            Err(e) => prop_assert!(e.to_string().contains(".csv:") || e.to_string().contains("h.toml:"), "{e}\n{csv}"),
        }
    }

    #[test]
    fn stl_random_bytes(bytes in prop::collection::vec(any::<u8>(), 0..600)) {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("r.stl");
        std::fs::write(&p, &bytes).unwrap();
        has_message(read_stl(&p))?;
    }

    #[test]
    fn stl_binary_with_drawn_count_and_coordinates(
        count in prop_oneof![0u32..8, Just(u32::MAX), Just(100_000_000)],
        triangles in prop::collection::vec(prop::array::uniform12(
            prop_oneof![-10.0f32..10.0, Just(f32::NAN), Just(f32::INFINITY), Just(0.0f32)]
        ), 0..8),
        cut in 0usize..60,
    ) {
        let mut bytes = vec![0u8; 80];
        bytes.extend(count.to_le_bytes());
        for t in &triangles {
            for v in t {
                bytes.extend(v.to_le_bytes());
            }
            bytes.extend([0u8, 0u8]);
        }
        bytes.truncate(bytes.len().saturating_sub(cut));
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("b.stl");
        std::fs::write(&p, &bytes).unwrap();
        has_message(read_stl(&p))?;
        has_message(import(&p, &import_options(None)))?;
    }

    #[test]
    fn stl_ascii_with_drawn_tokens(
        tokens in prop::collection::vec(prop_oneof![
            Just("facet normal 0 0 1".to_string()),
            Just("outer loop".to_string()),
            Just("endloop".to_string()),
            Just("endfacet".to_string()),
            (number(), number(), number()).prop_map(|(a, b, c)| format!("vertex {a} {b} {c}")),
            Just("vertex 1 2".to_string()),
        ], 0..20),
    ) {
        let text = format!("solid s\n{}\nendsolid s\n", tokens.join("\n"));
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("a.stl");
        std::fs::write(&p, &text).unwrap();
        has_message(read_stl(&p))?;
    }

    #[test]
    fn grid_import_with_drawn_cells(
        waterlines in prop::collection::vec(number(), 1..4),
        rows in prop::collection::vec((number(), prop::collection::vec(
            prop_oneof![number(), Just(String::new())], 1..4)), 0..5),
        stations in prop::option::of(0usize..8),
    ) {
        let mut csv = format!("x_m,{}\n", waterlines.join(","));
        for (x, cells) in &rows {
            csv += &format!("{x},{}\n", cells.join(","));
        }
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("g.csv");
        std::fs::write(&p, &csv).unwrap();
        has_message(import(&p, &import_options(stations)))?;
    }
}
