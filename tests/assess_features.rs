//! `slamtool assess` beyond the events: default sensor panels, the `[limits]` table, the total bow
//! slamming force, the comparisons with published results (Hermundstad & Moan 2005; Ochi 1958 and Veen
//! 2010) and the design events of irregular seas. All at the analytic fidelity (seconds).

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

use slamtool::assess::{self, Assessment, Fidelity, Settings};
use slamtool::hull::Hull;
use slamtool::progress::ProgressHandle;
use slamtool::sea::SeaState;

fn data(rel: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join(rel)
}

fn slamtool(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_slamtool"))
        .args(args)
        .current_dir(env!("CARGO_MANIFEST_DIR"))
        .output()
        .unwrap()
}

fn analytic(hull: &str, sea: &str, stations: Vec<f64>, speeds: Option<Vec<f64>>) -> Assessment {
    let h = Hull::from_file(&data(hull)).unwrap();
    let s = SeaState::from_file(&data(sea)).unwrap();
    let d = tempfile::tempdir().unwrap();
    let settings = Settings {
        stations,
        speeds,
        fidelity: Fidelity::Analytic,
        ..Settings::default()
    };
    assess::run(&h, &s, &settings, d.path(), &ProgressHandle::default())
        .unwrap()
        .0
}

fn reference(table: &str, key: &str) -> f64 {
    let text = std::fs::read_to_string(data("data/reference/hermundstad2005_panel.toml")).unwrap();
    let v: toml::Value = toml::from_str(&text).unwrap();
    v[table][key].as_float().unwrap()
}

#[test]
fn a_station_without_sensors_gets_panels_every_5_percent_of_the_girth_to_the_deck_edge() {
    let h = Hull::from_file(&data("hulls/ochi-vform.toml")).unwrap();
    let sea = SeaState::from_file(&data("sea_states/ochi-1958.toml")).unwrap();
    let f = 1.0 / 12.0; // 0.5 m aft of the FP: no sensors there
    let s = Settings {
        stations: vec![f],
        speeds: Some(vec![2.0]),
        ..Settings::default()
    };
    let plan = assess::plan::plan(&h, &sea, &s).unwrap();
    let q = &plan.sensors[0];
    assert!(q.default);
    let sec = h.section_at(h.station_x(f)).unwrap();
    let z_w = h.loadings[0].draft_at(h.station_x(f), h.lpp);
    let g_wl = slamtool::impact::default_sensors::girth_to_height(&sec.points, z_w);
    assert_eq!(q.sensors[0].name, "G05");
    assert_eq!(q.sensors[1].name, "G10");
    let wl = q
        .sensors
        .iter()
        .find(|s| s.name == "G100")
        .expect("a panel at the waterline");
    assert!((wl.s_m - g_wl).abs() < 1e-9, "{} vs {g_wl}", wl.s_m);
    for (k, s) in q.sensors.iter().enumerate() {
        assert!((s.s_m - 0.05 * (k + 1) as f64 * g_wl).abs() < 1e-9);
        assert!((s.width_m - 0.05 * g_wl).abs() < 1e-12);
    }
    let last = q.sensors.last().unwrap();
    assert!(
        last.s_m + 0.5 * last.width_m <= sec.girth() + 1e-9,
        "on the contour"
    );
    assert!(
        last.s_m + 1.5 * last.width_m > sec.girth(),
        "up to the deck edge: the next panel would not fit"
    );
    assert!(
        plan.warnings
            .iter()
            .any(|w| w.contains("default panels G05..")),
        "{:?}",
        plan.warnings
    );
    // Events at that station carry the default panels.
    let e = plan.events.iter().find(|e| e.entry.is_some()).unwrap();
    assert_eq!(e.entry.as_ref().unwrap().sensors.len(), q.sensors.len());
}

#[test]
fn a_dry_bow_station_is_assessed_from_the_water_reaching_its_keel() {
    // The synthetic patrol boat's keel rises to the stem: at 0.05 Lpp it is above the calm waterline.
    let h = Hull::from_file(&data("tests/data/hard-chine-patrol.toml")).unwrap();
    let sea = SeaState::from_file(&data("tests/data/north-sea-hs2.5.toml")).unwrap();
    let f = 0.05;
    let x = h.station_x(f);
    let clearance = h.section_at(x).unwrap().keel_z() - h.loadings[0].draft_at(x, h.lpp);
    assert!(clearance > 0.1, "the test needs a dry station: {clearance}");
    let s = Settings {
        stations: vec![f],
        speeds: Some(vec![9.26]),
        fidelity: Fidelity::Analytic,
        ..Settings::default()
    };
    let plan = assess::plan::plan(&h, &sea, &s).unwrap();
    // its panels divide the keel-to-deck girth (D05..D95), and a warning says what a dry station's event is
    let q = &plan.sensors[0];
    assert!(q.default);
    assert_eq!(q.sensors.first().unwrap().name, "D05");
    assert_eq!(q.sensors.last().unwrap().name, "D95");
    let girth = h.section_at(x).unwrap().girth();
    assert!((q.sensors[0].width_m - 0.05 * girth).abs() < 1e-9);
    assert!(
        plan.warnings.iter().any(|w| w.contains("is a dry station")
            && w.contains(&format!("{clearance:.3} m above the calm waterline"))),
        "{:?}",
        plan.warnings
    );
    // the regular design wave wets the keel, with the draft negative in the event
    let e = plan.events.iter().find(|e| e.entry.is_some()).unwrap();
    assert!((e.draft_m + clearance).abs() < 1e-9, "{}", e.draft_m);
    assert!(e.entry_velocity_m_s.unwrap() > 0.0);
    // and the analytic assessment gives every panel below the chine a design pressure
    let a = analytic(
        "tests/data/hard-chine-patrol.toml",
        "tests/data/north-sea-hs2.5.toml",
        vec![f],
        Some(vec![9.26]),
    );
    let st = &a.stations[0];
    assert!(st.emerging_events > 0);
    assert!(
        st.design_pressure_pa[..5]
            .iter()
            .all(|d| d.value.is_some_and(|v| v.is_finite() && v > 0.0)),
        "{:?}",
        st.design_pressure_pa
    );
}

#[test]
fn panels_above_a_chine_are_named_in_a_warning() {
    // The patrol boat's station 0.1 Lpp has a 30 deg chine; its default panels run up to the deck.
    let h = Hull::from_file(&data("tests/data/hard-chine-patrol.toml")).unwrap();
    let sea = SeaState::from_file(&data("tests/data/north-sea-hs2.5.toml")).unwrap();
    let at = |f: f64| Settings {
        stations: vec![f],
        speeds: Some(vec![9.26]),
        fidelity: Fidelity::Analytic,
        ..Settings::default()
    };
    let plan = assess::plan::plan(&h, &sea, &at(0.1)).unwrap();
    let w: Vec<&String> = plan
        .warnings
        .iter()
        .filter(|w| w.contains("has a chine at girth"))
        .collect();
    assert_eq!(w.len(), 1, "{:?}", plan.warnings);
    let chine =
        slamtool::assess::chines::chines(&h.section_at(h.station_x(0.1)).unwrap().points)[0];
    assert!(
        w[0].contains(&format!("girth {:.3} m", chine.girth_m)),
        "{}",
        w[0]
    );
    let above = plan.sensors[0]
        .sensors
        .iter()
        .filter(|s| s.s_m + 0.5 * s.width_m > chine.girth_m)
        .count();
    // the panel that straddles the chine is among them
    assert!(plan.sensors[0].sensors.iter().any(
        |s| s.s_m - 0.5 * s.width_m < chine.girth_m && s.s_m + 0.5 * s.width_m > chine.girth_m
    ));
    assert!(w[0].contains(&format!("({above} panels,")), "{}", w[0]);
    // station 0.15 has its two sensors below the chine: no warning
    let plan = assess::plan::plan(&h, &sea, &at(0.15)).unwrap();
    assert!(!plan.warnings.iter().any(|w| w.contains("has a chine")));
    // nor has any station of the Ochi hull (smooth sections; the flat keels' edges are not chines)
    let ochi = Hull::from_file(&data("hulls/ochi-vform.toml")).unwrap();
    let osea = SeaState::from_file(&data("sea_states/ochi-1958.toml")).unwrap();
    let s = Settings {
        fidelity: Fidelity::Analytic,
        ..Settings::default()
    };
    let plan = assess::plan::plan(&ochi, &osea, &s).unwrap();
    assert!(!plan.warnings.iter().any(|w| w.contains("has a chine")));
}

fn hull_with_limits(dir: &Path, limits: &str) -> PathBuf {
    let text = std::fs::read_to_string(data("hulls/ochi-vform.toml")).unwrap();
    let p = dir.join("limited.toml");
    std::fs::write(&p, format!("{text}\n{limits}")).unwrap();
    p
}

#[test]
fn the_limits_table_gates_with_status_4_and_one_verdict_per_violation() {
    let d = tempfile::tempdir().unwrap();
    let hull = hull_with_limits(
        d.path(),
        "[limits]\npressure_kpa = 100.0\n\n[[limits.station]]\naft_of_fp = 0.093\npressure_kpa = 2.0\n\n\
         [[limits.sensor]]\nname = \"S133-1\"\npressure_kpa = 0.5\n",
    );
    let out = d.path().join("o");
    let o = slamtool(&[
        "assess",
        hull.to_str().unwrap(),
        "--sea",
        "sea_states/ochi-1958.toml",
        "--station",
        "0.093,0.133",
        "--speeds",
        "2.0",
        "--fidelity",
        "analytic",
        "-q",
        "-o",
        out.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(o.status.code(), Some(4), "{stdout}");
    let lines: Vec<&str> = stdout
        .lines()
        .filter(|l| l.starts_with("LIMIT EXCEEDED: "))
        .collect();
    // every sensor of 0.093 above 2 kPa, and S133-1 above 0.5 kPa; nothing above 100 kPa
    let summary: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("summary.json")).unwrap()).unwrap();
    let mut expected = 0;
    for st in summary["stations"].as_array().unwrap() {
        for p in st["design_pressure_pa"].as_array().unwrap() {
            let v = p["value"].as_f64().unwrap();
            let f = st["station"].as_f64().unwrap();
            expected += usize::from((f - 0.093).abs() < 1e-9 && v > 2000.0);
            expected += usize::from(p["name"] == "S133-1" && v > 500.0);
        }
    }
    assert!(expected > 0);
    assert_eq!(lines.len(), expected, "{lines:?}");
    assert_eq!(
        summary["limit_violations"].as_array().unwrap().len(),
        expected
    );
    assert!(
        lines
            .iter()
            .any(|l| l.contains("sensor S133-1") && l.contains("> 0.50 kPa"))
    );
    assert!(
        lines.iter().all(|l| l.contains("limited.toml:")),
        "each verdict names the limit's line: {lines:?}"
    );
}

#[test]
fn bad_limits_stations_and_seas_are_located_errors() {
    let d = tempfile::tempdir().unwrap();
    let run = |hull: &Path, extra: &[&str]| {
        let out = d.path().join("o");
        let args = [
            &[
                "assess",
                hull.to_str().unwrap(),
                "--sea",
                "sea_states/ochi-1958.toml",
                "--fidelity",
                "analytic",
                "-o",
                out.to_str().unwrap(),
            ][..],
            extra,
        ]
        .concat();
        slamtool(&args)
    };
    let text = std::fs::read_to_string(data("hulls/ochi-vform.toml")).unwrap();
    let line = text.lines().count() + 4; // after the appended "\n[limits]\n[[limits.sensor]]\n"
    let hull = hull_with_limits(
        d.path(),
        "[limits]\n[[limits.sensor]]\nname = \"S999-9\"\npressure_kpa = 10.0\n",
    );
    let o = run(&hull, &[]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains(&format!("limited.toml:{line}:8")), "{err}");
    assert!(err.contains("S999-9") && !err.contains("panicked"), "{err}");
    let hull = hull_with_limits(
        d.path(),
        "[limits]\n[[limits.station]]\naft_of_fp = 1.5\npressure_kpa = 10.0\n",
    );
    let o = run(&hull, &[]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(
        err.contains(&format!("limited.toml:{line}:13")) && err.contains("outside"),
        "{err}"
    );
    let o = run(&data("hulls/ochi-vform.toml"), &["--x-m", "10"]);
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(1), "{err}");
    assert!(err.contains("--x-m 10") && err.contains("outside"), "{err}");
}

#[test]
fn the_bow_force_is_the_trapezoid_of_the_section_forces() {
    let a = analytic(
        "hulls/ochi-vform.toml",
        "sea_states/ochi-1958.toml",
        vec![0.093, 0.133, 0.174],
        Some(vec![2.0]),
    );
    let b = &a.bow_force[0];
    assert_eq!(b.stations.len(), 3);
    // By hand: stations at x = 3 - 6 f; f(x) linear between them.
    let s = &b.stations;
    let (x, f): (Vec<f64>, Vec<f64>) = s
        .iter()
        .map(|q| (q.x_m, q.section_force_peak_n_per_m))
        .unzip();
    assert!(f.iter().all(|&v| v > 0.0), "{f:?}");
    let (mut total, mut moment) = (0.0, 0.0);
    for k in 0..2 {
        // x descends with the station fraction
        let (x0, x1, f0, f1) = (x[k + 1], x[k], f[k + 1], f[k]);
        total += 0.5 * (f0 + f1) * (x1 - x0);
        // exact moment of the linear f on [x0, x1]
        moment += (x1 - x0) * (x0 * (2.0 * f0 + f1) + x1 * (f0 + 2.0 * f1)) / 6.0;
    }
    assert!((b.peak_sum_total_n.unwrap() - total).abs() < 1e-9 * total);
    assert!((b.peak_sum_x_action_m.unwrap() - moment / total).abs() < 1e-9);
    let c = b.time_coincident.as_ref().unwrap();
    assert!(
        c.total_n <= total * (1.0 + 1e-9),
        "coincident {} <= peak sum {total}",
        c.total_n
    );
    assert!(c.x_action_m >= x[2] && c.x_action_m <= x[0]);
    assert!(a.bow_force_definition.contains("trapezoid"));
}

#[test]
fn the_car_carrier_is_compared_with_hermundstad_and_moan() {
    let a = analytic(
        "hulls/car-carrier-hm2005.toml",
        "sea_states/car-carrier-hm2005.toml",
        Vec::new(),
        None,
    );
    let c = &a.validation.comparisons;
    let refs: Vec<f64> = c.iter().map(|c| c.reference).collect();
    for (t, k) in [
        ("measured", "panel_peak_pressure_kpa"),
        ("reported_comparisons", "sph_peak_pressure_kpa"),
        ("reported_comparisons", "wagner_peak_pressure_kpa"),
        ("reported_comparisons", "flare_impact_speed_m_s"),
        ("reported_comparisons", "flare_impact_delay_after_keel_s"),
    ] {
        let r = reference(t, k);
        assert!(refs.contains(&r), "{k} = {r} in {refs:?}");
    }
    assert!(c.iter().all(|c| c.source.contains("Hermundstad")));
    assert!(
        c.iter()
            .filter(|c| c.quantity.contains("flare panel P1"))
            .count()
            == 3
    );
    let v = c
        .iter()
        .find(|c| c.quantity.starts_with("relative velocity at flare impact"))
        .unwrap();
    assert!(v.computed.is_some_and(|v| v > 0.0), "{v:?}");
    // Veen's Wagner number: the same equation at the reconstructed panel's chord angle and 1.4 m/s.
    let w = c
        .iter()
        .find(|c| c.quantity.contains("and the reference 1.4 m/s"))
        .unwrap();
    assert!((w.computed.unwrap() - 4.2).abs() < 0.1, "{w:?}");
}

#[test]
fn the_ochi_hull_gets_trend_checks_and_veens_p2() {
    let a = analytic(
        "hulls/ochi-vform.toml",
        "sea_states/ochi-1958.toml",
        vec![0.093, 0.133],
        Some(vec![2.0, 2.2, 2.4]),
    );
    let v = &a.validation;
    assert_eq!(v.trend_checks.len(), 3);
    for t in &v.trend_checks {
        assert!(
            ["reproduced", "not reproduced"].contains(&t.verdict),
            "{t:?}"
        );
        assert!(t.detail.contains("kPa"), "numbers in the detail: {t:?}");
    }
    let p2 = v
        .comparisons
        .iter()
        .find(|c| c.quantity.starts_with("P2"))
        .unwrap();
    assert_eq!(p2.reference, 3.0);
    assert!(p2.computed.is_some_and(|p| p > 0.0));
    assert!(v.notes.iter().any(|n| n.contains("not available")));
    // Another sea state: no comparison, and a note saying why.
    let b = analytic(
        "hulls/ochi-vform.toml",
        "sea_states/model-scale-jonswap.toml",
        vec![0.093],
        Some(vec![2.0]),
    );
    assert!(b.validation.comparisons.is_empty() && b.validation.trend_checks.is_empty());
    assert!(b.validation.notes[0].contains("not compared"));
}

#[test]
fn irregular_seas_give_design_events_that_state_their_definition() {
    let a = analytic(
        "hulls/ochi-vform.toml",
        "sea_states/model-scale-jonswap.toml",
        vec![0.093, 0.133],
        Some(vec![2.0]),
    );
    let design: Vec<_> = a
        .events
        .iter()
        .filter(|e| e.design_event.is_some())
        .collect();
    assert_eq!(design.len(), 2, "one per slamming station and speed");
    for e in design {
        let d = e.design_event.as_ref().unwrap();
        assert_eq!(e.wave, "SS6-model/design");
        assert!(d.definition.contains("most probable largest") && d.definition.contains("N = "));
        assert!(d.expected_slams >= 1.0);
        let v = e.entry_velocity_m_per_s.unwrap();
        assert!(
            (v - d.design_entry_velocity_m_per_s).abs() < 1e-6,
            "{v} {d:?}"
        );
        // V_N = sqrt(v_th^2 + 2 m2 ln N) from the sea's statistics
        assert!(v > d.threshold_velocity_m_per_s);
        assert!(
            e.analytic
                .as_ref()
                .is_some_and(|x| x.force_peak_n_per_m.is_some_and(|f| f > 0.0))
        );
    }
    let d = tempfile::tempdir().unwrap();
    let out = d.path().join("irr");
    let o = slamtool(&[
        "assess",
        "hulls/ochi-vform.toml",
        "--sea",
        "sea_states/model-scale-jonswap.toml",
        "--station",
        "0.093",
        "--speeds",
        "2.0",
        "--fidelity",
        "analytic",
        "--risk-level",
        "0.01",
        "-o",
        out.to_str().unwrap(),
    ]);
    let stdout = String::from_utf8_lossy(&o.stdout);
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    assert!(stdout.contains("probability alpha = 0.01"), "{stdout}");
    let csv = std::fs::read_to_string(out.join("pressures.csv")).unwrap();
    assert!(csv.contains("design_event_definition") && csv.contains("alpha = 0.01"));
}

#[test]
fn the_flat_keel_stations_get_the_air_cushion_warning() {
    let h = Hull::from_file(&data("hulls/ochi-vform.toml")).unwrap();
    let sea = SeaState::from_file(&data("sea_states/ochi-1958.toml")).unwrap();
    let s = Settings {
        stations: vec![0.093, 0.227],
        speeds: Some(vec![2.0]),
        ..Settings::default()
    };
    let plan = assess::plan::plan(&h, &sea, &s).unwrap();
    let air: Vec<&String> = plan
        .warnings
        .iter()
        .filter(|w| w.contains("air trapped"))
        .collect();
    assert_eq!(air.len(), 1, "{air:?}");
    assert!(
        air[0].starts_with("station 0.227 Lpp has a flat keel"),
        "{air:?}"
    );
}
