"""Colour in ochre's Python module (docs/python.md): spectra and their XYZ, CIELAB and RGB, CIEDE2000 and
the image metrics of ochre-diff."""

import unittest

import numpy as np

import ochre


class Spectra(unittest.TestCase):
    def test_named_illuminants_and_blackbodies_have_luminance_one(self):
        for s in (ochre.Spectrum.named("D65"), ochre.Spectrum.named("A"), ochre.Spectrum.blackbody(2700)):
            self.assertAlmostEqual(float(s.to_xyz()[1]), 1.0, places=5)
        self.assertAlmostEqual(float(ochre.Spectrum.named("D65", scale=3).luminance), 3.0, places=4)

    def test_white_reflector_is_the_white_point(self):
        white = ochre.Spectrum.constant(1.0)
        np.testing.assert_allclose(white.to_lab("D65"), [100, 0, 0], atol=1e-3)
        np.testing.assert_allclose(white.to_lab("A"), [100, 0, 0], atol=1e-3)
        np.testing.assert_allclose(white.to_rgb(illuminant="D65"), [1, 1, 1], atol=1e-4)
        np.testing.assert_allclose(ochre.Spectrum.named("D65").to_rgb(), [1, 1, 1], atol=1e-4)

    def test_rgb_upsampling_round_trips_under_d65(self):
        rgb = [0.6, 0.3, 0.1]
        s = ochre.Spectrum.from_rgb(rgb)
        np.testing.assert_allclose(s.to_rgb(illuminant="D65"), rgb, atol=2e-3)
        self.assertLessEqual(s.max_value, 1.0)
        light = ochre.Spectrum.from_rgb([2.0, 1.0, 0.5], kind="illuminant")
        np.testing.assert_allclose(light.to_rgb(), [2.0, 1.0, 0.5], rtol=5e-3)

    def test_tables_evaluate_linearly(self):
        s = ochre.Spectrum([400, 500, 600], [0.2, 0.6, 0.4], extrapolate="zero")
        np.testing.assert_allclose(s([450, 550, 650]), [0.4, 0.5, 0.0], atol=1e-7)
        self.assertAlmostEqual(s(500), 0.6, places=6)

    def test_bad_spectra_are_input_errors(self):
        with self.assertRaises(ochre.InputError) as error:
            ochre.Spectrum([400, 500], [0.1])
        self.assertIn("'values' must have as many entries as 'wavelengths'", str(error.exception))
        with self.assertRaises(ochre.InputError) as error:
            ochre.Spectrum.named("D64")
        self.assertIn("spectrum.name", str(error.exception))
        with self.assertRaises(ochre.InputError):
            ochre.Spectrum.from_rgb([1.5, 0, 0])
        with self.assertRaises(ochre.InputError):
            ochre.Spectrum.from_csv("no-such-file.csv")


class Differences(unittest.TestCase):
    def test_ciede2000_of_sharma_wu_dalal(self):
        # Pairs 1, 7 and 17 of Sharma, Wu & Dalal (2005), Table 1.
        lab1 = [[50.0, 2.6772, -79.7751], [50.0, 0.0, 0.0], [50.0, 2.5, 0.0]]
        lab2 = [[50.0, 0.0, -82.7485], [50.0, -1.0, 2.0], [73.0, 25.0, -18.0]]
        np.testing.assert_allclose(ochre.ciede2000(lab1, lab2), [2.0425, 2.3669, 27.1492], atol=1e-4)
        self.assertIsInstance(ochre.ciede2000(lab1[0], lab2[0]), float)

    def test_xyz_to_lab(self):
        np.testing.assert_allclose(ochre.xyz_to_lab([0.5, 0.5, 0.5], [0.5, 0.5, 0.5]), [100, 0, 0], atol=1e-9)

    def test_image_metrics(self):
        rng = np.random.default_rng(1)
        a = rng.random((8, 6, 3)).astype(np.float32)
        same = ochre.image_metrics(a, a)
        self.assertEqual(same["rmse"], 0.0)
        self.assertEqual(same["mean_de00"], 0.0)
        b = a + 0.1
        m = ochre.image_metrics(b, a)
        self.assertAlmostEqual(m["rmse"], 0.1, places=5)
        self.assertAlmostEqual(m["max_error"], 0.1, places=5)
        self.assertEqual(m["de00_map"].shape, (8, 6))
        with self.assertRaises(ochre.InputError):
            ochre.image_metrics(a, a[:4])

    def test_display(self):
        rgb = np.full((2, 3, 3), 0.18, dtype=np.float32)
        d = ochre.to_display(rgb, ocio_config="none")
        self.assertEqual(d.dtype, np.uint8)
        self.assertEqual(d.shape, (2, 3, 3))
        self.assertEqual(int(d[0, 0, 0]), 118)  # sRGB encoding of 0.18


if __name__ == "__main__":
    unittest.main()
