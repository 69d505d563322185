//! Planar curves through given points: C² cubic splines (chord-length parameter) broken at
//! corners, and polylines. Used by the constructions to turn a user's point lists into
//! smooth profiles.
//!
//! - [`spline`]: [`PlanarCurve`], a piecewise cubic Hermite curve through the points;
//! - [`corners`]: which input points are corners (one-sided tangents turning by more than
//!   an angle) and the end tangents.

pub mod corners;
pub mod spline;

pub use spline::{EndCondition, Interpolation, PlanarCurve};
