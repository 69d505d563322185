#!/bin/bash
# Blends of N = 3..8 evenly spread pipes (radius 1, four columns, α = k_α = 0.5, GBS level 1)
# at orders 3, 4 and 6: for each, the distance between the GBS and Catmull-Clark limit
# surfaces (max and mean x diagonal, as `profsubd blend` prints it), whether the
# Catmull-Clark result folds (`profsubd check --surface`) and its highest valence.
#   bash scripts/measure_blends.sh [PROFSUBD [OTHER_PROFSUBD]]
# With a second binary (e.g. one built from an older commit) each row shows both, "this / other".
set -euo pipefail
bin=${1:-target/release/profsubd}
other=${2:-}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT

# Prints "max M, mean A | folds F | highest valence V" for binary $1 on input $2.
measure() {
    local out=$dir/out.obj
    local fit
    fit=$("$1" blend "$2" -o "$out" | grep -o 'max [0-9.e-]*, mean [0-9.e-]*')
    local folds=no
    "$1" check --surface "$out" > "$dir/check.txt" 2>&1 || folds="yes (exit $?)"
    local valence
    valence=$(grep -m1 -o 'valences: .*' "$dir/check.txt" | grep -o '[0-9]*:' | tr -d : | sort -n | tail -1)
    echo "$fit | $folds | $valence"
}

echo "| N | k | distance (max, mean) | folds | highest valence |"
echo "| --- | --- | --- | --- | --- |"
for n in 3 4 5 6 7 8; do
    for k in 3 4 6; do
        input=$dir/star${n}_k$k.json
        python3 - "$n" "$k" > "$input" <<'PY'
import json, math, sys
n, k = int(sys.argv[1]), int(sys.argv[2])
d = 1.2 / math.sin(math.pi / n)
pipes = []
for i in range(n):
    a = 2 * math.pi * i / n + 0.1
    u = [round(math.cos(a), 9), round(math.sin(a), 9), 0.0]
    pipes.append({"end": [d * u[0], d * u[1], 0.0], "axis": u, "radius": 1.0, "length": 4.0})
print(json.dumps({"pipes": pipes, "order": k}))
PY
        IFS='|' read -r fit folds valence <<< "$(measure "$bin" "$input")"
        if [ -n "$other" ]; then
            IFS='|' read -r ofit ofolds ovalence <<< "$(measure "$other" "$input")"
            echo "| $n | $k | ${fit% } / ${ofit# } |${folds}/${ofolds}|${valence} / ${ovalence# } |"
        else
            echo "| $n | $k | ${fit% } |${folds}|${valence} |"
        fi
    done
done
