//! Hydrostatics against closed forms: the Journee (1992) Wigley III analytic hull (published volume,
//! waterplane area and Cb; data/reference/journee1992_wigley3.toml) and a trimmed box barge.

use slamtool::hull::{Hull, Hydrostatics};
use slamtool::input::SourceText;

/// Wigley III offsets from its analytic form (Journee 1992):
/// 2y/B = (1 − ζ²)(1 − ξ²)(1 + 0.2ξ²), ξ = 2x/L, ζ = z/T − 1 (z from base), sides vertical above the waterline.
fn wigley_text(stations: usize, points: usize) -> String {
    let (l, b, t, depth) = (3.0, 0.3, 0.1875, 0.25);
    let mut s = String::from(
        "name = \"Wigley III\"\nlpp_m = 3.0\ndepth_m = 0.25\n\n[[loading]]\nname = \"design\"\ndraft_fp_m = 0.1875\ndraft_ap_m = 0.1875\nwater_density_kg_m3 = 1000.0\nkg_m = 0.17\nk_yy_m = 0.75\n",
    );
    for i in 0..stations {
        let xi = -1.0 + 2.0 * i as f64 / (stations - 1) as f64;
        let lon = (1.0 - xi * xi) * (1.0 + 0.2 * xi * xi);
        let mut pts = vec![[0.0, 0.0]];
        for j in 1..points {
            let zeta = -1.0 + j as f64 / (points - 1) as f64;
            pts.push([0.5 * b * (1.0 - zeta * zeta) * lon, t * (1.0 + zeta)]);
        }
        pts.push([0.5 * b * lon, depth]);
        pts.dedup_by(|a, b| (a[0] - b[0]).abs() < 1e-12 && (a[1] - b[1]).abs() < 1e-12);
        let list: Vec<String> = pts
            .iter()
            .map(|p| format!("[{:.8}, {:.8}]", p[0], p[1]))
            .collect();
        s += &format!(
            "\n[[station]]\nx_m = {:.8}\npoints = [{}]\n",
            0.5 * l * xi,
            list.join(", ")
        );
    }
    s
}

#[test]
fn wigley_iii_reproduces_published_particulars() {
    let hull =
        Hull::from_source(&SourceText::from_string("wigley.toml", wigley_text(41, 41))).unwrap();
    let hs = Hydrostatics::compute(&hull, &hull.loadings[0]);
    // Journee (1992): volume 0.0780 m3, waterplane area 0.6240 m2, Cb 0.4622.
    let rel = |a: f64, b: f64| (a - b).abs() / b;
    assert!(rel(hs.volume, 0.0780) < 0.005, "volume {}", hs.volume);
    assert!(rel(hs.awp, 0.6240) < 0.005, "Awp {}", hs.awp);
    assert!(rel(hs.cb, 0.4622) < 0.005, "Cb {}", hs.cb);
    // Closed forms of the analytic hull: Cm = 2/3, Cwp = 0.69333, LCB = LCF = 0 by symmetry.
    assert!(rel(hs.cm, 2.0 / 3.0) < 0.005, "Cm {}", hs.cm);
    assert!(rel(hs.cwp, 0.693333) < 0.005, "Cwp {}", hs.cwp);
    assert!(hs.lcb.abs() < 1e-6 && hs.lcf.abs() < 1e-6);
}

#[test]
fn coarse_offsets_converge_to_the_fine_result() {
    let fine = Hull::from_source(&SourceText::from_string("w.toml", wigley_text(81, 61))).unwrap();
    let coarse =
        Hull::from_source(&SourceText::from_string("w.toml", wigley_text(11, 11))).unwrap();
    let vf = Hydrostatics::compute(&fine, &fine.loadings[0]).volume;
    let vc = Hydrostatics::compute(&coarse, &coarse.loadings[0]).volume;
    let exact = 0.3 * 3.0 * 0.1875 * (2.0 / 3.0) * 0.693333;
    assert!(
        (vf - exact).abs() < (vc - exact).abs(),
        "fine {vf} coarse {vc} exact {exact}"
    );
    assert!((vc - exact).abs() / exact < 0.02);
}

#[test]
fn trimmed_box_barge_matches_closed_form() {
    // Box 10 m x 2 m, drafts 0.6 (FP) and 1.4 (AP): volume L B Tm, LCB from the trapezoidal profile.
    let text = "name = \"box\"\nlpp_m = 10.0\ndepth_m = 2.0\n\n[[loading]]\nname = \"trim\"\ndraft_fp_m = 0.6\ndraft_ap_m = 1.4\nkg_m = 1.0\nk_yy_over_lpp = 0.25\n\n[[station]]\naft_of_fp = 1.0\npoints = [[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]\n\n[[station]]\naft_of_fp = 0.0\npoints = [[0.0, 0.0], [1.0, 0.0], [1.0, 2.0]]\n";
    let hull = Hull::from_source(&SourceText::from_string("box.toml", text)).unwrap();
    let l = &hull.loadings[0];
    assert_eq!(l.rho, 1025.0);
    assert!((l.k_yy - 2.5).abs() < 1e-12);
    let hs = Hydrostatics::compute(&hull, l);
    assert!((hs.volume - 20.0).abs() < 1e-9);
    // T(x) = 1 − 0.08 x → ∫ x·2T dx / V = −0.16·(L³/12)/V
    let lcb = -0.16 * 1000.0 / 12.0 / 20.0;
    assert!((hs.lcb - lcb).abs() < 1e-9, "LCB {} vs {lcb}", hs.lcb);
    assert!((hs.trim_by_stern_m - 0.8).abs() < 1e-12);
    // KB = ∫ T²/2 · 2 dx / V with T linear
    let kb = (2.0 * (1.0 * 10.0 + 0.0064 * 1000.0 / 12.0) / 2.0) / 20.0;
    assert!((hs.kb - kb).abs() < 1e-9, "KB {} vs {kb}", hs.kb);
    let m = hs.mass_properties(l);
    assert!(m.lcg_from_lcb && (m.lcg_m - hs.lcb).abs() < 1e-12);
    assert!(m.mass_from_buoyancy && (m.mass_kg - 20.0 * 1025.0).abs() < 1e-6);
}

#[test]
fn section_at_any_station_and_trim() {
    let hull =
        Hull::from_source(&SourceText::from_string("wigley.toml", wigley_text(21, 21))).unwrap();
    // Between stations the interpolated waterline half-breadth follows the analytic hull closely.
    let x = 0.52; // not a station
    let s = hull.section_at(x).unwrap();
    let xi: f64 = 2.0 * x / 3.0;
    let exact = 0.15 * (1.0 - xi * xi) * (1.0 + 0.2 * xi * xi);
    assert!((s.half_breadth_at(0.1875) - exact).abs() < 1e-3);
    let rel = s.relative_to_waterline(0.1875);
    assert!((rel.keel_z() + 0.1875).abs() < 1e-12);
    assert!(hull.section_at(1.6).is_err());
}

/// A prism of constant section between two stations at the perpendiculars.
fn prism(lpp: f64, depth: f64, t_fp: f64, t_ap: f64, points: &[[f64; 2]]) -> Hull {
    let list: Vec<String> = points
        .iter()
        .map(|p| format!("[{:.17e}, {:.17e}]", p[0], p[1]))
        .collect();
    let pts = list.join(", ");
    let text = format!(
        "name = \"prism\"\nlpp_m = {lpp}\ndepth_m = {depth}\n\n[[loading]]\nname = \"c\"\ndraft_fp_m = {t_fp}\ndraft_ap_m = {t_ap}\nkg_m = 0.1\nk_yy_over_lpp = 0.25\n\n[[station]]\naft_of_fp = 1.0\npoints = [{pts}]\n\n[[station]]\naft_of_fp = 0.0\npoints = [{pts}]\n"
    );
    Hull::from_source(&SourceText::from_string("prism.toml", text)).unwrap()
}

fn close(a: f64, b: f64, tol: f64, what: &str) {
    assert!(
        (a - b).abs() <= tol * b.abs().max(1e-12),
        "{what}: {a} vs {b}"
    );
}

#[test]
fn wedge_prism_even_keel_matches_closed_form() {
    // V sections y = z tan θ, draft T: A = T² tan θ, KB = 2T/3, BM_T = (2/3) T tan²θ, BM_L = L²/(6T),
    // Cb = Cm = 1/2, Cp = Cwp = 1.
    let (l, t, tan) = (10.0, 1.0, 0.7_f64);
    let hull = prism(l, 2.0, t, t, &[[0.0, 0.0], [2.0 * tan, 2.0]]);
    let hs = Hydrostatics::compute(&hull, &hull.loadings[0]);
    close(hs.volume, t * t * tan * l, 1e-12, "volume");
    close(hs.kb, 2.0 * t / 3.0, 1e-12, "KB");
    close(hs.bm_t, 2.0 / 3.0 * t * tan * tan, 1e-12, "BM_T");
    close(hs.bm_l, l * l / (6.0 * t), 1e-12, "BM_L");
    close(hs.awp, 2.0 * t * tan * l, 1e-12, "Awp");
    close(hs.cb, 0.5, 1e-12, "Cb");
    close(hs.cm, 0.5, 1e-12, "Cm");
    close(hs.cp, 1.0, 1e-12, "Cp");
    close(hs.cwp, 1.0, 1e-12, "Cwp");
}

#[test]
fn trimmed_wedge_prism_matches_closed_form() {
    // T(x) = Tm + τ x/L with τ = T_FP − T_AP. With A = T² tan θ and b = T tan θ:
    //   ∇ = tan θ L (Tm² + τ²/12), LCB = (Tm τ L/6)/(Tm² + τ²/12), KB = (2/3)(Tm³ + Tm τ²/4)/(Tm² + τ²/12),
    //   A_wp = 2 tan θ L Tm, LCF = τ L/(12 Tm), I_L(about LCF) = 2 tan θ L³ (Tm/12 − τ²/(144 Tm)),
    //   I_T = (2/3) tan³θ L (Tm³ + Tm τ²/4).
    // I_L about midship would be 2 tan θ L³ Tm/12, 5 % larger here: the test tells the two apart.
    let (l, tan) = (10.0, 0.7_f64);
    let (t_fp, t_ap) = (0.6, 1.4);
    let (tm, tau) = (0.5 * (t_fp + t_ap), t_fp - t_ap);
    let hull = prism(l, 2.0, t_fp, t_ap, &[[0.0, 0.0], [2.0 * tan, 2.0]]);
    let hs = Hydrostatics::compute(&hull, &hull.loadings[0]);
    let q2 = tm * tm + tau * tau / 12.0;
    let vol = tan * l * q2;
    close(hs.volume, vol, 1e-12, "volume");
    close(hs.lcb, tm * tau * l / 6.0 / q2, 1e-12, "LCB");
    close(
        hs.kb,
        2.0 / 3.0 * (tm.powi(3) + tm * tau * tau / 4.0) / q2,
        1e-12,
        "KB",
    );
    close(hs.awp, 2.0 * tan * l * tm, 1e-12, "Awp");
    close(hs.lcf, tau * l / (12.0 * tm), 1e-12, "LCF");
    let i_l = 2.0 * tan * l.powi(3) * (tm / 12.0 - tau * tau / (144.0 * tm));
    close(hs.bm_l, i_l / vol, 1e-12, "BM_L about LCF");
    let i_t = 2.0 / 3.0 * tan.powi(3) * l * (tm.powi(3) + tm * tau * tau / 4.0);
    close(hs.bm_t, i_t / vol, 1e-12, "BM_T");
    // Coefficients on Lpp, the widest waterline (at the AP, 2 T_AP tan θ) and the mean draft.
    close(hs.beam_wl_m, 2.0 * t_ap * tan, 1e-12, "B");
    close(hs.cb, vol / (l * hs.beam_wl_m * tm), 1e-12, "Cb");
    close(hs.am, tm * tm * tan, 1e-12, "Am");
}

#[test]
fn half_immersed_circular_section_hull() {
    // Semicircular sections of radius r with the waterline through the centre: A = π r²/2,
    // centroid 4r/(3π) below the waterline (KB = r − 4r/(3π)), BM_T = (2/3) r³/(π r²/2) = 4r/(3π), Cm = π/4.
    // The polygon of n chords has the error of the inscribed polygon, O(1/n²).
    let (r, l, n) = (0.5, 4.0, 400);
    let mut pts: Vec<[f64; 2]> = (0..=n)
        .map(|i| {
            let phi = std::f64::consts::FRAC_PI_2 * i as f64 / n as f64;
            [r * phi.sin(), r - r * phi.cos()]
        })
        .collect();
    pts.push([r, 2.0 * r]);
    let hull = prism(l, 2.0 * r, r, r, &pts);
    let hs = Hydrostatics::compute(&hull, &hull.loadings[0]);
    let pi = std::f64::consts::PI;
    close(hs.volume, pi * r * r / 2.0 * l, 2e-5, "volume");
    close(hs.kb, r - 4.0 * r / (3.0 * pi), 2e-5, "KB");
    close(hs.bm_t, 4.0 * r / (3.0 * pi), 2e-5, "BM_T");
    close(hs.cm, pi / 4.0, 2e-5, "Cm");
    close(hs.cb, pi / 4.0, 2e-5, "Cb");
}

#[test]
fn interpolation_is_shape_preserving_and_degenerates_cleanly_at_the_stem() {
    // A wedge body whose half-breadth grows monotonically aft from a stem that is a vertical line on the
    // centreline; in between, the interpolated waterline half-breadth must stay monotone in x and within
    // the station values (no overshoot), and vanish at the stem.
    let text = "name = \"bow\"\nlpp_m = 4.0\ndepth_m = 1.0\n\n[[loading]]\nname = \"c\"\ndraft_fp_m = 0.5\ndraft_ap_m = 0.5\nkg_m = 0.4\nk_yy_over_lpp = 0.25\n\n\
        [[station]]\nx_m = -2.0\npoints = [[0.0, 0.0], [0.5, 0.0], [0.5, 1.0]]\n\n\
        [[station]]\nx_m = 0.0\npoints = [[0.0, 0.0], [0.5, 0.0], [0.5, 1.0]]\n\n\
        [[station]]\nx_m = 1.0\npoints = [[0.0, 0.0], [0.45, 0.3], [0.5, 1.0]]\n\n\
        [[station]]\nx_m = 1.6\npoints = [[0.0, 0.05], [0.1, 0.5], [0.15, 1.0]]\n\n\
        [[station]]\nx_m = 2.0\npoints = [[0.0, 0.2], [0.0, 1.0]]\n";
    let hull = Hull::from_source(&SourceText::from_string("bow.toml", text)).unwrap();
    let mut prev = f64::INFINITY;
    for i in 0..=400 {
        let x = i as f64 * 0.005;
        let s = hull.section_at(x).unwrap();
        let b = s.half_breadth_at(0.5);
        assert!(
            b <= prev + 1e-12,
            "waterline breadth grows forward at x = {x}: {b} > {prev}"
        );
        assert!((0.0..=0.5 + 1e-12).contains(&b), "overshoot {b} at x = {x}");
        assert!(s.max_half_breadth() <= 0.5 + 1e-12);
        // z never falls along an interpolated contour, and it starts on the centreline.
        assert!(s.points.windows(2).all(|w| w[1][1] >= w[0][1]));
        assert_eq!(s.points[0][0], 0.0);
        prev = b;
    }
    assert_eq!(hull.section_at(2.0).unwrap().half_breadth_at(0.5), 0.0);
    let near = hull.section_at(2.0 - 1e-6).unwrap().half_breadth_at(0.5);
    assert!(near < 1e-5, "{near}");
}
