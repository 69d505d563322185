"""Render every example OBJ with the add-on: the limit surface (Subdivision Surface modifier,
imported with its tags) in grey, its creases as red (infinitely sharp) and orange
(semi-sharp) tubes, with Blender's Workbench engine, into PNG files.

    blender -b --factory-startup --python integrations/blender/render_examples.py -- OUT_DIR [OBJ ...]

(`scripts/render_examples` runs it for examples/ into docs/images/.) Without OBJ arguments
every OBJ under examples/ is rendered; the picture of examples/DIR/NAME.obj is OUT_DIR/NAME.png.
"""

import glob
import os
import sys

import bpy
from mathutils import Vector

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)

import profsubd_blender  # noqa: E402
from profsubd_blender import blender_mesh  # noqa: E402

WIDTH, HEIGHT = 640, 480
# View direction (from the model towards the camera) per example, Z up, and optionally a
# close-up (centre, width of the picture); default: a 3/4 view of the whole model from the
# front right and above.
VIEWS = {
    "torus_knot_tube": {"view": (0.35, -0.6, 1.0)},
    "handrail": {"view": (0.5, -1.0, 0.8), "focus": ((3.2, 0.0, 1.15), 0.9)},
    "vase_cutaway": {"view": (-0.4, -1.0, 0.45)},
    "wine_glass_cutaway": {"view": (-0.4, -1.0, 0.45)},
}
DEFAULT_VIEW = (1.0, -1.5, 0.8)
SURFACE = (0.72, 0.74, 0.78, 1.0)
INFINITE_CREASE = (0.85, 0.1, 0.08, 1.0)
SEMI_SHARP_CREASE = (0.95, 0.55, 0.05, 1.0)


def clear_scene():
    for o in list(bpy.data.objects):
        bpy.data.objects.remove(o, do_unlink=True)
    for block in (bpy.data.meshes, bpy.data.curves, bpy.data.cameras):
        for d in list(block):
            block.remove(d)


def setup_scene():
    scene = bpy.context.scene
    scene.render.engine = "BLENDER_WORKBENCH"
    scene.render.resolution_x, scene.render.resolution_y = WIDTH, HEIGHT
    scene.render.resolution_percentage = 100
    scene.render.film_transparent = False
    scene.render.image_settings.file_format = "PNG"
    scene.render.image_settings.color_mode = "RGB"
    scene.render.image_settings.compression = 100
    shading = scene.display.shading
    shading.light = "STUDIO"
    shading.color_type = "OBJECT"
    shading.show_cavity = False
    shading.show_object_outline = False
    shading.show_specular_highlight = True
    scene.display.render_aa = "8"
    if scene.world is None:
        scene.world = bpy.data.worlds.new("World")
    scene.world.color = (1.0, 1.0, 1.0)
    scene.view_settings.view_transform = "Standard"
    # No date, render time, host name ... in the PNG's metadata: same input, same bytes.
    for prop in scene.render.bl_rna.properties:
        if prop.identifier.startswith("use_stamp"):
            setattr(scene.render, prop.identifier, False)


def crease_curves(obj, name, select, color, radius):
    """A curve object of tubes along the evaluated mesh's edges for which select(crease)."""
    me = obj.evaluated_get(bpy.context.evaluated_depsgraph_get()).data
    creases = [0.0] * len(me.edges)
    if me.has_crease_edge:
        me.edges.foreach_get("crease", creases)
    curve = bpy.data.curves.new(name, "CURVE")
    curve.dimensions = "3D"
    curve.bevel_depth = radius
    curve.bevel_resolution = 2
    for e, c in zip(me.edges, creases):
        if select(c):
            spline = curve.splines.new("POLY")
            spline.points.add(1)
            for p, v in zip(spline.points, e.vertices):
                p.co = (*me.vertices[v].co, 1.0)
    if not curve.splines:
        bpy.data.curves.remove(curve)
        return None
    tube = bpy.data.objects.new(name, curve)
    tube.color = color
    bpy.context.collection.objects.link(tube)
    return tube


def frame(obj, view, focus=None):
    """An orthographic camera looking along -`view` that fits the evaluated object (or the
    close-up `focus` = (centre, width)); returns the picture's width in model units."""
    me = obj.evaluated_get(bpy.context.evaluated_depsgraph_get()).data
    direction = Vector(view).normalized()
    rotation = (-direction).to_track_quat("-Z", "Y")
    to_camera = rotation.to_matrix().transposed()
    pts = [to_camera @ v.co for v in me.vertices]
    lo = Vector([min(p[k] for p in pts) for k in range(3)])
    hi = Vector([max(p[k] for p in pts) for k in range(3)])
    cam_data = bpy.data.cameras.new("camera")
    cam_data.type = "ORTHO"
    if focus is None:
        centre = rotation.to_matrix() @ ((lo + hi) / 2)
        width = 1.12 * max(hi.x - lo.x, (hi.y - lo.y) * WIDTH / HEIGHT)
    else:
        centre, width = Vector(focus[0]), focus[1]
    cam_data.ortho_scale = width
    cam_data.clip_end = 10 * (hi - lo).length + 10
    cam = bpy.data.objects.new("camera", cam_data)
    bpy.context.collection.objects.link(cam)
    cam.location = centre + direction * (2 * (hi - lo).length + 1)
    cam.rotation_euler = rotation.to_euler()
    bpy.context.scene.camera = cam
    return width


def render(path, out_dir):
    clear_scene()
    name = os.path.splitext(os.path.basename(path))[0]
    obj, _ = profsubd_blender.import_file(bpy.context, path)
    mod = obj.modifiers[blender_mesh.MODIFIER]
    mod.levels = mod.render_levels = 3 if len(obj.data.polygons) <= 1000 else 2
    obj.color = SURFACE
    view = VIEWS.get(name, {})
    width = frame(obj, view.get("view", DEFAULT_VIEW), view.get("focus"))
    tube = 0.0025 * width
    crease_curves(obj, name + "_infinite", lambda c: c >= 1.0, INFINITE_CREASE, tube)
    crease_curves(obj, name + "_semi", lambda c: 0.0 < c < 1.0, SEMI_SHARP_CREASE, tube)
    out = os.path.join(out_dir, name + ".png")
    bpy.context.scene.render.filepath = out
    bpy.ops.render.render(write_still=True)
    print(f"rendered {os.path.relpath(path, ROOT)} -> {out}")
    return out


def main():
    args = sys.argv[sys.argv.index("--") + 1 :] if "--" in sys.argv else []
    if not args:
        raise SystemExit("usage: blender -b --python render_examples.py -- OUT_DIR [OBJ ...]")
    out_dir, files = args[0], args[1:]
    if not files:
        files = sorted(glob.glob(os.path.join(ROOT, "examples", "**", "*.obj"), recursive=True))
    names = [os.path.splitext(os.path.basename(f))[0] for f in files]
    if len(set(names)) != len(names):
        raise SystemExit("two examples share a file name; the pictures would overwrite each other")
    os.makedirs(out_dir, exist_ok=True)
    profsubd_blender.register()
    setup_scene()
    for f in files:
        render(f, out_dir)


main()
