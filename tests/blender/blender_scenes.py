"""Run inside Blender by test_blender.py: build a test scene by script, export it with the add-on, render it
with ochre and with Cycles (or with the ochre render engine) and print the mean colours as one JSON line.

    blender -b --factory-startup --python blender_scenes.py -- CASE WORK_DIR OCHRE_BINARY

CASE: point, spot, area, ellipse, sun, world, envmap (a grey Lambertian plane lit by that light alone; envmap: an
environment texture turned by a Mapping node, partly in view), suzanne (Suzanne on a textured plane under an
area light), ortho, vertical (that scene through an orthographic camera in a portrait image, and with the
sensor fitted vertically), engine (the suzanne scene through the render engine and directly), cave and cornell
(round trips: scenes/default, scenes/cornell-box imported into Blender, exported back, both rendered by
ochre); several separated by commas.
"""
import json
import math
import os
import subprocess
import sys

import bpy
import numpy as np

ROOT = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..'))
sys.path.insert(0, os.path.join(ROOT, 'tools', 'blender'))

import ochre_blender  # noqa: E402 (after the path above)
from ochre_blender import export, exr, import_scene  # noqa: E402

CASES, WORK, OCHRE = sys.argv[sys.argv.index('--') + 1:][:3]
WIDTH, HEIGHT, SPP, MAX_DEPTH = 64, 48, 64, 4


def clear():
    for ob in list(bpy.data.objects):
        bpy.data.objects.remove(ob)


def diffuse_material(name, colour, principled=False):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nt = mat.node_tree
    out = nt.nodes['Material Output']
    if principled:
        node = nt.nodes['Principled BSDF']
        node.inputs['Base Color'].default_value = (*colour, 1.0)
        node.inputs['Specular'].default_value = 0.0
        node.inputs['Roughness'].default_value = 1.0
    else:
        nt.nodes.remove(nt.nodes['Principled BSDF'])
        node = nt.nodes.new('ShaderNodeBsdfDiffuse')
        node.inputs['Color'].default_value = (*colour, 1.0)
        node.inputs['Roughness'].default_value = 0.0
    nt.links.new(node.outputs[0], out.inputs['Surface'])
    return mat, node


def add_camera(location, rotation_deg, lens=35.0):
    cam = bpy.data.cameras.new('cam')
    cam.lens = lens
    ob = bpy.data.objects.new('cam', cam)
    ob.location = location
    ob.rotation_euler = [math.radians(a) for a in rotation_deg]
    bpy.context.scene.collection.objects.link(ob)
    bpy.context.scene.camera = ob
    return ob


def add_light(kind, location, rotation_deg=(0, 0, 0), **props):
    light = bpy.data.lights.new(kind.lower(), kind)
    for k, v in props.items():
        setattr(light, k, v)
    ob = bpy.data.objects.new(kind.lower(), light)
    ob.location = location
    ob.rotation_euler = [math.radians(a) for a in rotation_deg]
    bpy.context.scene.collection.objects.link(ob)
    return ob


def black_world():
    world = bpy.data.worlds.new('world')
    world.use_nodes = True
    world.node_tree.nodes['Background'].inputs['Color'].default_value = (0, 0, 0, 1)
    bpy.context.scene.world = world
    return world


def plane(size, material):
    bpy.ops.mesh.primitive_plane_add(size=size)
    ob = bpy.context.active_object
    ob.data.materials.append(material)
    return ob


def light_scene(kind):
    clear()
    world = black_world()
    mat, _ = diffuse_material('grey', (0.5, 0.5, 0.5))
    plane(8.0, mat)
    add_camera((0.0, -3.0, 2.2), (55.0, 0.0, 0.0))
    if kind == 'point':
        add_light('POINT', (0.3, -0.2, 1.2), energy=150.0, shadow_soft_size=0.0)
    elif kind == 'spot':
        add_light('SPOT', (0.2, 0.0, 1.6), (-15.0, 0.0, 0.0), energy=400.0, shadow_soft_size=0.0,
                  spot_size=math.radians(60.0), spot_blend=0.3)
    elif kind == 'area':
        add_light('AREA', (0.0, 0.2, 1.4), (10.0, -5.0, 30.0), energy=60.0, shape='RECTANGLE', size=0.6,
                  size_y=0.3)
    elif kind == 'ellipse':  # an elliptic area light, scaled by its object: a disk shape in ochre
        light = add_light('AREA', (0.3, 0.0, 1.2), (0.0, 20.0, 0.0), energy=40.0, shape='ELLIPSE', size=0.5,
                          size_y=0.2)
        light.scale = (1.5, 1.0, 1.0)
    elif kind == 'sun':
        add_light('SUN', (0.0, 0.0, 5.0), (30.0, 10.0, 0.0), energy=2.0, angle=0.0)
    elif kind == 'world':
        world.node_tree.nodes['Background'].inputs['Color'].default_value = (0.4, 0.5, 0.6, 1.0)
        world.node_tree.nodes['Background'].inputs['Strength'].default_value = 1.5
    elif kind == 'envmap':
        image = bpy.data.images.new('sky', 64, 32, float_buffer=True)
        image.generated_type = 'COLOR_GRID'
        nt = world.node_tree
        env, mapping = nt.nodes.new('ShaderNodeTexEnvironment'), nt.nodes.new('ShaderNodeMapping')
        coords = nt.nodes.new('ShaderNodeTexCoord')
        env.image = image
        mapping.inputs['Rotation'].default_value = (0.0, 0.0, math.radians(40.0))
        nt.links.new(coords.outputs['Generated'], mapping.inputs['Vector'])
        nt.links.new(mapping.outputs['Vector'], env.inputs['Vector'])
        nt.links.new(env.outputs['Color'], nt.nodes['Background'].inputs['Color'])
        nt.nodes['Background'].inputs['Strength'].default_value = 0.8
        bpy.context.scene.camera.rotation_euler = (math.radians(80.0), 0.0, math.radians(30.0))


def suzanne_scene():
    clear()
    black_world()
    image = bpy.data.images.new('grid', 256, 256)
    image.generated_type = 'COLOR_GRID'
    floor_mat, bsdf = diffuse_material('floor', (1.0, 1.0, 1.0), principled=True)
    tex = floor_mat.node_tree.nodes.new('ShaderNodeTexImage')
    tex.image = image
    floor_mat.node_tree.links.new(tex.outputs['Color'], bsdf.inputs['Base Color'])
    plane(6.0, floor_mat)
    bpy.ops.mesh.primitive_monkey_add(location=(-0.6, 0.0, 0.8), rotation=(0.0, 0.0, math.radians(20.0)))
    monkey = bpy.context.active_object
    subsurf = monkey.modifiers.new('subdivision', 'SUBSURF')
    subsurf.levels = subsurf.render_levels = 1  # the same mesh for the viewport (export) and F12 (engine)
    bpy.ops.object.shade_smooth()
    skin, _ = diffuse_material('skin', (0.8, 0.35, 0.2))
    monkey.data.materials.append(skin)
    monkeys = bpy.data.collections.new('monkeys')  # a collection instance: one PLY for both Suzannes
    bpy.context.scene.collection.children.link(monkeys)
    for owner in list(monkey.users_collection):
        owner.objects.unlink(monkey)
    monkeys.objects.link(monkey)
    twin = bpy.data.objects.new('twin', None)
    twin.instance_type, twin.instance_collection = 'COLLECTION', monkeys
    twin.location = (1.5, 0.4, 0.0)
    bpy.context.scene.collection.objects.link(twin)
    bpy.ops.mesh.primitive_cube_add(size=0.4, location=(-1.6, -1.0, 0.2))
    cube = bpy.context.active_object
    paint = cube.data.color_attributes.new('paint', 'BYTE_COLOR', 'POINT')  # vertex colours: 8 corners
    for i, value in enumerate(paint.data):
        value.color = (0.9 if i & 1 else 0.1, 0.8 if i & 2 else 0.2, 0.7 if i & 4 else 0.05, 1.0)
    painted, bsdf = diffuse_material('painted', (1.0, 1.0, 1.0))
    colours = painted.node_tree.nodes.new('ShaderNodeVertexColor')
    colours.layer_name = 'paint'
    painted.node_tree.links.new(colours.outputs['Color'], bsdf.inputs['Color'])
    cube.data.materials.append(painted)
    for x in (-0.8, 0.0):  # linked duplicates: one PLY for the three cubes
        dup = cube.copy()
        dup.location.x = x
        bpy.context.scene.collection.objects.link(dup)
    add_light('AREA', (0.5, -1.0, 3.0), (20.0, 0.0, 0.0), energy=400.0, shape='SQUARE', size=1.0)
    add_camera((0.0, -5.0, 3.0), (60.0, 0.0, 0.0), lens=30.0)


def settings(engine):
    scene = bpy.context.scene
    r, c = scene.render, scene.cycles
    r.engine = engine
    r.resolution_x, r.resolution_y, r.resolution_percentage = WIDTH, HEIGHT, 100
    c.device, c.samples, c.seed = 'CPU', SPP * 2, 0
    c.use_adaptive_sampling = c.use_denoising = False
    scene.view_layers[0].cycles.use_denoising = False
    c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = MAX_DEPTH - 1
    c.sample_clamp_direct = c.sample_clamp_indirect = 0.0
    c.caustics_reflective = c.caustics_refractive = True
    c.pixel_filter_type, c.filter_width = 'BOX', 1.0
    r.threads_mode, r.threads = 'FIXED', 2
    r.use_compositing = r.use_sequencer = False
    scene.view_settings.view_transform, scene.view_settings.look = 'Standard', 'None'
    im = r.image_settings
    im.file_format, im.color_depth, im.color_mode = 'OPEN_EXR', '32', 'RGB'
    scene.ochre.samples, scene.ochre.max_depth, scene.ochre.preset = SPP, MAX_DEPTH, 'final'


def exr_mean(path):
    """The mean colour of an EXR and the means of its 4 x 3 blocks (3 x 4 for a portrait image)."""
    img = bpy.data.images.load(path)
    w, h = img.size
    px = np.array(img.pixels[:], dtype=np.float64).reshape(h, w, img.channels)[:, :, :3]
    bpy.data.images.remove(img)
    rows, cols = (3, 4) if w >= h else (4, 3)
    blocks = px.reshape(rows, h // rows, cols, w // cols, 3).mean(axis=(1, 3)).reshape(-1, 3)
    return px.reshape(-1, 3).mean(axis=0).tolist(), blocks.tolist()


def render_ochre(scene_json, exr):
    subprocess.run([OCHRE, 'render', scene_json, '-o', exr, '-q', '--threads', '2'], check=True)
    return exr_mean(exr)


def render_blender(path):
    scene = bpy.context.scene
    scene.render.filepath = path
    bpy.ops.render.render(write_still=True)
    return exr_mean(path)


def spot_profile():
    """A wide spot straight down on a plane, seen through a tiny orthographic camera on its axis and 25 degrees
    off it: (angle, ochre, Cycles) radiances."""
    out = []
    for angle in (0.0, 25.0):
        clear()
        black_world()
        mat, _ = diffuse_material('grey', (0.5, 0.5, 0.5))
        plane(20.0, mat)
        cam = add_camera((2.0 * math.tan(math.radians(angle)), 0.0, 1.0), (0.0, 0.0, 0.0))
        cam.data.type, cam.data.ortho_scale = 'ORTHO', 0.02
        add_light('SPOT', (0.0, 0.0, 2.0), energy=100.0, shadow_soft_size=0.0, spot_size=math.radians(80.0),
                  spot_blend=0.0)
        settings('CYCLES')
        path = os.path.join(WORK, f'spot_profile_{angle:g}.json')
        export.export_scene(bpy.context.evaluated_depsgraph_get(), path)
        out.append([angle, render_ochre(path, path[:-5] + '_ochre.exr')[0][1],
                    render_blender(path[:-5] + '_cycles.exr')[0][1]])
    return out


def material_variety():
    """Every mapped shader on its own sphere (metal, half metal, glass, rough glass, emission, glossy, add and mix
    shaders, an unmapped shader): ochre accepts the exported materials and the approximations are warned about."""
    clear()
    black_world()
    add_light('SUN', (0.0, 0.0, 5.0), (20.0, 0.0, 0.0), energy=3.0, angle=0.0)
    add_camera((0.0, -8.0, 1.0), (85.0, 0.0, 0.0))
    variants = []
    for name, values in (('metal', {'Metallic': 1.0, 'Roughness': 0.3}), ('half_metal', {'Metallic': 0.5}),
                         ('glass', {'Transmission': 1.0, 'Roughness': 0.0}),
                         ('rough_glass', {'Transmission': 1.0, 'Roughness': 0.4}),
                         ('glow', {'Emission': (1.0, 0.5, 0.2, 1.0), 'Emission Strength': 2.0})):
        mat = bpy.data.materials.new(name)
        mat.use_nodes = True
        bsdf = mat.node_tree.nodes['Principled BSDF']
        for key, value in values.items():
            bsdf.inputs[key].default_value = value
        variants.append(mat)
    for name, kind in (('glossy', 'ShaderNodeBsdfGlossy'), ('added', 'ShaderNodeAddShader'),
                       ('mixed', 'ShaderNodeMixShader'), ('velvet', 'ShaderNodeBsdfVelvet')):
        mat, _ = diffuse_material(name, (0.5, 0.5, 0.5))
        nt = mat.node_tree
        node = nt.nodes.new(kind)
        if kind in ('ShaderNodeAddShader', 'ShaderNodeMixShader'):
            nt.links.new(nt.nodes['Diffuse BSDF'].outputs[0], node.inputs[-1])
            nt.links.new(nt.nodes.new('ShaderNodeEmission').outputs[0], node.inputs[-2])
        nt.links.new(node.outputs[0], nt.nodes['Material Output'].inputs['Surface'])
        variants.append(mat)
    for i, mat in enumerate(variants):
        bpy.ops.mesh.primitive_uv_sphere_add(radius=0.4, location=(i - len(variants) / 2, 0.0, 0.0))
        bpy.context.active_object.data.materials.append(mat)
    path = os.path.join(WORK, 'materials.json')
    warnings = export.export_scene(bpy.context.evaluated_depsgraph_get(), path, samples=4)
    render_ochre(path, os.path.join(WORK, 'materials.exr'))
    return warnings


def library_materials():
    """`ochre_material` on an object (the pigment library's red ochre), on a material (limestone) and an
    unknown name: the scene includes the library files, renders, and the unknown name is warned about."""
    bpy.data.objects['Cube']['ochre_material'] = 'red_ochre'
    bpy.data.materials['floor']['ochre_material'] = 'limestone'
    bpy.data.materials['skin']['ochre_material'] = 'no_such_pigment'
    path = os.path.join(WORK, 'library.json')
    warnings = export.export_scene(bpy.context.evaluated_depsgraph_get(), path, samples=4)
    render_ochre(path, os.path.join(WORK, 'library.exr'))
    with open(path, encoding='utf-8') as f:
        scene = json.load(f)
    return {'include': [os.path.basename(p) for p in scene.get('include', [])], 'warnings': warnings,
            'materials': sorted({s['material'] for s in scene['shapes']})}


def framing(case):
    """The Suzanne scene through other cameras: orthographic in a portrait image (sensor fit Auto), and
    perspective with the sensor fitted vertically."""
    scene = bpy.context.scene
    cam = scene.camera.data
    if case == 'ortho':
        cam.type, cam.ortho_scale = 'ORTHO', 5.0
        scene.render.resolution_x, scene.render.resolution_y = HEIGHT, WIDTH
    else:
        cam.sensor_fit, cam.sensor_height, cam.lens = 'VERTICAL', 20.0, 28.0


ROUND_TRIP_SPP = 16


def exr_pixels(path):
    img = bpy.data.images.load(path)
    w, h = img.size
    px = np.array(img.pixels[:], dtype=np.float64).reshape(h, w, img.channels)[:, :, :3]
    bpy.data.images.remove(img)
    return px


ROUND_TRIPS = {'cave': ('scenes/default/default.json', '160x90'),  # its material in a library file
               'cornell': ('scenes/cornell-box/cornell-box.json', '64x64')}  # materials beside the shapes


def round_trip(case):
    """An ochre scene imported into an empty Blender scene, exported back and rendered by ochre beside the
    original (same seed; and the original with another seed, for the noise level)."""
    clear()
    relative, resolution = ROUND_TRIPS[case]
    original = os.path.join(ROOT, relative)
    result = {'case': case, 'import_warnings': import_scene.import_scene(original, OCHRE)}
    scene_json = os.path.join(WORK, case, case + '.json')
    result['warnings'] = export.export_scene(bpy.context.evaluated_depsgraph_get(), scene_json)
    with open(scene_json, encoding='utf-8') as f:
        exported = json.load(f)
    result['lights'], result['include'] = exported['lights'], exported.get('include', [])
    result['materials'] = sorted({s.get('material') for s in exported['shapes']})
    images = {}
    for name, scene, seed in (('original', original, 0), ('round_trip', scene_json, 0), ('original_seed1', original, 1)):
        out = os.path.join(WORK, case, name + '.exr')
        subprocess.run([OCHRE, 'render', scene, '-o', out, '-q', '--threads', '2', '--resolution', resolution,
                        '--spp', str(ROUND_TRIP_SPP), '--seed', str(seed)], check=True)
        images[name] = exr_pixels(out)

    def relmse(a, b):
        return float(np.mean((a - b) ** 2 / (b ** 2 + 1e-2)))
    ref = images['original']
    result['means'] = {k: v.reshape(-1, 3).mean(axis=0).tolist() for k, v in images.items()}
    result['relmse_round_trip'] = relmse(images['round_trip'], ref)
    result['relmse_other_seed'] = relmse(images['original_seed1'], ref)
    print('RESULT ' + json.dumps(result))
    sys.stdout.flush()


def run_case(case):
    if case in ROUND_TRIPS:
        return round_trip(case)
    if case in ('suzanne', 'engine', 'ortho', 'vertical'):
        suzanne_scene()
    else:
        light_scene(case)
    scene_json = os.path.join(WORK, case + '.json')
    result = {'case': case}
    settings('OCHRE' if case == 'engine' else 'CYCLES')
    if case in ('ortho', 'vertical'):
        framing(case)
    result['warnings'] = export.export_scene(bpy.context.evaluated_depsgraph_get(), scene_json)
    if case == 'engine':
        os.environ['OCHRE_EXECUTABLE'] = OCHRE
        bpy.context.scene.ochre.threads = 2
        bpy.context.scene.ochre.spectral_bins = 4  # more EXR layers: the render result still takes R, G, B
        bpy.data.objects['area']['ochre_light_group'] = 'key'  # and a light group
        bpy.context.scene.ochre.exr_copy = os.path.join(WORK, 'engine_kept.exr')
        result['ochre'], result['ochre_blocks'] = render_ochre(scene_json, os.path.join(WORK, 'engine_direct.exr'))
        result['other'], result['other_blocks'] = render_blender(os.path.join(WORK, 'engine_result.exr'))
        result['kept_channels'] = exr.channel_names(bpy.context.scene.ochre.exr_copy)
    else:
        result['ochre'], result['ochre_blocks'] = render_ochre(scene_json, os.path.join(WORK, case + '_ochre.exr'))
        result['other'], result['other_blocks'] = render_blender(os.path.join(WORK, case + '_cycles.exr'))
    with open(scene_json, encoding='utf-8') as f:
        result['files'] = sorted({s['file'] for s in json.load(f)['shapes'] if 'file' in s})
    if case == 'spot':
        result['profile'] = spot_profile()
    if case == 'suzanne':
        result['library'] = library_materials()
        result['material_warnings'] = material_variety()
    if case == 'engine':  # a NaN in the scene: F12 fails with a message naming the value, nothing renders
        bpy.data.objects['area'].data.energy = float('nan')
        try:
            bpy.ops.render.render()
            result['nan_error'] = None
        except RuntimeError as e:
            result['nan_error'] = str(e)
    print('RESULT ' + json.dumps(result))
    sys.stdout.flush()


def main():
    ochre_blender.register()
    os.makedirs(WORK, exist_ok=True)
    for case in CASES.split(','):
        run_case(case)


try:
    main()
except Exception as e:  # noqa: BLE001 (any failure is the test's failure, with its message)
    import traceback
    traceback.print_exc()
    print(f'blender_scenes.py: {e}', file=sys.stderr)
    sys.stdout.flush()
    os._exit(1)
os._exit(0)
