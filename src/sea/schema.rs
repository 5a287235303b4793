//! The `sea_state.toml` file as written by the user.

use serde::Deserialize;
use toml::Spanned;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct SeaFile {
    pub name: String,
    pub description: Option<String>,
    pub water_depth_m: Option<Spanned<f64>>,
    pub heading: Option<Spanned<String>>,
    pub speeds_m_s: Option<Spanned<Vec<Spanned<f64>>>>,
    pub speeds_kn: Option<Spanned<Vec<Spanned<f64>>>>,
    pub froude_numbers: Option<Spanned<Vec<Spanned<f64>>>>,
    #[serde(default)]
    pub regular: Vec<Spanned<RegularRaw>>,
    #[serde(default)]
    pub irregular: Vec<Spanned<IrregularRaw>>,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct RegularRaw {
    pub name: Option<String>,
    pub height_m: Spanned<f64>,
    pub period_s: Option<Spanned<f64>>,
    pub wavelength_m: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize, Clone, Copy, PartialEq, Eq)]
pub(crate) enum SpectrumKind {
    #[serde(rename = "jonswap")]
    Jonswap,
    #[serde(rename = "pierson-moskowitz")]
    PiersonMoskowitz,
    #[serde(rename = "ittc", alias = "bretschneider")]
    Ittc,
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct IrregularRaw {
    pub name: Option<String>,
    pub spectrum: Spanned<SpectrumKind>,
    pub hs_m: Spanned<f64>,
    pub tp_s: Option<Spanned<f64>>,
    pub tz_s: Option<Spanned<f64>>,
    pub gamma: Option<Spanned<f64>>,
    pub duration_h: Option<Spanned<f64>>,
}
