//! Constructions: from curves to interpolating Catmull-Clark control meshes.
//!
//! A construction is an input type and a build function,
//! `build(&Input, &Settings) -> Result<Fitted>`, with the shared [`Settings`] (defaults and
//! checks written once) and the shared result [`Fitted`]. One room per construction:
//! - [`profile`]: the Hui–Lai construction from four planar silhouettes;
//! - [`revolve`]: surfaces of revolution, full or partial turns with their caps;
//! - [`sweep`]: a planar profile swept along a 3-D trajectory;
//! - [`curves`]: a patch through unorganized 3-D sketch curves (Qin & Wright);
//! - [`blend`]: N pipes joined by a generalized B-spline (GBS) blend (its control mesh).
//!
//! Shared pieces beside them:
//! - [`settings`]: [`Settings`], the sample limits, the JSON inputs' common keys;
//! - [`fitted`]: [`Fitted`], the fit of a cage and its surface report;
//! - [`design`]: distance to the design surface between the data points, folds and
//!   undulation of a fitted construction;
//! - `equidistribute`: ring spacing weighted by the profile's curvature (resolves a
//!   sharply turning rim without wasting rings on flat parts);
//! - `grid`: ring-by-meridian quad grids with their end treatments, and crease tagging on
//!   rings;
//! - `grid_mesh`: a sampled grid of data points (revolutions, sweeps) to quad mesh parts;
//! - `pole_cap`: the quad patches that close a ring (smooth poles, flat caps) and the
//!   pointed-tip fan.

pub mod blend;
pub mod curves;
pub mod design;
pub(crate) mod equidistribute;
pub mod fitted;
pub(crate) mod grid;
pub(crate) mod grid_mesh;
pub(crate) mod pole_cap;
pub mod profile;
pub mod revolve;
pub mod settings;
pub mod shell;
pub mod sweep;

pub use fitted::Fitted;
pub use settings::{Caps, Settings};
