//! Mesh topology as flat adjacency arrays in OpenSubdiv's component order.
//!
//! [`Level`] holds one level: face-vertices, face-edges, edge-vertices, edge-faces,
//! vertex-faces and vertex-edges (with local indices), sharpness and vertex rules. The base
//! level is built from a [`crate::Mesh`] exactly as OpenSubdiv's Far builds it, so that edge
//! numbers, the order around vertices and therefore every refined index agree with OpenSubdiv.

mod build;
mod level;
#[cfg(test)]
mod tests;
mod validate;

pub(crate) use build::Tags;
pub use level::Level;
