//! The saved results an assessment report is drawn from: `summary.json`, `motions.json`, the hull file
//! named in the provenance (checked against its SHA-256), and each SPH run folder (`cache/<key>/`:
//! `summary.json` with the run's settings, `history.csv`, `peak_pressure.png`). Nothing is recomputed
//! except the hull's hydrostatics and body plan, which are geometry, from the very file assessed.

use std::path::{Path, PathBuf};

use serde_json::Value;
use sha2::{Digest, Sha256};

use crate::error::{Error, Result};
use crate::hull::Hull;

/// A number field of a JSON object.
pub fn num(v: &Value, key: &str) -> Option<f64> {
    v.get(key).and_then(Value::as_f64)
}

/// A text field of a JSON object ("" when absent).
pub fn text<'a>(v: &'a Value, key: &str) -> &'a str {
    v.get(key).and_then(Value::as_str).unwrap_or("")
}

/// An array field of a JSON object (empty when absent).
pub fn list<'a>(v: &'a Value, key: &str) -> &'a [Value] {
    v.get(key)
        .and_then(Value::as_array)
        .map_or(&[][..], Vec::as_slice)
}

/// One SPH run folder as saved.
#[derive(Debug, Clone)]
pub struct Run {
    pub folder: PathBuf,
    /// The run's own summary.json (settings under `setup`).
    pub summary: Value,
    /// Columns of history.csv by name.
    pub columns: Vec<(String, Vec<f64>)>,
    /// Columns of each keel stage's history.csv (`stage_<k>/`), by stage index
    /// ([`crate::sph::keel_stage`]); empty where a stage's folder is missing.
    pub stages: Vec<Vec<(String, Vec<f64>)>>,
    /// Each keel stage's own summary.json, by stage index; `None` where it is missing or unreadable.
    pub stage_summaries: Vec<Option<Value>>,
    pub peak_png: Option<Vec<u8>>,
}

impl Run {
    pub fn column(&self, name: &str) -> Option<&[f64]> {
        self.columns
            .iter()
            .find(|(n, _)| n == name)
            .map(|(_, c)| c.as_slice())
    }

    /// The time and values of column `col` of the record a sensor's values come from: the keel
    /// stage's when one resolved the sensor (its index in the run summary), else the run's own.
    pub fn record_of(&self, sensor: &str, col: &str) -> Option<(&[f64], &[f64])> {
        let stage = self.summary["sensors"]
            .as_array()?
            .iter()
            .find(|q| q["name"].as_str() == Some(sensor))
            .and_then(|q| q["stage"]["stage"].as_u64());
        let cols = match stage {
            Some(k) => self.stages.get(k as usize)?,
            None => &self.columns,
        };
        let find = |name: &str| {
            cols.iter()
                .find(|(n, _)| n == name)
                .map(|(_, c)| c.as_slice())
        };
        Some((find("time_s")?, find(col)?))
    }
}

/// Everything the report draws from.
#[derive(Debug)]
pub struct Saved {
    pub dir: PathBuf,
    pub summary: Value,
    /// Strip-theory results (`motions.json`), when this assessment saved them.
    pub motions: Option<Value>,
    /// The hull, when its file is where the provenance says and unchanged.
    pub hull: std::result::Result<Hull, String>,
    /// Run folders by event index (None: no SPH run, or the folder is missing).
    pub runs: Vec<Option<Run>>,
    /// Why a run folder named in summary.json could not be read.
    pub missing: Vec<String>,
}

fn read_json(path: &Path) -> Result<Value> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
    serde_json::from_str(&text).map_err(|e| {
        Error::Invalid(format!(
            "{}:{}:{}: not a valid results file: {e}",
            path.display(),
            e.line(),
            e.column()
        ))
    })
}

fn sha256_of(path: &Path) -> std::io::Result<String> {
    let bytes = std::fs::read(path)?;
    Ok(format!("{:x}", Sha256::digest(&bytes)))
}

/// The assessed hull file: the path in the provenance as written (relative to where `assess` ran), or,
/// when the report is made from another folder, that path under each folder above the results folder;
/// the first that exists with the recorded SHA-256 is the one.
fn load_hull(summary: &Value, dir: &Path) -> std::result::Result<Hull, String> {
    let inputs = list(&summary["provenance"], "inputs");
    let first = inputs.first().ok_or("summary.json names no input files")?;
    let path = PathBuf::from(text(first, "path"));
    let mut candidates = vec![path.clone()];
    if path.is_relative()
        && let Ok(d) = dir.canonicalize()
    {
        candidates.extend(d.ancestors().map(|a| a.join(&path)));
    }
    let mut changed = None;
    for c in candidates.iter().filter(|c| c.is_file()) {
        match sha256_of(c) {
            Ok(sha) if sha == text(first, "sha256") => {
                return Hull::from_file(c).map_err(|e| e.to_string());
            }
            _ => changed = changed.or(Some(c.clone())),
        }
    }
    Err(match changed {
        Some(c) => format!(
            "hull file {} has changed since the assessment (SHA-256 differs)",
            c.display()
        ),
        None => format!(
            "hull file {} not found (looked relative to the current folder and to every folder above {})",
            path.display(),
            dir.display()
        ),
    })
}

fn read_history(path: &Path) -> Result<Vec<(String, Vec<f64>)>> {
    let text = std::fs::read_to_string(path).map_err(|e| Error::io(path, e))?;
    let mut r = csv::ReaderBuilder::new()
        .comment(Some(b'#'))
        .from_reader(text.as_bytes());
    let header: Vec<String> = r
        .headers()
        .map_err(|e| Error::Invalid(format!("{}: {e}", path.display())))?
        .iter()
        .map(str::to_string)
        .collect();
    let mut cols: Vec<Vec<f64>> = vec![Vec::new(); header.len()];
    for (i, rec) in r.records().enumerate() {
        let rec = rec.map_err(|e| Error::Invalid(format!("{}: {e}", path.display())))?;
        for (j, field) in rec.iter().enumerate().take(header.len()) {
            let v: f64 = field.trim().parse().map_err(|_| {
                Error::Invalid(format!(
                    "{}: record {} column '{}': '{field}' is not a number",
                    path.display(),
                    i + 1,
                    header[j]
                ))
            })?;
            cols[j].push(v);
        }
    }
    Ok(header.into_iter().zip(cols).collect())
}

fn load_run(dir: &Path) -> Result<Run> {
    let summary = read_json(&dir.join("summary.json"))?;
    let columns = read_history(&dir.join("history.csv"))?;
    let peak_png = std::fs::read(dir.join(crate::sph::peak_snapshot::FILE)).ok();
    let n_stages = summary["stages"].as_array().map_or(0, Vec::len);
    let stage_dir = |k: usize| dir.join(format!("stage_{k}"));
    let stages = (0..n_stages)
        .map(|k| read_history(&stage_dir(k).join("history.csv")).unwrap_or_default())
        .collect();
    let stage_summaries = (0..n_stages)
        .map(|k| read_json(&stage_dir(k).join("summary.json")).ok())
        .collect();
    Ok(Run {
        folder: dir.to_path_buf(),
        summary,
        columns,
        stages,
        stage_summaries,
        peak_png,
    })
}

impl Saved {
    /// Read the results in `dir` (the output folder of `slamtool assess`).
    pub fn load(dir: &Path) -> Result<Self> {
        let path = dir.join("summary.json");
        if !path.is_file() {
            return Err(Error::Invalid(format!(
                "{} holds no summary.json: give the output folder of `slamtool assess`",
                dir.display()
            )));
        }
        let summary = read_json(&path)?;
        if summary.get("events").and_then(Value::as_array).is_none() {
            return Err(Error::Invalid(format!(
                "{}: not the summary of an assessment (no 'events' list)",
                path.display()
            )));
        }
        let motions = read_json(&dir.join("motions.json")).ok();
        let hull = load_hull(&summary, dir);
        let mut runs = Vec::new();
        let mut missing = Vec::new();
        for e in list(&summary, "events") {
            let folder = text(e, "run_folder");
            if folder.is_empty() {
                runs.push(None);
                continue;
            }
            // A path read back from the results is confined to the results folder.
            let run_dir = crate::output_policy::confined(dir, folder).map_err(|why| {
                Error::Invalid(format!(
                    "{}: the run_folder of an event is refused: {why}; the results folder is damaged \
                     (run `slamtool assess` again)",
                    path.display()
                ))
            })?;
            match load_run(&run_dir) {
                Ok(r) => runs.push(Some(r)),
                Err(err) => {
                    missing.push(format!("run folder {folder}: {err}"));
                    runs.push(None);
                }
            }
        }
        Ok(Self {
            dir: dir.to_path_buf(),
            summary,
            motions,
            hull,
            runs,
            missing,
        })
    }

    pub fn events(&self) -> &[Value] {
        list(&self.summary, "events")
    }

    pub fn stations(&self) -> &[Value] {
        list(&self.summary, "stations")
    }

    /// Sensor names at a station, in the order of the estimates (the colour index of each sensor).
    pub fn sensors_at(&self, station: f64) -> Vec<String> {
        let mut names: Vec<String> = Vec::new();
        for e in self.events().iter().filter(|e| at(e, station)) {
            for s in list(&e["analytic"], "sensors")
                .iter()
                .chain(list(&e["sph"], "sensors"))
            {
                let n = text(s, "name").to_string();
                if !names.contains(&n) {
                    names.push(n);
                }
            }
        }
        names
    }

    /// The local deadrise (deg) of sensor `name`'s panel: the mean slope of its section's contour over
    /// the panel's girth span [s - w/2, s + w/2], s the sensor's girth and w the panel width; `None`
    /// without the hull file.
    pub fn local_deadrise_deg(&self, name: &str, width: f64) -> Option<f64> {
        let hull = self.hull.as_ref().ok()?;
        let sensor = hull.sensors.iter().find(|s| s.name == name)?;
        let section = hull.section_at(sensor.x).ok()?;
        let a = section.point_at_girth((sensor.girth - 0.5 * width).max(0.0));
        let b = section.point_at_girth((sensor.girth + 0.5 * width).min(section.girth()));
        let (dy, dz) = ((b[0] - a[0]).abs(), (b[1] - a[1]).abs());
        (dy + dz > 0.0).then(|| dz.atan2(dy).to_degrees())
    }

    /// Girth of a sensor from the keel (m), from the hull file.
    pub fn girth(&self, name: &str) -> Option<f64> {
        self.hull
            .as_ref()
            .ok()?
            .sensors
            .iter()
            .find(|s| s.name == name)
            .map(|s| s.girth)
    }
}

/// Whether an event is at `station` (fraction of Lpp aft of the FP).
/// `v` times `scale` with `digits` decimals, "-" where there is no value.
pub fn fmt(v: Option<f64>, scale: f64, digits: usize) -> String {
    v.map_or("-".into(), |x| format!("{:.*}", digits, x * scale))
}

pub fn at(e: &Value, station: f64) -> bool {
    num(e, "station").is_some_and(|s| (s - station).abs() < 1e-9)
}

/// `s` with its first letter in upper case.
pub fn capitalised(s: &str) -> String {
    let mut c = s.chars();
    c.next()
        .map(|f| f.to_uppercase().chain(c).collect())
        .unwrap_or_default()
}

/// A speed (m/s) as printed: at most three decimals, trailing zeros dropped ("10.289", "2.2"), "-" for
/// none.
pub fn speed_text(v: Option<f64>) -> String {
    v.map_or("-".into(), |x| {
        let s = format!("{x:.3}");
        s.trim_end_matches('0').trim_end_matches('.').to_string()
    })
}
