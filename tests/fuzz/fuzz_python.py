#!/usr/bin/env python3
"""Fuzz driver of ochre's Python module (docs/validation.md, "Fuzzing"; docs/python.md, "Errors").

Each iteration calls one entry point of the module (load_scene, Scene.render, RenderResult.write_exr,
mitsuba_to_json, the Material methods, Spectrum, the colour functions, read_exr, relight) with arguments drawn from
a seeded random generator: good values most of the time, and otherwise values of random types, huge,
negative, NaN or infinite numbers, nested and self-containing containers, scenes and materials with one
value changed, and paths to FIFOs, devices, links, directories and the call's own input files in a scratch
directory. Every call must either succeed or raise ochre.InputError, TypeError or ValueError whose message
is ochre's own (not pybind11's "incompatible function arguments", not a bare numpy conversion error); a
write_exr or relight that is refused must leave every file as it was, and no call may leave a temporary file.

The calls run in child processes, so that a crash (SIGSEGV, abort) or a hang is caught and reported with
the call that caused it and the command that repeats it, instead of ending the driver:

  tests/fuzz/fuzz_python.py --seconds 15            the test suite's run (ctest fuzz_python.short)
  tests/fuzz/fuzz_python.py --seconds 3600          a long run
  tests/fuzz/fuzz_python.py --iterations 20000 --seed 7
  tests/fuzz/fuzz_python.py --repeat SEED:ITERATION  one iteration again, printing its call

The module is imported from PYTHONPATH (build/python by default, beside this script's source tree), and
the image library module from build/lib/ochre. Exit status: 0 when every call behaved, 1 with a report of
the first finding otherwise, 2 for bad usage.
"""

import argparse
import copy
import decimal
import fractions
import hashlib
import json
import math
import os
import pathlib
import random
import shutil
import signal
import stat
import subprocess
import sys
import tempfile
import time
import traceback

SOURCE_DIR = pathlib.Path(__file__).resolve().parents[2]
BATCH_SECONDS = 20  # a child process runs this long (or to the end of the run), then the next one starts
HANG_SECONDS = 120  # a child still running this long after its batch is hung
# Messages of conversions that did not go through the module's own argument checks.
FOREIGN_MESSAGES = ("incompatible function arguments", "Unable to cast", "unable to convert",
                    "could not convert", "setting an array element", "cannot be interpreted as",
                    "must be real number", "argument must be", "object is not", "unhashable")


# ----------------------------------------------------------------------------------------------------------
# The scratch directory: inputs, and the things no output may replace.

def same_json(a, b):
    """a == b for JSON-like values that may hold numpy arrays (whose == compares element by element)."""
    return json.dumps(a, sort_keys=True, default=repr) == json.dumps(b, sort_keys=True, default=repr)


def small_scene(**changes):
    scene = {
        "camera": {"eye": [0, 0, 4], "fov": 30},
        "film": {"resolution": [8, 6]},
        "integrator": {"spp": 2, "max_depth": 3},
        "materials": {
            "grey": {"type": "lambert", "color": 0.5},
            "gold": {"type": "conductor", "metal": "Au", "roughness": 0.3},
            "red": {"type": "lambert", "color": {"file": "red.csv"}},
        },
        "lights": [{"type": "environment", "radiance": 1.0}],
        "shapes": [
            {"type": "sphere", "radius": 1, "material": "grey"},
            {"type": "mesh", "file": "quad.obj", "material": "red"},
        ],
    }
    scene.update(changes)
    return scene


# The lights of the render that relight recombines: two light groups (docs/lights.md, "Light groups").
GROUP_LIGHTS = [{"type": "point", "position": [0, 2, 2], "intensity": 3, "group": "lamp"},
                {"type": "environment", "radiance": 0.5, "group": "sky"}]


def make_groups_render(ochre, directory):
    """groups.exr, a render with light groups, made by the first child (the parent does not import the
    module); the same file serves every later call."""
    path = pathlib.Path(directory) / "groups.exr"
    if not path.exists():
        ochre.load_scene(small_scene(lights=GROUP_LIGHTS), base_dir=str(directory)).render(spp=1).write_exr(path)


def make_scratch(directory):
    d = pathlib.Path(directory)
    shutil.copy(SOURCE_DIR / "tests/data/quad.obj", d / "quad.obj")
    shutil.copy(SOURCE_DIR / "tests/data/colours.ply", d / "colours.ply")
    (d / "mitsuba").mkdir()
    for name in ("elements.xml", "checker.ppm", "white.spd"):
        shutil.copy(SOURCE_DIR / "tests/data/mitsuba" / name, d / "mitsuba" / name)
    (d / "red.csv").write_text("nm,value\n380,0.1\n550,0.2\n600,0.7\n780,0.8\n")
    (d / "scene.json").write_text(json.dumps(small_scene()))
    (d / "material.json").write_text(json.dumps({"materials": {
        "paint": {"type": "lambert", "color": {"file": "red.csv"}},
        "glass": {"type": "dielectric", "ior": 1.5}}}))
    os.mkfifo(d / "fifo")
    (d / "dir").mkdir()
    (d / "target.txt").write_text("a file a link points to\n")
    os.symlink("target.txt", d / "link")
    os.symlink("dir", d / "dirlink")
    os.symlink("no-such-file", d / "dangling")


# The scratch directory's regular files: inputs of the calls that no output may replace.
PROTECTED_FILES = ("quad.obj", "colours.ply", "red.csv", "scene.json", "material.json", "target.txt",
                   "mitsuba/elements.xml", "groups.exr")


def protected_state(directory):
    """What must never change: the inputs' content and identity, and the kind of every special file."""
    d = pathlib.Path(directory)
    state = {}
    for name in PROTECTED_FILES:
        info = os.stat(d / name)
        state[name] = (info.st_ino, hashlib.sha256((d / name).read_bytes()).hexdigest())
    for name in ("fifo", "dir", "link", "dirlink", "dangling"):
        info = os.lstat(d / name)
        state[name] = (stat.S_IFMT(info.st_mode), os.readlink(d / name) if stat.S_ISLNK(info.st_mode) else "")
    state["dir/"] = sorted(os.listdir(d / "dir"))
    return state


# ----------------------------------------------------------------------------------------------------------
# Values.

class Index:
    """An object with __index__ (as numpy integers have), returning `value`."""
    def __init__(self, value):
        self.value = value

    def __index__(self):
        return self.value

    def __repr__(self):
        return f"Index({self.value!r})"


class BadIndex:
    def __index__(self):
        raise ValueError("no index")

    def __repr__(self):
        return "BadIndex()"


class FloatLike:
    def __init__(self, value):
        self.value = value

    def __float__(self):
        return self.value

    def __repr__(self):
        return f"FloatLike({self.value!r})"


class PathLike:
    def __init__(self, value):
        self.value = value

    def __fspath__(self):
        return self.value

    def __repr__(self):
        return f"PathLike({self.value!r})"


def nested_list(depth, leaf=0.5):
    v = leaf
    for _ in range(depth):
        v = [v]
    return v


def nested_dict(depth, leaf=0.5):
    v = leaf
    for _ in range(depth):
        v = {"a": v}
    return v


def cyclic_list():
    a = [1]
    a.append(a)
    return a


def cyclic_dict():
    d = {"type": "lambert"}
    d["color"] = d
    return d


def self_array(np):
    a = np.empty(2, dtype=object)
    a[0] = 1.0
    a[1] = a
    return a


class Values:
    """The random values of one iteration."""

    def __init__(self, rng, np, scratch):
        self.rng, self.np, self.scratch = rng, np, pathlib.Path(scratch)

    def choice(self, options):
        return options[self.rng.randrange(len(options))]

    def ints(self, cost="cheap"):
        """cost "cheap": any integer (seeds); "bounded": no large value that could be valid where the
        argument's range is wide (scene values); "work": no valid count of work beyond 10^6 (a valid
        albedo(samples=2**32) is a long computation, interruptible by Ctrl-C, not a hang)."""
        values = [0, 1, -1, 2, 3, 7, -7, 255, 2**31, 2**32 - 1, 2**32, 2**63, 2**64, -2**63 - 1, 10**30,
                  10**400, -(10**400)]
        if cost == "cheap":
            values += [2**31 - 1, 2**63 - 1, 2**64 - 1]
        elif cost == "work":
            values = [v for v in values if not 10**6 <= v < 2**64]
        return self.choice(values)

    def floats(self):
        return self.choice([0.0, -0.0, 0.5, 1.5, -1.5, 550.0, 1e-320, 1e-45, 1e300, -1e300, 3.4e38, 3.5e38,
                            math.nan, math.inf, -math.inf, 2.0**64])

    def strings(self):
        return self.choice(["", "x", "rec709", "acescg", "D65", "A", "stokes", "auto", "sobol", "clamp",
                            "zero", "reflectance", "\0", "a\0b", "\ud800", "é", "1", "550", "nan", "x" * 5000,
                            "../" * 40 + "etc/passwd", "scene.json", "builtin", "none", "sRGB"])

    def paths(self):
        s = self.scratch
        return self.choice([str(s / "scene.json"), str(s / "fifo"), str(s / "dir"), str(s / "link"),
                            str(s / "dirlink"), str(s / "dangling"), str(s / "no-such.json"),
                            str(s / "no/such/dir/x"), "/dev/null", "/dev/zero", "/dev/full", "", "\0",
                            str(s / "quad.obj"), str(s / "red.csv"), str(s / "material.json"),
                            str(s / "mitsuba/elements.xml"), str(s / "out.exr"), "dir/../scene.json",
                            pathlib.Path(s / "scene.json"), PathLike(str(s / "fifo")), PathLike(3),
                            os.fsencode(str(s / "scene.json")), b"\xff\xfe", "x" * 5000, "/", "."])

    def containers(self):
        np = self.np
        return self.choice([[], [1], [1, 2], [1, 2, 3], (1, 2), (0.5, 0.5, 0.5), [[1, 2, 3]], [[0, 0, 1]] * 3,
                            {}, {"a": 1}, {1: 2}, {"type": "lambert"}, cyclic_list(), cyclic_dict(),
                            nested_list(257), nested_list(30000), nested_dict(300), nested_dict(30000), {1, 2},
                            frozenset(), range(3), bytearray(b"ab"), memoryview(b"ab"), [1, None], [[1, 2], [3]],
                            [math.nan, 1.0, 2.0], ["a", "b", "c"], self_array(np), np.zeros((2, 3)),
                            np.array([["a"]]), np.array([None], dtype=object), np.zeros((0, 3)), np.zeros(0),
                            np.ones((1, 1, 3), dtype=np.float32), np.full((2, 2, 3), np.nan),
                            np.array([True, False, True])])

    def others(self, cost="cheap"):
        np = self.np
        # A valid count of work beyond 10^6 is a long computation, not a hang (ints, cost "work").
        big = np.uint64(2**64 - 1) if cost != "work" else np.uint64(7)
        return self.choice([None, True, False, np.bool_(True), np.int64(3), big,
                            np.float32(math.nan), np.float64(2.5), np.array(3), np.array(2.5), object(),
                            lambda *a: None, complex(1, 2), decimal.Decimal("nan"), decimal.Decimal("2.5"),
                            fractions.Fraction(1, 3), Index(3), Index(2**70), BadIndex(), FloatLike(2.0),
                            FloatLike(math.nan), print, ValueError])

    def anything(self, cost="cheap"):
        kind = self.rng.randrange(6)
        return [lambda: self.ints(cost), self.floats, self.strings, self.paths, self.containers,
                lambda: self.others(cost)][kind]()

    def maybe(self, good, cost="cheap", bad=0.3):
        """good() most of the time; a random value of any type otherwise."""
        return self.anything(cost) if self.rng.random() < bad else good()

    # Values that should mostly be valid.
    def small_int(self, lo, hi):
        return self.rng.randint(lo, hi)

    def direction_array(self):
        np, rng = self.np, self.rng
        shape = self.choice([(3,), (2, 3), (4, 1, 3), (1, 3), (0, 3)])
        a = np.array([rng.uniform(-1, 1) for _ in range(int(np.prod(shape)))]).reshape(shape)
        if a.size and rng.random() < 0.1:
            a.flat[0] = self.choice([math.nan, math.inf, 0.0, 1e300])
        if rng.random() < 0.05:
            a = np.zeros(shape)
        if rng.random() < 0.03:  # broadcasting to far more rows than memory holds
            a = np.ones((10**6, 1, 3)) if rng.random() < 0.5 else np.broadcast_to(np.ones(3), (10**7, 1, 3))
        return a

    def wavelengths(self):
        rng = self.rng
        return self.choice([550.0, 360, 830, [450.0, 650.0], self.np.array([400.0, 500.0, 600.0]),
                            rng.uniform(300, 900), 359.9, 830.1])

    def mutated(self, value, extra_keys=("colour", "radiance", "spp")):
        """A deep copy of a JSON value with one random change: a value replaced, a key removed or added."""
        value = copy.deepcopy(value)
        parents = []

        def walk(v):
            if isinstance(v, dict):
                for k in list(v):
                    parents.append((v, k))
                    walk(v[k])
            elif isinstance(v, list):
                for i in range(len(v)):
                    parents.append((v, i))
                    walk(v[i])

        walk(value)
        if not parents:
            return value
        parent, key = self.choice(parents)
        action = self.rng.random()
        if action < 0.15 and isinstance(parent, dict):
            del parent[key]
        elif action < 0.25 and isinstance(parent, dict):
            parent[self.choice(list(extra_keys))] = self.anything("bounded")
        else:
            parent[key] = self.anything("bounded")
        return value


# ----------------------------------------------------------------------------------------------------------
# The calls. Each returns (description, thunk); the thunk returns a value or raises.

class Calls:
    def __init__(self, ochre, np, scratch, values):
        self.ochre, self.np, self.scratch, self.v = ochre, np, pathlib.Path(scratch), values
        self.rng = values.rng

    def scene_source(self):
        v, s = self.v, self.scratch
        r = self.rng.random()
        if r < 0.35:
            return small_scene(), True
        if r < 0.6:
            return v.mutated(small_scene()), True
        if r < 0.75:
            return str(s / "scene.json"), False
        if r < 0.8:
            return str(s / "mitsuba/elements.xml"), False
        return v.anything(cost="bounded"), False

    def load_kwargs(self, dict_source):
        v = self.v
        kwargs = {}
        if self.rng.random() < 0.5:
            kwargs["spp"] = v.maybe(lambda: v.small_int(1, 3), cost="bounded")
        if self.rng.random() < 0.5:
            kwargs["resolution"] = v.maybe(lambda: (v.small_int(1, 8), v.small_int(1, 8)), cost="bounded")
        for name, good in (("seed", lambda: v.small_int(0, 2**64 - 1)), ("threads", lambda: v.small_int(0, 2)),
                           ("polarization", lambda: v.choice(["auto", "off", "intensity", "stokes"])),
                           ("sampler", lambda: v.choice(["independent", "sobol"])),
                           ("parameters", lambda: v.choice([{"spp": 2}, {"spp": "2"}, {"res": 4.5}, {}]))):
            if self.rng.random() < 0.3:
                kwargs[name] = v.maybe(good)
        if dict_source and self.rng.random() < 0.3:
            kwargs["base_dir"] = v.maybe(lambda: str(self.scratch))
        return kwargs

    def loaded_scene(self):
        """(scene, source, inputs): a scene to render, loaded from random arguments when they load and render
        cheaply, else the small scene; `inputs` are files it certainly read (write_exr must refuse them)."""
        source, is_dict = self.scene_source()
        kwargs = self.load_kwargs(is_dict)
        s = self.scratch
        known = {str(s / "scene.json"): ["scene.json", "quad.obj", "red.csv"],
                 str(s / "mitsuba/elements.xml"): ["mitsuba/elements.xml", "quad.obj", "colours.ply"]}
        try:
            scene = self.ochre.load_scene(source, **kwargs)
            settings = scene.settings
            if settings["width"] * settings["height"] <= 4096 and settings["spp"] * settings["branches"] <= 16:
                if isinstance(source, dict):
                    inputs = ["quad.obj", "red.csv"] if same_json(source, small_scene()) and "base_dir" not in kwargs else []
                else:
                    inputs = known.get(source, []) if isinstance(source, str) else []
                return scene, source, inputs
        except (ValueError, TypeError):
            pass
        source = str(s / "scene.json")
        return self.ochre.load_scene(source, spp=1), source, known[source]

    def render_kwargs(self, scene):
        v = self.v
        kwargs = {}
        choices = [("spp", lambda: v.small_int(1, 3), False), ("seed", lambda: v.small_int(0, 2**64 - 1), True),
                   ("threads", lambda: v.small_int(0, 2), False),
                   ("sample_begin", lambda: v.choice([0, 5, 2**32 - 4, 2**32 - 3, 2**32 - 2]), False),
                   ("aovs", lambda: v.choice([True, False]), True),
                   ("stokes", lambda: v.choice([True, False]), True),
                   ("spectral_bins", lambda: v.small_int(0, 8), False),
                   ("spectral_range", lambda: v.choice([(360, 830), (400.0, 700.0), [500, 501]]), True),
                   ("colorspace", lambda: v.choice(["rec709", "acescg"]), True)]
        for name, good, cheap in choices:
            if self.rng.random() < 0.35:
                kwargs[name] = v.maybe(good, cost="cheap" if cheap else "bounded")
        if self.rng.random() < 0.3:
            kwargs["progress"] = v.maybe(lambda: self.progress(scene))
        return kwargs

    def progress(self, scene):
        kind = self.rng.randrange(4)
        if kind == 0:
            return lambda done, total: None
        if kind == 1:
            def fail(done, total):
                raise ValueError("progress stops the render")
            return fail
        if kind == 2:  # a render of the same scene inside the callback, once
            nested = []

            def render_again(done, total):
                if not nested:
                    nested.append(scene.render(spp=1))
            return render_again
        return lambda: None  # wrong signature: TypeError from the call, which propagates

    def call(self):
        kind = self.rng.choices(
            ["load", "render", "write_exr", "polarization_mode", "mitsuba", "material", "material_method",
             "spectrum", "spectrum_method", "colour", "read_exr", "relight"],
            weights=[14, 14, 10, 2, 3, 8, 14, 8, 8, 10, 4, 5])[0]
        return getattr(self, "call_" + kind)()

    def call_load(self):
        source, is_dict = self.scene_source()
        kwargs = self.load_kwargs(is_dict)
        return f"load_scene({short(source)}, **{short(kwargs)})", lambda: self.ochre.load_scene(source, **kwargs)

    def call_render(self):
        scene, source, _ = self.loaded_scene()
        kwargs = self.render_kwargs(scene)
        return f"load_scene({short(source)}).render(**{short(kwargs)})", lambda: scene.render(**kwargs)

    def call_write_exr(self):
        scene, source, inputs = self.loaded_scene()
        result = scene.render(spp=1)
        v, s = self.v, self.scratch
        own_inputs = [str(s / name) for name in inputs]
        fresh = str(s / f"out-{self.rng.randrange(4)}.exr")
        special = [str(s / n) for n in ("fifo", "dir", "link", "dirlink", "dangling")] + \
            ["/dev/null", "/dev/full", str(s / "no/such/dir/x.exr"), "", "\0", str(s / "out.png")]
        r = self.rng.random()
        if r < 0.4:
            path = fresh
        elif r < 0.55 and own_inputs:
            path = v.choice(own_inputs + (["dir/../scene.json", PathLike(str(s / "scene.json"))]
                                          if "scene.json" in inputs else []))
        elif r < 0.85:
            path = v.choice(special)
        else:
            path = v.anything()
        # A file of the scratch directory this scene did not read may be replaced: aim elsewhere.
        if self.protected_file(path) and self.protected_file(path) not in [os.path.realpath(p) for p in own_inputs]:
            path = fresh
        return f"load_scene({short(source)}).render(spp=1).write_exr({short(path)})", \
            lambda: result.write_exr(path)

    def protected_file(self, path):
        """The real path of `path` when it names one of the scratch directory's regular files, else None."""
        try:
            name = os.fsdecode(os.fspath(path))
            if os.path.islink(name):  # refused whatever it points to
                return None
            real = os.path.realpath(name)
        except (TypeError, ValueError):
            return None
        files = [os.path.realpath(self.scratch / n) for n in PROTECTED_FILES]
        return real if real in files else None

    def call_polarization_mode(self):
        scene, source, _ = self.loaded_scene()
        stokes = self.v.maybe(lambda: self.v.choice([True, False]))
        return f"load_scene({short(source)}).polarization_mode({short(stokes)})", \
            lambda: scene.polarization_mode(stokes)

    def call_mitsuba(self):
        v = self.v
        path = v.maybe(lambda: str(self.scratch / "mitsuba/elements.xml"), bad=0.5)
        parameters = v.maybe(lambda: v.choice([None, {"spp": 2}, {"nope": 1}, {"spp": [1]}, {"": 1}]))
        return f"mitsuba_to_json({short(path)}, {short(parameters)})", \
            lambda: self.ochre.mitsuba_to_json(path, parameters)

    def material_source(self):
        v = self.v
        good = [{"type": "lambert", "color": 0.8}, {"type": "conductor", "metal": "Au", "roughness": 0.3},
                {"type": "dielectric", "ior": 1.5, "roughness": 0.1}, {"type": "lambert", "color": {"file": "red.csv"}},
                {"type": "oren_nayar", "color": 0.8, "sigma": 0.5}]
        r = self.rng.random()
        if r < 0.4:
            return v.choice(good)
        if r < 0.65:
            return v.mutated(v.choice(good), extra_keys=("roughness", "colour", "ior"))
        if r < 0.75:
            return str(self.scratch / "material.json")
        return v.anything(cost="bounded")

    def call_material(self):
        v = self.v
        source = self.material_source()
        kwargs = {}
        if self.rng.random() < 0.3:
            kwargs["name"] = v.maybe(lambda: v.choice(["paint", "glass", "", "nope"]))
        if self.rng.random() < 0.3:
            kwargs["base_dir"] = v.maybe(lambda: str(self.scratch))
        return f"material({short(source)}, **{short(kwargs)})", lambda: self.ochre.material(source, **kwargs)

    def call_material_method(self):
        v = self.v
        try:
            material = self.ochre.material(self.material_source(), base_dir=str(self.scratch))
        except (ValueError, TypeError):
            material = self.ochre.material({"type": "lambert", "color": 0.5})
        method = v.choice(["eval", "mueller", "sample", "albedo", "polarizes"])
        if method in ("eval", "mueller"):
            args = [v.maybe(v.direction_array), v.maybe(v.direction_array), v.maybe(v.wavelengths)]
        elif method == "sample":
            args = [v.maybe(v.direction_array), v.maybe(v.wavelengths),
                    v.maybe(lambda: v.choice([None, [0.5, 0.25, 0.75], [[1.0, 0.5, 0.5]], [0.1, 0.2]])),
                    v.maybe(lambda: v.small_int(0, 2**64 - 1))]
        elif method == "albedo":
            args = [v.maybe(lambda: v.choice([[0], [30, 60], 45.0, [], [90], [-1], self.np.array([10.0])])),
                    v.maybe(v.wavelengths), v.maybe(lambda: v.small_int(1, 300), cost="work"),
                    v.maybe(lambda: v.small_int(0, 2**64 - 1))]
        else:
            args = [v.maybe(v.wavelengths)]
        return f"material(...).{method}(*{short(args)})", lambda: getattr(material, method)(*args)

    def call_spectrum(self):
        v, S = self.v, self.ochre.Spectrum
        kind = v.choice(["table", "named", "blackbody", "from_csv", "from_rgb", "constant"])
        if kind == "table":
            args = [v.maybe(lambda: [400, 500, 600]), v.maybe(lambda: [0.1, 0.5, 0.2]),
                    v.maybe(lambda: v.choice(["clamp", "zero"]))]
            return f"Spectrum(*{short(args)})", lambda: S(*args)
        if kind == "named":
            args = [v.maybe(lambda: v.choice(["D65", "A", "E", "cie_y", "metal-Au-eta"])), v.maybe(lambda: 2.0)]
            return f"Spectrum.named(*{short(args)})", lambda: S.named(*args)
        if kind == "blackbody":
            args = [v.maybe(lambda: v.choice([1000, 6500.0, 1e6, 1e7])), v.maybe(lambda: 1.0)]
            return f"Spectrum.blackbody(*{short(args)})", lambda: S.blackbody(*args)
        if kind == "from_csv":
            args = [v.maybe(lambda: str(self.scratch / "red.csv")), v.maybe(lambda: v.choice([None, "value", "nope"])),
                    v.maybe(lambda: v.choice(["clamp", "zero"]))]
            return f"Spectrum.from_csv(*{short(args)})", lambda: S.from_csv(*args)
        if kind == "from_rgb":
            args = [v.maybe(lambda: [v.rng.random() for _ in range(3)]),
                    v.maybe(lambda: v.choice(["reflectance", "illuminant", "unbounded"]))]
            return f"Spectrum.from_rgb(*{short(args)})", lambda: S.from_rgb(*args)
        args = [v.maybe(lambda: v.rng.uniform(-2, 2))]
        return f"Spectrum.constant(*{short(args)})", lambda: S.constant(*args)

    def call_spectrum_method(self):
        v, S = self.v, self.ochre.Spectrum
        spectrum = v.choice([S.named("D65"), S([400, 500], [0.2, 0.8]), S.blackbody(3000),
                             S.from_rgb([0.5, 0.2, 0.1]), S.constant(0.5)])
        method = v.choice(["__call__", "to_xyz", "to_lab", "to_rgb"])
        if method == "__call__":
            args = [v.maybe(v.wavelengths)]
        elif method == "to_rgb":
            args = [v.maybe(lambda: v.choice(["rec709", "acescg"])), v.maybe(lambda: v.choice([None, "D65", S.named("A")]))]
        else:
            args = [v.maybe(lambda: v.choice([None, "D65", "A", S.constant(0.0), S.blackbody(2000)]))]
        return f"Spectrum(...).{method}(*{short(args)})", lambda: getattr(spectrum, method)(*args)

    def image(self):
        np, v = self.np, self.v
        return v.maybe(lambda: np.random.default_rng(v.rng.randrange(1000)).random(
            (v.small_int(1, 4), v.small_int(1, 4), 3)).astype(v.choice([np.float32, np.float64])))

    def call_colour(self):
        v, o = self.v, self.ochre
        kind = v.choice(["xyz_to_lab", "ciede2000", "image_metrics", "to_display"])
        if kind == "xyz_to_lab":
            args = [v.maybe(lambda: [0.3, 0.4, 0.5]), v.maybe(lambda: [0.95, 1.0, 1.09])]
            return f"xyz_to_lab(*{short(args)})", lambda: o.xyz_to_lab(*args)
        if kind == "ciede2000":
            args = [v.maybe(lambda: [50, 2, -3]), v.maybe(lambda: [[50, 0, 0], [60, 1, 1]]),
                    v.maybe(lambda: 1.0), v.maybe(lambda: 1.0), v.maybe(lambda: 1.0)]
            return f"ciede2000(*{short(args)})", lambda: o.ciede2000(*args)
        if kind == "image_metrics":
            a = self.image()
            b = a if v.rng.random() < 0.5 else self.image()
            kwargs = {}
            if v.rng.random() < 0.3:
                kwargs["colorspace"] = v.maybe(lambda: v.choice(["rec709", "acescg"]))
            if v.rng.random() < 0.3:
                kwargs["ocio_config"] = v.maybe(lambda: v.choice(["none", "builtin"]))
            return f"image_metrics({short(a)}, {short(b)}, **{short(kwargs)})", lambda: o.image_metrics(a, b, **kwargs)
        rgb = self.image()
        kwargs = {}
        for name, good in (("colorspace", lambda: v.choice(["rec709", "acescg"])),
                           ("ocio_config", lambda: v.choice(["builtin", "none", ""] + [str(p) for p in (
                               self.scratch / "fifo", self.scratch / "dir", self.scratch / "scene.json")])),
                           ("display", lambda: v.choice(["", "sRGB", "nope"])), ("view", lambda: v.choice(["", "nope"])),
                           ("exposure", lambda: v.choice([0.0, -2, 3.5, 64, 65]))):
            if v.rng.random() < 0.3:
                kwargs[name] = v.maybe(good)
        return f"to_display({short(rgb)}, **{short(kwargs)})", lambda: o.to_display(rgb, **kwargs)

    def call_read_exr(self):
        v = self.v
        path = v.maybe(lambda: v.choice([str(self.scratch / "out-0.exr"), str(self.scratch / "mitsuba/checker.ppm")]),
                       bad=0.6)
        return f"read_exr({short(path)})", lambda: self.ochre.read_exr(path)

    def call_relight(self):
        v, s = self.v, self.scratch
        groups_exr = str(s / "groups.exr")
        render = v.maybe(lambda: v.choice([groups_exr, pathlib.Path(groups_exr), str(s / "out-0.exr")]), bad=0.3)
        groups = v.maybe(lambda: v.choice([None, {}, {"lamp": 0.5}, {"sky": "off", "lamp": 2}, {"lamp": "on"},
                                           {"lamp": v.anything()}, {"nope": 1}, {"sky": "cct=2000"},
                                           {"lamp": "scale=3,off"}, {v.choice([1, None, b"lamp", 2.5]): 1}]))

        def output(extension):
            r = self.rng.random()
            if r < 0.5:
                return None
            if r < 0.8:
                path = str(s / f"out-{self.rng.randrange(4)}{extension}")
            elif r < 0.9:
                path = groups_exr
            else:
                path = v.choice([v.anything(), *[str(s / n) for n in ("fifo", "dir", "link", "dangling")],
                                 "/dev/null", str(s / ("no/such/dir/x" + extension))])
            # Only the render itself is an input of relight: any other file of the scratch directory may be
            # replaced, so aim elsewhere.
            protected = self.protected_file(path)
            own = isinstance(render, (str, pathlib.Path)) and str(render) == groups_exr and \
                protected == os.path.realpath(groups_exr)
            return str(s / f"out-{self.rng.randrange(4)}{extension}") if protected and not own else path

        kwargs = {"groups": groups, "exr": output(".exr"), "png": output(".png")}
        kwargs = {k: value for k, value in kwargs.items() if value is not None or self.rng.random() < 0.2}
        return f"relight({short(render)}, **{short(kwargs)})", lambda: self.ochre.relight(render, **kwargs)


def short(value, limit=300):
    try:
        text = repr(value)
    except Exception:  # a container too deep for repr
        text = f"<{type(value).__name__}>"
    return text if len(text) <= limit else text[:limit] + "..."


# ----------------------------------------------------------------------------------------------------------
# The child: runs iterations and checks each.

class Finding(Exception):
    pass


def fault_call(kind):
    """The faults --selftest injects, to show that each kind of finding is reported."""
    if kind == "crash":
        import ctypes
        return "selftest: a crash", lambda: ctypes.string_at(0)
    if kind == "hang":
        return "selftest: a hang", lambda: time.sleep(3600)
    if kind == "exception":
        def internal():
            raise RuntimeError("an internal error")
        return "selftest: another exception", internal
    def foreign():
        raise TypeError("incompatible function arguments")
    return "selftest: a message naming no argument", foreign


def check_outcome(ochre, description, thunk, scratch, before):
    outcome = "ok"
    try:
        thunk()
    except (ochre.InputError, TypeError, ValueError) as e:
        message = str(e)
        outcome = "InputError" if isinstance(e, ochre.InputError) else type(e).__name__
        if isinstance(e, ValueError) and not isinstance(e, ochre.InputError) and "progress stops" in message:
            outcome = "progress"
        elif any(foreign in message for foreign in FOREIGN_MESSAGES) and "wrong signature" not in message \
                and "positional argument" not in message:
            raise Finding(f"{description}\n  raised {type(e).__name__} with a message that names no argument: "
                          f"{message[:500]}")
        elif not message:
            raise Finding(f"{description}\n  raised {type(e).__name__} without a message")
    except BaseException as e:  # any other exception is a bug (KeyboardInterrupt included: nothing sent one)
        raise Finding(f"{description}\n  raised {type(e).__name__}: {str(e)[:500]}\n"
                      + "".join(traceback.format_exception(e))[-3000:])
    after = protected_state(scratch)
    if after != before:
        changed = [k for k in before if before[k] != after.get(k)]
        raise Finding(f"{description}\n  changed {', '.join(changed)} in the scratch directory")
    leftovers = [p.name for p in pathlib.Path(scratch).rglob("*.tmp-*")]
    if leftovers:
        raise Finding(f"{description}\n  left temporary files {leftovers}")
    return outcome


def run_child(seed, first, count, seconds, scratch, log_path, only=None):
    import numpy as np
    import ochre

    os.chdir(scratch)
    make_groups_render(ochre, scratch)
    before = protected_state(scratch)
    deadline = time.monotonic() + seconds
    counts = {}
    with open(log_path, "a", buffering=1) as log:
        i = first
        while (only is None and i < first + count and time.monotonic() < deadline) or (only is not None and i == only):
            rng = random.Random(f"{seed}:{i}")
            values = Values(rng, np, scratch)
            calls = Calls(ochre, np, scratch, values)
            description, thunk = calls.call()
            if os.environ.get("OCHRE_FUZZ_PYTHON_FAULT") and i == first + 2:  # --selftest
                description, thunk = fault_call(os.environ["OCHRE_FUZZ_PYTHON_FAULT"])
            log.write(f"start {seed}:{i} {description[:2000]}\n")
            if only is not None:
                print(f"{seed}:{i}: {description}")
            try:
                outcome = check_outcome(ochre, description, thunk, scratch, before)
            except Finding as finding:
                log.write(f"finding {seed}:{i}\n")
                print(f"fuzz_python: finding at iteration {seed}:{i} (repeat: {sys.argv[0]} --repeat {seed}:{i})\n"
                      f"  {finding}", flush=True)
                return 1
            if only is not None:
                print(f"  -> {outcome}")
            counts[outcome] = counts.get(outcome, 0) + 1
            log.write(f"done {seed}:{i} {outcome}\n")
            i += 1
            for p in pathlib.Path(scratch).glob("out-*"):
                if rng.random() < 0.1:
                    p.unlink()
    print(json.dumps({"iterations": sum(counts.values()), "outcomes": counts}), flush=True)
    return 0


# ----------------------------------------------------------------------------------------------------------
# The parent: runs children until the time or the iterations are spent, and reports.

def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--seconds", type=float, default=None, help="run this long (default 15 without --iterations)")
    parser.add_argument("--iterations", type=int, default=None, help="run this many calls")
    parser.add_argument("--seed", type=int, default=1, help="first seed (each child process takes the next)")
    parser.add_argument("--repeat", metavar="SEED:ITERATION", help="run one iteration, printing the call")
    parser.add_argument("--selftest", action="store_true",
                        help="check that a crash, a hang and a bad exception are each reported")
    parser.add_argument("--child", nargs=5, metavar=("SEED", "FIRST", "COUNT", "SECONDS", "SCRATCH"),
                        help=argparse.SUPPRESS)
    parser.add_argument("--log", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.child:
        seed, first, count = (int(x) for x in args.child[:3])
        return run_child(seed, first, count, float(args.child[3]), args.child[4], args.log)
    if args.seconds is not None and not args.seconds > 0 or args.iterations is not None and args.iterations < 1:
        parser.error("--seconds and --iterations must be positive")

    with tempfile.TemporaryDirectory(prefix="ochre-fuzz-python-") as work:
        scratch = os.path.join(work, "scratch")
        os.mkdir(scratch)
        make_scratch(scratch)
        log_path = os.path.join(work, "calls.log")
        if args.repeat:  # in this process: a crash shows as it happens
            seed, _, iteration = args.repeat.partition(":")
            return run_child(int(seed), int(iteration), 1, 600, scratch, log_path, only=int(iteration))
        if args.selftest:
            return selftest(scratch, log_path)
        seconds = args.seconds if args.seconds is not None else (None if args.iterations else 15.0)
        deadline = None if seconds is None else time.monotonic() + seconds
        remaining = args.iterations
        total, outcomes, children, seed = 0, {}, 0, args.seed
        start = time.monotonic()
        while (deadline is None or time.monotonic() < deadline) and (remaining is None or remaining > 0):
            batch = BATCH_SECONDS if deadline is None else max(0.5, min(BATCH_SECONDS, deadline - time.monotonic()))
            count = remaining if remaining is not None else 10**9
            status, summary = run_child_process(seed, 0, count, batch, scratch, log_path)
            children += 1
            if status != 0:
                return status
            total += summary["iterations"]
            for k, n in summary["outcomes"].items():
                outcomes[k] = outcomes.get(k, 0) + n
            if remaining is not None:
                remaining -= summary["iterations"]
            seed += 1
        print(f"fuzz_python: {total} calls in {time.monotonic() - start:.1f} s ({children} process{'es' if children != 1 else ''}, seeds "
              f"{args.seed}-{seed - 1}): " + ", ".join(f"{k} {n}" for k, n in sorted(outcomes.items())) +
              "; no finding")
        return 0


def selftest(scratch, log_path):
    global HANG_SECONDS
    HANG_SECONDS = 3
    for fault in ("crash", "hang", "exception", "foreign"):
        os.environ["OCHRE_FUZZ_PYTHON_FAULT"] = fault
        print(f"fuzz_python: selftest: injecting {fault}:")
        status, _ = run_child_process(1, 0, 10, 5, scratch, log_path)
        if status != 1:
            print(f"fuzz_python: selftest: the {fault} was not reported")
            return 1
        if "selftest: " not in last_call(log_path):  # a finding of a real call before the injected one
            print(f"fuzz_python: selftest: a finding before the injected {fault}")
            return 1
    print("fuzz_python: selftest: a crash, a hang, an internal error and a message naming no argument are each "
          "reported")
    return 0


def run_child_process(seed, first, count, seconds, scratch, log_path):
    """Runs a child; returns (exit status, its summary). A crash or a hang is a finding (status 1)."""
    command = [sys.executable, os.path.abspath(__file__), "--child", str(seed), str(first), str(count),
               str(seconds), scratch, "--log", log_path]
    environment = dict(os.environ)
    environment.setdefault("PYTHONPATH", str(SOURCE_DIR / "build/python"))
    open(log_path, "w").close()
    process = subprocess.Popen(command, env=environment, stdout=subprocess.PIPE, text=True,
                               start_new_session=True)
    try:
        out, _ = process.communicate(timeout=seconds + HANG_SECONDS)
    except subprocess.TimeoutExpired:
        os.killpg(process.pid, signal.SIGKILL)
        process.communicate()
        print(f"fuzz_python: finding: a call hung (more than {HANG_SECONDS} s):\n  {last_call(log_path)}")
        return 1, None
    if process.returncode != 0:
        if process.returncode < 0:
            print(f"fuzz_python: finding: the process ended by signal {signal.Signals(-process.returncode).name} in:\n"
                  f"  {last_call(log_path)}")
        else:
            print(out, end="")
            if "finding at iteration" not in out:
                print(f"fuzz_python: the child failed (exit {process.returncode}) in:\n  {last_call(log_path)}")
        return 1, None
    return 0, json.loads(out.strip().splitlines()[-1])


def last_call(log_path):
    with open(log_path) as log:
        starts = [line for line in log if line.startswith("start ")]
    if not starts:
        return "(before the first call)"
    seed_iteration, _, description = starts[-1][len("start "):].partition(" ")
    return f"{description.strip()}\n  (repeat: {sys.argv[0]} --repeat {seed_iteration})"


if __name__ == "__main__":
    sys.exit(main())
