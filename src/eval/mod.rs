//! Exact limit evaluation: positions, derivatives and stencils.
//!
//! - [`limit_stencils`]: the exact limit position of every control vertex as weights on
//!   the control vertices (what the profile fitter solves with);
//! - [`limit_vertex_samples`] / [`vertex_limit_stencils`]: positions and derivatives at the
//!   control vertices ([`vertex_limit`] documents the conventions);
//! - [`Evaluator`] ([`evaluator`]): the limit surface at any `(face, u, v)`, addressed as
//!   [`ptex`] documents, or in Bfr's tiled domain ([`domain`]); `bspline`,
//!   `patch_regular`, `patch_topology`: regular bicubic patches, when a face is one, and
//!   the neighbourhoods refined until it is;
//! - [`folds`]: where the limit surface folds (its normal turns through zero and back);
//! - [`StencilTable`], [`LimitSample`]: the shared result types;
//! - [`surface`]: which faces and vertices have a limit surface, and how points without one
//!   are marked.

pub(crate) mod bspline;
mod dense;
pub mod domain;
pub mod evaluator;
pub mod folds;
pub(crate) mod parallel;
pub(crate) mod patch_corner;
pub(crate) mod patch_regular;
pub(crate) mod patch_topology;
mod points;
pub mod ptex;
pub mod sample;
pub mod stencil;
pub mod surface;
pub mod vertex_limit;
mod vertex_ring;

pub use domain::Domain;
pub use evaluator::{Evaluator, PrimvarSamples};
pub use sample::LimitSample;
pub use stencil::StencilTable;
pub use surface::{require_surface, vertices_with_surface};
pub use vertex_limit::{
    limit_stencils, limit_vertex_samples, vertex_limit_stencils, VertexLimitStencils,
};
