//! The interpolating fit of a sweep's or revolution's grid: the public constructions.

use glam::DVec3;

use super::revolve::RevolveInput;
use super::sweep::SweepInput;
use crate::construct::design::{DesignLattice, SurfaceReport};
use crate::error::Result;
use crate::fit::{fit_cage, FitOptions, FitReport, FittedCage};
use crate::mesh::{Mesh, MeshParts};

/// A fitted control mesh and the data point its limit surface passes through at each vertex.
#[derive(Debug, Clone, PartialEq)]
pub struct SweptSurface {
    /// The control mesh: all quads, creases and corners tagged.
    pub mesh: Mesh,
    /// The data point of each vertex, in vertex order: the limit position at that vertex.
    pub targets: Vec<DVec3>,
    /// How well the fit met the data.
    pub fit: FitReport,
    /// The design surface on every face's lattice ([`crate::construct::design`]).
    pub design: DesignLattice,
}

impl SweptSurface {
    /// Distance to the design surface between the data points, folds and undulation of the
    /// fitted limit surface ([`crate::construct::design::surface_report`]), computed on the
    /// first call. Errors: those of the evaluation.
    pub fn surface_report(&self) -> Result<&SurfaceReport> {
        self.design.report(&self.mesh)
    }
}

/// Fit `parts` (each vertex at its data point) with the profile pipeline's fitter under
/// `options` ([`fit_cage`], which also writes them as the mesh's option tags): the exact
/// limit surface then passes through every data point, to
/// [`crate::fit::RELATIVE_TOLERANCE`] × their diagonal.
/// `design` is the design surface on the faces' lattice (empty if unknown).
pub fn fit_parts(
    parts: MeshParts,
    options: FitOptions,
    design: DesignLattice,
) -> Result<SweptSurface> {
    let FittedCage { mesh, targets, fit } = fit_cage(parts, options)?;
    Ok(SweptSurface {
        mesh,
        targets,
        fit,
        design,
    })
}

/// The surface of revolution of `input`, fitted. Errors: those of [`RevolveInput::mesh_parts`]
/// ([`crate::Error::InvalidArgument`] for bad input) and of the fit.
pub fn revolve(input: &RevolveInput) -> Result<SweptSurface> {
    let (parts, design) = input.cage()?;
    fit_parts(parts, input.fit_options(), design)
}

/// The sweep of `input`, fitted. Errors: those of [`SweepInput::mesh_parts`]
/// ([`crate::Error::InvalidArgument`] for bad input) and of the fit.
pub fn sweep(input: &SweepInput) -> Result<SweptSurface> {
    let (parts, design) = input.cage()?;
    fit_parts(parts, input.fit_options(), design)
}
