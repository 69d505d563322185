//! profsubd's files read by independent programs: Pixar's USD library (`usd-core`), trimesh
//! and OpenSCAD, driven by `tests/external/check_readers.py` (needs `python3` with
//! `usd-core` and `trimesh`, and `openscad`; `scripts/test_all.sh` installs them).
//!
//! - `.usda` written by `profsubd convert`: USD opens it, `UsdGeom.Mesh.ValidateTopology`
//!   passes, every array (faces, points, creases expanded from chains, corners, holes,
//!   boundary and triangle rules, extent, up axis, Chaikin custom data) equals the mesh's;
//!   the stage exported by USD itself reads back into the same mesh, and read → write → read
//!   is identical.
//! - Tessellations written by `profsubd tessellate` as OFF, PLY, binary and ASCII STL:
//!   trimesh reads the same counts and coordinates (binary STL: the `f32` of each), finds the
//!   closed ones watertight with the control mesh's Euler number; OpenSCAD imports the OFF
//!   and the STL and exports a solid of the same volume.

#[path = "support/cli.rs"]
mod cli;
#[path = "support/osd_shapes.rs"]
#[allow(dead_code)] // the shapes index is not needed here
mod osd_shapes;

use std::path::Path;
use std::process::Command;

use cli::example_file;
use glam::DVec3;
use profsubd::eval::Evaluator;
use profsubd::io::obj::read_obj_file;
use profsubd::io::up_axis::UpAxis;
use profsubd::io::usda::{read_usda_file, to_usda};
use profsubd::options::{BoundaryInterpolation, CreaseMethod, TriangleSubdivision};
use profsubd::tessellate::{tessellate, Rate, TessellateOptions};
use serde_json::{json, Value};

/// Run `profsubd` with `args`, which must succeed.
fn profsubd(args: &[&str]) {
    let out = cli::profsubd(args);
    assert!(
        out.status.success(),
        "profsubd {args:?}: {}",
        cli::stderr(&out)
    );
}

fn s(p: &Path) -> &str {
    p.to_str().unwrap()
}

/// Expected USD arrays of `input` converted with the given extra flags and up axis.
fn usd_case(dir: &Path, input: &Path, extra: &[&str], up: UpAxis) -> Value {
    let name = input.file_stem().unwrap().to_string_lossy();
    let out = dir.join(format!("{name}.usda"));
    let up_flag = if up == UpAxis::Y { "y" } else { "z" };
    let mut args = vec!["convert", s(input), "-o", s(&out), "--up", up_flag];
    args.extend_from_slice(extra);
    profsubd(&args);
    let mut parts = read_obj_file(input).unwrap().mesh.into_parts();
    if extra.contains(&"chaikin") {
        parts.options.crease_method = Some(CreaseMethod::Chaikin);
    }
    let mesh = profsubd::Mesh::from_parts(parts).unwrap();
    let o = mesh.options().resolve();
    json!({
        "usda": s(&out),
        "usda_exported": s(&dir.join(format!("{name}.exported.usda"))),
        "up": up.name(),
        "face_sizes": mesh.face_sizes(),
        "face_indices": mesh.face_indices(),
        "points": mesh.positions().iter().map(|&p| up.from_z_up(p).to_array()).collect::<Vec<_>>(),
        "boundary": match o.boundary {
            BoundaryInterpolation::None => "none",
            BoundaryInterpolation::EdgeOnly => "edgeOnly",
            BoundaryInterpolation::EdgeAndCorner => "edgeAndCorner",
        },
        "triangles": match o.triangles {
            TriangleSubdivision::Catmark => "catmullClark",
            TriangleSubdivision::Smooth => "smooth",
        },
        "creases": mesh.creases().iter().map(|c| json!([c.vertices[0], c.vertices[1], c.sharpness])).collect::<Vec<_>>(),
        "corners": mesh.corners().iter().map(|c| json!([c.vertex, c.sharpness])).collect::<Vec<_>>(),
        "holes": mesh.holes(),
        "crease_method": if o.crease_method == CreaseMethod::Chaikin { json!("chaikin") } else { Value::Null },
    })
}

/// Expected tessellation (rate 3) of `input` written in four formats.
fn surface_case(dir: &Path, input: &Path) -> Value {
    let name = input.file_stem().unwrap().to_string_lossy();
    let file = |ext: &str| dir.join(format!("{name}.{ext}"));
    for ext in ["off", "ply", "stl"] {
        profsubd(&["tessellate", s(input), "-o", s(&file(ext)), "--rate", "3"]);
    }
    let ascii = dir.join(format!("{name}_ascii.stl"));
    profsubd(&[
        "tessellate",
        s(input),
        "-o",
        s(&ascii),
        "--rate",
        "3",
        "--format",
        "stl-ascii",
    ]);
    let mesh = read_obj_file(input).unwrap().mesh;
    let ev = Evaluator::new(&mesh, &mesh.options().resolve()).unwrap();
    let options = TessellateOptions {
        rate: Rate::Uniform(3),
        ..TessellateOptions::default()
    };
    let t = tessellate(&ev, &options).unwrap();
    let tris = t.triangles();
    let volume: f64 = tris
        .iter()
        .map(|tri| {
            let [a, b, c] = tri.map(|i| t.positions[i as usize]);
            a.dot(b.cross(c)) / 6.0
        })
        .sum();
    let mut faces = Vec::new();
    let mut start = 0;
    for &n in &t.face_sizes {
        faces.push(t.face_vertices[start..start + n as usize].to_vec());
        start += n as usize;
    }
    let r = t.edge_report();
    json!({
        "dir": s(dir),
        "off": s(&file("off")), "ply": s(&file("ply")), "stl": s(&file("stl")), "stl_ascii": s(&ascii),
        "positions": t.positions.iter().map(|p: &DVec3| p.to_array()).collect::<Vec<_>>(),
        "faces": faces,
        "triangles": tris,
        "closed": r.is_closed_oriented_manifold(),
        "euler": r.euler_characteristic(),
        "volume": volume,
    })
}

#[test]
fn usd_trimesh_and_openscad_read_what_profsubd_writes() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let mut usd = vec![
        usd_case(
            d,
            &example_file("meshes", "cube_creased", "obj"),
            &[],
            UpAxis::Z,
        ),
        usd_case(
            d,
            &example_file("profiles", "bottle", "obj"),
            &[],
            UpAxis::Y,
        ),
    ];
    let mut surface = vec![
        surface_case(d, &example_file("meshes", "cube_creased", "obj")),
        surface_case(d, &example_file("profiles", "bottle", "obj")),
        surface_case(d, &example_file("profiles", "vase", "obj")),
    ];
    if let Some(shapes) = osd_shapes::shapes_dir() {
        for (name, extra) in [
            ("catmark_hole_test1", &[][..]),
            ("catmark_cube_corner4", &[]),
            ("catmark_chaikin0", &["--crease", "chaikin"]),
            ("catmark_smoothtris0", &[]),
            ("catmark_edgeonly", &[]),
            ("catmark_pyramid_creases0", &[]),
        ] {
            usd.push(usd_case(
                d,
                &shapes.join(format!("{name}.obj")),
                extra,
                UpAxis::Z,
            ));
        }
        surface.push(surface_case(
            d,
            &shapes.join("catmark_pyramid_creases0.obj"),
        ));
        surface.push(surface_case(d, &shapes.join("catmark_torus.obj")));
    }
    let cases = json!({ "usd": usd, "surface": surface });
    std::fs::write(d.join("cases.json"), cases.to_string()).unwrap();
    let script = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/external/check_readers.py");
    let out = Command::new("python3").arg(&script).arg(d).output().unwrap_or_else(|e| {
        panic!("python3 cannot run ({e}): install python3, usd-core, trimesh and openscad (scripts/test_all.sh does)")
    });
    let text = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(out.status.success(), "{text}");
    eprintln!("{text}");
    // USD's own writer's text reads back into the same mesh; read -> write -> read is identical.
    for case in cases["usd"].as_array().unwrap() {
        let ours = read_usda_file(Path::new(case["usda"].as_str().unwrap())).unwrap();
        let exported = read_usda_file(Path::new(case["usda_exported"].as_str().unwrap())).unwrap();
        assert_eq!(exported, ours, "{}", case["usda"]);
        let up = if case["up"] == "Y" {
            UpAxis::Y
        } else {
            UpAxis::Z
        };
        let text = std::fs::read_to_string(case["usda"].as_str().unwrap()).unwrap();
        assert_eq!(to_usda(&ours, up).0, text, "{}", case["usda"]);
    }
}
