"""profsubd for Blender: OBJ files with OpenSubdiv tags in and out, and profile models.

File ▸ Import ▸ "OpenSubdiv OBJ (.obj with tags)" reads profsubd's OBJ files (and
OpenSubdiv's regression shapes) with their `t` tag lines into edge and vertex creases and a
Subdivision Surface modifier set to reproduce OpenSubdiv's limit surface; File ▸ Export
writes the tags back; Add ▸ Mesh ▸ "profsubd Profile Model" builds a model from profile
curves through the `profsubd` Python package.
"""

bl_info = {
    "name": "profsubd: OpenSubdiv OBJ with tags, profile models",
    "author": "profsubd contributors",
    "version": (0, 1, 0),
    "blender": (3, 4, 0),
    "location": "File > Import/Export > OpenSubdiv OBJ (.obj with tags); Add > Mesh > profsubd Profile Model",
    "description": "Creases, corners and boundary rule of OpenSubdiv OBJ files on the "
    "Subdivision Surface modifier; models from profile curves through the profsubd package",
    "category": "Import-Export",
}

import json
import os
import sys
import tempfile

import bpy
from bpy.props import EnumProperty, IntProperty, StringProperty
from bpy_extras.io_utils import ExportHelper, ImportHelper

from . import blender_mesh, objtags

UP_AXIS_ITEMS = (
    ("Z", "Z up", "Coordinates as they are (profsubd's files are Z up, as Blender)"),
    ("Y", "Y up", "The file is Y up: (x, y, z) in the file is (x, -z, y) in Blender"),
)


def import_file(context, path, up="Z", levels=2, render_levels=3, quality=0):
    """Import one OBJ file with tags; returns (object, warnings). Raises ObjError, OSError."""
    with open(path, encoding="utf-8") as f:
        tagged = objtags.parse(f.read())
    name = os.path.splitext(os.path.basename(path))[0]
    return blender_mesh.build_object(context, tagged, name, up, levels, render_levels, quality)


def export_file(obj, path, up="Z"):
    """Write the control mesh of `obj` with its tags to `path`."""
    text = objtags.write(blender_mesh.tagged_from_object(obj, up))
    with open(path, "w", encoding="utf-8", newline="\n") as f:
        f.write(text)


def _report_warnings(op, obj, warnings):
    for w in warnings:
        op.report({"WARNING"}, f"{obj.name}: {w}")


class IMPORT_SCENE_OT_profsubd_obj(bpy.types.Operator, ImportHelper):
    """Import an OBJ with OpenSubdiv tags: creases, corners, boundary rule on the modifier"""

    bl_idname = "import_scene.profsubd_obj"
    bl_label = "Import OpenSubdiv OBJ"
    bl_options = {"REGISTER", "UNDO", "PRESET"}
    filename_ext = ".obj"
    filter_glob: StringProperty(default="*.obj", options={"HIDDEN"})
    up_axis: EnumProperty(name="Up Axis", items=UP_AXIS_ITEMS, default="Z")
    levels: IntProperty(name="Viewport Levels", default=2, min=0, max=6)
    render_levels: IntProperty(name="Render Levels", default=3, min=0, max=6)
    quality: IntProperty(
        name="Quality",
        description="The modifier's Quality (adaptive isolation of the limit surface); 0: what "
        "makes this mesh's limit exact to single precision (higher with semi-sharp tags and "
        "edge-only corners)",
        default=0, min=0, max=10,
    )

    def execute(self, context):
        try:
            obj, warnings = import_file(context, self.filepath, self.up_axis, self.levels,
                                        self.render_levels, self.quality)
        except (objtags.ObjError, OSError, UnicodeDecodeError) as e:
            self.report({"ERROR"}, f"{self.filepath}: {e}")
            return {"CANCELLED"}
        _report_warnings(self, obj, warnings)
        for o in context.selected_objects:
            o.select_set(False)
        obj.select_set(True)
        context.view_layer.objects.active = obj
        return {"FINISHED"}


class EXPORT_SCENE_OT_profsubd_obj(bpy.types.Operator, ExportHelper):
    """Export the active mesh's control mesh as OBJ with OpenSubdiv tags"""

    bl_idname = "export_scene.profsubd_obj"
    bl_label = "Export OpenSubdiv OBJ"
    filename_ext = ".obj"
    filter_glob: StringProperty(default="*.obj", options={"HIDDEN"})
    up_axis: EnumProperty(name="Up Axis", items=UP_AXIS_ITEMS, default="Z")

    @classmethod
    def poll(cls, context):
        return context.active_object is not None and context.active_object.type == "MESH"

    def execute(self, context):
        try:
            export_file(context.active_object, self.filepath, self.up_axis)
        except OSError as e:
            self.report({"ERROR"}, f"{self.filepath}: {e}")
            return {"CANCELLED"}
        return {"FINISHED"}


def profile_model(**kwargs):
    """`profsubd.profile(**kwargs)` written to a temporary OBJ; returns its path.

    Raises ImportError when the `profsubd` Python package is missing, and whatever the
    package raises (`profsubd.ProfsubdError`) for bad curves."""
    import profsubd

    model = profsubd.profile(**kwargs)
    fd, path = tempfile.mkstemp(suffix=".obj", prefix="profsubd_profile_")
    os.close(fd)
    try:
        model.mesh.write_obj(path)
    except BaseException:
        os.remove(path)
        raise
    return path


def missing_package_message(error):
    """What to tell the user when `import profsubd` fails inside Blender."""
    return (
        f"the profsubd Python package is not importable from Blender's Python "
        f"{sys.version.split()[0]} ({error}); install it for that interpreter "
        f"(`pip install ./python` from a profsubd clone, README 'Use it from Blender')"
    )


class MESH_OT_profsubd_profile(bpy.types.Operator):
    """Build an interpolating Catmull-Clark model from profile curves with profsubd"""

    bl_idname = "mesh.profsubd_profile"
    bl_label = "profsubd Profile Model"
    bl_options = {"REGISTER", "UNDO"}
    curves_json: StringProperty(
        name="Curves (JSON)",
        description="A profile input as `profsubd profile` reads it (c1, c2, ...); empty: the built-in bottle",
        subtype="FILE_PATH",
        default="",
    )
    around: IntProperty(name="Around", description="Meridians (multiple of 4); 0: the input's", default=0, min=0)
    along: IntProperty(name="Along", description="Ring intervals; 0: the input's", default=0, min=0)

    def execute(self, context):
        kwargs = {}
        if self.curves_json:
            try:
                with open(bpy.path.abspath(self.curves_json), encoding="utf-8") as f:
                    kwargs = json.load(f)
            except (OSError, ValueError) as e:
                self.report({"ERROR"}, f"{self.curves_json}: {e}")
                return {"CANCELLED"}
        if self.around:
            kwargs["around"] = self.around
        if self.along:
            kwargs["along"] = self.along
        try:
            path = profile_model(**kwargs)
        except ImportError as e:
            self.report({"ERROR"}, missing_package_message(e))
            return {"CANCELLED"}
        except Exception as e:  # the package's ProfsubdError, with the library's message
            self.report({"ERROR"}, f"profsubd: {e}")
            return {"CANCELLED"}
        try:
            obj, warnings = import_file(context, path)
        finally:
            os.remove(path)
        obj.name = "profsubd_profile"
        _report_warnings(self, obj, warnings)
        return {"FINISHED"}


def _menu_import(self, context):
    self.layout.operator(IMPORT_SCENE_OT_profsubd_obj.bl_idname, text="OpenSubdiv OBJ (.obj with tags)")


def _menu_export(self, context):
    self.layout.operator(EXPORT_SCENE_OT_profsubd_obj.bl_idname, text="OpenSubdiv OBJ (.obj with tags)")


def _menu_add(self, context):
    self.layout.operator(MESH_OT_profsubd_profile.bl_idname, text="profsubd Profile Model")


CLASSES = (IMPORT_SCENE_OT_profsubd_obj, EXPORT_SCENE_OT_profsubd_obj, MESH_OT_profsubd_profile)


def register():
    for c in CLASSES:
        bpy.utils.register_class(c)
    bpy.types.TOPBAR_MT_file_import.append(_menu_import)
    bpy.types.TOPBAR_MT_file_export.append(_menu_export)
    bpy.types.VIEW3D_MT_mesh_add.append(_menu_add)


def unregister():
    bpy.types.VIEW3D_MT_mesh_add.remove(_menu_add)
    bpy.types.TOPBAR_MT_file_export.remove(_menu_export)
    bpy.types.TOPBAR_MT_file_import.remove(_menu_import)
    for c in reversed(CLASSES):
        bpy.utils.unregister_class(c)
