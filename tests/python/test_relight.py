"""ochre.relight (docs/python.md, "Relighting"): the call of `ochre relight`, with its checks."""

import os
import subprocess
import tempfile
import unittest

import numpy as np

import ochre

SCENE = """{
  "camera": {"eye": [0, 1, 4], "target": [0, 1, 0], "fov": 50},
  "film": {"resolution": [16, 12]}, "integrator": {"spp": 16},
  "materials": {"rock": {"type": "lambert", "color": [0.6, 0.5, 0.4]}},
  "lights": [{"type": "flame", "preset": "torch", "position": [0.3, 1.2, 0.5], "group": "torch"},
             {"type": "point", "position": [-1, 2, 1], "intensity": 3, "group": "lamp"}],
  "shapes": [{"type": "plane", "size": [6, 4], "material": "rock", "transform": [{"translate": [0, 1, 0]}]}]
}"""


class Relight(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.dir = tempfile.mkdtemp()
        with open(os.path.join(cls.dir, "scene.json"), "w") as f:
            f.write(SCENE)
        result = ochre.load_scene(os.path.join(cls.dir, "scene.json")).render()
        cls.render = os.path.join(cls.dir, "render.exr")
        result.write_exr(cls.render)

    def test_scales_and_off_recombine_the_groups(self):
        channels, attributes = ochre.relight(self.render, groups={"torch": "off", "lamp": 2})
        original, _ = ochre.read_exr(self.render)
        self.assertEqual(attributes["ochre.relight"], "torch:scale=0 lamp:scale=2")
        for c in "RGB":
            np.testing.assert_allclose(channels[c], 2 * original["group.lamp." + c], rtol=1e-6, atol=1e-7)

    def test_outputs_are_those_of_the_command_line(self):
        exr = os.path.join(self.dir, "py.exr")
        ochre.relight(self.render, groups={"lamp": 0.5}, exr=exr)
        cli = os.path.join(self.dir, "cli.exr")
        ochre_bin = os.path.join(os.environ.get("OCHRE_BIN_DIR", ""), "ochre")
        self.assertTrue(os.path.exists(ochre_bin), "OCHRE_BIN_DIR must name the build's bin/")
        subprocess.run([ochre_bin, "relight", self.render, "--group", "lamp:scale=0.5", "-o", cli, "-q"], check=True)
        a, _ = ochre.read_exr(exr)
        b, _ = ochre.read_exr(cli)
        self.assertEqual(sorted(a), sorted(b))
        for name in a:
            np.testing.assert_array_equal(a[name], b[name])

    def test_the_page_is_that_of_the_command_line(self):
        page = os.path.join(self.dir, "page")
        ochre.relight(self.render, groups={"lamp": 0.5}, html=page)
        cli = os.path.join(self.dir, "cli-page")
        ochre_bin = os.path.join(os.environ.get("OCHRE_BIN_DIR", ""), "ochre")
        subprocess.run([ochre_bin, "relight", self.render, "--html", cli, "-q"], check=True)
        with open(os.path.join(page, "index.html"), "rb") as a, open(os.path.join(cli, "index.html"), "rb") as b:
            self.assertEqual(a.read(), b.read())
        # A folder that is not empty is refused before anything is written.
        exr = os.path.join(self.dir, "not-written.exr")
        with self.assertRaisesRegex(ochre.InputError, "page"):
            ochre.relight(self.render, exr=exr, html=self.dir)
        self.assertFalse(os.path.exists(exr))

    def test_bad_changes_raise_naming_them(self):
        with self.assertRaisesRegex(ochre.InputError, "no light group 'candle'"):
            ochre.relight(self.render, groups={"candle": 1})
        with self.assertRaisesRegex(ochre.InputError, r"groups\['torch'\]: --group 'torch:cct=hot'"):
            ochre.relight(self.render, groups={"torch": "cct=hot"})
        with self.assertRaisesRegex(ochre.InputError, "light group 'torch' has no spectral bins"):
            ochre.relight(self.render, groups={"torch": "scale=0.5,cct=1850"})
        with self.assertRaisesRegex(ochre.InputError, "finite number >= 0"):
            ochre.relight(self.render, groups={"torch": -1})
        with self.assertRaises(TypeError):
            ochre.relight(self.render, groups={"torch": True})
        before = open(self.render, "rb").read()
        with self.assertRaises(ochre.InputError):
            ochre.relight(self.render, groups={"lamp": 0.5}, exr=self.render)
        self.assertEqual(open(self.render, "rb").read(), before)

    def test_arguments_of_the_wrong_type_or_value_name_the_argument(self):
        # docs/python.md, "Errors": TypeError for a wrong type, InputError for a bad value, each message
        # starting with the argument's name.
        def message(error, **kwargs):
            kwargs.setdefault("render", self.render)
            with self.assertRaises(error) as raised:
                ochre.relight(**kwargs)
            if error is TypeError:
                self.assertNotIsInstance(raised.exception, ochre.InputError)
            return str(raised.exception)

        self.assertEqual(message(TypeError, render=3), "render: expected a path (str or os.PathLike), got int 3")
        self.assertEqual(message(TypeError, groups=[("torch", 1)]),
                         "groups: expected a dict of group name -> scale, 'off', 'on' or changes ('scale=S,cct=T'), got list")
        self.assertEqual(message(TypeError, groups={1: 1}), "groups: expected str keys (group names), got int 1")
        self.assertEqual(message(TypeError, groups={"torch": True}),
                         "groups['torch']: expected a number (the scale), 'off', 'on' or changes ('scale=S,cct=T'), got bool True")
        self.assertEqual(message(TypeError, groups={"torch": [1]}), "groups['torch']: expected a number (the scale), 'off', 'on' or changes ('scale=S,cct=T'), got list")
        self.assertTrue(message(TypeError, exr=3.5).startswith("exr: expected a path"))
        self.assertTrue(message(TypeError, png=7).startswith("png: expected a path"))
        self.assertEqual(message(ochre.InputError, groups={"torch": -1}),
                         "groups['torch']: a scale must be a finite number >= 0 (got -1)")
        self.assertTrue(message(ochre.InputError, groups={"torch": float("nan")}).startswith("groups['torch']: "))
        self.assertTrue(message(ochre.InputError, groups={"torch": "cct=hot"}).startswith("groups['torch']: "))
        self.assertTrue(message(ochre.InputError, groups={"torch": "dim"}).startswith("groups['torch']: "))
        self.assertEqual(message(ochre.InputError, render=""), "render: the path is empty")
        self.assertEqual(message(ochre.InputError, exr=""), "exr: the path is empty")
        # Numbers of numpy and the words are accepted as the command line's NAME:scale=S, NAME:off, NAME:on.
        _, attributes = ochre.relight(self.render, groups={"torch": np.float32(0.5), "lamp": "on"})
        self.assertEqual(attributes["ochre.relight"], "torch:scale=0.5 lamp:scale=1")


if __name__ == "__main__":
    unittest.main()
