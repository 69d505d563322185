//! `profsubd check MESH.obj`: counts, valences, boundary, non-manifold findings, tags, and
//! where OpenSubdiv 3.5 is not exact or not safe (warnings).

use std::collections::BTreeMap;
use std::fmt::Write;
use std::path::PathBuf;

use clap::Args;

use super::{check_surface, read_mesh, SubdivFlags};
use crate::error::Result;
use crate::eval::folds::FoldSettings;
use crate::mesh::{Mesh, MeshReport, SHARPNESS_INFINITE};
use crate::options::{BoundaryInterpolation, CreaseMethod, TriangleSubdivision};

/// How many offending items a line lists before it says "...".
const LISTED: usize = 8;

/// Arguments of `check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// The OBJ file to check.
    #[arg(value_name = "MESH.obj")]
    pub mesh: PathBuf,
    /// Print the report as one JSON object (full lists, snake_case keys) instead of text.
    #[arg(long)]
    pub json: bool,
    /// Options to report as in effect (they override the file's tags).
    #[command(flatten)]
    pub options: SubdivFlags,
    // --- surface (folds) ---
    /// Also sample the limit surface and report its folds (exit code 3 if it folds).
    #[arg(long)]
    pub surface: bool,
    /// With --surface: samples along each edge of a parametric face's lattice (before
    /// adaptive refinement).
    #[arg(long, value_name = "N", default_value_t = 9, requires = "surface")]
    pub samples: usize,
    /// With --surface: how many times a lattice cell may be halved (near extraordinary or
    /// non-smooth corners, and where the normal turns fast).
    #[arg(long, value_name = "D", default_value_t = 4, requires = "surface")]
    pub adaptive_depth: usize,
    // --- end surface ---
}

/// Run `check`: print the report; exit code 0 for a manifold mesh, 2 for a mesh that loads
/// but is not a manifold (an unreadable or invalid file is an error, exit code 1); with
/// `--surface`, [`check_surface::EXIT_FOLDED`] (3) when the limit surface folds, whether
/// or not the mesh is a manifold.
pub fn run(args: &CheckArgs) -> Result<i32> {
    let mesh = read_mesh(&args.mesh)?;
    let report = mesh.check();
    // --- surface (folds) ---
    let surface = if args.surface {
        let settings = FoldSettings {
            samples_per_edge: args.samples,
            adaptive_depth: args.adaptive_depth,
            ..Default::default()
        };
        let options = args.options.partial().over(mesh.options()).resolve();
        Some((check_surface::check(&mesh, &options, &settings)?, settings))
    } else {
        None
    };
    // --- end surface ---
    if args.json {
        let mut value = json_report(&args.mesh, &mesh, &report, &args.options);
        if let (Some(obj), Some((folds, settings))) = (value.as_object_mut(), &surface) {
            obj.insert(
                "surface".to_string(),
                check_surface::json_folds(folds, settings),
            );
        }
        println!("{value}");
    } else {
        print!(
            "{}",
            format_report(&args.mesh, &mesh, &report, &args.options)
        );
        if let Some((folds, settings)) = &surface {
            print!("{}", check_surface::format_folds(folds, settings));
        }
    }
    if surface.is_some_and(|(folds, _)| !folds.is_fold_free()) {
        return Ok(check_surface::EXIT_FOLDED);
    }
    Ok(if report.is_manifold() { 0 } else { 2 })
}

/// The text `check` prints: one `name: value` line per finding.
pub fn format_report(
    path: &std::path::Path,
    mesh: &Mesh,
    r: &MeshReport,
    flags: &SubdivFlags,
) -> String {
    let mut out = String::new();
    let mut line = |name: &str, value: String| {
        let _ = writeln!(out, "{name}: {value}");
    };
    line("mesh", path.display().to_string());
    line("vertices", r.num_vertices.to_string());
    line("edges", r.num_edges.to_string());
    line(
        "faces",
        format!("{} (sizes {})", r.num_faces, histogram(&r.face_sizes)),
    );
    line("valences", histogram(&r.valences));
    line(
        "boundary",
        if r.is_closed() {
            "closed".to_string()
        } else {
            format!(
                "{} edges in {} loop{}{}",
                r.boundary_edges.len(),
                r.num_boundary_loops,
                if r.num_boundary_loops == 1 { "" } else { "s" },
                listed(r.boundary_edges.iter().map(|[a, b]| format!("{a}-{b}")))
            )
        },
    );
    line("components", r.num_components.to_string());
    line("euler characteristic", r.euler_characteristic.to_string());
    let edges = |list: &[[u32; 2]]| {
        count_and_list(list.len(), list.iter().map(|[a, b]| format!("{a}-{b}")))
    };
    let indices = |list: &[u32]| count_and_list(list.len(), list.iter().map(u32::to_string));
    line("non-manifold edges", edges(&r.non_manifold_edges));
    line(
        "inconsistently oriented edges",
        edges(&r.inconsistent_edges),
    );
    line("non-manifold vertices", indices(&r.non_manifold_vertices));
    line("isolated vertices", indices(&r.isolated_vertices));
    line(
        "faces with repeated vertices",
        indices(&r.faces_with_repeated_vertices),
    );
    line(
        "creases",
        sharpness_summary(mesh.creases().iter().map(|c| c.sharpness)),
    );
    line(
        "corners",
        sharpness_summary(mesh.corners().iter().map(|c| c.sharpness)),
    );
    line("holes", indices(mesh.holes()));
    let settings = settings(mesh, flags);
    for (name, value, from) in settings {
        line(name, format!("{value} ({from})"));
    }
    out.push_str(&hazards::lines(mesh, flags));
    let mut line = |name: &str, value: String| {
        let _ = writeln!(out, "{name}: {value}");
    };
    let verdict = if r.is_manifold() {
        "manifold mesh".to_string()
    } else {
        let problems: Vec<String> = [
            (r.non_manifold_edges.len(), "non-manifold edges"),
            (r.inconsistent_edges.len(), "inconsistently oriented edges"),
            (r.non_manifold_vertices.len(), "non-manifold vertices"),
            (r.isolated_vertices.len(), "isolated vertices"),
            (
                r.faces_with_repeated_vertices.len(),
                "faces with repeated vertices",
            ),
        ]
        .iter()
        .filter(|(n, _)| *n > 0)
        .map(|(n, what)| format!("{n} {what}"))
        .collect();
        format!("not a manifold ({})", problems.join(", "))
    };
    line("result", verdict);
    out
}

/// The subdivision options in effect: (name, value, where it comes from) for each.
fn settings(mesh: &Mesh, flags: &SubdivFlags) -> [(&'static str, &'static str, &'static str); 3] {
    let file = mesh.options();
    let given = flags.partial();
    let resolved = given.over(file).resolve();
    let source = |flag: bool, tag: bool| match (flag, tag) {
        (true, _) => "command line",
        (false, true) => "file tag",
        _ => "default",
    };
    [
        (
            "boundary interpolation",
            match resolved.boundary {
                BoundaryInterpolation::None => "none",
                BoundaryInterpolation::EdgeOnly => "edge-only",
                BoundaryInterpolation::EdgeAndCorner => "edge-and-corner",
            },
            source(given.boundary.is_some(), file.boundary.is_some()),
        ),
        (
            "crease method",
            match resolved.crease_method {
                CreaseMethod::Uniform => "uniform",
                CreaseMethod::Chaikin => "chaikin",
            },
            source(given.crease_method.is_some(), file.crease_method.is_some()),
        ),
        (
            "triangles",
            match resolved.triangles {
                TriangleSubdivision::Catmark => "catmark",
                TriangleSubdivision::Smooth => "smooth",
            },
            source(given.triangles.is_some(), file.triangles.is_some()),
        ),
    ]
}

/// The `--json` output: the whole report, the verdicts, the tags and the options.
pub fn json_report(
    path: &std::path::Path,
    mesh: &Mesh,
    r: &MeshReport,
    flags: &SubdivFlags,
) -> serde_json::Value {
    let mut value = serde_json::to_value(r).unwrap_or_default();
    let options: serde_json::Map<String, serde_json::Value> = settings(mesh, flags)
        .iter()
        .map(|(name, value, from)| {
            (
                name.replace(' ', "_"),
                serde_json::json!({ "value": value, "source": from }),
            )
        })
        .collect();
    let extra = serde_json::json!({
        "mesh": path.display().to_string(),
        "is_manifold": r.is_manifold(),
        "is_closed": r.is_closed(),
        "is_consistently_oriented": r.is_consistently_oriented(),
        "creases": mesh.creases().iter().map(|c| serde_json::json!({
            "vertices": c.vertices, "sharpness": c.sharpness })).collect::<Vec<_>>(),
        "corners": mesh.corners().iter().map(|c| serde_json::json!({
            "vertex": c.vertex, "sharpness": c.sharpness })).collect::<Vec<_>>(),
        "holes": mesh.holes(),
        "options": options,
        "osd_hazards": hazards::json(mesh, flags),
    });
    if let (Some(obj), serde_json::Value::Object(more)) = (value.as_object_mut(), extra) {
        obj.extend(more);
    }
    value
}

/// OpenSubdiv 3.5 hazards ([`crate::mesh::osd_hazards()`]): warnings, no effect on the exit code.
mod hazards {
    use super::{count_and_list, SubdivFlags};
    use crate::mesh::{osd_hazards, Hazard, Mesh};

    fn of(mesh: &Mesh, flags: &SubdivFlags) -> Vec<Hazard> {
        osd_hazards(mesh, &flags.partial().over(mesh.options()).resolve())
    }

    /// `opensubdiv 3.5 hazards: n` and one `hazard KIND: ...` line per kind that occurs.
    pub(super) fn lines(mesh: &Mesh, flags: &SubdivFlags) -> String {
        let found = of(mesh, flags);
        let mut out = format!("opensubdiv 3.5 hazards: {}\n", found.len());
        for h in found {
            let list = |l: &[u32]| count_and_list(l.len(), l.iter().map(u32::to_string));
            let faces = if h.faces.is_empty() {
                String::new()
            } else {
                format!(", faces {}", list(&h.faces))
            };
            out.push_str(&format!(
                "hazard {}: vertices {}{faces} ({}): {}\n",
                h.kind.name(),
                list(&h.vertices),
                h.kind.affects().join(", "),
                h.kind.figure()
            ));
        }
        out
    }

    /// The `osd_hazards` array of `--json`: kind, vertices, faces, affects, figure.
    pub(super) fn json(mesh: &Mesh, flags: &SubdivFlags) -> serde_json::Value {
        of(mesh, flags)
            .iter()
            .map(|h| {
                serde_json::json!({
                    "kind": h.kind, "vertices": h.vertices, "faces": h.faces,
                    "affects": h.kind.affects(), "figure": h.kind.figure(),
                })
            })
            .collect()
    }
}

/// `k:n k:n ...` for a histogram.
fn histogram(h: &BTreeMap<usize, usize>) -> String {
    let parts: Vec<String> = h.iter().map(|(k, n)| format!("{k}:{n}")).collect();
    parts.join(" ")
}

/// ` [a b c ...]`: the first [`LISTED`] items, or nothing for an empty list.
fn listed(items: impl ExactSizeIterator<Item = String>) -> String {
    let n = items.len();
    if n == 0 {
        return String::new();
    }
    let shown: Vec<String> = items.take(LISTED).collect();
    let more = if n > LISTED { " ..." } else { "" };
    format!(" [{}{more}]", shown.join(" "))
}

/// `n [a b c ...]`.
fn count_and_list(n: usize, items: impl ExactSizeIterator<Item = String>) -> String {
    format!("{n}{}", listed(items))
}

/// `n (sharpness lo to hi, k infinitely sharp)`, or `0`.
fn sharpness_summary(values: impl Iterator<Item = f32>) -> String {
    let values: Vec<f32> = values.collect();
    if values.is_empty() {
        return "0".to_string();
    }
    let lo = values.iter().copied().fold(f32::INFINITY, f32::min);
    let hi = values.iter().copied().fold(f32::NEG_INFINITY, f32::max);
    let infinite = values.iter().filter(|&&s| s >= SHARPNESS_INFINITE).count();
    format!(
        "{} (sharpness {lo} to {hi}, {infinite} infinitely sharp)",
        values.len()
    )
}
