//! Constructions: from curves to interpolating Catmull-Clark control meshes.
//!
//! - [`design`]: distance to the design surface between the data points, folds and
//!   undulation of a fitted construction;
//! - [`equidistribute`]: ring spacing weighted by the profile's curvature (resolves a
//!   sharply turning rim without wasting rings on flat parts);
//! - [`grid`]: ring-by-meridian quad grids with their end treatments, and crease tagging on
//!   rings — shared by every swept construction;
//! - [`pole_cap`]: the quad patches that close a ring (smooth poles, flat caps) and the
//!   pointed-tip fan;
//! - [`profile`]: the Hui–Lai construction from four planar silhouettes;
//! - [`sweep`]: revolution and general sweeps.

pub mod design;
pub mod equidistribute;
pub mod grid;
pub mod pole_cap;
pub mod profile;
pub mod sweep;
