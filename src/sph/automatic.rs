//! The automatic choices of a water-entry run that follow from the section and its motion: when the
//! impact is over (the end time), how large the tank must be, and the sound speed. Each returns its
//! value with a note that says how it was chosen; [`crate::sph::case::resolve`] records the notes.

use crate::analytic::generalised_wagner::penetration_for_half_width;
use crate::sph::body::{Motion, Section, half_contour_length, point_at_arc};
use crate::sph::sensors::SensorSpec;

/// Margin on the time at which Wagner's wetted half-width reaches the widest point of the section, so
/// that the run sees the section force pass its maximum there (Wagner's force peaks when the wetting
/// reaches the chine or the deck edge and falls once the flow separates).
pub const END_MARGIN: f64 = 1.2;

/// Water depth under the keel's deepest position and clear width beside the widest point, in
/// half-breadths b, of the undamped part of an automatic tank; and the thickness of its absorbing layer.
pub const CLEAR_DEPTH_B: f64 = 3.0;
pub const CLEAR_WIDTH_B: f64 = 5.0;
pub const DAMPING_B: f64 = 1.5;

/// Keel penetration, in particle spacings, that a run lasts at least: well past the contact transient
/// ([`crate::sph::CONTACT_TRANSIENT_DP`]), for a section whose impact Wagner's condition puts at the
/// instant of contact (a flat keel under steep sides).
pub const MIN_PENETRATION_DP: f64 = 10.0;

/// Largest sound speed an automatic choice may make: the real sound speed of water. A run that would
/// need more is an impact whose acoustic phase is real physics, outside weakly compressible SPH.
pub const MAX_C0: f64 = 1480.0;

/// The density variation delta allowed at the expected peak pressure, rho0 c0^2 delta = Cp rho0 V^2 / 2.
pub const DENSITY_VARIATION: f64 = 0.01;

/// A chosen value and how it was chosen.
#[derive(Debug, Clone)]
pub struct Choice {
    pub value: f64,
    pub note: String,
}

/// Local deadrise (deg) from which a contour segment counts as a side rather than a bottom: the
/// wetting that reaches it has run through the bottom's impact, and the flow separates or runs up the
/// side without a new slam (a chine, a knuckle into a near-vertical side, the turn of a bilge).
pub const SIDE_DEADRISE_DEG: f64 = 75.0;

/// How far the wetting must go for the impact to be over. Above the lowest contour point from which
/// every segment up to the deck edge is a side ([`SIDE_DEADRISE_DEG`] or steeper) no new slam can
/// happen: the wetting that reaches that point (a chine, a knuckle into a vertical side, the turn of a
/// bilge) has run through the impact. A section whose top segment is not that steep (a flared bow) is
/// wetted to its widest point. In any case the wetting goes past the upper edge of the highest sensor
/// (a flare panel above a knuckle). Returns the half-breadth and what it is.
pub fn wetting_target(section: &Section, sensors: &[SensorSpec]) -> (f64, String) {
    let half = section.half_points();
    let b = section.half_breadth();
    let steep = SIDE_DEADRISE_DEG.to_radians();
    let mut k = half.len() - 1;
    while k > 0 {
        let (dy, dz) = (half[k][0] - half[k - 1][0], half[k][1] - half[k - 1][1]);
        if dz > 0.0 && dz.atan2(dy.abs()) >= steep {
            k -= 1;
        } else {
            break;
        }
    }
    let widest = half[..=k].iter().map(|p| p[0]).fold(0.0, f64::max);
    let mut target = if k + 1 < half.len() && widest > 0.0 {
        (
            widest,
            format!(
                "the chine, above which the contour is a side steeper than {SIDE_DEADRISE_DEG} deg up to the deck \
                 edge (half-breadth {widest:.4} m, {:.4} m above the keel)",
                half[k][1]
            ),
        )
    } else {
        (b, format!("the widest point (half-breadth {b:.4} m)"))
    };
    let top = sensor_top_edges(section, sensors)
        .map(|p| p[0])
        .fold(0.0, f64::max);
    if top > target.0 {
        let y = top.min(b);
        target = (
            y,
            format!("the upper edge of the highest sensor (half-breadth {y:.4} m)"),
        );
    }
    target
}

/// Penetration at which the wetted contour, by Wagner's condition for the actual shape, reaches the
/// half-breadth `y`; `None` when the condition cannot be solved for this shape.
pub fn wetting_penetration(section: &Section, y: f64) -> Option<f64> {
    let d = penetration_for_half_width(section.half_points(), y * (1.0 - 1e-9))?;
    (d.is_finite() && d > 0.0).then_some(d)
}

/// Penetration since the start at which the wetted contour of a section immersed to `d0` at rest
/// reaches the half-breadth `y` (Wagner's condition on the body above the initial waterline); `None`
/// when it cannot be solved or `y` is wetted from the start.
pub fn immersed_wetting_penetration(section: &Section, y: f64, d0: f64) -> Option<f64> {
    let p =
        crate::analytic::section_profile::Profile::from_half_points(section.half_points()).ok()?;
    let d = p
        .above(d0)
        .ok()?
        .wagner_depth((y * (1.0 - 1e-9)).min(p.y_end()))?;
    (d.is_finite() && d > 0.0).then_some(d)
}

/// Time at which the keel reaches `depth` below the calm surface, and the first time the downward speed
/// falls to zero (the relative motion reverses), whichever comes first; `None` when neither happens
/// within `t_max`.
pub fn time_to_depth(m: &Motion, depth: f64, t_max: f64) -> Option<(f64, bool)> {
    match m {
        Motion::Constant { speed } => {
            let t = depth / speed;
            (t <= t_max).then_some((t, false))
        }
        Motion::FreeHeave { speed0, .. } => Some((1.3 * depth / speed0, false)),
        _ => {
            // Midpoint steps of t_max / n; within the step where the depth is passed or the speed
            // changes sign the instant is found to rounding (linear in the depth, bisection on the
            // speed), so the end time does not depend on the step.
            let n = 20_000;
            let dt = t_max / n as f64;
            let speed = |t: f64| m.speed_at(t).unwrap_or(0.0);
            let mut z = 0.0;
            let mut was_going_down = false;
            for k in 0..n {
                let t = k as f64 * dt;
                let v = speed(t + 0.5 * dt);
                if v <= 0.0 && t > 0.0 {
                    if !was_going_down {
                        return Some((t, true));
                    }
                    let mut bracket = (t - 0.5 * dt, t + 0.5 * dt);
                    for _ in 0..60 {
                        let mid = 0.5 * (bracket.0 + bracket.1);
                        if speed(mid) > 0.0 {
                            bracket.0 = mid;
                        } else {
                            bracket.1 = mid;
                        }
                    }
                    return Some((bracket.1, true));
                }
                if v > 0.0 && z + dt * v >= depth {
                    return Some((t + (depth - z) / v, false));
                }
                z += dt * v;
                was_going_down = v > 0.0;
            }
            None
        }
    }
}

/// The upper edge (y, z above the keel) of every sensor on the starboard contour.
fn sensor_top_edges<'a>(
    section: &'a Section,
    sensors: &'a [SensorSpec],
) -> impl Iterator<Item = [f64; 2]> + 'a {
    let len = half_contour_length(section);
    sensors
        .iter()
        .filter_map(move |s| point_at_arc(section, (s.s_m + 0.5 * s.width_m).min(len)))
}

/// Height above the keel of the upper edge of the highest sensor (m); `None` without sensors.
pub fn sensor_top_height(section: &Section, sensors: &[SensorSpec]) -> Option<f64> {
    sensor_top_edges(section, sensors)
        .map(|p| p[1])
        .reduce(f64::max)
}

/// Longest automatic end time, s.
pub const T_END_MAX_S: f64 = 60.0;

/// The words of the end-time note when the keel never reaches the depth the impact needs within
/// [`T_END_MAX_S`] (a creeping or rising body): the run would end before any impact.
pub const NEVER_DEEP_ENOUGH: &str = "the keel never gets";

/// End time: the impact is over when Wagner's wetted contour has reached the chine (or the widest point,
/// or past the highest sensor: [`wetting_target`]) and the force has passed its maximum there
/// ([`END_MARGIN`] times the wetting time), or when the entry velocity has fallen to zero, whichever
/// comes first; never past the keel reaching 0.9 of the section height (the deck would go under).
///
/// Wagner's condition over-predicts the pile-up of the water on steep sides (it tends to pi/2 times the
/// calm-water intersection at every deadrise, where the exact wedge solutions tend to 1 as the deadrise
/// tends to 90 deg; Zhao & Faltinsen 1993), so a run ended by it alone can end before the water reaches
/// the upper sensors of a steep section. The wetting time is therefore never taken shorter than the time
/// at which the calm-water line itself reaches the upper edge of the highest sensor (pile-up factor 1,
/// the von Karman limit, which no pile-up undercuts).
///
/// For a section that starts immersed to the keel depth `d0` (0 for a keel entry), depths count from the
/// start: the wetting uses Wagner's condition with the initial immersion
/// ([`crate::analytic::entry_kinematics`]), and the cap is the keel 0.9 of the height deep in all.
///
/// A prescribed motion is known only as far as its velocity table goes, so the run never goes past the
/// table's end (a strip-theory profile ends where the relative velocity reverses or the keel is fully
/// immersed; past it the section would begin to exit, which the run does not model). The table's last
/// velocity is held after its end ([`Motion::speed_at`]) only in a run given a longer end time.
pub fn end_time(section: &Section, m: &Motion, sensors: &[SensorSpec], dp: f64, d0: f64) -> Choice {
    let t_max = T_END_MAX_S;
    let table_end = match m {
        Motion::Prescribed { t_end, .. } if *t_end < t_max => Some(*t_end),
        _ => None,
    };
    let (y_target, what) = wetting_target(section, sensors);
    let min_depth = MIN_PENETRATION_DP * dp;
    let wet = if d0 > 0.0 {
        immersed_wetting_penetration(section, y_target, d0)
    } else {
        wetting_penetration(section, y_target)
    };
    let (mut depth, mut what) = match wet {
        Some(d) if d >= min_depth => (d, format!("Wagner's wetted half-width reaches {what}")),
        _ => (
            min_depth,
            format!(
                "Wagner's wetted half-width reaches {what}, which a flat keel reaches at contact; the run goes \
                 on to a keel depth of {MIN_PENETRATION_DP} particle spacings"
            ),
        ),
    };
    if let Some(z_top) = sensor_top_height(section, sensors)
        && z_top - d0 > depth
    {
        depth = z_top - d0;
        what = format!(
            "the calm-water line reaches the upper edge of the highest sensor ({z_top:.4} m above the keel; \
             Wagner's condition, which over-predicts the pile-up on steep sides, puts the wetting there \
             sooner)"
        );
    }
    let depth = depth.min(0.9 * section.height() - d0);
    let reached = time_to_depth(m, depth, t_max).filter(|r| table_end.is_none_or(|te| r.0 <= te));
    match reached {
        Some((t, true)) => Choice {
            value: t,
            note: format!("t_end = {t:.5} s: the entry velocity falls to zero before {what}"),
        },
        Some((t, false)) => {
            let tm = END_MARGIN * t;
            let cap =
                time_to_depth(m, 0.9 * section.height() - d0, t_max).map_or(f64::INFINITY, |d| d.0);
            let rev = time_to_depth(m, f64::INFINITY, tm.min(t_max))
                .filter(|r| r.1)
                .map_or(f64::INFINITY, |r| r.0);
            let value = tm.min(cap).min(rev).min(table_end.unwrap_or(t_max));
            Choice {
                value,
                note: format!(
                    "t_end = {value:.5} s: {END_MARGIN} x the time ({t:.5} s) at which {what}, so that the force \
                     and the sensor pressures pass their maxima (at most until the entry velocity reverses, \
                     the keel is 0.9 x the height deep or the velocity table ends)"
                ),
            }
        }
        None => match table_end {
            Some(te) => Choice {
                value: te,
                note: format!(
                    "t_end = {te:.5} s: the velocity table ends before {what} (the keel {depth:.4} m deep); \
                     the motion after the table is not given"
                ),
            },
            None => Choice {
                value: t_max,
                note: format!(
                    "t_end = {t_max} s: {NEVER_DEEP_ENOUGH} {depth:.4} m deep within that time"
                ),
            },
        },
    }
}

/// Tank of an automatic case: [`CLEAR_WIDTH_B`] b of water beside the widest point and
/// [`CLEAR_DEPTH_B`] b under the keel's deepest position, plus an absorbing layer [`DAMPING_B`] b
/// thick along the walls and the bottom. Returns (half-width, depth, layer thickness, note).
pub fn tank(section: &Section, keel_depth_end: f64) -> (f64, f64, f64, String) {
    let b = section.half_breadth();
    let layer = DAMPING_B * b;
    let half_width = b + CLEAR_WIDTH_B * b + layer;
    let depth = keel_depth_end + CLEAR_DEPTH_B * b + layer;
    let note = format!(
        "tank half-width {half_width:.3} m and depth {depth:.3} m: {CLEAR_WIDTH_B} b of water beside the widest \
         point and {CLEAR_DEPTH_B} b under the keel's deepest position ({keel_depth_end:.3} m), plus an \
         absorbing layer {layer:.3} m ({DAMPING_B} b) thick along the walls and the bottom that takes up the \
         impact's pressure wave (b = {b:.4} m)"
    );
    (half_width, depth, layer, note)
}

/// Water at the base resolution beside the widest point and under the keel's deepest position in a
/// refined tank ([`crate::sph::refinement`]), in half-breadths b.
pub const REFINED_CLEAR_B: f64 = 1.5;

/// The band of base resolution of a refined tank: [`REFINED_CLEAR_B`] b beside the widest point and
/// under the keel's deepest position, on the 2 dp lattice of the far field. Returns the band and a note.
pub fn refinement_band(
    section: &Section,
    keel_depth_end: f64,
    dp: f64,
) -> (crate::sph::refinement::Band, String) {
    use crate::sph::refinement::{Band, to_coarse_lattice};
    let b = section.half_breadth();
    let clear = REFINED_CLEAR_B;
    let band = Band {
        half_width: to_coarse_lattice(b + clear * b, dp),
        depth: to_coarse_lattice(keel_depth_end + clear * b, dp),
    };
    let note = format!(
        "refined tank: particles at dp within {:.3} m of the centre plane and {:.3} m of the surface \
         ({REFINED_CLEAR_B} b beside the widest point and under the keel's deepest position), at 2 dp beyond \
         (variable-mass SPH with the mean smoothing length of each pair; the tank rounded to whole 2 dp)",
        band.half_width, band.depth
    );
    (band, note)
}

/// Sound speed: the largest of V sqrt(Cp / (2 delta)) (density variation delta = 1 % at Wagner's peak pressure
/// coefficient Cp = (pi^2/4) cot^2(beta), beta the smallest deadrise below the widest point, not below
/// 10 deg), 10 V (Mach number at most 0.1) and 10 sqrt(g D) (hydrostatic pressure at the tank bottom
/// within 1 % of rho0 c0^2). The tank depth D is the one the run uses.
pub fn sound_speed(section: &Section, v_max: f64, g: f64, tank_depth: f64) -> Choice {
    let b = section.half_breadth();
    let z_chine = section
        .half_points()
        .iter()
        .find(|p| p[0] >= b * (1.0 - 1e-9))
        .map_or(section.height(), |p| p[1]);
    let beta = section.min_deadrise_below(z_chine).max(10f64.to_radians());
    // 0 for a section whose contour below the chine is all vertical: the other bounds then set c0.
    let cp = crate::analytic::wagner::peak_pressure_coefficient(beta).unwrap_or(0.0);
    let c_imp = v_max * (cp / (2.0 * DENSITY_VARIATION)).sqrt();
    let c_mach = 10.0 * v_max;
    let c_hyd = 10.0 * (g * tank_depth).sqrt();
    let value = c_imp.max(c_mach).max(c_hyd);
    let mach = contact_mach(v_max, beta, value);
    Choice {
        value,
        note: format!(
            "c0 = max(V sqrt(Cp / (2 x {DENSITY_VARIATION})), 10 V, 10 sqrt(g D)) = max({c_imp:.2}, {c_mach:.2}, {c_hyd:.2}) \
             = {value:.2} m/s (V = {v_max:.3} m/s, Cp Wagner {cp:.3} at deadrise {:.1} deg, D = {tank_depth:.3} m, \
             the depth of the tank the run uses); Mach number of Wagner's wetted contact (pi/2) V cot(beta) / c0 \
             = {mach:.3}: at 0.14, on constant-speed wedges of 20-45 deg, the SPH section force read 7-9 % below \
             its value as c0 grows (a compressibility error of first order in 1/c0; \
             docs/numerics/wedge-convergence.md, item 10)",
            beta.to_degrees()
        ),
    }
}

/// Mach number of Wagner's wetted contact, dc/dt / c0 with dc/dt = (pi/2) V cot(beta) (constant-speed
/// wedge of deadrise beta; Wagner 1932, [`crate::analytic::wagner::wetted_half_width`] per unit time):
/// the automatic c0 puts it at (pi/2) cot(beta) / sqrt((pi^2/4) cot^2(beta) / (2 delta)) = sqrt(2 delta)
/// = 0.14 wherever the pressure bound sets c0. The load error of weakly compressible SPH measured against
/// the similarity solution falls in proportion to it (docs/numerics/wedge-convergence.md, item 10). 0
/// outside 0 < beta < 90 deg (no wetted contact to speak of) and for c0 <= 0.
pub fn contact_mach(v: f64, beta: f64, c0: f64) -> f64 {
    match crate::analytic::wagner::wetted_half_width(beta, v, 1.0) {
        Ok(contact_speed) if c0 > 0.0 => contact_speed / c0,
        _ => 0.0,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn sensor(s_m: f64, width_m: f64) -> SensorSpec {
        SensorSpec {
            name: "P".into(),
            s_m,
            width_m,
        }
    }

    /// Where the pressure bound sets c0, Wagner's wetted contact runs at the Mach number sqrt(2 delta)
    /// whatever the deadrise, and the note says so.
    #[test]
    fn the_automatic_sound_speed_puts_the_contact_at_one_mach_number() {
        for deg in [20.0_f64, 30.0, 45.0] {
            let beta = deg.to_radians();
            let sec = Section::wedge(beta, 0.25, 0.4).unwrap();
            let c = sound_speed(&sec, 5.0, 0.0, 0.5);
            let m = contact_mach(5.0, beta, c.value);
            assert!(
                (m - (2.0 * DENSITY_VARIATION).sqrt()).abs() < 1e-9,
                "{deg}: {m}"
            );
            assert!(c.note.contains(&format!("{m:.3}")), "{}", c.note);
        }
        assert_eq!(contact_mach(5.0, std::f64::consts::FRAC_PI_2, 100.0), 0.0);
        assert_eq!(contact_mach(5.0, 0.0, 100.0), 0.0);
    }

    /// On a steep wedge Wagner's pile-up (pi/2) would end the run before the calm-water line reaches
    /// a sensor at the top of the V; the run now lasts until it does (times the margin).
    #[test]
    fn a_steep_section_runs_until_the_calm_water_line_passes_the_highest_sensor() {
        let beta = 60f64.to_radians();
        let b = 0.1;
        let sec = Section::wedge(beta, b, 1.5 * b * beta.tan()).unwrap();
        let side = b / beta.cos();
        let q = [sensor(side - 0.01, 0.02)];
        let v = 2.0;
        let c = end_time(&sec, &Motion::Constant { speed: v }, &q, 0.002, 0.0);
        let z_top = sensor_top_height(&sec, &q).unwrap();
        assert!((z_top - b * beta.tan()).abs() < 1e-9, "{z_top}");
        let wagner = wetting_penetration(&sec, b).unwrap();
        assert!(wagner < 0.7 * z_top, "Wagner {wagner} vs {z_top}");
        assert!(
            (c.value - END_MARGIN * z_top / v).abs() < 1e-9,
            "{} {}",
            c.value,
            c.note
        );
        assert!(c.note.contains("calm-water line"), "{}", c.note);
    }

    /// Where Wagner's wetting of the chine comes later than the calm-water line at the highest sensor
    /// (a low sensor on a shallow wedge) the rule is unchanged.
    #[test]
    fn a_low_sensor_on_a_shallow_wedge_keeps_the_wagner_end_time() {
        let beta = 20f64.to_radians();
        let b = 0.2;
        let sec = Section::wedge(beta, b, 1.5 * b * beta.tan()).unwrap();
        let q = [sensor(0.05, 0.01)];
        let v = 3.0;
        let c = end_time(&sec, &Motion::Constant { speed: v }, &q, 0.002, 0.0);
        let wagner = wetting_penetration(&sec, b).unwrap();
        assert!(
            (c.value - END_MARGIN * wagner / v).abs() < 1e-9,
            "{} {}",
            c.value,
            c.note
        );
        assert!(c.note.contains("Wagner"), "{}", c.note);
    }

    /// A velocity table that ends with the section still creeping down, short of the depth the impact
    /// needs (a strip-theory profile cut at the keel's full immersion by the relative motion, whose
    /// integral of V falls short of it), ends the run at the table's end rather than holding the last
    /// velocity to the 60 s cap; a table that reaches the depth keeps the usual end time, found to rounding
    /// rather than to the search step.
    #[test]
    fn a_velocity_table_ends_the_run_at_its_end_at_the_latest() {
        let beta = 20f64.to_radians();
        let b = 0.2;
        let sec = Section::wedge(beta, b, 1.5 * b * beta.tan()).unwrap();
        let q = [sensor(0.05, 0.01)];
        let creeping = Motion::prescribed(&[0.0, 0.01, 0.02], &[3.0, 1.0, 0.02]).unwrap();
        let c = end_time(&sec, &creeping, &q, 0.002, 0.0);
        assert_eq!(c.value, 0.02, "{}", c.note);
        assert!(c.note.contains("velocity table ends"), "{}", c.note);
        let long = Motion::prescribed(&[0.0, 1.0], &[3.0, 3.0]).unwrap();
        let steady = end_time(&sec, &Motion::Constant { speed: 3.0 }, &q, 0.002, 0.0);
        let c = end_time(&sec, &long, &q, 0.002, 0.0);
        assert!(
            (c.value - steady.value).abs() < 1e-9 * steady.value,
            "{} against {}: {}",
            c.value,
            steady.value,
            c.note
        );
        assert!(c.value < 1.0, "{}", c.note);
    }
}
