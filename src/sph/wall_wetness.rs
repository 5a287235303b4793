//! Wall wetness: each body dummy counts in the pair sums only as far as the body's face beside it is
//! wetted (`[numerics] wall_wetness = true`, `--wall-wetness`).
//!
//! The dummy particles of Adami et al. (2012) stand for the wall with their full lattice volume V = dp^2
//! wherever they are, so a dummy beside a spray root that water has only begun to reach pushes on that
//! water as if the wall were fully wetted, and the water near the root and ahead of it is compressed
//! before it touches the hull (the early over-read and the late, wide root of
//! `docs/numerics/wedge-convergence.md`, items 27-29). The rule weights each body dummy by the water
//! fraction of the part of its kernel outside the body, measured at the body's face.
//!
//! For a body dummy i, with the Wendland C2 kernel W of the base resolution:
//!
//! * S_f,i = sum_{j water} W(r_ij) V_j, the water's kernel sum;
//! * S_d,i = W(0) V_i + sum_{j dummy} W(r_ij) V_j, the dummies' (the body's and the tank's);
//! * O_i = integral of W(|x - x_i|) over the part of the support outside the section contour, computed
//!   once from the contour ([`face_outside`], a midpoint quadrature on cells of dp / 16: within 0.1 % of
//!   the exact value beside a plane wall and about 1 % at the contour's corners). The body
//!   dummies move with the body, so O_i is carried with the particle.
//!
//! A *face dummy* is one within one spacing of the contour: the band's first layer, dp/2 deep (the
//! band's layers are at (k + 1/2) dp within 0.3 dp, [`crate::sph::dummy_band`]). It takes
//!
//! phi_i = clamp(S_f,i / min(1 - S_d,i, O_i), 0, 1),
//!
//! the wetted fraction of the space outside the wall beside it. The divisor is that space measured two
//! ways. 1 - S_d is what the dummies leave empty, as the lattice sees it: beside a plane wall it is the
//! water's own kernel sum under full contact (about 0.25 for the first layer, where the continuous O is
//! 0.27, so S_f / O would read a fully wetted plane wall 0.94-0.97), but it also counts what no water can
//! fill, the holes of the band at a V keel and the body's empty inside beyond the band. O counts only the
//! outside. The smaller of the two is the space the water can fill as the lattice measures it.
//!
//! A deeper dummy takes the phi of the nearest face dummy within its kernel (the lower storage index where
//! two are equally near, so the result does not depend on the thread count), or 1 where there is none
//! (it then has no water within its kernel and its weight does not enter any sum). Each body dummy's
//! volume becomes phi_i V_i from the boundary pass of one step to the next one's, so the momentum pass,
//! the sensors' panel forces, the section force, the continuity pass and the shifting all see the same
//! wall. In full contact phi = 1 and the scheme is the one without the rule.
//!
//! Until 2026-12-01 (`docs/numerics/wedge-convergence.md`, items 29-31) the face was found from the kernel
//! sums alone (1 - S_d >= 0.1) and phi was S_f / (1 - S_d). At a V keel that misreads a wetted wall: on
//! Ochi's 0.093 Lpp section (44.5 deg at the keel) the band's second layer next to the keel has 1 - S_d
//! of 0.11-0.23, mostly the holes and the inside, so it counted as a face with phi 0.11-0.20 under water,
//! and the first layer read 0.78-0.91; the wall next to the keel was weakened, and water particles
//! reached it (44 contact corrections at 40 particles, all within 3.3 spacings of the keel). Measured
//! from the contour the same dummies read 1.
//!
//! At the start of a section immersed at rest (a flare event) the water stands off the wall by the
//! initial lattice's gap (at least dp/2 from the contour, more where the lattice is cut along a sloping
//! wall), and the face dummies under the water read 0.24-0.67 (a 30 deg wedge at 20 and 40 particles per
//! half-beam). The water closes the gap: moving down at 0.05 m/s, nearly at rest, they read 0.90-1
//! after 0.02 s at 40 particles and after 0.04 s at 20, and 0.92-1 at both after 0.05 s (gravity: the
//! free fall of a 2.5 mm gap takes 23 ms); at 0.5 m/s, 0.95-1 after 0.01 s. A flare panel is reached
//! tenths of a second after the start. A keel entry has no such start: the wall meets the water as it
//! moves.
//!
//! Measured against the nonlinear similarity solution of constant-speed wedge entry (items 29-31; refined
//! tank, force-panel sensors, shifting and the corrected divergence): at 80 particles per half-beam the
//! mean sensor error is 4.2, 4.5 and 4.6 % at 20, 30 and 45 deg, every 20 and 30 deg sensor within 10 %
//! and every 45 deg one within 12.2 % (those peaks are the re-attachments of item 11, which the smallest
//! change near the keel moves by up to 25 %); the section force reads 4-6 % low at the automatic sound
//! speed and within 1 % at twice it (item 31). Without the shifting and the corrected divergence the 30
//! and 45 deg wedges read up to 20 and 49 % off, so the rule is offered with them and not alone as a
//! default.
//!
//! The refined tank keeps its coarse particles more than a kernel support from the body, so the sums
//! use the base kernel only.

use rayon::prelude::*;

use crate::sph::body::{Section, distance_to_polyline};
use crate::sph::kernel::WendlandC2;
use crate::sph::neighbours::{Grid, for_each_neighbour};
use crate::sph::particles::{Kind, Particles};

/// Sub-cells per particle spacing of the quadrature of [`face_outside`].
pub const QUADRATURE_CELLS_PER_DP: f64 = 16.0;

/// For each point of the band of body dummies `band` (body frame), its face part O (module doc): the
/// integral of the kernel over the part of its support outside the section, for a dummy within one
/// spacing of the contour (the band's first layer), and 0 for a deeper one. Midpoint quadrature on
/// square cells of dp / [`QUADRATURE_CELLS_PER_DP`]; the full section is used, so with a symmetry plane
/// the outside across it (where the mirror images of the water are) counts too.
pub fn face_outside(
    section: &Section,
    band: &[[f64; 2]],
    dp: f64,
    kernel: &WendlandC2,
) -> Vec<f64> {
    face_outside_on_cells(section, band, dp, kernel, QUADRATURE_CELLS_PER_DP)
}

/// [`face_outside`] with `cells_per_dp` quadrature cells per spacing.
fn face_outside_on_cells(
    section: &Section,
    band: &[[f64; 2]],
    dp: f64,
    kernel: &WendlandC2,
    cells_per_dp: f64,
) -> Vec<f64> {
    let contour = section.closed_contour();
    let cell = dp / cells_per_dp;
    let n = (kernel.support() / cell).ceil() as i64;
    band.par_iter()
        .map(|p| {
            if distance_to_polyline(&contour, p[0], p[1]) >= dp {
                return 0.0;
            }
            let mut sum = 0.0;
            for a in -n..n {
                for b in -n..n {
                    let (dy, dz) = ((a as f64 + 0.5) * cell, (b as f64 + 0.5) * cell);
                    let r2 = dy * dy + dz * dz;
                    if r2 < kernel.support2() && !section.contains(p[0] + dy, p[1] + dz) {
                        sum += kernel.w(r2.sqrt());
                    }
                }
            }
            sum * cell * cell
        })
        .collect()
}

/// Multiply each body dummy's volume by its wetness phi (module doc). Call after the boundary pass has
/// set the dummies' volumes to the lattice volume.
pub fn weight_body_dummies(grid: &Grid, pt: &mut Particles, kernel: &WendlandC2) {
    let phi = wetness(grid, pt, kernel);
    pt.vol
        .par_iter_mut()
        .with_min_len(4096)
        .zip(phi.par_iter())
        .for_each(|(v, f)| {
            if let Some(f) = f {
                *v *= f;
            }
        });
}

/// Visit the particles within the kernel support of particle i: (j, r^2).
fn for_each_near(
    grid: &Grid,
    pt: &Particles,
    i: usize,
    kernel: &WendlandC2,
    mut f: impl FnMut(usize, f64),
) {
    let (y, z) = (pt.y[i], pt.z[i]);
    for_each_neighbour(
        grid,
        &pt.y,
        &pt.z,
        y,
        z,
        i,
        kernel.support2(),
        |j, _, _, r2, _| f(j, r2),
    );
}

/// Per body dummy on the face, phi = clamp(S_f / min(1 - S_d, O), 0, 1); `None` for every other
/// particle.
fn face_wetness(grid: &Grid, pt: &Particles, kernel: &WendlandC2) -> Vec<Option<f64>> {
    (0..pt.len())
        .into_par_iter()
        .with_min_len(1024)
        .map(|i| {
            // `face_outside` is empty in a run without a section (no body dummies then).
            let o = pt.face_outside.get(i).copied().unwrap_or(0.0);
            if pt.kind[i] != Kind::Body || o <= 0.0 {
                return None;
            }
            let (mut sf, mut sd) = (0.0, kernel.w(0.0) * pt.vol[i]);
            for_each_near(grid, pt, i, kernel, |j, r2| {
                let w = kernel.w(r2.sqrt()) * pt.vol[j];
                if pt.kind[j].is_fluid() {
                    sf += w;
                } else {
                    sd += w;
                }
            });
            Some((sf / (1.0 - sd).min(o)).clamp(0.0, 1.0))
        })
        .collect()
}

/// Per body dummy, its wetness phi (module doc); `None` for other particles.
pub fn wetness(grid: &Grid, pt: &Particles, kernel: &WendlandC2) -> Vec<Option<f64>> {
    let face = face_wetness(grid, pt, kernel);
    (0..pt.len())
        .into_par_iter()
        .with_min_len(1024)
        .map(|i| {
            if pt.kind[i] != Kind::Body {
                return None;
            }
            if face[i].is_some() {
                return face[i];
            }
            let mut nearest: Option<(f64, usize)> = None;
            for_each_near(grid, pt, i, kernel, |j, r2| {
                let nearer = nearest.is_none_or(|(b, k)| r2 < b || (r2 == b && j < k));
                if face[j].is_some() && nearer {
                    nearest = Some((r2, j));
                }
            });
            Some(nearest.map_or(1.0, |(_, j)| face[j].expect("a face dummy has a wetness")))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::{QUADRATURE_CELLS_PER_DP, face_outside, face_outside_on_cells};
    use crate::sph::Simulation;
    use crate::sph::body::Section;
    use crate::sph::body::distance_to_polyline;
    use crate::sph::case::{self, MotionSpec, Overrides};
    use crate::sph::dummy_band::dummy_points;
    use crate::sph::kernel::WendlandC2;
    use crate::sph::particles::Kind;

    /// The face part of a first-layer dummy on a plane bottom is the kernel's integral over the half
    /// plane beyond dp/2 (here by Simpson's rule across and along the wall, independent of the
    /// quadrature under test, within 0.2 %); deeper dummies have none; on a 20 deg V keel the quadrature
    /// at dp / 16 is within 0.005 of the one at dp / 64 for every face dummy (2 % of a plane wall's face
    /// part; the largest differences, about 1 % of the dummy's own value, are at the contour's corners, the
    /// knuckle and the deck edge, where a cell-cut corner converges slowly).
    #[test]
    fn the_face_part_is_the_kernel_outside_the_contour() {
        let dp = 0.005;
        let kernel = WendlandC2::new(1.5 * dp);
        let support = kernel.support();
        let simpson = |f: &dyn Fn(f64) -> f64, a: f64, b: f64| {
            let n = 400;
            let step = (b - a) / n as f64;
            (0..=n)
                .map(|k| {
                    let c = if k == 0 || k == n {
                        1.0
                    } else if k % 2 == 1 {
                        4.0
                    } else {
                        2.0
                    };
                    c * f(a + k as f64 * step)
                })
                .sum::<f64>()
                * step
                / 3.0
        };
        let half_plane = simpson(
            &|x: f64| {
                let half_chord = (support * support - x * x).max(0.0).sqrt();
                simpson(
                    &|y: f64| kernel.w((x * x + y * y).sqrt()),
                    -half_chord,
                    half_chord,
                )
            },
            0.5 * dp,
            support,
        );
        let flat = Section::from_half_points(vec![[0.0, 0.0], [0.2, 0.0], [0.2, 0.1]]).unwrap();
        let band = dummy_points(&flat, dp, 3, 0.25 * dp);
        let o = face_outside(&flat, &band, dp, &kernel);
        let contour = flat.closed_contour();
        let mut plane = 0;
        for (p, o) in band.iter().zip(&o) {
            let d = distance_to_polyline(&contour, p[0], p[1]);
            if d >= dp {
                assert_eq!(*o, 0.0, "{p:?}");
            } else if p[0] > support && p[0] < 0.2 - support {
                plane += 1;
                assert!((o / half_plane - 1.0).abs() < 0.002, "{o} {half_plane}");
            }
        }
        assert!(plane > 20, "{plane}");
        let vee = Section::wedge(20f64.to_radians(), 0.1, 0.1).unwrap();
        let band = dummy_points(&vee, dp, 3, 0.25 * dp);
        let coarse = face_outside(&vee, &band, dp, &kernel);
        let fine = face_outside_on_cells(&vee, &band, dp, &kernel, 4.0 * QUADRATURE_CELLS_PER_DP);
        let mut worst: f64 = 0.0;
        for (c, f) in coarse.iter().zip(&fine) {
            assert_eq!(*c == 0.0, *f == 0.0);
            if *f > 0.0 {
                worst = worst.max((c - f).abs());
            }
        }
        assert!(worst < 0.005, "{worst}");
    }

    /// A 30 deg wedge (0.1 m half-beam) at `speed` m/s, 20 particles per half-beam, with the rule,
    /// shifting and the corrected divergence; its keel `immersion` m deep at the start, or at the surface.
    fn wedge30_with_the_rule(speed: f64, immersion: Option<f64>) -> case::Setup {
        let section = Section::wedge(30f64.to_radians(), 0.1, 0.1).unwrap();
        case::resolve(
            "wetness",
            &section,
            &MotionSpec::Constant { speed_m_s: speed },
            vec![],
            &Overrides {
                particles_per_half_beam: Some(20.0),
                wall_wetness: Some(true),
                shifting: Some(true),
                divergence_correction: Some(true),
                initial_immersion: immersion,
                ..Default::default()
            },
        )
        .unwrap()
    }

    /// A 30 deg wedge entering at 5 m/s (20 particles per half-beam, shifting and the corrected
    /// divergence), 7 spacings deep: the body dummies of the first two layers under the wetted wall (more
    /// than a kernel support below the still-water line, water within 2.2 dp) count with their full
    /// volume, and those more than a support above the highest water with none. A wetness measured per
    /// dummy with a guard on its divisor reads the second layer 0.4-0.6 there (item 29 of
    /// `docs/numerics/wedge-convergence.md`).
    #[test]
    fn the_wetted_wall_counts_in_its_first_layers_and_the_dry_wall_not_at_all() {
        let setup = wedge30_with_the_rule(5.0, None);
        let dp = setup.dp;
        let mut sim = Simulation::new(setup).unwrap();
        while sim.body.z_keel > -7.0 * dp {
            sim.step().unwrap();
        }
        let support = sim.kernel.support();
        let fluid: Vec<usize> = (0..sim.pt.len())
            .filter(|&j| sim.pt.kind[j].is_fluid())
            .collect();
        let top = fluid.iter().map(|&j| sim.pt.z[j]).fold(f64::MIN, f64::max);
        let (mut wet, mut dry) = (Vec::new(), Vec::new());
        for i in (0..sim.pt.len()).filter(|&i| sim.pt.kind[i] == Kind::Body) {
            let (y, z) = (sim.pt.y[i], sim.pt.z[i]);
            let near = fluid
                .iter()
                .map(|&j| (sim.pt.y[j] - y).hypot(sim.pt.z[j] - z))
                .fold(f64::INFINITY, f64::min);
            let phi = sim.pt.vol[i] / sim.dummy_vol;
            if z < -support && near < 2.2 * dp {
                wet.push(phi);
            } else if z > top + support && sim.pt.face_outside[i] > 0.0 {
                dry.push(phi);
            }
        }
        assert!(
            wet.len() >= 8 && dry.len() >= 8,
            "{} {}",
            wet.len(),
            dry.len()
        );
        assert!(wet.iter().all(|&f| (0.95..=1.0).contains(&f)), "{wet:.3?}");
        assert!(dry.iter().all(|&f| f == 0.0), "{dry:.3?}");
    }

    /// A section that starts immersed (a flare event of `assess`) starts with a gap: the water keeps
    /// dp/2 from the contour, and the lattice cut along a sloping wall leaves more in places, so the
    /// submerged face dummies of a 30 deg wedge at 20 particles per half-beam read phi 0.27-0.59 at the
    /// first step. Moving down at 0.05 m/s, nearly at rest, the water falls into the gap within a few
    /// hundredths of a second (the free fall of a 2.5 mm gap takes 23 ms): by 0.05 s every face dummy under
    /// the water reads at least 0.85 and their median at least 0.9 (measured 0.92 and 0.956; at 0.5 m/s the
    /// motion closes the gap in 10 ms). A flare panel's impact comes tenths of a second later.
    #[test]
    fn the_face_of_a_section_immersed_at_the_start_is_wetted_within_hundredths_of_a_second() {
        let mut sim = Simulation::new(wedge30_with_the_rule(0.05, Some(0.04))).unwrap();
        let support = sim.kernel.support();
        let submerged_face = |sim: &Simulation| {
            let mut phi: Vec<f64> = (0..sim.pt.len())
                .filter(|&i| {
                    sim.pt.kind[i] == Kind::Body
                        && sim.pt.face_outside[i] > 0.0
                        && sim.pt.z[i] < -support
                })
                .map(|i| sim.pt.vol[i] / sim.dummy_vol)
                .collect();
            phi.sort_by(f64::total_cmp);
            phi
        };
        while sim.time < 0.05 {
            sim.step().unwrap();
        }
        let settled = submerged_face(&sim);
        assert!(settled.len() >= 8, "{settled:.3?}");
        assert!(
            settled[0] >= 0.85 && settled[settled.len() / 2] >= 0.9,
            "{settled:.3?}"
        );
    }
}
