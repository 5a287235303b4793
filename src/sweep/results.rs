//! The results of a sweep: one [`CaseResult`] per case (kept in the case cache and in `sweep.json`), the
//! tidy table (`results.csv`, one row per case × station × sensor), the case table (`cases.csv`, one row
//! per case) and the best variants under the sweep file's limits (`best.csv`).

use serde::{Deserialize, Serialize};

use super::file::{Best, Objective};
use crate::assess::{EventResult, StationResult};
use crate::error::Result;
use crate::provenance::{InputFile, Provenance};
use crate::report::csv_number;
use crate::report::sanity::SlamFlag;

/// One parameter value of a case.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct Param {
    pub name: String,
    pub value: f64,
}

/// A sensor's design pressure in a case: the largest over the case's events (SPH where it ran at the
/// station, the analytic MLM peak otherwise, as `assess` decides).
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct CaseSensor {
    pub name: String,
    /// `None` where no model computes it ([`crate::assess::design_rule::NO_VALUE_FLAT_KEEL`]).
    pub design_pressure_pa: Option<f64>,
    pub source: String,
    pub speed_m_per_s: f64,
    pub wave: String,
}

/// A station in a case.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct CaseStation {
    pub station: f64,
    pub x_m: f64,
    pub emerging_events: usize,
    pub slamming_events: usize,
    /// Largest keel-entry velocity over the case's regular-wave events.
    pub max_entry_velocity_m_per_s: Option<f64>,
    /// Ochi's slam probability per encounter, the largest over the case's speeds and irregular seas
    /// (None without an irregular sea).
    pub slam_probability: Option<f64>,
    pub slams_per_hour: Option<f64>,
    pub section_force_peak_n_per_m: Option<f64>,
    pub sensors: Vec<CaseSensor>,
}

/// One case.
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct CaseResult {
    pub index: usize,
    pub id: String,
    /// Content hash of everything that determines the case (its cache key).
    pub key: String,
    pub parameters: Vec<Param>,
    pub wave: Option<String>,
    /// The variant hull file (relative to the output folder), when the hull is transformed.
    pub hull_file: Option<String>,
    pub lpp_m: f64,
    pub speeds_m_per_s: Vec<f64>,
    pub stations: Vec<CaseStation>,
    pub max_design_pressure_pa: Option<f64>,
    pub max_section_force_n_per_m: Option<f64>,
    pub max_slam_probability: Option<f64>,
    pub failed: Option<String>,
    pub warnings: Vec<String>,
}

impl CaseResult {
    /// The value the best-variants table ranks by.
    pub fn objective(&self, o: Objective) -> Option<f64> {
        match o {
            Objective::DesignPressure => self.max_design_pressure_pa,
            Objective::SectionForce => self.max_section_force_n_per_m,
            Objective::SlamProbability => self.max_slam_probability,
        }
    }

    pub fn param(&self, name: &str) -> Option<f64> {
        self.parameters
            .iter()
            .find(|p| p.name == name)
            .map(|p| p.value)
    }
}

/// Slam statistics of one station: (probability, slams per hour), the largest probability.
pub type Stats = Option<(f64, f64)>;

/// The stations of a case from its events and per-station design values (as `assess` computes them)
/// and the slam statistics per station.
pub fn stations(
    events: &[EventResult],
    per_station: &[StationResult],
    stats: &[Stats],
) -> Vec<CaseStation> {
    per_station
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let at: Vec<&EventResult> = events
                .iter()
                .filter(|e| (e.station - s.station).abs() < 1e-9)
                .collect();
            CaseStation {
                station: s.station,
                x_m: s.x_m,
                emerging_events: s.emerging_events,
                slamming_events: at.iter().filter(|e| e.slam_flag == SlamFlag::Slam).count(),
                max_entry_velocity_m_per_s: at
                    .iter()
                    .filter_map(|e| e.entry_velocity_m_per_s)
                    .reduce(f64::max),
                slam_probability: stats.get(k).copied().flatten().map(|s| s.0),
                slams_per_hour: stats.get(k).copied().flatten().map(|s| s.1),
                section_force_peak_n_per_m: s
                    .section_force_peak_n_per_m
                    .as_ref()
                    .and_then(|d| d.value),
                sensors: s
                    .design_pressure_pa
                    .iter()
                    .map(|d| CaseSensor {
                        name: d.name.clone(),
                        design_pressure_pa: d.value,
                        source: d.source.to_string(),
                        speed_m_per_s: d.speed_m_per_s,
                        wave: d.wave.clone(),
                    })
                    .collect(),
            }
        })
        .collect()
}

/// Fill the case-level maxima from the stations.
pub fn summarise(c: &mut CaseResult) {
    c.max_design_pressure_pa = c
        .stations
        .iter()
        .flat_map(|s| s.sensors.iter().filter_map(|q| q.design_pressure_pa))
        .reduce(f64::max);
    c.max_section_force_n_per_m = c
        .stations
        .iter()
        .filter_map(|s| s.section_force_peak_n_per_m)
        .reduce(f64::max);
    c.max_slam_probability = c
        .stations
        .iter()
        .filter_map(|s| s.slam_probability)
        .reduce(f64::max);
}

/// Provenance as stored in `sweep.json` (read back by `merge`).
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct Prov {
    pub tool: String,
    pub commit: String,
    pub inputs: Vec<ProvInput>,
    pub settings: serde_json::Value,
}

#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct ProvInput {
    pub path: String,
    pub sha256: String,
}

impl Prov {
    pub fn from_provenance(p: &Provenance) -> Self {
        Self {
            tool: p.tool.clone(),
            commit: p.commit.clone(),
            inputs: p
                .inputs
                .iter()
                .map(|i| ProvInput {
                    path: i.path.clone(),
                    sha256: i.sha256.clone(),
                })
                .collect(),
            settings: p.settings.clone(),
        }
    }

    pub fn provenance(&self) -> Provenance {
        Provenance {
            tool: self.tool.clone(),
            commit: self.commit.clone(),
            inputs: self
                .inputs
                .iter()
                .map(|i| InputFile {
                    path: i.path.clone(),
                    sha256: i.sha256.clone(),
                })
                .collect(),
            settings: self.settings.clone(),
        }
    }
}

/// Which part of a sweep a result holds.
#[derive(Debug, Clone, Copy, Serialize, Deserialize, PartialEq, Eq)]
pub struct Shard {
    /// 0-based.
    pub index: usize,
    pub count: usize,
}

/// A sweep's results (`sweep.json`).
#[derive(Debug, Clone, Serialize, Deserialize, PartialEq)]
pub struct SweepResult {
    pub tool: String,
    pub provenance: Prov,
    /// SHA-256 of the sweep file and of the hull and sea files it names: shards of one sweep share it.
    pub sweep_hash: String,
    pub name: String,
    pub fidelity: String,
    /// The parameters varied (numeric, then `wave`), in case-table order.
    pub parameters: Vec<String>,
    pub best: Best,
    pub total_cases: usize,
    /// The shard this holds, or None for a whole sweep (run unsharded, or merged).
    pub shard: Option<Shard>,
    pub cases: Vec<CaseResult>,
    pub failed_cases: usize,
    pub warnings: Vec<String>,
}

/// The sweep's warnings from its cases' own: each text once, in the order of first appearance, followed
/// by the cases that gave it ("(case c003)", or "(cases c001, c004 and 3 more)" when it came from more
/// than one), so that a reader of the sweep's report can find the case a warning belongs to.
pub fn warnings_of(cases: &[CaseResult]) -> Vec<String> {
    let mut texts: Vec<(&str, Vec<&str>)> = Vec::new();
    for c in cases {
        for w in &c.warnings {
            match texts.iter_mut().find(|(t, _)| *t == w.as_str()) {
                Some((_, ids)) => ids.push(&c.id),
                None => texts.push((w, vec![&c.id])),
            }
        }
    }
    const LISTED: usize = 3;
    texts
        .into_iter()
        .map(|(t, ids)| {
            let mut who = ids[..ids.len().min(LISTED)].join(", ");
            if ids.len() > LISTED {
                who.push_str(&format!(" and {} more", ids.len() - LISTED));
            }
            let noun = if ids.len() == 1 { "case" } else { "cases" };
            format!("{t} ({noun} {who})")
        })
        .collect()
}

/// Warnings a sweep prints (and its report lists) one by one up to this many; beyond it they are also
/// given by kind ([`warning_kinds`]).
pub const WARNINGS_IN_FULL: usize = 12;

/// The cases' warnings grouped by kind: warnings that differ only in their numbers (values, stations,
/// speeds) are of one kind. Each kind is given as its text with every number replaced by the range of
/// that number over the kind ("0.093..0.227" where the warnings differ, the number where they agree),
/// with the number of cases that gave it, in the order of first appearance, so that a long sweep's
/// hundreds of warnings can be read as a handful (every warning stays in `sweep.json` and the report).
/// The ranges are taken number by number: they bound the kind's warnings, they do not pair up.
pub fn warning_kinds(cases: &[CaseResult]) -> Vec<(String, usize)> {
    struct Kind {
        text: Vec<String>,
        ranges: Vec<(String, String)>,
        cases: usize,
        last_case: usize,
    }
    let mut kinds: Vec<Kind> = Vec::new();
    let all = cases
        .iter()
        .enumerate()
        .flat_map(|(i, c)| c.warnings.iter().map(move |w| (i, w)));
    for (case, w) in all {
        let (text, numbers) = split_numbers(w);
        match kinds.iter_mut().find(|k| k.text == text) {
            Some(k) => {
                if k.last_case != case {
                    (k.cases, k.last_case) = (k.cases + 1, case);
                }
                for (r, x) in k.ranges.iter_mut().zip(numbers) {
                    if number_order(&x, &r.0).is_lt() {
                        r.0 = x;
                    } else if number_order(&x, &r.1).is_gt() {
                        r.1 = x;
                    }
                }
            }
            None => kinds.push(Kind {
                text,
                ranges: numbers.into_iter().map(|x| (x.clone(), x)).collect(),
                cases: 1,
                last_case: case,
            }),
        }
    }
    kinds
        .into_iter()
        .map(|k| {
            let mut out = k.text[0].clone();
            for ((lo, hi), piece) in k.ranges.iter().zip(&k.text[1..]) {
                if lo == hi {
                    out.push_str(lo);
                } else {
                    out.push_str(&format!("{lo}..{hi}"));
                }
                out.push_str(piece);
            }
            (out, k.cases)
        })
        .collect()
}

/// A kind of [`warning_kinds`] as one line: "[n cases] text".
pub fn kind_line((text, cases): &(String, usize)) -> String {
    let noun = if *cases == 1 { "case" } else { "cases" };
    format!("[{cases} {noun}] {text}")
}

/// The order of two numbers as written: by value where both read as numbers, else as text (a version
/// or a date).
fn number_order(a: &str, b: &str) -> std::cmp::Ordering {
    match (a.parse::<f64>(), b.parse::<f64>()) {
        (Ok(x), Ok(y)) => x.total_cmp(&y),
        _ => a.cmp(b),
    }
}

/// `text` cut at its numbers (runs of digits, with the decimal points between them): the pieces of text
/// around them (one more than the numbers) and the numbers as written.
fn split_numbers(text: &str) -> (Vec<String>, Vec<String>) {
    let c: Vec<char> = text.chars().collect();
    let digit = |k: usize| c.get(k).is_some_and(|d| d.is_ascii_digit());
    let (mut pieces, mut numbers) = (vec![String::new()], Vec::new());
    let mut k = 0;
    while k < c.len() {
        if digit(k) {
            let start = k;
            while digit(k) || (c.get(k) == Some(&'.') && digit(k + 1)) {
                k += 1;
            }
            numbers.push(c[start..k].iter().collect());
            pieces.push(String::new());
        } else {
            pieces.last_mut().unwrap().push(c[k]);
            k += 1;
        }
    }
    (pieces, numbers)
}

fn num(v: Option<f64>) -> String {
    v.map_or(String::new(), csv_number)
}

/// The parameter columns of a case.
fn param_cells(r: &SweepResult, c: &CaseResult) -> Vec<String> {
    r.parameters
        .iter()
        .map(|p| {
            if p == "wave" {
                c.wave.clone().unwrap_or_default()
            } else {
                num(c.param(p))
            }
        })
        .collect()
}

/// The tidy table: one row per case × station × sensor (one row per station without sensors, one row per
/// failed case).
pub fn results_csv(r: &SweepResult) -> Result<String> {
    let mut header: Vec<String> = vec!["case".into()];
    header.extend(r.parameters.iter().cloned());
    header.extend(
        [
            "station",
            "x_m",
            "sensor",
            "design_pressure_pa",
            "source",
            "governing_speed_m_per_s",
            "governing_wave",
            "emerging_events",
            "slamming_events",
            "max_entry_velocity_m_per_s",
            "slam_probability",
            "slams_per_hour",
            "section_force_peak_n_per_m",
            "failed",
        ]
        .map(String::from),
    );
    let mut rows = Vec::new();
    for c in &r.cases {
        let head = || {
            let mut v = vec![c.id.clone()];
            v.extend(param_cells(r, c));
            v
        };
        if c.stations.is_empty() {
            let mut row = head();
            row.extend(std::iter::repeat_n(String::new(), 13));
            row.push(c.failed.clone().unwrap_or_default());
            rows.push(row);
        }
        for s in &c.stations {
            let station_cells = |row: &mut Vec<String>| {
                row.push(s.emerging_events.to_string());
                row.push(s.slamming_events.to_string());
                row.push(num(s.max_entry_velocity_m_per_s));
                row.push(num(s.slam_probability));
                row.push(num(s.slams_per_hour));
                row.push(num(s.section_force_peak_n_per_m));
                row.push(c.failed.clone().unwrap_or_default());
            };
            if s.sensors.is_empty() {
                let mut row = head();
                row.extend([csv_number(s.station), csv_number(s.x_m)]);
                row.extend(std::iter::repeat_n(String::new(), 5));
                station_cells(&mut row);
                rows.push(row);
            }
            for q in &s.sensors {
                let mut row = head();
                row.extend([
                    csv_number(s.station),
                    csv_number(s.x_m),
                    q.name.clone(),
                    q.design_pressure_pa.map_or(String::new(), csv_number),
                    q.source.clone(),
                    csv_number(q.speed_m_per_s),
                    q.wave.clone(),
                ]);
                station_cells(&mut row);
                rows.push(row);
            }
        }
    }
    crate::sph::output::csv_text(Some(&r.provenance.provenance()), &header, &rows)
}

/// One row per case: its parameters and maxima.
pub fn cases_csv(r: &SweepResult) -> Result<String> {
    let (header, rows) = case_table(r, &r.cases.iter().collect::<Vec<_>>());
    crate::sph::output::csv_text(Some(&r.provenance.provenance()), &header, &rows)
}

fn case_table(r: &SweepResult, cases: &[&CaseResult]) -> (Vec<String>, Vec<Vec<String>>) {
    let mut header: Vec<String> = vec!["case".into()];
    header.extend(r.parameters.iter().cloned());
    header.extend(
        [
            "max_design_pressure_pa",
            "max_section_force_n_per_m",
            "max_slam_probability",
            "hull_file",
            "failed",
        ]
        .map(String::from),
    );
    let rows = cases
        .iter()
        .map(|c| {
            let mut v = vec![c.id.clone()];
            v.extend(param_cells(r, c));
            v.extend([
                num(c.max_design_pressure_pa),
                num(c.max_section_force_n_per_m),
                num(c.max_slam_probability),
                c.hull_file.clone().unwrap_or_default(),
                c.failed.clone().unwrap_or_default(),
            ]);
            v
        })
        .collect();
    (header, rows)
}

/// The best variants: cases that finished, meet every limit of the rule and have a value of its
/// objective, lowest objective first (ties by case order), at most `count`.
pub fn best<'a>(r: &'a SweepResult, rule: &Best) -> Vec<&'a CaseResult> {
    let mut ok: Vec<&CaseResult> = r
        .cases
        .iter()
        .filter(|c| c.failed.is_none())
        .filter(|c| {
            rule.max_slam_probability
                .is_none_or(|p| c.max_slam_probability.is_some_and(|v| v < p))
        })
        .filter(|c| {
            rule.max_design_pressure_pa
                .is_none_or(|p| c.max_design_pressure_pa.is_some_and(|v| v <= p))
        })
        .filter(|c| c.objective(rule.minimise).is_some())
        .collect();
    ok.sort_by(|a, b| {
        let (x, y) = (
            a.objective(rule.minimise).unwrap_or(f64::INFINITY),
            b.objective(rule.minimise).unwrap_or(f64::INFINITY),
        );
        x.total_cmp(&y).then(a.index.cmp(&b.index))
    });
    ok.truncate(rule.count);
    ok
}

/// Why [`best`] is empty, in words: no case finished, none has a value of the objective, or none of
/// those meets the limits.
pub fn why_no_best(r: &SweepResult, rule: &Best) -> String {
    let finished: Vec<&CaseResult> = r.cases.iter().filter(|c| c.failed.is_none()).collect();
    let what = match rule.minimise {
        Objective::DesignPressure => "a design pressure",
        Objective::SectionForce => "a section-force peak",
        Objective::SlamProbability => "a slam probability (it needs an irregular sea)",
    };
    if finished.is_empty() {
        "No case finished.".into()
    } else if finished
        .iter()
        .all(|c| c.objective(rule.minimise).is_none())
    {
        format!(
            "No finished case has {what}, the quantity the rule ranks by: no station of any case had an \
             event with a load (no keel entry or flare impact in the sea file's waves, and no irregular \
             sea with a slam expected)."
        )
    } else {
        "No finished case meets the limits.".into()
    }
}

/// The rule in words, for the table's heading.
pub fn rule_text(rule: &Best) -> String {
    let what = match rule.minimise {
        Objective::DesignPressure => {
            "lowest design pressure (largest sensor design pressure of the case)"
        }
        Objective::SectionForce => "lowest section force (largest section-force peak of the case)",
        Objective::SlamProbability => "lowest slam probability (largest over the stations)",
    };
    let mut limits = Vec::new();
    if let Some(p) = rule.max_slam_probability {
        limits.push(format!("slam probability below {} %", p * 100.0));
    }
    if let Some(p) = rule.max_design_pressure_pa {
        limits.push(format!("design pressure at most {} kPa", p / 1e3));
    }
    if limits.is_empty() {
        format!("{what}, no limits")
    } else {
        format!("{what}, with {}", limits.join(" and "))
    }
}

/// `best.csv`: the best variants under the rule.
pub fn best_csv(r: &SweepResult) -> Result<String> {
    let chosen = best(r, &r.best);
    let (mut header, rows) = case_table(r, &chosen);
    header.insert(0, "rank".into());
    let rows: Vec<Vec<String>> = rows
        .into_iter()
        .enumerate()
        .map(|(i, mut row)| {
            row.insert(0, (i + 1).to_string());
            row
        })
        .collect();
    let mut prov = r.provenance.provenance();
    prov.settings["best_rule"] = serde_json::json!(rule_text(&r.best));
    crate::sph::output::csv_text(Some(&prov), &header, &rows)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn case(id: &str, warnings: &[&str]) -> CaseResult {
        CaseResult {
            index: 0,
            id: id.into(),
            key: String::new(),
            parameters: Vec::new(),
            wave: None,
            hull_file: None,
            lpp_m: 1.0,
            speeds_m_per_s: Vec::new(),
            stations: Vec::new(),
            max_design_pressure_pa: None,
            max_section_force_n_per_m: None,
            max_slam_probability: None,
            failed: None,
            warnings: warnings.iter().map(|w| w.to_string()).collect(),
        }
    }

    #[test]
    fn an_empty_best_table_says_why() {
        let rule = Best {
            minimise: Objective::DesignPressure,
            max_slam_probability: None,
            max_design_pressure_pa: Some(50e3),
            count: 5,
        };
        let mut r = SweepResult {
            tool: String::new(),
            provenance: Prov {
                tool: String::new(),
                commit: String::new(),
                inputs: Vec::new(),
                settings: serde_json::Value::Null,
            },
            sweep_hash: String::new(),
            name: "s".into(),
            fidelity: "analytic".into(),
            parameters: Vec::new(),
            best: rule.clone(),
            total_cases: 2,
            shard: None,
            cases: vec![case("c1", &[]), case("c2", &[])],
            failed_cases: 0,
            warnings: Vec::new(),
        };
        assert!(best(&r, &rule).is_empty());
        assert!(why_no_best(&r, &rule).starts_with("No finished case has a design pressure"));
        r.cases[0].max_design_pressure_pa = Some(80e3);
        assert_eq!(why_no_best(&r, &rule), "No finished case meets the limits.");
        for c in &mut r.cases {
            c.failed = Some("x".into());
        }
        assert_eq!(why_no_best(&r, &rule), "No case finished.");
    }

    #[test]
    fn a_warning_is_listed_once_with_the_cases_that_gave_it() {
        let cases = [
            case("c1", &["a", "b"]),
            case("c2", &["a"]),
            case("c3", &["a"]),
            case("c4", &["a"]),
            case("c5", &["a"]),
        ];
        assert_eq!(
            warnings_of(&cases),
            ["a (cases c1, c2, c3 and 2 more)", "b (case c1)"]
        );
        assert!(warnings_of(&[case("c1", &[])]).is_empty());
    }

    /// Warnings that differ only in their numbers are one kind, with the number of cases that gave it
    /// and each number given as its range over the kind.
    #[test]
    fn warnings_that_differ_in_their_numbers_are_one_kind() {
        let cases = [
            case(
                "c1",
                &[
                    "station 0.093 Lpp: keel rises at 0.0133",
                    "no design event at 1.000 m/s",
                    "station 0.133 Lpp: keel rises at 0.0133",
                ],
            ),
            case("c2", &["no design event at 1.100 m/s"]),
            case(
                "c3",
                &[
                    "station 0.133 Lpp: keel rises at 0.0133.",
                    "station 0.05 Lpp: keel rises at 0.0133",
                ],
            ),
        ];
        assert_eq!(
            warning_kinds(&cases),
            vec![
                (
                    "station 0.05..0.133 Lpp: keel rises at 0.0133".to_string(),
                    2
                ),
                ("no design event at 1.000..1.100 m/s".to_string(), 2),
                ("station 0.133 Lpp: keel rises at 0.0133.".to_string(), 1)
            ]
        );
    }
}
