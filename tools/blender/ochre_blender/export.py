"""Export a Blender scene to an ochre scene (docs/scene-format.md): a JSON file and a folder of binary PLY
meshes and images beside it.

    warnings = export_scene(depsgraph, "/path/scene.json")

Every object, light, material or setting that is not exported, or only approximately, gives one warning
(a string in the returned list); nothing is dropped silently.
"""
import glob
import json
import math
import os
import re
import struct
import zlib

import bpy
import numpy as np
from mathutils import Matrix, Vector

from . import units

DEFAULT_MATERIAL = 'blender_default'  # Blender renders objects without a material as grey 0.8 diffuse


def library_dirs(scene=None):
    """Folders whose scene files define named materials that `ochre_material` may name: the pigment library,
    $OCHRE_MATERIAL_LIBRARY, and the Blender scene's `ochre_material_library` (set by the importer to the
    folders of the imported scene and its includes)."""
    here = os.path.dirname(os.path.realpath(__file__))
    dirs = [os.path.normpath(os.path.join(here, '..', '..', '..', 'scenes', 'pigments'))]
    for extra in (os.environ.get('OCHRE_MATERIAL_LIBRARY', ''),
                  str(scene.get('ochre_material_library', '')) if scene is not None else ''):
        dirs += [d for d in extra.split(os.pathsep) if d and d not in dirs]
    return [d for d in dirs if os.path.isdir(d)]


def _strip_comments(text):
    text = re.sub(r'/\*.*?\*/', '', text, flags=re.S)
    return re.sub(r'(?m)^\s*//.*$', '', text)


def library_materials(dirs=None):
    """Material name -> the scene file that defines it, over the library folders."""
    found = {}
    for d in dirs if dirs is not None else library_dirs():
        for path in sorted(glob.glob(os.path.join(d, '*.json'))):
            try:
                with open(path, encoding='utf-8') as f:
                    data = json.loads(_strip_comments(f.read()))
            except (OSError, ValueError):
                continue
            for name in data.get('materials', {}) if isinstance(data, dict) else {}:
                found.setdefault(name, path)
    return found


def is_library_file(path):
    """Whether a scene file holds materials only (and includes, a description): one that can be included
    without adding shapes, lights or a camera to the export."""
    try:
        with open(path, encoding='utf-8') as f:
            data = json.loads(_strip_comments(f.read()))
    except (OSError, ValueError):
        return False
    return isinstance(data, dict) and set(data) <= {'description', 'include', 'materials'}


def _absolute_files(value, folder):
    """A copy of a material definition with its `file` entries (textures, spectra) made absolute."""
    if isinstance(value, dict):
        return {k: (os.path.normpath(os.path.join(folder, v)) if k == 'file' and isinstance(v, str)
                    and not v.startswith('mtl:') else
                    _absolute_files(v, folder)) for k, v in value.items()}
    return [_absolute_files(x, folder) for x in value] if isinstance(value, list) else value


def _safe_name(name):
    return re.sub(r'[^A-Za-z0-9_-]', '_', name) or 'unnamed'


def _write_ply(path, positions, normals, uvs, colours, faces):
    fields = [('x', '<f4'), ('y', '<f4'), ('z', '<f4'), ('nx', '<f4'), ('ny', '<f4'), ('nz', '<f4')]
    if uvs is not None:
        fields += [('s', '<f4'), ('t', '<f4')]
    if colours is not None:
        fields += [('red', 'u1'), ('green', 'u1'), ('blue', 'u1')]
    v = np.empty(len(positions), dtype=fields)
    v['x'], v['y'], v['z'] = positions.T
    v['nx'], v['ny'], v['nz'] = normals.T
    if uvs is not None:
        v['s'], v['t'] = uvs.T
    if colours is not None:
        c = np.clip(colours, 0.0, 1.0)
        c = np.where(c <= 0.0031308, 12.92 * c, 1.055 * np.power(c, 1.0 / 2.4) - 0.055)  # sRGB, as units.srgb_encode
        c8 = np.round(c * 255.0).astype(np.uint8)
        v['red'], v['green'], v['blue'] = c8.T
    f = np.empty(len(faces), dtype=[('n', 'u1'), ('i', '<i4', (3,))])
    f['n'] = 3
    f['i'] = faces
    header = ['ply', 'format binary_little_endian 1.0', f'element vertex {len(v)}']
    kinds = {'<f4': 'float', 'u1': 'uchar'}
    header += [f'property {kinds[t]} {n}' for n, t in fields]
    header += [f'element face {len(f)}', 'property list uchar int vertex_indices', 'end_header']
    with open(path, 'wb') as out:
        out.write(('\n'.join(header) + '\n').encode('ascii'))
        out.write(v.tobytes())
        out.write(f.tobytes())


def _write_png(path, rgb8):
    """An 8-bit RGB PNG of an (h, w, 3) uint8 array, top row first."""
    h, w, _ = rgb8.shape
    raw = np.concatenate([np.zeros((h, 1), dtype=np.uint8), rgb8.reshape(h, w * 3)], axis=1).tobytes()

    def chunk(kind, data):
        return struct.pack('>I', len(data)) + kind + data + struct.pack('>I', zlib.crc32(kind + data) & 0xFFFFFFFF)

    with open(path, 'wb') as out:
        out.write(b'\x89PNG\r\n\x1a\n' + chunk(b'IHDR', struct.pack('>IIBBBBB', w, h, 8, 2, 0, 0, 0)) +
                  chunk(b'IDAT', zlib.compress(raw, 6)) + chunk(b'IEND', b''))


def _write_hdr(path, rgb):
    """A Radiance RGBE file (flat scanlines) of an (h, w, 3) array of linear values, top row first."""
    h, w, _ = rgb.shape
    rgb = np.maximum(np.nan_to_num(rgb.astype(np.float64), nan=0.0, posinf=0.0), 0.0)
    peak = rgb.max(axis=2)
    mantissa, exponent = np.frexp(peak)
    scale = np.where(peak > 1e-32, mantissa * 256.0 / np.where(peak > 1e-32, peak, 1.0), 0.0)
    rgbe = np.zeros((h, w, 4), dtype=np.uint8)
    rgbe[..., :3] = np.clip(rgb * scale[..., None], 0, 255).astype(np.uint8)
    rgbe[..., 3] = np.where(peak > 1e-32, exponent + 128, 0).astype(np.uint8)
    with open(path, 'wb') as out:
        out.write(f'#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y {h} +X {w}\n'.encode('ascii'))
        out.write(rgbe.tobytes())


def _foreach(collection, attr, n, dtype=np.float32):
    a = np.empty(n, dtype=dtype)
    collection.foreach_get(attr, a)
    return a


class Exporter:
    def __init__(self, depsgraph, filepath, samples=None, max_depth=None, library=None):
        self.depsgraph = depsgraph
        self.scene = depsgraph.scene
        self.filepath = os.path.abspath(filepath)
        self.dir = os.path.dirname(self.filepath)
        stem = os.path.splitext(os.path.basename(self.filepath))[0]
        self.assets_rel = stem + '_assets'
        self.assets = os.path.join(self.dir, self.assets_rel)
        settings = getattr(self.scene, 'ochre', None)
        self.samples = samples or (settings.samples if settings else 64)
        self.max_depth = max_depth or (settings.max_depth if settings else 8)
        self.library = library if library is not None else library_materials(library_dirs(self.scene))
        self.warnings = []
        self.materials = {}       # ochre material name -> material
        self.material_names = {}  # Blender material name -> ochre material name
        self.includes = []
        self.inlined = set()      # scene files whose materials were copied into the export
        self.meshes = {}          # mesh key -> [(relative PLY path, material slot index)]
        self.images = {}          # Blender image name -> relative file
        self.shapes, self.lights = [], []

    def warn(self, message):
        if message not in self.warnings:
            self.warnings.append(message)

    def asset(self, name):
        os.makedirs(self.assets, exist_ok=True)
        return os.path.join(self.assets, name), self.assets_rel + '/' + name

    # ------------------------------------------------------------------ camera and settings
    def camera(self):
        scene, r = self.scene, self.scene.render
        w, h = units.resolution(r.resolution_x, r.resolution_y, r.resolution_percentage)
        film = {'resolution': [w, h], 'colorspace': 'rec709'}
        ob = scene.camera
        if ob is None:
            self.warn('scene: no active camera; the camera is ochre\'s default')
            return None, film
        cam = ob.data
        if r.pixel_aspect_x != r.pixel_aspect_y:
            self.warn('render: non-square pixel aspect not exported (square pixels)')
        if cam.shift_x != 0.0 or cam.shift_y != 0.0:
            self.warn(f'camera {ob.name}: lens shift not exported')
        if cam.dof.use_dof:
            self.warn(f'camera {ob.name}: depth of field not exported (pinhole camera)')
        loc, rot, _ = ob.matrix_world.decompose()
        m = Matrix.Translation(loc) @ rot.to_matrix().to_4x4()
        out = {'transform': units.to_ochre_matrix(m)}
        if cam.type == 'ORTHO':
            out['type'] = 'orthographic'
            out['size'] = units.orthographic_size(cam.ortho_scale, cam.sensor_fit, w, h)
        else:
            if cam.type != 'PERSP':
                self.warn(f'camera {ob.name}: type {cam.type} not exported (exported as perspective)')
            fov, axis = units.perspective_fov(cam.lens, cam.sensor_width, cam.sensor_height, cam.sensor_fit, w, h)
            out.update(type='perspective', fov=fov, fov_axis=axis)
        return out, film

    # ------------------------------------------------------------------ images
    def image_file(self, image, hdr=False):
        if image.name in self.images:
            return self.images[image.name]
        if image.source in ('TILED', 'SEQUENCE', 'MOVIE'):
            self.warn(f'image {image.name}: {image.source.lower()} images not exported (its first image is used)')
        src = bpy.path.abspath(image.filepath, library=image.library) if image.filepath else ''
        ext = os.path.splitext(src)[1].lower()
        usable = ('.hdr', '.exr') if hdr else ('.png', '.jpg', '.jpeg', '.exr', '.hdr', '.tif', '.tiff', '.tga', '.bmp')
        if image.source == 'FILE' and not image.packed_file and os.path.isfile(src) and ext in usable:
            rel = os.path.abspath(src)
        elif hdr or image.is_float:  # generated, packed or another format: a Radiance HDR copy
            path, rel = self.asset(_safe_name(image.name) + '.hdr')
            w, h = image.size
            pixels = np.empty(w * h * image.channels, dtype=np.float32)
            image.pixels.foreach_get(pixels)
            rgb = pixels.reshape(h, w, image.channels)[::-1, :, :3]  # Blender's rows go bottom up
            if image.channels < 3:
                rgb = np.repeat(pixels.reshape(h, w, image.channels)[::-1, :, :1], 3, axis=2)
            _write_hdr(path, rgb)
        else:  # an 8-bit image that is generated, packed or in a format ochre does not read: a PNG copy
            path, rel = self.asset(_safe_name(image.name) + '.png')
            w, h = image.size
            pixels = np.empty(w * h * image.channels, dtype=np.float32)
            image.pixels.foreach_get(pixels)  # 8-bit images: the stored (encoded) values / 255
            rows = pixels.reshape(h, w, image.channels)[::-1]
            rgb = rows[:, :, :3] if image.channels >= 3 else np.repeat(rows[:, :, :1], 3, axis=2)
            _write_png(path, np.round(np.clip(rgb, 0.0, 1.0) * 255.0).astype(np.uint8))
        self.images[image.name] = rel
        return rel

    # ------------------------------------------------------------------ materials
    def use_library(self, name, owner):
        path = self.library.get(name)
        if path is None:
            self.warn(f'{owner}: ochre_material "{name}" is in no material library; the node tree is used')
            return None
        if is_library_file(path):
            if path not in self.includes:
                self.includes.append(path)
        else:
            self.inline_materials(path, owner)
        return name

    def inline_materials(self, path, owner):
        """The materials of a scene file that has more than materials (shapes, a camera: it cannot be included),
        copied into the export with their files made absolute; the material libraries it includes are
        included."""
        if path in self.inlined:
            return
        self.inlined.add(path)
        with open(path, encoding='utf-8') as f:
            data = json.loads(_strip_comments(f.read()))
        here = os.path.dirname(path)
        for name, definition in data.get('materials', {}).items():
            self.materials.setdefault(name, _absolute_files(definition, here))
        for inc in data.get('include', []):
            full = os.path.normpath(os.path.join(here, inc))
            if is_library_file(full):
                if full not in self.includes:
                    self.includes.append(full)
            else:
                self.warn(f'{owner}: {os.path.basename(path)} includes {inc}, which is more than materials: '
                          'not included (its materials are not available)')

    def material(self, mat):
        """The ochre material name for a Blender material (None: the default grey)."""
        if mat is None:
            return self.default_material()
        if mat.name in self.material_names:
            return self.material_names[mat.name]
        name = None
        lib = mat.get('ochre_material')
        if isinstance(lib, str):
            name = self.use_library(lib, f'material {mat.name}')
        if name is None:
            name = 'm_' + _safe_name(mat.name)
            while name in self.materials:
                name += '_'
            self.materials[name] = MaterialTranslator(self, mat).translate()
        self.material_names[mat.name] = name
        return name

    def default_material(self):
        self.materials.setdefault(DEFAULT_MATERIAL, {'type': 'lambert', 'color': 0.8})
        return DEFAULT_MATERIAL

    # ------------------------------------------------------------------ meshes
    def mesh_files(self, ob):
        """Write the evaluated mesh of `ob` once; [(relative PLY, material slot)] for its parts."""
        orig = ob.original
        key = ('data', orig.data.name) if orig.type == 'MESH' and not orig.modifiers else ('object', orig.name)
        if key in self.meshes:
            return self.meshes[key]
        me = ob.to_mesh()
        try:
            parts = self.write_mesh(me, _safe_name(orig.name), ob.name)
        finally:
            ob.to_mesh_clear()
        self.meshes[key] = parts
        return parts

    def write_mesh(self, me, stem, owner):
        me.calc_loop_triangles()
        if hasattr(me, 'calc_normals_split'):
            me.calc_normals_split()
        nt, nl, nv = len(me.loop_triangles), len(me.loops), len(me.vertices)
        if nt == 0:
            return []
        tri_loops = _foreach(me.loop_triangles, 'loops', nt * 3, np.int64).reshape(-1, 3)
        tri_mat = _foreach(me.loop_triangles, 'material_index', nt, np.int64)
        loop_vert = _foreach(me.loops, 'vertex_index', nl, np.int64)
        co = _foreach(me.vertices, 'co', nv * 3).reshape(-1, 3)
        normals = _foreach(me.loops, 'normal', nl * 3).reshape(-1, 3)
        columns = [co[loop_vert], normals]
        uvs = colours = None
        if me.uv_layers.active is not None:
            uvs = _foreach(me.uv_layers.active.data, 'uv', nl * 2).reshape(-1, 2)
            if len(me.uv_layers) > 1:
                self.warn(f'mesh {owner}: only the active UV map is exported')
            columns.append(uvs)
        attrs = getattr(me, 'color_attributes', None)
        ca = attrs.active_color if attrs is not None else None
        if ca is not None and ca.domain in ('POINT', 'CORNER'):
            n = nv if ca.domain == 'POINT' else nl
            c = _foreach(ca.data, 'color', n * 4).reshape(-1, 4)[:, :3]
            colours = c[loop_vert] if ca.domain == 'POINT' else c
            columns.append(colours)
        elif ca is not None:
            self.warn(f'mesh {owner}: colour attribute {ca.name} on {ca.domain} not exported')
        corners = np.concatenate(columns, axis=1)
        parts = []
        for slot in np.unique(tri_mat):
            loops = tri_loops[tri_mat == slot].reshape(-1)
            unique, inverse = np.unique(corners[loops], axis=0, return_inverse=True)
            path, rel = self.asset(f'{stem}_{slot}.ply' if len(np.unique(tri_mat)) > 1 else f'{stem}.ply')
            i = 6
            u = unique[:, i:i + 2] if uvs is not None else None
            i += 2 if uvs is not None else 0
            c = unique[:, i:i + 3] if colours is not None else None
            _write_ply(path, unique[:, :3], unique[:, 3:6], u, c, inverse.reshape(-1, 3))
            parts.append((rel, int(slot)))
        return parts

    def mesh_object(self, ob, matrix):
        override = ob.original.get('ochre_material')
        override_name = None
        if isinstance(override, str):
            override_name = self.use_library(override, f'object {ob.original.name}')
        for rel, slot in self.mesh_files(ob):
            if override_name:
                mat_name = override_name
            else:
                slots = ob.material_slots
                mat = slots[slot].material if slot < len(slots) else None
                mat_name = self.material(mat.original if mat is not None else None)
            shape = {'type': 'mesh', 'name': _safe_name(ob.original.name), 'file': rel,
                     'transform': units.to_ochre_matrix(matrix), 'material': mat_name}
            if _emits(self.materials.get(mat_name)):
                self.warn(f'object {ob.original.name}: emits from the side its normals face only (ochre\'s '
                          'emission is one-sided; Cycles\' is two-sided)')
                group = self.light_group(ob.original, f'object {ob.original.name}')
                if group:
                    shape['light_group'] = group
            self.shapes.append(shape)

    # ------------------------------------------------------------------ lights
    def light(self, ob, matrix):
        light = ob.data
        name = ob.original.name
        colour = light.color
        position = units.to_ochre_point(matrix.translation)
        axis = units.to_ochre_direction((matrix.to_3x3() @ Vector((0.0, 0.0, -1.0))).normalized())
        group = self.light_group(ob.original, f'light {name}')
        first = len(self.lights)
        shapes = len(self.shapes)
        given = self.ochre_light(ob.original, position, axis)
        if given is not None:  # the ochre light itself: Blender's colour, power and radius do not apply
            self.lights.append(given)
        else:
            if light.use_nodes:
                self.warn(f'light {name}: its node tree is not exported (colour and power only)')
            if light.type in ('POINT', 'SPOT') and light.shadow_soft_size > 0.0:
                self.warn(f'light {name}: radius {light.shadow_soft_size:g} not exported (a point source: hard shadows)')
            self.add_light(light, name, matrix, colour, position, axis)
        if group:
            for entry in self.lights[first:]:
                entry['group'] = group
            for entry in self.shapes[shapes:]:
                entry['light_group'] = group

    def ochre_light(self, owner, position, axis):
        """The ochre light a custom property `ochre_light` holds (JSON, as the importer writes it), at the
        object's position and, where it has one, along the object's direction; None without the property."""
        text = owner.get('ochre_light')
        if text is None:
            return None
        try:
            light = json.loads(str(text))
        except ValueError as e:
            self.warn(f'light {owner.name}: ochre_light is not JSON ({e}); the Blender light is exported')
            return None
        if not isinstance(light, dict) or not isinstance(light.get('type', 'point'), str):
            self.warn(f'light {owner.name}: ochre_light is not an ochre light (an object); the Blender light is exported')
            return None
        light['position'] = position
        if 'direction' in light:
            light['direction'] = axis
        return light

    def light_group(self, owner, what):
        """The light group a custom property `ochre_light_group` names, or None."""
        group = owner.get('ochre_light_group')
        if group is None:
            return None
        safe = _safe_name(str(group))
        if safe == 'other':
            self.warn(f'{what}: light group "other" is ochre\'s group of the lights without one: not set')
            return None
        if safe != group:
            self.warn(f'{what}: light group "{group}" written as "{safe}" (letters, digits, _ and - only)')
        return safe

    def add_light(self, light, name, matrix, colour, position, axis):
        if light.type == 'POINT':
            self.lights.append({'type': 'point', 'position': position,
                                'intensity': units.scaled_colour(colour, units.point_intensity(light.energy))})
        elif light.type == 'SPOT':
            cone, start = units.spot_cone(light.spot_size, light.spot_blend)
            self.lights.append({'type': 'spot', 'position': position, 'direction': axis,
                                'cone_angle': cone, 'falloff_start': start, 'falloff': 'smoothstep',
                                'intensity': units.scaled_colour(colour, units.spot_intensity(light.energy))})
        elif light.type == 'SUN':
            if light.angle > 0.01:
                self.warn(f'light {name}: sun angle {math.degrees(light.angle):.2f} degrees not exported '
                          '(parallel light: hard shadows)')
            self.lights.append({'type': 'directional', 'direction': axis,
                                'irradiance': units.scaled_colour(colour, units.sun_irradiance(light.energy))})
        elif light.type == 'AREA':
            self.area_light(light, name, matrix)
        else:
            self.warn(f'light {name}: type {light.type} not exported')

    def area_light(self, light, name, matrix):
        sx = light.size
        sy = light.size_y if light.shape in ('RECTANGLE', 'ELLIPSE') else light.size
        m3 = matrix.to_3x3()
        area = units.area_of_light(light.shape, sx, sy) * m3.col[0].length * m3.col[1].length
        if area <= 0.0:
            self.warn(f'light {name}: area light of zero area not exported')
            return
        if getattr(light, 'spread', math.pi) < math.pi - 1e-6:
            self.warn(f'light {name}: spread not exported (emits as a Lambertian surface)')
        mat_name = 'light_' + _safe_name(name)
        self.materials[mat_name] = {'type': 'emission', 'color': units.scaled_colour(light.color, 1.0),
                                    'strength': units.area_radiance(light.energy, area)}
        shape = {'name': _safe_name(name), 'material': mat_name, 'flip_normals': True}  # Blender: emits along -z
        if light.shape in ('SQUARE', 'RECTANGLE'):
            shape.update(type='plane', size=[sx, sy])
            shape['transform'] = units.to_ochre_matrix(matrix)
        else:
            shape.update(type='disk', radius=0.5)
            shape['transform'] = units.to_ochre_matrix(matrix @ Matrix.Diagonal(Vector((sx, sy, 1.0, 1.0))))
        self.shapes.append(shape)

    # ------------------------------------------------------------------ world
    def world(self):
        world = self.scene.world
        if world is None:
            return
        first = len(self.lights)
        self.world_light(world)
        group = self.light_group(world, f'world {world.name}') if len(self.lights) > first else None
        if group:
            self.lights[-1]['group'] = group

    def world_light(self, world):
        if not world.use_nodes:
            self.constant_environment(world.color, 1.0)
            return
        out = next((n for n in world.node_tree.nodes if n.type == 'OUTPUT_WORLD' and n.is_active_output), None)
        if out is None or not out.inputs['Surface'].is_linked:
            return
        bg = out.inputs['Surface'].links[0].from_node
        if bg.type != 'BACKGROUND':
            self.warn(f'world {world.name}: surface node {bg.name} not exported (only Background)')
            return
        strength = bg.inputs['Strength'].default_value
        if bg.inputs['Strength'].is_linked:
            self.warn(f'world {world.name}: linked strength not exported (its value {strength:g} is used)')
        col = bg.inputs['Color']
        if not col.is_linked:
            self.constant_environment(col.default_value, strength)
            return
        tex = col.links[0].from_node
        if tex.type != 'TEX_ENVIRONMENT' or tex.image is None:
            self.warn(f'world {world.name}: colour node {tex.name} not exported (black world)')
            return
        if tex.projection != 'EQUIRECTANGULAR':
            self.warn(f'world {world.name}: {tex.projection} projection not exported (read as equirectangular)')
        rotation_z = 0.0
        if tex.inputs['Vector'].is_linked:
            mapping = tex.inputs['Vector'].links[0].from_node
            rotation_z = self.environment_mapping(world.name, mapping)
        self.lights.append({'type': 'environment', 'file': self.image_file(tex.image, hdr=True),
                            'scale': strength, 'rotation': units.environment_rotation(rotation_z)})

    def environment_mapping(self, world_name, mapping):
        if mapping.type != 'MAPPING':
            self.warn(f'world {world_name}: environment vector from {mapping.name} not exported')
            return 0.0
        rot = mapping.inputs['Rotation'].default_value
        loc = mapping.inputs['Location'].default_value
        scale = mapping.inputs['Scale'].default_value
        if abs(rot[0]) > 1e-6 or abs(rot[1]) > 1e-6 or any(abs(s - 1.0) > 1e-6 for s in scale) or \
                any(abs(x) > 1e-6 for x in loc) or mapping.vector_type not in ('POINT', 'TEXTURE'):
            self.warn(f'world {world_name}: mapping other than a rotation about z not exported')
        src = mapping.inputs['Vector']
        if src.is_linked and not (src.links[0].from_node.type == 'TEX_COORD' and
                                  src.links[0].from_socket.name == 'Generated'):
            self.warn(f'world {world_name}: mapping input other than Generated coordinates not exported')
        return rot[2] if mapping.vector_type == 'POINT' else -rot[2]

    def constant_environment(self, colour, strength):
        radiance = units.scaled_colour(colour, strength)
        if max(radiance) > 0.0:
            self.lights.append({'type': 'environment', 'radiance': radiance})

    # ------------------------------------------------------------------ the scene
    def run(self):
        camera, film = self.camera()
        for inst in self.depsgraph.object_instances:
            ob = inst.object
            if inst.is_instance:  # placed by a collection instance: hidden when its instancer is
                if inst.parent.original.hide_render:
                    continue
            elif ob.original.hide_render or any(c.hide_render for c in ob.original.users_collection):
                continue
            matrix = inst.matrix_world.copy()
            if ob.type in ('MESH', 'CURVE', 'SURFACE', 'META', 'FONT'):
                self.mesh_object(ob, matrix)
            elif ob.type == 'LIGHT':
                self.light(ob, matrix)
            elif ob.type in ('CAMERA', 'EMPTY'):
                continue
            else:
                self.warn(f'object {ob.original.name}: type {ob.type} not exported')
        self.world()
        if not self.shapes:
            self.warn('scene: nothing to render; a tiny black disk far below is exported (ochre needs a shape)')
            self.materials['black'] = {'type': 'lambert', 'color': 0.0}
            self.shapes.append({'type': 'disk', 'radius': 1e-6, 'material': 'black',
                                'transform': [{'translate': [0, -1e6, 0]}]})
        stem = os.path.splitext(os.path.basename(self.filepath))[0]
        scene = {'description': f'exported from Blender {bpy.app.version_string}: {bpy.data.filepath or "unsaved"}'}
        if self.includes:
            scene['include'] = self.includes
        if camera is not None:
            scene['camera'] = camera
        scene['film'] = film
        scene['integrator'] = {'spp': int(self.samples), 'max_depth': int(self.max_depth)}
        scene['output'] = {'exr': stem + '.exr', 'png': stem + '.png'}
        scene['presets'] = {'fast': {'description': 'a quick look: 16 samples, 4 bounces',
                                     'integrator': {'spp': min(16, int(self.samples)),
                                                    'max_depth': min(4, int(self.max_depth))}},
                            'final': {'description': 'the scene as exported'}}
        scene['materials'] = self.materials
        scene['lights'] = self.lights
        scene['shapes'] = self.shapes
        bad = _non_finite(scene)
        if bad:
            raise ValueError(f'{self.filepath}: {bad} is not a finite number (a NaN or infinite value in Blender)')
        os.makedirs(self.dir, exist_ok=True)
        with open(self.filepath, 'w', encoding='utf-8') as f:
            f.write(_dumps(scene))
        return self.warnings


# A list of numbers as json.dumps indents it (a string never holds a raw line break, so none is matched).
NUMBER_LIST = re.compile(r'\[\n\s*(-?[0-9][-0-9.eE+]*(?:,\n\s*-?[0-9][-0-9.eE+]*)*)\n\s*\]')


def _dumps(scene):
    """The scene as indented JSON with each list of numbers on one line."""
    text = json.dumps(scene, indent=1)
    return NUMBER_LIST.sub(lambda m: '[' + ', '.join(x.strip() for x in m.group(1).split(',')) + ']', text) + '\n'


def _emits(material):
    """Whether an ochre material (shorthand or graph) has an emission node."""
    if not isinstance(material, dict):
        return False
    nodes = material.get('nodes', {'': material})
    return any(n.get('type') == 'emission' for n in nodes.values())


def _non_finite(value, path=''):
    """The JSON path of the first NaN or infinite number in value, or None."""
    if isinstance(value, float) and not math.isfinite(value):
        return path or 'a value'
    items = value.items() if isinstance(value, dict) else enumerate(value) if isinstance(value, list) else ()
    for key, item in items:
        found = _non_finite(item, f'{path}.{key}' if isinstance(key, str) else f'{path}[{key}]')
        if found:
            return found.lstrip('.')
    return None


class MaterialTranslator:
    """A Blender material's node tree as an ochre material graph (docs/nodes.md)."""

    def __init__(self, exporter, mat):
        self.exporter, self.mat, self.nodes, self.count = exporter, mat, {}, 0

    def warn(self, what):
        self.exporter.warn(f'material {self.mat.name}: {what}')

    def node(self, prefix, value):
        self.count += 1
        name = f'{prefix}{self.count}'
        self.nodes[name] = value
        return name

    def translate(self):
        mat = self.mat
        if not mat.use_nodes or mat.node_tree is None:
            return {'type': 'lambert', 'color': [float(x) for x in mat.diffuse_color[:3]]}
        out = next((n for n in mat.node_tree.nodes if n.type == 'OUTPUT_MATERIAL' and n.is_active_output), None)
        if out is None or not out.inputs['Surface'].is_linked:
            self.warn('no surface shader (black)')
            return {'type': 'lambert', 'color': 0.0}
        if out.inputs['Volume'].is_linked:
            self.warn('volume shader not exported')
        if out.inputs['Displacement'].is_linked:
            self.warn('displacement not exported')
        root = self.closure(out.inputs['Surface'].links[0].from_node)
        return {'nodes': self.nodes, 'output': root}

    def closure(self, node):
        t = node.type
        if t == 'BSDF_PRINCIPLED':
            return self.principled(node)
        if t == 'BSDF_DIFFUSE':
            if node.inputs['Roughness'].default_value > 0.0 or node.inputs['Roughness'].is_linked:
                self.warn(f'{node.name}: diffuse roughness not exported (Lambertian)')
            return self.node('diffuse', {'type': 'lambert', 'color': self.colour(node.inputs['Color'])})
        if t == 'EMISSION':
            return self.node('emission', {'type': 'emission', 'color': self.colour(node.inputs['Color']),
                                          'strength': self.number(node.inputs['Strength'])})
        if t == 'BSDF_GLOSSY':
            return self.metal(node.inputs['Color'], node.inputs['Roughness'])
        if t == 'ADD_SHADER':
            a, b = (self.input_closure(node.inputs[i]) for i in (0, 1))
            return self.node('add', {'type': 'add', 'a': {'link': a}, 'b': {'link': b}})
        if t == 'MIX_SHADER':
            a, b = (self.input_closure(node.inputs[i]) for i in (1, 2))
            return self.node('mix', {'type': 'mix', 'a': {'link': a}, 'b': {'link': b},
                                     'factor': self.number(node.inputs['Fac'])})
        self.warn(f'shader {node.name} ({t}) not exported (grey diffuse instead)')
        return self.node('diffuse', {'type': 'lambert', 'color': 0.8})

    def input_closure(self, socket):
        if not socket.is_linked:
            return self.node('black', {'type': 'lambert', 'color': 0.0})
        return self.closure(socket.links[0].from_node)

    def number(self, socket):
        if socket.is_linked:
            self.warn(f'{socket.node.name}: linked {socket.name} not exported (its value '
                      f'{socket.default_value:g} is used)')
        return float(socket.default_value)

    def colour(self, socket):
        """A colour input: a constant [r, g, b] or a link to an image texture or the vertex colours."""
        value = [float(x) for x in socket.default_value[:3]]
        if not socket.is_linked:
            return value
        src = socket.links[0].from_node
        if src.type == 'TEX_IMAGE' and src.image is not None:
            if src.inputs['Vector'].is_linked:
                self.warn(f'{src.name}: texture coordinates other than the UV map not exported')
            if src.extension != 'REPEAT':
                self.warn(f'{src.name}: extension {src.extension} not exported (ochre repeats textures)')
            if src.interpolation == 'Closest':
                self.warn(f'{src.name}: closest interpolation not exported (filtered lookups)')
            colorspace = 'linear' if src.image.colorspace_settings.name in ('Linear', 'Non-Color', 'Raw') \
                else 'srgb'
            if src.image.is_float and colorspace == 'srgb':
                colorspace = 'linear'
            tex = self.node('texture', {'type': 'texture', 'file': self.exporter.image_file(src.image),
                                        'colorspace': colorspace})
            return {'link': tex + '.color'}
        if src.type in ('VERTEX_COLOR', 'ATTRIBUTE'):
            return {'link': self.node('vertex_colour', {'type': 'vertex_colour'}) + '.color'}
        if src.type == 'RGB':
            return [float(x) for x in src.outputs[0].default_value[:3]]
        self.warn(f'{socket.node.name}: {socket.name} from {src.name} ({src.type}) not exported '
                  f'(the constant {value} is used)')
        return value

    def metal(self, colour_socket, roughness_socket):
        """A metal of the given colour: silver's conductor (nearly white) tinted by the colour."""
        conductor = self.node('metal', {'type': 'conductor', 'metal': 'Ag',
                                        'roughness': units.ggx_alpha(self.number(roughness_socket))})
        return self.node('tint', {'type': 'multiply', 'a': {'link': conductor},
                                  'b': self.colour(colour_socket)})

    def principled(self, node):
        inp = node.inputs
        base = self.colour(inp['Base Color'])
        metallic = min(max(self.number(inp['Metallic']), 0.0), 1.0)
        transmission = min(max(self.number(inp['Transmission']), 0.0), 1.0)
        if self.number(inp['Subsurface']) > 0.0:
            self.warn(f'{node.name}: subsurface not exported')
        for key in ('Sheen', 'Clearcoat'):
            if self.number(inp[key]) > 0.0:
                self.warn(f'{node.name}: {key.lower()} not exported')
        if self.number(inp['Alpha']) < 1.0:
            self.warn(f'{node.name}: alpha not exported (opaque)')
        if inp['Normal'].is_linked:
            self.warn(f'{node.name}: normal map not exported')
        result = None
        if metallic < 1.0:
            result = self.node('diffuse', {'type': 'lambert', 'color': base})
        if metallic > 0.0:
            conductor = self.node('metal', {'type': 'conductor', 'metal': 'Ag',
                                            'roughness': units.ggx_alpha(self.number(inp['Roughness']))})
            metal = self.node('tint', {'type': 'multiply', 'a': {'link': conductor}, 'b': base})
            result = metal if result is None else self.node(
                'mix', {'type': 'mix', 'a': {'link': result}, 'b': {'link': metal}, 'factor': metallic})
        if transmission > 0.0 and metallic < 1.0:
            roughness = units.ggx_alpha(self.number(inp['Roughness']))
            if roughness > 0.0:
                self.warn(f'{node.name}: rough transmission exported as reflection only (ochre\'s rough '
                          'dielectric does not refract)')
            glass = self.node('glass', {'type': 'dielectric', 'ior': max(self.number(inp['IOR']), 0.01),
                                        'roughness': roughness})
            result = self.node('mix', {'type': 'mix', 'a': {'link': result}, 'b': {'link': glass},
                                       'factor': transmission * (1.0 - metallic)})
        strength = self.number(inp['Emission Strength'])
        emission = inp['Emission']
        if strength > 0.0 and (emission.is_linked or max(emission.default_value[:3]) > 0.0):
            glow = self.node('emission', {'type': 'emission', 'color': self.colour(emission),
                                          'strength': strength})
            result = self.node('add', {'type': 'add', 'a': {'link': result}, 'b': {'link': glow}})
        return result


def export_scene(depsgraph, filepath, samples=None, max_depth=None):
    """Write the scene of `depsgraph` to `filepath` (JSON) and its assets folder; returns the warnings."""
    return Exporter(depsgraph, filepath, samples=samples, max_depth=max_depth).run()
