//! `slamtool hull info|section|generate`

use std::path::PathBuf;

use clap::{Args, Subcommand};
use slamtool::hull::{Hull, Hydrostatics, LoadingCondition, MassProperties};
use slamtool::provenance::{Provenance, TOOL};
use slamtool::report::{mass_text, sanity};

use super::global::{self, JsonArg};
use super::hull_generate;
use super::hull_import;
use super::hull_plot;
use super::station::StationArg;

/// Examples at the end of `slamtool hull --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool hull info hulls/ochi-vform.toml
  slamtool hull section hulls/ochi-vform.toml --station 0.1 --loading test-condition
  slamtool hull generate wigley-iii -o my-wigley.toml";

const INFO_EXAMPLES: &str = "\
Examples:
  slamtool hull info hulls/ochi-vform.toml
  slamtool hull info hulls/ochi-vform.toml --loading max-draft
  slamtool hull info hulls/wigley-iii.toml --json > wigley.json";

const SECTION_EXAMPLES: &str = "\
Examples:
  slamtool hull section hulls/ochi-vform.toml --station 0.1 > section.csv
  slamtool hull section hulls/ochi-vform.toml --x-m -1.2 --loading test-condition
  slamtool hull section hulls/car-carrier-hm2005.toml --station 0.05 --json";

const GENERATE_EXAMPLES: &str = "\
Examples:
  slamtool hull generate ochi-vform -o hulls/ochi-vform.toml
  slamtool hull generate wigley-iii > my-wigley.toml
  slamtool hull generate car-carrier -o car-carrier.toml";

#[derive(Debug, Subcommand)]
pub enum HullCommand {
    /// Hydrostatics, form coefficients and mass properties at each loading condition.
    #[command(after_long_help = INFO_EXAMPLES)]
    Info(InfoArgs),
    /// The section contour at any station, relative to the baseline or to the local waterline (CSV).
    #[command(after_long_help = SECTION_EXAMPLES)]
    Section(SectionArgs),
    /// Write one of the example/reference hulls (hulls/*.toml) from its generator.
    #[command(after_long_help = GENERATE_EXAMPLES)]
    Generate(hull_generate::GenerateArgs),
    /// Import a hull from an offsets grid (CSV) or a closed surface (STL).
    Import(hull_import::ImportArgs),
    /// Draw the body plan as SVG.
    Plot(hull_plot::PlotArgs),
}

#[derive(Debug, Args)]
pub struct InfoArgs {
    /// Hull file (hull.toml).
    file: PathBuf,
    /// Only this loading condition [default: all].
    #[arg(long)]
    loading: Option<String>,
    #[command(flatten)]
    json: JsonArg,
}

#[derive(Debug, Args)]
pub struct SectionArgs {
    /// Hull file (hull.toml).
    file: PathBuf,
    #[command(flatten)]
    station: StationArg,
    /// Give z relative to the local waterline of this loading condition [default: z above baseline].
    #[arg(long)]
    loading: Option<String>,
    #[command(flatten)]
    json: JsonArg,
}

pub fn run(c: HullCommand) -> slamtool::Result<()> {
    match c {
        HullCommand::Info(a) => info(a),
        HullCommand::Section(a) => section(a),
        HullCommand::Generate(a) => hull_generate::run(a),
        HullCommand::Import(a) => hull_import::run(a),
        HullCommand::Plot(a) => hull_plot::run(a),
    }
}

#[derive(serde::Serialize)]
struct LoadingReport<'a> {
    hydrostatics: &'a Hydrostatics,
    mass: MassProperties,
}

fn info(a: InfoArgs) -> slamtool::Result<()> {
    let hull = Hull::from_file(&a.file)?;
    let loadings: Vec<&LoadingCondition> = match &a.loading {
        Some(n) => vec![hull.loading(Some(n))?],
        None => hull.loadings.iter().collect(),
    };
    let hs: Vec<Hydrostatics> = loadings.iter().map(|l| hull.hydrostatics(l)).collect();
    let mut warnings: Vec<String> = hs.iter().flat_map(sanity::negative_gm).collect();
    warnings.extend(
        hs.iter()
            .flat_map(|h| sanity::implausible_form(h, hull.x_range())),
    );
    if a.json.json {
        let reports: Vec<LoadingReport> = hs
            .iter()
            .zip(&loadings)
            .map(|(h, l)| LoadingReport {
                hydrostatics: h,
                mass: h.mass_properties(l),
            })
            .collect();
        let sensors: Vec<serde_json::Value> = hull
            .sensors
            .iter()
            .map(|s| {
                serde_json::json!({"name": s.name, "x_m": s.x, "station": hull.aft_of_fp(s.x),
                "girth_m": s.girth, "y_m": s.position[0], "z_m": s.position[1], "diameter_m": s.diameter})
            })
            .collect();
        let prov = Provenance::new(
            &hull.input_files(),
            serde_json::json!({ "loading": a.loading }),
        )?;
        let out = serde_json::json!({
            "tool": TOOL,
            "provenance": prov,
            "warnings": warnings,
            "outputs": null,
            "file": a.file.display().to_string(),
            "name": hull.name,
            "lpp_m": hull.lpp,
            "depth_m": hull.depth,
            "number_of_offset_stations": hull.stations.len(),
            "loadings": reports,
            "sensors": sensors,
        });
        global::print_json(out);
        return Ok(());
    }
    println!("{}", hull.name);
    println!("  file        {}", a.file.display());
    let (xa, xf) = hull.x_range();
    println!("  Lpp         {:.4} m", hull.lpp);
    println!("  depth       {:.4} m", hull.depth);
    println!(
        "  offsets     {} stations from x = {xa:.3} m to {xf:.3} m (midship origin, x forward)",
        hull.stations.len()
    );
    for (h, l) in hs.iter().zip(&loadings) {
        let m = h.mass_properties(l);
        println!();
        println!("loading '{}'", h.loading);
        row(
            "draft FP / AP",
            &format!("{:.4} / {:.4} m", l.draft_fp, l.draft_ap),
        );
        row("mean draft T", &format!("{:.4} m", h.mean_draft_m));
        row("trim by stern", &format!("{} m", fx(h.trim_by_stern_m, 4)));
        row("water density", &format!("{:.1} kg/m3", h.rho_kg_m3));
        row("volume", &format!("{:.6} m3", h.volume));
        row("displacement (buoyancy)", &mass_text(h.displacement_kg));
        row("LCB (from midship, +fwd)", &format!("{} m", fx(h.lcb, 4)));
        row("KB", &format!("{:.4} m", h.kb));
        row("waterplane area", &format!("{:.5} m2", h.awp));
        row("LCF (from midship, +fwd)", &format!("{} m", fx(h.lcf, 4)));
        row("BM_T / BM_L", &format!("{:.4} / {:.3} m", h.bm_t, h.bm_l));
        row("GM_T / GM_L", &format!("{:.4} / {:.3} m", h.gm_t, h.gm_l));
        row("waterline beam B", &format!("{:.4} m", h.beam_wl_m));
        row("midship area", &format!("{:.5} m2", h.am));
        row(
            "Cb / Cp / Cm / Cwp",
            &format!("{:.4} / {:.4} / {:.4} / {:.4}", h.cb, h.cp, h.cm, h.cwp),
        );
        let note = |b: bool, s: &str| if b { format!(" ({s})") } else { String::new() };
        row(
            "mass",
            &format!(
                "{}{}",
                mass_text(m.mass_kg),
                note(m.mass_from_buoyancy, "from buoyancy")
            ),
        );
        if !m.mass_from_buoyancy {
            row(
                "mass - buoyancy",
                &format!("{:+.2} % of buoyancy", 100.0 * m.mass_buoyancy_mismatch),
            );
        }
        row(
            "LCG",
            &format!(
                "{} m{}",
                fx(m.lcg_m, 4),
                note(m.lcg_from_lcb, "= LCB, not given")
            ),
        );
        row("KG", &format!("{:.4} m", m.kg_m));
        row(
            "k_yy",
            &format!("{:.4} m ({:.3} Lpp)", m.k_yy_m, m.k_yy_m / hull.lpp),
        );
        println!("  sectional-area curve:");
        println!(
            "    {:>9} {:>9} {:>8} {:>10} {:>14}",
            "x_m", "station", "draft_m", "area_m2", "half_breadth_m"
        );
        for s in &h.sectional_area {
            println!(
                "    {:>9.4} {:>9.4} {:>8.4} {:>10.6} {:>14.4}",
                s.x_m,
                hull.aft_of_fp(s.x_m),
                s.draft_m,
                s.area_m2,
                s.half_breadth_m
            );
        }
    }
    println!();
    if hull.sensors.is_empty() {
        println!("sensors: none in this file");
    } else {
        println!("sensors (station = fraction of Lpp aft of the FP):");
        println!(
            "  {:<8} {:>8} {:>9} {:>8} {:>8} {:>8} {:>10}",
            "name", "station", "x_m", "girth_m", "y_m", "z_m", "diameter_m"
        );
        for s in &hull.sensors {
            println!(
                "  {:<8} {:>8.4} {:>9.4} {:>8.4} {:>8.4} {:>8.4} {:>10.4}",
                s.name,
                hull.aft_of_fp(s.x),
                s.x,
                s.girth,
                s.position[0],
                s.position[1],
                s.diameter
            );
        }
    }
    for w in &warnings {
        println!("{}", global::warning_line(w));
    }
    Ok(())
}

/// Fixed-point with `p` decimals, without the sign of a value that rounds to zero ("-0.0000").
fn fx(v: f64, p: usize) -> String {
    let s = format!("{v:.p$}");
    match s.strip_prefix('-') {
        Some(rest) if rest.chars().all(|c| c == '0' || c == '.') => rest.to_string(),
        _ => s,
    }
}

fn row(label: &str, value: &str) {
    println!("  {label:<26}{value}");
}

fn section(a: SectionArgs) -> slamtool::Result<()> {
    let hull = Hull::from_file(&a.file)?;
    let st = a.station.resolve(&hull)?;
    let x = st.x;
    let sec = hull
        .section_at(x)
        .map_err(|e| slamtool::Error::Invalid(format!("{}: {e}", st.given)))?;
    let (sec, frame) = match &a.loading {
        Some(n) => {
            let l = hull.loading(Some(n))?;
            let zw = l.draft_at(x, hull.lpp);
            (
                sec.relative_to_waterline(zw),
                format!("z from the local waterline of '{n}' ({zw:.4} m above base)"),
            )
        }
        None => (sec, "z above baseline".to_string()),
    };
    let warnings: Vec<String> = st.warning.into_iter().collect();
    let settings = serde_json::json!({
        "x_m": x, "station": hull.aft_of_fp(x), "loading": a.loading, "z_from": frame,
    });
    let prov = Provenance::new(&hull.input_files(), settings)?;
    // `+ 0.0` turns -0 into 0 so that no "-0.000000" appears
    let points: Vec<[f64; 2]> = sec
        .points
        .iter()
        .map(|p| [p[0] + 0.0, p[1] + 0.0])
        .collect();
    if a.json.json {
        let out = serde_json::json!({
            "tool": TOOL,
            "provenance": prov,
            "warnings": warnings,
            "outputs": null,
            "hull": hull.name,
            "x_m": x + 0.0,
            "station": hull.aft_of_fp(x) + 0.0,
            "z_from": frame,
            "points_y_z_m": points,
        });
        global::print_json(out);
        return Ok(());
    }
    for w in &warnings {
        global::warn_stderr(w);
    }
    let rows = points
        .iter()
        .map(|p| vec![format!("{:.6}", p[0]), format!("{:.6}", p[1])])
        .collect();
    let table = slamtool::report::CsvTable {
        file_name: "section.csv",
        header: &["y_m", "z_m"],
        notes: Vec::new(),
        rows,
    };
    print!(
        "# {} at x = {:.4} m (station {:.4}, fraction of Lpp aft of the FP); {frame}\n{}",
        hull.name,
        x + 0.0,
        hull.aft_of_fp(x) + 0.0,
        table.to_text(&prov)?
    );
    Ok(())
}
