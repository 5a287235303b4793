//! The entry-velocity definitions of issue 29 (`seakeeping::entry_definitions`, `wave_readings`): each
//! definition does what its doc says, on the bundled Ochi and Hermundstad hulls.

use std::path::PathBuf;

use slamtool::hull::Hull;
use slamtool::sea::SeaState;
use slamtool::seakeeping::ShipModel;
use slamtool::seakeeping::entry_definitions::{
    self, DraftReading, STRIPS, Target, Variant, keel_slope,
};
use slamtool::seakeeping::relative_motion::{self, Definition, VelocityDefinition};
use slamtool::seakeeping::strip_theory::{self, StripSettings};
use slamtool::seakeeping::wave_readings::{self, Reading};

fn root() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR"))
}

fn ochi() -> (Hull, SeaState) {
    (
        Hull::from_file(&root().join("hulls/ochi-vform.toml")).unwrap(),
        SeaState::from_file(&root().join("sea_states/ochi-1958.toml")).unwrap(),
    )
}

#[test]
fn the_bundled_ochi_wave_is_veens_two_second_wave() {
    let (_, sea) = ochi();
    let w = &sea.regular[0];
    assert!((w.period_s - 2.0).abs() < 1e-12, "{}", w.period_s);
    assert!((w.height_m - 0.2).abs() < 1e-12);
    // deep water: lambda = g T^2 / (2 pi) = 6.24 m, not the hull's 6 m
    let lambda = slamtool::sea::G * 4.0 / (2.0 * std::f64::consts::PI);
    assert!((w.wavelength_m - lambda).abs() < 1e-9, "{}", w.wavelength_m);
    assert!((w.wavelength_m - 6.0).abs() > 0.2);
}

#[test]
fn velocity_definitions_differ_by_their_forward_speed_terms_only() {
    let (hull, _) = ochi();
    let loading = hull.loading(Some("test-condition")).unwrap();
    let model = ShipModel::from_hull(&hull, loading, STRIPS).unwrap();
    let r = strip_theory::respond(&model, std::f64::consts::PI, 2.0, &StripSettings::default())
        .unwrap();
    let x = hull.station_x(0.093);
    let at = |velocity, heave_of_g_at| {
        relative_motion::at_station_as(
            &r,
            x,
            &Definition {
                swell_up: 1.0,
                velocity,
                heave_of_g_at,
            },
        )
        .unwrap()
    };
    let full = at(VelocityDefinition::EarthFixedPlane, None);
    let no_pitch = at(VelocityDefinition::WithoutPitchSpeedTerm, None);
    let ship = at(VelocityDefinition::ShipFixedStation, None);
    // the default is the project's at_station
    let bundled = relative_motion::at_station(&r, x, 1.0).unwrap();
    assert!((bundled.velocity - full.velocity).norm() < 1e-12);
    // Ds/Dt - (without U eta5) = U eta5
    assert!((full.velocity - no_pitch.velocity - r.pitch * 2.0).norm() < 1e-12);
    // ship-fixed: i w_e s, so |v| = w_e |s|
    assert!((ship.velocity.norm() - r.omega_e * ship.motion.norm()).abs() < 1e-12);
    // the forward-speed terms are not small here
    assert!((full.velocity - ship.velocity).norm() > 0.05 * full.velocity.norm());
    // heave of G with the lever from amidships: s shifts by -x_G eta5
    let g = at(VelocityDefinition::EarthFixedPlane, Some(model.xg));
    assert!((g.motion - full.motion + r.pitch * model.xg).norm() < 1e-12);
    assert!(model.xg.abs() > 0.05, "x_G {}", model.xg);
}

#[test]
fn keel_slope_of_a_keel_on_the_baseline_is_the_trim_over_lpp() {
    let (hull, _) = ochi();
    let loading = hull.loading(Some("test-condition")).unwrap();
    let trim = loading.draft_ap - loading.draft_fp;
    assert!(trim > 0.0);
    for f in [0.093, 0.174, 0.5] {
        let s = keel_slope(&hull, loading, hull.station_x(f)).unwrap();
        assert!((s - trim / hull.lpp).abs() < 1e-9, "{f}: {s}");
    }
    let even = hull.loading(Some("max-draft")).unwrap();
    assert!(keel_slope(&hull, even, 0.0).unwrap().abs() < 1e-9);
}

#[test]
fn draft_readings_keep_the_trim_and_move_the_mean() {
    let (hull, _) = ochi();
    let l = hull.loading(Some("test-condition")).unwrap();
    assert_eq!(DraftReading::AsFile.drafts(l), (l.draft_fp, l.draft_ap));
    let (fp, ap) = DraftReading::MeanAtFp.drafts(l);
    assert!((fp - 0.2).abs() < 1e-12 && (ap - 0.28).abs() < 1e-12);
    let (fp, ap) = DraftReading::MeanAtAp.drafts(l);
    assert!((fp - 0.12).abs() < 1e-12 && (ap - 0.2).abs() < 1e-12);
    let (fp, ap) = DraftReading::EvenKeel.drafts(l);
    assert!((fp - 0.2).abs() < 1e-12 && (ap - 0.2).abs() < 1e-12);
}

#[test]
fn ochi_keel_entry_by_definition() {
    let (hull, sea) = ochi();
    let loading = hull.loading(Some("test-condition")).unwrap();
    let target = |f: f64| Target {
        label: format!("{f}"),
        hull: &hull,
        loading,
        wave: &sea.regular[0],
        speed: 2.0,
        aft_of_fp: f,
        height_above_keel: 0.0,
        fixed_wave: false,
    };
    let v = |f: f64, var: &Variant| {
        entry_definitions::evaluate(&target(f), var)
            .unwrap()
            .crossing_velocity_m_per_s
            .expect("the keel emerges at P1 and P3 at 2.0 m/s")
    };
    let base = Variant::default();
    for f in [0.093, 0.174] {
        let b = v(f, &base);
        assert!(b > 0.0, "{f}: entry velocity {b}");
        // the keel-slope term adds exactly U trim / Lpp
        let ks = v(
            f,
            &Variant {
                keel_slope: true,
                ..Variant::default()
            },
        );
        assert!((ks - b - 2.0 * 0.08 / 6.0).abs() < 1e-9, "{f}: {ks} {b}");
        // a swell-up factor scales the relative motion, so the keel emerges earlier and enters faster
        let sw = v(
            f,
            &Variant {
                swell_up: Some(1.2),
                ..Variant::default()
            },
        );
        assert!(sw > b, "{f}: {sw} <= {b}");
    }
    // the table has a row per variant and a column per target
    let rows = entry_definitions::table(
        &[target(0.093), target(0.174)],
        &entry_definitions::standard_variants(loading),
    )
    .unwrap();
    assert_eq!(
        rows.len(),
        entry_definitions::standard_variants(loading).len()
    );
    let md = entry_definitions::markdown(&[target(0.093), target(0.174)], &rows, None);
    assert_eq!(md.lines().count(), rows.len() + 2, "{md}");
}

#[test]
fn hermundstad_readings_state_the_needed_relative_motion() {
    let hull = Hull::from_file(&root().join("hulls/car-carrier-hm2005.toml")).unwrap();
    let loading = hull.loading(Some("design")).unwrap();
    let readings = [
        Reading {
            label: "height".into(),
            amplitude_m: 0.05,
            period_s: 1.9,
        },
        Reading {
            label: "amplitude".into(),
            amplitude_m: 0.1,
            period_s: 1.9,
        },
    ];
    let rows = wave_readings::readings(&hull, loading, 0.05, 0.3, 2.2, &readings, 1.4).unwrap();
    // linear: the same RAO under both readings, twice the relative motion for twice the amplitude
    assert!((rows[0].relative_motion_rao - rows[1].relative_motion_rao).abs() < 1e-9);
    assert!(
        (rows[1].relative_motion_amplitude_m - 2.0 * rows[0].relative_motion_amplitude_m).abs()
            < 1e-12
    );
    for r in &rows {
        // w_e = w + w^2 U / g in head seas
        let w = 2.0 * std::f64::consts::PI / 1.9;
        let we = w + w * w * 2.2 / slamtool::sea::G;
        assert!((r.encounter_frequency_rad_per_s - we).abs() < 1e-9);
        assert!((r.needed_amplitude_m * we - 1.4).abs() < 1e-12);
        assert!((r.needed_rao * r.wave_amplitude_m - r.needed_amplitude_m).abs() < 1e-12);
    }
    assert!(wave_readings::wave("bad", -1.0, 1.9).is_err());
    assert!(wave_readings::wave("bad", 0.1, f64::NAN).is_err());
}
