//! File input and output.
//!
//! - [`obj`]: Wavefront OBJ with OpenSubdiv's tag lines (creases, corners, holes, boundary
//!   interpolation, crease method, triangle rule), read and written losslessly.

pub mod obj;
