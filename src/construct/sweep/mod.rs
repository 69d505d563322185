//! Revolution and general sweeps: a planar profile moved along a trajectory (issue 5).
//!
//! - [`frames`]: fixed, Frenet and rotation-minimizing frames along a sampled trajectory;
//! - [`profile`]: the swept profile, its samples, scaling and morphing;
//! - [`trajectory`]: the validated trajectory, its samples and their frames;
//! - [`sweep`](mod@sweep): the sweep input (JSON) and its grid of data points;
//! - [`revolve`](mod@revolve): surfaces of revolution (JSON input, poles, grid of data points);
//! - [`wedge`]: partial revolutions: sector caps at poles and flat ends, flat meridian caps;
//! - [`mesh`]: quad mesh parts of a grid (shared caps and crease tagging);
//! - [`build`]: the fitted constructions [`revolve`](build::revolve) and [`sweep`](build::sweep).

pub mod build;
pub mod frames;
pub mod mesh;
pub mod profile;
pub mod revolve;
#[allow(clippy::module_inception)]
pub mod sweep;
pub mod trajectory;
pub mod wedge;

pub use build::{revolve, sweep, SweptSurface};
