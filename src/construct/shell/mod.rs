//! Thin shells (Wang & Cheng 2014): the offset of a Catmull-Clark limit surface by a Bézier
//! crust, and hollow solids built from it.
//!
//! - [`crust`]: the bi-quintic Bernstein crust of one face from its four corner vectors;
//! - [`corners`]: the corner vector of every vertex (the exact limit normal times the
//!   thickness; one mitered vector at creases and corners; errors for vertices without
//!   normal and cusps too sharp to miter);
//! - [`offset`]: [`OffsetSurface`], the offset `O = S − D` and its first derivatives at any
//!   `(face, u, v)`, on the surface refined `level` times, with fold detection;
//! - [`thickness`]: the distance from the offset to the surface, and the crust level that
//!   keeps it within a tolerance;
//! - [`solid`]: the hollow solid's cage (outer mesh, reversed inner mesh, rim).
//!
//! The construction: [`ShellInput`] (a mesh and the offset settings) and [`build`], which
//! fits the solid's cage with the shared fitter so that its limit passes through the outer
//! limit positions and the offset at every vertex (at the crust's level). The shell takes
//! its subdivision options from the input mesh's tags (its surface), not from the shared
//! [`Settings`]: the solid is fitted under them and tagged with them.

pub mod corners;
pub mod crust;
pub mod offset;
pub mod solid;
pub mod thickness;

pub use offset::{OffsetSample, OffsetSettings, OffsetSurface, Side};
pub use thickness::{measure, offset_within, ThicknessReport};

use crate::construct::{Fitted, Settings};
use crate::control::Control;
use crate::error::Result;
use crate::fit::FitOptions;
use crate::mesh::Mesh;

/// The input of a hollow solid: the mesh whose limit surface is the outer wall, and the
/// offset.
#[derive(Debug, Clone)]
pub struct ShellInput {
    /// The outer wall's control mesh (manifold; its tags give the subdivision options).
    pub mesh: Mesh,
    /// Thickness, side, crust level, folds.
    pub offset: OffsetSettings,
    /// With a tolerance (model units) the crust level is the lowest from `offset.level` on
    /// whose thickness is within it ([`offset_within`]).
    pub tolerance: Option<f64>,
}

impl ShellInput {
    /// The offset surface of the input (at the level the tolerance chooses, if any) and its
    /// thickness report when measured.
    pub fn offset(&self) -> Result<(OffsetSurface, Option<ThicknessReport>)> {
        let options = self.mesh.options().resolve();
        Ok(match self.tolerance {
            None => (OffsetSurface::new(&self.mesh, &options, self.offset)?, None),
            Some(t) => {
                let (o, r) = offset_within(&self.mesh, &options, self.offset, t)?;
                (o, Some(r))
            }
        })
    }
}

/// Build the hollow solid of `input`: one closed, consistently oriented quad mesh (two
/// sheets for a closed input) whose limit passes through the outer wall's limit and the
/// offset at every vertex. Of the shared settings only the progress hook and memory budget
/// (`settings.control`) apply (see the module doc).
///
/// Errors: those of [`OffsetSurface::new`] and [`offset_within`]; those of the fit.
pub fn build(input: &ShellInput, settings: &Settings) -> Result<Fitted> {
    hollow_solid(&input.offset()?.0, &settings.control)
}

/// The fitted hollow solid of `offset` ([`solid::hollow_parts`], fitted under the offset
/// surface's subdivision options), polling `control` while fitting.
///
/// Errors: those of the fit ([`crate::Error::Cancelled`] and
/// [`crate::Error::LimitExceeded`] from `control`).
pub fn hollow_solid(offset: &OffsetSurface, control: &Control) -> Result<Fitted> {
    let (parts, design) = solid::hollow_parts(offset)?;
    let o = offset.fine().options();
    let options = FitOptions::new(o.boundary, o.crease_method);
    Fitted::fit_with(parts, options, control, design, &[])
}
