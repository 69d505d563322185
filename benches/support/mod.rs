//! The bench model shared by the benches: the bundled bottle example (extraordinary vertices
//! of valence 3 at its pole caps, a crease ring at its shoulder, a flat-capped base) at a
//! chosen sampling.

use std::path::Path;

use profsubd::construct::settings::read_json;
use profsubd::eval::Evaluator;
use profsubd::profile::{build, ProfileInput};
use profsubd::Fitted;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// The bottle of `examples/profiles/bottle.json` sampled `around × along`.
pub fn bottle(around: u32, along: u32) -> Fitted {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/profiles/bottle.json");
    let (mut input, settings) = read_json::<ProfileInput>(&path).expect("bottle input");
    input.around = around;
    input.along = along;
    build(&input, &settings).expect("bottle model")
}

/// `n` random points (face, u, v) of `ev`'s parametric faces, the same for every bench (seed 7).
// Each bench compiles this module on its own; the profile bench draws no points.
#[allow(dead_code)]
pub fn random_points(ev: &Evaluator, n: usize) -> (Vec<u32>, Vec<f64>, Vec<f64>) {
    let mut rng = ChaCha8Rng::seed_from_u64(7);
    let faces: Vec<u32> = (0..n)
        .map(|_| rng.random_range(0..ev.num_parametric_faces() as u32))
        .collect();
    let us: Vec<f64> = (0..n).map(|_| rng.random::<f64>()).collect();
    let vs: Vec<f64> = (0..n).map(|_| rng.random::<f64>()).collect();
    (faces, us, vs)
}
