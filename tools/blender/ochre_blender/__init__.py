"""ochre for Blender: File > Export > ochre scene (.json), File > Import > ochre scene (.json), and ochre as
a render engine.

Install: link or copy this folder into Blender's add-ons folder and enable "ochre" (docs/blender.md).
"""
bl_info = {
    'name': 'ochre',
    'author': 'the ochre authors',
    'version': (0, 1, 0),
    'blender': (3, 4, 0),
    'location': 'File > Export / Import > ochre scene (.json); Render Properties > Render Engine > ochre',
    'description': 'Export scenes to the ochre spectral path tracer and render them with it',
    'category': 'Render',
}

import bpy
from bpy.props import EnumProperty, IntProperty, StringProperty
from bpy_extras.io_utils import ExportHelper, ImportHelper

from . import engine, export, import_scene


class OchrePreferences(bpy.types.AddonPreferences):
    bl_idname = __package__
    ochre_path: StringProperty(name='ochre executable', subtype='FILE_PATH', default='',
                               description='Path of the ochre program; empty: $OCHRE_EXECUTABLE or ochre on PATH')

    def draw(self, context):
        self.layout.prop(self, 'ochre_path')


class OchreSettings(bpy.types.PropertyGroup):
    preset: EnumProperty(name='Preset', default='final',
                         items=[('fast', 'Fast', 'a quick look: at most 16 samples and 4 bounces'),
                                ('final', 'Final', 'the samples and bounces below')])
    samples: IntProperty(name='Samples', default=64, min=1, max=1 << 24, description='Samples per pixel')
    max_depth: IntProperty(name='Max bounces', default=8, min=0, max=1024,
                           description='Scattering events on a path (1: direct light only)')
    threads: IntProperty(name='Threads', default=0, min=0, max=4096, description='0: all cores')
    spectral_bins: IntProperty(name='Spectral bins', default=0, min=0, max=471,
                               description='Spectral radiance layers in the EXR (0: none); kept with Keep EXR')
    exr_copy: StringProperty(name='Keep EXR', subtype='FILE_PATH', default='',
                             description='Where to copy the EXR ochre writes, with all its layers (spectral bins, '
                                         'light groups) and its render settings in the header; empty: not kept')


class RENDER_PT_ochre(bpy.types.Panel):
    bl_label = 'ochre'
    bl_space_type = 'PROPERTIES'
    bl_region_type = 'WINDOW'
    bl_context = 'render'
    COMPAT_ENGINES = {'OCHRE'}

    @classmethod
    def poll(cls, context):
        return context.engine in cls.COMPAT_ENGINES

    def draw(self, context):
        settings = context.scene.ochre
        layout = self.layout
        layout.use_property_split = True
        for key in ('preset', 'samples', 'max_depth', 'threads', 'spectral_bins', 'exr_copy'):
            layout.prop(settings, key)


class EXPORT_SCENE_OT_ochre(bpy.types.Operator, ExportHelper):
    """Export the scene to an ochre scene file (JSON with PLY meshes)"""
    bl_idname = 'export_scene.ochre'
    bl_label = 'Export ochre scene'
    filename_ext = '.json'
    filter_glob: StringProperty(default='*.json', options={'HIDDEN'})

    def execute(self, context):
        try:
            warnings = export.export_scene(context.evaluated_depsgraph_get(), self.filepath)
        except (ValueError, OSError) as e:
            self.report({'ERROR'}, f'ochre export failed: {e}')
            return {'CANCELLED'}
        for message in warnings:
            self.report({'WARNING'}, message)
        self.report({'INFO'}, f'exported {self.filepath} ({len(warnings)} warnings)')
        return {'FINISHED'}


class IMPORT_SCENE_OT_ochre(bpy.types.Operator, ImportHelper):
    """Import an ochre scene: its meshes as ochre renders them, lights, camera and materials by name"""
    bl_idname = 'import_scene.ochre'
    bl_label = 'Import ochre scene'
    filename_ext = '.json'
    filter_glob: StringProperty(default='*.json', options={'HIDDEN'})
    preset: StringProperty(name='Preset', description='A preset of the scene (e.g. final); empty: as written')

    def execute(self, context):
        try:
            warnings = import_scene.import_scene(self.filepath, engine.ochre_executable(context),
                                                 self.preset or None)
        except (ValueError, OSError) as e:
            self.report({'ERROR'}, f'ochre import failed: {e}')
            return {'CANCELLED'}
        for message in warnings:
            self.report({'WARNING'}, message)
        self.report({'INFO'}, f'imported {self.filepath} ({len(warnings)} warnings)')
        return {'FINISHED'}


def menu_import(self, context):
    self.layout.operator(IMPORT_SCENE_OT_ochre.bl_idname, text='ochre scene (.json)')


def menu_export(self, context):
    self.layout.operator(EXPORT_SCENE_OT_ochre.bl_idname, text='ochre scene (.json)')


CLASSES = (OchrePreferences, OchreSettings, RENDER_PT_ochre, EXPORT_SCENE_OT_ochre, IMPORT_SCENE_OT_ochre)


def register():
    for cls in CLASSES:
        bpy.utils.register_class(cls)
    bpy.types.Scene.ochre = bpy.props.PointerProperty(type=OchreSettings)
    bpy.types.TOPBAR_MT_file_export.append(menu_export)
    bpy.types.TOPBAR_MT_file_import.append(menu_import)
    engine.register()


def unregister():
    engine.unregister()
    bpy.types.TOPBAR_MT_file_import.remove(menu_import)
    bpy.types.TOPBAR_MT_file_export.remove(menu_export)
    del bpy.types.Scene.ochre
    for cls in reversed(CLASSES):
        bpy.utils.unregister_class(cls)
