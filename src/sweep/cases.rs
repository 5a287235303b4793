//! Expanding a sweep file into its cases, in a fixed order: the Cartesian product of the `[grid]` axes
//! (in the parameter order of [`super::file::NUMERIC`], then `wave`; the first axis varies slowest), each
//! combined with every sample of the `[latin_hypercube]` (when given). Case `i` is `c<i>` (zero-padded);
//! the order, and so the ids, depend on the sweep file only.

use std::ops::Range;

use toml::Spanned;

use super::file::{AxisRaw, NUMERIC, SweepFile};
use super::lhs;
use crate::error::InputError;
use crate::input::num;

/// Most cases a sweep may have (a typo in a step should not start a billion runs).
pub const MAX_CASES: usize = 1_000_000;

/// The range of the hull scale factors (`flare_scale`, `deadrise_scale`, `length_scale`, `beam_scale`)
/// a sweep accepts: a factor of ten either way is already far outside any design study.
pub const SCALE_RANGE: (f64, f64) = (0.1, 10.0);

/// Highest speed a sweep accepts, m/s (as a sea-state file's `speeds_m_s`).
pub const MAX_SPEED_M_S: f64 = 100.0;

/// One value of one parameter, with where it comes from in the sweep file.
#[derive(Debug, Clone)]
pub struct Value {
    pub name: &'static str,
    pub value: f64,
    pub span: Range<usize>,
}

/// One case of a sweep.
#[derive(Debug, Clone)]
pub struct Case {
    pub index: usize,
    pub id: String,
    /// Numeric parameters, in [`NUMERIC`] order.
    pub values: Vec<Value>,
    /// A regular wave of the sea file chosen by name, and where.
    pub wave: Option<(String, Range<usize>)>,
}

impl Case {
    pub fn get(&self, name: &str) -> Option<f64> {
        self.values.iter().find(|v| v.name == name).map(|v| v.value)
    }

    pub fn span(&self, name: &str) -> Option<Range<usize>> {
        self.values
            .iter()
            .find(|v| v.name == name)
            .map(|v| v.span.clone())
    }

    /// "speed_m_s=2, flare_scale=1.1, wave=H0.20"
    pub fn label(&self) -> String {
        let mut parts: Vec<String> = self
            .values
            .iter()
            .map(|v| format!("{}={}", v.name, v.value))
            .collect();
        if let Some((w, _)) = &self.wave {
            parts.push(format!("wave={w}"));
        }
        if parts.is_empty() {
            "base".into()
        } else {
            parts.join(", ")
        }
    }
}

/// What a parameter accepts, checked on every value (hull-dependent limits are left to the hull checks).
fn check_value(f: &SweepFile, name: &str, x: f64, span: Range<usize>) -> Result<(), InputError> {
    let bad = |why: &str| f.error_at(span.clone(), format!("{name} = {}: {why}", num(x)));
    if !x.is_finite() {
        return Err(bad("not a finite number"));
    }
    match name {
        "speed_m_s" if x < 0.0 => Err(bad("a speed must not be negative")),
        "wave_height_m" | "hs_m" if !(1e-3..=40.0).contains(&x) => Err(bad(
            "wave heights lie between 1 mm and 40 m (the limits of a sea-state file)",
        )),
        "wavelength_m" if !(0.015..=6000.0).contains(&x) => Err(bad(
            "wavelengths lie between 0.015 m and 6000 m (the limits of a sea-state file)",
        )),
        "tp_s" if !(0.1..=60.0).contains(&x) => Err(bad(
            "periods lie between 0.1 s and 60 s (the limits of a sea-state file)",
        )),
        "draft_m" if x <= 0.0 => Err(bad("the mean draft must be positive")),
        "flare_scale" | "deadrise_scale" | "length_scale" | "beam_scale" if x <= 0.0 => {
            Err(bad("a scale factor must be positive"))
        }
        "flare_scale" | "deadrise_scale" | "length_scale" | "beam_scale"
            if !(SCALE_RANGE.0..=SCALE_RANGE.1).contains(&x) =>
        {
            Err(bad(&format!(
                "a scale factor between {} and {} keeps a hull a ship (beyond it the variant is another \
                 object, and its pressures mean nothing)",
                SCALE_RANGE.0, SCALE_RANGE.1
            )))
        }
        "speed_m_s" if x > MAX_SPEED_M_S => Err(bad(&format!(
            "speeds lie between 0 and {MAX_SPEED_M_S} m/s (the limit of a sea-state file)"
        ))),
        _ => Ok(()),
    }
}

/// The values of one grid axis.
fn axis_values(f: &SweepFile, name: &str, a: &Spanned<AxisRaw>) -> Result<Vec<Value>, InputError> {
    let name = NUMERIC.iter().find(|n| **n == name).copied().unwrap_or("?");
    let mut out: Vec<Value> = Vec::new();
    match a.get_ref() {
        AxisRaw::List(v) => {
            if v.is_empty() {
                return Err(f.error(a, format!("{name}: the list of values is empty")));
            }
            for x in v {
                out.push(Value {
                    name,
                    value: *x.get_ref(),
                    span: x.span(),
                });
            }
        }
        AxisRaw::Range(r) => {
            let (start, stop) = (*r.start.get_ref(), *r.stop.get_ref());
            for (v, w) in [(&r.start, "start"), (&r.stop, "stop")] {
                if !v.get_ref().is_finite() {
                    return Err(f.error(v, format!("{name}: {w} must be a finite number")));
                }
            }
            let values: Vec<f64> = match (&r.step, &r.count) {
                (Some(s), None) => {
                    let step = *s.get_ref();
                    if !step.is_finite() || step == 0.0 {
                        return Err(f.error(s, format!("{name}: step must be a non-zero number")));
                    }
                    let n = (stop - start) / step;
                    if n < -1e-9 {
                        return Err(f.error(
                            s,
                            format!(
                                "{name}: step = {} goes away from stop = {} (start = {}): the range is empty",
                                num(step),
                                num(stop),
                                num(start)
                            ),
                        ));
                    }
                    let whole = n.round();
                    if (n - whole).abs() > 1e-9 * whole.max(1.0) {
                        return Err(f.error(
                            s,
                            format!(
                                "{name}: stop − start = {} is not a whole number of steps of {} (it is \
                                 {n:.4} steps); change stop or step, or give count instead",
                                num(stop - start),
                                num(step)
                            ),
                        ));
                    }
                    if whole + 1.0 > MAX_CASES as f64 {
                        return Err(f.error(s, format!("{name}: more than {MAX_CASES} values")));
                    }
                    let n = whole as usize;
                    (0..=n)
                        .map(|i| {
                            if i == n {
                                stop
                            } else {
                                start + i as f64 * step
                            }
                        })
                        .collect()
                }
                (None, Some(c)) => {
                    let n = *c.get_ref();
                    if n < 1 || n as usize > MAX_CASES {
                        return Err(f.error(
                            c,
                            format!("{name}: count must be between 1 and {MAX_CASES}, got {n}"),
                        ));
                    }
                    if n == 1 && start != stop {
                        return Err(f.error(
                            c,
                            format!("{name}: count = 1 needs start = stop (a range of one value)"),
                        ));
                    }
                    let n = n as usize;
                    (0..n)
                        .map(|i| {
                            if n == 1 {
                                start
                            } else if i + 1 == n {
                                stop
                            } else {
                                start + (stop - start) * i as f64 / (n - 1) as f64
                            }
                        })
                        .collect()
                }
                (Some(s), Some(_)) => {
                    return Err(f.error(s, format!("{name}: give either step or count, not both")));
                }
                (None, None) => {
                    return Err(f.error(
                        a,
                        format!("{name}: a range needs step or count besides start and stop"),
                    ));
                }
            };
            out.extend(values.into_iter().map(|v| Value {
                name,
                value: v,
                span: a.span(),
            }));
        }
    }
    for v in &out {
        check_value(f, name, v.value, v.span.clone())?;
    }
    for (i, v) in out.iter().enumerate() {
        if out[..i].iter().any(|w| w.value == v.value) {
            return Err(f.error_at(
                v.span.clone(),
                format!(
                    "{name} = {} is given twice (each case would run twice)",
                    num(v.value)
                ),
            ));
        }
    }
    Ok(out)
}

/// All cases of the sweep, in order.
pub fn expand(f: &SweepFile) -> Result<Vec<Case>, InputError> {
    // Axes of the grid: each a list of (numeric values | wave name).
    enum Item {
        Num(Value),
        Wave(String, Range<usize>),
    }
    let mut axes: Vec<Vec<Item>> = Vec::new();
    let mut grid_names: Vec<&'static str> = Vec::new();
    if let Some(g) = &f.raw.grid {
        for (name, a) in g.get_ref().axes() {
            axes.push(
                axis_values(f, name, a)?
                    .into_iter()
                    .map(Item::Num)
                    .collect(),
            );
            grid_names.push(name);
        }
        if let Some(w) = &g.get_ref().wave {
            if w.get_ref().is_empty() {
                return Err(f.error(w, "wave: the list of wave names is empty"));
            }
            let mut items = Vec::new();
            for (i, n) in w.get_ref().iter().enumerate() {
                if w.get_ref()[..i].iter().any(|m| m.get_ref() == n.get_ref()) {
                    return Err(f.error(n, format!("wave '{}' is given twice", n.get_ref())));
                }
                items.push(Item::Wave(n.get_ref().clone(), n.span()));
            }
            axes.push(items);
        }
    }
    // The Latin hypercube: samples of the parameters it varies.
    let mut samples: Vec<Vec<Value>> = vec![Vec::new()];
    if let Some(l) = &f.raw.latin_hypercube {
        let l = l.get_ref();
        let n = *l.samples.get_ref();
        if !(1..=MAX_CASES as i64).contains(&n) {
            return Err(f.error(
                &l.samples,
                format!("samples must be between 1 and {MAX_CASES}, got {n}"),
            ));
        }
        if *l.seed.get_ref() < 0 {
            return Err(f.error(&l.seed, "seed must not be negative"));
        }
        let bounds = l.bounds();
        if bounds.is_empty() {
            return Err(f.error(
                &l.samples,
                "the latin_hypercube varies no parameter: give at least one, e.g. speed_m_s = { min = 1.0, max = 2.0 }",
            ));
        }
        let mut b = Vec::new();
        for (name, r) in &bounds {
            if grid_names.contains(name) {
                return Err(f.error(
                    r,
                    format!("{name} is varied in [grid] already; vary it in one place only"),
                ));
            }
            let (lo, hi) = (*r.get_ref().min.get_ref(), *r.get_ref().max.get_ref());
            check_value(f, name, lo, r.get_ref().min.span())?;
            check_value(f, name, hi, r.get_ref().max.span())?;
            if hi <= lo {
                return Err(f.error(
                    &r.get_ref().max,
                    format!(
                        "{name}: max = {} must be larger than min = {}",
                        num(hi),
                        num(lo)
                    ),
                ));
            }
            b.push((*name, lo, hi, r.span()));
        }
        let unit = lhs::unit_hypercube(n as usize, b.len(), *l.seed.get_ref() as u64);
        samples = unit
            .iter()
            .map(|row| {
                b.iter()
                    .zip(row)
                    .map(|((name, lo, hi, span), u)| Value {
                        name,
                        value: lo + u * (hi - lo),
                        span: span.clone(),
                    })
                    .collect()
            })
            .collect();
    }
    let grid_count = axes
        .iter()
        .try_fold(1usize, |acc, a| acc.checked_mul(a.len()))
        .unwrap_or(usize::MAX);
    let total = grid_count.saturating_mul(samples.len());
    if total > MAX_CASES {
        return Err(f.error(
            &f.raw.name,
            format!("the sweep has {total} cases, more than the {MAX_CASES} allowed"),
        ));
    }
    let width = format!("{}", total.saturating_sub(1)).len().max(4);
    let mut cases = Vec::with_capacity(total);
    for g in 0..grid_count {
        // Mixed-radix digits of g, the first axis slowest.
        let mut rest = g;
        let mut pick = vec![0usize; axes.len()];
        for (k, a) in axes.iter().enumerate().rev() {
            pick[k] = rest % a.len();
            rest /= a.len();
        }
        for s in &samples {
            let mut values: Vec<Value> = Vec::new();
            let mut wave = None;
            for (k, a) in axes.iter().enumerate() {
                match &a[pick[k]] {
                    Item::Num(v) => values.push(v.clone()),
                    Item::Wave(n, sp) => wave = Some((n.clone(), sp.clone())),
                }
            }
            values.extend(s.iter().cloned());
            values.sort_by_key(|v| NUMERIC.iter().position(|n| *n == v.name));
            let index = cases.len();
            cases.push(Case {
                index,
                id: format!("c{index:0width$}"),
                values,
                wave,
            });
        }
    }
    Ok(cases)
}
