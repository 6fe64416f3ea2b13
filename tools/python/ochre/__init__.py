"""ochre: a spectral path tracer with Mueller-matrix polarization, from Python (docs/python.md).

Scenes:    load_scene(path_or_dict, spp=..., resolution=..., ...) -> Scene; Scene.render(...) -> RenderResult
           mitsuba_to_json(path) -> the ochre scene a Mitsuba 3 XML scene becomes
Materials: material(dict_or_path) -> Material with eval, mueller, sample, albedo over numpy arrays
Colour:    Spectrum (named, blackbody, from_csv, from_rgb, tables) with to_xyz, to_lab, to_rgb;
           xyz_to_lab, ciede2000, image_metrics, to_display, read_exr
Lighting:  relight(render_exr, groups={"torch": 0.5, "lamp": "off"}, exr=..., png=...), as ochre relight
Errors:    InputError (a ValueError) names the argument, or the file and the field, as the command line does;
           a value of the wrong type raises TypeError naming the argument (docs/python.md, "Errors")
"""

import numpy as _np

from ._ochre import (  # noqa: F401  (the public API)
    InputError,
    RenderResult,
    Scene,
    Spectrum,
    __version__,
    image_metrics,
    load_scene,
    mitsuba_to_json,
    read_exr,
    relight,
    to_display,
    xyz_to_lab,
)
from . import _ochre


def _numbers(value, what):
    """value as a float64 array; TypeError naming `what` unless it holds numbers (ints or floats: never bools,
    str or other objects), as docs/python.md, "Errors" says."""
    try:
        a = _np.asarray(value)
    except (TypeError, ValueError, OverflowError, RecursionError):
        a = None
    if a is None or a.dtype.kind not in "iuf":
        raise TypeError(f"{what}: expected numbers (an array or a sequence of numbers), got {_ochre._describe(value)}")
    return a.astype(_np.float64, copy=False)


def _directions(v, what):
    a = _numbers(v, what)
    if a.shape[-1:] != (3,):
        raise InputError(f"{what}: expected directions of 3 components (shape (..., 3)), got shape {a.shape}")
    return a


def _broadcast(shapes, names, bytes_per_row):
    """The broadcast shape of the arguments `names`; InputError when they do not broadcast or when the rows
    would not fit in memory (docs/cli.md, "Memory")."""
    try:
        shape = _np.broadcast_shapes(*shapes)
    except ValueError:
        raise InputError(f"{names}: the shapes {', '.join(str(s) for s in shapes)} do not broadcast together") from None
    rows = 1
    for n in shape:
        rows *= n
    _ochre._check_memory(float(rows) * bytes_per_row, f"{names}: {rows} rows of shape {shape}")
    return shape


class Material:
    """A material of the scene format (docs/nodes.md) evaluated as a BSDF at a shading point with normal z,
    in the local frame (z = normal): wo points toward the viewer, wi toward the light, both away from the
    surface. The arrays broadcast against each other; results have their broadcast shape."""

    def __init__(self, source, name="", base_dir=None):
        self._m = _ochre._material(source, name, base_dir)

    @property
    def name(self):
        return self._m.name

    def _rows(self, wi, wo, wavelengths, bytes_per_row):
        wi, wo = _directions(wi, "wi"), _directions(wo, "wo")
        lam = _numbers(wavelengths, "wavelengths")
        shape = _broadcast((wi.shape[:-1], wo.shape[:-1], lam.shape), "wi, wo, wavelengths", bytes_per_row)
        rows = lambda a, tail: _np.ascontiguousarray(_np.broadcast_to(a, shape + tail).reshape((-1,) + tail))
        return shape, rows(wi, (3,)), rows(wo, (3,)), rows(lam, ())

    def eval(self, wi, wo, wavelengths=550.0):
        """The BRDF/BTDF f(wi, wo) of the non-delta lobes (Mueller M00, 1/sr, without the cosine)."""
        shape, wi, wo, lam = self._rows(wi, wo, wavelengths, 64)
        return self._m.eval(wi, wo, lam).reshape(shape)

    def mueller(self, wi, wo, wavelengths=550.0):
        """dict of 'matrix' (..., 4, 4), the Mueller matrix of the non-delta lobes, and its reference axes
        'in_x' (light arriving along -wi) and 'out_x' (light leaving along wo), (..., 3) each
        (docs/polarization.md)."""
        shape, wi, wo, lam = self._rows(wi, wo, wavelengths, 232)
        r = self._m.mueller(wi, wo, lam)
        return {"matrix": r["matrix"].reshape(shape + (4, 4)), "in_x": r["in_x"].reshape(shape + (3,)),
                "out_x": r["out_x"].reshape(shape + (3,))}

    def sample(self, wo, wavelengths=550.0, u=None, seed=1):
        """One sample of the material's own sampler per wo: dict of 'wi' (..., 3), 'weight' (f |cos| / pdf),
        'pdf', 'delta' and 'valid'. u (..., 3) gives the random numbers (u_choice, u1, u2), else they come
        from `seed`."""
        wo = _directions(wo, "wo")
        lam = _numbers(wavelengths, "wavelengths")
        u = None if u is None else _directions(u, "u")
        shape = _broadcast((wo.shape[:-1], lam.shape, () if u is None else u.shape[:-1]), "wo, wavelengths, u", 160)
        rows = lambda a, tail: _np.ascontiguousarray(_np.broadcast_to(a, shape + tail).reshape((-1,) + tail))
        r = self._m.sample(rows(wo, (3,)), rows(lam, ()), None if u is None else rows(u, (3,)), seed)
        return {k: v.reshape(shape + ((3,) if k == "wi" else ())) for k, v in r.items()}

    def albedo(self, angles, wavelength=550.0, samples=200000, seed=1):
        """Directional albedo at each polar angle of wo (degrees, azimuth 0), two ways as ochre-brdf albedo:
        dict of 'mc_albedo', 'mc_se' (the material's sampler) and 'quadrature_albedo', 'quadrature_error'
        (eval; blind to delta lobes)."""
        a = _np.atleast_1d(_numbers(angles, "angles"))
        return self._m.albedo(a.reshape(-1), wavelength, samples, seed)

    def polarizes(self, wavelength=550.0):
        """Whether a lobe of the material polarizes (changes the state of polarization of light)."""
        return self._m.polarizes(wavelength)


def material(source, name="", base_dir=None):
    """A Material from a dict (one material as under "materials" in a scene, or a one-node shorthand such
    as {"type": "lambert", "color": 0.8}; files named in it resolve against base_dir, default the current
    directory) or from a material JSON file (ochre-brdf's MAT.json; `name` picks one of its materials)."""
    return Material(source, name, base_dir)


def ciede2000(lab1, lab2, kl=1.0, kc=1.0, kh=1.0):
    """CIEDE2000 colour difference (Sharma, Wu & Dalal 2005) of CIELAB colours (..., 3); broadcasts."""
    a, b = _numbers(lab1, "lab1"), _numbers(lab2, "lab2")
    for x, what in ((a, "lab1"), (b, "lab2")):
        if x.shape[-1:] != (3,):
            raise InputError(f"{what}: expected CIELAB colours of 3 components (shape (..., 3)), got shape {x.shape}")
    shape = _broadcast((a.shape[:-1], b.shape[:-1]), "lab1, lab2", 56)
    rows = lambda x: _np.ascontiguousarray(_np.broadcast_to(x, shape + (3,)).reshape(-1, 3))
    de = _ochre._ciede2000(rows(a), rows(b), kl, kc, kh).reshape(shape)
    return float(de) if de.ndim == 0 else de
