//! File input and output.
//!
//! - [`obj`]: Wavefront OBJ with OpenSubdiv's tag lines (creases, corners, holes, boundary
//!   interpolation, crease method, triangle rule), read and written losslessly.
//! - [`json`]: the JSON inputs of the constructions, with file and line in parse errors.
//! - [`surface`]: tessellated limit surfaces as STL, OFF, PLY and OBJ; [`up_axis`]: Z- or Y-up.
//! - [`usda`]: control meshes as USD `UsdGeomMesh` with every subdivision tag.

pub mod json;
pub mod obj;
pub mod surface;
pub mod up_axis;
pub mod usda;
