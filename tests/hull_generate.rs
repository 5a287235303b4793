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

// Journée (1992), Delft Ship Hydromechanics Laboratory report 0909, model III (as transcribed in
// /work/shared/reference/journee1992_wigley3.toml): L 3.0 m, B 0.3 m, T 0.1875 m, volume 0.0780 m³,
// waterplane area 0.6240 m², Cb 0.4622, KG 0.170 m, k_yy 0.75 m, fresh water.
const WIGLEY_VOLUME_M3: f64 = 0.0780;
const WIGLEY_AWP_M2: f64 = 0.6240;
const WIGLEY_CB: f64 = 0.4622;

#[test]
fn wigley_iii_reproduces_the_published_hydrostatics() {
    let hull = hull_of(GeneratedHull::WigleyIii);
    let l = hull.loading(None).unwrap();
    let h = Hydrostatics::compute(&hull, l);
    assert_within("Wigley III volume", h.volume, WIGLEY_VOLUME_M3, 0.005);
    assert_within("Wigley III waterplane area", h.awp, WIGLEY_AWP_M2, 0.005);
    assert_within("Wigley III Cb", h.cb, WIGLEY_CB, 0.005);
    assert_within("Wigley III beam", h.beam_wl_m, 0.3, 1e-6);
    assert_eq!(hull.lpp, 3.0);
    assert_eq!((l.draft_fp, l.draft_ap), (0.1875, 0.1875));
    assert_eq!((l.rho, l.kg, l.k_yy), (1000.0, 0.17, 0.75));
    assert!(h.lcb.abs() < 1e-9, "symmetric hull: LCB {}", h.lcb);
    assert!(hull.depth > 0.1875);
}

// Ochi (1958), Trans. SNAME 66: 345-383, as reported in Veen (2010), Table 6.1
// (/work/shared/reference/ochi1958_vform.toml): Lpp 6.0 m, beam 0.83 m, max draft 0.36 m, displacement
// 1334 kg, Cb 0.74, Cp 0.75, Cm 0.99, Cwp 0.83. Test condition: draft 0.20 m, trim by stern 0.08 m.
// Instrumented sections at 0.093, 0.133, 0.174, 0.227 Lpp aft of FP; sensor diameter 0.02 m.
const OCHI_LPP: f64 = 6.0;
const OCHI_BEAM: f64 = 0.83;
const OCHI_DRAFT_MAX: f64 = 0.36;
const OCHI_DISPLACEMENT_KG: f64 = 1334.0;
const OCHI_CB: f64 = 0.74;
const OCHI_CP: f64 = 0.75;
const OCHI_CM: f64 = 0.99;
const OCHI_CWP: f64 = 0.83;
const OCHI_TOL: f64 = 0.025;

#[test]
fn ochi_vform_matches_the_published_particulars() {
    let hull = hull_of(GeneratedHull::OchiVform);
    let max = hull.loading(Some("max-draft")).unwrap();
    let h = Hydrostatics::compute(&hull, max);
    assert_within("Ochi Lpp", hull.lpp, OCHI_LPP, OCHI_TOL);
    assert_within("Ochi beam", h.beam_wl_m, OCHI_BEAM, OCHI_TOL);
    assert_within("Ochi max draft", h.mean_draft_m, OCHI_DRAFT_MAX, OCHI_TOL);
    assert_within(
        "Ochi displacement (buoyancy at max draft)",
        h.displacement_kg,
        OCHI_DISPLACEMENT_KG,
        OCHI_TOL,
    );
    assert_within("Ochi Cb", h.cb, OCHI_CB, OCHI_TOL);
    assert_within("Ochi Cp", h.cp, OCHI_CP, OCHI_TOL);
    assert_within("Ochi Cm", h.cm, OCHI_CM, OCHI_TOL);
    assert_within("Ochi Cwp", h.cwp, OCHI_CWP, OCHI_TOL);
    // The given mass equals the buoyancy of the offsets (a loading in equilibrium).
    let m = h.mass_properties(max);
    assert!(m.mass_buoyancy_mismatch.abs() < 0.005, "{m:?}");
    assert!(m.lcg_from_lcb);
    assert_within("Ochi k_yy", m.k_yy_m, 0.25 * OCHI_LPP, 1e-9);
}

#[test]
fn ochi_vform_test_condition_and_v_sections_forward() {
    let hull = hull_of(GeneratedHull::OchiVform);
    let test = hull.loading(None).unwrap();
    assert_eq!(test.name, "test-condition");
    assert!((test.mean_draft() - 0.20).abs() < 1e-9);
    assert!((test.trim_by_stern() - 0.08).abs() < 1e-9);
    assert_eq!(test.displacement_kg, None);
    // V-shaped sections forward: area coefficient A/(2 b T) at the max draft below 0.65 at 0.1 Lpp.
    for f in [0.05, 0.1] {
        let s = hull.section_at(hull.station_x(f)).unwrap();
        let p = s.properties(OCHI_DRAFT_MAX);
        let sigma = p.area / (2.0 * p.half_breadth * OCHI_DRAFT_MAX);
        assert!(
            sigma < 0.65,
            "section at {f} Lpp aft of FP: sigma {sigma:.3}"
        );
        assert!(
            sigma > 0.45,
            "section at {f} Lpp aft of FP: sigma {sigma:.3}"
        );
    }
    // Four sensors on each instrumented section, below the test-condition waterline.
    assert_eq!(hull.sensors.len(), 16);
    for (k, f) in [0.093, 0.133, 0.174, 0.227].iter().enumerate() {
        let on: Vec<_> = hull
            .sensors
            .iter()
            .filter(|s| (s.x - hull.station_x(*f)).abs() < 1e-9)
            .collect();
        assert_eq!(on.len(), 4, "section {k}");
        let t = test.draft_at(hull.station_x(*f), hull.lpp);
        for s in on {
            assert_eq!(s.diameter, 0.02);
            assert!(s.position[1] < t, "{} above the waterline", s.name);
        }
    }
}

#[test]
fn ochi_fit_meets_its_constraints() {
    let form = ochi_vform::fitted_form().unwrap();
    assert!((form.cb() - ochi_vform::cb_target()).abs() < 1e-6);
    assert!((form.cm() - OCHI_CM).abs() < 1e-6);
    assert!((form.cwp() - OCHI_CWP).abs() < 1e-6);
    for k in 0..=200 {
        let u = k as f64 / 200.0;
        assert!(form.beta(u) <= 1.0 + 1e-6 && form.beta(u) >= -1e-6);
        assert!(form.alpha(u) <= OCHI_CM + 1e-6);
        assert!(form.alpha(u) >= 0.5 * form.beta(u) - 1e-6);
    }
}

// Hermundstad & Moan (2005), as reported in Veen (2010), Section 6.2
// (/work/shared/reference/hermundstad2005_panel.toml): 120 m car carrier, scale 21.6; flared section at
// 0.05 Lpp aft of FP with model-scale beam 0.82 m; flare equivalent deadrise 37 deg; panel width 0.067 m.
#[test]
fn car_carrier_has_the_published_bow_section() {
    let hull = hull_of(GeneratedHull::CarCarrier);
    assert_within("car carrier Lpp", hull.lpp, 120.0 / 21.6, 1e-6);
    let x = hull.station_x(0.05);
    let s = hull.section_at(x).unwrap();
    assert_within(
        "beam at the deck, 0.05 Lpp",
        2.0 * s.max_half_breadth(),
        0.82,
        0.01,
    );
    let t = hull.loading(None).unwrap().draft_at(x, hull.lpp);
    let wl = [s.half_breadth_at(t), t];
    let deck = *s.points.last().unwrap();
    let chord_deg = (deck[1] - wl[1]).atan2(deck[0] - wl[0]).to_degrees();
    assert!(
        (chord_deg - 37.0).abs() < 1.0,
        "flare chord {chord_deg:.2} deg"
    );
    // The panel sits on the flare, above the waterline and below the deck.
    let p1 = hull
        .sensors
        .iter()
        .find(|s| s.name == "P1")
        .expect("panel P1");
    assert_eq!(p1.diameter, 0.067);
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

/// Compare two hull texts token by token; numbers may differ in the last written digit (platform
/// round-off in libm or the QP solver), anything else must be identical.
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
    for (i, (la, lb)) in a.iter().zip(&b).enumerate() {
        if la == lb {
            continue;
        }
        let (ta, tb) = (split(la), split(lb));
        let ok = ta.len() == tb.len()
            && ta.iter().zip(&tb).all(|(x, y)| {
                x == y
                    || match (x.parse::<f64>(), y.parse::<f64>()) {
                        // One unit in the last written digit, with a margin for the decimal parse.
                        (Ok(p), Ok(q)) => {
                            let last = 10f64.powi(-(decimals(x).max(decimals(y)) as i32));
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
    assert!(same_up_to_last_digit("a = 0.123456", "a = 0.123457").is_ok());
    assert!(same_up_to_last_digit("a = 0.123456", "a = 0.123466").is_err());
    assert!(same_up_to_last_digit("Cb 0.7439,", "Cb 0.7440,").is_ok());
    assert!(same_up_to_last_digit("Cb 0.7439,", "Cb 0.7449,").is_err());
    assert!(same_up_to_last_digit("name = \"a\"", "name = \"b\"").is_err());
    assert!(same_up_to_last_digit("x\ny", "x").is_err());
}
