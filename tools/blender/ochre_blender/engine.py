"""The ochre render engine: F12 exports the scene to a temporary folder, runs `ochre render` on it, shows its
progress and loads the EXR it writes into the render result."""
import os
import queue
import shutil
import subprocess
import tempfile
import threading

import bpy
import numpy as np

from . import cli, exr, export, units


def ochre_executable(context=None):
    """The ochre binary: the add-on preference, else $OCHRE_EXECUTABLE, else `ochre` on PATH."""
    prefs = (context or bpy.context).preferences.addons.get(__package__)
    path = prefs.preferences.ochre_path if prefs is not None else ''
    path = bpy.path.abspath(path) if path else ''
    return path or os.environ.get('OCHRE_EXECUTABLE') or 'ochre'


def _pump(stream, lines):
    for line in iter(stream.readline, ''):
        lines.put(line)
    lines.put(None)


class OchreRenderEngine(bpy.types.RenderEngine):
    bl_idname = 'OCHRE'
    bl_label = 'ochre'
    bl_use_preview = False
    bl_use_postprocess = True

    def render(self, depsgraph):
        scene = depsgraph.scene
        r = scene.render
        width, height = units.resolution(r.resolution_x, r.resolution_y, r.resolution_percentage)
        settings = getattr(scene, 'ochre', None)
        with tempfile.TemporaryDirectory(prefix='ochre_blender_') as tmp:
            scene_path = os.path.join(tmp, 'scene.json')
            exr_path = os.path.join(tmp, 'render.exr')
            self.update_stats('', 'ochre: exporting the scene')
            try:
                warnings = export.export_scene(depsgraph, scene_path)
            except (ValueError, OSError) as e:
                self.report({'ERROR'}, f'ochre: export failed: {e}')
                return
            for message in warnings:
                self.report({'WARNING'}, message)
            cmd = cli.render_command(ochre_executable(), scene_path, exr_path)
            if settings is not None:
                cmd = cli.render_command(ochre_executable(), scene_path, exr_path, settings.preset, settings.threads,
                                         settings.spectral_bins)
            env = dict(os.environ, OCHRE_PROGRESS='plain')
            try:
                proc = subprocess.Popen(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                                        env=env)
            except OSError as e:
                self.report({'ERROR'}, f'ochre: cannot run {cmd[0]}: {e} (set its path in the add-on preferences)')
                return
            lines, tail = queue.Queue(), []
            threading.Thread(target=_pump, args=(proc.stdout, lines), daemon=True).start()
            while True:
                if self.test_break():
                    proc.terminate()
                    proc.wait()
                    return
                try:
                    line = lines.get(timeout=0.1)
                except queue.Empty:
                    continue
                if line is None:
                    break
                line = line.rstrip()
                tail = (tail + [line])[-8:]
                done = cli.render_progress(line)
                if done is not None:
                    self.update_progress(done)
                self.update_stats('', line[:200])
            if proc.wait() != 0 or not os.path.isfile(exr_path):
                self.report({'ERROR'}, f'ochre render failed (exit {proc.returncode}): ' + ' | '.join(tail))
                return
            keep = bpy.path.abspath(settings.exr_copy) if settings is not None and settings.exr_copy else ''
            if keep:
                os.makedirs(os.path.dirname(os.path.abspath(keep)), exist_ok=True)
                shutil.copyfile(exr_path, keep)
            try:
                rgb = exr.read_rgb(exr_path)
            except (OSError, ValueError) as e:
                self.report({'ERROR'}, f'ochre: cannot read {exr_path}: {e}')
                return
            rgba = np.ones((height, width, 4), dtype=np.float32)
            rgba[:, :, :3] = rgb[::-1]  # Blender's rows go bottom up
            result = self.begin_result(0, 0, width, height)
            result.layers[0].passes['Combined'].rect = rgba.reshape(-1, 4)
            self.end_result(result)


def _compatible_panels():
    for name in dir(bpy.types):
        panel = getattr(bpy.types, name)
        engines = getattr(panel, 'COMPAT_ENGINES', None)
        if isinstance(engines, set) and 'BLENDER_EEVEE' in engines and \
                getattr(panel, 'bl_context', '') in ('material', 'data', 'world', 'output', 'object'):
            yield panel


def register():
    bpy.utils.register_class(OchreRenderEngine)
    for panel in _compatible_panels():
        panel.COMPAT_ENGINES.add('OCHRE')


def unregister():
    for panel in _compatible_panels():
        panel.COMPAT_ENGINES.discard('OCHRE')
    bpy.utils.unregister_class(OchreRenderEngine)
