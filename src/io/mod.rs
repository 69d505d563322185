//! File input and output.
//!
//! - [`obj`]: Wavefront OBJ with OpenSubdiv's tag lines (creases, corners, holes, boundary
//!   interpolation, crease method, triangle rule), read and written losslessly.
//! - [`json`]: the JSON inputs of the constructions, with file and line in parse errors.

pub mod json;
pub mod obj;
