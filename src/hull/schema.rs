//! The `hull.toml` file as written by the user, before validation. Every number that is checked later
//! keeps its position in the file.

use serde::Deserialize;
use toml::Spanned;

use crate::input::Pair;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct HullFile {
    pub name: Spanned<String>,
    pub description: Option<String>,
    pub lpp_m: Spanned<f64>,
    pub depth_m: Option<Spanned<f64>>,
    pub loading: Spanned<Vec<Spanned<LoadingRaw>>>,
    pub station: Option<Spanned<Vec<Spanned<StationRaw>>>>,
    pub offsets_csv: Option<Spanned<OffsetsCsvRaw>>,
    #[serde(default)]
    pub sensor: Vec<Spanned<SensorRaw>>,
    /// Design pressure limits of `slamtool assess`, read and checked by `assess::limits` (kept here only so
    /// that the table is accepted).
    #[allow(dead_code)]
    pub limits: Option<toml::Value>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct LoadingRaw {
    pub name: Spanned<String>,
    pub draft_fp_m: Spanned<f64>,
    pub draft_ap_m: Spanned<f64>,
    pub water_density_kg_m3: Option<Spanned<f64>>,
    pub displacement_kg: Option<Spanned<f64>>,
    pub lcg_m: Option<Spanned<f64>>,
    pub kg_m: Spanned<f64>,
    pub k_yy_m: Option<Spanned<f64>>,
    pub k_yy_over_lpp: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct StationRaw {
    pub x_m: Option<Spanned<f64>>,
    pub aft_of_fp: Option<Spanned<f64>>,
    pub points: Spanned<Vec<Spanned<Pair>>>,
}

#[derive(Debug, Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(try_from = "String")]
pub(crate) enum StationColumn {
    XM,
    AftOfFp,
}

impl TryFrom<String> for StationColumn {
    type Error = String;
    fn try_from(s: String) -> Result<Self, String> {
        match s.as_str() {
            "x_m" => Ok(Self::XM),
            "aft_of_fp" => Ok(Self::AftOfFp),
            _ => Err(format!(
                "station = \"{s}\" is not a station column kind: use \"x_m\" (m from midship, positive forward) or \"aft_of_fp\" (fraction of Lpp aft of the FP)"
            )),
        }
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct OffsetsCsvRaw {
    pub file: Spanned<String>,
    pub station: StationColumn,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct SensorRaw {
    pub name: Spanned<String>,
    pub x_m: Option<Spanned<f64>>,
    pub aft_of_fp: Option<Spanned<f64>>,
    pub girth_m: Option<Spanned<f64>>,
    pub y_m: Option<Spanned<f64>>,
    pub z_m: Option<Spanned<f64>>,
    pub diameter_m: Spanned<f64>,
}
