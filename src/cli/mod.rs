//! The `profsubd` command-line tool.
//!
//! One clap-derive enum, [`Command`], lists the subcommands; each subcommand's arguments and
//! logic live in their own file (`src/cli/<name>.rs`) with `pub fn run(args: &XArgs) ->
//! Result<i32>`. To add a subcommand: a file, a variant here, and an arm in [`dispatch`].
//! Flags shared by subcommands that take subdivision options are in [`SubdivFlags`].
//!
//! Exit codes: 0 success; 1 error (unreadable or invalid input, bad arguments), with the
//! reason on stderr; subcommands may define more (`check`: 2 for a non-manifold mesh, 3 with
//! `--surface` for a limit surface that folds); 130 when Ctrl-C stopped the work (nothing
//! written; [`progress`]).

pub mod blend;
pub mod check;
pub mod check_surface;
pub mod construct;
pub mod convert;
pub mod curves;
pub mod limit;
pub mod offset;
pub mod profile;
pub mod progress;
pub mod refine;
pub mod revolve;
pub mod shell;
pub mod sweep;
pub mod tessellate;

use std::ffi::OsString;
use std::path::Path;

use clap::{Args, Parser, Subcommand, ValueEnum};

use crate::error::Result;
use crate::io::obj::read_obj_file;
use crate::mesh::Mesh;
use crate::options::{BoundaryInterpolation, CreaseMethod, PartialOptions, TriangleSubdivision};

/// Profile curves to Catmull-Clark control meshes, and tools for OBJ meshes with
/// OpenSubdiv tags.
#[derive(Debug, Parser)]
#[command(name = "profsubd", version, propagate_version = true)]
#[command(
    long_about = "Profile curves to Catmull-Clark control meshes, and tools for \
    OBJ meshes with OpenSubdiv tags (t crease, t corner, t hole, t interpolateboundary, \
    t creasemethod, t smoothtriangles; indices 0-based as in OpenSubdiv's shapes)."
)]
#[command(after_help = "Exit codes: 0 success, 1 error (reason on stderr), \
    2 from `check` for a mesh that loads but is not a manifold, \
    3 from `check --surface` for a limit surface that folds, \
    130 when Ctrl-C stopped the work (nothing written).")]
pub struct Cli {
    /// The subcommand to run.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Report a mesh's topology, tags and options; exit 0 if it is a manifold.
    ///
    /// Prints counts, face sizes and valences (size:count), the boundary, components,
    /// Euler characteristic, non-manifold edges and vertices, inconsistently oriented edges,
    /// isolated vertices, faces that repeat a vertex (with the first few offenders,
    /// 0-based vertex and face indices as in OBJ tags), crease, corner and hole tags, and
    /// the subdivision options in effect with where each comes from, and where OpenSubdiv
    /// 3.5 is not exact or not safe under them (darts, valence-2 vertices, Chaikin, repeated
    /// vertices, PrimvarRefiner::Limit; warnings only). Exit code 0 for a
    /// manifold mesh, 2 for a mesh that loads but is not a manifold (OpenSubdiv accepts
    /// it), 1 for a file that cannot be read or is not a valid mesh (reason on stderr).
    /// With --surface, also samples the limit surface of every face and reports where it
    /// folds (its normal turns through zero and comes back reversed); exit code 3 when it
    /// does.
    Check(check::CheckArgs),
    /// Rewrite an OBJ mesh: exact coordinates, normalized tags, options overridden.
    ///
    /// Reads an OBJ mesh with OpenSubdiv tags and writes it back with every coordinate
    /// exact (shortest decimals that read back to the same double) and its tags
    /// normalized (one crease or corner per line). --boundary, --crease and --triangles
    /// replace the file's interpolateboundary, creasemethod and smoothtriangles tags.
    /// Tags that are ignored (face-varying, hierarchical edits, unknown) are reported on
    /// stderr and not written.
    Convert(convert::ConvertArgs),
    /// Refine a mesh uniformly N times, in OpenSubdiv Far's order.
    ///
    /// Writes the refined mesh: vertices as Far numbers them (children of vertices, then of
    /// faces, then of edges; --faces-first: faces, edges, vertices), faces in Far's order,
    /// the decayed crease and corner sharpness and the holes as tags, and the options used
    /// as tags. Positions equal OpenSubdiv's PrimvarRefiner in double precision.
    Refine(refine::RefineArgs),
    /// Exact limit positions (and derivatives) at the control vertices or at (face, u, v).
    ///
    /// Without --at: one line `x y z` per control vertex, in vertex order. With --at
    /// POINTS.txt (lines `face u v`): one line per point. --derivs appends `dux duy duz dvx
    /// dvy dvz` (at a vertex: with respect to the (u, v) of its first face). Numbers as
    /// %.17g, with the shortest digits that read back exactly. With --domain ptex (the
    /// default) `face` is OpenSubdiv's Ptex face (the face index on a mesh of quads; a face
    /// with N != 4 vertices counts as N faces, one per corner: (0,0) at the corner, (1,1) at
    /// the face centre); with --domain bfr it is the control face with Bfr's tiled
    /// parameterization. A vertex or point without limit surface (isolated vertex, holes,
    /// boundary faces under --boundary none) prints `nan nan nan`; --strict fails instead.
    Limit(limit::LimitArgs),
    /// Offset the limit surface by a thickness (a Bézier crust) at (face, u, v) points.
    ///
    /// O = S - D: the exact limit S minus a bi-quintic crust whose corners are the
    /// thickness times the exact limit normal (mitered at creases and corners), inward
    /// (against S_u x S_v) unless --outward. --at POINTS.txt as `limit`; one line `x y z`
    /// per point, --derivs appends the offset's derivatives. --level L builds the crust on
    /// the surface refined L times; --tolerance T chooses the lowest level whose measured
    /// thickness is within T of c. A thickness beyond the radius of curvature folds the
    /// offset: an error unless --accept-folds.
    Offset(offset::OffsetArgs),
    /// Build a hollow solid: the surface, its offset by a thickness, and a rim.
    ///
    /// Writes one closed, consistently oriented quad mesh with tags: the outer wall (the
    /// input refined to the crust's level, same limit surface), the inner wall (same
    /// topology, faces reversed) and for open surfaces a rim of quads creased infinitely
    /// sharp where it meets the walls, fitted so that its limit passes through the outer
    /// limit and the offset (see `offset`) at every vertex. --stl also writes the limit
    /// surface tessellated. --targets writes the data points.
    Shell(shell::ShellArgs),
    /// Build an interpolating Catmull-Clark mesh from profile curves (Hui & Lai).
    ///
    /// Reads four planar silhouettes from JSON (c1: +x, c2: +y, c3: -x, c4: -y; c3/c4
    /// default to mirrors), blends their sweeps, samples data points on rings x meridians
    /// (rings through every corner), closes poles with quad caps (smooth) or a corner tip
    /// (pointed), creases rings at corners, and fits the control points so that the exact
    /// limit surface passes through every data point. Without INPUT: a built-in bottle.
    /// The fit uses, and the OBJ records, the boundary rule and crease method (JSON
    /// `boundary`, `crease_method`; --boundary, --crease override them).
    Profile(profile::ProfileArgs),
    /// Build a surface of revolution: a profile (r, z) turned about the z axis.
    ///
    /// Reads the profile from JSON (bottom to top, r >= 0; angle_deg, samples_profile,
    /// samples_around, interpolation, sharp_angle_deg, corners, crease_sharpness, boundary,
    /// crease_method, caps), closes ends on the axis with quad
    /// caps (smooth) or a corner tip (pointed), creases rings at profile corners, and fits
    /// the control points so that the exact limit surface passes through every data point.
    /// "caps": "flat" closes the solid with flat caps (ends off the axis; a partial turn's
    /// start and end meridian planes).
    Revolve(revolve::RevolveArgs),
    /// Sweep a planar profile along a 3-D trajectory with a fixed, Frenet or
    /// rotation-minimizing frame.
    ///
    /// Reads profile and trajectory from JSON (closed_profile, closed_trajectory, frame,
    /// samples_profile, samples_trajectory, scale, profile_end, interpolation,
    /// sharp_angle_deg, corners, crease_sharpness, boundary, crease_method), creases profile
    /// corners along the sweep and trajectory corners
    /// across it (mitered), and fits the control points so that the exact limit surface
    /// passes through every data point.
    Sweep(sweep::SweepArgs),
    /// Build a patch through unorganized 3-D sketch curves (Qin & Wright).
    ///
    /// Reads 3 or 4 boundary curves (in order around the patch; corners may stay open) and
    /// any interior curves from JSON (tau, samples, projection), projects them on a plane,
    /// maps the boundary to the unit square (Coons map) and the interior curves with it,
    /// blends the curve points on a grid by the paper's attraction weights (1/d)^tau, and
    /// fits the control points so that the exact limit surface passes through every point.
    Curves(curves::CurvesArgs),
    /// Blend 3 to 8 pipes at a junction with generalized B-spline (GBS) subdivision, as a
    /// fitted Catmull-Clark mesh.
    ///
    /// Reads the pipes (end centre, axis away from the junction, radius, length), the GBS
    /// order (even), tension, shape parameters alpha (centre) and k_alpha (valleys) from
    /// JSON; each pipe is an exact cylinder in the GBS limit, and the Catmull-Clark limit
    /// passes through the GBS limit at the vertices of GBS level --gbs-level.
    Blend(blend::BlendArgs),
    /// Tessellate the limit surface: triangles or quads on it, watertight, as STL, OFF, PLY
    /// or OBJ (format from the extension or --format).
    ///
    /// Uniform (--rate N: N x N per quad, N-gons through their sub-faces) or adaptive
    /// (--tolerance T: no triangle farther than T from the surface). Points on shared edges
    /// are computed once, so the result is closed wherever the control mesh is; normals
    /// come from the exact derivatives, split along infinitely sharp creases (OBJ keeps the
    /// split, PLY averages it, STL has facet normals). Holes and faces without limit
    /// surface are left out. --up y writes (x, y, z) as (x, z, -y).
    Tessellate(tessellate::TessellateArgs),
}

/// Subdivision option flags. Given on the command line they override the tags of the mesh
/// file, which override the defaults (edge-and-corner, uniform, catmark).
#[derive(Debug, Clone, Default, Args)]
pub struct SubdivFlags {
    /// Boundary interpolation; overrides the file's `interpolateboundary` tag
    /// [default without either: edge-and-corner].
    #[arg(long, value_enum, value_name = "RULE")]
    pub boundary: Option<BoundaryArg>,
    /// Crease sharpness decay; overrides the file's `creasemethod` tag
    /// [default without either: uniform].
    #[arg(long, value_enum, value_name = "METHOD")]
    pub crease: Option<CreaseArg>,
    /// Rule for triangles; overrides the file's `smoothtriangles` tag
    /// [default without either: catmark].
    #[arg(long, value_enum, value_name = "RULE")]
    pub triangles: Option<TrianglesArg>,
}

impl SubdivFlags {
    /// The options given on the command line; unset where no flag was given.
    pub fn partial(&self) -> PartialOptions {
        PartialOptions {
            boundary: self.boundary.map(|b| match b {
                BoundaryArg::None => BoundaryInterpolation::None,
                BoundaryArg::EdgeOnly => BoundaryInterpolation::EdgeOnly,
                BoundaryArg::EdgeAndCorner => BoundaryInterpolation::EdgeAndCorner,
            }),
            crease_method: self.crease.map(|c| match c {
                CreaseArg::Uniform => CreaseMethod::Uniform,
                CreaseArg::Chaikin => CreaseMethod::Chaikin,
            }),
            triangles: self.triangles.map(|t| match t {
                TrianglesArg::Catmark => TriangleSubdivision::Catmark,
                TrianglesArg::Smooth => TriangleSubdivision::Smooth,
            }),
        }
    }
}

/// `--threads`, for the commands that build an evaluator or refine.
#[derive(Debug, Clone, Default, Args)]
pub struct ThreadsFlag {
    /// Threads for building the evaluator and evaluating batches of points, or for
    /// refining, 0 for all cores; results are the same for any count.
    #[arg(long, value_name = "N", default_value_t = 0)]
    pub threads: usize,
}

/// `--boundary` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum BoundaryArg {
    /// Boundary faces have no limit surface.
    None,
    /// Boundary edges are infinitely sharp.
    EdgeOnly,
    /// Boundary edges are sharp and corners with one face too.
    EdgeAndCorner,
}

/// `--crease` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum CreaseArg {
    /// Sharpness decreases by 1 per level.
    Uniform,
    /// Chaikin's rule averages neighbouring sharpness.
    Chaikin,
}

/// `--triangles` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TrianglesArg {
    /// Catmull-Clark weights on triangles too.
    Catmark,
    /// Smoother weights for triangles.
    Smooth,
}

/// Run the CLI with the process arguments; returns the exit code.
pub fn main() -> i32 {
    run_from(std::env::args_os())
}

/// Run the CLI with the given arguments (the first is the program name); returns the exit
/// code. Errors are printed to stderr as `profsubd: error: ...`.
pub fn run_from<I, T>(args: I) -> i32
where
    I: IntoIterator<Item = T>,
    T: Into<OsString> + Clone,
{
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        Err(e) => {
            // --help and --version are "errors" to clap that go to stdout with code 0.
            let _ = e.print();
            return if e.use_stderr() { 1 } else { 0 };
        }
    };
    progress::install_interrupt_handler();
    match dispatch(&cli.command) {
        Ok(code) => code,
        Err(e @ crate::Error::Cancelled(_)) => {
            eprintln!("profsubd: {e}");
            progress::EXIT_INTERRUPTED
        }
        Err(e) => {
            eprintln!("profsubd: error: {e}");
            1
        }
    }
}

/// Run one subcommand.
pub fn dispatch(command: &Command) -> Result<i32> {
    match command {
        Command::Check(args) => check::run(args),
        Command::Convert(args) => convert::run(args),
        Command::Refine(args) => refine::run(args),
        Command::Limit(args) => limit::run(args),
        Command::Offset(args) => offset::run(args),
        Command::Shell(args) => shell::run(args),
        Command::Profile(args) => profile::run(args),
        Command::Revolve(args) => revolve::run(args),
        Command::Blend(args) => blend::run(args),
        Command::Sweep(args) => sweep::run(args),
        Command::Curves(args) => curves::run(args),
        Command::Tessellate(args) => tessellate::run(args),
    }
}

/// Read an OBJ mesh, printing the reader's warnings to stderr, one per line.
pub(crate) fn read_mesh(path: &Path) -> Result<Mesh> {
    let read = read_obj_file(path)?;
    for w in &read.warnings {
        eprintln!("profsubd: warning: {w}");
    }
    Ok(read.mesh)
}
