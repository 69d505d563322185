//! Refinement of every OpenSubdiv shape and every example mesh of the project, checked
//! without OpenSubdiv (the C++ test `conformance_refine` compares with Far): each level's
//! relations are consistent, counts are Vtr's, refined stencils reproduce the positions,
//! and the written refined mesh, read back, has the refined level's sharpness and holes.

#[path = "support/osd_shapes.rs"]
mod osd_shapes;

use std::path::{Path, PathBuf};

use glam::DVec3;
use profsubd::io::obj::{parse_obj, read_obj_file, to_obj_string};
use profsubd::refine::{
    interpolate, refine, refine_levels, refine_uniform, SparseStencil, VertexOrder,
};
use profsubd::topology::Level;
use profsubd::{BoundaryInterpolation, CreaseMethod, Mesh, SubdivOptions};

fn meshes() -> Vec<(String, Mesh)> {
    let mut files: Vec<PathBuf> = Vec::new();
    if let Some(dir) = osd_shapes::shapes_dir() {
        files.extend(osd_shapes::index(&dir).into_iter().map(|r| r.path));
    }
    let examples = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples");
    for sub in ["meshes", "profiles", "sweeps"] {
        if let Ok(rd) = std::fs::read_dir(examples.join(sub)) {
            let mut v: Vec<PathBuf> = rd
                .map(|e| e.unwrap().path())
                .filter(|p| p.extension().is_some_and(|x| x == "obj"))
                .collect();
            v.sort();
            files.extend(v);
        }
    }
    files
        .into_iter()
        .map(|p| (p.display().to_string(), read_obj_file(&p).unwrap().mesh))
        .collect()
}

/// Two option sets between them covering every boundary rule's special case and both
/// crease methods (the C++ conformance test runs all six against Far).
fn option_sets() -> [SubdivOptions; 2] {
    [
        SubdivOptions {
            boundary: BoundaryInterpolation::None,
            crease_method: CreaseMethod::Chaikin,
            ..Default::default()
        },
        SubdivOptions {
            boundary: BoundaryInterpolation::EdgeAndCorner,
            crease_method: CreaseMethod::Uniform,
            ..Default::default()
        },
    ]
}

#[test]
fn levels_are_consistent_with_vtr_counts() {
    let meshes = meshes();
    assert!(meshes.len() >= 8, "the example meshes are missing");
    for (name, mesh) in &meshes {
        let opts = SubdivOptions {
            triangles: mesh.options().resolve().triangles,
            ..Default::default()
        };
        let mut level = Level::from_mesh_with_options(mesh, &opts);
        level
            .validate()
            .unwrap_or_else(|e| panic!("{name} level 0: {e}"));
        for depth in 1..=2 {
            let r = refine(&level, VertexOrder::VerticesFirst);
            let c = &r.child;
            assert_eq!(
                c.num_vertices(),
                level.num_vertices() + level.num_faces() + level.num_edges(),
                "{name}"
            );
            assert_eq!(c.num_faces(), level.num_face_vertices_total(), "{name}");
            assert_eq!(
                c.num_edges(),
                level.num_face_vertices_total() + 2 * level.num_edges(),
                "{name}"
            );
            c.validate()
                .unwrap_or_else(|e| panic!("{name} level {depth}: {e}"));
            level = r.child;
        }
    }
}

#[test]
fn stencils_reproduce_positions_and_written_meshes_keep_their_sharpness() {
    for (name, mesh) in meshes() {
        let diag = mesh.bounding_box_diagonal().max(1e-300);
        for opts in option_sets() {
            let opts = SubdivOptions {
                triangles: mesh.options().resolve().triangles,
                ..opts
            };
            let (level, pos) = refine_levels(&mesh, &opts, 2, VertexOrder::VerticesFirst).unwrap();
            let out = refine_uniform(&mesh, &opts, 2).unwrap();
            assert_eq!(out.positions(), &pos[..], "{name} {opts:?}");
            // Refined meshes are built unchecked: they must pass the checks all the same.
            let checked = Mesh::from_parts(out.parts().clone())
                .unwrap_or_else(|e| panic!("{name} {opts:?}: refined mesh invalid: {e}"));
            assert_eq!(checked, out, "{name} {opts:?}");

            // Written and read back: same sharpness and holes as the refined level.
            let text = to_obj_string(&out);
            let back = parse_obj(&text, Path::new("<refined>")).unwrap().mesh;
            assert_eq!(back.positions(), out.positions(), "{name}");
            let reread = Level::from_mesh(&back);
            for e in 0..level.num_edges() {
                let [a, b] = level.edge_vertices(e);
                let f = reread.find_edge(a as usize, b as usize).unwrap();
                assert_eq!(
                    reread.edge_sharpness(f as usize),
                    level.edge_sharpness(e),
                    "{name} {opts:?} edge {e}"
                );
            }
            for v in 0..level.num_vertices() {
                // A file cannot say "smooth" for a non-manifold vertex: reading sharpens it,
                // where Far's refinement leaves the children of non-manifold edges smooth.
                if reread.is_vertex_non_manifold(v) && level.vertex_sharpness(v) == 0.0 {
                    assert!(level.is_vertex_non_manifold(v), "{name} vertex {v}");
                    continue;
                }
                assert_eq!(
                    reread.vertex_sharpness(v),
                    level.vertex_sharpness(v),
                    "{name} {opts:?} vertex {v}"
                );
            }
            for f in 0..level.num_faces() {
                assert_eq!(
                    reread.is_face_hole(f),
                    level.is_face_hole(f),
                    "{name} face {f}"
                );
            }
        }
        // Stencils (one option set: the file's).
        let opts = mesh.options().resolve();
        let mut level = Level::from_mesh_with_options(&mesh, &opts);
        let mut pos = mesh.positions().to_vec();
        let mut st: Vec<SparseStencil> = (0..mesh.num_vertices() as u32)
            .map(SparseStencil::unit)
            .collect();
        for _ in 0..2 {
            let r = refine(&level, VertexOrder::VerticesFirst);
            pos = interpolate(&level, &r, &pos);
            st = interpolate(&level, &r, &st);
            level = r.child;
        }
        for (i, (p, s)) in pos.iter().zip(&st).enumerate() {
            let d: DVec3 = s.apply(mesh.positions()) - *p;
            assert!(d.length() <= 1e-14 * diag, "{name} vertex {i}: {d}");
        }
    }
}
