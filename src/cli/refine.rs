//! `profsubd refine MESH.obj --level N -o OUT.obj`: uniform Catmull-Clark refinement in
//! OpenSubdiv Far's vertex and face order, written with the decayed crease and corner tags;
//! `--threads N` (default all cores) does not change the output.

use std::path::PathBuf;

use clap::Args;

use super::{read_mesh, SubdivFlags, ThreadsFlag};
use crate::error::Result;
use crate::io::obj::write_obj_file;
use crate::refine::{refine_uniform_with, VertexOrder};

/// Arguments of `refine`.
#[derive(Debug, Args)]
pub struct RefineArgs {
    /// The OBJ mesh to refine.
    #[arg(value_name = "MESH.obj")]
    pub input: PathBuf,
    /// Number of refinement levels (0 to 8).
    #[arg(short, long, value_name = "N")]
    pub level: u32,
    /// The OBJ file to write.
    #[arg(short, long, value_name = "OUT.obj")]
    pub output: PathBuf,
    /// Number child vertices of faces first, then of edges, then of vertices (Far's
    /// `orderVerticesFromFacesFirst`, Vtr's `faceVertsFirst`); default: vertices, faces, edges.
    #[arg(long, visible_alias = "face-verts-first")]
    pub faces_first: bool,
    /// Subdivision options.
    #[command(flatten)]
    pub options: SubdivFlags,
    /// Threads (0, the default: all cores).
    #[command(flatten)]
    pub threads: ThreadsFlag,
}

/// Run `refine`; returns exit code 0 on success.
pub fn run(args: &RefineArgs) -> Result<i32> {
    let mesh = read_mesh(&args.input)?;
    let options = args.options.partial().over(mesh.options()).resolve();
    let order = if args.faces_first {
        VertexOrder::FacesFirst
    } else {
        VertexOrder::VerticesFirst
    };
    let control = super::progress::control("refining").with_threads(args.threads.threads);
    let refined = refine_uniform_with(&mesh, &options, args.level, order, &control)?;
    super::progress::check_interrupted()?;
    write_obj_file(&refined, &args.output)?;
    println!(
        "wrote {} (level {}: {} vertices, {} faces, {} creases, {} corners, {} holes)",
        args.output.display(),
        args.level,
        refined.num_vertices(),
        refined.num_faces(),
        refined.creases().len(),
        refined.corners().len(),
        refined.holes().len()
    );
    Ok(0)
}
