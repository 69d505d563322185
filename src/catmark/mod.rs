//! The Catmull-Clark ("Catmark") subdivision rules as pure functions of plain values, with
//! OpenSubdiv's `Sdc` semantics; no mesh storage here.
//!
//! - [`crease`]: sharpness decay (uniform and Chaikin, in `f32`), vertex rule classification
//!   (smooth / dart / crease / corner) and the fractional weight between two rules;
//! - [`masks`]: face, edge and vertex point weights for any polygon, the smooth-triangle
//!   option, and the blending of rules while semi-sharp features decay;
//! - [`boundary`]: what the boundary interpolation rules and non-manifold features do to
//!   sharpness before refinement.

pub mod boundary;
pub mod crease;
pub mod masks;

pub use crease::Rule;
