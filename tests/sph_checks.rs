//! Checks around an SPH run: settings refused before the run, and caveats attached to its summary (the
//! single-phase, no-air limit at low deadrise).

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
