#!/usr/bin/env bash
# The undulation measure's limit bending energy against OpenSubdiv: profsubd's fold_free
# test `bending_energy_cases_for_bfr` builds the examples, a sphere and capped partial turns
# (flat-based bottle, goblet), writes each mesh and the library's limit energy
# ∫ (κ₁² + κ₂²) dA (SurfaceReport::limit_bending_energy), and cpp_tests/bending_energy
# integrates the same energy by Gauss quadrature of Bfr's second derivatives and compares
# (relative tolerance 0.02, 0.25 on the two least fair wedges: see the test).
# Usage: scripts/bending_energy.sh [BUILD_DIR]  (default: build, configured as in README)
set -euo pipefail
cd "$(dirname "$0")/.."
build="${1:-build}"
dir="$(mktemp -d)"
trap 'rm -rf "$dir"' EXIT
PROFSUBD_ENERGY_DIR="$dir" cargo test --release --test fold_free -- --ignored --nocapture \
    bending_energy_cases_for_bfr
cmake --build "$build" --target bending_energy -j2
"$build/cpp_tests/bending_energy" --compare "$dir/energies.tsv"
