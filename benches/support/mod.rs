//! The bench model shared by the benches: the bundled bottle example (extraordinary vertices
//! of valence 3 at its pole caps, a crease ring at its shoulder, a flat-capped base) at a
//! chosen sampling.

use std::path::Path;

use profsubd::construct::profile::{build, ProfileInput, ProfileModel};

/// The bottle of `examples/profiles/bottle.json` sampled `around × along`.
pub fn bottle(around: u32, along: u32) -> ProfileModel {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("examples/profiles/bottle.json");
    let text = std::fs::read_to_string(&path).expect("examples/profiles/bottle.json");
    let mut input = ProfileInput::from_json(&text, &path).expect("bottle input");
    input.around = around;
    input.along = along;
    build(&input).expect("bottle model")
}
