"""The `ochre render` command line and its progress output. Pure functions (no bpy): tested with python3."""
import re

PROGRESS = re.compile(r'^render: (\d+(?:\.\d+)?)%')


def render_command(executable, scene_path, exr_path, preset='final', threads=0, spectral_bins=0):
    """The arguments of `ochre render` for an exported scene (docs/cli.md)."""
    cmd = [executable, 'render', scene_path, '-o', exr_path, '--preset', preset]
    if threads > 0:
        cmd += ['--threads', str(int(threads))]
    if spectral_bins > 0:
        cmd += ['--spectral-bins', str(int(spectral_bins))]
    return cmd


def render_progress(line):
    """The fraction done (0 to 1) of a progress line of `ochre render` (OCHRE_PROGRESS=plain), else None."""
    m = PROGRESS.match(line.strip())
    return min(float(m.group(1)), 100.0) / 100.0 if m else None
