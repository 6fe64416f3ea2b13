"""Export a .blend file's scene to an ochre scene from the command line:

    blender -b FILE.blend --python tools/blender/export_scene.py -- OUT.json [--samples N] [--max-depth N]

Writes OUT.json and the folder OUT_assets/ beside it (meshes as binary PLY, images) and prints one line per
warning (what was not exported, or only approximately). Exit 2 on bad arguments, 1 when the export
fails, 0 otherwise.
"""
import argparse
import os
import sys
import traceback

import bpy

sys.path.insert(0, os.path.dirname(os.path.realpath(__file__)))

from ochre_blender import export  # noqa: E402 (after the path above)


def main():
    argv = sys.argv[sys.argv.index('--') + 1:] if '--' in sys.argv else []
    parser = argparse.ArgumentParser(prog='blender -b FILE.blend --python export_scene.py --',
                                     description='Export the scene of a .blend file to an ochre scene (JSON).')
    parser.add_argument('out', help='the ochre scene to write, ending in .json')
    parser.add_argument('--samples', type=int, help='samples per pixel (default: the scene\'s ochre settings, 64)')
    parser.add_argument('--max-depth', type=int, help='scattering events on a path (default 8)')
    try:
        args = parser.parse_args(argv)
    except SystemExit as e:
        sys.stdout.flush()
        os._exit(2 if e.code else 0)
    if not args.out.endswith('.json'):
        print(f'export_scene.py: the output must end in .json (got {args.out!r})', file=sys.stderr)
        os._exit(2)
    for n, name in ((args.samples, '--samples'), (args.max_depth, '--max-depth')):
        if n is not None and n < (1 if name == '--samples' else 0):
            print(f'export_scene.py: {name} out of range (got {n})', file=sys.stderr)
            os._exit(2)
    warnings = export.export_scene(bpy.context.evaluated_depsgraph_get(), args.out, samples=args.samples,
                                   max_depth=args.max_depth)
    for w in warnings:
        print(f'export_scene.py: warning: {w}')
    print(f'export_scene.py: wrote {os.path.abspath(args.out)} ({len(warnings)} warnings)')
    sys.stdout.flush()


try:
    main()
except Exception:  # noqa: BLE001 (Blender would exit 0 after a failed script: say so and exit 1)
    traceback.print_exc()
    sys.stdout.flush()
    os._exit(1)
os._exit(0)
