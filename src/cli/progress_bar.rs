//! The command line's [`Progress`] sink: an `indicatif` bar on stderr when stderr is a terminal and `-q`
//! was not given, and nothing otherwise (no `\r` lines in log files).

use std::sync::Mutex;
use std::time::Duration;

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use slamtool::progress::{Progress, ProgressHandle};

use super::global;

/// Progress bars, one per task, drawn on stderr.
struct Bars {
    bar: Mutex<Option<ProgressBar>>,
}

/// Bars work in thousandths of the task's unit, since indicatif counts in integers.
const SCALE: f64 = 1000.0;

impl Progress for Bars {
    fn start(&self, label: &str, total: f64, unit: &str) {
        let bar = ProgressBar::with_draw_target(
            Some((total * SCALE).round().max(1.0) as u64),
            ProgressDrawTarget::stderr_with_hz(4),
        );
        // Whole units (runs) are counted as integers; fractional ones (ms of simulated time) to 0.1.
        let decimals = if total.fract() == 0.0 { 0 } else { 1 };
        let template = format!(
            "{{prefix}} [{{bar:30}}] {{human_pos_f}} / {{total_f}} {unit}  eta {{eta}}  {{msg}}"
        );
        let style = ProgressStyle::with_template(&template)
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .with_key(
                "human_pos_f",
                move |s: &indicatif::ProgressState, w: &mut dyn std::fmt::Write| {
                    let _ = write!(w, "{:.*}", decimals, s.pos() as f64 / SCALE);
                },
            )
            .with_key(
                "total_f",
                move |s: &indicatif::ProgressState, w: &mut dyn std::fmt::Write| {
                    let _ = write!(w, "{:.*}", decimals, s.len().unwrap_or(0) as f64 / SCALE);
                },
            )
            .progress_chars("=> ");
        bar.set_style(style);
        bar.set_prefix(label.to_string());
        bar.enable_steady_tick(Duration::from_millis(500));
        if let Some(old) = self.bar.lock().expect("progress lock").replace(bar) {
            old.finish_and_clear();
        }
    }

    fn update(&self, done: f64, detail: &str) {
        if let Some(b) = self.bar.lock().expect("progress lock").as_ref() {
            b.set_position((done * SCALE).round().max(0.0) as u64);
            b.set_message(detail.to_string());
        }
    }

    fn finish(&self) {
        if let Some(b) = self.bar.lock().expect("progress lock").take() {
            b.finish_and_clear();
        }
    }

    fn note(&self, message: &str) {
        global::note(message);
    }
}

/// Notes only, for when no bars may be drawn.
struct NotesOnly;

impl Progress for NotesOnly {
    fn start(&self, _: &str, _: f64, _: &str) {}
    fn update(&self, _: f64, _: &str) {}
    fn finish(&self) {}
    fn note(&self, message: &str) {
        global::note(message);
    }
}

/// The progress sink for this invocation: bars on a terminal, notes only otherwise, nothing with `-q`.
pub fn handle() -> ProgressHandle {
    if global::progress_visible() {
        ProgressHandle::new(Bars {
            bar: Mutex::new(None),
        })
    } else {
        ProgressHandle::new(NotesOnly)
    }
}
