//! # profsubd
//!
//! Planar profile curves to Catmull-Clark quad control meshes with crease and corner
//! sharpness tags, and an exact Catmull-Clark evaluator that follows OpenSubdiv's
//! Catmark rules.
//!
//! Layout, by domain:
//! - [`mesh`]: the control mesh (OpenSubdiv `Far::TopologyDescriptor` model) and its validation;
//! - [`topology`]: flat adjacency arrays with OpenSubdiv's component order;
//! - [`catmark`]: the subdivision rules (masks, crease decay, vertex classification) as pure functions;
//! - [`refine`]: uniform refinement in OpenSubdiv Far's vertex/edge/face order;
//! - [`eval`]: exact limit positions, derivatives and stencils;
//! - [`curves`]: curve input (splines broken at corners, polylines);
//! - [`construct`]: constructions (profiles, sweeps, ...);
//! - [`fit`]: interpolating fit of control points to data points;
//! - [`io`]: OBJ with OpenSubdiv tag lines;
//! - [`ffi`]: the C ABI (`include/profsubd.h`);
//! - [`cli`]: the `profsubd` command-line tool.

#![deny(missing_docs)]

pub mod catmark;
pub mod cli;
pub mod construct;
pub mod curves;
pub mod error;
pub mod eval;
pub mod ffi;
pub mod fit;
pub mod io;
pub(crate) mod math;
pub mod mesh;
pub mod options;
pub mod refine;
pub mod topology;

pub use error::{Error, Result};
pub use mesh::{Corner, Crease, Mesh, MeshParts};
pub use options::{
    BoundaryInterpolation, CreaseMethod, PartialOptions, SubdivOptions, TriangleSubdivision,
};
