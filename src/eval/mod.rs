//! Exact limit evaluation: positions, derivatives and stencils on control vertices.
//!
//! - [`limit_stencils`]: the exact limit position of every control vertex as weights on
//!   the control vertices (what the profile fitter solves with);
//! - [`limit_vertex_samples`] / [`vertex_limit_stencils`]: positions and derivatives at the
//!   control vertices ([`vertex_limit`] documents the conventions);
//! - [`StencilTable`], [`LimitSample`]: the shared result types.

mod dense;
pub mod sample;
pub mod stencil;
pub mod vertex_limit;
mod vertex_ring;

pub use sample::LimitSample;
pub use stencil::StencilTable;
pub use vertex_limit::{
    limit_stencils, limit_vertex_samples, vertex_limit_stencils, VertexLimitStencils,
};
