//! GBS subdivision of order 4 at tension 1 against Catmull–Clark: every vertex of levels
//! 1–3 equals `refine_uniform`'s (boundary edge-only), on the untagged OpenSubdiv shapes
//! (triangles and pentagons included) and the shapes whose tags are all infinitely sharp.
//! The reference is `refine_uniform`, which the C++ test `conformance_refine` checks against
//! OpenSubdiv's Far (`TopologyRefiner::RefineUniform` + `PrimvarRefiner`) index by index on
//! every shape under every boundary option; GBS even orders use the same quad split, so a
//! child is matched to Far's by its parent. The C++ test `conformance_gbs` compares GBS with
//! Far directly (through `profsubd_gbs_refine`).

#[path = "support/osd_shapes.rs"]
mod osd_shapes;

use profsubd::gbs::{refine_gbs, GbsOptions};
use profsubd::io::obj::read_obj_file;
use profsubd::{refine_uniform, BoundaryInterpolation, SubdivOptions};

/// Shapes whose only tags are infinitely sharp creases or corners, manifold, without holes.
const INFINITELY_SHARP: [&str; 3] = [
    "catmark_cube_corner4",
    "catmark_inf_crease0",
    "catmark_inf_crease1",
];

#[test]
fn order_four_unit_tension_is_catmull_clark() {
    let Some(dir) = osd_shapes::shapes_dir() else {
        return;
    };
    let rows: Vec<_> = osd_shapes::index(&dir)
        .into_iter()
        .filter(|r| {
            let untagged = !r.has_creases && !r.has_corners && r.boundary == "untagged";
            let plain = ![
                "holes",
                "non-manifold",
                "smoothtriangles smooth",
                "left-handed",
            ]
            .iter()
            .any(|n| r.notes.contains(n));
            (untagged && plain) || INFINITELY_SHARP.contains(&r.name.as_str())
        })
        .collect();
    let names: Vec<&str> = rows.iter().map(|r| r.name.as_str()).collect();
    // The untagged manifold shapes, with triangles (pyramid, smoothtris0) and pentagons
    // (gregory_test8), and the infinitely sharp ones.
    for needed in [
        "catmark_cube",
        "catmark_torus",
        "catmark_pyramid",
        "catmark_gregory_test8",
    ] {
        assert!(names.contains(&needed), "{needed} missing from {names:?}");
    }
    let gbs = GbsOptions {
        order: 4,
        tension: 1.0,
    };
    let catmark = SubdivOptions {
        boundary: BoundaryInterpolation::EdgeOnly,
        ..Default::default()
    };
    for row in &rows {
        let mesh = read_obj_file(&row.path).unwrap().mesh;
        let diag = mesh.bounding_box_diagonal();
        for level in 1..=3 {
            let mine =
                refine_gbs(&mesh, &gbs, level).unwrap_or_else(|e| panic!("{}: {e}", row.name));
            let reference = refine_uniform(&mesh, &catmark, level).unwrap();
            assert_eq!(
                mine.positions.len(),
                reference.num_vertices(),
                "{}",
                row.name
            );
            let worst = mine
                .positions
                .iter()
                .zip(reference.positions())
                .map(|(a, b)| (*a - *b).length())
                .fold(0.0, f64::max);
            assert!(
                worst <= 1e-12 * diag,
                "{} level {level}: {worst:e} × diagonal {diag}",
                row.name
            );
            // Same faces, index for index.
            let faces = mine.to_mesh().unwrap();
            assert_eq!(
                faces.face_indices(),
                reference.face_indices(),
                "{}",
                row.name
            );
        }
        eprintln!("{}: levels 1-3 agree", row.name);
    }
}
