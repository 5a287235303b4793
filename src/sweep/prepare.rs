//! Everything a sweep decides before it runs anything: the cases, each case's speeds and waves, the hull
//! variants (built and checked, all of them, so a sweep with one invalid variant is refused before any run
//! and every shard refuses it alike), and the content keys.

use std::ops::Range;
use std::path::{Path, PathBuf};

use rayon::prelude::*;

use super::cases::{self, Case};
use super::file::{Common, NUMERIC, SweepFile};
use super::motions;
use super::transform::{self, HullParams};
use crate::error::{Error, InputError, Result};
use crate::hull::{Hull, LoadingCondition};
use crate::input::num;
use crate::provenance::{TOOL, sha256_hex};
use crate::sea::{IrregularSea, RegularWave, SeaState, Spectrum, breaking_steepness};

/// The version of how a case is computed, part of every case key: a sweep resumed with a build that
/// computes its cases differently computes them again instead of mixing old and new cases. Raise it with
/// every such change. 2 (2026-11-30): analytic cases make the irregular seas' design events (before,
/// their regular waves' events only).
pub const CASE_RULES: u32 = 2;

/// The speeds and waves of one case.
#[derive(Debug, Clone)]
pub struct CaseSea {
    pub speeds: Vec<f64>,
    pub regular: Vec<RegularWave>,
    pub irregular: Vec<IrregularSea>,
}

/// A hull variant: the hull, its parameters and, when transformed, its file (relative to the output).
pub struct Variant {
    pub key: String,
    pub params: HullParams,
    pub hull: Hull,
    pub loading: LoadingCondition,
    pub text: Option<String>,
    pub file: Option<String>,
    /// The strip-theory model this variant shares (index into `Prepared::models`).
    pub model: usize,
}

/// A strip-theory model shared by the variants with the same underwater form.
pub struct ModelSpec {
    pub key: String,
    pub model: crate::seakeeping::ShipModel,
    /// Lowest and highest encounter frequency of all the sweep's cases of its variants.
    pub band: (f64, f64),
}

/// A sweep ready to run.
pub struct Prepared {
    pub file: SweepFile,
    pub common: Common,
    pub cases: Vec<Case>,
    pub base: Hull,
    pub sea: SeaState,
    /// Stations assessed (fractions of Lpp aft of the FP).
    pub stations: Vec<f64>,
    pub variants: Vec<Variant>,
    pub models: Vec<ModelSpec>,
    pub case_variant: Vec<usize>,
    pub case_sea: Vec<CaseSea>,
    pub case_keys: Vec<String>,
    pub sweep_hash: String,
    /// Parameter columns: the numeric parameters varied, then `wave` if it is.
    pub parameters: Vec<String>,
}

fn file_sha(paths: &[&Path]) -> Result<String> {
    let mut all = String::new();
    for p in paths {
        let bytes = std::fs::read(p).map_err(|e| Error::io(p, e))?;
        all += &sha256_hex(&bytes);
    }
    Ok(sha256_hex(all.as_bytes()))
}

fn hull_params(c: &Case) -> HullParams {
    HullParams {
        draft_m: c.get("draft_m"),
        trim_m: c.get("trim_m"),
        flare_scale: c.get("flare_scale"),
        deadrise_scale: c.get("deadrise_scale"),
        length_scale: c.get("length_scale"),
        beam_scale: c.get("beam_scale"),
    }
}

/// Where a hull error of a case is reported: the first hull parameter of the case.
fn hull_span(c: &Case) -> Range<usize> {
    [
        "length_scale",
        "beam_scale",
        "flare_scale",
        "deadrise_scale",
        "draft_m",
        "trim_m",
    ]
    .iter()
    .find_map(|n| c.span(n))
    .unwrap_or(0..0)
}

/// A spectrum with H_s and/or T_p replaced (same family and shape).
fn respectrum(s: &Spectrum, hs: Option<f64>, tp: Option<f64>) -> Spectrum {
    let h = hs.unwrap_or(s.hs());
    let t = tp.unwrap_or(s.peak_period());
    match s {
        Spectrum::PiersonMoskowitz { .. } if tp.is_none() => Spectrum::pierson_moskowitz(h),
        Spectrum::PiersonMoskowitz { .. } | Spectrum::Bretschneider { .. } => {
            Spectrum::bretschneider(h, t)
        }
        Spectrum::Jonswap { gamma, .. } => Spectrum::jonswap(h, t, *gamma),
    }
}

fn case_sea(f: &SweepFile, sea: &SeaState, c: &Case, lpp: f64) -> Result<CaseSea, InputError> {
    let speeds = match c.get("speed_m_s") {
        Some(u) => vec![u],
        None => sea.speeds.resolve(lpp),
    };
    let base: Vec<&RegularWave> = match &c.wave {
        Some((name, span)) => match sea.regular.iter().find(|w| &w.name == name) {
            Some(w) => vec![w],
            None => {
                let names: Vec<&str> = sea.regular.iter().map(|w| w.name.as_str()).collect();
                return Err(f.error_at(
                    span.clone(),
                    format!(
                        "the sea file has no regular wave named '{name}' (it has: {})",
                        if names.is_empty() {
                            "none".into()
                        } else {
                            names.join(", ")
                        }
                    ),
                ));
            }
        },
        None => sea.regular.iter().collect(),
    };
    let (h, l) = (c.get("wave_height_m"), c.get("wavelength_m"));
    if (h.is_some() || l.is_some()) && base.is_empty() {
        let span = c
            .span("wave_height_m")
            .or(c.span("wavelength_m"))
            .unwrap_or(0..0);
        return Err(f.error_at(
            span,
            "the sea file has no [[regular]] wave whose height or length could be varied",
        ));
    }
    let mut regular = Vec::new();
    for w in base {
        if h.is_none() && l.is_none() {
            regular.push(w.clone());
            continue;
        }
        let height = h.unwrap_or(w.height_m);
        let lambda = l.unwrap_or(w.wavelength_m);
        let omega = crate::sea::frequency_from_wavelength(lambda, sea.water_depth_m);
        let limit = breaking_steepness(2.0 * std::f64::consts::PI / lambda, sea.water_depth_m);
        if height / lambda > limit {
            let span = c
                .span("wave_height_m")
                .or(c.span("wavelength_m"))
                .unwrap_or(0..0);
            return Err(f.error_at(
                span,
                format!(
                    "case {}: wave height {} m over wavelength {} m (H/λ = {:.4}) is steeper than the \
                     breaking limit H/λ = {limit:.4}",
                    c.id,
                    num(height),
                    num(lambda),
                    height / lambda
                ),
            ));
        }
        regular.push(RegularWave {
            name: format!("H{height}-L{lambda}"),
            height_m: height,
            omega,
            period_s: 2.0 * std::f64::consts::PI / omega,
            wavelength_m: lambda,
        });
    }
    let (hs, tp) = (c.get("hs_m"), c.get("tp_s"));
    if (hs.is_some() || tp.is_some()) && sea.irregular.is_empty() {
        let span = c.span("hs_m").or(c.span("tp_s")).unwrap_or(0..0);
        return Err(f.error_at(
            span,
            "the sea file has no [[irregular]] sea whose Hs or Tp could be varied",
        ));
    }
    let irregular = sea
        .irregular
        .iter()
        .map(|s| {
            if hs.is_none() && tp.is_none() {
                return s.clone();
            }
            let spectrum = respectrum(&s.spectrum, hs, tp);
            IrregularSea {
                name: format!(
                    "{}-Hs{}-Tp{}",
                    s.name,
                    spectrum.hs(),
                    spectrum.peak_period()
                ),
                spectrum,
                duration_h: s.duration_h,
            }
        })
        .collect();
    Ok(CaseSea {
        speeds,
        regular,
        irregular,
    })
}

/// Read a sweep file and prepare it (`out`: where variant hull files will be written).
pub fn prepare(path: &Path, out: &Path) -> Result<Prepared> {
    let file = SweepFile::read(path)?;
    let common = file.common()?;
    let cases = cases::expand(&file)?;
    let base = Hull::from_file(&common.hull_path)?;
    let sea = SeaState::from_file(&common.sea_path)?;
    let loading = match base.loading(common.loading.as_deref()) {
        Ok(l) => l.clone(),
        Err(e) => {
            let at = file.raw.loading.as_ref().map_or(0..0, |l| l.span());
            return Err(file.error_at(at, e.to_string()).into());
        }
    };
    if sea.regular.is_empty() && sea.irregular.is_empty() {
        return Err(file
            .error(
                &file.raw.sea,
                "the sea file has no waves ([[regular]] or [[irregular]])",
            )
            .into());
    }
    let needs_stats = common.best.max_slam_probability.is_some()
        || common.best.minimise == super::file::Objective::SlamProbability;
    if needs_stats && sea.irregular.is_empty() {
        let at = file.raw.best.as_ref().map_or(0..0, |b| b.span());
        return Err(file
            .error_at(
                at,
                "the best-variants rule uses the slam probability, which needs an [[irregular]] sea in the \
                 sea file",
            )
            .into());
    }
    let stations = if common.stations.is_empty() {
        crate::impact::sensor_stations(&base)
    } else {
        common.stations.clone()
    };
    let hull_sha = file_sha(&base.input_files())?;
    let sea_sha = file_sha(&[common.sea_path.as_path()])?;
    let sweep_hash =
        sha256_hex(format!("{}{}{}", file_sha(&[path])?, hull_sha, sea_sha).as_bytes());

    // Hull variants, each built once.
    let mut variant_of: Vec<usize> = Vec::with_capacity(cases.len());
    let mut keys: Vec<(String, HullParams, usize)> = Vec::new();
    for (i, c) in cases.iter().enumerate() {
        let p = hull_params(c);
        let key = if p.is_identity() {
            "base".to_string()
        } else {
            sha256_hex(
                serde_json::json!({
                    "tool": TOOL, "hull": hull_sha, "loading": loading.name,
                    "region": common.region, "params": p,
                })
                .to_string()
                .as_bytes(),
            )
        };
        let k = match keys.iter().position(|(k, _, _)| *k == key) {
            Some(k) => k,
            None => {
                keys.push((key, p, i));
                keys.len() - 1
            }
        };
        variant_of.push(k);
    }
    let built: Vec<Result<Variant>> = keys
        .par_iter()
        .map(|(key, p, first)| {
            if key == "base" {
                return Ok(Variant {
                    key: key.clone(),
                    params: *p,
                    hull: base.clone(),
                    loading: loading.clone(),
                    text: None,
                    file: None,
                    model: 0,
                });
            }
            let rel = format!("hulls/{}.toml", &key[..16]);
            let c = &cases[*first];
            let label = c
                .values
                .iter()
                .filter(|v| NUMERIC[5..].contains(&v.name))
                .map(|v| format!("{}={}", v.name, v.value))
                .collect::<Vec<_>>()
                .join(", ");
            match transform::variant(&base, &loading, p, common.region, &label, &out.join(&rel)) {
                Ok((text, hull)) => {
                    let l = hull.loadings[0].clone();
                    Ok(Variant {
                        key: key.clone(),
                        params: *p,
                        hull,
                        loading: l,
                        text: Some(text),
                        file: Some(rel),
                        model: 0,
                    })
                }
                Err(e) => {
                    let why = match &e {
                        Error::Input(ie) => ie.message.clone(),
                        other => other.to_string(),
                    };
                    Err(file
                        .error_at(
                            hull_span(c),
                            format!(
                                "case {} ({}): the transformed hull is not valid: {why}",
                                c.id,
                                c.label()
                            ),
                        )
                        .into())
                }
            }
        })
        .collect();
    let mut variants = Vec::with_capacity(built.len());
    for v in built {
        variants.push(v?);
    }

    // The strip-theory models, shared between variants with the same underwater form.
    // Linear strip theory sees the hull below the calm waterline only: a variant that differs from
    // another only in flare (above the waterline) gets the model of its twin without the flare change, so
    // that the two share one model (built from the twin, where the sections between stations are
    // interpolated without the flare change; the model of the flared variant would differ from it only by
    // that interpolation).
    let ship_models: Vec<crate::seakeeping::ShipModel> = variants
        .par_iter()
        .map(|v| {
            if v.params.flare_scale.is_none() {
                return crate::seakeeping::ShipModel::from_hull(&v.hull, &v.loading, common.strips);
            }
            let twin = HullParams {
                flare_scale: None,
                ..v.params
            };
            if twin.is_identity() {
                return crate::seakeeping::ShipModel::from_hull(&base, &loading, common.strips);
            }
            let (_, h) = transform::variant(
                &base,
                &loading,
                &twin,
                common.region,
                "underwater twin",
                &out.join("hulls").join("twin.toml"),
            )?;
            crate::seakeeping::ShipModel::from_hull(&h, &h.loadings[0], common.strips)
        })
        .collect::<Result<_>>()?;
    let mut models: Vec<ModelSpec> = Vec::new();
    for (v, m) in variants.iter_mut().zip(ship_models) {
        let key = motions::model_key(&m);
        v.model = match models.iter().position(|s| s.key == key) {
            Some(k) => k,
            None => {
                models.push(ModelSpec {
                    key,
                    model: m,
                    band: (f64::INFINITY, 0.0),
                });
                models.len() - 1
            }
        };
    }
    // Speeds and waves of each case, and the frequency band of each model.
    let mut case_sea_v = Vec::with_capacity(cases.len());
    for (i, c) in cases.iter().enumerate() {
        let v = &variants[variant_of[i]];
        let cs = case_sea(&file, &sea, c, v.hull.lpp)?;
        let m = &mut models[v.model];
        for &u in &cs.speeds {
            for w in motions::needed(u, &cs.regular, &cs.irregular)? {
                m.band = (m.band.0.min(w), m.band.1.max(w));
            }
        }
        case_sea_v.push(cs);
    }

    let settings = serde_json::json!({
        "loading": loading.name, "stations": stations, "fidelity": common.fidelity.name(),
        "resolution": common.resolution, "convergence_levels": common.convergence_levels,
        "strips": common.strips, "region": common.region, "air": common.air,
        "keel_slope_term": common.keel_slope_term,
    });
    let case_keys = cases
        .iter()
        .enumerate()
        .map(|(i, c)| {
            let v = &variants[variant_of[i]];
            let cs = &case_sea_v[i];
            let params: Vec<(&str, f64)> = c.values.iter().map(|v| (v.name, v.value)).collect();
            // The analytic path shares one frequency table per variant: its band decides the result.
            let band = (common.fidelity == crate::assess::Fidelity::Analytic)
                .then_some(models[v.model].band);
            sha256_hex(
                serde_json::json!({
                    "tool": TOOL, "rules": CASE_RULES, "hull": hull_sha, "sea": sea_sha,
                    "variant": v.key, "settings": settings, "params": params,
                    "wave": c.wave.as_ref().map(|w| &w.0), "speeds": cs.speeds, "band": band,
                })
                .to_string()
                .as_bytes(),
            )
        })
        .collect();
    let mut parameters: Vec<String> = NUMERIC
        .iter()
        .filter(|n| cases.iter().any(|c| c.get(n).is_some()))
        .map(|n| n.to_string())
        .collect();
    if cases.iter().any(|c| c.wave.is_some()) {
        parameters.push("wave".into());
    }
    Ok(Prepared {
        file,
        common,
        cases,
        base,
        sea,
        stations,
        variants,
        models,
        case_variant: variant_of,
        case_sea: case_sea_v,
        case_keys,
        sweep_hash,
        parameters,
    })
}

impl Prepared {
    /// The input files of the sweep (for provenance).
    pub fn inputs(&self) -> Vec<PathBuf> {
        let mut v = vec![self.file.src.path.clone()];
        v.extend(self.base.input_files().iter().map(|p| p.to_path_buf()));
        v.push(self.common.sea_path.clone());
        v
    }
}
