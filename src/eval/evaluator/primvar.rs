//! Primvars: a caller's per-vertex data of any width (colours, UVs as vertex data,
//! displacements) evaluated on the limit surface through the evaluator's topology.
//!
//! The data runs through the same point program, patches and on-the-spot refinement as the
//! positions, three components at a time (a `DVec3` whose unused lanes are zero): every
//! operation is per component, so a primvar of width 3 equal to the positions gives the
//! positions' limit bit for bit, and any other width gives each component as that
//! component alone would.

use glam::DVec3;

use super::{BatchOutput, Evaluator, NoSurface};
use crate::error::{Error, Result};
use crate::eval::domain::Domain;
use crate::eval::sample::LimitSample;

/// Limit values and first derivatives of a primvar of width `dim` at a batch of points.
#[derive(Debug, Clone, PartialEq)]
pub struct PrimvarSamples {
    /// Components per point.
    pub dim: usize,
    /// `dim` values per point, point after point.
    pub values: Vec<f64>,
    /// The derivatives with respect to `u`, laid out as `values`.
    pub du: Vec<f64>,
    /// The derivatives with respect to `v`, laid out as `values`.
    pub dv: Vec<f64>,
}

impl Evaluator {
    /// The limit of per-vertex data `data` (`dim` doubles per control vertex, vertex after
    /// vertex) and its derivatives at the points `(faces[i], u[i], v[i])` (Ptex domain, as
    /// [`Evaluator::evaluate`]). Cost: a pass over the evaluator's points per three
    /// components (as [`Evaluator::set_positions`]), then the points; on the evaluator's
    /// threads, with results independent of the thread count.
    ///
    /// Errors ([`Error::InvalidArgument`]): `dim` 0, not `dim` values per control vertex, a
    /// non-finite value; the point errors of [`Evaluator::evaluate_many`] (naming the first
    /// bad point).
    pub fn evaluate_primvar(
        &self,
        data: &[f64],
        dim: usize,
        faces: &[u32],
        u: &[f64],
        v: &[f64],
    ) -> Result<PrimvarSamples> {
        let nv = self.mesh.num_vertices();
        if dim == 0 {
            return Err(Error::invalid_argument(
                "primvar width (dim) must be at least 1",
            ));
        }
        if nv.checked_mul(dim) != Some(data.len()) {
            return Err(Error::invalid_argument(format!(
                "{} primvar values given; {nv} vertices of width {dim} need {}",
                data.len(),
                nv.saturating_mul(dim)
            )));
        }
        if let Some(i) = data.iter().position(|x| !x.is_finite()) {
            return Err(Error::invalid_argument(format!(
                "primvar value {i} (vertex {}, component {}) is not finite ({})",
                i / dim,
                i % dim,
                data[i]
            )));
        }
        let n = faces.len();
        let mut out = PrimvarSamples {
            dim,
            values: vec![0.0; n * dim],
            du: vec![0.0; n * dim],
            dv: vec![0.0; n * dim],
        };
        for first in (0..dim).step_by(3) {
            let width = (dim - first).min(3);
            let control: Vec<DVec3> = data
                .chunks_exact(dim)
                .map(|x| {
                    let mut c = [0.0; 3];
                    c[..width].copy_from_slice(&x[first..first + width]);
                    DVec3::from_array(c)
                })
                .collect();
            let points = self.program.run(&control);
            let columns = Columns {
                values: &mut out.values,
                du: &mut out.du,
                dv: &mut out.dv,
                dim,
                first,
                width,
            };
            self.evaluate_batch_with(
                &points,
                Domain::Ptex,
                (faces, u, v),
                NoSurface::Error,
                columns,
            )?;
        }
        Ok(out)
    }
}

/// Columns `first..first + width` of a primvar result of width `dim` (a piece of its rows
/// on each thread): where one pass of three components is written.
struct Columns<'a> {
    values: &'a mut [f64],
    du: &'a mut [f64],
    dv: &'a mut [f64],
    dim: usize,
    first: usize,
    width: usize,
}

impl BatchOutput for Columns<'_> {
    fn split(self, n: usize) -> (Self, Self) {
        let at = n * self.dim;
        let (values, values_rest) = self.values.split_at_mut(at);
        let (du, du_rest) = self.du.split_at_mut(at);
        let (dv, dv_rest) = self.dv.split_at_mut(at);
        let (dim, first, width) = (self.dim, self.first, self.width);
        (
            Columns {
                values,
                du,
                dv,
                dim,
                first,
                width,
            },
            Columns {
                values: values_rest,
                du: du_rest,
                dv: dv_rest,
                dim,
                first,
                width,
            },
        )
    }

    fn put(&mut self, k: usize, sample: Option<LimitSample>) {
        let s = sample.unwrap_or(LimitSample::NO_SURFACE);
        let at = k * self.dim + self.first..k * self.dim + self.first + self.width;
        self.values[at.clone()].copy_from_slice(&s.position.to_array()[..self.width]);
        self.du[at.clone()].copy_from_slice(&s.du.to_array()[..self.width]);
        self.dv[at].copy_from_slice(&s.dv.to_array()[..self.width]);
    }
}
