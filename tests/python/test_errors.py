"""Bad arguments (docs/python.md, "Errors"): every public function names the argument in its error, a
TypeError for a value of the wrong type, ochre.InputError (a ValueError) for a bad value; integers never
wrap, booleans are True or False, NaN and infinities are refused; counts of 0 are refused where the
command line refuses them; files that are missing, directories, FIFOs or devices are refused as inputs."""

import math
import os
import tempfile
import unittest

import numpy as np

import ochre

SOURCE = os.environ["OCHRE_SOURCE_DIR"]
BOX = os.path.join(SOURCE, "scenes/cornell-box/cornell-box.json")
ELEMENTS_XML = os.path.join(SOURCE, "tests/data/mitsuba/elements.xml")

SCENE = {
    "camera": {"eye": [0, 0, 4], "fov": 30},
    "film": {"resolution": [8, 6]},
    "integrator": {"spp": 1},
    "materials": {"grey": {"type": "lambert", "color": 0.5}},
    "lights": [{"type": "environment", "radiance": 1.0}],
    "shapes": [{"type": "sphere", "radius": 1, "material": "grey"}],
}


class Case(unittest.TestCase):
    def raises(self, error, what, call, *args, **kwargs):
        """call(*args, **kwargs) raises `error` (exactly TypeError, or an InputError) whose message starts
        with `what: ` (the argument's name)."""
        with self.assertRaises(error) as raised:
            call(*args, **kwargs)
        if error is TypeError:
            self.assertNotIsInstance(raised.exception, ochre.InputError)
        message = str(raised.exception)
        self.assertTrue(message.startswith(what + ": "), f"{message!r} does not start with {what!r}")
        for foreign in ("incompatible function arguments", "Unable to cast", "could not convert"):
            self.assertNotIn(foreign, message)
        return message

    def wrong_type(self, what, call, *args, **kwargs):
        return self.raises(TypeError, what, call, *args, **kwargs)

    def bad_value(self, what, call, *args, **kwargs):
        return self.raises(ochre.InputError, what, call, *args, **kwargs)


class LoadScene(Case):
    def test_wrong_types_name_the_argument(self):
        load = ochre.load_scene
        self.assertEqual(self.wrong_type("source", load, 3),
                         "source: expected a dict (the scene) or a path (str or os.PathLike), got int 3")
        self.wrong_type("source", load, [SCENE])
        self.assertEqual(self.wrong_type("spp", load, SCENE, spp="x"), "spp: expected an integer, got str 'x'")
        self.wrong_type("spp", load, SCENE, spp=4.0)
        self.assertEqual(self.wrong_type("spp", load, SCENE, spp=True), "spp: expected an integer, got bool True")
        self.wrong_type("spp", load, SCENE, spp=np.bool_(True))
        self.wrong_type("resolution", load, SCENE, resolution="64x64")
        self.wrong_type("resolution[0]", load, SCENE, resolution=(8.0, 8))
        self.wrong_type("seed", load, SCENE, seed="1")
        self.wrong_type("threads", load, SCENE, threads=1.5)
        self.wrong_type("polarization", load, SCENE, polarization=1)
        self.wrong_type("sampler", load, SCENE, sampler=b"sobol")
        self.wrong_type("parameters", load, ELEMENTS_XML, parameters=[("spp", 2)])
        self.wrong_type("parameters['spp']", load, ELEMENTS_XML, parameters={"spp": [2]})
        self.wrong_type("parameters['spp']", load, ELEMENTS_XML, parameters={"spp": True})
        self.wrong_type("parameters", load, ELEMENTS_XML, parameters={2: 2})
        self.wrong_type("base_dir", load, SCENE, base_dir=3)

    def test_bad_values_name_the_argument(self):
        load = ochre.load_scene
        self.assertEqual(self.bad_value("spp", load, SCENE, spp=0), "spp: must be in [1, 16777216] (got 0)")
        self.bad_value("spp", load, SCENE, spp=2**64 + 1)  # never wrapped to 1
        self.bad_value("spp", load, SCENE, spp=10**5000)
        self.bad_value("resolution", load, SCENE, resolution=(8,))
        self.bad_value("resolution", load, SCENE, resolution=(8, 0))
        self.bad_value("resolution", load, SCENE, resolution=(2**32 + 8, 8))
        self.assertEqual(self.bad_value("seed", load, SCENE, seed=-1), "seed: must be in [0, 2^64 - 1] (got -1)")
        self.bad_value("seed", load, SCENE, seed=2**64)
        self.bad_value("threads", load, SCENE, threads=-1)
        self.bad_value("threads", load, SCENE, threads=4097)
        self.bad_value("polarization", load, SCENE, polarization="")
        self.bad_value("parameters['']", load, ELEMENTS_XML, parameters={"": 2})
        self.bad_value("parameters['spp']", load, ELEMENTS_XML, parameters={"spp": math.nan})
        self.bad_value("source", load, "")
        self.bad_value("source", load, "scene\0.json")
        with tempfile.NamedTemporaryFile() as f:
            self.bad_value("base_dir", load, SCENE, base_dir=f.name)  # a file, not a directory
        self.bad_value("base_dir", load, BOX, base_dir=SOURCE)  # a dict only

    def test_the_largest_values_are_accepted(self):
        scene = ochre.load_scene(SCENE, seed=2**64 - 1, threads=np.int64(2), resolution=np.array([4, 2]))
        self.assertEqual(scene.settings["seed"], 2**64 - 1)
        self.assertEqual((scene.width, scene.height), (4, 2))

    def test_inputs_that_are_not_regular_files(self):
        with tempfile.TemporaryDirectory() as d:
            fifo = os.path.join(d, "scene.json")
            os.mkfifo(fifo)
            # A FIFO is refused before anything opens it: no hang.
            self.assertIn("the scene file is a FIFO, not a regular file", self.bad_value(fifo, ochre.load_scene, fifo))
            self.assertIn("is a directory", self.bad_value(d, ochre.load_scene, d))
            self.bad_value("/dev/zero", ochre.load_scene, "/dev/zero")
            self.bad_value(fifo, ochre.mitsuba_to_json, fifo)
            self.bad_value(fifo, ochre.material, fifo)
            self.bad_value(d, ochre.material, d)
            self.bad_value(fifo, ochre.read_exr, fifo)
            self.bad_value("/dev/zero", ochre.read_exr, "/dev/zero")
            self.bad_value("spectrum.file", ochre.Spectrum.from_csv, fifo)
            self.bad_value(fifo, ochre.to_display, np.zeros((1, 1, 3)), ocio_config=fifo)
            self.bad_value(d, ochre.to_display, np.zeros((1, 1, 3)), ocio_config=d)
            self.bad_value(os.path.join(d, "missing.json"), ochre.load_scene, os.path.join(d, "missing.json"))


class Render(Case):
    @classmethod
    def setUpClass(cls):
        cls.scene = ochre.load_scene(SCENE)

    def test_wrong_types_name_the_argument(self):
        render = self.scene.render
        for name, value in [("spp", "4"), ("spp", 4.0), ("seed", 1.0), ("threads", "2"), ("sample_begin", True),
                            ("sample_begin", "0"), ("spectral_bins", 2.0), ("spectral_range", "360-830"),
                            ("colorspace", 709), ("progress", 5)]:
            self.wrong_type(name, render, **{name: value})
        self.assertEqual(self.wrong_type("aovs", render, aovs=1), "aovs: expected True or False, got int 1")
        self.wrong_type("stokes", render, stokes="yes")
        self.wrong_type("spectral_range[0]", render, spectral_range=("a", 500))
        self.wrong_type("stokes", self.scene.polarization_mode, 1)
        self.assertEqual(self.scene.render(aovs=np.bool_(True)).aovs["depth"].shape, (6, 8))

    def test_bad_values_name_the_argument(self):
        render = self.scene.render
        self.bad_value("spp", render, spp=0)
        self.bad_value("spp", render, spp=-1)
        self.bad_value("seed", render, seed=-1)
        self.bad_value("seed", render, seed=2**64)
        self.bad_value("threads", render, threads=5000)
        self.bad_value("sample_begin", render, sample_begin=-1)
        self.bad_value("spectral_bins", render, spectral_bins=-1)
        self.bad_value("spectral_bins", render, spectral_bins=472)
        self.bad_value("spectral_range", render, spectral_range=(400,))
        self.bad_value("spectral_range", render, spectral_range=(700, 400))
        self.bad_value("spectral_range[1]", render, spectral_range=(400, math.nan))
        self.bad_value("spectral_range[1]", render, spectral_range=(400, math.inf))
        self.assertIn("known: rec709, acescg", self.bad_value("colorspace", render, colorspace="srgb"))

    def test_a_film_larger_than_memory_is_refused(self):
        # The command line's message (docs/cli.md, "Memory").
        huge = ochre.load_scene(SCENE, resolution=(65536, 65536))
        with self.assertRaises(ochre.InputError) as error:
            huge.render(spectral_bins=400)
        self.assertRegex(str(error.exception), r"^film 65536x65536 \(XYZ, 400 spectral bins\) .* needs .* TiB")


class SampleRange(Case):
    """Sample indices are 32-bit: a range ends at 2^32 - 1 at most, as --sample-range A:B (docs/cli.md)."""

    def test_the_last_samples_render(self):
        scene = ochre.load_scene(SCENE)
        last = scene.render(spp=1, sample_begin=2**32 - 2)  # samples [2^32 - 2, 2^32 - 1)
        self.assertEqual(last.stats["samples"], 8 * 6)
        self.assertGreater(float(last.rgb.mean()), 0.1)
        self.assertIsNone(last.aovs)
        four = scene.render(spp=4, sample_begin=2**32 - 5)
        self.assertEqual(four.stats["samples"], 8 * 6 * 4)
        self.assertGreater(float(four.rgb.mean()), 0.1)

    def test_a_range_ending_at_2_32_is_refused(self):
        scene = ochre.load_scene(SCENE)
        message = self.bad_value("sample_begin, spp", scene.render, spp=1, sample_begin=2**32 - 1)
        self.assertIn("[4294967295, 4294967296)", message)
        self.bad_value("sample_begin, spp", scene.render, spp=4, sample_begin=2**32 - 4)
        self.bad_value("sample_begin, spp", scene.render, spp=16, sample_begin=2**32 - 8)
        self.bad_value("sample_begin", scene.render, spp=1, sample_begin=2**32)
        self.bad_value("sample_begin", scene.render, spp=1, sample_begin=2**64 + 3)
        # The scene's own spp counts when spp is not given.
        self.bad_value("sample_begin, spp", ochre.load_scene(SCENE, spp=3).render, sample_begin=2**32 - 3)


class Material(Case):
    @classmethod
    def setUpClass(cls):
        cls.m = ochre.material({"type": "lambert", "color": 0.8})

    def test_counts_of_zero_are_refused(self):
        self.assertEqual(self.bad_value("samples", self.m.albedo, [30], samples=0),
                         "samples: must be in [1, 2^64 - 1] (got 0)")
        self.bad_value("samples", self.m.albedo, [30], samples=-1)
        self.bad_value("samples", self.m.albedo, [30], samples=2**64)
        self.bad_value("angles", self.m.albedo, [], samples=10)
        self.bad_value("angles[1]", self.m.albedo, [10, 90], samples=10)

    def test_wrong_types_name_the_argument(self):
        m = self.m
        self.wrong_type("source", ochre.material, 3)
        self.wrong_type("name", ochre.material, {"type": "lambert"}, name=3)
        self.wrong_type("base_dir", ochre.material, {"type": "lambert"}, base_dir=3.5)
        self.wrong_type("wi", m.eval, "abc", [0, 0, 1])
        self.wrong_type("wo", m.eval, [0, 0, 1], [0, None, 1])
        self.wrong_type("wavelengths", m.eval, [0, 0, 1], [0, 0, 1], "550")
        self.wrong_type("wi", m.mueller, [[True, False, True]], [0, 0, 1])
        self.wrong_type("wo", m.sample, {"x": 1})
        self.wrong_type("u", m.sample, [0, 0, 1], u="uuu")
        self.wrong_type("seed", m.sample, [0, 0, 1], seed=1.0)
        self.wrong_type("angles", m.albedo, "30")
        self.wrong_type("wavelength", m.albedo, [30], wavelength="550", samples=10)
        self.wrong_type("samples", m.albedo, [30], samples=100.0)
        self.wrong_type("samples", m.albedo, [30], samples=True)
        self.wrong_type("seed", m.albedo, [30], samples=10, seed="1")
        self.wrong_type("wavelength", m.polarizes, None)
        self.wrong_type("lab1", ochre.ciede2000, "x", [50, 0, 0])

    def test_bad_values_name_the_argument(self):
        m = self.m
        self.bad_value("wi", m.eval, [0, 1], [0, 0, 1])
        self.bad_value("wi[0]", m.eval, [0, 0, math.nan], [0, 0, 1])
        self.bad_value("wavelengths[1]", m.eval, [0, 0, 1], [0, 0, 1], [550, 900])
        self.bad_value("wavelengths[0]", m.eval, [0, 0, 1], [0, 0, 1], math.nan)
        self.bad_value("wi, wo, wavelengths", m.eval, np.ones((3, 3)), np.ones((4, 3)))
        # A broadcast larger than the memory limit is refused before anything is allocated.
        self.assertIn("needs", self.bad_value("wi, wo, wavelengths", m.eval, np.ones((10**6, 1, 3)),
                                              np.ones((10**6, 3))))
        self.bad_value("seed", m.sample, [0, 0, 1], seed=-1)
        self.bad_value("u[0]", m.sample, [0, 0, 1], u=[0.5, 1.0, 0.5])
        self.bad_value("wavelength", m.albedo, [30], wavelength=math.inf, samples=10)
        self.bad_value("wavelength", m.polarizes, 1000)
        self.bad_value("seed", m.albedo, [30], samples=10, seed=2**64)
        with tempfile.NamedTemporaryFile() as f:
            self.bad_value("base_dir", ochre.material, {"type": "lambert"}, base_dir=f.name)
        self.bad_value("base_dir", ochre.material, BOX, base_dir=SOURCE)
        self.bad_value("source", ochre.material, "")


class Colour(Case):
    def test_wrong_types_name_the_argument(self):
        S = ochre.Spectrum
        self.wrong_type("extrapolate", S, [400, 500], [1, 2], extrapolate=0)
        self.wrong_type("name", S.named, 65)
        self.wrong_type("scale", S.named, "D65", scale="2")
        self.wrong_type("kelvin", S.blackbody, "hot")
        self.wrong_type("path", S.from_csv, 3)
        self.wrong_type("column", S.from_csv, "x.csv", column=1)
        self.wrong_type("rgb", S.from_rgb, "red")
        self.wrong_type("rgb[1]", S.from_rgb, [0.5, "x", 0.5])
        self.wrong_type("kind", S.from_rgb, [0.5, 0.5, 0.5], kind=None)
        self.wrong_type("value", S.constant, "1")
        self.wrong_type("wavelengths", S.constant(1), "550")
        self.wrong_type("illuminant", S.constant(1).to_xyz, 65)
        self.wrong_type("illuminant", S.constant(1).to_lab, None)
        self.wrong_type("space", S.constant(1).to_rgb, space=709)
        self.wrong_type("xyz", ochre.xyz_to_lab, "xyz", [1, 1, 1])
        self.wrong_type("kl", ochre.ciede2000, [50, 0, 0], [50, 1, 1], kl="1")
        self.wrong_type("test", ochre.image_metrics, "image", np.zeros((2, 2, 3)))
        self.wrong_type("colorspace", ochre.image_metrics, np.zeros((2, 2, 3)), np.zeros((2, 2, 3)), colorspace=1)
        self.wrong_type("ocio_config", ochre.to_display, np.zeros((2, 2, 3)), ocio_config=None)
        self.wrong_type("display", ochre.to_display, np.zeros((2, 2, 3)), display=1)
        self.wrong_type("view", ochre.to_display, np.zeros((2, 2, 3)), view=b"x")
        self.wrong_type("exposure", ochre.to_display, np.zeros((2, 2, 3)), exposure="1")
        self.wrong_type("rgb", ochre.to_display, np.array([[["a", "b", "c"]]]))
        self.wrong_type("path", ochre.read_exr, None)

    def test_bad_values_name_the_argument(self):
        S = ochre.Spectrum
        self.bad_value("scale", S.named, "D65", scale=math.nan)
        self.bad_value("spectrum.scale", S.named, "D65", scale=1e300)  # infinite in single precision
        self.bad_value("kelvin", S.blackbody, math.inf)
        self.bad_value("spectrum.blackbody", S.blackbody, 0)
        self.bad_value("rgb", S.from_rgb, [0.5, 0.5])
        self.bad_value("rgb[2]", S.from_rgb, [0.5, 0.5, math.nan])
        self.bad_value("value", S.constant, math.inf)
        self.bad_value("value", S.constant, 1e300)
        self.bad_value("wavelengths", S.constant(1), math.nan)
        self.bad_value("wavelengths[1]", S.constant(1), [550, math.inf])
        self.bad_value("white", ochre.xyz_to_lab, [0.5, 0.5, 0.5], [1, 0, 1])
        self.bad_value("xyz[0]", ochre.xyz_to_lab, [math.nan, 0.5, 0.5], [1, 1, 1])
        self.bad_value("kl", ochre.ciede2000, [50, 0, 0], [50, 1, 1], kl=0)
        self.bad_value("kh", ochre.ciede2000, [50, 0, 0], [50, 1, 1], kh=math.nan)
        self.bad_value("lab1", ochre.ciede2000, [50, 0], [50, 1, 1])
        self.bad_value("colorspace", ochre.image_metrics, np.zeros((2, 2, 3)), np.zeros((2, 2, 3)), colorspace="srgb2")
        self.bad_value("rgb", ochre.to_display, np.zeros((0, 4, 3)))
        self.bad_value("rgb", ochre.to_display, np.zeros((4, 3)))
        self.bad_value("exposure", ochre.to_display, np.zeros((2, 2, 3)), exposure=65)
        self.bad_value("exposure", ochre.to_display, np.zeros((2, 2, 3)), exposure=math.nan)
        self.bad_value("path", ochre.read_exr, "")

    def test_spectra_evaluate_far_outside_their_range(self):
        for s in (ochre.Spectrum.named("D65"), ochre.Spectrum([400, 500], [1, 2]), ochre.Spectrum.blackbody(3000),
                  ochre.Spectrum.from_rgb([0.5, 0.2, 0.1]), ochre.Spectrum.named("cie_y")):
            values = s(np.array([-1e29, 0.0, 1e-30, 1e29]))
            self.assertTrue(np.all(np.isfinite(values)))


if __name__ == "__main__":
    unittest.main()
