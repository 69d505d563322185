//! Fitted sweeps and revolutions: the exact limit at every control vertex equals its data
//! point, and the meshes have the topology the construction promises.
// Reference geometry for tolerance checks: the platform's libm is fine here.
#![allow(clippy::disallowed_methods)]

#[allow(dead_code)]
#[path = "support/swept.rs"]
mod swept;

use std::f64::consts::{PI, TAU};

use profsubd::mesh::validate::check;
use profsubd::RevolveInput;
use profsubd::SweepInput;
use profsubd::{revolve, sweep, Settings};
use swept::relative_residual;

fn circle(n: usize, r: f64) -> Vec<[f64; 2]> {
    (0..n)
        .map(|i| {
            let t = TAU * i as f64 / n as f64;
            [r * t.cos(), r * t.sin()]
        })
        .collect()
}

#[test]
fn torus_sphere_cylinder_cone_interpolate_their_targets() {
    let mut torus = SweepInput::new(
        circle(16, 0.5),
        circle(24, 2.0)
            .into_iter()
            .map(|[x, y]| [x, y, 0.0])
            .collect(),
    );
    torus.closed_profile = true;
    torus.closed_trajectory = true;
    let semicircle: Vec<[f64; 2]> = (0..=12)
        .map(|i| {
            let t = -PI / 2.0 + PI * i as f64 / 12.0;
            [if i == 0 || i == 12 { 0.0 } else { t.cos() }, t.sin()]
        })
        .collect();
    let surfaces = [
        ("torus", sweep::build(&torus, &Settings::default()).unwrap()),
        (
            "sphere",
            revolve::build(&RevolveInput::new(semicircle), &Settings::default()).unwrap(),
        ),
        (
            "cylinder",
            revolve::build(
                &RevolveInput::new(vec![[1.0, 0.0], [1.0, 2.0]]),
                &Settings::default(),
            )
            .unwrap(),
        ),
        (
            "cone",
            revolve::build(
                &RevolveInput::new(vec![[1.0, 0.0], [0.0, 2.0]]),
                &Settings::default(),
            )
            .unwrap(),
        ),
    ];
    for (name, s) in &surfaces {
        let r = relative_residual(s);
        eprintln!(
            "{name}: {} vertices, residual {r:.2e} x diagonal",
            s.mesh.num_vertices()
        );
        assert!(r <= 1e-10, "{name}: residual {r}");
        assert!(s.mesh.face_sizes().iter().all(|&n| n == 4));
        let report = check(&s.mesh);
        assert!(
            report.is_manifold() && report.is_consistently_oriented(),
            "{name}"
        );
    }
}

#[test]
fn every_frame_kind_with_scale_and_morph_interpolates_its_targets() {
    // A helix-like open trajectory; a square morphing into a diamond while growing.
    let trajectory: Vec<[f64; 3]> = (0..=24)
        .map(|i| {
            let t = TAU * i as f64 / 24.0;
            [2.0 * t.cos(), 2.0 * t.sin(), 0.4 * t]
        })
        .collect();
    let square = vec![[-0.3, -0.3], [0.3, -0.3], [0.3, 0.3], [-0.3, 0.3]];
    let diamond = vec![[0.0, -0.4], [0.4, 0.0], [0.0, 0.4], [-0.4, 0.0]];
    for frame in ["fixed", "frenet", "rmf"] {
        let json = format!(
            r#"{{"profile": {square:?}, "closed_profile": true, "trajectory": {:?}, "frame": "{frame}",
                "scale": [1, 1.5], "profile_end": {diamond:?}, "samples_profile": 8, "samples_trajectory": 24}}"#,
            if frame == "fixed" {
                &trajectory[..3]
            } else {
                &trajectory[..]
            }
        );
        let (input, settings) =
            SweepInput::from_json(&json, std::path::Path::new("t.json")).unwrap();
        let s = sweep::build(&input, &settings).unwrap();
        assert!(relative_residual(&s) <= 1e-10, "{frame}");
        // Four crease lines along the sweep, one per profile corner.
        assert_eq!(s.mesh.creases().len(), 4 * 24, "{frame}");
        // The last ring is the diamond scaled by 1.5 (corners at distance 0.6 from the axis).
        let last = &s.targets[s.targets.len() - 8..];
        let end = input
            .trajectory
            .last()
            .map(|&p| glam::DVec3::from(p))
            .unwrap();
        for (k, p) in last.iter().enumerate().step_by(2) {
            assert!(
                (p.distance(end) - 0.6).abs() < 1e-9,
                "{frame}: corner {k} at {}",
                p.distance(end)
            );
        }
    }
}
