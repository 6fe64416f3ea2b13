"""ochre.load_scene and Scene.render (docs/python.md): scenes from files, dicts and Mitsuba XML; the same
bits as the command line; overrides; progress; Ctrl-C; the GIL released while rendering."""

import os
import signal
import subprocess
import sys
import tempfile
import threading
import time
import unittest

import numpy as np

import ochre

SOURCE = os.environ["OCHRE_SOURCE_DIR"]
BIN = os.environ["OCHRE_BIN_DIR"]
BOX = os.path.join(SOURCE, "scenes/cornell-box/cornell-box.json")
POLARIZED_BOX = os.path.join(SOURCE, "scenes/cornell-box/cornell-box-polarized.json")
ELEMENTS_XML = os.path.join(SOURCE, "tests/data/mitsuba/elements.xml")


def sphere_scene(**changes):
    scene = {
        "camera": {"eye": [0, 0, 4], "fov": 30},
        "film": {"resolution": [16, 12]},
        "integrator": {"spp": 4},
        "materials": {"grey": {"type": "lambert", "color": 0.5}},
        "lights": [{"type": "environment", "radiance": 1.0}],
        "shapes": [{"type": "sphere", "radius": 1, "material": "grey"}],
    }
    scene.update(changes)
    return scene


class LoadScene(unittest.TestCase):
    def test_file_scene_renders_with_overrides(self):
        scene = ochre.load_scene(BOX, resolution=(24, 16), spp=2, seed=5, threads=1)
        self.assertEqual(scene.settings["width"], 24)
        self.assertEqual(scene.settings["spp"], 2)
        self.assertEqual(scene.settings["seed"], 5)
        self.assertEqual(scene.settings["light_selection"], "auto")  # the default: the pilot chooses
        self.assertEqual(scene.settings["guiding"], "off")  # path guiding is asked for by the scene
        result = scene.render()
        self.assertEqual(result.rgb.shape, (16, 24, 3))
        self.assertEqual(result.rgb.dtype, np.float32)
        self.assertEqual(result.xyz.shape, (16, 24, 3))
        self.assertEqual(result.stats["samples"], 24 * 16 * 2)
        self.assertGreater(result.rgb.mean(), 0.0)

    def test_dict_scene_is_validated_like_a_file(self):
        result = ochre.load_scene(sphere_scene()).render()
        self.assertEqual(result.rgb.shape, (12, 16, 3))
        bad = sphere_scene(shapes=[{"type": "sphere", "radius": -1, "material": "grey"}])
        with self.assertRaises(ochre.InputError) as error:
            ochre.load_scene(bad)
        self.assertEqual(str(error.exception), "<dict>: shapes[0].radius: must be in (0, 1e+30] (got -1)")
        with self.assertRaises(ochre.InputError) as error:
            ochre.load_scene(sphere_scene(integrator={"spp": 4, "max_dept": 2}))
        self.assertIn("<dict>: integrator.max_dept: unknown parameter 'max_dept'", str(error.exception))
        with self.assertRaises(ochre.InputError) as error:
            ochre.load_scene(sphere_scene(materials={"grey": {"type": "lambert", "colour": 0.5}}))
        self.assertIn("material 'grey'", str(error.exception))
        self.assertIn("colour", str(error.exception))
        self.assertTrue(issubclass(ochre.InputError, ValueError))

    def test_dict_values_that_json_cannot_hold(self):
        with self.assertRaises(TypeError) as error:
            ochre.load_scene(sphere_scene(description=object()))
        self.assertIn("scene.description: cannot be written in a scene (type object)", str(error.exception))
        # numpy values are numbers and lists.
        scene = sphere_scene(camera={"eye": np.array([0.0, 0.0, 4.0]), "fov": np.float32(30)})
        self.assertEqual(ochre.load_scene(scene).width, 16)

    def test_dict_paths_resolve_against_base_dir(self):
        scene = sphere_scene(shapes=[{"type": "mesh", "file": "quad.obj", "material": "grey"}])
        loaded = ochre.load_scene(scene, base_dir=os.path.join(SOURCE, "tests/data"))
        self.assertEqual(loaded.mesh_count, 1)
        with self.assertRaises(ochre.InputError) as error:
            ochre.load_scene(scene, base_dir=tempfile.gettempdir())
        self.assertIn("<dict>: shapes[0].file", str(error.exception))

    def test_bad_overrides(self):
        with self.assertRaises(ochre.InputError) as error:
            ochre.load_scene(BOX, spp=0)
        self.assertIn("spp", str(error.exception))
        with self.assertRaises(ochre.InputError):
            ochre.load_scene(BOX, resolution=(0, 8))
        with self.assertRaises(ochre.InputError) as error:
            ochre.load_scene(BOX, polarization="sideways")
        # The argument is named, with the known values.
        self.assertIn("polarization: unknown 'sideways' (known: auto, off, intensity, stokes)", str(error.exception))
        with self.assertRaises(ochre.InputError) as error:
            ochre.load_scene(BOX, sampler="halton")
        self.assertIn("sampler: unknown 'halton' (known: independent, sobol)", str(error.exception))
        with self.assertRaises(ochre.InputError) as error:
            ochre.load_scene(os.path.join(SOURCE, "no/such/scene.json"))
        self.assertIn("cannot open scene file", str(error.exception))

    def test_mitsuba_scene_with_parameters(self):
        scene = ochre.load_scene(ELEMENTS_XML, parameters={"spp": 3})
        self.assertEqual(scene.settings["spp"], 3)
        self.assertEqual(scene.settings["max_depth"], 4)
        self.assertEqual(scene.settings["filter"], "gaussian (stddev 0.5, radius 2)")
        translated = ochre.mitsuba_to_json(ELEMENTS_XML)
        self.assertEqual(translated["integrator"]["max_depth"], 4)
        self.assertEqual(translated["film"]["resolution"], [24, 16])
        # The translation loads as a dict too (its file names are relative to the XML's directory).
        again = ochre.load_scene(translated, base_dir=os.path.dirname(ELEMENTS_XML))
        self.assertEqual(again.mesh_count, scene.mesh_count)
        with self.assertRaises(ochre.InputError) as error:
            ochre.load_scene(ELEMENTS_XML, parameters={"sp": 3})
        self.assertIn("scene parameter 'sp' is not used", str(error.exception))


class SameBitsAsTheCommandLine(unittest.TestCase):
    def test_every_channel_equals_the_exr_of_ochre_render(self):
        with tempfile.TemporaryDirectory() as d:
            exr = os.path.join(d, "cli.exr")
            subprocess.run([os.path.join(BIN, "ochre"), "render", POLARIZED_BOX, "-o", exr, "-q", "--spp", "3",
                            "--resolution", "20x12", "--seed", "7", "--aovs", "--stokes", "--spectral-bins", "4"],
                           check=True)
            cli, attributes = ochre.read_exr(exr)
            scene = ochre.load_scene(POLARIZED_BOX, resolution=(20, 12), seed=7)
            result = scene.render(spp=3, aovs=True, stokes=True, spectral_bins=4)
            ours = result.channels
            self.assertEqual(sorted(ours), sorted(cli))
            for name in cli:
                self.assertTrue(np.array_equal(ours[name], cli[name]), name)
            self.assertTrue(np.array_equal(result.rgb, np.stack([cli["R"], cli["G"], cli["B"]], axis=-1)))
            self.assertEqual(attributes["ochre.spp"], "3")
            # The arrays of the layers.
            self.assertEqual(result.aovs["albedo"].shape, (12, 20, 3))
            self.assertEqual(result.aovs["depth"].shape, (12, 20))
            self.assertEqual(result.stokes.shape, (4, 12, 20, 3))
            self.assertTrue(np.array_equal(result.stokes[1][..., 1], cli["stokes.S1.Y"]))
            self.assertEqual(result.dolp.shape, (12, 20))
            self.assertEqual(result.spectral.shape, (4, 12, 20, 4))
            np.testing.assert_allclose(result.wavelengths, [418.75, 536.25, 653.75, 771.25])
            # write_exr writes the same file content.
            mine = os.path.join(d, "python.exr")
            result.write_exr(mine)
            written, _ = ochre.read_exr(mine)
            for name in cli:
                self.assertTrue(np.array_equal(written[name], cli[name]), name)

    def test_noise_threshold_equals_the_command_line(self):
        # The same bits as `ochre render --noise-threshold`; pixels stop at a power of two from 16 up.
        with tempfile.TemporaryDirectory() as d:
            exr = os.path.join(d, "cli.exr")
            subprocess.run([os.path.join(BIN, "ochre"), "render", BOX, "-o", exr, "-q", "--spp", "64",
                            "--resolution", "16x12", "--seed", "3", "--noise-threshold", "0.2"], check=True)
            cli, attributes = ochre.read_exr(exr)
            result = ochre.load_scene(BOX, resolution=(16, 12), seed=3).render(spp=64, noise_threshold=0.2)
            self.assertEqual(sorted(result.channels), sorted(cli))
            for name in cli:
                self.assertTrue(np.array_equal(result.channels[name], cli[name]), name)
            counts = set(np.unique(result.channels["samples.Y"]).tolist())
            self.assertLessEqual(counts, {16.0, 32.0, 64.0})
            self.assertIn(16.0, counts)  # a threshold of 20 % stops some pixels early
            self.assertEqual(attributes["ochre.noiseThreshold"], "0.2")

    def test_noise_threshold_refusals(self):
        scene = ochre.load_scene(BOX, resolution=(8, 8), spp=16)
        for bad in (-0.1, 1.5, float("nan")):
            with self.assertRaises(ochre.InputError) as error:
                scene.render(noise_threshold=bad)
            self.assertIn("noise_threshold", str(error.exception))
        with self.assertRaises(TypeError) as error:
            scene.render(noise_threshold="low")
        self.assertIn("noise_threshold", str(error.exception))
        with self.assertRaises(ochre.InputError) as error:
            scene.render(noise_threshold=0.1, sample_begin=16)
        self.assertIn("starts at sample 0", str(error.exception))

    def test_threads_do_not_change_the_image(self):
        scene = ochre.load_scene(BOX, resolution=(16, 16), spp=2)
        self.assertTrue(np.array_equal(scene.render(threads=1).rgb, scene.render(threads=2).rgb))


class Concurrency(unittest.TestCase):
    def test_two_threads_rendering_one_scene_get_their_own_settings(self):
        scene = ochre.load_scene(BOX, resolution=(16, 16))
        results = {}

        def render(spp):
            results[spp] = scene.render(spp=spp, seed=3)

        threads = [threading.Thread(target=render, args=(spp,)) for spp in (1, 7)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        self.assertEqual(results[1].stats["samples"], 16 * 16)
        self.assertEqual(results[7].stats["samples"], 16 * 16 * 7)
        self.assertTrue(np.array_equal(results[7].rgb, scene.render(spp=7, seed=3).rgb))


class Reentrance(unittest.TestCase):
    """A progress callback may render the scene it reports on (docs/python.md): renders copy the scene's
    settings and take no lock, so both finish, with the bits of plain renders, and an exception raised in
    the nested render propagates out of both. Each case runs in a child process with a timeout, so that a
    deadlock fails the test instead of hanging the suite."""

    def run_child(self, code):
        prelude = f"import sys\nimport numpy as np\nimport ochre\nBOX = {BOX!r}\n"
        result = subprocess.run([sys.executable, "-c", prelude + code], capture_output=True, text=True, timeout=300)
        self.assertEqual(result.returncode, 0, result.stdout + result.stderr)
        return result.stdout

    def test_a_render_started_by_the_progress_callback(self):
        out = self.run_child("""
scene = ochre.load_scene(BOX, resolution=(64, 64))
plain_outer, plain_inner = scene.render(spp=128, seed=1), scene.render(spp=3, seed=9)
calls, inner = [], []

def progress(done, total):
    calls.append((done, total))
    if not inner:
        inner.append(scene.render(spp=3, seed=9))

outer = scene.render(spp=128, seed=1, progress=progress)
print("started before the end:", calls[0][0] < calls[0][1])
print("outer same bits:", np.array_equal(outer.rgb, plain_outer.rgb), outer.stats["samples"])
print("inner same bits:", np.array_equal(inner[0].rgb, plain_inner.rgb), inner[0].stats["samples"])
print("settings kept:", scene.settings["spp"])
""")
        self.assertIn("started before the end: True", out)
        self.assertIn(f"outer same bits: True {64 * 64 * 128}", out)
        self.assertIn(f"inner same bits: True {64 * 64 * 3}", out)
        self.assertIn("settings kept: 128", out)

    def test_an_exception_in_the_nested_render_propagates(self):
        out = self.run_child("""
scene = ochre.load_scene(BOX, resolution=(64, 64))

def inner_fails(done, total):
    raise ValueError("raised in the nested render")

def progress(done, total):
    scene.render(spp=256, progress=inner_fails)

try:
    scene.render(spp=1024, progress=progress)
    print("no exception")
except ValueError as e:
    print("propagated:", e)
print("renders again:", scene.render(spp=1).stats["samples"])
""")
        self.assertIn("propagated: raised in the nested render", out)
        self.assertIn(f"renders again: {64 * 64}", out)


class Progress(unittest.TestCase):
    def test_progress_reaches_the_total(self):
        calls = []
        result = ochre.load_scene(sphere_scene()).render(spp=8, progress=lambda done, total: calls.append((done, total)))
        self.assertGreater(len(calls), 0)
        self.assertEqual(calls[-1], (16 * 12 * 8, 16 * 12 * 8))
        self.assertEqual([d for d, _ in calls], sorted(d for d, _ in calls))
        self.assertEqual(result.stats["samples"], 16 * 12 * 8)

    def test_an_exception_in_progress_stops_the_render(self):
        scene = ochre.load_scene(BOX, resolution=(128, 128))

        def fail(done, total):
            raise RuntimeError("stop here")

        start = time.monotonic()
        with self.assertRaises(RuntimeError):
            scene.render(spp=4096, progress=fail)
        self.assertLess(time.monotonic() - start, 10.0)
        self.assertEqual(scene.render(spp=1).rgb.shape, (128, 128, 3))  # the scene still renders


class Interrupt(unittest.TestCase):
    def test_ctrl_c_stops_the_render_with_keyboard_interrupt(self):
        # 128 x 128 pixels at 4096 samples: minutes of work; SIGINT after 0.3 s must end it in seconds.
        scene = ochre.load_scene(BOX, resolution=(128, 128))
        timer = threading.Timer(0.3, lambda: os.kill(os.getpid(), signal.SIGINT))
        start = time.monotonic()
        timer.start()
        with self.assertRaises(KeyboardInterrupt):
            scene.render(spp=4096)
        elapsed = time.monotonic() - start
        timer.join()
        self.assertLess(elapsed, 5.0)
        self.assertEqual(scene.settings["spp"], 128)  # the scene's own settings are back
        self.assertEqual(scene.render(spp=1).rgb.shape, (128, 128, 3))


class GilReleased(unittest.TestCase):
    def test_python_runs_while_ochre_renders(self):
        # The render runs in a second thread; the progress callback (every 0.1 s, in that thread) notes how
        # far this thread has counted meanwhile. With the GIL held while rendering it could not count.
        scene = ochre.load_scene(BOX, resolution=(64, 64))
        counter, seen = [0], []
        finished = threading.Event()

        def render():
            scene.render(spp=256, threads=1, progress=lambda done, total: seen.append(counter[0]))
            finished.set()

        worker = threading.Thread(target=render)
        worker.start()
        while not finished.is_set():
            counter[0] += 1
        worker.join()
        self.assertGreaterEqual(len(seen), 3)
        steps = np.diff(seen[:-1])
        self.assertGreater(int(steps.min()), 1000, seen)  # this thread counted between every two calls


if __name__ == "__main__":
    unittest.main()
