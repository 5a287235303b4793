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
