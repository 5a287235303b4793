//! Strip-theory bookkeeping: transom terms, restoring, time histories, bad input.

mod common;

use slamtool::seakeeping::rao;
use slamtool::seakeeping::section::HalfSection;
use slamtool::seakeeping::strip_theory::{self, StripSettings};
use slamtool::seakeeping::{ShipModel, StripSection};

/// A box barge L x B x T with a wetted transom at the aft end and a bow that tapers to nothing.
fn barge(with_transom: bool) -> ShipModel {
    let (l, b, t) = (20.0, 4.0, 1.0);
    let n = 21;
    let stations = (0..n)
        .map(|i| {
            let x = -0.5 * l + l * i as f64 / (n - 1) as f64;
            let taper = if i == n - 1 || (!with_transom && i == 0) {
                0.0
            } else {
                1.0
            };
            let section = (taper > 0.0)
                .then(|| HalfSection::new(vec![[0.0, -t], [0.5 * b, -t], [0.5 * b, 0.0]]).unwrap());
            StripSection { x, section }
        })
        .collect();
    let mut m = ShipModel {
        lpp: l,
        rho: 1025.0,
        g: 9.81,
        mass: 1.0,
        xg: 0.0,
        zg: 0.5,
        k_yy: 0.25 * l,
        stations,
    };
    m.mass = m.rho * m.volume();
    m.xg = m.x_buoyancy();
    m
}

#[test]
fn transom_terms_follow_stf() {
    let m = barge(true);
    let u = 3.0;
    let w = 1.2;
    let s = strip_theory::strips(&m, w, &StripSettings::default()).unwrap();
    let a = s.radiation[0].as_ref().unwrap();
    let c0 = strip_theory::coefficients(&m, &s, 0.0);
    let cu = strip_theory::coefficients(&m, &s, u);
    // STF (1970): B33 = B33^0 + U a33^A, A33 = A33^0 - U/w^2 b33^A
    assert!((cu.damping[0][0] - c0.damping[0][0] - u * a.a33).abs() < 1e-9 * cu.damping[0][0]);
    assert!(
        (cu.added_mass[0][0] - c0.added_mass[0][0] + u / (w * w) * a.b33).abs()
            < 1e-9 * cu.added_mass[0][0]
    );
    // without a transom the heave coefficients do not depend on speed
    let m = barge(false);
    let s = strip_theory::strips(&m, w, &StripSettings::default()).unwrap();
    let c0 = strip_theory::coefficients(&m, &s, 0.0);
    let cu = strip_theory::coefficients(&m, &s, u);
    assert!((cu.damping[0][0] - c0.damping[0][0]).abs() < 1e-12 * c0.damping[0][0]);
}

#[test]
fn restoring_of_a_box() {
    let m = barge(false);
    let c = strip_theory::restoring(&m);
    let awp = m.waterplane_area();
    assert!((c[0][0] - m.rho * m.g * awp).abs() < 1e-9 * c[0][0]);
    // box: z_B = -T/2
    assert!((m.z_buoyancy() + 0.5).abs() < 1e-12);
}

#[test]
fn time_history_is_the_real_part_of_the_complex_amplitude() {
    let m = barge(false);
    let r = strip_theory::respond(&m, 0.8, 2.0, &StripSettings::default()).unwrap();
    let (z0, p0) = rao::time_history(&r, 2.0, 0.0);
    assert!((z0 - 2.0 * r.heave.re).abs() < 1e-12 && (p0 - 2.0 * r.pitch.re).abs() < 1e-12);
    let quarter = 0.5 * std::f64::consts::PI / r.omega_e;
    let (zq, _) = rao::time_history(&r, 2.0, quarter);
    assert!((zq + 2.0 * r.heave.im).abs() < 1e-9);
}

#[test]
fn bad_model_and_frequency_are_errors() {
    let mut m = barge(false);
    assert!(strip_theory::respond(&m, -1.0, 0.0, &StripSettings::default()).is_err());
    assert!(strip_theory::respond(&m, 1.0, f64::NAN, &StripSettings::default()).is_err());
    m.k_yy = 0.0;
    assert!(m.validate().is_err());
    let mut m = barge(false);
    m.stations.swap(0, 1);
    assert!(m.validate().is_err());
}

#[test]
fn results_do_not_depend_on_the_thread_count() {
    let m = barge(true);
    let run = |threads: usize| {
        rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .unwrap()
            .install(|| strip_theory::respond(&m, 0.9, 2.5, &StripSettings::default()).unwrap())
    };
    let (a, b) = (run(1), run(3));
    assert_eq!(a.heave, b.heave);
    assert_eq!(a.pitch, b.pitch);
}

/// A ship symmetric fore and aft with G at midship (Wigley III) has no heave-pitch coupling at zero speed
/// (C35 = A35 = M35 = 0): its coupled normal-mode periods are the uncoupled periods.
#[test]
fn natural_mode_periods_of_a_symmetric_ship_are_the_uncoupled_ones() {
    let m = common::wigley3(21, 12);
    let s = StripSettings::default();
    let (uh, up) = strip_theory::natural_periods(&m, &s).unwrap();
    let (th, tp) = strip_theory::natural_mode_periods(&m, &s).unwrap();
    assert!((th / uh - 1.0).abs() < 1e-6, "heave {th} vs {uh}");
    assert!((tp / up - 1.0).abs() < 1e-6, "pitch {tp} vs {up}");
}
