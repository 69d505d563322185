//! Thin shells (Wang & Cheng 2014): the offset of a Catmull-Clark limit surface by a Bézier
//! crust, and hollow solids built from it.
//!
//! - [`crust`]: the bi-quintic Bernstein crust of one face from its four corner vectors;
//! - [`corners`]: the corner vector of every vertex (the exact limit normal times the
//!   thickness; one mitered vector at creases and corners; errors for vertices without
//!   normal and cusps too sharp to miter);
//! - [`offset`]: [`OffsetSurface`], the offset `O = S − D` and its first derivatives at any
//!   `(face, u, v)`, on the surface refined `level` times, with fold detection;
//! - [`thickness`]: the distance from the offset to the surface, and the crust level that
//!   keeps it within a tolerance.

pub mod corners;
pub mod crust;
pub mod offset;
pub mod thickness;

pub use offset::{OffsetSample, OffsetSettings, OffsetSurface, Side};
pub use thickness::{measure, offset_within, ThicknessReport};
