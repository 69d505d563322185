//! The evaluator's points as a program over the control points: what lets an evaluator be
//! built from topology alone and take new positions (or any vertex data) cheaply.
//!
//! Every vertex of every refined fragment the evaluator keeps is a *local point*: the
//! weighted sum that refinement computed it with ([`crate::refine::interpolate`]), its
//! terms in the same order with the same weights, over control points and earlier local
//! points. Replaying the program on positions repeats refinement's arithmetic operation for
//! operation, so an evaluator given new positions is bit for bit the one built with them
//! (it is how every evaluator gets its positions). Like Far's refinement stencils, but
//! factorized level by level rather than flattened onto the control points: a point deep
//! under a semi-sharp crease has a handful of terms, not the 30-odd control points it
//! depends on.

use glam::DVec3;

use crate::control::Control;
use crate::error::Result;
use crate::refine::{interpolate, Primvar, Refinement};
use crate::topology::Level;

/// Fewest points a position update computes between two polls of its control (well under a
/// millisecond of work; more on programs of over a thousand times this, to keep to about a
/// thousand reports per call).
const POLL_POINTS: usize = 1024;

/// Local points as weighted sums of earlier points. Point `i < num_control` is control
/// point `i`; point `num_control + k` is row `k`.
#[derive(Debug, Clone, Default)]
pub(crate) struct PointProgram {
    num_control: u32,
    offsets: Vec<u32>,
    sources: Vec<u32>,
    weights: Vec<f64>,
}

/// Bit marking a term of [`Recorded`] as a child vertex of the same refinement (face points,
/// which edge and vertex points read) rather than a parent vertex.
const CHILD: u32 = 1 << 31;

/// Terms a [`Recorded`] holds in place; more (vertices of valence above 5) spill to the heap.
const INLINE_TERMS: usize = 12;

/// A refined vertex as the weighted sum interpolation built: its terms over parent vertices
/// and (with [`CHILD`]) earlier child vertices, in the order they were added. Held in place
/// rather than in a `Vec` each: a build records millions of them.
#[derive(Debug, Clone)]
struct Recorded {
    /// This vertex: its parent index, or [`CHILD`] | its child index once complete.
    own: u32,
    len: u32,
    sources: [u32; INLINE_TERMS],
    weights: [f64; INLINE_TERMS],
    /// Terms past [`INLINE_TERMS`].
    spill: Vec<(u32, f64)>,
}

impl Recorded {
    fn vertex(own: u32) -> Recorded {
        Recorded {
            own,
            len: 0,
            sources: [0; INLINE_TERMS],
            weights: [0.0; INLINE_TERMS],
            spill: Vec::new(),
        }
    }
}

impl Primvar for Recorded {
    fn zero() -> Self {
        Recorded::vertex(0)
    }
    fn add_weighted(&mut self, src: &Self, weight: f64) {
        let k = self.len as usize;
        if k < INLINE_TERMS {
            self.sources[k] = src.own;
            self.weights[k] = weight;
        } else {
            self.spill.push((src.own, weight));
        }
        self.len += 1;
    }
    fn finish(&mut self, child: u32) {
        self.own = CHILD | child;
    }
}

impl PointProgram {
    /// A program over `num_control` control points, with no local points yet.
    pub fn new(num_control: usize) -> PointProgram {
        PointProgram {
            num_control: num_control as u32,
            offsets: vec![0],
            sources: Vec::new(),
            weights: Vec::new(),
        }
    }

    /// Number of points: control and local.
    pub fn num_points(&self) -> usize {
        self.num_control as usize + self.offsets.len() - 1
    }

    /// The points of the child of refinement `r` of `level`, whose vertices are points
    /// `parent`, recorded as new local points; returns the child vertices' points. Face
    /// points come first, then edge points, then vertex points: the order refinement
    /// completes them in, so that every term reads an earlier point.
    pub fn record(&mut self, level: &Level, r: &Refinement, parent: &[u32]) -> Vec<u32> {
        let src: Vec<Recorded> = (0..level.num_vertices() as u32)
            .map(Recorded::vertex)
            .collect();
        let dst = interpolate(level, r, &src);
        let mut points = vec![0u32; dst.len()];
        let first_face = r.face_child_vertex(0) as usize;
        let faces = first_face..first_face + level.num_faces();
        let first_edge = r.edge_child_vertex(0) as usize;
        let edges = first_edge..first_edge + level.num_edges();
        let first_vertex = r.vertex_child_vertex(0) as usize;
        let vertices = first_vertex..first_vertex + level.num_vertices();
        let terms: usize = dst.iter().map(|d| d.len as usize).sum();
        self.sources.reserve(terms);
        self.weights.reserve(terms);
        self.offsets.reserve(dst.len());
        for cv in faces.chain(edges).chain(vertices) {
            let d = &dst[cv];
            let point = |s: u32| {
                if s & CHILD != 0 {
                    points[(s & !CHILD) as usize]
                } else {
                    parent[s as usize]
                }
            };
            // A plain loop over the terms held in place, then the spilled ones: an iterator
            // chain over both cost several times as much per term.
            let n = (d.len as usize).min(INLINE_TERMS);
            for k in 0..n {
                self.sources.push(point(d.sources[k]));
                self.weights.push(d.weights[k]);
            }
            for &(s, w) in &d.spill {
                self.sources.push(point(s));
                self.weights.push(w);
            }
            self.offsets.push(self.sources.len() as u32);
            points[cv] = self.num_points() as u32 - 1;
        }
        points
    }

    /// Every point's value from the control points' `control` (one per control point):
    /// each local point summed as refinement sums it.
    ///
    /// Panics if `control` has fewer values than the program has control points.
    pub fn run(&self, control: &[DVec3]) -> Vec<DVec3> {
        let mut values = Vec::new();
        self.run_into(control, &mut values);
        values
    }

    /// [`PointProgram::run`] into `values` (replaced; its allocation is reused).
    ///
    /// Panics as [`PointProgram::run`].
    pub fn run_into(&self, control: &[DVec3], values: &mut Vec<DVec3>) {
        self.run_polled(control, values, &Control::NONE)
            .expect("a control without a hook never cancels");
    }

    /// [`PointProgram::run_into`] polling `progress` every [`POLL_POINTS`] points or more:
    /// the same values bit for bit (the same sums in the same order).
    ///
    /// Errors: [`crate::Error::Cancelled`] from `progress` (`values` then holds a prefix).
    pub fn run_polled(
        &self,
        control: &[DVec3],
        values: &mut Vec<DVec3>,
        progress: &Control,
    ) -> Result<()> {
        let nc = self.num_control as usize;
        values.clear();
        values.reserve(self.num_points());
        values.extend_from_slice(&control[..nc]);
        let rows = self.offsets.len() - 1;
        let chunk = rows.div_ceil(1000).max(POLL_POINTS);
        for first in (0..rows).step_by(chunk) {
            progress.report(first as f64 / rows as f64)?;
            let mut a = self.offsets[first] as usize;
            for &end in &self.offsets[first + 1..(first + chunk).min(rows) + 1] {
                let b = end as usize;
                let mut acc = DVec3::ZERO;
                for (&s, &wt) in self.sources[a..b].iter().zip(&self.weights[a..b]) {
                    acc.add_weighted(&values[s as usize], wt);
                }
                values.push(acc);
                a = b;
            }
        }
        Ok(())
    }

    /// Append the local points of `other` (a program over the same control points) after
    /// these; returns how `other`'s points are numbered now.
    pub fn append(&mut self, other: &PointProgram) -> impl Fn(u32) -> u32 + Copy {
        let nc = self.num_control;
        let shift = self.num_points() as u32 - nc;
        let point = move |p: u32| if p < nc { p } else { p + shift };
        let base = self.sources.len() as u32;
        self.sources.extend(other.sources.iter().map(|&s| point(s)));
        self.weights.extend_from_slice(&other.weights);
        self.offsets
            .extend(other.offsets[1..].iter().map(|&o| o + base));
        point
    }

    /// Keep only the points `roots` name and those they read, numbered in the same order;
    /// `roots` are renumbered in place.
    pub fn prune(&mut self, roots: &mut [&mut [u32]]) {
        let nc = self.num_control as usize;
        let np = self.num_points();
        let mut needed = vec![false; np];
        for list in roots.iter() {
            for &p in list.iter() {
                if p != u32::MAX {
                    needed[p as usize] = true;
                }
            }
        }
        for p in (nc..np).rev() {
            if needed[p] {
                let k = p - nc;
                let (a, b) = (self.offsets[k] as usize, self.offsets[k + 1] as usize);
                for &s in &self.sources[a..b] {
                    needed[s as usize] = true;
                }
            }
        }
        // Compacted in place: a kept point and its terms move to a place at or before
        // their own, and it reads only earlier points, renumbered before it.
        let mut renumber: Vec<u32> = (0..nc as u32).collect();
        renumber.resize(np, u32::MAX);
        let (mut rows, mut terms) = (0, 0);
        for p in nc..np {
            if !needed[p] {
                continue;
            }
            let k = p - nc;
            let (a, b) = (self.offsets[k] as usize, self.offsets[k + 1] as usize);
            for j in a..b {
                self.sources[terms] = renumber[self.sources[j] as usize];
                self.weights[terms] = self.weights[j];
                terms += 1;
            }
            // Row `k`'s start is read above before row `rows` (at most `k`) ends here.
            self.offsets[rows + 1] = terms as u32;
            renumber[p] = (nc + rows) as u32;
            rows += 1;
        }
        self.offsets.truncate(rows + 1);
        self.sources.truncate(terms);
        self.weights.truncate(terms);
        self.offsets.shrink_to_fit();
        self.sources.shrink_to_fit();
        self.weights.shrink_to_fit();
        for list in roots.iter_mut() {
            for p in list.iter_mut() {
                if *p != u32::MAX {
                    *p = renumber[*p as usize];
                }
            }
        }
    }
}
