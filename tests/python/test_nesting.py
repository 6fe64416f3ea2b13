"""Python values converted to JSON (a scene, a material, a spectrum table given as dicts and lists;
docs/python.md, "Errors"): containers nested deeper than 256 levels, and containers that hold themselves,
are refused with ochre.InputError naming the path, as a JSON parser would refuse them, instead of
recursing until the interpreter's stack overflows (SIGSEGV). Each case runs in a child process, so that a
crash fails the test instead of ending the test runner."""

import subprocess
import sys
import textwrap
import unittest

import ochre  # noqa: F401 (the child imports it from the same PYTHONPATH)

PRELUDE = textwrap.dedent("""
    import numpy as np
    import ochre

    SCENE = {
        "camera": {"eye": [0, 0, 4], "fov": 30},
        "film": {"resolution": [8, 6]},
        "materials": {"grey": {"type": "lambert", "color": 0.5}},
        "lights": [{"type": "environment", "radiance": 1.0}],
        "shapes": [{"type": "sphere", "radius": 1, "material": "grey"}],
    }

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

    def message(call, error=ochre.InputError):
        try:
            call()
        except error as e:
            return str(e)
        raise AssertionError("no error")
""")


def run(code):
    """Runs PRELUDE + code in a child interpreter; returns its stdout. A crash or a hang fails the test."""
    result = subprocess.run([sys.executable, "-c", PRELUDE + textwrap.dedent(code)], capture_output=True, text=True,
                            timeout=300)
    if result.returncode != 0:
        raise AssertionError(f"the child ended with status {result.returncode}:\n{result.stdout}\n{result.stderr}")
    return result.stdout


class SelfReference(unittest.TestCase):
    def test_a_dict_that_holds_itself(self):
        out = run("""
            d = {}
            d["a"] = d
            print(message(lambda: ochre.load_scene(d)))
            scene = dict(SCENE)
            m = {"type": "lambert"}
            m["a"] = m
            scene["materials"] = {"a": m}
            print(message(lambda: ochre.load_scene(scene)))
        """).splitlines()
        self.assertEqual(out[0], "scene.a: refers to itself (it is scene, which contains it)")
        self.assertEqual(out[1], "scene.materials.a.a: refers to itself (it is scene.materials.a, which contains it)")

    def test_lists_and_arrays_that_hold_themselves(self):
        out = run("""
            a = [1.0]
            a.append(a)
            print(message(lambda: ochre.load_scene(dict(SCENE, shapes=[{"type": "sphere", "center": a}]))))
            print(message(lambda: ochre.material({"type": "lambert", "color": a})))
            print(message(lambda: ochre.Spectrum([400, 500], a)))
            o = np.empty(2, dtype=object)
            o[0], o[1] = 1.0, o
            print(message(lambda: ochre.material({"type": "lambert", "color": o})))
        """).splitlines()
        self.assertEqual(out[0], "scene.shapes[0].center[1]: refers to itself (it is scene.shapes[0].center, which "
                                 "contains it)")
        self.assertEqual(out[1], "material.color[1]: refers to itself (it is material.color, which contains it)")
        self.assertEqual(out[2], "values[1]: refers to itself (it is values, which contains it)")
        self.assertIn("material.color[1]: refers to itself", out[3])

    def test_a_value_used_twice_is_no_cycle(self):
        out = run("""
            colour = [0.5, 0.5, 0.5]
            scene = dict(SCENE, materials={"a": {"type": "lambert", "color": colour},
                                           "grey": {"type": "lambert", "color": colour}})
            print(ochre.load_scene(scene).material_names)
        """)
        self.assertIn("'grey'", out)


class Depth(unittest.TestCase):
    def test_a_list_nested_30000_deep(self):
        out = run("""
            deep = nested_list(30000)
            print(message(lambda: ochre.load_scene(dict(SCENE, shapes=deep))))
            print(message(lambda: ochre.load_scene(deep), TypeError))
            print(message(lambda: ochre.material({"type": "lambert", "color": deep})))
            print(message(lambda: ochre.Spectrum(deep, [1, 2])))
            print(message(lambda: ochre.load_scene(dict(SCENE, materials=nested_dict(30000)))))
        """).splitlines()
        self.assertEqual(out[0], "scene.shapes[0][0][0][0][0][0][0]...: nested deeper than 256 levels")
        self.assertEqual(out[1], "source: expected a dict (the scene) or a path (str or os.PathLike), got list")
        self.assertEqual(out[2], "material.color[0][0][0][0][0][0][0]...: nested deeper than 256 levels")
        self.assertEqual(out[3], "wavelengths[0][0][0][0][0][0][0][0]...: nested deeper than 256 levels")
        self.assertEqual(out[4], "scene.materials.a.a.a.a.a.a.a...: nested deeper than 256 levels")

    def test_256_levels_convert_and_257_do_not(self):
        # The scene's own dict is the first level: 255 lists inside it make 256.
        out = run("""
            print(message(lambda: ochre.load_scene(dict(SCENE, description=nested_list(255)))))
            print(message(lambda: ochre.load_scene(dict(SCENE, description=nested_list(256)))))
        """).splitlines()
        self.assertNotIn("nested deeper", out[0])  # converted, then refused by the scene's validation
        self.assertIn("<dict>: description", out[0])
        self.assertIn("nested deeper than 256 levels", out[1])


if __name__ == "__main__":
    unittest.main()
