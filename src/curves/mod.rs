//! Curves through given points: C² cubic splines (chord-length parameter) broken at corners,
//! and polylines, open or closed. Used by the constructions to turn a user's point lists
//! into smooth profiles and trajectories.
//!
//! - [`curve`]: [`SpaceCurve`], the piecewise cubic Hermite curve through 3-D points;
//! - [`planar`]: [`PlanarCurve`], an open [`SpaceCurve`] in the plane `z = 0` with 2-D points;
//! - [`corners`]: which input points are corners (one-sided tangents or chords turning by
//!   more than an angle) and the end tangents.

pub mod corners;
pub mod curve;
pub mod planar;

pub use curve::{CurvePoint, CurveSample, EndCondition, Interpolation, SpaceCurve};
pub use planar::PlanarCurve;
