//! Relative motion, keel entry and Ochi slam statistics.

use nalgebra::Complex;
use slamtool::seakeeping::ShipModel;
use slamtool::seakeeping::relative_motion::{self, RelativeMotion};
use slamtool::seakeeping::slamming::{self, SampledSpectrum};
use slamtool::seakeeping::strip_theory::{self, StripSettings};

mod common;
use common::G;

/// Wigley III (see tests/common), coarser.
fn wigley3(n_stations: usize) -> ShipModel {
    common::wigley3(n_stations, 12)
}

fn coarse() -> StripSettings {
    let mut s = StripSettings::default();
    s.frank.body_panels = 16;
    s.frank.lid_panels = 4;
    s
}

#[test]
fn relative_velocity_is_the_time_derivative_at_zero_speed_and_has_speed_terms() {
    let m = wigley3(21);
    let w0 = 3.5;
    let r0 = strip_theory::respond(&m, w0, 0.0, &coarse()).unwrap();
    let rm = relative_motion::at_station(&r0, 1.2, 1.0).unwrap();
    let dsdt = Complex::new(0.0, r0.omega_e) * rm.motion;
    assert!((rm.velocity - dsdt).norm() < 1e-12 * dsdt.norm());
    // at speed: Ds/Dt = i w_e s + U eta5 + i k U zeta, which is not i w_e s
    let u = 0.3 * (G * m.lpp).sqrt();
    let r = strip_theory::respond(&m, w0, u, &coarse()).unwrap();
    let rm = relative_motion::at_station(&r, 1.2, 1.0).unwrap();
    let zeta = Complex::new(0.0, r.wave_number * 1.2).exp();
    let expect = Complex::new(0.0, r.omega_e) * rm.motion
        + r.pitch * u
        + Complex::new(0.0, r.wave_number * u) * zeta;
    assert!((rm.velocity - expect).norm() < 1e-12 * expect.norm());
    assert!(
        (rm.velocity - Complex::new(0.0, r.omega_e) * rm.motion).norm() > 0.01 * rm.velocity.norm()
    );
    // swell-up scales both; below 1 is refused
    let rm2 = relative_motion::at_station(&r, 1.2, 1.3).unwrap();
    assert!((rm2.motion.norm() / rm.motion.norm() - 1.3).abs() < 1e-12);
    assert!(relative_motion::at_station(&r, 1.2, 0.9).is_err());
}

#[test]
fn long_waves_are_followed() {
    // lambda = 8 L: the ship contours the wave, relative motion at midship is small
    let m = wigley3(21);
    let w0 = (G * 2.0 * std::f64::consts::PI / (8.0 * m.lpp)).sqrt();
    let r = strip_theory::respond(&m, w0, 0.0, &coarse()).unwrap();
    assert!(
        (r.heave.norm() - 1.0).abs() < 0.1,
        "heave RAO {}",
        r.heave.norm()
    );
    let rm = relative_motion::at_station(&r, 0.0, 1.0).unwrap();
    assert!(
        rm.motion.norm() < 0.15,
        "relative motion {}",
        rm.motion.norm()
    );
}

/// A relative motion of unit amplitude and phase 0.4 rad whose velocity is its time derivative ds/dt at
/// the encounter frequency `we` (no forward-speed terms).
fn sinusoid(we: f64) -> RelativeMotion {
    RelativeMotion {
        x: 1.0,
        motion: Complex::from_polar(1.0, 0.4),
        velocity: Complex::new(0.0, we) * Complex::from_polar(1.0, 0.4),
    }
}

/// s(t) of `rm` in a wave of amplitude `zeta_a`.
fn motion_at(rm: &RelativeMotion, we: f64, zeta_a: f64, t: f64) -> f64 {
    (rm.motion * Complex::new(0.0, we * t).exp()).re * zeta_a
}

#[test]
fn keel_entry_instant_and_profile() {
    let we = 2.0;
    let rm = sinusoid(we);
    let (zeta_a, draft) = (0.5, 0.2);
    let e = relative_motion::keel_entry(&rm, we, zeta_a, draft, 10.0, 50).unwrap();
    let s = |t: f64| motion_at(&rm, we, zeta_a, t);
    assert!(
        (s(e.t_entry) - draft).abs() < 1e-9,
        "s at entry {}",
        s(e.t_entry)
    );
    assert!(
        s(e.t_entry + 1e-4) < draft,
        "keel must be going down at entry"
    );
    assert!(e.entry_velocity > 0.0 && e.samples[0].penetration.abs() < 1e-9);
    // pure sinusoid: the entry lasts until the bottom of the motion, V falls to zero there
    let last = e.samples.last().unwrap();
    assert!(last.velocity.abs() < 0.01 * e.entry_velocity);
    assert!((last.penetration - (draft + zeta_a)).abs() < 1e-3);
    // no emergence, no entry
    assert!(relative_motion::keel_entry(&rm, we, 0.15, draft, 10.0, 50).is_none());
}

#[test]
fn keel_entry_of_a_dry_station_is_the_water_reaching_its_keel() {
    // keel 0.2 m above the calm water (draft -0.2): s falls through -0.2 where cos(w t + 0.4) = -0.4
    let we = 2.0;
    let rm = sinusoid(we);
    let (zeta_a, draft) = (0.5, -0.2);
    let e = relative_motion::keel_entry(&rm, we, zeta_a, draft, 10.0, 50).unwrap();
    let s = |t: f64| motion_at(&rm, we, zeta_a, t);
    assert!((s(e.t_entry) - draft).abs() < 1e-9, "{}", s(e.t_entry));
    assert!(s(e.t_entry + 1e-4) < draft, "the water rises past the keel");
    // V = w sqrt(amp^2 - T^2) at the crossing, the same as for a keel 0.2 m deep
    let v = we * (zeta_a * zeta_a - draft * draft).sqrt();
    assert!(
        (e.entry_velocity - v).abs() < 1e-9,
        "{} vs {v}",
        e.entry_velocity
    );
    let last = e.samples.last().unwrap();
    assert!((last.penetration - (draft + zeta_a)).abs() < 1e-3);
    // a wave whose relative motion does not reach the keel gives no entry (it did, wrongly, before
    // dry stations were allowed: the test was amp <= draft)
    assert!(relative_motion::keel_entry(&rm, we, 0.15, draft, 10.0, 50).is_none());
}

#[test]
fn ochi_formulas() {
    let v_th = slamming::threshold_velocity(G, 6.0);
    assert!((v_th - 0.7135).abs() < 1e-3, "{v_th}"); // ochi1958_vform.toml: 0.7135 m/s for Lpp 6 m
    let s = slamming::ochi(1.0, 2.0, 0.3, 0.04, 0.5, v_th);
    let p = (-0.09 / 0.08 - v_th * v_th / 1.0_f64).exp();
    assert!((s.probability - p).abs() < 1e-15);
    assert!(
        (s.slams_per_hour - 3600.0 / (2.0 * std::f64::consts::PI) * (0.5f64 / 0.04).sqrt() * p)
            .abs()
            < 1e-9
    );
    assert!((s.most_probable_extreme_velocity(1.0) - v_th).abs() < 1e-12);
    assert!(s.most_probable_extreme_velocity(100.0) > s.most_probable_extreme_velocity(10.0));
}

#[test]
fn operability_limit_interpolates_and_reports_none() {
    let op = slamming::operability_limit(&[1.0, 2.0, 3.0], &[0.01, 0.02, 0.06], 0.03).unwrap();
    assert!((op.limit_speed.unwrap() - 2.25).abs() < 1e-12);
    let op = slamming::operability_limit(&[1.0, 2.0], &[0.05, 0.06], 0.03).unwrap();
    assert!(op.limit_speed.is_none());
    let op = slamming::operability_limit(&[1.0, 2.0], &[0.0, 0.01], 0.03).unwrap();
    assert_eq!(op.limit_speed, Some(2.0));
    assert!(slamming::operability_limit(&[2.0, 1.0], &[0.0, 0.01], 0.03).is_err());
    assert!(slamming::operability_limit(&[1.0], &[0.0], 1.5).is_err());
}

#[test]
fn slam_probability_grows_with_speed_and_sea_severity() {
    let m = wigley3(21);
    // Pierson-Moskowitz-type spectrum at model scale, S(w) = A/w^5 exp(-B/w^4), Hs = 4 sqrt(m0)
    let spec = |hs: f64, tp: f64| {
        let wp = 2.0 * std::f64::consts::PI / tp;
        let b = 1.25 * wp.powi(4);
        let a = hs * hs * b / 4.0;
        SampledSpectrum::from_fn(
            |w| a / w.powi(5) * (-b / w.powi(4)).exp(),
            0.5 * wp,
            3.0 * wp,
            24,
        )
        .unwrap()
    };
    let s1 = spec(0.08, 1.6);
    let hs = 4.0 * s1.m0().sqrt();
    assert!((hs - 0.08).abs() < 0.01, "sampled Hs {hs}");
    let bow = [(1.2, 0.1875)];
    let p = |sp: &SampledSpectrum, u: f64| {
        slamming::statistics(&m, sp, u, &bow, 1.0, &coarse()).unwrap()[0]
    };
    let slow = p(&s1, 0.5);
    let fast = p(&s1, 1.5);
    assert!(
        fast.probability > slow.probability,
        "{} vs {}",
        fast.probability,
        slow.probability
    );
    assert!(fast.m2 > slow.m2);
    let rough = p(&spec(0.12, 1.6), 1.5);
    assert!(rough.probability > fast.probability);
    assert!(rough.slams_per_hour > fast.slams_per_hour);
}

#[test]
fn response_spectrum_moments_equal_the_statistics() {
    let m = wigley3(21);
    let sp =
        SampledSpectrum::from_fn(|w| 0.001 * (-(w - 4.5f64).powi(2)).exp(), 2.0, 8.0, 12).unwrap();
    let u = 1.0;
    let rs = slamming::response_spectra(&m, &sp, u, &[1.2], 1.0, &coarse()).unwrap();
    let st = slamming::statistics(&m, &sp, u, &[(1.2, 0.1875)], 1.0, &coarse()).unwrap();
    let (m0, m2) = rs[0].moments(G);
    assert!((m0 - st[0].m0).abs() < 1e-15 && (m2 - st[0].m2).abs() < 1e-15);
    // encounter frequencies follow w_e = w0 + w0^2 U / g; integrating over w_e gives about the same m0
    for (w0, we) in rs[0].omega0.iter().zip(&rs[0].omega_e) {
        assert!((we - (w0 + w0 * w0 * u / G)).abs() < 1e-12);
    }
    let m0_e = slamtool::numerics::quadrature::trapezoid(&rs[0].omega_e, &rs[0].motion);
    assert!((m0_e / m0 - 1.0).abs() < 0.05, "{m0_e} vs {m0}");
}
