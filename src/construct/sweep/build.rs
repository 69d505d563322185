//! The interpolating fit of a sweep's or revolution's grid: the public constructions.

use glam::DVec3;

use super::revolve::RevolveInput;
use super::sweep::SweepInput;
use crate::error::Result;
use crate::eval::limit_stencils;
use crate::fit::{solve, CsrRef, FitReport};
use crate::mesh::{Mesh, MeshParts};

/// Fit tolerance relative to the bounding-box diagonal of the data points.
pub const FIT_TOLERANCE: f64 = 1e-10;

/// A fitted control mesh and the data point its limit surface passes through at each vertex.
#[derive(Debug, Clone, PartialEq)]
pub struct SweptSurface {
    /// The control mesh: all quads, creases and corners tagged.
    pub mesh: Mesh,
    /// The data point of each vertex, in vertex order: the limit position at that vertex.
    pub targets: Vec<DVec3>,
    /// How well the fit met the data.
    pub fit: FitReport,
}

/// Move the vertices of `parts` (each at its data point) so that the exact limit surface
/// interpolates the data points, to [`FIT_TOLERANCE`] × the data's bounding-box diagonal.
pub fn fit_parts(parts: MeshParts) -> Result<SweptSurface> {
    let mesh = Mesh::from_parts(parts)?;
    let targets = mesh.positions().to_vec();
    let table = limit_stencils(&mesh, &mesh.options().resolve())?;
    let a = CsrRef {
        offsets: &table.offsets,
        indices: &table.indices,
        weights: &table.weights,
    };
    let (positions, fit) = solve(a, &targets, FIT_TOLERANCE * mesh.bounding_box_diagonal())?;
    let mut parts = mesh.into_parts();
    parts.positions = positions;
    Ok(SweptSurface {
        mesh: Mesh::from_parts(parts)?,
        targets,
        fit,
    })
}

/// The surface of revolution of `input`, fitted. Errors: those of [`RevolveInput::mesh_parts`]
/// ([`crate::Error::InvalidArgument`] for bad input) and of the fit.
pub fn revolve(input: &RevolveInput) -> Result<SweptSurface> {
    fit_parts(input.mesh_parts()?)
}

/// The sweep of `input`, fitted. Errors: those of [`SweepInput::mesh_parts`]
/// ([`crate::Error::InvalidArgument`] for bad input) and of the fit.
pub fn sweep(input: &SweepInput) -> Result<SweptSurface> {
    fit_parts(input.mesh_parts()?)
}
