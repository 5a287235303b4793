//! The physical conditions of a case's computation, stated in its outputs and report (issue 26): the
//! water density and the scale. Wedge, drop and quoted-panel cases compute 2D sections in fresh water at
//! [`WATER_DENSITY`] (the SPH runs' `rho0`, [`crate::sph::case::resolve`], and the analytic references
//! here), at the dimensions of the experiment; ship cases read the density and the dimensions of the
//! hull file's loading condition.

use super::Case;
use crate::hull::Hull;

/// Water density of the 2D cases and their analytic references (kg/m3): fresh water, as in the
/// experiments compared (Zhao et al. 1996, Yettou et al. 2006, Breder 2005, Whelan 2004).
pub const WATER_DENSITY: f64 = 1000.0;

/// (condition, value) pairs for the case: water density and scale.
pub fn of(case: &Case) -> Vec<(String, String)> {
    if let (Ok(hull), Ok(loading)) = (case.file("hull"), case.text("loading")) {
        return match Hull::from_file(&hull) {
            Ok(h) => match h.loading(Some(&loading)) {
                Ok(l) => vec![
                    (
                        "water density".into(),
                        format!("{} kg/m³ (hull file, loading '{}')", l.rho, l.name),
                    ),
                    (
                        "scale".into(),
                        format!(
                            "the hull file's dimensions, Lpp {} m ({}), not scaled",
                            h.lpp, h.name
                        ),
                    ),
                ],
                Err(e) => vec![("water density".into(), format!("not known: {e}"))],
            },
            Err(e) => vec![("water density".into(), format!("not known: {e}"))],
        };
    }
    if let Ok(rho) = case.number("water_density_kg_per_m3") {
        return vec![
            (
                "water density".into(),
                format!("{rho} kg/m³ (case parameter)"),
            ),
            (
                "scale".into(),
                "model scale of the published test (the reference's own numbers)".into(),
            ),
        ];
    }
    match case.kind.as_str() {
        "whelan2004-peak-pressure" | "yettou2006-momentum-models" | "breder2005-load-ratio" => {
            vec![
                (
                    "water density".into(),
                    format!("{WATER_DENSITY} kg/m³ (fresh water)"),
                ),
                (
                    "scale".into(),
                    "2D section at the dimensions of the experiment, not scaled".into(),
                ),
            ]
        }
        k if k.starts_with("wedge-") || k.starts_with("zhao1996") || k.starts_with("yettou") => {
            vec![
                (
                    "water density".into(),
                    format!("{WATER_DENSITY} kg/m³ (fresh water; the SPH rho0 and the theory)"),
                ),
                (
                    "scale".into(),
                    "2D section at the dimensions in the case file, not scaled".into(),
                ),
            ]
        }
        _ => vec![(
            "water density".into(),
            "not used by this computation".into(),
        )],
    }
}
