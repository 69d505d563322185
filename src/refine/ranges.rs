//! One pass of refinement over the child components of one kind, split over threads:
//! contiguous ranges of indices, one per thread ([`crate::eval::parallel::fill_ranges`]).

use crate::control::{Control, SplitPoll};
use crate::error::Result;
use crate::eval::parallel::fill_ranges;

/// `out[i] = item(scratch, i)` for every `i`, in contiguous ranges on `control`'s threads
/// ([`Control::threads`], 0: all cores), each range with scratch space of its own (so `item`
/// must not depend on what an earlier index left there). The first range (on the calling
/// thread) reports to `control`, its fraction standing for the pass; a cancel there stops the
/// other ranges at their next index.
///
/// Errors: [`crate::Error::Cancelled`] from `control`.
pub(super) fn fill_pass<T: Send, S: Default>(
    out: &mut [T],
    control: &Control,
    item: impl Fn(&mut S, usize) -> T + Sync,
) -> Result<()> {
    let poll = SplitPoll::default();
    let ranges = fill_ranges(out, control.threads(), |range, part| {
        let (reporter, len) = ((range.start == 0).then_some(control), range.len());
        let mut scratch = S::default();
        for (k, (slot, i)) in part.iter_mut().zip(range).enumerate() {
            poll.step(reporter, k, len)?;
            *slot = item(&mut scratch, i);
        }
        Ok(())
    });
    ranges.into_iter().collect()
}
