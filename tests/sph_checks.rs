//! Checks around an SPH run: settings refused before the run, and caveats attached to its summary (the
//! single-phase, no-air limit at low deadrise).

mod common;

use slamtool::sph::{self, MotionSpec, Overrides, RunOptions, body::Section};

fn short_wedge_run(deadrise_deg: f64) -> sph::RunSummary {
    let beta = deadrise_deg.to_radians();
    let b = 0.1;
    let section = Section::wedge(beta, b, 0.05_f64.max(1.5 * b * beta.tan())).unwrap();
    let setup = sph::case::resolve(
        "wedge",
        &section,
        &MotionSpec::Constant { speed_m_s: 2.0 },
        Vec::new(),
        &Overrides {
            particles_per_half_beam: Some(12.0),
            t_end: Some(0.004),
            ..Default::default()
        },
    )
    .unwrap();
    sph::run(setup, &RunOptions::default()).unwrap().summary
}

#[test]
fn low_deadrise_runs_carry_the_single_phase_warning() {
    let w = short_wedge_run(10.0).warnings;
    assert_eq!(w.len(), 1, "{w:?}");
    assert!(w[0].contains("air cushion"), "{}", w[0]);
    assert!(short_wedge_run(30.0).warnings.is_empty());
}

#[test]
fn a_sound_speed_not_above_the_entry_speed_is_refused() {
    let section = Section::wedge(30f64.to_radians(), 0.1, 0.1).unwrap();
    let resolve = |c0: f64| {
        sph::case::resolve(
            "wedge",
            &section,
            &MotionSpec::Constant { speed_m_s: 5.0 },
            Vec::new(),
            &Overrides {
                particles_per_half_beam: Some(12.0),
                c0: Some(c0),
                ..Default::default()
            },
        )
    };
    let e = resolve(4.0).unwrap_err().to_string();
    assert!(e.contains("sound speed") && e.contains("5 m/s"), "{e}");
    assert!(resolve(5.0).is_err());
    assert!(resolve(60.0).is_ok());
}

/// A constant-speed wedge run to its automatic end at 16 particles per half-beam with its companion at
/// twice the spacing.
fn wedge_study(sensors: Vec<sph::SensorSpec>) -> sph::RunSummary {
    let beta = 30f64.to_radians();
    let b = 0.1;
    let section = Section::wedge(beta, b, 1.5 * b * beta.tan()).unwrap();
    let setup = sph::case::resolve(
        "wedge",
        &section,
        &MotionSpec::Constant { speed_m_s: 2.0 },
        sensors,
        &Overrides {
            particles_per_half_beam: Some(16.0),
            ..Default::default()
        },
    )
    .unwrap();
    sph::run_with_convergence(setup, &RunOptions::default(), sph::StudyPlan::default())
        .unwrap()
        .summary
}

/// The keel's contact spike (an acoustic pressure of order rho c0 V in the first spacings of
/// penetration, the same at every resolution) is reported apart and is not the peak, and the peaks are
/// not called converged for being identical at both spacings.
#[test]
fn a_constant_speed_wedge_peak_is_not_the_contact_spike() {
    let s = wedge_study(Vec::new());
    let t_tr = s.contact_transient_end_s;
    assert!(t_tr > 0.0);
    // The spike is there, early and large: above half of Wagner's peak pressure at this deadrise.
    let rho_v2 = 0.5 * 1000.0 * 4.0;
    assert!(s.contact_transient_pressure_time_s < t_tr);
    assert!(
        s.contact_transient_pressure_pa > 0.5 * 7.4 * rho_v2,
        "{}",
        s.contact_transient_pressure_pa
    );
    // The reported peaks come after it.
    assert!(s.peak_contour_pressure_time_s >= t_tr);
    assert!(s.force.summary.raw.time >= t_tr);
    let conv = s.convergence.as_ref().unwrap();
    for p in &conv.peaks {
        let identical = p.values.windows(2).all(|w| w[0] == w[1]);
        assert!(
            !(identical && p.statement.contains("(converged")),
            "{}: {}",
            p.name,
            p.statement
        );
    }
}

/// A sensor narrower than the narrowest span (`MIN_WIDTH_DP` particle spacings) is integrated over that
/// span, and the summary says so.
#[test]
fn narrow_sensors_are_integrated_over_the_narrowest_span_with_a_warning() {
    let side = 0.1 / 30f64.to_radians().cos();
    let s = wedge_study(vec![
        sph::SensorSpec {
            name: "narrow".into(),
            s_m: 0.5 * side,
            width_m: 0.002,
        },
        sph::SensorSpec {
            name: "wide".into(),
            s_m: 0.3 * side,
            width_m: 0.03,
        },
    ]);
    let dp = s.dp_m;
    let narrow = &s.sensors[0];
    let span = narrow.integration_span_m.unwrap();
    assert!(
        (span[1] - span[0] - sph::sensors::MIN_WIDTH_DP * dp).abs() < 1e-12,
        "{span:?}"
    );
    assert!((0.5 * (span[0] + span[1]) - 0.5 * side).abs() < 1e-12);
    let wide = s.sensors[1].integration_span_m.unwrap();
    assert!((wide[1] - wide[0] - 0.03).abs() < 1e-12);
    let warned = common::sph::widened_sensor_warning(&s);
    assert!(warned.contains("narrow (2.0 mm wide"), "{warned}");
    assert!(!warned.contains("wide (30.0 mm"), "{warned}");
}
