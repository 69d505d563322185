//! # profsubd
//!
//! Planar profile curves to Catmull-Clark quad control meshes with crease and corner
//! sharpness tags, and an exact Catmull-Clark evaluator that follows OpenSubdiv's
//! Catmark rules.
//!
//! What a Rust user needs is re-exported here: [`Mesh`] and its parts, the subdivision
//! options, [`refine_uniform`], [`limit_stencils`], [`Evaluator`], the three constructions
//! ([`profile`], [`revolve`], [`sweep`]: each an input type and
//! `build(&Input, &Settings) -> Result<Fitted>`) with their shared [`Settings`] and result
//! [`Fitted`], and [`Error`]. Points are [`DVec3`] (glam).
//!
//! ## A mesh, refined, its limit at the vertices and anywhere
//!
//! ```
//! use profsubd::{limit_stencils, refine_uniform, DVec3, Evaluator, Mesh, MeshParts};
//! use profsubd::SubdivOptions;
//!
//! // A unit square of four quads (3 × 3 vertices), boundary edges and corners sharp.
//! let positions = (0..9)
//!     .map(|i| DVec3::new((i % 3) as f64 * 0.5, (i / 3) as f64 * 0.5, 0.0))
//!     .collect();
//! let mesh = Mesh::from_parts(MeshParts {
//!     positions,
//!     face_sizes: vec![4; 4],
//!     face_indices: vec![0, 1, 4, 3, 1, 2, 5, 4, 3, 4, 7, 6, 4, 5, 8, 7],
//!     ..Default::default()
//! })?;
//! let options = SubdivOptions::default();
//!
//! // Uniform refinement in OpenSubdiv Far's order: 4 quads → 16 → 64.
//! let refined = refine_uniform(&mesh, &options, 2)?;
//! assert_eq!(refined.num_faces(), 64);
//!
//! // The limit position of every control vertex (the corners stay put).
//! let limits = limit_stencils(&mesh, &options)?.apply(mesh.positions())?;
//! assert_eq!(limits[8], DVec3::new(1.0, 1.0, 0.0));
//!
//! // Exact evaluation at (face, u, v): the planar square's limit is the square itself.
//! let evaluator = Evaluator::new(&mesh, &options)?;
//! let p = evaluator.evaluate(3, 0.5, 0.5)?.position;
//! assert!((p - DVec3::new(0.75, 0.75, 0.0)).length() < 1e-12);
//! # Ok::<(), profsubd::Error>(())
//! ```
//!
//! ## Profile curves (Hui & Lai), revolutions and sweeps
//!
//! ```
//! use profsubd::{profile, revolve, sweep, Caps, RevolveInput, Settings, SweepInput};
//!
//! // The built-in profile model (a bottle), and a settings change.
//! let (bottle, settings) = profile::default_model();
//! let fitted = profile::build(&bottle, &Settings { crease_sharpness: 3.0, ..settings })?;
//! assert!(fitted.fit.residual <= fitted.fit.tolerance);
//!
//! // Half a vase, closed by flat caps.
//! let mut vase = RevolveInput::new(vec![[1.0, 0.0], [1.4, 0.8], [1.3, 2.0], [0.9, 3.0]]);
//! (vase.angle_deg, vase.samples_profile, vase.samples_around) = (180.0, 8, 16);
//! let caps = Settings { caps: Caps::Flat, ..Settings::default() };
//! let half = revolve::build(&vase, &caps)?;
//! // Every control vertex's limit position is its data point.
//! assert_eq!(half.targets.len(), half.mesh.num_vertices());
//!
//! // A square tube along a quarter circle, from JSON (input keys and settings keys).
//! let json = r#"{"profile": [[-0.1,-0.1],[0.1,-0.1],[0.1,0.1],[-0.1,0.1]],
//!               "closed_profile": true, "trajectory": [[1,0,0],[0.7071,0.7071,0],[0,1,0]],
//!               "samples_profile": 8, "samples_trajectory": 8, "crease_sharpness": 2}"#;
//! let (tube, settings) = SweepInput::from_json(json, std::path::Path::new("tube.json"))?;
//! let tube = sweep::build(&tube, &settings)?;
//! assert!(tube.mesh.creases().iter().all(|c| c.sharpness == 2.0));
//! // Distance to the design surface, folds and fairness.
//! assert_eq!(tube.surface_report()?.folded_faces, 0);
//! # Ok::<(), profsubd::Error>(())
//! ```
//!
//! ## OBJ files (with OpenSubdiv's tag lines)
//!
//! ```
//! use profsubd::io::obj::{parse_obj, to_obj_string};
//! use profsubd::{profile, revolve, RevolveInput, Settings};
//!
//! let cone = revolve::build(&RevolveInput::new(vec![[1.0, 0.0], [0.0, 2.0]]), &Settings::default())?;
//! let text = to_obj_string(&cone.mesh);
//! let read = parse_obj(&text, std::path::Path::new("cone.obj"))?;
//! assert_eq!(read.mesh.corners(), cone.mesh.corners());
//! # Ok::<(), profsubd::Error>(())
//! ```
//!
//! Layout, by domain:
//! - [`mesh`]: the control mesh (OpenSubdiv `Far::TopologyDescriptor` model) and its validation;
//! - [`topology`]: flat adjacency arrays with OpenSubdiv's component order;
//! - [`catmark`]: the subdivision rules (masks, crease decay, vertex classification) as pure functions;
//! - [`refine`]: uniform refinement in OpenSubdiv Far's vertex/edge/face order;
//! - [`eval`]: exact limit positions, derivatives and stencils;
//! - [`curves`]: curve input (splines broken at corners, polylines);
//! - [`construct`]: the constructions, their shared settings and result;
//! - [`tessellate`]: triangles or quads on the limit surface, watertight;
//! - `fit` (internal): interpolating fit of control points to data points ([`FitReport`],
//!   [`FitOptions`] re-exported);
//! - [`control`]: progress, cancellation and the memory budget of long work;
//! - [`io`]: OBJ with OpenSubdiv tag lines;
//! - `ffi` (hidden here): the C ABI, documented in `include/profsubd.h`.

#![deny(missing_docs)]

pub mod catmark;
#[doc(hidden)]
pub mod cli;
pub mod construct;
pub mod control;
pub mod curves;
pub mod error;
pub mod eval;
#[doc(hidden)]
pub mod ffi;
pub(crate) mod fit;
pub mod gbs;
pub mod io;
pub(crate) mod math;
pub mod mesh;
pub mod options;
pub mod refine;
pub mod tessellate;
#[cfg(test)]
pub(crate) mod test_support;
pub mod topology;

pub use construct::curves::CurvesInput;
pub use construct::profile::ProfileInput;
pub use construct::revolve::RevolveInput;
pub use construct::sweep::SweepInput;
pub use construct::{profile, revolve, sweep, Caps, Fitted, Settings};
pub use control::{Control, Progress};
pub use curves::Interpolation;
pub use error::{Error, Result};
pub use eval::{limit_stencils, Evaluator};
pub use fit::{FitOptions, FitReport, MAX_CONDITION as MAX_FIT_CONDITION};
pub use glam::DVec3;
pub use mesh::{Corner, Crease, Mesh, MeshParts};
pub use options::{
    BoundaryInterpolation, CreaseMethod, PartialOptions, SubdivOptions, TriangleSubdivision,
};
pub use refine::refine_uniform;
