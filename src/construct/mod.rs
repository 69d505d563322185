//! Constructions: from curves to interpolating Catmull-Clark control meshes.
//!
//! - [`equidistribute`]: ring spacing weighted by the profile's curvature (resolves a
//!   sharply turning rim without wasting rings on flat parts);
//! - [`grading`]: ring spacing graded towards smooth poles (keeps the fourth-order
//!   convergence next to the caps' valence-3 vertices);
//! - [`grid`]: ring-by-meridian quad grids with their end treatments, and crease tagging on
//!   rings — shared by every swept construction;
//! - [`pole_cap`]: the quad patches that close a ring (smooth poles, flat caps) and the
//!   pointed-tip fan;
//! - [`profile`]: the Hui–Lai construction from four planar silhouettes;
//! - [`sweep`]: revolution and general sweeps.

pub mod equidistribute;
pub mod grading;
pub mod grid;
pub mod pole_cap;
pub mod profile;
pub mod sweep;
