"""Build an ochre scene (a subset of docs/scene-format.md) in Blender and render it with Cycles.

    blender -b --factory-startup --debug-cycles --python tools/dev/cycles/make_and_render.py -- \
        --scene scenes/benchmark/cbox-matched.json --spp 64 --seed 0 --out out/cbox_64.exr

The benchmark harness of docs/performance.md ("Time to error against Cycles"): run_benchmark.py calls
this once per render. Read from the ochre scene: camera (perspective: eye, target, up, fov across the
shorter axis), film resolution, integrator max_depth (ochre counts scattering events, Cycles bounces
after the first: bounces = max_depth - 1), meshes (OBJ, fan-triangulated or kept as polygons for
Catmull-Clark subdivision, UVs, transforms), planes and spheres, `subdivision` and `displacement`
(Blender's Subdivision Surface and Displace modifiers; a procedural `displacement.noise`, which Blender has
no counterpart for, through `ochre export-mesh` (--ochre): the triangles ochre renders, with its shading
normals), lambert (constant, [r,g,b], spectrum file or texture), the add-of-lambert-and-emission light
material, conductors (metal, roughness), an HDR environment (scale, rotation), spot lights and flame lights
(a point light of the flame's radius and blackbody colour, power matched by hand).

Spectra become linear Rec.709 (Blender's scene-linear space) with the CIE 1931 2-degree observer:
an emitted spectrum E gives M int(E xyz) / int(ybar) (what a spectral renderer writes for a pixel that
sees E); a reflectance spectrum r gives, per channel c, [M int(E r xyz)]_c / [M int(E xyz)]_c under the
scene's area-light spectrum E (so the single-bounce colour of each surface equals the spectral result;
further bounces are RGB products, inherent to an RGB renderer), or under D65 without an area light.
A conductor's colour is its normal-incidence Fresnel reflectance under D65 (Cycles 3.4 has no complex
Fresnel); ochre's GGX alpha is Blender's roughness squared.

Writes OUT (32-bit float linear RGB EXR, ZIP = lossless) and OUT with .json (the parameters used and
the wall and CPU time of the render call). --debug-cycles makes Cycles log 'Render time (without
synchronization)', which run_benchmark.py reads.
"""
import argparse, json, math, os, subprocess, sys, time
import bpy
import numpy as np
from mathutils import Matrix, Vector

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, '..', '..', '..'))
ap = argparse.ArgumentParser()
ap.add_argument('--scene', default=os.path.join(ROOT, 'scenes/benchmark/cbox-matched.json'))
ap.add_argument('--spp', type=int, default=16)
ap.add_argument('--seed', type=int, default=0)
ap.add_argument('--res', default='', help='WxH; default: the scene film resolution')
ap.add_argument('--threads', type=int, default=2)
ap.add_argument('--adaptive-threshold', type=float, default=0.0,
                help='Cycles adaptive sampling with this noise threshold (0: off, every pixel --spp samples)')
ap.add_argument('--ochre', default=os.path.join(ROOT, 'build/bin/ochre'),
                help='ochre binary: writes meshes whose displacement is procedural (ochre export-mesh)')
ap.add_argument('--out', required=True)
args = ap.parse_args(sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else [])

scene_path = os.path.abspath(args.scene)
scene_dir = os.path.dirname(scene_path)
S = json.load(open(scene_path))


# The flame presets of docs/lights.md (radius in m, CCT in K, intensity in cd) and the Blender point-light power
# per candela that gives an image as bright as ochre's (matched on the cave pair, docs/performance.md).
FLAME_PRESETS = {'torch': dict(radius=0.08, cct=1700, intensity=5.0),
                 'torch_juniper': dict(radius=0.08, cct=1700, intensity=5.0),
                 'grease_lamp': dict(radius=0.015, cct=1850, intensity=1.0),
                 'fireplace': dict(radius=0.25, cct=1650, intensity=12.0)}
FLAME_WATTS_PER_CANDELA = 0.94 * 4 * math.pi  # 4 pi gave a Cycles image 1/0.94 as bright (16 spp means)


def asset(name):
    return os.path.join(scene_dir, name)


# ---------------------------------------------------------------- spectra -> linear Rec.709
def read_csv(path):
    rows = [l.split(',') for l in open(path) if l[:1].isdigit()]
    return np.array(rows, dtype=np.float64)


cmf = read_csv(os.path.join(ROOT, 'spectra/data/cie1931_2deg_1nm.csv'))  # nm, xbar, ybar, zbar
LAM, XYZ = cmf[:, 0], cmf[:, 1:]
XYZ_TO_REC709 = np.array([[3.2404542, -1.5371385, -0.4985314],
                          [-0.9692660, 1.8760108, 0.0415560],
                          [0.0556434, -0.2040259, 1.0572252]])
d65 = read_csv(os.path.join(ROOT, 'spectra/data/d65_5nm.csv'))
D65 = np.interp(LAM, d65[:, 0], d65[:, 1])


def spectrum_file(spec):  # {"file": csv, "extrapolate": "zero"} on the 1 nm CIE grid
    t = read_csv(asset(spec['file']))
    zero = spec.get('extrapolate') == 'zero'
    return np.interp(LAM, t[:, 0], t[:, 1], left=0.0 if zero else t[0, 1], right=0.0 if zero else t[-1, 1])


def emitted_rgb(E):
    return XYZ_TO_REC709 @ (E @ XYZ) / XYZ[:, 1].sum()


def reflectance_rgb(r, E):
    return emitted_rgb(E * r) / emitted_rgb(E)


def fresnel_f0_rgb(metal):
    t = read_csv(os.path.join(ROOT, f'spectra/data/ior_{metal}_5nm.csv'))
    n, k = np.interp(LAM, t[:, 0], t[:, 1]), np.interp(LAM, t[:, 0], t[:, 2])
    return reflectance_rgb(((n - 1) ** 2 + k ** 2) / ((n + 1) ** 2 + k ** 2), D65)


# ochre is y-up, Blender z-up: (x, y, z) -> (x, -z, y).
def to_blender(p):
    return Vector((p[0], -p[2], p[1]))


def ochre_transform(items):  # the list of docs/scene-format.md transforms, applied in order
    m = Matrix.Identity(4)
    for it in items or []:
        if 'translate' in it:
            m = Matrix.Translation(Vector(it['translate'])) @ m
        elif 'scale' in it:
            s = it['scale']
            s = [s, s, s] if isinstance(s, (int, float)) else s
            m = Matrix.Diagonal(Vector((*s, 1.0))) @ m
        elif 'rotate' in it:
            m = Matrix.Rotation(math.radians(it['rotate']['angle']), 4, Vector(it['rotate']['axis'])) @ m
    return m


# ---------------------------------------------------------------- scene
area_light_spd = None  # the emission spectrum of an area light, for reflectances "under the light"
for m in S.get('materials', {}).values():
    for n in m.get('nodes', {}).values():
        if n.get('type') == 'emission' and isinstance(n.get('color'), dict) and 'file' in n['color']:
            area_light_spd = spectrum_file(n['color'])
WHITE = area_light_spd if area_light_spd is not None else D65


def color_rgb(c):
    if isinstance(c, (int, float)):
        return np.array([c, c, c], dtype=float)
    if isinstance(c, list):
        return np.array(c, dtype=float)
    if 'file' in c:
        return reflectance_rgb(spectrum_file(c), WHITE)
    raise SystemExit(f'{scene_path}: colour {c} not supported by the Cycles harness')


scene = bpy.context.scene
for ob in list(bpy.data.objects):  # factory scene: cube, point light, camera
    bpy.data.objects.remove(ob)


def new_material(name):
    mat = bpy.data.materials.new(name)
    mat.use_nodes = True
    nt = mat.node_tree
    nt.nodes.clear()
    return mat, nt, nt.nodes.new('ShaderNodeOutputMaterial')


def diffuse(nt, color):
    d = nt.nodes.new('ShaderNodeBsdfDiffuse')
    d.inputs['Roughness'].default_value = 0.0  # Lambert
    if isinstance(color, dict) and 'link' in color:
        return d, d.inputs['Color']
    d.inputs['Color'].default_value = (*color_rgb(color), 1.0)
    return d, None


def build_material(name, m):
    mat, nt, out = new_material(name)
    if m.get('type') == 'lambert':
        nt.links.new(diffuse(nt, m['color'])[0].outputs[0], out.inputs['Surface'])
    elif m.get('type') == 'conductor':
        g = nt.nodes.new('ShaderNodeBsdfGlossy')
        g.distribution = 'GGX'
        g.inputs['Color'].default_value = (*fresnel_f0_rgb(m['metal']), 1.0)
        g.inputs['Roughness'].default_value = math.sqrt(m.get('roughness', 0.0))  # ochre: GGX alpha
        nt.links.new(g.outputs[0], out.inputs['Surface'])
    elif 'nodes' in m:
        nodes = m['nodes']
        surf = nodes[m['output']]
        if surf['type'] == 'lambert':  # a textured lambert: {"texture" -> lambert.color}
            d, socket = diffuse(nt, surf['color'])
            tex = nodes[surf['color']['link'].split('.')[0]]
            img = nt.nodes.new('ShaderNodeTexImage')
            img.image = bpy.data.images.load(asset(tex['file']))
            nt.links.new(img.outputs['Color'], socket)
            nt.links.new(d.outputs[0], out.inputs['Surface'])
        elif surf['type'] == 'add':  # lambert + emission: a one-sided area light (front face only)
            parts = [nodes[surf[k]['link']] for k in ('a', 'b')]
            lam = next(p for p in parts if p['type'] == 'lambert')
            emi = next(p for p in parts if p['type'] == 'emission')
            d, _ = diffuse(nt, lam['color'])
            rgb = emitted_rgb(spectrum_file(emi['color'])) * emi.get('strength', 1.0)
            em = nt.nodes.new('ShaderNodeEmission')
            em.inputs['Color'].default_value = (*(rgb / max(rgb)), 1.0)
            em.inputs['Strength'].default_value = float(max(rgb))  # mesh emission radiance = Color x Strength
            add, mix = nt.nodes.new('ShaderNodeAddShader'), nt.nodes.new('ShaderNodeMixShader')
            geo = nt.nodes.new('ShaderNodeNewGeometry')
            nt.links.new(em.outputs[0], add.inputs[0])
            nt.links.new(d.outputs[0], add.inputs[1])
            nt.links.new(geo.outputs['Backfacing'], mix.inputs['Fac'])
            nt.links.new(add.outputs[0], mix.inputs[1])
            nt.links.new(d.outputs[0], mix.inputs[2])
            nt.links.new(mix.outputs[0], out.inputs['Surface'])
        else:
            raise SystemExit(f'{scene_path}: material {name} not supported by the Cycles harness')
    else:
        raise SystemExit(f'{scene_path}: material {name} not supported by the Cycles harness')
    return mat


materials = {k: build_material(k, m) for k, m in S['materials'].items()}


def load_obj(path, fan):  # vertices, faces (fan-triangulated as Mitsuba and ochre's Assimp do, or polygons), uvs
    verts, uvs, faces, face_uvs = [], [], [], []
    for line in open(path):
        w = line.split()
        if not w:
            continue
        if w[0] == 'v':
            verts.append([float(x) for x in w[1:4]])
        elif w[0] == 'vt':
            uvs.append([float(x) for x in w[1:3]])
        elif w[0] == 'f':
            ref = [x.split('/') for x in w[1:]]
            vi = [int(r[0]) - 1 for r in ref]
            ti = [int(r[1]) - 1 if len(r) > 1 and r[1] else -1 for r in ref]
            polys = [(0, i - 1, i) for i in range(2, len(vi))] if fan else [tuple(range(len(vi)))]
            for p in polys:
                faces.append([vi[j] for j in p])
                face_uvs.append([ti[j] for j in p])
    return verts, faces, uvs, face_uvs


def load_ply(path):  # the binary PLY of `ochre export-mesh`: vertices (world), normals, faces (triangles)
    with open(path, 'rb') as f:
        header = []
        while not header or header[-1] != 'end_header':
            header.append(f.readline().decode('ascii').strip())
        body = f.read()
    counts = {w[1]: int(w[2]) for w in (h.split() for h in header) if w[0] == 'element'}
    props = [h.split()[-1] for h in header if h.startswith('property float')]
    if 'red' in ' '.join(header):
        raise SystemExit(f'{path}: vertex colours are not read by the Cycles harness')
    nv, nf = counts['vertex'], counts['face']
    vertex = np.frombuffer(body, dtype='<f4', count=nv * len(props)).reshape(nv, len(props))
    faces = np.frombuffer(body, dtype=np.dtype([('n', 'u1'), ('i', '<i4', (3,))]), count=nf,
                          offset=vertex.nbytes)
    if np.any(faces['n'] != 3):
        raise SystemExit(f'{path}: only triangles are read by the Cycles harness')
    column = {name: i for i, name in enumerate(props)}
    normals = vertex[:, [column['nx'], column['ny'], column['nz']]] if 'nx' in column else None
    return vertex[:, :3], faces['i'], normals


def exported_mesh(name):  # a mesh as ochre renders it (procedural displacement), cached beside --out
    ply = os.path.join(os.path.dirname(os.path.abspath(args.out)), f'{os.path.basename(scene_path)}.{name}.ply')
    if not os.path.exists(ply):
        tmp = ply + '.tmp.ply'
        subprocess.run([args.ochre, 'export-mesh', scene_path, '--shape', name, '-o', tmp, '-q'], check=True)
        os.replace(tmp, ply)
    return load_ply(ply)


def add_object(name, verts, faces, uvs, face_uvs, material, xform):
    me = bpy.data.meshes.new(name)
    me.from_pydata([to_blender(xform @ Vector(v)) for v in verts], [], faces)
    if uvs:
        layer = me.uv_layers.new(name='UVMap')
        loop = 0
        for fu in face_uvs:
            for t in fu:
                layer.data[loop].uv = uvs[t] if t >= 0 else (0.0, 0.0)
                loop += 1
    me.materials.append(material)
    ob = bpy.data.objects.new(name, me)
    scene.collection.objects.link(ob)
    return ob


for i, sh in enumerate(S['shapes']):
    name = sh.get('name', f'shape{i}')
    xform = ochre_transform(sh.get('transform'))
    mat = materials[sh['material']]
    if sh['type'] == 'mesh' and 'noise' in sh.get('displacement', {}):
        # ochre's procedural displacement has no Blender counterpart: the mesh as ochre renders it, in world
        # coordinates, with ochre's shading normals as custom normals.
        verts, faces, normals = exported_mesh(name)
        ob = add_object(name, verts.tolist(), faces.tolist(), [], [], mat, Matrix.Identity(4))
        for p in ob.data.polygons:
            p.use_smooth = True
        if normals is not None:
            ob.data.use_auto_smooth = True
            ob.data.normals_split_custom_set_from_vertices([tuple(to_blender(Vector(n))) for n in normals])
    elif sh['type'] == 'mesh':
        subdiv = sh.get('subdivision')
        verts, faces, uvs, fuv = load_obj(asset(sh['file']), fan=subdiv is None)
        ob = add_object(name, verts, faces, uvs, fuv, mat, xform)
        if subdiv:
            mod = ob.modifiers.new('subdivision', 'SUBSURF')
            mod.subdivision_type = 'CATMULL_CLARK'
            mod.levels = mod.render_levels = subdiv['level']
            mod.uv_smooth = 'PRESERVE_BOUNDARIES'
        if 'displacement' in sh:
            dsp = sh['displacement']
            tex = bpy.data.textures.new(name + '_height', 'IMAGE')
            tex.image = bpy.data.images.load(asset(dsp['file']))
            tex.image.colorspace_settings.name = 'Non-Color'
            mod = ob.modifiers.new('displacement', 'DISPLACE')
            mod.texture, mod.texture_coords, mod.direction = tex, 'UV', 'NORMAL'
            mod.strength, mod.mid_level = dsp.get('scale', 1.0), dsp.get('offset', 0.0)
        for p in ob.data.polygons:
            p.use_smooth = subdiv is not None or sh.get('smooth_normals', False)
    elif sh['type'] == 'plane':
        sx, sy = sh.get('size', [2, 2])
        v = [[-sx / 2, -sy / 2, 0], [sx / 2, -sy / 2, 0], [sx / 2, sy / 2, 0], [-sx / 2, sy / 2, 0]]
        add_object(name, v, [[0, 1, 2, 3]], [[0, 0], [1, 0], [1, 1], [0, 1]], [[0, 1, 2, 3]], mat, xform)
    elif sh['type'] == 'sphere':
        c, r = Vector(sh.get('center', [0, 0, 0])), sh.get('radius', 1.0)
        bpy.ops.mesh.primitive_uv_sphere_add(segments=192, ring_count=96, radius=r)
        ob = bpy.context.active_object
        ob.matrix_world = Matrix.Translation(to_blender(xform @ c))
        ob.data.materials.append(mat)
        for p in ob.data.polygons:
            p.use_smooth = True
    else:
        raise SystemExit(f'{scene_path}: shapes[{i}].type {sh["type"]} not supported by the Cycles harness')

# ---------------------------------------------------------------- lights
world = bpy.data.worlds.new('world')
scene.world = world
world.use_nodes = True
wn = world.node_tree
bg = wn.nodes['Background']
bg.inputs['Color'].default_value = (0, 0, 0, 1)
for i, li in enumerate(S.get('lights', [])):
    if li['type'] == 'environment':
        env = wn.nodes.new('ShaderNodeTexEnvironment')
        env.image = bpy.data.images.load(asset(li['file']))
        coord, mapping = wn.nodes.new('ShaderNodeTexCoord'), wn.nodes.new('ShaderNodeMapping')
        # ochre: the map's centre column looks along -z (Blender +y), rotation counter-clockwise about
        # +y seen from above; Blender's centre column looks along +x.
        mapping.inputs['Rotation'].default_value = (0, 0, -math.radians(90 + li.get('rotation', 0.0)))
        wn.links.new(coord.outputs['Generated'], mapping.inputs['Vector'])
        wn.links.new(mapping.outputs['Vector'], env.inputs['Vector'])
        wn.links.new(env.outputs['Color'], bg.inputs['Color'])
        bg.inputs['Strength'].default_value = li.get('scale', 1.0)
    elif li['type'] == 'spot':
        pos = Vector(li['position'])
        axis = (Vector(li['target']) - pos) if 'target' in li else Vector(li['direction'])
        spot = bpy.data.lights.new(f'spot{i}', 'SPOT')
        cone = math.radians(li.get('cone_angle', 30.0))
        spot.spot_size = 2 * cone
        spot.spot_blend = 1.0 - math.radians(li.get('falloff_start', li.get('cone_angle', 30.0))) / cone
        spot.shadow_soft_size = 0.0
        it = li['intensity']
        spot.use_nodes = True
        if isinstance(it, dict) and 'blackbody' in it:
            bb = spot.node_tree.nodes.new('ShaderNodeBlackbody')
            bb.inputs['Temperature'].default_value = it['blackbody']
            spot.node_tree.links.new(bb.outputs[0], spot.node_tree.nodes['Emission'].inputs['Color'])
            strength = it.get('scale', 1.0)
        else:
            strength = float(np.mean(color_rgb(it)))
        spot.energy = 4 * math.pi * strength  # Blender spot power in W: intensity x 4 pi
        ob = bpy.data.objects.new(f'spot{i}', spot)
        ob.matrix_world = Matrix.Translation(to_blender(pos)) @ \
            to_blender(axis).to_track_quat('-Z', 'Y').to_matrix().to_4x4()
        scene.collection.objects.link(ob)
    elif li['type'] == 'flame':
        # A sphere light with a blackbody colour (docs/lights.md); its flicker is off in a still. Cycles' point
        # light with the flame's radius; the power is matched by hand (FLAME_WATTS_PER_CANDELA), as the rock's
        # spot, so that both renderers' images are alike in brightness.
        preset = FLAME_PRESETS[li.get('preset', 'torch')]
        lamp = bpy.data.lights.new(f'flame{i}', 'POINT')
        lamp.shadow_soft_size = li.get('radius', preset['radius'])
        lamp.use_nodes = True
        bb = lamp.node_tree.nodes.new('ShaderNodeBlackbody')
        bb.inputs['Temperature'].default_value = li.get('cct', preset['cct'])
        lamp.node_tree.links.new(bb.outputs[0], lamp.node_tree.nodes['Emission'].inputs['Color'])
        lamp.energy = FLAME_WATTS_PER_CANDELA * li.get('intensity', preset['intensity']) * li.get('scale', 1.0)
        ob = bpy.data.objects.new(f'flame{i}', lamp)
        ob.matrix_world = Matrix.Translation(to_blender(Vector(li['position'])))
        scene.collection.objects.link(ob)
    else:
        raise SystemExit(f'{scene_path}: lights[{i}].type {li["type"]} not supported by the Cycles harness')

# ---------------------------------------------------------------- camera
C = S['camera']
w, h = S['film']['resolution']
if args.res:
    w, h = (int(x) for x in args.res.split('x'))
eye, target, up = to_blender(C['eye']), to_blender(C['target']), to_blender(C.get('up', [0, 1, 0]))
fwd = (target - eye).normalized()
right = fwd.cross(up).normalized()
cam = bpy.data.cameras.new('cam')
cam.lens_unit = 'FOV'
cam.sensor_fit = 'VERTICAL' if w >= h else 'HORIZONTAL'  # ochre's fov spans the shorter axis
cam.angle = math.radians(C.get('fov', 40.0))
corners = [o.matrix_world @ Vector(c) for o in scene.objects if o.type == 'MESH' for c in o.bound_box]
extent = max((max(c[i] for c in corners) - min(c[i] for c in corners)) for i in range(3))
far = max((c - eye).length for c in corners)
cam.clip_start, cam.clip_end = 1e-6 * extent, 10.0 * far + extent  # nothing in the scene is clipped
cam_ob = bpy.data.objects.new('cam', cam)
cam_ob.matrix_world = Matrix((tuple(right) + (0,), tuple(right.cross(fwd)) + (0,), tuple(-fwd) + (0,),
                              tuple(eye) + (1,))).transposed()  # camera looks down its -Z, up +Y
scene.collection.objects.link(cam_ob)
scene.camera = cam_ob

# ---------------------------------------------------------------- Cycles settings
max_depth = S.get('integrator', {}).get('max_depth', 8)
bounces = max(max_depth - 1, 0)  # ochre max_depth 1 (direct lighting) == Cycles 0 bounces
r, c = scene.render, scene.cycles
r.engine = 'CYCLES'
c.device, c.feature_set = 'CPU', 'SUPPORTED'
c.samples, c.seed, c.use_animated_seed = args.spp, args.seed, False
c.use_adaptive_sampling = args.adaptive_threshold > 0
if c.use_adaptive_sampling:  # --spp is then the most a pixel takes; the minimum is Cycles' automatic one
    c.adaptive_threshold, c.adaptive_min_samples = args.adaptive_threshold, 0
c.use_denoising = False
scene.view_layers[0].cycles.use_denoising = False
c.max_bounces = c.diffuse_bounces = c.glossy_bounces = c.transmission_bounces = bounces
c.transparent_max_bounces = 0
c.sample_clamp_direct = c.sample_clamp_indirect = 0.0  # no clamping (the default indirect 10 is biased)
c.use_guiding = False
c.caustics_reflective = c.caustics_refractive = True
c.blur_glossy = 0.0  # filter glossy is biased
c.pixel_filter_type, c.filter_width = 'BOX', 1.0  # ochre's film: box-filtered pixels
r.resolution_x, r.resolution_y, r.resolution_percentage = w, h, 100
r.threads_mode, r.threads = 'FIXED', args.threads
r.use_compositing = r.use_sequencer = False
r.film_transparent = False
scene.view_settings.view_transform, scene.view_settings.look = 'Standard', 'None'
scene.view_settings.exposure, scene.view_settings.gamma = 0.0, 1.0
im = r.image_settings
im.file_format, im.color_depth, im.color_mode, im.exr_codec = 'OPEN_EXR', '32', 'RGB', 'ZIP'
out = os.path.abspath(args.out)
r.filepath = out

params = dict(blender=bpy.app.version_string, scene=scene_path, res=[w, h], spp=args.spp, seed=args.seed,
              adaptive_threshold=args.adaptive_threshold,
              threads=args.threads, ochre_max_depth=max_depth, cycles_max_bounces=bounces,
              sampling_pattern=c.sampling_pattern, min_light_bounces=c.min_light_bounces,
              triangles=sum(len(o.evaluated_get(bpy.context.evaluated_depsgraph_get()).data.loop_triangles)
                            for o in scene.objects if o.type == 'MESH'))
print('SCENE', json.dumps(params))
t_wall, t_cpu = time.perf_counter(), time.process_time()
bpy.ops.render.render(write_still=True)
params.update(render_op_wall_s=time.perf_counter() - t_wall, render_op_cpu_s=time.process_time() - t_cpu)
with open(os.path.splitext(out)[0] + '.json', 'w') as f:
    json.dump(params, f, indent=1)
