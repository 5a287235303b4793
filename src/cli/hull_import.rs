//! `slamtool hull import FILE --draft-m T [--stations N] -o hull.toml`: a hull file from a lines-plan
//! offsets grid (CSV) or a closed triangulated surface (STL), then the usual checks on the written file.

use std::path::PathBuf;

use clap::Args;
use slamtool::hull::import::{ImportOptions, import};
use slamtool::hull::{Hull, Hydrostatics};

/// Import a hull from an offsets grid (.csv) or a closed hull surface (.stl, ASCII or binary).
///
/// The grid CSV has a header row `x_m` (or `aft_of_fp`) followed by waterline heights z in m, and one
/// row per station: its position, then the half-breadth on each waterline (blank or `-` for none). An
/// STL surface must be closed (deck and transom included), symmetric about y = 0, with x forward and z
/// up; it is cut into `--stations` equally spaced sections from its aft to its forward end. The baseline
/// is put at the lowest point. The hull file is written, then read back with the usual checks, so any
/// problem is reported as file:line:column.
#[derive(Debug, Args)]
pub struct ImportArgs {
    /// Offsets grid (.csv) or hull surface (.stl).
    pub file: PathBuf,
    /// Number of stations: STL surfaces are cut at this many equally spaced stations (default 21); a grid
    /// is resampled to it by shape-preserving interpolation (default: keep the table's stations).
    #[arg(long, value_name = "N")]
    pub stations: Option<usize>,
    /// Draft above the baseline, m, level keel (required: the geometry does not say where the water is).
    #[arg(long, value_name = "M")]
    pub draft_m: f64,
    /// Length between perpendiculars, m [default: the length of the offsets, aftmost to foremost
    /// station; required for an `aft_of_fp` grid].
    #[arg(long, value_name = "M")]
    pub lpp_m: Option<f64>,
    /// Aft perpendicular in the source's x, m [default: the aft end of the offsets].
    #[arg(long, value_name = "M", allow_negative_numbers = true)]
    pub ap_x_m: Option<f64>,
    /// Centre of gravity above the baseline, m [default: the draft, stated as assumed in the file].
    #[arg(long, value_name = "M")]
    pub kg_m: Option<f64>,
    /// Pitch radius of gyration over Lpp [default: 0.25, stated as assumed].
    #[arg(long, value_name = "F")]
    pub k_yy_over_lpp: Option<f64>,
    /// Water density, kg/m3 [default: 1025, stated as assumed].
    #[arg(long, value_name = "KG_M3")]
    pub water_density_kg_m3: Option<f64>,
    /// Hull name [default: the file name without extension].
    #[arg(long)]
    pub name: Option<String>,
    /// The hull file to write (TOML, written atomically).
    #[arg(short = 'o', long = "out", value_name = "FILE")]
    pub out: PathBuf,
    /// Write the hull file even where FILE is the offsets grid or surface being imported.
    #[arg(long)]
    pub force: bool,
}

pub fn run(a: ImportArgs) -> slamtool::Result<()> {
    slamtool::output_policy::refuse_input_target(&a.out, &[a.file.as_path()], "-o", a.force)?;
    let opts = ImportOptions {
        name: a.name,
        lpp: a.lpp_m,
        ap_x: a.ap_x_m,
        draft: a.draft_m,
        kg: a.kg_m,
        k_yy_over_lpp: a.k_yy_over_lpp,
        rho: a.water_density_kg_m3,
        stations: a.stations,
    };
    let imported = import(&a.file, &opts)?;
    slamtool::files::write_text_atomic(&a.out, &imported.to_toml())?;
    eprintln!(
        "wrote {} ({} stations)",
        a.out.display(),
        imported.spec.stations.len()
    );
    for n in &imported.notes {
        eprintln!("  note: {n}");
    }
    // The usual checks, on the file as written: errors point into it.
    let hull = Hull::from_file(&a.out)?;
    let l = hull.loading(None)?;
    let h = Hydrostatics::compute(&hull, l);
    eprintln!(
        "  checked: Lpp {:.4} m, draft {:.4} m, volume {:.6} m3, LCB {:+.4} m, waterplane {:.5} m2, Cb {:.4}",
        hull.lpp, l.draft_fp, h.volume, h.lcb, h.awp, h.cb
    );
    Ok(())
}
