//! `profsubd convert IN.obj -o OUT.obj`: read, optionally override the option tags, write.

use std::path::PathBuf;

use clap::Args;

use super::{read_mesh, SubdivFlags};
use crate::error::Result;
use crate::io::obj::write_obj_file;
use crate::mesh::Mesh;

/// Arguments of `convert`.
#[derive(Debug, Args)]
pub struct ConvertArgs {
    /// The OBJ file to read.
    #[arg(value_name = "IN.obj")]
    pub input: PathBuf,
    /// The OBJ file to write.
    #[arg(short, long, value_name = "OUT.obj")]
    pub output: PathBuf,
    /// Tags to write instead of the file's.
    #[command(flatten)]
    pub options: SubdivFlags,
}

/// Run `convert`; returns exit code 0 on success.
pub fn run(args: &ConvertArgs) -> Result<i32> {
    let mut parts = read_mesh(&args.input)?.into_parts();
    parts.options = args.options.partial().over(parts.options);
    let mesh = Mesh::from_parts(parts)?;
    write_obj_file(&mesh, &args.output)?;
    println!(
        "wrote {} ({} vertices, {} faces, {} creases, {} corners, {} holes)",
        args.output.display(),
        mesh.num_vertices(),
        mesh.num_faces(),
        mesh.creases().len(),
        mesh.corners().len(),
        mesh.holes().len()
    );
    Ok(0)
}
