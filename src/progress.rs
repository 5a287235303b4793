//! Progress reporting for long computations (SPH runs, and later whole assessments).
//!
//! The library never draws anything itself: a long computation calls a [`Progress`] sink, and the caller
//! decides what to show. The command line implements it with progress bars on a terminal and shows
//! nothing when stderr is a file or `-q` is given; library users get [`Silent`] by default.

use std::fmt;
use std::sync::Arc;

/// Receives the progress of a long computation. Implementations must be cheap: `update` may be called
/// many times a second.
pub trait Progress: Send + Sync {
    /// A new task begins: `label` names it, `total` is the amount of work in `unit` (for an SPH run, the
    /// simulated time in ms).
    fn start(&self, label: &str, total: f64, unit: &str);
    /// `done` of the task's total has been done; `detail` is a short status (time step, force, ...).
    fn update(&self, done: f64, detail: &str);
    /// The current task has ended (successfully or not).
    fn finish(&self);
    /// A one-line note between tasks (e.g. "convergence companion at dp 2.5 mm").
    fn note(&self, _message: &str) {}
}

/// A sink that shows nothing.
#[derive(Debug, Clone, Copy, Default)]
pub struct Silent;

impl Progress for Silent {
    fn start(&self, _: &str, _: f64, _: &str) {}
    fn update(&self, _: f64, _: &str) {}
    fn finish(&self) {}
}

/// A shareable handle to a [`Progress`] sink; the default is [`Silent`].
#[derive(Clone)]
pub struct ProgressHandle(Arc<dyn Progress>);

impl ProgressHandle {
    /// Wrap a sink.
    pub fn new(sink: impl Progress + 'static) -> Self {
        Self(Arc::new(sink))
    }

    /// The sink.
    pub fn sink(&self) -> &dyn Progress {
        self.0.as_ref()
    }
}

impl Default for ProgressHandle {
    fn default() -> Self {
        Self::new(Silent)
    }
}

impl fmt::Debug for ProgressHandle {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str("ProgressHandle")
    }
}

impl std::ops::Deref for ProgressHandle {
    type Target = dyn Progress;
    fn deref(&self) -> &Self::Target {
        self.0.as_ref()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Mutex;

    #[derive(Default)]
    struct Record(Mutex<Vec<String>>);

    impl Progress for Record {
        fn start(&self, label: &str, total: f64, unit: &str) {
            self.0
                .lock()
                .unwrap()
                .push(format!("start {label} {total} {unit}"));
        }
        fn update(&self, done: f64, _: &str) {
            self.0.lock().unwrap().push(format!("update {done}"));
        }
        fn finish(&self) {
            self.0.lock().unwrap().push("finish".into());
        }
    }

    #[test]
    fn handle_forwards_to_its_sink() {
        let rec = Arc::new(Record::default());
        struct Shared(Arc<Record>);
        impl Progress for Shared {
            fn start(&self, l: &str, t: f64, u: &str) {
                self.0.start(l, t, u)
            }
            fn update(&self, d: f64, s: &str) {
                self.0.update(d, s)
            }
            fn finish(&self) {
                self.0.finish()
            }
        }
        let h = ProgressHandle::new(Shared(rec.clone()));
        h.start("run", 2.0, "ms");
        h.update(1.0, "");
        h.finish();
        assert_eq!(
            *rec.0.lock().unwrap(),
            vec!["start run 2 ms", "update 1", "finish"]
        );
    }
}
