//! Work split over threads with results independent of the thread count: contiguous ranges
//! of indices, one per thread, joined in order (scoped standard threads, no pool).

use std::ops::Range;

/// Fewest items worth a thread: below this a batch runs on the calling thread.
const MIN_ITEMS_PER_THREAD: usize = 1024;

/// The number of threads `requested` means: itself, or all cores for 0.
pub(crate) fn resolve_threads(requested: usize) -> usize {
    if requested > 0 {
        requested
    } else {
        std::thread::available_parallelism().map_or(1, |n| n.get())
    }
}

/// `f(range)` for contiguous ranges covering `0..n`, in order, one per thread on up to
/// `threads` threads (0: all cores; one range, possibly empty, below `MIN_ITEMS_PER_THREAD`
/// items a thread). The first range runs on the calling thread.
pub(crate) fn map_ranges<T: Send>(
    n: usize,
    threads: usize,
    f: impl Fn(Range<usize>) -> T + Sync,
) -> Vec<T> {
    let ranges = ranges(n, threads);
    on_threads(ranges.len(), |t| f(ranges[t].clone()))
}

/// The ranges [`map_ranges`] splits `0..n` into: one per thread, at least one.
fn ranges(n: usize, threads: usize) -> Vec<Range<usize>> {
    let threads = resolve_threads(threads)
        .min(n / MIN_ITEMS_PER_THREAD)
        .max(1);
    let chunk = n.div_ceil(threads);
    (0..threads)
        .map(|t| t * chunk..((t + 1) * chunk).min(n))
        .collect()
}

/// [`map_ranges`] over the indices of `out`, `f` also given `out[range]` to fill: disjoint
/// parts of one slice written on several threads.
pub(crate) fn fill_ranges<T: Send, R: Send>(
    out: &mut [T],
    threads: usize,
    f: impl Fn(Range<usize>, &mut [T]) -> R + Sync,
) -> Vec<R> {
    let mut rest = out;
    let parts: Vec<(Range<usize>, &mut [T])> = ranges(rest.len(), threads)
        .into_iter()
        .map(|r| {
            let (part, tail) = std::mem::take(&mut rest).split_at_mut(r.len());
            rest = tail;
            (r, part)
        })
        .collect();
    each_on_threads(parts, |(r, part)| f(r, part))
}

/// `f(t)` for every `t` in `0..threads`, in order, each on its own thread (at least one):
/// [`each_on_threads`] over the thread numbers.
pub(crate) fn on_threads<T: Send>(threads: usize, f: impl Fn(usize) -> T + Sync) -> Vec<T> {
    each_on_threads((0..threads.max(1)).collect(), f)
}

/// `f(item)` for every item, each on its own thread, the results in order. The first item
/// runs on the calling thread: it is the one that reports progress, and the C API promises
/// callbacks on the thread that made the call. A panic on any thread resumes here.
pub(crate) fn each_on_threads<T: Send, R: Send>(
    items: Vec<T>,
    f: impl Fn(T) -> R + Sync,
) -> Vec<R> {
    let f = &f;
    let mut items = items.into_iter();
    let Some(first) = items.next() else {
        return Vec::new();
    };
    std::thread::scope(|scope| {
        let handles: Vec<_> = items.map(|item| scope.spawn(move || f(item))).collect();
        let mut out = vec![f(first)];
        out.extend(
            handles
                .into_iter()
                .map(|h| h.join().unwrap_or_else(|p| std::panic::resume_unwind(p))),
        );
        out
    })
}

/// `f(i)` for every `i` in `0..n`, in order, on up to `threads` threads (0: all cores). Each
/// item is computed exactly as on one thread, so the result does not depend on the thread
/// count; on error, the error of the lowest failing index (as one thread would stop at).
pub(crate) fn try_map<T: Send, E: Send>(
    n: usize,
    threads: usize,
    f: impl Fn(usize) -> Result<T, E> + Sync,
) -> Result<Vec<T>, E> {
    let parts = map_ranges(n, threads, |range| {
        range.map(&f).collect::<Result<Vec<T>, E>>()
    });
    let mut parts = parts.into_iter();
    let mut out = parts.next().unwrap_or_else(|| Ok(Vec::new()))?;
    for part in parts {
        out.extend(part?);
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn results_and_first_error_do_not_depend_on_the_thread_count() {
        let n = 10_000;
        let f = |i: usize| if i % 3001 == 3000 { Err(i) } else { Ok(i * i) };
        let ok = |i: usize| Ok::<usize, usize>(i * 7 + 1);
        let one = try_map(n, 1, ok).unwrap();
        assert_eq!(one, (0..n).map(|i| i * 7 + 1).collect::<Vec<_>>());
        for threads in [0, 2, 3, 7, 64] {
            assert_eq!(try_map(n, threads, ok).unwrap(), one);
            assert_eq!(try_map(n, threads, f), Err(3000));
        }
        assert_eq!(try_map(0, 4, ok).unwrap(), Vec::<usize>::new());
        assert!(resolve_threads(0) >= 1 && resolve_threads(5) == 5);
        let fill = |threads: usize| {
            let mut out = vec![0usize; n];
            let starts = fill_ranges(&mut out, threads, |range, part| {
                for (x, i) in part.iter_mut().zip(range.clone()) {
                    *x = i * 7 + 1;
                }
                range.start
            });
            (out, starts.len())
        };
        assert_eq!(fill(1), (one.clone(), 1));
        assert_eq!(fill(3), (one.clone(), 3));
        assert_eq!(fill(64).0, one);
    }
}
