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
//! * 1 - S_d,i is the part of its kernel that no dummy fills: about 1/4 for the band's first layer (dp/2
//!   deep) and 0.03 for the second (1.5 dp); the third and innermost layer (2.5 dp) also reads about 1/4,
//!   the part of its kernel in the empty inside of the body.
//!
//! A *face dummy*, one whose kernel reaches out of the body (1 - S_d,i >= [`FACE_FRACTION`]), takes
//! phi_i = clamp(S_f,i / (1 - S_d,i), 0, 1), the wetted fraction of the space outside the wall beside it. A
//! deeper dummy takes the phi of the nearest face dummy within its kernel (the lower storage index where
//! two are equally near, so the result does not depend on the thread count), or 1 where there is none
//! (it then has no water within its kernel and its weight does not enter any sum). Each body dummy's
//! volume becomes phi_i V_i from the boundary pass of one step to the next one's, so the momentum pass,
//! the sensors' panel forces, the section force, the continuity pass and the shifting all see the same
//! wall. In full contact phi = 1 and the scheme is the one without the rule.
//!
//! The wetness is taken at the face because the second layer's outside part (0.03) is too small to
//! divide by: measured per dummy, a guard on the divisor decided its weight and held the wetted wall at
//! about half strength (item 29). The innermost layer counts as a face by this measure, with water in its
//! kernel only once the water is within half a spacing of the wall, and then at the edge of the support
//! (W below 1e-4 W(0)): it weighs about nothing either way. The parts differ by an order of magnitude, so
//! [`FACE_FRACTION`] between 0.05 and 0.2 gives the same digits: the rule has no parameter that moves its
//! result.
//!
//! At the start of a section immersed at rest (a flare event) the water stands off the wall by the
//! initial lattice's gap (at least dp/2 from the contour), and the face dummies under the water read
//! 0.3-0.6; on a 30 deg wedge at 20 particles per half-beam they settle to about 0.8 within 0.05 s. A keel
//! entry has no such start: the wall meets the water as it moves.
//!
//! Measured against the nonlinear similarity solution of constant-speed wedge entry (item 29; refined
//! tank, force-panel sensors, shifting and the corrected divergence): at 80 particles per half-beam every
//! sensor of the 20, 30 and 45 deg wedges reads within 10 %, and the mean error falls with refinement at
//! each angle. Without the shifting and the corrected divergence the 30 and 45 deg wedges read up to 20
//! and 49 % off, so the rule is offered with them and not alone as a default.
//!
//! The refined tank keeps its coarse particles more than a kernel support from the body, so the sums
//! use the base kernel only.

use rayon::prelude::*;

use crate::sph::kernel::WendlandC2;
use crate::sph::neighbours::{Grid, for_each_neighbour};
use crate::sph::particles::{Kind, Particles};

/// The outside part 1 - S_d of a dummy's kernel at and above which the dummy is on the body's face.
pub const FACE_FRACTION: f64 = 0.1;

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

/// Per body dummy, the water's and the dummies' kernel sums (S_f, S_d); `None` for other particles.
fn kernel_sums(grid: &Grid, pt: &Particles, kernel: &WendlandC2) -> Vec<Option<(f64, f64)>> {
    (0..pt.len())
        .into_par_iter()
        .with_min_len(1024)
        .map(|i| {
            if pt.kind[i] != Kind::Body {
                return None;
            }
            let (mut sf, mut sd) = (0.0, kernel.w(0.0) * pt.vol[i]);
            for_each_neighbour(
                grid,
                &pt.y,
                &pt.z,
                pt.y[i],
                pt.z[i],
                i,
                kernel.support2(),
                |j, _, _, r2, _| {
                    let w = kernel.w(r2.sqrt()) * pt.vol[j];
                    if pt.kind[j].is_fluid() {
                        sf += w;
                    } else {
                        sd += w;
                    }
                },
            );
            Some((sf, sd))
        })
        .collect()
}

/// Per body dummy, its wetness phi (module doc); `None` for other particles.
pub fn wetness(grid: &Grid, pt: &Particles, kernel: &WendlandC2) -> Vec<Option<f64>> {
    let sums = kernel_sums(grid, pt, kernel);
    let on_face = |sd: f64| 1.0 - sd >= FACE_FRACTION;
    let face_phi = |sf: f64, sd: f64| (sf / (1.0 - sd)).clamp(0.0, 1.0);
    (0..pt.len())
        .into_par_iter()
        .with_min_len(1024)
        .map(|i| {
            let (sf, sd) = sums[i]?;
            if on_face(sd) {
                return Some(face_phi(sf, sd));
            }
            let mut nearest: Option<(f64, usize)> = None;
            for_each_neighbour(
                grid,
                &pt.y,
                &pt.z,
                pt.y[i],
                pt.z[i],
                i,
                kernel.support2(),
                |j, _, _, r2, _| {
                    if let Some((_, sdj)) = sums[j] {
                        let nearer = nearest.is_none_or(|(b, k)| r2 < b || (r2 == b && j < k));
                        if on_face(sdj) && nearer {
                            nearest = Some((r2, j));
                        }
                    }
                },
            );
            Some(nearest.map_or(1.0, |(_, j)| {
                let (sfj, sdj) = sums[j].expect("a face dummy has sums");
                face_phi(sfj, sdj)
            }))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use crate::sph::Simulation;
    use crate::sph::body::Section;
    use crate::sph::case::{self, MotionSpec, Overrides};
    use crate::sph::particles::Kind;

    /// A 30 deg wedge entering at 5 m/s (20 particles per half-beam, shifting and the corrected
    /// divergence), 7 spacings deep: the body dummies of the first two layers under the wetted wall (more
    /// than a kernel support below the still-water line, water within 2.2 dp) count with their full
    /// volume, and those more than a support above the highest water with none. A wetness measured per
    /// dummy with a guard on its divisor reads the second layer 0.4-0.6 there (item 29 of
    /// `docs/numerics/wedge-convergence.md`).
    #[test]
    fn the_wetted_wall_counts_in_its_first_layers_and_the_dry_wall_not_at_all() {
        let section = Section::wedge(30f64.to_radians(), 0.1, 0.1).unwrap();
        let setup = case::resolve(
            "wetness",
            &section,
            &MotionSpec::Constant { speed_m_s: 5.0 },
            vec![],
            &Overrides {
                particles_per_half_beam: Some(20.0),
                wall_wetness: Some(true),
                shifting: Some(true),
                divergence_correction: Some(true),
                ..Default::default()
            },
        )
        .unwrap();
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
            } else if z > top + support {
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
}
