//! `slamtool sea info`

use std::path::PathBuf;

use clap::{Args, Subcommand};
use slamtool::provenance::{Provenance, TOOL};
use slamtool::sea::{SeaState, Speeds, encounter_frequency};

use super::global::{self, JsonArg};

/// Examples at the end of `slamtool sea --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool sea info sea_states/north-atlantic-jonswap.toml
  slamtool sea info sea_states/model-scale-jonswap.toml --lpp-m 6 --json";

const INFO_EXAMPLES: &str = "\
Examples:
  slamtool sea info sea_states/north-atlantic-jonswap.toml
  slamtool sea info sea_states/model-scale-jonswap.toml --lpp-m 6
  slamtool sea info sea_states/ochi-1958.toml --json";

#[derive(Debug, Subcommand)]
pub enum SeaCommand {
    /// Waves, spectra (H_s, T_p, T_z, moments), speeds and encounter periods of a sea-state file.
    #[command(after_long_help = INFO_EXAMPLES)]
    Info(InfoArgs),
}

/// Numbers as a comma-separated list with `p` decimals.
fn list(v: &[f64], p: usize) -> String {
    v.iter()
        .map(|x| format!("{x:.p$}"))
        .collect::<Vec<_>>()
        .join(", ")
}

#[derive(Debug, Args)]
pub struct InfoArgs {
    /// Sea-state file (sea_state.toml).
    file: PathBuf,
    /// Ship length (m), needed to turn Froude numbers into speeds.
    #[arg(long, allow_negative_numbers = true)]
    lpp_m: Option<f64>,
    #[command(flatten)]
    json: JsonArg,
}

pub fn run(c: SeaCommand) -> slamtool::Result<()> {
    match c {
        SeaCommand::Info(a) => info(a),
    }
}

fn info(a: InfoArgs) -> slamtool::Result<()> {
    if let Some(l) = a.lpp_m
        && !(l.is_finite() && l > 0.0 && l <= 1000.0)
    {
        return Err(slamtool::Error::Invalid(format!(
            "--lpp-m must be a ship length in metres (0 to 1000 m), got {}",
            slamtool::input::num(l)
        )));
    }
    let sea = SeaState::from_file(&a.file)?;
    let speeds = match (&sea.speeds, a.lpp_m) {
        (Speeds::MetresPerSecond(v), _) => Some(v.clone()),
        (Speeds::FroudeNumbers(_), Some(l)) => Some(sea.speeds.resolve(l)),
        (Speeds::FroudeNumbers(_), None) => None,
    };
    let summaries: Vec<_> = sea.irregular.iter().map(|s| s.spectrum.summary()).collect();
    if a.json.json {
        let prov = Provenance::new(&[a.file.as_path()], serde_json::json!({ "lpp_m": a.lpp_m }))?;
        let irregular: Vec<_> = sea
            .irregular
            .iter()
            .zip(&summaries)
            .map(|(s, m)| serde_json::json!({"sea": s, "summary": m}))
            .collect();
        let out = serde_json::json!({
            "tool": TOOL,
            "provenance": prov,
            "warnings": [],
            "outputs": null,
            "file": a.file.display().to_string(),
            "name": sea.name,
            "water_depth_m": sea.water_depth_m,
            "speeds": sea.speeds,
            "speeds_m_per_s": speeds,
            "regular": sea.regular,
            "irregular": irregular,
        });
        global::print_json(out);
        return Ok(());
    }
    println!("{}", sea.name);
    println!("  file         {}", a.file.display());
    match sea.water_depth_m {
        Some(h) => println!("  water depth  {h} m"),
        None => println!("  water depth  deep water"),
    }
    match (&sea.speeds, &speeds) {
        (Speeds::FroudeNumbers(f), None) => {
            println!(
                "  speeds       Fn {} (give --lpp-m to convert to m/s)",
                list(f, 3)
            )
        }
        (Speeds::FroudeNumbers(f), Some(v)) => {
            println!("  speeds       Fn {} = {} m/s", list(f, 3), list(v, 3))
        }
        (_, Some(v)) => println!("  speeds       {} m/s", list(v, 3)),
        _ => {}
    }
    println!();
    if sea.regular.is_empty() {
        println!("regular head waves: none in this file");
    } else {
        println!("regular head waves (encounter periods at each speed in turn):");
        println!(
            "  {:<14} {:>8} {:>8} {:>12} {:>10}  encounter_period_s",
            "name", "height_m", "period_s", "wavelength_m", "steepness"
        );
        for w in &sea.regular {
            let te: Vec<String> = speeds
                .iter()
                .flatten()
                .map(|u| {
                    let we = encounter_frequency(w.omega, *u, sea.water_depth_m);
                    format!("{:.3}", 2.0 * std::f64::consts::PI / we)
                })
                .collect();
            let te = if te.is_empty() {
                "- (speeds in m/s needed)".to_string()
            } else {
                te.join(", ")
            };
            println!(
                "  {:<14} {:>8.3} {:>8.3} {:>12.3} {:>10.4}  {}",
                w.name,
                w.height_m,
                w.period_s,
                w.wavelength_m,
                w.steepness(),
                te
            );
        }
    }
    println!();
    if sea.irregular.is_empty() {
        println!("irregular seas: none in this file");
    } else {
        println!(
            "irregular seas (significant height, peak, zero-crossing and mean periods, moments):"
        );
        println!(
            "  {:<14} {:<18} {:>6} {:>7} {:>7} {:>7} {:>9} {:>11}",
            "name", "spectrum", "Hs_m", "Tp_s", "Tz_s", "T1_s", "m0_m2", "m2_m2_per_s2"
        );
        for (s, m) in sea.irregular.iter().zip(&summaries) {
            let kind = match s.spectrum {
                slamtool::sea::Spectrum::PiersonMoskowitz { .. } => "Pierson-Moskowitz".to_string(),
                slamtool::sea::Spectrum::Bretschneider { .. } => "ITTC/Bretschneider".to_string(),
                slamtool::sea::Spectrum::Jonswap { gamma, .. } => format!("JONSWAP gamma {gamma}"),
            };
            println!(
                "  {:<14} {:<18} {:>6.3} {:>7.3} {:>7.3} {:>7.3} {:>9.5} {:>11.5}",
                s.name, kind, m.hs_m, m.tp_s, m.tz_s, m.t1_s, m.m0, m.m2
            );
        }
    }
    Ok(())
}
