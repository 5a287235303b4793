//! `slamtool similarity`: the nonlinear similarity solution of constant-speed wedge entry
//! ([`slamtool::analytic::similarity`]).

use std::path::PathBuf;

use clap::Args;
use slamtool::analytic::similarity::{self as sim, DEFAULT_GRID, Similarity, TABLE_DEG};
use slamtool::provenance::{Provenance, TOOL};

use super::global::JsonArg;

/// Examples at the end of `slamtool similarity --help`.
pub const EXAMPLES: &str = "\
Examples:
  slamtool similarity --deadrise-deg 20
  slamtool similarity --deadrise-deg 20 --json -o wedge20-similarity.csv
  slamtool similarity --table

Validity: a symmetric wedge entering calm water at constant speed V; potential flow,
no gravity, no air. The flow is self-similar in x/(V t), z/(V t); z is measured from
the undisturbed surface (keel at z/(V t) = -1). A deadrise where the iteration does
not converge is a numerical failure (exit status 3), not an estimate (today: 60 deg).";

#[derive(Debug, Args)]
pub struct SimilarityArgs {
    /// Deadrise angle (deg), 5 to 60.
    #[arg(long, allow_negative_numbers = true, required_unless_present = "table")]
    deadrise_deg: Option<f64>,
    /// The table for 5 to 60 deg in steps of 5 instead of one deadrise.
    #[arg(long, conflicts_with = "deadrise_deg")]
    table: bool,
    /// Write the pressure distribution (or the table) as CSV, with its provenance.
    #[arg(short = 'o', long = "out", value_name = "FILE")]
    out: Option<PathBuf>,
    #[command(flatten)]
    json: JsonArg,
}

fn summary_json(s: &Similarity) -> serde_json::Value {
    serde_json::json!({
        "deadrise_deg": s.deadrise_deg,
        "cp_max": s.cp_max,
        "z_cp_max_over_vt": s.z_cp_max,
        "spray_root_over_vt": s.root,
        "spray_root_body_z_over_vt": s.root_body_z,
        "force_over_rho_v3_t": s.force,
        "wagner_cp_max": sim::wagner_cp_max(s.deadrise_deg),
        "panels": s.panels,
        "residual": s.residual,
    })
}

pub fn run(a: SimilarityArgs) -> slamtool::Result<()> {
    let settings = serde_json::json!({
        "deadrise_deg": a.deadrise_deg, "table": a.table,
        "h_root": DEFAULT_GRID.h_root, "growth": DEFAULT_GRID.growth,
        "far": DEFAULT_GRID.far, "jet": DEFAULT_GRID.jet,
    });
    let prov = Provenance::new(&[], settings)?;
    if a.table {
        return table(&a, &prov);
    }
    let deg = a.deadrise_deg.unwrap_or(f64::NAN);
    sim::check_deadrise(deg)?;
    let s = sim::solve(deg)?;
    if let Some(path) = &a.out {
        let header = vec!["z_over_vt".to_string(), "cp".to_string()];
        let rows: Vec<Vec<String>> = s
            .pressure
            .iter()
            .map(|p| vec![format!("{:.6}", p[0]), format!("{:.6}", p[1])])
            .collect();
        let text = slamtool::sph::output::csv_text(Some(&prov), &header, &rows)?;
        slamtool::files::write_text_atomic(path, &text)?;
    }
    if a.json.json {
        let mut out = summary_json(&s);
        out["tool"] = TOOL.into();
        out["provenance"] = serde_json::to_value(&prov).unwrap_or_default();
        out["warnings"] = serde_json::json!([]);
        out["outputs"] = serde_json::json!({ "csv": a.out });
        out["pressure"] = serde_json::to_value(&s.pressure).unwrap_or_default();
        println!("{out}");
        return Ok(());
    }
    println!("similarity solution, wedge of deadrise {deg} deg at constant speed (no gravity)");
    println!(
        "  Cp_max = 2 p_max/(rho V^2)  {:.3}   (Wagner (pi^2/4) cot^2 beta: {:.3})",
        s.cp_max,
        sim::wagner_cp_max(deg)
    );
    println!(
        "  at z/(V t)                  {:.4}   (z from the undisturbed surface, keel at -1)",
        s.z_cp_max
    );
    println!(
        "  spray root x/(V t), z/(V t) {:.4}, {:.4}",
        s.root[0], s.root[1]
    );
    println!("  F / (rho V^3 t)             {:.3}", s.force);
    println!(
        "  panels {}, kinematic residual {:.1e}",
        s.panels, s.residual
    );
    if let Some(p) = &a.out {
        println!("  pressure distribution: {}", p.display());
    }
    Ok(())
}

fn table(a: &SimilarityArgs, prov: &Provenance) -> slamtool::Result<()> {
    let rows = sim::table(&TABLE_DEG, &DEFAULT_GRID);
    let cell = |r: &sim::TableRow| -> Vec<String> {
        match &r.solution {
            Ok(s) => vec![
                format!("{}", r.deadrise_deg),
                format!("{:.4}", s.cp_max),
                format!("{:.4}", s.z_cp_max),
                format!("{:.4}", s.root[0]),
                format!("{:.4}", s.root[1]),
                format!("{:.4}", s.force),
                format!("{:.4}", s.cp_max / sim::wagner_cp_max(r.deadrise_deg)),
                "converged".into(),
            ],
            Err(e) => {
                let mut v = vec![format!("{}", r.deadrise_deg)];
                v.extend(std::iter::repeat_n(String::new(), 6));
                v.push(e.clone());
                v
            }
        }
    };
    let header: Vec<String> = [
        "deadrise_deg",
        "cp_max",
        "z_cp_max_over_vt",
        "root_x_over_vt",
        "root_z_over_vt",
        "force_over_rho_v3_t",
        "cp_max_over_wagner",
        "status",
    ]
    .iter()
    .map(|s| s.to_string())
    .collect();
    let table: Vec<Vec<String>> = rows.iter().map(cell).collect();
    if let Some(path) = &a.out {
        let text = slamtool::sph::output::csv_text(Some(prov), &header, &table)?;
        slamtool::files::write_text_atomic(path, &text)?;
    }
    if a.json.json {
        let list: Vec<serde_json::Value> = rows
            .iter()
            .map(|r| match &r.solution {
                Ok(s) => summary_json(s),
                Err(e) => serde_json::json!({"deadrise_deg": r.deadrise_deg, "error": e}),
            })
            .collect();
        let out = serde_json::json!({
            "tool": TOOL, "provenance": prov, "warnings": [], "outputs": { "csv": a.out },
            "table": list,
        });
        println!("{out}");
        return Ok(());
    }
    println!(
        "similarity solution of constant-speed wedge entry (no gravity); z from the undisturbed surface"
    );
    println!(
        "  {:>6} {:>10} {:>9} {:>9} {:>9} {:>11} {:>9}",
        "beta", "Cp_max", "z/Vt", "root x", "root z", "F/rhoV3t", "/Wagner"
    );
    for (r, c) in rows.iter().zip(&table) {
        if r.solution.is_ok() {
            println!(
                "  {:>6} {:>10} {:>9} {:>9} {:>9} {:>11} {:>9}",
                c[0], c[1], c[2], c[3], c[4], c[5], c[6]
            );
        } else {
            println!("  {:>6}  {}", c[0], c[7]);
        }
    }
    Ok(())
}
