//! Keel stages ([`slamtool::sph::keel_stage`]): a sensor the main run crosses inside its contact
//! transient is resolved by a fine run of the section's lower part, at the spacing that puts
//! `PARTICLES_ACROSS_RESOLVED` particles across the wetted half-width at its crossing.

mod common;

use common::sph::widened_sensor_warning;
use slamtool::loads::anatomy::ImpactStatus;
use slamtool::sph::keel_stage::{PARTICLES_ACROSS_RESOLVED, STAGE_BREADTH};
use slamtool::sph::{self, MotionSpec, Overrides, SensorSpec, StudyPlan, body::Section};

#[test]
fn a_keel_sensor_crossed_in_the_transient_is_resolved_by_a_stage() {
    let beta = 25f64.to_radians();
    let b = 0.25;
    let section = Section::wedge(beta, b, 1.5 * b * beta.tan()).unwrap();
    let sensors = vec![
        SensorSpec {
            name: "keel".into(),
            s_m: 0.012,
            width_m: 0.008,
        },
        SensorSpec {
            name: "side".into(),
            s_m: 0.2,
            width_m: 0.01,
        },
    ];
    let speed = 3.0;
    let t_wet = 2.0 / std::f64::consts::PI * b * beta.tan() / speed;
    let setup = sph::case::resolve(
        "wedge",
        &section,
        &MotionSpec::Constant { speed_m_s: speed },
        sensors,
        &Overrides {
            particles_per_half_beam: Some(40.0),
            t_end: Some(0.8 * t_wet),
            ..Default::default()
        },
    )
    .unwrap();
    let dp = setup.dp;
    let one = StudyPlan {
        levels: 1,
        ratio: 2.0,
    };
    // the main run alone: the keel sensor is crossed inside the contact transient
    let plain = sph::run_with_convergence(setup.clone(), &Default::default(), one).unwrap();
    let status = |s: &sph::RunSummary, n: &str| {
        s.sensors
            .iter()
            .find(|q| q.name == n)
            .and_then(|q| q.anatomy.as_ref())
            .map(|a| (a.status, a.crossing_half_width_m))
    };
    let (st, c_keel) = status(&plain.summary, "keel").unwrap();
    assert_eq!(st, ImpactStatus::InTransient);
    let c_keel = c_keel.unwrap();
    assert!(c_keel / dp < 5.0, "{}", c_keel / dp);

    let staged = sph::run_staged(setup, &Default::default(), one).unwrap();
    let s = &staged.summary;
    assert_eq!(s.stages.len(), 1, "{:?}", s.stages);
    let stage = &s.stages[0];
    assert!(stage.left_out.is_none(), "{:?}", stage.left_out);
    assert_eq!(stage.sensors, vec!["keel".to_string()]);
    // the stage's spacing puts N particles across the keel sensor's crossing half-width, on the section
    // cut at K times it
    assert!((c_keel / stage.dp_m - PARTICLES_ACROSS_RESOLVED).abs() < 1e-6);
    assert!((stage.cut_half_breadth_m - STAGE_BREADTH * c_keel).abs() < 1e-9);
    let keel = s.sensors.iter().find(|q| q.name == "keel").unwrap();
    assert_eq!(keel.stage.map(|r| r.stage), Some(0));
    let a = keel.anatomy.as_ref().unwrap();
    assert_eq!(a.status, ImpactStatus::Resolved, "{a:?}");
    let peak = a
        .slamming_peak
        .expect("a resolved impact has a slamming peak");
    // a slamming pressure of the order of the wedge's: between 1/2 rho V^2 and the similarity maximum
    // of a 25 deg wedge (Cp about 11) with a wide margin, not an acoustic spike rho c0 V
    let q = 0.5 * 1000.0 * speed * speed;
    assert!(peak.value > q && peak.value < 20.0 * q, "{} Pa", peak.value);
    // the side sensor keeps the main run's record
    let side = s.sensors.iter().find(|q| q.name == "side").unwrap();
    assert!(side.stage.is_none());
    let (st_side, _) = status(s, "side").unwrap();
    assert_eq!(st_side, ImpactStatus::Resolved);
    // the list of widened sensors follows the records: both are narrower than 4 dp of the main run, the
    // keel sensor's stage record is not widened
    let main = widened_sensor_warning(&plain.summary);
    assert!(main.contains("keel (") && main.contains("side ("), "{main}");
    let after = widened_sensor_warning(s);
    assert!(
        !after.contains("keel (") && after.contains("side ("),
        "{after}"
    );
}
