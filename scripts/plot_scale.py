#!/usr/bin/env python3
"""Plot `bench_eval --scale` output: time per face against faces, profsubd beside OpenSubdiv.

    build/cpp_tests/bench_eval --scale | tee docs/scale.txt
    python3 scripts/plot_scale.py docs/scale.txt docs/images/scale.png

Reads the `row` lines (family, faces, then build / update / evaluation / refinement times in
ms for profsubd and OpenSubdiv, with ratios) and draws four panels, log-log: build, position
update and uniform refinement in microseconds per face, evaluation in nanoseconds per point
(the same number of random points at every size, read from the header line). Linear cost is a
flat line. A part that failed (out of memory under `prlimit`) or was skipped is `nan` and left
out of the plot. Installs matplotlib with pip if it is missing.
"""
import math
import subprocess
import sys


def matplotlib_pyplot():
    try:
        import matplotlib
    except ImportError:
        subprocess.check_call(
            [sys.executable, "-m", "pip", "install", "--quiet", "--break-system-packages", "matplotlib"]
        )
        import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def read_rows(path):
    """The number of random points, and {family: [(faces, {quantity: (profsubd ms,
    OpenSubdiv ms)})]} from the `row` lines."""
    rows, points = {}, None
    with open(path, encoding="utf-8") as f:
        for line in f:
            if line.startswith("scale:"):
                points = int(line.split(" random points")[0].split()[-1])
            if not line.startswith("row "):
                continue
            cells = line.replace("|", " ").split()
            if not cells[2].isdigit():
                continue  # the column header
            family, faces = cells[1], int(cells[2])
            v = [float(x) for x in cells[3:]]
            if all(math.isnan(x) for x in v):
                continue  # every part of the row failed or was skipped
            times = {
                "build": (v[0], v[1]),
                "update": (v[3], v[4]),
                "evaluate": (v[6], v[7]),
                "refine": (v[9], v[10]),
            }
            rows.setdefault(family, []).append((faces, times))
    return points, rows


def main():
    if len(sys.argv) != 3:
        sys.exit("usage: plot_scale.py SCALE_OUTPUT.txt OUT.png")
    points, rows = read_rows(sys.argv[1])
    if not rows or not points:
        sys.exit(f"{sys.argv[1]}: no `row` lines (run bench_eval --scale)")
    plt = matplotlib_pyplot()
    panels = [
        ("build", "evaluator build vs Far adaptive + PatchTable + PatchMap", "µs per face", 1e3, "faces"),
        ("update", "position update vs Far stencils (UpdateValues)", "µs per face", 1e3, "faces"),
        ("evaluate", "random points vs PatchTable + PatchMap", "ns per point", None, "points"),
        ("refine", "uniform refinement to level 1 vs Far", "µs per face", 1e3, "faces"),
    ]
    fig, axes = plt.subplots(2, 2, figsize=(12, 8.5))
    colours = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    for ax, (key, title, unit, scale, _) in zip(axes.flat, panels):
        for k, (family, data) in enumerate(sorted(rows.items())):
            faces = [f for f, _ in data]
            for side, style, label in ((0, "-o", "profsubd"), (1, "--s", "OpenSubdiv")):
                if scale is None:
                    y = [t[key][side] * 1e6 / points for _, t in data]
                else:
                    y = [t[key][side] * scale / f for f, t in data]
                ax.plot(faces, y, style, color=colours[k % len(colours)], label=f"{label} {family}", markersize=4)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("faces")
        ax.set_ylabel(unit)
        ax.grid(True, which="both", alpha=0.3)
    axes.flat[0].legend(fontsize=7, ncol=2)
    fig.suptitle("bench_eval --scale: cost per face against mesh size (one thread each side; flat = linear)")
    fig.tight_layout()
    fig.savefig(sys.argv[2], dpi=90)
    print(f"wrote {sys.argv[2]}")


if __name__ == "__main__":
    main()
