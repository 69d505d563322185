//! Interpolation of vertex data through one refinement step, with OpenSubdiv's arithmetic
//! (`Far::PrimvarRefinerReal<double>::Interpolate`): face points, then edge points (which use
//! the new face points), then vertex points (face points, then the vertices across the
//! incident edges, then the vertex itself), each a weighted sum accumulated in that order.

use glam::DVec3;

use super::ranges::fill_pass;
use super::step::{Refinement, VertexOrder};
use crate::catmark::masks::{
    face_point_weight, EdgeMask, EdgeNeighbourhood, VertexMask, VertexMaskBuilder,
    VertexNeighbourhood,
};
use crate::catmark::Rule;
use crate::control::Control;
use crate::error::Result;
use crate::options::TriangleSubdivision;
use crate::topology::Level;

/// Vertex data that can be refined: a value that starts at zero and accumulates weighted
/// copies of other values (`Clear` and `AddWithWeight` in OpenSubdiv).
pub trait Primvar: Sized + Send + Sync {
    /// The zero value.
    fn zero() -> Self;
    /// `self += weight * src`.
    fn add_weighted(&mut self, src: &Self, weight: f64);
    /// Called on the value of child vertex `child` once it is complete, before it is stored
    /// (and, for a face point, read by the edge and vertex points): a value that records
    /// how it was computed can learn its own index here. Nothing by default.
    #[inline]
    fn finish(&mut self, _child: u32) {}
}

impl Primvar for DVec3 {
    fn zero() -> Self {
        DVec3::ZERO
    }
    fn add_weighted(&mut self, src: &Self, weight: f64) {
        // Component by component, product then sum: the same rounding as OpenSubdiv's
        // `_p[i] += src._p[i] * weight`.
        *self += *src * weight;
    }
}

impl Primvar for f64 {
    fn zero() -> Self {
        0.0
    }
    fn add_weighted(&mut self, src: &Self, weight: f64) {
        *self += *src * weight;
    }
}

/// A sparse linear combination of base-level values: `(index, weight)` pairs, one per index.
///
/// Refining the unit stencils of the base vertices gives, for every refined vertex, its
/// weights on the base vertices; applying them to positions gives the refined positions up to
/// rounding.
#[derive(Debug, Clone, Default, PartialEq)]
pub struct SparseStencil {
    /// `(base index, weight)` pairs, each index at most once, in order of first appearance.
    pub entries: Vec<(u32, f64)>,
}

impl SparseStencil {
    /// The stencil that selects base value `index`.
    pub fn unit(index: u32) -> SparseStencil {
        SparseStencil {
            entries: vec![(index, 1.0)],
        }
    }

    /// Apply to base values.
    pub fn apply<T: Primvar>(&self, values: &[T]) -> T {
        let mut out = T::zero();
        for &(i, w) in &self.entries {
            out.add_weighted(&values[i as usize], w);
        }
        out
    }
}

impl Primvar for SparseStencil {
    fn zero() -> Self {
        SparseStencil::default()
    }
    fn add_weighted(&mut self, src: &Self, weight: f64) {
        if weight == 0.0 {
            return;
        }
        for &(i, w) in &src.entries {
            match self.entries.iter_mut().find(|(j, _)| *j == i) {
                Some((_, acc)) => *acc += w * weight,
                None => self.entries.push((i, w * weight)),
            }
        }
    }
}

/// Values of the child vertices of `r` from the values `src` of the parent level's vertices,
/// on the calling thread (the evaluators call this within their own threads).
///
/// Panics if `src` has fewer values than `parent` has vertices.
pub fn interpolate<T: Primvar>(parent: &Level, r: &Refinement, src: &[T]) -> Vec<T> {
    interpolate_polled(parent, r, src, &Control::NONE.with_threads(1))
        .expect("a control without a hook never cancels")
}

/// [`interpolate`] on `control`'s threads ([`Control::threads`], 0: all cores), reporting to
/// `control` through its passes over the parent's faces, edges and vertices: the same values
/// bit for bit whatever the thread count. Each pass fills contiguous ranges of its child
/// vertices, one per thread, each point the same weighted sum in the same order as on one
/// thread; the first range reports (its fraction stands for the pass) and a cancel there
/// stops the others at their next point.
///
/// Errors: [`crate::Error::Cancelled`] from `control`.
pub(crate) fn interpolate_polled<T: Primvar>(
    parent: &Level,
    r: &Refinement,
    src: &[T],
    control: &Control,
) -> Result<Vec<T>> {
    assert!(src.len() >= parent.num_vertices());
    let (nv, nf, ne) = (
        parent.num_vertices(),
        parent.num_faces(),
        parent.num_edges(),
    );
    let steps = (nf + ne + nv) as f64;
    let child = &r.child;
    // Filled in chunks, each polled: on a large level the first touch of its pages is a
    // wait of its own.
    let nc = child.num_vertices();
    let mut dst: Vec<T> = Vec::with_capacity(nc);
    for start in (0..nc).step_by(1 << 16) {
        control.report(0.0)?;
        dst.extend((start..nc.min(start + (1 << 16))).map(|_| T::zero()));
    }
    // The children of the parent's vertices, faces and edges: three runs of `dst`.
    let (vertex_points, face_points, edge_points) = match r.order() {
        VertexOrder::VerticesFirst => {
            let (v, rest) = dst.split_at_mut(nv);
            let (f, e) = rest.split_at_mut(nf);
            (v, f, e)
        }
        VertexOrder::FacesFirst => {
            let (f, rest) = dst.split_at_mut(nf);
            let (e, v) = rest.split_at_mut(ne);
            (v, f, e)
        }
    };
    let pass =
        |done: usize, n: usize| control.stage(done as f64 / steps, (done + n) as f64 / steps);
    let options = parent.options();

    fill_pass(face_points, &pass(0, nf), |_: &mut (), f| {
        let fv = parent.face_vertices(f);
        let w = face_point_weight(fv.len());
        let mut acc = T::zero();
        for &v in fv {
            acc.add_weighted(&src[v as usize], w);
        }
        acc.finish(r.face_child_vertex(f));
        acc
    })?;
    let face_points = &*face_points;

    let smooth_triangles = options.triangles == TriangleSubdivision::Smooth;
    fill_pass(edge_points, &pass(nf, ne), |emask: &mut EdgeMask, e| {
        let ev = parent.edge_vertices(e);
        let ef = parent.edge_faces(e);
        let cv = r.edge_child_vertex(e);
        if parent.edge_sharpness(e) <= 0.0 && ef.len() == 2 && !smooth_triangles {
            // The common case, the plain smooth mask, without building it.
            let mut acc = T::zero();
            acc.add_weighted(&src[ev[0] as usize], 0.25);
            acc.add_weighted(&src[ev[1] as usize], 0.25);
            acc.add_weighted(&face_points[ef[0] as usize], 0.25);
            acc.add_weighted(&face_points[ef[1] as usize], 0.25);
            acc.finish(cv);
            return acc;
        }
        let mut tri = [false; 2];
        if ef.len() == 2 {
            for (t, &f) in tri.iter_mut().zip(ef) {
                *t = parent.face_vertices(f as usize).len() == 3;
            }
        }
        let hood = EdgeNeighbourhood {
            sharpness: parent.edge_sharpness(e),
            num_faces: ef.len(),
            faces_are_triangles: tri,
        };
        emask.compute(
            &hood,
            Some(child.vertex_rule(cv as usize)),
            options.crease_method,
            options.triangles,
        );
        let mut acc = T::zero();
        acc.add_weighted(&src[ev[0] as usize], emask.vertices[0]);
        acc.add_weighted(&src[ev[1] as usize], emask.vertices[1]);
        for (&f, &w) in ef.iter().zip(&emask.faces) {
            acc.add_weighted(&face_points[f as usize], w);
        }
        acc.finish(cv);
        acc
    })?;

    type VertexScratch = (VertexMaskBuilder, VertexMask, Vec<f32>);
    fill_pass(
        vertex_points,
        &pass(nf + ne, nv),
        |scratch: &mut VertexScratch, v| {
            let (builder, vmask, edge_sharpness) = scratch;
            let cv = r.vertex_child_vertex(v);
            let ve = parent.vertex_edges(v);
            let vf = parent.vertex_faces(v);
            let p_rule = parent.vertex_rule(v);
            if p_rule == Rule::Smooth {
                // The common case, the smooth mask (a smooth vertex stays smooth), inline.
                let n = vf.len();
                let w = 1.0 / (n * n) as f64;
                let mut acc = T::zero();
                for &f in vf {
                    acc.add_weighted(&face_points[f as usize], w);
                }
                for &e in ve {
                    let [a, b] = parent.edge_vertices(e as usize);
                    let across = if a as usize == v { b } else { a };
                    acc.add_weighted(&src[across as usize], w);
                }
                acc.add_weighted(&src[v], (n as f64 - 2.0) / n as f64);
                acc.finish(cv);
                return acc;
            }
            edge_sharpness.clear();
            if !matches!(p_rule, Rule::Smooth | Rule::Dart) {
                edge_sharpness.extend(ve.iter().map(|&e| parent.edge_sharpness(e as usize)));
            }
            let hood = VertexNeighbourhood {
                num_faces: vf.len(),
                sharpness: parent.vertex_sharpness(v),
                child_sharpness: child.vertex_sharpness(cv as usize),
                edge_sharpness,
            };
            builder.compute(
                &hood,
                p_rule,
                child.vertex_rule(cv as usize),
                options.crease_method,
                vmask,
            );
            let mut acc = T::zero();
            for (&f, &w) in vf.iter().zip(&vmask.faces) {
                acc.add_weighted(&face_points[f as usize], w);
            }
            for (&e, &w) in ve.iter().zip(&vmask.edges) {
                let [a, b] = parent.edge_vertices(e as usize);
                let across = if a as usize == v { b } else { a };
                acc.add_weighted(&src[across as usize], w);
            }
            acc.add_weighted(&src[v], vmask.vertex);
            acc.finish(cv);
            acc
        },
    )?;
    Ok(dst)
}
