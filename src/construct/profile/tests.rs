//! Tests of the cage (data points, topology, tags) before fitting.

use std::collections::HashMap;

use glam::DVec3;

use super::shapes::{double_cone, ellipsoid};
use super::*;
use crate::construct::settings::{Caps, Settings};
use crate::error::Error;
use crate::mesh::Mesh;

/// Edges with their face counts, and each vertex's valence.
fn edge_stats(p: &MeshParts) -> (HashMap<(u32, u32), usize>, Vec<usize>) {
    let mut edges = HashMap::new();
    let mut off = 0;
    for &n in &p.face_sizes {
        let f = &p.face_indices[off..off + n as usize];
        for i in 0..f.len() {
            let (a, b) = (f[i], f[(i + 1) % f.len()]);
            *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
        off += n as usize;
    }
    let mut val = vec![0; p.positions.len()];
    for &(a, b) in edges.keys() {
        val[a as usize] += 1;
        val[b as usize] += 1;
    }
    (edges, val)
}

/// Signed volume of the closed quad mesh (positive when outward oriented).
fn volume(p: &MeshParts) -> f64 {
    let mut v = 0.0;
    let mut off = 0;
    for &n in &p.face_sizes {
        let f = &p.face_indices[off..off + n as usize];
        let c: DVec3 = f.iter().map(|&i| p.positions[i as usize]).sum::<DVec3>() / f.len() as f64;
        for i in 0..f.len() {
            let a = p.positions[f[i] as usize];
            let b = p.positions[f[(i + 1) % f.len()] as usize];
            v += a.dot(b.cross(c)) / 6.0;
        }
        off += n as usize;
    }
    v
}

/// Closed-model topology: all quads, every edge twice, Euler characteristic 2, extraordinary
/// vertices of valence 3 or 5 except corner-tagged tips, positive volume.
fn check_closed(cage: &ProfileCage) {
    let p = &cage.parts;
    assert!(p.face_sizes.iter().all(|&n| n == 4));
    let (edges, val) = edge_stats(p);
    assert!(
        edges.values().all(|&c| c == 2),
        "boundary or non-manifold edge"
    );
    let euler = p.positions.len() as i64 - edges.len() as i64 + p.face_sizes.len() as i64;
    assert_eq!(euler, 2);
    let tips: Vec<u32> = p.corners.iter().map(|c| c.vertex).collect();
    for (v, &n) in val.iter().enumerate() {
        if !tips.contains(&(v as u32)) {
            assert!(n == 3 || n == 4 || n == 5, "vertex {v} has valence {n}");
        }
    }
    assert!(volume(p) > 0.0, "not outward");
    Mesh::from_parts(p.clone()).unwrap();
}

#[test]
fn ellipsoid_data_points_lie_on_the_ellipsoid_with_smooth_caps() {
    let (a, b, c) = (2.0, 1.0, 1.5);
    for (around, along) in [(16, 12), (12, 9), (32, 16), (4, 3)] {
        let mut input = ellipsoid(a, b, c, 24);
        input.around = around;
        input.along = along;
        let cage = build_cage(&input, &Settings::default()).unwrap();
        assert_eq!(cage.ends, [EndKind::Smooth, EndKind::Smooth]);
        assert!(cage.parts.creases.is_empty() && cage.parts.corners.is_empty());
        check_closed(&cage);
        for p in targets(&cage) {
            let e = (p.x / a).powi(2) + (p.y / b).powi(2) + (p.z / c).powi(2) - 1.0;
            // The spline through 25 points of the silhouette approximates the ellipse.
            assert!(e.abs() < 2e-4, "{p} off by {e}");
        }
        let (_, val) = edge_stats(&cage.parts);
        assert_eq!(
            val.iter().filter(|&&n| n == 3).count(),
            8,
            "around {around}"
        );
    }
}

#[test]
fn double_cone_has_an_equator_crease_loop_and_corner_tips() {
    let input = double_cone(1.0, 1.0, 4);
    let cage = build_cage(&input, &Settings::default()).unwrap();
    assert_eq!(cage.ends, [EndKind::Tip, EndKind::Tip]);
    check_closed(&cage);
    let p = &cage.parts;
    assert_eq!(p.corners.len(), 2);
    assert!(p.corners.iter().all(|c| c.sharpness == SHARPNESS_INFINITE));
    let tip_z: Vec<f64> = p
        .corners
        .iter()
        .map(|c| p.positions[c.vertex as usize].z)
        .collect();
    assert_eq!(tip_z, vec![-1.0, 1.0]);
    // A full loop of 16 infinitely sharp edges on the equator ring (z = 0, radius 1).
    assert_eq!(p.creases.len(), 16);
    for cr in &p.creases {
        assert_eq!(cr.sharpness, SHARPNESS_INFINITE);
        for &v in &cr.vertices {
            let q = p.positions[v as usize];
            assert!(q.z.abs() < 1e-15 && (q.truncate().length() - 1.0).abs() < 1e-12);
        }
    }
    // Data points lie on the cone.
    for q in &p.positions {
        assert!(
            (q.truncate().length() - (1.0 - q.z.abs())).abs() < 1e-12,
            "{q}"
        );
    }
}

#[test]
fn a_kink_in_one_view_gives_a_half_ring_crease_ending_in_darts() {
    let mut input = double_cone(1.0, 1.0, 4);
    // c2 smooth (an ellipse-like bulge through the same heights), c1 kinked.
    input.c2 = (0..=8)
        .map(|i| {
            let z = i as f64 / 4.0 - 1.0;
            [1.0 - z * z, z]
        })
        .collect();
    // c3 smooth too (the mirror of c2 in x), so only c1 kinks.
    input.c3 = Some(input.c2.iter().map(|p| [-p[0], p[1]]).collect());
    let settings = Settings {
        sharp_angle_deg: 60.0,
        ..Settings::default()
    };
    let cage = build_cage(&input, &settings).unwrap();
    let p = &cage.parts;
    // Quadrants 1 and 4 (next to c1): half of the 16 ring edges.
    assert_eq!(p.creases.len(), 8);
    let mut count: HashMap<u32, usize> = HashMap::new();
    for c in &p.creases {
        for v in c.vertices {
            *count.entry(v).or_insert(0) += 1;
        }
    }
    let ends: Vec<u32> = count
        .iter()
        .filter(|(_, &n)| n == 1)
        .map(|(&v, _)| v)
        .collect();
    assert_eq!(ends.len(), 2);
    for v in ends {
        let q = p.positions[v as usize];
        // The darts sit on the ±y meridians (c2 and c4).
        assert!(q.x.abs() < 1e-12 && (q.y.abs() - 1.0).abs() < 1e-12, "{q}");
    }
}

#[test]
fn bottle_keeps_its_shoulder_crease_and_flat_bottom() {
    let c1 = vec![
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0, 1.0],
        [1.0, 2.0],
        [0.4, 2.6],
        [0.4, 3.2],
        [0.0, 3.2],
    ];
    let mut input = ProfileInput::new(c1.clone(), c1);
    input.along = 16;
    let cage = build_cage(&input, &Settings::default()).unwrap();
    check_closed(&cage);
    assert_eq!(cage.ends, [EndKind::Smooth, EndKind::Smooth]);
    // Corners at points 1, 3, 4, 5 (bottom rim, shoulder, neck, lip): four crease loops.
    assert_eq!(cage.crease_rings.len(), 4);
    assert_eq!(cage.parts.creases.len(), 4 * 16);
    let shoulder = cage
        .parts
        .creases
        .iter()
        .filter(|c| {
            c.vertices.iter().all(|&v| {
                let q = cage.parts.positions[v as usize];
                (q.z - 2.0).abs() < 1e-12 && (q.truncate().length() - 1.0).abs() < 1e-12
            })
        })
        .count();
    assert_eq!(shoulder, 16);
}

#[test]
fn open_and_flat_ends() {
    let c = vec![[1.0, 0.0], [1.2, 1.0], [1.0, 2.0]];
    let input = ProfileInput::new(c.clone(), c.clone());
    let cage = build_cage(&input, &Settings::default()).unwrap();
    assert_eq!(cage.ends, [EndKind::Open, EndKind::Open]);
    let (edges, _) = edge_stats(&cage.parts);
    assert_eq!(edges.values().filter(|&&n| n == 1).count(), 32);
    let input = ProfileInput::new(c.clone(), c);
    let flat = Settings {
        caps: Caps::Flat,
        ..Settings::default()
    };
    let cage = build_cage(&input, &flat).unwrap();
    assert_eq!(cage.ends, [EndKind::Flat, EndKind::Flat]);
    check_closed(&cage);
    assert_eq!(cage.parts.creases.len(), 32);
    // Flat caps are planar.
    let zs: Vec<f64> = cage.parts.positions.iter().map(|p| p.z).collect();
    // The crease ring, the cap's inner ring and the 3 × 3 interior of its grid cap.
    assert_eq!(zs.iter().filter(|&&z| z == 0.0).count(), 16 + 16 + 9);
}

fn err(input: &ProfileInput) -> String {
    match build_cage(input, &Settings::default()) {
        Err(Error::InvalidArgument(m)) => m,
        other => panic!("expected an invalid-argument error, got {other:?}"),
    }
}

#[test]
fn bad_inputs_give_specific_errors() {
    let good = ellipsoid(1.0, 1.0, 1.0, 8);
    let mut i = good.clone();
    i.c1 = vec![[0.0, 0.0]];
    assert!(err(&i).contains("at least 2 points"));
    let mut i = good.clone();
    i.c2[3][0] = f64::NAN;
    assert!(err(&i).contains("c2 point 3"));
    let mut i = good.clone();
    i.c2.reverse();
    assert!(err(&i).contains("bottom to top"));
    let mut i = good.clone();
    i.c1[4][0] = -0.5;
    assert!(err(&i).contains("crosses the axis"));
    let mut i = good.clone();
    i.c3 = Some(good.c1.iter().map(|p| [0.5 - p[0], p[1]]).collect());
    i.c3.as_mut().unwrap()[0][0] = 0.7;
    assert!(err(&i).contains("cross the axis"));
    let mut i = good.clone();
    i.around = 10;
    assert!(err(&i).contains("multiple of 4"));
    let mut i = good.clone();
    i.around = 1 << 20;
    assert!(err(&i).contains("between 4 and"));
    let mut i = good.clone();
    i.along = 2;
    i.around = 32;
    assert!(err(&i).contains("too small"));
    let mut i = double_cone(1.0, 1.0, 4);
    i.around = 4;
    assert!(err(&i).contains("valence 2"));
    let mut i = good.clone();
    i.corners.c1 = vec![40];
    assert!(err(&i).contains("no point 40"));
    let mut i = good.clone();
    i.c1[8][1] = 1.2;
    assert!(err(&i).contains("different heights"));
    let mut i = good.clone();
    i.c2[8][0] = 0.5;
    assert!(err(&i).contains("slit"));
    let mut i = good;
    i.c1[5] = i.c1[4];
    assert!(err(&i).contains("coincide"));
}
