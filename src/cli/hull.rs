//! `slamtool hull info|section|generate`

use std::path::PathBuf;

use clap::{Args, Subcommand};
use slamtool::hull::{Hull, Hydrostatics, MassProperties};

use super::hull_generate;
use super::hull_import;
use super::hull_plot;

#[derive(Debug, Subcommand)]
pub enum HullCommand {
    /// Hydrostatics, form coefficients and mass properties at each loading condition.
    Info(InfoArgs),
    /// The section contour at any station, relative to the baseline or to the local waterline (CSV).
    Section(SectionArgs),
    /// Write one of the example/reference hulls (hulls/*.toml) from its generator.
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
    /// Only this loading condition (default: all).
    #[arg(long)]
    loading: Option<String>,
    /// Print JSON instead of tables.
    #[arg(long)]
    json: bool,
}

#[derive(Debug, Args)]
pub struct SectionArgs {
    /// Hull file (hull.toml).
    file: PathBuf,
    /// Station as a fraction of Lpp aft of the forward perpendicular.
    #[arg(
        long,
        conflicts_with = "x_m",
        required_unless_present = "x_m",
        allow_negative_numbers = true
    )]
    aft_of_fp: Option<f64>,
    /// Station as x in m from midship (positive forward; aft of midship is negative, e.g. --x-m -1.2).
    #[arg(long, allow_negative_numbers = true)]
    x_m: Option<f64>,
    /// Give z relative to the local waterline of this loading condition (default: above baseline).
    #[arg(long)]
    loading: Option<String>,
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
    let loadings: Vec<_> = match &a.loading {
        Some(n) => vec![hull.loading(Some(n))?],
        None => hull.loadings.iter().collect(),
    };
    let hs: Vec<Hydrostatics> = loadings
        .iter()
        .map(|l| Hydrostatics::compute(&hull, l))
        .collect();
    if a.json {
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
                serde_json::json!({"name": s.name, "x_m": s.x, "aft_of_fp": hull.aft_of_fp(s.x),
                "girth_m": s.girth, "y_m": s.position[0], "z_m": s.position[1], "diameter_m": s.diameter})
            })
            .collect();
        let out = serde_json::json!({
            "tool": concat!("slamtool ", env!("CARGO_PKG_VERSION")),
            "file": a.file.display().to_string(),
            "name": hull.name,
            "lpp_m": hull.lpp,
            "depth_m": hull.depth,
            "stations": hull.stations.len(),
            "loadings": reports,
            "sensors": sensors,
        });
        println!(
            "{}",
            serde_json::to_string_pretty(&out).expect("serialisable")
        );
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
        row(
            "displacement (buoyancy)",
            &format!("{:.3} kg", h.displacement_kg),
        );
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
                "{:.3} kg{}",
                m.mass_kg,
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
        println!("  sectional-area curve (x m, aft_of_fp, draft m, area m2, half-breadth m):");
        for s in &h.sectional_area {
            println!(
                "    {:>9.4} {:>7.4} {:>8.4} {:>10.6} {:>8.4}",
                s.x_m,
                hull.aft_of_fp(s.x_m),
                s.draft_m,
                s.area_m2,
                s.half_breadth_m
            );
        }
    }
    if !hull.sensors.is_empty() {
        println!();
        println!("sensors (name, aft_of_fp, x m, girth m, y m, z m, diameter m):");
        for s in &hull.sensors {
            println!(
                "  {:<8} {:>7.4} {:>9.4} {:>8.4} {:>8.4} {:>8.4} {:>7.4}",
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
    let (x, given) = match (a.x_m, a.aft_of_fp) {
        (Some(x), _) => (x, format!("--x-m {x}")),
        (None, Some(f)) => (hull.station_x(f), format!("--aft-of-fp {f}")),
        (None, None) => unreachable!("clap requires one of them"),
    };
    if !x.is_finite() {
        return Err(slamtool::Error::Invalid(format!(
            "{given}: the station must be a finite number"
        )));
    }
    let sec = hull
        .section_at(x)
        .map_err(|e| slamtool::Error::Invalid(format!("{given}: {e}")))?;
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
    println!(
        "# {} at x = {:.4} m ({:.4} Lpp aft of FP); {frame}",
        hull.name,
        x + 0.0,
        hull.aft_of_fp(x) + 0.0
    );
    println!("y_m,z_m");
    for p in &sec.points {
        // `+ 0.0` turns −0 into 0 so that no "-0.000000" appears
        println!("{:.6},{:.6}", p[0] + 0.0, p[1] + 0.0);
    }
    Ok(())
}
