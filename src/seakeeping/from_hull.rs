//! Building a [`ShipModel`] from a hull file and a loading condition.

use super::section::HalfSection;
use super::{ShipModel, StripSection};
use crate::error::{Error, Result};
use crate::hull::{Hull, Hydrostatics, LoadingCondition};

impl ShipModel {
    /// Strips at `n_stations` equally spaced stations over the hull's offsets, each cut at the local
    /// waterline of `loading` (trim included) and expressed in that waterline's frame. Mass, LCG, KG and
    /// k_yy come from the loading condition (mass and LCG default to buoyancy and LCB, as in
    /// `hull::Hydrostatics`). The vertical centre of gravity is taken relative to the waterline at midship;
    /// for a trimmed ship the sections use their local waterline, a difference of order trim x x_B / Lpp
    /// in z_B that the linear theory neglects.
    pub fn from_hull(
        hull: &Hull,
        loading: &LoadingCondition,
        n_stations: usize,
    ) -> Result<ShipModel> {
        if n_stations < 3 {
            return Err(Error::Invalid(format!(
                "need at least 3 strip stations, got {n_stations}"
            )));
        }
        let (xa, xf) = hull.x_range();
        let area_floor = 1e-9 * hull.lpp * hull.lpp;
        let mut stations = Vec::with_capacity(n_stations);
        for i in 0..n_stations {
            let x = xa + (xf - xa) * i as f64 / (n_stations - 1) as f64;
            let z_w = loading.draft_at(x, hull.lpp);
            let wet = hull.section_at(x)?.wetted(z_w);
            let mut pts: Vec<[f64; 2]> = Vec::with_capacity(wet.len());
            for p in wet {
                let q = [p[0], p[1] - z_w];
                if pts
                    .last()
                    .is_none_or(|l: &[f64; 2]| (l[0] - q[0]).hypot(l[1] - q[1]) > 1e-9 * hull.lpp)
                {
                    pts.push(q);
                }
            }
            let section = if pts.len() >= 2 {
                let h = HalfSection::new(pts).map_err(|e| {
                    Error::Invalid(format!(
                        "{}: station x = {x:.4} m: {e}",
                        hull.source.display()
                    ))
                })?;
                (h.area() > area_floor && h.beam() > 0.0).then_some(h)
            } else {
                None
            };
            stations.push(StripSection { x, section });
        }
        let hs = Hydrostatics::compute(hull, loading);
        let mp = hs.mass_properties(loading);
        let model = ShipModel {
            lpp: hull.lpp,
            rho: loading.rho,
            g: crate::sea::G,
            mass: mp.mass_kg,
            xg: mp.lcg_m,
            zg: mp.kg_m - loading.draft_at(0.0, hull.lpp),
            k_yy: mp.k_yy_m,
            stations,
        };
        model.validate()?;
        Ok(model)
    }
}
