//! `profsubd tessellate MESH.obj -o OUT [--rate N | --tolerance T] [--quads] [--up z|y]`:
//! the limit surface as triangles or quads (see [`crate::tessellate`]), written as STL, OFF,
//! PLY or OBJ ([`crate::io::surface`]).

use std::path::PathBuf;

use clap::{Args, ValueEnum};

use super::{read_mesh, SubdivFlags, ThreadsFlag};
use crate::error::Result;
use crate::eval::Evaluator;
use crate::io::surface::{write_surface_file, SurfaceFormat};
use crate::io::up_axis::UpAxis;
use crate::tessellate::{tessellate, Rate, TessellateOptions};

/// Arguments of `tessellate`.
#[derive(Debug, Args)]
pub struct TessellateArgs {
    /// The control mesh (OBJ with OpenSubdiv tags).
    #[arg(value_name = "MESH.obj")]
    pub input: PathBuf,
    /// The file to write; its extension (.stl, .off, .ply, .obj) picks the format unless
    /// --format is given.
    #[arg(short, long, value_name = "OUT")]
    pub output: PathBuf,
    /// Uniform rate: N x N cells per quad, ceil(N/2) per sub-face of an N-gon
    /// [default without --tolerance: 4].
    #[arg(long, value_name = "N", conflicts_with = "tolerance")]
    pub rate: Option<u32>,
    /// Adaptive rates: no triangle farther than T (model units) from the limit surface.
    #[arg(long, value_name = "T")]
    pub tolerance: Option<f64>,
    /// Highest rate of a face in adaptive mode.
    #[arg(long, value_name = "N", default_value_t = 64)]
    pub max_rate: u32,
    /// Keep grid cells as quads (transitions between rates stay triangles; STL splits them).
    #[arg(long)]
    pub quads: bool,
    /// Up axis of the written file: z keeps the coordinates, y writes (x, y, z) as (x, z, -y).
    #[arg(long, value_enum, default_value_t = UpArg::Z)]
    pub up: UpArg,
    /// Output format instead of the extension's.
    #[arg(long, value_enum)]
    pub format: Option<FormatArg>,
    /// Subdivision options.
    #[command(flatten)]
    pub options: SubdivFlags,
    /// Threads.
    #[command(flatten)]
    pub threads: ThreadsFlag,
}

/// `--up` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum UpArg {
    /// Z up (profsubd's axes).
    Z,
    /// Y up.
    Y,
}

impl From<UpArg> for UpAxis {
    fn from(a: UpArg) -> UpAxis {
        match a {
            UpArg::Z => UpAxis::Z,
            UpArg::Y => UpAxis::Y,
        }
    }
}

/// `--format` values.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum FormatArg {
    /// Binary STL.
    Stl,
    /// ASCII STL.
    StlAscii,
    /// OFF.
    Off,
    /// Binary PLY with normals.
    Ply,
    /// OBJ with normals.
    Obj,
}

/// Run `tessellate`; returns exit code 0 on success.
pub fn run(args: &TessellateArgs) -> Result<i32> {
    let format = match args.format {
        Some(FormatArg::Stl) => SurfaceFormat::Stl,
        Some(FormatArg::StlAscii) => SurfaceFormat::StlAscii,
        Some(FormatArg::Off) => SurfaceFormat::Off,
        Some(FormatArg::Ply) => SurfaceFormat::Ply,
        Some(FormatArg::Obj) => SurfaceFormat::Obj,
        None => SurfaceFormat::from_path(&args.output)?,
    };
    let mesh = read_mesh(&args.input)?;
    let options = args.options.partial().over(mesh.options()).resolve();
    let control = super::progress::control("building the evaluator");
    let ev = Evaluator::build_on(&mesh, &options, args.threads.threads, &control)?;
    let rate = match (args.tolerance, args.rate) {
        (Some(t), _) => Rate::Tolerance(t),
        (None, n) => Rate::Uniform(n.unwrap_or(4)),
    };
    let t = tessellate(
        &ev,
        &TessellateOptions {
            rate,
            quads: args.quads,
            max_rate: args.max_rate,
        },
    )?;
    if !t.unmet.is_empty() {
        eprintln!(
            "profsubd: warning: {} faces reach --max-rate {} and still miss the tolerance \
             (first: parametric face {}); raise --max-rate",
            t.unmet.len(),
            args.max_rate,
            t.unmet[0]
        );
    }
    super::progress::check_interrupted()?;
    write_surface_file(&t, &args.output, format, args.up.into())?;
    let r = t.edge_report();
    println!(
        "wrote {} ({} vertices, {} polygons, {} boundary edges, Euler characteristic {}{})",
        args.output.display(),
        t.num_vertices(),
        t.num_faces(),
        r.boundary_edges,
        r.euler_characteristic(),
        if r.is_closed_oriented_manifold() {
            ", closed"
        } else {
            ""
        }
    );
    Ok(0)
}
