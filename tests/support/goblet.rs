//! A goblet's revolution profile for the fold tests: `mod goblet;` via
//! `#[path = "support/goblet.rs"]`.

/// A goblet: a wide flat foot (radius 3, 0.08 to 0.25 thick) with a smooth pole at its
/// centre, a thin stem (radius 0.1) and a solid bowl closed by a pole.
pub fn goblet() -> Vec<[f64; 2]> {
    vec![
        [0.0, 0.0],
        [3.0, 0.0],
        [3.05, 0.08],
        [0.4, 0.25],
        [0.12, 0.6],
        [0.1, 2.5],
        [0.3, 3.2],
        [1.4, 3.8],
        [2.0, 5.0],
        [2.1, 6.0],
        [0.0, 5.9],
    ]
}
