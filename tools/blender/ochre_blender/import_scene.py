"""Import an ochre scene (docs/scene-format.md) into Blender, so that it can be edited there and exported back.

    warnings = import_scene("/path/scene.json", ochre="ochre", preset=None)

What comes in, and how it comes back out through export.py:
- Every mesh as ochre renders it: `ochre export-mesh` writes each shape subdivided, displaced and transformed
  (world coordinates, vertex normals, uvs, colours), read here into a Blender mesh with those normals as
  custom normals. Procedural shapes (spheres, planes, groove plates...) come in the same way, as meshes.
- Each shape's material as a Blender material of the same name whose custom property `ochre_material` names
  the ochre material, so the exporter writes the scene's own material back; its Principled BSDF only
  approximates it for Cycles and the viewport (a constant or RGB colour; grey otherwise). The folders of the
  scene and of its includes are stored on the Blender scene (`ochre_material_library`), where the exporter
  finds the files that define the materials (docs/blender.md, "Materials").
- Each light as a Blender light of the nearest kind (point, spot, sun) whose custom property `ochre_light`
  holds the ochre light itself (JSON): the exporter writes it back with the position and direction of the
  Blender object, so a light moved in Blender moves in ochre. Its Blender power only approximates it.
- The camera (eye, target, up or a transform; perspective or orthographic) and the film resolution; the
  integrator's spp and max_depth as the ochre render settings.
- A constant environment as the Blender world (none without one).
Anything else (an environment map, a camera's polarizer, output settings) gives one warning each.
"""
import json
import math
import os
import subprocess
import tempfile

import bpy
import numpy as np
from mathutils import Matrix, Vector

from . import export, units

PLY_TYPES = {'float': '<f4', 'float32': '<f4', 'double': '<f8', 'uchar': 'u1', 'uint8': 'u1', 'char': 'i1',
             'int': '<i4', 'int32': '<i4', 'uint': '<u4', 'uint32': '<u4', 'short': '<i2', 'ushort': '<u2'}


# ---------------------------------------------------------------------------------------------- scene files
def read_json(path):
    with open(path, encoding='utf-8') as f:
        return json.loads(export._strip_comments(f.read()))


def scene_with_includes(path, stack=(), done=None):
    """The scene file with its includes merged: materials, shapes and lights from every file (a file included
    twice counts once), camera, film, integrator and presets from the main file; `dirs` lists the folders of
    all the files (where the exporter looks for the materials by name)."""
    done = set() if done is None else done
    path = os.path.realpath(path)
    if path in stack:
        raise ValueError(f'{path}: includes itself')
    done.add(path)
    data = read_json(path)
    here = os.path.dirname(path)
    merged = {'materials': {}, 'shapes': [], 'lights': [], 'dirs': []}
    for inc in data.get('include', []):
        if os.path.realpath(os.path.join(here, inc)) in done:
            continue
        part = scene_with_includes(os.path.join(here, inc), stack + (path,), done)
        merged['materials'].update(part['materials'])
        merged['shapes'] += part['shapes']
        merged['lights'] += part['lights']
        merged['dirs'] += [d for d in part['dirs'] if d not in merged['dirs']]
    merged['materials'].update(data.get('materials', {}))
    merged['shapes'] += data.get('shapes', [])
    merged['lights'] += data.get('lights', [])
    if here not in merged['dirs']:
        merged['dirs'].append(here)
    for key in ('camera', 'film', 'integrator', 'presets'):
        if key in data:
            merged[key] = data[key]
    return merged


def apply_preset(scene, preset):
    """The scene's settings with presets.<preset> applied (film and integrator; shapes are left to
    `ochre export-mesh --preset`, which applies the preset to them)."""
    if not preset:
        return
    chosen = scene.get('presets', {}).get(preset)
    if chosen is None:
        raise ValueError(f'no preset "{preset}" (the scene\'s: {", ".join(scene.get("presets", {})) or "none"})')
    for key in ('film', 'integrator', 'camera'):
        if key in chosen:
            scene[key] = dict(scene.get(key, {}), **chosen[key])


# ---------------------------------------------------------------------------------------------- meshes
def read_ply(path):
    """(positions, normals or None, uvs or None, colours or None, triangles) of a binary little-endian PLY
    with one vertex element and one face element of triangles (what `ochre export-mesh` writes)."""
    with open(path, 'rb') as f:
        header = []
        while True:
            line = f.readline()
            if not line:
                raise ValueError(f'{path}: no end_header')
            line = line.decode('ascii').strip()
            header.append(line)
            if line == 'end_header':
                break
        body = f.read()
    if 'format binary_little_endian 1.0' not in header:
        raise ValueError(f'{path}: only binary little-endian PLY files are read here')
    elements, current = [], None
    for line in header:
        words = line.split()
        if words[0] == 'element':
            current = (words[1], int(words[2]), [])
            elements.append(current)
        elif words[0] == 'property' and current is not None:
            current[2].append(words[1:])
    offset, vertices, faces = 0, None, None
    for name, count, props in elements:
        if name == 'face':
            if len(props) != 1 or props[0][0] != 'list':
                raise ValueError(f'{path}: faces must be one list property')
            dtype = np.dtype([('n', PLY_TYPES[props[0][1]]), ('i', PLY_TYPES[props[0][2]], (3,))])
            faces = np.frombuffer(body, dtype=dtype, count=count, offset=offset)
            if count and not np.all(faces['n'] == 3):
                raise ValueError(f'{path}: only triangles are read here')
            faces = faces['i'].astype(np.int64)
        else:
            dtype = np.dtype([(p[1], PLY_TYPES[p[0]]) for p in props])
            data = np.frombuffer(body, dtype=dtype, count=count, offset=offset)
            if name == 'vertex':
                vertices = data
        offset += dtype.itemsize * count
    if vertices is None or faces is None:
        raise ValueError(f'{path}: no vertex or face element')
    names = vertices.dtype.names

    def columns(*keys):
        return np.stack([vertices[k].astype(np.float64) for k in keys], axis=1) if all(k in names for k in keys) else None
    uvs = columns('s', 't')
    if uvs is None:
        uvs = columns('u', 'v')
    colours = columns('red', 'green', 'blue')
    if colours is not None and vertices['red'].dtype == np.uint8:
        c = colours / 255.0
        colours = np.where(c <= 0.04045, c / 12.92, ((c + 0.055) / 1.055) ** 2.4)  # sRGB codes to linear
    return columns('x', 'y', 'z'), columns('nx', 'ny', 'nz'), uvs, colours, faces


def to_blender(v):
    """ochre (y up) points or directions, rows of an (n, 3) array, to Blender (z up): (x, y, z) -> (x, -z, y)."""
    return np.stack([v[:, 0], -v[:, 2], v[:, 1]], axis=1)


def blender_mesh(name, positions, normals, uvs, colours, faces):
    me = bpy.data.meshes.new(name)
    me.vertices.add(len(positions))
    me.vertices.foreach_set('co', to_blender(positions).astype(np.float32).ravel())
    me.loops.add(3 * len(faces))
    me.loops.foreach_set('vertex_index', faces.astype(np.int32).ravel())
    me.polygons.add(len(faces))
    me.polygons.foreach_set('loop_start', np.arange(0, 3 * len(faces), 3, dtype=np.int32))
    me.polygons.foreach_set('loop_total', np.full(len(faces), 3, dtype=np.int32))
    me.update(calc_edges=True)
    me.polygons.foreach_set('use_smooth', np.full(len(faces), normals is not None))
    if uvs is not None:
        layer = me.uv_layers.new(name='UVMap')
        layer.data.foreach_set('uv', uvs[faces.ravel()].astype(np.float32).ravel())
    if colours is not None:
        attr = me.color_attributes.new('Col', 'FLOAT_COLOR', 'POINT')
        rgba = np.concatenate([colours, np.ones((len(colours), 1))], axis=1)
        attr.data.foreach_set('color', rgba.astype(np.float32).ravel())
    if normals is not None:  # the renderer's shading normals, kept exactly (custom normals)
        me.use_auto_smooth = True
        n = to_blender(normals)
        me.normals_split_custom_set_from_vertices(n.astype(np.float32).tolist())
    me.validate(clean_customdata=False)
    return me


# ---------------------------------------------------------------------------------------------- importer
class Importer:
    def __init__(self, filepath, ochre='ochre', preset=None, collection=None):
        self.filepath = os.path.abspath(filepath)
        self.ochre, self.preset = ochre, preset
        self.collection = collection or bpy.context.scene.collection
        self.warnings = []
        self.scene = scene_with_includes(self.filepath)
        apply_preset(self.scene, preset)
        self.materials = {}

    def warn(self, message):
        if message not in self.warnings:
            self.warnings.append(message)

    def link(self, ob):
        self.collection.objects.link(ob)
        return ob

    # ---- camera and settings
    def camera(self):
        bscene = bpy.context.scene
        w, h = self.scene.get('film', {}).get('resolution', [640, 480])
        bscene.render.resolution_x, bscene.render.resolution_y, bscene.render.resolution_percentage = w, h, 100
        integrator = self.scene.get('integrator', {})
        if hasattr(bscene, 'ochre'):
            bscene.ochre.samples = int(integrator.get('spp', bscene.ochre.samples))
            bscene.ochre.max_depth = int(integrator.get('max_depth', bscene.ochre.max_depth))
        c = self.scene.get('camera')
        if c is None:
            self.warn('camera: none in the scene; Blender\'s scene keeps its own')
            return
        cam = bpy.data.cameras.new('camera')
        kind = c.get('type', 'perspective')
        axis = c.get('fov_axis', 'x' if w < h else 'y')  # ochre's fov spans the shorter axis by default
        cam.sensor_fit = 'HORIZONTAL' if axis == 'x' else 'VERTICAL'
        if kind == 'orthographic':
            cam.type = 'ORTHO'
            size = float(c.get('size', 1.0))  # ochre: the extent across the shorter axis
            cam.sensor_fit = 'AUTO'  # Blender's ortho_scale then spans the longer axis
            cam.ortho_scale = size * max(w, h) / min(w, h)
        else:
            if kind != 'perspective':
                self.warn(f'camera: type {kind} imported as perspective')
            cam.lens_unit = 'FOV'
            cam.angle = math.radians(float(c.get('fov', 40.0)))
        for key in ('polarizer', 'aperture', 'lens_radius', 'focus_distance'):
            if key in c:
                self.warn(f'camera: {key} not imported')
        ob = self.link(bpy.data.objects.new('camera', cam))
        if 'transform' in c and isinstance(c['transform'], list) and len(c['transform']) == 16:
            m = Matrix([c['transform'][4 * i:4 * i + 4] for i in range(4)])
        else:
            eye, target = Vector(c.get('eye', [0, 0, 0])), Vector(c.get('target', [0, 0, -1]))
            up = Vector(c.get('up', [0, 1, 0]))
            fwd = (target - eye).normalized()
            right = fwd.cross(up).normalized()
            true_up = right.cross(fwd)
            m = Matrix(((right.x, true_up.x, -fwd.x, eye.x), (right.y, true_up.y, -fwd.y, eye.y),
                        (right.z, true_up.z, -fwd.z, eye.z), (0, 0, 0, 1)))
        y_up_to_z_up = Matrix(units.Z_UP_TO_Y_UP).inverted()
        ob.matrix_world = y_up_to_z_up @ m
        bpy.context.scene.camera = ob

    # ---- materials
    def material(self, name):
        if name in self.materials:
            return self.materials[name]
        mat = bpy.data.materials.new(name)
        mat['ochre_material'] = name
        mat.use_nodes = True
        bsdf = mat.node_tree.nodes.get('Principled BSDF')
        colour = self.scene['materials'].get(name, {}).get('color')
        if isinstance(colour, (int, float)):
            colour = [colour] * 3
        if bsdf is not None:
            if isinstance(colour, list) and len(colour) == 3 and all(isinstance(x, (int, float)) for x in colour):
                bsdf.inputs['Base Color'].default_value = (*colour, 1.0)
            else:
                bsdf.inputs['Base Color'].default_value = (0.5, 0.5, 0.5, 1.0)
                self.warn(f'material {name}: shown in Blender as grey (ochre renders it as defined, through '
                          'its ochre_material property)')
        self.materials[name] = mat
        return mat

    # ---- shapes
    def exported_mesh(self, shape_name, folder):
        ply = os.path.join(folder, f'{export._safe_name(shape_name)}.ply')
        cmd = [self.ochre, 'export-mesh', self.filepath, '--shape', shape_name, '-o', ply, '-q']
        if self.preset:
            cmd += ['--preset', self.preset]
        proc = subprocess.run(cmd, capture_output=True, text=True)
        if proc.returncode != 0:
            raise ValueError(f'{" ".join(cmd)} failed (exit {proc.returncode}): {proc.stderr.strip()[-2000:]}')
        return read_ply(ply)

    def shapes(self):
        names = [s.get('name', s.get('type', 'mesh')) for s in self.scene['shapes']]
        with tempfile.TemporaryDirectory() as folder:
            for shape, name in zip(self.scene['shapes'], names):
                if names.count(name) > 1:
                    self.warn(f'shape {name}: several shapes have that name; not imported (name them apart)')
                    continue
                if 'materials' in shape:
                    self.warn(f'shape {name}: a mesh with several materials is not imported')
                    continue
                if shape.get('light_group') or shape.get('visible') is False:
                    self.warn(f'shape {name}: its light group and visibility are not imported')
                me = blender_mesh(name, *self.exported_mesh(name, folder))
                if 'material' in shape:
                    me.materials.append(self.material(shape['material']))
                self.link(bpy.data.objects.new(name, me))

    # ---- lights
    def light(self, index, light):
        kind = light.get('type', 'point')
        name = light.get('name', f'{kind}_{index}')
        if kind == 'environment':
            radiance = light.get('radiance')
            if isinstance(radiance, (int, float)) or (isinstance(radiance, list) and len(radiance) == 3):
                world = bpy.data.worlds.new(name)
                world.color = [float(radiance)] * 3 if isinstance(radiance, (int, float)) else radiance
                bpy.context.scene.world = world
            else:
                self.warn(f'light {name}: an environment other than a constant radiance is not imported')
            return
        blender_kind = {'spot': 'SPOT', 'directional': 'SUN'}.get(kind, 'POINT')
        data = bpy.data.lights.new(name, blender_kind)
        radius = light.get('radius', 0.0)
        if blender_kind != 'SUN':
            data.shadow_soft_size = float(radius) if isinstance(radius, (int, float)) else 0.0
        # Blender's power, for Cycles and the viewport only (ochre renders `ochre_light`): a point of intensity I
        # has power 4 pi I, a sun of irradiance E strength E (units.py); spectra and presets count as 1.
        value = light.get('irradiance' if blender_kind == 'SUN' else 'intensity', 1.0)
        value = float(np.mean(value)) if isinstance(value, (int, float, list)) and np.size(value) else 1.0
        data.energy = value if blender_kind == 'SUN' else 4.0 * math.pi * value
        ob = self.link(bpy.data.objects.new(name, data))
        ob['ochre_light'] = json.dumps(light)
        ob.location = Vector(units.to_blender_point(light.get('position', [0.0, 0.0, 0.0])))
        direction = light.get('direction')
        if direction is not None:  # Blender lights shine along their -z
            d = Vector(units.to_blender_point(direction)).normalized()
            ob.rotation_euler = d.to_track_quat('-Z', 'Y').to_euler()
        if 'group' in light:
            ob['ochre_light_group'] = light['group']

    # ---- all
    def run(self):
        # The scene's lights only: no Blender world unless the scene has a constant environment.
        bpy.context.scene.world = None
        self.camera()
        self.shapes()
        for i, light in enumerate(self.scene['lights']):
            self.light(i, light)
        bpy.context.scene['ochre_material_library'] = os.pathsep.join(self.scene['dirs'])
        return self.warnings


def import_scene(filepath, ochre='ochre', preset=None):
    """Imports an ochre scene into the current Blender scene; returns the warnings (one string each)."""
    return Importer(filepath, ochre, preset).run()
