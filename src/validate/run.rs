//! The computations a case file can name (`kind`), and a memo of SPH runs shared by the cases of one
//! suite (the 20 deg similarity and convergence cases use the same runs).

use std::collections::HashMap;
use std::sync::{Arc, Mutex};

use super::{
    Case, Mode, Outcome, drops, entry_velocities, hermundstad_forcing, ochi_trends, quoted,
    seakeeping, ships, wedge_bounds, wedge_table, wedges,
};
use crate::error::{Error, Result};
use crate::sph;

/// Every `kind` a case file may give.
pub const KINDS: &[&str] = &[
    "wedge-similarity",
    "wedge-convergence",
    "wedge-convergence-table",
    "wedge-force-bounds",
    "wedge-pressure-bound",
    "breder2005-load-ratio",
    "air-single-phase-limit",
    "air-cushion-sound-speed",
    "air-cushion-ratio",
    "whelan2004-peak-pressure",
    "zhao1996-prescribed",
    "zhao1996-drop",
    "yettou2006-drop",
    "yettou2006-momentum-models",
    "wigley3-heave-coefficients",
    "wigley3-wave-loads",
    "wigley3-heave-rao",
    "wigley3-zero-speed-raos",
    "ochi-vform-period",
    "ochi1958-particulars",
    "ochi1958-trend",
    "ochi1958-speed-trend",
    "ochi1958-fore-trend",
    "ochi1958-pressures",
    "hermundstad2005-wagner",
    "hermundstad2005-assess",
    "ochi1958-entry-velocities",
    "hermundstad2005-measured-forcing",
];

/// SPH runs of this suite, by a key that names everything that determines them, and the folder where
/// cases that run `assess` keep their outputs.
#[derive(Default)]
pub struct Memo {
    runs: Mutex<HashMap<String, Arc<sph::RunResult>>>,
    assessments: Mutex<HashMap<String, Arc<crate::assess::Assessment>>>,
    /// Work folder (`None`: the system's temporary folder).
    pub work: Option<std::path::PathBuf>,
    /// Whether the suite runs in `--full` mode (the ship cases then assess with SPH, `screen`).
    pub full: bool,
}

impl Memo {
    /// A memo whose assessments are written under `work`, for a suite run in `mode`.
    pub fn new(work: std::path::PathBuf, mode: Mode) -> Self {
        Memo {
            work: Some(work),
            full: matches!(mode, Mode::Full),
            ..Default::default()
        }
    }

    /// The assessment under `key`, computed by `f` the first time (the ship cases share one).
    pub fn assessment(
        &self,
        key: String,
        f: impl FnOnce() -> Result<crate::assess::Assessment>,
    ) -> Result<Arc<crate::assess::Assessment>> {
        if let Some(a) = self.assessments.lock().map_err(poisoned)?.get(&key) {
            return Ok(a.clone());
        }
        let a = Arc::new(f()?);
        self.assessments
            .lock()
            .map_err(poisoned)?
            .insert(key, a.clone());
        Ok(a)
    }

    /// The work folder of one case.
    pub fn work_dir(&self, case: &str) -> std::path::PathBuf {
        match &self.work {
            Some(w) => w.join(case),
            None => std::env::temp_dir()
                .join(format!("slamtool-validate-{}", std::process::id()))
                .join(case),
        }
    }

    /// The run under `key`, computed by `f` the first time.
    pub fn run(
        &self,
        key: String,
        f: impl FnOnce() -> Result<sph::RunResult>,
    ) -> Result<Arc<sph::RunResult>> {
        if let Some(r) = self.runs.lock().map_err(poisoned)?.get(&key) {
            return Ok(r.clone());
        }
        let r = Arc::new(f()?);
        self.runs.lock().map_err(poisoned)?.insert(key, r.clone());
        Ok(r)
    }
}

fn poisoned<T>(_: T) -> Error {
    Error::Invalid("a validation run panicked earlier".into())
}

/// Run the computation of a case.
pub fn run(case: &Case, mode: Mode, memo: &Memo) -> Result<Outcome> {
    match case.kind.as_str() {
        "wedge-similarity" => wedges::similarity(case, mode, memo),
        "wedge-convergence" => wedges::convergence(case, mode, memo),
        "wedge-convergence-table" => wedge_table::table(case, mode, memo),
        "wedge-force-bounds" => wedge_bounds::force_bounds(case, mode, memo),
        "wedge-pressure-bound" => wedge_bounds::pressure_bound(case, mode, memo),
        "breder2005-load-ratio" => quoted::breder_load_ratio(case, mode, memo),
        "air-single-phase-limit" => super::air::single_phase_limit(case, mode, memo),
        "air-cushion-sound-speed" => super::air::sound_speed_sensitivity(case, mode, memo),
        "air-cushion-ratio" => super::air::cushion_ratio(case, mode, memo),
        "whelan2004-peak-pressure" => quoted::whelan_peak_pressure(case),
        "zhao1996-prescribed" => drops::zhao_prescribed(case, mode, memo),
        "zhao1996-drop" => drops::zhao_drop(case, mode, memo),
        "yettou2006-drop" => drops::yettou_drop(case, mode, memo),
        "yettou2006-momentum-models" => drops::yettou_momentum_models(case),
        "wigley3-heave-coefficients" => seakeeping::wigley_coefficients(case),
        "wigley3-wave-loads" => seakeeping::wigley_wave_loads(case),
        "wigley3-heave-rao" => seakeeping::wigley_heave_rao(case),
        "wigley3-zero-speed-raos" => seakeeping::wigley_zero_speed(case),
        "ochi-vform-period" => seakeeping::ochi_period(case),
        "ochi1958-particulars" => ships::ochi_particulars(case),
        "ochi1958-trend" => ochi_trends::keel_trend(case, memo),
        "ochi1958-speed-trend" => ochi_trends::speed_trend(case, memo),
        "ochi1958-fore-trend" => ochi_trends::fore_trend(case, memo),
        "ochi1958-pressures" => ships::ochi_pressures(case, memo),
        "hermundstad2005-wagner" => ships::hermundstad_wagner(case),
        "hermundstad2005-assess" => ships::hermundstad_assess(case, memo),
        "ochi1958-entry-velocities" => entry_velocities::ochi_entry_velocities(case),
        "hermundstad2005-measured-forcing" => {
            hermundstad_forcing::measured_forcing(case, mode, memo)
        }
        other => Err(Error::Invalid(format!("unknown validation kind `{other}`"))),
    }
}

/// Read the numeric rows of a reference CSV file (lines starting with `#` and the header are skipped).
pub fn csv_rows(path: &std::path::Path) -> Result<Vec<Vec<f64>>> {
    let src = crate::input::SourceText::read(path)?;
    let mut rows = Vec::new();
    let mut header = true;
    for (i, line) in src.text.lines().enumerate() {
        let l = line.trim();
        if l.is_empty() || l.starts_with('#') {
            continue;
        }
        if header {
            header = false;
            continue;
        }
        let mut row = Vec::new();
        for (k, cell) in l.split(',').enumerate() {
            let x: f64 = cell.trim().parse().map_err(|_| {
                Error::Input(src.error_line(
                    i + 1,
                    k + 1,
                    format!("`{}` is not a number", cell.trim()),
                ))
            })?;
            row.push(x);
        }
        rows.push(row);
    }
    Ok(rows)
}

/// Read a reference TOML file as a table.
pub fn toml_table(path: &std::path::Path) -> Result<toml::Table> {
    let src = crate::input::SourceText::read(path)?;
    src.parse_toml::<toml::Table>().map_err(Error::Input)
}

/// A number at `a.b.c` in a reference table.
pub fn toml_number(t: &toml::Table, keys: &[&str]) -> Result<f64> {
    let v = lookup(t, keys)?;
    v.as_float()
        .or_else(|| v.as_integer().map(|i| i as f64))
        .ok_or_else(|| {
            Error::Invalid(format!(
                "reference value {} is not a number",
                keys.join(".")
            ))
        })
}

/// A list of numbers at `a.b.c` in a reference table.
pub fn toml_numbers(t: &toml::Table, keys: &[&str]) -> Result<Vec<f64>> {
    let v = lookup(t, keys)?;
    let bad = || {
        Error::Invalid(format!(
            "reference value {} is not a list of numbers",
            keys.join(".")
        ))
    };
    v.as_array()
        .ok_or_else(bad)?
        .iter()
        .map(|x| {
            x.as_float()
                .or_else(|| x.as_integer().map(|i| i as f64))
                .ok_or_else(bad)
        })
        .collect()
}

/// The value at `a.b.c` in a reference table.
pub fn lookup<'a>(t: &'a toml::Table, keys: &[&str]) -> Result<&'a toml::Value> {
    let missing = || Error::Invalid(format!("reference value {} not found", keys.join(".")));
    let (last, path) = keys.split_last().ok_or_else(missing)?;
    let mut cur = t;
    for k in path {
        cur = cur.get(*k).and_then(|v| v.as_table()).ok_or_else(missing)?;
    }
    cur.get(*last).ok_or_else(missing)
}
