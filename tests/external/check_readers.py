"""Reads profsubd's outputs with independent readers: Pixar's USD (usd-core), trimesh and
OpenSCAD. Called by tests/external_readers.rs with a work folder holding `cases.json`
(written by the Rust test: expected arrays and coordinates). Exits non-zero on the first
mismatch, with a message."""

import json
import os
import subprocess
import sys

import numpy as np
import trimesh
from pxr import Usd, UsdGeom


def fail(msg):
    print("MISMATCH:", msg)
    sys.exit(1)


def check_usd(case):
    path = case["usda"]
    stage = Usd.Stage.Open(path)
    if stage is None:
        fail(f"{path}: USD cannot open it")
    mesh = UsdGeom.Mesh(stage.GetDefaultPrim())
    if not mesh:
        fail(f"{path}: the default prim is not a Mesh")
    counts = list(mesh.GetFaceVertexCountsAttr().Get())
    indices = list(mesh.GetFaceVertexIndicesAttr().Get())
    points = np.array(mesh.GetPointsAttr().Get(), dtype=np.float64)
    ok, why = UsdGeom.Mesh.ValidateTopology(indices, counts, len(points))
    if not ok:
        fail(f"{path}: ValidateTopology: {why}")
    if UsdGeom.GetStageUpAxis(stage) != case["up"]:
        fail(f"{path}: upAxis {UsdGeom.GetStageUpAxis(stage)}")
    if counts != case["face_sizes"] or indices != case["face_indices"]:
        fail(f"{path}: faces differ")
    if not np.array_equal(points, np.array(case["points"], dtype=np.float32).astype(np.float64)):
        fail(f"{path}: points differ")
    if mesh.GetSubdivisionSchemeAttr().Get() != "catmullClark":
        fail(f"{path}: scheme")
    for attr, want in [
        (mesh.GetInterpolateBoundaryAttr(), case["boundary"]),
        (mesh.GetTriangleSubdivisionRuleAttr(), case["triangles"]),
    ]:
        if attr.Get() != want:
            fail(f"{path}: {attr.GetName()} {attr.Get()} != {want}")
    # Creases: expand chains into edges with their sharpness.
    ci = list(mesh.GetCreaseIndicesAttr().Get() or [])
    cl = list(mesh.GetCreaseLengthsAttr().Get() or [])
    cs = list(mesh.GetCreaseSharpnessesAttr().Get() or [])
    edges, start = [], 0
    for k, n in enumerate(cl):
        chain = ci[start:start + n]
        s = cs[k] if len(cs) == len(cl) else None
        for a, b in zip(chain, chain[1:]):
            edges.append([a, b, s if s is not None else cs[len(edges)]])
        start += n
    want = [[a, b, np.float32(s)] for a, b, s in case["creases"]]
    if edges != want:
        fail(f"{path}: creases {edges[:4]}... != {want[:4]}...")
    corners = list(mesh.GetCornerIndicesAttr().Get() or [])
    corner_s = [np.float32(s) for s in (mesh.GetCornerSharpnessesAttr().Get() or [])]
    if corners != [c[0] for c in case["corners"]] or corner_s != [np.float32(c[1]) for c in case["corners"]]:
        fail(f"{path}: corners")
    if list(mesh.GetHoleIndicesAttr().Get() or []) != case["holes"]:
        fail(f"{path}: holes")
    extent = np.array(mesh.GetExtentAttr().Get(), dtype=np.float64)
    computed = UsdGeom.PointBased.ComputeExtent(mesh.GetPointsAttr().Get())
    if not np.array_equal(extent, np.array(computed, dtype=np.float64)):
        fail(f"{path}: extent {extent} != {computed}")
    custom = stage.GetDefaultPrim().GetCustomDataByKey("profsubdCreaseMethod")
    if custom != case["crease_method"]:
        fail(f"{path}: crease method custom data {custom}")
    # USD's own writer: profsubd reads this back (checked by the Rust test).
    stage.Export(case["usda_exported"])


def check_surface(case):
    positions = np.array(case["positions"], dtype=np.float64)
    faces = case["faces"]
    tris = np.array(case["triangles"], dtype=np.int64)
    for fmt in ["off", "ply"]:
        path = case[fmt]
        m = trimesh.load(path, process=False)
        if not np.array_equal(np.asarray(m.vertices, dtype=np.float64), positions):
            fail(f"{path}: coordinates differ")
        if all(len(f) == 3 for f in faces) and m.faces.tolist() != faces:
            fail(f"{path}: faces differ")
        if fmt == "ply" and not np.allclose(np.linalg.norm(m.vertex_normals, axis=1), 1.0):
            fail(f"{path}: normals are not unit")
    for fmt in ["stl", "stl_ascii"]:
        path = case[fmt]
        m = trimesh.load(path, process=False)
        if len(m.faces) != len(tris):
            fail(f"{path}: {len(m.faces)} triangles, expected {len(tris)}")
        got = np.asarray(m.vertices, dtype=np.float64)[np.asarray(m.faces)]
        want = positions[tris]
        if fmt == "stl":
            want = want.astype(np.float32).astype(np.float64)
        if not np.array_equal(got, want):
            fail(f"{path}: coordinates differ (max {np.abs(got - want).max()})")
        merged = trimesh.load(path)
        if case["closed"] and not (merged.is_watertight and merged.is_winding_consistent):
            fail(f"{path}: trimesh does not find it watertight and consistently wound")
        if case["closed"] and merged.euler_number != case["euler"]:
            fail(f"{path}: Euler number {merged.euler_number} != {case['euler']}")
    if case["closed"]:
        for fmt in ["off", "stl"]:
            scad = os.path.join(case["dir"], f"import_{fmt}.scad")
            out = os.path.join(case["dir"], f"openscad_{fmt}.stl")
            with open(scad, "w") as f:
                f.write(f'import("{os.path.basename(case[fmt])}");\n')
            r = subprocess.run(["openscad", "-o", out, scad], capture_output=True, text=True)
            if r.returncode != 0 or not os.path.exists(out):
                fail(f"openscad on {case[fmt]}: exit {r.returncode}: {r.stderr}")
            back = trimesh.load(out)
            if len(back.faces) == 0 or abs(back.volume - case["volume"]) > 1e-3 * abs(case["volume"]):
                fail(f"openscad on {case[fmt]}: volume {back.volume} != {case['volume']}")


def main():
    work = sys.argv[1]
    with open(os.path.join(work, "cases.json")) as f:
        cases = json.load(f)
    for case in cases["usd"]:
        check_usd(case)
    for case in cases["surface"]:
        check_surface(case)
    print(f"ok: {len(cases['usd'])} USD files, {len(cases['surface'])} tessellations")


main()
