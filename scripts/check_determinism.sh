#!/usr/bin/env bash
# Same bytes on every CPU: runs the release CLI on every bundled example (profiles, sweeps,
# sketch curves, blends) natively and under
# QEMU user-mode emulation of CPUs with fewer SIMD features (qemu64: SSE2 only, no AVX, no FMA;
# Haswell: AVX2 + FMA, no AVX-512), so every runtime-dispatched kernel (ours, the C library's
# libm variants, any dependency's) takes a different path; each output must equal the
# committed file byte for byte. Installs qemu-user when run as root and it is missing.
# Usage: scripts/check_determinism.sh [PROFSUBD] (default target/release/profsubd).
set -euo pipefail
cd "$(dirname "${BASH_SOURCE[0]}")/.."
BIN="${1:-target/release/profsubd}"
[ -x "$BIN" ] || cargo build --release --bin profsubd
if ! command -v qemu-x86_64 >/dev/null && [ "$(id -u)" -eq 0 ] && command -v apt-get >/dev/null; then
    DEBIAN_FRONTEND=noninteractive apt-get install -y --no-install-recommends qemu-user >/dev/null
fi
runners=("native")
if [ "$(uname -m)" = x86_64 ] && command -v qemu-x86_64 >/dev/null; then
    runners+=("qemu-x86_64 -cpu qemu64" "qemu-x86_64 -cpu Haswell")
else
    echo "qemu-x86_64 not available: native run only" >&2
fi
# Every bundled example, as tests/example_bytes.rs runs them natively.
examples=(examples/profiles/*.json examples/sweeps/*.json examples/curves/*.json examples/blends/*.json)
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
failed=0
for runner in "${runners[@]}"; do
    prefix=()
    [ "$runner" = native ] || read -r -a prefix <<<"$runner"
    for json in "${examples[@]}"; do
        base="${json%.json}"
        case "$json" in
            examples/profiles/*) cmd=profile ;;
            examples/curves/*) cmd=curves ;;
            examples/blends/*) cmd=blend ;;
            *) if grep -q '"trajectory"' "$json"; then cmd=sweep; else cmd=revolve; fi ;;
        esac
        # (QEMU warns about host-only CPUID bits it does not emulate: noise.)
        "${prefix[@]}" "$BIN" "$cmd" "$json" -o "$out/x.obj" --targets "$out/x.txt" >/dev/null \
            2> >(grep -v "TCG doesn't support requested feature" >&2)
        for pair in "x.obj:$base.obj" "x.txt:$base.targets.txt"; do
            if ! cmp -s "$out/${pair%%:*}" "${pair#*:}"; then
                echo "DIFFERS under $runner: ${pair#*:}"
                failed=1
            fi
        done
    done
    echo "$runner: ${#examples[@]} examples compared"
done
[ "$failed" -eq 0 ] && echo "determinism: every example byte-identical under: ${runners[*]}"
exit "$failed"
