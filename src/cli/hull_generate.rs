//! `slamtool hull generate <hull> [-o/--out FILE]`: write one of the example/reference hulls.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use slamtool::hull::generate::GeneratedHull;

/// Which hull to generate.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum HullName {
    /// Journee (1992) Wigley III, from its analytic form.
    WigleyIii,
    /// Reconstruction of Ochi's (1958) 6 m V-form model, fitted to its published form coefficients.
    OchiVform,
    /// Reconstruction of the Hermundstad & Moan (2005) flared car carrier, model 1:21.6.
    CarCarrier,
}

impl From<HullName> for GeneratedHull {
    fn from(h: HullName) -> Self {
        match h {
            HullName::WigleyIii => GeneratedHull::WigleyIii,
            HullName::OchiVform => GeneratedHull::OchiVform,
            HullName::CarCarrier => GeneratedHull::CarCarrier,
        }
    }
}

/// Write an example or reference hull file (hulls/*.toml are made this way).
#[derive(Debug, Args)]
pub struct GenerateArgs {
    /// The hull to generate.
    #[arg(value_enum)]
    pub hull: HullName,
    /// Output file (written atomically); the hull TOML goes to standard output without it.
    #[arg(short, long, value_name = "FILE", alias = "output")]
    pub out: Option<PathBuf>,
}

pub fn run(args: GenerateArgs) -> slamtool::Result<()> {
    let text = GeneratedHull::from(args.hull).toml()?;
    match args.out {
        Some(path) => {
            slamtool::files::write_text_atomic(&path, &text)?;
            println!("hull file written to {}", path.display());
        }
        None => print!("{text}"),
    }
    Ok(())
}
