//! `slamtool sea info`

use std::path::PathBuf;

use clap::{Args, Subcommand};
use slamtool::sea::{SeaState, Speeds, encounter_frequency};

#[derive(Debug, Subcommand)]
pub enum SeaCommand {
    /// Waves, spectra (H_s, T_p, T_z, moments), speeds and encounter frequencies of a sea-state file.
    Info(InfoArgs),
}

#[derive(Debug, Args)]
pub struct InfoArgs {
    /// Sea-state file (sea_state.toml).
    file: PathBuf,
    /// Ship length (m), needed to turn Froude numbers into speeds.
    #[arg(long)]
    lpp_m: Option<f64>,
    /// Print JSON instead of tables.
    #[arg(long)]
    json: bool,
}

pub fn run(c: SeaCommand) -> slamtool::Result<()> {
    match c {
        SeaCommand::Info(a) => info(a),
    }
}

fn info(a: InfoArgs) -> slamtool::Result<()> {
    let sea = SeaState::from_file(&a.file)?;
    let speeds = match (&sea.speeds, a.lpp_m) {
        (Speeds::MetresPerSecond(v), _) => Some(v.clone()),
        (Speeds::FroudeNumbers(_), Some(l)) if l.is_finite() && l > 0.0 => {
            Some(sea.speeds.resolve(l))
        }
        (Speeds::FroudeNumbers(_), Some(l)) => {
            return Err(slamtool::Error::Invalid(format!(
                "--lpp-m must be a positive length, got {l}"
            )));
        }
        (Speeds::FroudeNumbers(_), None) => None,
    };
    let summaries: Vec<_> = sea.irregular.iter().map(|s| s.spectrum.summary()).collect();
    if a.json {
        let irregular: Vec<_> = sea
            .irregular
            .iter()
            .zip(&summaries)
            .map(|(s, m)| serde_json::json!({"sea": s, "summary": m}))
            .collect();
        let out = serde_json::json!({
            "tool": concat!("slamtool ", env!("CARGO_PKG_VERSION")),
            "file": a.file.display().to_string(),
            "name": sea.name,
            "water_depth_m": sea.water_depth_m,
            "speeds": sea.speeds,
            "speeds_m_s": speeds,
            "regular": sea.regular,
            "irregular": irregular,
        });
        println!(
            "{}",
            serde_json::to_string_pretty(&out).expect("serialisable")
        );
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
            println!("  speeds       Fn {f:?} (give --lpp-m to convert to m/s)")
        }
        (Speeds::FroudeNumbers(f), Some(v)) => println!("  speeds       Fn {f:?} = {v:.3?} m/s"),
        (_, Some(v)) => println!("  speeds       {v:.3?} m/s"),
        _ => {}
    }
    if !sea.regular.is_empty() {
        println!();
        println!(
            "regular head waves (name, H m, T s, lambda m, H/lambda, encounter period s at each speed):"
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
            println!(
                "  {:<14} {:>6.3} {:>7.3} {:>8.3} {:>8.4}  [{}]",
                w.name,
                w.height_m,
                w.period_s,
                w.wavelength_m,
                w.steepness(),
                te.join(", ")
            );
        }
    }
    if !sea.irregular.is_empty() {
        println!();
        println!("irregular seas (name, spectrum, Hs m, Tp s, Tz s, T1 s, m0 m2, m2 m2/s2):");
        for (s, m) in sea.irregular.iter().zip(&summaries) {
            let kind = match s.spectrum {
                slamtool::sea::Spectrum::PiersonMoskowitz { .. } => "Pierson-Moskowitz".to_string(),
                slamtool::sea::Spectrum::Bretschneider { .. } => "ITTC/Bretschneider".to_string(),
                slamtool::sea::Spectrum::Jonswap { gamma, .. } => format!("JONSWAP g={gamma}"),
            };
            println!(
                "  {:<14} {:<18} {:>6.3} {:>7.3} {:>7.3} {:>7.3} {:>9.5} {:>9.5}",
                s.name, kind, m.hs_m, m.tp_s, m.tz_s, m.t1_s, m.m0, m.m2
            );
        }
    }
    Ok(())
}
