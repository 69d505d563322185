//! N-way blends of pipes with generalized B-spline (GBS) subdivision (Shen & Fang 2016):
//! N cylinders, each the exact GBS limit of a four-column control mesh, joined at their
//! junction ends by a hub of low valence ([`hub`]); the GBS control mesh is
//! [`control_mesh`]'s, and [`build`] fits a Catmull–Clark mesh to its limit ([`fit`]).

pub mod dual;
pub mod fit;
pub mod hub;
pub mod input;
#[cfg(test)]
mod tests;

pub use fit::build;
pub use hub::{control_mesh, BlendMesh};
pub use input::{BlendInput, Pipe};
