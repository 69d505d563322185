use glam::DVec3;

use super::*;
use crate::eval::Evaluator;
use crate::io::obj::parse_obj;
use crate::mesh::{Mesh, MeshParts};
use crate::options::SubdivOptions;
use crate::tessellate::{tessellate, Rate, TessellateOptions};

fn cube_tessellation(quads: bool) -> Tessellation {
    let positions = (0..8)
        .map(|k| {
            DVec3::new(
                (k & 1) as f64,
                ((k >> 1) & 1) as f64,
                ((k >> 2) & 1) as f64 * 2.0,
            )
        })
        .collect();
    let mesh = Mesh::from_parts(MeshParts {
        positions,
        face_sizes: vec![4; 6],
        face_indices: vec![
            0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5,
        ],
        ..Default::default()
    })
    .unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    let options = TessellateOptions {
        rate: Rate::Uniform(2),
        quads,
        ..TessellateOptions::default()
    };
    tessellate(&ev, &options).unwrap()
}

#[test]
fn binary_stl_has_the_triangles_as_f32() {
    let t = cube_tessellation(true);
    let tris = t.triangles();
    assert_eq!(tris.len(), 48);
    let b = surface_to_bytes(&t, SurfaceFormat::Stl, UpAxis::Z);
    assert_eq!(b.len(), 84 + 50 * 48);
    assert!(!b.starts_with(b"solid"));
    assert_eq!(u32::from_le_bytes(b[80..84].try_into().unwrap()), 48);
    let f = |o: usize| f32::from_le_bytes(b[o..o + 4].try_into().unwrap());
    // First triangle's first vertex, after the normal.
    let p = t.positions[tris[0][0] as usize];
    assert_eq!(
        [f(84 + 12), f(84 + 16), f(84 + 20)],
        [p.x as f32, p.y as f32, p.z as f32]
    );
    assert_eq!(b, surface_to_bytes(&t, SurfaceFormat::Stl, UpAxis::Z));
}

#[test]
fn text_formats_keep_exact_coordinates() {
    let t = cube_tessellation(false);
    let off = String::from_utf8(surface_to_bytes(&t, SurfaceFormat::Off, UpAxis::Z)).unwrap();
    let mut lines = off.lines();
    assert_eq!(lines.next(), Some("OFF"));
    assert_eq!(
        lines.next(),
        Some(format!("{} {} 0", t.num_vertices(), t.num_faces()).as_str())
    );
    let first: Vec<f64> = lines
        .next()
        .unwrap()
        .split(' ')
        .map(|x| x.parse().unwrap())
        .collect();
    assert_eq!(first, t.positions[0].to_array());
    let obj = String::from_utf8(surface_to_bytes(&t, SurfaceFormat::Obj, UpAxis::Z)).unwrap();
    let read = parse_obj(&obj, Path::new("t.obj")).unwrap().mesh;
    assert_eq!(read.positions(), &t.positions[..]);
    assert_eq!(read.face_indices(), &t.face_vertices[..]);
    assert_eq!(
        obj.lines().filter(|l| l.starts_with("vn ")).count(),
        t.normals.len()
    );
    let ascii =
        String::from_utf8(surface_to_bytes(&t, SurfaceFormat::StlAscii, UpAxis::Z)).unwrap();
    assert_eq!(ascii.matches("facet normal").count(), t.triangles().len());
}

#[test]
fn ply_header_counts_and_y_up_rotation() {
    let t = cube_tessellation(false);
    let b = surface_to_bytes(&t, SurfaceFormat::Ply, UpAxis::Y);
    let end = b.windows(11).position(|w| w == b"end_header\n").unwrap() + 11;
    let header = std::str::from_utf8(&b[..end]).unwrap();
    assert!(header.contains(&format!("element vertex {}\n", t.num_vertices())));
    assert!(header.contains(&format!("element face {}\n", t.num_faces())));
    assert_eq!(b.len(), end + 48 * t.num_vertices() + 13 * t.num_faces());
    let d = |o: usize| f64::from_le_bytes(b[end + o..end + o + 8].try_into().unwrap());
    let p = t.positions[0];
    assert_eq!([d(0), d(8), d(16)], [p.x, p.z, -p.y]);
}

#[test]
fn format_from_extension() {
    assert_eq!(
        SurfaceFormat::from_path(Path::new("a/b.STL")).unwrap(),
        SurfaceFormat::Stl
    );
    assert_eq!(
        SurfaceFormat::from_path(Path::new("b.ply")).unwrap(),
        SurfaceFormat::Ply
    );
    assert!(SurfaceFormat::from_path(Path::new("b.glb")).is_err());
    assert!(SurfaceFormat::from_path(Path::new("b")).is_err());
}
