//! Wigley III validation against Journee (1992), data in data/reference/journee1992_wigley3.toml (with
//! provenance). Tolerances are those of issue 4: coefficients and wave loads 15 %, heave RAO 15 %,
//! zero-speed pitch RAO 25 % for lambda/L >= 1.

use slamtool::seakeeping::ShipModel;
use slamtool::seakeeping::strip_theory::{self, StripSettings};

mod common;
use common::G;

fn reference() -> toml::Table {
    let text = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/data/reference/journee1992_wigley3.toml"
    ))
    .unwrap();
    text.parse::<toml::Table>().unwrap()
}

fn arr(t: &toml::Table, table: &str, key: &str) -> Vec<f64> {
    t[table][key]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| {
            v.as_float()
                .or_else(|| v.as_integer().map(|i| i as f64))
                .unwrap()
        })
        .collect()
}

fn wigley3(n_stations: usize) -> ShipModel {
    common::wigley3(n_stations, 16)
}

fn within(what: &str, got: f64, want: f64, tol: f64) -> bool {
    let ok = (got - want).abs() <= tol * want.abs();
    println!(
        "{what}: computed {got:.4}, measured {want:.4}, diff {:+.1} % {}",
        100.0 * (got / want - 1.0),
        if ok { "ok" } else { "OUT" }
    );
    ok
}

#[test]
fn wigley3_hydrostatics_match_the_report() {
    let m = wigley3(41);
    let r = reference();
    let v = r["hull"]["volume_m3"].as_float().unwrap();
    let awp = r["hull"]["waterplane_area_m2"].as_float().unwrap();
    assert!((m.volume() - v).abs() < 0.01 * v, "volume {}", m.volume());
    assert!(
        (m.waterplane_area() - awp).abs() < 0.01 * awp,
        "Awp {}",
        m.waterplane_area()
    );
}

#[test]
fn wigley3_forced_heave_coefficients_fn030() {
    let m = wigley3(41);
    let r = reference();
    let u = 0.3 * (G * m.lpp).sqrt();
    let scale = (m.lpp / G).sqrt();
    let rv = m.rho * m.volume();
    let mut ok = true;
    for ((wn, a), b) in arr(&r, "forced_heave_fn030", "omega_nd")
        .iter()
        .zip(arr(&r, "forced_heave_fn030", "a33_nd"))
        .zip(arr(&r, "forced_heave_fn030", "b33_nd"))
    {
        let we = wn / scale;
        let s = strip_theory::strips(&m, we, &StripSettings::default()).unwrap();
        let c = strip_theory::coefficients(&m, &s, u);
        ok &= within(&format!("A33'' w' {wn}"), c.added_mass[0][0] / rv, a, 0.15);
        ok &= within(
            &format!("B33'' w' {wn}"),
            c.damping[0][0] / rv * scale,
            b,
            0.15,
        );
    }
    assert!(ok, "forced-heave coefficients outside 15 %");
}

fn omega0_of(lambda_over_l: f64, l: f64) -> f64 {
    (G * 2.0 * std::f64::consts::PI / (lambda_over_l * l)).sqrt()
}

#[test]
fn wigley3_wave_loads_fn030() {
    let m = wigley3(41);
    let r = reference();
    let u = 0.3 * (G * m.lpp).sqrt();
    let c = strip_theory::restoring(&m);
    let mut ok = true;
    for ((lr, x3), x5) in arr(&r, "wave_loads_fn030", "lambda_over_l")
        .iter()
        .zip(arr(&r, "wave_loads_fn030", "x3_nd"))
        .zip(arr(&r, "wave_loads_fn030", "x5_nd"))
    {
        let w0 = omega0_of(*lr, m.lpp);
        let k = w0 * w0 / G;
        let resp = strip_theory::respond(&m, w0, u, &StripSettings::default()).unwrap();
        ok &= within(
            &format!("X3'' lambda/L {lr}"),
            resp.excitation.f3.norm() / c[0][0],
            x3,
            0.15,
        );
        ok &= within(
            &format!("X5'' lambda/L {lr}"),
            resp.excitation.f5.norm() / (k * c[1][1]),
            x5,
            0.15,
        );
    }
    assert!(ok, "wave loads outside 15 %");
}

#[test]
fn wigley3_heave_rao_fn030() {
    let m = wigley3(41);
    let r = reference();
    let u = 0.3 * (G * m.lpp).sqrt();
    let mut ok = true;
    for (lr, h) in
        arr(&r, "heave_rao_fn030", "lambda_over_l")
            .iter()
            .zip(arr(&r, "heave_rao_fn030", "heave"))
    {
        let resp =
            strip_theory::respond(&m, omega0_of(*lr, m.lpp), u, &StripSettings::default()).unwrap();
        ok &= within(
            &format!("heave RAO Fn 0.3 lambda/L {lr}"),
            resp.heave.norm(),
            h,
            0.15,
        );
    }
    assert!(ok, "heave RAO at Fn 0.3 outside 15 %");
}

#[test]
fn wigley3_zero_speed_raos() {
    let m = wigley3(41);
    let r = reference();
    let mut ok = true;
    for ((lr, h), p) in arr(&r, "zero_speed", "lambda_over_l")
        .iter()
        .zip(arr(&r, "zero_speed", "heave"))
        .zip(arr(&r, "zero_speed", "pitch"))
    {
        if *lr < 1.0 {
            continue;
        }
        let resp = strip_theory::respond(&m, omega0_of(*lr, m.lpp), 0.0, &StripSettings::default())
            .unwrap();
        ok &= within(
            &format!("heave RAO Fn 0 lambda/L {lr}"),
            resp.heave.norm(),
            h,
            0.15,
        );
        let theta = resp.pitch.norm() * m.lpp / (2.0 * std::f64::consts::PI);
        ok &= within(&format!("pitch RAO Fn 0 lambda/L {lr}"), theta, p, 0.25);
    }
    assert!(ok, "zero-speed RAOs outside tolerance");
}

#[test]
fn timman_newman_symmetry() {
    let m = wigley3(41);
    let u = 0.3 * (G * m.lpp).sqrt();
    let s = strip_theory::strips(&m, 5.0, &StripSettings::default()).unwrap();
    let plus = strip_theory::coefficients(&m, &s, u);
    let minus = strip_theory::coefficients(&m, &s, -u);
    let a = plus.added_mass[0][1];
    let b = minus.added_mass[1][0];
    assert!(
        (a - b).abs() < 1e-9 * a.abs().max(1.0),
        "A35(U) {a} vs A53(-U) {b}"
    );
    let a = plus.damping[0][1];
    let b = minus.damping[1][0];
    assert!(
        (a - b).abs() < 1e-9 * a.abs().max(1.0),
        "B35(U) {a} vs B53(-U) {b}"
    );
    // and the speed terms are really there: A35(U) differs from A53(U)
    assert!(
        (plus.added_mass[0][1] - plus.added_mass[1][0]).abs() > 1e-3 * plus.added_mass[0][1].abs()
    );
}

/// The known limitation (physics.md s. 1, Journee 1992): strip theory over-predicts pitch damping at speed.
/// STF's B55 contains + U^2/w^2 B33^0, so it must grow with speed here, while the measured B55'' is nearly
/// speed-independent. Prints the comparison (B55'' = B55 / (rho V L^2) sqrt(L/g), as we read Journee's
/// nondimensional form; the normalisation is our assumption, the trend is not affected by it).
#[test]
fn wigley3_pitch_damping_at_speed_known_overprediction() {
    let m = wigley3(41);
    let r = reference();
    let wn = r["pitch_damping_measured"]["omega_nd"].as_float().unwrap();
    let scale = (m.lpp / G).sqrt();
    let s = strip_theory::strips(&m, wn / scale, &StripSettings::default()).unwrap();
    let mut last = 0.0;
    for (f, meas) in arr(&r, "pitch_damping_measured", "fn").iter().zip(arr(
        &r,
        "pitch_damping_measured",
        "b55_nd",
    )) {
        let u = f * (G * m.lpp).sqrt();
        let b55 = strip_theory::coefficients(&m, &s, u).damping[1][1]
            / (m.rho * m.volume() * m.lpp * m.lpp)
            * scale;
        println!(
            "B55'' at w' {wn}, Fn {f}: strip theory {b55:.4}, measured {meas:.4} ({:+.0} %)",
            100.0 * (b55 / meas - 1.0)
        );
        assert!(b55 > last, "B55 must grow with speed in STF");
        last = b55;
    }
}

/// Phases at zero speed, lambda/L >= 1 (leads relative to the wave crest amidships, as Journee prints them;
/// his pitch phases 258-264 deg are read modulo 360). This checks the sign conventions (heave up, pitch bow
/// down, wave e^{i(w t + k x)}). The 15 deg tolerance is ours (no published one), chosen after a first run
/// gave differences of at most 9 deg.
#[test]
fn wigley3_zero_speed_phases() {
    let m = wigley3(41);
    let r = reference();
    let wrap = |d: f64| (d + 180.0).rem_euclid(360.0) - 180.0;
    let mut ok = true;
    for ((lr, hp), pp) in arr(&r, "zero_speed", "lambda_over_l")
        .iter()
        .zip(arr(&r, "zero_speed", "heave_phase_deg"))
        .zip(arr(&r, "zero_speed", "pitch_phase_deg"))
    {
        if *lr < 1.0 {
            continue;
        }
        let resp = strip_theory::respond(&m, omega0_of(*lr, m.lpp), 0.0, &StripSettings::default())
            .unwrap();
        let dh = wrap(resp.heave.arg().to_degrees() - hp);
        let dp = wrap(resp.pitch.arg().to_degrees() - pp);
        println!("lambda/L {lr}: heave phase diff {dh:+.1} deg, pitch phase diff {dp:+.1} deg");
        ok &= dh.abs() < 15.0 && dp.abs() < 15.0;
    }
    assert!(ok, "phases outside 15 deg");
}

/// The Lewis method gives the Fn 0.3 heave RAO within the same 15 % (Wigley sections are close to Lewis forms).
#[test]
fn wigley3_heave_rao_fn030_lewis() {
    let m = wigley3(41);
    let r = reference();
    let u = 0.3 * (G * m.lpp).sqrt();
    let s = StripSettings {
        method: slamtool::seakeeping::section::SectionMethod::Lewis,
        ..StripSettings::default()
    };
    let mut ok = true;
    for (lr, h) in
        arr(&r, "heave_rao_fn030", "lambda_over_l")
            .iter()
            .zip(arr(&r, "heave_rao_fn030", "heave"))
    {
        let resp = strip_theory::respond(&m, omega0_of(*lr, m.lpp), u, &s).unwrap();
        ok &= within(
            &format!("Lewis heave RAO Fn 0.3 lambda/L {lr}"),
            resp.heave.norm(),
            h,
            0.15,
        );
    }
    assert!(ok);
}
