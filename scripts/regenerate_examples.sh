#!/usr/bin/env bash
# Rewrites every bundled example's OBJ and data points (examples/profiles/, examples/sweeps/,
# examples/curves/, examples/blends/)
# with the release CLI, as tests/profile_examples.rs and tests/sweep_examples.rs expect and
# tests/example_bytes.rs checks byte for byte. Usage: scripts/regenerate_examples.sh [PROFSUBD]
# (PROFSUBD: the binary to run, default target/release/profsubd, built if missing).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BIN="${1:-target/release/profsubd}"
[ -x "$BIN" ] || cargo build --release --bin profsubd
for json in examples/profiles/*.json examples/sweeps/*.json; do
    base="${json%.json}"
    case "$json" in
        examples/profiles/*) cmd=profile ;;
        # A revolution has a profile and no trajectory.
        *) if grep -q '"trajectory"' "$json"; then cmd=sweep; else cmd=revolve; fi ;;
    esac
    "$BIN" "$cmd" "$json" -o "$base.obj" --targets "$base.targets.txt"
done
for json in examples/curves/*.json; do
    base="${json%.json}"
    "$BIN" curves "$json" -o "$base.obj" --targets "$base.targets.txt"
done
for json in examples/blends/*.json; do
    base="${json%.json}"
    "$BIN" blend "$json" -o "$base.obj" --targets "$base.targets.txt"
done
