"""Between a `TaggedMesh` and a Blender object with a Subdivision Surface modifier.

Blender's modifier gives OpenSubdiv the sharpness 10·c² for an edge or vertex crease c, so a
tag of sharpness s becomes crease √(s/10) (`objtags.sharpness_to_crease`). What the file
says exactly (double coordinates, single-precision sharpness, file order, option tags) is
kept on the mesh as custom properties, so that export writes an unedited mesh back
unchanged and an edited one with the edits.
"""

import math

import bmesh
import bpy

from . import objtags

MODIFIER = "Subdivision (OpenSubdiv tags)"
HOLE_ATTRIBUTE = "profsubd_hole"


def to_blender_axes(p, up):
    """A file point in Blender's Z-up axes (`up` = the file's up axis, "Z" or "Y")."""
    x, y, z = p
    return (x, -z, y) if up == "Y" else (x, y, z)


def from_blender_axes(p, up):
    """A Blender point in the axes of a file with up axis `up`."""
    x, y, z = p
    return (x, z, -y) if up == "Y" else (x, y, z)


def _chaikin_matters(tagged):
    """Vertices where semi-sharp creases of different sharpness meet (Chaikin differs there)."""
    seen = {}
    for (a, b), s in tagged.creases:
        if 0.0 < s < objtags.INFINITE:
            for v in (a, b):
                seen.setdefault(v, set()).add(s)
    return sorted(v for v, values in seen.items() if len(values) > 1)


def limitations(tagged):
    """Warnings for what Blender's Subdivision Surface modifier cannot represent."""
    out = []
    if tagged.crease_method == "chaikin":
        where = _chaikin_matters(tagged)
        if where:
            out.append(
                f"Chaikin crease method: Blender decays creases uniformly; the surface differs "
                f"near {len(where)} vertices where semi-sharp creases of different sharpness meet "
                f"(first: {where[0]})"
            )
        else:
            out.append("Chaikin crease method: Blender decays creases uniformly (the same surface "
                       "here: no semi-sharp creases of different sharpness meet)")
    if tagged.boundary == objtags.BOUNDARY_NONE:
        out.append("boundary rule none: Blender has no such rule; boundary faces, which have no "
                   "limit surface in OpenSubdiv, are drawn with edge-and-corner")
    if tagged.holes:
        out.append(f"{len(tagged.holes)} hole faces: Blender's modifier has no holes; they stay "
                   f"faces, marked by the face attribute '{HOLE_ATTRIBUTE}' (written back on export)")
    if tagged.triangles == "smooth" and any(len(f) == 3 for f in tagged.faces):
        out.append("smooth triangle rule: Blender uses Catmull-Clark weights on triangles")
    return out


def _faces_per_edge(tagged):
    count = {}
    for f in tagged.faces:
        for i, a in enumerate(f):
            e = (min(a, f[i - 1]), max(a, f[i - 1]))
            count[e] = count.get(e, 0) + 1
    return count


def darts(tagged):
    """Interior vertices with exactly one infinitely sharp edge and no infinitely sharp corner.

    There OpenSubdiv's patches (and so Blender) use the smooth limit mask at their last
    isolation level: off by ~7e-6 x diagonal at Quality 10, more at lower levels
    (`profsubd check` lists them as the `dart` hazard)."""
    on_boundary = set()
    for (a, b), n in _faces_per_edge(tagged).items():
        if n == 1:
            on_boundary.update((a, b))
    sharp_edges = {}
    for (a, b), s in tagged.creases:
        if s >= objtags.INFINITE:
            sharp_edges.setdefault(a, set()).add(b)
            sharp_edges.setdefault(b, set()).add(a)
    sharp_corner = {v for v, s in tagged.corners if s >= objtags.INFINITE}
    return sorted(v for v, nb in sharp_edges.items()
                  if len(nb) == 1 and v not in on_boundary and v not in sharp_corner)


def auto_quality(tagged):
    """The modifier's Quality (Far's adaptive isolation level) for this mesh's limit surface.

    3 (Blender's default) where that is exact to single precision; 10 (the most Blender
    allows) with semi-sharp tags, darts or a one-face corner under the edge-only rule, where
    OpenSubdiv's patches approach the limit level by level (x diagonal at Quality 3 / 6 / 10:
    one-face corners of a 4 x 4 patch 7.0e-4 / 1.1e-5 / 1.6e-7, the darts of
    examples/meshes/cube_creased.obj 2.5e-3 / 2.0e-4 / 9.1e-6, integrations/blender/
    test_blender.py; OpenSubdiv's catmark_rook, creases up to sharpness 8, 2.3e-4 at 7 and
    1.0e-6 at 8 to 10; catmark_bishop 2.3e-6 at 7, 6.3e-7 at 10)."""
    if any(0.0 < s < objtags.INFINITE for _, s in tagged.creases + tagged.corners) or darts(tagged):
        return 10
    if tagged.boundary == objtags.BOUNDARY_EDGE_ONLY:
        faces_at = [0] * len(tagged.positions)
        for f in tagged.faces:
            for v in f:
                faces_at[v] += 1
        if any(n == 1 for n in faces_at):
            return 10
    return 3


def _boundary_smooth(boundary):
    return "ALL" if boundary == objtags.BOUNDARY_EDGE_ONLY else "PRESERVE_CORNERS"


def build_object(context, tagged, name, up="Z", levels=2, render_levels=3, quality=0):
    """A new object in the active collection for `tagged`; returns (object, warnings).
    `quality` 0: `auto_quality(tagged)`."""
    warnings = list(tagged.warnings) + limitations(tagged)
    me = bpy.data.meshes.new(name)
    positions = [to_blender_axes(p, up) for p in tagged.positions]
    me.from_pydata(positions, [], tagged.faces)
    me.update(calc_edges=True)
    if len(me.vertices) != len(positions) or len(me.polygons) != len(tagged.faces):
        raise objtags.ObjError("Blender changed the vertex or face count (degenerate faces?)")
    edge_index = {tuple(sorted(e.vertices)): e.index for e in me.edges}

    # Crease layers (bmesh creates them; the values are set on the mesh afterwards).
    bm = bmesh.new()
    bm.from_mesh(me)
    bm.edges.layers.crease.verify()
    if tagged.corners:
        bm.verts.layers.crease.verify()
    bm.to_mesh(me)
    bm.free()

    creases = [0.0] * len(me.edges)
    sharp = [False] * len(me.edges)
    for (a, b), s in tagged.creases:
        e = edge_index.get((min(a, b), max(a, b)))
        if e is None:
            raise objtags.ObjError(f"crease on vertices {a} {b}, which no face joins by an edge")
        creases[e] = objtags.sharpness_to_crease(s)
        sharp[e] = s >= objtags.INFINITE
    me.edges.foreach_set("crease", creases)
    me.edges.foreach_set("use_edge_sharp", sharp)
    if tagged.corners:
        values = [0.0] * len(me.vertices)
        for v, s in tagged.corners:
            values[v] = objtags.sharpness_to_crease(s)
        me.vertex_creases[0].data.foreach_set("value", values)
    if tagged.holes:
        attr = me.attributes.new(HOLE_ATTRIBUTE, "BOOLEAN", "FACE")
        flags = [False] * len(me.polygons)
        for h in tagged.holes:
            flags[h] = True
        attr.data.foreach_set("value", flags)

    # What the file said exactly, for export.
    me["profsubd_positions"] = [c for p in positions for c in p]
    me["profsubd_crease_edges"] = [i for (a, b), _ in tagged.creases for i in (a, b)]
    me["profsubd_crease_sharpness"] = [float(s) for _, s in tagged.creases]
    me["profsubd_corner_vertices"] = [v for v, _ in tagged.corners]
    me["profsubd_corner_sharpness"] = [float(s) for _, s in tagged.corners]
    me["profsubd_options"] = {
        "boundary": -1 if tagged.boundary is None else tagged.boundary,
        "crease_method": tagged.crease_method or "",
        "triangles": tagged.triangles or "",
    }

    # Smooth shading split at the sharp (infinitely sharp) edges only.
    me.polygons.foreach_set("use_smooth", [True] * len(me.polygons))
    me.use_auto_smooth = True
    me.auto_smooth_angle = math.pi
    me.update()

    obj = bpy.data.objects.new(name, me)
    context.collection.objects.link(obj)
    mod = obj.modifiers.new(MODIFIER, "SUBSURF")
    mod.subdivision_type = "CATMULL_CLARK"
    mod.levels = levels
    mod.render_levels = render_levels
    mod.quality = quality or auto_quality(tagged)
    mod.use_limit_surface = True
    mod.use_creases = True
    mod.boundary_smooth = _boundary_smooth(tagged.boundary)
    obj["profsubd_import_warnings"] = warnings
    return obj, warnings


def _stored(me, key, default):
    value = me.get(key)
    return default if value is None else list(value)


def tagged_from_object(obj, up="Z"):
    """The control mesh of `obj` (modifiers not applied) with its tags, as a `TaggedMesh`."""
    me = obj.data
    t = objtags.TaggedMesh()
    nv = len(me.vertices)
    co = [0.0] * (3 * nv)
    me.vertices.foreach_get("co", co)
    exact = _stored(me, "profsubd_positions", [])
    if len(exact) == 3 * nv:
        # Unedited coordinates (the same single-precision value) keep the file's double.
        co = [x if objtags.f32(x) == c else c for x, c in zip(exact, co)]
    t.positions = [from_blender_axes(co[3 * i : 3 * i + 3], up) for i in range(nv)]
    t.faces = [list(p.vertices) for p in me.polygons]

    edge_index = {tuple(sorted(e.vertices)): e.index for e in me.edges}
    creases = [0.0] * len(me.edges)
    if me.has_crease_edge:
        me.edges.foreach_get("crease", creases)
    pairs = _stored(me, "profsubd_crease_edges", [])
    done = set()
    for j, s in enumerate(_stored(me, "profsubd_crease_sharpness", [])):
        a, b = pairs[2 * j], pairs[2 * j + 1]
        e = edge_index.get((min(a, b), max(a, b)))
        if e is None or e in done:
            continue
        done.add(e)
        c = creases[e]
        if objtags.same_crease(c, s):
            t.creases.append(((a, b), s))
        elif c > 0.0:
            t.creases.append(((a, b), objtags.crease_to_sharpness(c)))
    for e in me.edges:
        if e.index not in done and creases[e.index] > 0.0:
            t.creases.append((tuple(e.vertices), objtags.crease_to_sharpness(creases[e.index])))

    corners = [0.0] * nv
    if me.has_crease_vertex:
        me.vertex_creases[0].data.foreach_get("value", corners)
    stored_v = _stored(me, "profsubd_corner_vertices", [])
    done = set()
    for v, s in zip(stored_v, _stored(me, "profsubd_corner_sharpness", [])):
        if v >= nv or v in done:
            continue
        done.add(v)
        if objtags.same_crease(corners[v], s):
            t.corners.append((v, s))
        elif corners[v] > 0.0:
            t.corners.append((v, objtags.crease_to_sharpness(corners[v])))
    t.corners += [(v, objtags.crease_to_sharpness(c)) for v, c in enumerate(corners)
                  if c > 0.0 and v not in done]

    attr = me.attributes.get(HOLE_ATTRIBUTE)
    if attr is not None and attr.domain == "FACE":
        flags = [False] * len(me.polygons)
        attr.data.foreach_get("value", flags)
        t.holes = [i for i, h in enumerate(flags) if h]

    options = dict(me.get("profsubd_options", {}))
    boundary = options.get("boundary", -1)
    mod = next((m for m in obj.modifiers if m.type == "SUBSURF"), None)
    if mod is not None and not (boundary == objtags.BOUNDARY_NONE and mod.boundary_smooth == "PRESERVE_CORNERS"):
        from_modifier = (objtags.BOUNDARY_EDGE_ONLY if mod.boundary_smooth == "ALL"
                         else objtags.BOUNDARY_EDGE_AND_CORNER)
        # A file without the tag meant edge-and-corner: keep it untagged while that holds.
        if not (boundary == -1 and from_modifier == objtags.BOUNDARY_EDGE_AND_CORNER):
            boundary = from_modifier
    t.boundary = None if boundary == -1 else boundary
    t.crease_method = options.get("crease_method") or None
    t.triangles = options.get("triangles") or None
    return t
