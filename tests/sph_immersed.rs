//! SPH of a section immersed at the start (the flare events of `slamtool assess`): the fluid at rest
//! around the body with no particle inside it, and a run that completes with a finite, positive force.

use slamtool::sph::particles::Kind;
use slamtool::sph::{
    self, MotionSpec, Overrides, RunOptions, SensorSpec, Simulation, body::Section,
};

/// A 30 deg wedge (half-beam 0.1 m) with its keel `d0` under the water at rest, at 2 m/s, coarse.
fn immersed_wedge(d0: f64, t_end: f64) -> sph::Setup {
    let beta = 30f64.to_radians();
    let b = 0.1;
    let section = Section::wedge(beta, b, 1.5 * b * beta.tan()).unwrap();
    let side = b / beta.cos();
    sph::case::resolve(
        "immersed_wedge",
        &section,
        &MotionSpec::Constant { speed_m_s: 2.0 },
        vec![SensorSpec {
            name: "p1".into(),
            s_m: 0.7 * side,
            width_m: 0.01,
        }],
        &Overrides {
            particles_per_half_beam: Some(16.0),
            t_end: Some(t_end),
            initial_immersion: Some(d0),
            ..Default::default()
        },
    )
    .unwrap()
}

#[test]
fn no_fluid_inside_the_immersed_body_at_the_start() {
    let d0 = 0.02;
    let setup = immersed_wedge(d0, 0.01);
    let dp = setup.dp;
    let sim = Simulation::new(setup).unwrap();
    let sec = Section::wedge(
        30f64.to_radians(),
        0.1,
        1.5 * 0.1 * 30f64.to_radians().tan(),
    )
    .unwrap();
    let p = &sim.pt;
    let mut fluid_near = 0;
    for i in 0..p.len() {
        if p.kind[i] != Kind::Fluid {
            continue;
        }
        let (y, z) = (p.y[i], p.z[i]);
        assert!(
            !sec.contains(y, z + d0),
            "fluid particle inside the body at ({y}, {z})"
        );
        let d = sph::body::distance_to_polyline(sec.full_contour(), y, z + d0);
        assert!(d >= 0.5 * dp - 1e-12, "fluid {d} m from the contour");
        if d < 2.0 * dp {
            fluid_near += 1;
        }
    }
    // the water does wet the immersed part: fluid next to the contour below the surface
    assert!(fluid_near > 5, "{fluid_near}");
    assert_eq!(sim.body.z_keel, -d0);
}

#[test]
fn an_immersed_wedge_at_constant_speed_runs_with_a_positive_force() {
    let setup = immersed_wedge(0.02, 0.02);
    assert!(setup.notes.iter().any(|n| n.contains("starts immersed")));
    let dir = tempfile::tempdir().unwrap();
    let opts = RunOptions {
        out_dir: Some(dir.path().to_path_buf()),
        ..Default::default()
    };
    let r = sph::run(setup, &opts).unwrap();
    let s = &r.summary;
    assert!(s.stopped_early.is_none(), "{:?}", s.stopped_early);
    let f = s.force.summary.raw.value;
    assert!(f.is_finite() && f > 0.0, "force peak {f}");
    // the transient is the start of the motion: 2 dp of travel at 2 m/s
    let expected = 2.0 * s.dp_m / 2.0;
    assert!(
        (s.contact_transient_end_s - expected).abs() < 0.1 * expected,
        "{} vs {expected}",
        s.contact_transient_end_s
    );
}
