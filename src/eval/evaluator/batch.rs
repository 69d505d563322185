//! Batches of points evaluated straight into the caller's arrays, in two passes.
//!
//! Pass 1 checks every point and finds its leaf (a few bytes a point: which leaf, how deep),
//! evaluating the rare points below the cache depth on the spot; nothing is written yet, so
//! a bad point leaves the caller's arrays untouched. Pass 2 evaluates each point in its leaf
//! and hands the sample to the output. Compared with collecting samples and copying them,
//! this writes each result once, and pass 1's loads (the quadtree) do not wait on pass 2's
//! (the leaves' points), so the memory accesses of neighbouring points overlap. The
//! arithmetic is [`Evaluator::evaluate_in`]'s operation for operation: the same bits.

use std::ops::Range;

use glam::DVec3;

use super::{check_point_lists, quadrant, Evaluator, Node};
use crate::error::{Error, Result};
use crate::eval::domain::{Domain, PtexPoint};
use crate::eval::sample::LimitSample;

/// Where pass 1 found a point.
#[derive(Debug, Clone, Copy)]
enum Landing {
    /// In leaf `leaf`, `depth` levels below its face's root.
    Leaf { leaf: u32, depth: u8 },
    /// Below the cache depth: the range's next sample of [`Landed::deep`].
    Deep,
    /// On a face without limit surface.
    NoSurface,
}

/// Pass 1 over one range of points.
struct Landed {
    range: Range<usize>,
    landings: Vec<Landing>,
    /// The samples of the [`Landing::Deep`] points, in order.
    deep: Vec<LimitSample>,
}

/// What a batch does with a point without limit surface.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum NoSurface {
    /// `None` for that point ([`Evaluator::evaluate_points`]).
    Mark,
    /// The batch fails naming the first such point, after every point has been checked
    /// (C strict mode, [`crate::eval::require_surface`]'s message).
    Strict,
    /// The point is a bad point like any other ([`Evaluator::evaluate_many`]: the error of
    /// [`Evaluator::evaluate`] there).
    Error,
}

/// The receiver of a batch's samples: one call per point of its range, in order (index
/// relative to the range). Split in pieces, one per thread.
pub(crate) trait BatchOutput: Send + Sized {
    /// The first `n` points' part and the rest.
    fn split(self, n: usize) -> (Self, Self);
    /// Sample of point `k` (`None`: no limit surface).
    fn put(&mut self, k: usize, sample: Option<LimitSample>);
}

impl BatchOutput for &mut [Option<LimitSample>] {
    fn split(self, n: usize) -> (Self, Self) {
        self.split_at_mut(n)
    }
    #[inline]
    fn put(&mut self, k: usize, sample: Option<LimitSample>) {
        self[k] = sample;
    }
}

impl BatchOutput for &mut [LimitSample] {
    fn split(self, n: usize) -> (Self, Self) {
        self.split_at_mut(n)
    }
    #[inline]
    fn put(&mut self, k: usize, sample: Option<LimitSample>) {
        self[k] = sample.unwrap_or(LimitSample::NO_SURFACE);
    }
}

/// An [`Error::InvalidArgument`] of point `i` named as such; other errors unchanged.
pub(crate) fn name_point(i: usize, e: Error) -> Error {
    match e {
        Error::InvalidArgument(m) => Error::InvalidArgument(format!("point {i}: {m}")),
        other => other,
    }
}

impl Evaluator {
    /// Evaluate `(faces[i], u[i], v[i])` in `domain` for every point into `out` (derivatives
    /// in the domain's units, as [`Evaluator::evaluate_in`]), on the evaluator's threads.
    /// On error (the first bad point by index, whatever the thread count) `out` has not been
    /// written to.
    pub(crate) fn evaluate_batch<O: BatchOutput>(
        &self,
        domain: Domain,
        (faces, u, v): (&[u32], &[f64], &[f64]),
        no_surface: NoSurface,
        out: O,
    ) -> Result<()> {
        self.evaluate_batch_with(&self.points, domain, (faces, u, v), no_surface, out)
    }

    /// [`Evaluator::evaluate_batch`] under `points` (the program's points from the
    /// positions or from three components of a primvar).
    pub(crate) fn evaluate_batch_with<O: BatchOutput>(
        &self,
        points: &[DVec3],
        domain: Domain,
        (faces, u, v): (&[u32], &[f64], &[f64]),
        no_surface: NoSurface,
        out: O,
    ) -> Result<()> {
        check_point_lists(faces, u, v)?;
        let landed = crate::eval::parallel::map_ranges(faces.len(), self.threads, |range| {
            self.land(points, domain, (faces, u, v), no_surface, range)
        });
        let landed = landed.into_iter().collect::<Result<Vec<Landed>>>()?;
        if no_surface == NoSurface::Strict {
            let first = landed.iter().find_map(|part| {
                let k = part
                    .landings
                    .iter()
                    .position(|l| matches!(l, Landing::NoSurface))?;
                Some(part.range.start + k)
            });
            if let Some(i) = first {
                return Err(crate::eval::surface::no_surface_strict("point", i));
            }
        }
        let mut parts = Vec::with_capacity(landed.len());
        let mut rest = out;
        for part in &landed {
            let (this, after) = rest.split(part.range.len());
            parts.push((part, this));
            rest = after;
        }
        crate::eval::parallel::each_on_threads(parts, |(part, out)| {
            self.evaluate_landed(points, domain, (faces, u, v), part, out)
        });
        Ok(())
    }

    /// Pass 1 over `range`: check each point, find its leaf, evaluate the deep ones.
    fn land(
        &self,
        points: &[DVec3],
        domain: Domain,
        (faces, u, v): (&[u32], &[f64], &[f64]),
        no_surface: NoSurface,
        range: Range<usize>,
    ) -> Result<Landed> {
        let mut landings = Vec::with_capacity(range.len());
        let mut deep = Vec::new();
        for i in range.clone() {
            let p = self
                .ptex
                .locate_in(domain, faces[i], u[i], v[i])
                .map_err(|e| name_point(i, e))?;
            let (node, s, t, scale, depth) = self.descend(self.roots[p.face as usize], p.u, p.v);
            landings.push(match node {
                Node::Patch(leaf) => Landing::Leaf { leaf, depth },
                Node::Deep(d) => {
                    let sample = self
                        .evaluate_fragment(points, d, s, t, scale)
                        .map_err(|e| name_point(i, e))?;
                    deep.push(LimitSample {
                        position: sample.position,
                        du: sample.du * p.derivative_scale,
                        dv: sample.dv * p.derivative_scale,
                    });
                    Landing::Deep
                }
                Node::NoSurface if no_surface == NoSurface::Error => {
                    return Err(name_point(i, self.no_surface_error(p.face)));
                }
                Node::NoSurface => Landing::NoSurface,
                Node::Split(_) => unreachable!("a descent ends below every split"),
            });
        }
        Ok(Landed {
            range,
            landings,
            deep,
        })
    }

    /// Pass 2 over one range landed by pass 1: every sample into `out`.
    fn evaluate_landed<O: BatchOutput>(
        &self,
        points: &[DVec3],
        domain: Domain,
        (faces, u, v): (&[u32], &[f64], &[f64]),
        part: &Landed,
        mut out: O,
    ) {
        let mut deep = part.deep.iter();
        for (k, (i, &landing)) in part.range.clone().zip(&part.landings).enumerate() {
            let sample = match landing {
                Landing::Leaf { leaf, depth } => {
                    let p = match domain {
                        Domain::Ptex => PtexPoint {
                            face: faces[i],
                            u: u[i],
                            v: v[i],
                            derivative_scale: 1.0,
                        },
                        // Checked in pass 1: the same point again.
                        _ => match self.ptex.locate_in(domain, faces[i], u[i], v[i]) {
                            Ok(p) => p,
                            Err(_) => unreachable!("point {i} was located in pass 1"),
                        },
                    };
                    let (mut s, mut t, mut scale) = (p.u, p.v, 1.0);
                    for _ in 0..depth {
                        (_, s, t) = quadrant(s, t);
                        scale *= 2.0;
                    }
                    let (position, ds, dt) = self.evaluate_leaf(points, leaf, s, t);
                    Some(LimitSample {
                        position,
                        du: ds * scale * p.derivative_scale,
                        dv: dt * scale * p.derivative_scale,
                    })
                }
                Landing::Deep => deep.next().copied(),
                Landing::NoSurface => None,
            };
            out.put(k, sample);
        }
    }
}
