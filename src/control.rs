//! Progress, cancellation and the memory budget of long work: one [`Control`] value, carried
//! by [`crate::Settings`] (every construction and its fit) and given to
//! [`crate::Evaluator::with_control`], [`crate::refine::refine_uniform_with`] and
//! [`crate::eval::folds::find_folds_with`].
//!
//! The work reports the fraction done, in `[0, 1]` and non-decreasing, to the caller's
//! [`Progress`] at its first step, regularly after (at most about a thousand times per call,
//! so a cheap callback costs nothing measurable) and at its end; when the callback asks to stop,
//! the call returns [`Error::Cancelled`] at once, having written nothing the caller sees.
//! A construction that fits through [`crate::construct::Fitted::fit`] gets all of this
//! without code of its own.
//!
//! The memory budget bounds what one call allocates: a call estimates its largest allocations
//! from the sizes it is given and refuses with [`Error::LimitExceeded`] before allocating
//! when the estimate is above the budget.

use std::fmt;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::Arc;

use crate::error::{Error, Result};

/// A caller's progress hook: called with the fraction of the work done; returning `true`
/// cancels the work (the C callback's non-zero return). Called on the thread that made the
/// call, never concurrently by one call.
pub trait Progress: Send + Sync {
    /// `fraction` in `[0, 1]`, non-decreasing within a call. Return `true` to cancel.
    fn report(&self, fraction: f64) -> bool;
}

impl<F: Fn(f64) -> bool + Send + Sync> Progress for F {
    fn report(&self, fraction: f64) -> bool {
        self(fraction)
    }
}

/// Progress hook and memory budget of a call (the default: neither). Cheap to clone (the
/// hook is shared).
#[derive(Clone)]
pub struct Control {
    progress: Option<Arc<dyn Progress>>,
    /// Largest estimated allocation of one call, bytes; `None`: no budget.
    memory_budget: Option<u64>,
    /// The part `[start, end]` of the caller's fraction this piece of work fills.
    start: f64,
    end: f64,
    /// Threads the work may use (0: all cores); results do not depend on it.
    threads: usize,
}

/// Polling shared by the ranges of one piece of work split over threads
/// ([`crate::eval::parallel`]): the first range, on the calling thread, reports to the
/// caller's [`Control`] (callbacks come on the thread that made the call) and records a
/// cancel; the other ranges see it at their next poll and stop too. A split joins its
/// ranges' results in order, so the first range's error is the one returned.
#[derive(Default)]
pub(crate) struct SplitPoll {
    cancelled: AtomicBool,
}

impl SplitPoll {
    /// Poll before step `i` of `n` of a range: `reporter` is the control on the first range
    /// and `None` on the others. Errors: [`Error::Cancelled`] from the control, or on the
    /// other ranges once the first has been cancelled.
    pub(crate) fn step(&self, reporter: Option<&Control>, i: usize, n: usize) -> Result<()> {
        match reporter {
            Some(control) => control
                .step(i, n)
                .inspect_err(|_| self.cancelled.store(true, Ordering::Relaxed)),
            None if self.cancelled.load(Ordering::Relaxed) => {
                Err(Error::Cancelled("cancelled on the calling thread".into()))
            }
            None => Ok(()),
        }
    }
}

/// Most progress reports a loop of `n` steps makes through [`Control::step`].
const REPORTS_PER_LOOP: usize = 1000;

impl Control {
    /// No hook, no budget.
    pub const NONE: Control = Control {
        progress: None,
        memory_budget: None,
        start: 0.0,
        end: 1.0,
        threads: 0,
    };

    /// This control with `progress` as its hook.
    pub fn with_progress(self, progress: impl Progress + 'static) -> Control {
        Control {
            progress: Some(Arc::new(progress)),
            ..self
        }
    }

    /// This control with a memory budget of `bytes` (`None`: no budget).
    pub fn with_memory_budget(self, bytes: Option<u64>) -> Control {
        Control {
            memory_budget: bytes,
            ..self
        }
    }

    /// This control with `threads` threads for the work that splits (0: all cores, the
    /// default): the fit's limit stencils and solve, uniform refinement's positions. Results
    /// are the same for every count.
    pub fn with_threads(self, threads: usize) -> Control {
        Control { threads, ..self }
    }

    /// The thread count (0: all cores).
    pub fn threads(&self) -> usize {
        self.threads
    }

    /// The memory budget, bytes.
    pub fn memory_budget(&self) -> Option<u64> {
        self.memory_budget
    }

    /// Whether a progress hook is set.
    pub fn has_progress(&self) -> bool {
        self.progress.is_some()
    }

    /// The control of a stage that fills `[from, to]` of this one's fraction.
    pub(crate) fn stage(&self, from: f64, to: f64) -> Control {
        let span = self.end - self.start;
        Control {
            progress: self.progress.clone(),
            memory_budget: self.memory_budget,
            start: self.start + span * from,
            end: self.start + span * to,
            threads: self.threads,
        }
    }

    /// Report that `fraction` of this stage is done. Errors: [`Error::Cancelled`] when the
    /// hook asks to stop.
    pub(crate) fn report(&self, fraction: f64) -> Result<()> {
        let Some(p) = &self.progress else {
            return Ok(());
        };
        let f = self.start + (self.end - self.start) * fraction.clamp(0.0, 1.0);
        if p.report(f) {
            Err(Error::Cancelled(format!(
                "cancelled by the progress callback at {:.1} % of the work",
                100.0 * f
            )))
        } else {
            Ok(())
        }
    }

    /// Report step `i` of `n` (every `n / 1000`-th step): what a loop calls each turn.
    pub(crate) fn step(&self, i: usize, n: usize) -> Result<()> {
        if self.progress.is_none() || i % n.div_ceil(REPORTS_PER_LOOP).max(1) != 0 {
            return Ok(());
        }
        self.report(i as f64 / n.max(1) as f64)
    }

    /// Refuse `bytes` of estimated allocation for `what` above the memory budget. Errors:
    /// [`Error::LimitExceeded`] naming both figures.
    pub fn check_memory(&self, what: &str, bytes: u64) -> Result<()> {
        match self.memory_budget {
            Some(budget) if bytes > budget => Err(Error::LimitExceeded(format!(
                "{what} needs about {bytes} bytes, above the memory budget of {budget} bytes"
            ))),
            _ => Ok(()),
        }
    }
}

impl Default for Control {
    fn default() -> Control {
        Control::NONE
    }
}

impl fmt::Debug for Control {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("Control")
            .field("progress", &self.progress.is_some())
            .field("memory_budget", &self.memory_budget)
            .field("threads", &self.threads)
            .finish()
    }
}

/// Two controls are equal when they share their hook (or have none) and budget.
impl PartialEq for Control {
    fn eq(&self, other: &Control) -> bool {
        let same_hook = match (&self.progress, &other.progress) {
            (None, None) => true,
            (Some(a), Some(b)) => Arc::ptr_eq(a, b),
            _ => false,
        };
        same_hook
            && self.memory_budget == other.memory_budget
            && (self.start, self.end) == (other.start, other.end)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Mutex;

    #[test]
    fn stages_map_into_the_callers_fraction_and_cancel() {
        let seen = Arc::new(Mutex::new(Vec::new()));
        let log = seen.clone();
        let c = Control::NONE.with_progress(move |f: f64| {
            log.lock().unwrap().push(f);
            f > 0.74
        });
        let s = c.stage(0.5, 1.0);
        assert!(s.report(0.0).is_ok());
        assert!(s.stage(0.0, 0.5).report(0.5).is_ok());
        match s.report(0.5) {
            Err(Error::Cancelled(m)) => assert!(m.contains("75.0 %"), "{m}"),
            other => panic!("{other:?}"),
        }
        assert_eq!(*seen.lock().unwrap(), vec![0.5, 0.625, 0.75]);
        // A loop of 10,000 steps reports every 10th.
        let n = Arc::new(Mutex::new(0));
        let count = n.clone();
        let c = Control::NONE.with_progress(move |_| {
            *count.lock().unwrap() += 1;
            false
        });
        (0..10_000).for_each(|i| c.step(i, 10_000).unwrap());
        assert_eq!(*n.lock().unwrap(), 1000);
    }

    #[test]
    fn budget_refuses_above_it_only() {
        let c = Control::NONE.with_memory_budget(Some(1000));
        assert!(c.check_memory("x", 1000).is_ok());
        match c.check_memory("the fit", 1001) {
            Err(Error::LimitExceeded(m)) => assert_eq!(
                m,
                "the fit needs about 1001 bytes, above the memory budget of 1000 bytes"
            ),
            other => panic!("{other:?}"),
        }
        assert!(Control::NONE.check_memory("x", u64::MAX).is_ok());
    }
}
