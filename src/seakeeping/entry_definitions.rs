//! Keel-entry and flare-impact velocities under alternative definitions of the strip-theory chain, one
//! definition changed at a time, to explain a difference from a published number (issue 29: Veen's 2010
//! SEAWAY entry speeds for Ochi's V-form) or to measure the effect of an option.
//!
//! The chain: heave and pitch by strip theory ([`super::strip_theory`]) in a regular head wave, the relative
//! motion s(t) at a station ([`super::relative_motion::at_station_as`]), and the velocity at the instant s
//! falls through a level: the local draft for keel entry, the draft minus a height above the keel for the
//! water reaching a panel (flare impact). Each [`Variant`] changes one input or definition:
//!
//! * the wave: as in the sea file, or of length lambda = r Lpp with the same height;
//! * the loading: the mean draft read as the draft at the FP or the AP (same trim), or even keel;
//! * the pitch radius of gyration k_yy / Lpp;
//! * the heave of G combined with the pitch lever from amidships (Veen 2010, eq. 6.1, if fed with G's heave);
//! * the velocity definition ([`VelocityDefinition`]);
//! * a constant dynamic swell-up factor;
//! * the keel-slope term: a station whose keel is not parallel to the calm waterline (a rising keel, or
//!   trim) sinks in an earth-fixed transverse plane as the ship passes through it. With z_k(x) the keel
//!   height above the local calm waterline, x forward, the plane sees the ship station x = X - U t, so the
//!   keel moves down at U dz_k/dx (positive for a keel rising towards the bow, or trim by the stern). This
//!   is the "velocity normal to a keel that is not longitudinally flat" Veen (2010, pp. 2230, 2247 of the
//!   thesis text) names as a limitation of his 2D+t method; it is added to the downward entry velocity.

use serde::Serialize;

use super::ShipModel;
use super::relative_motion::{self, Definition, VelocityDefinition};
use super::strip_theory::{self, StripSettings};
use crate::error::{Error, Result};
use crate::hull::{Hull, LoadingCondition};
use crate::sea::{G, RegularWave};

/// Strips along the hull, as `assess` and `motions` use by default.
pub const STRIPS: usize = 31;

/// Where and what velocity is evaluated.
#[derive(Debug, Clone)]
pub struct Target<'a> {
    /// Column heading.
    pub label: String,
    pub hull: &'a Hull,
    pub loading: &'a LoadingCondition,
    /// The wave as the sea file gives it.
    pub wave: &'a RegularWave,
    /// Ship speed (m/s).
    pub speed: f64,
    /// Station as a fraction of Lpp aft of the FP.
    pub aft_of_fp: f64,
    /// Height above the keel the water must reach (m): 0 for keel entry, a panel's lower edge for a
    /// flare impact.
    pub height_above_keel: f64,
    /// Keep the sea file's wave under every variant (a target beside the table whose wave is not the
    /// question: its changes are then counted from its own sea-file wave).
    pub fixed_wave: bool,
}

impl<'a> Target<'a> {
    /// The keel entry at station `aft_of_fp` (fraction of Lpp aft of the FP) at `speed`, in the
    /// sea file's wave varied with the table's definitions.
    pub fn keel_entry(
        label: String,
        hull: &'a Hull,
        loading: &'a LoadingCondition,
        wave: &'a RegularWave,
        speed: f64,
        aft_of_fp: f64,
    ) -> Self {
        Self {
            label,
            hull,
            loading,
            wave,
            speed,
            aft_of_fp,
            height_above_keel: 0.0,
            fixed_wave: false,
        }
    }
}

/// The chain with one or more definitions changed; `Variant::default()` is the bundled chain.
#[derive(Debug, Clone, Default)]
pub struct Variant {
    /// Wave of length lambda = r Lpp, the height of the sea file's wave (None: the sea file's wave).
    pub lambda_over_l: Option<f64>,
    /// How the loading's drafts are read.
    pub drafts: DraftReading,
    /// k_yy / Lpp replacing the loading's.
    pub k_yy_over_lpp: Option<f64>,
    /// Heave of G with the lever from amidships ([`Definition::heave_of_g_at`]).
    pub heave_of_g: bool,
    pub velocity: VelocityDefinition,
    /// Constant dynamic swell-up factor (None: 1, no swell-up).
    pub swell_up: Option<f64>,
    /// Add the keel-slope term U dz_k/dx.
    pub keel_slope: bool,
}

/// How a loading's drafts are read: the hull file's mean draft T_m = (T_FP + T_AP)/2 and trim
/// t = T_AP - T_FP taken as the draft at another place.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub enum DraftReading {
    /// As in the hull file.
    #[default]
    AsFile,
    /// T_m is the draft at the FP: FP T_m, AP T_m + t.
    MeanAtFp,
    /// T_m is the draft at the AP: FP T_m - t, AP T_m.
    MeanAtAp,
    /// Even keel at T_m (trim ignored).
    EvenKeel,
}

impl DraftReading {
    /// (T_FP, T_AP) of `base` under this reading.
    pub fn drafts(self, base: &LoadingCondition) -> (f64, f64) {
        let (fp, ap) = (base.draft_fp, base.draft_ap);
        let (mean, trim) = (0.5 * (fp + ap), ap - fp);
        match self {
            DraftReading::AsFile => (fp, ap),
            DraftReading::MeanAtFp => (mean, mean + trim),
            DraftReading::MeanAtAp => (mean - trim, mean),
            DraftReading::EvenKeel => (mean, mean),
        }
    }
}

/// The velocity of one target under one variant.
#[derive(Debug, Clone, Copy, Serialize)]
pub struct Velocity {
    /// Relative-motion amplitude |s_a| (m).
    pub relative_motion_amplitude_m: f64,
    /// Local draft of the station (m).
    pub draft_m: f64,
    /// Encounter frequency (rad/s).
    pub encounter_frequency_rad_per_s: f64,
    /// Amplitude of the relative velocity as defined (m/s).
    pub relative_velocity_amplitude_m_per_s: f64,
    /// Downward velocity when the water reaches the target height, steady keel-slope term included (m/s);
    /// None when it is not reached (the relative motion is smaller than the draft minus the height).
    pub crossing_velocity_m_per_s: Option<f64>,
    /// Instant of the crossing within the encounter period (s; 0: wave crest at midship).
    pub crossing_time_s: Option<f64>,
    /// The steady keel-slope velocity included (m/s).
    pub keel_slope_velocity_m_per_s: f64,
}

/// The loading condition of `variant` (drafts, k_yy) from `base`.
pub fn loading_of(base: &LoadingCondition, variant: &Variant, lpp: f64) -> LoadingCondition {
    let mut l = base.clone();
    if variant.drafts != DraftReading::AsFile {
        let (fp, ap) = variant.drafts.drafts(base);
        l.draft_fp = fp;
        l.draft_ap = ap;
        // a changed draft changes the displacement (the file's, if any, belonged to the old drafts)
        l.displacement_kg = None;
    }
    if let Some(r) = variant.k_yy_over_lpp {
        l.k_yy = r * lpp;
    }
    l
}

/// Slope dz_k/dx of the keel above the local calm waterline at x (central difference over +-0.005 Lpp,
/// one-sided at the ends of the offsets): the keel's own rise in the offsets minus the waterline's slope
/// (T_FP - T_AP)/Lpp.
pub fn keel_slope(hull: &Hull, loading: &LoadingCondition, x: f64) -> Result<f64> {
    let (xa, xf) = hull.x_range();
    let d = 0.005 * hull.lpp;
    let (x0, x1) = ((x - d).max(xa), (x + d).min(xf));
    if x1 <= x0 {
        return Err(Error::Invalid(format!(
            "x = {x:.4} m: no keel slope outside the offsets"
        )));
    }
    let zk = |x: f64| -> Result<f64> {
        Ok(hull.section_at(x)?.keel_z() - loading.draft_at(x, hull.lpp))
    };
    Ok((zk(x1)? - zk(x0)?) / (x1 - x0))
}

/// The velocity of `target` under `variant`.
pub fn evaluate(target: &Target, variant: &Variant) -> Result<Velocity> {
    let hull = target.hull;
    let loading = loading_of(target.loading, variant, hull.lpp);
    let model = ShipModel::from_hull(hull, &loading, STRIPS)?;
    let x = hull.station_x(target.aft_of_fp);
    let draft = loading.draft_at(x, hull.lpp) - hull.section_at(x)?.keel_z();
    if draft <= 0.0 {
        return Err(Error::Invalid(format!(
            "station {} Lpp aft of the FP is dry at loading '{}'",
            target.aft_of_fp, loading.name
        )));
    }
    let (omega, zeta_a) = match variant.lambda_over_l.filter(|_| !target.fixed_wave) {
        Some(r) => (
            (2.0 * std::f64::consts::PI * G / (r * hull.lpp)).sqrt(),
            target.wave.amplitude(),
        ),
        None => (target.wave.omega, target.wave.amplitude()),
    };
    let r = strip_theory::respond(&model, omega, target.speed, &StripSettings::default())?;
    let def = Definition {
        swell_up: variant.swell_up.unwrap_or(1.0),
        velocity: variant.velocity,
        heave_of_g_at: variant.heave_of_g.then_some(model.xg),
    };
    let rm = relative_motion::at_station_as(&r, x, &def)?;
    let steady = if variant.keel_slope {
        target.speed * keel_slope(hull, &loading, x)?
    } else {
        0.0
    };
    let hit = crate::impact::flare::water_reaches(
        &rm,
        r.omega_e,
        zeta_a,
        draft,
        target.height_above_keel,
    );
    Ok(Velocity {
        relative_motion_amplitude_m: rm.motion.norm() * zeta_a,
        draft_m: draft,
        encounter_frequency_rad_per_s: r.omega_e,
        relative_velocity_amplitude_m_per_s: rm.velocity.norm() * zeta_a,
        crossing_velocity_m_per_s: hit.map(|c| c.velocity_m_per_s + steady),
        crossing_time_s: hit.map(|c| c.time_s),
        keel_slope_velocity_m_per_s: steady,
    })
}

/// One row of a definitions table: a labelled variant and its velocities at every target.
#[derive(Debug, Clone, Serialize)]
pub struct Row {
    pub definition: String,
    #[serde(skip)]
    pub variant: Variant,
    /// Crossing velocity per target (m/s), None where the level is not reached.
    pub velocities_m_per_s: Vec<Option<f64>>,
}

/// The variants of the definitions table, each definition alone on the reference row (lambda = Lpp) and
/// then together (the draft labels give the drafts of the loading `base`; applied
/// to another loading, a draft reading uses that loading's mean draft and trim): each definition alone, then the options, then the stated definitions of
/// Veen (2010) eq. 6.1-6.2 together. The first row is the reference the differences are taken from:
/// lambda = Lpp, the wave of the bundled Ochi sea state before issue 29.
pub fn standard_variants(base: &LoadingCondition) -> Vec<(String, Variant)> {
    // each definition alone is changed on the reference chain (lambda = Lpp); the stated-definitions rows
    // take the sea file's wave
    let d = || Variant {
        lambda_over_l: Some(1.0),
        ..Variant::default()
    };
    let veen = Variant {
        velocity: VelocityDefinition::ShipFixedStation,
        ..Variant::default()
    };
    vec![
        (
            "reference: λ = Lpp, loading as in the hull file, Ds/Dt (bundled before issue 29)".into(),
            d(),
        ),
        ("wave as in the sea file".into(), Variant::default()),
        (
            format!(
                "mean draft read as the draft at the FP (FP {:.3} m, AP {:.3} m)",
                DraftReading::MeanAtFp.drafts(base).0,
                DraftReading::MeanAtFp.drafts(base).1
            ),
            Variant {
                drafts: DraftReading::MeanAtFp,
                ..d()
            },
        ),
        (
            format!(
                "mean draft read as the draft at the AP (FP {:.3} m, AP {:.3} m)",
                DraftReading::MeanAtAp.drafts(base).0,
                DraftReading::MeanAtAp.drafts(base).1
            ),
            Variant {
                drafts: DraftReading::MeanAtAp,
                ..d()
            },
        ),
        (
            format!(
                "even keel at the mean draft {:.3} m (trim ignored)",
                DraftReading::EvenKeel.drafts(base).0
            ),
            Variant {
                drafts: DraftReading::EvenKeel,
                ..d()
            },
        ),
        (
            "heave of G with the pitch lever from amidships (eq. 6.1 fed with G's heave)".into(),
            Variant {
                heave_of_g: true,
                ..d()
            },
        ),
        (
            "keel entry against the incident wave only, no swell-up (what the chain already does)".into(),
            d(),
        ),
        (
            "velocity without the U η5 term".into(),
            Variant {
                velocity: VelocityDefinition::WithoutPitchSpeedTerm,
                ..d()
            },
        ),
        (
            "velocity ds/dt at a fixed ship station (Veen eq. 6.2: no U η5, no U ∂ζ/∂x)".into(),
            veen.clone(),
        ),
        (
            "k_yy = 0.22 Lpp".into(),
            Variant {
                k_yy_over_lpp: Some(0.22),
                ..d()
            },
        ),
        (
            "k_yy = 0.28 Lpp".into(),
            Variant {
                k_yy_over_lpp: Some(0.28),
                ..d()
            },
        ),
        (
            "option: constant swell-up factor 1.2".into(),
            Variant {
                swell_up: Some(1.2),
                ..d()
            },
        ),
        (
            "option: constant swell-up factor 1.5".into(),
            Variant {
                swell_up: Some(1.5),
                ..d()
            },
        ),
        (
            "option: keel-slope term U dz_k/dx".into(),
            Variant {
                keel_slope: true,
                ..d()
            },
        ),
        (
            "all of Veen's stated definitions: sea-file wave, pitch about amidships, incident wave only, eq. 6.2 velocity".into(),
            veen.clone(),
        ),
        (
            "the same, with the heave of G (an assumption: SEAWAY's heave at G)".into(),
            Variant {
                heave_of_g: true,
                ..veen
            },
        ),
    ]
}

/// Evaluate `variants` at `targets`.
pub fn table(targets: &[Target], variants: &[(String, Variant)]) -> Result<Vec<Row>> {
    variants
        .iter()
        .map(|(label, v)| {
            let velocities = targets
                .iter()
                .map(|t| evaluate(t, v).map(|e| e.crossing_velocity_m_per_s))
                .collect::<Result<Vec<_>>>()?;
            Ok(Row {
                definition: label.clone(),
                variant: v.clone(),
                velocities_m_per_s: velocities,
            })
        })
        .collect()
}

/// A published value beside a column, for the last row of the table.
#[derive(Debug, Clone)]
pub struct Published {
    pub label: String,
    /// Per target, None where nothing is published.
    pub values: Vec<Option<f64>>,
}

fn cell(v: Option<f64>) -> String {
    v.map_or("not reached".into(), |v| format!("{v:.3}"))
}

/// The table as Markdown: the velocity per target, its change from the first row, and, with a published
/// value, the share of the gap between the first row and the published value that the row closes
/// (100 %: reaches it; negative: moves away).
pub fn markdown(targets: &[Target], rows: &[Row], published: Option<&Published>) -> String {
    let mut head = "| definition |".to_string();
    let mut rule = "|---|".to_string();
    for t in targets {
        head += &format!(" {} (m/s) | change |", t.label);
        rule += "---:|---:|";
        if published.is_some_and(|p| p.values.iter().any(Option::is_some)) {
            head += " gap closed |";
            rule += "---:|";
        }
    }
    let with_gap = published.is_some_and(|p| p.values.iter().any(Option::is_some));
    let mut out = format!("{head}\n{rule}\n");
    let first = rows.first().map(|r| r.velocities_m_per_s.clone());
    for r in rows {
        out += &format!("| {} |", r.definition.replace('|', "/"));
        for (k, v) in r.velocities_m_per_s.iter().enumerate() {
            let base = first.as_ref().and_then(|f| f[k]);
            let change = match (v, base) {
                (Some(v), Some(b)) => format!("{:+.3}", v - b),
                _ => "-".into(),
            };
            out += &format!(" {} | {change} |", cell(*v));
            if with_gap {
                let p = published.and_then(|p| p.values.get(k).copied().flatten());
                let closed = match (v, base, p) {
                    (Some(v), Some(b), Some(p)) if (p - b).abs() > 1e-12 => {
                        format!("{:+.0} %", 100.0 * (v - b) / (p - b) + 0.0)
                    }
                    _ => "-".into(),
                };
                out += &format!(" {closed} |");
            }
        }
        out += "\n";
    }
    if let Some(p) = published {
        out += &format!("| {} |", p.label);
        for v in &p.values {
            out += &format!(
                " {} | - |{}",
                v.map_or("-".into(), |v| format!("{v:.3}")),
                if with_gap { " - |" } else { "" }
            );
        }
        out += "\n";
    }
    out
}
