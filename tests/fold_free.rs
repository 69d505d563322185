//! Valid surfaces (issue #10): the fitted limit surfaces of the examples and of generated
//! spheres, ellipsoids, flat-based bottles and flat-footed goblets do not fold (the library's
//! fold check, `eval::folds`), stay close to their design surfaces between the data points
//! and are about as fair as them (`construct::design`).
// Reference geometry for tolerance checks: the platform's libm is fine here.
#![allow(clippy::disallowed_methods)]

#[path = "support/arc.rs"]
mod arc;
#[path = "support/goblet.rs"]
mod goblet;
#[path = "support/random_profile.rs"]
mod random_profile;

use std::path::PathBuf;

use arc::semicircle;
use goblet::goblet;
use profsubd::construct::design::SurfaceReport;
use profsubd::construct::settings::read_json;
use profsubd::profile::{build, shapes::ellipsoid, ProfileInput};
use profsubd::RevolveInput;
use profsubd::SweepInput;
use profsubd::{revolve, sweep, Settings};
use random_profile::RandomProfiles;

/// Samplings from 16 × 8 to 128 × 64 (around × along).
const SAMPLINGS: [(usize, usize); 4] = [(16, 8), (32, 16), (64, 32), (128, 64)];

fn example(dir: &str, name: &str) -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join(format!("examples/{dir}/{name}.json"))
}

/// Print `r`; assert no folds and a largest design distance below `max_distance`.
fn assert_unfolded(name: &str, r: &SurfaceReport, max_distance: f64) {
    println!(
        "{name}: folded {} (worst reversal {:.1}°), design distance max {:.2e} mean {:.2e}, \
         undulation {:.3}",
        r.folded_faces,
        r.worst_reversal_deg,
        r.max_design_distance,
        r.mean_design_distance,
        r.undulation
    );
    assert_eq!(r.folded_faces, 0, "{name}: {r:?}");
    assert!(r.worst_reversal_deg < 90.0, "{name}: {r:?}");
    assert!(r.max_design_distance < max_distance, "{name}: {r:?}");
}

/// [`assert_unfolded`], and a mean design distance below a tenth of `max_distance`.
fn assert_valid(name: &str, r: &SurfaceReport, max_distance: f64) {
    assert_unfolded(name, r, max_distance);
    assert!(r.mean_design_distance < 0.1 * max_distance, "{name}: {r:?}");
}

#[test]
fn examples_do_not_fold_and_follow_their_design() {
    for name in ["bottle", "vase", "mouse", "spinning_top"] {
        let (input, settings) = read_json::<ProfileInput>(&example("profiles", name)).unwrap();
        let model = build(&input, &settings).unwrap();
        let r = model.surface_report().unwrap();
        assert_valid(name, r, 3e-3);
        assert!((0.9..1.1).contains(&r.undulation), "{name}: {r:?}");
    }
    let path = example("sweeps", "wine_glass");
    let text = std::fs::read_to_string(&path).unwrap();
    let glass = {
        let (input, settings) = RevolveInput::from_json(&text, &path).unwrap();
        revolve::build(&input, &settings).unwrap()
    };
    let r = glass.surface_report().unwrap();
    assert_valid("wine_glass", r, 1e-3);
    assert!((0.9..1.1).contains(&r.undulation), "{r:?}");
    for name in ["handrail", "torus_knot_tube"] {
        let path = example("sweeps", name);
        let text = std::fs::read_to_string(&path).unwrap();
        let s = {
            let (input, settings) = SweepInput::from_json(&text, &path).unwrap();
            sweep::build(&input, &settings).unwrap()
        };
        assert_valid(name, s.surface_report().unwrap(), 5e-3);
    }
}

#[test]
fn ellipsoids_of_several_aspect_ratios_do_not_fold() {
    for (a, b, c) in [
        (1.0, 1.0, 1.0),
        (2.0, 1.0, 1.5),
        (3.0, 2.0, 0.75),
        (1.0, 1.0, 5.0),
    ] {
        let mut previous = f64::INFINITY;
        // 128 x 64 is in the full matrix (tests/fold_matrix.rs, ignored in CI).
        for &(around, along) in &SAMPLINGS[..3] {
            let mut input = ellipsoid(a, b, c, 400);
            input.around = around as u32;
            input.along = along as u32;
            let model = build(&input, &Settings::default()).unwrap();
            let r = model.surface_report().unwrap();
            assert_valid(
                &format!("ellipsoid ({a}, {b}, {c}) {around}x{along}"),
                r,
                5e-3,
            );
            if around == 32 {
                assert!(r.max_design_distance < 1e-3, "{r:?}");
            }
            assert!(r.max_design_distance < previous, "{r:?}");
            previous = r.max_design_distance;
        }
    }
}

#[test]
fn spheres_and_goblets_by_revolution_do_not_fold() {
    // A goblet with a wide flat foot (a smooth pole at its centre), a thin stem and a bowl.
    for (name, profile) in [("sphere", semicircle(48)), ("goblet", goblet())] {
        for (around, along) in SAMPLINGS {
            let mut input = RevolveInput::new(profile.clone());
            input.samples_around = around;
            input.samples_profile = along * if name == "goblet" { 2 } else { 1 };
            let s = revolve::build(&input, &Settings::default()).unwrap();
            let r = s.surface_report().unwrap();
            assert_valid(&format!("{name} {around}x{along}"), r, 5e-3);
        }
    }
}

#[test]
fn capped_goblet_wedges_with_a_thin_stem_do_not_fold() {
    // The solid goblet's meridian caps at 32 x 16: every Coons and Winslow layout's limit
    // folded in the thin stem (14 faces, refused); the rung caps (`revolve::wedge`,
    // `CapLayout::Rungs`) have a ruled limit there, as close to the design and as fair as
    // the open turns.
    for angle in [90.0, 180.0, 270.0] {
        let mut input = RevolveInput::new(goblet());
        (input.angle_deg, input.samples_around, input.samples_profile) = (angle, 32, 32);
        let settings = Settings {
            caps: profsubd::Caps::Flat,
            ..Settings::default()
        };
        let r = revolve::build(&input, &settings)
            .unwrap()
            .surface_report()
            .unwrap()
            .clone();
        assert_valid(&format!("capped goblet {angle}° 32x16"), &r, 1e-3);
        assert!(r.undulation > 0.9 && r.undulation < 1.1, "{r:?}");
    }
}

#[test]
fn bottles_with_flat_bases_do_not_fold() {
    let (input, settings) = read_json::<ProfileInput>(&example("profiles", "bottle")).unwrap();
    for (around, along) in SAMPLINGS {
        let mut bottle: ProfileInput = input.clone();
        bottle.around = around as u32;
        bottle.along = along as u32 + 8;
        let model = build(&bottle, &settings).unwrap();
        assert_valid(
            &format!("bottle {around}x{}", along + 8),
            model.surface_report().unwrap(),
            5e-3,
        );
    }
}

#[test]
fn flat_meridian_caps_leave_the_undulation_of_the_open_turn() {
    // A flat-based bottle turned 90°, 180° and 270°: its flat meridian caps are planar (no
    // bending energy) and the side is that of the open turn, so the capped turn's undulation
    // is the open turn's. The lattice-difference estimate reversed normals in the caps'
    // skewed cells next to the axis: 29.9 to 87.6 at 32 x 16 against the open 0.98.
    let profile = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.8], [0.45, 2.5], [0.45, 3.2]];
    for angle in [90.0, 180.0, 270.0] {
        let undulation = |caps| {
            let mut input = RevolveInput::new(profile.clone());
            (input.angle_deg, input.samples_around, input.samples_profile) = (angle, 32, 16);
            let settings = Settings {
                caps,
                ..Settings::default()
            };
            let s = revolve::build(&input, &settings).unwrap();
            s.surface_report().unwrap().undulation
        };
        let (open, capped) = (
            undulation(profsubd::Caps::Open),
            undulation(profsubd::Caps::Flat),
        );
        println!("bottle {angle}° 32x16: undulation open {open:.4}, capped {capped:.4}");
        assert!((0.9..1.1).contains(&open), "{open}");
        assert!(
            (capped / open - 1.0).abs() < 1e-3,
            "{angle}°: {capped} {open}"
        );
    }
}

#[test]
fn random_full_turn_revolutions_do_not_fold() {
    // The generator of `sweep_wedge`'s random-profile test, full turns only, fitted: every
    // profile that is accepted gives a limit surface without folds.
    let mut random = RandomProfiles::new();
    let mut built = 0;
    for _ in 0..60 {
        let pts = random.profile();
        let mut input = RevolveInput::new(pts);
        let mut settings = Settings::default();
        if random.next() < 0.5 {
            settings.caps = profsubd::Caps::Flat;
        }
        input.samples_around = 4 * (2 + (random.next() * 6.0) as usize);
        input.samples_profile = 4 + (random.next() * 28.0) as usize;
        let Ok(s) = revolve::build(&input, &settings) else {
            continue;
        };
        let r = s.surface_report().unwrap();
        assert_eq!(r.folded_faces, 0, "{input:?}: {r:?}");
        built += 1;
    }
    assert!(built > 30, "{built}");
}

#[test]
fn partial_vase_revolutions_with_flat_caps_do_not_fold() {
    // Flat ends (sectors), two flat meridian caps and a neck: a crease ring where the
    // profile turns towards the axis, whose meridian-cap corner spans a reflex angle.
    let path = example("sweeps", "vase_cutaway");
    let text = std::fs::read_to_string(&path).unwrap();
    let (input, settings) = RevolveInput::from_json(&text, &path).unwrap();
    let r = revolve::build(&input, &settings)
        .unwrap()
        .surface_report()
        .unwrap()
        .clone();
    println!(
        "vase_cutaway: folded {}, design distance max {:.2e} mean {:.2e}",
        r.folded_faces, r.max_design_distance, r.mean_design_distance
    );
    assert_eq!(r.folded_faces, 0, "{r:?}");
    for angle in [90.0, 180.0, 270.0] {
        for (around, along) in [(16, 16), (32, 32)] {
            let mut vase = input.clone();
            (vase.angle_deg, vase.samples_around, vase.samples_profile) = (angle, around, along);
            let r = revolve::build(&vase, &settings)
                .unwrap()
                .surface_report()
                .unwrap()
                .clone();
            println!("vase {angle}° {around}x{along}: folded {}", r.folded_faces);
            assert_eq!(r.folded_faces, 0, "{angle} {around}x{along}: {r:?}");
            assert!(r.worst_reversal_deg < 90.0, "{r:?}");
        }
    }
}

#[test]
fn wine_glass_cutaway_does_not_fold() {
    // 244 folded faces before the pole sectors were deepened, the meridian caps' layout chosen
    // by shape and their reflex corners split; 4 (the first face of each pole sector half at
    // the two apexes, a 270° span between two creases) before the pole sectors' bisectors were
    // creased along the whole middle meridian.
    let path = example("sweeps", "wine_glass_cutaway");
    let text = std::fs::read_to_string(&path).unwrap();
    let s = {
        let (input, settings) = RevolveInput::from_json(&text, &path).unwrap();
        revolve::build(&input, &settings).unwrap()
    };
    let r = s.surface_report().unwrap();
    assert_valid("wine_glass_cutaway", r, 1e-3);
    assert!((0.9..1.1).contains(&r.undulation), "{r:?}");
}

/// Capped partial turns of `profile` at 90°, 180° and 270°, at each sampling of `samplings`
/// (around × profile intervals): no folds, within `max_distance` of the design surface, an
/// undulation between 0.8 and `max_undulation`, and
/// closer at each finer sampling if `falling` (else at the finest than at the coarsest).
/// Returns the largest distance at 32 × 16 (if sampled).
fn assert_capped_wedges(
    name: &str,
    profile: &[[f64; 2]],
    samplings: &[(usize, usize)],
    max_distance: f64,
    max_undulation: f64,
    falling: bool,
) -> f64 {
    let mut at_32x16 = 0.0f64;
    for angle in [90.0, 180.0, 270.0] {
        let (mut previous, mut first) = (f64::INFINITY, None);
        for &(around, along) in samplings {
            let mut input = RevolveInput::new(profile.to_vec());
            let settings = Settings {
                caps: profsubd::Caps::Flat,
                ..Settings::default()
            };
            (input.angle_deg, input.samples_around, input.samples_profile) = (angle, around, along);
            let label = format!("{name} {angle}° {around}x{along}");
            let s = revolve::build(&input, &settings).unwrap();
            let r = s.surface_report().unwrap();
            assert_unfolded(&label, r, max_distance);
            assert!(
                (0.8..max_undulation).contains(&r.undulation),
                "{label}: {r:?}"
            );
            assert!(
                !falling || r.max_design_distance < previous,
                "{label}: {r:?}"
            );
            previous = r.max_design_distance;
            first.get_or_insert(previous);
            if (around, along) == (32, 16) {
                at_32x16 = at_32x16.max(r.max_design_distance);
            }
        }
        assert!(previous < 0.5 * first.unwrap_or(0.0), "{name} {angle}°");
    }
    at_32x16
}

#[test]
fn capped_sphere_wedges_do_not_fold() {
    // Partial turns of a profile touching the axis at both ends: each pole is closed by a
    // sector (two quarters of a grid cap) whose apex is an infinitely sharp corner where the
    // two meridian caps meet; 16, 12 and 8 folded faces at 90°, 180° and 270° (32 x 32)
    // before the sectors' interior vertices were placed as a grid cap's and their bisectors
    // creased.
    let d = assert_capped_wedges("sphere", &semicircle(48), &SAMPLINGS, 3e-3, 2.5, true);
    assert!(d < 1e-3, "{d}");
}

#[test]
fn capped_ellipsoid_wedges_do_not_fold() {
    // Below 1e-3 of the diagonal at 32 x 16 and closer at every finer sampling since the
    // pole sectors' radial lines follow the side's ring spacing (`revolve::sector_point`);
    // 1.7e-3 to 4.3e-3 at 32 x 16, and rising from 16 x 8 to 32 x 16, before. The prolate
    // 90° wedge's undulation is up to 2.8 (1.9 before).
    for (a, c) in [(2.0, 0.75), (1.0, 3.0), (1.0, 0.3)] {
        let profile: Vec<[f64; 2]> = semicircle(48)
            .iter()
            .map(|p| [a * p[0], c * p[1]])
            .collect();
        let d = assert_capped_wedges(
            &format!("ellipsoid ({a}, {a}, {c})"),
            &profile,
            &SAMPLINGS,
            3e-3,
            3.0,
            true,
        );
        assert!(d < 1e-3, "({a}, {a}, {c}): {d}");
    }
}

#[test]
fn random_partial_turns_are_fold_free_or_refused() {
    // The same generator, partial turns of 90°, 180° or 270°, open or with flat caps: every
    // turn built has no fold (its interpolating fit, or, where that folds, the refit with
    // faired pole sectors), and the rest are refused with InvalidArgument.
    let mut random = RandomProfiles::new();
    let (mut built, mut refused) = (0, Vec::new());
    for draw in 0..40 {
        let pts = random.profile();
        let mut input = RevolveInput::new(pts);
        input.angle_deg = [90.0, 180.0, 270.0][(random.next() * 3.0) as usize];
        let mut settings = Settings::default();
        if random.next() < 0.5 {
            settings.caps = profsubd::Caps::Flat;
        }
        input.samples_around = 4 * (2 + (random.next() * 6.0) as usize);
        input.samples_profile = 4 + (random.next() * 28.0) as usize;
        match revolve::build(&input, &settings) {
            Ok(s) => {
                let r = s.surface_report().unwrap();
                assert_eq!(r.folded_faces, 0, "{input:?}: {r:?}");
                built += 1;
            }
            Err(profsubd::Error::InvalidArgument(m)) => {
                println!("#{draw}: {m}");
                refused.push(draw);
            }
            Err(e) => panic!("{input:?}: {e}"),
        }
    }
    println!("built {built}, refused {refused:?}");
    // Since the pole runs widen and the sectors follow the side's spacing, every draw builds.
    assert!(refused.is_empty(), "built {built}, refused {refused:?}");
}

#[test]
#[ignore = "writes the cases of scripts/bending_energy.sh"]
fn bending_energy_cases_for_bfr() {
    // The examples, a sphere and the capped partial turns whose undulation the lattice
    // estimate once blew up: each fitted mesh to DIR/NAME.obj and its limit bending energy
    // with the relative tolerance to hold to DIR/energies.tsv, for OpenSubdiv's side
    // (cpp_tests/bending_energy.cpp, by quadrature of Bfr's second derivatives) to compare.
    // DIR: $PROFSUBD_ENERGY_DIR. Not the spinning top: its pointed tip is a cone point, where
    // the energy does not converge under quadrature (Bfr: 34.1 with 4 x 4 squares per face,
    // 36.6 with 8 x 8).
    let dir = PathBuf::from(std::env::var_os("PROFSUBD_ENERGY_DIR").expect("PROFSUBD_ENERGY_DIR"));
    std::fs::create_dir_all(&dir).unwrap();
    let mut cases: Vec<(String, profsubd::Fitted)> = Vec::new();
    for name in ["bottle", "vase", "mouse"] {
        let (input, settings) = read_json::<ProfileInput>(&example("profiles", name)).unwrap();
        cases.push((name.to_string(), build(&input, &settings).unwrap()));
    }
    for name in ["wine_glass", "vase_cutaway", "wine_glass_cutaway"] {
        let path = example("sweeps", name);
        let text = std::fs::read_to_string(&path).unwrap();
        let (input, settings) = RevolveInput::from_json(&text, &path).unwrap();
        cases.push((name.to_string(), revolve::build(&input, &settings).unwrap()));
    }
    for name in ["handrail", "torus_knot_tube"] {
        let path = example("sweeps", name);
        let text = std::fs::read_to_string(&path).unwrap();
        let (input, settings) = SweepInput::from_json(&text, &path).unwrap();
        cases.push((name.to_string(), sweep::build(&input, &settings).unwrap()));
    }
    let mut sphere = RevolveInput::new(semicircle(48));
    (sphere.samples_around, sphere.samples_profile) = (32, 16);
    cases.push((
        "sphere_32x16".to_string(),
        revolve::build(&sphere, &Settings::default()).unwrap(),
    ));
    let bottle = vec![[0.0, 0.0], [1.0, 0.0], [1.0, 1.8], [0.45, 2.5], [0.45, 3.2]];
    let capped = Settings {
        caps: profsubd::Caps::Flat,
        ..Settings::default()
    };
    for (shape, profile, angles, samplings) in [
        (
            "bottle",
            bottle,
            &[90.0, 180.0, 270.0][..],
            &[(32, 16), (64, 32)][..],
        ),
        ("goblet", goblet(), &[90.0, 270.0][..], &[(64, 64)][..]),
        // The least fair partial turns left (undulation 2.0 and 2.8 at 32 x 16).
        ("sphere", semicircle(48), &[90.0][..], &[(32, 16)][..]),
        (
            "spheroid_3",
            semicircle(48).iter().map(|p| [p[0], 3.0 * p[1]]).collect(),
            &[90.0][..],
            &[(32, 16)][..],
        ),
    ] {
        for &angle in angles {
            for &(around, along) in samplings {
                let mut input = RevolveInput::new(profile.clone());
                (input.angle_deg, input.samples_around, input.samples_profile) =
                    (angle, around, along);
                cases.push((
                    format!("{shape}_{angle}_capped_{around}x{along}"),
                    revolve::build(&input, &capped).unwrap(),
                ));
            }
        }
    }
    let mut table = String::new();
    for (name, fitted) in &cases {
        let r = fitted.surface_report().unwrap();
        assert_eq!(r.folded_faces, 0, "{name}: {r:?}");
        assert!(r.limit_bending_energy > 0.0, "{name}: {r:?}");
        let path = dir.join(format!("{name}.obj"));
        profsubd::io::obj::write_obj_file(&fitted.mesh, &path).unwrap();
        println!(
            "{name}: limit bending energy {:.6}, design {:.6}, undulation {:.4}",
            r.limit_bending_energy, r.design_bending_energy, r.undulation
        );
        // The lattice misses curvature varying inside the wedges' pole-sector faces (their
        // undulation, not the estimate's breakdown): 16% and 21% below Bfr's there.
        let tolerance = if name.starts_with("sph") { 0.25 } else { 0.02 };
        table += &format!(
            "{}\t{:.17e}\t{tolerance}\n",
            path.display(),
            r.limit_bending_energy
        );
    }
    std::fs::write(dir.join("energies.tsv"), table).unwrap();
}
