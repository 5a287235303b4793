use super::*;
use crate::analytic::{von_karman, wagner};

fn wedge(deg: f64) -> [[f64; 2]; 2] {
    let b = 0.5;
    [[0.0, 0.0], [b, b * deg.to_radians().tan()]]
}

fn times(n: usize, dt: f64) -> Vec<f64> {
    (0..n).map(|k| k as f64 * dt).collect()
}

/// Wedge at constant speed, values at t = 10 ms, V = 1 m/s (printed with `--nocapture`). Values
/// computed with this module (F/(rho V^3 t); Cp = 2 p_max/(rho V^2)):
///
/// | deadrise | F MLM  | F Wagner | F von Karman | Cp MLM | Cp Wagner |
/// |----------|--------|----------|--------------|--------|-----------|
/// | 10 deg   | 209.3  | 249.3    | 101.0        | 81.80  | 79.36     |
/// | 20 deg   | 42.87  | 58.51    | 23.71        | 20.98  | 18.63     |
/// | 30 deg   | 15.09  | 23.25    | 9.425        | 9.620  | 7.402     |
///
/// The MLM force lies below Wagner's (as Korobkin 2004 reports for the MLM) and above von Karman's
/// (no pile-up, the lower bound of `von_karman`). The self-similar wedge flow makes F/(rho V^3 t) constant.
#[test]
fn wedge_force_lies_between_von_karman_and_wagner_and_is_self_similar() {
    for deg in [10.0f64, 20.0, 30.0, 45.0] {
        let beta = deg.to_radians();
        let t = times(101, 1e-4);
        let m = Mlm::new(&wedge(deg), &t, &vec![1.0; t.len()], 1000.0).unwrap();
        let s = m.history().states[100];
        let f = m.force(&s);
        let fw = wagner::force(beta, 1000.0, 1.0, s.t).unwrap();
        let fv = von_karman::force(beta, 1000.0, 1.0, s.t).unwrap();
        let (x, p) = m.peak(&s);
        println!(
            "{deg}: F/(rho V^3 t) MLM {:.4} Wagner {:.4} vK {:.4}; Cp MLM {:.4} at x/c {:.5}, Wagner {:.4}",
            f / (1000.0 * s.t),
            fw / (1000.0 * s.t),
            fv / (1000.0 * s.t),
            2.0 * p / 1000.0,
            x / s.c,
            wagner::peak_pressure_coefficient(beta).unwrap()
        );
        assert!(fv < f && f < fw, "{deg}: {fv} < {f} < {fw}");
        let s50 = m.history().states[50];
        let ratio = (m.force(&s50) / s50.t) / (f / s.t);
        assert!((ratio - 1.0).abs() < 2e-3, "{deg}: {ratio}");
    }
}

/// The formula's own asymptotics near the contact point: p_max -> rho c'^2 (1 + tan^2 beta) / 2 as the
/// deadrise goes to zero (see the module notes), reached just inside x = c.
#[test]
fn wedge_peak_follows_the_contact_point_asymptote() {
    for (deg, tol) in [(10.0f64, 0.005), (20.0, 0.01), (30.0, 0.03)] {
        let beta = deg.to_radians();
        let t = times(21, 1e-4);
        let m = Mlm::new(&wedge(deg), &t, &vec![5.0; t.len()], 1000.0).unwrap();
        let s = m.history().states[20];
        let cd = s.c_dot.unwrap();
        let expect = 0.5 * 1000.0 * cd * cd / beta.cos().powi(2);
        let (x, p) = m.peak(&s);
        assert!((p / expect - 1.0).abs() < tol, "{deg}: {p} vs {expect}");
        assert!(x < s.c && x > 0.9 * s.c);
        let peaks = m.peak_pressure_history();
        assert!(peaks.iter().all(|p| p.is_finite()));
    }
}

/// The only similarity value in the reference data: Zhao & Faltinsen (1993), Cp_max = 17.77 at 20 deg.
/// No published MLM peak value was at hand; the MLM's 20.98 is 18 % above the similarity solution (and
/// Wagner's 18.63 is 5 % above). This pins the comparison so that a change shows.
#[test]
fn wedge_peak_against_zhao_faltinsen_at_20_deg() {
    let t = times(21, 1e-4);
    let m = Mlm::new(&wedge(20.0), &t, &vec![5.0; t.len()], 1000.0).unwrap();
    let (_, p) = m.peak(&m.history().states[20]);
    let cp = 2.0 * p / (1000.0 * 25.0);
    let r = cp / crate::analytic::zhao_faltinsen1993::CP_MAX;
    assert!((1.15..1.22).contains(&r), "{cp} ({r})");
}

#[test]
fn force_is_the_integral_of_the_clipped_distribution() {
    let t = times(21, 1e-4);
    let m = Mlm::new(&wedge(20.0), &t, &vec![5.0; t.len()], 1000.0).unwrap();
    let s = m.history().states[20];
    let d = m.distribution_at(s.t, 200_000).unwrap();
    let mut f: f64 = d
        .windows(2)
        .map(|w| (w[1][0] - w[0][0]) * (w[0][1] + w[1][1]))
        .sum();
    f += (s.c - d.last().unwrap()[0]) * d.last().unwrap()[1];
    assert!(
        (f / m.force(&s) - 1.0).abs() < 2e-3,
        "{f} vs {}",
        m.force(&s)
    );
    assert!(d.iter().all(|p| p[1] >= 0.0));
}

#[test]
fn sensor_means() {
    let beta = 20f64.to_radians();
    let t = times(21, 1e-4);
    let m = Mlm::new(&wedge(20.0), &t, &vec![5.0; t.len()], 1000.0).unwrap();
    let s = m.history().states[20];
    let (x, p) = m.peak(&s);
    let sp = x / beta.cos();
    let narrow = m.sensor_mean(&s, sp - 1e-7, sp + 1e-7);
    assert!((narrow / p - 1.0).abs() < 1e-3, "{narrow} vs {p}");
    let wide = m.sensor_mean(&s, sp - 5e-3, sp + 5e-3);
    assert!(wide < narrow && wide > 0.0);
    let dry = s.c / beta.cos() + 0.01;
    assert_eq!(m.sensor_mean(&s, dry, dry + 0.01), 0.0);
    let h = m.sensor_history(sp - 1e-3, sp + 1e-3);
    assert_eq!(h.len(), 21);
    assert!(h.iter().all(|p| p.is_finite() && *p >= 0.0));
}

#[test]
fn flat_bottom_with_deadrise_is_finite() {
    let half = [[0.0, 0.0], [0.1, 0.0], [0.25, 0.15], [0.25, 0.3]];
    let t = times(400, 1e-4);
    let m = Mlm::new(&half, &t, &vec![5.0; t.len()], 1000.0).unwrap();
    let f = m.force_history();
    let p = m.peak_pressure_history();
    assert!(f.len() > 10);
    assert!(f.iter().chain(&p).all(|v| v.is_finite() && *v >= 0.0));
    let ac = m.acoustic();
    assert!(ac[0] && !ac.last().unwrap());
    assert_eq!(p[0], 1000.0 * WATER_SOUND_SPEED * 5.0);
    // On the flat part and on the vertical side above the chine a sensor reads finite values.
    let k = f.len() - 1;
    let s = m.history().states[k];
    assert!(m.sensor_mean(&s, 0.0, 0.05).is_finite());
    let side = 0.1 + 0.15 * 2f64.sqrt();
    assert_eq!(m.sensor_mean(&s, side + 0.01, side + 0.05), 0.0);
    let d = m.distribution_at(s.t, 100).unwrap();
    assert!(d.iter().all(|q| q[1].is_finite()));
}

#[test]
fn decelerating_entry_is_finite_and_loads_less() {
    let half = [
        [0.0, 0.0],
        [0.05, 0.0],
        [0.3, 0.3 * 25f64.to_radians().tan()],
    ];
    let t = times(300, 1e-4);
    let v: Vec<f64> = t.iter().map(|&tk| 5.0 * (1.0 - 20.0 * tk)).collect();
    let m = Mlm::new(&half, &t, &v, 1000.0).unwrap();
    let f = m.force_history();
    let p = m.peak_pressure_history();
    assert!(f.len() > 100);
    assert!(f.iter().chain(&p).all(|x| x.is_finite() && *x >= 0.0));
    // Same section at a constant 5 m/s: at equal penetration the decelerating body carries less load.
    let c = Mlm::new(&half, &t, &vec![5.0; t.len()], 1000.0).unwrap();
    let k = 100;
    let h = m.history().states[k].h;
    let kc = c.history().states.iter().position(|s| s.h >= h).unwrap();
    assert!(m.force(&m.history().states[k]) < c.force(&c.history().states[kc]));
}

#[test]
fn bulb_and_keel_bar_are_finite() {
    let bulb = [
        [0.0, 0.0],
        [0.08, 0.02],
        [0.12, 0.08],
        [0.1, 0.15],
        [0.06, 0.2],
        [0.3, 0.45],
    ];
    let bar = [[0.0, 0.0], [0.0, 0.02], [0.2, 0.1], [0.2, 0.2]];
    for half in [&bulb[..], &bar[..]] {
        let t = times(300, 1e-4);
        let m = Mlm::new(half, &t, &vec![4.0; t.len()], 1000.0).unwrap();
        let f = m.force_history();
        let p = m.peak_pressure_history();
        assert!(!f.is_empty());
        assert!(f.iter().chain(&p).all(|x| x.is_finite() && *x >= 0.0));
        let s = *m.history().states.last().unwrap();
        assert!(m.sensor_mean(&s, 0.0, 0.5).is_finite());
    }
}

/// Composite Simpson rule on `n` (even) intervals of [a, b]: a brute-force reference.
fn simpson(a: f64, b: f64, n: usize, f: impl Fn(f64) -> f64) -> f64 {
    let h = (b - a) / n as f64;
    let inner: f64 = (1..n)
        .map(|k| (if k % 2 == 1 { 4.0 } else { 2.0 }) * f(a + k as f64 * h))
        .sum();
    (f(a) + inner + f(b)) * h / 3.0
}

/// The panel means of [`Mlm::sensor_means`] (one cumulative integral along the arc) equal the direct
/// per-panel quadrature of [`Mlm::sensor_mean`] and a brute-force Simpson rule of the pressure along the
/// arc, on contiguous 5 %-of-girth panels of a wedge and of a flat keel with a chine and a vertical side,
/// in the MLM and the acoustic stage.
#[test]
fn panel_means_from_the_cumulative_integral_equal_direct_quadrature() {
    let sections: [&[[f64; 2]]; 2] = [
        &wedge(20.0),
        &[[0.0, 0.0], [0.1, 0.0], [0.25, 0.15], [0.25, 0.3]],
    ];
    for half in sections {
        let t = times(200, 1e-4);
        let m = Mlm::new(half, &t, &vec![5.0; t.len()], 1000.0).unwrap();
        let girth = m.contour.last().unwrap()[2];
        let panels: Vec<(f64, f64)> = (0..20)
            .map(|k| (0.05 * k as f64 * girth, 0.05 * (k + 1) as f64 * girth))
            .collect();
        let states = &m.history().states;
        let mut checked = 0;
        for s in states.iter().step_by(states.len() / 7) {
            let fast = m.sensor_means(s, &panels);
            let p_max = m.peak(s).1;
            for (&(a, b), &pf) in panels.iter().zip(&fast) {
                let direct = m.sensor_mean(s, a, b);
                let tol = 5e-3 * direct.abs() + 1e-6 * p_max;
                assert!(
                    (pf - direct).abs() <= tol,
                    "t {}: panel [{a}, {b}]: {pf} vs {direct}",
                    s.t
                );
                checked += usize::from(direct > 0.0);
            }
            // The panel with the contact point against a brute-force rule (the peak lies in it).
            let sc = m.arc_of_y(s.c).unwrap();
            let j = panels.iter().position(|p| p.0 <= sc && sc < p.1).unwrap();
            let (a, b) = panels[j];
            let brute = simpson(a, b, 400_000, |x| m.pressure_at_arc(s, x)) / (b - a);
            assert!(
                (fast[j] - brute).abs() <= 5e-3 * brute.abs() + 1e-6 * p_max,
                "t {}: {} vs brute force {brute}",
                s.t,
                fast[j]
            );
        }
        assert!(checked > 10, "{checked} wetted panels checked");
        let h = m.sensor_histories(&panels);
        assert_eq!((h.len(), h[0].len()), (20, states.len()));
    }
}

/// The MLM's own wedge peak (its peak search at 5 m/s, 2 ms) is the closed form
/// pi^2 / (4 sin^2 beta) - sin^2 beta of `similarity_table` within 0.5 % from 5 to 55 deg, and the
/// wedge-equivalent correction brings it to the tabulated similarity Cp_max within 0.5 % (the
/// correction is built on that table: this checks the code path, the interpolation error is checked
/// against fresh solves in `similarity::tests`).
#[test]
fn corrected_wedge_peak_is_the_similarity_peak() {
    use crate::analytic::similarity_table as tab;
    for deg in tab::DEADRISE_DEG {
        let t = times(21, 1e-4);
        let m = Mlm::new(&wedge(deg), &t, &vec![5.0; t.len()], 1000.0).unwrap();
        let s = m.history().states[20];
        let q = 0.5 * 1000.0 * 25.0;
        let cp = m.peak(&s).1 / q;
        let closed = tab::mlm_wedge_cp_max(deg.to_radians());
        assert!((cp / closed - 1.0).abs() < 5e-3, "{deg}: {cp} vs {closed}");
        let corrected = m.corrected_peak(&s).1 / q;
        let sim = tab::cp_max(deg).unwrap();
        assert!(
            (corrected / sim - 1.0).abs() < 5e-3,
            "{deg}: {corrected} vs {sim}"
        );
        let k = m.correction(&s);
        assert!(!k.above_table && k.factor < 1.0, "{deg}: {k:?}");
    }
}

/// On a section whose side steepens above 55 deg the correction says so, and a flat keel's acoustic
/// samples are not corrected.
#[test]
fn correction_above_the_table_and_at_a_flat_keel() {
    let half = [
        [0.0, 0.0],
        [0.1, 0.0],
        [0.2, 0.1 * 70f64.to_radians().tan()],
    ];
    let t = times(200, 1e-4);
    let m = Mlm::new(&half, &t, &vec![2.0; t.len()], 1000.0).unwrap();
    let k = m.corrections();
    assert_eq!(k.len(), m.times().len());
    for ((c, a), s) in k.iter().zip(m.acoustic()).zip(&m.history().states) {
        if a || s.c <= 0.1 {
            assert_eq!(c.factor, 1.0);
        }
    }
    assert!(k.iter().any(|c| c.above_table), "{k:?}");
}
