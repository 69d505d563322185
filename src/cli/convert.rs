//! `profsubd convert IN.obj -o OUT.obj`: read, optionally override the option tags, write;
//! `.usda` on either side reads or writes USD ([`crate::io::usda`]).

use std::path::PathBuf;

use clap::Args;

use super::tessellate::UpArg;
use super::{read_mesh, SubdivFlags};
use crate::error::Result;
use crate::io::obj::write_obj_file;
use crate::io::usda::{read_usda_file, write_usda_file};
use crate::mesh::Mesh;

/// Arguments of `convert`.
#[derive(Debug, Args)]
pub struct ConvertArgs {
    /// The OBJ (or .usda) file to read.
    #[arg(value_name = "IN.obj")]
    pub input: PathBuf,
    /// The OBJ (or .usda) file to write.
    #[arg(short, long, value_name = "OUT.obj")]
    pub output: PathBuf,
    /// Tags to write instead of the file's.
    #[command(flatten)]
    pub options: SubdivFlags,
    /// Up axis of a written .usda stage: z keeps the coordinates, y writes (x, y, z) as
    /// (x, z, -y) (reading a Y-up stage turns it back).
    #[arg(long, value_enum, default_value_t = UpArg::Z)]
    pub up: UpArg,
}

fn is_usda(path: &std::path::Path) -> bool {
    path.extension()
        .is_some_and(|e| e.eq_ignore_ascii_case("usda"))
}

/// Run `convert`; returns exit code 0 on success.
pub fn run(args: &ConvertArgs) -> Result<i32> {
    let read = if is_usda(&args.input) {
        read_usda_file(&args.input)?
    } else {
        read_mesh(&args.input)?
    };
    let mut parts = read.into_parts();
    parts.options = args.options.partial().over(parts.options);
    let mesh = Mesh::from_parts(parts)?;
    if is_usda(&args.output) {
        for w in write_usda_file(&mesh, &args.output, args.up.into())? {
            eprintln!("profsubd: warning: {w}");
        }
    } else {
        write_obj_file(&mesh, &args.output)?;
    }
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
