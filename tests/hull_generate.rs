//! The generated hulls (hulls/*.toml): each parses, matches its published targets, and the committed file
//! is what its generator produces now.

use std::path::{Path, PathBuf};

use slamtool::hull::generate::{GeneratedHull, car_carrier, ochi_vform};
use slamtool::hull::{Hull, Hydrostatics};
use slamtool::input::SourceText;

fn hull_of(kind: GeneratedHull) -> Hull {
    let text = kind.toml().expect("generator runs");
    let src = SourceText::from_string(format!("hulls/{}", kind.file_name()), text);
    match Hull::from_source(&src) {
        Ok(h) => h,
        Err(e) => panic!("generated {} does not parse: {e}", kind.file_name()),
    }
}

fn rel(a: f64, b: f64) -> f64 {
    (a - b).abs() / b.abs()
}

fn assert_within(what: &str, got: f64, want: f64, tol: f64) {
    assert!(
        rel(got, want) <= tol,
        "{what}: got {got:.6}, published {want}, off by {:.3} % (allowed {:.1} %)",
        100.0 * rel(got, want),
        100.0 * tol
    );
}

/// A reference-data file from `data/reference/` (published numbers with their provenance headers).
fn reference(file: &str) -> toml::Table {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("data/reference")
        .join(file);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    text.parse()
        .unwrap_or_else(|e| panic!("{}: {e}", path.display()))
}

fn num(t: &toml::Table, table: &str, key: &str) -> f64 {
    let v = &t[table][key];
    v.as_float()
        .or_else(|| v.as_integer().map(|i| i as f64))
        .unwrap_or_else(|| panic!("[{table}] {key} is not a number"))
}

fn nums(t: &toml::Table, table: &str, key: &str) -> Vec<f64> {
    t[table][key]
        .as_array()
        .unwrap_or_else(|| panic!("[{table}] {key} is not an array"))
        .iter()
        .map(|v| v.as_float().expect("number"))
        .collect()
}

// Journée (1992), Delft Ship Hydromechanics Laboratory report 0909, model III:
// data/reference/journee1992_wigley3.toml.
#[test]
fn wigley_iii_reproduces_the_published_hydrostatics() {
    let r = reference("journee1992_wigley3.toml");
    let hull = hull_of(GeneratedHull::WigleyIii);
    let l = hull.loading(None).unwrap();
    let h = Hydrostatics::compute(&hull, l);
    assert_within(
        "Wigley III volume",
        h.volume,
        num(&r, "hull", "volume_m3"),
        0.005,
    );
    assert_within(
        "Wigley III waterplane area",
        h.awp,
        num(&r, "hull", "waterplane_area_m2"),
        0.005,
    );
    assert_within(
        "Wigley III Cb",
        h.cb,
        num(&r, "hull", "block_coefficient"),
        0.005,
    );
    assert_within(
        "Wigley III beam",
        h.beam_wl_m,
        num(&r, "hull", "beam_m"),
        1e-6,
    );
    assert_eq!(hull.lpp, num(&r, "hull", "length_m"));
    let t = num(&r, "hull", "draft_m");
    assert_eq!((l.draft_fp, l.draft_ap), (t, t));
    assert_eq!(l.rho, 1000.0, "fresh water");
    assert_eq!(l.kg, num(&r, "hull", "kg_m"));
    assert_eq!(l.k_yy, num(&r, "hull", "k_yy_m"));
    assert!(h.lcb.abs() < 1e-9, "symmetric hull: LCB {}", h.lcb);
    assert!(hull.depth > t);
    // The published spot offsets on the waterline.
    for o in r["hull"]["offsets"].as_array().unwrap() {
        let xi = o["xi"].as_float().unwrap();
        let zeta = o["zeta"].as_float().unwrap();
        let y = o["half_breadth_m"].as_float().unwrap();
        let x = 0.5 * hull.lpp * xi;
        let got = hull
            .section_at(x)
            .unwrap()
            .half_breadth_at(t * (1.0 + zeta));
        assert!(
            (got - y).abs() < 1e-4,
            "half-breadth at xi {xi}, zeta {zeta}: {got:.5} m, published {y} m"
        );
    }
}

// Ochi (1958), Trans. SNAME 66: 345-383, as reported in Veen (2010), Table 6.1:
// data/reference/ochi1958_vform.toml. Tolerance of the issue: 2.5 % on each particular.
const OCHI_TOL: f64 = 0.025;

#[test]
fn ochi_vform_matches_the_published_particulars() {
    let r = reference("ochi1958_vform.toml");
    let hull = hull_of(GeneratedHull::OchiVform);
    let max = hull.loading(Some("max-draft")).unwrap();
    let h = Hydrostatics::compute(&hull, max);
    let m = |k: &str| num(&r, "model", k);
    assert_within("Ochi Lpp", hull.lpp, m("lpp_m"), OCHI_TOL);
    assert_within("Ochi beam", h.beam_wl_m, m("beam_m"), OCHI_TOL);
    assert_within("Ochi max draft", h.mean_draft_m, m("draft_max_m"), OCHI_TOL);
    assert_within(
        "Ochi displacement (buoyancy at max draft, fresh water)",
        h.displacement_kg,
        m("displacement_kg"),
        OCHI_TOL,
    );
    assert_within("Ochi Cb", h.cb, m("block_coefficient"), OCHI_TOL);
    assert_within("Ochi Cp", h.cp, m("prismatic_coefficient"), OCHI_TOL);
    assert_within("Ochi Cm", h.cm, m("midship_coefficient"), OCHI_TOL);
    assert_within("Ochi Cwp", h.cwp, m("waterplane_coefficient"), OCHI_TOL);
    // The given mass equals the buoyancy of the offsets (a loading in equilibrium).
    let mp = h.mass_properties(max);
    assert_eq!(max.displacement_kg, Some(m("displacement_kg")));
    assert!(mp.mass_buoyancy_mismatch.abs() < 0.005, "{mp:?}");
    assert!(mp.lcg_from_lcb);
    assert_within("Ochi k_yy", mp.k_yy_m, 0.25 * m("lpp_m"), 1e-9);
}

#[test]
fn ochi_vform_test_condition_and_v_sections_forward() {
    let r = reference("ochi1958_vform.toml");
    let hull = hull_of(GeneratedHull::OchiVform);
    let test = hull.loading(None).unwrap();
    assert_eq!(test.name, "test-condition");
    assert!((test.mean_draft() - num(&r, "test_condition", "draft_m")).abs() < 1e-9);
    assert!((test.trim_by_stern() - num(&r, "test_condition", "trim_by_stern_m")).abs() < 1e-9);
    assert_eq!(test.displacement_kg, None);
    // V-shaped sections forward: area coefficient A/(2 b T) at the max draft below 0.65 at 0.1 Lpp.
    let t_max = num(&r, "model", "draft_max_m");
    for f in [0.05, 0.1] {
        let s = hull.section_at(hull.station_x(f)).unwrap();
        let p = s.properties(t_max);
        let sigma = p.area / (2.0 * p.half_breadth * t_max);
        assert!(
            sigma < 0.65,
            "section at {f} Lpp aft of FP: sigma {sigma:.3}"
        );
        assert!(
            sigma > 0.45,
            "section at {f} Lpp aft of FP: sigma {sigma:.3}"
        );
    }
    // V-sections forward (a V-form); Veen (2010) calls the section at 0.174 Lpp flat-bottomed.
    for (f, flat) in [(0.093, false), (0.133, false), (0.174, true)] {
        let s = hull.section_at(hull.station_x(f)).unwrap();
        let p = s.points[1];
        let has_flat = p[1] == s.points[0][1] && p[0] > 0.05;
        assert_eq!(
            has_flat,
            flat,
            "section at {f} Lpp aft of FP: {:?}",
            &s.points[..3]
        );
    }
    // Four sensors on each instrumented section, below the test-condition waterline.
    let stations = nums(&r, "instrumentation", "stations_aft_of_fp");
    let diameter = num(&r, "instrumentation", "sensor_diameter_m");
    assert_eq!(hull.sensors.len(), 4 * stations.len());
    for f in stations {
        let x = hull.station_x(f);
        let on: Vec<_> = hull
            .sensors
            .iter()
            .filter(|s| (s.x - x).abs() < 1e-9)
            .collect();
        assert_eq!(on.len(), 4, "section {f}");
        let t = test.draft_at(x, hull.lpp);
        for s in on {
            assert_eq!(s.diameter, diameter);
            assert!(s.position[1] < t, "{} above the waterline", s.name);
        }
    }
}

#[test]
fn ochi_fit_meets_its_constraints() {
    let form = ochi_vform::fitted_form().unwrap();
    assert!((form.cb() - ochi_vform::cb_target()).abs() < 1e-6);
    assert!((form.cm() - ochi_vform::CM).abs() < 1e-6);
    assert!((form.cwp() - ochi_vform::CWP).abs() < 1e-6);
    for k in 0..=200 {
        let u = k as f64 / 200.0;
        assert!(form.beta(u) <= 1.0 + 1e-6 && form.beta(u) >= -1e-6);
        assert!(form.alpha(u) <= ochi_vform::CM + 1e-6);
        assert!(form.alpha(u) >= 0.5 * form.beta(u) - 1e-6);
    }
}

// Hermundstad & Moan (2005), as reported in Veen (2010), Section 6.2:
// data/reference/hermundstad2005_panel.toml ("car carrier, 120 m full scale", scale 21.6, flared section at
// 0.05 Lpp aft of FP with model-scale beam 0.82 m, flare equivalent deadrise 37 deg, panel width 0.067 m).
const HM2005_LPP_FULL_M: f64 = 120.0;

#[test]
fn car_carrier_has_the_published_bow_section() {
    let r = reference("hermundstad2005_panel.toml");
    let hull = hull_of(GeneratedHull::CarCarrier);
    let scale = num(&r, "model", "scale");
    assert_within("car carrier Lpp", hull.lpp, HM2005_LPP_FULL_M / scale, 1e-6);
    let x = hull.station_x(num(&r, "model", "section_aft_of_fp_fraction"));
    let s = hull.section_at(x).unwrap();
    assert_within(
        "beam at the deck, 0.05 Lpp",
        2.0 * s.max_half_breadth(),
        num(&r, "model", "section_beam_m"),
        0.01,
    );
    let t = hull.loading(None).unwrap().draft_at(x, hull.lpp);
    let wl = [s.half_breadth_at(t), t];
    let deck = *s.points.last().unwrap();
    let chord_deg = (deck[1] - wl[1]).atan2(deck[0] - wl[0]).to_degrees();
    let quoted = num(&r, "reported_comparisons", "flare_equivalent_deadrise_deg");
    assert!(
        (chord_deg - quoted).abs() < 1.0,
        "flare chord {chord_deg:.2} deg"
    );
    // The panel sits on the flare, above the waterline and below the deck.
    let p1 = hull
        .sensors
        .iter()
        .find(|s| s.name == "P1")
        .expect("panel P1");
    assert_eq!(p1.diameter, num(&r, "model", "panel_width_m"));
    assert!((p1.x - x).abs() < 1e-9);
    assert!(p1.position[1] > t && p1.position[1] < deck[1]);
    // Bulb: forward sections are wider low down than just below the waterline (a neck above the bulb).
    let fwd = hull.section_at(hull.station_x(0.025)).unwrap();
    let bulb = (1..40)
        .map(|k| fwd.half_breadth_at(0.6 * t * k as f64 / 40.0))
        .fold(0.0, f64::max);
    let neck = fwd.half_breadth_at(0.8 * t);
    assert!(bulb > 1.3 * neck, "bulb {bulb:.4} m vs neck {neck:.4} m");
    let h = Hydrostatics::compute(&hull, hull.loading(None).unwrap());
    assert!(
        (0.55..0.70).contains(&h.cb),
        "Cb {:.3} implausible for a car carrier",
        h.cb
    );
    assert!((h.cb - car_carrier::block_coefficient_of_curves()).abs() < 0.02);
}

/// Compare two hull texts token by token. Numbers may differ by one unit in their last digit (platform
/// round-off in libm or the QP solver could flip a rounding): the data values are written to 1e-6 with
/// trailing zeros dropped, so they may differ by 1e-6; numbers in the description are written with a
/// fixed number of decimals, so they may differ by one unit in that decimal. Integers (counts), words and
/// everything else must be identical.
fn same_up_to_last_digit(committed: &str, generated: &str) -> Result<(), String> {
    let (a, b): (Vec<&str>, Vec<&str>) = (committed.lines().collect(), generated.lines().collect());
    if a.len() != b.len() {
        return Err(format!(
            "{} lines committed, {} generated",
            a.len(),
            b.len()
        ));
    }
    let split = |l: &str| -> Vec<String> {
        l.split(|c: char| c.is_whitespace() || ",[]=\"()".contains(c))
            .filter(|t| !t.is_empty())
            .map(|t| t.trim_end_matches(['.', ';', ':']).to_string())
            .collect()
    };
    let mut in_description = false;
    for (i, (la, lb)) in a.iter().zip(&b).enumerate() {
        let starts = la.starts_with("description = \"\"\"");
        if la.trim_end() == "\"\"\"" {
            in_description = false;
        }
        if la != lb {
            let (ta, tb) = (split(la), split(lb));
            let ok = ta.len() == tb.len()
                && ta.iter().zip(&tb).all(|(x, y)| {
                    if x == y {
                        return true;
                    }
                    let (dx, dy) = (decimals(x), decimals(y));
                    match (x.parse::<f64>(), y.parse::<f64>()) {
                        (Ok(p), Ok(q)) if dx > 0 && dy > 0 => {
                            let last = if in_description && dx == dy {
                                10f64.powi(-(dx as i32))
                            } else {
                                1e-6
                            };
                            (p - q).abs() <= 1.5 * last
                        }
                        _ => false,
                    }
                });
            if !ok {
                return Err(format!(
                    "line {}:\n  committed: {la}\n  generated: {lb}",
                    i + 1
                ));
            }
        }
        if starts {
            in_description = true;
        }
    }
    Ok(())
}

fn decimals(t: &str) -> usize {
    t.split_once('.').map_or(0, |(_, d)| d.len())
}

#[test]
fn committed_hulls_equal_their_generators() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("hulls");
    for kind in GeneratedHull::ALL {
        let path: PathBuf = dir.join(kind.file_name());
        let committed =
            std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        let generated = kind.toml().unwrap();
        if let Err(d) = same_up_to_last_digit(&committed, &generated) {
            panic!(
                "{} differs from its generator at {d}\nregenerate with: slamtool hull generate {} -o hulls/{}",
                path.display(),
                kind.cli_name(),
                kind.file_name()
            );
        }
        // And the committed file itself is a valid hull.
        Hull::from_file(&path).unwrap_or_else(|e| panic!("{e}"));
    }
}

#[test]
fn cli_writes_the_same_text() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("w.toml");
    let status = std::process::Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(["hull", "generate", "wigley-iii", "-o"])
        .arg(&out)
        .status()
        .unwrap();
    assert!(status.success());
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(text, GeneratedHull::WigleyIii.toml().unwrap());
}

#[test]
fn comparison_catches_real_differences() {
    let data = |v: &str| format!("name = \"x\"\npoints = [[0.0, {v}]]\n");
    let desc = |v: &str| format!("description = \"\"\"\nCb {v},\n\"\"\"\n");
    assert!(same_up_to_last_digit(&data("0.123456"), &data("0.123457")).is_ok());
    assert!(same_up_to_last_digit(&data("0.5"), &data("0.500001")).is_ok());
    assert!(same_up_to_last_digit(&data("0.123456"), &data("0.123466")).is_err());
    assert!(same_up_to_last_digit(&data("0.5"), &data("0.51")).is_err());
    assert!(same_up_to_last_digit(&data("0.5"), &data("0.6")).is_err());
    assert!(same_up_to_last_digit(&desc("0.7439"), &desc("0.7440")).is_ok());
    assert!(same_up_to_last_digit(&desc("0.7439"), &desc("0.7449")).is_err());
    assert!(same_up_to_last_digit(&desc("45"), &desc("46")).is_err());
    assert!(same_up_to_last_digit("name = \"a\"", "name = \"b\"").is_err());
    assert!(same_up_to_last_digit("x\ny", "x").is_err());
}
