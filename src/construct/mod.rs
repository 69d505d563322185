//! Constructions: from curves to interpolating Catmull-Clark control meshes.
//!
//! - [`grid`]: ring-by-meridian quad grids with their end treatments, and crease tagging on
//!   rings — shared by every swept construction;
//! - [`pole_cap`]: the quad patches that close a ring (smooth poles, flat caps) and the
//!   pointed-tip fan;
//! - [`profile`]: the Hui–Lai construction from four planar silhouettes;
//! - [`sweep`]: revolution and general sweeps.

pub mod grid;
pub mod pole_cap;
pub mod profile;
pub mod sweep;
