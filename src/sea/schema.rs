//! The `sea_state.toml` file as written by the user.

use serde::Deserialize;
use toml::Spanned;

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct SeaFile {
    pub name: Spanned<String>,
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
    pub name: Option<Spanned<String>>,
    pub height_m: Spanned<f64>,
    pub period_s: Option<Spanned<f64>>,
    pub wavelength_m: Option<Spanned<f64>>,
}

#[derive(Debug, Deserialize, Clone, Copy, PartialEq, Eq)]
#[serde(try_from = "String")]
pub(crate) enum SpectrumKind {
    Jonswap,
    PiersonMoskowitz,
    Ittc,
}

impl TryFrom<String> for SpectrumKind {
    type Error = String;
    fn try_from(s: String) -> Result<Self, String> {
        match s.as_str() {
            "jonswap" => Ok(Self::Jonswap),
            "pierson-moskowitz" => Ok(Self::PiersonMoskowitz),
            "ittc" | "bretschneider" => Ok(Self::Ittc),
            _ => Err(format!(
                "spectrum = \"{s}\" is not a known spectrum: use \"jonswap\", \"pierson-moskowitz\" or \"ittc\" (also called \"bretschneider\")"
            )),
        }
    }
}

#[derive(Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub(crate) struct IrregularRaw {
    pub name: Option<Spanned<String>>,
    pub spectrum: Spanned<SpectrumKind>,
    pub hs_m: Spanned<f64>,
    pub tp_s: Option<Spanned<f64>>,
    pub tz_s: Option<Spanned<f64>>,
    pub gamma: Option<Spanned<f64>>,
    pub duration_h: Option<Spanned<f64>>,
}
