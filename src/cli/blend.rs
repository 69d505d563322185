//! `profsubd blend INPUT.json -o OUT.obj [--gbs-level L] [--targets TARGETS.txt]`: N pipes
//! joined by a generalized B-spline blend, as a fitted Catmull–Clark mesh (JSON keys and
//! defaults: [`crate::construct::blend::BlendInput`]).

use std::path::PathBuf;

use clap::Args;

use super::construct::{write_fitted, FitFlags, SurfaceOutput};
use crate::construct::blend::{build, control_mesh, BlendInput};
use crate::construct::settings::read_json;
use crate::error::Result;
use crate::mesh::Mesh;
use crate::topology::Level;

/// Arguments of `blend`.
#[derive(Debug, Args)]
pub struct BlendArgs {
    /// JSON input: `{"pipes": [{"end": [x,y,z], "axis": [x,y,z], "radius": r, "length": l},
    /// ...], "order": 4, "alpha": 0.5, "k_alpha": 0.5, ...}` (see the README).
    #[arg(value_name = "INPUT.json")]
    pub input: PathBuf,
    /// The GBS level whose vertices the Catmull–Clark limit interpolates (1..=4); overrides
    /// the JSON's `gbs_level` [default without either: 1].
    #[arg(long, value_name = "L")]
    pub gbs_level: Option<u32>,
    /// Where to write.
    #[command(flatten)]
    pub out: SurfaceOutput,
    /// Subdivision options and crease sharpness.
    #[command(flatten)]
    pub fit: FitFlags,
}

/// Run `blend`; returns exit code 0 on success. Nothing is written on error.
pub fn run(args: &BlendArgs) -> Result<i32> {
    let (mut input, mut settings) = read_json::<BlendInput>(&args.input)?;
    input.gbs_level = args.gbs_level.unwrap_or(input.gbs_level);
    args.fit.apply(&mut settings);
    let fitted = build(&input, &settings)?;
    let report = fitted.surface_report()?;
    let gbs = control_mesh(&input)?;
    write_fitted(&fitted, &args.out)?;
    println!(
        "valences: GBS control mesh {}; Catmull-Clark result {} ({} pipes)",
        valences(&gbs.mesh),
        valences(&fitted.mesh),
        input.pipes.len()
    );
    println!(
        "distance between the GBS and Catmull-Clark limit surfaces: max {:.3e}, mean {:.3e} (x bounding-box diagonal, normal distance on a 4 x 4 lattice per face)",
        report.max_design_distance, report.mean_design_distance
    );
    Ok(0)
}

/// "valence x count, ..." of the vertices of `mesh`, ascending.
fn valences(mesh: &Mesh) -> String {
    let level = Level::from_mesh(mesh);
    let mut counts = std::collections::BTreeMap::new();
    for v in 0..level.num_vertices() {
        *counts.entry(level.valence(v)).or_insert(0usize) += 1;
    }
    counts
        .iter()
        .map(|(valence, count)| format!("{valence} x {count}"))
        .collect::<Vec<_>>()
        .join(", ")
}
