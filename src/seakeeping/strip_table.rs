//! Sectional solutions tabulated over encounter frequency, so that a run over many speeds, wave
//! frequencies and spectrum samples solves each station's 2D problem at a fixed set of frequencies only.
//!
//! The table holds the radiation solution of every station at `n` frequencies equally spaced in ln w over
//! [w_min, w_max]. At an encounter frequency w inside the range, a33, b33 and the radiation potential at
//! every body sample are interpolated by the four-point Lagrange cubic in ln w through the nearest grid
//! frequencies (one-sided at the ends of the range). The panels of a section do not depend on frequency, so
//! the samples of all grid frequencies lie at the same points and interpolate point by point. Interior
//! lid panels remove the irregular frequencies (see `frank_close_fit`), so the coefficients are smooth in
//! w and the interpolation error falls as the fourth power of the spacing: at 0.1 in ln w (the
//! `slamtool motions` default, recorded in its provenance settings) the RAOs agree with direct solves to
//! about 1e-4 relative, 3e-6 at 0.05 (`tests/seakeeping_strip_table.rs`).
//!
//! Frequencies outside the table are an error, never extrapolated.

use rayon::prelude::*;

use super::ShipModel;
use super::section::{BodySample, Radiation};
use super::strip_theory::{self, SectionSolutions, StripSettings, Strips};
use crate::error::{Error, Result};

/// Radiation solutions of all stations on a grid of encounter frequencies.
pub struct StripTable {
    ln_w0: f64,
    d_ln_w: f64,
    /// Grid frequencies, increasing.
    omegas: Vec<f64>,
    /// Solutions per grid frequency.
    grid: Vec<Strips>,
    /// Number of stations of the model the table was built for (a guard against mixing models).
    stations: usize,
}

impl StripTable {
    /// Solve every station at `n >= 4` frequencies from `w_min` to `w_max`, equally spaced in ln w.
    pub fn new(
        model: &ShipModel,
        w_min: f64,
        w_max: f64,
        n: usize,
        settings: &StripSettings,
    ) -> Result<Self> {
        if !(w_min > 0.0 && w_max > w_min && w_max.is_finite()) || n < 4 {
            return Err(Error::Invalid(format!(
                "frequency table needs 0 < w_min < w_max and at least 4 frequencies, got \
                 [{w_min}, {w_max}] with {n}"
            )));
        }
        let ln_w0 = w_min.ln();
        let d_ln_w = (w_max.ln() - ln_w0) / (n - 1) as f64;
        let omegas: Vec<f64> = (0..n)
            .map(|i| {
                if i + 1 == n {
                    w_max
                } else {
                    (ln_w0 + d_ln_w * i as f64).exp()
                }
            })
            .collect();
        // Frequencies in parallel as well as the strips of each (collected in order: deterministic).
        let grid = omegas
            .par_iter()
            .map(|&w| strip_theory::strips(model, w, settings))
            .collect::<Result<Vec<_>>>()?;
        Ok(Self {
            ln_w0,
            d_ln_w,
            omegas,
            grid,
            stations: model.stations.len(),
        })
    }

    /// A table for the frequencies `needed`, with at most `d_ln_w` between grid frequencies (at least 4
    /// frequencies; the range is widened by half a spacing at each end).
    pub fn covering(
        model: &ShipModel,
        needed: &[f64],
        d_ln_w: f64,
        settings: &StripSettings,
    ) -> Result<Self> {
        let lo = needed.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = needed.iter().copied().fold(0.0, f64::max);
        if !(lo > 0.0 && hi.is_finite() && d_ln_w > 0.0) {
            return Err(Error::Invalid(format!(
                "frequency table: frequencies must be positive and finite (got {lo} to {hi}) and the \
                 spacing positive (got {d_ln_w})"
            )));
        }
        let (a, b) = (lo * (-0.5 * d_ln_w).exp(), hi * (0.5 * d_ln_w).exp());
        let n = (((b / a).ln() / d_ln_w).ceil() as usize + 1).max(4);
        Self::new(model, a, b, n, settings)
    }

    /// Grid frequencies.
    pub fn omegas(&self) -> &[f64] {
        &self.omegas
    }

    /// Interpolated sectional solutions at encounter frequency `w`.
    pub fn interpolate(&self, model: &ShipModel, w: f64) -> Result<Strips> {
        let n = self.omegas.len();
        let (first, last) = (self.omegas[0], self.omegas[n - 1]);
        if !(w >= first && w <= last) {
            return Err(Error::Invalid(format!(
                "encounter frequency {w} is outside the frequency table [{first}, {last}]"
            )));
        }
        if model.stations.len() != self.stations {
            return Err(Error::Invalid(
                "frequency table was built for another ship model".into(),
            ));
        }
        // Four grid points k0..k0+3 around w, and the Lagrange weights in t = (ln w - ln w_k0)/d.
        let s = (w.ln() - self.ln_w0) / self.d_ln_w;
        let k0 = (s.floor() as isize - 1).clamp(0, n as isize - 4) as usize;
        let t = s - k0 as f64;
        let mut wt = [0.0; 4];
        for (j, wj) in wt.iter_mut().enumerate() {
            let mut p = 1.0;
            for m in 0..4 {
                if m != j {
                    p *= (t - m as f64) / (j as f64 - m as f64);
                }
            }
            *wj = p;
        }
        let radiation = (0..self.stations)
            .map(|st| {
                let rs: Vec<&Radiation> = (0..4)
                    .filter_map(|j| self.grid[k0 + j].radiation[st].as_ref())
                    .collect();
                match rs.len() {
                    0 => Ok(None),
                    4 => Ok(Some(combine(&rs, &wt, w))),
                    _ => Err(Error::Numerical(
                        "frequency table: a station is wetted at some frequencies only".into(),
                    )),
                }
            })
            .collect::<Result<Vec<_>>>()?;
        Ok(Strips {
            omega_e: w,
            radiation,
        })
    }
}

/// sum_j wt_j r_j for a33, b33 and the potential at each body sample (same points in every r_j).
fn combine(rs: &[&Radiation], wt: &[f64; 4], w: f64) -> Radiation {
    let mut a33 = 0.0;
    let mut b33 = 0.0;
    for (r, &c) in rs.iter().zip(wt) {
        a33 += c * r.a33;
        b33 += c * r.b33;
    }
    let samples = rs[0]
        .samples
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let mut phi = rs[0].samples[i].phi * wt[0];
            for (r, &c) in rs.iter().zip(wt).skip(1) {
                phi += r.samples[i].phi * c;
            }
            BodySample { phi, ..*s }
        })
        .collect();
    Radiation {
        omega: w,
        a33,
        b33,
        samples,
    }
}

impl SectionSolutions for StripTable {
    fn strips(&self, model: &ShipModel, omega_e: f64) -> Result<Strips> {
        self.interpolate(model, omega_e)
    }
}

/// A table that falls back to direct solves outside its range (for iterations such as the natural
/// frequencies, whose iterates are not known in advance).
pub struct TableOrSolve<'a> {
    pub table: &'a StripTable,
    pub settings: &'a StripSettings,
}

impl SectionSolutions for TableOrSolve<'_> {
    fn strips(&self, model: &ShipModel, omega_e: f64) -> Result<Strips> {
        let w = self.table.omegas();
        if omega_e >= w[0] && omega_e <= w[w.len() - 1] {
            self.table.interpolate(model, omega_e)
        } else {
            strip_theory::strips(model, omega_e, self.settings)
        }
    }
}
