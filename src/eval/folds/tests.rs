//! Tests of [`super::find_folds`] against exact expectations: symmetric shapes, planar
//! pieces, and a planar B-spline grid whose fold region is known in closed form.

use crate::math;
use glam::DVec3;

use super::{find_folds, find_folds_with, FoldSettings};
use crate::error::Error;
use crate::eval::Evaluator;
use crate::mesh::{Corner, Crease, Mesh, MeshParts, SHARPNESS_INFINITE};
use crate::options::SubdivOptions;
use crate::test_support::grid;

fn report(parts: MeshParts) -> super::FoldReport {
    let mesh = Mesh::from_parts(parts).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    find_folds(&ev, &FoldSettings::default()).unwrap()
}

fn cube(sharp_edges: bool) -> MeshParts {
    let positions = (0..8)
        .map(|k| DVec3::new((k & 1) as f64, ((k >> 1) & 1) as f64, (k >> 2) as f64) * 2.0 - 1.0)
        .collect();
    let face_indices = vec![
        0, 2, 3, 1, 4, 5, 7, 6, 0, 1, 5, 4, 2, 6, 7, 3, 0, 4, 6, 2, 1, 3, 7, 5,
    ];
    let creases = if sharp_edges {
        let mut edges: Vec<[u32; 2]> = face_indices
            .chunks(4)
            .flat_map(|f| (0..4).map(move |i| [f[i].min(f[(i + 1) % 4]), f[i].max(f[(i + 1) % 4])]))
            .collect();
        edges.sort_unstable();
        edges.dedup();
        edges
            .into_iter()
            .map(|vertices| Crease {
                vertices,
                sharpness: SHARPNESS_INFINITE,
            })
            .collect()
    } else {
        Vec::new()
    };
    MeshParts {
        positions,
        face_sizes: vec![4; 6],
        face_indices,
        creases,
        ..Default::default()
    }
}

#[test]
fn smooth_cube_is_fold_free_and_its_corner_normal_is_the_diagonal() {
    let r = report(cube(false));
    assert!(r.is_fold_free(), "{:?}", r.folded_faces);
    assert_eq!(r.faces_checked, 6);
    // By symmetry the limit normal at a cube corner (valence 3, exact vertex limit) is the
    // diagonal and each face's reference normal its axis: 54.7356° apart, the largest angle.
    let expected = math::acos(1.0 / 3f64.sqrt()).to_degrees();
    assert!(
        (r.worst_reversal_deg - expected).abs() < 1e-9,
        "{} vs {expected}",
        r.worst_reversal_deg
    );
    let (_, u, v) = r.worst_at.unwrap();
    assert!((u == 0.0 || u == 1.0) && (v == 0.0 || v == 1.0), "{u} {v}");
    assert!(r.min_relative_jacobian > 0.0);
}

#[test]
fn infinitely_sharp_cube_is_flat_per_face_and_not_folded() {
    // Each face's limit is the flat square; the normal jumps by 90° across every edge and
    // corner, which a one-sided, per-face check must not see.
    let r = report(cube(true));
    assert!(r.is_fold_free(), "{:?}", r.folded_faces);
    assert!(r.worst_reversal_deg < 1e-5, "{}", r.worst_reversal_deg);
}

#[test]
fn a_cone_point_is_not_a_fold() {
    // An infinitely sharp vertex with smooth edges: the surface has a cone point there, whose
    // normal depends on the direction of approach (119° between the two edges of one face at
    // 2^-7 from it, across one finest lattice cell): not a fold.
    let mut parts = cube(false);
    parts.corners = vec![Corner {
        vertex: 0,
        sharpness: SHARPNESS_INFINITE,
    }];
    let mesh = Mesh::from_parts(parts.clone()).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    // Face 0 has vertex 0 at (u, v) = (0, 0).
    let n = |u, v| ev.evaluate(0, u, v).unwrap().normal();
    let (along_u, along_v) = (n(1.0 / 128.0, 0.0), n(0.0, 1.0 / 128.0));
    assert!(along_u.dot(along_v) < -0.45, "{along_u} {along_v}");
    let r = report(parts);
    assert!(r.is_fold_free(), "{:?}", r.folded_faces);
    assert!(r.worst_reversal_deg < 90.0, "{}", r.worst_reversal_deg);
}

/// A 6 × 4 grid bent along the line x = 3 so the two halves' normals are 120° apart, with
/// that line tagged infinitely sharp when `sharp`.
fn roof(sharp: bool) -> MeshParts {
    let turn = 120f64.to_radians();
    let mut parts = grid(6, |_, _| 0.0);
    for p in parts.positions.iter_mut() {
        if p.x > 3.0 {
            let d = p.x - 3.0;
            *p = DVec3::new(3.0 + d * math::cos(turn), p.y, d * math::sin(turn));
        }
    }
    if sharp {
        parts.creases = (0..6)
            .map(|j| Crease {
                vertices: [j * 7 + 3, (j + 1) * 7 + 3],
                sharpness: SHARPNESS_INFINITE,
            })
            .collect();
    }
    parts
}

#[test]
fn a_sharp_crease_is_not_a_fold() {
    let parts = roof(true);
    // The two faces at the crease (face (2, 2) left of it, (3, 2) right of it) meet at
    // 120° at the crease: the jump a check across faces would see.
    let mesh = Mesh::from_parts(parts.clone()).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    let left = ev.evaluate(2 * 6 + 2, 1.0, 0.5).unwrap().normal();
    let right = ev.evaluate(2 * 6 + 3, 0.0, 0.5).unwrap().normal();
    assert!((left.dot(right) - math::cos(120f64.to_radians())).abs() < 1e-12);
    let r = report(parts);
    assert!(r.is_fold_free(), "{:?}", r.folded_faces);
    // Both halves are planar control nets cut by an infinitely sharp crease: flat limits.
    assert!(r.worst_reversal_deg < 1e-5, "{}", r.worst_reversal_deg);
    // Without the tag the surface bends smoothly through 120°: no fold either.
    assert!(report(roof(false)).is_fold_free());
}

/// An 8 × 8 planar grid (unit spacing) with vertex (4, 4) moved by `d` along +x.
///
/// The interior patches are uniform bicubic B-splines, so the limit map is
/// `x = X + d N(s) N(t)`, `y = Y` with `N` the cubic B-spline centred on the vertex and
/// `(s, t)` the offsets from it. Its Jacobian `1 + d N'(s) N(t)` is smallest at
/// `(s, t) = (2/3, 0)`, where `N' = -2/3` and `N = 2/3`: `1 - 4d/9`, negative (a fold)
/// exactly when `d > 2.25`, in the two faces along the edge from vertex (4, 4) to (5, 4).
fn pushed_grid(d: f64) -> MeshParts {
    let mut parts = grid(8, |_, _| 0.0);
    parts.positions[4 * 9 + 4].x += d;
    parts
}

#[test]
fn a_pushed_control_point_folds_exactly_the_predicted_faces() {
    let r = report(pushed_grid(2.3));
    // Faces (4, 3) and (4, 4): x in [4, 5], y in [3, 4] and [4, 5].
    assert_eq!(r.folded_face_indices(), vec![3 * 8 + 4, 4 * 8 + 4]);
    // In the plane the reversed normal is exactly -z.
    assert_eq!(r.worst_reversal_deg, 180.0);
    let (ptex, u, v) = r.worst_at.unwrap();
    assert!(ptex == 3 * 8 + 4 || ptex == 4 * 8 + 4);
    // The reversed region is s in (0.568, 0.765), |t| < 0.12 around the edge y = 4.
    assert!(
        (0.5..0.8).contains(&u) && !(0.15..=0.85).contains(&v),
        "{u} {v}"
    );
    assert!(r.min_relative_jacobian < 0.0);
    for f in &r.folded_faces {
        assert!(f.reversed_samples > 0);
        assert!(f.max_turn_deg > 179.0, "{}", f.max_turn_deg);
    }
}

#[test]
fn a_control_point_pushed_less_than_the_fold_threshold_does_not_fold() {
    let r = report(pushed_grid(2.2));
    assert!(r.is_fold_free(), "{:?}", r.folded_faces);
    assert!(r.worst_reversal_deg < 1e-5, "{}", r.worst_reversal_deg);
    // The smallest Jacobian, 1 - 4(2.2)/9 = 0.022 of the unit grid's, is positive.
    assert!(r.min_relative_jacobian > 0.0 && r.min_relative_jacobian < 0.1);
}

#[test]
fn holes_are_skipped_and_bad_settings_are_refused() {
    let mut parts = grid(4, |x, y| 0.1 * x * y);
    parts.holes = vec![5];
    let r = report(parts.clone());
    assert_eq!(r.faces_checked, 15);
    let ev = Evaluator::new(&Mesh::from_parts(parts).unwrap(), &SubdivOptions::default()).unwrap();
    for bad in [
        FoldSettings {
            samples_per_edge: 1,
            ..Default::default()
        },
        FoldSettings {
            adaptive_depth: 17,
            ..Default::default()
        },
        FoldSettings {
            refine_turn_deg: f64::NAN,
            ..Default::default()
        },
    ] {
        assert!(matches!(
            find_folds(&ev, &bad),
            Err(Error::InvalidArgument(_))
        ));
    }
}

/// The running ceilings: a check allowed exactly the evaluations it makes passes with the
/// same report; one fewer stops in the adaptive halving (the base lattices fit) with a
/// message naming the face and figures; a memory budget that holds the base lattice of one
/// face but not its halving stops there with both figures; the polls report 0 to 1.
#[test]
fn running_ceilings_stop_the_adaptive_halving() {
    use super::{check_folds, fold_check_bytes, SAMPLE_BYTES};
    use crate::control::Control;
    let mesh = Mesh::from_parts(pushed_grid(2.3)).unwrap();
    let ev = Evaluator::new(&mesh, &SubdivOptions::default()).unwrap();
    let s = FoldSettings::default();
    let full = find_folds(&ev, &s).unwrap();
    let made = full.samples as u64;
    assert!(made > 64 * 81, "{made}: some halving");
    assert_eq!(check_folds(&ev, &s, &Control::NONE, made).unwrap(), full);
    match check_folds(&ev, &s, &Control::NONE, made - 1) {
        Err(Error::LimitExceeded(m)) => assert!(
            m.contains(&format!(
                "reached its limit of {} limit evaluations",
                made - 1
            )) && m.contains("64 faces at 9 × 9 samples, take 5184"),
            "{m}"
        ),
        other => panic!("{:?}", other.map(|r| r.samples)),
    }
    // Room for one face's base lattice and 10 more samples: the faces at the pushed vertex
    // halve further.
    let budget = fold_check_bytes(&ev, 9) + 10 * SAMPLE_BYTES;
    let control = Control::NONE.with_memory_budget(Some(budget));
    match find_folds_with(&ev, &s, &control) {
        Err(Error::LimitExceeded(m)) => assert!(
            m.contains("the fold check's samples of parametric face")
                && m.contains(&format!("above the memory budget of {budget} bytes")),
            "{m}"
        ),
        other => panic!("{:?}", other.map(|r| r.samples)),
    }
    match find_folds_with(
        &ev,
        &s,
        &Control::NONE.with_memory_budget(Some(budget - 11 * SAMPLE_BYTES)),
    ) {
        Err(Error::LimitExceeded(m)) => assert!(
            m.contains("the fold check of 64 parametric faces at 9 × 9 samples needs about"),
            "{m}"
        ),
        other => panic!("{:?}", other.map(|r| r.samples)),
    }
    let seen = std::sync::Arc::new(std::sync::Mutex::new(Vec::new()));
    let log = seen.clone();
    let control = Control::NONE.with_progress(move |f: f64| {
        log.lock().unwrap().push(f);
        false
    });
    assert_eq!(find_folds_with(&ev, &s, &control).unwrap(), full);
    let f = seen.lock().unwrap().clone();
    assert_eq!((f[0], *f.last().unwrap()), (0.0, 1.0));
    assert!(f.windows(2).all(|w| w[0] <= w[1]) && f.iter().any(|&x| x > 0.0 && x < 1.0));
}
