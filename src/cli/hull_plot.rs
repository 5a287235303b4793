//! `slamtool hull plot HULL -o bodyplan.svg`: the body plan as SVG.

use std::path::PathBuf;

use clap::Args;
use slamtool::hull::Hull;
use slamtool::hull::body_plan::body_plan_svg;

/// Draw the body plan (SVG): fore-body sections right of the centreline, aft-body sections left,
/// the waterline of each loading, the sensors marked and named.
#[derive(Debug, Args)]
pub struct PlotArgs {
    /// Hull file (hull.toml).
    pub file: PathBuf,
    /// The SVG file to write (atomically).
    #[arg(short = 'o', long = "out", value_name = "FILE")]
    pub out: PathBuf,
    /// Write the SVG even where FILE is one of the hull's own input files.
    #[arg(long)]
    pub force: bool,
}

pub fn run(a: PlotArgs) -> slamtool::Result<()> {
    let hull = Hull::from_file(&a.file)?;
    slamtool::output_policy::refuse_input_target(&a.out, &hull.input_files(), "-o", a.force)?;
    let svg = body_plan_svg(&hull)?;
    slamtool::files::write_text_atomic(&a.out, &svg)?;
    eprintln!("wrote {}", a.out.display());
    Ok(())
}
